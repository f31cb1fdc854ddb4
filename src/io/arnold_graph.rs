//! Arnold shader networks: a shader parameter whose value is another shader node's output
//! (a ramp, a multiply), evaluated to what tress's materials take. The readers of Arnold
//! scene sources (`.ass`) and of Arnold shaders in USD files present their nodes through
//! [`Network`]; [`Eval`] follows the links and gives a [`Pattern`]: a constant colour,
//! or a colour that varies along a strand, which the readers bake into the strands'
//! per-point colours ([`bake`]). Nodes tress does not evaluate give `None`, and the
//! parameter keeps its own value; each is listed in [`Eval::unread`] for the reader to
//! report once per node type.
//!
//! Nodes evaluated (Arnold user guide, texture and utility shaders):
//!
//! - `ramp_rgb`, `ramp_float`: keys `position`, `color` (or `value`) and `interpolation`
//!   (Arnold's 0 constant, 1 linear, 2 Catmull-Rom; 3, monotone cubic, drawn as
//!   Catmull-Rom, which passes the same keys), evaluated by the hair system's ramp
//!   ([`crate::hair_system::ramp`]). `type "v"` is the curve's v, 0 at the root to 1 at
//!   the tip; `type "u"` runs across a strand, which tress shades alike all round, so the
//!   ramp's mean over u is drawn; other types and a linked `input` are reported (the mean
//!   drawn).
//! - `multiply` (`input1 × input2`, both 1 by default), `color_correct` (its `input`; its
//!   other parameters are reported, not applied).
//! - `checkerboard` (`color1`, `color2`, frequencies, offsets, `contrast`; the texture
//!   filtered over the ray's footprint instead of Arnold's filter controls): on strands by
//!   the curve's `uvs`, else Arnold's implicit coordinates (v along); on a surface shader's
//!   diffuse or emitted colour a textured surface ([`super::arnold_surface::textured`]).
//! - A link to one channel (`node.r`, `.g`, `.b`) reads that channel as grey; `.a`, the
//!   alpha of an opaque colour, is 1.

use super::arnold_hair::{ArnoldShader, Param};
use crate::geometry::StrandSet;
use crate::hair_system::ramp::{Interp, Ramp, RampKey};
use crate::math::Color;
use crate::shading::texture::{Checker, ColorMap};
use crate::shading::Material;

/// A parameter's value as a reader finds it in its file.
#[derive(Clone, Debug, PartialEq)]
pub enum Value<N> {
    /// Numbers: one for a float, three (or four) for a colour, any count for an array.
    Numbers(Vec<f32>),
    /// A string or an enum.
    Text(String),
    /// The output of another node, whole or one channel of it (0 to 3: r, g, b, a).
    Link(N, Option<usize>),
}

/// A file's shader nodes, as [`Eval`] reads them.
pub trait Network {
    /// How the file names a node.
    type Node: Clone;
    /// The node's Arnold type (`ramp_rgb`), without any prefix the file adds.
    fn kind(&self, node: &Self::Node) -> String;
    /// The value of the node's parameter `name`, `None` when not set.
    fn value(&self, node: &Self::Node, name: &str) -> Option<Value<Self::Node>>;
}

/// Where on a strand a pattern is evaluated.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StrandPlace {
    /// Arnold's v: 0 at the root, 1 at the tip.
    pub v: f32,
    /// The strand's index in its set.
    pub strand: u32,
    /// The curve segment (Arnold's primitive) along the strand.
    pub segment: u32,
    /// The curve's texture coordinates, when it has them (Arnold's curve `uvs`).
    pub uv: Option<[f32; 2]>,
}

impl StrandPlace {
    /// Point `v` along strand 0's first segment, without texture coordinates.
    pub fn at(v: f32) -> StrandPlace {
        StrandPlace { v, strand: 0, segment: 0, uv: None }
    }
}

