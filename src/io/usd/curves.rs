//! `BasisCurves`, `HermiteCurves` and `NurbsCurves` prims to strand sets, at the frame's
//! time code.

use super::skel::Skinning;
use super::values::{doubles, floats, held_value, interpolation, ints, value, vec3s, Interpolation, Res};
use super::{Notes, PIECES_PER_SEGMENT};
use crate::geometry::curve::{Blend, CubicBasis, Nurbs};
use crate::geometry::{StrandInfo, StrandSet};
use crate::scene::{HairEntry, HairSource};
use crate::shading::{tube::Tube, Material};
use glam::{Affine3A, Vec3};
use openusd::usd::{Prim, TimeCode};

/// The width of curves without `widths`: the schema's fallback, one unit (as USD's own
/// renderer draws them).
pub const FALLBACK_WIDTH: f32 = 1.0;

/// How the curves of a batch are drawn through their control points: linear (`basis`
/// `None`) or of a cubic basis, open, periodic or pinned (the USD BasisCurves schema's
/// wraps; Arnold's `curves` are open).
pub struct CurveShape {
    /// The cubic basis, `None` for linear curves.
    pub basis: Option<CubicBasis>,
    /// Whether each curve closes on itself.
    pub periodic: bool,
    /// Whether B-spline and Catmull-Rom curves reach their end points.
    pub pinned: bool,
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

    /// Segment ends a curve of `n` control points has (its varying values).
    pub fn ends(&self, n: usize) -> usize {
        let s = self.segments(self.wrap(&vec![0.0f32; n]).len());
        if self.periodic {
            s
        } else {
            s + 1
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
        spread(ends, self.pieces())
    }

    /// The pieces each segment is sampled in.
    pub fn pieces(&self) -> usize {
        if self.basis.is_some() {
            PIECES_PER_SEGMENT
        } else {
            1
        }
    }
}

/// Spreads `k + 1` values linearly over `k` runs of `pieces` samples each.
fn spread<T: Blend>(ends: &[T], pieces: usize) -> Vec<T> {
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
            let mut e = values[varying..varying + shape.ends(count)].to_vec();
            if shape.periodic {
                e.push(e[0]);
            }
            shape.spread(&e)
        }
    };
    anyhow::ensure!(v.len() == samples, "a primvar gives {} values for {samples} samples", v.len());
    Ok(v)
}

/// A curves prim's shared attributes at the frame: control points and counts (read at one
/// sample when the counts change between the samples around the frame, so points of
/// different topologies are never blended), widths and colours with their
/// interpolations, and texture coordinates (of which each curve takes its root's).
struct CurveData {
    points: Vec<Vec3>,
    counts: Vec<usize>,
    widths: Option<(Vec<f32>, Interpolation)>,
    colors: Option<(Vec<Vec3>, Interpolation)>,
    uvs: Option<(Vec<[f32; 2]>, Interpolation)>,
    /// The width of curves without (usable) `widths`: [`FALLBACK_WIDTH`], or Blender's
    /// default in a stage Blender wrote.
    fallback_width: f32,
}

