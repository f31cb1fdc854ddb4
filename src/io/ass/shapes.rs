//! The shapes of an Arnold scene: `polymesh`, `curves` and `sphere` nodes with their
//! shaders, and `ginstance` copies of them (and of procedurals).
//!
//! - `polymesh`: `nsides` (all triangles without it), `vidxlist`, `vlist`, and `uvlist` by
//!   `uvidxlist` (or by vertex); `subdiv_type catclark` refined `subdiv_iterations` times
//!   (Arnold's default 1) by [`crate::geometry::subdivision`], as the USD and Maya readers
//!   do; `smoothing` on interpolates vertex normals over the faces (`nlist` and `nidxs`
//!   are not read: the normals are the mesh's own, area-weighted). `vidxs` and `uvidxs`
//!   are Arnold 5's names of the index lists. Per-face shaders (`shidxs`): the first.
//! - `curves`: `num_points` per curve, `points`, `radius` (one for all, one per point, or
//!   one per segment end as Arnold gives cubic curves), `basis` `bezier` (Arnold's
//!   default), `b-spline`, `catmull-rom` or `linear`, sampled by the USD reader's
//!   evaluation ([`crate::io::usd::curves::strands`]); Arnold's cubic curves are open (they
//!   do not reach a B-spline's or Catmull-Rom's end points). Every `mode` (ribbon, thick,
//!   oriented) is drawn as round strands. `uvs`, one per curve, texture the curves.
//! - `sphere`: `center`, `radius`.
//! - `visibility`: Arnold's ray bits ([`crate::io::usd::visibility::from_bits`]), with
//!   `matte`; a shape of visibility 0 is not drawn, but its `ginstance`s are.
//! - `ginstance`: `node` placed by its `matrix`, over the node's own unless
//!   `inherit_xform` is off; its own `visibility`.
//! - `shader` (the first of a list): `standard_surface`, `lambert`, `flat`, the legacy
//!   `standard`, and on curves also `standard_hair` and the legacy `hair`, by Arnold's
//!   parameter names ([`crate::io::arnold_surface`], [`crate::io::arnold_hair`]). A
//!   parameter linked to other nodes is evaluated by [`crate::io::arnold_graph`]: a
//!   constant sets it, a colour varying along v colours the curves' points (on meshes,
//!   its mean); a network it does not evaluate leaves the parameter's own value, reported.
//!   Meshes without a shader are Lambert 0.5 grey, curves the default hair colour.

use super::parse::{Atom, Node};
use super::{flag, matrix, node_label, num, num32, numbers, text, Reader, Res};
use crate::geometry::curve::CubicBasis;
use crate::geometry::subdivision::{arnold_iterations, PolygonMesh};
use crate::geometry::{StrandInfo, StrandSet, TriangleMesh};
use crate::io::arnold_graph::{self, Eval, Network, Value};
use crate::io::arnold_hair::{ArnoldShader, Hair, StandardHair};
use crate::io::arnold_surface::{Flat, Lambert, Standard, StandardSurface, Utility};
use crate::io::usd::curves::{self, CurveShape};
use crate::io::usd::values::Interpolation;
use crate::io::usd::visibility;
use crate::scene::{HairEntry, HairSource, MaterialSource, MeshEntry, MeshSource, Visibility};
use crate::shading::Material;
use glam::{Affine3A, Vec3};
use std::collections::HashMap;

/// The parameters read of each shape type (others are reported).
pub(super) const POLYMESH_READ: [&str; 17] = [
    "nsides",
    "vidxs",
    "vidxlist",
    "vlist",
    "uvlist",
    "uvidxs",
    "uvidxlist",
    "smoothing",
    "nidxs",
    "subdiv_type",
    "subdiv_iterations",
    "matrix",
    "shader",
    "visibility",
    "matte",
    "nlist",
    "shidxs",
];
/// The parameters read of `curves`.
pub(super) const CURVES_READ: [&str; 10] =
    ["num_points", "points", "radius", "basis", "mode", "matrix", "shader", "visibility", "matte", "uvs"];
