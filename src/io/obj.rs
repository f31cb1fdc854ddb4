//! Wavefront OBJ meshes, read with the `tobj` crate.
//!
//! All objects and groups in the file are merged into one [`TriangleMesh`]; polygons are
//! triangulated as fans, and points and lines (faces with one or two vertices) are skipped,
//! since they bound no surface. Vertices are re-indexed so that positions, normals and
//! texture coordinates share one index (a position used with two different normals becomes
//! two vertices). Normals and texture coordinates are kept only if every vertex of every
//! object has them, because the mesh stores them for all vertices or none. Materials
//! (`mtllib`, `usemtl`) are ignored: shading comes from the scene description.
//!
//! A file with line elements (`l`) and no faces holds strands ([`read_obj_geometry`]):
//! each `l` line is a polyline through its vertices (1-based, or negative relative
//! indices), and a line starting at the vertex the previous one ended at continues it, as
//! exporters that write one `l` per segment produce. Vertex colours (`v x y z r g b`, an
//! extension many tools write) become strand colours. OBJ has no widths.

use std::io::{BufRead, BufReader};
use std::path::Path;

use glam::Vec3;

use crate::error::LoadError;
use crate::geometry::{StrandSet, TriangleMesh};

/// Reads an OBJ file into a single validated triangle mesh.
///
/// Fails, naming the file, if it cannot be read, does not parse, has a face index out of
/// range, holds a non-finite position, normal or texture coordinate, or has no triangles.
pub fn read_obj(path: &Path) -> Result<TriangleMesh, LoadError> {
    let file = crate::input_file::open(path, crate::input_file::Kind::Geometry)?;
    // tobj drops the underlying error of a failed read; the usual cause is text that is not
    // UTF-8, so look for it in the file to tell the user.
    let cause = || match std::fs::read(path) {
        Err(e) => e.to_string(),
        Ok(bytes) => not_utf8(&bytes),
    };
    load(&mut BufReader::new(file), path, cause)
}

/// What an OBJ file holds: a mesh, or polyline strands (without widths: every radius is 0).
#[derive(Clone, Debug, PartialEq)]
pub enum ObjGeometry {
    /// Triangles.
    Mesh(TriangleMesh),
    /// The `l` polylines.
    Strands(StrandSet),
}

/// Reads an OBJ file of either kind: its faces as [`read_obj`] does, or, when it has line
/// elements and no faces, its polylines as strands.
pub fn read_obj_geometry(path: &Path) -> Result<ObjGeometry, LoadError> {
    let bytes = crate::input_file::read(path, crate::input_file::Kind::Geometry)?;
    parse_obj_geometry(&bytes, path)
}

/// Decodes the bytes of an OBJ file like [`read_obj_geometry`]; `path` names it in messages.
pub fn parse_obj_geometry(bytes: &[u8], path: &Path) -> Result<ObjGeometry, LoadError> {
    let has = |tag: &[u8]| bytes.split(|&b| b == b'\n').any(|l| l.trim_ascii_start().starts_with(tag));
    match has(b"l ") && !has(b"f ") {
        true => polylines(bytes, path).map(ObjGeometry::Strands),
        false => parse_obj(bytes, path).map(ObjGeometry::Mesh),
    }
}

