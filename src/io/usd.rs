//! USD text files (`.usda`): `BasisCurves` and `Mesh` prims in, strands and meshes out,
//! through the pure-Rust `openusd` crate (its 0.6 release: later ones need a newer Rust
//! than tress's toolchain). The crate composes the stage (sublayers, references,
//! variants) and evaluates transform stacks; this module reads the two prim types:
//!
//! - **BasisCurves**: `type` linear or cubic (the schema's default), `basis` bezier (the
//!   default), bspline or catmullRom, `wrap` nonperiodic, periodic or pinned;
//!   `curveVertexCounts`, `points`, `widths` (diameters; constant, uniform, varying or
//!   vertex) and `primvars:displayColor` (the same interpolations). Cubic curves are
//!   sampled at [`PIECES_PER_SEGMENT`] linear pieces per segment; vertex widths and colours
//!   follow the curve's basis. Hermite curves are skipped.
//! - **Mesh**: `points`, `faceVertexCounts`, `faceVertexIndices` (polygons as fans),
//!   vertex `normals`, `primvars:st` (vertex or face-varying, indexed or not) and a
//!   constant `displayColor`. Subdivision surfaces are rendered as their control cage.
//! - `DistantLight`, `DomeLight` (constant colour) and `SphereLight`: colour × intensity ×
//!   2^exposure.
//!
//! A Z-up stage (`upAxis = "Z"`) is turned Y-up. Only text layers are read: the crate's
//! binary (`.usdc`) reader has not been checked against hostile files here. The crate's
//! text parser recurses once per nesting level, so every layer's nesting depth is checked
//! before it is parsed ([`MAX_NESTING`]); hostile files cannot overflow the stack. The
//! crate walks a path's ancestors without end when a `}` closes no `{`, so path literals
//! and `xformOpOrder` entries are checked too.
//!
//! [`write_usd`] writes linear `BasisCurves` (points, vertex widths and colours) and
//! triangle `Mesh`es, which this module reads back unchanged.

use super::imported::Imported;
use crate::accel::Shape;
use crate::error::LoadError;
use crate::geometry::curve::{Blend, CubicBasis};
use crate::geometry::{StrandSet, TriangleMesh};
use crate::light::Light;
use crate::scene::{HairEntry, HairSource, MeshEntry, MeshSource};
use crate::shading::{tube::Tube, Material};
use glam::{Affine3A, DMat4, Vec3};
use openusd::schemas::geom::{BasisCurves, Curves, Gprim, Imageable, Mesh, PointBased, Visibility, Xformable};
use openusd::usd::{Prim, PrimPredicate, SchemaBase, SchemaKind, Stage, TimeCode};
use openusd::{ar, gf, sdf};
use std::io;
use std::path::Path;

/// Linear pieces per cubic segment.
pub const PIECES_PER_SEGMENT: usize = 8;
/// Deepest nesting of `(`, `[` and `{` a layer may have.
pub const MAX_NESTING: usize = 128;
/// Width given to curves without `widths` (Maya's default hair width).
const DEFAULT_WIDTH: f32 = 0.01;

/// Reads a `.usda` file (and the layers it composes).
pub fn read_usd(path: &Path) -> Result<Imported, LoadError> {
    let text = std::fs::read(path).map_err(|e| LoadError::io(path, "read the file", e))?;
    check_layer(&text).map_err(|m| LoadError::format(path, m))?;
    let name = path.to_str().ok_or_else(|| LoadError::format(path, "the path is not UTF-8"))?;
    let stage = Stage::builder().resolver(GuardedResolver(ar::DefaultResolver::new())).open(name).map_err(|e| {
        // The crate's stage errors do not carry the line; its parser does.
        let text = String::from_utf8_lossy(&text);
        let mut parser = openusd::usda::parser::Parser::new(&text);
        match (parser.parse(), parser.last_error_highlight()) {
            (Err(_), Some(h)) => LoadError::format(path, format!("line {}: {e:#}", h.line)),
            _ => LoadError::format(path, format!("{e:#}")),
        }
    })?;
    let errors = stage.composition_errors();
    let mut out = Imported::default();
    if let Some(first) = errors.first() {
        out.warnings.push(format!("{}: {} composition problem(s), the first: {first}", path.display(), errors.len()));
    }
    read_stage(&stage, &mut out).map_err(|e| LoadError::invalid(path, format!("{e:#}")))?;
    Ok(out)
}