/// The parameters read of `sphere`.
pub(super) const SPHERE_READ: [&str; 6] = ["center", "radius", "matrix", "shader", "visibility", "matte"];
/// The parameters read of `ginstance`.
pub(super) const GINSTANCE_READ: [&str; 5] = ["node", "matrix", "inherit_xform", "visibility", "matte"];

/// A shape's geometry and material, in its own space.
#[derive(Clone)]
pub(super) enum Shape {
    Mesh(TriangleMesh, Material),
    Hair(StrandSet, Material),
}

/// Whether `kind` is a shape type this module reads.
pub(super) fn is_shape(kind: &str) -> bool {
    matches!(kind, "polymesh" | "curves" | "sphere")
}

/// The visibility a node's `visibility` byte and `matte` give, `None` when hidden from
/// every ray.
fn node_visibility(node: &Node) -> Res<Option<Visibility>> {
    let bits = num(node, "visibility", 255.0)?;
    let line = node.param("visibility").map_or(node.line, |p| p.line);
    if !(bits.fract() == 0.0 && (0.0..=255.0).contains(&bits)) {
        return Err((line, format!("`{}` `visibility` {bits} is not a byte", node_label(node))));
    }
    Ok(visibility::from_bits(bits as u8, flag(node, "matte", false)?))
}

