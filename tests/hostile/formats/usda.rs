//! USD text layers. The reader opens layers by path (a layer can name others), so the
//! bytes go to a file in a temporary directory first.

/// Seed files.
pub const SEEDS: &[&str] = &["tests/data/small.usda", "scenes/usd_hair.usda"];

/// Reads `bytes` as a `.usda` file: an error naming it, or a usable scene.
pub fn check(bytes: &[u8]) -> bool {
    let dir = tempfile::tempdir().expect("a temporary directory");
    let path = dir.path().join("scene.usda");
    std::fs::write(&path, bytes).expect("writing the layer");
    match tress::io::usd::read_usd(&path, &tress::io::ImportOptions::default()) {
        Ok(scene) => {
            super::imported::assert_usable(scene);
            true
        }
        Err(e) => {
            super::imported::assert_names_file(&e, dir.path());
            false
        }
    }
}
