//! What every accepted imported scene (Maya ASCII, pbrt, USD) must satisfy, and how their
//! errors must read.

use std::path::Path;
use tress::io::imported::Imported;
use tress::scene::{HairSource, MeshSource};

/// Inline meshes and strands usable, numbers finite, and a description that either
/// validates or is refused by validation (never panics) with its memory estimate running.
pub fn assert_usable(scene: Imported) {
    for m in &scene.contents.meshes {
        if let MeshSource::Inline(mesh) = &m.source {
            super::assert_usable_mesh(mesh);
        }
    }
    for h in &scene.contents.hair {
        if let HairSource::Inline(s) = &h.source {
            super::assert_usable_strands(s);
        }
    }
    if let Some(c) = &scene.camera {
        assert!(c.eye.is_finite() && c.target.is_finite() && c.up.is_finite() && c.vfov.is_finite(), "{c:?}");
    }
    let (desc, _) = scene.into_description();
    if desc.validate().is_ok() {
        let _ = tress::prepare::estimate_memory(&desc);
    }
}

/// An error must start with the name of the file it is about: `dir` or a file in it.
pub fn assert_names_file(error: &tress::error::LoadError, dir: &Path) {
    let text = error.to_string();
    assert!(text.starts_with(&dir.display().to_string()), "error does not name the file: {text}");
}
