//! Materials: how a surface or a hair strand responds to light.
//!
//! Every material answers one question for direct lighting, [`Material::response`]: the
//! radiance leaving towards `wo` per unit of light arriving from `wi` (a BRDF times the
//! cosine for surfaces; the tube model or the physical hair BSDF times its cosine for
//! hair). Mirror and glass answer through [`Material::specular`] instead, which the
//! integrator follows recursively. An unlit surface ([`Material::Unlit`],
//! [`Material::UnlitTextured`]) answers neither:
//! it shows its colour whatever the light ([`Material::unlit_radiance`]), and the
//! integrators draw it without sampling lights at it or scattering from it.

pub mod fur_tube;
pub mod hair_bsdf;
pub mod scatter;
pub mod surface;
pub mod texture;
pub mod tube;

use crate::math::rng::PixelSampler;
use crate::math::Color;
use glam::Vec3;

/// A material of a surface or a strand set.
#[derive(Clone, Debug, PartialEq)]
pub enum Material {
    /// Lambertian reflection.
    Diffuse {
        /// Albedo.
        color: Color,
    },
    /// Lambertian plus a normalised Phong lobe.
    Phong {
        /// Diffuse albedo.
        diffuse: Color,
        /// Specular reflectance.
        specular: Color,
        /// Phong exponent.
        exponent: f32,
    },
    /// A perfect mirror.
    Mirror {
        /// Reflectance.
        color: Color,
    },
    /// A smooth dielectric: Fresnel-weighted reflection and refraction.
    Glass {
        /// Index of refraction inside.
        ior: f32,
        /// Transmittance tint.
        color: Color,
    },
    /// The thesis' tube shading for hair (section 2.1.8, eq. 2.1 to 2.3).
    Tube(tube::Tube),
    /// The physically based hair BSDF of Chiang et al. 2016 ([`hair_bsdf`]).
    Physical(hair_bsdf::PhysicalHair),
    /// The thesis' fur shading (section 2.1.8, eq. 2.4 to 2.7), root-to-tip colours.
    Fur(fur_tube::Fur),
    /// A surface whose diffuse colour comes from a colour map by UV (an image or a
    /// checkerboard), and optionally its glossiness from an image ([`Textured`]).
    Textured(Textured),
    /// An unlit surface, as Arnold's `flat` shader draws one (Arnold user guide, "Flat"):
    /// the radiance leaving it in every direction is `color` (the geometry's colour where it has
    /// one, as for every material), whatever light arrives, for
    /// every ray that reaches it (camera, mirror, gathered and path rays), so under global
    /// illumination it lights its neighbours like an emitter of that radiance. It has no
    /// BSDF: light arriving is not reflected, and no light is sampled at it. It blocks
    /// light like any opaque surface (it casts shadows); light sampling does not find it
    /// (it is not a light), only rays that reach it.
    Unlit {
        /// The outgoing radiance (linear RGB, may exceed 1).
        color: Color,
    },
    /// An unlit surface ([`Material::Unlit`]) whose radiance is `tint` times a colour map
    /// by UV (the map's mean where the mesh has no UVs), as Arnold's `flat` shader draws a
    /// texture on its colour. The geometry's colour does not replace it (as for
    /// [`Material::Textured`]).
    UnlitTextured {
        /// The radiance by UV.
        color: texture::ColorMap,
        /// Factor on the map's colour.
        tint: Color,
    },
}

/// A textured surface: Lambert with the colour `tint` times the `color` map, plus,
/// with a roughness, a normalised Phong lobe of reflectance `specular` whose exponent
/// the roughness gives (`2 / r^2 - 2`, the Phong exponent equivalent to a Beckmann
/// roughness r; Walter et al. 2007, "Microfacet Models for Refraction", section 5.2).
#[derive(Clone, Debug, PartialEq)]
pub struct Textured {
    /// Diffuse colour by UV.
    pub color: texture::ColorMap,
    /// Factor on the texture's colour.
    pub tint: Color,
    /// Roughness in (0, 1]: a constant or a texture's red channel; `None` is matte.
    pub roughness: Option<Roughness>,
    /// Reflectance of the glossy lobe (with a roughness).
    pub specular: Color,
}

/// A roughness: one value, or a texture's red channel by UV.
#[derive(Clone, Debug, PartialEq)]
pub enum Roughness {
    /// The same everywhere.
    Constant(f32),
    /// By UV (the red channel).
    Map(texture::Texture),
}

