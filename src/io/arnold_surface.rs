//! Arnold's surface shader, `standard_surface` (MtoA's `aiStandardSurface` node in Maya
//! files, Arnold-USD's `arnold:standard_surface` shader in USD), as tress's surface
//! materials. Both readers fill a [`StandardSurface`] by Arnold's parameter names through
//! [`ArnoldShader`], as they do Arnold's hair shader ([`super::arnold_hair`]).
//!
//! Autodesk Standard Surface (the specification Arnold's shader implements) layers a
//! dielectric specular coating over a diffuse base, blends to a metal by `metalness` and to
//! a transmissive dielectric by `transmission`. tress's materials hold one of these at a
//! time, so the mapping picks the dominant layer:
//!
//! - `transmission` 0.5 or more: `glass` of index `specular_IOR` and colour
//!   `transmission_color`;
//! - else `metalness` 0.5 or more: a metal, its reflectance `base × base_color`: a
//!   `mirror` when `specular_roughness` is 0, else a `phong` lobe of that reflectance with
//!   no diffuse;
//! - else the dielectric: Lambert of `base × base_color` plus, unless `specular` is 0, a
//!   `phong` lobe of reflectance `specular × specular_color × F0`, F0 = ((η − 1)/(η + 1))²
//!   the coating's Fresnel reflectance at normal incidence (η = `specular_IOR`); a
//!   dielectric that reflects nothing (base and specular 0) but emits is `unlit` of
//!   `emission × emission_color`, the radiance Arnold adds.
//!
//! A checkerboard on `base_color` or `base` (or `Kd_color`, `Kd` of `lambert`) makes the
//! Lambert or Phong surface [`Material::Textured`]; on `emission_color` or `emission` of
//! an emitting surface, or on flat's `color`, [`Material::UnlitTextured`] ([`textured`]).
//!
//! The glossy lobe's exponent is [`crate::shading::phong_exponent`] of the microfacet
//! roughness α = `specular_roughness`², Standard Surface's remapping of its roughness
//! control (Georgiev et al. 2019, "Autodesk Standard Surface", specular section).
//!
//! What the mapping cannot hold (coat, sheen, subsurface, thin film, emission, opacity,
//! thin walls, diffuse roughness, a partial metal or transmission, connected shading
//! networks) is named in one warning per shader.
//!
//! Arnold's two simple surface shaders are read the same way: `lambert` ([`Lambert`],
//! Lambert of `Kd × Kd_color`) and `flat` ([`Flat`], an unlit colour), which is tress's
//! `unlit` material ([`Material::Unlit`]): the shader returns its `color` as the radiance
//! leaving the surface for every ray type, lights nothing by reflection and lights its
//! neighbours under global illumination (Arnold user guide, "Flat"). Its opacity and a
//! shading network on its colour are not evaluated, said in its warning.

use super::arnold_graph::Pattern;
use super::arnold_hair::{fmt_color, ArnoldShader, Param};
use crate::math::Color;
use crate::shading::texture::ColorMap;
use crate::shading::{phong_exponent, Material, Roughness, Textured};

/// What a shader parameter driven by a colour map colours: the diffuse reflectance of a
/// lit surface, or the radiance of an unlit one.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Slot {
    /// A factor on the diffuse colour (`base`, `base_color`, `Kd`, `Kd_color`).
    Diffuse,
    /// A factor on the radiance (`emission`, `emission_color`, flat's `color`).
    Radiance,
}

/// `material`, made with the mapped parameter at 1, with that parameter's `map` applied:
/// a Lambert or Phong surface becomes [`Material::Textured`] (its diffuse colour the tint,
/// its Phong exponent given back as the equivalent roughness), an unlit one
/// [`Material::UnlitTextured`]. `None` when the map cannot colour what the material draws
/// (a metal's or glass's reflectance, an emission on a lit surface).
pub fn textured(material: &Material, slot: Slot, map: ColorMap) -> Option<Material> {
    Some(match (slot, material) {
        (Slot::Diffuse, Material::Diffuse { color }) => {
            Material::Textured(Textured { color: map, tint: *color, roughness: None, specular: Color::ZERO })
        }
        (Slot::Diffuse, Material::Phong { diffuse, specular, exponent }) if *diffuse != Color::ZERO => {
            // The inverse of `phong_exponent`: r = sqrt(2 / (n + 2)).
            let r = (2.0 / (exponent + 2.0)).sqrt();
            Material::Textured(Textured {
                color: map,
                tint: *diffuse,
                roughness: Some(Roughness::Constant(r)),
                specular: *specular,
            })
        }
        (Slot::Radiance, Material::Unlit { color }) => Material::UnlitTextured { color: map, tint: *color },
        _ => return None,
    })
}

