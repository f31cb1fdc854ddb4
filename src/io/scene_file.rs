//! Scene files in TOML (documented in `docs/scene-format.md`), read into a
//! [`Description`]. Unknown keys and wrong types are errors naming the file, line and key.

use crate::fur::{AttractorModel, Attractors, FurDescription, Placement};
use crate::geometry::TriangleMesh;
use crate::light::Light;
use crate::scene::{CameraDesc, Description, FurEntry, HairEntry, HairSource, MeshEntry, MeshSource, RenderSettings};
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
    #[serde(default)]
    fur: Vec<FurToml>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct CameraToml {
    eye: V3,
    target: V3,
    #[serde(default = "default_up")]
    up: V3,
    #[serde(default = "default_vfov")]
    vfov: f32,
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
}
fn default_radius_scale() -> f32 {
    1.0
}
fn default_true() -> bool {
    true
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
            PlacementToml::Area => Placement::Area,
            PlacementToml::Uv => Placement::Uv,
        },
        seed: f.seed,
        guides,
    })
}

/// Reads a scene file. Relative paths inside it are relative to its directory.
pub fn read_scene(path: &Path) -> Result<Description, SceneFileError> {
    let text = std::fs::read_to_string(path).map_err(|source| SceneFileError::Io { path: path.to_owned(), source })?;
    parse_scene(&text, path)
}

/// Parses scene text; `path` names the file in messages and anchors relative paths.
pub fn parse_scene(text: &str, path: &Path) -> Result<Description, SceneFileError> {
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
    finite("camera", &[c.eye, c.target, c.up].concat())?;
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
            (Some(file), None) => MeshSource::File(base.join(file)),
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
            source: HairSource::File(base.join(&h.file)),
            material: material(&h.material).map_err(what)?,
            transform: transform(&h.transform).map_err(what)?,
            radius_scale: h.radius_scale,
            file_colors: h.file_colors,
        });
    }
    let mut furs = Vec::new();
    for (i, f) in scene.fur.iter().enumerate() {
        furs.push(fur(f, meshes.len(), base).map_err(|m| invalid(format!("fur {}: {m}", i + 1)))?);
    }
    let desc = Description {
        camera: CameraDesc { eye: c.eye.into(), target: c.target.into(), up: c.up.into(), vfov: c.vfov },
        settings,
        lights,
        meshes,
        hair,
        fur: furs,
    };
    desc.validate().map_err(|e| invalid(e.to_string()))?;
    Ok(desc)
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
        assert_eq!((f.mesh, f.seed, f.placement), (1, 9, Placement::Uv));
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
