//! UsdSkel linear blend skinning of points-based prims (`Mesh`, `BasisCurves`,
//! `NurbsCurves`) at the frame's time code, as the UsdSkel documentation ("Schemas
//! In-Depth": Skeleton, SkelAnimation, BindingAPI) specifies:
//!
//! - a prim under a `SkelRoot` is bound to the Skeleton its `skel:skeleton` targets, the
//!   binding inherited down namespace from the nearest ancestor that authors one;
//! - the Skeleton's `joints` are paths whose parent-child relations give the hierarchy
//!   (parents before children); each joint's local transform is the bound
//!   `SkelAnimation`'s `translations`, `rotations` and `scales` at the time code (the
//!   stage lerps them, slerps the quaternions and holds them outside the samples), its
//!   `restTransforms` entry where the animation does not name the joint. The animation is
//!   found by `skel:animationSource` on the Skeleton, else on an ancestor of the skinned
//!   prim (the older binding on the `SkelRoot`), and mapped onto the skeleton by name;
//! - joint skel-space transforms chain outwards, `jointSkel = jointLocal · parentSkel`;
//!   the skinning transform of a joint is `inverse(bindTransform) · jointSkel`, the
//!   `bindTransforms` being world-space bind poses;
//! - a point is `Σ w_i · skinning_i(geomBindTransform(p))` over its `elementSize`
//!   influences (`primvars:skel:jointIndices` and `jointWeights`, vertex or constant
//!   interpolation, indices into `skel:joints` when authored, else the Skeleton's
//!   joints), weights normalised to sum 1;
//! - the result is in the Skeleton's space: the Skeleton prim's local-to-world places it
//!   and the skinned prim's own transform no longer applies.
//!
//! (The matrices above are USD's, row vectors; here they are glam's column-vector
//! transposes, so every product reads in the opposite order.)
//!
//! Influence primvars, `geomBindTransform` and `skel:joints` not on the prim are inherited
//! from its nearest ancestor that authors them, as the BindingAPI documents for
//! bindings shared by a group of gprims. A binding that cannot be evaluated (counts that do
//! not match, an index out of range, weights that are not finite, unknown joint names, a
//! target that is missing or of the wrong type) is one warning naming the prim and the
//! problem, and the prim is drawn in its rest pose.
//!
//! Blend shapes ("Schemas In-Depth": BlendShape) deform the points first, in the prim's
//! rest space: the prim's `skel:blendShapes` names its `skel:blendShapeTargets` (both
//! inherited like the influences), each target a `BlendShape` whose `offsets` (and
//! `normalOffsets`, for vertex normals) move every point, or the points of its
//! `pointIndices`, by the weight the bound animation's `blendShapeWeights` gives that name
//! in its `blendShapes` (0 for names it does not list). A target's inbetween shapes
//! (`inbetweens:NAME` offsets, a `weight` in their metadata) join the implicit rest shape at
//! weight 0 and the primary shape at 1: a weight takes the linear blend of the two shapes
//! around it, extrapolated from the two nearest below the first or above the last, as
//! `UsdSkelBlendShapeQuery` resolves them. Blend shapes that cannot be applied (counts
//! that do not match, an index out of range, a target that is no `BlendShape`) are one
//! warning naming the prim and why; the prim is skinned without them.

use super::values::{floats, ints, number, short, token, value, vec3s, Res};
use super::Notes;
use glam::{DMat3, DMat4, DQuat, DVec3, Vec3};
use openusd::sdf;
use openusd::usd::{Prim, TimeCode};
use std::collections::HashMap;
use std::rc::Rc;

/// What skinning a prim does at one time code: the blend-shape offsets of its points,
/// each point's blended matrix (one for the whole prim with constant influences), taking
/// bind-time prim points to skeleton space, and the skeleton's local-to-world, which
/// replaces the prim's own transform.
pub struct Skinning {
    /// Per point, or one for all, `Σ w_i · skinning_i · geomBindTransform`.
    matrices: Vec<DMat4>,
    /// The weighted blend shapes, added to the points before they are skinned.
    shapes: Option<Offsets>,
    /// The Skeleton prim's local-to-world at the time code.
    pub skel_to_world: DMat4,
}

