//! Scene files in TOML (documented in `docs/scene-format.md`), read into a
//! [`Description`]. Unknown keys and wrong types are errors naming the file, line and key.
//!
//! An animated scene (camera keys, or file names with `#` runs standing for the frame
//! number) is read at one frame: the camera is interpolated and the frame substituted.

use crate::geometry::TriangleMesh;
use crate::light::Light;
use crate::scene::{CameraDesc, Description, HairEntry, HairSource, MeshEntry, MeshSource, RenderSettings};
use crate::shading::{tube::Tube, Material};
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
}

impl Default for RenderToml {
    fn default() -> Self {
        let d = RenderSettings::default();
        RenderToml { resolution: [d.width, d.height], spp: d.spp, seed: d.seed, max_depth: d.max_depth, threads: 0 }
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
}
fn default_radius_scale() -> f32 {
    1.0
}
fn default_true() -> bool {
    true
}

/// Reads a scene file. Relative paths inside it are relative to its directory.
pub fn read_scene(path: &Path) -> Result<Description, SceneFileError> {
    let text = std::fs::read_to_string(path).map_err(|source| SceneFileError::Io { path: path.to_owned(), source })?;
    parse_scene(&text, path)
}

/// Parses scene text; `path` names the file in messages and anchors relative paths.
/// An animated scene is an error here: read it with [`read_scene_frame`].
pub fn parse_scene(text: &str, path: &Path) -> Result<Description, SceneFileError> {
    parse_scene_frame(text, path, None)
}

/// Reads a scene file at animation frame `frame` (see [`parse_scene_frame`]).
pub fn read_scene_frame(path: &Path, frame: Option<u32>) -> Result<Description, SceneFileError> {
    let text = std::fs::read_to_string(path).map_err(|source| SceneFileError::Io { path: path.to_owned(), source })?;
    parse_scene_frame(&text, path, frame)
}

/// Parses scene text at animation frame `frame`: the camera keys are interpolated at it
/// and every run of `#` in a file name becomes the frame number, zero-padded to the run's
/// length (`hair.####.hair` at frame 7 is `hair.0007.hair`). A scene with keys or
/// patterns needs a frame; a frame given to a scene with neither changes nothing.
pub fn parse_scene_frame(text: &str, path: &Path, frame: Option<u32>) -> Result<Description, SceneFileError> {
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
    let settings = RenderSettings {
        width: r.resolution[0],
        height: r.resolution[1],
        spp: r.spp,
        seed: r.seed,
        max_depth: r.max_depth,
        threads: r.threads,
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
        });
    }
    let desc = Description {
        camera: CameraDesc { eye: eye.into(), target: target.into(), up: c.up.into(), vfov },
        settings,
        lights,
        meshes,
        hair,
    };
    desc.validate().map_err(|e| invalid(e.to_string()))?;
    Ok(desc)
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
        LightToml::Distant { direction, irradiance } => {
            check("direction", &direction, ANY)?;
            check("irradiance", &irradiance, 0.0)?;
            let direction = Vec3::from(direction).try_normalize().ok_or("`direction` is zero")?;
            Light::Distant { direction, irradiance: irradiance.into() }
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
        let at = |f| parse_scene_frame(KEYS, path, Some(f)).unwrap();
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
        assert_eq!(parse_scene_frame(MINIMAL, path, Some(3)).unwrap(), parse_scene(MINIMAL, path).unwrap());
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
}
