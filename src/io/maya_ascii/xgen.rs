//! XGen's interactive groom splines, as Maya stores them inside the `.ma`: the spline data
//! of an `xgmSplineBase` node (`.csd`, `-type "xgmSplineData"`).
//!
//! Autodesk does not document the layout; it is read as Maya 2017 to 2022 write it (the
//! header names every part, so the reading checks itself):
//!
//! - The value is a list of quoted words: blocks of a tag (`"Header"` or `"Group"`), a
//!   character count and a line count, then that many strings whose concatenation is the
//!   block's text, of that many characters.
//! - The header is JSON: `Header.GroupCount` groups follow, base64-encoded
//!   (`GroupBase64`) and zlib-deflated (`GroupDeflate`); each `Items` entry (one per bound
//!   mesh) names its arrays by index: `PrimitiveInfos`, `Positions`, `WIDTH_CV`, ...
//! - A group, decoded: four little-endian 64-bit words (0, the number of arrays, the bytes
//!   of the arrays' data, 0), then (inflated) the arrays one after another, each a 64-bit
//!   type tag, a 64-bit byte length and its bytes. Arrays are numbered across the groups in
//!   order.
//! - `PrimitiveInfos` holds 12 bytes per spline: its first control vertex (32 bits) and its
//!   number of control vertices (64 bits); `Positions` three 32-bit floats per control
//!   vertex, in world space; `WIDTH_CV` one float per control vertex, the width the Width
//!   brush paints (a factor on the description's width scale).

use super::parse::Value;
use super::{attr, build_ramp, ramp_keys, scalar, xgen_collection, Reader, Res};
use crate::fur::{AttractorModel, Attractors};
use crate::fur::{FurDescription, Placement, Scalar};
use crate::geometry::StrandSet;
use crate::hair_system::Ramp;
use crate::scene::{FurEntry, HairSource};
use glam::Vec3;
use std::collections::BTreeSet;
use std::io::Read;

/// Most bytes one group may inflate to.
const MAX_GROUP_BYTES: u64 = 1 << 30;
/// Most control vertices of one spline.
const MAX_CVS: u64 = 1 << 16;
/// Most strands one XGen collection description grows on one mesh (2^21): XGen's
/// densities are per unit area, so a large mesh in small units could otherwise ask for
/// more than memory holds.
const MAX_COLLECTION_STRANDS: u32 = 1 << 21;
/// Segments of an XGen collection strand whose width varies along it or that bends: XGen
/// draws its strands as smooth curves, which 16 straight segments follow closely.
const SHAPED_SEGMENTS: u32 = 16;

/// The splines of one `xgmSplineData` value: each spline's control vertices and the width
/// factor at each.
#[derive(Debug, Default)]
pub struct Splines {
    /// Control vertices of each spline, root first.
    pub strands: Vec<Vec<Vec3>>,
    /// `WIDTH_CV` at each control vertex (1 when the data has none).
    pub widths: Vec<Vec<f32>>,
    /// The bound mesh each spline grows on: the index `k` of its item's name
    /// `.boundMesh[k]`, the base's `.bm[k]` input.
    pub bound: Vec<Option<usize>>,
}

