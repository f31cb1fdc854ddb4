//! pbrt-v4 scenes.

use std::path::Path;

/// Seed files.
pub const SEEDS: &[&str] = &["tests/data/small.pbrt", "scenes/pbrt_hair_curves.pbrt"];

/// Parses `bytes` as a pbrt file: an error naming it (or the file it includes), or a
/// usable scene.
pub fn check(bytes: &[u8]) -> bool {
    let path = Path::new("fuzz/scene.pbrt");
    match tress::io::pbrt::parse_pbrt(&String::from_utf8_lossy(bytes), path) {
        Ok(scene) => {
            super::imported::assert_usable(scene);
            true
        }
        Err(e) => {
            super::imported::assert_names_file(&e, Path::new("fuzz"));
            false
        }
    }
}
