//! File formats: scene TOML ([`scene_file`]), OBJ and PLY meshes, Cem Yuksel `.hair`
//! strands ([`cem_hair`]), and other tools' scenes (Maya ASCII, pbrt-v4, USD text) as an
//! [`imported::Imported`]. Images (environment maps, textures, fur maps) are named by path
//! and read by `prepare`. The readers produce [`crate::scene`] descriptions and entries;
//! the dispatch by extension ([`read_mesh`], [`read_imported`]) is here, so no reader
//! imports another.

pub mod arnold_graph;
pub mod arnold_hair;
pub mod arnold_light;
pub mod arnold_surface;
pub mod ass;
pub mod cem_hair;
pub mod gzip;
pub mod imported;
pub mod maya_ascii;
pub mod obj;
pub mod pbrt;
pub mod ply;
pub mod reference_scene;
pub mod scene_file;
pub mod usd;

use crate::error::LoadError;
use crate::geometry::TriangleMesh;
use crate::math::Aabb;
use crate::scene::{Contents, GuideSource, HairSource, MeshSource};
use std::path::Path;

/// Reads a mesh, choosing the format by the file extension (`.obj` or `.ply`).
pub fn read_mesh(path: &Path) -> Result<TriangleMesh, LoadError> {
    match extension(path).as_deref() {
        Some("obj") => obj::read_obj(path),
        Some("ply") => ply::read_ply(path),
        _ => Err(LoadError::format(path, "unknown mesh format: expected a .obj or .ply file")),
    }
}

/// The formats [`read_imported`] reads, by extension: other tools' scenes, and raw
/// geometry (`.hair` strands, `.ply` and `.obj` meshes or polyline strands).
pub const IMPORTED_EXTENSIONS: [&str; 10] = ["ma", "ass", "pbrt", "usda", "usdc", "usdz", "usd", "hair", "ply", "obj"];

/// What to read of a file that holds more than one frame or camera.
#[derive(Clone, Debug, Default)]
pub struct ImportOptions {
    /// The frame (a USD time code, a Maya frame); `None` reads the file's start (USD's
    /// `startTimeCode`, Maya's saved current time).
    pub frame: Option<u32>,
    /// The camera to render through, by its prim path (USD) or its transform's or shape's
    /// name (Maya); `None` takes the file's first (Maya: other than `persp`).
    pub camera: Option<String>,
    /// Prims not to draw, by path patterns (`*` any run of characters, `?` one), as an
    /// Arnold `disable` operator on a `usd` procedural selects them; read by USD files.
    pub hidden: Vec<String>,
    /// Read a USD stage in its own axes, as Arnold's `usd` procedural does: a Z-up stage is
    /// not turned to Y up.
    pub stage_axes: bool,
}

/// True when `path` names a file [`read_imported`] reads (by its extension).
pub fn is_imported(path: &Path) -> bool {
    extension(path).is_some_and(|e| IMPORTED_EXTENSIONS.contains(&e.as_str()))
}

/// The file's extension, lowercase; `ass` for a gzipped Arnold scene (`.ass.gz`).
fn extension(path: &Path) -> Option<String> {
    let ext = path.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase);
    let stem_ext = || Path::new(path.file_stem()?).extension()?.to_str().map(str::to_ascii_lowercase);
    match ext.as_deref() {
        Some("gz") if stem_ext().as_deref() == Some("ass") => Some("ass".into()),
        _ => ext,
    }
}

/// Reads a Maya ASCII (`.ma`), Arnold (`.ass`, `.ass.gz`), pbrt (`.pbrt`) or USD (`.usda`,
/// `.usdc`, `.usdz`, `.usd`) scene, or a raw geometry file (`.hair`, `.ply`, `.obj`) as a scene holding just that
/// geometry, choosing the reader by the file's extension. Strands without widths are given
/// [`imported::RELATIVE_WIDTH`] of the scene's size, reported once.
pub fn read_imported(path: &Path) -> Result<imported::Imported, LoadError> {
    read_imported_with(path, &ImportOptions::default())
}

/// [`read_imported`] at a frame and through a camera of the file's.
pub fn read_imported_with(path: &Path, options: &ImportOptions) -> Result<imported::Imported, LoadError> {
    use imported::{raw_mesh, raw_strands};
    let ext = extension(path);
    if options.camera.is_some() && !matches!(ext.as_deref(), Some("ma" | "ass" | "usda" | "usdc" | "usdz" | "usd")) {
        return Err(no_named_cameras(path));
    }
    let mut imported = match ext.as_deref() {
        Some("ma") => maya_ascii::read_maya(path, options.camera.as_deref(), options.frame)?,
        Some("ass") => read_ass_tree(path, options, &mut vec![canonical(path)])?,
        Some("pbrt") => pbrt::read_pbrt(path)?,
        Some("usda" | "usdc" | "usdz" | "usd") => usd::read_usd(path, options)?,
        Some("hair") => raw_strands(cem_hair::read_hair(path)?),
        Some("ply") => match ply::read_ply_geometry(path)? {
            ply::PlyGeometry::Mesh(m) => raw_mesh(m),
            ply::PlyGeometry::Strands { strands, .. } => raw_strands(strands),
        },
        Some("obj") => match obj::read_obj_geometry(path)? {
            obj::ObjGeometry::Mesh(m) => raw_mesh(m),
            obj::ObjGeometry::Strands(s) => raw_strands(s),
        },
        _ => {
            return Err(LoadError::format(
                path,
                "unknown scene format: expected a .ma, .ass, .ass.gz, .pbrt, .usda, .usdc, .usdz, .usd, .hair, .ply or .obj file",
            ))
        }
    };
    imported.give_widths();
    Ok(imported)
}