/// Checks a layer's bytes before the crate parses them: UTF-8 text with a `#usda` header,
/// at most [`MAX_NESTING`] levels of brackets outside strings and comments, prim names
/// that are identifiers and path literals whose `}` close a `{`.
fn check_layer(bytes: &[u8]) -> Result<(), String> {
    let text =
        std::str::from_utf8(bytes).map_err(|_| "not UTF-8 text (binary .usdc layers are not read)".to_string())?;
    if !text.trim_start().starts_with("#usda") {
        return Err("not a USD text layer: it does not start with `#usda`".into());
    }
    check_prim_names(text)?;
    let (mut depth, mut line) = (0usize, 1u32);
    let b = text.as_bytes();
    let mut i = 0;
    while i < b.len() {
        match b[i] {
            b'\n' => line += 1,
            b'#' => {
                while i < b.len() && b[i] != b'\n' {
                    i += 1;
                }
                continue;
            }
            q @ (b'"' | b'\'') => {
                let triple = b.get(i..i + 3) == Some(&[q, q, q][..]);
                i += if triple { 3 } else { 1 };
                while i < b.len() {
                    if b[i] == b'\\' {
                        i += 2;
                        continue;
                    }
                    if b[i] == b'\n' {
                        line += 1;
                    }
                    if b[i] == q && (!triple || b.get(i..i + 3) == Some(&[q, q, q][..])) {
                        i += if triple { 3 } else { 1 };
                        break;
                    }
                    i += 1;
                }
                continue;
            }
            b'<' => check_path_literal(b, i, line)?,
            b'(' | b'[' | b'{' => {
                depth += 1;
                if depth > MAX_NESTING {
                    return Err(format!("line {line}: brackets nest deeper than {MAX_NESTING} levels"));
                }
            }
            b')' | b']' | b'}' => depth = depth.saturating_sub(1),
            _ => {}
        }
        i += 1;
    }
    Ok(())
}

/// Checks that every prim a layer defines (`def`, `over` or `class`, then an optional type,
/// then the quoted name) is named by an identifier (a letter or `_`, then letters, digits
/// or `_`), as USD requires: the crate recurses without end on a prim path holding other
/// characters (a name like `"Wor}d"` overflowed the stack).
fn check_prim_names(text: &str) -> Result<(), String> {
    for (n, line) in text.lines().enumerate() {
        let words = line.trim_start();
        let Some(rest) = ["def ", "over ", "class "].iter().find_map(|k| words.strip_prefix(k)) else { continue };
        // The name is the first quoted string; a line without one is left to the parser.
        let Some(name) = rest.split('"').nth(1) else { continue };
        if !is_identifier(name) {
            return Err(format!("line {}: prim name \"{name}\" is not an identifier (letters, digits and _)", n + 1));
        }
    }
    Ok(())
}

/// Whether `name` is an identifier: a letter or `_`, then letters, digits or `_`.
fn is_identifier(name: &str) -> bool {
    let mut chars = name.chars();
    chars.next().is_some_and(|c| c.is_ascii_alphabetic() || c == '_')
        && chars.all(|c| c.is_ascii_alphanumeric() || c == '_')
}

/// Checks the path literal opening at `b[at]` (a `<`, up to the next `>`): every `}` in it
/// must close a variant selection's `{`. The crate's `Path::parent` returns a path ending in
/// a `}` without a `{` unchanged, so walking the ancestors of `</A}>` never ends.
fn check_path_literal(b: &[u8], at: usize, line: u32) -> Result<(), String> {
    let mut open = false;
    // Stopping at the next `<` or line end keeps the whole check linear in the text.
    for &c in b[at + 1..].iter().take_while(|&&c| !matches!(c, b'>' | b'<' | b'\n')) {
        match c {
            b'{' => open = true,
            b'}' if !open => return Err(format!("line {line}: path has a `}}` that closes no variant selection `{{`")),
            b'}' => open = false,
            _ => {}
        }
    }
    Ok(())
}

/// Checks that every `xformOpOrder` entry of a prim is `!resetXformStack!` or an
/// (optionally `!invert!`ed) property name, identifiers joined by `:`: the crate makes an
/// attribute path of each entry, and one holding a `}` (`xformOp:tr}anslate`) sends its
/// ancestor walk round forever, like a path literal in [`check_path_literal`].
fn check_op_order(x: &AnyPrim) -> Res<()> {
    for op in x.xform_op_order()?.unwrap_or_default() {
        let name = op.strip_prefix("!invert!").unwrap_or(&op);
        if op != "!resetXformStack!" && !name.split(':').all(is_identifier) {
            anyhow::bail!("{}: xformOpOrder entry \"{op}\" is not a property name", x.0.path());
        }
    }
    Ok(())
}