impl Reader<'_> {
    /// A shape node: drawn where it is unless its visibility hides it.
    pub(super) fn shape(&mut self, i: usize) -> Res<()> {
        let nodes = self.nodes;
        let Some(vis) = node_visibility(&nodes[i])? else { return Ok(()) };
        self.place(i, matrix(&nodes[i])?, vis)
    }

    /// A `ginstance`: its node's shape (or procedural) under its matrix.
    pub(super) fn ginstance(&mut self, node: &Node) -> Res<()> {
        let Some(vis) = node_visibility(node)? else { return Ok(()) };
        let Some(target) = text(node, "node") else {
            self.notes.note("ginstances without a `node`: not drawn", node);
            return Ok(());
        };
        let Some(&t) = self.by_name.get(target.as_str()) else {
            self.notes.note("ginstances of nodes the file does not hold: not drawn", node);
            return Ok(());
        };
        let mut m = matrix(node)?;
        let nodes = self.nodes;
        let inner = &nodes[t];
        if flag(node, "inherit_xform", true)? {
            m *= matrix(inner)?;
        }
        match inner.kind.as_str() {
            k if is_shape(k) => self.place(t, m, vis),
            "usd" | "procedural" => self.procedural(inner, m),
            k => {
                self.notes.note(format!("ginstances of `{k}` nodes: not drawn"), node);
                Ok(())
            }
        }
    }

    /// Draws shape node `i` placed by `m`, its geometry read once for all its placements.
    fn place(&mut self, i: usize, m: Affine3A, visibility: Visibility) -> Res<()> {
        if !self.shapes.contains_key(&i) {
            let nodes = self.nodes;
            let shape = self.read_shape(&nodes[i])?;
            self.shapes.insert(i, shape);
        }
        let contents = &mut self.out.imported.contents;
        match self.shapes[&i].clone() {
            None => {}
            Some(Shape::Mesh(mesh, material)) => contents.meshes.push(MeshEntry {
                source: MeshSource::Inline(mesh),
                material: material.into(),
                transform: m,
                visibility,
            }),
            Some(Shape::Hair(set, material)) => contents.hair.push(HairEntry {
                source: HairSource::Inline(set),
                material: MaterialSource::Inline(material),
                transform: m,
                radius_scale: 1.0,
                file_colors: true,
                lod: None,
                visibility,
            }),
        }
        Ok(())
    }

    /// The geometry and material of a shape node; `None` (reported) when it draws nothing.
    fn read_shape(&mut self, node: &Node) -> Res<Option<Shape>> {
        Ok(match node.kind.as_str() {
            "polymesh" => self.polymesh(node)?.map(|mesh| Shape::Mesh(mesh, self.surface(node))),
            "sphere" => {
                let r = num32(node, "radius", 0.5)?;
                let c = match numbers(node, "center")? {
                    Some(c) if c.len() == 3 => Vec3::new(c[0], c[1], c[2]),
                    _ => Vec3::ZERO,
                };
                let mut mesh = TriangleMesh::sphere(r.abs(), 48);
                mesh.positions.iter_mut().for_each(|p| *p += c);
                Some(Shape::Mesh(mesh, self.surface(node)))
            }
            _ => self.curves(node)?.map(|(mut set, pieces)| {
                let material = self.hair_material(node, (&mut set, pieces));
                Shape::Hair(set, material)
            }),
        })
    }

    fn polymesh(&mut self, node: &Node) -> Res<Option<TriangleMesh>> {
        let line = node.line;
        let bad = |m: String| (line, format!("polymesh `{}`: {m}", node_label(node)));
        let whole = |name: &str| -> Res<Option<Vec<u32>>> {
            let Some(v) = numbers(node, name)? else { return Ok(None) };
            v.iter()
                .map(|&x| match x.fract() == 0.0 && (0.0..4.0e9).contains(&x) {
                    true => Ok(x as u32),
                    false => Err(bad(format!("`{name}` holds {x}, not an index"))),
                })
                .collect::<Res<Vec<u32>>>()
                .map(Some)
        };
        let vlist = numbers(node, "vlist")?.unwrap_or_default();
        if vlist.len() % 3 != 0 {
            return Err(bad(format!("`vlist` has {} numbers, not points of 3", vlist.len())));
        }
        let positions: Vec<Vec3> = vlist.chunks(3).map(|c| Vec3::new(c[0], c[1], c[2])).collect();
        // Arnold 5 names its index lists `vidxs`, `uvidxs`; older files `vidxlist`, `uvidxlist`.
        let either = |new: &str, old: &str| -> Res<Option<Vec<u32>>> {
            Ok(match whole(new)? {
                Some(v) => Some(v),
                None => whole(old)?,
            })
        };
        let indices = either("vidxs", "vidxlist")?.unwrap_or_default();
        let counts = match whole("nsides")? {
            Some(n) => n,
            None => vec![3; indices.len() / 3],
        };
        let mut mesh = PolygonMesh { positions, counts, indices, ..Default::default() };
        if let Some(uv) = numbers(node, "uvlist")? {
            if uv.len() % 2 != 0 {
                return Err(bad(format!("`uvlist` has {} numbers, not pairs", uv.len())));
            }
            let uvs: Vec<[f32; 2]> = uv.chunks(2).map(|c| [c[0], c[1]]).collect();
            let ix = either("uvidxs", "uvidxlist")?.unwrap_or_else(|| mesh.indices.clone());
            if ix.len() != mesh.indices.len() {
                return Err(bad(format!(
                    "`uvidxlist` has {} indices for {} face corners",
                    ix.len(),
                    mesh.indices.len()
                )));
            }
            let corner = |k: &u32| uvs.get(*k as usize).copied();
            mesh.uvs = Some(
                ix.iter()
                    .map(corner)
                    .collect::<Option<_>>()
                    .ok_or_else(|| bad("a `uvidxlist` index is past `uvlist`".into()))?,
            );
        }
        mesh.validate().map_err(bad)?;
        if mesh.counts.is_empty() {
            self.notes.note("polymeshes without faces: not drawn", node);
            return Ok(None);
        }
        let kind = text(node, "subdiv_type").unwrap_or_else(|| "none".into());
        // `smoothing` interpolates the normals over the faces: the mesh's own vertex normals.
        let smooth = flag(node, "smoothing", false)?;
        let triangles = match kind.as_str() {
            "catclark" => {
                let asked = num(node, "subdiv_iterations", 1.0)?;
                let Some(iterations) = arnold_iterations(asked as i64).filter(|_| asked.fract() == 0.0) else {
                    return Err(bad(format!("`subdiv_iterations` {asked} is not a whole number from 0 to 255")));
                };
                let (refined, done) = self.faces.subdivide(&mesh, iterations);
                if let Some(stopped) = done.stopped() {
                    self.notes.note(stopped, node);
                }
                refined.triangulate(iterations > 0).0
            }
            "none" | "linear" => mesh.triangulate(smooth).0,
            other => {
                self.notes.note(format!("polymesh `subdiv_type` `{other}`: drawn as authored"), node);
                mesh.triangulate(smooth).0
            }
        };
        triangles.validate().map_err(bad)?;
        Ok(Some(triangles))
    }

    /// The strands of a `curves` node, and the pieces each curve segment is sampled in.
    fn curves(&mut self, node: &Node) -> Res<Option<(StrandSet, usize)>> {
        let line = node.line;
        let bad = |m: String| (line, format!("curves `{}`: {m}", node_label(node)));
        let counts: Vec<usize> = numbers(node, "num_points")?
            .unwrap_or_default()
            .iter()
            .map(|&x| match x.fract() == 0.0 && (0.0..4.0e9).contains(&x) {
                true => Ok(x as usize),
                false => Err(bad(format!("`num_points` holds {x}, not a count"))),
            })
            .collect::<Res<_>>()?;
        let p = numbers(node, "points")?.unwrap_or_default();
        if p.len() % 3 != 0 {
            return Err(bad(format!("`points` has {} numbers, not points of 3", p.len())));
        }
        let points: Vec<Vec3> = p.chunks(3).map(|c| Vec3::new(c[0], c[1], c[2])).collect();
        let total: usize = counts.iter().sum();
        if total != points.len() {
            return Err(bad(format!("`num_points` adds up to {total} but there are {} points", points.len())));
        }
        let basis = match text(node, "basis").as_deref().unwrap_or("bezier") {
            "bezier" => Some(CubicBasis::Bezier),
            "b-spline" => Some(CubicBasis::BSpline),
            "catmull-rom" => Some(CubicBasis::CatmullRom),
            "linear" => None,
            other => return Err(bad(format!("`basis` `{other}` is not bezier, b-spline, catmull-rom or linear"))),
        };
        let shape = CurveShape { basis, periodic: false, pinned: false };
        let radius = numbers(node, "radius")?.unwrap_or_else(|| vec![0.01]);
        let varying: usize = counts.iter().map(|&n| shape.ends(n)).sum();
        let interp = match radius.len() {
            1 => Interpolation::Constant,
            n if n == points.len() => Interpolation::Vertex,
            n if n == varying => Interpolation::Varying,
            n => return Err(bad(format!("{n} radii for {} points ({varying} segment ends)", points.len()))),
        };
        let widths: Vec<f32> = radius.iter().map(|r| 2.0 * r).collect();
        let (mut set, kept, skipped) = curves::strands(&shape, &points, &counts, (Some((&widths, interp)), 0.0), None)
            .map_err(|e| bad(format!("{e:#}")))?;
        // `uvs`: one texture coordinate per curve (Arnold's, from the surface it grows on),
        // which textures on the curves read.
        if let Some(uv) = numbers(node, "uvs")? {
            match uv.len() == 2 * counts.len() {
                true => {
                    let root_uv = kept.iter().map(|&(i, _, _)| [uv[2 * i], uv[2 * i + 1]]).collect();
                    set.strand_info = Some(StrandInfo { root_uv, clump: Vec::new() });
                }
                false => self.notes.note("curves `uvs` not one per curve: not read", node),
            }
        }
        if skipped > 0 {
            self.notes.note("curves with too few points for their basis: skipped", node);
        }
        if !set.points.iter().flatten().all(|c| c.is_finite()) {
            return Err(bad("the curves' points are beyond single precision".into()));
        }
        Ok((set.strand_count() > 0).then_some((set, shape.pieces())))
    }

    /// The shader node a shape names, if the file holds it.
    fn shader_of(&mut self, node: &Node) -> Option<&Node> {
        let name = node.param("shader")?.values.first().and_then(Atom::text)?.to_string();
        match self.by_name.get(name.as_str()) {
            Some(&s) => Some(&self.nodes[s]),
            None => {
                self.notes.note("shaders the file does not hold: drawn with the default", node);
                None
            }
        }
    }

    /// A surface's material: its Arnold shader's, else Lambert 0.5 grey.
    pub(super) fn surface(&mut self, node: &Node) -> Material {
        let default = Material::Diffuse { color: Vec3::splat(0.5) };
        let Some(s) = self.shader_of(node) else { return default };
        let s = s.clone();
        match s.kind.as_str() {
            "standard_surface" => self.arnold_material::<StandardSurface>(&s, None),
            "lambert" => self.arnold_material::<Lambert>(&s, None),
            "flat" => self.arnold_material::<Flat>(&s, None),
            "standard" => self.arnold_material::<Standard>(&s, None),
            "utility" => self.arnold_material::<Utility>(&s, None),
            other => {
                self.notes.note(format!("`{other}` surface shaders: drawn Lambert 0.5 grey"), &s);
                default
            }
        }
    }

    /// A curve's material: its Arnold shader's (a surface shader shades the curves as the
    /// tubes they are), else the default hair colour; colours its networks give along the
    /// strands go to the set's colours (its segments sampled in `pieces` pieces each).
    fn hair_material(&mut self, node: &Node, set: (&mut StrandSet, usize)) -> Material {
        let default = curves::tube_material(None);
        let Some(s) = self.shader_of(node) else { return default };
        let s = s.clone();
        let set = Some(set);
        match s.kind.as_str() {
            "standard_hair" => self.arnold_material::<StandardHair>(&s, set),
            "hair" => self.arnold_material::<Hair>(&s, set),
            "standard_surface" => self.arnold_material::<StandardSurface>(&s, set),
            "lambert" => self.arnold_material::<Lambert>(&s, set),
            "flat" => self.arnold_material::<Flat>(&s, set),
            "standard" => self.arnold_material::<Standard>(&s, set),
            "utility" => self.arnold_material::<Utility>(&s, set),
            other => {
                self.notes.note(format!("`{other}` shaders on curves: drawn with the default hair colour"), &s);
                default
            }
        }
    }

    /// The material of Arnold shader `s`, its parameters read by `S`'s names and their
    /// links evaluated ([`arnold_graph::shade`]); on curves (`strands`, their set) the
    /// colours a network gives along them are baked into the strands. What is not
    /// evaluated, and what the material leaves out, is reported.
    fn arnold_material<S: ArnoldShader>(&mut self, s: &Node, strands: Option<(&mut StrandSet, usize)>) -> Material {
        let net = AssNetwork { nodes: self.nodes, by_name: &self.by_name };
        let index = self.by_name.get(s.name.as_str()).copied().unwrap_or_default();
        let mut eval = Eval::new(&net);
        let shaded = arnold_graph::shade::<S, _>(&mut eval, &index, &node_label(s), strands.is_some());
        for (what, n) in eval.unread {
            self.notes.note(what, &self.nodes[n]);
        }
        if let (Some(p), Some((set, pieces))) = (&shaded.along, strands) {
            set.colors = Some(arnold_graph::bake(p, Vec3::ONE, set, pieces));
        }
        if let Some(left_out) = shaded.warning {
            let what = left_out.strip_prefix(&format!("{}: ", node_label(s))).unwrap_or(&left_out).to_string();
            self.notes.note(what, s);
        }
        shaded.material
    }
}

