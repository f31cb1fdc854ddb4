//! One module per file format tress reads: the real files that mutations start from and a
//! `check` that parses arbitrary bytes and asserts the result is an error or usable data.
//!
//! Shared by the proptests (`tests/hostile.rs`) and the cargo-fuzz targets (`fuzz/`), so
//! covering a new format is one file here plus a line in [`ALL`] and a fuzz target.

pub mod ass;
pub mod exr;
pub mod gzip;
pub mod hair;
pub mod imported;
pub mod ma;
pub mod obj;
pub mod pbrt;
pub mod ply;
pub mod scene;
pub mod scene_files;
pub mod usda;

use tress::geometry::{StrandSet, TriangleMesh};

/// A format under test.
#[derive(Debug)]
pub struct Format {
    /// Short name, also the fuzz target's name.
    pub name: &'static str,
    /// Real files (paths from the repository root) that mutations start from.
    pub seeds: &'static [&'static str],
    /// Parses the bytes and tells whether they were accepted; panics only when the parser
    /// accepted unusable data.
    pub check: fn(&[u8]) -> bool,
}

/// Every format.
pub const ALL: &[Format] = &[
    Format { name: "hair", seeds: hair::SEEDS, check: hair::check },
    Format { name: "obj", seeds: obj::SEEDS, check: obj::check },
    Format { name: "ply", seeds: ply::SEEDS, check: ply::check },
    Format { name: "scene", seeds: scene::SEEDS, check: scene::check },
    Format { name: "exr", seeds: exr::SEEDS, check: exr::check },
    Format { name: "ma", seeds: ma::SEEDS, check: ma::check },
    Format { name: "pbrt", seeds: pbrt::SEEDS, check: pbrt::check },
    Format { name: "gzip", seeds: gzip::SEEDS, check: gzip::check },
    Format { name: "usda", seeds: usda::SEEDS, check: usda::check },
    Format { name: "ass", seeds: ass::SEEDS, check: ass::check },
    Format { name: "scene_files", seeds: scene_files::SEEDS, check: scene_files::check },
];

/// What every accepted mesh must satisfy: indices in range, finite data, triangles.
pub fn assert_usable_mesh(mesh: &TriangleMesh) {
    assert!(!mesh.indices.is_empty(), "accepted a mesh without triangles");
    if let Err(e) = mesh.validate() {
        panic!("accepted an invalid mesh: {e}");
    }
    assert!(mesh.normals.iter().flatten().all(|n| n.is_finite()), "non-finite normal accepted");
    assert!(mesh.uvs.iter().flatten().flatten().all(|c| c.is_finite()), "non-finite uv accepted");
    for list in [mesh.normals.as_ref().map(Vec::len), mesh.uvs.as_ref().map(Vec::len)].into_iter().flatten() {
        assert_eq!(list, mesh.positions.len(), "per-vertex array of the wrong length");
    }
}

/// What every accepted strand set must satisfy: consistent offsets and arrays, finite points,
/// non-negative radii, opacity in [0, 1], finite non-negative colours.
pub fn assert_usable_strands(s: &StrandSet) {
    assert!(s.points.iter().all(|p| p.iter().all(|c| c.is_finite()) && p[3] >= 0.0), "bad point accepted");
    assert_eq!(s.offsets.first(), Some(&0));
    assert!(s.offsets.windows(2).all(|w| w[0] < w[1]), "empty or reversed strand");
    assert_eq!(*s.offsets.last().unwrap() as usize, s.points.len());
    if let Some(c) = &s.colors {
        assert_eq!(c.len(), s.points.len());
        assert!(c.iter().flatten().all(|v| v.is_finite() && *v >= 0.0));
    }
    if let Some(o) = &s.opacity {
        assert_eq!(o.len(), s.points.len());
        assert!(o.iter().all(|o| (0.0..=1.0).contains(o)));
    }
}