/// The default file resolver, with every layer it opens checked by [`check_layer`].
struct GuardedResolver(ar::DefaultResolver);

impl ar::Resolver for GuardedResolver {
    fn create_identifier(&self, asset_path: &str, anchor: Option<&ar::ResolvedPath>) -> String {
        self.0.create_identifier(asset_path, anchor)
    }
    fn resolve(&self, asset_path: &str) -> Option<ar::ResolvedPath> {
        self.0.resolve(asset_path)
    }
    fn resolve_for_new_asset(&self, asset_path: &str) -> Option<ar::ResolvedPath> {
        self.0.resolve_for_new_asset(asset_path)
    }
    fn open_asset(&self, resolved: &ar::ResolvedPath) -> io::Result<Box<dyn ar::Asset>> {
        let bytes = self.0.open_asset(resolved)?.read_all()?;
        check_layer(&bytes)
            .map_err(|m| io::Error::new(io::ErrorKind::InvalidData, format!("{}: {m}", resolved.display())))?;
        Ok(Box::new(io::Cursor::new(bytes)))
    }
    fn identity(&self) -> String {
        self.0.identity()
    }
}

/// Any prim seen as transformable, to evaluate the transform ops of ancestors whatever
/// their type.
struct AnyPrim(Prim);

impl SchemaBase for AnyPrim {
    const KIND: SchemaKind = SchemaKind::ConcreteTyped;
    fn prim(&self) -> &Prim {
        &self.0
    }
}
impl Imageable for AnyPrim {}
impl Xformable for AnyPrim {}

type Res<T> = anyhow::Result<T>;

fn read_stage(stage: &Stage, out: &mut Imported) -> Res<()> {
    let z_up = matches!(stage.stage_metadata("upAxis")?, Some(sdf::Value::Token(t)) if t.as_str() == "Z");
    // Z up to Y up: (x, y, z) -> (x, z, -y).
    let up_fix = if z_up { DMat4::from_rotation_x(-std::f64::consts::FRAC_PI_2) } else { DMat4::IDENTITY };
    let mut paths = Vec::new();
    stage.traverse(PrimPredicate::DEFAULT, |p| paths.push(p.clone()))?;
    for path in paths {
        let prim = stage.prim(path.clone());
        let kind = prim.type_name()?.map(|t| t.as_str().to_string()).unwrap_or_default();
        if !matches!(kind.as_str(), "BasisCurves" | "Mesh" | "DistantLight" | "DomeLight" | "SphereLight") {
            continue;
        }
        if AnyPrim(prim.clone()).compute_visibility()? == Visibility::Invisible {
            continue;
        }
        let world = up_fix * world_matrix(stage, &path)?;
        let transform = Affine3A::from_mat4(world.as_mat4());
        if !transform.is_finite() {
            anyhow::bail!("{path}: its transform is not finite");
        }
        let what = |e: anyhow::Error| e.context(format!("{path}"));
        match kind.as_str() {
            "BasisCurves" => {
                let c = BasisCurves::get(stage, path.clone())?.expect("typed BasisCurves");
                if let Some(entry) = read_curves(&c, transform, &mut out.warnings).map_err(what)? {
                    out.hair.push(entry);
                }
            }
            "Mesh" => {
                let m = Mesh::get(stage, path.clone())?.expect("typed Mesh");
                let (mesh, color) = read_mesh(&m).map_err(what)?;
                let material = Material::Diffuse { color: color.unwrap_or(Vec3::splat(0.5)) };
                out.meshes.push(MeshEntry { source: MeshSource::Inline(mesh), material, transform });
            }
            light => out.lights.push(read_light(&prim, light, &transform).map_err(what)?),
        }
    }
    Ok(())
}

/// The prim's local-to-world matrix: its ancestors' transform ops, outermost first, up to
/// one that resets the stack.
fn world_matrix(stage: &Stage, path: &sdf::Path) -> Res<DMat4> {
    let mut chain = vec![path.clone()];
    while let Some(p) = chain.last().and_then(|p| p.parent()) {
        if p.as_str() == "/" || p.as_str().is_empty() {
            break;
        }
        chain.push(p);
    }
    let mut m = DMat4::IDENTITY;
    for p in chain.iter().rev() {
        let x = AnyPrim(stage.prim(p.clone()));
        check_op_order(&x)?;
        let local = DMat4::from_cols_array(&x.local_to_parent_transform(TimeCode::new(0.0))?.0);
        m = if x.resets_xform_stack()? { local } else { m * local };
    }
    Ok(m)
}