/// A colour a shader network gives: constant, or varying along a strand.
#[derive(Clone, Debug, PartialEq)]
pub enum Pattern {
    /// The same everywhere.
    Constant(Color),
    /// A ramp by v, root (0) to tip (1).
    RampV(Ramp<Color>),
    /// The product of two patterns.
    Product(Box<Pattern>, Box<Pattern>),
    /// One channel of a pattern, as grey.
    Channel(Box<Pattern>, usize),
    /// The first pattern at the root blended linearly by v to the second at the tip.
    RootToTip(Box<Pattern>, Box<Pattern>),
    /// A random colour per curve segment, as Arnold's `utility` shader colours primitives
    /// (`color_mode "prims"`): each channel a hash of the strand and segment.
    Primitives,
    /// A checkerboard by the curve's texture coordinates, else by Arnold's implicit ones
    /// on curves (u 0.5 across, v along).
    Checker(Checker),
}

/// Samples along v that [`Pattern::mean`] averages.
const MEAN_SAMPLES: usize = 64;

impl Pattern {
    /// The colour, when the same everywhere.
    pub fn constant(&self) -> Option<Color> {
        match self {
            Pattern::Constant(c) => Some(*c),
            _ => None,
        }
    }

    /// The colour at `at`.
    pub fn at(&self, at: StrandPlace) -> Color {
        match self {
            Pattern::Constant(c) => *c,
            Pattern::RampV(r) => r.eval(at.v),
            Pattern::Product(a, b) => a.at(at) * b.at(at),
            Pattern::Channel(p, k) => Color::splat(p.at(at)[*k]),
            Pattern::RootToTip(root, tip) => root.at(at).lerp(tip.at(at), at.v.clamp(0.0, 1.0)),
            Pattern::Primitives => {
                use crate::math::rng::{hash_u32, unit_float};
                let h = hash_u32(at.strand.wrapping_mul(0x9e37_79b9) ^ hash_u32(at.segment));
                Color::new(unit_float(h), unit_float(hash_u32(h)), unit_float(hash_u32(h ^ 0x5bd1_e995)))
            }
            Pattern::Checker(c) => c.lookup(at.uv.unwrap_or([0.5, at.v]), 0.0),
        }
    }

    /// The mean over a strand's length (v from 0 to 1, at sample midpoints, each sample
    /// another segment, so that random colours per segment average too).
    pub fn mean(&self) -> Color {
        match self {
            Pattern::Constant(c) => return *c,
            Pattern::Checker(c) => return c.average(),
            _ => {}
        }
        let sum: Color = (0..MEAN_SAMPLES)
            .map(|i| {
                self.at(StrandPlace { segment: i as u32, ..StrandPlace::at((i as f32 + 0.5) / MEAN_SAMPLES as f32) })
            })
            .sum();
        sum / MEAN_SAMPLES as f32
    }

    /// `a × b`, folded to a constant when both are.
    pub fn product(a: Pattern, b: Pattern) -> Pattern {
        match (a.constant(), b.constant()) {
            (Some(x), Some(y)) => Pattern::Constant(x * y),
            (Some(x), _) if x == Color::ONE => b,
            (_, Some(y)) if y == Color::ONE => a,
            _ => Pattern::Product(Box::new(a), Box::new(b)),
        }
    }

    /// `root` at the root blended to `tip` at the tip, a constant when both are the same
    /// constant.
    pub fn root_to_tip(root: Pattern, tip: Pattern) -> Pattern {
        match (root.constant(), tip.constant()) {
            (Some(r), Some(t)) if r == t => root,
            _ => Pattern::RootToTip(Box::new(root), Box::new(tip)),
        }
    }

    fn channel(self, k: usize) -> Pattern {
        match (self.constant(), k) {
            (_, 3) => Pattern::Constant(Color::ONE),
            (Some(c), _) => Pattern::Constant(Color::splat(c[k])),
            _ => Pattern::Channel(Box::new(self), k),
        }
    }
}