/// The `l` polylines of OBJ text, over its `v` vertices.
fn polylines(bytes: &[u8], path: &Path) -> Result<StrandSet, LoadError> {
    let text = std::str::from_utf8(bytes).map_err(|e| {
        LoadError::format(path, format!("it is not utf-8 text (invalid byte at offset {})", e.valid_up_to()))
    })?;
    let at = |line: usize, m: String| LoadError::format(path, format!("line {}: {m}", line + 1));
    let mut positions: Vec<Vec3> = Vec::new();
    let mut colors: Vec<[f32; 3]> = Vec::new();
    let mut chains: Vec<Vec<usize>> = Vec::new();
    for (n, line) in text.lines().enumerate() {
        let mut words = line.split_whitespace();
        match words.next() {
            Some("v") => {
                let v: Vec<f32> = words
                    .map(|w| w.parse::<f32>().ok().filter(|x| x.is_finite()))
                    .collect::<Option<_>>()
                    .ok_or_else(|| at(n, "a vertex coordinate is not a finite number".into()))?;
                match v.len() {
                    3 | 4 => colors.push([1.0; 3]),
                    6 | 7 => colors.push([v[3], v[4], v[5]]),
                    k => return Err(at(n, format!("a vertex needs 3 coordinates (and optionally r g b), not {k}"))),
                }
                positions.push(Vec3::new(v[0], v[1], v[2]));
            }
            Some("l") => {
                let count = positions.len() as i64;
                let chain: Vec<usize> = words
                    .map(|w| {
                        // `l v/vt`: the vertex is the first number.
                        let i: i64 = w.split('/').next().and_then(|i| i.parse().ok()).unwrap_or(0);
                        let i = if i < 0 { count + i } else { i - 1 };
                        (0..count)
                            .contains(&i)
                            .then_some(i as usize)
                            .ok_or_else(|| at(n, format!("`{w}` is not one of the {count} vertices before this line")))
                    })
                    .collect::<Result<_, _>>()?;
                match chains.last_mut() {
                    // An `l` without vertices is no strand and breaks no chain.
                    _ if chain.is_empty() => {}
                    Some(last) if last.last() == chain.first() && chain.len() > 1 => last.extend(&chain[1..]),
                    _ => chains.push(chain),
                }
            }
            _ => {}
        }
    }
    let mut set = StrandSet::new();
    for c in &chains {
        set.push_strand(c.iter().map(|&i| (positions[i], 0.0)));
    }
    if colors.iter().any(|c| *c != [1.0; 3]) {
        set.colors = Some(chains.iter().flatten().map(|&i| colors[i]).collect());
        if set.colors.iter().flatten().flatten().any(|c| *c < 0.0) {
            return Err(LoadError::invalid(path, "vertex colours must not be negative"));
        }
    }
    if set.segment_count() == 0 {
        return Err(LoadError::invalid(path, "the obj file's lines hold no segment"));
    }
    Ok(set)
}

/// Counts the vertices (`v` lines) and the triangles the faces (`f` lines) make, without
/// parsing the numbers, for estimates made before reading the file.
pub fn count_obj(path: &Path) -> Result<(u64, u64), LoadError> {
    let file = crate::input_file::open(path, crate::input_file::Kind::Geometry)?;
    let (mut vertices, mut triangles) = (0u64, 0u64);
    for line in BufReader::new(file).split(b'\n') {
        let line = line.map_err(|e| LoadError::io(path, "read the file", e))?;
        let mut words = line.split(|b| b.is_ascii_whitespace()).filter(|w| !w.is_empty());
        match words.next() {
            Some(b"v") => vertices += 1,
            Some(b"f") => triangles += (words.count() as u64).saturating_sub(2),
            _ => {}
        }
    }
    Ok((vertices, triangles))
}

/// Decodes the bytes of an OBJ file like [`read_obj`]; `path` is used only in messages.
pub fn parse_obj(bytes: &[u8], path: &Path) -> Result<TriangleMesh, LoadError> {
    load(&mut std::io::Cursor::new(bytes), path, || not_utf8(bytes))
}

/// Why tobj could not read `bytes`, for its `ReadError`.
fn not_utf8(bytes: &[u8]) -> String {
    match std::str::from_utf8(bytes) {
        Err(e) => format!("it is not utf-8 text (invalid byte at offset {})", e.valid_up_to()),
        Ok(_) => "read error".to_string(),
    }
}

/// Parses OBJ text from `reader` and validates the mesh; `cause` explains a read error.
fn load(reader: &mut impl BufRead, path: &Path, cause: impl FnOnce() -> String) -> Result<TriangleMesh, LoadError> {
    // `..Default::default()` although every field is set: tobj has more fields behind cargo
    // features that another crate in the build could enable.
    #[allow(clippy::needless_update)]
    let options = tobj::LoadOptions {
        triangulate: true,
        single_index: true,
        ignore_points: true,
        ignore_lines: true,
        ..Default::default()
    };
    // Material libraries are never opened: materials are not used, and a missing .mtl file
    // should not stop a mesh from loading.
    let no_materials = |_: &Path| -> tobj::MTLLoadResult { Ok(Default::default()) };
    // tobj does unchecked index arithmetic on some malformed face indices (e.g. a normal
    // index near isize::MAX), which can panic in builds with overflow checks; a bad file
    // must give an error, not bring down the program.
    let loaded =
        std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| tobj::load_obj_buf(reader, &options, no_materials)));
    let models = match loaded {
        Ok(Ok((models, _materials))) => models,
        Ok(Err(tobj::LoadError::ReadError)) => {
            return Err(LoadError::format(path, format!("could not read the obj file: {}", cause())));
        }
        Ok(Err(e)) => return Err(LoadError::format(path, format!("malformed obj file: {e}"))),
        Err(_) => return Err(LoadError::format(path, "malformed obj file: a face index is out of any usable range")),
    };
    let mesh = merge(path, &models)?;
    if mesh.indices.is_empty() {
        return Err(LoadError::invalid(path, "the obj file contains no triangles"));
    }
    check_mesh(path, &mesh)?;
    Ok(mesh)
}

