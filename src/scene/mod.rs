//! The scene description (what a scene file or the demo says) and the prepared world
//! (plain data the renderer reads). [`prepare`] turns one into the other: it loads the
//! files a description names, applies transforms and builds the acceleration structures.

mod estimate;

pub use estimate::{estimate_memory, parse_memory_size, MemoryEstimate};

use crate::accel::lod::LodParams;
use crate::accel::{Accel, Shape};
use crate::camera::{Camera, CameraError};
use crate::geometry::{StrandSet, TriangleMesh};
use crate::hair_system::{self, FollicleParams, Guides, HairColors, HairSystem};
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
    /// Level of detail for the strand sets that ask for it; `false` renders every strand.
    pub lod: bool,
    /// How light is transported: which integrator renders.
    pub integrator: Integrator,
    /// Partial hits collected per traversal for semi-transparent hair (the K of thesis
    /// section 2.2.8's fast transparency); 1 re-traces the ray after every hit.
    pub transparency_layers: u32,
    /// Adaptive supersampling; `None` takes `spp` samples in every pixel.
    pub adaptive: Option<Adaptive>,
    /// Rays gathered per camera sample at the first diffuse hit by the final gather.
    pub gather_rays: u32,
    /// The final gather's irradiance cache on diffuse surfaces; `None` gathers at every hit.
    pub irradiance_cache: Option<IrradianceCacheSettings>,
    /// How each pixel's samples spread over the image (the reconstruction filter).
    pub filter: crate::film::PixelFilter,
}

/// The irradiance cache of the final gather (Ward et al. 1988): records of the gathered
/// light on diffuse surfaces, computed before the render at image points `spacing` pixels
/// apart (and coarser), and interpolated where their error estimate is below `accuracy`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct IrradianceCacheSettings {
    /// Ward's `a`: the largest error estimate a record is used at (smaller is more
    /// accurate and takes more records).
    pub accuracy: f32,
    /// Pixels between the image points of the finest pre-pass level.
    pub spacing: u32,
    /// Rays gathered per record (stratified over the hemisphere).
    pub rays: u32,
}

impl Default for IrradianceCacheSettings {
    fn default() -> Self {
        IrradianceCacheSettings { accuracy: 0.3, spacing: 4, rays: 256 }
    }
}

/// The light-transport algorithm.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Integrator {
    /// Direct light with hard or soft shadows, and mirror and glass recursion (Whitted).
    #[default]
    Direct,
    /// Direct light plus one gathered bounce of indirect light (Turtle's final gather).
    FinalGather,
    /// Unbiased path tracing with next-event estimation and multiple importance sampling.
    Path,
}

impl Integrator {
    /// The integrator named `name` (`direct`, `final-gather` or `path`).
    pub fn from_name(name: &str) -> Option<Integrator> {
        match name {
            "direct" => Some(Integrator::Direct),
            "final-gather" | "final_gather" => Some(Integrator::FinalGather),
            "path" => Some(Integrator::Path),
            _ => None,
        }
    }
}

/// Adaptive supersampling: every pixel takes `min_spp` samples, then more in batches of
/// `min_spp` while its samples differ by more than `threshold` in contrast or hit
/// different objects or strands, up to `max_spp`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Adaptive {
    /// Samples every pixel takes.
    pub min_spp: u32,
    /// Most samples a pixel takes.
    pub max_spp: u32,
    /// Contrast `(max - min) / (max + min)` of a colour channel above which a pixel is refined.
    pub threshold: f32,
}

impl Default for CameraDesc {
    /// Looking at the origin from 5 units along +z, y up, 35 degrees.
    fn default() -> Self {
        CameraDesc { eye: Vec3::new(0.0, 0.0, 5.0), target: Vec3::ZERO, up: Vec3::Y, vfov: 35.0 }
    }
}