/// Per-point colours for `set`: `tint × pattern`, each point at its v (its index along
/// its strand over the strand's pieces: the sampled curves' pieces are even in the
/// curve's parameter), each curve segment sampled in `pieces` pieces.
pub fn bake(pattern: &Pattern, tint: Color, set: &StrandSet, pieces: usize) -> Vec<[f32; 3]> {
    let mut out = Vec::with_capacity(set.points.len());
    let pieces = pieces.max(1);
    let uvs = set.strand_info.as_ref().map(|i| &i.root_uv);
    for (strand, s) in set.offsets.windows(2).enumerate() {
        let uv = uvs.and_then(|u| u.get(strand).copied());
        let n = (s[1] - s[0]) as usize;
        let last = n.saturating_sub(1).max(1);
        out.extend((0..n).map(|k| {
            // A point where two segments meet starts the next one; the tip ends the last.
            let segment = (k.min(last - 1) / pieces) as u32;
            let at = StrandPlace { v: k as f32 / last as f32, strand: strand as u32, segment, uv };
            (tint * pattern.at(at)).to_array()
        }));
    }
    out
}

/// An Arnold shader as a material, its linked parameters evaluated ([`shade`]).
#[derive(Clone, Debug, PartialEq)]
pub struct Shaded {
    /// The material.
    pub material: Material,
    /// The colour along the strands that replaces the material's base colour (already
    /// times it): to be baked into the strands' colours ([`bake`]).
    pub along: Option<Pattern>,
    /// What the material leaves out, in one sentence naming the shader.
    pub warning: Option<String>,
}

/// The colour a material's base colour stands for, which a strand's own colour replaces
/// when it has one (diffuse, Phong, tube and unlit materials); `None` for the others.
pub fn base_color(material: &Material) -> Option<Color> {
    match material {
        Material::Diffuse { color } | Material::Unlit { color } => Some(*color),
        Material::Phong { diffuse, .. } if *diffuse != Color::ZERO => Some(*diffuse),
        Material::Tube(t) => Some(t.diffuse),
        _ => None,
    }
}