fn curve_data(prim: &Prim, time: TimeCode, skin: Option<&Skinning>, notes: &mut Notes) -> Res<CurveData> {
    let blender = super::blender::wrote(prim.stage());
    let fallback_width = if blender { super::blender::CURVE_WIDTH } else { FALLBACK_WIDTH };
    let counts_attr = prim.attribute("curveVertexCounts");
    let counts = ints(counts_attr.get_at(time)?, "curveVertexCounts")?.unwrap_or_default();
    let around = counts_attr.bracketing_time_samples(time)?;
    let changes = match around {
        Some((lo, hi)) if lo != hi => {
            let at = |t| -> Res<_> { ints(counts_attr.get_at(TimeCode::new(t))?, "curveVertexCounts") };
            at(lo)? != at(hi)?
        }
        _ => false,
    };
    let points_attr = prim.attribute("points");
    let points = if changes { held_value(&points_attr, time)? } else { points_attr.get_at(time)? };
    let Some(mut points) = vec3s(points, "points")? else {
        if !counts.is_empty() {
            notes.note("curves without `points`: skipped".into(), prim);
        }
        return Ok(CurveData {
            points: Vec::new(),
            counts: Vec::new(),
            widths: None,
            colors: None,
            uvs: None,
            fallback_width,
        });
    };
    anyhow::ensure!(counts.iter().all(|&n| n >= 0), "`curveVertexCounts` has a negative count");
    let total: i64 = counts.iter().sum();
    anyhow::ensure!(
        total as usize == points.len(),
        "`curveVertexCounts` sum to {total} but there are {} points",
        points.len()
    );
    anyhow::ensure!(points.iter().all(|p| p.is_finite()), "`points` must be finite");
    if let Some(skin) = skin {
        skin.points(&mut points)?;
    }
    let widths_attr = prim.attribute("widths");
    let widths = match floats(widths_attr.get_at(time)?, "widths")? {
        // One value without interpolation metadata is constant, as USD's renderer reads it.
        Some(w) if w.len() == 1 && widths_attr.get_metadata::<openusd::sdf::Value>("interpolation")?.is_none() => {
            Some((w, Interpolation::Constant))
        }
        Some(w) => Some((w, interpolation(&widths_attr, Interpolation::Vertex)?)),
        None => {
            let why = if blender { "Blender's default curve radius" } else { "USD's fallback" };
            notes.note(format!("curves without `widths`: drawn {fallback_width} unit wide ({why})"), prim);
            None
        }
    };
    if let Some((w, _)) = &widths {
        anyhow::ensure!(w.iter().all(|x| x.is_finite() && *x >= 0.0), "widths must be finite and not negative");
    }
    let color_attr = prim.attribute("primvars:displayColor");
    let colors = vec3s(color_attr.get_at(time)?, "primvars:displayColor")?;
    if let Some(c) = &colors {
        anyhow::ensure!(
            c.iter().all(|x| x.is_finite() && x.min_element() >= 0.0),
            "colours must be finite and not negative"
        );
    }
    let colors = match colors {
        Some(c) => Some((c, interpolation(&color_attr, Interpolation::Constant)?)),
        None => None,
    };
    let uvs = match curve_uvs(prim, time) {
        Ok(uvs) => uvs,
        // The curves are still drawn: only their texturing is lost.
        Err(e) => {
            notes.note(format!("curves whose texture coordinates cannot be read: drawn untextured ({e})"), prim);
            None
        }
    };
    Ok(CurveData { points, counts: counts.iter().map(|&n| n as usize).collect(), widths, colors, uvs, fallback_width })
}

/// A curves prim's texture coordinates ([`super::shapes::uv_primvar`]), unindexed, with
/// their interpolation.
fn curve_uvs(prim: &Prim, time: TimeCode) -> Res<Option<(Vec<[f32; 2]>, Interpolation)>> {
    Ok(match super::shapes::uv_primvar(prim, time)? {
        (name, Some(mut uv)) => {
            // An empty index array indexes nothing: the values are read in order.
            let indices = ints(value(prim, &format!("{name}:indices"), time)?, name)?.filter(|ix| !ix.is_empty());
            if let Some(ix) = indices {
                uv = ix
                    .iter()
                    .map(|&i| uv.get(usize::try_from(i).unwrap_or(usize::MAX)).copied())
                    .collect::<Option<_>>()
                    .ok_or_else(|| anyhow::anyhow!("`{name}:indices` points past its {} values", uv.len()))?;
            }
            Some((uv, interpolation(&prim.attribute(name), Interpolation::Vertex)?))
        }
        (_, None) => None,
    })
}

/// The texture coordinates of a curve's root, from `values` of `interp`: `offset` is the
/// curve's first control point, `varying` its first segment end, `c` its index. Arnold
/// textures a curve by the UV its `uvs` give it, one per curve; a varying or vertex
/// primvar gives the root's.
fn root_uv(values: &[[f32; 2]], interp: Interpolation, c: usize, offset: usize, varying: usize) -> [f32; 2] {
    let k = match interp {
        Interpolation::Constant => 0,
        Interpolation::Uniform => c,
        Interpolation::Vertex => offset,
        Interpolation::Varying => varying,
    };
    values[k]
}

