//! Wavefront OBJ files: meshes, and `l` polylines as strands.

use std::path::Path;
use tress::io::obj::ObjGeometry;

/// Seed files.
pub const SEEDS: &[&str] = &["tests/data/cube.obj", "scenes/ground.obj", "tests/data/strands.obj"];

/// Parses `bytes` as an OBJ file: an error, or a mesh or strands fit to render.
pub fn check(bytes: &[u8]) -> bool {
    let parsed = tress::io::obj::parse_obj_geometry(bytes, Path::new("fuzz.obj"));
    match &parsed {
        Ok(ObjGeometry::Mesh(mesh)) => super::assert_usable_mesh(mesh),
        Ok(ObjGeometry::Strands(strands)) => super::assert_usable_strands(strands),
        Err(_) => {}
    }
    parsed.is_ok()
}
