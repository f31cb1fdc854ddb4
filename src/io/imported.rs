//! Scenes read from other tools' files (Maya ASCII, pbrt-v4, USD text; read by
//! [`super::read_imported`]), in tress's terms:
//! an [`Imported`] holds the camera and settings a file gives and its [`Contents`] (lights
//! and entries, every geometry already in memory), ready to become a [`Description`] of
//! its own (`tress render scene.ma`) or to join a TOML scene (`[[import]]`, whose contents
//! it is appended to).

use crate::geometry::{StrandSet, TriangleMesh};
use crate::light::Light;
use crate::math::Aabb;
use crate::scene::{
    CameraDesc, Contents, Description, HairEntry, HairSource, MeshEntry, MeshSource, DEFAULT_SKY_RADIANCE,
};
use crate::shading::hair_bsdf::{Absorption, HairParams, PhysicalHair};
use crate::shading::Material;
use crate::world::{Integrator, RenderSettings};
use glam::{Affine3A, Vec3};

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
    /// The largest colour channel of a camera sample (tress's `max_sample_value`), if the
    /// file gives one.
    pub max_sample_value: Option<f32>,
    /// Lights (in world space) and entries, with their geometry inline; fur's `mesh`
    /// indexes its meshes (see [`super::maya_ascii::fur_nodes`]).
    pub contents: Contents,
    /// What was read only in part or skipped, one line each, for the user.
    pub warnings: Vec<String>,
    /// The file's renderer lights a scene only by its own lights (Arnold): without any, it
    /// renders black, not with tress's default light and sky.
    pub no_default_light: bool,
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
        material: material.into(),
        transform: Affine3A::IDENTITY,
        radius_scale: 1.0,
        file_colors: true,
        lod: None,
        visibility: Default::default(),
    };
    Imported { contents: Contents { hair: vec![hair], ..Contents::default() }, ..Imported::default() }
}

/// A scene of one mesh, diffuse grey.
pub fn raw_mesh(mesh: TriangleMesh) -> Imported {
    let material = Material::Diffuse { color: Vec3::splat(0.5) };
    let mesh = MeshEntry {
        source: MeshSource::Inline(mesh),
        material: material.into(),
        transform: Affine3A::IDENTITY,
        visibility: Default::default(),
    };
    Imported { contents: Contents { meshes: vec![mesh], ..Contents::default() }, ..Imported::default() }
}

impl Imported {
    /// Gives the strand sets whose points all have radius 0 (their file gives no widths)
    /// [`RELATIVE_WIDTH`] of the scene's size, with one warning.
    pub fn give_widths(&mut self) {
        let widthless =
            |e: &HairEntry| matches!(&e.source, HairSource::Inline(s) if s.points.iter().all(|p| p[3] == 0.0));
        let count: usize = self
            .contents
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
        let width = relative_width(&self.contents.bounds());
        for e in self.contents.hair.iter_mut().filter(|e| widthless(e)) {
            if let HairSource::Inline(s) = &mut e.source {
                s.points.iter_mut().for_each(|p| p[3] = 0.5 * width);
            }
        }
        self.warnings.push(format!(
            "{count} strand(s) have no width: drawn {width:.3e} wide ({RELATIVE_WIDTH} of the scene's size; \
             set one with --hair-width or `width`)"
        ));
    }

    /// Applies `m` on top of every entry's, light's and the camera's own transform (a TOML
    /// `[[import]]`'s `transform`).
    pub fn transform(&mut self, m: &Affine3A) {
        self.contents.transform(m);
        if let Some(c) = &mut self.camera {
            // The clip distances are along the view: they stretch with it.
            let stretch = m.transform_vector3((c.target - c.eye).normalize_or(Vec3::NEG_Z)).length();
            c.clip = c.clip.map(|d| d * stretch);
            c.eye = m.transform_point3(c.eye);
            c.target = m.transform_point3(c.target);
            c.up = m.transform_vector3(c.up).normalize_or(Vec3::Y);
        }
    }

    /// A scene of its own: the file's camera (or one framing the geometry from the front,
    /// slightly above, when it has none), its settings over tress's defaults, and its
    /// lights (or, as Maya renders a scene without lights, one distant light from the
    /// camera and a dim sky; none when [`Imported::no_default_light`]). Returns the
    /// warnings too, with those this adds.
    pub fn into_description(mut self) -> (Description, Vec<String>) {
        let mut settings = RenderSettings::default();
        if let Some([w, h]) = self.resolution {
            (settings.width, settings.height) = (w, h);
        }
        settings.spp = self.spp.unwrap_or(settings.spp);
        settings.max_depth = self.max_depth.unwrap_or(settings.max_depth);
        settings.integrator = self.integrator.unwrap_or(settings.integrator);
        settings.max_sample_value = self.max_sample_value.unwrap_or(settings.max_sample_value);
        let camera = match self.camera.take() {
            Some(c) => c,
            None => {
                self.warnings.push("the file has no camera: framing the geometry from the front".into());
                framing_camera(&self.contents.bounds())
            }
        };
        if self.contents.lights.is_empty() && self.no_default_light {
            self.warnings.push("the file has no lights: black, as its renderer draws it".into());
        } else if self.contents.lights.is_empty() {
            self.warnings.push("the file has no lights: lighting with a default light from the camera".into());
            let direction = (camera.eye - camera.target + camera.up * 0.5 * (camera.eye - camera.target).length())
                .normalize_or(Vec3::Y);
            self.contents
                .lights
                .push(Light::Distant { direction, irradiance: Vec3::splat(std::f32::consts::PI) }.into());
            self.contents.lights.push(
                Light::Environment { radiance: Vec3::splat(DEFAULT_SKY_RADIANCE), camera_visibility: 1.0 }.into(),
            );
        }
        (Description { camera, settings, contents: self.contents }, self.warnings)
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
