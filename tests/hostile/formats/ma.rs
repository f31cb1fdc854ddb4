//! Maya ASCII scenes.

use std::path::Path;

/// Seed files.
pub const SEEDS: &[&str] = &["tests/data/small.ma", "scenes/maya_hair.ma"];

/// Parses `bytes` as a Maya ASCII file: an error naming it, or a usable scene.
pub fn check(bytes: &[u8]) -> bool {
    let path = Path::new("fuzz/scene.ma");
    match tress::io::maya_ascii::parse_maya(&String::from_utf8_lossy(bytes), path) {
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
