//! Scenes read from other tools' files (Maya ASCII, pbrt-v4, USD text; read by
//! [`super::read_imported`]), in tress's terms:
//! an [`Imported`] holds the camera, settings, lights and entries a file describes, with
//! every geometry already in memory, ready to become a [`Description`] of its own
//! (`tress render scene.ma`) or to join a TOML scene (`[[import]]`).

use crate::geometry::{StrandSet, TriangleMesh};
use crate::light::Light;
use crate::math::Aabb;
use crate::scene::{
    CameraDesc, Description, FurEntry, GuideSource, HairEntry, HairSource, HairSystemEntry, MeshEntry, MeshSource,
    DEFAULT_SKY_RADIANCE,
};
use crate::shading::hair_bsdf::{Absorption, HairParams, PhysicalHair};
use crate::shading::Material;
use crate::world::{Integrator, RenderSettings};
use glam::{Affine3A, Vec3, Vec3A};

/// What a foreign scene file describes.
#[derive(Clone, Debug, Default)]
pub struct Imported {
    /// The file's camera, if it has one.
    pub camera: Option<CameraDesc>,
    /// Image size `[width, height]`, if the file gives one.
    pub resolution: Option<[u32; 2]>,
    /// Samples per pixel, if the file gives them.
    pub spp: Option<u32>,
    /// Maximum depth (tress's `max_depth`), if the file gives one.
    pub max_depth: Option<u32>,
    /// The integrator the file's renderer would use, if it says.
    pub integrator: Option<Integrator>,
    /// Lights, in world space.
    pub lights: Vec<Light>,
    /// Meshes (inline geometry).
    pub meshes: Vec<MeshEntry>,
    /// Strand sets (inline geometry).
    pub hair: Vec<HairEntry>,
    /// Hair systems (inline guides).
    pub hair_systems: Vec<HairSystemEntry>,
    /// Fur; `mesh` indexes [`Imported::meshes`] (see [`super::maya_ascii::fur_nodes`]).
    pub fur: Vec<FurEntry>,
    /// What was read only in part or skipped, one line each, for the user.
    pub warnings: Vec<String>,
}

/// Fraction of a scene's size (its bounding box's diagonal) that strands whose file gives
/// no width are drawn wide: a head of hair 25 cm across gets 0.25 mm.
pub const RELATIVE_WIDTH: f32 = 1e-3;

/// The width of strands without one in a scene of bounds `b` ([`RELATIVE_WIDTH`] of its
/// diagonal; 1e-3 for an empty or degenerate scene).
pub fn relative_width(b: &Aabb) -> f32 {
    let diagonal = if b.is_empty() { 0.0 } else { Vec3::from(b.max - b.min).length() };
    match diagonal.is_finite() && diagonal > 0.0 {
        true => RELATIVE_WIDTH * diagonal,
        false => RELATIVE_WIDTH,
    }
}

/// A scene of one strand set: the physical hair material, coloured by the strands' own
/// colours when they have them (pbrt's default brown otherwise).
pub fn raw_strands(strands: StrandSet) -> Imported {
    let absorption = match strands.colors {
        Some(_) => Absorption::FromStrands,
        None => HairParams::default().absorption,
    };
    let material = Material::Physical(PhysicalHair::new(HairParams { absorption, ..HairParams::default() }));
    let hair = HairEntry {
        source: HairSource::Inline(strands),
        material,
        transform: Affine3A::IDENTITY,
        radius_scale: 1.0,
        file_colors: true,
        lod: None,
    };
    Imported { hair: vec![hair], ..Imported::default() }
}

/// A scene of one mesh, diffuse grey.
pub fn raw_mesh(mesh: TriangleMesh) -> Imported {
    let material = Material::Diffuse { color: Vec3::splat(0.5) };
    let mesh = MeshEntry { source: MeshSource::Inline(mesh), material, transform: Affine3A::IDENTITY };
    Imported { meshes: vec![mesh], ..Imported::default() }
}

