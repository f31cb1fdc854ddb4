//! Stanford PLY meshes and polyline strands (ascii and binary, either byte order), read
//! with `ply-rs-bw`.
//!
//! What is read for a mesh:
//! - the `vertex` element's `x`, `y`, `z` (any numeric type; doubles are narrowed to `f32`),
//!   with optional normals `nx`, `ny`, `nz` and texture coordinates `u`, `v` (also spelled
//!   `s`, `t`, `texture_u`, `texture_v`, `texture_s`, `texture_t`);
//! - the `face` element's `vertex_indices` (or `vertex_index`) list of any integer type;
//!   polygons become triangle fans and faces with fewer than three vertices are skipped,
//!   like points and lines in OBJ files.
//!
//! A file without a `face` element but with one of these is strands, as hair-capture tools
//! write them ([`read_ply_geometry`]):
//! - a `strand` element (also `strands`, `curve`, `curves`, `hair`) whose one integer
//!   property is each strand's vertex count, the strands' vertices following each other in
//!   the `vertex` element; or whose integer list property lists each strand's vertices;
//! - an `edge` element of `vertex1`, `vertex2` pairs, chained into polylines (a vertex has
//!   at most one edge in and one out).
//!
//! Strand vertices may carry a `radius` (or a diameter: `width`, `thickness`) and a colour
//! (`red`, `green`, `blue`: 0..255 as bytes, 0..1 as floats).
//!
//! Every other element and property is parsed and dropped. Before any element data is
//! read, the counts in the header are checked against the bytes that follow it, using the
//! least each element can occupy (its scalar sizes and list-length sizes in binary files,
//! two characters per value in ascii ones, and never less than a byte). So a forged header
//! claiming 10^12 vertices in a 1 KB file is rejected up front instead of driving the
//! parser into a huge loop or allocation.

use std::io::{BufRead, BufReader, Seek};
use std::path::Path;

use glam::Vec3;
use ply_rs_bw::parser::{ParseError, Parser, Reader};
use ply_rs_bw::ply::{
    BeginList, ElementDef, Encoding, Header, PropertyAccess, PropertyAccessResult, PropertyType, ScalarType,
};

use super::obj::check_mesh;
use crate::error::LoadError;
use crate::geometry::{StrandSet, TriangleMesh};

/// Pairs of names under which the two texture coordinates appear in the wild.
const UV_NAMES: [(&str, &str); 4] = [("u", "v"), ("s", "t"), ("texture_u", "texture_v"), ("texture_s", "texture_t")];
/// Names of the face element's index list.
const INDEX_NAMES: [&str; 2] = ["vertex_indices", "vertex_index"];

/// Names of the element listing strands.
const STRAND_NAMES: [&str; 5] = ["strand", "strands", "curve", "curves", "hair"];
/// Names of a strand vertex's colour channels.
const COLOR_NAMES: [&str; 3] = ["red", "green", "blue"];

/// One vertex as read from the file: only the properties tress uses.
#[derive(Clone, Copy, Default)]
struct PlyVertex {
    position: [f32; 3],
    normal: [f32; 3],
    uv: [f32; 2],
    radius: f32,
    color: [f32; 3],
}

impl PlyVertex {
    fn set(&mut self, name: &str, value: f64) -> PropertyAccessResult {
        // Narrowing to f32 turns out-of-range doubles into infinities, which validation
        // then reports as non-finite.
        let value = value as f32;
        let slot = match name {
            "radius" => &mut self.radius,
            "width" | "thickness" => {
                self.radius = 0.5 * value;
                return PropertyAccessResult::Set;
            }
            "red" => &mut self.color[0],
            "green" => &mut self.color[1],
            "blue" => &mut self.color[2],
            "x" => &mut self.position[0],
            "y" => &mut self.position[1],
            "z" => &mut self.position[2],
            "nx" => &mut self.normal[0],
            "ny" => &mut self.normal[1],
            "nz" => &mut self.normal[2],
            "u" | "s" | "texture_u" | "texture_s" => &mut self.uv[0],
            "v" | "t" | "texture_v" | "texture_t" => &mut self.uv[1],
            _ => return PropertyAccessResult::Ignored,
        };
        *slot = value;
        PropertyAccessResult::Set
    }
}

impl PropertyAccess for PlyVertex {
    fn new() -> Self {
        PlyVertex::default()
    }
    fn set_char(&mut self, name: &str, value: i8) -> PropertyAccessResult {
        self.set(name, value.into())
    }
    fn set_uchar(&mut self, name: &str, value: u8) -> PropertyAccessResult {
        // Byte colours run 0..255.
        match COLOR_NAMES.contains(&name) {
            true => self.set(name, f64::from(value) / 255.0),
            false => self.set(name, value.into()),
        }
    }
    fn set_short(&mut self, name: &str, value: i16) -> PropertyAccessResult {
        self.set(name, value.into())
    }
    fn set_ushort(&mut self, name: &str, value: u16) -> PropertyAccessResult {
        self.set(name, value.into())
    }
    fn set_int(&mut self, name: &str, value: i32) -> PropertyAccessResult {
        self.set(name, value.into())
    }
    fn set_uint(&mut self, name: &str, value: u32) -> PropertyAccessResult {
        self.set(name, value.into())
    }
    fn set_float(&mut self, name: &str, value: f32) -> PropertyAccessResult {
        self.set(name, value.into())
    }
    fn set_double(&mut self, name: &str, value: f64) -> PropertyAccessResult {
        self.set(name, value)
    }
}

