//! Scene files (TOML).

use std::path::Path;

/// Seed files.
pub const SEEDS: &[&str] = &["scenes/hairy_torus.toml", "scenes/lights_and_glass.toml", "scenes/animated.toml"];

/// Parses `bytes` as a scene file, at no frame and at frame 7: an error, or a description
/// whose every number is usable and whose memory estimate does not fail. True when
/// accepted at either frame.
pub fn check(bytes: &[u8]) -> bool {
    let Ok(text) = std::str::from_utf8(bytes) else { return false };
    let mut accepted = false;
    let path = Path::new("scenes/fuzz.toml");
    for frame in [None, Some(7)] {
        let Ok((desc, _)) = tress::io::scene_file::parse(text, path, frame) else { continue };
        if let Err(e) = desc.validate() {
            panic!("accepted a scene that does not validate: {e}");
        }
        let c = &desc.camera;
        assert!(c.eye.is_finite() && c.target.is_finite() && c.up.is_finite() && c.vfov.is_finite());
        // Either a camera or a clear error; never a panic.
        let _ = tress::prepare::camera(c, desc.settings.width, desc.settings.height);
        // Reads only headers of the files the scene names (which mostly do not exist here).
        let _ = tress::prepare::estimate_memory(&desc);
        accepted = true;
    }
    accepted
}