fn vec3s(v: Option<sdf::Value>, what: &str) -> Res<Option<Vec<Vec3>>> {
    let g = |v: &gf::Vec3f| Vec3::new(v.x, v.y, v.z);
    Ok(match v {
        None => None,
        Some(sdf::Value::Vec3fVec(v)) => Some(v.iter().map(g).collect()),
        Some(sdf::Value::Vec3dVec(v)) => {
            Some(v.iter().map(|p| Vec3::new(p.x as f32, p.y as f32, p.z as f32)).collect())
        }
        Some(sdf::Value::Vec3hVec(v)) => {
            Some(v.iter().map(|p| Vec3::new(p.x.to_f32(), p.y.to_f32(), p.z.to_f32())).collect())
        }
        Some(other) => anyhow::bail!("`{what}` is not an array of 3-vectors: {}", short(&other)),
    })
}

fn floats(v: Option<sdf::Value>, what: &str) -> Res<Option<Vec<f32>>> {
    Ok(match v {
        None => None,
        Some(sdf::Value::FloatVec(v)) => Some(v),
        Some(sdf::Value::DoubleVec(v)) => Some(v.iter().map(|&x| x as f32).collect()),
        Some(sdf::Value::HalfVec(v)) => Some(v.iter().map(|x| x.to_f32()).collect()),
        Some(other) => anyhow::bail!("`{what}` is not an array of numbers: {}", short(&other)),
    })
}

fn ints(v: Option<sdf::Value>, what: &str) -> Res<Option<Vec<i64>>> {
    Ok(match v {
        None => None,
        Some(sdf::Value::IntVec(v)) => Some(v.iter().map(|&x| x as i64).collect()),
        Some(sdf::Value::Int64Vec(v)) => Some(v),
        Some(sdf::Value::UintVec(v)) => Some(v.iter().map(|&x| x as i64).collect()),
        Some(other) => anyhow::bail!("`{what}` is not an array of integers: {}", short(&other)),
    })
}

fn token(v: Option<sdf::Value>, default: &str) -> String {
    match v {
        Some(sdf::Value::Token(t)) => t.as_str().to_string(),
        Some(sdf::Value::String(s)) => s,
        _ => default.to_string(),
    }
}

/// A value's variant for messages, without its (possibly huge) contents.
fn short(v: &sdf::Value) -> String {
    let s = format!("{v:?}");
    s.split('(').next().unwrap_or(&s).to_string()
}

/// How a primvar's values map onto a curve batch.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Interpolation {
    Constant,
    Uniform,
    Varying,
    Vertex,
}

fn interpolation(attr: &openusd::usd::Attribute, default: Interpolation) -> Res<Interpolation> {
    Ok(match attr.get_metadata::<sdf::Value>("interpolation")? {
        None => default,
        Some(v) => match token(Some(v), "").as_str() {
            "constant" => Interpolation::Constant,
            "uniform" => Interpolation::Uniform,
            "varying" => Interpolation::Varying,
            "vertex" | "faceVarying" => Interpolation::Vertex,
            other => anyhow::bail!("unknown interpolation `{other}`"),
        },
    })
}

/// One curve of a batch, ready to sample: its control points (with wrap phantoms added)
/// and its segments.
struct CurveShape {
    basis: Option<CubicBasis>,
    periodic: bool,
    pinned: bool,
}

impl CurveShape {
    /// Control values with the wrap applied: periodic curves repeat their first values,
    /// pinned B-spline and Catmull-Rom curves get phantom ends `2 P0 − P1` so they start
    /// and end at their end points (the USD BasisCurves schema's rule).
    fn wrap<T: Blend>(&self, v: &[T]) -> Vec<T> {
        let mut out = v.to_vec();
        match self.basis {
            None if self.periodic && !v.is_empty() => out.push(v[0]),
            Some(b) if self.periodic => out.extend(v.iter().cycle().take(if b == CubicBasis::Bezier { 1 } else { 3 })),
            Some(CubicBasis::BSpline | CubicBasis::CatmullRom) if self.pinned && v.len() >= 2 => {
                let n = v.len();
                out.insert(0, v[0].scaled(2.0).plus(v[1].scaled(-1.0)));
                out.push(v[n - 1].scaled(2.0).plus(v[n - 2].scaled(-1.0)));
            }
            _ => {}
        }
        out
    }

    /// Number of segments of a curve with `n` control values (after wrapping).
    fn segments(&self, n: usize) -> usize {
        match self.basis {
            None => n.saturating_sub(1),
            Some(b) => b.segments(n),
        }
    }

    /// Samples per-vertex values (after wrapping) along the curve.
    fn sample<T: Blend>(&self, v: &[T]) -> Vec<T> {
        match self.basis {
            None => v.to_vec(),
            Some(b) => crate::geometry::curve::sample_cubic(b, v, PIECES_PER_SEGMENT),
        }
    }