/// One entry of a strand or edge element: its integer scalars in file order (a vertex
/// count, or an edge's two vertices) and its integer list (a strand's vertices).
#[derive(Default)]
struct PlyLink {
    scalars: Vec<i64>,
    list: Vec<i64>,
    /// Set when a value is not an integer.
    fractional: bool,
}

impl PlyLink {
    fn scalar(&mut self, v: i64) -> PropertyAccessResult {
        self.scalars.push(v);
        PropertyAccessResult::Set
    }
    fn list<T: Copy + Into<i64>>(&mut self, values: &[T]) -> PropertyAccessResult {
        self.list = values.iter().map(|&v| v.into()).collect();
        PropertyAccessResult::Set
    }
    fn float(&mut self, v: f64) -> PropertyAccessResult {
        match v.fract() == 0.0 && v.abs() < 1e15 {
            true => self.scalar(v as i64),
            false => {
                self.fractional = true;
                PropertyAccessResult::Set
            }
        }
    }
}

impl PropertyAccess for PlyLink {
    fn new() -> Self {
        PlyLink::default()
    }
    fn set_char(&mut self, _: &str, value: i8) -> PropertyAccessResult {
        self.scalar(value.into())
    }
    fn set_uchar(&mut self, _: &str, value: u8) -> PropertyAccessResult {
        self.scalar(value.into())
    }
    fn set_short(&mut self, _: &str, value: i16) -> PropertyAccessResult {
        self.scalar(value.into())
    }
    fn set_ushort(&mut self, _: &str, value: u16) -> PropertyAccessResult {
        self.scalar(value.into())
    }
    fn set_int(&mut self, _: &str, value: i32) -> PropertyAccessResult {
        self.scalar(value.into())
    }
    fn set_uint(&mut self, _: &str, value: u32) -> PropertyAccessResult {
        self.scalar(value.into())
    }
    fn set_float(&mut self, _: &str, value: f32) -> PropertyAccessResult {
        self.float(value.into())
    }
    fn set_double(&mut self, _: &str, value: f64) -> PropertyAccessResult {
        self.float(value)
    }
    fn set_list_char(&mut self, _: &str, value: Vec<i8>) -> PropertyAccessResult {
        self.list(&value)
    }
    fn set_list_uchar(&mut self, _: &str, value: Vec<u8>) -> PropertyAccessResult {
        self.list(&value)
    }
    fn set_list_short(&mut self, _: &str, value: Vec<i16>) -> PropertyAccessResult {
        self.list(&value)
    }
    fn set_list_ushort(&mut self, _: &str, value: Vec<u16>) -> PropertyAccessResult {
        self.list(&value)
    }
    fn set_list_int(&mut self, _: &str, value: Vec<i32>) -> PropertyAccessResult {
        self.list(&value)
    }
    fn set_list_uint(&mut self, _: &str, value: Vec<u32>) -> PropertyAccessResult {
        self.list(&value)
    }
}

/// One face as read from the file.
#[derive(Default)]
struct PlyFace {
    indices: Vec<u32>,
    /// Set when the list held a negative index, which cannot be stored in `indices`.
    negative: bool,
}

impl PlyFace {
    fn set_signed<T: Copy + Into<i64>>(&mut self, name: &str, values: &[T]) -> PropertyAccessResult {
        if !INDEX_NAMES.contains(&name) {
            return PropertyAccessResult::Ignored;
        }
        self.indices.clear();
        for &v in values {
            match u32::try_from(v.into()) {
                Ok(i) => self.indices.push(i),
                Err(_) => self.negative = true,
            }
        }
        PropertyAccessResult::Set
    }
}

impl PropertyAccess for PlyFace {
    fn new() -> Self {
        PlyFace::default()
    }
    fn set_list_char(&mut self, name: &str, value: Vec<i8>) -> PropertyAccessResult {
        self.set_signed(name, &value)
    }
    fn set_list_uchar(&mut self, name: &str, value: Vec<u8>) -> PropertyAccessResult {
        self.set_signed(name, &value)
    }
    fn set_list_short(&mut self, name: &str, value: Vec<i16>) -> PropertyAccessResult {
        self.set_signed(name, &value)
    }
    fn set_list_ushort(&mut self, name: &str, value: Vec<u16>) -> PropertyAccessResult {
        self.set_signed(name, &value)
    }
    fn set_list_int(&mut self, name: &str, value: Vec<i32>) -> PropertyAccessResult {
        self.set_signed(name, &value)
    }
    fn begin_list_uint(&mut self, name: &str, _len: usize) -> BeginList<'_, u32> {
        // The common case: the parser fills our vector directly, with no temporary.
        if INDEX_NAMES.contains(&name) {
            BeginList::Fill(&mut self.indices)
        } else {
            BeginList::UseSetter
        }
    }
}