/// Smallest `specular_roughness` drawn as a glossy lobe (below it the exponent grows
/// past what sampling resolves): a metal rougher than 0 but below this is a `phong` of
/// this roughness.
const MIN_ROUGHNESS: f32 = 0.01;

/// Arnold's `standard_surface` parameters that tress reads, with Arnold's defaults.
#[derive(Clone, Debug, PartialEq)]
pub struct StandardSurface {
    /// Weight of the base (diffuse or metal) colour.
    pub base: f32,
    /// Base colour.
    pub base_color: Color,
    /// Oren–Nayar roughness of the diffuse base.
    pub diffuse_roughness: f32,
    /// Blend from dielectric (0) to metal (1).
    pub metalness: f32,
    /// Weight of the specular coating.
    pub specular: f32,
    /// Tint of the specular coating.
    pub specular_color: Color,
    /// Roughness of the specular coating (and of the metal).
    pub specular_roughness: f32,
    /// Index of refraction of the coating and of transmission.
    pub specular_ior: f32,
    /// Blend to a transmissive dielectric.
    pub transmission: f32,
    /// Transmission colour.
    pub transmission_color: Color,
    /// Weight of subsurface scattering.
    pub subsurface: f32,
    /// Weight of the sheen layer.
    pub sheen: f32,
    /// Weight of the clear coat.
    pub coat: f32,
    /// Thin-film thickness in nanometres (0: none).
    pub thin_film_thickness: f32,
    /// Weight of the emission.
    pub emission: f32,
    /// Colour of the emission.
    pub emission_color: Color,
    /// Opacity.
    pub opacity: Color,
    /// A thin, two-sided surface with no interior.
    pub thin_walled: bool,
}

impl Default for StandardSurface {
    /// Arnold's defaults (Arnold user guide, "Standard Surface").
    fn default() -> Self {
        StandardSurface {
            base: 0.8,
            base_color: Color::ONE,
            diffuse_roughness: 0.0,
            metalness: 0.0,
            specular: 1.0,
            specular_color: Color::ONE,
            specular_roughness: 0.2,
            specular_ior: 1.5,
            transmission: 0.0,
            transmission_color: Color::ONE,
            subsurface: 0.0,
            sheen: 0.0,
            coat: 0.0,
            thin_film_thickness: 0.0,
            emission: 0.0,
            emission_color: Color::ONE,
            opacity: Color::ONE,
            thin_walled: false,
        }
    }
}

