//! Maya animation curves (`animCurveTL`, `animCurveTA`, `animCurveTU`, `animCurveTT`)
//! evaluated at the frame and written over the attributes they drive, before anything is
//! read from the graph.
//!
//! What is read, as Autodesk's node reference documents the `animCurve` node and as Maya
//! writes it:
//!
//! - **Keys** `.ktv[i]` (`keyTimeValue`): time/value pairs. Times are in the file's time unit
//!   (`currentUnit -t`: `film` 24 frames a second, `pal` 25, `ntsc` 30, ...), i.e. frames, the
//!   unit `--frame` counts in; values in the unit of the output: the file's linear unit
//!   (`TL`), its angle unit (`TA`: degrees under `currentUnit -a degree`), plain numbers
//!   (`TU`, `TT`).
//! - **Tangent types**: the curve's `.tan` (`tangentType`, used by keys whose type is
//!   global) and per key `.kit`/`.kot` (`keyTanInType`/`keyTanOutType`), as the node's enum
//!   numbers them: 0 global, 1 fixed, 2 linear, 3 flat, 4 smooth, 5 step, 6 slow, 7 fast,
//!   9 spline, 10 clamped, 16 plateau, 17 step next, 18 auto (19 to 21: auto mix, ease,
//!   custom). (`itt`/`ott` are flags of the `keyTangent` command, not attributes of the
//!   node.) The rules, from Maya's Graph Editor Tangents menu reference:
//!   - *spline* (and the legacy smooth, slow and fast): the curve is smooth through the key
//!     before and after: slope (v₊ − v₋)/(t₊ − t₋); at the first and last key the slope of
//!     its one segment.
//!   - *linear*: the segment on that side is a straight line (the slope of that segment).
//!   - *flat*: slope 0.
//!   - *step*: the value holds until the next key (decided by the out tangent of the key
//!     starting a segment); *step next*: the segment takes the next key's value.
//!   - *clamped*: spline, except that a side whose neighbouring key has (nearly) the same
//!     value is linear; "very close" is taken as within 10⁻⁶ of the curve's value range
//!     (Maya does not give its tolerance).
//!   - *plateau* and *auto* (Maya's default since 2016, documented as "first and last
//!     keyframes have flat tangents, keyframes in between do not overshoot the neighboring
//!     keyframe value"): flat at the first and last key and at a local extreme, else the
//!     spline slope limited to 3× the smaller neighbouring segment slope, the bound under
//!     which a Hermite segment stays monotone (Fritsch and Carlson 1980, "Monotone
//!     Piecewise Cubic Interpolation"), so the curve never overshoots a key. Maya does not
//!     publish its exact auto formula; this is the documented behaviour.
//!   - *fixed*: the stored tangent (below); without one, spline.
//! - **Stored tangents** `.kix`/`.kiy`/`.kox`/`.koy` (`keyTanInX`, ...): when a key has them
//!   they are used whatever its type (Maya writes the tangent it evaluates). As the
//!   `MFnAnimCurve` reference gives them, x is in seconds and y in Maya's internal unit of
//!   the output (centimetres, radians), since these attributes carry no unit: slope =
//!   y / x, converted to the file's units per frame. (Checked on a file: an auto key's
//!   x is its segment's length in seconds.)
//! - **Weighted tangents** `.wgt`: each segment is the cubic Bézier through the keys with
//!   inner control points at a third of the stored (x, y) from each key (the form in which
//!   an unweighted Hermite segment is that Bézier with x the segment's length), solved for
//!   the parameter at the frame's time by bisection. Unweighted curves are Hermite segments
//!   with the keys' slopes.
//! - **Infinity** `.pre`/`.pst` (`preInfinity`/`postInfinity`): 0 constant, 1 linear (along
//!   the end key's tangent), 3 cycle, 4 cycle with offset (each repeat shifted by the last
//!   minus the first value), 5 oscillate (back and forth).
//!
//! A curve drives `node.attr` through `connectAttr "curve.o" "node.attr"` (`.o` or
//! `.output`; short or long attribute names). Only the attributes tress reads at the frame
//! are written (transform channels and visibility, the camera's lens and clip planes, the
//! lights' colour, intensity and exposure, Lambert-family and surface shader colours); the
//! others, curves whose input is not time
//! (driven keys), and the other drivers Maya has (expressions, constraints, blends,
//! characters and animation layers) are reported, once per kind with a count. Bad data (an
//! odd number of key values, values that are not numbers, times that do not increase)
//! leaves the curve out with a warning naming its line and node.

