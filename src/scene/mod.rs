//! The scene description: what a scene file, an importer or the demo says, before any
//! file is read. Entries name their geometry, environment maps and textures by path or
//! carry them inline; [`crate::prepare`] loads them into a [`crate::world::World`].

mod contents;
mod images;

pub use contents::Contents;
pub use images::{EnvironmentFile, LightSource, MaterialSource, Projection, RoughnessSource, TexturedFiles};

use crate::accel::lod::LodParams;
pub use crate::accel::Visibility;
use crate::error::PrepareError;
use crate::geometry::{StrandSet, TriangleMesh};
use crate::hair_system::{FollicleParams, Guides, HairColors, HairSystem};
use crate::world::RenderSettings;
use glam::{Affine3A, Vec2, Vec3};
use std::path::PathBuf;

/// Radiance of the uniform sky lighting a scene that brings no environment of its own
/// (the demo, an imported scene without lights), so shadowed sides are not black.
pub const DEFAULT_SKY_RADIANCE: f32 = 0.15;

/// Camera placement.
#[derive(Clone, Debug, PartialEq)]
pub struct CameraDesc {
    /// Position of the eye.
    pub eye: Vec3,
    /// Point looked at.
    pub target: Vec3,
    /// Up direction.
    pub up: Vec3,
    /// Vertical field of view in degrees of a perspective camera; a [`Film`] overrides it.
    pub vfov: f32,
    /// Perspective (a pinhole) or orthographic (parallel rays).
    pub projection: CameraProjection,
    /// The film back of a camera read from a file with one (USD, Maya): the field of view
    /// is fitted from it to the aspect of the image finally rendered, so an image size given
    /// later (`-r`) refits it as the source application would.
    pub film: Option<Film>,
    /// Near and far clipping distances, measured along the view direction (Blender's Clip
    /// Start and End, Maya's near and far clip planes): nothing nearer or farther is seen.
    /// `[0, inf]` clips nothing.
    pub clip: [f32; 2],
    /// The part of the screen the image sees, lower-left and upper-right corners, in screen
    /// coordinates where −1..1 spans the whole field of view (or orthographic window) on
    /// each axis: [`FULL_SCREEN`] sees it all; an off-centre window shifts the view as a
    /// shifted lens does (Arnold's `screen_window_min`/`max`, USD's aperture offsets).
    pub window: [Vec2; 2],
}

/// The whole screen, as [`CameraDesc::window`].
pub const FULL_SCREEN: [Vec2; 2] = [Vec2::NEG_ONE, Vec2::ONE];

impl Default for CameraDesc {
    /// Looking at the origin from 5 units along +z, y up, 35 degrees.
    fn default() -> Self {
        CameraDesc {
            eye: Vec3::new(0.0, 0.0, 5.0),
            target: Vec3::ZERO,
            up: Vec3::Y,
            vfov: 35.0,
            projection: CameraProjection::Perspective,
            film: None,
            clip: [0.0, f32::INFINITY],
            window: FULL_SCREEN,
        }
    }
}

impl CameraDesc {
    /// The vertical field of view in degrees for a `width` x `height` image: the film's
    /// fit when there is one, else `vfov`. Perspective cameras only.
    pub fn vfov_for(&self, width: u32, height: u32) -> f32 {
        self.film.map_or(self.vfov, |f| f.vfov(width, height))
    }

    /// The height in scene units of an orthographic camera's window for a `width` x
    /// `height` image: the film's fit when there is one (its apertures are then lengths in
    /// scene units), else the projection's `height`; `None` for a perspective camera.
    pub fn ortho_height_for(&self, width: u32, height: u32) -> Option<f32> {
        match self.projection {
            CameraProjection::Perspective => None,
            CameraProjection::Orthographic { height: h } => {
                Some(self.film.map_or(h, |f| f.fitted_height(width, height)))
            }
        }
    }
}

/// How a camera projects the scene.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub enum CameraProjection {
    /// A pinhole: rays fan out from the eye over `vfov` (or the film's angle of view).
    #[default]
    Perspective,
    /// Parallel rays along the view direction, from a window centred on the eye `height`
    /// scene units tall (its width follows the image aspect). A [`Film`] overrides the
    /// height; its apertures are then the window's sides in scene units.
    Orthographic {
        /// The window's height in scene units.
        height: f32,
    },
}

/// Which side of a film aperture meets the image edge when the two aspects differ (Maya's
/// Film Fit; Arnold's USD reader always fits the horizontal aperture, as Arnold's
/// `persp_camera` `fov` is horizontal).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FilmFit {
    /// The horizontal aperture spans the image width.
    Horizontal,
    /// The vertical aperture spans the image height.
    Vertical,
    /// The film fills the image: the side that fits with the film's other side cropped.
    Fill,
    /// The whole film is seen: the side that fits with the image extending past the other.
    Overscan,
}