    /// Spreads `k + 1` per-segment-end values over the samples of `k` segments.
    fn spread<T: Blend>(&self, ends: &[T]) -> Vec<T> {
        let pieces = if self.basis.is_some() { PIECES_PER_SEGMENT } else { 1 };
        let mut out = Vec::with_capacity((ends.len().saturating_sub(1)) * pieces + 1);
        for (s, w) in ends.windows(2).enumerate() {
            for k in usize::from(s > 0)..=pieces {
                let t = k as f32 / pieces as f32;
                out.push(w[0].scaled(1.0 - t).plus(w[1].scaled(t)));
            }
        }
        if ends.len() == 1 {
            out.push(ends[0]);
        }
        out
    }
}

/// Values of one curve for a primvar with `interp`: `offset` is the curve's first control
/// point, `varying` its first segment end, `c` its index.
fn per_curve<T: Blend>(
    shape: &CurveShape,
    values: &[T],
    interp: Interpolation,
    (c, offset, count, varying): (usize, usize, usize, usize),
    samples: usize,
) -> Res<Vec<T>> {
    let v = match interp {
        Interpolation::Constant => vec![values[0]; samples],
        Interpolation::Uniform => vec![values[c]; samples],
        Interpolation::Vertex => shape.sample(&shape.wrap(&values[offset..offset + count])),
        Interpolation::Varying => {
            let ends = shape.segments(shape.wrap(&vec![0.0f32; count]).len()) + 1;
            let ends = if shape.periodic { ends - 1 } else { ends };
            let mut e = values[varying..varying + ends].to_vec();
            if shape.periodic {
                e.push(e[0]);
            }
            shape.spread(&e)
        }
    };
    anyhow::ensure!(v.len() == samples, "a primvar gives {} values for {samples} samples", v.len());
    Ok(v)
}

fn read_curves(c: &BasisCurves, transform: Affine3A, warnings: &mut Vec<String>) -> Res<Option<HairEntry>> {
    let kind = token(c.type_attr().get()?, "cubic");
    let basis_name = token(c.basis_attr().get()?, "bezier");
    let wrap = token(c.wrap_attr().get()?, "nonperiodic");
    let basis = match (kind.as_str(), basis_name.as_str()) {
        ("linear", _) => None,
        ("cubic", "bezier") => Some(CubicBasis::Bezier),
        ("cubic", "bspline") => Some(CubicBasis::BSpline),
        ("cubic", "catmullRom") => Some(CubicBasis::CatmullRom),
        (t, b) => {
            warnings.push(format!("{}: {t} {b} curves are not supported: skipped", c.path()));
            return Ok(None);
        }
    };
    let shape = CurveShape { basis, periodic: wrap == "periodic", pinned: wrap == "pinned" };
    let points = vec3s(c.points_attr().get()?, "points")?.unwrap_or_default();
    let counts = ints(c.curve_vertex_counts_attr().get()?, "curveVertexCounts")?.unwrap_or_default();
    anyhow::ensure!(counts.iter().all(|&n| n >= 0), "`curveVertexCounts` has a negative count");
    let total: i64 = counts.iter().sum();
    anyhow::ensure!(
        total as usize == points.len(),
        "`curveVertexCounts` sum to {total} but there are {} points",
        points.len()
    );
    anyhow::ensure!(points.iter().all(|p| p.is_finite()), "`points` must be finite");
    let widths_attr = c.widths_attr();
    let widths = floats(widths_attr.get()?, "widths")?;
    let width_interp = interpolation(&widths_attr, Interpolation::Vertex)?;
    let color_attr = c.display_color_attr();
    let colors = vec3s(color_attr.get()?, "primvars:displayColor")?;
    let color_interp = interpolation(&color_attr, Interpolation::Constant)?;
    // Each primvar's expected length for its interpolation.
    let varying_total: usize = counts
        .iter()
        .map(|&n| {
            let s = shape.segments(shape.wrap(&vec![0.0f32; n as usize]).len());
            if shape.periodic {
                s
            } else {
                s + 1
            }
        })
        .sum();
    let expect = |i: Interpolation| match i {
        Interpolation::Constant => 1,
        Interpolation::Uniform => counts.len(),
        Interpolation::Varying => varying_total,
        Interpolation::Vertex => points.len(),
    };
    if let Some(w) = &widths {
        anyhow::ensure!(
            w.len() == expect(width_interp),
            "{} widths where {width_interp:?} needs {}",
            w.len(),
            expect(width_interp)
        );
        anyhow::ensure!(w.iter().all(|x| x.is_finite() && *x >= 0.0), "widths must be finite and not negative");
    } else {
        warnings.push(format!("{}: no widths: curves are {DEFAULT_WIDTH} wide", c.path()));
    }
    if let Some(col) = &colors {
        anyhow::ensure!(
            col.len() == expect(color_interp),
            "{} colours where {color_interp:?} needs {}",
            col.len(),
            expect(color_interp)
        );
        anyhow::ensure!(
            col.iter().all(|x| x.is_finite() && x.min_element() >= 0.0),
            "colours must be finite and not negative"
        );
    }
    let constant_color = match (&colors, color_interp) {
        (Some(c), Interpolation::Constant) => Some(c[0]),
        _ => None,
    };
    let mut set = StrandSet::new();
    let mut point_colors = Vec::new();
    let (mut offset, mut varying, mut skipped) = (0usize, 0usize, 0usize);
    for (i, &n) in counts.iter().enumerate() {
        let n = n as usize;
        let cps = shape.wrap(&points[offset..offset + n]);
        let segments = shape.segments(cps.len());
        let ends = if shape.periodic { segments } else { segments + 1 };
        if segments == 0 {
            skipped += 1;
        } else {
            let p = shape.sample(&cps);
            let at = (i, offset, n, varying);
            let w = match &widths {
                Some(w) => per_curve(&shape, w, width_interp, at, p.len())?,
                None => vec![DEFAULT_WIDTH; p.len()],
            };
            if let (Some(col), None) = (&colors, constant_color) {
                point_colors.extend(per_curve(&shape, col, color_interp, at, p.len())?.iter().map(|c| c.to_array()));
            }
            set.push_strand(p.into_iter().zip(w).map(|(q, w)| (q, 0.5 * w.max(0.0))));
        }
        offset += n;
        varying += ends;
    }
    if skipped > 0 {
        warnings.push(format!("{}: {skipped} curve(s) with too few points for their basis: skipped", c.path()));
    }
    if set.strand_count() == 0 {
        return Ok(None);
    }
    if !point_colors.is_empty() {
        set.colors = Some(point_colors);
    }
    let d = constant_color.unwrap_or(crate::hair_system::HairSystem::default().hair_color);
    let material = Material::Tube(Tube { ambient: d, diffuse: d, ..Tube::default() });
    Ok(Some(HairEntry {
        source: HairSource::Inline(set),
        material,
        transform,
        radius_scale: 1.0,
        file_colors: true,
        lod: None,
    }))
}

