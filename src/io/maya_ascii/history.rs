//! Curves Maya builds from construction history rather than storing: a `makeNurbCircle`
//! node feeding a curve's `.create`.
//!
//! A circle is built as Maya's node builds it (Maya's node reference, `makeNurbCircle`):
//! in the plane through `center` with normal `normal`, starting towards `first` (projected
//! into that plane), of `radius`, and, for the full circle (`sweep` 360°), periodic:
//!
//! - **cubic** (`degree` 3, the default): `sections` spans of a uniform periodic B-spline
//!   whose `sections` control points sit on a regular polygon of radius
//!   `ρ = radius · 6 / (4 + 2 cos(2π / sections))`, control point `k` at the angle
//!   `(k + 1) · 2π / sections` turning about the normal from the start direction. A uniform
//!   cubic B-spline passes through `(P₋₁ + 4 P₀ + P₁) / 6` at each knot, so that `ρ` puts
//!   every knot's point on the circle; this is the layout of the `.cc` blocks Maya writes
//!   for its circles (8 sections, radius 1: control points 1.10819 from the centre).
//! - **linear** (`degree` 1): a closed polygon of `sections` sides with its corners on
//!   the circle, the first at the start direction.
//!
//! A partial circle (an arc, `|sweep|` under 360°) is drawn as the exact arc, sampled
//! [`super::SAMPLES_PER_SPAN`] times per section for degree 3 (Maya's open cubic arc is a
//! close approximation of it) or with its `sections` corners on the arc for degree 1.
//! With `useTolerance` on, the number of sections is the fewest whose curve keeps within
//! `tolerance` of the true circle: `ρ (46 cos(s/2) + 2 cos(3s/2)) / 48 − radius` at the
//! middle of a cubic span of angle `s` (the B-spline weights 1/48, 23/48, 23/48, 1/48), and
//! `radius (1 − cos(s/2))` for a linear one. With `fixCenter` off, the circle is moved so
//! that it passes through `first`.

use super::parse::Graph;
use super::{scalar, vec3, Res, SAMPLES_PER_SPAN};
use crate::geometry::curve::Nurbs;
use glam::{DVec3, Vec4};
use std::f64::consts::TAU;

/// Most sections a circle is built with (Maya's own attribute is unbounded).
pub const MAX_SECTIONS: usize = 10_000;