/// Reads the quoted words of an `xgmSplineData` value.
pub fn spline_data(words: &[String]) -> Result<Splines, String> {
    let blocks = blocks(words)?;
    let Some((tag, header)) = blocks.first() else { return Err("the spline data is empty".into()) };
    if tag != "Header" {
        return Err(format!("the spline data starts with `{tag}`, not its header"));
    }
    let header: serde_json::Value =
        serde_json::from_str(header).map_err(|e| format!("the spline data's header is not JSON: {e}"))?;
    let flag = |k: &str| header["Header"][k].as_bool().unwrap_or(false);
    let (base64, deflate) = (flag("GroupBase64"), flag("GroupDeflate"));
    if !base64 {
        return Err("spline data groups that are not base64 are not read".into());
    }
    let mut arrays: Vec<Vec<u8>> = Vec::new();
    for (tag, text) in &blocks[1..] {
        if tag != "Group" {
            return Err(format!("unexpected block `{tag}` in the spline data"));
        }
        group(&decode_base64(text)?, deflate, &mut arrays)?;
    }
    let mut out = Splines::default();
    let items = header["Items"].as_array().ok_or("the spline data's header lists no items")?;
    for item in items {
        let array = |key: &str| -> Result<Option<&[u8]>, String> {
            match item.get(key) {
                None => Ok(None),
                Some(i) => {
                    let i = i.as_u64().ok_or(format!("`{key}` is not an array index"))?;
                    let a = arrays.get(i as usize).ok_or(format!("`{key}` names array {i} of {}", arrays.len()))?;
                    Ok(Some(a.as_slice()))
                }
            }
        };
        let bound = item["Name"].as_str().and_then(super::plug_index);
        let infos = array("PrimitiveInfos")?.ok_or("an item has no `PrimitiveInfos`")?;
        let positions = floats(array("Positions")?.ok_or("an item has no `Positions`")?, "Positions")?;
        let widths = array("WIDTH_CV")?.map(|a| floats(a, "WIDTH_CV")).transpose()?;
        if !infos.len().is_multiple_of(12) || !positions.len().is_multiple_of(3) {
            return Err(format!(
                "{} bytes of `PrimitiveInfos` and {} floats of `Positions` are not whole records",
                infos.len(),
                positions.len()
            ));
        }
        let cvs = (positions.len() / 3) as u64;
        if widths.as_ref().is_some_and(|w| w.len() as u64 != cvs) {
            return Err(format!("`WIDTH_CV` has {} values for {cvs} control vertices", widths.map_or(0, |w| w.len())));
        }
        for (k, info) in infos.chunks_exact(12).enumerate() {
            let first = u64::from(u32::from_le_bytes(info[0..4].try_into().expect("4 bytes")));
            let count = u64::from_le_bytes(info[4..12].try_into().expect("8 bytes"));
            if !(2..=MAX_CVS).contains(&count) || first + count > cvs {
                return Err(format!("spline {k} has control vertices {first} + {count} of {cvs}"));
            }
            let range = first as usize..(first + count) as usize;
            let strand: Vec<Vec3> = range.clone().map(|i| Vec3::from_slice(&positions[3 * i..3 * i + 3])).collect();
            if strand.iter().any(|p| !p.is_finite()) {
                return Err(format!("spline {k} has a control vertex that is not finite"));
            }
            out.strands.push(strand);
            out.bound.push(bound);
            out.widths.push(match &widths {
                Some(w) => w[range].iter().map(|x| if x.is_finite() { x.max(0.0) } else { 1.0 }).collect(),
                None => vec![1.0; count as usize],
            });
        }
    }
    Ok(out)
}