/// The summed blend-shape offsets of a prim's points, in its rest space.
struct Offsets {
    /// One per point.
    points: Vec<Vec3>,
    /// One per point, when a target authors `normalOffsets`.
    normals: Option<Vec<Vec3>>,
}

impl Skinning {
    /// The one matrix of a constant (rigid) binding.
    pub fn rigid(&self) -> Option<DMat4> {
        (self.matrices.len() == 1).then(|| self.matrices[0])
    }

    fn matrix(&self, i: usize) -> DMat4 {
        self.matrices[if self.matrices.len() == 1 { 0 } else { i }]
    }

    /// Deforms `points` (the prim's, as authored) by the blend shapes and skins them into
    /// skeleton space.
    pub fn points(&self, points: &mut [Vec3]) -> Res<()> {
        self.fits(points.len())?;
        if let Some(shapes) = &self.shapes {
            points.iter_mut().zip(&shapes.points).for_each(|(p, d)| *p += *d);
        }
        for (i, p) in points.iter_mut().enumerate() {
            *p = self.matrix(i).transform_point3(p.as_dvec3()).as_vec3();
        }
        Ok(())
    }

    /// Skins vertex `normals` (one per point): the blend shapes' normal offsets added and
    /// renormalised, as `UsdSkelBlendShapeQuery` deforms normals, then each by the inverse
    /// transpose of its point's matrix, renormalised.
    pub fn normals(&self, normals: &mut [Vec3]) -> Res<()> {
        self.fits(normals.len())?;
        if let Some(offsets) = self.shapes.as_ref().and_then(|s| s.normals.as_ref()) {
            normals.iter_mut().zip(offsets).for_each(|(n, d)| *n = (*n + *d).normalize_or_zero());
        }
        for (i, n) in normals.iter_mut().enumerate() {
            let m = DMat3::from_mat4(self.matrix(i)).inverse().transpose();
            *n = (m * n.as_dvec3()).normalize_or_zero().as_vec3();
        }
        Ok(())
    }

    fn fits(&self, n: usize) -> Res<()> {
        let m = self.matrices.len();
        anyhow::ensure!(m == 1 || m == n, "the skinning has influences for {m} points, the prim {n}");
        if let Some(shapes) = &self.shapes {
            let k = shapes.points.len();
            anyhow::ensure!(k == n, "the blend shapes move {k} points, the prim has {n}");
        }
        Ok(())
    }
}

/// The skeletons of a stage posed at one time code, each once (by Skeleton and animation
/// paths), for all the prims bound to it.
#[derive(Default)]
pub struct Poses(HashMap<(String, Option<String>), Rc<Checked<Pose>>>);

