//! tress's own EXR files read back: farm tiles, checkpoints and interrupted renders.

use std::path::Path;

/// Seed files.
pub const SEEDS: &[&str] = &["tests/data/tile_1_of_3.exr", "tests/data/checkpoint.exr"];

/// Reads `bytes` as a partial render: an error, or pixels that fit the image they claim to
/// be part of.
pub fn check(bytes: &[u8]) -> bool {
    let parsed = tress::partial::Partial::decode(bytes, Path::new("fuzz.exr"));
    if let Ok(part) = &parsed {
        assert!(part.is_consistent(), "accepted an inconsistent partial render");
    }
    parsed.is_ok()
}