impl Reader<'_> {
    /// The interactive groom of each visible `xgmSplineDescription` (the splines of the
    /// `xgmSplineBase` upstream of it, drawn through their control vertices, as wide as its
    /// width scale `.w` × `WIDTH_CV` × its width ramp `.wdr`), and each XGen collection
    /// (`xgmPalette`) approximated from its collection file ([`Reader::collection`]).
    pub(super) fn xgen(&mut self) -> Res<()> {
        let g = self.g;
        let mut set = StrandSet::new();
        let mut no_width = Vec::new();
        for d in self.of_kind("xgmSplineDescription").collect::<Vec<_>>() {
            if self.hidden(d)? {
                continue;
            }
            let name = &g.nodes[d].name;
            // Up the spline data (`.isd` from `.osd`), through the modifier stack, to the base.
            let (mut cur, mut base, mut modifiers) = (d, None, BTreeSet::new());
            for _ in 0..g.nodes.len() {
                let Some(&src) = self.inputs(cur, &["isd", "inSplineData"]).first() else { break };
                if self.kind(src) == "xgmSplineBase" {
                    base = Some(src);
                    break;
                }
                modifiers.insert(self.kind(src).to_string());
                cur = src;
            }
            let data = base.and_then(|b| attr(g, b, &["csd"]).map(|a| (b, a)));
            let Some((base, a)) = data else {
                self.out
                    .warnings
                    .push(format!("XGen description {name}: no `xgmSplineBase` with spline data feeds it: no strands"));
                continue;
            };
            let bad = |e: String| (a.line, format!("xgmSplineBase {}: {e}", g.nodes[base].name));
            let Value::Strings(words) = &a.value else {
                return Err(bad("`.csd` must have -type \"xgmSplineData\"".into()));
            };
            let splines = spline_data(words).map_err(bad)?;
            if !modifiers.is_empty() {
                let list: Vec<&str> = modifiers.iter().map(String::as_str).collect();
                self.out.warnings.push(format!(
                    "XGen description {name}: drawn as its base's splines, before its modifiers ({}), \
                     which tress does not evaluate",
                    list.join(", ")
                ));
            }
            let scale = scalar(g, d, &["w", "width"], f64::NAN)? as f32;
            if !(scale.is_nan() || scale.is_finite() && scale >= 0.0) {
                return Err((g.nodes[d].line, format!("XGen description {name}: width {scale} is not a width")));
            }
            let ramp = match ramp_keys(g, d, "wdr", "widthRamp", 1)? {
                Some(keys) => build_ramp(g, d, "widthRamp", keys, |v| v[0] as f32)?,
                None => Ramp::constant(1.0),
            };
            let first = set.strand_count();
            let moves = self.bound_mesh_moves(base)?;
            for ((strand, widths), bound) in splines.strands.iter().zip(&splines.widths).zip(&splines.bound) {
                let last = (strand.len() - 1) as f32;
                let m = bound.and_then(|k| moves.get(&k)).copied().unwrap_or(glam::Affine3A::IDENTITY);
                set.push_strand(strand.iter().zip(widths).enumerate().map(|(k, (&p, &w))| {
                    let p = m.transform_point3(p);
                    (p, 0.5 * w * ramp.eval(k as f32 / last).max(0.0) * if scale.is_nan() { 1.0 } else { scale })
                }));
            }
            if scale.is_nan() {
                no_width.push((first, set.strand_count(), name.clone()));
            }
        }
        if !no_width.is_empty() {
            // Maya's reference does not give the width scale's default: one relative to the scene.
            let mut b = self.out.contents.bounds();
            for p in &set.points {
                b = b.grow(glam::Vec3A::new(p[0], p[1], p[2]));
            }
            let w = super::relative_width(&b);
            for &(from, to, _) in &no_width {
                let (a, b) = (set.offsets[from] as usize, set.offsets[to] as usize);
                set.points[a..b].iter_mut().for_each(|p| p[3] *= w);
            }
            let names: Vec<&str> = no_width.iter().map(|u| u.2.as_str()).collect();
            self.out.warnings.push(format!(
                "XGen description(s) {} set no width scale (`.w`): drawn {w:.3e} wide ({} of the scene's size)",
                names.join(", "),
                super::RELATIVE_WIDTH
            ));
        }
        self.push_curves(set);
        for p in self.of_kind("xgmPalette").collect::<Vec<_>>() {
            self.collection(p);
        }
        Ok(())
    }

    /// How each mesh bound to an `xgmSplineBase` (`.bm[k]`, from the mesh's `.worldMesh`)
    /// moved between the file's saved time, when XGen stored the splines in world space,
    /// and the frame read: its world matrix at the frame times the inverse of the one at the
    /// saved time, by `k`. Empty when the frame is the saved time.
    fn bound_mesh_moves(&mut self, base: usize) -> Res<std::collections::HashMap<usize, glam::Affine3A>> {
        let mut out = std::collections::HashMap::new();
        let Some(saved) = self.saved_pose else { return Ok(out) };
        let bound: Vec<(usize, usize)> = self
            .g
            .inputs_of(base)
            .filter(|c| matches!(super::plug_base(&c.dst_attr), "bm" | "boundMesh"))
            .filter_map(|c| Some((super::plug_index(&c.dst_attr)?, c.src)))
            .collect();
        for (k, mesh) in bound {
            let then = Reader::new(saved).world(mesh)?;
            let now = self.world(mesh)?;
            if then.matrix3.determinant().abs() > 1e-12 {
                out.insert(k, super::to_affine(&(now * then.inverse())));
            }
        }
        Ok(out)
    }

    /// The guides of the patch under transform `pt` (`xgmSplineGuide`s under transforms of
    /// its own, their world-space control points in the `.cgm` point array of the
    /// `xgmMakeGuide` feeding each), `None` when it has none; guides whose points cannot be
    /// read are noted and left out. XGen ties guides to their patch, so each mesh follows
    /// its own.
    fn patch_guides(&self, pt: usize, notes: &mut Vec<String>) -> Option<StrandSet> {
        let g = self.g;
        let mut set = StrandSet::new();
        let mut bad = Vec::new();
        for guide in self.of_kind("xgmSplineGuide") {
            if g.parent(guide).and_then(|gt| g.parent(gt)) != Some(pt) {
                continue;
            }
            let points =
                self.inputs(guide, &["is"]).into_iter().find(|&m| self.kind(m) == "xgmMakeGuide").and_then(|m| {
                    match attr(g, m, &["cgm"]).map(|a| &a.value) {
                        Some(Value::Numbers(v)) => Some(v.clone()),
                        _ => None,
                    }
                });
            // `COUNT x y z w ...`.
            let cvs = points.filter(|v| {
                v.first().is_some_and(|&n| n >= 2.0 && n.fract() == 0.0 && v.len() == 1 + 4 * n as usize)
                    && v.iter().all(|x| x.is_finite())
            });
            match cvs {
                Some(v) => {
                    set.push_strand(v[1..].chunks(4).map(|c| (Vec3::new(c[0] as f32, c[1] as f32, c[2] as f32), 0.01)))
                }
                None => bad.push(g.nodes[guide].name.clone()),
            }
        }
        if !bad.is_empty() {
            notes.push(format!("guide(s) without readable control points left out: {}", bad.join(", ")));
        }
        (set.strand_count() > 0).then_some(set)
    }

    /// An XGen collection (`xgmPalette`): each of its descriptions that its collection file
    /// (`.xfn`, beside the scene) describes grows as Maya Fur on the meshes its
    /// `xgmSubdPatch`es are bound to ([`xgen_collection`]); a missing or unreadable file
    /// leaves the collection out, said.
    fn collection(&mut self, p: usize) {
        let g = self.g;
        let palette = &g.nodes[p].name;
        let descriptions: Vec<usize> =
            self.of_kind("xgmDescription").filter(|&d| g.parent(d).and_then(|t| g.parent(t)) == Some(p)).collect();
        let names: Vec<&str> = descriptions.iter().map(|&d| g.nodes[d].name.as_str()).collect();
        let names = if names.is_empty() { "none".to_string() } else { names.join(", ") };
        let file = match attr(g, p, &["xfn", "xgFileName"]).map(|a| &a.value) {
            Some(Value::Strings(s)) if s.first().is_some_and(|f| !f.is_empty()) => Some(s[0].clone()),
            _ => None,
        };
        let path = file.as_ref().and_then(|f| self.dir.as_ref().map(|d| d.join(f)));
        let text = path.as_ref().and_then(|p| std::fs::read(p).ok());
        let (Some(path), Some(text)) = (path, text) else {
            let file = file.map_or("its collection file".to_string(), |f| format!("`{f}`"));
            self.out.warnings.push(format!(
                "XGen collection {palette} (descriptions: {names}): XGen generates its strands at render time from \
                 {file} and the collection's folder beside the scene; {file} was not found there: no strands"
            ));
            return;
        };
        let parsed = match xgen_collection::parse_collection(&String::from_utf8_lossy(&text), &path) {
            Ok(d) => d,
            Err(e) => {
                self.out.warnings.push(format!("XGen collection {palette}: {e}: no strands"));
                return;
            }
        };
        for d in descriptions {
            let Some(t) = g.parent(d) else { continue };
            let name = &g.nodes[t].name;
            let Some(cd) = parsed.iter().find(|c| &c.name == name || c.name == g.nodes[d].name) else {
                self.out.warnings.push(format!(
                    "XGen description {name}: `{}` has no description of that name: no strands",
                    path.display()
                ));
                continue;
            };
            if cd.primitive.as_deref() != Some("SplinePrimitive") {
                let what = cd.primitive.as_deref().unwrap_or("no primitive");
                self.out.warnings.push(format!(
                    "XGen description {name}: `{}` gives it {what}; tress grows only spline primitives: no strands",
                    path.display()
                ));
                continue;
            }
            let mut notes = Vec::new();
            // The description's patches (`xgmSubdPatch` under the description's transform,
            // through a transform of its own), the meshes bound to them and the faces
            // that grow (the file's `Patch` record of the mesh's transform).
            let mut meshes: Vec<GrownMesh> = Vec::new();
            for patch in self.of_kind("xgmSubdPatch") {
                let Some(pt) = g.parent(patch).filter(|&pt| g.parent(pt) == Some(t)) else { continue };
                let guides = self.patch_guides(pt, &mut notes);
                for m in self.inputs(patch, &["geo", "geometry"]) {
                    let Some((i, mesh, faces)) = self.meshes.get(&m) else { continue };
                    if meshes.iter().any(|&(j, ..)| j == *i) {
                        continue;
                    }
                    let mesh_name = g.parent(m).map_or(g.nodes[m].name.as_str(), |p| g.nodes[p].name.as_str());
                    let listed = cd
                        .patches
                        .iter()
                        .find(|p| p.name == mesh_name || p.name == g.nodes[m].name)
                        .and_then(|p| p.faces.as_deref());
                    let grows_on = listed.and_then(|ids| grown_faces(ids, faces, mesh_name, &mut notes));
                    let area = (0..mesh.indices.len())
                        .filter(|&k| grows_on.as_ref().is_none_or(|g| g[k]))
                        .map(|k| f64::from(mesh.area(k as u32)))
                        .sum::<f64>();
                    let guides = guides.clone().map(|set| {
                        let a = guide_attraction(&set, mesh);
                        (set, a)
                    });
                    meshes.push((*i, area, grows_on, guides));
                }
            }
            if meshes.is_empty() {
                self.out.warnings.push(format!("XGen description {name}: bound to no drawn mesh: no strands"));
                continue;
            }
            let width_profile = cd.width_profile();
            let guided: Vec<u32> =
                meshes.iter().filter_map(|m| m.3.as_ref().map(|g| g.0.strand_count() as u32)).collect();
            notes.push(match guided.iter().sum::<u32>() {
                0 => "along the normal (no guides)".to_string(),
                n => format!(
                    "{n} guide(s) on {} of its {} patch(es) shape their strands (each the mean of the up to 3 nearest \
                     guides' shapes, weighted 1 − d/radius, at their lengths × length)",
                    guided.len(),
                    meshes.len()
                ),
            });
            if !cd.maps.is_empty() {
                notes.push(format!("maps not read ({})", cd.maps.join(", ")));
            }
            if !cd.fallbacks.is_empty() {
                notes.push(format!(
                    "expressions or maps not evaluated, a new description's value used instead: {}",
                    cd.fallbacks.join(", ")
                ));
            }
            for (k, (mesh, area, grows_on, guides)) in meshes.into_iter().enumerate() {
                let wanted = cd.density * area;
                let count = wanted.round().min(MAX_COLLECTION_STRANDS as f64) as u32;
                if wanted > MAX_COLLECTION_STRANDS as f64 {
                    notes.push(format!("{wanted:.0} strands cut to {MAX_COLLECTION_STRANDS}"));
                }
                let mut desc = FurDescription { density: count, ..FurDescription::default() };
                // Under guides, XGen's Length scales the guides' lengths.
                desc[Scalar::Length].value = cd.length as f32;
                let length = cd.length * guides.as_ref().map_or(1.0, |g| mean_length(&g.0));
                let (applied, not) = cd.apply_fx(&mut desc, area, length, guides.is_some());
                // (The modules are the same on every mesh: said once.)
                if k == 0 && !applied.is_empty() {
                    notes.push(format!("FX modules applied as Maya Fur: {}", applied.join(", ")));
                }
                if k == 0 && !not.is_empty() {
                    notes.push(format!("FX modules not applied: {}", not.join(", ")));
                }
                // One straight segment serves a plain strand; a width profile, guides or FX
                // modules need points along the strand.
                let shaped = width_profile.is_some() || guides.is_some() || !applied.is_empty();
                desc.segments = if shaped { SHAPED_SEGMENTS } else { 1 };
                desc[Scalar::BaseWidth].value = cd.width as f32;
                desc[Scalar::TipWidth].value = cd.width as f32;
                // Maya Fur's curl 0.5 is straight (its node default 0 curls).
                desc[Scalar::BaseCurl].value = 0.5;
                desc[Scalar::TipCurl].value = 0.5;
                self.out.contents.fur.push(FurEntry {
                    mesh,
                    description: desc,
                    placement: Placement::Area,
                    seed: 0,
                    guides: guides.map(|(set, a)| (HairSource::Inline(set), a)),
                    lod: None,
                    grows_on,
                    width_profile: width_profile.clone(),
                    visibility: Default::default(),
                });
            }
            self.out.warnings.push(format!(
                "XGen description {name}: approximated as Maya Fur from `{}` (density {} per unit area, length {}, \
                 width {}, taper {} from {}{}): {}",
                path.display(),
                cd.density,
                cd.length,
                cd.width,
                cd.taper,
                cd.taper_start,
                if cd.width_ramp.is_some() { ", width ramp" } else { "" },
                notes.join("; ")
            ));
        }
    }
}