impl ArnoldShader for StandardSurface {
    const MAPS: &'static [(&'static str, Slot)] = &[
        ("base_color", Slot::Diffuse),
        ("base", Slot::Diffuse),
        ("emission_color", Slot::Radiance),
        ("emission", Slot::Radiance),
    ];
    const NAMES: &'static [&'static str] = &[
        "base",
        "base_color",
        "diffuse_roughness",
        "metalness",
        "specular",
        "specular_color",
        "specular_roughness",
        "specular_IOR",
        "transmission",
        "transmission_color",
        "subsurface",
        "sheen",
        "coat",
        "thin_film_thickness",
        "emission",
        "emission_color",
        "opacity",
        "thin_walled",
    ];

    fn param(&mut self, name: &str) -> Option<Param<'_>> {
        use Param::{Bool, Color as C, Float};
        Some(match name {
            "base" => Float(&mut self.base),
            "base_color" => C(&mut self.base_color),
            "diffuse_roughness" => Float(&mut self.diffuse_roughness),
            "metalness" => Float(&mut self.metalness),
            "specular" => Float(&mut self.specular),
            "specular_color" => C(&mut self.specular_color),
            "specular_roughness" => Float(&mut self.specular_roughness),
            "specular_IOR" => Float(&mut self.specular_ior),
            "transmission" => Float(&mut self.transmission),
            "transmission_color" => C(&mut self.transmission_color),
            "subsurface" => Float(&mut self.subsurface),
            "sheen" => Float(&mut self.sheen),
            "coat" => Float(&mut self.coat),
            "thin_film_thickness" => Float(&mut self.thin_film_thickness),
            "emission" => Float(&mut self.emission),
            "emission_color" => C(&mut self.emission_color),
            "opacity" => C(&mut self.opacity),
            "thin_walled" => Bool(&mut self.thin_walled),
            _ => return None,
        })
    }

    /// The material standing in for the shader (module documentation), and the warning
    /// naming what it leaves out.
    fn material(&self, shader: &str, connected: &[String]) -> (Material, Option<String>) {
        let mut left_out: Vec<String> = Vec::new();
        // NaN takes the parameter's low end, like a value out of range.
        let unit = |v: f32| if v.is_nan() { 0.0 } else { v.clamp(0.0, 1.0) };
        let rgb = |c: Color| c.clamp(Color::ZERO, Color::ONE);
        let (transmission, metalness) = (unit(self.transmission), unit(self.metalness));
        let ior = if self.specular_ior.is_finite() { self.specular_ior.clamp(1.0, 10.0) } else { 1.5 };
        let roughness = unit(self.specular_roughness);
        let exponent = || phong_exponent(roughness.max(MIN_ROUGHNESS).powi(2));
        let base = rgb(self.base_color * unit(self.base));
        let finite = |c: Color| Color::from_array(c.to_array().map(|x| if x.is_finite() { x.max(0.0) } else { 0.0 }));
        let emitted = finite(self.emission_color * self.emission.max(0.0));
        let material = if transmission >= 0.5 {
            if transmission < 1.0 {
                left_out.push(format!("transmission {transmission} (drawn as glass)"));
            }
            if roughness > 0.0 {
                left_out.push(format!("specular_roughness {roughness} of the glass (drawn smooth)"));
            }
            Material::Glass { ior, color: rgb(self.transmission_color) }
        } else {
            if transmission > 0.0 {
                left_out.push(format!("transmission {transmission} (drawn opaque)"));
            }
            if metalness >= 0.5 {
                if metalness < 1.0 {
                    left_out.push(format!("metalness {metalness} (drawn as a metal)"));
                }
                match roughness == 0.0 {
                    true => Material::Mirror { color: base },
                    false => Material::Phong { diffuse: Color::ZERO, specular: base, exponent: exponent() },
                }
            } else {
                if metalness > 0.0 {
                    left_out.push(format!("metalness {metalness} (drawn as a dielectric)"));
                }
                let f0 = ((ior - 1.0) / (ior + 1.0)).powi(2);
                let specular = rgb(self.specular_color * unit(self.specular) * f0);
                match (specular == Color::ZERO, base == Color::ZERO && emitted != Color::ZERO) {
                    // Nothing reflected: the emission is all Arnold draws, an unlit colour.
                    (true, true) => Material::Unlit { color: emitted },
                    (true, false) => Material::Diffuse { color: base },
                    (false, _) => Material::Phong { diffuse: base, specular, exponent: exponent() },
                }
            }
        };
        for (name, v) in [
            ("diffuse_roughness", self.diffuse_roughness),
            ("subsurface", self.subsurface),
            ("sheen", self.sheen),
            ("coat", self.coat),
            ("thin_film_thickness", self.thin_film_thickness),
        ] {
            if v != 0.0 {
                left_out.push(format!("{name} {v}"));
            }
        }
        if self.emission != 0.0 && self.emission_color != Color::ZERO && !matches!(material, Material::Unlit { .. }) {
            left_out.push(format!("emission {} of colour {}", self.emission, fmt_color(self.emission_color)));
        }
        if self.opacity != Color::ONE {
            left_out.push(format!("opacity {}", fmt_color(self.opacity)));
        }
        if self.thin_walled {
            left_out.push("thin_walled".into());
        }
        if !connected.is_empty() {
            left_out.push(format!("shading networks on {} (their own values used)", connected.join(", ")));
        }
        let warning = (!left_out.is_empty()).then(|| {
            format!("{shader}: Arnold standard_surface settings tress does not represent: {}", left_out.join(", "))
        });
        (material, warning)
    }
}

