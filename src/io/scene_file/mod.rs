//! Scene files in TOML (documented in `docs/scene-format.md`), read into a
//! [`Description`] by [`read`] (or [`parse`] for text in memory). Unknown keys and wrong
//! types are errors naming the file, line and key.
//!
//! - `schema`: what each table may hold (serde), defaults from the domain types.
//! - `convert`: tables into lights, materials, transforms, hair systems, fur.
//! - `animation`: camera keys and `#` frame patterns at one frame.
//!
//! `[[import]]` entries bring in other tools' scenes through [`crate::io::read_imported`].

mod animation;
mod convert;
mod schema;

use crate::scene::{
    CameraDesc, CameraProjection, Contents, Description, HairEntry, HairSource, MeshEntry, MeshSource, Visibility,
};
use crate::world::{Adaptive, Integrator, IrradianceCacheSettings, RenderSettings};
pub use animation::{at_frame, has_pattern};
use animation::{camera_at, frame_warning};
use convert::{fur, hair_system, light, material, procedural, transform, visibility_keys};
use schema::{IrradianceCacheToml, LodToml, ProjectionToml, SceneToml};

/// An orthographic camera's window height in scene units when the scene gives none (the
/// size of pbrt's default screen window, from -1 to 1).
const DEFAULT_ORTHO_HEIGHT: f32 = 2.0;
use std::path::{Path, PathBuf};