/// Merges tobj's models into one mesh, offsetting each model's indices past the vertices
/// of the models before it.
fn merge(path: &Path, models: &[tobj::Model]) -> Result<TriangleMesh, LoadError> {
    let vertex_total: usize = models.iter().map(|m| m.mesh.positions.len() / 3).sum();
    if u32::try_from(vertex_total).is_err() {
        return Err(LoadError::invalid(path, format!("{vertex_total} vertices is more than a mesh can index (2^32)")));
    }
    let all_have = |per_vertex: usize, field: fn(&tobj::Mesh) -> usize| {
        models.iter().all(|m| field(&m.mesh) == m.mesh.positions.len() / 3 * per_vertex)
    };
    let keep_normals = all_have(3, |m| m.normals.len());
    let keep_uvs = all_have(2, |m| m.texcoords.len());

    let mut mesh = TriangleMesh {
        positions: Vec::with_capacity(vertex_total),
        normals: keep_normals.then(|| Vec::with_capacity(vertex_total)),
        uvs: keep_uvs.then(|| Vec::with_capacity(vertex_total)),
        indices: Vec::new(),
    };
    for model in models {
        let m = &model.mesh;
        // Cannot truncate: the total vertex count was checked to fit a u32 above.
        let base = mesh.positions.len() as u32;
        mesh.positions.extend(m.positions.chunks_exact(3).map(|p| Vec3::new(p[0], p[1], p[2])));
        if let Some(normals) = &mut mesh.normals {
            normals.extend(m.normals.chunks_exact(3).map(|n| Vec3::new(n[0], n[1], n[2])));
        }
        if let Some(uvs) = &mut mesh.uvs {
            uvs.extend(m.texcoords.chunks_exact(2).map(|t| [t[0], t[1]]));
        }
        // Out-of-range indices wrap here only to be caught by validation below.
        mesh.indices.extend(
            m.indices
                .chunks_exact(3)
                .map(|t| [base.wrapping_add(t[0]), base.wrapping_add(t[1]), base.wrapping_add(t[2])]),
        );
    }
    Ok(mesh)
}