/// The warning naming what a simple shader leaves out (`None` when nothing).
fn simple_warning(
    shader: &str,
    kind: &str,
    mut left_out: Vec<String>,
    opacity: Color,
    connected: &[String],
) -> Option<String> {
    if opacity != Color::ONE {
        left_out.push(format!("opacity {}", fmt_color(opacity)));
    }
    if !connected.is_empty() {
        left_out.push(format!("shading networks on {} (their own values used)", connected.join(", ")));
    }
    (!left_out.is_empty())
        .then(|| format!("{shader}: Arnold {kind} settings tress does not represent: {}", left_out.join(", ")))
}

/// Arnold's `lambert` shader, with Arnold's defaults.
#[derive(Clone, Debug, PartialEq)]
pub struct Lambert {
    /// Diffuse weight.
    pub kd: f32,
    /// Diffuse colour.
    pub kd_color: Color,
    /// Opacity.
    pub opacity: Color,
}

impl Default for Lambert {
    /// Arnold's defaults (Arnold user guide, "Lambert").
    fn default() -> Self {
        Lambert { kd: 0.7, kd_color: Color::ONE, opacity: Color::ONE }
    }
}

impl ArnoldShader for Lambert {
    const MAPS: &'static [(&'static str, Slot)] = &[("Kd_color", Slot::Diffuse), ("Kd", Slot::Diffuse)];
    const NAMES: &'static [&'static str] = &["Kd", "Kd_color", "opacity"];

    fn param(&mut self, name: &str) -> Option<Param<'_>> {
        Some(match name {
            "Kd" => Param::Float(&mut self.kd),
            "Kd_color" => Param::Color(&mut self.kd_color),
            "opacity" => Param::Color(&mut self.opacity),
            _ => return None,
        })
    }

    /// Lambert of `Kd × Kd_color`, clamped to [0, 1] (NaN is 0).
    fn material(&self, shader: &str, connected: &[String]) -> (Material, Option<String>) {
        let kd = if self.kd.is_nan() { 0.0 } else { self.kd.clamp(0.0, 1.0) };
        let color = (self.kd_color * kd).clamp(Color::ZERO, Color::ONE);
        (Material::Diffuse { color }, simple_warning(shader, "lambert", Vec::new(), self.opacity, connected))
    }
}

/// Arnold's `flat` shader (an unlit colour), with Arnold's defaults.
#[derive(Clone, Debug, PartialEq)]
pub struct Flat {
    /// The colour drawn.
    pub color: Color,
    /// Opacity.
    pub opacity: Color,
}

impl Default for Flat {
    /// Arnold's defaults (Arnold user guide, "Flat").
    fn default() -> Self {
        Flat { color: Color::ONE, opacity: Color::ONE }
    }
}

impl ArnoldShader for Flat {
    const MAPS: &'static [(&'static str, Slot)] = &[("color", Slot::Radiance)];
    const NAMES: &'static [&'static str] = &["color", "opacity"];

    fn param(&mut self, name: &str) -> Option<Param<'_>> {
        Some(match name {
            "color" => Param::Color(&mut self.color),
            "opacity" => Param::Color(&mut self.opacity),
            _ => return None,
        })
    }

    /// Unlit, of its colour: a radiance, so above 1 is kept; negative, NaN and infinite
    /// components are 0 (an infinite radiance would fill the image with infinities).
    fn material(&self, shader: &str, connected: &[String]) -> (Material, Option<String>) {
        let color = Color::from_array(self.color.to_array().map(|c| if c.is_finite() { c.max(0.0) } else { 0.0 }));
        (Material::Unlit { color }, simple_warning(shader, "flat", Vec::new(), self.opacity, connected))
    }
}