impl Default for RenderSettings {
    fn default() -> Self {
        RenderSettings {
            width: 640,
            height: 480,
            spp: 16,
            seed: 0,
            max_depth: 5,
            threads: 0,
            integrator: Integrator::Direct,
            transparency_layers: 8,
            adaptive: None,
            gather_rays: 8,
            irradiance_cache: None,
            lod: true,
            filter: crate::film::PixelFilter::Box,
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
    /// Level of detail (stochastic pruning), when wanted.
    pub lod: Option<LodParams>,
}

/// Where a hair system's guide curves come from.
#[derive(Clone, Debug, PartialEq)]
pub enum GuideSource {
    /// A Cem Yuksel `.hair` file: one guide per strand.
    File(PathBuf),
    /// Follicles grown on the description's mesh number `mesh` (0-based), in world space.
    Follicles {
        /// Index into [`Description::meshes`].
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
    pub material: Material,
    /// Where per-point colours come from.
    pub colors: HairColors,
    /// Object-to-world transform of file or inline guides (follicles are already in
    /// world space), applied before expansion so widths are in world units.
    pub transform: Affine3A,
    /// Seed of follicle placement and of every per-hair random choice.
    pub seed: u32,
    /// Level of detail (stochastic pruning), when wanted.
    pub lod: Option<LodParams>,
}

/// Fur grown on one of the scene's meshes (Maya Fur, [`crate::fur`]).
#[derive(Clone, Debug, PartialEq)]
pub struct FurEntry {
    /// Index of the mesh it grows on, into [`Description::meshes`]; it grows on the mesh
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
}

/// Everything a scene says, before any file is read. The default is an empty scene seen
/// by [`CameraDesc::default`].
#[derive(Clone, Debug, Default, PartialEq)]
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
    /// Hair systems.
    pub hair_systems: Vec<HairSystemEntry>,
    /// Fur grown on meshes.
    pub fur: Vec<FurEntry>,
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
    /// CPU time of building the BVHs, all threads together.
    pub build_cpu: Duration,
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
        let lods = (self.hair.iter().map(|h| ("hair", h.lod)).enumerate())
            .chain(self.hair_systems.iter().map(|h| ("hair_system", h.lod)).enumerate())
            .chain(self.fur.iter().map(|f| ("fur", f.lod)).enumerate());
        for (i, (kind, p)) in lods {
            if let Some(p) = p {
                p.validate().map_err(|e| PrepareError::Invalid(format!("{kind} {}: {e}", i + 1)))?;
            }
        }
        for h in &self.hair {
            if !(h.radius_scale.is_finite() && h.radius_scale >= 0.0) {
                return Err(PrepareError::Invalid(format!(
                    "hair radius_scale {} must be finite and >= 0",
                    h.radius_scale
                )));
            }
        }
        for (i, h) in self.hair_systems.iter().enumerate() {
            let what = |e: String| PrepareError::Invalid(format!("hair_system {}: {e}", i + 1));
            h.system.validate().map_err(what)?;
            if let GuideSource::Follicles { mesh, params } = &h.guides {
                params.validate().map_err(what)?;
                if *mesh >= self.meshes.len() {
                    return Err(what(format!(
                        "follicles `mesh = {}` names no mesh (the scene has {})",
                        mesh + 1,
                        self.meshes.len()
                    )));
                }
            }
        }
        for (i, f) in self.fur.iter().enumerate() {
            let what = |e: String| PrepareError::Invalid(format!("fur {}: {e}", i + 1));
            if f.mesh >= self.meshes.len() {
                return Err(what(format!("`mesh` = {} names no mesh (there are {})", f.mesh + 1, self.meshes.len())));
            }
            f.description.validate().map_err(what)?;
            if let Some((_, a)) = &f.guides {
                a.validate().map_err(what)?;
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
    /// Level of detail per shape (meshes and strand sets without it: `None`).
    pub lods: Vec<Option<LodParams>>,
    /// What was skipped: strands or triangles whose numbers are not finite once
    /// transformed (enormous coordinates scaled past the float range, NaN from a generator).
    pub warnings: Vec<String>,
}

/// Loads every mesh and strand set a description names and applies its transform.
pub fn load_geometry(desc: &Description) -> Result<LoadedGeometry, PrepareError> {
    load_geometry_taking(desc, &mut [])
}

/// [`load_geometry`], with the inline strand sets of some hair entries already moved out
/// of the description (`taken[i]` for entry `i`): those are used as they are, not copied.
fn load_geometry_taking(desc: &Description, taken: &mut [Option<StrandSet>]) -> Result<LoadedGeometry, PrepareError> {
    let mut materials = Vec::new();
    let mut shapes = Vec::new();
    let mut warnings = Vec::new();
    let mut lods = Vec::new();
    for (i, m) in desc.meshes.iter().enumerate() {
        let mut mesh = match &m.source {
            MeshSource::File(path) => io::read_mesh(path)?,
            MeshSource::Inline(mesh) => mesh.clone(),
        };
        mesh.transform(&m.transform);
        lods.push(None);
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
            HairSource::File(path) => io::cem_hair::read_hair(path)?,
            HairSource::Inline(s) => taken.get_mut(i).and_then(Option::take).unwrap_or_else(|| s.clone()),
        };
        strands.transform(&h.transform);
        if h.radius_scale != 1.0 {
            strands.points.iter_mut().for_each(|p| p[3] *= h.radius_scale);
        }
        if !h.file_colors {
            strands.colors = None;
        }
        if let Material::Physical(m) = &h.material {
            if m.needs_strand_colors() && strands.colors.is_none() {
                let from = match &h.source {
                    HairSource::File(path) => path.display().to_string(),
                    HairSource::Inline(_) => "the strand set".into(),
                };
                return Err(PrepareError::Invalid(format!(
                    "hair {}: the material takes its colour from the strands (`from_file`), but {from} has no \
                     colours (or `file_colors = false` drops them)",
                    i + 1
                )));
            }
        }
        lods.push(h.lod);
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
    for (i, h) in desc.hair_systems.iter().enumerate() {
        let what = |e: String| PrepareError::Invalid(format!("hair_system {}: {e}", i + 1));
        let guides = match &h.guides {
            GuideSource::File(path) => {
                let mut curves = io::cem_hair::read_hair(path)?;
                curves.transform(&h.transform);
                Guides::from_curves(curves)
            }
            GuideSource::Inline(guides) => {
                let mut guides = guides.clone();
                guides.curves.transform(&h.transform);
                guides
            }
            GuideSource::Follicles { mesh, params } => match shapes.get(*mesh) {
                // Meshes come first in `shapes`, in description order, already in world space.
                Some((Shape::Mesh(m), _)) => hair_system::grow_guides(m, params, h.seed).map_err(what)?,
                _ => return Err(what(format!("follicles `mesh = {}` names no mesh", mesh + 1))),
            },
        };
        let strands = hair_system::expand(&h.system, &guides, h.colors, h.seed).map_err(what)?;
        lods.push(h.lod);
        shapes.push((Shape::Strands(strands), materials.len() as u32));
        materials.push(h.material.clone());
    }
    for (i, f) in desc.fur.iter().enumerate() {
        let what = |e: String| PrepareError::Invalid(format!("fur {}: {e}", i + 1));
        // Meshes come first among the shapes, in order.
        let Some((Shape::Mesh(mesh), _)) = shapes.get(f.mesh) else {
            return Err(what(format!("there is no mesh {}", f.mesh + 1)));
        };
        let guides = match &f.guides {
            Some((HairSource::File(path), attractors)) => Some((io::cem_hair::read_hair(path)?, attractors)),
            Some((HairSource::Inline(s), attractors)) => Some((s.clone(), attractors)),
            None => None,
        };
        let options = crate::fur::GrowOptions {
            placement: f.placement,
            seed: f.seed,
            guides: guides.as_ref().map(|(s, a)| (s, *a)),
        };
        let grown = crate::fur::grow(mesh, &f.description, options).map_err(|e| match e {
            crate::fur::FurError::Load(e) => PrepareError::Load(e),
            e => what(e.to_string()),
        })?;
        lods.push(f.lod);
        shapes.push((Shape::Strands(grown.strands), materials.len() as u32));
        materials.push(Material::Fur(grown.shading));
    }
    for (i, (shape, _)) in shapes.iter().enumerate() {
        if shape.primitive_count() > crate::accel::bvh::MAX_ITEMS {
            return Err(PrepareError::Invalid(format!(
                "object {} has {} primitives; one object holds at most {} (split the strands into several files)",
                i + 1,
                shape.primitive_count(),
                crate::accel::bvh::MAX_ITEMS
            )));
        }
    }
    Ok(LoadedGeometry { shapes, materials, lods, warnings })
}

/// Loads geometry, applies transforms and builds the BVHs.
pub fn prepare(desc: &Description) -> Result<(World, PrepareTimes), PrepareError> {
    prepare_taking(desc, &mut [])
}

/// [`prepare`] for a description not needed afterwards: inline strand sets (the demo's,
/// other tools' scenes) are moved into the scene instead of copied, which keeps their whole
/// size (16 bytes a point: 2.6 GB for 150 million segments) off the peak of the build.
pub fn prepare_owned(mut desc: Description) -> Result<(World, PrepareTimes), PrepareError> {
    let mut taken: Vec<Option<StrandSet>> = desc
        .hair
        .iter_mut()
        .map(|h| match &mut h.source {
            HairSource::Inline(s) => Some(std::mem::take(s)),
            HairSource::File(_) => None,
        })
        .collect();
    prepare_taking(&desc, &mut taken)
}

fn prepare_taking(desc: &Description, taken: &mut [Option<StrandSet>]) -> Result<(World, PrepareTimes), PrepareError> {
    desc.validate()?;
    let c = &desc.camera;
    let camera = Camera::new(c.eye, c.target, c.up, c.vfov, desc.settings.width, desc.settings.height)?;
    let start = Instant::now();
    let LoadedGeometry { shapes, materials, lods, warnings } = load_geometry_taking(desc, taken)?;
    let load = start.elapsed();
    let (start, cpu) = (Instant::now(), crate::stats::process_cpu_time());
    // The global switch drops every strand set's level of detail.
    let lod = |p: Option<LodParams>| p.filter(|_| desc.settings.lod);
    let lod_camera = crate::accel::lod::LodCamera { eye: c.eye, pixel_spread: camera.pixel_spread() };
    let accel = Accel::build_with_lod_for(
        shapes.into_iter().zip(lods).map(|((s, m), l)| (in_spatial_order(s, lod(l)), m, lod(l))).collect(),
        Some(lod_camera),
    );
    let build = start.elapsed();
    let build_cpu = crate::stats::process_cpu_time().saturating_sub(cpu);
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
    Ok((world, PrepareTimes { load, build, build_cpu }))
}

/// A shape as the acceleration structure stores it: a strand set along a Morton curve
/// ([`StrandSet::reorder_spatially`]) for the memory locality of its BVH leaves, unless
/// rendering it hashes point indices, which the reorder changes: with level of detail
/// (segment jitter) or per-point opacity (stochastic transparency draws), it keeps the
/// file's order so that every image stays the same.
fn in_spatial_order(shape: Shape, lod: Option<LodParams>) -> Shape {
    match shape {
        Shape::Strands(mut s) if lod.is_none() && s.opacity.is_none() => {
            s.reorder_spatially();
            Shape::Strands(s)
        }
        shape => shape,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn prepare_owned_moves_inline_strands_into_the_same_world() {
        // The demo's hair is inline and moved by `prepare_owned`, with a transform applied
        // after the move: the objects must equal those `prepare` builds from a copy.
        let mut desc = crate::demo::description(300, 5);
        desc.hair[0].transform = Affine3A::from_translation(Vec3::new(0.1, 0.2, 0.3));
        let (copied, _) = prepare(&desc).unwrap();
        let (moved, _) = prepare_owned(desc.clone()).unwrap();
        let (a, b) = (strand_sets(&copied), strand_sets(&moved));
        assert_eq!(a.len(), 1);
        assert_eq!(a[0].strand_count(), 300);
        assert_eq!(a, b);
        assert_eq!(crate::partial::fingerprint(&copied), crate::partial::fingerprint(&moved));
    }

    /// Every strand set of `world`, in object order.
    fn strand_sets(world: &World) -> Vec<StrandSet> {
        world
            .accel
            .objects
            .iter()
            .filter_map(|o| match &o.shape {
                Shape::Strands(s) => Some(s.clone()),
                Shape::Mesh(_) => None,
            })
            .collect()
    }

    /// A hair system (per-strand root UV and clump, per-strand random diffuse colour) and
    /// opaque fur (per-strand mapped material arrays) on a torus: strand sets that
    /// `prepare` stores in Morton order.
    const STRAND_SCENE: &str = r#"
[camera]
eye = [0.0, 1.9, 3.7]
target = [0.0, -0.15, 0.0]
[render]
resolution = [96, 72]
spp = 2
[[light]]
type = "distant"
direction = [0.45, 0.8, 0.4]
irradiance = [3.0, 3.0, 3.0]
[[light]]
type = "environment"
radiance = [0.15, 0.15, 0.15]
[[mesh]]
shape = { type = "torus", major = 1.0, minor = 0.35 }
material = { type = "diffuse", color = [0.3, 0.22, 0.15] }
[[hair_system]]
follicles = { mesh = 1, placement = "grid", u = 40, v = 12, randomization = 0.7, points_per_hair = 6, length = 0.3 }
seed = 1
hairs_per_clump = 6
clump_width = 0.09
hair_width = 0.004
hair_color = [0.35, 0.2, 0.1]
diffuse_rand = 0.5
[[fur]]
mesh = 1
preset = "Squirrel"
density = 3000
tip_opacity = 1.0
seed = 3
"#;

    #[test]
    fn strands_in_spatial_order_give_the_hits_strand_ids_and_image_of_file_order() {
        let desc = crate::io::scene_file::parse_scene(STRAND_SCENE, std::path::Path::new("order.toml")).unwrap();
        let (world, _) = prepare(&desc).unwrap();
        // The same scene with its strands in the file's order.
        let geometry = load_geometry(&desc).unwrap();
        let file = World {
            camera: world.camera.clone(),
            settings: world.settings.clone(),
            lights: world.lights.clone(),
            materials: geometry.materials,
            accel: Accel::build(geometry.shapes),
            background: world.background,
            warnings: Vec::new(),
        };
        let (moved, kept) = (strand_sets(&world), strand_sets(&file));
        assert_eq!(moved.len(), 2);
        for (m, k) in moved.iter().zip(&kept) {
            assert!(k.file_order.is_none());
            let order = m.file_order.as_ref().expect("an opaque set without level of detail is reordered");
            assert!(order.windows(2).any(|w| w[0] > w[1]), "the order changed");
            assert_eq!(m.strand_count(), k.strand_count());
        }
        // Every camera ray's hit: same distance and normal, same strand by its file index,
        // same place along it; hit segments are the same points of that strand.
        let (w, h) = (world.settings.width, world.settings.height);
        let mut strand_hits = 0;
        for y in 0..h {
            for x in 0..w {
                let ray = world.camera.ray(x as f32 + 0.5, y as f32 + 0.5);
                let (a, b) = (world.accel.intersect(&ray), file.accel.intersect(&ray));
                assert_eq!(a.map(|h| (h.t, h.object, h.kind)), b.map(|h| (h.t, h.object, h.kind)), "pixel {x}, {y}");
                let (Some(a), Some(b)) = (a, b) else { continue };
                if let (Shape::Strands(m), Shape::Strands(k)) =
                    (&world.accel.objects[a.object as usize].shape, &file.accel.objects[b.object as usize].shape)
                {
                    assert_eq!(m.hit_point(a.prim, 0.3), k.hit_point(b.prim, 0.3));
                    assert_eq!(m.points[a.prim as usize], k.points[b.prim as usize]);
                    strand_hits += 1;
                }
            }
        }
        assert!(strand_hits > (w * h / 5) as usize, "the test needs strand hits: {strand_hits}");
        // The image and every AOV (strandId, strand random, root UV, clump) bit for bit.
        let (a, b) = (crate::render::render(&world, None).0, crate::render::render(&file, None).0);
        assert!(a == b, "the reordered scene renders another image");
        assert!(a.pixels.iter().any(|p| p.strand_id >= 0.0 && p.clump_id >= 0.0 && p.root_uv[0] >= 0.0));
    }
}