use super::parse::{Attr, Graph, Value};
use std::collections::BTreeMap;

/// The curve types evaluated here: time in, distance, angle, number or time out.
pub const TIME_CURVES: [&str; 4] = ["animCurveTL", "animCurveTA", "animCurveTU", "animCurveTT"];

/// Node types that drive attributes in ways tress does not evaluate, with the name used in
/// warnings (a prefix match on the type: every `…Constraint`, `animBlendNode…`).
const OTHER_DRIVERS: [(&str, &str); 9] = [
    ("expression", "expressions"),
    ("animCurveU", "driven keys (animCurveU*)"),
    ("pairBlend", "pair blends"),
    ("animBlendNode", "animation layer blends (animBlendNode*)"),
    ("animLayer", "animation layers"),
    ("character", "characters"),
    ("motionPath", "motion paths"),
    ("blendWeighted", "blendWeighted nodes"),
    ("Constraint", "constraints"),
];

/// Attributes tress reads when they are animated, by the node types that have them.
const TRANSFORM_ATTRS: &[&str] = &[
    "t",
    "translate",
    "tx",
    "ty",
    "tz",
    "translateX",
    "translateY",
    "translateZ",
    "r",
    "rotate",
    "rx",
    "ry",
    "rz",
    "rotateX",
    "rotateY",
    "rotateZ",
    "s",
    "scale",
    "sx",
    "sy",
    "sz",
    "scaleX",
    "scaleY",
    "scaleZ",
    "v",
    "visibility",
];
const CAMERA_ATTRS: &[&str] = &[
    "fl",
    "focalLength",
    "ncp",
    "nearClipPlane",
    "fcp",
    "farClipPlane",
    "coi",
    "centerOfInterest",
    "hfa",
    "horizontalFilmAperture",
    "vfa",
    "verticalFilmAperture",
    "v",
    "visibility",
];
const LIGHT_ATTRS: &[&str] = &[
    "in",
    "intensity",
    "cr",
    "cg",
    "cb",
    "colorR",
    "colorG",
    "colorB",
    "scr",
    "scg",
    "scb",
    "ai_exposure",
    "aiExposure",
    "v",
    "visibility",
];
const LIGHTS: [&str; 7] =
    ["directionalLight", "pointLight", "spotLight", "ambientLight", "areaLight", "aiSkyDomeLight", "aiAreaLight"];
/// Surface shaders' colour channels tress reads (`color × diffuse`, `outColor`).
const LAMBERT_ATTRS: &[&str] = &["c", "color", "cr", "cg", "cb", "colorR", "colorG", "colorB", "dc", "diffuse"];
const SURFACE_SHADER_ATTRS: &[&str] = &["oc", "outColor", "ocr", "ocg", "ocb", "outColorR", "outColorG", "outColorB"];
/// Shapes whose visibility tress reads.
const SHAPES: [&str; 5] = ["mesh", "nurbsCurve", "hairSystem", "follicle", "xgmSplineDescription"];

/// True when tress reads `attr` of a node of type `kind` (so an animation of it is applied).
fn applied(kind: &str, attr: &str) -> bool {
    match kind {
        "transform" => TRANSFORM_ATTRS.contains(&attr),
        "camera" => CAMERA_ATTRS.contains(&attr),
        k if LIGHTS.contains(&k) => LIGHT_ATTRS.contains(&attr),
        // A mesh's point tweaks by component (`pt[3].px`), which Maya keys one curve each.
        "mesh" if super::tweak_component(attr).is_some() => true,
        k if SHAPES.contains(&k) => matches!(attr, "v" | "visibility"),
        "lambert" | "blinn" | "phong" | "phongE" => LAMBERT_ATTRS.contains(&attr),
        "surfaceShader" => SURFACE_SHADER_ATTRS.contains(&attr),
        _ => false,
    }
}

/// How a curve continues before its first or after its last key.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Infinity {
    Constant,
    Linear,
    Cycle,
    CycleOffset,
    Oscillate,
}