/// Most `.ass` files pulled in inside each other by procedurals (an `.ass` whose procedural
/// names an `.ass` whose procedural names another ...).
const MAX_PROCEDURAL_DEPTH: usize = 16;

/// The path as the file system resolves it (for finding cycles), else as given.
fn canonical(path: &Path) -> std::path::PathBuf {
    path.canonicalize().unwrap_or_else(|_| path.to_path_buf())
}

/// An Arnold scene with the files its procedurals pull in, each read by the reader of its
/// format at the procedural's frame and placed by its matrix; `chain` holds the `.ass`
/// files being read, outermost first, so that one pulling itself back in is an error.
fn read_ass_tree(
    path: &Path,
    options: &ImportOptions,
    chain: &mut Vec<std::path::PathBuf>,
) -> Result<imported::Imported, LoadError> {
    let scene = ass::read_ass(path, options.camera.as_deref())?;
    let mut out = scene.imported;
    for p in scene.procedurals {
        if !p.path.exists() {
            // Arnold reports a procedural it cannot load and renders the rest.
            out.warnings.push(format!("procedural `{}`: {} is missing: not drawn", p.node, p.path.display()));
            continue;
        }
        let options = ImportOptions {
            frame: p.frame.or(options.frame),
            camera: None,
            hidden: p.disabled.clone(),
            stage_axes: true,
        };
        let mut inner = match extension(&p.path).as_deref() {
            Some("ass") => {
                let file = canonical(&p.path);
                if chain.contains(&file) {
                    let names: Vec<String> = chain.iter().chain([&file]).map(|f| f.display().to_string()).collect();
                    let message =
                        format!("procedural `{}` pulls in a file already being read: {}", p.node, names.join(" -> "));
                    return Err(LoadError::invalid(path, message));
                }
                if chain.len() >= MAX_PROCEDURAL_DEPTH {
                    let message =
                        format!("procedural `{}`: procedurals nest deeper than {MAX_PROCEDURAL_DEPTH} files", p.node);
                    return Err(LoadError::invalid(path, message));
                }
                chain.push(file);
                let inner = read_ass_tree(&p.path, &options, chain);
                chain.pop();
                inner?
            }
            Some("usda" | "usdc" | "usdz" | "usd") => usd::read_usd(&p.path, &options)?,
            _ => {
                let message =
                    format!("procedurals of files tress does not read as procedurals: not drawn ({})", p.node);
                out.warnings.push(format!("{message}: {}", p.path.display()));
                continue;
            }
        };
        inner.transform(&p.transform);
        if let Some(shader) = p.shader {
            for mesh in &mut inner.contents.meshes {
                mesh.material = shader.clone().into();
            }
        }
        out.contents.append(inner.contents);
        let name =
            p.path.file_name().map_or_else(|| p.path.display().to_string(), |f| f.to_string_lossy().into_owned());
        out.warnings.extend(inner.warnings.into_iter().map(|w| format!("{name}: {w}")));
    }
    Ok(out)
}

/// The bounds in world space of `contents`' meshes, strand sets and guides, those in memory
/// ([`Contents::bounds`]) and those named by file, which are read (fur and hair grown from
/// follicles add what they grow on).
pub fn bounds(contents: &Contents) -> Result<Aabb, LoadError> {
    let mut b = contents.bounds();
    for e in &contents.meshes {
        if let MeshSource::File(path) = &e.source {
            b = b.union(read_mesh(path)?.bounds_under(&e.transform));
        }
    }
    for e in &contents.hair {
        if let HairSource::File(path) = &e.source {
            b = b.union(cem_hair::read_hair(path)?.bounds_under(&e.transform));
        }
    }
    for e in &contents.hair_systems {
        if let GuideSource::File(path) = &e.guides {
            b = b.union(cem_hair::read_hair(path)?.bounds_under(&e.transform));
        }
    }
    Ok(b)
}

/// Draws every strand of `contents` `width` wide (`--hair-width`): strand sets, read from
/// their files if need be, and hair systems ([`Contents::set_hair_width`]).
pub fn override_hair_width(contents: &mut Contents, width: f32) -> Result<(), LoadError> {
    for e in &mut contents.hair {
        if let HairSource::File(path) = &e.source {
            e.source = HairSource::Inline(cem_hair::read_hair(path)?);
        }
    }
    contents.set_hair_width(width);
    Ok(())
}