/// The entry of a strand set: a tube material of the constant colour (or the default
/// hair colour, the set's own colours drawn where it has them); an error when the set's
/// points are not finite.
fn entry(set: StrandSet, constant: Option<Vec3>, transform: Affine3A) -> Res<HairEntry> {
    // Finite control points can sample past single precision: Catmull-Rom overshoots its
    // points, skinning and NURBS weights scale them.
    anyhow::ensure!(
        set.points.iter().flatten().all(|c| c.is_finite()),
        "the curves' points are beyond single precision"
    );
    Ok(HairEntry {
        source: HairSource::Inline(set),
        material: tube_material(constant).into(),
        transform,
        radius_scale: 1.0,
        file_colors: true,
        lod: None,
        visibility: Default::default(),
    })
}

/// Tube shading of `color`, the default hair colour without one: how curves without a
/// hair shader are drawn.
pub fn tube_material(color: Option<Vec3>) -> Material {
    let d = color.unwrap_or(crate::hair_system::HairSystem::default().hair_color);
    Material::Tube(Tube { ambient: d, diffuse: d, ..Tube::default() })
}

/// Checks a primvar's length against what its interpolation needs.
impl CurveData {
    /// Fits widths and colours to the length their interpolation needs (`varying_total`
    /// values for `varying`, which depends on the curve type): a primvar whose length does
    /// not fit its interpolation is read with the interpolation its length fits (one value
    /// is constant), else left out, as USD's renderers ignore a primvar of the wrong size;
    /// both reported. Returns the colour when it is constant.
    fn check_primvars(&mut self, varying_total: usize, prim: &Prim, notes: &mut Notes) -> Option<Vec3> {
        let expect = [
            (Interpolation::Constant, 1),
            (Interpolation::Vertex, self.points.len()),
            (Interpolation::Varying, varying_total),
            (Interpolation::Uniform, self.counts.len()),
        ];
        fit(&mut self.widths, "widths", &expect, prim, notes);
        fit(&mut self.colors, "displayColor", &expect, prim, notes);
        fit(&mut self.uvs, "texture coordinates", &expect, prim, notes);
        match &self.colors {
            Some((c, Interpolation::Constant)) => Some(c[0]),
            _ => None,
        }
    }
}

/// A primvar fitted to the length its interpolation needs (see `check_primvars`).
fn fit<T>(
    primvar: &mut Option<(Vec<T>, Interpolation)>,
    what: &str,
    expect: &[(Interpolation, usize)],
    prim: &Prim,
    notes: &mut Notes,
) {
    let Some((values, interp)) = primvar else { return };
    let needs = expect.iter().find(|(i, _)| i == interp).map_or(0, |e| e.1);
    if values.len() == needs {
        return;
    }
    let (len, was) = (values.len(), *interp);
    match expect.iter().find(|(_, n)| *n == len) {
        Some((i, _)) => {
            notes.note(format!("{what} whose count does not fit their interpolation: read as {i:?}"), prim);
            *interp = *i;
        }
        None => {
            notes.note(
                format!("{what} whose count fits no interpolation ({len} where {was:?} needs {needs}): left out"),
                prim,
            );
            *primvar = None;
        }
    }
}

/// A `BasisCurves` prim: linear or cubic (bezier, bspline, catmullRom) with its wrap;
/// with `skin`, its control points skinned first.
pub fn read_basis_curves(
    prim: &Prim,
    time: TimeCode,
    transform: Affine3A,
    skin: Option<&Skinning>,
    notes: &mut Notes,
) -> Res<Option<HairEntry>> {
    let tok = |name: &str, d: &str| -> Res<String> { Ok(super::values::token(value(prim, name, time)?, d)) };
    let (kind, basis_name, wrap) = (tok("type", "cubic")?, tok("basis", "bezier")?, tok("wrap", "nonperiodic")?);
    let basis = match (kind.as_str(), basis_name.as_str()) {
        ("linear", _) => None,
        ("cubic", "bezier") => Some(CubicBasis::Bezier),
        ("cubic", "bspline") => Some(CubicBasis::BSpline),
        ("cubic", "catmullRom") => Some(CubicBasis::CatmullRom),
        (t, b) => {
            notes.note(format!("{t} {b} BasisCurves are not read: skipped"), prim);
            return Ok(None);
        }
    };
    let shape = CurveShape { basis, periodic: wrap == "periodic", pinned: wrap == "pinned" };
    let d = curve_data(prim, time, skin, notes)?;
    curves_entry(prim, &shape, d, transform, notes)
}