/// One key: time (frames), value, slopes (value per frame) on each side, the weighted
/// handles' lengths in frames (x of the stored tangent), and whether the segment after it
/// steps.
#[derive(Clone, Copy, Debug)]
struct Key {
    t: f64,
    v: f64,
    slope_in: f64,
    slope_out: f64,
    /// Weighted curves: handle (x, y) in frames and file units, in and out.
    handle_in: Option<(f64, f64)>,
    handle_out: Option<(f64, f64)>,
    step: Step,
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum Step {
    No,
    Hold,
    Next,
}

/// An animation curve ready to evaluate.
#[derive(Clone, Debug)]
pub struct Curve {
    keys: Vec<Key>,
    weighted: bool,
    pre: Infinity,
    post: Infinity,
}

/// Tangent type numbers of the node's enum.
const GLOBAL: i64 = 0;
const FIXED: i64 = 1;
const LINEAR: i64 = 2;
const FLAT: i64 = 3;
const STEP: i64 = 5;
const SPLINE: i64 = 9;
const CLAMPED: i64 = 10;
const PLATEAU: i64 = 16;
const STEP_NEXT: i64 = 17;

/// The unit conversions a curve's data needs.
#[derive(Clone, Copy, Debug)]
pub struct Units {
    /// Frames in a second (`currentUnit -t`).
    pub fps: f64,
    /// Internal units (cm, radians) in one file unit of the curve's output.
    pub internal_per_file: f64,
}

impl Curve {
    /// Reads the curve node `n`; `Err` is the line and the problem.
    pub fn read(g: &Graph, n: usize, units: Units) -> Result<Curve, (u32, String)> {
        let node = &g.nodes[n];
        let bad = |line: u32, what: String| (line, format!("{} {}: {what}", node.kind, node.name));
        let mut raw: BTreeMap<usize, [f64; 2]> = BTreeMap::new();
        let mut keys_line = node.line;
        let mut per_key: [BTreeMap<usize, f64>; 6] = Default::default();
        let (mut tan, mut weighted, mut pre, mut post) = (SPLINE, false, Infinity::Constant, Infinity::Constant);
        for a in &node.attrs {
            let nums = |a: &Attr| match &a.value {
                Value::Numbers(v) => Ok(v.clone()),
                _ => Err(bad(a.line, format!("`{}` must be numbers", a.name))),
            };
            let one = |a: &Attr| -> Result<f64, (u32, String)> {
                match nums(a)?.as_slice() {
                    [x] => Ok(*x),
                    _ => Err(bad(a.line, format!("`{}` must be one number", a.name))),
                }
            };
            let infinity = |a: &Attr| -> Result<Infinity, (u32, String)> {
                Ok(match one(a)? as i64 {
                    0 => Infinity::Constant,
                    1 => Infinity::Linear,
                    3 => Infinity::Cycle,
                    4 => Infinity::CycleOffset,
                    5 => Infinity::Oscillate,
                    k => return Err(bad(a.line, format!("`{}` {k} is not an infinity type", a.name))),
                })
            };
            match a.name.as_str() {
                "tan" | "tangentType" => tan = one(a)? as i64,
                "wgt" | "weightedTangents" => weighted = one(a)? != 0.0,
                "pre" | "preInfinity" => pre = infinity(a)?,
                "pst" | "postInfinity" => post = infinity(a)?,
                name => {
                    let fields = ["kit", "kot", "kix", "kiy", "kox", "koy"];
                    let long = ["keyTanInType", "keyTanOutType", "keyTanInX", "keyTanInY", "keyTanOutX", "keyTanOutY"];
                    if let Some((start, end)) =
                        super::element_range(name, "ktv").or_else(|| super::element_range(name, "keyTimeValue"))
                    {
                        let v = nums(a)?;
                        if v.len() % 2 != 0 {
                            return Err(bad(a.line, format!("`{name}` has {} values, not time/value pairs", v.len())));
                        }
                        if end.is_some_and(|e| e < start || (e - start).checked_add(1) != Some(v.len() / 2)) {
                            return Err(bad(a.line, format!("`{name}` has {} pairs for its range", v.len() / 2)));
                        }
                        keys_line = a.line;
                        for (i, p) in v.chunks(2).enumerate() {
                            raw.insert(start.saturating_add(i), [p[0], p[1]]);
                        }
                    } else if let Some(f) = (0..6).find(|&f| {
                        super::element_range(name, fields[f]).or_else(|| super::element_range(name, long[f])).is_some()
                    }) {
                        let (start, _) = super::element_range(name, fields[f])
                            .or_else(|| super::element_range(name, long[f]))
                            .expect("matched above");
                        for (i, x) in nums(a)?.into_iter().enumerate() {
                            per_key[f].insert(start.saturating_add(i), x);
                        }
                    }
                }
            }
        }
        if raw.is_empty() {
            return Err(bad(node.line, "has no keys (`.ktv`)".into()));
        }
        // Keys by index; the index order is the time order Maya writes.
        let index: Vec<usize> = raw.keys().copied().collect();
        let times: Vec<f64> = raw.values().map(|p| p[0]).collect();
        let values: Vec<f64> = raw.values().map(|p| p[1]).collect();
        if let Some(w) = times.windows(2).position(|w| w[1] <= w[0]) {
            return Err(bad(
                keys_line,
                format!("key times do not increase (key {} at {} after {})", index[w + 1], times[w + 1], times[w]),
            ));
        }
        let kind = |f: usize, i: usize| match per_key[f].get(&index[i]).map(|&x| x as i64).unwrap_or(GLOBAL) {
            GLOBAL => tan,
            k => k,
        };
        let n = times.len();
        let seg = |i: usize| (values[i + 1] - values[i]) / (times[i + 1] - times[i]);
        let range = values.iter().fold(f64::NEG_INFINITY, |m, &v| m.max(v))
            - values.iter().fold(f64::INFINITY, |m, &v| m.min(v));
        let close = |a: f64, b: f64| (a - b).abs() <= 1e-6 * range;
        // The slope a tangent type gives key `i` on its left (`left`) or right side.
        let computed = |i: usize, kind: i64, left: bool| -> f64 {
            let (l, r) = ((i > 0).then(|| seg(i - 1)), (i + 1 < n).then(|| seg(i)));
            let spline = match (l, r) {
                (Some(_), Some(_)) => (values[i + 1] - values[i - 1]) / (times[i + 1] - times[i - 1]),
                (Some(s), None) | (None, Some(s)) => s,
                (None, None) => 0.0,
            };
            let side = if left { l.or(r) } else { r.or(l) }.unwrap_or(0.0);
            match kind {
                LINEAR => side,
                FLAT | STEP | STEP_NEXT => 0.0,
                CLAMPED => {
                    let neighbour = if left { i.checked_sub(1) } else { (i + 1 < n).then_some(i + 1) };
                    match neighbour {
                        Some(j) if close(values[j], values[i]) => side,
                        _ => spline,
                    }
                }
                PLATEAU | 18..=21 => match (l, r) {
                    (Some(a), Some(b)) if a * b > 0.0 => {
                        let limit = 3.0 * a.abs().min(b.abs());
                        spline.clamp(-limit, limit)
                    }
                    _ => 0.0,
                },
                _ => spline,
            }
        };
        let stored = |fx: usize, fy: usize, i: usize| -> Option<(f64, f64)> {
            let (x, y) = (per_key[fx].get(&index[i])?, per_key[fy].get(&index[i])?);
            // x seconds → frames; y internal units → file units.
            Some((x * units.fps, y / units.internal_per_file))
        };
        let mut keys = Vec::with_capacity(n);
        for i in 0..n {
            let (kin, kout) = (kind(0, i), kind(1, i));
            let (sin, sout) = (stored(2, 3, i), stored(4, 5, i));
            let slope = |s: Option<(f64, f64)>, k: i64, left: bool| match s {
                Some((x, y)) if x.abs() > 1e-12 && !matches!(k, STEP | STEP_NEXT) => y / x,
                _ => computed(i, if k == FIXED { SPLINE } else { k }, left),
            };
            let (slope_in, slope_out) = (slope(sin, kin, true), slope(sout, kout, false));
            let step = match kout {
                STEP => Step::Hold,
                STEP_NEXT => Step::Next,
                _ => Step::No,
            };
            if !(slope_in.is_finite() && slope_out.is_finite()) {
                return Err(bad(node.line, format!("key {} has a tangent that is not finite", index[i])));
            }
            keys.push(Key {
                t: times[i],
                v: values[i],
                slope_in,
                slope_out,
                handle_in: sin.filter(|_| weighted),
                handle_out: sout.filter(|_| weighted),
                step,
            });
        }
        Ok(Curve { keys, weighted, pre, post })
    }