/// An element tress does not use: parsed (to move past it) and dropped.
struct Skip;

impl PropertyAccess for Skip {
    fn new() -> Self {
        Skip
    }
}

/// Reads a PLY file (ascii or binary) into a single validated triangle mesh.
///
/// Fails, naming the file, if it cannot be read or parsed, if its header claims more data
/// than the file holds, if it lacks a `vertex` element with `x`, `y`, `z` or a `face`
/// element with a vertex index list, if a face refers to a vertex that does not exist, if a
/// position, normal or texture coordinate is not finite, or if it has no triangles.
pub fn read_ply(path: &Path) -> Result<TriangleMesh, LoadError> {
    read_ply_geometry(path)?.into_mesh(path)
}

/// What a PLY file holds: a mesh, or polyline strands.
#[derive(Clone, Debug, PartialEq)]
pub enum PlyGeometry {
    /// Triangles (polygons fanned).
    Mesh(TriangleMesh),
    /// Strands; `widths` tells whether the vertices gave a radius (otherwise every radius
    /// is 0, for the caller to choose).
    Strands {
        /// The strands, in file order.
        strands: StrandSet,
        /// True when the vertices carry `radius`, `width` or `thickness`.
        widths: bool,
    },
}

impl PlyGeometry {
    fn into_mesh(self, path: &Path) -> Result<TriangleMesh, LoadError> {
        match self {
            PlyGeometry::Mesh(m) => Ok(m),
            PlyGeometry::Strands { .. } => {
                Err(LoadError::invalid(path, "the ply file holds strands, not triangles: use it as hair"))
            }
        }
    }
}

/// Reads a PLY file of either kind: a mesh as [`read_ply`] does, or polyline strands (see
/// the module documentation), validated (finite positions, radii and colours; indices and
/// counts that match the vertices).
pub fn read_ply_geometry(path: &Path) -> Result<PlyGeometry, LoadError> {
    let file = crate::input_file::open(path, crate::input_file::Kind::Geometry)?;
    let file_len = file.metadata().map_err(|e| LoadError::io(path, "read the file", e))?.len();
    load(Reader::new(BufReader::new(file)), file_len, path)
}

/// Reads only the header of a PLY file: its numbers of vertices and faces, for estimates
/// made before reading it.
pub fn read_ply_counts(path: &Path) -> Result<(u64, u64), LoadError> {
    let file = crate::input_file::open(path, crate::input_file::Kind::Geometry)?;
    let mut reader = Reader::new(BufReader::new(file));
    let start = reader.get_mut().fill_buf().map_err(|e| LoadError::io(path, "read the file", e))?;
    if !start.starts_with(b"ply") {
        return Err(LoadError::format(path, "not a ply file: it does not start with the line 'ply'"));
    }
    let header = Parser::<Skip>::new()
        .read_header(&mut reader)
        .map_err(|e| LoadError::format(path, format!("malformed ply file: {}", tidy(&e))))?;
    let count = |name: &str| header.elements.get(name).map_or(0, |e| e.count as u64);
    Ok((count("vertex"), count("face")))
}

/// Decodes the bytes of a PLY file like [`read_ply`]; `path` is used only in messages.
pub fn parse_ply(bytes: &[u8], path: &Path) -> Result<TriangleMesh, LoadError> {
    parse_ply_geometry(bytes, path)?.into_mesh(path)
}

/// Decodes the bytes of a PLY file like [`read_ply_geometry`]; `path` is used only in
/// messages.
pub fn parse_ply_geometry(bytes: &[u8], path: &Path) -> Result<PlyGeometry, LoadError> {
    load(Reader::new(std::io::Cursor::new(bytes)), bytes.len() as u64, path)
}

