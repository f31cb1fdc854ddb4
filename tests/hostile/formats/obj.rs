//! Wavefront OBJ meshes.

use std::path::Path;

/// Seed files.
pub const SEEDS: &[&str] = &["tests/data/cube.obj", "scenes/ground.obj"];

/// Parses `bytes` as an OBJ file: an error, or a mesh fit to render.
pub fn check(bytes: &[u8]) -> bool {
    let parsed = tress::io::obj::parse_obj(bytes, Path::new("fuzz.obj"));
    if let Ok(mesh) = &parsed {
        super::assert_usable_mesh(mesh);
    }
    parsed.is_ok()
}
