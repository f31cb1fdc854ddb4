//! The scene file's schema: what each TOML table may hold, as serde reads it. Defaults
//! come from the domain types' own (`Default` on settings, materials, lights' parameters),
//! never restated here.

use crate::scene::CameraDesc;
use crate::shading::hair_bsdf::HairParams;
use crate::shading::{tube::Tube, Material};
use crate::world::RenderSettings;
use serde::de::Error as _;
use serde::{Deserialize, Deserializer};
use std::path::PathBuf;

/// Three floats: a point, a direction or a colour.
pub(super) type V3 = [f32; 3];

/// An array of exactly `N` items. Serde reads a fixed-size array by taking its first `N`
/// items and ignoring the rest, so `resolution = [64, 48, 3]` would pass as 64x48: every
/// fixed-size array of the schema is read through this instead, and a wrong length is an
/// error at the key's line.
fn exact<'de, D: Deserializer<'de>, T: Deserialize<'de>, const N: usize>(d: D) -> Result<[T; N], D::Error> {
    let items = Vec::<T>::deserialize(d)?;
    let len = items.len();
    items.try_into().map_err(|_| D::Error::invalid_length(len, &Items(N)))
}

/// [`exact`] for an optional key.
fn exact_opt<'de, D: Deserializer<'de>, T: Deserialize<'de>, const N: usize>(d: D) -> Result<Option<[T; N]>, D::Error> {
    match Option::<Vec<T>>::deserialize(d)? {
        None => Ok(None),
        Some(items) => {
            let len = items.len();
            items.try_into().map(Some).map_err(|_| D::Error::invalid_length(len, &Items(N)))
        }
    }
}

/// What [`exact`] expected, for its message.
struct Items(usize);

impl serde::de::Expected for Items {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        write!(f, "an array of exactly {} items", self.0)
    }
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct SceneToml {
    /// Without one, the camera frames the geometry.
    pub(super) camera: Option<CameraToml>,
    #[serde(default)]
    pub(super) render: RenderToml,
    #[serde(default)]
    pub(super) light: Vec<LightToml>,
    #[serde(default)]
    pub(super) mesh: Vec<MeshToml>,
    #[serde(default)]
    pub(super) hair: Vec<HairToml>,
    #[serde(default)]
    pub(super) hair_system: Vec<HairSystemToml>,
    #[serde(default)]
    pub(super) fur: Vec<FurToml>,
    #[serde(default)]
    pub(super) import: Vec<ImportToml>,
}

/// An `[[import]]` entry: the meshes, hair and hair systems of a Maya ASCII, pbrt-v4 or
/// USD text file, optionally moved, optionally with its lights.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct ImportToml {
    pub(super) file: PathBuf,
    #[serde(default)]
    pub(super) transform: TransformToml,
    #[serde(default)]
    pub(super) lights: bool,
    /// Every strand this wide (strand sets and hair systems).
    pub(super) width: Option<f32>,
    /// Every strand's radius multiplied by this.
    pub(super) radius_scale: Option<f32>,
    /// Visibility set on every imported object (each key given overrides the file's).
    pub(super) camera_visible: Option<bool>,
    pub(super) casts_shadows: Option<bool>,
    pub(super) matte: Option<bool>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct CameraToml {
    /// Required unless there are keys.
    #[serde(default, deserialize_with = "exact_opt")]
    pub(super) eye: Option<V3>,
    /// Required unless there are keys.
    #[serde(default, deserialize_with = "exact_opt")]
    pub(super) target: Option<V3>,
    #[serde(default = "default_up", deserialize_with = "exact")]
    pub(super) up: V3,
    #[serde(default = "default_vfov")]
    pub(super) vfov: f32,
    #[serde(default)]
    pub(super) projection: ProjectionToml,
    /// The orthographic window's height in scene units.
    #[serde(default)]
    pub(super) ortho_height: Option<f32>,
    /// `[near, far]` clipping distances along the view direction.
    #[serde(default)]
    pub(super) clip: Option<[f32; 2]>,
    /// A camera path: keys at frames, interpolated linearly between them.
    #[serde(default)]
    pub(super) key: Vec<CameraKeyToml>,
}
/// `projection` of `[camera]`.
#[derive(Deserialize, Default, Clone, Copy, PartialEq)]
#[serde(rename_all = "lowercase")]
pub(super) enum ProjectionToml {
    #[default]
    Perspective,
    Orthographic,
}