/// A mesh an XGen description grows on: its index in the scene's meshes, the area that
/// grows, which triangles grow (all when `None`), and its patch's guides with how the
/// strands follow them.
type GrownMesh = (usize, f64, Option<Vec<bool>>, Option<(StrandSet, Attractors)>);

/// How an XGen collection's strands follow their patch's guides, through Maya Fur's
/// attraction: each strand becomes the weighted mean of the shapes of the (up to) three
/// guides nearest its root, weighted `1 − d / radius`, each at its own length times the
/// description's length ([`AttractorModel::Interpolate`]), wholly (an influence so large
/// the pull is always complete). The radius is twice the farthest any vertex of `mesh` lies
/// from its nearest guide root, so every root has a guide.
fn guide_attraction(guides: &StrandSet, mesh: &crate::geometry::TriangleMesh) -> Attractors {
    let roots: Vec<Vec3> = guides.offsets[..guides.offsets.len() - 1].iter().map(|&o| guides.position(o)).collect();
    let farthest = mesh
        .positions
        .iter()
        .map(|p| roots.iter().map(|r| (*r - *p).length()).fold(f32::INFINITY, f32::min))
        .fold(0.0f32, f32::max);
    Attractors {
        model: AttractorModel::Interpolate,
        curves_per_fur: 3,
        global_scale: 1.0,
        radius: (2.0 * farthest).max(1e-6),
        power: 0.0,
        influence: 1e9,
        threshold_length: 0.0,
    }
}