/// Why a scene file cannot be read.
#[derive(Debug, thiserror::Error)]
pub enum SceneFileError {
    /// The file cannot be opened or read (not a regular file, too large, missing).
    #[error(transparent)]
    Read(#[from] crate::error::LoadError),
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

/// Reads the scene file `path` at animation frame `frame` (see [`parse`]). Relative paths
/// inside it are relative to its directory. Returns the warnings of its `[[import]]`s
/// (what the imported files hold that tress skipped) with it.
pub fn read(path: &Path, frame: Option<u32>) -> Result<(Description, Vec<String>), SceneFileError> {
    let text = crate::input_file::read_text(path, crate::input_file::Kind::Scene)?;
    parse(&text, path, frame)
}

/// Parses scene text at animation frame `frame`; `path` names the file in messages and
/// anchors relative paths. At a frame the camera keys are interpolated at it
/// and every run of `#` in a file name becomes the frame number, zero-padded to the run's
/// length (`hair.####.hair` at frame 7 is `hair.0007.hair`). A scene with keys or
/// patterns needs a frame; a frame given to a scene with neither changes nothing.
/// Returns with it the warnings of the scene's `[[import]]`s and of a frame outside its
/// camera keys (or given to a scene that is not animated).
pub fn parse(text: &str, path: &Path, frame: Option<u32>) -> Result<(Description, Vec<String>), SceneFileError> {
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
    let animated = scene.camera.as_ref().is_some_and(|c| !c.key.is_empty())
        || scene
            .mesh
            .iter()
            .filter_map(|m| m.file.as_ref())
            .chain(scene.hair.iter().map(|h| &h.file))
            .any(|f| has_pattern(f));
    let frame_warning = frame.and_then(|f| scene.camera.as_ref().and_then(|c| frame_warning(c, animated, f)));
    let frame = match (frame, animated) {
        (None, true) => {
            return Err(invalid(
                "the scene is animated (camera keys or `#` frame patterns in file names): give a frame (--frame F)"
                    .into(),
            ))
        }
        (frame, _) => frame.unwrap_or(0),
    };
    let camera = match &scene.camera {
        Some(c) => {
            let (eye, target, vfov) = camera_at(c, frame).map_err(|m| invalid(format!("camera: {m}")))?;
            for (key, v) in [("eye", &eye[..]), ("target", &target[..]), ("up", &c.up[..]), ("vfov", &[vfov][..])] {
                finite(&format!("camera `{key}`"), v)?;
            }
            let clip = c.clip.unwrap_or(CameraDesc::default().clip);
            if !(clip[0] >= 0.0 && clip[0].is_finite() && clip[1] > clip[0]) {
                return Err(invalid(format!(
                    "camera `clip` [{}, {}]: give [near, far] with a finite near >= 0 and a larger far (inf for none)",
                    clip[0], clip[1]
                )));
            }
            let projection = match (c.projection, c.ortho_height) {
                (ProjectionToml::Perspective, None) => CameraProjection::Perspective,
                (ProjectionToml::Perspective, Some(_)) => {
                    return Err(invalid("camera `ortho_height` is for `projection = \"orthographic\"`".into()))
                }
                (ProjectionToml::Orthographic, height) => {
                    let height = height.unwrap_or(DEFAULT_ORTHO_HEIGHT);
                    if !(height.is_finite() && height > 0.0) {
                        return Err(invalid(format!(
                            "camera `ortho_height` {height}: give the window's height, a finite positive length"
                        )));
                    }
                    CameraProjection::Orthographic { height }
                }
            };
            Some(CameraDesc {
                eye: eye.into(),
                target: target.into(),
                up: c.up.into(),
                vfov,
                projection,
                film: None,
                clip,
                window: crate::scene::FULL_SCREEN,
            })
        }
        None => None,
    };
    let r = &scene.render;
    let defaults = RenderSettings::default();
    let integrator = match r.integrator.as_deref() {
        None => defaults.integrator,
        Some(name) => name.parse::<Integrator>().map_err(|m| invalid(format!("render: {m}")))?,
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
        indirect_hair_roughness: r.indirect_hair_roughness,
        max_sample_value: r.max_sample_value,
        threads: r.threads,
        lod: r.lod,
        integrator,
        transparency_layers: r.transparency_layers,
        gather_rays: r.gather_rays,
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
    let mut contents = Contents::default();
    for (i, l) in scene.light.iter().enumerate() {
        contents.lights.extend(light(l, base).map_err(|m| invalid(format!("light {}: {m}", i + 1)))?);
    }
    for (i, m) in scene.mesh.iter().enumerate() {
        let what = |m: String| invalid(format!("mesh {}: {m}", i + 1));
        let source = match (&m.file, &m.shape) {
            (Some(file), None) => MeshSource::File(base.join(at_frame(file, frame))),
            (None, Some(shape)) => MeshSource::Inline(procedural(shape).map_err(what)?),
            _ => return Err(what("give exactly one of `file` and `shape`".into())),
        };
        contents.meshes.push(MeshEntry {
            source,
            material: material(&m.material, base).map_err(what)?,
            transform: transform(&m.transform).map_err(what)?,
            visibility: visibility_keys(Visibility::default(), (m.camera_visible, m.casts_shadows, m.matte)),
        });
    }
    for (i, h) in scene.hair.iter().enumerate() {
        let what = |m: String| invalid(format!("hair {}: {m}", i + 1));
        contents.hair.push(HairEntry {
            source: HairSource::File(base.join(at_frame(&h.file, frame))),
            material: material(&h.material, base).map_err(what)?,
            transform: transform(&h.transform).map_err(what)?,
            radius_scale: h.radius_scale,
            file_colors: h.file_colors,
            lod: h.lod.as_ref().map(LodToml::params).transpose().map_err(what)?,
            visibility: visibility_keys(Visibility::default(), (h.camera_visible, h.casts_shadows, h.matte)),
        });
    }
    for (i, h) in scene.hair_system.iter().enumerate() {
        let entry =
            hair_system(h, base, contents.meshes.len()).map_err(|m| invalid(format!("hair_system {}: {m}", i + 1)))?;
        contents.hair_systems.push(entry);
    }
    for (i, f) in scene.fur.iter().enumerate() {
        let entry = fur(f, contents.meshes.len(), base).map_err(|m| invalid(format!("fur {}: {m}", i + 1)))?;
        contents.fur.push(entry);
    }
    // Imported entries come after the file's own, so `[[mesh]]` numbers stay as written.
    let mut warnings: Vec<String> = frame_warning.into_iter().collect();
    for (i, imp) in scene.import.iter().enumerate() {
        let what = |m: String| invalid(format!("import {}: {m}", i + 1));
        let file = base.join(&imp.file);
        let mut imported = crate::io::read_imported(&file).map_err(|e| what(e.to_string()))?;
        imported.transform(&transform(&imp.transform).map_err(what)?);
        let positive = |name: &str, v: Option<f32>| match v {
            Some(v) if !(v.is_finite() && v > 0.0) => Err(what(format!("`{name}` must be a positive number"))),
            _ => Ok(v),
        };
        if let Some(w) = positive("width", imp.width)? {
            crate::io::override_hair_width(&mut imported.contents, w).map_err(|e| what(e.to_string()))?;
        }
        if let Some(k) = positive("radius_scale", imp.radius_scale)? {
            imported.contents.scale_hair_radius(k);
        }
        warnings.extend(imported.warnings.iter().map(|w| format!("{}: {w}", file.display())));
        if !imp.lights {
            imported.contents.lights.clear();
        }
        for v in imported.contents.visibilities_mut() {
            *v = visibility_keys(*v, (imp.camera_visible, imp.casts_shadows, imp.matte));
        }
        contents.append(imported.contents);
    }
    let mut desc = Description { camera: camera.clone().unwrap_or_default(), settings, contents };
    if camera.is_none() {
        let bounds = crate::io::bounds(&desc.contents).map_err(|e| invalid(e.to_string()))?;
        desc.camera = crate::io::imported::framing_camera(&bounds);
        warnings.push("the scene has no [camera]: framing the geometry from the front".into());
    }
    desc.validate().map_err(|e| invalid(e.to_string()))?;
    Ok((desc, warnings))
}

#[cfg(test)]
mod tests;