/// The error for a camera asked for by name in a file whose cameras have none.
fn no_named_cameras(path: &Path) -> LoadError {
    LoadError::invalid(
        path,
        "has no cameras to choose by name (--camera takes a USD camera's prim path or a Maya or Arnold camera's name)",
    )
}

/// Why [`read_scene`] cannot read a scene.
#[derive(Debug, thiserror::Error)]
pub enum ReadSceneError {
    /// A scene TOML that cannot be read or does not match the scene format.
    #[error(transparent)]
    SceneFile(#[from] scene_file::SceneFileError),
    /// Another tool's scene or a reference scene directory that cannot be read.
    #[error(transparent)]
    Load(#[from] LoadError),
}

/// Reads any scene `tress render` takes: a reference scene directory (`scene.json`), a
/// Maya ASCII, pbrt, USD text or raw .hair, .ply or .obj file (by extension), or a scene TOML at `frame`.
/// Returns the description and the reader's warnings, each prefixed with the file's name.
pub fn read_scene(path: &Path, frame: Option<u32>) -> Result<(crate::scene::Description, Vec<String>), ReadSceneError> {
    read_scene_with(path, &ImportOptions { frame, camera: None, ..Default::default() })
}

/// [`read_scene`] through a camera of the file's (USD files with several).
pub fn read_scene_with(
    path: &Path,
    options: &ImportOptions,
) -> Result<(crate::scene::Description, Vec<String>), ReadSceneError> {
    let frame = options.frame;
    if path.is_dir() && options.camera.is_some() {
        return Err(no_named_cameras(path).into());
    }
    if path.is_dir() {
        return Ok((reference_scene::read_reference_scene(path)?, Vec::new()));
    }
    let (desc, mut warnings) = if is_imported(path) {
        read_imported_with(path, options)?.into_description()
    } else if options.camera.is_some() {
        return Err(no_named_cameras(path).into());
    } else if let Some(kind) = image_kind(path) {
        // Anything else is read as a scene TOML, where an image's bytes (or an empty image
        // file) would make a parse error about TOML or an empty scene.
        return Err(LoadError::invalid(path, format!("is {kind} image, not a scene")).into());
    } else {
        scene_file::read(path, frame)?
    };
    let c = &desc.contents;
    if c.meshes.is_empty() && c.hair.is_empty() && c.hair_systems.is_empty() && c.fur.is_empty() {
        warnings.push("the scene has nothing to render (no meshes, hair, hair systems or fur)".into());
    }
    Ok((desc, warnings.into_iter().map(|w| format!("{}: {w}", path.display())).collect()))
}

/// The kind of image `path` names by its extension (`"an OpenEXR"`), if it names one.
fn image_kind(path: &Path) -> Option<&'static str> {
    let ext = path.extension()?.to_str()?.to_ascii_lowercase();
    Some(match ext.as_str() {
        "exr" => "an OpenEXR",
        "png" => "a PNG",
        "jpg" | "jpeg" => "a JPEG",
        "hdr" => "a Radiance HDR",
        "pfm" => "a PFM",
        "tif" | "tiff" => "a TIFF",
        _ => return None,
    })
}

/// The bytes of base64 `text` in the standard alphabet (RFC 4648), its `=` padding
/// optional: XGen's spline groups and Arnold's `b64` arrays write it both ways.
pub(crate) fn decode_base64(text: &str) -> Result<Vec<u8>, base64::DecodeError> {
    use base64::engine::{DecodePaddingMode, GeneralPurpose, GeneralPurposeConfig};
    use base64::Engine;
    const BASE64: GeneralPurpose = GeneralPurpose::new(
        &base64::alphabet::STANDARD,
        GeneralPurposeConfig::new().with_decode_padding_mode(DecodePaddingMode::Indifferent),
    );
    BASE64.decode(text)
}

/// Writes `bytes` to `path` atomically: to a temporary file in the same directory (so the
/// rename stays on one file system), synced, then renamed over `path`, so a crash or a
/// full disk never leaves a half-written file under the final name.
pub(crate) fn write_atomically(path: &Path, bytes: &[u8]) -> Result<(), LoadError> {
    use std::io::Write;
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    let mut builder = tempfile::Builder::new();
    builder.prefix(".tress-").suffix(".tmp");
    // Temporary files are private by default; the result should get the usual permissions.
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        builder.permissions(std::fs::Permissions::from_mode(0o666));
    }
    let mut tmp =
        builder.tempfile_in(dir).map_err(|e| LoadError::io(path, "create a temporary file next to the file", e))?;
    tmp.write_all(bytes).map_err(|e| LoadError::io(path, "write the file", e))?;
    tmp.as_file().sync_all().map_err(|e| LoadError::io(path, "write the file", e))?;
    tmp.persist(path).map_err(|e| LoadError::io(path, "replace the file", e.error))?;
    Ok(())
}
