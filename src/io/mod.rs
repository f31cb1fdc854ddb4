//! File formats: scene TOML, OBJ and PLY meshes, Cem Yuksel `.hair` strands, and other
//! tools' scenes (Maya ASCII, pbrt-v4, USD text) through [`imported`].

pub mod cem_hair;
pub mod imported;
pub mod maya_ascii;
pub mod obj;
pub mod pbrt;
pub mod ply;
pub mod scene_file;
pub mod usd;

use crate::error::LoadError;
use crate::geometry::TriangleMesh;
use std::path::Path;

/// Reads a mesh, choosing the format by the file extension (`.obj` or `.ply`).
pub fn read_mesh(path: &Path) -> Result<TriangleMesh, LoadError> {
    match path.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase).as_deref() {
        Some("obj") => obj::read_obj(path),
        Some("ply") => ply::read_ply(path),
        _ => Err(LoadError::format(path, "unknown mesh format: expected a .obj or .ply file")),
    }
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
