//! Scene files in TOML (documented in `docs/scene-format.md`), read into a
//! [`Description`]. Unknown keys and wrong types are errors naming the file, line and key.
//!
//! An animated scene (camera keys, or file names with `#` runs standing for the frame
//! number) is read at one frame: the camera is interpolated and the frame substituted.

use crate::accel::lod::LodParams;
use crate::film::PixelFilter;
use crate::fur::{AttractorModel, Attractors, FurDescription, Placement as FurPlacement};
use crate::geometry::TriangleMesh;
use crate::hair_system::ramp::RampValue;
use crate::hair_system::{FollicleParams, HairColors, HairSystem, Interp, NoiseMethod, Placement, Ramp, RampKey};
use crate::light::Light;
use crate::scene::{
    CameraDesc, Description, FurEntry, GuideSource, HairEntry, HairSource, HairSystemEntry, MeshEntry, MeshSource,
};
use crate::shading::hair_bsdf::{Absorption, HairParams, PhysicalHair};
use crate::shading::{tube::Tube, Material};
use crate::world::{Adaptive, Integrator, IrradianceCacheSettings, RenderSettings};
use glam::{Affine3A, Quat, Vec3};
use serde::Deserialize;
use std::path::{Path, PathBuf};

/// Why a scene file cannot be read.
#[derive(Debug, thiserror::Error)]
pub enum SceneFileError {
    /// The file cannot be read.
    #[error("{path}: {source}")]
    Io {
        /// The scene file.
        path: PathBuf,
        /// What failed.
        source: std::io::Error,
    },
    /// The TOML is malformed or does not match the scene format.
    #[error("{path}: {message}")]
    Syntax {
        /// The scene file.
        path: PathBuf,
        /// The parser's message, with line and column.
        message: String,
    },
    /// A value is out of range.
    #[error("{path}: {message}")]
    Invalid {
        /// The scene file.
        path: PathBuf,
        /// What is wrong.
        message: String,
    },
}

type V3 = [f32; 3];

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct SceneToml {
    camera: CameraToml,
    #[serde(default)]
    render: RenderToml,
    #[serde(default)]
    light: Vec<LightToml>,
    #[serde(default)]
    mesh: Vec<MeshToml>,
    #[serde(default)]
    hair: Vec<HairToml>,
    #[serde(default)]
    hair_system: Vec<HairSystemToml>,
    #[serde(default)]
    fur: Vec<FurToml>,
    #[serde(default)]
    import: Vec<ImportToml>,
}