/// The skinning of `prim` at `time`: `None` when it is not bound to a skeleton, or (said in
/// `notes`) when its binding cannot be evaluated and it is drawn in its rest pose.
pub fn skinning(prim: &Prim, time: TimeCode, poses: &mut Poses, notes: &mut Notes) -> Res<Option<Skinning>> {
    let Some((skeleton, under_root)) = bound_skeleton(prim)? else {
        if prim.attribute("skel:skeleton").get::<sdf::Value>().ok().flatten().is_some() {
            notes.note("`skel:skeleton` authored as an attribute, not a relationship: not skinned".into(), prim);
        }
        return Ok(None);
    };
    if !under_root {
        notes.note("skeleton bindings outside a `SkelRoot`: not skinned (UsdSkel skins only beneath one)".into(), prim);
        return Ok(None);
    }
    if token(value(prim, "primvars:skel:skinningMethod", time)?, "classicLinear") == "dualQuaternion" {
        notes.note("dual-quaternion skinning: skinned linearly".into(), prim);
    }
    let anim = animation(prim, &skeleton)?;
    let key = (skeleton.path().to_string(), anim.as_ref().map(|a| a.path().to_string()));
    let pose = match poses.0.get(&key) {
        Some(pose) => pose.clone(),
        None => {
            let pose = Rc::new(skeleton_pose(&skeleton, anim.as_ref(), time, notes)?);
            poses.0.insert(key, pose.clone());
            pose
        }
    };
    let skinned = (*pose).as_ref().map_err(String::clone).and_then(|pose| {
        let points = vec3s(value(prim, "points", time).map_err(|e| format!("{e:#}"))?, "points")
            .map_err(|e| format!("{}: {e:#}", prim.path()))?
            .map(|p| p.len());
        Ok((influences(prim, time, pose, points)?, pose, points))
    });
    match skinned {
        Ok((matrices, pose, points)) => {
            let shapes = match blend_shapes(prim, time, &pose.blend_weights, points, notes) {
                Ok(shapes) => shapes,
                Err(why) => {
                    let what = "UsdSkel blend shapes that cannot be applied: skinned without them";
                    notes.note_why(what.into(), prim, &why);
                    None
                }
            };
            Ok(Some(Skinning { matrices, shapes, skel_to_world: pose.skel_to_world }))
        }
        Err(why) => {
            notes.note_why("UsdSkel bindings that cannot be evaluated: drawn in the rest pose".into(), prim, &why);
            Ok(None)
        }
    }
}

/// The Skeleton `prim` is bound to (its own `skel:skeleton` or its nearest ancestor's) and
/// whether a `SkelRoot` holds it.
fn bound_skeleton(prim: &Prim) -> Res<Option<(Prim, bool)>> {
    let mut skeleton = None;
    let mut under_root = false;
    for p in lineage(prim) {
        if skeleton.is_none() {
            if let Some(t) = p.relationship("skel:skeleton").targets()?.into_iter().next() {
                skeleton = Some(prim.stage().prim(t));
            }
        }
        under_root |= p.type_name()?.is_some_and(|t| t.as_str() == "SkelRoot");
    }
    Ok(skeleton.map(|s| (s, under_root)))
}

/// `prim` and its ancestors, nearest first, without the pseudo-root.
fn lineage(prim: &Prim) -> Vec<Prim> {
    let mut out = vec![prim.clone()];
    let mut path = prim.path().clone();
    while let Some(p) = path.parent() {
        if p.as_str() == "/" || p.as_str().is_empty() {
            break;
        }
        out.push(prim.stage().prim(p.clone()));
        path = p;
    }
    out
}

/// The nearest of `prim` and its ancestors that authors `name`.
fn inherited(prim: &Prim, name: &str) -> Option<Prim> {
    lineage(prim).into_iter().find(|p| p.attribute(name).get::<sdf::Value>().ok().flatten().is_some())
}

/// A `token[]` (or `string[]`) attribute's value.
fn tokens(v: Option<sdf::Value>, what: &str) -> Checked<Option<Vec<String>>> {
    match v {
        None => Ok(None),
        Some(sdf::Value::TokenVec(t)) => Ok(Some(t.iter().map(|t| t.as_str().to_string()).collect())),
        Some(sdf::Value::StringVec(s)) => Ok(Some(s)),
        Some(other) => Err(format!("`{what}` is not an array of tokens: {}", short(&other))),
    }
}

/// A `matrix4d[]` attribute's value as glam matrices.
fn matrices(v: Option<sdf::Value>, what: &str) -> Checked<Option<Vec<DMat4>>> {
    match v {
        None => Ok(None),
        Some(sdf::Value::Matrix4dVec(m)) => Ok(Some(m.iter().map(|m| DMat4::from_cols_array(&m.0)).collect())),
        Some(other) => Err(format!("`{what}` is not an array of 4x4 matrices: {}", short(&other))),
    }
}

/// A result whose error says why a binding cannot be evaluated (the prim is then drawn in
/// its rest pose), where [`Res`] errors are the stage's.
type Checked<T> = Result<T, String>;

