//! Cem Yuksel `.hair` files.

use std::path::Path;

/// Seed files.
pub const SEEDS: &[&str] = &["tests/data/two_strands.hair", "scenes/hairy_torus.hair"];

/// Parses `bytes` as a `.hair` file: an error, or strands fit to render.
pub fn check(bytes: &[u8]) -> bool {
    let parsed = tress::io::cem_hair::parse_hair(bytes, Path::new("fuzz.hair"));
    if let Ok(s) = &parsed {
        super::assert_usable_strands(s);
    }
    parsed.is_ok()
}