/// A `HermiteCurves` prim: each span between two points is the cubic Hermite curve of
/// their outgoing `tangents`, drawn as the cubic Bézier of control points `P0`,
/// `P0 + T0 / 3`, `P1 − T1 / 3`, `P1` (the same polynomial). Vertex primvars, one per
/// point, are then one per Bézier segment end (varying). With `skin`, the points are
/// skinned first (the tangents are not).
pub fn read_hermite_curves(
    prim: &Prim,
    time: TimeCode,
    transform: Affine3A,
    skin: Option<&Skinning>,
    notes: &mut Notes,
) -> Res<Option<HairEntry>> {
    let mut d = curve_data(prim, time, skin, notes)?;
    let tangents = vec3s(value(prim, "tangents", time)?, "tangents")?.unwrap_or_default();
    if tangents.len() != d.points.len() {
        notes.note(
            format!(
                "HermiteCurves with {} `tangents` for {} points: drawn through their points",
                tangents.len(),
                d.points.len()
            ),
            prim,
        );
        return curves_entry(prim, &CurveShape { basis: None, periodic: false, pinned: false }, d, transform, notes);
    }
    anyhow::ensure!(tangents.iter().all(|t| t.is_finite()), "`tangents` must be finite");
    let (mut points, mut at) = (Vec::new(), 0);
    for n in &mut d.counts {
        let curve = d.points[at..at + *n].iter().zip(&tangents[at..at + *n]);
        for (i, (&p, &t)) in curve.enumerate() {
            if i > 0 {
                points.push(p - t / 3.0);
            }
            points.push(p);
            if i + 1 < *n {
                points.push(p + t / 3.0);
            }
        }
        at += *n;
        *n = (3 * *n).saturating_sub(2);
    }
    d.points = points;
    vertex_as_varying(&mut d.widths);
    vertex_as_varying(&mut d.colors);
    vertex_as_varying(&mut d.uvs);
    curves_entry(
        prim,
        &CurveShape { basis: Some(CubicBasis::Bezier), periodic: false, pinned: false },
        d,
        transform,
        notes,
    )
}

/// A vertex primvar of Hermite curves, one per point, as the varying primvar (one per
/// segment end) of the Bézier curves they are drawn as.
fn vertex_as_varying<T>(primvar: &mut Option<(Vec<T>, Interpolation)>) {
    if let Some((_, interp)) = primvar {
        if *interp == Interpolation::Vertex {
            *interp = Interpolation::Varying;
        }
    }
}

/// Curves of `shape` through the control points of `d` as a hair entry, with their
/// primvars fitted (see `check_primvars`); `None` when no curve has enough points.
fn curves_entry(
    prim: &Prim,
    shape: &CurveShape,
    mut d: CurveData,
    transform: Affine3A,
    notes: &mut Notes,
) -> Res<Option<HairEntry>> {
    let varying_total: usize = d.counts.iter().map(|&n| shape.ends(n)).sum();
    let constant_color = d.check_primvars(varying_total, prim, notes);
    let widths = d.widths.as_ref().map(|(w, i)| (w.as_slice(), *i));
    let colors = d.colors.as_ref().filter(|_| constant_color.is_none()).map(|(c, i)| (c.as_slice(), *i));
    let (mut set, kept, skipped) = strands(shape, &d.points, &d.counts, (widths, d.fallback_width), colors)?;
    if let Some((uv, interp)) = &d.uvs {
        let root_uv = kept.iter().map(|&(i, offset, varying)| root_uv(uv, *interp, i, offset, varying)).collect();
        set.strand_info = Some(StrandInfo { root_uv, clump: Vec::new() });
    }
    if skipped > 0 {
        notes.add("curves with too few points for their basis: skipped".into(), prim, skipped);
    }
    if set.strand_count() == 0 {
        return Ok(None);
    }
    Ok(Some(entry(set, constant_color, transform)?))
}

/// Where a curve starts: its index, its first control point and its first segment end.
pub type CurveStart = (usize, usize, usize);