impl Textured {
    /// The diffuse albedo at a shading point: the map at its UV filtered by the ray's
    /// footprint (the map's mean where the mesh has no UVs).
    pub fn albedo(&self, sp: &ShadingPoint) -> Color {
        self.tint * map_at(&self.color, sp)
    }

    fn response(&self, sp: &ShadingPoint, wo: Vec3, wi: Vec3) -> Color {
        let kd = self.albedo(sp);
        let roughness = match &self.roughness {
            None => return surface::lambert(kd, sp.normal, wi),
            Some(Roughness::Constant(r)) => *r,
            Some(Roughness::Map(t)) => match sp.uv {
                Some(at) => t.lookup(at.uv, at.width).x,
                None => t.average().x,
            },
        };
        let r = roughness.clamp(0.02, 1.0);
        surface::phong(kd, self.specular, phong_exponent(r), sp.normal, wo, wi)
    }
}

/// A colour map at a shading point: at its UV filtered by the ray's footprint, the map's
/// mean without UVs.
fn map_at(map: &texture::ColorMap, sp: &ShadingPoint) -> Color {
    match sp.uv {
        Some(t) => map.lookup(t.uv, t.width),
        None => map.average(),
    }
}

/// The Phong exponent equivalent to a Beckmann roughness `r`: `2 / r² − 2` (Walter et al.
/// 2007, "Microfacet Models for Refraction", section 5.2), 0 for `r` of 1 or more.
pub fn phong_exponent(r: f32) -> f32 {
    (2.0 / (r * r) - 2.0).max(0.0)
}

/// Texture coordinates at a hit and the width of the ray's footprint there in UV units.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TexCoord {
    /// Texture coordinates.
    pub uv: [f32; 2],
    /// Width of the ray's footprint on the surface, in UV units.
    pub width: f32,
}

/// Where and how a ray met a surface or a strand, as the materials need it.
#[derive(Clone, Copy, Debug)]
pub struct ShadingPoint {
    /// Hit position.
    pub p: Vec3,
    /// Unit normal of the true surface (for hair, the cylinder normal at the hit), facing
    /// the side the ray came from.
    pub normal: Vec3,
    /// Unit hair tangent, interpolated along the strand; `None` on surfaces.
    pub tangent: Option<Vec3>,
    /// Per-strand or per-vertex colour from the geometry, replacing the material's base
    /// colour when present.
    pub color: Option<Color>,
    /// True when the ray hit the surface from its back (inside glass).
    pub backface: bool,
    /// On hair: the strand index and the fraction of its length at the hit (0 root, 1 tip).
    pub strand: Option<(u32, f32)>,
    /// On meshes with UVs: the texture coordinates and the ray's footprint.
    pub uv: Option<TexCoord>,
}

/// A ray a specular material continues with.
#[derive(Clone, Copy, Debug)]
pub struct SpecularRay {
    /// Unit direction.
    pub dir: Vec3,
    /// Weight of the radiance it brings back.
    pub weight: Color,
    /// True for transmission (the ray leaves on the far side of the surface).
    pub transmitted: bool,
}

impl Material {
    /// The default colour of diffuse and Phong surfaces: mid grey.
    pub const DEFAULT_COLOR: Color = Color::splat(0.5);
    /// The default specular colour of a Phong surface.
    pub const DEFAULT_PHONG_SPECULAR: Color = Color::splat(0.2);
    /// The default Phong exponent.
    pub const DEFAULT_PHONG_EXPONENT: f32 = 20.0;
    /// The default index of refraction of glass (crown glass, about 1.5).
    pub const DEFAULT_IOR: f32 = 1.5;