/// Parses a PLY file of `file_len` bytes from `reader` and validates what it holds.
fn load<R: BufRead + Seek>(mut reader: Reader<R>, file_len: u64, path: &Path) -> Result<PlyGeometry, LoadError> {
    let malformed = |e: ParseError| LoadError::format(path, format!("malformed ply file: {}", tidy(&e)));

    // The library's own message for a wrong signature is a parser-state dump; say it plainly.
    let start = reader.get_mut().fill_buf().map_err(|e| LoadError::io(path, "read the file", e))?;
    if !start.starts_with(b"ply") {
        return Err(LoadError::format(path, "not a ply file: it does not start with the line 'ply'"));
    }
    let header = Parser::<Skip>::new().read_header(&mut reader).map_err(malformed)?;
    // The BufReader's position accounts for what it has buffered, so this is where the
    // element data starts.
    let header_len = reader.get_mut().stream_position().map_err(|e| LoadError::io(path, "read the file", e))?;
    check_counts(&header, file_len.saturating_sub(header_len)).map_err(|m| LoadError::format(path, m))?;
    let layout = check_layout(&header).map_err(|m| LoadError::format(path, m))?;

    let mut vertices = Vec::new();
    let mut faces = Vec::new();
    let mut links = Vec::new();
    for (name, def) in &header.elements {
        match name.as_str() {
            "vertex" => {
                vertices =
                    Parser::<PlyVertex>::new().read_payload_for_element(&mut reader, def, &header).map_err(malformed)?
            }
            "face" => {
                faces =
                    Parser::<PlyFace>::new().read_payload_for_element(&mut reader, def, &header).map_err(malformed)?
            }
            n if matches!(layout, Layout::Strands { element, .. } if element == n) => {
                links =
                    Parser::<PlyLink>::new().read_payload_for_element(&mut reader, def, &header).map_err(malformed)?
            }
            _ => {
                Parser::<Skip>::new().read_payload_for_element(&mut reader, def, &header).map_err(malformed)?;
            }
        }
    }
    let (has_normals, has_uvs) = match layout {
        Layout::Mesh { normals, uvs } => (normals, uvs),
        Layout::Strands { element, widths, colors } => {
            return strands(path, &vertices, &links, element, colors)
                .map(|strands| PlyGeometry::Strands { strands, widths })
        }
    };

    let vertex_count = u32::try_from(vertices.len()).map_err(|_| {
        LoadError::invalid(path, format!("{} vertices is more than a mesh can index (2^32)", vertices.len()))
    })?;
    let mut indices = Vec::new();
    for (f, face) in faces.iter().enumerate() {
        if face.negative {
            return Err(LoadError::invalid(path, format!("face {f} has a negative vertex index")));
        }
        if let Some(&bad) = face.indices.iter().find(|&&i| i >= vertex_count) {
            return Err(LoadError::invalid(
                path,
                format!("face {f} refers to vertex {bad}, but there are only {vertex_count} vertices"),
            ));
        }
        // Fan triangulation, exact for the convex polygons PLY files hold in practice.
        if let Some((&first, rest)) = face.indices.split_first() {
            indices.extend(rest.windows(2).map(|w| [first, w[0], w[1]]));
        }
    }
    if indices.is_empty() {
        return Err(LoadError::invalid(path, "the ply file contains no triangles"));
    }

    let mesh = TriangleMesh {
        positions: vertices.iter().map(|v| Vec3::from(v.position)).collect(),
        normals: has_normals.then(|| vertices.iter().map(|v| Vec3::from(v.normal)).collect()),
        uvs: has_uvs.then(|| vertices.iter().map(|v| v.uv).collect()),
        indices,
    };
    check_mesh(path, &mesh)?;
    Ok(PlyGeometry::Mesh(mesh))
}

/// The strands of `element`'s entries (`links`) over `vertices`: vertex counts, vertex
/// lists, or edges chained into polylines.
fn strands(
    path: &Path,
    vertices: &[PlyVertex],
    links: &[PlyLink],
    element: &str,
    colors: bool,
) -> Result<StrandSet, LoadError> {
    let bad = |m: String| LoadError::invalid(path, m);
    let n = vertices.len();
    let vertex = |i: i64, what: &dyn Fn() -> String| -> Result<usize, LoadError> {
        usize::try_from(i)
            .ok()
            .filter(|&i| i < n)
            .ok_or_else(|| bad(format!("{} refers to vertex {i}, but there are only {n} vertices", what())))
    };
    if let Some(k) = links.iter().position(|l| l.fractional) {
        return Err(bad(format!("{element} {k} has a value that is not an integer")));
    }
    let mut chains: Vec<Vec<usize>> = Vec::new();
    if element == "edge" {
        // Each vertex has at most one edge out and one in; chains start where none comes in.
        let (mut next, mut has_prev) = (vec![usize::MAX; n], vec![false; n]);
        for (k, l) in links.iter().enumerate() {
            let [a, b] = l.scalars[..] else {
                return Err(bad(format!("edge {k} must have two vertex indices (vertex1, vertex2)")));
            };
            let what = || format!("edge {k}");
            let (a, b) = (vertex(a, &what)?, vertex(b, &what)?);
            if next[a] != usize::MAX || has_prev[b] || a == b {
                return Err(bad(format!("edge {k} ({a} to {b}) branches or loops: edges must form open polylines")));
            }
            (next[a], has_prev[b]) = (b, true);
        }
        let mut seen = 0;
        for start in (0..n).filter(|&v| next[v] != usize::MAX && !has_prev[v]) {
            let mut chain = vec![start];
            while let Some(&v) = chain.last().filter(|&&v| next[v] != usize::MAX) {
                chain.push(next[v]);
            }
            seen += chain.len() - 1;
            chains.push(chain);
        }
        if seen != links.len() {
            return Err(bad("some edges form closed loops: edges must form open polylines".into()));
        }
    } else if links.iter().all(|l| l.list.is_empty() && l.scalars.len() == 1) {
        let mut start = 0usize;
        for (k, l) in links.iter().enumerate() {
            let count = usize::try_from(l.scalars[0])
                .ok()
                .filter(|&c| c <= n - start)
                .ok_or_else(|| bad(format!("{element} {k} has {} vertices, past the {n} vertices", l.scalars[0])))?;
            chains.push((start..start + count).collect());
            start += count;
        }
        if start != n {
            return Err(bad(format!("the {element} vertex counts add up to {start}, but there are {n} vertices")));
        }
    } else {
        for (k, l) in links.iter().enumerate() {
            let what = || format!("{element} {k}");
            chains.push(l.list.iter().map(|&i| vertex(i, &what)).collect::<Result<_, _>>()?);
        }
    }
    let mut set = StrandSet::new();
    let mut rgb = Vec::new();
    // A strand of no vertices (a count of 0, an empty list) is no strand.
    for chain in chains.iter().filter(|c| !c.is_empty()) {
        set.push_strand(chain.iter().map(|&i| (Vec3::from(vertices[i].position), vertices[i].radius)));
        rgb.extend(chain.iter().map(|&i| vertices[i].color));
    }
    if let Some(i) = set.points.iter().position(|p| !p.iter().all(|v| v.is_finite()) || p[3] < 0.0) {
        return Err(bad(format!(
            "strand point {i} has a coordinate or radius that is not finite, or a negative radius"
        )));
    }
    if colors {
        if rgb.iter().flatten().any(|c| !(c.is_finite() && *c >= 0.0)) {
            return Err(bad("strand colours must be finite and not negative".into()));
        }
        set.colors = Some(rgb);
    }
    if set.segment_count() == 0 {
        return Err(bad(format!("the ply file's {element} element holds no strand of two or more vertices")));
    }
    Ok(set)
}