/// Curves of `shape` as strands: `counts` control points each, taken in turn from
/// `points`, sampled by the basis; widths (diameters, `fallback_width` without) and
/// colours by their interpolation, their lengths already fitted to it. Returns the strand
/// set, each strand's curve (its index, first control point and first segment end), and
/// how many curves were skipped for having too few points for the basis.
pub fn strands(
    shape: &CurveShape,
    points: &[Vec3],
    counts: &[usize],
    (widths, fallback_width): (Option<(&[f32], Interpolation)>, f32),
    colors: Option<(&[Vec3], Interpolation)>,
) -> Res<(StrandSet, Vec<CurveStart>, usize)> {
    let mut set = StrandSet::new();
    let mut point_colors = Vec::new();
    let mut kept = Vec::new();
    let (mut offset, mut varying, mut skipped) = (0usize, 0usize, 0usize);
    for (i, &n) in counts.iter().enumerate() {
        let cps = shape.wrap(&points[offset..offset + n]);
        if shape.segments(cps.len()) == 0 {
            skipped += 1;
        } else {
            let p = shape.sample(&cps);
            let at = (i, offset, n, varying);
            let w = match widths {
                Some((w, interp)) => per_curve(shape, w, interp, at, p.len())?,
                None => vec![fallback_width; p.len()],
            };
            if let Some((col, interp)) = colors {
                point_colors.extend(per_curve(shape, col, interp, at, p.len())?.iter().map(|c| c.to_array()));
            }
            set.push_strand(p.into_iter().zip(w).map(|(q, w)| (q, 0.5 * w.max(0.0))));
            kept.push((i, offset, varying));
        }
        offset += n;
        varying += shape.ends(n);
    }
    if !point_colors.is_empty() {
        set.colors = Some(point_colors);
    }
    Ok((set, kept, skipped))
}

/// Knots for curves of `counts` points and `orders` (as many): uniform inside, the ends
/// repeated `order` times so each curve starts and ends at its end points. Curves whose
/// order exceeds their points get none (and fail validation with a message).
fn clamped_knots(counts: &[usize], orders: &[i64]) -> Vec<f64> {
    let mut k = Vec::new();
    for (&n, &o) in counts.iter().zip(orders) {
        let o = o.clamp(0, 32) as usize;
        if n < o {
            continue;
        }
        let inner = n - o;
        k.extend(std::iter::repeat_n(0.0, o));
        k.extend((1..=inner).map(|i| i as f64));
        k.extend(std::iter::repeat_n((inner + 1) as f64, o));
    }
    k
}

/// Whether every curve's knots are finite and non-decreasing with a non-empty range
/// (what [`Nurbs::validate`] would refuse, checked before choosing how to draw the prim).
fn knots_valid(knots: &[f64], counts: &[usize], orders: &[i64]) -> bool {
    let mut at = 0;
    counts.iter().zip(orders).all(|(&n, &o)| {
        let o = o as usize;
        let k = &knots[at..at + n + o];
        at += n + o;
        k.iter().all(|x| x.is_finite()) && k.windows(2).all(|w| w[0] <= w[1]) && k[o - 1] < k[n]
    })
}