/// The curve a `makeNurbCircle` node builds, and whether it is closed (a full circle);
/// `warnings` gets what was clamped.
pub fn nurb_circle(g: &Graph, n: usize, warnings: &mut Vec<String>) -> Res<(Nurbs, bool)> {
    let node = &g.nodes[n];
    let bad = |m: String| (node.line, format!("makeNurbCircle {}: {m}", node.name));
    // Per-component defaults (the node's: normal +Z, first point +X).
    let with_default = |whole: &[&str], parts: &[[&str; 2]; 3], d: DVec3| -> Res<DVec3> {
        let v = vec3(g, n, whole, parts, f64::NAN)?;
        Ok(DVec3::new(
            if v.x.is_nan() { d.x } else { v.x },
            if v.y.is_nan() { d.y } else { v.y },
            if v.z.is_nan() { d.z } else { v.z },
        ))
    };
    let center = vec3(g, n, &["c", "center"], &[["cx", "centerX"], ["cy", "centerY"], ["cz", "centerZ"]], 0.0)?;
    let normal =
        with_default(&["nr", "normal"], &[["nrx", "normalX"], ["nry", "normalY"], ["nrz", "normalZ"]], DVec3::Z)?;
    let first = with_default(
        &["fp", "first"],
        &[["fpx", "firstPointX"], ["fpy", "firstPointY"], ["fpz", "firstPointZ"]],
        DVec3::X,
    )?;
    let radius = scalar(g, n, &["r", "radius"], 1.0)?;
    // The sweep is an angle attribute: in the file's angular unit when set, 2π radians when not.
    let sweep = match super::attr(g, n, &["sw", "sweep"]) {
        Some(_) => scalar(g, n, &["sw", "sweep"], 0.0)? * g.angle_to_radians,
        None => TAU,
    };
    let degree = scalar(g, n, &["d", "degree"], 3.0)?;
    let sections = scalar(g, n, &["s", "sections"], 8.0)?;
    let tolerance = scalar(g, n, &["tol", "tolerance"], 0.01)?;
    let use_tolerance = scalar(g, n, &["ut", "useTolerance"], 0.0)? != 0.0;
    let fix_center = scalar(g, n, &["fc", "fixCenter"], 1.0)? != 0.0;

    if !(center.is_finite() && first.is_finite()) {
        return Err(bad(format!("center {center} and first point {first} must be finite")));
    }
    if !(radius.is_finite() && radius != 0.0 && radius.abs() < 1e15) {
        return Err(bad(format!("radius {radius} must be finite and not 0")));
    }
    let Some(axis) = normal.try_normalize().filter(|_| normal.is_finite()) else {
        return Err(bad(format!("normal {normal} has no direction")));
    };
    if !(sweep.is_finite() && sweep != 0.0) {
        return Err(bad(format!("sweep {sweep} rad must be finite and not 0")));
    }
    let cubic = match degree {
        1.0 => false,
        3.0 => true,
        d => return Err(bad(format!("degree {d} is not 1 (linear) or 3 (cubic)"))),
    };
    let full = sweep.abs() >= TAU - 1e-9;
    let sweep = sweep.clamp(-TAU, TAU);
    // A periodic curve needs as many spans as its degree; an arc one span.
    let fewest = if full { 3 } else { 1 };
    let sections = if use_tolerance {
        match sections_for_tolerance(radius.abs(), sweep.abs(), full, cubic, tolerance, fewest) {
            Some(s) => s,
            None => {
                warnings.push(format!(
                    "makeNurbCircle {}: no section count up to {MAX_SECTIONS} keeps within tolerance {tolerance}: \
                     built with {MAX_SECTIONS}",
                    node.name
                ));
                MAX_SECTIONS
            }
        }
    } else {
        if !sections.is_finite() {
            return Err(bad(format!("sections {sections} is not a number")));
        }
        let s = sections.trunc();
        let clamped = s.clamp(fewest as f64, MAX_SECTIONS as f64);
        if clamped != s {
            warnings.push(format!(
                "makeNurbCircle {}: sections {sections} clamped to {clamped} ({fewest} to {MAX_SECTIONS})",
                node.name
            ));
        }
        clamped as usize
    };

    // The start direction: towards the first point, in the circle's plane.
    let towards = first - center;
    let start = (towards - axis * towards.dot(axis))
        .try_normalize()
        .unwrap_or_else(|| crate::math::frame(axis.as_vec3()).0.as_dvec3());
    let side = axis.cross(start);
    let center = if fix_center { center } else { first - start * radius };
    let at = |angle: f64, r: f64| center + (start * angle.cos() + side * angle.sin()) * r;
    let point = |p: DVec3| Vec4::new(p.x as f32, p.y as f32, p.z as f32, 1.0);

    let curve = if full && cubic {
        let step = TAU / sections as f64;
        let rho = radius * 6.0 / (4.0 + 2.0 * step.cos());
        let mut cvs: Vec<Vec4> = (0..sections).map(|k| point(at((k + 1) as f64 * step, rho))).collect();
        // Periodic: the first three control points again, on uniform knots.
        cvs.extend_from_within(..3);
        let knots = (0..cvs.len() + 4).map(|i| i as f64 - 3.0).collect();
        Nurbs { degree: 3, knots, cvs }
    } else {
        // The polygon on the circle (degree 1), or the exact arc sampled finely (degree 3).
        let pieces = if cubic { sections * SAMPLES_PER_SPAN } else { sections };
        let cvs: Vec<Vec4> = (0..=pieces).map(|k| point(at(sweep * k as f64 / pieces as f64, radius))).collect();
        let mut knots = vec![0.0];
        knots.extend((0..=pieces).map(|k| k as f64));
        knots.push(pieces as f64);
        Nurbs { degree: 1, knots, cvs }
    };
    curve.validate().map_err(bad)?;
    Ok((curve, full))
}

/// The fewest sections (at least `fewest`, at most [`MAX_SECTIONS`]) whose curve keeps
/// within `tolerance` of a circle of `radius` over `sweep` radians; `None` when none does.
fn sections_for_tolerance(
    radius: f64,
    sweep: f64,
    full: bool,
    cubic: bool,
    tolerance: f64,
    fewest: usize,
) -> Option<usize> {
    if !(tolerance.is_finite() && tolerance > 0.0) {
        return None;
    }
    (fewest..=MAX_SECTIONS).find(|&n| {
        let s = sweep / n as f64;
        let deviation = if cubic && full {
            let rho = radius * 6.0 / (4.0 + 2.0 * s.cos());
            (rho * (46.0 * (0.5 * s).cos() + 2.0 * (1.5 * s).cos()) / 48.0 - radius).abs()
        } else if cubic {
            // The arc is drawn through points on it, SAMPLES_PER_SPAN per section.
            radius * (1.0 - (0.5 * s / SAMPLES_PER_SPAN as f64).cos())
        } else {
            radius * (1.0 - (0.5 * s).cos())
        };
        deviation <= tolerance
    })
}