/// The `standard` shader of Arnold 4 (the legacy shader older files and MtoA's
/// `aiStandard` write), by its parameter names and defaults (Arnold 4 node reference):
/// Lambert of `Kd × Kd_color` plus, with `Ks`, a Phong lobe of reflectance
/// `Ks × Ks_color` whose exponent `specular_roughness` gives as it does for
/// `standard_surface` (with no diffuse and a roughness of 0, a mirror of that
/// reflectance); `Kt` 0.5 or more is glass of index `IOR` and colour `Kt_color`,
/// else `Kr` 0.5 or more a mirror of `Kr × Kr_color`. A surface that reflects nothing but
/// emits is unlit of `emission × emission_color`.
#[derive(Clone, Debug, PartialEq)]
pub struct Standard {
    /// Diffuse weight.
    pub kd: f32,
    /// Diffuse colour.
    pub kd_color: Color,
    /// Diffuse roughness (Oren-Nayar), not drawn.
    pub diffuse_roughness: f32,
    /// Specular weight.
    pub ks: f32,
    /// Specular colour.
    pub ks_color: Color,
    /// Specular roughness.
    pub specular_roughness: f32,
    /// Mirror reflection weight.
    pub kr: f32,
    /// Mirror reflection colour.
    pub kr_color: Color,
    /// Refraction weight.
    pub kt: f32,
    /// Refraction colour.
    pub kt_color: Color,
    /// Index of refraction.
    pub ior: f32,
    /// Subsurface weight, not drawn.
    pub ksss: f32,
    /// Emission weight.
    pub emission: f32,
    /// Emission colour.
    pub emission_color: Color,
    /// Opacity, not drawn.
    pub opacity: Color,
}

impl Default for Standard {
    fn default() -> Self {
        Standard {
            kd: 0.7,
            kd_color: Color::ONE,
            diffuse_roughness: 0.0,
            ks: 0.0,
            ks_color: Color::ONE,
            specular_roughness: 0.466905,
            kr: 0.0,
            kr_color: Color::ONE,
            kt: 0.0,
            kt_color: Color::ONE,
            ior: 1.0,
            ksss: 0.0,
            emission: 0.0,
            emission_color: Color::ONE,
            opacity: Color::ONE,
        }
    }
}

impl ArnoldShader for Standard {
    const MAPS: &'static [(&'static str, Slot)] = &[("Kd_color", Slot::Diffuse), ("Kd", Slot::Diffuse)];
    const NAMES: &'static [&'static str] = &[
        "Kd",
        "Kd_color",
        "diffuse_roughness",
        "Ks",
        "Ks_color",
        "specular_roughness",
        "Kr",
        "Kr_color",
        "Kt",
        "Kt_color",
        "IOR",
        "Ksss",
        "emission",
        "emission_color",
        "opacity",
    ];

    fn param(&mut self, name: &str) -> Option<Param<'_>> {
        use Param::{Color as C, Float};
        Some(match name {
            "Kd" => Float(&mut self.kd),
            "Kd_color" => C(&mut self.kd_color),
            "diffuse_roughness" => Float(&mut self.diffuse_roughness),
            "Ks" => Float(&mut self.ks),
            "Ks_color" => C(&mut self.ks_color),
            "specular_roughness" => Float(&mut self.specular_roughness),
            "Kr" => Float(&mut self.kr),
            "Kr_color" => C(&mut self.kr_color),
            "Kt" => Float(&mut self.kt),
            "Kt_color" => C(&mut self.kt_color),
            "IOR" => Float(&mut self.ior),
            "Ksss" => Float(&mut self.ksss),
            "emission" => Float(&mut self.emission),
            "emission_color" => C(&mut self.emission_color),
            "opacity" => C(&mut self.opacity),
            _ => return None,
        })
    }

    fn material(&self, shader: &str, connected: &[String]) -> (Material, Option<String>) {
        let unit = |v: f32| if v.is_nan() { 0.0 } else { v.clamp(0.0, 1.0) };
        let rgb = |c: Color| c.clamp(Color::ZERO, Color::ONE);
        let mut left_out = Vec::new();
        let (kt, kr) = (unit(self.kt), unit(self.kr));
        let base = rgb(self.kd_color * unit(self.kd));
        let specular = rgb(self.ks_color * unit(self.ks));
        let emitted = rgb(self.emission_color * self.emission.max(0.0));
        let material = if kt >= 0.5 {
            let ior = if self.ior.is_finite() { self.ior.clamp(1.0, 10.0) } else { 1.0 };
            Material::Glass { ior, color: rgb(self.kt_color) }
        } else if kr >= 0.5 {
            Material::Mirror { color: rgb(self.kr_color * kr) }
        } else if specular != Color::ZERO && base == Color::ZERO && unit(self.specular_roughness) == 0.0 {
            // A sharp specular lobe alone: what it reflects is the scene, mirrored.
            Material::Mirror { color: specular }
        } else if specular != Color::ZERO {
            let r = unit(self.specular_roughness).max(MIN_ROUGHNESS);
            Material::Phong { diffuse: base, specular, exponent: phong_exponent(r * r) }
        } else if base == Color::ZERO && emitted != Color::ZERO {
            Material::Unlit { color: emitted }
        } else {
            Material::Diffuse { color: base }
        };
        for (name, v, drawn) in [("Kt", kt, kt >= 0.5), ("Kr", kr, kr >= 0.5 && kt < 0.5)] {
            if v > 0.0 && v < 1.0 {
                left_out.push(format!("{name} {v} ({})", if drawn { "drawn whole" } else { "not drawn" }));
            }
        }
        for (name, v) in [("diffuse_roughness", self.diffuse_roughness), ("Ksss", self.ksss)] {
            if v != 0.0 {
                left_out.push(format!("{name} {v}"));
            }
        }
        if emitted != Color::ZERO && !matches!(material, Material::Unlit { .. }) {
            left_out.push(format!("emission {} of colour {}", self.emission, fmt_color(self.emission_color)));
        }
        (material, simple_warning(shader, "standard", left_out, self.opacity, connected))
    }
}