/// [`TriangleMesh::validate`] plus finiteness of normals and texture coordinates, with the
/// file named in the error. Shared with the PLY reader.
pub(crate) fn check_mesh(path: &Path, mesh: &TriangleMesh) -> Result<(), LoadError> {
    mesh.validate().map_err(|problem| LoadError::invalid(path, problem))?;
    if let Some(i) = mesh.normals.iter().flatten().position(|n| !n.is_finite()) {
        return Err(LoadError::invalid(path, format!("normal of vertex {i} is not finite")));
    }
    if let Some(i) = mesh.uvs.iter().flatten().position(|t| !t.iter().all(|c| c.is_finite())) {
        return Err(LoadError::invalid(path, format!("texture coordinate of vertex {i} is not finite")));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::path::PathBuf;

    fn data(name: &str) -> PathBuf {
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/data").join(name)
    }

    /// Writes `text` to `name` in a fresh temporary directory.
    fn temp_obj(name: &str, text: &str) -> (tempfile::TempDir, PathBuf) {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join(name);
        std::fs::write(&path, text).unwrap();
        (dir, path)
    }

    fn error_for(name: &str, text: &str) -> String {
        let (_dir, path) = temp_obj(name, text);
        let msg = read_obj(&path).unwrap_err().to_string();
        assert!(msg.contains(name), "message does not name the file: {msg}");
        msg
    }

    #[test]
    fn reads_a_cube_with_two_objects() {
        let mesh = read_obj(&data("cube.obj")).unwrap();
        // Six quads in two objects become 12 triangles; each face has its own normal, so
        // every face gets its own 4 vertices.
        assert_eq!(mesh.indices.len(), 12);
        assert_eq!(mesh.positions.len(), 24);
        assert!(mesh.normals.as_ref().is_some_and(|n| n.len() == 24));
        assert!(mesh.uvs.is_none(), "the file has no texture coordinates");
        assert!(mesh.positions.contains(&Vec3::new(1.0, 1.0, 1.0)));
        assert!(mesh.positions.iter().all(|p| p.abs().max_element() == 1.0));
        assert!(mesh.validate().is_ok());
        // Winding: the +x face's triangles face +x.
        let total_area: f32 = (0..12).map(|i| mesh.area(i)).sum();
        assert!((total_area - 24.0).abs() < 1e-5);
    }

    #[test]
    fn reads_uvs_and_relative_indices() {
        let (_dir, path) = temp_obj(
            "quad.obj",
            "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nf -4/-4 -3/-3 -2/-2 -1/-1\n",
        );
        let mesh = read_obj(&path).unwrap();
        assert_eq!(mesh.indices.len(), 2);
        assert_eq!(mesh.positions.len(), 4);
        assert_eq!(mesh.uvs.as_ref().unwrap()[2], [1.0, 1.0]);
        assert!(mesh.normals.is_none());
    }

    #[test]
    fn missing_file_names_the_file() {
        let dir = tempfile::tempdir().unwrap();
        let msg = read_obj(&dir.path().join("nowhere.obj")).unwrap_err().to_string();
        assert!(msg.contains("nowhere.obj") && msg.contains("could not open the file"), "{msg}");
    }

    #[test]
    fn malformed_files_give_clear_errors() {
        let msg = error_for("garbled.obj", "v 1 2 banana\nf 1 1 1\n");
        assert!(msg.contains("malformed obj file: position parse error"), "{msg}");
        let msg = error_for("range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n");
        assert!(msg.contains("out of bounds"), "{msg}");
        let msg = error_for("huge.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//9223372036854775807 2//1 3//1\n");
        assert!(msg.contains("malformed obj file"), "{msg}");
    }

    #[test]
    fn binary_garbage_is_reported_as_not_text() {
        let (_dir, path) = temp_obj("binary.obj", "v 0 0 0\n");
        std::fs::write(&path, b"v 0 0 0\n\xff\xfe\x00\x01").unwrap();
        let msg = read_obj(&path).unwrap_err().to_string();
        assert!(
            msg.contains("binary.obj: could not read the obj file: it is not utf-8 text (invalid byte at offset 8)"),
            "{msg}"
        );
    }

    #[test]
    fn rejects_non_finite_values() {
        let msg = error_for("nan.obj", "v 0 0 0\nv 1 nan 0\nv 0 1 0\nf 1 2 3\n");
        assert!(msg.contains("vertex 1 is not finite"), "{msg}");
        let msg = error_for("inf.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 inf\nf 1//1 2//1 3//1\n");
        assert!(msg.contains("normal of vertex 0 is not finite"), "{msg}");
    }

    #[test]
    fn rejects_files_without_triangles() {
        let msg = error_for("empty.obj", "# nothing here\nv 0 0 0\nl 1 1\n");
        assert!(msg.contains("contains no triangles"), "{msg}");
    }

    #[test]
    fn missing_material_library_is_ignored() {
        let (_dir, path) = temp_obj("mat.obj", "mtllib absent.mtl\nusemtl red\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
        assert_eq!(read_obj(&path).unwrap().indices, vec![[0, 1, 2]]);
    }

    #[test]
    fn line_elements_are_strands_and_segments_chain() {
        let text = "# hair\nv 0 0 0 1 0 0\nv 0 1 0 1 0 0\nv 0 2 0 0 1 0\nv 1 0 0 0 0 1\nv 1 1 0 0 0 1\n\
                    l 1 2\nl 2 3\nl -2 -1\n";
        let ObjGeometry::Strands(s) = parse_obj_geometry(text.as_bytes(), Path::new("c.obj")).unwrap() else {
            panic!("not strands")
        };
        // `l 1 2` and `l 2 3` share vertex 2: one strand of three points; `l -2 -1` another.
        assert_eq!(s.offsets, vec![0, 3, 5]);
        // An empty `l` adds nothing.
        let ObjGeometry::Strands(e) =
            parse_obj_geometry(text.replace("l 2 3\n", "l \nl 2 3\nl \n").as_bytes(), Path::new("c.obj")).unwrap()
        else {
            panic!("not strands")
        };
        assert_eq!(e.offsets, s.offsets);
        assert_eq!(s.points[2], [0.0, 2.0, 0.0, 0.0]);
        assert_eq!(s.colors.as_ref().unwrap()[2], [0.0, 1.0, 0.0]);
        // Faces make it a mesh, lines or not.
        let mesh = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nl 1 2\n";
        assert!(matches!(parse_obj_geometry(mesh.as_bytes(), Path::new("m.obj")).unwrap(), ObjGeometry::Mesh(_)));
        for (text, needle) in
            [("v 0 0 0\nl 1 2\n", "line 2"), ("v 0 0 nan\nl 1 1\n", "line 1"), ("v 0 0 0\nl 1\n", "no segment")]
        {
            let e = parse_obj_geometry(text.as_bytes(), Path::new("c.obj")).unwrap_err().to_string();
            assert!(e.starts_with("c.obj: ") && e.contains(needle), "{text:?}: {e}");
        }
    }
}
