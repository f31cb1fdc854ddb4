//! Arnold scene source (`.ass`) files, parsed from memory (procedurals are listed, not
//! followed).

use std::path::Path;

/// Seed files.
pub const SEEDS: &[&str] = &["tests/data/small.ass"];

/// Parses `bytes` as an `.ass` file: an error naming it, or a usable scene.
pub fn check(bytes: &[u8]) -> bool {
    let path = Path::new("fuzz/scene.ass");
    match tress::io::ass::parse_ass(&String::from_utf8_lossy(bytes), path, None) {
        Ok(scene) => {
            super::imported::assert_usable(scene.imported);
            true
        }
        Err(e) => {
            super::imported::assert_names_file(&e, Path::new("fuzz"));
            false
        }
    }
}