/// The varying patterns of `varying` on the parameters `names` (which colour the
/// material's base colour) multiplied together, each such parameter set to 1; they are
/// taken from `varying`, the others left in it. `None` when none is there.
pub fn mapped<S: ArnoldShader>(
    params: &mut S,
    varying: &mut Vec<(&'static str, Pattern)>,
    names: &[&str],
) -> Option<Pattern> {
    let mut along: Option<Pattern> = None;
    varying.retain(|(name, p)| {
        if !names.contains(name) {
            return true;
        }
        set(params, name, Color::ONE);
        along = Some(match along.take() {
            None => p.clone(),
            Some(a) => Pattern::product(a, p.clone()),
        });
        false
    });
    along
}

/// Sets parameter `name` of `params` to `c` (a number to its red channel).
pub fn set<S: ArnoldShader>(params: &mut S, name: &str, c: Color) {
    match params.param(name) {
        Some(Param::Float(f)) => *f = c.x,
        Some(Param::Color(v)) => *v = c,
        _ => {}
    }
}

/// Arnold shader `node` of `net` (labelled `label` in messages) as a material: its
/// parameters read by `S`'s names, their links evaluated. Constant networks set the
/// parameter; on strands (`strands`), networks varying along them colour the strands
/// (what `S` makes of them: [`ArnoldShader::along`]), elsewhere they are drawn in their
/// mean, said in the warning, as are parameters of the wrong kind and networks not
/// evaluated (listed in `eval`'s [`Eval::unread`]), which keep their own values.
pub fn shade<S: ArnoldShader, N: Network>(
    eval: &mut Eval<'_, N>,
    node: &N::Node,
    label: &str,
    strands: bool,
) -> Shaded {
    let mut params = S::default();
    let (mut connected, mut varying, mut wrong) = (Vec::new(), Vec::new(), Vec::new());
    for &name in S::NAMES {
        let Some(v) = eval.net.value(node, name) else { continue };
        if let (Some(t), Value::Text(w)) = (params.text(name), &v) {
            *t = w.clone();
            continue;
        }
        let linked = matches!(v, Value::Link(..));
        let pattern = match params.param(name) {
            Some(Param::Float(f)) => eval.color(node, name, Color::splat(*f)).map(|p| p.channel(0)),
            Some(Param::Color(c)) => eval.color(node, name, *c),
            Some(Param::Bool(b)) => {
                match &v {
                    Value::Text(w) if matches!(w.as_str(), "on" | "true" | "off" | "false") => {
                        *b = matches!(w.as_str(), "on" | "true")
                    }
                    Value::Numbers(x) if x.len() == 1 => *b = x[0] != 0.0,
                    _ => wrong.push(name),
                }
                continue;
            }
            None => continue,
        };
        match pattern {
            Some(p) => match p.constant() {
                Some(c) => set(&mut params, name, c),
                None => varying.push((name, p)),
            },
            None if linked => connected.push(name.to_string()),
            None => wrong.push(name),
        }
        if params.param(name).is_some_and(|p| p.is_infinite()) {
            wrong.push(name);
            params = S::default();
        }
    }
    let along = match strands {
        true => params.along(&mut varying),
        false => None,
    };
    // On a surface, the first checkerboard on a parameter that colours the surface
    // textures it: the material made with that parameter at 1, the map applied.
    let mut map = None;
    if !strands {
        if let Some(k) = varying
            .iter()
            .position(|(name, p)| matches!(p, Pattern::Checker(_)) && S::MAPS.iter().any(|(m, _)| m == name))
        {
            let (name, p) = varying.remove(k);
            let slot = S::MAPS.iter().find(|(m, _)| *m == name).map(|(_, s)| *s);
            if let (Pattern::Checker(c), Some(slot)) = (p, slot) {
                set(&mut params, name, Color::ONE);
                map = Some((name, slot, c));
            }
        }
    }
    let mut left_out = Vec::new();
    for (name, p) in varying {
        set(&mut params, name, p.mean());
        left_out.push(name.to_string());
    }
    let (mut material, mut warning) = params.material(label, &connected);
    if let Some((name, slot, c)) = map {
        match super::arnold_surface::textured(&material, slot, ColorMap::Checker(c.clone())) {
            Some(m) => material = m,
            None => {
                set(&mut params, name, c.average());
                (material, warning) = params.material(label, &connected);
                left_out.push(name.to_string());
            }
        }
    }
    let along = match (along, base_color(&material)) {
        (Some(p), Some(tint)) => Some(Pattern::product(Pattern::Constant(tint), p)),
        (Some(p), None) => {
            // The material has no base colour the strands' colours replace: the mean.
            let mean = p.mean();
            for &(name, _) in S::MAPS {
                set(&mut params, name, mean);
            }
            (material, warning) = params.material(label, &connected);
            left_out.push("the colours along the strands".into());
            None
        }
        (None, _) => None,
    };
    let mut extra = Vec::new();
    if !left_out.is_empty() {
        extra.push(format!("varying shading networks on {} (drawn in their mean)", left_out.join(", ")));
    }
    if !wrong.is_empty() {
        extra.push(format!("{} of the wrong kind or beyond single precision (defaults used)", wrong.join(", ")));
    }
    if !extra.is_empty() {
        let w = warning.get_or_insert_with(|| format!("{label}: Arnold shader settings tress does not represent: "));
        if !w.ends_with(": ") {
            w.push_str(", ");
        }
        w.push_str(&extra.join(", "));
    }
    Shaded { material, along, warning }
}

/// Links followed before a network is taken to loop.
const MAX_DEPTH: usize = 64;

/// Evaluates the links of a [`Network`], listing what it does not evaluate.
pub struct Eval<'a, N: Network> {
    net: &'a N,
    /// What was not evaluated: a message (one per node type and parameter, the reader
    /// counts them) and the node it concerns.
    pub unread: Vec<(String, N::Node)>,
}

impl<'a, N: Network> Eval<'a, N> {
    /// An evaluator of `net`'s nodes.
    pub fn new(net: &'a N) -> Self {
        Eval { net, unread: Vec::new() }
    }

    /// The pattern of colour parameter `name` of `node`, `default` when it is not set;
    /// `None` when it is linked to a network tress does not evaluate (listed in
    /// [`Eval::unread`]) or is not a colour.
    pub fn color(&mut self, node: &N::Node, name: &str, default: Color) -> Option<Pattern> {
        self.param(node, name, default, 0)
    }

    fn note(&mut self, what: String, node: &N::Node) {
        self.unread.push((what, node.clone()));
    }

