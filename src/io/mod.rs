//! File formats: scene TOML ([`scene_file`]), OBJ and PLY meshes, Cem Yuksel `.hair`
//! strands ([`cem_hair`]), images (environment maps and textures, [`raster`]), and other tools' scenes (Maya ASCII, pbrt-v4, USD text) as an
//! [`imported::Imported`]. The readers produce [`crate::scene`] descriptions and entries;
//! the dispatch by extension ([`read_mesh`], [`read_imported`]) is here, so no reader
//! imports another.

pub mod cem_hair;
pub mod imported;
pub mod maya_ascii;
pub mod obj;
pub mod pbrt;
pub mod ply;
pub mod raster;
pub mod reference_scene;
pub mod scene_file;
pub mod usd;

use crate::error::LoadError;
use crate::geometry::TriangleMesh;
use std::path::Path;

/// Reads a mesh, choosing the format by the file extension (`.obj` or `.ply`).
pub fn read_mesh(path: &Path) -> Result<TriangleMesh, LoadError> {
    match extension(path).as_deref() {
        Some("obj") => obj::read_obj(path),
        Some("ply") => ply::read_ply(path),
        _ => Err(LoadError::format(path, "unknown mesh format: expected a .obj or .ply file")),
    }
}

/// The scene formats [`read_imported`] reads, by extension.
pub const IMPORTED_EXTENSIONS: [&str; 6] = ["ma", "pbrt", "usda", "usdc", "usdz", "usd"];

/// What to read of a file that holds more than one frame or camera.
#[derive(Clone, Debug, Default)]
pub struct ImportOptions {
    /// The frame (a USD time code); `None` reads the file's start (USD's `startTimeCode`).
    pub frame: Option<u32>,
    /// The camera to render through, by its path in the file (USD); `None` takes the first.
    pub camera: Option<String>,
}

/// True when `path` names a file [`read_imported`] reads (by its extension).
pub fn is_imported(path: &Path) -> bool {
    extension(path).is_some_and(|e| IMPORTED_EXTENSIONS.contains(&e.as_str()))
}

/// The file's extension, lowercase.
fn extension(path: &Path) -> Option<String> {
    path.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase)
}

/// Reads a Maya ASCII (`.ma`), pbrt-v4 (`.pbrt`) or USD (`.usda`, `.usdc`, `.usdz`,
/// `.usd`) scene, choosing the reader by the file's extension.
pub fn read_imported(path: &Path) -> Result<imported::Imported, LoadError> {
    read_imported_with(path, &ImportOptions::default())
}

/// [`read_imported`] at a frame and through a camera of the file's.
pub fn read_imported_with(path: &Path, options: &ImportOptions) -> Result<imported::Imported, LoadError> {
    match extension(path).as_deref() {
        Some("ma") => maya_ascii::read_maya(path),
        Some("pbrt") => pbrt::read_pbrt(path),
        Some("usda" | "usdc" | "usdz" | "usd") => usd::read_usd(path, options),
        _ => Err(LoadError::format(
            path,
            "unknown scene format: expected a .ma, .pbrt, .usda, .usdc, .usdz or .usd file",
        )),
    }
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
/// Maya ASCII, pbrt-v4 or USD text file (by extension), or a scene TOML at `frame`.
/// Returns the description and the reader's warnings, each prefixed with the file's name.
pub fn read_scene(path: &Path, frame: Option<u32>) -> Result<(crate::scene::Description, Vec<String>), ReadSceneError> {
    read_scene_with(path, &ImportOptions { frame, camera: None })
}

/// [`read_scene`] through a camera of the file's (USD files with several).
pub fn read_scene_with(
    path: &Path,
    options: &ImportOptions,
) -> Result<(crate::scene::Description, Vec<String>), ReadSceneError> {
    let frame = options.frame;
    if path.is_dir() {
        return Ok((reference_scene::read_reference_scene(path)?, Vec::new()));
    }
    let (desc, warnings) = if is_imported(path) {
        read_imported_with(path, options)?.into_description()
    } else {
        scene_file::read(path, frame)?
    };
    Ok((desc, warnings.into_iter().map(|w| format!("{}: {w}", path.display())).collect()))
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
