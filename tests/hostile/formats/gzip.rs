//! gzip-compressed input (pbrt's `.pbrt.gz` includes), decompressed and read as pbrt.

use std::path::Path;

/// Seed files.
pub const SEEDS: &[&str] = &["tests/data/small.pbrt.gz"];

/// Decompresses `bytes` (with a small cap) and parses the result as a pbrt file: an error
/// naming the file, or a usable scene.
pub fn check(bytes: &[u8]) -> bool {
    let path = Path::new("fuzz/scene.pbrt.gz");
    match tress::io::gzip::decompress_capped(bytes.to_vec(), path, 1 << 20) {
        Ok(text) => super::pbrt::check(&text),
        Err(e) => {
            assert!(e.to_string().starts_with("fuzz/scene.pbrt.gz"), "{e}");
            false
        }
    }
}