    fn param(&mut self, node: &N::Node, name: &str, default: Color, depth: usize) -> Option<Pattern> {
        match self.net.value(node, name) {
            None => Some(Pattern::Constant(default)),
            Some(Value::Numbers(v)) => match v.len() {
                1 => Some(Pattern::Constant(Color::splat(v[0]))),
                3 | 4 => Some(Pattern::Constant(Color::new(v[0], v[1], v[2]))),
                _ => None,
            },
            Some(Value::Text(_)) => None,
            Some(Value::Link(source, channel)) => {
                if depth >= MAX_DEPTH {
                    self.note(
                        format!("shader networks more than {MAX_DEPTH} links deep (a loop?): not evaluated"),
                        node,
                    );
                    return None;
                }
                let p = self.output(&source, depth + 1)?;
                Some(match channel {
                    Some(k) => p.channel(k.min(3)),
                    None => p,
                })
            }
        }
    }

    /// The output of `node`.
    fn output(&mut self, node: &N::Node, depth: usize) -> Option<Pattern> {
        let kind = self.net.kind(node);
        match kind.as_str() {
            "ramp_rgb" | "ramp_float" => self.ramp(node, &kind),
            "multiply" => {
                let a = self.param(node, "input1", Color::ONE, depth)?;
                let b = self.param(node, "input2", Color::ONE, depth)?;
                Some(Pattern::product(a, b))
            }
            "checkerboard" => self.checker(node, depth),
            "color_correct" => {
                let set: Vec<&str> =
                    COLOR_CORRECT_READ[2..].iter().copied().filter(|p| self.net.value(node, p).is_some()).collect();
                if !set.is_empty() {
                    self.note(format!("`color_correct` {}: not applied (its input drawn)", set.join(", ")), node);
                }
                self.param(node, "input", Color::ZERO, depth)
            }
            other => {
                self.note(
                    format!("`{other}` nodes in shader networks: not evaluated (the parameter's own value used)"),
                    node,
                );
                None
            }
        }
    }

    /// A checkerboard whose colours and numbers are constants.
    fn checker(&mut self, node: &N::Node, depth: usize) -> Option<Pattern> {
        let mut c = Checker::default();
        for (name, slot) in [("color1", &mut c.color1), ("color2", &mut c.color2)] {
            *slot = match self.param(node, name, *slot, depth)?.constant() {
                Some(x) => x,
                None => {
                    self.note("checkerboards of varying colours: not evaluated".into(), node);
                    return None;
                }
            };
        }
        for (name, slot) in c.numbers_mut() {
            match self.net.value(node, name) {
                None => {}
                Some(Value::Numbers(v)) if v.len() == 1 && v[0].is_finite() => *slot = v[0],
                Some(_) => {
                    self.note(format!("checkerboard `{name}` not a number: its default used"), node);
                }
            }
        }
        for name in ["filter_strength", "filter_offset", "uvset"] {
            if self.net.value(node, name).is_some() {
                self.note(format!("checkerboard `{name}`: not applied (filtered over the ray's footprint)"), node);
            }
        }
        if !(c.color1.is_finite() && c.color2.is_finite()) {
            return None;
        }
        Some(Pattern::Checker(c))
    }