    /// The curve's value at time `t` (frames).
    pub fn eval(&self, t: f64) -> f64 {
        let k = &self.keys;
        let (first, last) = (k[0], k[k.len() - 1]);
        let span = last.t - first.t;
        if t < first.t || t > last.t {
            let (mode, before) = if t < first.t { (self.pre, true) } else { (self.post, false) };
            match mode {
                Infinity::Constant => return if before { first.v } else { last.v },
                Infinity::Linear => {
                    return if before {
                        first.v + first.slope_in * (t - first.t)
                    } else {
                        last.v + last.slope_out * (t - last.t)
                    }
                }
                _ if span <= 0.0 => return if before { first.v } else { last.v },
                Infinity::Cycle | Infinity::CycleOffset | Infinity::Oscillate => {
                    let cycles = ((t - first.t) / span).floor();
                    let mut local = t - first.t - cycles * span;
                    if mode == Infinity::Oscillate && (cycles as i64).rem_euclid(2) == 1 {
                        local = span - local;
                    }
                    let offset = if mode == Infinity::CycleOffset { cycles * (last.v - first.v) } else { 0.0 };
                    return self.inside(first.t + local) + offset;
                }
            }
        }
        self.inside(t)
    }

    /// The value at a time within the keys.
    fn inside(&self, t: f64) -> f64 {
        let k = &self.keys;
        let i = k.partition_point(|key| key.t <= t);
        if i == 0 {
            return k[0].v;
        }
        if i == k.len() {
            return k[k.len() - 1].v;
        }
        let (a, b) = (k[i - 1], k[i]);
        if t == a.t {
            return a.v;
        }
        let dt = b.t - a.t;
        match a.step {
            Step::Hold => return a.v,
            Step::Next => return b.v,
            Step::No => {}
        }
        if self.weighted {
            // Bézier control points: a third of each stored handle (or of the slope over
            // the segment's length when a key stores none).
            let out = a.handle_out.unwrap_or((dt, a.slope_out * dt));
            let inn = b.handle_in.unwrap_or((dt, b.slope_in * dt));
            let x = [a.t, a.t + (out.0 / 3.0).clamp(0.0, dt), b.t - (inn.0 / 3.0).clamp(0.0, dt), b.t];
            let y = [a.v, a.v + out.1 / 3.0, b.v - inn.1 / 3.0, b.v];
            let bez = |p: &[f64; 4], u: f64| {
                let w = 1.0 - u;
                w * w * w * p[0] + 3.0 * w * w * u * p[1] + 3.0 * w * u * u * p[2] + u * u * u * p[3]
            };
            // x(u) increases with u (control points clamped inside the segment).
            let (mut lo, mut hi) = (0.0, 1.0);
            for _ in 0..60 {
                let mid = 0.5 * (lo + hi);
                if bez(&x, mid) < t {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            return bez(&y, 0.5 * (lo + hi));
        }
        // Cubic Hermite on the unit interval with the slopes scaled to the segment.
        let s = (t - a.t) / dt;
        let (s2, s3) = (s * s, s * s * s);
        (2.0 * s3 - 3.0 * s2 + 1.0) * a.v
            + (s3 - 2.0 * s2 + s) * a.slope_out * dt
            + (-2.0 * s3 + 3.0 * s2) * b.v
            + (s3 - s2) * b.slope_in * dt
    }
}

/// The frame a file is read at when `--frame` does not say: Maya's current time as saved
/// (`time1.o`, what a batch render of a file without an animation range renders), else
/// the playback start (`playbackOptions -min` in the `sceneConfigurationScriptNode`), else 1.
pub fn saved_time(g: &Graph) -> f64 {
    let current = g.find("time1").and_then(|n| {
        g.nodes[n].attrs.iter().rev().find(|a| matches!(a.name.as_str(), "o" | "outTime")).and_then(|a| {
            match &a.value {
                Value::Numbers(v) if v.len() == 1 => Some(v[0]),
                _ => None,
            }
        })
    });
    let playback = || {
        let n = g.find("sceneConfigurationScriptNode")?;
        let script = g.nodes[n].attrs.iter().find_map(|a| match &a.value {
            Value::Strings(s) if a.name == "b" || a.name == "before" => s.first().cloned(),
            _ => None,
        })?;
        let mut words = script.split_whitespace();
        words.by_ref().find(|w| *w == "playbackOptions")?;
        let mut words = words.skip_while(|w| *w != "-min" && *w != "-minTime");
        words.next()?;
        words.next()?.trim_end_matches(';').parse::<f64>().ok().filter(|v| v.is_finite())
    };
    current.or_else(playback).unwrap_or(1.0)
}

/// Evaluates every time curve of `g` at `time` (frames) and appends its value to the
/// attribute it drives, where tress reads that attribute; returns the warnings (bad
/// curves, what is not applied) and how many attributes were written.
pub fn apply(g: &mut Graph, time: f64) -> (Vec<String>, usize) {
    let mut warnings = Vec::new();
    let mut writes: Vec<(usize, String, f64, u32)> = Vec::new();
    let mut not_read: BTreeMap<String, usize> = BTreeMap::new();
    let mut driven: usize = 0;
    let mut curves: BTreeMap<usize, Option<Curve>> = BTreeMap::new();
    for c in &g.connections {
        let src = &g.nodes[c.src];
        if !TIME_CURVES.contains(&src.kind.as_str()) || !matches!(super::plug_base(&c.src_attr), "o" | "output") {
            continue;
        }
        let dst = &g.nodes[c.dst];
        if TIME_CURVES.contains(&dst.kind.as_str()) || dst.kind.starts_with("animCurve") {
            continue;
        }
        let attr = c.dst_attr.as_str();
        if !applied(&dst.kind, attr) {
            // By node type (a default node the file only selects, by its name), indices
            // dropped: `nurbsCurve.cp[].xv`.
            let kind = if dst.kind.is_empty() { dst.name.as_str() } else { dst.kind.as_str() };
            let mut plug = String::with_capacity(attr.len());
            let mut inside = false;
            for ch in attr.chars() {
                match ch {
                    '[' => inside = true,
                    ']' => inside = false,
                    _ if inside => continue,
                    _ => {}
                }
                plug.push(ch);
            }
            *not_read.entry(format!("{kind}.{plug}")).or_default() += 1;
            continue;
        }
        let curve = curves.entry(c.src).or_insert_with(|| {
            // A curve whose input is connected to anything but time is a driven key.
            let input = g.inputs_of(c.src).find(|i| matches!(super::plug_base(&i.dst_attr), "i" | "input"));
            if input.is_some_and(|i| g.nodes[i.src].kind != "time" && g.nodes[i.src].name != "time1") {
                driven += 1;
                return None;
            }
            let internal_per_file = match src.kind.as_str() {
                "animCurveTL" => g.centimeters_per_unit,
                "animCurveTA" => g.angle_to_radians,
                _ => 1.0,
            };
            match Curve::read(g, c.src, Units { fps: g.frames_per_second, internal_per_file }) {
                Ok(curve) => Some(curve),
                Err((line, e)) => {
                    warnings.push(format!("line {line}: {e}: the curve is not applied"));
                    None
                }
            }
        });
        if let Some(curve) = curve {
            let v = curve.eval(time);
            if v.is_finite() {
                writes.push((c.dst, attr.to_string(), v, src.line));
            }
        }
    }
    let written = writes.len();
    for (node, name, v, line) in writes {
        g.nodes[node].attrs.push(Attr { name, value: Value::Numbers(vec![v]), line });
    }
    if driven > 0 {
        warnings.push(format!(
            "{driven} animation curve(s) driven by something other than time: drawn at their stored values"
        ));
    }
    if !not_read.is_empty() {
        let list: Vec<String> = not_read.iter().map(|(k, n)| format!("{k} ({n})")).collect();
        warnings.push(format!(
            "animated attributes tress does not read at the frame, drawn at their stored values: {}",
            list.join(", ")
        ));
    }
    // Other drivers of attributes: counted by kind, the nodes that connect into a node of
    // a type tress reads.
    let mut others: BTreeMap<&str, std::collections::BTreeSet<usize>> = BTreeMap::new();
    for c in &g.connections {
        let kind = g.nodes[c.src].kind.as_str();
        let Some(&(_, label)) =
            OTHER_DRIVERS.iter().find(
                |(p, _)| {
                    if *p == "Constraint" {
                        kind.ends_with(p)
                    } else {
                        kind.starts_with(p)
                    }
                },
            )
        else {
            continue;
        };
        let dst = g.nodes[c.dst].kind.as_str();
        if dst == "transform" || dst == "camera" || LIGHTS.contains(&dst) || SHAPES.contains(&dst) {
            others.entry(label).or_default().insert(c.src);
        }
    }
    for (label, nodes) in others {
        warnings.push(format!(
            "{label} ({}) drive attributes tress does not evaluate: drawn at their stored values",
            nodes.len()
        ));
    }
    (warnings, written)
}