/// An `[[import]]` entry: the meshes, hair and hair systems of a Maya ASCII, pbrt-v4 or
/// USD text file, optionally moved, optionally with its lights.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct ImportToml {
    file: PathBuf,
    #[serde(default)]
    transform: TransformToml,
    #[serde(default)]
    lights: bool,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct CameraToml {
    /// Required unless there are keys.
    eye: Option<V3>,
    /// Required unless there are keys.
    target: Option<V3>,
    #[serde(default = "default_up")]
    up: V3,
    #[serde(default = "default_vfov")]
    vfov: f32,
    /// A camera path: keys at frames, interpolated linearly between them.
    #[serde(default)]
    key: Vec<CameraKeyToml>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct CameraKeyToml {
    frame: u32,
    eye: V3,
    target: V3,
    /// Defaults to the camera's `vfov`.
    vfov: Option<f32>,
}

fn default_up() -> V3 {
    [0.0, 1.0, 0.0]
}
fn default_vfov() -> f32 {
    35.0
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RenderToml {
    #[serde(default = "default_resolution")]
    resolution: [u32; 2],
    #[serde(default = "default_spp")]
    spp: u32,
    #[serde(default)]
    seed: u32,
    #[serde(default = "default_max_depth")]
    max_depth: u32,
    #[serde(default)]
    threads: usize,
    #[serde(default = "default_true")]
    lod: bool,
    /// `direct`, `final-gather` or `path`.
    #[serde(default)]
    integrator: Option<String>,
    #[serde(default)]
    transparency_layers: Option<u32>,
    #[serde(default)]
    gather_rays: Option<u32>,
    #[serde(default)]
    adaptive: Option<AdaptiveToml>,
    #[serde(default)]
    irradiance_cache: Option<IrradianceCacheToml>,
    #[serde(default)]
    filter: Option<FilterToml>,
}

/// `filter = "box"`, `filter = "gaussian"` or `filter = { type = "gaussian", radius = 1.5,
/// sigma = 0.5 }` (radius and sigma optional).
#[derive(Deserialize)]
#[serde(untagged)]
enum FilterToml {
    Name(String),
    With(FilterTable),
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct FilterTable {
    #[serde(rename = "type")]
    kind: String,
    radius: Option<f32>,
    sigma: Option<f32>,
}

impl FilterToml {
    fn filter(&self) -> Result<PixelFilter, String> {
        let (kind, radius, sigma) = match self {
            FilterToml::Name(name) => (name.as_str(), None, None),
            FilterToml::With(t) => (t.kind.as_str(), t.radius, t.sigma),
        };
        let f = match kind {
            "box" if radius.is_none() && sigma.is_none() => PixelFilter::Box,
            "box" => return Err("the `box` filter takes no `radius` or `sigma`".into()),
            "gaussian" => {
                let radius = radius.unwrap_or(1.5);
                PixelFilter::Gaussian { radius, sigma: sigma.unwrap_or(radius / 3.0) }
            }
            other => return Err(format!("unknown filter `{other}` (box or gaussian)")),
        };
        f.validate()?;
        Ok(f)
    }
}

/// `irradiance_cache = true`, or `irradiance_cache = { accuracy = 0.3, spacing = 4, rays = 256 }`
/// (each key optional).
#[derive(Deserialize)]
#[serde(untagged)]
enum IrradianceCacheToml {
    On(bool),
    With(IrradianceCacheTable),
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct IrradianceCacheTable {
    accuracy: Option<f32>,
    spacing: Option<u32>,
    rays: Option<u32>,
}

/// `adaptive = { min_spp = 4, max_spp = 64, threshold = 0.05 }`.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct AdaptiveToml {
    min_spp: u32,
    max_spp: u32,
    #[serde(default = "default_threshold")]
    threshold: f32,
}
fn default_threshold() -> f32 {
    0.05
}

impl Default for RenderToml {
    fn default() -> Self {
        let d = RenderSettings::default();
        RenderToml {
            resolution: [d.width, d.height],
            spp: d.spp,
            seed: d.seed,
            max_depth: d.max_depth,
            threads: 0,
            lod: d.lod,
            integrator: None,
            transparency_layers: None,
            gather_rays: None,
            adaptive: None,
            irradiance_cache: None,
            filter: None,
        }
    }
}
fn default_resolution() -> [u32; 2] {
    let d = RenderSettings::default();
    [d.width, d.height]
}
fn default_spp() -> u32 {
    RenderSettings::default().spp
}
fn default_max_depth() -> u32 {
    RenderSettings::default().max_depth
}

#[derive(Deserialize)]
#[serde(tag = "type", rename_all = "lowercase", deny_unknown_fields)]
enum LightToml {
    Distant {
        direction: V3,
        irradiance: V3,
        /// Degrees; 0 is a sharp light.
        #[serde(default)]
        angular_diameter: f32,
    },
    Point {
        position: V3,
        intensity: V3,
    },
    Spot {
        position: V3,
        target: V3,
        intensity: V3,
        #[serde(default = "default_inner")]
        inner_angle: f32,
        #[serde(default = "default_outer")]
        outer_angle: f32,
    },
    Quad {
        corner: V3,
        edge_u: V3,
        edge_v: V3,
        radiance: V3,
    },
    Sphere {
        center: V3,
        radius: f32,
        radiance: V3,
    },
    Environment {
        radiance: V3,
    },
}
fn default_inner() -> f32 {
    20.0
}
fn default_outer() -> f32 {
    30.0
}

#[derive(Deserialize)]
#[serde(tag = "type", rename_all = "lowercase", deny_unknown_fields)]
enum MaterialToml {
    Diffuse {
        color: V3,
    },
    Phong {
        diffuse: V3,
        specular: V3,
        exponent: f32,
    },
    Mirror {
        #[serde(default = "one3")]
        color: V3,
    },
    Glass {
        #[serde(default = "default_ior")]
        ior: f32,
        #[serde(default = "one3")]
        color: V3,
    },
    Tube {
        /// Defaults to the diffuse colour.
        ambient: Option<V3>,
        diffuse: V3,
        #[serde(default = "default_tube_specular")]
        specular: V3,
        #[serde(default = "default_specular_power")]
        specular_power: f32,
    },
    /// The physical hair BSDF; exactly one of melanin, `color` and `from_file`.
    Physical {
        eumelanin: Option<f32>,
        pheomelanin: Option<f32>,
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
fn one3() -> V3 {
    [1.0; 3]
}
fn default_ior() -> f32 {
    1.5
}
fn default_tube_specular() -> V3 {
    [0.3; 3]
}
fn default_specular_power() -> f32 {
    40.0
}

#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields)]
struct TransformToml {
    #[serde(default)]
    translate: Option<V3>,
    /// Axis (x, y, z) and angle in degrees.
    #[serde(default)]
    rotate: Option<[f32; 4]>,
    #[serde(default)]
    scale: Option<ScaleToml>,
}

#[derive(Deserialize)]
#[serde(untagged)]
enum ScaleToml {
    Uniform(f32),
    Axes(V3),
}

#[derive(Deserialize)]
#[serde(tag = "type", rename_all = "lowercase", deny_unknown_fields)]
enum ShapeToml {
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
struct MeshToml {
    file: Option<PathBuf>,
    shape: Option<ShapeToml>,
    material: MaterialToml,
    #[serde(default)]
    transform: TransformToml,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct HairToml {
    file: PathBuf,
    material: MaterialToml,
    #[serde(default)]
    transform: TransformToml,
    #[serde(default = "default_radius_scale")]
    radius_scale: f32,
    #[serde(default = "default_true")]
    file_colors: bool,
    lod: Option<LodToml>,
}

/// `lod = { decimation = 1.5, levels = 8, compensation = 0.8, contrast = false }`, every
/// key optional ([`LodParams::default`]).
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct LodToml {
    decimation: Option<f32>,
    levels: Option<u32>,
    compensation: Option<f32>,
    contrast: Option<bool>,
    start: Option<f32>,
    spread: Option<f32>,
    simplify: Option<u32>,
    smooth: Option<bool>,
}

impl LodToml {
    fn params(&self) -> Result<LodParams, String> {
        let d = LodParams::default();
        let p = LodParams {
            decimation: self.decimation.unwrap_or(d.decimation),
            levels: self.levels.unwrap_or(d.levels),
            compensation: self.compensation.unwrap_or(d.compensation),
            contrast: self.contrast.unwrap_or(d.contrast),
            start: self.start.unwrap_or(d.start),
            spread: self.spread.unwrap_or(d.spread),
            simplify: self.simplify.unwrap_or(d.simplify),
            smooth: self.smooth.unwrap_or(d.smooth),
        };
        p.validate()?;
        Ok(p)
    }
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
struct HairSystemToml {
    file: Option<PathBuf>,
    follicles: Option<FolliclesToml>,
    material: Option<MaterialToml>,
    colors: Option<String>,
    #[serde(default)]
    seed: u32,
    transform: Option<TransformToml>,
    lod: Option<LodToml>,
    hairs_per_clump: Option<u32>,
    sub_segments: Option<u32>,
    thinning: Option<f32>,
    clump_width: Option<f32>,
    clump_width_scale: Option<RampToml<f32>>,
    clump_twist: Option<f32>,
    clump_curl: Option<RampToml<f32>>,
    clump_flatness: Option<RampToml<f32>>,
    bend_follow: Option<f32>,
    hair_width: Option<f32>,
    hair_width_scale: Option<RampToml<f32>>,
    displacement_scale: Option<RampToml<f32>>,
    curl: Option<f32>,
    curl_frequency: Option<f32>,
    noise_method: Option<String>,
    noise: Option<f32>,
    noise_frequency: Option<f32>,
    noise_frequency_u: Option<f32>,
    noise_frequency_v: Option<f32>,
    noise_frequency_w: Option<f32>,
    hair_color: Option<V3>,
    hair_color_scale: Option<RampToml<V3>>,
    opacity: Option<f32>,
    translucence: Option<f32>,
    specular_color: Option<V3>,
    specular_power: Option<f32>,
    diffuse_rand: Option<f32>,
    specular_rand: Option<f32>,
    hue_rand: Option<f32>,
    sat_rand: Option<f32>,
    val_rand: Option<f32>,
}

/// `follicles = { mesh = 1, placement = "grid", u = 10, v = 10, ... }`.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct FolliclesToml {
    /// 1-based index of a `[[mesh]]` entry.
    mesh: usize,
    #[serde(default = "default_placement")]
    placement: String,
    u: Option<u32>,
    v: Option<u32>,
    count: Option<u32>,
    randomization: Option<f32>,
    uv_range: Option<[[f32; 2]; 2]>,
    points_per_hair: Option<u32>,
    length: Option<f32>,
    droop: Option<f32>,
    gravity: Option<V3>,
}
fn default_placement() -> String {
    "grid".into()
}

/// A ramp: one value everywhere, or keys.
#[derive(Deserialize)]
#[serde(untagged)]
enum RampToml<T> {
    Constant(T),
    Keys(Vec<RampKeyToml<T>>),
}

/// A ramp key: `[position, value]` (linear), `[position, value, "interp"]` or
/// `{ position, value, interp }`.
#[derive(Deserialize)]
#[serde(untagged)]
enum RampKeyToml<T> {
    Pair(f32, T),
    Triple(f32, T, String),
    Table { position: f32, value: T, interp: Option<String> },
}

/// Converts a ramp with `convert` for its values, naming the attribute in errors.
fn ramp<U: Copy, T: RampValue>(name: &str, r: &RampToml<U>, convert: impl Fn(U) -> T) -> Result<Ramp<T>, String> {
    let keys = match r {
        RampToml::Constant(v) => return Ok(Ramp::constant(convert(*v))),
        RampToml::Keys(keys) => keys,
    };
    let mut out = Vec::with_capacity(keys.len());
    for (i, k) in keys.iter().enumerate() {
        let (position, value, interp) = match k {
            RampKeyToml::Pair(p, v) => (*p, *v, None),
            RampKeyToml::Triple(p, v, s) => (*p, *v, Some(s)),
            RampKeyToml::Table { position, value, interp } => (*position, *value, interp.as_ref()),
        };
        let interp = match interp {
            None => Interp::Linear,
            Some(how) => Interp::from_name(how).ok_or_else(|| {
                format!("`{name}` key {}: unknown interpolation `{how}` (none, linear, smooth or spline)", i + 1)
            })?,
        };
        out.push(RampKey { position, value: convert(value), interp });
    }
    Ramp::new(out).map_err(|e| format!("`{name}` {e}"))
}

fn hair_system(h: &HairSystemToml, base: &Path, meshes: usize) -> Result<HairSystemEntry, String> {
    let mut s = HairSystem::default();
    macro_rules! set {
        ($($field:ident),*) => { $( if let Some(v) = h.$field { s.$field = v; } )* };
    }
    set!(
        hairs_per_clump,
        sub_segments,
        thinning,
        clump_width,
        clump_twist,
        bend_follow,
        hair_width,
        curl,
        curl_frequency,
        noise,
        noise_frequency,
        noise_frequency_u,
        noise_frequency_v,
        noise_frequency_w,
        opacity,
        translucence,
        specular_power,
        diffuse_rand,
        specular_rand,
        hue_rand,
        sat_rand,
        val_rand
    );
    macro_rules! set_ramp {
        ($($field:ident),*) => { $( if let Some(r) = &h.$field { s.$field = ramp(stringify!($field), r, |x| x)?; } )* };
    }
    set_ramp!(clump_width_scale, clump_curl, clump_flatness, hair_width_scale, displacement_scale);
    if let Some(r) = &h.hair_color_scale {
        s.hair_color_scale = ramp("hair_color_scale", r, Vec3::from)?;
    }
    if let Some(c) = h.hair_color {
        s.hair_color = c.into();
    }
    if let Some(c) = h.specular_color {
        s.specular_color = c.into();
    }
    if let Some(m) = &h.noise_method {
        s.noise_method = match m.as_str() {
            "random" => NoiseMethod::Random,
            "surface_uv" => NoiseMethod::SurfaceUv,
            "clump_uv" => NoiseMethod::ClumpUv,
            _ => return Err(format!("unknown `noise_method` `{m}` (random, surface_uv or clump_uv)")),
        };
    }
    s.validate()?;
    let colors = match h.colors.as_deref() {
        None | Some("system") => HairColors::System,
        Some("guides") => HairColors::Guides,
        Some("material") => HairColors::Material,
        Some(c) => return Err(format!("unknown `colors` `{c}` (system, guides or material)")),
    };
    let guides = match (&h.file, &h.follicles) {
        (Some(file), None) => GuideSource::File(base.join(file)),
        (None, Some(f)) => {
            if h.transform.is_some() {
                return Err("`transform` applies to guides from a `file`; follicles follow their mesh".into());
            }
            GuideSource::Follicles { mesh: follicle_mesh(f, meshes)?, params: follicles(f)? }
        }
        _ => return Err("give exactly one of `file` and `follicles`".into()),
    };
    let material = match &h.material {
        Some(m) => material(m)?,
        None => Material::Tube(s.tube()),
    };
    let transform = match &h.transform {
        Some(t) => transform(t)?,
        None => Affine3A::IDENTITY,
    };
    let lod = h.lod.as_ref().map(LodToml::params).transpose()?;
    Ok(HairSystemEntry { guides, system: s, material, colors, transform, seed: h.seed, lod })
}

fn follicle_mesh(f: &FolliclesToml, meshes: usize) -> Result<usize, String> {
    match f.mesh {
        m if m >= 1 && m <= meshes => Ok(m - 1),
        m => Err(format!("follicles `mesh = {m}` names no [[mesh]] entry (the scene has {meshes}, numbered from 1)")),
    }
}

fn follicles(f: &FolliclesToml) -> Result<FollicleParams, String> {
    let d = FollicleParams::default();
    let placement = match (f.placement.as_str(), f.count) {
        ("grid", None) => Placement::Grid { u: f.u.unwrap_or(10), v: f.v.unwrap_or(10) },
        ("random", Some(count)) if f.u.is_none() && f.v.is_none() => Placement::Random { count },
        ("grid", Some(_)) => return Err("follicles: `count` goes with `placement = \"random\"`".into()),
        ("random", _) => return Err("follicles: `placement = \"random\"` takes `count` (not `u`, `v`)".into()),
        (p, _) => return Err(format!("follicles: unknown `placement` `{p}` (grid or random)")),
    };
    let [uv_min, uv_max] = f.uv_range.unwrap_or([d.uv_min, d.uv_max]);
    let params = FollicleParams {
        placement,
        randomization: f.randomization.unwrap_or(d.randomization),
        uv_min,
        uv_max,
        points_per_hair: f.points_per_hair.unwrap_or(d.points_per_hair),
        length: f.length.unwrap_or(d.length),
        droop: f.droop.unwrap_or(d.droop),
        gravity: match f.gravity {
            // Normalised here; a zero or non-finite direction fails validation below.
            Some(g) => Vec3::from(g).try_normalize().unwrap_or(Vec3::NAN),
            None => d.gravity,
        },
    };
    params.validate().map_err(|e| format!("follicles: {e}"))?;
    Ok(params)
}

/// A `[[fur]]` entry: its own keys, and every other key a fur attribute.
#[derive(Deserialize)]
struct FurToml {
    /// 1-based, as messages count meshes.
    mesh: i64,
    preset: Option<String>,
    #[serde(default)]
    seed: u32,
    #[serde(default)]
    placement: PlacementToml,
    guides: Option<PathBuf>,
    attractors: Option<AttractorsToml>,
    lod: Option<LodToml>,
    #[serde(flatten)]
    attributes: toml::Table,
}

#[derive(Deserialize, Default)]
#[serde(rename_all = "lowercase")]
enum PlacementToml {
    #[default]
    Area,
    Uv,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct AttractorsToml {
    model: Option<AttractorModelToml>,
    curves_per_fur: Option<u32>,
    global_scale: Option<f32>,
    radius: Option<f32>,
    power: Option<f32>,
    influence: Option<f32>,
    threshold_length: Option<f32>,
}

#[derive(Deserialize)]
#[serde(rename_all = "lowercase")]
enum AttractorModelToml {
    Local,
    Global,
}

fn fur(f: &FurToml, meshes: usize, base: &Path) -> Result<FurEntry, String> {
    if f.mesh < 1 || f.mesh as usize > meshes {
        return Err(format!("`mesh` = {} names no mesh (give 1 to {meshes}, the [[mesh]] entries in order)", f.mesh));
    }
    let mut description = match &f.preset {
        Some(name) => crate::fur::presets::preset(name)?,
        None => FurDescription::default(),
    };
    description.apply_table(&f.attributes, base)?;
    let guides = match (&f.guides, &f.attractors) {
        (Some(file), a) => {
            let d = Attractors::default();
            let a = a.as_ref();
            let attractors = Attractors {
                model: match a.and_then(|a| a.model.as_ref()) {
                    Some(AttractorModelToml::Global) => AttractorModel::Global,
                    Some(AttractorModelToml::Local) => AttractorModel::Local,
                    None => d.model,
                },
                curves_per_fur: a.and_then(|a| a.curves_per_fur).unwrap_or(d.curves_per_fur),
                global_scale: a.and_then(|a| a.global_scale).unwrap_or(d.global_scale),
                radius: a.and_then(|a| a.radius).unwrap_or(d.radius),
                power: a.and_then(|a| a.power).unwrap_or(d.power),
                influence: a.and_then(|a| a.influence).unwrap_or(d.influence),
                threshold_length: a.and_then(|a| a.threshold_length).unwrap_or(d.threshold_length),
            };
            attractors.validate()?;
            Some((HairSource::File(base.join(file)), attractors))
        }
        (None, Some(_)) => return Err("`attractors` needs `guides`".into()),
        (None, None) => None,
    };
    Ok(FurEntry {
        mesh: f.mesh as usize - 1,
        description,
        placement: match f.placement {
            PlacementToml::Area => FurPlacement::Area,
            PlacementToml::Uv => FurPlacement::Uv,
        },
        seed: f.seed,
        guides,
        lod: f.lod.as_ref().map(LodToml::params).transpose()?,
    })
}

/// Reads a scene file. Relative paths inside it are relative to its directory.
pub fn read_scene(path: &Path) -> Result<Description, SceneFileError> {
    let text = std::fs::read_to_string(path).map_err(|source| SceneFileError::Io { path: path.to_owned(), source })?;
    parse_scene(&text, path)
}

/// Reads a scene file and returns with it the warnings of its `[[import]]`s (what the
/// imported files hold that tress skipped).
pub fn read_scene_with_warnings(path: &Path) -> Result<(Description, Vec<String>), SceneFileError> {
    read_scene_frame_with_warnings(path, None)
}

/// Parses scene text; `path` names the file in messages and anchors relative paths.
/// An animated scene is an error here: read it with [`read_scene_frame`]. The warnings of
/// `[[import]]`s are dropped: [`parse_scene_frame`] returns them.
pub fn parse_scene(text: &str, path: &Path) -> Result<Description, SceneFileError> {
    parse_scene_frame(text, path, None).map(|(d, _)| d)
}

/// Reads a scene file at animation frame `frame` (see [`parse_scene_frame`]).
pub fn read_scene_frame(path: &Path, frame: Option<u32>) -> Result<Description, SceneFileError> {
    read_scene_frame_with_warnings(path, frame).map(|(d, _)| d)
}

/// [`read_scene_frame`], with the warnings of the scene's `[[import]]`s.
pub fn read_scene_frame_with_warnings(
    path: &Path,
    frame: Option<u32>,
) -> Result<(Description, Vec<String>), SceneFileError> {
    let text = std::fs::read_to_string(path).map_err(|source| SceneFileError::Io { path: path.to_owned(), source })?;
    parse_scene_frame(&text, path, frame)
}

/// Parses scene text at animation frame `frame`: the camera keys are interpolated at it
/// and every run of `#` in a file name becomes the frame number, zero-padded to the run's
/// length (`hair.####.hair` at frame 7 is `hair.0007.hair`). A scene with keys or
/// patterns needs a frame; a frame given to a scene with neither changes nothing.
/// Returns the warnings of the scene's `[[import]]`s with it.
pub fn parse_scene_frame(
    text: &str,
    path: &Path,
    frame: Option<u32>,
) -> Result<(Description, Vec<String>), SceneFileError> {
    let syntax = |e: toml::de::Error| SceneFileError::Syntax { path: path.to_owned(), message: e.to_string() };
    let invalid = |message: String| SceneFileError::Invalid { path: path.to_owned(), message };
    let scene: SceneToml = toml::from_str(text).map_err(syntax)?;
    let base = path.parent().unwrap_or(Path::new(""));
    let finite = |name: &str, v: &[f32]| -> Result<(), SceneFileError> {
        match v.iter().all(|x| x.is_finite()) {
            true => Ok(()),
            false => Err(invalid(format!("{name} has a value that is not a finite number"))),
        }
    };
    let c = &scene.camera;
    let animated = !c.key.is_empty()
        || scene
            .mesh
            .iter()
            .filter_map(|m| m.file.as_ref())
            .chain(scene.hair.iter().map(|h| &h.file))
            .any(|f| has_pattern(f));
    let frame = match (frame, animated) {
        (None, true) => {
            return Err(invalid(
                "the scene is animated (camera keys or `#` frame patterns in file names): give a frame (--frame F)"
                    .into(),
            ))
        }
        (frame, _) => frame.unwrap_or(0),
    };
    let (eye, target, vfov) = camera_at(c, frame).map_err(|m| invalid(format!("camera: {m}")))?;
    finite("camera", &[eye, target, c.up, [vfov, 0.0, 0.0]].concat())?;
    let r = &scene.render;
    let defaults = RenderSettings::default();
    let integrator = match r.integrator.as_deref() {
        None => defaults.integrator,
        Some(name) => Integrator::from_name(name)
            .ok_or_else(|| invalid(format!("render: unknown `integrator` `{name}` (direct, final-gather or path)")))?,
    };
    let filter = match &r.filter {
        None => defaults.filter,
        Some(f) => f.filter().map_err(|m| invalid(format!("render: {m}")))?,
    };
    let settings = RenderSettings {
        filter,
        width: r.resolution[0],
        height: r.resolution[1],
        spp: r.spp,
        seed: r.seed,
        max_depth: r.max_depth,
        threads: r.threads,
        lod: r.lod,
        integrator,
        transparency_layers: r.transparency_layers.unwrap_or(defaults.transparency_layers),
        gather_rays: r.gather_rays.unwrap_or(defaults.gather_rays),
        adaptive: r.adaptive.as_ref().map(|a| Adaptive {
            min_spp: a.min_spp,
            max_spp: a.max_spp,
            threshold: a.threshold,
        }),
        irradiance_cache: match &r.irradiance_cache {
            None | Some(IrradianceCacheToml::On(false)) => None,
            Some(IrradianceCacheToml::On(true)) => Some(IrradianceCacheSettings::default()),
            Some(IrradianceCacheToml::With(t)) => {
                let d = IrradianceCacheSettings::default();
                Some(IrradianceCacheSettings {
                    accuracy: t.accuracy.unwrap_or(d.accuracy),
                    spacing: t.spacing.unwrap_or(d.spacing),
                    rays: t.rays.unwrap_or(d.rays),
                })
            }
        },
    };
    let mut lights = Vec::new();
    for (i, l) in scene.light.iter().enumerate() {
        lights.push(light(l).map_err(|m| invalid(format!("light {}: {m}", i + 1)))?);
    }
    let mut meshes = Vec::new();
    for (i, m) in scene.mesh.iter().enumerate() {
        let what = |m: String| invalid(format!("mesh {}: {m}", i + 1));
        let source = match (&m.file, &m.shape) {
            (Some(file), None) => MeshSource::File(base.join(at_frame(file, frame))),
            (None, Some(shape)) => MeshSource::Inline(procedural(shape).map_err(what)?),
            _ => return Err(what("give exactly one of `file` and `shape`".into())),
        };
        meshes.push(MeshEntry {
            source,
            material: material(&m.material).map_err(what)?,
            transform: transform(&m.transform).map_err(what)?,
        });
    }
    let mut hair = Vec::new();
    for (i, h) in scene.hair.iter().enumerate() {
        let what = |m: String| invalid(format!("hair {}: {m}", i + 1));
        hair.push(HairEntry {
            source: HairSource::File(base.join(at_frame(&h.file, frame))),
            material: material(&h.material).map_err(what)?,
            transform: transform(&h.transform).map_err(what)?,
            radius_scale: h.radius_scale,
            file_colors: h.file_colors,
            lod: h.lod.as_ref().map(LodToml::params).transpose().map_err(what)?,
        });
    }
    let mut hair_systems = Vec::new();
    for (i, h) in scene.hair_system.iter().enumerate() {
        let entry = hair_system(h, base, meshes.len()).map_err(|m| invalid(format!("hair_system {}: {m}", i + 1)))?;
        hair_systems.push(entry);
    }
    let mut furs = Vec::new();
    for (i, f) in scene.fur.iter().enumerate() {
        furs.push(fur(f, meshes.len(), base).map_err(|m| invalid(format!("fur {}: {m}", i + 1)))?);
    }
    // Imported entries come after the file's own, so `[[mesh]]` numbers stay as written.
    let mut warnings = Vec::new();
    for (i, imp) in scene.import.iter().enumerate() {
        let what = |m: String| invalid(format!("import {}: {m}", i + 1));
        let file = base.join(&imp.file);
        let mut imported = crate::io::imported::read_imported(&file).map_err(|e| what(e.to_string()))?;
        imported.transform(&transform(&imp.transform).map_err(what)?);
        warnings.extend(imported.warnings.iter().map(|w| format!("{}: {w}", file.display())));
        if imp.lights {
            lights.append(&mut imported.lights);
        }
        // Imported fur grows on imported meshes: their numbers move by the meshes before.
        furs.extend(imported.fur.drain(..).map(|f| FurEntry { mesh: f.mesh + meshes.len(), ..f }));
        meshes.append(&mut imported.meshes);
        hair.append(&mut imported.hair);
        hair_systems.append(&mut imported.hair_systems);
    }
    let desc = Description {
        camera: CameraDesc { eye: eye.into(), target: target.into(), up: c.up.into(), vfov },
        settings,
        lights,
        meshes,
        hair,
        hair_systems,
        fur: furs,
    };
    desc.validate().map_err(|e| invalid(e.to_string()))?;
    Ok((desc, warnings))
}

/// Eye, target and field of view at `frame`: the fixed camera, or the keys interpolated
/// linearly (held before the first key and after the last).
fn camera_at(c: &CameraToml, frame: u32) -> Result<(V3, V3, f32), String> {
    let (first, last) = match (c.key.first(), c.key.last()) {
        (None, _) | (_, None) => {
            return match (c.eye, c.target) {
                (Some(eye), Some(target)) => Ok((eye, target, c.vfov)),
                _ => Err("give `eye` and `target`, or camera keys".into()),
            }
        }
        (Some(first), Some(last)) => (first, last),
    };
    if c.eye.is_some() || c.target.is_some() {
        return Err("give either `eye` and `target` or camera keys, not both".into());
    }
    if let Some(w) = c.key.windows(2).find(|w| w[0].frame >= w[1].frame) {
        return Err(format!("key frames must increase: frame {} comes after frame {}", w[1].frame, w[0].frame));
    }
    let vfov = |k: &CameraKeyToml| k.vfov.unwrap_or(c.vfov);
    let key = |k: &CameraKeyToml| (k.eye, k.target, vfov(k));
    if frame <= first.frame {
        return Ok(key(first));
    }
    if frame >= last.frame {
        return Ok(key(last));
    }
    let after = c.key.partition_point(|k| k.frame <= frame);
    let (a, b) = (&c.key[after - 1], &c.key[after]);
    let t = (frame - a.frame) as f32 / (b.frame - a.frame) as f32;
    let lerp3 = |p: V3, q: V3| std::array::from_fn(|i| p[i] + (q[i] - p[i]) * t);
    Ok((lerp3(a.eye, b.eye), lerp3(a.target, b.target), vfov(a) + (vfov(b) - vfov(a)) * t))
}

/// True when a file name holds a `#` frame pattern.
fn has_pattern(file: &Path) -> bool {
    file.file_name().is_some_and(|n| n.to_string_lossy().contains('#'))
}

/// The file name with every run of `#` replaced by `frame`, zero-padded to the run's length.
fn at_frame(file: &Path, frame: u32) -> PathBuf {
    let Some(name) = file.file_name().map(|n| n.to_string_lossy().into_owned()) else { return file.to_owned() };
    if !name.contains('#') {
        return file.to_owned();
    }
    let mut out = String::new();
    let mut chars = name.chars().peekable();
    while let Some(ch) = chars.next() {
        if ch != '#' {
            out.push(ch);
            continue;
        }
        let mut width = 1;
        while chars.next_if_eq(&'#').is_some() {
            width += 1;
        }
        out.push_str(&format!("{frame:0width$}"));
    }
    file.with_file_name(out)
}

fn check(name: &str, v: &[f32], min: f32) -> Result<(), String> {
    match v.iter().all(|x| x.is_finite() && *x >= min) {
        true => Ok(()),
        false if min == 0.0 => Err(format!("`{name}` must be finite and not negative")),
        false => Err(format!("`{name}` must be finite")),
    }
}

fn light(l: &LightToml) -> Result<Light, String> {
    const ANY: f32 = f32::NEG_INFINITY;
    Ok(match *l {
        LightToml::Distant { direction, irradiance, angular_diameter } => {
            check("direction", &direction, ANY)?;
            check("irradiance", &irradiance, 0.0)?;
            if !(0.0..=180.0).contains(&angular_diameter) {
                return Err("`angular_diameter` must be between 0 and 180 degrees".into());
            }
            let direction = Vec3::from(direction).try_normalize().ok_or("`direction` is zero")?;
            Light::distant(direction, irradiance.into(), angular_diameter.to_radians())
        }
        LightToml::Point { position, intensity } => {
            check("position", &position, ANY)?;
            check("intensity", &intensity, 0.0)?;
            Light::Point { position: position.into(), intensity: intensity.into() }
        }
        LightToml::Spot { position, target, intensity, inner_angle, outer_angle } => {
            check("position", &position, ANY)?;
            check("target", &target, ANY)?;
            check("intensity", &intensity, 0.0)?;
            check("angles", &[inner_angle, outer_angle], 0.0)?;
            if inner_angle > outer_angle || outer_angle > 180.0 {
                return Err("need 0 <= inner_angle <= outer_angle <= 180".into());
            }
            let direction = (Vec3::from(target) - Vec3::from(position)).try_normalize().ok_or("target = position")?;
            Light::Spot {
                position: position.into(),
                direction,
                intensity: intensity.into(),
                cos_inner: inner_angle.to_radians().cos(),
                cos_outer: outer_angle.to_radians().cos(),
            }
        }
        LightToml::Quad { corner, edge_u, edge_v, radiance } => {
            check("corner and edges", &[corner, edge_u, edge_v].concat(), ANY)?;
            check("radiance", &radiance, 0.0)?;
            if Vec3::from(edge_u).cross(edge_v.into()).length_squared() == 0.0 {
                return Err("quad edges are parallel or zero".into());
            }
            Light::Quad {
                corner: corner.into(),
                edge_u: edge_u.into(),
                edge_v: edge_v.into(),
                radiance: radiance.into(),
            }
        }
        LightToml::Sphere { center, radius, radiance } => {
            check("center", &center, ANY)?;
            check("radius", &[radius], 0.0)?;
            check("radiance", &radiance, 0.0)?;
            Light::Sphere { center: center.into(), radius, radiance: radiance.into() }
        }
        LightToml::Environment { radiance } => {
            check("radiance", &radiance, 0.0)?;
            Light::Environment { radiance: radiance.into() }
        }
    })
}

fn material(m: &MaterialToml) -> Result<Material, String> {
    Ok(match *m {
        MaterialToml::Diffuse { color } => {
            check("color", &color, 0.0)?;
            Material::Diffuse { color: color.into() }
        }
        MaterialToml::Phong { diffuse, specular, exponent } => {
            check("diffuse, specular and exponent", &[&diffuse[..], &specular[..], &[exponent]].concat(), 0.0)?;
            Material::Phong { diffuse: diffuse.into(), specular: specular.into(), exponent }
        }
        MaterialToml::Mirror { color } => {
            check("color", &color, 0.0)?;
            Material::Mirror { color: color.into() }
        }
        MaterialToml::Glass { ior, color } => {
            check("color", &color, 0.0)?;
            if !(ior.is_finite() && ior >= 1.0) {
                return Err("`ior` must be finite and at least 1".into());
            }
            Material::Glass { ior, color: color.into() }
        }
        MaterialToml::Tube { ambient, diffuse, specular, specular_power } => {
            let ambient = ambient.unwrap_or(diffuse);
            check(
                "tube colours and specular_power",
                &[&ambient[..], &diffuse, &specular, &[specular_power]].concat(),
                0.0,
            )?;
            Material::Tube(Tube {
                ambient: ambient.into(),
                diffuse: diffuse.into(),
                specular: specular.into(),
                specular_power,
            })
        }
        MaterialToml::Physical { eumelanin, pheomelanin, color, from_file, beta_m, beta_n, alpha, eta } => {
            let melanin = eumelanin.is_some() || pheomelanin.is_some();
            let absorption = match (melanin, color, from_file) {
                (true, None, false) => {
                    Absorption::Melanin { eumelanin: eumelanin.unwrap_or(0.0), pheomelanin: pheomelanin.unwrap_or(0.0) }
                }
                (false, Some(c), false) => Absorption::Color(c.into()),
                (false, None, true) => Absorption::FromStrands,
                _ => {
                    return Err(
                        "physical: give exactly one of `eumelanin`/`pheomelanin`, `color` and `from_file = true`"
                            .into(),
                    )
                }
            };
            let params = HairParams { absorption, beta_m, beta_n, alpha_degrees: alpha, eta };
            params.validate().map_err(|m| format!("physical: {m}"))?;
            Material::Physical(PhysicalHair::new(params))
        }
    })
}

fn transform(t: &TransformToml) -> Result<Affine3A, String> {
    let scale = match t.scale {
        None => Vec3::ONE,
        Some(ScaleToml::Uniform(s)) => Vec3::splat(s),
        Some(ScaleToml::Axes(a)) => a.into(),
    };
    check("scale", &scale.to_array(), f32::NEG_INFINITY)?;
    if scale.x * scale.y * scale.z == 0.0 {
        return Err("`scale` must not be zero".into());
    }
    let rotation = match t.rotate {
        None => Quat::IDENTITY,
        Some([x, y, z, deg]) => {
            check("rotate", &[x, y, z, deg], f32::NEG_INFINITY)?;
            let axis = Vec3::new(x, y, z).try_normalize().ok_or("`rotate` axis is zero")?;
            Quat::from_axis_angle(axis, deg.to_radians())
        }
    };
    let translate = t.translate.unwrap_or([0.0; 3]);
    check("translate", &translate, f32::NEG_INFINITY)?;
    Ok(Affine3A::from_scale_rotation_translation(scale, rotation, translate.into()))
}

fn procedural(s: &ShapeToml) -> Result<TriangleMesh, String> {
    Ok(match *s {
        ShapeToml::Torus { major, minor } => {
            check("major and minor", &[major, minor], 0.0)?;
            TriangleMesh::torus(major, minor, 96, 48)
        }
        ShapeToml::Sphere { radius } => {
            check("radius", &[radius], 0.0)?;
            TriangleMesh::sphere(radius, 48)
        }
        ShapeToml::Plane { size } => {
            check("size", &[size], 0.0)?;
            TriangleMesh::plane(size)
        }
        ShapeToml::Pillow { size, thickness } => {
            check("size and thickness", &[size, thickness], 0.0)?;
            TriangleMesh::pillow(size, thickness, 64)
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    const MINIMAL: &str = r#"
[camera]
eye = [0.0, 1.6, 3.2]
target = [0.0, 0.0, 0.0]
"#;

    fn parse(extra: &str) -> Result<Description, SceneFileError> {
        parse_scene(&format!("{MINIMAL}{extra}"), Path::new("dir/test.toml"))
    }

    #[test]
    fn reads_the_issue_example_with_defaults() {
        let d = parse(
            r#"
[render]
resolution = [320, 240]
spp = 4
[[light]]
type = "distant"
direction = [0.45, 0.8, 0.4]
irradiance = [3.0, 3.0, 3.0]
[[mesh]]
file = "torus.obj"
material = { type = "diffuse", color = [0.5, 0.5, 0.5] }
[[hair]]
file = "hairy_torus.hair"
material = { type = "tube", diffuse = [0.35, 0.2, 0.1], specular = [0.3, 0.3, 0.3], specular_power = 40.0 }
"#,
        )
        .unwrap();
        assert_eq!((d.settings.width, d.settings.height, d.settings.spp), (320, 240, 4));
        assert_eq!(d.camera.vfov, 35.0);
        assert_eq!(d.meshes[0].source, MeshSource::File(PathBuf::from("dir/torus.obj")));
        assert_eq!(d.hair[0].source, HairSource::File(PathBuf::from("dir/hairy_torus.hair")));
        match &d.hair[0].material {
            Material::Tube(t) => assert_eq!(t.ambient, t.diffuse),
            m => panic!("{m:?}"),
        }
        match d.lights[0] {
            Light::Distant { direction, .. } => assert!((direction.length() - 1.0).abs() < 1e-6),
            ref l => panic!("{l:?}"),
        }
    }

    #[test]
    fn unknown_key_is_an_error_naming_file_and_key() {
        let e = parse("[render]\nsppp = 4\n").unwrap_err().to_string();
        assert!(e.contains("dir/test.toml") && e.contains("sppp"), "{e}");
        let e = parse("[[light]]\ntype = \"distant\"\ndirection = [0,1,0]\nirradiance = [1,1,1]\ncolour = 1\n")
            .unwrap_err()
            .to_string();
        assert!(e.contains("colour"), "{e}");
    }

    #[test]
    fn wrong_type_and_missing_field_are_errors() {
        let e = parse("[render]\nspp = \"many\"\n").unwrap_err().to_string();
        assert!(e.contains("dir/test.toml") && e.contains("spp"), "{e}");
        let e = parse_scene("[render]\nspp = 4\n", Path::new("s.toml")).unwrap_err().to_string();
        assert!(e.contains("camera"), "{e}");
        let e = parse("[[light]]\ntype = \"laser\"\n").unwrap_err().to_string();
        assert!(e.contains("laser"), "{e}");
    }

    #[test]
    fn out_of_range_values_are_errors() {
        let e = parse("[render]\nresolution = [0, 10]\n").unwrap_err().to_string();
        assert!(e.contains("resolution"), "{e}");
        let e =
            parse("[[light]]\ntype = \"point\"\nposition = [0,1,0]\nintensity = [-1,1,1]\n").unwrap_err().to_string();
        assert!(e.contains("light 1") && e.contains("intensity"), "{e}");
        let e = parse("[[mesh]]\nshape = { type = \"sphere\" }\nfile = \"a.obj\"\nmaterial = { type = \"mirror\" }\n")
            .unwrap_err()
            .to_string();
        assert!(e.contains("mesh 1") && e.contains("exactly one"), "{e}");
        // TOML has inf and nan literals; they must not reach the geometry.
        let e = parse("[[mesh]]\nshape = { type = \"sphere\", radius = nan }\nmaterial = { type = \"mirror\" }\n")
            .unwrap_err()
            .to_string();
        assert!(e.contains("radius"), "{e}");
        let e = parse_scene("[camera]\neye = [inf, 0, 0]\ntarget = [0, 0, 0]\n", Path::new("s.toml")).unwrap_err();
        assert!(e.to_string().contains("camera"), "{e}");
    }

    const HAIR_SYSTEM: &str = r#"
[[mesh]]
shape = { type = "sphere" }
material = { type = "diffuse", color = [0.5, 0.5, 0.5] }
[[hair_system]]
follicles = { mesh = 1, placement = "grid", u = 12, v = 6, points_per_hair = 8, length = 1.5 }
hairs_per_clump = 20
clump_width_scale = [[0.0, 1.0, "linear"], [1.0, 0.2]]
hair_width_scale = [{ position = 0.8, value = 1.0, interp = "smooth" }, { position = 1.0, value = 0.2 }]
clump_curl = 0.6
hair_color = [0.5, 0.3, 0.1]
hair_color_scale = [[0.0, [0.5, 0.5, 0.5], "spline"], [1.0, [1.0, 1.0, 1.0], "spline"]]
noise_method = "clump_uv"
seed = 7
"#;

    #[test]
    fn reads_a_hair_system_with_follicles_and_ramps() {
        let d = parse(HAIR_SYSTEM).unwrap();
        let h = &d.hair_systems[0];
        let GuideSource::Follicles { mesh, params } = &h.guides else { panic!("{:?}", h.guides) };
        assert_eq!((*mesh, params.placement, params.points_per_hair), (0, Placement::Grid { u: 12, v: 6 }, 8));
        assert_eq!((params.length, h.seed, h.system.hairs_per_clump), (1.5, 7, 20));
        assert_eq!(h.system.clump_width, HairSystem::default().clump_width);
        assert!((h.system.clump_width_scale.eval(0.5) - 0.6).abs() < 1e-6);
        assert_eq!(h.system.hair_width_scale.keys()[0].interp, Interp::Smooth);
        assert_eq!(h.system.hair_width_scale.keys()[1].interp, Interp::Linear);
        assert_eq!(h.system.clump_curl.eval(0.3), 0.6);
        assert_eq!(h.system.hair_color_scale.eval(1.0), Vec3::ONE);
        assert_eq!(h.system.noise_method, NoiseMethod::ClumpUv);
        // No material given: tube shading from the hair-system attributes.
        assert_eq!(h.material, Material::Tube(h.system.tube()));
        let d = parse(&format!("{HAIR_SYSTEM}[[hair_system]]\nfile = \"g.hair\"\nfollicles = {{ mesh = 1 }}\n"));
        assert!(d.unwrap_err().to_string().contains("hair_system 2: give exactly one"));
        let d =
            parse("[[hair_system]]\nfile = \"g.hair\"\ncolors = \"guides\"\ntransform = { scale = 2.0 }\n").unwrap();
        assert_eq!(d.hair_systems[0].guides, GuideSource::File(PathBuf::from("dir/g.hair")));
        assert_eq!(d.hair_systems[0].colors, HairColors::Guides);
    }

    #[test]
    fn bad_hair_system_values_name_the_entry_and_attribute() {
        for (bad, words) in [
            ("thinning = nan", &["hair_system 1", "thinning"][..]),
            ("clump_width = -1.0", &["hair_system 1", "clump_width"]),
            ("hairs_per_clump = 0", &["hair_system 1", "hairs_per_clump"]),
            ("clump_flatness = [[0.0, 0.0], [1.5, 1.0]]", &["clump_flatness", "key 2", "position"]),
            ("clump_curl = [[0.0, 2.0]]", &["clump_curl", "key 1"]),
            ("hair_width_scale = [[0.0, 1.0, \"cubic\"]]", &["hair_width_scale", "cubic"]),
            ("hair_color = [0.1, inf, 0.1]", &["hair_color"]),
            ("noise_method = \"perlin\"", &["noise_method", "perlin"]),
            ("colors = \"rainbow\"", &["colors", "rainbow"]),
            ("transform = { scale = 2.0 }", &["transform"]),
            ("hairz = 1", &["hairz"]),
        ] {
            let minimal = &HAIR_SYSTEM[..HAIR_SYSTEM.find("hairs_per_clump").unwrap()];
            let e = parse(&format!("{minimal}{bad}\n")).unwrap_err().to_string();
            assert!(e.contains("dir/test.toml"), "{e}");
            for w in words {
                assert!(e.contains(w), "`{bad}`: {e}");
            }
        }
        for (follicles, words) in [
            ("{ mesh = 2 }", &["mesh = 2", "names no"][..]),
            ("{ mesh = 1, placement = \"random\" }", &["count"]),
            ("{ mesh = 1, placement = \"grid\", count = 4 }", &["count"]),
            ("{ mesh = 1, placement = \"spiral\" }", &["spiral"]),
            ("{ mesh = 1, length = nan }", &["follicles", "length"]),
            ("{ mesh = 1, u = 0 }", &["follicles", "count"]),
            ("{ mesh = 1, uv_range = [[0.5, 0.0], [0.2, 1.0]] }", &["uv_range"]),
            ("{ mesh = 1, gravity = [0.0, 0.0, 0.0] }", &["follicles", "gravity"]),
        ] {
            let text = HAIR_SYSTEM.replace(
                "{ mesh = 1, placement = \"grid\", u = 12, v = 6, points_per_hair = 8, length = 1.5 }",
                follicles,
            );
            let e = parse(&text).unwrap_err().to_string();
            assert!(e.contains("hair_system 1"), "{e}");
            for w in words {
                assert!(e.contains(w), "`{follicles}`: {e}");
            }
        }
    }

    #[test]
    fn lod_tables_take_defaults_and_reject_bad_values() {
        let minimal = &HAIR_SYSTEM[..HAIR_SYSTEM.find("hairs_per_clump").unwrap()];
        let d = parse(&format!("{minimal}lod = {{ levels = 4, start = 8 }}\n[render]\nlod = false\n")).unwrap();
        assert_eq!(d.hair_systems[0].lod, Some(LodParams { levels: 4, start: 8.0, ..Default::default() }));
        assert!(!d.settings.lod);
        let d = parse(&format!("{minimal}lod = {{ spread = 4, smooth = true }}\n")).unwrap();
        assert_eq!(d.hair_systems[0].lod, Some(LodParams { spread: 4.0, smooth: true, ..Default::default() }));
        assert!(parse(minimal).unwrap().settings.lod && parse(minimal).unwrap().hair_systems[0].lod.is_none());
        for (bad, key) in [
            ("decimation = 1.0", "decimation"),
            ("levels = 0", "levels"),
            ("levels = 17", "levels"),
            ("compensation = nan", "compensation"),
            ("start = 0.5", "start"),
            ("decimate = 2.0", "decimate"),
        ] {
            let e = parse(&format!("{minimal}lod = {{ {bad} }}\n")).unwrap_err().to_string();
            assert!(e.contains("dir/test.toml") && e.contains(key), "{bad}: {e}");
        }
        let e = parse("[[hair]]\nfile = \"h.hair\"\nmaterial = { type = \"mirror\" }\nlod = { levels = 99 }\n");
        assert!(e.unwrap_err().to_string().contains("hair 1: lod `levels`"));
    }

    #[test]
    fn physical_hair_material_takes_one_colour_source() {
        let hair =
            |m: &str| parse(&format!("[[hair]]\nfile = \"h.hair\"\nmaterial = {{ type = \"physical\", {m} }}\n"));
        let params = |m: &str| match &hair(m).unwrap().hair[0].material {
            Material::Physical(p) => *p.params(),
            m => panic!("{m:?}"),
        };
        let p = params("eumelanin = 1.3");
        assert_eq!(p, HairParams::default());
        assert_eq!(p.beta_m, 0.3);
        assert_eq!(p.alpha_degrees, 2.0);
        assert_eq!(p.eta, 1.55);
        let p = params("pheomelanin = 0.5, beta_m = 0.1, beta_n = 0.7, alpha = -3.0, eta = 1.6");
        assert_eq!(p.absorption, Absorption::Melanin { eumelanin: 0.0, pheomelanin: 0.5 });
        assert_eq!((p.beta_m, p.beta_n, p.alpha_degrees, p.eta), (0.1, 0.7, -3.0, 1.6));
        assert_eq!(params("color = [0.8, 0.6, 0.3]").absorption, Absorption::Color(Vec3::new(0.8, 0.6, 0.3)));
        assert_eq!(params("from_file = true").absorption, Absorption::FromStrands);
        for bad in [
            "",
            "from_file = false",
            "eumelanin = 1.0, color = [0.5, 0.5, 0.5]",
            "color = [0.5, 0.5, 0.5], from_file = true",
        ] {
            let e = hair(bad).unwrap_err().to_string();
            assert!(e.contains("hair 1") && e.contains("exactly one"), "{bad}: {e}");
        }
        for (bad, key) in [
            ("eumelanin = -1.0", "eumelanin"),
            ("color = [2.0, 0.5, 0.5]", "color"),
            ("eumelanin = 1.0, beta_m = 0.0", "beta_m"),
            ("eumelanin = 1.0, eta = 0.5", "eta"),
            ("eumelanin = 1.0, alpha = 60.0", "alpha"),
        ] {
            let e = hair(bad).unwrap_err().to_string();
            assert!(e.contains("hair 1") && e.contains(key), "{bad}: {e}");
        }
        let e = hair("eumelanin = 1.0, roughness = 0.3").unwrap_err().to_string();
        assert!(e.contains("roughness"), "{e}");
    }

    const MESH: &str = "[[mesh]]\nshape = { type = \"torus\" }\nmaterial = { type = \"diffuse\", color = [1, 1, 1] }\n";

    #[test]
    fn fur_entries_take_a_preset_overrides_maps_and_guides() {
        use crate::fur::{presets::preset, MapSource, Scalar};
        let d = parse(&format!(
            "{MESH}{MESH}[[fur]]\nmesh = 2\npreset = \"Squirrel\"\nseed = 9\nplacement = \"uv\"\nlength = 0.5\n\
             dbw = 0.02\nlength_map = \"len.png\"\nguides = \"g.hair\"\nattractors = {{ model = \"global\", radius = 2.0 }}\n"
        ))
        .unwrap();
        let f = &d.fur[0];
        assert_eq!((f.mesh, f.seed, f.placement), (1, 9, FurPlacement::Uv));
        let mut expected = preset("Squirrel").unwrap();
        expected[Scalar::Length].value = 0.5;
        expected[Scalar::BaseWidth].value = 0.02;
        expected[Scalar::Length].map = Some(MapSource::Image(PathBuf::from("dir/len.png")));
        assert_eq!(f.description, expected);
        let (source, a) = f.guides.as_ref().unwrap();
        assert_eq!(source, &HairSource::File(PathBuf::from("dir/g.hair")));
        assert_eq!((a.model, a.radius, a.power), (AttractorModel::Global, 2.0, 1.0));
        // Without a preset: Maya's node defaults.
        let d = parse(&format!("{MESH}[[fur]]\nmesh = 1\n")).unwrap();
        assert_eq!(d.fur[0].description, FurDescription::default());
    }

    #[test]
    fn bad_fur_entries_are_errors_naming_the_entry_and_key() {
        for (entry, needles) in [
            ("mesh = 2", &["fur 1", "mesh"][..]),
            ("mesh = 0", &["fur 1", "mesh"]),
            ("mesh = 1\ndensity = -5", &["fur 1", "density", "-5"]),
            ("mesh = 1\nlength = nan", &["fur 1", "length", "finite"]),
            ("mesh = 1\nbaldness = 2", &["fur 1", "baldness", "0 to 1"]),
            ("mesh = 1\nfluffiness = 2", &["fur 1", "fluffiness"]),
            ("mesh = 1\npreset = \"Chinchilla\"", &["fur 1", "Chinchilla", "Duckling"]),
            ("mesh = 1\nattractors = { radius = 1.0 }", &["fur 1", "guides"]),
            ("mesh = 1\nguides = \"g.hair\"\nattractors = { radius = -1.0 }", &["fur 1", "radius"]),
            ("mesh = 1\nguides = \"g.hair\"\nattractors = { pull = 1.0 }", &["pull"]),
            ("mesh = 1\nplacement = \"random\"", &["random"]),
        ] {
            let e = parse(&format!("{MESH}[[fur]]\n{entry}\n")).unwrap_err().to_string();
            assert!(e.contains("dir/test.toml"), "{e}");
            for n in needles {
                assert!(e.contains(n), "{entry}: `{e}` lacks `{n}`");
            }
        }
    }

    const KEYS: &str = r#"
[camera]
vfov = 40.0
[[camera.key]]
frame = 10
eye = [0.0, 0.0, 10.0]
target = [0.0, 0.0, 0.0]
[[camera.key]]
frame = 20
eye = [10.0, 0.0, 0.0]
target = [0.0, 2.0, 0.0]
vfov = 20.0
[[hair]]
file = "sim/hair.####.hair"
material = { type = "diffuse", color = [1, 1, 1] }
[[mesh]]
file = "ground_#.obj"
material = { type = "diffuse", color = [1, 1, 1] }
"#;

    #[test]
    fn camera_keys_interpolate_and_frame_patterns_substitute() {
        let path = Path::new("dir/anim.toml");
        let at = |f| parse_scene_frame(KEYS, path, Some(f)).unwrap().0;
        let d = at(15);
        assert_eq!(d.camera.eye, Vec3::new(5.0, 0.0, 5.0));
        assert_eq!(d.camera.target, Vec3::new(0.0, 1.0, 0.0));
        assert_eq!(d.camera.vfov, 30.0);
        assert_eq!(d.hair[0].source, HairSource::File(PathBuf::from("dir/sim/hair.0015.hair")));
        assert_eq!(d.meshes[0].source, MeshSource::File(PathBuf::from("dir/ground_15.obj")));
        // Held before the first key and after the last.
        assert_eq!((at(0).camera.eye, at(0).camera.vfov), (Vec3::new(0.0, 0.0, 10.0), 40.0));
        assert_eq!((at(99).camera.eye, at(99).camera.vfov), (Vec3::new(10.0, 0.0, 0.0), 20.0));
        assert_eq!(at(12345).hair[0].source, HairSource::File(PathBuf::from("dir/sim/hair.12345.hair")));
        let e = parse_scene(KEYS, path).unwrap_err().to_string();
        assert!(e.contains("dir/anim.toml") && e.contains("--frame"), "{e}");
        // A still scene ignores the frame.
        assert_eq!(parse_scene_frame(MINIMAL, path, Some(3)).unwrap().0, parse_scene(MINIMAL, path).unwrap());
    }

    #[test]
    fn bad_camera_paths_are_errors() {
        let path = Path::new("a.toml");
        let both = KEYS.replace("vfov = 40.0", "vfov = 40.0\neye = [1, 1, 1]");
        assert!(parse_scene_frame(&both, path, Some(1)).unwrap_err().to_string().contains("not both"));
        let order = KEYS.replace("frame = 20", "frame = 10");
        assert!(parse_scene_frame(&order, path, Some(1)).unwrap_err().to_string().contains("must increase"));
        let e = parse_scene_frame("[camera]\nvfov = 3.0\n", path, None).unwrap_err().to_string();
        assert!(e.contains("give `eye` and `target`"), "{e}");
        let nan = KEYS.replace("target = [0.0, 2.0, 0.0]", "target = [0.0, nan, 0.0]");
        assert!(parse_scene_frame(&nan, path, Some(15)).unwrap_err().to_string().contains("camera"));
    }

    #[test]
    fn transforms_compose_scale_rotate_translate() {
        let t = transform(&TransformToml {
            translate: Some([1.0, 0.0, 0.0]),
            rotate: Some([0.0, 1.0, 0.0, 90.0]),
            scale: Some(ScaleToml::Uniform(2.0)),
        })
        .unwrap();
        let p = t.transform_point3(Vec3::X);
        assert!((p - Vec3::new(1.0, 0.0, -2.0)).length() < 1e-5, "{p}");
    }

    #[test]
    fn reads_the_pixel_filter() {
        assert_eq!(parse("").unwrap().settings.filter, PixelFilter::Box);
        assert_eq!(parse("[render]\nfilter = \"box\"\n").unwrap().settings.filter, PixelFilter::Box);
        assert_eq!(parse("[render]\nfilter = \"gaussian\"\n").unwrap().settings.filter, PixelFilter::gaussian(1.5));
        let d = parse("[render]\nfilter = { type = \"gaussian\", radius = 2.0, sigma = 0.8 }\n").unwrap();
        assert_eq!(d.settings.filter, PixelFilter::Gaussian { radius: 2.0, sigma: 0.8 });
        for (bad, names) in [
            ("filter = \"mitchell\"", "mitchell"),
            ("filter = { type = \"gaussian\", radius = -1.0 }", "radius"),
            ("filter = { type = \"box\", radius = 2.0 }", "box"),
        ] {
            let e = parse(&format!("[render]\n{bad}\n")).unwrap_err().to_string();
            assert!(e.contains("dir/test.toml") && e.contains(names), "{e}");
        }
    }
}