fn read_mesh(m: &Mesh) -> Res<(TriangleMesh, Option<Vec3>)> {
    let positions = vec3s(m.points_attr().get()?, "points")?.unwrap_or_default();
    let counts = ints(m.face_vertex_counts_attr().get()?, "faceVertexCounts")?.unwrap_or_default();
    let indices = ints(m.face_vertex_indices_attr().get()?, "faceVertexIndices")?.unwrap_or_default();
    let total: i64 = counts.iter().map(|&c| c.max(0)).sum();
    anyhow::ensure!(counts.iter().all(|&c| c >= 0), "`faceVertexCounts` has a negative count");
    anyhow::ensure!(
        total as usize == indices.len(),
        "`faceVertexCounts` sum to {total} but there are {} indices",
        indices.len()
    );
    let n = positions.len();
    anyhow::ensure!(indices.iter().all(|&i| i >= 0 && (i as usize) < n), "a face index is not one of the {n} points");
    let normals_attr = m.normals_attr();
    let normals = vec3s(normals_attr.get()?, "normals")?.filter(|v| {
        v.len() == n && interpolation(&normals_attr, Interpolation::Vertex).ok() == Some(Interpolation::Vertex)
    });
    // UVs: vertex (one per point) or face-varying (one per face corner), optionally indexed.
    let st_attr = m.prim().attribute("primvars:st");
    let st: Option<Vec<[f32; 2]>> = match st_attr.get::<sdf::Value>()? {
        None => None,
        Some(sdf::Value::Vec2fVec(v)) => Some(v.iter().map(|p| [p.x, p.y]).collect()),
        Some(sdf::Value::Vec2dVec(v)) => Some(v.iter().map(|p| [p.x as f32, p.y as f32]).collect()),
        Some(other) => anyhow::bail!("`primvars:st` is not an array of 2-vectors: {}", short(&other)),
    };
    let st_indices = ints(m.prim().attribute("primvars:st:indices").get()?, "primvars:st:indices")?;
    interpolation(&st_attr, Interpolation::Vertex)?;
    let face_varying = matches!(st_attr.get_metadata::<sdf::Value>("interpolation")?, Some(sdf::Value::Token(t)) if t.as_str() == "faceVarying");
    // The UV of corner `k` (running over all faces) of point `p`.
    let uv_of = |k: usize, p: usize| -> Res<Option<[f32; 2]>> {
        let Some(st) = &st else { return Ok(None) };
        let slot = if face_varying { k } else { p };
        let slot = match &st_indices {
            Some(ix) => *ix.get(slot).ok_or_else(|| anyhow::anyhow!("`primvars:st:indices` is too short"))? as usize,
            None => slot,
        };
        Ok(Some(*st.get(slot).ok_or_else(|| anyhow::anyhow!("`primvars:st` has no value {slot}"))?))
    };
    let mut mesh = TriangleMesh::default();
    let (mut uvs, mut out_normals) = (Vec::new(), Vec::new());
    let mut corners: std::collections::HashMap<(u32, [u32; 2]), u32> = std::collections::HashMap::new();
    let mut k = 0usize;
    for &c in &counts {
        let mut ids = Vec::with_capacity(c as usize);
        for _ in 0..c {
            let p = indices[k] as usize;
            let uv = uv_of(k, p)?;
            let key = (p as u32, uv.map_or([u32::MAX; 2], |u| u.map(f32::to_bits)));
            let id = *corners.entry(key).or_insert_with(|| {
                mesh.positions.push(positions[p]);
                uvs.push(uv.unwrap_or([0.0; 2]));
                if let Some(ns) = &normals {
                    out_normals.push(ns[p]);
                }
                (mesh.positions.len() - 1) as u32
            });
            ids.push(id);
            k += 1;
        }
        for j in 1..ids.len().saturating_sub(1) {
            mesh.indices.push([ids[0], ids[j], ids[j + 1]]);
        }
    }
    if st.is_some() {
        mesh.uvs = Some(uvs);
    }
    if normals.is_some() {
        mesh.normals = Some(out_normals);
    }
    mesh.validate().map_err(|e| anyhow::anyhow!("{e}"))?;
    let color = match vec3s(m.display_color_attr().get()?, "primvars:displayColor")? {
        Some(c) if c.len() == 1 && c[0].is_finite() && c[0].min_element() >= 0.0 => Some(c[0]),
        _ => None,
    };
    Ok((mesh, color))
}