/// Flattens a `ply-rs-bw` error onto one line in our style: its messages contain tabs and
/// newlines meant for a terminal dump and start with capitals ("Line 3: Couldn't ...").
fn tidy(e: &ParseError) -> String {
    let text = e.to_string().split_whitespace().collect::<Vec<_>>().join(" ");
    let (prefix, rest) = match text.strip_prefix("Line ").and_then(|t| t.split_once(": ")) {
        Some((line, rest)) => (format!("line {line}: "), rest),
        None => (String::new(), text.as_str()),
    };
    let mut chars = rest.chars();
    match chars.next() {
        Some(c) => prefix + &c.to_lowercase().chain(chars).collect::<String>(),
        None => prefix + "unknown error",
    }
}

/// The least number of bytes one entry of `element` can take in the file.
fn min_entry_bytes(element: &ElementDef, encoding: Encoding) -> u64 {
    let min = match encoding {
        // Each value is at least one character followed by a space or the newline.
        Encoding::Ascii => 2 * element.properties.len() as u64,
        Encoding::BinaryBigEndian | Encoding::BinaryLittleEndian => element
            .properties
            .values()
            .map(|p| match &p.data_type {
                PropertyType::Scalar(t) => scalar_size(t),
                // An empty list is just its length.
                PropertyType::List(len, _) => scalar_size(len),
            })
            .sum(),
    };
    // At least a byte, so that an element without properties cannot make the parser spin
    // through a huge count without consuming input.
    min.max(1)
}

/// "1 byte", "2 bytes".
fn bytes(n: u64) -> String {
    format!("{n} byte{}", if n == 1 { "" } else { "s" })
}

fn scalar_size(t: &ScalarType) -> u64 {
    match t {
        ScalarType::Char | ScalarType::UChar => 1,
        ScalarType::Short | ScalarType::UShort => 2,
        ScalarType::Int | ScalarType::UInt | ScalarType::Float => 4,
        ScalarType::Double => 8,
    }
}

/// Checks that the element counts in the header fit in the `available` bytes after it.
fn check_counts(header: &Header, available: u64) -> Result<(), String> {
    // u128: a count near usize::MAX times a per-entry size cannot overflow it.
    let mut need: u128 = 0;
    // An ascii file may end without a newline after its last value.
    let slack = u128::from(header.encoding == Encoding::Ascii);
    for (name, element) in &header.elements {
        let min = min_entry_bytes(element, header.encoding);
        let before = need;
        need += element.count as u128 * u128::from(min);
        if need > u128::from(available) + slack {
            let count = element.count;
            return Err(if before == 0 {
                format!(
                    "file too short for its header: it declares {count} '{name}' elements of at least {} each, \
                     but only {available} bytes follow the header",
                    bytes(min)
                )
            } else {
                format!(
                    "file too short for its header: it declares {count} '{name}' elements of at least {} each, \
                     which with the elements before them need at least {need} bytes, but only {available} bytes \
                     follow the header",
                    bytes(min)
                )
            });
        }
    }
    Ok(())
}

/// What a header describes.
#[derive(Clone, Copy)]
enum Layout<'h> {
    /// Faces, with or without normals and texture coordinates.
    Mesh { normals: bool, uvs: bool },
    /// Strands listed by the element named `element`.
    Strands { element: &'h str, widths: bool, colors: bool },
}