/// A Skeleton posed at one time code.
pub struct Pose {
    /// Per joint, `jointSkel · inverse(bindTransform)` in glam's order.
    skinning: Vec<DMat4>,
    /// The joints' paths.
    joints: Vec<String>,
    /// The Skeleton prim's local-to-world.
    skel_to_world: DMat4,
    /// The animation's blend-shape weights by name, or why they cannot be read.
    blend_weights: Checked<HashMap<String, f32>>,
}

/// `skeleton` posed at `time` by `anim` (else by its rest transforms).
fn skeleton_pose(skeleton: &Prim, anim: Option<&Prim>, time: TimeCode, notes: &mut Notes) -> Res<Checked<Pose>> {
    let at = skeleton.path();
    if skeleton.type_name()?.is_none_or(|t| t.as_str() != "Skeleton") {
        return Ok(Err(format!("`skel:skeleton` targets {at}, which is not a Skeleton")));
    }
    let read = || -> Checked<_> {
        let joints = tokens(value(skeleton, "joints", time).map_err(|e| e.to_string())?, "joints")?.unwrap_or_default();
        let bind = matrices(value(skeleton, "bindTransforms", time).map_err(|e| e.to_string())?, "bindTransforms")?;
        let rest = matrices(value(skeleton, "restTransforms", time).map_err(|e| e.to_string())?, "restTransforms")?;
        Ok((joints, bind, rest))
    };
    let (joints, bind, rest) = match read() {
        Ok(r) => r,
        Err(why) => return Ok(Err(format!("{at}: {why}"))),
    };
    let n = joints.len();
    let bind = match bind {
        Some(b) if b.len() == n => b,
        b => return Ok(Err(format!("{at}: {} `bindTransforms` for {n} joints", b.map_or(0, |b| b.len())))),
    };
    let mut index = HashMap::new();
    for (i, j) in joints.iter().enumerate() {
        if index.insert(j.as_str(), i).is_some() {
            return Ok(Err(format!("{at}: joint `{j}` is listed twice")));
        }
    }
    // A joint's parent is the joint at its path's parent path (a root when there is none);
    // UsdSkel orders parents before children.
    let mut parents = Vec::with_capacity(n);
    for (i, j) in joints.iter().enumerate() {
        let parent = j.rsplit_once('/').and_then(|(p, _)| index.get(p).copied());
        if parent.is_some_and(|p| p >= i) {
            return Ok(Err(format!("{at}: joint `{j}` comes before its parent")));
        }
        parents.push(parent);
    }
    let mut local: Vec<Option<DMat4>> = match rest {
        Some(r) if r.len() == n => r.into_iter().map(Some).collect(),
        Some(r) => return Ok(Err(format!("{at}: {} `restTransforms` for {n} joints", r.len()))),
        None => vec![None; n],
    };
    let mut blend_weights = Ok(HashMap::new());
    match anim {
        Some(anim) if anim.type_name()?.is_some_and(|t| t.as_str() == "SkelAnimation") => {
            if let Err(why) = animate(anim, time, &index, &mut local, notes) {
                return Ok(Err(format!("{}: {why}", anim.path())));
            }
            blend_weights = animation_weights(anim, time).map_err(|why| format!("{}: {why}", anim.path()));
        }
        Some(anim) => {
            return Ok(Err(format!("`skel:animationSource` targets {}, which is not a SkelAnimation", anim.path())))
        }
        None => {}
    }
    let mut skel: Vec<DMat4> = Vec::with_capacity(n);
    for i in 0..n {
        let Some(l) = local[i] else {
            return Ok(Err(format!("{at}: joint `{}` has no `restTransforms` entry and is not animated", joints[i])));
        };
        skel.push(parents[i].map_or(l, |p| skel[p] * l));
    }
    let mut skinning = Vec::with_capacity(n);
    for (i, (j, b)) in skel.iter().zip(&bind).enumerate() {
        let d = b.determinant();
        if !d.is_finite() || d.abs() < 1e-12 {
            return Ok(Err(format!("{at}: the bind transform of joint `{}` is not invertible", joints[i])));
        }
        let m = *j * b.inverse();
        if !m.is_finite() {
            return Ok(Err(format!("{at}: joint `{}` has a transform that is not finite", joints[i])));
        }
        skinning.push(m);
    }
    let skel_to_world = match super::world_matrix(skeleton.stage(), at, time) {
        Ok(m) => m,
        Err(e) => return Ok(Err(format!("{at}: {e:#}"))),
    };
    Ok(Ok(Pose { skinning, joints, skel_to_world, blend_weights }))
}