/// The mean length of the strands of `set` (polylines through their points).
fn mean_length(set: &StrandSet) -> f64 {
    let total: f64 = (0..set.strand_count())
        .map(|k| {
            let (a, b) = (set.offsets[k], set.offsets[k + 1]);
            (a + 1..b).map(|i| f64::from((set.position(i) - set.position(i - 1)).length())).sum::<f64>()
        })
        .sum();
    total / set.strand_count().max(1) as f64
}

/// Which triangles of a mesh grow strands, from a patch's face list `ids` (Ptex face ids,
/// [`super::Faces`]): `None` when every face is listed. A triangle grows when any Ptex face
/// of its polygon is listed. A mesh built by a primitive node, whose faces tress does not
/// number as Maya does, grows whole when the list leaves faces out, noted; ids past the
/// mesh's faces are noted too.
fn grown_faces(ids: &[u32], faces: &super::Faces, mesh: &str, notes: &mut Vec<String>) -> Option<Vec<bool>> {
    let count = match faces {
        super::Faces::Of(of) => of.iter().map(|f| f[0] + f[1]).max().unwrap_or(0),
        super::Faces::Count(c) => *c,
    };
    let mut listed = vec![false; count as usize];
    let mut beyond = 0;
    for &id in ids {
        match listed.get_mut(id as usize) {
            Some(l) => *l = true,
            None => beyond += 1,
        }
    }
    if beyond > 0 {
        notes.push(format!("{beyond} face id(s) of {mesh}'s face list past its {count} faces ignored"));
    }
    if listed.iter().all(|&l| l) {
        return None;
    }
    match faces {
        super::Faces::Of(of) => {
            Some(of.iter().map(|f| listed[f[0] as usize..(f[0] + f[1]) as usize].iter().any(|&l| l)).collect())
        }
        super::Faces::Count(_) => {
            let n = listed.iter().filter(|&&l| l).count();
            notes.push(format!(
                "{mesh} grown whole: its face list names {n} of its {count} faces, and it is built by history, \
                 whose faces tress does not number as Maya does"
            ));
            None
        }
    }
}