fn read_light(prim: &Prim, kind: &str, transform: &Affine3A) -> Res<Light> {
    let number = |name: &str, d: f32| -> Res<f32> {
        Ok(match prim.attribute(name).get::<sdf::Value>()? {
            Some(sdf::Value::Float(x)) => x,
            Some(sdf::Value::Double(x)) => x as f32,
            Some(sdf::Value::Half(x)) => x.to_f32(),
            None => d,
            Some(other) => anyhow::bail!("`{name}` is not a number: {}", short(&other)),
        })
    };
    let color = match prim.attribute("inputs:color").get::<sdf::Value>()? {
        Some(sdf::Value::Vec3fVec(_)) | None => Vec3::ONE,
        Some(sdf::Value::Vec3f(c)) => Vec3::new(c.x, c.y, c.z),
        Some(sdf::Value::Vec3d(c)) => Vec3::new(c.x as f32, c.y as f32, c.z as f32),
        Some(other) => anyhow::bail!("`inputs:color` is not a colour: {}", short(&other)),
    };
    let power = color * number("inputs:intensity", 1.0)? * number("inputs:exposure", 0.0)?.exp2();
    anyhow::ensure!(
        power.is_finite() && power.min_element() >= 0.0,
        "light colour × intensity must be finite and not negative"
    );
    Ok(match kind {
        // UsdLux lights shine along their local −Z.
        "DistantLight" => {
            Light::Distant { direction: transform.transform_vector3(Vec3::Z).normalize_or(Vec3::Y), irradiance: power }
        }
        "DomeLight" => Light::Environment { radiance: power },
        _ => {
            let radius = number("inputs:radius", 0.5)?;
            anyhow::ensure!(radius.is_finite() && radius >= 0.0, "`inputs:radius` must not be negative");
            let scale = transform.matrix3.determinant().abs().cbrt();
            Light::Sphere { center: transform.transform_point3(Vec3::ZERO), radius: radius * scale, radiance: power }
        }
    })
}