/// The blend-shape weights of `anim` at `time` by name: its `blendShapes` and
/// `blendShapeWeights` (none when it has neither).
fn animation_weights(anim: &Prim, time: TimeCode) -> Checked<HashMap<String, f32>> {
    let get = |name: &str| value(anim, name, time).map_err(|e| format!("{e:#}"));
    let names = tokens(get("blendShapes")?, "blendShapes")?.unwrap_or_default();
    let weights = floats(get("blendShapeWeights")?, "blendShapeWeights").map_err(|e| format!("{e:#}"))?;
    let weights = weights.unwrap_or_default();
    if names.len() != weights.len() {
        return Err(format!("{} `blendShapeWeights` for {} `blendShapes`", weights.len(), names.len()));
    }
    if let Some((name, w)) = names.iter().zip(&weights).find(|(_, w)| !w.is_finite()) {
        return Err(format!("the weight of blend shape `{name}` is not finite ({w})"));
    }
    Ok(names.into_iter().zip(weights).collect())
}

/// One shape of a blend shape: the implicit rest shape (no offsets) at weight 0, the
/// primary shape at 1, or an inbetween at its authored weight.
struct SubShape {
    weight: f64,
    /// `(offsets, normalOffsets)` attribute names, `None` for the rest shape.
    attrs: Option<(String, String)>,
}

/// The summed blend-shape offsets of `prim`'s `points` points at `time`, weighted by
/// `weights` (the bound animation's, by name): `None` when it has no blend shapes or
/// none weighs anything.
fn blend_shapes(
    prim: &Prim,
    time: TimeCode,
    weights: &Checked<HashMap<String, f32>>,
    points: Option<usize>,
    notes: &mut Notes,
) -> Checked<Option<Offsets>> {
    let stage_err = |e: anyhow::Error| format!("{e:#}");
    let Some(holder) = inherited(prim, "skel:blendShapes") else { return Ok(None) };
    let names = tokens(value(&holder, "skel:blendShapes", time).map_err(stage_err)?, "skel:blendShapes")?;
    let names = names.unwrap_or_default();
    let mut targets = Vec::new();
    for p in lineage(prim) {
        targets = p.relationship("skel:blendShapeTargets").targets().map_err(stage_err)?;
        if !targets.is_empty() {
            break;
        }
    }
    if names.len() != targets.len() {
        return Err(format!("{} `skel:blendShapes` for {} `skel:blendShapeTargets`", names.len(), targets.len()));
    }
    let weights = weights.as_ref().map_err(String::clone)?;
    let n = points.ok_or("blend shapes on a prim without points")?;
    let mut out: Option<Offsets> = None;
    for (name, target) in names.iter().zip(targets) {
        let w = f64::from(weights.get(name).copied().unwrap_or(0.0));
        if w == 0.0 {
            continue;
        }
        let shape = prim.stage().prim(target.clone());
        if shape.type_name().map_err(stage_err)?.is_none_or(|t| t.as_str() != "BlendShape") {
            return Err(format!("`skel:blendShapeTargets` names {target}, which is not a BlendShape"));
        }
        let indices = ints(value(&shape, "pointIndices", time).map_err(stage_err)?, "pointIndices")
            .map_err(stage_err)?
            .filter(|ix| !ix.is_empty());
        let mut slots = Vec::new();
        if let Some(ix) = &indices {
            for &i in ix {
                match usize::try_from(i).ok().filter(|&i| i < n) {
                    Some(i) => slots.push(i),
                    None => return Err(format!("{target}: point index {i} is not one of the {n} points")),
                }
            }
        }
        let out = out.get_or_insert_with(|| Offsets { points: vec![Vec3::ZERO; n], normals: None });
        // A shape's offsets are for its point indices, or for every point without them.
        let read = |name: &str| -> Checked<Option<Vec<Vec3>>> {
            let Some(v) = vec3s(value(&shape, name, time).map_err(stage_err)?, name).map_err(stage_err)? else {
                return Ok(None);
            };
            let want = if indices.is_some() { slots.len() } else { n };
            if v.len() != want {
                return Err(format!("{target}: {} `{name}` for {want} points", v.len()));
            }
            if v.iter().any(|d| !d.is_finite()) {
                return Err(format!("{target}: `{name}` holds an offset that is not finite"));
            }
            Ok(Some(v))
        };
        let at = |k: usize| if indices.is_some() { slots[k] } else { k };
        for (a, (offsets, normal_offsets)) in sub_shape_weights(&sub_shapes(&shape, notes).map_err(stage_err)?, w) {
            let a = a as f32;
            let v = read(&offsets)?.ok_or_else(|| format!("{target}: no `{offsets}`"))?;
            v.iter().enumerate().for_each(|(k, d)| out.points[at(k)] += *d * a);
            if let Some(v) = read(&normal_offsets)? {
                let normals = out.normals.get_or_insert_with(|| vec![Vec3::ZERO; n]);
                v.iter().enumerate().for_each(|(k, d)| normals[at(k)] += *d * a);
            }
        }
    }
    Ok(out)
}