    /// A ramp node: by v along strands; across them (u) its mean; else reported.
    fn ramp(&mut self, node: &N::Node, kind: &str) -> Option<Pattern> {
        let numbers = |name: &str| match self.net.value(node, name) {
            Some(Value::Numbers(v)) => Some(v),
            _ => None,
        };
        let values = if kind == "ramp_rgb" { "color" } else { "value" };
        let (Some(position), Some(raw)) = (numbers("position"), numbers(values)) else {
            self.note(format!("`{kind}` nodes without `position` and `{values}` arrays: not evaluated"), node);
            return None;
        };
        let colors: Vec<Color> = match kind {
            "ramp_rgb" => raw.chunks_exact(3).map(|c| Color::new(c[0], c[1], c[2])).collect(),
            _ => raw.iter().map(|&x| Color::splat(x)).collect(),
        };
        let interp = numbers("interpolation").unwrap_or_default();
        if colors.len() != position.len() || position.is_empty() {
            self.note(
                format!("`{kind}` nodes whose keys do not match ({} positions): not evaluated", position.len()),
                node,
            );
            return None;
        }
        let mut odd = false;
        let keys = position
            .iter()
            .zip(&colors)
            .enumerate()
            .map(|(i, (&p, &value))| {
                // Arnold's interpolation enum; 3, monotone cubic, as Catmull-Rom.
                let interp = match interp.get(i).copied().unwrap_or(1.0) as i64 {
                    0 => Interp::None,
                    1 => Interp::Linear,
                    2 | 3 => Interp::Spline,
                    _ => {
                        odd = true;
                        Interp::Linear
                    }
                };
                RampKey { position: p.clamp(0.0, 1.0), value, interp }
            })
            .collect();
        if odd {
            self.note(format!("`{kind}` interpolations other than 0 to 3: drawn linear"), node);
        }
        let ramp = match Ramp::new(keys) {
            Ok(r) => r,
            Err(e) => {
                self.note(format!("`{kind}` nodes with bad keys ({e}): not evaluated"), node);
                return None;
            }
        };
        for p in ["input", "offset"] {
            if self.net.value(node, p).is_some() {
                self.note(format!("`{kind}` `{p}`: not applied"), node);
            }
        }
        let kind_of = match self.net.value(node, "type") {
            Some(Value::Text(t)) => t,
            _ => "custom".to_string(),
        };
        let along = Pattern::RampV(ramp);
        match kind_of.as_str() {
            "v" => Some(along),
            "u" => Some(Pattern::Constant(along.mean())),
            other => {
                self.note(format!("`{kind}` of `type` `{other}`: drawn in the ramp's mean colour"), node);
                Some(Pattern::Constant(along.mean()))
            }
        }
    }
}

/// The node types [`Eval`] evaluates and the parameters it reads of each (the readers
/// report the others).
pub const READ: [(&str, &[&str]); 5] = [
    (
        "checkerboard",
        &[
            "color1",
            "color2",
            "u_frequency",
            "v_frequency",
            "u_offset",
            "v_offset",
            "contrast",
            "filter_strength",
            "filter_offset",
            "uvset",
        ],
    ),
    ("ramp_rgb", &["type", "position", "color", "interpolation", "input", "offset"]),
    ("ramp_float", &["type", "position", "value", "interpolation", "input", "offset"]),
    ("multiply", &["input1", "input2"]),
    ("color_correct", &COLOR_CORRECT_READ),
];