fn default_up() -> V3 {
    CameraDesc::default().up.into()
}
fn default_vfov() -> f32 {
    CameraDesc::default().vfov
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct CameraKeyToml {
    pub(super) frame: u32,
    #[serde(deserialize_with = "exact")]
    pub(super) eye: V3,
    #[serde(deserialize_with = "exact")]
    pub(super) target: V3,
    /// Defaults to the camera's `vfov`.
    pub(super) vfov: Option<f32>,
}

/// `[render]`: every key optional, defaults from [`RenderSettings::default`].
#[derive(Deserialize)]
#[serde(default, deny_unknown_fields)]
pub(super) struct RenderToml {
    #[serde(deserialize_with = "exact")]
    pub(super) resolution: [u32; 2],
    pub(super) spp: u32,
    pub(super) seed: u32,
    pub(super) max_depth: u32,
    pub(super) indirect_hair_roughness: f32,
    pub(super) max_sample_value: f32,
    pub(super) threads: usize,
    pub(super) lod: bool,
    /// `direct`, `final-gather` or `path`.
    pub(super) integrator: Option<String>,
    pub(super) transparency_layers: u32,
    pub(super) gather_rays: u32,
    pub(super) adaptive: Option<AdaptiveToml>,
    pub(super) irradiance_cache: Option<IrradianceCacheToml>,
    pub(super) filter: Option<FilterToml>,
}

impl Default for RenderToml {
    fn default() -> Self {
        let d = RenderSettings::default();
        RenderToml {
            resolution: [d.width, d.height],
            spp: d.spp,
            seed: d.seed,
            max_depth: d.max_depth,
            indirect_hair_roughness: d.indirect_hair_roughness,
            max_sample_value: d.max_sample_value,
            threads: d.threads,
            lod: d.lod,
            integrator: None,
            transparency_layers: d.transparency_layers,
            gather_rays: d.gather_rays,
            adaptive: None,
            irradiance_cache: None,
            filter: None,
        }
    }
}

/// `filter = "box"`, `filter = "gaussian"` or `filter = { type = "gaussian", radius = 1.5,
/// sigma = 0.5 }` (radius and sigma optional).
#[derive(Deserialize)]
#[serde(untagged)]
pub(super) enum FilterToml {
    Name(String),
    With(FilterTable),
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct FilterTable {
    #[serde(rename = "type")]
    pub(super) kind: String,
    pub(super) radius: Option<f32>,
    pub(super) sigma: Option<f32>,
}

/// `irradiance_cache = true`, or `irradiance_cache = { accuracy = 0.3, spacing = 4, rays = 256 }`
/// (each key optional).
#[derive(Deserialize)]
#[serde(untagged)]
pub(super) enum IrradianceCacheToml {
    On(bool),
    With(IrradianceCacheTable),
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct IrradianceCacheTable {
    pub(super) accuracy: Option<f32>,
    pub(super) spacing: Option<u32>,
    pub(super) rays: Option<u32>,
}

/// `adaptive = { min_spp = 4, max_spp = 64, threshold = 0.05 }`.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct AdaptiveToml {
    pub(super) min_spp: u32,
    pub(super) max_spp: u32,
    #[serde(default = "default_threshold")]
    pub(super) threshold: f32,
}

fn default_threshold() -> f32 {
    0.05
}

#[derive(Deserialize)]
#[serde(tag = "type", rename_all = "lowercase", deny_unknown_fields)]
pub(super) enum LightToml {
    Distant {
        #[serde(deserialize_with = "exact")]
        direction: V3,
        #[serde(deserialize_with = "exact")]
        irradiance: V3,
        /// Degrees; 0 is a sharp light.
        #[serde(default)]
        angular_diameter: f32,
    },
    Point {
        #[serde(deserialize_with = "exact")]
        position: V3,
        #[serde(deserialize_with = "exact")]
        intensity: V3,
    },
    Spot {
        #[serde(deserialize_with = "exact")]
        position: V3,
        #[serde(deserialize_with = "exact")]
        target: V3,
        #[serde(deserialize_with = "exact")]
        intensity: V3,
        #[serde(default = "default_inner")]
        inner_angle: f32,
        #[serde(default = "default_outer")]
        outer_angle: f32,
    },
    Quad {
        #[serde(deserialize_with = "exact")]
        corner: V3,
        #[serde(deserialize_with = "exact")]
        edge_u: V3,
        #[serde(deserialize_with = "exact")]
        edge_v: V3,
        #[serde(deserialize_with = "exact")]
        radiance: V3,
        /// Weight camera rays see it with.
        #[serde(default = "one")]
        camera_visibility: f32,
    },
    Sphere {
        #[serde(deserialize_with = "exact")]
        center: V3,
        radius: f32,
        #[serde(deserialize_with = "exact")]
        radiance: V3,
        /// Weight camera rays see it with.
        #[serde(default = "one")]
        camera_visibility: f32,
    },
    /// Exactly one of `radiance` (constant) and `file` (an equirectangular map).
    Environment {
        #[serde(default, deserialize_with = "exact_opt")]
        radiance: Option<V3>,
        file: Option<PathBuf>,
        /// Degrees about +y.
        #[serde(default)]
        rotation: f32,
        #[serde(default = "default_intensity")]
        intensity: f32,
        /// Stops: the radiance is scaled by 2^exposure.
        #[serde(default)]
        exposure: f32,
        /// Weight camera rays see it with.
        #[serde(default = "one")]
        camera_visibility: f32,
    },
    /// A physical daylight sky and sun ([`crate::light::PhysicalSky`]).
    Sky {
        /// Degrees of the sun above the horizon.
        #[serde(default = "default_elevation")]
        elevation: f32,
        /// Degrees around +y from +x towards +z.
        #[serde(default = "default_azimuth")]
        azimuth: f32,
        #[serde(default = "default_turbidity")]
        turbidity: f32,
        #[serde(default = "default_ground_albedo", deserialize_with = "exact")]
        ground_albedo: V3,
        /// Degrees across; 0 leaves the sun out.
        #[serde(default = "default_sun_size")]
        sun_size: f32,
        #[serde(default = "default_intensity")]
        intensity: f32,
        #[serde(default)]
        exposure: f32,
        #[serde(default = "one")]
        camera_visibility: f32,
    },
}

fn default_elevation() -> f32 {
    crate::light::PhysicalSky::DEFAULT_ELEVATION
}
fn default_azimuth() -> f32 {
    crate::light::PhysicalSky::DEFAULT_AZIMUTH
}
fn default_turbidity() -> f32 {
    crate::light::PhysicalSky::arnold_default().turbidity
}
fn default_ground_albedo() -> V3 {
    crate::light::PhysicalSky::arnold_default().ground_albedo.into()
}
fn default_sun_size() -> f32 {
    crate::light::PhysicalSky::arnold_default().sun_size
}

fn default_intensity() -> f32 {
    1.0
}

/// A roughness: a number, or an image whose red channel holds it.
#[derive(Deserialize)]
#[serde(untagged)]
pub(super) enum RoughnessToml {
    Constant(f32),
    Map(PathBuf),
}

fn default_inner() -> f32 {
    20.0
}

fn default_outer() -> f32 {
    30.0
}

/// A material: every key optional, defaults from the shading models' own
/// ([`Material::DEFAULT_COLOR`], [`Tube::default`], [`HairParams::default`], ...).
#[derive(Deserialize)]
#[serde(tag = "type", rename_all = "lowercase", deny_unknown_fields)]
pub(super) enum MaterialToml {
    Diffuse {
        #[serde(default = "default_color", deserialize_with = "exact")]
        color: V3,
    },
    /// Diffuse colour from an image by UV, optionally glossy.
    Textured {
        color: PathBuf,
        #[serde(default = "one3", deserialize_with = "exact")]
        tint: V3,
        roughness: Option<RoughnessToml>,
        /// Defaults to 0.04 with a roughness, else 0.
        specular: Option<f32>,
    },
    Phong {
        #[serde(default = "default_color", deserialize_with = "exact")]
        diffuse: V3,
        #[serde(default = "default_phong_specular", deserialize_with = "exact")]
        specular: V3,
        #[serde(default = "default_phong_exponent")]
        exponent: f32,
    },
    Mirror {
        #[serde(default = "one3", deserialize_with = "exact")]
        color: V3,
    },
    /// Its colour whatever the light (Arnold's `flat`).
    Unlit {
        #[serde(default = "one3", deserialize_with = "exact")]
        color: V3,
    },
    Glass {
        #[serde(default = "default_ior")]
        ior: f32,
        #[serde(default = "one3", deserialize_with = "exact")]
        color: V3,
    },
    Tube {
        /// Defaults to the diffuse colour.
        #[serde(default, deserialize_with = "exact_opt")]
        ambient: Option<V3>,
        #[serde(default = "default_tube_diffuse", deserialize_with = "exact")]
        diffuse: V3,
        #[serde(default = "default_tube_specular", deserialize_with = "exact")]
        specular: V3,
        #[serde(default = "default_specular_power")]
        specular_power: f32,
    },
    /// The physical hair BSDF; at most one of melanin, `color` and `from_file` (none:
    /// the default melanin).
    Physical {
        eumelanin: Option<f32>,
        pheomelanin: Option<f32>,
        #[serde(default, deserialize_with = "exact_opt")]
        color: Option<V3>,
        #[serde(default)]
        from_file: bool,
        #[serde(default = "default_beta_m")]
        beta_m: f32,
        #[serde(default = "default_beta_n")]
        beta_n: f32,
        /// Degrees.
        #[serde(default = "default_alpha")]
        alpha: f32,
        #[serde(default = "default_hair_eta")]
        eta: f32,
    },
}
fn default_color() -> V3 {
    Material::DEFAULT_COLOR.into()
}
fn default_phong_specular() -> V3 {
    Material::DEFAULT_PHONG_SPECULAR.into()
}
fn default_phong_exponent() -> f32 {
    Material::DEFAULT_PHONG_EXPONENT
}
fn one() -> f32 {
    1.0
}
fn one3() -> V3 {
    [1.0; 3]
}
fn default_ior() -> f32 {
    Material::DEFAULT_IOR
}
fn default_tube_diffuse() -> V3 {
    Tube::default().diffuse.into()
}
fn default_tube_specular() -> V3 {
    Tube::default().specular.into()
}
fn default_specular_power() -> f32 {
    Tube::default().specular_power
}
fn default_beta_m() -> f32 {
    HairParams::default().beta_m
}
fn default_beta_n() -> f32 {
    HairParams::default().beta_n
}
fn default_alpha() -> f32 {
    HairParams::default().alpha_degrees
}
fn default_hair_eta() -> f32 {
    HairParams::default().eta
}

#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub(super) struct TransformToml {
    #[serde(default, deserialize_with = "exact_opt")]
    pub(super) translate: Option<V3>,
    /// Axis (x, y, z) and angle in degrees.
    #[serde(default, deserialize_with = "exact_opt")]
    pub(super) rotate: Option<[f32; 4]>,
    #[serde(default)]
    pub(super) scale: Option<ScaleToml>,
}

#[derive(Deserialize)]
#[serde(untagged)]
pub(super) enum ScaleToml {
    Uniform(f32),
    Axes(#[serde(deserialize_with = "exact")] V3),
}

#[derive(Deserialize)]
#[serde(tag = "type", rename_all = "lowercase", deny_unknown_fields)]
pub(super) enum ShapeToml {
    Torus {
        #[serde(default = "default_major")]
        major: f32,
        #[serde(default = "default_minor")]
        minor: f32,
    },
    Sphere {
        #[serde(default = "default_radius")]
        radius: f32,
    },
    Plane {
        #[serde(default = "default_size")]
        size: f32,
    },
    Pillow {
        #[serde(default = "default_size")]
        size: f32,
        #[serde(default = "default_thickness")]
        thickness: f32,
    },
}

fn default_thickness() -> f32 {
    0.3
}

fn default_major() -> f32 {
    1.0
}

fn default_minor() -> f32 {
    0.35
}

fn default_radius() -> f32 {
    1.0
}

fn default_size() -> f32 {
    1.0
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct MeshToml {
    pub(super) file: Option<PathBuf>,
    pub(super) shape: Option<ShapeToml>,
    pub(super) material: MaterialToml,
    #[serde(default)]
    pub(super) transform: TransformToml,
    pub(super) camera_visible: Option<bool>,
    pub(super) casts_shadows: Option<bool>,
    pub(super) matte: Option<bool>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct HairToml {
    pub(super) file: PathBuf,
    pub(super) material: MaterialToml,
    #[serde(default)]
    pub(super) transform: TransformToml,
    #[serde(default = "default_radius_scale")]
    pub(super) radius_scale: f32,
    #[serde(default = "default_true")]
    pub(super) file_colors: bool,
    pub(super) lod: Option<LodToml>,
    pub(super) camera_visible: Option<bool>,
    pub(super) casts_shadows: Option<bool>,
    pub(super) matte: Option<bool>,
}

/// `lod = { decimation = 1.5, levels = 8, compensation = 0.8, contrast = false }`, every
/// key optional ([`LodParams::default`]).
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct LodToml {
    pub(super) decimation: Option<f32>,
    pub(super) levels: Option<u32>,
    pub(super) compensation: Option<f32>,
    pub(super) contrast: Option<bool>,
    pub(super) start: Option<f32>,
    pub(super) spread: Option<f32>,
    pub(super) simplify: Option<u32>,
    pub(super) smooth: Option<bool>,
}

fn default_radius_scale() -> f32 {
    1.0
}

fn default_true() -> bool {
    true
}

/// A `[[hair_system]]` entry: guides, material, seed and Maya's hair-system attributes
/// (every attribute optional, defaulting to [`HairSystem::default`]).
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct HairSystemToml {
    pub(super) file: Option<PathBuf>,
    pub(super) follicles: Option<FolliclesToml>,
    pub(super) material: Option<MaterialToml>,
    pub(super) colors: Option<String>,
    #[serde(default)]
    pub(super) seed: u32,
    pub(super) transform: Option<TransformToml>,
    pub(super) lod: Option<LodToml>,
    pub(super) hairs_per_clump: Option<u32>,
    pub(super) sub_segments: Option<u32>,
    pub(super) thinning: Option<f32>,
    pub(super) clump_width: Option<f32>,
    pub(super) clump_width_scale: Option<RampToml<f32>>,
    pub(super) clump_twist: Option<f32>,
    pub(super) clump_curl: Option<RampToml<f32>>,
    pub(super) clump_flatness: Option<RampToml<f32>>,
    pub(super) bend_follow: Option<f32>,
    pub(super) hair_width: Option<f32>,
    pub(super) hair_width_scale: Option<RampToml<f32>>,
    pub(super) displacement_scale: Option<RampToml<f32>>,
    pub(super) curl: Option<f32>,
    pub(super) curl_frequency: Option<f32>,
    pub(super) noise_method: Option<String>,
    pub(super) noise: Option<f32>,
    pub(super) noise_frequency: Option<f32>,
    pub(super) noise_frequency_u: Option<f32>,
    pub(super) noise_frequency_v: Option<f32>,
    pub(super) noise_frequency_w: Option<f32>,
    #[serde(default, deserialize_with = "exact_opt")]
    pub(super) hair_color: Option<V3>,
    pub(super) hair_color_scale: Option<RampToml<V3>>,
    pub(super) opacity: Option<f32>,
    pub(super) translucence: Option<f32>,
    #[serde(default, deserialize_with = "exact_opt")]
    pub(super) specular_color: Option<V3>,
    pub(super) specular_power: Option<f32>,
    pub(super) diffuse_rand: Option<f32>,
    pub(super) specular_rand: Option<f32>,
    pub(super) hue_rand: Option<f32>,
    pub(super) sat_rand: Option<f32>,
    pub(super) val_rand: Option<f32>,
    pub(super) camera_visible: Option<bool>,
    pub(super) casts_shadows: Option<bool>,
    pub(super) matte: Option<bool>,
}

/// `follicles = { mesh = 1, placement = "grid", u = 10, v = 10, ... }`.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct FolliclesToml {
    /// 1-based index of a `[[mesh]]` entry.
    pub(super) mesh: usize,
    #[serde(default = "default_placement")]
    pub(super) placement: String,
    pub(super) u: Option<u32>,
    pub(super) v: Option<u32>,
    pub(super) count: Option<u32>,
    pub(super) randomization: Option<f32>,
    #[serde(default, deserialize_with = "exact_opt")]
    pub(super) uv_range: Option<[[f32; 2]; 2]>,
    pub(super) points_per_hair: Option<u32>,
    pub(super) length: Option<f32>,
    pub(super) droop: Option<f32>,
    #[serde(default, deserialize_with = "exact_opt")]
    pub(super) gravity: Option<V3>,
}

fn default_placement() -> String {
    "grid".into()
}

/// A ramp: one value everywhere, or keys.
#[derive(Deserialize)]
#[serde(untagged)]
pub(super) enum RampToml<T> {
    Constant(T),
    Keys(Vec<RampKeyToml<T>>),
}

/// A ramp key: `[position, value]` (linear), `[position, value, "interp"]` or
/// `{ position, value, interp }`.
#[derive(Deserialize)]
#[serde(untagged)]
pub(super) enum RampKeyToml<T> {
    Pair(f32, T),
    Triple(f32, T, String),
    Table { position: f32, value: T, interp: Option<String> },
}

/// A `[[fur]]` entry: its own keys, and every other key a fur attribute.
#[derive(Deserialize)]
pub(super) struct FurToml {
    /// 1-based, as messages count meshes.
    pub(super) mesh: i64,
    pub(super) preset: Option<String>,
    #[serde(default)]
    pub(super) seed: u32,
    #[serde(default)]
    pub(super) placement: PlacementToml,
    pub(super) guides: Option<PathBuf>,
    pub(super) attractors: Option<AttractorsToml>,
    pub(super) lod: Option<LodToml>,
    pub(super) camera_visible: Option<bool>,
    pub(super) casts_shadows: Option<bool>,
    pub(super) matte: Option<bool>,
    #[serde(flatten)]
    pub(super) attributes: toml::Table,
}

#[derive(Deserialize, Default)]
#[serde(rename_all = "lowercase")]
pub(super) enum PlacementToml {
    #[default]
    Area,
    Uv,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct AttractorsToml {
    pub(super) model: Option<AttractorModelToml>,
    pub(super) curves_per_fur: Option<u32>,
    pub(super) global_scale: Option<f32>,
    pub(super) radius: Option<f32>,
    pub(super) power: Option<f32>,
    pub(super) influence: Option<f32>,
    pub(super) threshold_length: Option<f32>,
}

#[derive(Deserialize)]
#[serde(rename_all = "lowercase")]
pub(super) enum AttractorModelToml {
    Local,
    Global,
}