/// The shapes of BlendShape `shape`, by weight: the rest shape at 0, the primary at 1 and
/// its inbetweens (`inbetweens:NAME` with a `weight`; those without one, or at 0 or 1, are
/// skipped and said, as `UsdSkelBlendShapeQuery` skips them).
fn sub_shapes(shape: &Prim, notes: &mut Notes) -> Res<Vec<SubShape>> {
    let mut out = vec![
        SubShape { weight: 0.0, attrs: None },
        SubShape { weight: 1.0, attrs: Some(("offsets".into(), "normalOffsets".into())) },
    ];
    for name in shape.property_names()? {
        let name = name.as_str();
        if !name.starts_with("inbetweens:") || name.ends_with(":normalOffsets") {
            continue;
        }
        let weight = shape.attribute(name).get_metadata::<sdf::Value>("weight")?;
        match number(weight, "weight").ok().flatten().filter(|w| w.is_finite()) {
            Some(w) if (w - 0.0).abs() > 1e-6 && (w - 1.0).abs() > 1e-6 => {
                out.push(SubShape { weight: w, attrs: Some((name.to_string(), format!("{name}:normalOffsets"))) });
            }
            _ => notes.note("inbetween shapes without a weight (or at 0 or 1): ignored".into(), shape),
        }
    }
    out.sort_by(|a, b| a.weight.total_cmp(&b.weight));
    Ok(out)
}

/// How much of each shape of `shapes` (sorted by weight) a blend shape of weight `w`
/// takes: the linear blend of the two around `w`, or of the two nearest outside them all.
/// Without inbetweens this is the primary shape times `w`. The rest shape adds nothing and
/// is left out.
fn sub_shape_weights(shapes: &[SubShape], w: f64) -> Vec<(f64, (String, String))> {
    let above = shapes.partition_point(|s| s.weight <= w).clamp(1, shapes.len() - 1);
    let (lo, hi) = (&shapes[above - 1], &shapes[above]);
    if hi.weight - lo.weight < 1e-6 {
        // Two inbetweens at one weight: no span to blend across (USD's query adds nothing).
        return Vec::new();
    }
    let t = (w - lo.weight) / (hi.weight - lo.weight);
    [(lo, 1.0 - t), (hi, t)]
        .into_iter()
        .filter_map(|(s, a)| s.attrs.clone().filter(|_| a != 0.0).map(|attrs| (a, attrs)))
        .collect()
}

