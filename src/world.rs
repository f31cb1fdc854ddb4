//! The prepared world: what the renderer reads. Plain data with no file paths (geometry
//! already loaded, in world space, with its acceleration structures), so [`crate::render`]
//! never depends on where a scene came from. [`crate::prepare`] builds it from a
//! [`crate::scene::Description`].

use crate::accel::Accel;
use crate::camera::Camera;
use crate::light::Light;
use crate::math::Color;
use crate::shading::Material;

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
    /// Sum of the constant environment lights' radiance (what unblocked rays other than
    /// camera rays see, besides the environment maps).
    pub background: Color,
    /// What camera rays see of the constant environment lights: their radiance times
    /// their camera visibility ([`Light::camera_visibility`]).
    pub camera_background: Color,
    /// The light the tube and fur models' ambient term stands for: `background` plus every
    /// environment map's mean radiance over the sphere.
    pub ambient: Color,
    /// What was skipped while preparing (strands or triangles with unusable numbers).
    pub warnings: Vec<String>,
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
    /// Path tracing: the smallest roughness (β_m and β_n) of physical hair at the vertices
    /// after the camera hit, whose narrow lobes it widens (path regularization: less noise
    /// for a small bias; docs/validation.md measures it); 0 leaves every vertex as the
    /// material says, the unbiased path tracer.
    pub indirect_hair_roughness: f32,
    /// The largest colour channel a camera sample may have: a brighter sample is scaled
    /// down to it, hue kept (fewer fireflies, a darker and biased image; pbrt-v4's `Film`
    /// `maxcomponentvalue`). Infinite leaves every sample as it is.
    pub max_sample_value: f32,
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
    /// Path tracing with next-event estimation and multiple importance sampling, unbiased
    /// without path regularization ([`RenderSettings::indirect_hair_roughness`]).
    Path,
}

impl std::str::FromStr for Integrator {
    type Err = String;

    /// `direct`, `final-gather` (or `final_gather`) or `path`, as the command line and
    /// scene files name integrators.
    fn from_str(name: &str) -> Result<Integrator, String> {
        match name {
            "direct" => Ok(Integrator::Direct),
            "final-gather" | "final_gather" => Ok(Integrator::FinalGather),
            "path" => Ok(Integrator::Path),
            _ => Err(format!("unknown integrator `{name}` (direct, final-gather or path)")),
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

impl Default for RenderSettings {
    fn default() -> Self {
        RenderSettings {
            width: 640,
            height: 480,
            spp: 16,
            seed: 0,
            max_depth: 5,
            indirect_hair_roughness: 0.5,
            max_sample_value: f32::INFINITY,
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