/// A `NurbsCurves` prim: each curve evaluated by de Boor's algorithm with its `order` and
/// `knots` (rational with `pointWeights`), sampled at every knot and
/// [`PIECES_PER_SEGMENT`] points per span; vertex widths and colours follow the same
/// basis, varying ones are blended linearly along each span. With `skin`, the control
/// points are skinned first.
pub fn read_nurbs_curves(
    prim: &Prim,
    time: TimeCode,
    transform: Affine3A,
    skin: Option<&Skinning>,
    notes: &mut Notes,
) -> Res<Option<HairEntry>> {
    let mut d = curve_data(prim, time, skin, notes)?;
    let mut orders = ints(value(prim, "order", time)?, "order")?.unwrap_or_default();
    let mut knots = match doubles(value(prim, "knots", time)?, "knots")? {
        Some(k) => k,
        None => {
            notes.note("NurbsCurves without `knots`: uniform knots clamped at the ends assumed".into(), prim);
            clamped_knots(&d.counts, &orders)
        }
    };
    let weights = doubles(value(prim, "pointWeights", time)?, "pointWeights")?;
    if value(prim, "ranges", time)?.is_some() {
        notes.note("NurbsCurves `ranges` are not read: each curve is drawn over its whole knot range".into(), prim);
    }
    let knot_total: usize = d.counts.iter().zip(&orders).map(|(&n, &o)| n + o.clamp(0, 32) as usize).sum();
    let fits = orders.len() == d.counts.len()
        && orders.iter().zip(&d.counts).all(|(&o, &n)| (2..=32).contains(&o) && n >= o as usize)
        && knots.len() == knot_total
        && knots_valid(&knots, &d.counts, &orders);
    if !fits {
        notes.note(
            "NurbsCurves whose `order` and `knots` do not fit their points: drawn through their points, \
             as USD's own renderer draws NurbsCurves"
                .into(),
            prim,
        );
        orders = vec![2; d.counts.len()];
        knots = clamped_knots(&d.counts, &orders);
    }
    if let Some(w) = &weights {
        anyhow::ensure!(w.len() == d.points.len(), "{} pointWeights for {} points", w.len(), d.points.len());
    }
    let varying_total: usize = d.counts.iter().zip(&orders).map(|(&n, &o)| (n + 2).saturating_sub(o as usize)).sum();
    let constant_color = d.check_primvars(varying_total, prim, notes);
    let mut set = StrandSet::new();
    let mut point_colors = Vec::new();
    let mut root_uvs = Vec::new();
    let (mut offset, mut knot_at, mut varying) = (0usize, 0usize, 0usize);
    for (i, (&n, &order)) in d.counts.iter().zip(&orders).enumerate() {
        let order = order as usize;
        let w = |k: usize| weights.as_ref().map_or(1.0, |w| w[offset + k] as f32);
        // The same basis blends any per-point value: `x` in the first coordinate.
        let curve = |x: &dyn Fn(usize) -> glam::Vec3| Nurbs {
            degree: order - 1,
            knots: knots[knot_at..knot_at + n + order].to_vec(),
            cvs: (0..n).map(|k| (x(k) * w(k)).extend(w(k))).collect(),
        };
        let c = curve(&|k| d.points[offset + k]);
        if n < order {
            // Too few points for even a linear curve.
            offset += n;
            knot_at += n + order;
            varying += (n + 2).saturating_sub(order);
            continue;
        }
        c.validate().map_err(|e| anyhow::anyhow!("curve {i}: {e}"))?;
        let p = c.sample(PIECES_PER_SEGMENT);
        let spans = c.span_ends().len().saturating_sub(1);
        let pieces = if order == 2 { 1 } else { PIECES_PER_SEGMENT };
        let along = |values: &[f32], interp| -> Vec<f32> {
            match interp {
                Interpolation::Constant => vec![values[0]; p.len()],
                Interpolation::Uniform => vec![values[i]; p.len()],
                Interpolation::Vertex => curve(&|k| Vec3::new(values[offset + k], 0.0, 0.0))
                    .sample(PIECES_PER_SEGMENT)
                    .iter()
                    .map(|v| v.x)
                    .collect(),
                Interpolation::Varying => {
                    let e = &values[varying..(varying + spans + 1).min(values.len())];
                    spread(e, pieces)
                }
            }
        };
        let widths = match &d.widths {
            Some((w, interp)) => along(w, *interp),
            None => vec![d.fallback_width; p.len()],
        };
        anyhow::ensure!(widths.len() == p.len(), "curve {i}: widths do not match its spans");
        if let (Some((col, interp)), None) = (&d.colors, constant_color) {
            let channel = |k: usize| along(&col.iter().map(|c| c[k]).collect::<Vec<_>>(), *interp);
            let (r, g, b) = (channel(0), channel(1), channel(2));
            anyhow::ensure!(r.len() == p.len(), "curve {i}: colours do not match its spans");
            point_colors.extend((0..p.len()).map(|k| [r[k], g[k], b[k]]));
        }
        set.push_strand(p.into_iter().zip(widths).map(|(q, w)| (q, 0.5 * w.max(0.0))));
        if let Some((uv, interp)) = &d.uvs {
            root_uvs.push(root_uv(uv, *interp, i, offset, varying));
        }
        offset += n;
        knot_at += n + order;
        varying += (n + 2).saturating_sub(order);
    }
    if set.strand_count() == 0 {
        return Ok(None);
    }
    if !point_colors.is_empty() {
        set.colors = Some(point_colors);
    }
    if d.uvs.is_some() {
        set.strand_info = Some(StrandInfo { root_uv: root_uvs, clump: Vec::new() });
    }
    Ok(Some(entry(set, constant_color, transform)?))
}