impl Imported {
    /// Gives the strand sets whose points all have radius 0 (their file gives no widths)
    /// [`RELATIVE_WIDTH`] of the scene's size, with one warning.
    pub fn give_widths(&mut self) {
        let widthless =
            |e: &HairEntry| matches!(&e.source, HairSource::Inline(s) if s.points.iter().all(|p| p[3] == 0.0));
        let count: usize = self
            .hair
            .iter()
            .filter(|e| widthless(e))
            .map(|e| match &e.source {
                HairSource::Inline(s) => s.strand_count(),
                HairSource::File(_) => 0,
            })
            .sum();
        if count == 0 {
            return;
        }
        let width = relative_width(&self.bounds());
        for e in self.hair.iter_mut().filter(|e| widthless(e)) {
            if let HairSource::Inline(s) = &mut e.source {
                s.points.iter_mut().for_each(|p| p[3] = 0.5 * width);
            }
        }
        self.warnings.push(format!(
            "{count} strand(s) have no width: drawn {width:.3e} wide ({RELATIVE_WIDTH} of the scene's size; \
             set one with --hair-width or `width`)"
        ));
    }

    /// Draws every strand `width` wide: the strand sets' points, and the hairs of hair
    /// systems (their `hair_width`).
    pub fn set_hair_width(&mut self, width: f32) {
        for e in &mut self.hair {
            if let HairSource::Inline(s) = &mut e.source {
                s.points.iter_mut().for_each(|p| p[3] = 0.5 * width);
            }
            e.radius_scale = 1.0;
        }
        for e in &mut self.hair_systems {
            e.system.hair_width = width;
        }
    }

    /// Multiplies every strand's radius by `k` (strand sets and hair systems alike).
    pub fn scale_hair_radius(&mut self, k: f32) {
        for e in &mut self.hair {
            e.radius_scale *= k;
        }
        for e in &mut self.hair_systems {
            e.system.hair_width *= k;
        }
    }

    /// Applies `m` on top of every entry's and light's own transform (a TOML
    /// `[[import]]`'s `transform`).
    pub fn transform(&mut self, m: &Affine3A) {
        for e in &mut self.meshes {
            e.transform = *m * e.transform;
        }
        for e in &mut self.hair {
            e.transform = *m * e.transform;
        }
        for e in &mut self.hair_systems {
            e.transform = *m * e.transform;
        }
        for l in &mut self.lights {
            *l = transform_light(l, m);
        }
        if let Some(c) = &mut self.camera {
            // The clip distances are along the view: they stretch with it.
            let stretch = m.transform_vector3((c.target - c.eye).normalize_or(Vec3::NEG_Z)).length();
            c.clip = c.clip.map(|d| d * stretch);
            c.eye = m.transform_point3(c.eye);
            c.target = m.transform_point3(c.target);
            c.up = m.transform_vector3(c.up).normalize_or(Vec3::Y);
        }
    }

    /// The bounds of every mesh, strand set and hair-system guide, in world space (empty
    /// when there is no geometry).
    pub fn bounds(&self) -> Aabb {
        let mut b = Aabb::EMPTY;
        for e in &self.meshes {
            if let MeshSource::Inline(m) = &e.source {
                for p in &m.positions {
                    b = b.grow(Vec3A::from(e.transform.transform_point3(*p)));
                }
            }
        }
        let mut strands = |s: &StrandSet, t: &Affine3A| {
            for p in &s.points {
                b = b.grow(Vec3A::from(t.transform_point3(Vec3::new(p[0], p[1], p[2]))));
            }
        };
        for e in &self.hair {
            if let HairSource::Inline(s) = &e.source {
                strands(s, &e.transform);
            }
        }
        for e in &self.hair_systems {
            if let GuideSource::Inline(g) = &e.guides {
                strands(&g.curves, &e.transform);
            }
        }
        b
    }

