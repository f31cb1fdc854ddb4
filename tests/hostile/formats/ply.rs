//! Stanford PLY files, ascii and binary: meshes, and polyline strands (vertex counts,
//! vertex lists or edges).

use std::path::Path;
use tress::io::ply::PlyGeometry;

/// Seed files.
pub const SEEDS: &[&str] = &[
    "tests/data/quad_ascii.ply",
    "tests/data/quad_binary.ply",
    "scenes/box.ply",
    "tests/data/strands_counts.ply",
    "tests/data/strands_edges.ply",
];

/// Parses `bytes` as a PLY file: an error, or a mesh or strands fit to render.
pub fn check(bytes: &[u8]) -> bool {
    let parsed = tress::io::ply::parse_ply_geometry(bytes, Path::new("fuzz.ply"));
    match &parsed {
        Ok(PlyGeometry::Mesh(mesh)) => super::assert_usable_mesh(mesh),
        Ok(PlyGeometry::Strands { strands, .. }) => super::assert_usable_strands(strands),
        Err(_) => {}
    }
    parsed.is_ok()
}