/// A camera's film back: its apertures over its focal length (for an orthographic camera,
/// its window's sides in scene units), and how it fits the image.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Film {
    /// Horizontal and vertical aperture, each divided by the focal length (same unit), so
    /// half of each is the tangent of that side's half angle; an orthographic camera's in
    /// scene units. Finite and positive.
    pub aperture: [f32; 2],
    /// How the aperture is fitted to the image's aspect.
    pub fit: FilmFit,
}

impl Film {
    /// The vertical field of view in degrees for a `width` x `height` image (Maya's film
    /// fit, Autodesk Maya Help "Camera Attribute Editor: Film Back"; `2 atan(aperture / 2)`
    /// on the side that fits, the other side following the image aspect).
    pub fn vfov(&self, width: u32, height: u32) -> f32 {
        2.0 * (0.5 * self.fitted_height(width, height)).atan().to_degrees()
    }

    /// The vertical aperture fitted to a `width` x `height` image: the vertical aperture
    /// when that side fits, else the horizontal one over the image aspect. In the
    /// apertures' unit: over the focal length for a perspective camera, scene units for an
    /// orthographic one.
    pub fn fitted_height(&self, width: u32, height: u32) -> f32 {
        let [h, v] = self.aperture;
        let image_aspect = width.max(1) as f32 / height.max(1) as f32;
        let horizontal = match self.fit {
            FilmFit::Horizontal => true,
            FilmFit::Vertical => false,
            FilmFit::Fill => image_aspect > h / v,
            FilmFit::Overscan => image_aspect < h / v,
        };
        if horizontal {
            h / image_aspect
        } else {
            v
        }
    }
}

/// Where a mesh comes from.
#[derive(Clone, Debug, PartialEq)]
pub enum MeshSource {
    /// An OBJ or PLY file.
    File(PathBuf),
    /// Geometry already in memory (procedural shapes, tests).
    Inline(TriangleMesh),
}

/// Where a strand set comes from.
#[derive(Clone, Debug, PartialEq)]
pub enum HairSource {
    /// A Cem Yuksel `.hair` file.
    File(PathBuf),
    /// Strands already in memory.
    Inline(StrandSet),
}

/// A mesh in the scene.
#[derive(Clone, Debug, PartialEq)]
pub struct MeshEntry {
    /// Its geometry.
    pub source: MeshSource,
    /// Its material.
    pub material: MaterialSource,
    /// Object-to-world transform.
    pub transform: Affine3A,
    /// Which rays see it, and whether it is a holdout.
    pub visibility: Visibility,
}

/// A strand set in the scene.
#[derive(Clone, Debug, PartialEq)]
pub struct HairEntry {
    /// Its geometry.
    pub source: HairSource,
    /// Its material.
    pub material: MaterialSource,
    /// Object-to-world transform.
    pub transform: Affine3A,
    /// Factor on every strand radius.
    pub radius_scale: f32,
    /// Use per-point colours from the file, when it has them, instead of the material colour.
    pub file_colors: bool,
    /// Level of detail (stochastic pruning), when wanted.
    pub lod: Option<LodParams>,
    /// Which rays see it, and whether it is a holdout.
    pub visibility: Visibility,
}

/// Where a hair system's guide curves come from.
#[derive(Clone, Debug, PartialEq)]
pub enum GuideSource {
    /// A Cem Yuksel `.hair` file: one guide per strand.
    File(PathBuf),
    /// Follicles grown on the description's mesh number `mesh` (0-based), in world space.
    Follicles {
        /// Index into [`Contents::meshes`].
        mesh: usize,
        /// Placement, points per hair, length.
        params: FollicleParams,
    },
    /// Guides already in memory.
    Inline(Guides),
}

/// A Maya-style hair system in the scene: guides expanded into clumps of render hairs.
#[derive(Clone, Debug, PartialEq)]
pub struct HairSystemEntry {
    /// The guides.
    pub guides: GuideSource,
    /// The hair-system attributes.
    pub system: HairSystem,
    /// The render hairs' material.
    pub material: MaterialSource,
    /// Where per-point colours come from.
    pub colors: HairColors,
    /// Object-to-world transform of file or inline guides (follicles are already in
    /// world space), applied before expansion so widths are in world units.
    pub transform: Affine3A,
    /// Seed of follicle placement and of every per-hair random choice.
    pub seed: u32,
    /// Level of detail (stochastic pruning), when wanted.
    pub lod: Option<LodParams>,
    /// Which rays see it, and whether it is a holdout.
    pub visibility: Visibility,
}