/// The SkelAnimation bound to `skeleton`, else to the nearest ancestor of `prim` that
/// binds one.
fn animation(prim: &Prim, skeleton: &Prim) -> Res<Option<Prim>> {
    for p in std::iter::once(skeleton.clone()).chain(lineage(prim)) {
        if let Some(t) = p.relationship("skel:animationSource").targets()?.into_iter().next() {
            return Ok(Some(prim.stage().prim(t)));
        }
    }
    Ok(None)
}

/// Overwrites the local transforms of the joints `anim` names with its pose at `time`.
fn animate(
    anim: &Prim,
    time: TimeCode,
    index: &HashMap<&str, usize>,
    local: &mut [Option<DMat4>],
    notes: &mut Notes,
) -> Checked<()> {
    let get = |name: &str| value(anim, name, time).map_err(|e| e.to_string());
    let names = tokens(get("joints")?, "joints")?.unwrap_or_default();
    let n = names.len();
    let sized = |what: &str, len: Option<usize>| match len {
        Some(l) if l != n => Err(format!("{l} `{what}` for {n} joints")),
        _ => Ok(()),
    };
    let translations = vec3s(get("translations")?, "translations").map_err(|e| e.to_string())?;
    let rotations = super::values::quats(get("rotations")?, "rotations").map_err(|e| e.to_string())?;
    let scales = vec3s(get("scales")?, "scales").map_err(|e| e.to_string())?;
    sized("translations", translations.as_ref().map(Vec::len))?;
    sized("rotations", rotations.as_ref().map(Vec::len))?;
    sized("scales", scales.as_ref().map(Vec::len))?;
    let mut unknown = 0;
    for (k, name) in names.iter().enumerate() {
        let Some(&i) = index.get(name.as_str()) else {
            unknown += 1;
            continue;
        };
        // Unauthored components are the identity, as the crate's and Pixar's animation
        // queries default them.
        let t = translations.as_ref().map_or(DVec3::ZERO, |t| t[k].as_dvec3());
        let r = rotations.as_ref().map_or(DQuat::IDENTITY, |r| r[k]);
        let s = scales.as_ref().map_or(DVec3::ONE, |s| s[k].as_dvec3());
        let len = r.length();
        if !(t.is_finite() && s.is_finite() && len.is_finite() && len > 1e-12) {
            return Err(format!(
                "joint `{name}` has a translation, rotation or scale that is not finite (or a zero rotation)"
            ));
        }
        // USD's `scale · rotate · translate` on row vectors is glam's T · R · S.
        local[i] = Some(DMat4::from_scale_rotation_translation(s, r / len, t));
    }
    if unknown > 0 {
        notes.add("SkelAnimation joints that are not in the bound Skeleton: ignored".into(), anim, unknown);
    }
    Ok(())
}