/// Checks the header has the elements and properties a mesh or strands need.
fn check_layout(header: &Header) -> Result<Layout<'_>, String> {
    let vertex = header.elements.get("vertex").ok_or("no 'vertex' element in the header")?;
    let scalar =
        |name: &str| matches!(vertex.properties.get(name), Some(p) if matches!(p.data_type, PropertyType::Scalar(_)));
    for axis in ["x", "y", "z"] {
        if !scalar(axis) {
            return Err(format!("the 'vertex' element has no numeric '{axis}' property"));
        }
    }
    let has_normals = ["nx", "ny", "nz"].iter().all(|n| scalar(n));
    let has_uvs = UV_NAMES.iter().any(|(u, v)| scalar(u) && scalar(v));

    if !header.elements.contains_key("face") {
        let strand = STRAND_NAMES.iter().chain(&["edge"]).find_map(|n| header.elements.get_key_value(*n));
        if let Some((element, def)) = strand {
            let integers = def.properties.values().all(|p| match &p.data_type {
                PropertyType::Scalar(t) | PropertyType::List(_, t) => {
                    !matches!(t, ScalarType::Float | ScalarType::Double)
                }
            });
            if def.properties.is_empty() || !integers {
                return Err(format!("the '{element}' element must have integer properties (vertex counts or indices)"));
            }
            let widths = ["radius", "width", "thickness"].iter().any(|n| scalar(n));
            let colors = COLOR_NAMES.iter().all(|n| scalar(n));
            return Ok(Layout::Strands { element: element.as_str(), widths, colors });
        }
    }
    let face = header.elements.get("face").ok_or("no 'face' element in the header, so no triangles")?;
    let list = INDEX_NAMES
        .iter()
        .find_map(|n| face.properties.get(*n))
        .ok_or("the 'face' element has no 'vertex_indices' (or 'vertex_index') property")?;
    match &list.data_type {
        PropertyType::List(_, ScalarType::Float | ScalarType::Double) | PropertyType::Scalar(_) => {
            Err(format!("the face property '{}' must be a list of integers, not {:?}", list.name, list.data_type))
        }
        PropertyType::List(..) => Ok(Layout::Mesh { normals: has_normals, uvs: has_uvs }),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::path::PathBuf;

    fn data(name: &str) -> PathBuf {
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/data").join(name)
    }

    fn temp_ply(name: &str, bytes: &[u8]) -> (tempfile::TempDir, PathBuf) {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join(name);
        std::fs::write(&path, bytes).unwrap();
        (dir, path)
    }

    fn error_for(name: &str, bytes: &[u8]) -> String {
        let (_dir, path) = temp_ply(name, bytes);
        let msg = read_ply(&path).unwrap_err().to_string();
        assert!(msg.contains(name), "message does not name the file: {msg}");
        msg
    }

    /// The square both quad files in tests/data describe.
    fn check_quad(mesh: &TriangleMesh) {
        assert_eq!(mesh.positions.len(), 4);
        assert_eq!(mesh.indices, vec![[0, 1, 2], [0, 2, 3]]);
        assert_eq!(mesh.positions[2], Vec3::new(1.0, 1.0, 0.5));
        let normals = mesh.normals.as_ref().expect("normals");
        assert!(normals.iter().all(|&n| n == Vec3::Z));
        assert_eq!(mesh.uvs.as_ref().expect("uvs")[1], [1.0, 0.0]);
    }

    #[test]
    fn reads_ascii() {
        check_quad(&read_ply(&data("quad_ascii.ply")).unwrap());
    }

    #[test]
    fn reads_binary_little_endian() {
        check_quad(&read_ply(&data("quad_binary.ply")).unwrap());
    }

    /// Header and body of a binary file: double positions, a uchar/int index list, an extra
    /// element and property to skip, and a pentagon and a line among the faces.
    fn binary_file(big_endian: bool, vertex_count: &str) -> Vec<u8> {
        let order = if big_endian { "big" } else { "little" };
        let mut out = format!(
            "ply\nformat binary_{order}_endian 1.0\ncomment made by the tress tests\n\
             element vertex {vertex_count}\nproperty double x\nproperty double y\nproperty double z\n\
             property uchar red\nelement face 2\nproperty uchar flags\nproperty list uchar int vertex_indices\n\
             element edge 1\nproperty int vertex1\nproperty int vertex2\nend_header\n"
        )
        .into_bytes();
        let f64s = |out: &mut Vec<u8>, v: f64| out.extend(if big_endian { v.to_be_bytes() } else { v.to_le_bytes() });
        let i32s = |out: &mut Vec<u8>, v: i32| out.extend(if big_endian { v.to_be_bytes() } else { v.to_le_bytes() });
        for i in 0..5 {
            let angle = i as f64 * std::f64::consts::TAU / 5.0;
            f64s(&mut out, angle.cos());
            f64s(&mut out, angle.sin());
            f64s(&mut out, 2.5);
            out.push(200);
        }
        out.extend([7, 5]);
        for i in 0..5 {
            i32s(&mut out, i);
        }
        out.extend([0, 2]);
        i32s(&mut out, 0);
        i32s(&mut out, 1);
        i32s(&mut out, 3);
        i32s(&mut out, 4);
        out
    }

    #[test]
    fn reads_binary_with_polygons_and_extra_elements() {
        for big_endian in [false, true] {
            let (_dir, path) = temp_ply("pentagon.ply", &binary_file(big_endian, "5"));
            let mesh = read_ply(&path).unwrap();
            assert_eq!(mesh.positions.len(), 5);
            assert_eq!(mesh.indices, vec![[0, 1, 2], [0, 2, 3], [0, 3, 4]], "pentagon fan; the line is skipped");
            assert_eq!(mesh.positions[0], Vec3::new(1.0, 0.0, 2.5));
            assert!(mesh.normals.is_none() && mesh.uvs.is_none());
        }
    }

    #[test]
    fn absurd_counts_are_rejected_before_parsing() {
        let msg = error_for("absurd.ply", &binary_file(false, "1000000000000"));
        assert!(msg.contains("declares 1000000000000 'vertex' elements of at least 25 bytes each"), "{msg}");
        let mut text = b"ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n\
            property float z\nelement face 18446744073709551615\nproperty list uchar int vertex_indices\nend_header\n"
            .to_vec();
        text.extend_from_slice(b"0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
        let msg = error_for("absurd_ascii.ply", &text);
        assert!(msg.contains("18446744073709551615 'face' elements"), "{msg}");
        // A property-less element cannot be used to loop without reading.
        let text = b"ply\nformat binary_little_endian 1.0\nelement nothing 999999999999\nend_header\n";
        let msg = error_for("empty_element.ply", text);
        assert!(msg.contains("'nothing' elements of at least 1 byte each"), "{msg}");
    }

    #[test]
    fn missing_file_names_the_file() {
        let dir = tempfile::tempdir().unwrap();
        let msg = read_ply(&dir.path().join("nowhere.ply")).unwrap_err().to_string();
        assert!(msg.contains("nowhere.ply") && msg.contains("could not open the file"), "{msg}");
    }

    #[test]
    fn malformed_files_give_clear_errors() {
        let msg = error_for("not_ply.ply", b"solid cube\nfacet normal 0 0 1\n");
        assert!(msg.contains("not a ply file: it does not start with the line 'ply'"), "{msg}");

        let msg = error_for("no_end.ply", b"ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n");
        assert!(msg.contains("malformed ply file") && msg.contains("end_header"), "{msg}");

        let text = b"ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n\
            element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 zero 0\n0 1 0\n3 0 1 2\n";
        let msg = error_for("bad_number.ply", text);
        assert!(msg.contains("malformed ply file") && msg.contains("zero"), "{msg}");

        // Short enough to fail while parsing...
        let mut truncated = binary_file(false, "5");
        truncated.truncate(truncated.len() - 10);
        let msg = error_for("truncated.ply", &truncated);
        assert!(msg.contains("malformed ply file: line 22: unexpected end of file"), "{msg}");
        // ...or already when checking the header's counts against the length.
        truncated.truncate(truncated.len() - 20);
        let msg = error_for("truncated.ply", &truncated);
        assert!(msg.contains("too short for its header") && msg.contains("need at least 137 bytes"), "{msg}");
    }

    #[test]
    fn rejects_meshes_it_cannot_use() {
        let header = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n\
            element face 1\nproperty list uchar int vertex_indices\nend_header\n";
        let msg = error_for("range.ply", format!("{header}0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n").as_bytes());
        assert!(msg.contains("face 0 refers to vertex 7, but there are only 3 vertices"), "{msg}");
        let msg = error_for("negative.ply", format!("{header}0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n").as_bytes());
        assert!(msg.contains("face 0 has a negative vertex index"), "{msg}");
        // The ascii grammar has no spelling for NaN, so poke non-finite values into a binary file.
        let mut bytes = binary_file(false, "5");
        let body = bytes.len() - (5 * 25 + 22 + 10 + 8);
        bytes[body + 25 + 8..body + 25 + 16].copy_from_slice(&f64::NAN.to_le_bytes());
        let msg = error_for("nan.ply", &bytes);
        assert!(msg.contains("vertex 1 is not finite"), "{msg}");
        let mut bytes = binary_file(false, "5");
        bytes[body + 4 * 25..body + 4 * 25 + 8].copy_from_slice(&1e300f64.to_le_bytes());
        let msg = error_for("big.ply", &bytes);
        assert!(msg.contains("vertex 4 is not finite"), "{msg}");
        let msg = error_for("line.ply", format!("{header}0 0 0\n1 0 0\n0 1 0\n2 0 1\n").as_bytes());
        assert!(msg.contains("contains no triangles"), "{msg}");

        let no_z = b"ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nend_header\n0 0\n";
        let msg = error_for("no_z.ply", no_z);
        assert!(msg.contains("no numeric 'z' property"), "{msg}");
        let points = b"ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\n\
            end_header\n0 0 0\n";
        let msg = error_for("cloud.ply", points);
        assert!(msg.contains("no 'face' element"), "{msg}");
        let float_list = b"ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n\
            property float z\nelement face 0\nproperty list uchar float vertex_indices\nend_header\n0 0 0\n";
        let msg = error_for("float_list.ply", float_list);
        assert!(msg.contains("'vertex_indices' must be a list of integers"), "{msg}");
    }

    #[test]
    fn accepts_vertex_index_spelling_and_st_coordinates() {
        let text = b"ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n\
            property float s\nproperty float t\nelement face 1\nproperty list uchar uint vertex_index\nend_header\n\
            0 0 0 0 0\n1 0 0 1 0\n0 1 0 0.5 1\n3 0 1 2\n";
        let (_dir, path) = temp_ply("st.ply", text);
        let mesh = read_ply(&path).unwrap();
        assert_eq!(mesh.indices, vec![[0, 1, 2]]);
        assert_eq!(mesh.uvs.unwrap()[2], [0.5, 1.0]);
    }

    fn strands_of(bytes: &[u8]) -> (StrandSet, bool) {
        match parse_ply_geometry(bytes, Path::new("hair.ply")).unwrap() {
            PlyGeometry::Strands { strands, widths } => (strands, widths),
            PlyGeometry::Mesh(_) => panic!("a mesh"),
        }
    }

    const STRAND_HEADER: &str = "ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\nproperty float y\n\
                                 property float z\n";

    #[test]
    fn strands_by_vertex_counts_with_widths_and_byte_colours() {
        let text = format!(
            "{STRAND_HEADER}property float thickness\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n\
             element strand 2\nproperty int nvertices\nend_header\n\
             0 0 0 0.2 255 0 0\n0 1 0 0.2 255 0 0\n0 2 0 0.1 255 0 0\n1 0 0 0.4 0 0 51\n1 1 0 0.4 0 0 51\n2\n3\n"
        );
        // Two vertices then three: counts are in file order, the vertices follow each other.
        let text = text.replace("2\n3\n", "3\n2\n");
        let (s, widths) = strands_of(text.as_bytes());
        assert!(widths);
        assert_eq!(s.offsets, vec![0, 3, 5]);
        assert_eq!(s.points[2], [0.0, 2.0, 0.0, 0.05]);
        assert_eq!(s.points[4], [1.0, 1.0, 0.0, 0.2]);
        let c = s.colors.as_ref().unwrap();
        assert_eq!((c[0], c[3]), ([1.0, 0.0, 0.0], [0.0, 0.0, 0.2]));
        // As a mesh it is refused, plainly.
        let e = parse_ply(text.as_bytes(), Path::new("hair.ply")).unwrap_err().to_string();
        assert!(e.contains("strands, not triangles"), "{e}");
    }

    #[test]
    fn strands_by_vertex_lists_and_by_chained_edges() {
        let points = "0 0 0\n0 1 0\n0 2 0\n1 0 0\n1 1 0\n";
        let lists = format!(
            "{STRAND_HEADER}element curve 2\nproperty list uchar int vertex_indices\nend_header\n{points}3 0 1 2\n2 4 3\n"
        );
        let (s, widths) = strands_of(lists.as_bytes());
        assert!(!widths && s.points.iter().all(|p| p[3] == 0.0));
        assert_eq!(s.offsets, vec![0, 3, 5]);
        assert_eq!(s.points[3][..3], [1.0, 1.0, 0.0]);
        // Edges in any order chain into polylines from the vertex no edge enters.
        let edges = format!(
            "{STRAND_HEADER}element edge 3\nproperty int vertex1\nproperty int vertex2\nend_header\n{points}1 2\n3 4\n0 1\n"
        );
        let (s, _) = strands_of(edges.as_bytes());
        assert_eq!(s.offsets, vec![0, 3, 5]);
        // Strands of no vertices (a count of 0, an empty list) are no strands.
        let counts = format!("{STRAND_HEADER}element strand 4\nproperty int n\nend_header\n{points}0\n3\n0\n2\n");
        assert_eq!(strands_of(counts.as_bytes()).0.offsets, vec![0, 3, 5]);
        let empty = lists.replace("element curve 2", "element curve 3").replace("2 4 3\n", "2 4 3\n0\n");
        assert_eq!(strands_of(empty.as_bytes()).0.offsets, vec![0, 3, 5]);
        assert_eq!(s.points[2][..3], [0.0, 2.0, 0.0]);
        // Broken strand data: errors naming the file and the cause.
        for (text, needle) in [
            (lists.replace("3 0 1 2", "3 0 1 9"), "refers to vertex 9"),
            (edges.replace("3 4\n", "0 4\n"), "branches"),
            (edges.replace("1 2\n3 4\n0 1\n", "0 1\n1 2\n2 0\n"), "closed loops"),
            (format!("{STRAND_HEADER}element strand 1\nproperty int n\nend_header\n{points}4\n"), "add up to 4"),
            (format!("{STRAND_HEADER}element strand 1\nproperty float n\nend_header\n{points}4\n"), "integer"),
        ] {
            let e = parse_ply_geometry(text.as_bytes(), Path::new("hair.ply")).unwrap_err().to_string();
            assert!(e.starts_with("hair.ply: ") && e.contains(needle), "{needle}: {e}");
        }
    }
}