/// The nodes of an `.ass` file as a shader network: a parameter whose value is a word
/// naming a node (or `node.r`, one channel of it) links to that node.
struct AssNetwork<'a> {
    nodes: &'a [Node],
    by_name: &'a HashMap<&'a str, usize>,
}

impl Network for AssNetwork<'_> {
    type Node = usize;
    fn kind(&self, node: &usize) -> String {
        self.nodes[*node].kind.clone()
    }
    fn value(&self, node: &usize, name: &str) -> Option<Value<usize>> {
        let p = self.nodes[*node].param(name)?;
        match p.values.first() {
            Some(Atom::Word(w) | Atom::Str(w)) => Some(match self.by_name.get(w.as_str()) {
                Some(&n) => Value::Link(n, None),
                None => {
                    let channel = w.rsplit_once('.').and_then(|(n, c)| {
                        let k = ["r", "g", "b", "a"].iter().position(|x| *x == c)?;
                        Some((*self.by_name.get(n)?, k))
                    });
                    match channel {
                        Some((n, k)) => Value::Link(n, Some(k)),
                        None => Value::Text(w.clone()),
                    }
                }
            }),
            _ => p
                .values
                .iter()
                .map(|a| if let Atom::Num(x) = a { Some(*x as f32) } else { None })
                .collect::<Option<Vec<f32>>>()
                .map(Value::Numbers),
        }
    }
}