/// The blocks of the value: tag and text.
fn blocks(words: &[String]) -> Result<Vec<(String, String)>, String> {
    let mut out = Vec::new();
    let mut i = 0;
    while i < words.len() {
        let tag = &words[i];
        let count = |j: usize, what: &str| -> Result<usize, String> {
            let w = words.get(j).ok_or(format!("the `{tag}` block ends before its {what}"))?;
            w.parse::<usize>().map_err(|_| format!("the `{tag}` block's {what} `{w}` is not a count"))
        };
        let (chars, lines) = (count(i + 1, "size")?, count(i + 2, "line count")?);
        let body = words
            .get(i + 3..(i + 3).saturating_add(lines))
            .ok_or(format!("the `{tag}` block promises {lines} lines, the value has fewer"))?;
        let text: String = body.concat();
        if text.len() != chars {
            return Err(format!("the `{tag}` block has {} characters where it promises {chars}", text.len()));
        }
        out.push((tag.clone(), text));
        i += 3 + lines;
    }
    Ok(out)
}

/// Appends the arrays of one decoded group.
fn group(bytes: &[u8], deflate: bool, arrays: &mut Vec<Vec<u8>>) -> Result<(), String> {
    let word = |i: usize| u64::from_le_bytes(bytes[8 * i..8 * i + 8].try_into().expect("8 bytes"));
    if bytes.len() < 32 {
        return Err("a spline data group is shorter than its header".into());
    }
    let (count, size) = (word(1), word(2));
    // The arrays' data, and 16 bytes of tag and length before each.
    let total = count.checked_mul(16).and_then(|h| h.checked_add(size)).filter(|&t| t <= MAX_GROUP_BYTES);
    let Some(total) = total else {
        return Err(format!("a spline data group of {count} arrays and {size} bytes is too large"));
    };
    let body = &bytes[32..];
    let data = if deflate {
        let mut out = Vec::new();
        flate2::read::ZlibDecoder::new(body)
            .take(total + 1)
            .read_to_end(&mut out)
            .map_err(|e| format!("a spline data group does not inflate: {e}"))?;
        out
    } else {
        body.to_vec()
    };
    if data.len() as u64 != total {
        return Err(format!("a spline data group holds {} bytes where its header promises {total}", data.len()));
    }
    let mut at = 0;
    for _ in 0..count {
        let len = data
            .get(at + 8..at + 16)
            .map(|b| u64::from_le_bytes(b.try_into().expect("8 bytes")) as usize)
            .ok_or("a spline data array runs past its group")?;
        let array =
            data.get(at + 16..(at + 16).saturating_add(len)).ok_or("a spline data array runs past its group")?;
        arrays.push(array.to_vec());
        at += 16 + len;
    }
    Ok(())
}