/// Arnold's `utility` shader (a debugging shader: Arnold user guide, "Utility"), by
/// what tress's materials can draw of it: `shade_mode` `flat` is unlit of its colour,
/// `lambert` Lambert of it; `ndoteye` (Arnold's default, the colour dimmed by the facing
/// ratio, lit by no light) is drawn unlit, and `ambocc`, `plastic` and `metal` as Lambert,
/// each said. `color_mode` `color` (the default) is `color`; `prims`
/// a random colour per curve segment on strands
/// ([`super::arnold_graph::Pattern::Primitives`]) and their mean, 0.5 grey, on surfaces,
/// said; every other mode draws 0.5 grey, said.
#[derive(Clone, Debug, PartialEq)]
pub struct Utility {
    /// What colours the surface (`color`, `prims`, ...).
    pub color_mode: String,
    /// How it is shaded (`ndoteye`, `flat`, `lambert`, ...).
    pub shade_mode: String,
    /// The colour of `color_mode` `color`.
    pub color: Color,
    /// Opacity, not drawn.
    pub opacity: f32,
}

impl Default for Utility {
    fn default() -> Self {
        Utility { color_mode: "color".into(), shade_mode: "ndoteye".into(), color: Color::ONE, opacity: 1.0 }
    }
}

impl ArnoldShader for Utility {
    const MAPS: &'static [(&'static str, Slot)] = &[("color", Slot::Diffuse)];
    const NAMES: &'static [&'static str] = &["color_mode", "shade_mode", "color", "opacity"];

    fn param(&mut self, name: &str) -> Option<Param<'_>> {
        Some(match name {
            "color" => Param::Color(&mut self.color),
            "opacity" => Param::Float(&mut self.opacity),
            _ => return None,
        })
    }

    fn text(&mut self, name: &str) -> Option<&mut String> {
        match name {
            "color_mode" => Some(&mut self.color_mode),
            "shade_mode" => Some(&mut self.shade_mode),
            _ => None,
        }
    }

    fn material(&self, shader: &str, connected: &[String]) -> (Material, Option<String>) {
        let finite = |c: Color| Color::from_array(c.to_array().map(|x| if x.is_finite() { x.max(0.0) } else { 0.0 }));
        let mut left_out = Vec::new();
        // Colours tress cannot draw are tress's default surface grey, the mean of random
        // colours.
        let color = match self.color_mode.as_str() {
            "color" => finite(self.color),
            "prims" => {
                left_out.push("color_mode prims on surfaces (drawn 0.5 grey, their mean)".into());
                Material::DEFAULT_COLOR
            }
            other => {
                left_out.push(format!("color_mode {other} (drawn 0.5 grey)"));
                Material::DEFAULT_COLOR
            }
        };
        let material = match self.shade_mode.as_str() {
            "flat" => Material::Unlit { color },
            "lambert" => Material::Diffuse { color: color.min(Color::ONE) },
            // Lit by no light, as Arnold's: unlit, without the falloff.
            "ndoteye" => {
                left_out.push("shade_mode ndoteye (drawn flat, without the facing ratio)".to_string());
                Material::Unlit { color }
            }
            other => {
                left_out.push(format!("shade_mode {other} (drawn lambert)"));
                Material::Diffuse { color: color.min(Color::ONE) }
            }
        };
        let opacity = Color::splat(self.opacity);
        (material, simple_warning(shader, "utility", left_out, opacity, connected))
    }

    /// `color_mode prims` on strands: a random colour per curve segment.
    fn along(&mut self, varying: &mut Vec<(&'static str, Pattern)>) -> Option<Pattern> {
        if self.color_mode != "prims" {
            return super::arnold_graph::mapped(self, varying, &["color"]);
        }
        self.color_mode = "color".into();
        self.color = Color::ONE;
        varying.retain(|(n, _)| *n != "color");
        Some(Pattern::Primitives)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn material(s: StandardSurface) -> (Material, Option<String>) {
        s.material("s", &[])
    }

    #[test]
    fn the_default_is_a_grey_base_under_a_four_percent_coating() {
        // α = 0.2² = 0.04: exponent 2/α² − 2 = 1248; F0 of η 1.5 is 0.04.
        let (m, w) = material(StandardSurface::default());
        let Material::Phong { diffuse, specular, exponent } = m else { panic!("{m:?}") };
        assert_eq!(diffuse, Color::splat(0.8));
        assert!((specular - Color::splat(0.04)).abs().max_element() < 1e-6, "{specular}");
        assert!((exponent - 1248.0).abs() < 0.1, "{exponent}");
        assert_eq!(w, None);
        // No specular: plain Lambert of base × base_color.
        let red =
            StandardSurface { specular: 0.0, base: 0.5, base_color: Color::new(1.0, 0.2, 0.0), ..Default::default() };
        assert_eq!(material(red).0, Material::Diffuse { color: Color::new(0.5, 0.1, 0.0) });
    }

    #[test]
    fn metals_and_glass_take_the_dominant_layer() {
        let gold = Color::new(1.0, 0.8, 0.3);
        let metal = StandardSurface { metalness: 1.0, base: 1.0, base_color: gold, ..Default::default() };
        let Material::Phong { diffuse, specular, .. } = material(metal.clone()).0 else { panic!() };
        assert_eq!((diffuse, specular), (Color::ZERO, gold));
        let polished = StandardSurface { specular_roughness: 0.0, ..metal };
        assert_eq!(material(polished).0, Material::Mirror { color: gold });
        let glass =
            StandardSurface { transmission: 1.0, specular_ior: 1.33, specular_roughness: 0.0, ..Default::default() };
        assert_eq!(material(glass).0, Material::Glass { ior: 1.33, color: Color::ONE });
        // A half metal is drawn as a metal, said.
        let half = StandardSurface { metalness: 0.6, ..Default::default() };
        let (m, w) = material(half);
        assert!(matches!(m, Material::Phong { diffuse, .. } if diffuse == Color::ZERO));
        assert!(w.unwrap().contains("metalness 0.6 (drawn as a metal)"));
    }

    #[test]
    fn what_the_mapping_cannot_hold_is_said_once_naming_the_shader() {
        let s =
            StandardSurface { coat: 1.0, sheen: 0.5, emission: 2.0, opacity: Color::splat(0.5), ..Default::default() };
        let w = s.material("/Looks/car", &["base_color".into()]).1.unwrap();
        for part in ["/Looks/car:", "coat 1", "sheen 0.5", "emission 2", "opacity", "shading networks on base_color"] {
            assert!(w.contains(part), "{part}: {w}");
        }
        // Bad numbers are clamped, never a panic or a NaN material.
        let bad = StandardSurface {
            base: f32::NAN,
            specular_ior: f32::INFINITY,
            specular_roughness: -1.0,
            ..Default::default()
        };
        let Material::Phong { diffuse, exponent, .. } = material(bad).0 else { panic!() };
        assert!(diffuse == Color::ZERO && exponent.is_finite());
    }

    #[test]
    fn lambert_shaders_are_lambert_of_their_colour() {
        let (m, w) = Lambert::default().material("l", &[]);
        assert_eq!((m, w), (Material::Diffuse { color: Color::splat(0.7) }, None));
        let red = Lambert { kd: 0.5, kd_color: Color::new(1.0, 0.4, 0.0), ..Default::default() };
        assert_eq!(red.material("l", &[]).0, Material::Diffuse { color: Color::new(0.5, 0.2, 0.0) });
        let bad = Lambert { kd: f32::NAN, ..Default::default() };
        assert_eq!(bad.material("l", &[]).0, Material::Diffuse { color: Color::ZERO });
    }

    #[test]
    fn flat_shaders_are_unlit_of_their_colour() {
        // Nothing left out: no warning.
        let (m, w) = Flat { color: Color::new(0.2, 0.4, 0.6), ..Default::default() }.material("f", &[]);
        assert_eq!((m, w), (Material::Unlit { color: Color::new(0.2, 0.4, 0.6) }, None));
        // What is not evaluated (opacity, a network on the colour) is said, naming the shader.
        let green = Flat { color: Color::new(0.0, 1.0, 0.0), opacity: Color::splat(0.5) };
        let (m, w) = green.material("/materials/flat0", &["color".into()]);
        assert_eq!(m, Material::Unlit { color: Color::new(0.0, 1.0, 0.0) });
        let w = w.unwrap();
        for part in ["/materials/flat0: Arnold flat", "opacity", "shading networks on color"] {
            assert!(w.contains(part), "{part}: {w}");
        }
        assert!(!w.contains("lit"), "{w}");
        // A radiance above 1 is kept; bad components are 0, never a NaN or infinite material.
        let hot = Flat { color: Color::new(5.0, f32::INFINITY, -1.0), ..Default::default() };
        assert_eq!(hot.material("f", &[]).0, Material::Unlit { color: Color::new(5.0, 0.0, 0.0) });
        let nan = Flat { color: Color::new(f32::NAN, 0.5, 0.5), ..Default::default() };
        assert_eq!(nan.material("f", &[]).0, Material::Unlit { color: Color::new(0.0, 0.5, 0.5) });
    }

    #[test]
    fn legacy_standard_shaders_are_lambert_phong_mirror_or_glass() {
        let (m, w) = Standard::default().material("s", &[]);
        assert_eq!((m, w), (Material::Diffuse { color: Color::splat(0.7) }, None));
        let shiny = Standard { kd: 1.0, kd_color: Color::new(1.0, 0.5, 0.0), ks: 0.5, ..Default::default() };
        let Material::Phong { diffuse, specular, exponent } = shiny.material("s", &[]).0 else { panic!() };
        assert_eq!((diffuse, specular), (Color::new(1.0, 0.5, 0.0), Color::splat(0.5)));
        assert!(exponent > 1.0 && exponent.is_finite());
        let mirror = Standard { kr: 0.75, ..Default::default() };
        let (m, w) = mirror.material("/m", &[]);
        assert_eq!(m, Material::Mirror { color: Color::splat(0.75) });
        assert!(w.unwrap().contains("Kr 0.75 (drawn whole)"));
        let glass = Standard { kt: 1.0, ior: 1.4, ..Default::default() };
        assert_eq!(glass.material("g", &[]).0, Material::Glass { ior: 1.4, color: Color::ONE });
        let glow = Standard { kd: 0.0, emission: 2.0, ..Default::default() };
        assert_eq!(glow.material("e", &[]).0, Material::Unlit { color: Color::ONE });
    }

    #[test]
    fn utility_shaders_are_unlit_or_lambert_of_their_colour() {
        let red = Color::new(1.0, 0.0, 0.0);
        let flat = Utility { shade_mode: "flat".into(), color: red, ..Default::default() };
        assert_eq!(flat.material("u", &[]), (Material::Unlit { color: red }, None));
        let lit = Utility { shade_mode: "lambert".into(), color: red, ..Default::default() };
        assert_eq!(lit.material("u", &[]).0, Material::Diffuse { color: red });
        // Arnold's default, ndoteye, drawn flat; prims on a surface their mean: both said.
        let (m, w) = Utility { color_mode: "prims".into(), ..Default::default() }.material("u", &[]);
        assert_eq!(m, Material::Unlit { color: Color::splat(0.5) });
        let w = w.unwrap();
        assert!(w.contains("ndoteye") && w.contains("prims on surfaces"), "{w}");
        // On strands prims are random colours per segment, and no longer said.
        let mut on_strands = Utility { color_mode: "prims".into(), shade_mode: "flat".into(), ..Default::default() };
        assert_eq!(on_strands.along(&mut Vec::new()), Some(Pattern::Primitives));
        assert_eq!(on_strands.material("u", &[]), (Material::Unlit { color: Color::ONE }, None));
    }
}
