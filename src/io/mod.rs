//! File formats: scene TOML, OBJ and PLY meshes, Cem Yuksel `.hair` strands.

mod error;
pub mod hair;
pub mod obj;
pub mod ply;
pub mod scene_file;

pub use error::LoadError;

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