/// Little-endian 32-bit floats.
fn floats(bytes: &[u8], what: &str) -> Result<Vec<f32>, String> {
    if !bytes.len().is_multiple_of(4) {
        return Err(format!("`{what}` is {} bytes, not whole floats", bytes.len()));
    }
    Ok(bytes.chunks_exact(4).map(|b| f32::from_le_bytes(b.try_into().expect("4 bytes"))).collect())
}

/// Decodes a group's base64 text (RFC 4648, standard alphabet), with or without its `=`
/// padding.
fn decode_base64(text: &str) -> Result<Vec<u8>, String> {
    crate::io::decode_base64(text).map_err(|e| format!("a group is not base64: {e}"))
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;
    use std::io::Write;

    fn encode_base64(bytes: &[u8]) -> String {
        use base64::Engine;
        base64::engine::general_purpose::STANDARD.encode(bytes)
    }

    /// An `xgmSplineData` value in the layout Maya writes, split into lines of `width`
    /// characters: one item whose arrays are `PrimitiveInfos`, `Positions` and `WIDTH_CV`.
    pub(crate) fn value(strands: &[&[[f32; 3]]], widths: Option<&[f32]>, width: usize) -> Vec<String> {
        let (mut infos, mut positions) = (Vec::new(), Vec::new());
        let mut first = 0u32;
        for s in strands {
            infos.extend_from_slice(&first.to_le_bytes());
            infos.extend_from_slice(&(s.len() as u64).to_le_bytes());
            first += s.len() as u32;
            positions.extend(s.iter().flatten().flat_map(|x| x.to_le_bytes()));
        }
        let mut arrays = vec![infos, positions];
        let mut header = r#"{"Header":{"Version":1,"Type":"XgSplineData","GroupVersion":1,"GroupCount":1,"GroupBase64":true,"GroupDeflate":true},"Items":[{"Name":".boundMesh[0]","PrimitiveInfos":0,"Positions":1"#.to_string();
        if let Some(w) = widths {
            arrays.push(w.iter().flat_map(|x| x.to_le_bytes()).collect());
            header.push_str(r#","WIDTH_CV":2"#);
        }
        header.push_str("}]}");
        let mut data = Vec::new();
        for (k, a) in arrays.iter().enumerate() {
            data.extend_from_slice(&(0x43f6_0844u64 + k as u64).to_le_bytes());
            data.extend_from_slice(&(a.len() as u64).to_le_bytes());
            data.extend_from_slice(a);
        }
        let size: usize = arrays.iter().map(Vec::len).sum();
        let mut group =
            [0u64, arrays.len() as u64, size as u64, 0].iter().flat_map(|w| w.to_le_bytes()).collect::<Vec<_>>();
        let mut z = flate2::write::ZlibEncoder::new(Vec::new(), flate2::Compression::best());
        z.write_all(&data).unwrap();
        group.extend(z.finish().unwrap());
        let mut out = Vec::new();
        for (tag, text) in [("Header", header), ("Group", encode_base64(&group))] {
            let lines: Vec<String> =
                text.as_bytes().chunks(width).map(|c| String::from_utf8(c.to_vec()).unwrap()).collect();
            out.extend([tag.to_string(), text.len().to_string(), lines.len().to_string()]);
            out.extend(lines);
        }
        out
    }

    #[test]
    fn splines_read_back_with_their_widths() {
        let a: &[[f32; 3]] = &[[0.0, 0.0, 0.0], [0.0, 0.5, 0.0], [0.0, 1.0, 0.1]];
        let b: &[[f32; 3]] = &[[1.0, 0.0, 0.0], [1.0, 2.0, 0.0]];
        let s = spline_data(&value(&[a, b], Some(&[1.0, 0.5, 0.25, 2.0, 1.0]), 76)).unwrap();
        assert_eq!(s.strands.len(), 2);
        assert_eq!(s.strands[0][2], Vec3::new(0.0, 1.0, 0.1));
        assert_eq!(s.strands[1], vec![Vec3::X, Vec3::new(1.0, 2.0, 0.0)]);
        assert_eq!(s.widths, vec![vec![1.0, 0.5, 0.25], vec![2.0, 1.0]]);
        // Without per-CV widths, every factor is 1.
        let s = spline_data(&value(&[b], None, 5)).unwrap();
        assert_eq!(s.widths, vec![vec![1.0, 1.0]]);
    }

    #[test]
    fn damaged_spline_data_is_an_error_not_a_panic() {
        let a: &[[f32; 3]] = &[[0.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
        let good = value(&[a], Some(&[1.0, 1.0]), 60);
        // Every word changed or dropped in turn, and every prefix.
        for i in 0..good.len() {
            let mut v = good.clone();
            v[i] = "9999".into();
            let _ = spline_data(&v);
            v.remove(i);
            let _ = spline_data(&v);
            let _ = spline_data(&good[..i]);
        }
        let mut v = good.clone();
        v[1] = "5".into();
        assert!(spline_data(&v).unwrap_err().contains("promises 5"));
        // A group header promising more than any group may hold.
        let huge =
            encode_base64(&[0u64, u64::MAX / 8, 1 << 40, 0].iter().flat_map(|w| w.to_le_bytes()).collect::<Vec<_>>());
        let mut v = good[..good.iter().position(|w| w == "Group").unwrap()].to_vec();
        v.extend(["Group".into(), huge.len().to_string(), "1".into(), huge]);
        assert!(spline_data(&v).unwrap_err().contains("too large"), "{:?}", spline_data(&v));
        assert_eq!(decode_base64("AAECAw==").unwrap(), vec![0, 1, 2, 3]);
        assert_eq!(decode_base64("AAECAw").unwrap(), vec![0, 1, 2, 3]);
        assert!(decode_base64("AA*A").is_err());
    }
}
