//! The scene description (what a scene file or the demo says) and the prepared world
//! (plain data the renderer reads). [`prepare`] turns one into the other: it loads the
//! files a description names, applies transforms and builds the acceleration structures.

mod estimate;

pub use estimate::{estimate_memory, parse_memory_size, MemoryEstimate};

use crate::accel::{Accel, Shape};
use crate::camera::{Camera, CameraError};
use crate::geometry::{StrandSet, TriangleMesh};
use crate::io::{self, LoadError};
use crate::light::Light;
use crate::math::Color;
use crate::shading::Material;
use glam::{Affine3A, Vec3};
use std::path::PathBuf;
use std::time::{Duration, Instant};

/// Camera placement.
#[derive(Clone, Debug, PartialEq)]
pub struct CameraDesc {
    /// Position of the eye.
    pub eye: Vec3,
    /// Point looked at.
    pub target: Vec3,
    /// Up direction.
    pub up: Vec3,
    /// Vertical field of view in degrees.
    pub vfov: f32,
}

/// How to render.
#[derive(Clone, Debug, PartialEq)]
pub struct RenderSettings {
    /// Image width in pixels.
    pub width: u32,
    /// Image height in pixels.
    pub height: u32,
    /// Camera samples per pixel.
    pub spp: u32,
    /// Seed of every random decision of the render.
    pub seed: u32,
    /// Maximum number of specular bounces (mirror, glass) after the camera ray.
    pub max_depth: u32,
    /// Worker threads; 0 uses every core.
    pub threads: usize,
}

impl Default for RenderSettings {
    fn default() -> Self {
        RenderSettings { width: 640, height: 480, spp: 16, seed: 0, max_depth: 5, threads: 0 }
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
    pub material: Material,
    /// Object-to-world transform.
    pub transform: Affine3A,
}

/// A strand set in the scene.
#[derive(Clone, Debug, PartialEq)]
pub struct HairEntry {
    /// Its geometry.
    pub source: HairSource,
    /// Its material.
    pub material: Material,
    /// Object-to-world transform.
    pub transform: Affine3A,
    /// Factor on every strand radius.
    pub radius_scale: f32,
    /// Use per-point colours from the file, when it has them, instead of the material colour.
    pub file_colors: bool,
}

/// Everything a scene says, before any file is read.
#[derive(Clone, Debug, PartialEq)]
pub struct Description {
    /// Camera placement.
    pub camera: CameraDesc,
    /// Render settings.
    pub settings: RenderSettings,
    /// Lights.
    pub lights: Vec<Light>,
    /// Meshes.
    pub meshes: Vec<MeshEntry>,
    /// Strand sets.
    pub hair: Vec<HairEntry>,
}

/// The prepared scene: geometry with its BVHs, materials, lights and camera.
#[derive(Debug)]
pub struct World {
    /// The camera.
    pub camera: Camera,
    /// Render settings.
    pub settings: RenderSettings,
    /// Lights.
    pub lights: Vec<Light>,
    /// Materials, indexed by the objects.
    pub materials: Vec<Material>,
    /// Objects and their BVHs.
    pub accel: Accel,
    /// Sum of the environment lights' radiance (what unblocked rays see).
    pub background: Color,
    /// What was skipped while preparing (strands or triangles with unusable numbers).
    pub warnings: Vec<String>,
}

/// Why a description cannot be prepared.
#[derive(Debug, thiserror::Error)]
pub enum PrepareError {
    /// A geometry file could not be loaded.
    #[error(transparent)]
    Load(#[from] LoadError),
    /// The camera is ill-defined.
    #[error("camera: {0}")]
    Camera(#[from] CameraError),
    /// A setting is out of range.
    #[error("{0}")]
    Invalid(String),
}

/// How long preparing took, by stage.
#[derive(Clone, Copy, Debug, Default)]
pub struct PrepareTimes {
    /// Reading and transforming geometry.
    pub load: Duration,
    /// Building the BVHs.
    pub build: Duration,
}

impl Description {
    /// Checks settings and lights for values no render can use.
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
        if s.max_depth > 64 {
            return Err(PrepareError::Invalid(format!("max_depth {} is out of range (0 to 64)", s.max_depth)));
        }
        for h in &self.hair {
            if !(h.radius_scale.is_finite() && h.radius_scale >= 0.0) {
                return Err(PrepareError::Invalid(format!(
                    "hair radius_scale {} must be finite and >= 0",
                    h.radius_scale
                )));
            }
        }
        Ok(())
    }
}

/// The geometry of a description, loaded and in world space, with one material per shape.
pub struct LoadedGeometry {
    /// Shapes with the index of their material.
    pub shapes: Vec<(Shape, u32)>,
    /// Materials, indexed by the shapes.
    pub materials: Vec<Material>,
    /// What was skipped: strands or triangles whose numbers are not finite once
    /// transformed (enormous coordinates scaled past the float range, NaN from a generator).
    pub warnings: Vec<String>,
}

/// Loads every mesh and strand set a description names and applies its transform.
pub fn load_geometry(desc: &Description) -> Result<LoadedGeometry, PrepareError> {
    let mut materials = Vec::new();
    let mut shapes = Vec::new();
    let mut warnings = Vec::new();
    for (i, m) in desc.meshes.iter().enumerate() {
        let mut mesh = match &m.source {
            MeshSource::File(path) => io::read_mesh(path)?,
            MeshSource::Inline(mesh) => mesh.clone(),
        };
        mesh.transform(&m.transform);
        let dropped = mesh.remove_unusable_triangles();
        if dropped > 0 {
            warnings.push(format!(
                "mesh {}: skipped {dropped} triangles with corners not finite or beyond ±{:e}",
                i + 1,
                crate::geometry::MAX_COORDINATE
            ));
        }
        shapes.push((Shape::Mesh(mesh), materials.len() as u32));
        materials.push(m.material.clone());
    }
    for (i, h) in desc.hair.iter().enumerate() {
        let mut strands = match &h.source {
            HairSource::File(path) => io::hair::read_hair(path)?,
            HairSource::Inline(s) => s.clone(),
        };
        strands.transform(&h.transform);
        if h.radius_scale != 1.0 {
            strands.points.iter_mut().for_each(|p| p[3] *= h.radius_scale);
        }
        if !h.file_colors {
            strands.colors = None;
        }
        let dropped = strands.remove_unusable_strands();
        if dropped > 0 {
            warnings.push(format!(
                "hair {}: skipped {dropped} strands with coordinates or radii negative, not finite or beyond ±{:e}",
                i + 1,
                crate::geometry::MAX_COORDINATE
            ));
        }
        shapes.push((Shape::Strands(strands), materials.len() as u32));
        materials.push(h.material.clone());
    }
    Ok(LoadedGeometry { shapes, materials, warnings })
}

/// Loads geometry, applies transforms and builds the BVHs.
pub fn prepare(desc: &Description) -> Result<(World, PrepareTimes), PrepareError> {
    desc.validate()?;
    let c = &desc.camera;
    let camera = Camera::new(c.eye, c.target, c.up, c.vfov, desc.settings.width, desc.settings.height)?;
    let start = Instant::now();
    let LoadedGeometry { shapes, materials, warnings } = load_geometry(desc)?;
    let load = start.elapsed();
    let start = Instant::now();
    let accel = Accel::build(shapes);
    let build = start.elapsed();
    let background = desc.lights.iter().map(Light::background).sum();
    let world = World {
        camera,
        settings: desc.settings.clone(),
        lights: desc.lights.clone(),
        materials,
        accel,
        background,
        warnings,
    };
    Ok((world, PrepareTimes { load, build }))
}