/// Writes shapes (in world space) to a `.usda` file: strand sets as linear `BasisCurves`
/// with vertex widths (diameters) and colours, meshes as triangle `Mesh`es with their
/// normals, UVs and, for diffuse materials, `displayColor`. Strands with fewer than two
/// points are left out (a linear curve needs two). Written atomically, like
/// [`super::cem_hair::write_hair`].
pub fn write_usd(path: &Path, shapes: &[(Shape, u32)], materials: &[Material]) -> Result<(), LoadError> {
    let text =
        usda_text(shapes, materials).map_err(|e| LoadError::invalid(path, format!("cannot write USD: {e:#}")))?;
    super::write_atomically(path, text.as_bytes())
}

/// The `.usda` text [`write_usd`] writes.
pub fn usda_text(shapes: &[(Shape, u32)], materials: &[Material]) -> Res<String> {
    let stage = Stage::builder().in_memory("tress.usda")?;
    stage.define_prim(sdf::path("/World")?)?.set_type_name("Xform")?;
    stage.set_default_prim("World")?;
    let v3 = |p: Vec3| gf::Vec3f { x: p.x, y: p.y, z: p.z };
    let vertex = || sdf::Value::Token("vertex".into());
    let (mut curves, mut meshes) = (0, 0);
    for (shape, material) in shapes {
        match shape {
            Shape::Strands(s) => {
                let keep: Vec<usize> =
                    (0..s.strand_count()).filter(|&i| s.offsets[i + 1] >= s.offsets[i] + 2).collect();
                if keep.is_empty() {
                    continue;
                }
                curves += 1;
                let c = BasisCurves::define(&stage, sdf::path(format!("/World/Hair{curves}"))?)?;
                c.create_type_attr()?.set(sdf::Value::Token("linear".into()))?;
                let range = |i: usize| s.offsets[i] as usize..s.offsets[i + 1] as usize;
                let counts = keep.iter().map(|&i| (s.offsets[i + 1] - s.offsets[i]) as i32).collect();
                c.create_curve_vertex_counts_attr()?.set(sdf::Value::IntVec(counts))?;
                let pts =
                    keep.iter().flat_map(|&i| range(i)).map(|k| v3(Vec3::from_slice(&s.points[k][..3]))).collect();
                c.create_points_attr()?.set(sdf::Value::Vec3fVec(pts))?;
                let widths = keep.iter().flat_map(|&i| range(i)).map(|k| 2.0 * s.points[k][3]).collect();
                c.create_widths_attr()?.set(sdf::Value::FloatVec(widths))?.set_metadata("interpolation", vertex())?;
                if let Some(col) = &s.colors {
                    let col = keep.iter().flat_map(|&i| range(i)).map(|k| v3(Vec3::from(col[k]))).collect();
                    c.create_display_color_attr()?
                        .set(sdf::Value::Vec3fVec(col))?
                        .set_metadata("interpolation", vertex())?;
                } else if let Some(Material::Tube(t)) = materials.get(*material as usize) {
                    c.create_display_color_attr()?.set(sdf::Value::Vec3fVec(vec![v3(t.diffuse)]))?;
                }
            }
            Shape::Mesh(mesh) => {
                meshes += 1;
                let m = Mesh::define(&stage, sdf::path(format!("/World/Mesh{meshes}"))?)?;
                m.create_points_attr()?.set(sdf::Value::Vec3fVec(mesh.positions.iter().map(|p| v3(*p)).collect()))?;
                m.create_face_vertex_counts_attr()?.set(sdf::Value::IntVec(vec![3; mesh.indices.len()]))?;
                let idx = mesh.indices.iter().flatten().map(|&i| i as i32).collect();
                m.create_face_vertex_indices_attr()?.set(sdf::Value::IntVec(idx))?;
                m.create_subdivision_scheme_attr()?.set(sdf::Value::Token("none".into()))?;
                if let Some(n) = &mesh.normals {
                    m.create_normals_attr()?
                        .set(sdf::Value::Vec3fVec(n.iter().map(|p| v3(*p)).collect()))?
                        .set_metadata("interpolation", vertex())?;
                }
                if let Some(uv) = &mesh.uvs {
                    let st = uv.iter().map(|u| gf::Vec2f { x: u[0], y: u[1] }).collect();
                    m.prim()
                        .create_attribute("primvars:st", "texCoord2f[]")?
                        .set(sdf::Value::Vec2fVec(st))?
                        .set_metadata("interpolation", vertex())?;
                }
                if let Some(Material::Diffuse { color }) = materials.get(*material as usize) {
                    m.create_display_color_attr()?.set(sdf::Value::Vec3fVec(vec![v3(*color)]))?;
                }
            }
        }
    }
    let text = stage.root_layer().export_to_string()?;
    Ok(text)
}

#[cfg(test)]
mod tests;