/// Fur grown on one of the scene's meshes (Maya Fur, [`crate::fur`]).
#[derive(Clone, Debug, PartialEq)]
pub struct FurEntry {
    /// Index of the mesh it grows on, into [`Contents::meshes`]; it grows on the mesh
    /// as placed in the world (after the mesh's transform).
    pub mesh: usize,
    /// The fur description (a preset with overrides).
    pub description: crate::fur::FurDescription,
    /// Root placement by area or by UV area.
    pub placement: crate::fur::Placement,
    /// Seed of every random decision of the fur.
    pub seed: u32,
    /// Guide curves (world space) that attract the fur, and how.
    pub guides: Option<(HairSource, crate::fur::Attractors)>,
    /// Level of detail (stochastic pruning), when wanted.
    pub lod: Option<LodParams>,
    /// Which of the mesh's triangles grow fur (one flag each); all when `None`. Readers
    /// set it for growth limited to some faces (an XGen patch's face list).
    pub grows_on: Option<Vec<bool>>,
    /// A width multiplier along the hair, root to tip ([`crate::fur::GrowOptions`]);
    /// readers set it for a width profile Maya Fur has no attribute for (XGen's taper
    /// and width ramp).
    pub width_profile: Option<Vec<f32>>,
    /// Which rays see it, and whether it is a holdout.
    pub visibility: Visibility,
}

/// Everything a scene says, before any file is read. The default is an empty scene seen
/// by [`CameraDesc::default`].
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Description {
    /// Camera placement.
    pub camera: CameraDesc,
    /// Render settings.
    pub settings: RenderSettings,
    /// Lights and entries.
    pub contents: Contents,
}

impl Description {
    /// Checks settings, lights and entries for values no render can use.
    pub fn validate(&self) -> Result<(), PrepareError> {
        let s = &self.settings;
        if s.width == 0 || s.height == 0 || s.width > 65_536 || s.height > 65_536 {
            return Err(PrepareError::Invalid(format!(
                "resolution {}x{} is out of range (1 to 65536 a side)",
                s.width, s.height
            )));
        }
        if s.spp == 0 || s.spp > 1 << 20 {
            return Err(PrepareError::Invalid(format!("spp {} is out of range (1 to 1048576)", s.spp)));
        }
        if s.transparency_layers == 0 || s.transparency_layers > 64 {
            return Err(PrepareError::Invalid(format!(
                "transparency_layers {} is out of range (1 to 64)",
                s.transparency_layers
            )));
        }
        if s.gather_rays == 0 || s.gather_rays > 4096 {
            return Err(PrepareError::Invalid(format!("gather_rays {} is out of range (1 to 4096)", s.gather_rays)));
        }
        if let Some(c) = s.irradiance_cache {
            if !(c.accuracy.is_finite() && c.accuracy > 0.0 && c.accuracy <= 1.0) {
                return Err(PrepareError::Invalid(format!(
                    "irradiance cache accuracy {} is out of range (above 0, at most 1)",
                    c.accuracy
                )));
            }
            if c.spacing == 0 || c.spacing > 256 {
                return Err(PrepareError::Invalid(format!(
                    "irradiance cache spacing {} is out of range (1 to 256 pixels)",
                    c.spacing
                )));
            }
            if c.rays < 8 || c.rays > 65_536 {
                return Err(PrepareError::Invalid(format!(
                    "irradiance cache rays {} is out of range (8 to 65536)",
                    c.rays
                )));
            }
        }
        if let Some(a) = s.adaptive {
            if a.min_spp == 0 || a.min_spp > a.max_spp || a.max_spp > 1 << 20 {
                return Err(PrepareError::Invalid(format!(
                    "adaptive sampling needs 1 <= min_spp <= max_spp <= 1048576 (got {} and {})",
                    a.min_spp, a.max_spp
                )));
            }
            if !(a.threshold.is_finite() && a.threshold >= 0.0) {
                return Err(PrepareError::Invalid(format!(
                    "adaptive threshold {} must be finite and >= 0",
                    a.threshold
                )));
            }
        }
        if s.max_depth > 64 {
            return Err(PrepareError::Invalid(format!("max_depth {} is out of range (0 to 64)", s.max_depth)));
        }
        let r = s.indirect_hair_roughness;
        if !(0.0..=1.0).contains(&r) {
            return Err(PrepareError::Invalid(format!("indirect_hair_roughness {r} is out of range (0 to 1)")));
        }
        if s.max_sample_value.is_nan() || s.max_sample_value <= 0.0 {
            return Err(PrepareError::Invalid(format!("max_sample_value {} must be positive", s.max_sample_value)));
        }
        self.contents.validate()
    }
}