/// Each point's blended matrix (one for constant influences) from `prim`'s influences
/// and the skeleton's `pose`.
fn influences(prim: &Prim, time: TimeCode, pose: &Pose, points: Option<usize>) -> Checked<Vec<DMat4>> {
    let (skinning, joint_names) = (&pose.skinning, &pose.joints);
    let path = prim.path();
    let stage_err = |e: anyhow::Error| format!("{e:#}");
    let from = |name: &str| inherited(prim, name).unwrap_or_else(|| prim.clone());
    let (ip, wp) = (from("primvars:skel:jointIndices"), from("primvars:skel:jointWeights"));
    let indices_attr = ip.attribute("primvars:skel:jointIndices");
    let weights_attr = wp.attribute("primvars:skel:jointWeights");
    let indices =
        ints(indices_attr.get_at(time).map_err(stage_err)?, "primvars:skel:jointIndices").map_err(stage_err)?;
    let weights =
        floats(weights_attr.get_at(time).map_err(stage_err)?, "primvars:skel:jointWeights").map_err(stage_err)?;
    let (Some(indices), Some(weights)) = (indices, weights) else {
        return Err(format!("{path}: bound to a skeleton without `primvars:skel:jointIndices` and `jointWeights`"));
    };
    let element_size = |a: &openusd::usd::Attribute| -> Checked<usize> {
        match a.get_metadata::<sdf::Value>("elementSize").map_err(stage_err)? {
            None => Ok(1),
            Some(sdf::Value::Int(k)) if k >= 1 => Ok(k as usize),
            Some(sdf::Value::Int64(k)) if k >= 1 => Ok(k as usize),
            Some(other) => {
                Err(format!("{path}: `elementSize` of the joint influences is not a positive integer: {other:?}"))
            }
        }
    };
    let es = element_size(&indices_attr)?;
    if element_size(&weights_attr)? != es || indices.len() != weights.len() {
        return Err(format!(
            "{path}: {} joint indices and {} weights (they must match, with the same elementSize)",
            indices.len(),
            weights.len()
        ));
    }
    let interp = match indices_attr.get_metadata::<sdf::Value>("interpolation").map_err(stage_err)? {
        None if indices.len() == es => "constant".to_string(),
        None => "vertex".to_string(),
        Some(v) => token(Some(v), ""),
    };
    let components = match interp.as_str() {
        "constant" => 1,
        "vertex" => points.ok_or_else(|| format!("{path}: per-point joint influences on a prim without points"))?,
        other => {
            return Err(format!(
                "{path}: joint influences of `{other}` interpolation (UsdSkel reads vertex or constant)"
            ))
        }
    };
    if indices.len() != components * es {
        return Err(format!(
            "{path}: {} joint influences where {interp} interpolation with elementSize {es} needs {}",
            indices.len(),
            components * es
        ));
    }
    // `skel:joints` names the joints the indices refer to, in the skeleton's joints.
    let order: Vec<usize> = match inherited(prim, "skel:joints") {
        Some(p) => {
            let names = tokens(value(&p, "skel:joints", time).map_err(stage_err)?, "skel:joints")
                .map_err(|e| format!("{path}: {e}"))?;
            let mut out = Vec::new();
            for name in names.unwrap_or_default() {
                match joint_names.iter().position(|j| *j == name) {
                    Some(i) => out.push(i),
                    None => {
                        return Err(format!("{path}: `skel:joints` names `{name}`, which the Skeleton does not have"))
                    }
                }
            }
            out
        }
        None => (0..joint_names.len()).collect(),
    };
    let g = match inherited(prim, "primvars:skel:geomBindTransform") {
        Some(p) => match value(&p, "primvars:skel:geomBindTransform", time).map_err(stage_err)? {
            Some(sdf::Value::Matrix4d(m)) => DMat4::from_cols_array(&m.0),
            Some(other) => return Err(format!("{path}: `geomBindTransform` is not a 4x4 matrix: {}", short(&other))),
            None => DMat4::IDENTITY,
        },
        None => DMat4::IDENTITY,
    };
    if !g.is_finite() {
        return Err(format!("{path}: `geomBindTransform` is not finite"));
    }
    let mut out = Vec::with_capacity(components);
    for c in 0..components {
        let (ix, ws) = (&indices[c * es..(c + 1) * es], &weights[c * es..(c + 1) * es]);
        if ws.iter().any(|w| !w.is_finite() || *w < 0.0) {
            return Err(format!("{path}: point {c} has a joint weight that is negative or not finite"));
        }
        let sum: f64 = ws.iter().map(|&w| f64::from(w)).sum();
        if sum <= 0.0 {
            return Err(format!("{path}: the joint weights of point {c} sum to 0"));
        }
        let mut m = DMat4::ZERO;
        for (&j, &w) in ix.iter().zip(ws) {
            let Some(&s) = usize::try_from(j).ok().and_then(|j| order.get(j)) else {
                return Err(format!("{path}: joint index {j} is not one of the {} joints", order.len()));
            };
            if w > 0.0 {
                m += skinning[s] * (f64::from(w) / sum);
            }
        }
        out.push(m * g);
    }
    Ok(out)
}
