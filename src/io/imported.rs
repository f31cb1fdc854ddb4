//! Scenes read from other tools' files (Maya ASCII, pbrt-v4, USD text; read by
//! [`super::read_imported`]), in tress's terms:
//! an [`Imported`] holds the camera, settings, lights and entries a file describes, with
//! every geometry already in memory, ready to become a [`Description`] of its own
//! (`tress render scene.ma`) or to join a TOML scene (`[[import]]`).

use crate::geometry::StrandSet;
use crate::light::Light;
use crate::math::Aabb;
use crate::scene::{
    CameraDesc, Description, FurEntry, GuideSource, HairEntry, HairSource, HairSystemEntry, MeshEntry, MeshSource,
    DEFAULT_SKY_RADIANCE,
};
use crate::world::RenderSettings;
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
    /// Maximum specular depth, if the file gives one.
    pub max_depth: Option<u32>,
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

impl Imported {
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
fn framing_camera(b: &Aabb) -> CameraDesc {
    let vfov = 35.0f32;
    let (center, radius) = match b.is_empty() {
        true => (Vec3::ZERO, 1.0),
        false => (Vec3::from(b.center()), (0.5 * Vec3::from(b.max - b.min).length()).max(1e-3)),
    };
    let distance = 1.15 * radius / (0.5 * vfov.to_radians()).sin();
    let eye = center + Vec3::new(0.0, 0.3, 1.0).normalize() * distance;
    CameraDesc { eye, target: center, up: Vec3::Y, vfov }
}

/// `l` moved by `m` (directions keep unit length; radii and intensities stay).
fn transform_light(l: &Light, m: &Affine3A) -> Light {
    let dir = |d: Vec3| m.transform_vector3(d).normalize_or(d);
    match *l {
        Light::Distant { direction, irradiance } => Light::Distant { direction: dir(direction), irradiance },
        Light::Sun { direction, radiance, cos_max } => Light::Sun { direction: dir(direction), radiance, cos_max },
        Light::Point { position, intensity } => Light::Point { position: m.transform_point3(position), intensity },
        Light::Spot { position, direction, intensity, cos_inner, cos_outer } => Light::Spot {
            position: m.transform_point3(position),
            direction: dir(direction),
            intensity,
            cos_inner,
            cos_outer,
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
        // Infinitely far: only the transform's rotation turns it.
        Light::EnvironmentMap(ref map) => {
            Light::EnvironmentMap(map.rotated(glam::Mat3::from_quat(m.to_scale_rotation_translation().1)))
        }
    }
}