    /// A scene of its own: the file's camera (or one framing the geometry from the front,
    /// slightly above, when it has none), its settings over tress's defaults, and its
    /// lights (or, as Maya renders a scene without lights, one distant light from the
    /// camera and a dim sky). Returns the warnings too, with those this adds.
    pub fn into_description(mut self) -> (Description, Vec<String>) {
        let mut settings = RenderSettings::default();
        if let Some([w, h]) = self.resolution {
            (settings.width, settings.height) = (w, h);
        }
        settings.spp = self.spp.unwrap_or(settings.spp);
        settings.max_depth = self.max_depth.unwrap_or(settings.max_depth);
        settings.integrator = self.integrator.unwrap_or(settings.integrator);
        let camera = match self.camera.take() {
            Some(c) => c,
            None => {
                self.warnings.push("the file has no camera: framing the geometry from the front".into());
                framing_camera(&self.bounds())
            }
        };
        if self.lights.is_empty() {
            self.warnings.push("the file has no lights: lighting with a default light from the camera".into());
            let direction = (camera.eye - camera.target + camera.up * 0.5 * (camera.eye - camera.target).length())
                .normalize_or(Vec3::Y);
            self.lights.push(Light::Distant { direction, irradiance: Vec3::splat(std::f32::consts::PI) });
            self.lights.push(Light::Environment { radiance: Vec3::splat(DEFAULT_SKY_RADIANCE) });
        }
        let desc = Description {
            camera,
            settings,
            lights: self.lights,
            meshes: self.meshes,
            hair: self.hair,
            hair_systems: self.hair_systems,
            fur: self.fur,
        };
        (desc, self.warnings)
    }
}

/// A camera looking at the centre of `b` along −z from far enough to see all of it.
pub fn framing_camera(b: &Aabb) -> CameraDesc {
    let vfov = 35.0f32;
    let (center, radius) = match b.is_empty() {
        true => (Vec3::ZERO, 1.0),
        false => (Vec3::from(b.center()), (0.5 * Vec3::from(b.max - b.min).length()).max(1e-3)),
    };
    let distance = 1.15 * radius / (0.5 * vfov.to_radians()).sin();
    let eye = center + Vec3::new(0.0, 0.3, 1.0).normalize() * distance;
    CameraDesc { eye, target: center, up: Vec3::Y, vfov, ..Default::default() }
}

/// `l` moved by `m` (directions keep unit length; radii and intensities stay).
/// The orthogonal part of an affine map's linear part: its rotation, times the reflection
/// when it mirrors (glam puts a mirror's sign on the x scale).
pub fn orthogonal_part(m: &Affine3A) -> glam::Mat3 {
    let (scale, rotation, _) = m.to_scale_rotation_translation();
    glam::Mat3::from_quat(rotation) * glam::Mat3::from_diagonal(scale.signum())
}

fn transform_light(l: &Light, m: &Affine3A) -> Light {
    let dir = |d: Vec3| m.transform_vector3(d).normalize_or(d);
    match *l {
        Light::Distant { direction, irradiance } => Light::Distant { direction: dir(direction), irradiance },
        Light::Sun { direction, radiance, cos_max } => Light::Sun { direction: dir(direction), radiance, cos_max },
        Light::Point { position, intensity, decay } => {
            Light::Point { position: m.transform_point3(position), intensity, decay }
        }
        Light::Spot { position, direction, intensity, cos_inner, cos_outer, decay } => Light::Spot {
            position: m.transform_point3(position),
            direction: dir(direction),
            intensity,
            cos_inner,
            cos_outer,
            decay,
        },
        Light::Quad { corner, edge_u, edge_v, radiance } => Light::Quad {
            corner: m.transform_point3(corner),
            edge_u: m.transform_vector3(edge_u),
            edge_v: m.transform_vector3(edge_v),
            radiance,
        },
        Light::Sphere { center, radius, radiance } => {
            Light::Sphere { center: m.transform_point3(center), radius, radiance }
        }
        Light::Environment { radiance } => Light::Environment { radiance },
        // Infinitely far: only the transform's orthogonal part turns it, its rotation and,
        // when the transform mirrors (its determinant is negative), that reflection.
        Light::EnvironmentMap(ref map) => Light::EnvironmentMap(map.rotated(orthogonal_part(m))),
    }
}