/// The parameters of `color_correct` looked at: its input, the pivot of its contrast,
/// and those reported when set.
const COLOR_CORRECT_READ: [&str; 14] = [
    "input",
    "contrast_pivot",
    "alpha_is_luminance",
    "alpha_multiply",
    "alpha_add",
    "invert",
    "invert_alpha",
    "gamma",
    "hue_shift",
    "saturation",
    "contrast",
    "exposure",
    "multiply",
    "add",
];

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::HashMap;

    /// A node's type and parameters.
    type TestNode = (&'static str, Vec<(&'static str, Value<&'static str>)>);

    /// A network of nodes by name.
    struct Nodes(HashMap<&'static str, TestNode>);

    impl Network for Nodes {
        type Node = &'static str;
        fn kind(&self, node: &&'static str) -> String {
            self.0[node].0.to_string()
        }
        fn value(&self, node: &&'static str, name: &str) -> Option<Value<&'static str>> {
            self.0[node].1.iter().find(|(n, _)| *n == name).map(|(_, v)| v.clone())
        }
    }

    fn nums(v: &[f32]) -> Value<&'static str> {
        Value::Numbers(v.to_vec())
    }

    fn ramp(kind: &'static str, interp: f32) -> TestNode {
        (
            "ramp_rgb",
            vec![
                ("type", Value::Text(kind.into())),
                ("position", nums(&[0.0, 1.0])),
                ("color", nums(&[1.0, 0.0, 0.0, 0.0, 0.0, 1.0])),
                ("interpolation", nums(&[interp, interp])),
            ],
        )
    }

    fn at(v: f32) -> StrandPlace {
        StrandPlace::at(v)
    }

    #[test]
    fn a_v_ramp_through_a_multiply_varies_root_to_tip() {
        let net = Nodes(HashMap::from([
            ("shader", ("standard_hair", vec![("diffuse_color", Value::Link("mult", None))])),
            ("mult", ("multiply", vec![("input1", nums(&[0.5, 0.5, 0.5])), ("input2", Value::Link("ramp", None))])),
            ("ramp", ramp("v", 1.0)),
        ]));
        let mut e = Eval::new(&net);
        let p = e.color(&"shader", "diffuse_color", Color::ONE).unwrap();
        assert!(e.unread.is_empty());
        assert_eq!(p.constant(), None);
        assert!((p.at(at(0.0)) - Color::new(0.5, 0.0, 0.0)).length() < 1e-6);
        assert!((p.at(at(0.5)) - Color::new(0.25, 0.0, 0.25)).length() < 1e-6);
        assert!((p.at(at(1.0)) - Color::new(0.0, 0.0, 0.5)).length() < 1e-6);
        assert!((p.mean() - Color::new(0.25, 0.0, 0.25)).length() < 1e-5);
    }

    #[test]
    fn arnolds_interpolation_enum_steps_and_curves() {
        let net = Nodes(HashMap::from([("step", ramp("v", 0.0)), ("smooth", ramp("v", 2.0))]));
        let mut e = Eval::new(&net);
        let step = e.output(&"step", 0).unwrap();
        assert_eq!(step.at(at(0.9)), Color::new(1.0, 0.0, 0.0));
        let smooth = e.output(&"smooth", 0).unwrap();
        assert!((smooth.at(at(0.5)) - Color::new(0.5, 0.0, 0.5)).length() < 1e-6);
    }

    #[test]
    fn u_ramps_are_their_mean_and_unknown_nodes_are_listed() {
        let net = Nodes(HashMap::from([
            ("u", ramp("u", 1.0)),
            ("s", ("lambert", vec![("Kd_color", Value::Link("n", None)), ("Kd", Value::Link("u", Some(2)))])),
            ("n", ("noise", vec![])),
        ]));
        let mut e = Eval::new(&net);
        assert_eq!(e.color(&"s", "Kd", Color::ONE), Some(Pattern::Constant(Color::splat(0.5))));
        assert_eq!(e.color(&"s", "Kd_color", Color::ONE), None);
        assert_eq!(e.unread.len(), 1);
        assert!(e.unread[0].0.contains("`noise`"), "{:?}", e.unread);
    }

    #[test]
    fn loops_end_and_are_reported() {
        let net = Nodes(HashMap::from([("m", ("multiply", vec![("input1", Value::Link("m", None))]))]));
        let mut e = Eval::new(&net);
        assert_eq!(e.color(&"m", "input1", Color::ONE), None);
        assert!(e.unread.iter().any(|(w, _)| w.contains("loop")), "{:?}", e.unread);
    }

    #[test]
    fn baking_gives_each_point_its_v() {
        let mut set = StrandSet::new();
        set.push_strand((0..3).map(|i| (glam::Vec3::new(0.0, i as f32, 0.0), 0.1)));
        let p = Pattern::root_to_tip(Pattern::Constant(Color::ZERO), Pattern::Constant(Color::ONE));
        let c = bake(&p, Color::splat(2.0), &set, 1);
        assert_eq!(c, vec![[0.0; 3], [1.0; 3], [2.0; 3]]);
        // Random colours per segment: the same over a segment's pieces, the tip the last
        // segment's; another segment or strand another colour.
        set.push_strand((0..5).map(|i| (glam::Vec3::new(1.0, i as f32, 0.0), 0.1)));
        let c = bake(&Pattern::Primitives, Color::ONE, &set, 2);
        assert_eq!((c[0], c[1]), (c[1], c[2]));
        assert_eq!((c[3], c[5], c[6]), (c[4], c[6], c[7]));
        assert!(c[3] != c[5] && c[0] != c[3]);
        assert!(c.iter().flatten().all(|x| (0.0..1.0).contains(x)));
    }
}
