//! Stanford PLY meshes, ascii and binary.

use std::path::Path;

/// Seed files.
pub const SEEDS: &[&str] = &["tests/data/quad_ascii.ply", "tests/data/quad_binary.ply", "scenes/box.ply"];

/// Parses `bytes` as a PLY file: an error, or a mesh fit to render.
pub fn check(bytes: &[u8]) -> bool {
    let parsed = tress::io::ply::parse_ply(bytes, Path::new("fuzz.ply"));
    if let Ok(mesh) = &parsed {
        super::assert_usable_mesh(mesh);
    }
    parsed.is_ok()
}