    /// Radiance towards `wo` per unit of light from `wi` (both unit, pointing away from
    /// the point). Zero for purely specular materials.
    pub fn response(&self, sp: &ShadingPoint, wo: Vec3, wi: Vec3) -> Color {
        match self {
            Material::Diffuse { color } => surface::lambert(sp.color.unwrap_or(*color), sp.normal, wi),
            Material::Phong { diffuse, specular, exponent } => {
                surface::phong(sp.color.unwrap_or(*diffuse), *specular, *exponent, sp.normal, wo, wi)
            }
            Material::Mirror { .. }
            | Material::Glass { .. }
            | Material::Unlit { .. }
            | Material::UnlitTextured { .. } => Color::ZERO,
            Material::Tube(t) => match sp.tangent {
                Some(tangent) => t.response(sp.color, tangent, wo, wi),
                // Tube shading on a surface: fall back to Lambert with the diffuse colour.
                None => surface::lambert(sp.color.unwrap_or(t.diffuse), sp.normal, wi),
            },
            Material::Physical(h) => match sp.tangent {
                Some(tangent) => h.response(sp.color, tangent, sp.normal, wo, wi),
                // On a surface: Lambert with the colour the absorption stands for.
                None => surface::lambert(h.surface_color(sp.color), sp.normal, wi),
            },
            Material::Fur(f) => match (sp.tangent, sp.strand) {
                (Some(tangent), Some((strand, along))) => f.response(strand, along, sp.color, tangent, wo, wi),
                // Fur shading on a surface: Lambert with the base colour.
                _ => surface::lambert(sp.color.unwrap_or(f.diffuse[0]), sp.normal, wi),
            },
            Material::Textured(t) => t.response(sp, wo, wi),
        }
    }

    /// The radiance an unlit surface ([`Material::Unlit`], [`Material::UnlitTextured`])
    /// sends towards every direction at `sp`: its colour, or the geometry's colour there
    /// when it has one (as it replaces every untextured material's base colour), or its map
    /// at `sp`. `None` for every other material, which reflects light instead.
    pub fn unlit_radiance(&self, sp: &ShadingPoint) -> Option<Color> {
        match self {
            Material::Unlit { color } => Some(sp.color.unwrap_or(*color)),
            Material::UnlitTextured { color, tint } => Some(*tint * map_at(color, sp)),
            _ => None,
        }
    }

    /// The material with its lobes widened to at least roughness `min_roughness`, for path
    /// regularization ([`hair_bsdf::PhysicalHair::widened`]): only physical hair narrower
    /// than that changes; `None` for every other material and for hair already as rough.
    pub fn regularized(&self, min_roughness: f32) -> Option<Material> {
        match self {
            Material::Physical(h) => h.widened(min_roughness).map(Material::Physical),
            _ => None,
        }
    }

    /// A direction `wi` drawn in proportion to the material's response, and its
    /// solid-angle density, for materials that can importance-sample themselves: the hair
    /// BSDF on hair. `None` for the others, which then draw nothing from `sampler`.
    pub fn sample_direction(&self, sp: &ShadingPoint, wo: Vec3, sampler: &mut PixelSampler) -> Option<(Vec3, f32)> {
        match (self, sp.tangent) {
            (Material::Physical(h), Some(tangent)) => {
                let u = [sampler.next_1d(), sampler.next_1d(), sampler.next_1d(), sampler.next_1d()];
                h.sample(sp.color, tangent, sp.normal, wo, u)
            }
            _ => None,
        }
    }

    /// Constant light the material reflects from the environment without sampling it:
    /// the tube or fur model's ambient colour times the environment radiance (thesis
    /// eq. 2.3 and 2.7).
    pub fn ambient(&self, sp: &ShadingPoint, environment: Color) -> Color {
        match self {
            Material::Tube(t) if sp.tangent.is_some() => t.ambient_color(sp.color) * environment,
            Material::Fur(f) => match (sp.tangent, sp.strand) {
                (Some(_), Some((strand, along))) => f.ambient_color(strand, along) * environment,
                _ => Color::ZERO,
            },
            _ => Color::ZERO,
        }
    }

    /// True when the material lights itself from the environment through [`Material::ambient`],
    /// so the integrator must not also sample the environment for it.
    pub fn has_ambient_term(&self, sp: &ShadingPoint) -> bool {
        self.shades_whole_circle() && sp.tangent.is_some()
    }

    /// True for the tangent-based hair models (tube, fur), which shade a strand's whole
    /// circle alike: rays leaving a hit on hair start on the side facing their direction.
    pub fn shades_whole_circle(&self) -> bool {
        matches!(self, Material::Tube(_) | Material::Fur(_))
    }

    /// The specular rays to follow from this point for a ray arriving along `-wo`
    /// (at most two: reflection and refraction).
    pub fn specular(&self, sp: &ShadingPoint, wo: Vec3) -> [Option<SpecularRay>; 2] {
        match self {
            Material::Mirror { color } => {
                [Some(SpecularRay { dir: surface::reflect(wo, sp.normal), weight: *color, transmitted: false }), None]
            }
            Material::Glass { ior, color } => surface::dielectric(*ior, *color, sp.normal, sp.backface, wo),
            _ => [None, None],
        }
    }
}
