//! Maya ASCII (`.ma`) scenes: meshes, NURBS curves, hair systems with their follicles,
//! FurDescriptions, cameras and lights (docs/maya-fur-hair.md section 6).
//!
//! [`parse`] turns the text into a node graph; this module reads the nodes tress knows
//! into an [`Imported`] scene:
//!
//! - **mesh**: vertices (`.vt`, plus tweaks `.pt`), edges (`.ed`), faces (`.fc`, as edge
//!   loops) and UV set 0 (`.uvst[0].uvsp`, per face corner), as a [`PolygonMesh`]
//!   (Catmull-Clark subdivided when MtoA's `aiSubdivType` is 1, `aiSubdivIterations`
//!   times, Arnold's default 1) triangulated as
//!   fans, and placed by its DAG transforms (translate, rotate with its order, scale, pivots, rotate
//!   axis). A mesh built by a `polySphere`, `polyPlane`, `polyTorus`, `polyCube` or
//!   `polyCylinder` node is rebuilt from that node's attributes (spheres, cubes and
//!   cylinders with Maya's vertex numbers, so
//!   point tweaks land where Maya puts them), through the `transformGeometry` nodes on the
//!   way (their matrix applied) and the `deleteComponent` ones (their faces removed).
//!   Colour: the `lambert`/`blinn`/`phong` of its shading
//!   group (`color × diffuse`), else Maya's default grey. Hidden and intermediate shapes
//!   are skipped; a deformed shape (a mesh or curve with no geometry of its own) is drawn
//!   in its rest pose, from the shape its deformers start from (the intermediate `…Orig`).
//! - **nurbsCurve**: the `.cc` block (degree, spans, form, rational, knots, CVs), sampled
//!   by de Boor's algorithm at its knots and [`SAMPLES_PER_SPAN`] points per span, or the
//!   circle a `makeNurbCircle` node builds for it ([`history`]). A follicle's start curve
//!   is a guide of its hair system; other curves are drawn as hairs as wide as Arnold draws
//!   them (`aiCurveWidth`, the `aiCurveCollector`'s, MtoA's default for a curve marked
//!   `aiRenderCurve`; a collector's width profile `widthProfile` narrows its curves root to
//!   tip), else as the file's first hair system draws its hairs (`hairWidth` ×
//!   `hairWidthScale` along the curve), or, without one, [`RELATIVE_WIDTH`] of the scene's
//!   size (reported); closed curves Arnold is not told to render (rig controls) are skipped.
//! - **hairSystem** with its **follicles** (`follicle.oha → hairSystem.ih[i]`): the render
//!   attributes of spec section 5 by short or long name, ramps included, and one guide per
//!   follicle (its start curve, else its rest curve, else the output curve the file
//!   stores for it) with its root UV (`.pu`, `.pv`). A follicle transform whose placement the
//!   file does not store (it is computed by Maya from `.pu`, `.pv`) is placed on its
//!   mesh, local X along the surface normal and Y along the U tangent.
//! - **xgmSplineDescription**: an XGen interactive groom, the splines its `xgmSplineBase`
//!   stores in the file, see [`xgen`]; an XGen collection (`xgmPalette`), whose strands XGen
//!   generates from the collection file beside the scene, approximated as Maya Fur from
//!   that file's density, length and width, see [`xgen_collection`].
//! - **FurDescription**: its attributes (node defaults for those the file omits) become a
//!   fur description grown on each mesh it is attached to (through a `FurFeedback`), see
//!   [`fur_nodes`].
//! - **camera**: the one asked for by name (`--camera`: its transform's or its shape's
//!   name), else the first renderable perspective camera other than the default `persp`
//!   (else `persp`, else the first renderable orthographic one, its orthographic width
//!   spanning the image width), field of view from focal length (`.fl`), film aperture (`.cap`) and
//!   film fit (`.ff`), clipped at its near and far clip planes (`.ncp`, `.fcp`); image
//!   size from `defaultResolution`.
//! - **lights**: directional, point, spot, ambient and area lights, colour × intensity
//!   (× 2^`aiExposure` when Arnold's exposure is set). A Maya intensity `I` lights a white
//!   Lambert surface facing it to `I` (Maya's shading has no 1/π), so tress's irradiance is
//!   `π I`. Point and spot lights fall off with their decay rate (`.de`): none (Maya's
//!   default: the same light at every distance), linear, quadratic or cubic. When Arnold
//!   renders the file (`defaultRenderGlobals.currentRenderer`), the lights are Arnold's as
//!   MtoA translates them: irradiance `I` (Arnold's diffuse has tress's 1/π), point and spot
//!   lights decaying by `aiDecayType` (quadratic, its default, or none) whatever `.de` says,
//!   area lights normalized by their area (`aiNormalize`, on by default). Arnold's own
//!   `aiAreaLight` (a quad) always lights that way, and `aiSkyDomeLight` is a sky of
//!   radiance colour (`.sc`) × intensity × 2^exposure.
//!
//! - **hair shading** (docs/interop.md): an `aiStandardHair` as MtoA assigns it (a curve's
//!   `aiCurveCollector`, object set or own `aiCurveShader`; a hair system's `aiHairShader`
//!   with `aiOverrideHair`) becomes the physical material ([`super::arnold_hair`]); without
//!   one, when Arnold renders the file, the `standard_hair` MtoA makes (Arnold's defaults
//!   on curves; a diffuse one of the hair colour on hair systems); else tube shading.
//!
//! - **animation curves** (`animCurveT*`) are evaluated at the frame before anything else
//!   is read and override the attributes they drive, see [`anim`]; XGen grooms follow the
//!   meshes they are bound to from the file's saved time to that frame.
//!
//! Every other node type is skipped, all of them together in one warning.

pub mod anim;
pub mod fur_nodes;
pub mod history;
pub mod parse;
pub mod xgen;
pub mod xgen_collection;

use self::parse::{Face, Graph, Value};
use super::arnold_hair::{ArnoldShader, Param, StandardHair};
use super::arnold_surface::{Flat, StandardSurface};
use super::imported::{relative_width, Imported, RELATIVE_WIDTH};
use crate::error::LoadError;
use crate::geometry::curve::Nurbs;
use crate::geometry::subdivision::{self, arnold_iterations, FaceBudget, PolygonMesh};
use crate::geometry::{StrandSet, TriangleMesh};
use crate::hair_system::{
    follicles::follicles_at_uvs, Guides, HairColors, HairSystem, Interp, NoiseMethod, Ramp, RampKey,
};
use crate::light::Light;
use crate::scene::{
    CameraDesc, CameraProjection, Film, FilmFit, GuideSource, HairEntry, HairSource, HairSystemEntry, MeshEntry,
    MeshSource, Visibility,
};
use crate::shading::Material;
use glam::{Affine3A, DAffine3, DMat3, DVec3, Vec3, Vec4};
use std::collections::{BTreeMap, HashMap};
use std::f32::consts::PI;
use std::path::Path;

/// The primitive nodes a mesh's geometry is rebuilt from (`Reader::procedural`).
const PROCEDURAL_MESHES: &[&str] = &["polySphere", "polyPlane", "polyTorus", "polyCube", "polyCylinder"];
/// The attributes a deformed shape's geometry flows in through, from the shape it starts
/// from to the deformed one: a shape's `inMesh` and `create`, a deformer's
/// `input[i].inputGeometry`, `groupParts.inputGeometry`.
const GEOMETRY_INPUTS: &[&str] = &["i", "inMesh", "cr", "create", "ig", "inputGeometry"];
/// The attribute MtoA takes a curve's or curve collector's shader from, short and long.
const CURVE_SHADER: [&str; 2] = ["ai_curve_shader", "aiCurveShader"];
/// MtoA's default `aiCurveWidth`, in centimetres.
const ARNOLD_CURVE_WIDTH: f64 = 0.01;
/// Linear pieces per span when sampling a curve of degree 2 or more.
pub const SAMPLES_PER_SPAN: usize = 8;
/// Most control points one curve may have.
const MAX_CVS: usize = 1 << 22;

/// Reads a `.ma` file, through the camera named `camera` (its transform's or its shape's
/// name) when one is given, with its animation curves at `frame` (else at the file's saved
/// time, [`anim::saved_time`]).
pub fn read_maya(path: &Path, camera: Option<&str>, frame: Option<u32>) -> Result<Imported, LoadError> {
    let bytes = crate::input_file::read(path, crate::input_file::Kind::ImportedScene)?;
    // Maya writes files in the system code page; anything not UTF-8 is replaced, which can
    // only touch names and strings.
    parse_maya_with(&String::from_utf8_lossy(&bytes), path, camera, frame)
}

/// Reads `.ma` text; `path` names the file in messages.
pub fn parse_maya(text: &str, path: &Path) -> Result<Imported, LoadError> {
    parse_maya_with(text, path, None, None)
}

/// [`parse_maya`] through the camera named `camera`, at `frame`.
pub fn parse_maya_with(
    text: &str,
    path: &Path,
    camera: Option<&str>,
    frame: Option<u32>,
) -> Result<Imported, LoadError> {
    // Line 0: a problem of the whole file (a camera asked for that it does not have).
    let at = |(line, msg): (u32, String)| match line {
        0 => LoadError::invalid(path, msg),
        _ => LoadError::format(path, format!("line {line}: {msg}")),
    };
    let mut g = parse::parse(text).map_err(at)?;
    let saved = anim::saved_time(&g);
    let time = frame.map_or(saved, f64::from);
    // XGen's groom splines are stored in world space as the scene stood at its saved time;
    // the pose at that time places them again on their meshes at the frame.
    let saved_pose = (time != saved && g.nodes.iter().any(|n| n.kind == "xgmSplineDescription")).then(|| {
        let mut at_saved = g.clone();
        anim::apply(&mut at_saved, saved);
        at_saved
    });
    let (warnings, _) = anim::apply(&mut g, time);
    let mut reader = Reader::new(&g);
    reader.saved_pose = saved_pose.as_ref();
    reader.out.warnings = warnings;
    reader.wanted_camera = camera.map(str::to_string);
    reader.dir = path.parent().map(Path::to_path_buf);
    reader.read().map_err(at)
}

type Res<T> = Result<T, (u32, String)>;

/// The DAG and shading node types read here, and Maya's bookkeeping nodes that need no
/// reading; anything else is reported once.
const KNOWN: [&str; 64] = [
    "transform",
    "animCurveTL",
    "animCurveTA",
    "animCurveTU",
    "animCurveTT",
    "mesh",
    "nurbsCurve",
    "hairSystem",
    "follicle",
    "camera",
    "directionalLight",
    "pointLight",
    "spotLight",
    "ambientLight",
    "areaLight",
    "aiSkyDomeLight",
    "aiAreaLight",
    "aiCurveCollector",
    "aiStandardHair",
    "aiStandardSurface",
    "aiFlat",
    "FurDescription",
    "FurFeedback",
    "FurGlobals",
    "shadingEngine",
    "lambert",
    "blinn",
    "phong",
    "phongE",
    "surfaceShader",
    "polySphere",
    "polyPlane",
    "polyTorus",
    "polyCube",
    "polyCylinder",
    "transformGeometry",
    "deleteComponent",
    "makeNurbCircle",
    "xgmSplineDescription",
    "xgmSplineBase",
    "xgmPalette",
    "xgmDescription",
    "xgmSubdPatch",
    "xgmSplineGuide",
    "xgmMakeGuide",
    "materialInfo",
    "partition",
    "lightLinker",
    "displayLayer",
    "displayLayerManager",
    "renderLayer",
    "renderLayerManager",
    "script",
    "nodeGraphEditorInfo",
    "shapeEditorManager",
    "poseInterpolatorManager",
    "groupId",
    "groupParts",
    "pfxHair",
    "nucleus",
    "time",
    "objectSet",
    "dagPose",
    "",
];

struct Reader<'g> {
    g: &'g Graph,
    out: Imported,
    /// World matrices by node, filled lazily; follicle transforms Maya computes are put
    /// here before any curve is read.
    world: HashMap<usize, DAffine3>,
    /// Whether a node or one of its parents is hidden, by node, filled lazily.
    hidden: HashMap<usize, bool>,
    /// Mesh index in `out.contents.meshes`, the world-space mesh and its triangles' Maya
    /// faces, by mesh node.
    meshes: HashMap<usize, (usize, TriangleMesh, Faces)>,
    /// The camera asked for by name (`--camera`), if any.
    wanted_camera: Option<String>,
    /// Follicles whose UV no face covers, placed at the nearest UV: how many, the first.
    off_uv: Option<(usize, String)>,
    /// Shapes drawn in their rest pose (their deformers not evaluated), and the node types
    /// their deformation passes through.
    rest_posed: (std::collections::BTreeSet<usize>, std::collections::BTreeSet<String>),
    /// Arnold curve collector shapes, by the transform holding them.
    collectors: HashMap<usize, usize>,
    /// Curves built by history tress does not evaluate: how many, and the node types.
    unbuilt_curves: (usize, std::collections::BTreeSet<String>),
    /// The material of each Arnold hair or curve shader node met, `None` for a type tress
    /// does not read.
    hair_shaders: HashMap<usize, Option<Material>>,
    /// Those of types tress does not read, counted by type for one warning.
    unread_shaders: BTreeMap<String, usize>,
    /// The folder of the `.ma`, where XGen collection files are looked for.
    dir: Option<std::path::PathBuf>,
    /// The graph with its animation at the file's saved time, when the frame read is
    /// another and XGen grooms (stored as they stood then) must follow their meshes.
    saved_pose: Option<&'g Graph>,
    /// The material of each `aiStandardSurface` or `aiFlat` met on meshes (its warning said once).
    surface_shaders: HashMap<usize, Material>,
    /// The faces subdivision has made in this file.
    budget: FaceBudget,
    /// Warnings counted by kind ([`Reader::note`]): how many nodes, and the first.
    notes: BTreeMap<String, (usize, String)>,
}

impl<'g> Reader<'g> {
    fn new(g: &'g Graph) -> Reader<'g> {
        Reader {
            g,
            out: Imported::default(),
            world: HashMap::new(),
            hidden: HashMap::new(),
            meshes: HashMap::new(),
            wanted_camera: None,
            off_uv: None,
            rest_posed: Default::default(),
            collectors: HashMap::new(),
            unbuilt_curves: Default::default(),
            hair_shaders: HashMap::new(),
            unread_shaders: BTreeMap::new(),
            dir: None,
            saved_pose: None,
            surface_shaders: HashMap::new(),
            budget: FaceBudget::default(),
            notes: BTreeMap::new(),
        }
    }

    fn kind(&self, n: usize) -> &str {
        &self.g.nodes[n].kind
    }

    fn of_kind(&self, kind: &'g str) -> impl Iterator<Item = usize> + 'g {
        let g = self.g;
        (0..g.nodes.len()).filter(move |&i| g.nodes[i].kind == kind)
    }

    fn read(mut self) -> Res<Imported> {
        let g = self.g;
        // Malformed transform channels are errors even on transforms nothing renders under.
        for n in self.of_kind("transform") {
            self.local(n)?;
        }
        for n in self.of_kind("mesh").collect::<Vec<_>>() {
            self.mesh(n)?;
        }
        for (what, (count, first)) in std::mem::take(&mut self.notes) {
            self.out.warnings.push(format!("{what} ({count}; first: {first})"));
        }
        for n in self.of_kind("follicle").collect::<Vec<_>>() {
            self.place_follicle(n)?;
        }
        if let Some((n, first)) = self.off_uv.take() {
            self.out.warnings.push(format!(
                "{n} follicle(s) at UVs no face of their mesh covers: placed at the nearest UV (first: {first})"
            ));
        }
        let mut used_curves = vec![false; g.nodes.len()];
        for n in self.of_kind("hairSystem").collect::<Vec<_>>() {
            self.hair_system(n, &mut used_curves)?;
        }
        for c in &g.connections {
            // Output and rest curves of follicles are Maya's results, not extra hair.
            if self.kind(c.src) == "follicle" && self.kind(c.dst) == "nurbsCurve" {
                used_curves[c.dst] = true;
            }
        }
        self.free_curves(&used_curves)?;
        self.xgen()?;
        if self.unbuilt_curves.0 > 0 {
            let kinds: Vec<&str> = self.unbuilt_curves.1.iter().map(String::as_str).collect();
            self.out.warnings.push(format!(
                "{} curve(s) built by history tress does not evaluate ({}): skipped",
                self.unbuilt_curves.0,
                kinds.join(", ")
            ));
        }
        if !self.unread_shaders.is_empty() {
            let list: Vec<String> = self.unread_shaders.iter().map(|(k, n)| format!("{k} ({n})")).collect();
            self.out.warnings.push(format!(
                "Arnold hair or curve shaders of types tress does not read: {}; their hair keeps tress's tube shading",
                list.join(", ")
            ));
        }
        if !self.rest_posed.0.is_empty() {
            let kinds: Vec<&str> = self.rest_posed.1.iter().map(String::as_str).collect();
            self.out.warnings.push(format!(
                "{} deformed shape(s) drawn in their rest pose, as the shape their deformers start from \
                 (tress does not evaluate {})",
                self.rest_posed.0.len(),
                kinds.join(", ")
            ));
        }
        let mut furs = Vec::new();
        for n in self.of_kind("FurDescription").collect::<Vec<_>>() {
            let mut f = fur_nodes::read_fur(g, n)?;
            f.meshes = self.fur_meshes(n);
            furs.push(f);
        }
        let (entries, warnings) = fur_nodes::fur_entries(&furs)?;
        self.out.contents.fur.extend(entries);
        self.out.warnings.extend(warnings);
        self.camera()?;
        self.lights()?;
        if let Some(r) = g.find("defaultResolution") {
            let w = scalar(g, r, &["w", "width"], 640.0)?;
            let h = scalar(g, r, &["h", "height"], 480.0)?;
            if !(1.0..=65536.0).contains(&w) || !(1.0..=65536.0).contains(&h) {
                return Err((g.nodes[r].line, format!("defaultResolution {w}x{h} is out of range")));
            }
            self.out.resolution = Some([w as u32, h as u32]);
        }
        for r in &g.references {
            self.out.warnings.push(format!("references {r}, which tress does not load: nothing of it is rendered"));
        }
        let mut unknown: BTreeMap<&str, usize> = BTreeMap::new();
        for n in &g.nodes {
            if !KNOWN.contains(&n.kind.as_str()) {
                *unknown.entry(&n.kind).or_default() += 1;
            }
        }
        if !unknown.is_empty() {
            let total: usize = unknown.values().sum();
            let list: Vec<String> = unknown.iter().map(|(k, n)| format!("{k} ({n})")).collect();
            self.out
                .warnings
                .push(format!("skipped {total} node(s) of types tress does not read: {}", list.join(", ")));
        }
        Ok(self.out)
    }

    // ----- DAG -----

    /// The node's local matrix (a transform's channels; identity for shapes).
    fn local(&self, n: usize) -> Res<DAffine3> {
        let g = self.g;
        let node = &g.nodes[n];
        if node.attrs.is_empty() {
            return Ok(DAffine3::IDENTITY);
        }
        let a = g.angle_to_radians;
        let t =
            vec3(g, n, &["t", "translate"], &[["tx", "translateX"], ["ty", "translateY"], ["tz", "translateZ"]], 0.0)?;
        let r = vec3(g, n, &["r", "rotate"], &[["rx", "rotateX"], ["ry", "rotateY"], ["rz", "rotateZ"]], 0.0)? * a;
        let s = vec3(g, n, &["s", "scale"], &[["sx", "scaleX"], ["sy", "scaleY"], ["sz", "scaleZ"]], 1.0)?;
        let ra = vec3(
            g,
            n,
            &["ra", "rotateAxis"],
            &[["rax", "rotateAxisX"], ["ray", "rotateAxisY"], ["raz", "rotateAxisZ"]],
            0.0,
        )? * a;
        let rp = vec3(
            g,
            n,
            &["rp", "rotatePivot"],
            &[["rpx", "rotatePivotX"], ["rpy", "rotatePivotY"], ["rpz", "rotatePivotZ"]],
            0.0,
        )?;
        let sp = vec3(
            g,
            n,
            &["sp", "scalePivot"],
            &[["spx", "scalePivotX"], ["spy", "scalePivotY"], ["spz", "scalePivotZ"]],
            0.0,
        )?;
        let rpt = vec3(
            g,
            n,
            &["rpt", "rotatePivotTranslate"],
            &[["rptx", "rotatePivotTranslateX"], ["rpty", "rotatePivotTranslateY"], ["rptz", "rotatePivotTranslateZ"]],
            0.0,
        )?;
        let spt = vec3(
            g,
            n,
            &["spt", "scalePivotTranslate"],
            &[["sptx", "scalePivotTranslateX"], ["spty", "scalePivotTranslateY"], ["sptz", "scalePivotTranslateZ"]],
            0.0,
        )?;
        let order = scalar(g, n, &["ro", "rotateOrder"], 0.0)? as i64;
        if s.x * s.y * s.z == 0.0 {
            return Err((node.line, format!("{}: scale {s} has a zero component", node.name)));
        }
        let rot = euler(r, order).ok_or((node.line, format!("{}: rotate order {order} is not 0 to 5", node.name)))?;
        let rot_axis = euler(ra, 0).expect("order 0 exists");
        let tr = DAffine3::from_translation;
        // Maya's transform matrix (column vectors): T · RPT · RP · R · RA · RP⁻¹ · SPT · SP · S · SP⁻¹.
        Ok(tr(t + rpt + rp)
            * DAffine3::from_mat3(rot * rot_axis)
            * tr(-rp + spt + sp)
            * DAffine3::from_scale(s)
            * tr(-sp))
    }

    /// The node's world matrix: its local matrix under its parents'.
    fn world(&mut self, n: usize) -> Res<DAffine3> {
        let (mut chain, mut on_chain) = (Vec::new(), std::collections::HashSet::new());
        let mut cur = Some(n);
        while let Some(c) = cur {
            if let Some(m) = self.world.get(&c) {
                let mut m = *m;
                for &d in chain.iter().rev() {
                    m *= self.local(d)?;
                    self.world.insert(d, m);
                }
                return Ok(m);
            }
            if !on_chain.insert(c) {
                return Err(self.parent_cycle(&chain, c));
            }
            chain.push(c);
            let inherits = scalar(self.g, c, &["it", "inheritsTransform"], 1.0)? != 0.0;
            cur = if inherits { self.g.parent(c) } else { None };
        }
        let mut m = DAffine3::IDENTITY;
        for &d in chain.iter().rev() {
            m *= self.local(d)?;
            self.world.insert(d, m);
        }
        Ok(m)
    }

    /// The error for a chain of parents (`chain`, from a node upwards) that comes back to
    /// `again`: the cycle named, node by node.
    fn parent_cycle(&self, chain: &[usize], again: usize) -> (u32, String) {
        let start = chain.iter().position(|&c| c == again).unwrap_or(0);
        let cycle = &chain[start..];
        // A long cycle is named by its first few nodes.
        let mut names: Vec<&str> = cycle.iter().take(8).map(|&c| self.g.nodes[c].name.as_str()).collect();
        if cycle.len() > 8 {
            names.push("...");
        }
        names.push(&self.g.nodes[again].name);
        (self.g.nodes[again].line, format!("parent cycle: {}", names.join(" is a child of ")))
    }

    /// True when the node or a parent is hidden (`.v no`), or the node is an intermediate
    /// object (`.io yes`, e.g. a deformer's original shape).
    fn hidden(&mut self, n: usize) -> Res<bool> {
        if scalar(self.g, n, &["io", "intermediateObject"], 0.0)? != 0.0 {
            return Ok(true);
        }
        // Up to the first node whose answer is known (memoised like world matrices, so a
        // deep hierarchy costs its size, not its size times its depth), then down again.
        let (mut chain, mut on_chain) = (Vec::new(), std::collections::HashSet::new());
        let mut cur = Some(n);
        let mut above = false;
        while let Some(c) = cur {
            if let Some(&h) = self.hidden.get(&c) {
                above = h;
                break;
            }
            if !on_chain.insert(c) {
                return Err(self.parent_cycle(&chain, c));
            }
            chain.push(c);
            cur = self.g.parent(c);
        }
        for &c in chain.iter().rev() {
            above = above || scalar(self.g, c, &["v", "visibility"], 1.0)? == 0.0;
            self.hidden.insert(c, above);
        }
        Ok(above)
    }

    /// Sources connected into `n`'s attribute named by one of `attrs` (with or without an
    /// index).
    fn inputs(&self, n: usize, attrs: &[&str]) -> Vec<usize> {
        self.g.inputs_of(n).filter(|c| attrs.contains(&plug_base(&c.dst_attr))).map(|c| c.src).collect()
    }

    /// The shape a deformed shape (one with no geometry of its own, built by a chain of
    /// `skinCluster`, `tweak`, `groupParts`, ... nodes) is drawn as: the first node up its
    /// geometry inputs for which `stores` holds (Maya's intermediate `…Orig` shape: the rest
    /// pose), with the nodes between it and `n`, upstream first. The chain's node types
    /// other than `evaluated` (what the caller applies) and `groupParts` are noted for one
    /// warning. `None` when the chain reaches none.
    fn rest_shape(
        &mut self,
        n: usize,
        stores: impl Fn(&Self, usize) -> bool,
        evaluated: &[&str],
    ) -> Option<(usize, Vec<usize>)> {
        // Each node met, with the node downstream of it it was reached from.
        let mut via = HashMap::from([(n, n)]);
        let mut queue = std::collections::VecDeque::from([n]);
        while let Some(c) = queue.pop_front() {
            if c != n && stores(self, c) {
                let mut chain = Vec::new();
                let mut at = via[&c];
                while at != n {
                    chain.push(at);
                    at = via[&at];
                }
                // `groupParts` passes the geometry on as it is: not a deformation.
                let passed: std::collections::BTreeSet<String> = chain
                    .iter()
                    .map(|&m| self.kind(m))
                    .filter(|k| *k != "groupParts" && !evaluated.contains(k))
                    .map(str::to_string)
                    .collect();
                if !passed.is_empty() {
                    self.rest_posed.0.insert(n);
                    self.rest_posed.1.extend(passed);
                }
                return Some((c, chain));
            }
            for conn in self.g.inputs_of(c) {
                if GEOMETRY_INPUTS.contains(&plug_leaf(&conn.dst_attr)) && !via.contains_key(&conn.src) {
                    via.insert(conn.src, c);
                    queue.push_back(conn.src);
                }
            }
        }
        None
    }

    /// Where the geometry flowing into `n` starts: up its first geometry input (`i`,
    /// `inputGeometry`, ...) until a node with none; `n` itself when it has none.
    fn history_root(&self, n: usize) -> usize {
        let mut seen = std::collections::HashSet::from([n]);
        let mut at = n;
        while let Some(up) = self
            .g
            .inputs_of(at)
            .find(|c| GEOMETRY_INPUTS.contains(&plug_leaf(&c.dst_attr)))
            .map(|c| c.src)
            .filter(|&up| seen.insert(up))
        {
            at = up;
        }
        at
    }

    // ----- meshes -----

    fn mesh(&mut self, n: usize) -> Res<()> {
        let g = self.g;
        let node = &g.nodes[n];
        if self.hidden(n)? {
            return Ok(());
        }
        let history = self.inputs(n, &["i", "inMesh"]);
        let stores = |r: &Self, m: usize| {
            r.kind(m) == "mesh" && r.g.nodes[m].attrs.iter().any(|a| a.name.starts_with("vt"))
                || PROCEDURAL_MESHES.contains(&r.kind(m))
        };
        let (poly, ptex) = match history.first() {
            Some(&src) if !stores(self, n) => {
                // Built by a primitive node, or deformed from a shape upstream through a
                // chain of nodes: `transformGeometry` and `deleteComponent` ones are applied,
                // deformers are not (the rest pose is drawn).
                let (from, chain) = match PROCEDURAL_MESHES.contains(&self.kind(src)) {
                    true => (Some(src), Vec::new()),
                    false => self
                        .rest_shape(n, stores, &["transformGeometry", "deleteComponent"])
                        .map_or((None, Vec::new()), |(f, c)| (Some(f), c)),
                };
                let built = match from {
                    Some(f) if self.kind(f) == "mesh" => stored_mesh(g, f)?.map(Built::Poly),
                    Some(f) => self.procedural(f)?,
                    None => None,
                };
                let Some(mut built) = built else {
                    self.out.warnings.push(format!(
                        "mesh {} is built by a `{}` node, which tress cannot evaluate: skipped",
                        node.name,
                        self.kind(self.history_root(src))
                    ));
                    return Ok(());
                };
                // The shape's own point tweaks go on top of what its history builds, by Maya's
                // vertex numbers: only while every node on the way keeps them known.
                let mut numbered = true;
                for &t in &chain {
                    match self.kind(t) {
                        "transformGeometry" => built.transform(&transform_geometry(g, t)?),
                        "deleteComponent" => numbered &= self.delete_components(t, &mut built)?,
                        "groupParts" => {}
                        _ => numbered = false,
                    }
                }
                let tweaks = point_tweaks(g, n)?;
                let applied = tweaks.is_empty() || numbered && built.tweak(&tweaks);
                if !applied {
                    self.out.warnings.push(format!(
                        "mesh {}: the point tweaks of {} vertices are not applied to what its `{}` history builds",
                        node.name,
                        tweaks.len(),
                        self.kind(src)
                    ));
                }
                let (poly, ptex) = built.finish();
                if poly.polygons.is_empty() {
                    self.out
                        .warnings
                        .push(format!("mesh {}: its history deletes every face: nothing to draw", node.name));
                    return Ok(());
                }
                (poly, ptex)
            }
            _ => match stored_mesh(g, n)? {
                Some(m) => Built::Poly(m).finish(),
                None => return Ok(()),
            },
        };
        let (cage, mesh, faces) = self.triangles(n, poly, ptex)?;
        let world = self.world(n)?;
        let material = match self.mesh_shader(n) {
            Some(shader) if matches!(self.kind(shader), "aiStandardSurface" | "aiFlat") => {
                match self.surface_shaders.get(&shader) {
                    Some(m) => m.clone(),
                    None => {
                        let (m, warning) = match self.kind(shader) {
                            "aiFlat" => self.arnold_params::<Flat>(shader)?,
                            _ => self.arnold_params::<StandardSurface>(shader)?,
                        };
                        self.out.warnings.extend(warning);
                        self.surface_shaders.insert(shader, m.clone());
                        m
                    }
                }
            }
            _ => Material::Diffuse { color: self.mesh_color(n)? },
        };
        let mut placed = cage;
        let transform = finite_affine(g, n, &world)?;
        placed.transform(&transform);
        self.meshes.insert(n, (self.out.contents.meshes.len(), placed, faces));
        self.out.contents.meshes.push(MeshEntry {
            source: MeshSource::Inline(mesh),
            material: material.into(),
            transform,
            visibility: shape_visibility(g, n)?,
        });
        Ok(())
    }

    /// A mesh's polygons as triangles ([`PolygonMesh::triangulate`]): the cage as Maya has it
    /// (where follicles and XGen grooms are placed; with the Ptex faces of its triangles, or
    /// `ptex` of them when tress does not number its faces as Maya does), and the mesh drawn:
    /// the cage, or its Catmull-Clark subdivision as Arnold subdivides it
    /// ([`Reader::subdivision`]) within the file's [`FaceBudget`], smooth shaded.
    fn triangles(&mut self, n: usize, poly: PolyMesh, ptex: Option<u32>) -> Res<(TriangleMesh, TriangleMesh, Faces)> {
        let node = &self.g.nodes[n];
        let polygons = poly.polygon_mesh();
        polygons.validate().map_err(|e| (node.line, format!("mesh {}: {e}", node.name)))?;
        let (cage, _) = polygons.triangulate(poly.smooth);
        let drawn = match self.subdivision(n)? {
            Some(iterations) => {
                let (refined, done) = self.budget.subdivide(&polygons, iterations);
                if let Some(stopped) = done.stopped() {
                    self.note(stopped, n, "");
                }
                refined.triangulate(true).0
            }
            None => cage.clone(),
        };
        drawn.validate().map_err(|e| (node.line, format!("mesh {}: {e}", node.name)))?;
        let faces = match ptex {
            Some(count) => Faces::Count(count),
            None => Faces::Of(poly.ptex_faces()),
        };
        Ok((cage, drawn, faces))
    }

    /// The Catmull-Clark iterations Arnold applies to mesh `n`, from the attributes MtoA adds
    /// to meshes: `aiSubdivType` (0 none, its default; 1 `catclark`; 2 `linear`) and
    /// `aiSubdivIterations` (1 unless set; 0 to [`subdivision::MAX_ITERATIONS`], else not
    /// subdivided). `None`: drawn as stored. Linear subdivision, which tress does not apply,
    /// is drawn as the cage: the same surface but where a polygon is not flat.
    fn subdivision(&mut self, n: usize) -> Res<Option<u32>> {
        let g = self.g;
        match scalar(g, n, &["ai_subdiv_type", "aiSubdivType"], 0.0)? {
            0.0 => return Ok(None),
            1.0 => {}
            2.0 => {
                self.note("`aiSubdivType` linear, which tress does not apply: drawn as the cage".into(), n, "");
                return Ok(None);
            }
            other => {
                let what = "`aiSubdivType` other than 0, 1 or 2: not subdivided";
                self.note(what.into(), n, &other.to_string());
                return Ok(None);
            }
        }
        let authored = scalar(g, n, &["ai_subdiv_iterations", "aiSubdivIterations"], 1.0)?;
        let held = (authored.fract() == 0.0 && authored.abs() < 1e18).then(|| arnold_iterations(authored as i64));
        match held.flatten() {
            Some(0) => Ok(None),
            Some(iterations) => Ok(Some(iterations)),
            None => {
                let what = format!("`aiSubdivIterations` not 0 to {}: not subdivided", subdivision::MAX_ITERATIONS);
                self.note(what, n, &authored.to_string());
                Ok(None)
            }
        }
    }

    /// Counts node `n` under the warning `what`, the first named (with `why`, if any).
    fn note(&mut self, what: String, n: usize, why: &str) {
        let name = &self.g.nodes[n].name;
        let first = if why.is_empty() { name.clone() } else { format!("{name}: {why}") };
        self.notes.entry(what).or_insert((0, first)).0 += 1;
    }

    /// The mesh a primitive node builds, from that node's attributes (Maya's defaults when
    /// unset); `None` for other history.
    fn procedural(&self, src: usize) -> Res<Option<Built>> {
        let g = self.g;
        let check = |v: f64, what: &str| -> Res<f32> {
            match v.is_finite() && v > 0.0 && v < 1e12 {
                true => Ok(v as f32),
                false => Err((g.nodes[src].line, format!("{}: `{what}` = {v} must be positive", g.nodes[src].name))),
            }
        };
        let divisions = |names: &[&str], default: f64| -> Res<u32> {
            Ok(scalar(g, src, names, default)?.clamp(3.0, 1000.0) as u32)
        };
        Ok(match self.kind(src) {
            "polySphere" => {
                let (sa, sh) =
                    (divisions(&["sa", "subdivisionsAxis"], 20.0)?, divisions(&["sh", "subdivisionsHeight"], 20.0)?);
                let sphere = poly_sphere(check(scalar(g, src, &["r", "radius"], 1.0)?, "radius")?, sa, sh);
                // Quads between the rings and a triangle (three Ptex faces) per column at
                // each pole.
                let mut built =
                    Built::Primitive(Primitive { mesh: sphere, faces: sa * (sh - 2) + 6 * sa, numbered: true });
                built.transform(&primitive_axis(g, src)?);
                Some(built)
            }
            "polyCube" => {
                let size = Vec3::new(
                    check(scalar(g, src, &["w", "width"], 1.0)?, "width")?,
                    check(scalar(g, src, &["h", "height"], 1.0)?, "height")?,
                    check(scalar(g, src, &["d", "depth"], 1.0)?, "depth")?,
                );
                let grid = |names: &[&str]| -> Res<u32> { Ok(scalar(g, src, names, 1.0)?.clamp(1.0, 1000.0) as u32) };
                let divisions = [
                    grid(&["sw", "subdivisionsWidth"])?,
                    grid(&["sh", "subdivisionsHeight"])?,
                    grid(&["sd", "subdivisionsDepth"])?,
                ];
                // `createUVs` 0 makes none; the other modes lay out the same cross on a box
                // (every stored box of the MtoA files has it, whatever its proportions).
                let with_uvs = scalar(g, src, &["cuv", "createUVs"], 3.0)? != 0.0;
                let mut cube = Built::Poly(poly_cube(size, divisions, with_uvs));
                cube.transform(&primitive_axis(g, src)?);
                Some(cube)
            }
            "polyCylinder" => {
                let sa = scalar(g, src, &["sa", "subdivisionsAxis"], 20.0)?.clamp(3.0, 1000.0) as u32;
                let sh = scalar(g, src, &["sh", "subdivisionsHeight"], 1.0)?.clamp(1.0, 1000.0) as u32;
                let sc = scalar(g, src, &["sc", "subdivisionsCaps"], 0.0)?.clamp(0.0, 1000.0) as u32;
                let radius = check(scalar(g, src, &["r", "radius"], 1.0)?, "radius")?;
                let height = check(scalar(g, src, &["h", "height"], 2.0)?, "height")?;
                let with_uvs = scalar(g, src, &["cuv", "createUVs"], 3.0)? != 0.0;
                let cylinder = poly_cylinder(radius, height, [sa, sh, sc.min(1)], with_uvs);
                let mut built = match sc {
                    0 | 1 => Built::Poly(cylinder),
                    // Caps of more rings have the same shape; their numbering is not known
                    // here, so they are drawn as triangles no tweak or deletion refers to.
                    _ => {
                        // Ptex faces: the side's quads, each cap's inner triangles (3 each)
                        // and its rings of quads.
                        let faces = sa * sh + 2 * (3 * sa + (sc - 1) * sa);
                        Built::Primitive(Primitive { mesh: cylinder, faces, numbered: false })
                    }
                };
                built.transform(&primitive_axis(g, src)?);
                Some(built)
            }
            "polyTorus" => {
                let (sa, sh) =
                    (divisions(&["sa", "subdivisionsAxis"], 20.0)?, divisions(&["sh", "subdivisionsHeight"], 20.0)?);
                let m = TriangleMesh::torus(
                    check(scalar(g, src, &["r", "radius"], 1.0)?, "radius")?,
                    check(scalar(g, src, &["sr", "sectionRadius"], 0.5)?, "sectionRadius")?,
                    sa,
                    sh,
                );
                // Its quads over one vertex per place: the torus's grid repeats its first
                // row and column (at UV 1) for the UVs only.
                let (rows, row) = (sa, sh + 1);
                let at = |i: u32, j: u32| (i % rows) * row + j % sh;
                let polygons = (0..rows)
                    .flat_map(|i| (0..sh).map(move |j| [(i, j), (i, j + 1), (i + 1, j + 1), (i + 1, j)]))
                    .map(|q| (q.map(|(i, j)| at(i, j)).to_vec(), Some(q.map(|(i, j)| (i * row + j) as i64).to_vec())))
                    .collect();
                let torus = PolyMesh { positions: m.positions, uvs: m.uvs.unwrap_or_default(), polygons, smooth: true };
                Some(Built::Primitive(Primitive { mesh: torus, faces: sa * sh, numbered: false }))
            }
            "polyPlane" => {
                let w = check(scalar(g, src, &["w", "width"], 1.0)?, "width")?;
                let h = check(scalar(g, src, &["h", "height"], 1.0)?, "height")?;
                let m = TriangleMesh::plane(1.0);
                // Drawn as one quad (facing +Y); Maya divides it into a grid of faces (10 ×
                // 10 unless set).
                let quad = vec![0, 3, 2, 1];
                let uvs = m.uvs.unwrap_or_default();
                let plane = PolyMesh {
                    positions: m.positions,
                    polygons: vec![(quad.clone(), (!uvs.is_empty()).then(|| quad.iter().map(|&i| i as i64).collect()))],
                    uvs,
                    smooth: false,
                };
                let grid = |names: &[&str]| -> Res<u32> { Ok(scalar(g, src, names, 10.0)?.clamp(1.0, 1000.0) as u32) };
                let faces = grid(&["sw", "subdivisionsWidth"])? * grid(&["sh", "subdivisionsHeight"])?;
                let mut built = Built::Primitive(Primitive { mesh: plane, faces, numbered: false });
                built.transform(&Affine3A::from_scale(Vec3::new(w, 1.0, h)));
                Some(built)
            }
            _ => None,
        })
    }

    /// Applies a `deleteComponent` node to the mesh flowing through it: removes the faces
    /// its `.dc` lists (`f[2]`, `f[0:3]`, `f[*]`). Maya numbers the faces left in their
    /// order, from 0 again, so a later deletion counts from there. Returns whether the
    /// vertices still have the numbers they came in with (what point tweaks further down
    /// are indexed by): not when a vertex no face uses any more is left (Maya deletes it,
    /// and the vertices after it take new numbers), nor when the deletion is not applied.
    /// Vertices and edges (`vtx[…]`, `e[…]`) are not deleted: Maya merges the faces around
    /// them into one, which tress does not evaluate (said, the mesh drawn without that
    /// deletion); nor are faces of a mesh tress builds only as triangles.
    fn delete_components(&mut self, n: usize, built: &mut Built) -> Res<bool> {
        let g = self.g;
        let node = &g.nodes[n];
        let Some(a) = attr(g, n, &["dc", "deleteComponents"]) else { return Ok(true) };
        let bad = |m: String| (a.line, format!("deleteComponent {}: {m}", node.name));
        let Value::Strings(list) = &a.value else {
            return Err(bad(format!("`{}` must be a component list (-type \"componentList\")", a.name)));
        };
        let Built::Poly(mesh) = built else {
            self.out.warnings.push(format!(
                "deleteComponent {}: tress does not number the faces of `{}` meshes as Maya does: drawn without \
                 the deletion",
                node.name,
                self.kind(self.history_root(n))
            ));
            return Ok(false);
        };
        let count = mesh.polygons.len();
        let mut gone = vec![false; count];
        let mut other = Vec::new();
        for c in list {
            let (kind, range) = component(c).ok_or_else(|| bad(format!("`{c}` is not a component")))?;
            if kind != "f" {
                other.push(c.as_str());
                continue;
            }
            let (first, end) = match range {
                None => (0, count),
                Some((a, b)) if a > b => return Err(bad(format!("`{c}` is an empty range"))),
                Some((_, b)) if b >= count => {
                    return Err(bad(format!("`{c}`: the mesh coming in has {count} faces")));
                }
                Some((a, b)) => (a, b + 1),
            };
            gone[first..end].fill(true);
        }
        if !other.is_empty() {
            self.out.warnings.push(format!(
                "deleteComponent {}: deleting {} merges the faces around them, which tress does not evaluate: \
                 drawn without the deletion",
                node.name,
                other.join(", ")
            ));
            return Ok(false);
        }
        let used = |polygons: &[Polygon]| {
            let mut used = vec![false; mesh.positions.len()];
            for v in polygons.iter().flat_map(|p| &p.0) {
                used[*v as usize] = true;
            }
            used
        };
        let before = used(&mesh.polygons);
        let mut k = 0;
        mesh.polygons.retain(|_| {
            k += 1;
            !gone[k - 1]
        });
        Ok(used(&mesh.polygons) == before)
    }

    /// The surface shader of the mesh's shading group, if it has one.
    fn mesh_shader(&self, n: usize) -> Option<usize> {
        let sg = self.g.outputs_of(n).find_map(|c| {
            (matches!(plug_base(&c.src_attr), "iog" | "instObjGroups") && self.kind(c.dst) == "shadingEngine")
                .then_some(c.dst)
        })?;
        self.inputs(sg, &["ss", "surfaceShader"]).first().copied()
    }

    /// `color × diffuse` of the Lambert-family shader of the mesh's shading group; Maya's
    /// default `lambert1` (0.5 grey, diffuse 0.8) when there is none.
    fn mesh_color(&self, n: usize) -> Res<Vec3> {
        let g = self.g;
        let default = Vec3::splat(0.5 * 0.8);
        let Some(shader) = self.mesh_shader(n) else { return Ok(default) };
        let color = |names: &[&str], comps: &[[&str; 2]; 3], d: f64| vec3(g, shader, names, comps, d);
        let c = match self.kind(shader) {
            "lambert" | "blinn" | "phong" | "phongE" => {
                let c = color(&["c", "color"], &[["cr", "colorR"], ["cg", "colorG"], ["cb", "colorB"]], 0.5)?;
                (c * scalar(g, shader, &["dc", "diffuse"], 0.8)?).as_vec3()
            }
            "surfaceShader" => {
                color(&["oc", "outColor"], &[["ocr", "outColorR"], ["ocg", "outColorG"], ["ocb", "outColorB"]], 0.0)?
                    .as_vec3()
            }
            _ => default,
        };
        match c.is_finite() {
            true => Ok(c.max(Vec3::ZERO)),
            false => {
                Err((g.nodes[shader].line, format!("{}: its colour is beyond single precision", g.nodes[shader].name)))
            }
        }
    }

    // ----- follicles and hair systems -----

    /// Places the transform of follicle `f` on its mesh when the file does not store it
    /// (Maya computes it from the follicle's `.ot` and `.or`).
    fn place_follicle(&mut self, f: usize) -> Res<()> {
        let g = self.g;
        let Some(xf) = g.parent(f) else { return Ok(()) };
        let stored =
            g.nodes[xf].attrs.iter().any(|a| matches!(a.name.as_str(), "t" | "translate" | "tx" | "translateX"));
        let Some(&mesh_node) = self.inputs(f, &["inm", "inputMesh"]).first() else { return Ok(()) };
        if stored {
            return Ok(());
        }
        let Some((_, mesh, _)) = self.meshes.get(&mesh_node) else { return Ok(()) };
        let (u, v) = (scalar(g, f, &["pu", "parameterU"], 0.0)?, scalar(g, f, &["pv", "parameterV"], 0.0)?);
        let node = &g.nodes[f];
        // UVs are searched in single precision: a value finite in f64 but past f32's range
        // (1e39) would be infinite there, nearest to no point of the mesh.
        let uv = [u as f32, v as f32];
        if !uv.iter().all(|x| x.is_finite()) {
            return Err((node.line, format!("follicle {}: its UV (`pu`, `pv`) is beyond single precision", node.name)));
        }
        let found = follicles_at_uvs(mesh, &[uv]).map_err(|e| (node.line, format!("follicle {}: {e}", node.name)))?;
        let Some(placed) = found[0] else {
            return Err((node.line, format!("follicle {}: its mesh's UVs cover no area", node.name)));
        };
        if placed.uv_distance > 0.0 {
            let e = self.off_uv.get_or_insert_with(|| (0, node.name.clone()));
            e.0 += 1;
        }
        let (fol, tri) = (placed.follicle, placed.triangle);
        // Local X along the normal, Y along the surface's U direction (the follicle's
        // tangent U), Z completing a right-handed frame.
        let x = fol.normal;
        let y = tangent_u(mesh, tri)
            .map(|t| t - x * t.dot(x))
            .and_then(Vec3::try_normalize)
            .unwrap_or(crate::math::frame(x).0);
        let z = x.cross(y);
        let m = DAffine3::from_mat3_translation(
            DMat3::from_cols(x.as_dvec3(), y.as_dvec3(), z.as_dvec3()),
            fol.position.as_dvec3(),
        );
        self.world.insert(xf, m);
        Ok(())
    }

    fn hair_system(&mut self, n: usize, used: &mut [bool]) -> Res<()> {
        let g = self.g;
        let node = &g.nodes[n];
        let system = hair_attributes(g, n)?;
        system.validate().map_err(|e| (node.line, format!("hair system {}: {e}", node.name)))?;
        let mut follicles: Vec<(usize, usize)> = Vec::new();
        let mut seen = std::collections::HashSet::new();
        for c in g.connections_of(n) {
            let (follicle, index) = if c.dst == n && self.kind(c.src) == "follicle" {
                (c.src, plug_index(&c.dst_attr))
            } else if c.src == n && self.kind(c.dst) == "follicle" {
                (c.dst, plug_index(&c.src_attr))
            } else {
                continue;
            };
            if seen.insert(follicle) {
                follicles.push((index.unwrap_or(usize::MAX), follicle));
            }
        }
        follicles.sort();
        let mut curves = StrandSet::new();
        let mut root_uv = Vec::new();
        let mut missing = 0;
        for &(_, f) in &follicles {
            // Its start curve, else its rest curve, else the output curve Maya computed
            // from them when the file keeps only that.
            let out_curves = g.outputs_of(f).filter(|c| matches!(plug_base(&c.src_attr), "oc" | "outCurve"));
            let out_curves: Vec<usize> = out_curves.map(|c| c.dst).collect();
            let curve = self
                .inputs(f, &["sp", "startPosition"])
                .into_iter()
                .chain(self.inputs(f, &["rp", "restPosition"]))
                .filter(|&c| self.kind(c) == "nurbsCurve")
                .chain(out_curves.into_iter().filter(|&c| self.kind(c) == "nurbsCurve" && cc_block(g, c).is_some()))
                .next();
            let points = match curve {
                Some(c) => {
                    used[c] = true;
                    self.curve_points(c)?.map(|(p, _)| p)
                }
                None => None,
            };
            match points {
                Some(p) if p.len() >= 2 => {
                    curves.push_strand(p.into_iter().map(|q| (q, 0.0)));
                    let u = scalar(g, f, &["pu", "parameterU"], 0.0)? as f32;
                    let v = scalar(g, f, &["pv", "parameterV"], 0.0)? as f32;
                    root_uv.push([u, v]);
                }
                _ => missing += 1,
            }
        }
        if follicles.is_empty() {
            self.out.warnings.push(format!("{}: the hair system has no follicles: no hair", node.name));
            return Ok(());
        }
        if missing > 0 {
            // Maya grows a follicle's hair from its start curve: the hair's length is an
            // argument of the script that makes that curve (`createHairCurveNode`), held by
            // no node, so a follicle without one has no hair to draw.
            self.out.warnings.push(format!(
                "{}: {missing} follicle(s) without a start, rest or output curve give no hair",
                node.name
            ));
        }
        if curves.strand_count() == 0 {
            self.out.warnings.push(format!("{}: no follicle with a curve: the hair system gives no hair", node.name));
            return Ok(());
        }
        let material = self.hair_system_material(n, &system)?;
        self.out.contents.hair_systems.push(HairSystemEntry {
            guides: GuideSource::Inline(Guides { curves, root_uv: Some(root_uv) }),
            system,
            material: material.into(),
            colors: HairColors::System,
            transform: Affine3A::IDENTITY,
            seed: 0,
            lod: None,
            visibility: shape_visibility(self.g, n)?,
        });
        Ok(())
    }

    // ----- curves -----

    /// The curve a curve node is drawn as, and whether it is closed: its own `.cc` block,
    /// or, for a deformed curve, that of the curve its deformers start from
    /// ([`Self::rest_shape`]), or the circle a `makeNurbCircle` node builds for it
    /// ([`history`]). `None` for a curve with no geometry, or one Maya builds from other
    /// history (counted for one warning).
    fn curve_nurbs(&mut self, n: usize) -> Res<Option<(Nurbs, bool)>> {
        let g = self.g;
        let node = &g.nodes[n];
        let block = |m: usize| cc_block(g, m);
        let from = match block(n) {
            Some(_) => n,
            None => {
                let builds = |r: &Self, m: usize| {
                    r.kind(m) == "nurbsCurve" && block(m).is_some() || r.kind(m) == "makeNurbCircle"
                };
                match self.rest_shape(n, builds, &[]) {
                    Some((m, _)) => m,
                    None => {
                        if let Some(&src) = self.inputs(n, &["cr", "create"]).first() {
                            self.unbuilt_curves.0 += 1;
                            self.unbuilt_curves.1.insert(self.kind(src).to_string());
                        }
                        return Ok(None);
                    }
                }
            }
        };
        if self.kind(from) == "makeNurbCircle" {
            return history::nurb_circle(g, from, &mut self.out.warnings).map(Some);
        }
        let Some(a) = block(from) else { return Ok(None) };
        let Value::Curve(words) = &a.value else {
            return Err((a.line, format!("curve {}: `.cc` must have -type \"nurbsCurve\"", node.name)));
        };
        let curve = nurbs_block(words).map_err(|e| (a.line, format!("curve {}: {e}", node.name)))?;
        // The form: 0 open, 1 closed, 2 periodic.
        let closed = words.get(2).copied().unwrap_or(0.0) != 0.0;
        Ok(Some((curve, closed)))
    }

    /// The world-space samples of a curve node (placed by its own transforms, its curve by
    /// [`Self::curve_nurbs`]) and whether it is closed; `None` for a curve tress cannot build.
    fn curve_points(&mut self, n: usize) -> Res<Option<(Vec<Vec3>, bool)>> {
        let g = self.g;
        let node = &g.nodes[n];
        let Some((curve, closed)) = self.curve_nurbs(n)? else { return Ok(None) };
        let world = self.world(n)?;
        let m = finite_affine(g, n, &world)?;
        let points: Vec<Vec3> = curve.sample(SAMPLES_PER_SPAN).into_iter().map(|p| m.transform_point3(p)).collect();
        if points.iter().any(|p| !p.is_finite()) {
            return Err((node.line, format!("curve {}: its points overflow single precision", node.name)));
        }
        Ok(Some((points, closed)))
    }

    /// The width Arnold draws a free curve with, in the file's unit: its own
    /// `aiCurveWidth` (`cwdth`), else that of the `aiCurveCollector` it is under, else MtoA's
    /// default [`ARNOLD_CURVE_WIDTH`] for a curve marked for Arnold (`aiRenderCurve`,
    /// `rcurve`) or collected; `None` for a curve Arnold is not told about. MtoA takes the
    /// width in centimetres, Maya's internal unit. Second, the collector the curve is
    /// under, if any.
    fn arnold_curve_width(&self, n: usize) -> Res<(Option<f32>, Option<usize>)> {
        let g = self.g;
        let names = ["cwdth", "ai_curve_width", "aiCurveWidth"];
        // The width node `of` sets (else MtoA's default), in the file's unit: not negative and
        // finite in single precision, where the strands keep it.
        let width = |of: usize| -> Res<Option<f32>> {
            let w = scalar(g, of, &names, ARNOLD_CURVE_WIDTH)?;
            let in_unit = (w / g.centimeters_per_unit) as f32;
            match in_unit.is_finite() && in_unit >= 0.0 {
                true => Ok(Some(in_unit)),
                false => Err(match attr(g, of, &names) {
                    Some(a) => (
                        a.line,
                        format!("{}: `{}` {w} is negative or beyond single precision", g.nodes[of].name, a.name),
                    ),
                    None => {
                        (g.nodes[of].line, format!("{}: its curve width is beyond single precision", g.nodes[of].name))
                    }
                }),
            }
        };
        let collector = self.collector_of(n);
        if attr(g, n, &names).is_some() {
            return Ok((width(n)?, collector));
        }
        if let Some(c) = collector {
            return Ok((width(c)?, collector));
        }
        let render_curve = scalar(g, n, &["rcurve", "ai_render_curve", "aiRenderCurve"], 0.0)? != 0.0;
        Ok((if render_curve { width(n)? } else { None }, None))
    }

    /// The width profile of an `aiCurveCollector` (`widthProfile`, `.wdthP`): a ramp of
    /// factors on the width from root (0) to tip (1) of each curve it collects; flat 1 when
    /// unset.
    fn width_profile(&self, c: usize) -> Res<Ramp<f32>> {
        match ramp_keys(self.g, c, "wdthP", "widthProfile", 1)? {
            Some(keys) => build_ramp(self.g, c, "widthProfile", keys, |v| v[0] as f32),
            None => Ok(Ramp::constant(1.0)),
        }
    }

    /// The `aiCurveCollector` a curve is under: the first up the DAG (at most as deep as
    /// the file has nodes: a parent cycle is an error elsewhere).
    fn collector_of(&self, n: usize) -> Option<usize> {
        let mut cur = self.g.parent(n);
        for _ in 0..self.g.nodes.len() {
            let p = cur?;
            if let Some(&c) = self.collectors.get(&p) {
                return Some(c);
            }
            cur = self.g.parent(p);
        }
        None
    }

    fn free_curves(&mut self, used: &[bool]) -> Res<()> {
        let g = self.g;
        self.collectors = (0..g.nodes.len())
            .filter(|&c| g.nodes[c].kind == "aiCurveCollector")
            .filter_map(|c| Some((g.parent(c)?, c)))
            .collect();
        let set_shaders = self.set_curve_shaders();
        let mut set = StrandSet::new();
        // Each strand's width when Arnold gives it one, and its width profile: its
        // collector's, else, for a curve drawn as the hair system draws hairs, the system's
        // `hairWidthScale`.
        let mut widths: Vec<Option<f32>> = Vec::new();
        let mut profiles: Vec<Option<usize>> = Vec::new();
        let mut ramps: Vec<Ramp<f32>> = Vec::new();
        let mut ramp_of: HashMap<usize, usize> = HashMap::new();
        // Each strand's material and visibility, as an index into `materials`.
        let (mut groups, mut materials): (Vec<usize>, Vec<(Material, Visibility)>) = (Vec::new(), Vec::new());
        let mut closed = 0;
        for n in self.of_kind("nurbsCurve").collect::<Vec<_>>() {
            if used[n] || self.hidden(n)? {
                continue;
            }
            let Some((p, is_closed)) = self.curve_points(n)? else { continue };
            let (width, collector) = self.arnold_curve_width(n)?;
            // A closed curve is a rig control, unless Arnold is told to render it.
            if is_closed && width.is_none() {
                closed += 1;
                continue;
            }
            let profile = match collector {
                Some(c) => Some(match ramp_of.get(&c) {
                    Some(&i) => i,
                    None => {
                        ramps.push(self.width_profile(c)?);
                        ramp_of.insert(c, ramps.len() - 1);
                        ramps.len() - 1
                    }
                }),
                None => None,
            };
            set.push_strand(p.into_iter().map(|q| (q, 0.0)));
            widths.push(width);
            profiles.push(profile);
            // A collector's curves are seen as the collector is (MtoA renders it as one shape).
            let material = (self.curve_material(n, &set_shaders)?, shape_visibility(self.g, collector.unwrap_or(n))?);
            groups.push(materials.iter().position(|m| *m == material).unwrap_or_else(|| {
                materials.push(material);
                materials.len() - 1
            }));
        }
        let unset = widths.iter().filter(|w| w.is_none()).count();
        if unset > 0 {
            let system = self.of_kind("hairSystem").next().map(|n| hair_attributes(self.g, n)).transpose()?;
            let width = match system {
                Some(h) => {
                    ramps.push(h.hair_width_scale);
                    for (w, p) in widths.iter().zip(profiles.iter_mut()) {
                        if w.is_none() {
                            *p = Some(ramps.len() - 1);
                        }
                    }
                    h.hair_width
                }
                None => {
                    let mut b = self.out.contents.bounds();
                    for p in &set.points {
                        b = b.grow(glam::Vec3A::new(p[0], p[1], p[2]));
                    }
                    let w = relative_width(&b);
                    self.out.warnings.push(format!(
                        "{unset} curve(s) outside hair systems have no width: drawn {w:.3e} wide ({} of the scene's size)",
                        RELATIVE_WIDTH
                    ));
                    w
                }
            };
            widths.iter_mut().for_each(|w| *w = Some(w.unwrap_or(width)));
        }
        for (i, (w, profile)) in widths.iter().zip(&profiles).enumerate() {
            let r = 0.5 * w.unwrap_or_default();
            let (a, b) = (set.offsets[i] as usize, set.offsets[i + 1] as usize);
            // The profile runs along the curve's samples (evenly spaced in each span's
            // parameter), root 0 to tip 1.
            let last = (b - a).saturating_sub(1).max(1) as f32;
            for (k, p) in set.points[a..b].iter_mut().enumerate() {
                p[3] = r * profile.map_or(1.0, |j| ramps[j].eval(k as f32 / last).max(0.0));
            }
        }
        if closed > 0 {
            self.out.warnings.push(format!("skipped {closed} closed or periodic curve(s) (rig controls, not hair)"));
        }
        // One entry per material and visibility, its strands in file order.
        for (k, (material, visibility)) in materials.into_iter().enumerate() {
            let mut part = StrandSet::new();
            for i in (0..groups.len()).filter(|&i| groups[i] == k) {
                let (a, b) = (set.offsets[i] as usize, set.offsets[i + 1] as usize);
                part.push_strand(set.points[a..b].iter().map(|p| (Vec3::new(p[0], p[1], p[2]), p[3])));
            }
            self.push_hair(part, material, visibility);
        }
        Ok(())
    }

    /// Adds strands drawn with a hair system's default look, if there are any.
    fn push_curves(&mut self, set: StrandSet) {
        self.push_hair(set, Material::Tube(HairSystem::default().tube()), Visibility::default());
    }

    /// Adds strands drawn with `material` and seen as `visibility` says, if there are any.
    fn push_hair(&mut self, set: StrandSet, material: Material, visibility: Visibility) {
        if set.strand_count() > 0 {
            self.out.contents.hair.push(HairEntry {
                source: HairSource::Inline(set),
                material: material.into(),
                transform: Affine3A::IDENTITY,
                radius_scale: 1.0,
                file_colors: true,
                lod: None,
                visibility,
            });
        }
    }

    // ----- Arnold hair shaders -----

    /// The material of a hair system: the Arnold shader MtoA is told to use
    /// (`aiOverrideHair` on, a shader connected to `aiHairShader`), when tress reads its
    /// type; else, when Arnold renders the file, the `standard_hair` MtoA makes from the
    /// hair system's own attributes (`HairTranslator`: diffuse 1 of the hair colour, whose
    /// ramp the hairs' colours carry, specular tint `specularColor`, no secondary specular,
    /// transmission tint `translucence`, roughness 1 / `specularPower`); else the hair
    /// system's tube shading, as Maya draws it.
    fn hair_system_material(&mut self, n: usize, system: &HairSystem) -> Res<Material> {
        let g = self.g;
        if scalar(g, n, &["ai_override_hair", "aiOverrideHair"], 0.0)? != 0.0 {
            if let Some(&s) = self.inputs(n, &["ai_hair_shader", "aiHairShader"]).first() {
                return Ok(self.arnold_shader(s)?.unwrap_or_else(|| Material::Tube(system.tube())));
            }
        }
        if !self.arnold_renders() {
            return Ok(Material::Tube(system.tube()));
        }
        let mtoa = StandardHair {
            diffuse: 1.0,
            diffuse_color: system.hair_color,
            specular_tint: system.specular_color,
            specular2_tint: Vec3::ZERO,
            transmission_tint: Vec3::splat(system.translucence),
            roughness: 1.0 / system.specular_power.max(1.0),
            ..StandardHair::default()
        };
        let (material, warning) = mtoa.material(&g.nodes[n].name, &[]);
        self.out.warnings.extend(warning);
        Ok(material)
    }

    /// The material of a curve outside hair systems: the Arnold shader MtoA gives it (that
    /// of the `aiCurveCollector` it is under; else that of an object set holding it or a
    /// parent, MtoA's set overrides; else its own `aiCurveShader`) when tress reads its
    /// type; with none, when Arnold renders the file, the `standard_hair` of Arnold's
    /// defaults MtoA gives a curve; else tress's tube shading.
    fn curve_material(&mut self, n: usize, set_shaders: &HashMap<usize, usize>) -> Res<Material> {
        let g = self.g;
        let tube = || Material::Tube(HairSystem::default().tube());
        let from_set = || {
            // The curve and its parents (a parent cycle is an error elsewhere).
            let mut cur = Some(n);
            for _ in 0..=g.nodes.len() {
                let p = cur?;
                if let Some(&shader) = set_shaders.get(&p) {
                    return Some(shader);
                }
                cur = g.parent(p);
            }
            None
        };
        let shader = match self.collector_of(n) {
            Some(c) => self.inputs(c, &CURVE_SHADER).first().copied(),
            None => from_set().or_else(|| self.inputs(n, &CURVE_SHADER).first().copied()),
        };
        Ok(match shader {
            Some(s) => self.arnold_shader(s)?.unwrap_or_else(tube),
            None if self.arnold_renders() => StandardHair::default().material("", &[]).0,
            None => tube(),
        })
    }

    /// The curve shader of each member of an object set that has one (MtoA's set
    /// overrides: `aiCurveShader` added to a set), by member node.
    fn set_curve_shaders(&self) -> HashMap<usize, usize> {
        let mut out = HashMap::new();
        for set in self.of_kind("objectSet") {
            if let Some(&shader) = self.inputs(set, &CURVE_SHADER).first() {
                for m in self.inputs(set, &["dsm", "dagSetMembers"]) {
                    out.entry(m).or_insert(shader);
                }
            }
        }
        out
    }

    /// The material of an Arnold shader node (a shading group is followed to its surface
    /// shader) when it is an `aiStandardHair`, its warning given once; `None` for other
    /// types, counted for one warning.
    fn arnold_shader(&mut self, s: usize) -> Res<Option<Material>> {
        let s = match self.kind(s) {
            "shadingEngine" => match self.inputs(s, &["ss", "surfaceShader"]).first() {
                Some(&shader) => shader,
                None => return Ok(None),
            },
            _ => s,
        };
        if let Some(m) = self.hair_shaders.get(&s) {
            return Ok(m.clone());
        }
        let material = match self.kind(s) {
            "aiStandardHair" => {
                let (m, warning) = self.arnold_params::<StandardHair>(s)?;
                self.out.warnings.extend(warning);
                Some(m)
            }
            other => {
                *self.unread_shaders.entry(other.to_string()).or_default() += 1;
                None
            }
        };
        self.hair_shaders.insert(s, material.clone());
        Ok(material)
    }

    /// An Arnold shader node's parameters (`aiStandardHair`, `aiStandardSurface`: MtoA names its attributes by Arnold's
    /// parameter names, `base_color`, with camel-case long names, `baseColor`; colours also
    /// by component, `base_colorR`), Arnold's defaults for those the file omits.
    fn arnold_params<S: ArnoldShader>(&self, s: usize) -> Res<(Material, Option<String>)> {
        let g = self.g;
        let mut shader = S::default();
        let mut connected = Vec::new();
        for &name in S::NAMES {
            let long = camel_case(name);
            let names = [name, long.as_str()];
            let parts = ["R", "G", "B"].map(|c| [format!("{name}{c}"), format!("{long}{c}")]);
            let mut plugs: Vec<&str> = names.to_vec();
            plugs.extend(parts.iter().flatten().map(String::as_str));
            if !self.inputs(s, &plugs).is_empty() {
                connected.push(name.to_string());
            }
            match shader.param(name) {
                Some(Param::Float(v)) => *v = scalar(g, s, &names, f64::from(*v))? as f32,
                Some(Param::Bool(b)) => *b = scalar(g, s, &names, f64::from(u8::from(*b)))? != 0.0,
                Some(Param::Color(c)) => {
                    let parts = parts.each_ref().map(|[a, b]| [a.as_str(), b.as_str()]);
                    let v = vec3(g, s, &names, &parts, f64::NAN)?;
                    for k in 0..3 {
                        if !v[k].is_nan() {
                            c[k] = v[k] as f32;
                        }
                    }
                }
                None => {}
            }
            if shader.param(name).is_some_and(|p| p.is_infinite()) {
                let node = &g.nodes[s];
                let line = attr(g, s, &plugs).map_or(node.line, |a| a.line);
                return Err((line, format!("{}: `{name}` is beyond single precision", node.name)));
            }
        }
        Ok(shader.material(&g.nodes[s].name, &connected))
    }

    // ----- fur -----

    /// Meshes a FurDescription is attached to: through the FurFeedback nodes it is
    /// connected with (their input mesh), or directly.
    fn fur_meshes(&self, n: usize) -> Vec<usize> {
        let g = self.g;
        let mut out = Vec::new();
        let mut add = |mesh: usize| {
            if let Some(&(i, ..)) = self.meshes.get(&mesh) {
                if !out.contains(&i) {
                    out.push(i);
                }
            }
        };
        for c in g.connections_of(n) {
            let other = match (c.src == n, c.dst == n) {
                (true, _) => c.dst,
                (_, true) => c.src,
                _ => continue,
            };
            match self.kind(other) {
                "mesh" => add(other),
                "FurFeedback" => {
                    for m in self.inputs(other, &["imsh", "inputMesh", "is", "inputSurface"]) {
                        add(m);
                    }
                }
                _ => {}
            }
        }
        out
    }

    // ----- camera and lights -----

    fn camera(&mut self) -> Res<()> {
        let g = self.g;
        let orthographic = |c: usize| scalar(g, c, &["o", "orthographic"], 0.0).is_ok_and(|o| o != 0.0);
        let renderable: Vec<usize> = self
            .of_kind("camera")
            .filter(|&c| scalar(g, c, &["rnd", "renderable"], 1.0).is_ok_and(|r| r != 0.0))
            .collect();
        // Perspective cameras first: an orthographic one is rendered only when it is the
        // only kind renderable (Maya's top, front and side views are not, by default).
        let cameras: Vec<usize> = renderable
            .iter()
            .copied()
            .filter(|&c| !orthographic(c))
            .chain(renderable.iter().copied().filter(|&c| orthographic(c)))
            .collect();
        let cam = match &self.wanted_camera {
            // By its transform's name (what Maya's outliner shows) or its shape's.
            Some(want) => {
                let every: Vec<usize> = self.of_kind("camera").collect();
                let transform = |c: usize| g.nodes[c].parent.as_deref().map(|p| p.rsplit('|').next().unwrap_or(p));
                let named = every.iter().find(|&&c| g.nodes[c].name == *want || transform(c) == Some(want.as_str()));
                match named {
                    Some(&c) => c,
                    None => {
                        let names: Vec<&str> =
                            every.iter().map(|&c| transform(c).unwrap_or(&g.nodes[c].name)).collect();
                        return Err((
                            0,
                            format!(
                                "no camera `{want}` in the file (its cameras: {})",
                                if names.is_empty() { "none".to_string() } else { names.join(", ") }
                            ),
                        ));
                    }
                }
            }
            None => {
                match cameras.iter().find(|&&c| g.nodes[c].name != "perspShape" && !orthographic(c)).or(cameras.first())
                {
                    Some(&c) => c,
                    None => return Ok(()),
                }
            }
        };
        let m = self.world(cam)?;
        finite_affine(g, cam, &m)?;
        let eye = m.transform_point3(DVec3::ZERO).as_vec3();
        let forward = m.transform_vector3(DVec3::NEG_Z).as_vec3().normalize_or(Vec3::NEG_Z);
        let up = m.transform_vector3(DVec3::Y).as_vec3().normalize_or(Vec3::Y);
        let coi = scalar(g, cam, &["coi", "centerOfInterest"], 5.0)?.max(1e-3) as f32;
        let focal = scalar(g, cam, &["fl", "focalLength"], 35.0)?;
        let aperture = match attr(g, cam, &["cap", "cameraAperture"]) {
            Some(a) => match &a.value {
                Value::Numbers(v) if v.len() == 2 => [v[0], v[1]],
                _ => return Err((a.line, "camera aperture must be two numbers".into())),
            },
            None => [
                scalar(g, cam, &["hfa", "horizontalFilmAperture"], 1.41732)?,
                scalar(g, cam, &["vfa", "verticalFilmAperture"], 0.94488)?,
            ],
        };
        let node = &g.nodes[cam];
        if !(focal > 0.0 && aperture[0] > 0.0 && aperture[1] > 0.0) {
            return Err((node.line, format!("camera {}: focal length and aperture must be positive", node.name)));
        }
        // Film fit: 0 fill, 1 horizontal (the node default), 2 vertical, 3 overscan.
        let fit = match scalar(g, cam, &["ff", "filmFit"], 1.0)? as i64 {
            0 => FilmFit::Fill,
            2 => FilmFit::Vertical,
            3 => FilmFit::Overscan,
            _ => FilmFit::Horizontal,
        };
        let [w, h] = self.out.resolution.unwrap_or([640, 480]);
        let cm = g.centimeters_per_unit;
        let (film, vfov, projection) = if orthographic(cam) {
            // The orthographic width spans the image width (Maya's default 30, in its
            // internal centimetres), the height following the image aspect.
            let width = scalar(g, cam, &["ow", "orthographicWidth"], 30.0 / cm)?;
            let film = Film { aperture: [width as f32; 2], fit: FilmFit::Horizontal };
            if !(width.is_finite() && width > 0.0 && film.aperture[0].is_finite()) {
                return Err((
                    node.line,
                    format!("camera {}: orthographic width {width} is not a positive size", node.name),
                ));
            }
            let height = film.fitted_height(w, h);
            (film, CameraDesc::default().vfov, CameraProjection::Orthographic { height })
        } else {
            // Aperture in inches, focal length in millimetres.
            let film = Film { aperture: aperture.map(|a| (a * 25.4 / focal) as f32), fit };
            if !film.aperture.iter().all(|a| a.is_finite() && *a > 0.0) {
                return Err((node.line, format!("camera {}: aperture over focal length out of range", node.name)));
            }
            (film, film.vfov(w, h), CameraProjection::Perspective)
        };
        // The clip planes, along the view direction: the node's defaults are in Maya's
        // internal centimetres, set values in the file's unit; the camera's scale
        // stretches them.
        let (near, far) = (
            scalar(g, cam, &["ncp", "nearClipPlane"], 0.1 / cm)?,
            scalar(g, cam, &["fcp", "farClipPlane"], 10_000.0 / cm)?,
        );
        if !(near.is_finite() && near >= 0.0 && far > near) {
            return Err((node.line, format!("camera {}: clip planes {near} and {far} are not a range", node.name)));
        }
        let stretch = m.transform_vector3(DVec3::NEG_Z).length();
        let clip = [(near * stretch) as f32, (far * stretch) as f32];
        // The camera is kept in single precision: a centre of interest or near plane finite
        // in double precision (1e39) can be infinite there; a far plane past it is none.
        let target = eye + forward * coi;
        if !target.is_finite() {
            return Err((node.line, format!("camera {}: its target {coi} away is beyond single precision", node.name)));
        }
        if !clip[0].is_finite() {
            return Err((
                node.line,
                format!("camera {}: clip planes {near} and {far} are beyond single precision", node.name),
            ));
        }
        self.out.camera = Some(CameraDesc {
            eye,
            target,
            up,
            vfov,
            projection,
            film: Some(film),
            clip,
            window: crate::scene::FULL_SCREEN,
        });
        Ok(())
    }

    /// Whether Arnold renders the file (`defaultRenderGlobals.currentRenderer` is
    /// `arnold`): Maya's own lights then light as MtoA hands them to Arnold.
    fn arnold_renders(&self) -> bool {
        let g = self.g;
        let renderer = g.find("defaultRenderGlobals").and_then(|n| attr(g, n, &["ren", "currentRenderer"]));
        matches!(renderer.map(|a| &a.value), Some(Value::Strings(s)) if s.first().is_some_and(|r| r == "arnold"))
    }

    fn lights(&mut self) -> Res<()> {
        let g = self.g;
        let arnold_renders = self.arnold_renders();
        for n in 0..g.nodes.len() {
            let kind = g.nodes[n].kind.as_str();
            if !matches!(
                kind,
                "directionalLight"
                    | "pointLight"
                    | "spotLight"
                    | "ambientLight"
                    | "areaLight"
                    | "aiSkyDomeLight"
                    | "aiAreaLight"
            ) {
                continue;
            }
            if self.hidden(n)? {
                continue;
            }
            let node = &g.nodes[n];
            // Arnold's lights call their colour `sc`.
            let color = match kind {
                "aiSkyDomeLight" | "aiAreaLight" => {
                    vec3(g, n, &["sc", "color"], &[["scr", "colorR"], ["scg", "colorG"], ["scb", "colorB"]], 1.0)?
                }
                _ => vec3(g, n, &["cl", "color"], &[["cr", "colorR"], ["cg", "colorG"], ["cb", "colorB"]], 1.0)?,
            };
            // Arnold's exposure (stops) multiplies Maya's intensity.
            let exposure = scalar(g, n, &["ai_exposure", "aiExposure"], 0.0)?;
            let intensity = scalar(g, n, &["in", "intensity"], 1.0)? * exposure.clamp(-64.0, 64.0).exp2();
            let power = (color * intensity).as_vec3();
            if !(power.is_finite() && power.min_element() >= 0.0) {
                return Err((
                    node.line,
                    format!("light {}: colour × intensity must be finite and not negative", node.name),
                ));
            }
            // Arnold lights a diffuse surface to albedo × irradiance / π, as tress does; Maya's
            // own renderer to albedo × intensity, so its intensity is π times tress's.
            let arnold = arnold_renders || kind.starts_with("ai");
            let shading = if arnold { 1.0 } else { PI };
            let m = self.world(n)?;
            finite_affine(g, n, &m)?;
            let position = m.transform_point3(DVec3::ZERO).as_vec3();
            // Maya lights shine along their local −Z.
            let along = m.transform_vector3(DVec3::NEG_Z).as_vec3().normalize_or(Vec3::NEG_Y);
            // Arnold's weight for camera rays on the lights they can meet: the sky dome's
            // `camera` (1 by default), an area light's `ai_camera` (0 by default, as Arnold
            // leaves its area lights out of the camera's view).
            let camera_weight = |names: &[&str], default: f64| -> Res<f32> {
                let w = scalar(g, n, names, default)? as f32;
                if !(w.is_finite() && w >= 0.0) {
                    let what = format!("light {}: `{}` {w} must be finite and not negative", node.name, names[0]);
                    return Err((node.line, what));
                }
                Ok(w)
            };
            let light = match kind {
                "directionalLight" => Light::Distant { direction: -along, irradiance: power * shading },
                "ambientLight" => Light::Environment { radiance: power, camera_visibility: 1.0 },
                // Arnold's sky dome: a sky of that radiance, seen by camera rays with the weight
                // of its `camera` attribute. A texture on its colour is not read.
                "aiSkyDomeLight" => {
                    if !self.inputs(n, &["sc", "color"]).is_empty() {
                        self.out.warnings.push(format!(
                            "{}: the sky dome's colour texture is not read: lit by its constant colour",
                            node.name
                        ));
                    }
                    Light::Environment { radiance: power, camera_visibility: camera_weight(&["camera"], 1.0)? }
                }
                "pointLight" | "spotLight" => {
                    // Maya's decay rate 0 (No Decay, its default), 1 linear, 2 quadratic, 3
                    // cubic: the intensity lights a surface facing the light at distance d to
                    // I / d^rate. Arnold ignores it for its own decay type (`aiDecayType`):
                    // quadratic (its default) or constant.
                    let decay = match arnold {
                        true => match scalar(g, n, &["ai_decay_type", "aiDecayType"], 1.0)? {
                            0.0 => 0,
                            _ => 2,
                        },
                        false => {
                            let rate = scalar(g, n, &["de", "decayRate"], 0.0)?;
                            if !(rate.fract() == 0.0 && (0.0..=3.0).contains(&rate)) {
                                return Err((
                                    node.line,
                                    format!("light {}: decay rate {rate} is not 0, 1, 2 or 3", node.name),
                                ));
                            }
                            rate as u8
                        }
                    };
                    // Maya and MtoA measure the distance in centimetres, Maya's internal unit,
                    // whatever unit the file is in: I / (c d)^rate = (I c^-rate) / d^rate.
                    let power = power * (g.centimeters_per_unit as f32).powi(-i32::from(decay)) * shading;
                    if kind == "pointLight" {
                        Light::Point { position, intensity: power, decay }
                    } else {
                        let cone = scalar(g, n, &["ca", "coneAngle"], 40.0)?.clamp(0.0, 180.0);
                        let penumbra = scalar(g, n, &["pa", "penumbraAngle"], 0.0)?.clamp(-90.0, 90.0);
                        let half = 0.5 * cone;
                        let (inner, outer) =
                            ((half + penumbra.min(0.0)).max(0.0), (half + penumbra.max(0.0)).min(180.0));
                        Light::Spot {
                            position,
                            direction: along,
                            intensity: power,
                            cos_inner: (inner as f32).to_radians().cos(),
                            cos_outer: (outer as f32).to_radians().cos(),
                            decay,
                        }
                    }
                }
                _ => {
                    // An area light (Maya's, or Arnold's quad) is the square −1..1 in its local
                    // XY plane.
                    let corner = m.transform_point3(DVec3::new(-1.0, -1.0, 0.0)).as_vec3();
                    let edge_u = m.transform_vector3(DVec3::new(2.0, 0.0, 0.0)).as_vec3();
                    let edge_v = m.transform_vector3(DVec3::new(0.0, 2.0, 0.0)).as_vec3();
                    // Arnold normalizes its area lights by default (`aiNormalize`): the
                    // radiance is the intensity over the area in square centimetres.
                    let normalize = arnold && scalar(g, n, &["ai_normalize", "aiNormalize", "normalize"], 1.0)? != 0.0;
                    let cm = g.centimeters_per_unit as f32;
                    let area = edge_u.cross(edge_v).length() * cm * cm;
                    let radiance = match normalize {
                        true if area > 0.0 => power / area,
                        _ => power,
                    };
                    // The quad emits towards edge_u × edge_v; Maya's area light towards −Z.
                    Light::Quad {
                        corner: corner + edge_v,
                        edge_u,
                        edge_v: -edge_v,
                        radiance,
                        camera_visibility: camera_weight(&["ai_camera", "aiCamera"], 0.0)?,
                    }
                }
            };
            // The factors after the check above (π for Maya's renderer, the decay's unit, an
            // area light's area) can take a finite power past single precision.
            let emission = match &light {
                Light::Distant { irradiance: c, .. }
                | Light::Point { intensity: c, .. }
                | Light::Spot { intensity: c, .. }
                | Light::Quad { radiance: c, .. }
                | Light::Environment { radiance: c, .. } => *c,
                _ => Vec3::ZERO,
            };
            if !emission.is_finite() {
                return Err((node.line, format!("light {}: its emission is beyond single precision", node.name)));
            }
            self.out.contents.lights.push(light.into());
        }
        Ok(())
    }
}

// ----- attribute access -----

/// The last `setAttr` of node `n` named one of `names` exactly.
fn attr<'a>(g: &'a Graph, n: usize, names: &[&str]) -> Option<&'a parse::Attr> {
    g.nodes[n].attrs.iter().rev().find(|a| names.contains(&a.name.as_str()))
}

/// Which rays see shape `n`: Maya's render stats `primaryVisibility` (short name `vis`)
/// and `castsShadows` (`csh`), and MtoA's `aiMatte` (a holdout), as MtoA hands them to
/// Arnold's `visibility` and `matte`.
fn shape_visibility(g: &Graph, n: usize) -> Res<Visibility> {
    Ok(Visibility {
        camera: scalar(g, n, &["vis", "primaryVisibility"], 1.0)? != 0.0,
        shadows: scalar(g, n, &["csh", "castsShadows"], 1.0)? != 0.0,
        matte: scalar(g, n, &["aiMatte", "ai_matte"], 0.0)? != 0.0,
    })
}

/// A number attribute, `default` when unset.
fn scalar(g: &Graph, n: usize, names: &[&str], default: f64) -> Res<f64> {
    match attr(g, n, names) {
        None => Ok(default),
        Some(a) => match &a.value {
            Value::Numbers(v) if v.len() == 1 => Ok(v[0]),
            _ => Err((a.line, format!("{}: `{}` must be one number", g.nodes[n].name, a.name))),
        },
    }
}

/// Maya's `polySphere` as Maya builds it, so follicles find their UVs where Maya puts them
/// and point tweaks move the vertices Maya moves: `sh − 1` rings of `sa` vertices from the
/// −Y pole up (ring `i` at latitude `−90° + 180° i / sh`, vertex `j` at azimuth
/// `360° (j + 1) / sa` turning from +X towards −Z), numbered ring by ring from the bottom,
/// then the −Y and the +Y pole; quads between the rings and a triangle per column at each
/// pole, wound outwards. UV `(j / sa, i / sh)` with the seam column repeated at u = 1, and
/// at a pole the middle of its triangle's column, `v` 0 below and 1 above.
fn poly_sphere(radius: f32, sa: u32, sh: u32) -> PolyMesh {
    use std::f32::consts::{FRAC_PI_2, PI, TAU};
    let mut positions = Vec::new();
    let mut uvs = Vec::new();
    for i in 1..sh {
        let lat = -FRAC_PI_2 + PI * i as f32 / sh as f32;
        positions.extend((0..sa).map(|j| {
            let a = TAU * (j + 1) as f32 / sa as f32;
            radius * Vec3::new(lat.cos() * a.cos(), lat.sin(), -lat.cos() * a.sin())
        }));
        uvs.extend((0..=sa).map(|j| [j as f32 / sa as f32, i as f32 / sh as f32]));
    }
    let (bottom, top) = (positions.len() as u32, positions.len() as u32 + 1);
    positions.extend([-radius * Vec3::Y, radius * Vec3::Y]);
    let poles = uvs.len();
    for v in [0.0, 1.0] {
        uvs.extend((0..sa).map(|j| [(j as f32 + 0.5) / sa as f32, v]));
    }
    // Vertex and UV of ring `i` (1 to sh − 1), column `j` (0 to sa).
    let vertex = |i: u32, j: u32| (i - 1) * sa + j % sa;
    let uv = |i: u32, j: u32| ((i - 1) * (sa + 1) + j) as i64;
    let mut polygons: Vec<Polygon> = Vec::new();
    for i in 1..sh - 1 {
        for j in 0..sa {
            let corners = [(i, j), (i, j + 1), (i + 1, j + 1), (i + 1, j)];
            polygons.push((
                corners.iter().map(|&(i, j)| vertex(i, j)).collect(),
                Some(corners.iter().map(|&(i, j)| uv(i, j)).collect()),
            ));
        }
    }
    for j in 0..sa {
        let pole = (poles + j as usize) as i64;
        polygons.push((vec![vertex(1, j + 1), vertex(1, j), bottom], Some(vec![uv(1, j + 1), uv(1, j), pole])));
    }
    for j in 0..sa {
        let (last, pole) = (sh - 1, (poles + (sa + j) as usize) as i64);
        polygons
            .push((vec![vertex(last, j), vertex(last, j + 1), top], Some(vec![uv(last, j), uv(last, j + 1), pole])));
    }
    PolyMesh { positions, uvs, polygons, smooth: true }
}

/// The rotation a primitive node's `axis` (`.ax`, Maya's default +Y) gives what it
/// builds about +Y: the shortest turn from +Y to it; none when unset or of no length.
fn primitive_axis(g: &Graph, n: usize) -> Res<Affine3A> {
    let axis = vec3(g, n, &["ax", "axis"], &[["axx", "axisX"], ["axy", "axisY"], ["axz", "axisZ"]], 0.0)?;
    Ok(match axis.as_vec3().try_normalize().filter(|_| attr(g, n, &["ax", "axis"]).is_some()) {
        Some(axis) => Affine3A::from_quat(glam::Quat::from_rotation_arc(Vec3::Y, axis)),
        None => Affine3A::IDENTITY,
    })
}

/// Maya's `polyCube` of `size` (width along X, height along Y, depth along Z, centred on
/// the origin) with `divisions` faces along each, its vertices numbered, its faces ordered
/// and its UVs laid out as Maya's, read from the meshes Maya stores for its cubes (the
/// MtoA suite's `test_0152` keeps an unsubdivided one as `pCubeShape1_reference`;
/// subdivided ones show how the layout grows):
///
/// - **vertices**: first a strip of rows around the X axis, `sw + 1` vertices each from −X
///   to +X: up the front (+Z) from the bottom, back across the top, down the back, forward
///   under the bottom, `2 sh + 2 sd` rows in all; then the inner vertices of the +X side,
///   then those of the −X side, each by rows from the bottom and from −Z to +Z in a row.
/// - **faces**: the strip's quads row by row (front, top, back, bottom), then the +X side's
///   and the −X side's, each by rows from the bottom and from −Z in a row; all wound to
///   face outwards.
/// - **UVs** (when `with_uvs`): the cross of Maya's default layout, each side a quarter
///   wide: the strip at u 0.375 to 0.625 over v 0 to 1 (a quarter of v per side), the +X
///   side at u 0.625 to 0.875 and the −X side at u 0.125 to 0.375, both at v 0 to 0.25.
///
/// Flat shaded: Maya's cube edges are hard.
fn poly_cube(size: Vec3, divisions: [u32; 3], with_uvs: bool) -> PolyMesh {
    let [sw, sh, sd] = divisions;
    let rows = 2 * sh + 2 * sd;
    let half = size / 2.0;
    let x = |i: u32| -half.x + size.x * i as f32 / sw as f32;
    let y = |a: u32| -half.y + size.y * a as f32 / sh as f32;
    let z = |b: u32| -half.z + size.z * b as f32 / sd as f32;
    // Where strip row `r` runs (y, z), and its v.
    let row = |r: u32| -> (f32, f32, f32) {
        let quarter = |k: u32, t: f32| 0.25 * (k as f32 + t);
        if r <= sh {
            (y(r), half.z, quarter(0, r as f32 / sh as f32))
        } else if r <= sh + sd {
            (half.y, z(sd - (r - sh)), quarter(1, (r - sh) as f32 / sd as f32))
        } else if r <= 2 * sh + sd {
            (y(sh - (r - sh - sd)), -half.z, quarter(2, (r - sh - sd) as f32 / sh as f32))
        } else {
            (-half.y, z(r - 2 * sh - sd), quarter(3, (r - 2 * sh - sd) as f32 / sd as f32))
        }
    };
    let mut positions = Vec::new();
    for r in 0..rows {
        let (py, pz, _) = row(r);
        positions.extend((0..=sw).map(|i| Vec3::new(x(i), py, pz)));
    }
    let inner = (sh - 1) * (sd - 1);
    for side_x in [half.x, -half.x] {
        for a in 1..sh {
            positions.extend((1..sd).map(|b| Vec3::new(side_x, y(a), z(b))));
        }
    }
    let strip = |r: u32, i: u32| (r % rows) * (sw + 1) + i;
    // The vertex at height step `a`, depth step `b` of the side at strip column `i` (0: −X,
    // sw: +X): on the strip at the side's border, else one of the side's inner vertices.
    let side = |i: u32, a: u32, b: u32| -> u32 {
        if b == sd {
            strip(a, i)
        } else if a == sh {
            strip(sh + sd - b, i)
        } else if b == 0 {
            strip(2 * sh + sd - a, i)
        } else if a == 0 {
            strip(2 * sh + sd + b, i)
        } else {
            let first = rows * (sw + 1) + if i == 0 { inner } else { 0 };
            first + (a - 1) * (sd - 1) + (b - 1)
        }
    };
    // UVs: the strip's grid, then each side's, numbered as pushed.
    let mut uvs = Vec::new();
    for r in 0..=rows {
        let v = if r == rows { 1.0 } else { row(r).2 };
        uvs.extend((0..=sw).map(|i| [0.375 + 0.25 * i as f32 / sw as f32, v]));
    }
    let side_uv = |first: usize, a: u32, b: u32| (first + (a * (sd + 1) + b) as usize) as i64;
    let (plus_x, minus_x) = (uvs.len(), uvs.len() + ((sh + 1) * (sd + 1)) as usize);
    for u0 in [0.875, 0.125] {
        for a in 0..=sh {
            // +X runs from u 0.875 at −Z to 0.625 at +Z, −X from 0.125 at −Z to 0.375.
            let dir = if u0 > 0.5 { -1.0 } else { 1.0 };
            uvs.extend((0..=sd).map(|b| [u0 + dir * 0.25 * b as f32 / sd as f32, 0.25 * a as f32 / sh as f32]));
        }
    }
    let mut polygons: Vec<Polygon> = Vec::new();
    for r in 0..rows {
        for i in 0..sw {
            let at = |r: u32, i: u32| (r * (sw + 1) + i) as i64;
            polygons.push((
                vec![strip(r, i), strip(r, i + 1), strip(r + 1, i + 1), strip(r + 1, i)],
                Some(vec![at(r, i), at(r, i + 1), at(r + 1, i + 1), at(r + 1, i)]),
            ));
        }
    }
    for (i, first) in [(sw, plus_x), (0, minus_x)] {
        for a in 0..sh {
            for b in 0..sd {
                // Counter-clockwise seen from outside: +X from its +Z edge, −X from its −Z.
                let corners = match i {
                    0 => [(a, b), (a, b + 1), (a + 1, b + 1), (a + 1, b)],
                    _ => [(a, b + 1), (a, b), (a + 1, b), (a + 1, b + 1)],
                };
                polygons.push((
                    corners.iter().map(|&(a, b)| side(i, a, b)).collect(),
                    Some(corners.iter().map(|&(a, b)| side_uv(first, a, b)).collect()),
                ));
            }
        }
    }
    if !with_uvs {
        uvs.clear();
        for p in &mut polygons {
            p.1 = None;
        }
    }
    PolyMesh { positions, uvs, polygons, smooth: false }
}

/// Maya's `polyCylinder` of `radius` and `height` (along Y, centred on the origin) with
/// `[sa, sh, sc]` subdivisions around, along and on the caps (`sc` 0: each cap one
/// polygon; 1: a fan of triangles), numbered as in the cylinders Maya stores (the MtoA
/// suite's, of 20 sides, 1 and 10 rows, `sc` 1):
///
/// - **vertices**: `sh + 1` rings of `sa` from the bottom up, vertex `j` of a ring at the
///   azimuth `360° (j + 1) / sa` turning from +X towards −Z (as `polySphere`'s); then the
///   bottom cap's centre and the top's (`sc` 1).
/// - **faces**: the side's quads row by row from the bottom, then the bottom cap's, then
///   the top's (a triangle per side each, `sc` 1), all wound to face outwards.
/// - **UVs** (when `with_uvs`): the bottom cap on a circle of radius 0.15625 about
///   (0.5, 0.15625), the side a grid of `sa + 1` columns (the seam repeated) from u 0.375
///   to 0.625 and v 0.3125 to 0.68844, the top cap on the circle about (0.5, 0.84375)
///   mirrored, then the caps' centres at (0.5, 0.15) and (0.5, 0.8375), as stored.
///
/// Smooth shaded: most of Maya's cylinder edges are soft (all but the rims).
fn poly_cylinder(radius: f32, height: f32, [sa, sh, sc]: [u32; 3], with_uvs: bool) -> PolyMesh {
    use std::f32::consts::TAU;
    let angle = |j: u32| TAU * (j % sa + 1) as f32 / sa as f32;
    let mut positions = Vec::new();
    for i in 0..=sh {
        let y = -height / 2.0 + height * i as f32 / sh as f32;
        positions.extend((0..sa).map(|j| Vec3::new(radius * angle(j).cos(), y, -radius * angle(j).sin())));
    }
    let ring = |i: u32, j: u32| i * sa + j % sa;
    let (bottom, top) = (positions.len() as u32, positions.len() as u32 + 1);
    if sc > 0 {
        positions.extend([Vec3::new(0.0, -height / 2.0, 0.0), Vec3::new(0.0, height / 2.0, 0.0)]);
    }
    // UVs: the bottom circle (0..sa), the side grid, the top circle, the centres.
    const R: f32 = 0.15625;
    let circle = |v0: f32, k: u32| [0.5 + R * angle(k).cos(), v0 - R * angle(k).sin()];
    let mut uvs: Vec<[f32; 2]> = (0..sa).map(|k| circle(R, k)).collect();
    let grid = uvs.len() as u32;
    for i in 0..=sh {
        let v = 0.3125 + 0.37593985 * i as f32 / sh as f32;
        uvs.extend((0..=sa).map(|j| [0.375 + 0.25 * j as f32 / sa as f32, v]));
    }
    let upper = uvs.len() as u32;
    uvs.extend((0..sa).map(|k| circle(1.0 - R, k)));
    let centres = uvs.len() as u32;
    uvs.extend([[0.5, 0.15], [0.5, 0.8375]]);
    let side_uv = |i: u32, j: u32| (grid + i * (sa + 1) + j) as i64;
    // The top circle is mirrored: vertex j of the top ring at its UV sa − 2 − j.
    let top_uv = |j: u32| (upper + (2 * sa - 2 - j) % sa) as i64;
    let mut polygons: Vec<Polygon> = Vec::new();
    for i in 0..sh {
        for j in 0..sa {
            polygons.push((
                vec![ring(i, j), ring(i, j + 1), ring(i + 1, j + 1), ring(i + 1, j)],
                Some(vec![side_uv(i, j), side_uv(i, j + 1), side_uv(i + 1, j + 1), side_uv(i + 1, j)]),
            ));
        }
    }
    let bottom_uv = |j: u32| (j % sa) as i64;
    if sc == 0 {
        polygons.push(((0..sa).rev().map(|j| ring(0, j)).collect(), Some((0..sa).rev().map(bottom_uv).collect())));
        polygons.push(((0..sa).map(|j| ring(sh, j)).collect(), Some((0..sa).map(top_uv).collect())));
    } else {
        for j in 0..sa {
            polygons.push((
                vec![ring(0, j + 1), ring(0, j), bottom],
                Some(vec![bottom_uv(j + 1), bottom_uv(j), centres as i64]),
            ));
        }
        for j in 0..sa {
            polygons.push((
                vec![ring(sh, j), ring(sh, j + 1), top],
                Some(vec![top_uv(j), top_uv(j + 1), centres as i64 + 1]),
            ));
        }
    }
    if !with_uvs {
        uvs.clear();
        for p in &mut polygons {
            p.1 = None;
        }
    }
    PolyMesh { positions, uvs, polygons, smooth: true }
}

/// The matrix a `transformGeometry` node applies to the geometry passing through it: its
/// `transform` (`.txf`), in Maya's layout (a point is the row `[x y z 1]` times the matrix,
/// so the translation is the last row), inverted when `invertTransform` (`.itf`) is on.
fn transform_geometry(g: &Graph, n: usize) -> Res<Affine3A> {
    let node = &g.nodes[n];
    let Some(a) = attr(g, n, &["txf", "transform"]) else { return Ok(Affine3A::IDENTITY) };
    let bad = |m: &str| (a.line, format!("transformGeometry {}: `{}` {m}", node.name, a.name));
    let Value::Numbers(v) = &a.value else { return Err(bad("must be 16 numbers")) };
    if v.len() != 16 {
        return Err(bad("must be 16 numbers"));
    }
    if [v[3], v[7], v[11]] != [0.0; 3] || v[15] != 1.0 {
        return Err(bad("is not an affine matrix (its last column must be 0 0 0 1)"));
    }
    let row = |k: usize| DVec3::new(v[4 * k], v[4 * k + 1], v[4 * k + 2]);
    let mut m = DAffine3::from_cols(row(0), row(1), row(2), row(3));
    if scalar(g, n, &["itf", "invertTransform"], 0.0)? != 0.0 {
        if m.matrix3.determinant() == 0.0 {
            return Err(bad("cannot be inverted (invertTransform is on)"));
        }
        m = m.inverse();
    }
    let m = to_affine(&m);
    match m.is_finite() {
        true => Ok(m),
        false => Err(bad("overflows single precision")),
    }
}

/// A three-component attribute set whole (`.t`) or by component (`.tx`), in file order.
fn vec3(g: &Graph, n: usize, whole: &[&str], parts: &[[&str; 2]; 3], default: f64) -> Res<DVec3> {
    let mut v = DVec3::splat(default);
    for a in &g.nodes[n].attrs {
        let k = parts.iter().position(|p| p.contains(&a.name.as_str()));
        if k.is_none() && !whole.contains(&a.name.as_str()) {
            continue;
        }
        let bad = || (a.line, format!("{}: `{}` has the wrong number of values", g.nodes[n].name, a.name));
        let Value::Numbers(x) = &a.value else { return Err(bad()) };
        match (k, x.as_slice()) {
            (Some(k), [x]) => v[k] = *x,
            (None, [x, y, z]) => v = DVec3::new(*x, *y, *z),
            _ => return Err(bad()),
        }
    }
    Ok(v)
}

/// MtoA's long attribute name for an Arnold parameter: `base_color` → `baseColor`.
fn camel_case(name: &str) -> String {
    let mut out = String::with_capacity(name.len());
    let mut upper = false;
    for c in name.chars() {
        match c {
            '_' => upper = true,
            c if upper => {
                out.extend(c.to_uppercase());
                upper = false;
            }
            c => out.push(c),
        }
    }
    out
}

/// The attribute name of a plug without its index: `ih[0]` → `ih`.
fn plug_base(plug: &str) -> &str {
    plug.split(['[', '.']).next().unwrap_or(plug)
}

/// The last attribute of a plug like `ip[0].ig` (`ig`), without its index.
fn plug_leaf(plug: &str) -> &str {
    let last = plug.rsplit('.').next().unwrap_or(plug);
    last.split('[').next().unwrap_or(last)
}

/// A mesh component of a component list, `f[2]`, `f[0:3]` or `f[*]`: its kind (`f`, `vtx`,
/// `e`, ...) and the range of indices it covers, `None` for all.
fn component(c: &str) -> Option<(&str, Option<(usize, usize)>)> {
    let (kind, rest) = c.split_once('[')?;
    let inner = rest.strip_suffix(']')?;
    if inner == "*" {
        return Some((kind, None));
    }
    let (a, b) = inner.split_once(':').unwrap_or((inner, inner));
    Some((kind, Some((a.parse().ok()?, b.parse().ok()?))))
}

/// The index of a plug like `ih[3]`.
fn plug_index(plug: &str) -> Option<usize> {
    let (_, rest) = plug.split_once('[')?;
    rest.split(']').next()?.parse().ok()
}

/// The element range an attribute name covers under `base`: `base[a:b]`, `base[a]` or
/// `base` alone (from 0, as many as the values fill).
fn element_range(name: &str, base: &str) -> Option<(usize, Option<usize>)> {
    let rest = name.strip_prefix(base)?;
    if rest.is_empty() {
        return Some((0, None));
    }
    let inner = rest.strip_prefix('[')?.strip_suffix(']')?;
    match inner.split_once(':') {
        Some((a, b)) => Some((a.parse().ok()?, Some(b.parse().ok()?))),
        None => {
            let a = inner.parse().ok()?;
            Some((a, Some(a)))
        }
    }
}

/// The vertex and axis (0 x, 1 y, 2 z) of one component of a mesh's point tweak,
/// `pt[3].px` (`pnts[3].pntx` in long names).
fn tweak_component(name: &str) -> Option<(usize, usize)> {
    let (base, rest) = name.split_once('[')?;
    let (index, leaf) = rest.split_once("].")?;
    let axis = match (base, leaf) {
        ("pt" | "pnts", "px" | "pntx") => 0,
        ("pt" | "pnts", "py" | "pnty") => 1,
        ("pt" | "pnts", "pz" | "pntz") => 2,
        _ => return None,
    };
    Some((index.parse().ok()?, axis))
}

/// A mesh's point tweaks by vertex: the offsets Maya adds to its vertices (or to those its
/// construction history builds), set whole (`.pt[0:5]`, three numbers a vertex) or by
/// component (`.pt[3].px`, also what an animation curve drives), in file order.
fn point_tweaks(g: &Graph, n: usize) -> Res<BTreeMap<usize, DVec3>> {
    let mut out: BTreeMap<usize, DVec3> = BTreeMap::new();
    for a in &g.nodes[n].attrs {
        if let Some((i, axis)) = tweak_component(&a.name) {
            match &a.value {
                Value::Numbers(v) if v.len() == 1 => out.entry(i).or_default()[axis] = v[0],
                _ => return Err((a.line, format!("{}: `{}` must be one number", g.nodes[n].name, a.name))),
            }
        }
        let Some((start, end)) = element_range(&a.name, "pt").or_else(|| element_range(&a.name, "pnts")) else {
            continue;
        };
        let v = match &a.value {
            Value::Numbers(v)
                if v.len() % 3 == 0 && end.is_none_or(|e| e >= start && v.len() == 3 * (e - start + 1)) =>
            {
                v
            }
            _ => {
                return Err((a.line, format!("{}: `{}` must be three numbers a vertex", g.nodes[n].name, a.name)));
            }
        };
        for (k, d) in v.chunks(3).enumerate() {
            out.insert(start + k, DVec3::new(d[0], d[1], d[2]));
        }
    }
    Ok(out)
}

/// Elements of `k` numbers of an array attribute (written in chunks like `vt[0:99]`),
/// by index.
fn elements(g: &Graph, n: usize, bases: &[&str], k: usize) -> Res<BTreeMap<usize, Vec<f64>>> {
    let mut out = BTreeMap::new();
    for a in &g.nodes[n].attrs {
        let Some((start, end)) = bases.iter().find_map(|b| element_range(&a.name, b)) else { continue };
        let Value::Numbers(v) = &a.value else {
            return Err((a.line, format!("{}: `{}` must be numbers", g.nodes[n].name, a.name)));
        };
        let count = match end {
            Some(e) if e >= start => (e - start).saturating_add(1),
            Some(_) => return Err((a.line, format!("{}: `{}` is an empty range", g.nodes[n].name, a.name))),
            None => v.len() / k,
        };
        if Some(v.len()) != count.checked_mul(k) {
            return Err((
                a.line,
                format!("{}: `{}` has {} values for {count} elements of {k}", g.nodes[n].name, a.name, v.len()),
            ));
        }
        // Geometry is stored in single precision: a value past its range (`1e39`) would
        // become infinite there.
        if let Some(x) = v.iter().find(|x| !(**x as f32).is_finite()) {
            return Err((a.line, format!("{}: `{}` holds {x}, beyond single precision", g.nodes[n].name, a.name)));
        }
        for (i, chunk) in v.chunks(k).enumerate() {
            out.insert(start + i, chunk.to_vec());
        }
    }
    Ok(out)
}

/// The elements `0..len` with none missing.
fn dense(g: &Graph, n: usize, what: &str, map: BTreeMap<usize, Vec<f64>>) -> Res<Vec<Vec<f64>>> {
    let len = map.len();
    if let Some((i, _)) = map.iter().enumerate().find(|(i, (k, _))| *i != **k) {
        return Err((g.nodes[n].line, format!("{}: {what} {i} is missing", g.nodes[n].name)));
    }
    let out: Vec<Vec<f64>> = map.into_values().collect();
    debug_assert_eq!(out.len(), len);
    Ok(out)
}

// ----- geometry -----

fn euler(r: DVec3, order: i64) -> Option<DMat3> {
    let (x, y, z) = (DMat3::from_rotation_x(r.x), DMat3::from_rotation_y(r.y), DMat3::from_rotation_z(r.z));
    // The order names the first rotation applied first: xyz is z · y · x for column vectors.
    Some(match order {
        0 => z * y * x,
        1 => x * z * y,
        2 => y * x * z,
        3 => y * z * x,
        4 => z * x * y,
        5 => x * y * z,
        _ => return None,
    })
}

fn to_affine(m: &DAffine3) -> Affine3A {
    Affine3A::from_cols_array(&m.to_cols_array().map(|x| x as f32))
}

/// The world matrix of node `n` in single precision, refused when it does not fit.
fn finite_affine(g: &Graph, n: usize, m: &DAffine3) -> Res<Affine3A> {
    let a = to_affine(m);
    match a.is_finite() {
        true => Ok(a),
        false => Err((g.nodes[n].line, format!("{}: its transforms overflow single precision", g.nodes[n].name))),
    }
}

/// The direction of increasing U across triangle `t` (from its UV gradient).
fn tangent_u(mesh: &TriangleMesh, t: u32) -> Option<Vec3> {
    let uvs = mesh.uvs.as_ref()?;
    let [a, b, c] = mesh.corners(t);
    let [ta, tb, tc] = mesh.indices[t as usize].map(|i| uvs[i as usize]);
    let (e1, e2) = (b - a, c - a);
    let (du1, dv1, du2, dv2) = (tb[0] - ta[0], tb[1] - ta[1], tc[0] - ta[0], tc[1] - ta[1]);
    let det = du1 * dv2 - du2 * dv1;
    (det != 0.0).then(|| (e1 * dv2 - e2 * dv1) / det)
}

/// The mesh a `mesh` node stores, its point tweaks applied; `None` when it stores no faces.
fn stored_mesh(g: &Graph, n: usize) -> Res<Option<PolyMesh>> {
    let node = &g.nodes[n];
    let vt = dense(g, n, "vertex", elements(g, n, &["vt", "vrts"], 3)?)?;
    let tweaks = point_tweaks(g, n)?;
    let edges = dense(g, n, "edge", elements(g, n, &["ed", "edge"], 3)?)?;
    let uvs = dense(g, n, "uv", elements(g, n, &["uvst[0].uvsp", "uvSet[0].uvSetPoints"], 2)?)?;
    let mut chunks: Vec<(usize, u32, &Vec<Face>)> = Vec::new();
    for a in &node.attrs {
        if let Some((start, _)) = element_range(&a.name, "fc").or_else(|| element_range(&a.name, "face")) {
            match &a.value {
                Value::Faces(f) => chunks.push((start, a.line, f)),
                _ => return Err((a.line, format!("{}: `{}` must have -type \"polyFaces\"", node.name, a.name))),
            }
        }
    }
    if chunks.is_empty() {
        return Ok(None);
    }
    chunks.sort_by_key(|c| c.0);
    let mut positions: Vec<Vec3> = vt.iter().map(|v| DVec3::new(v[0], v[1], v[2]).as_vec3()).collect();
    for (i, d) in tweaks {
        if let Some(p) = positions.get_mut(i) {
            *p += d.as_vec3();
        }
    }
    let uvs: Vec<[f32; 2]> = uvs.iter().map(|uv| [uv[0] as f32, uv[1] as f32]).collect();
    let mut polygons = Vec::new();
    for (_, line, faces) in chunks {
        for f in faces {
            let mut loop_: Vec<u32> = Vec::with_capacity(f.edges.len());
            for &e in &f.edges {
                let (index, end) = if e >= 0 { (e as usize, 0) } else { ((-e - 1) as usize, 1) };
                let edge = edges
                    .get(index)
                    .ok_or((line, format!("{}: a face uses edge {index} of {}", node.name, edges.len())))?;
                let v = edge[end];
                if !(v >= 0.0 && (v as usize) < positions.len()) {
                    return Err((line, format!("{}: edge {index} uses vertex {v} of {}", node.name, positions.len())));
                }
                loop_.push(v as u32);
            }
            let face_uvs = f.uvs.clone().filter(|u| !uvs.is_empty() && u.len() == loop_.len());
            if let Some(&uv) = face_uvs.iter().flatten().find(|&&uv| uv >= 0 && uv as usize >= uvs.len()) {
                return Err((line, format!("{}: a face uses UV {uv} of {}", node.name, uvs.len())));
            }
            polygons.push((loop_, face_uvs));
        }
    }
    // Edges flagged smooth (third value 1) mean Maya shades with vertex normals.
    let smooth = edges.iter().filter(|e| e[2] != 0.0).count();
    let smooth = smooth * 2 >= edges.len() && !edges.is_empty();
    // Faces that are all empty chunks draw nothing: as a mesh storing no faces.
    if polygons.is_empty() {
        return Ok(None);
    }
    Ok(Some(PolyMesh { positions, uvs, polygons, smooth }))
}

/// A polygon: its vertices in order and, when it has UVs, the UV of each corner (an index
/// into the mesh's UVs, −1 for none).
type Polygon = (Vec<u32>, Option<Vec<i64>>);

/// A polygon mesh by Maya's numbers, as a stored mesh holds it or a primitive node builds
/// it: what history edits (`transformGeometry` moves its vertices, `deleteComponent`
/// removes faces) and point tweaks index, before it is subdivided and triangulated
/// ([`PolyMesh::polygon_mesh`]).
struct PolyMesh {
    /// Vertex positions, by Maya vertex number.
    positions: Vec<Vec3>,
    /// UV set 0.
    uvs: Vec<[f32; 2]>,
    /// The faces, by Maya face number.
    polygons: Vec<Polygon>,
    /// Shaded with vertex normals (most of its edges soft).
    smooth: bool,
}

impl PolyMesh {
    /// Its polygons over all its vertices (those no face uses are left out when it is
    /// triangulated), with the UV of each corner when the mesh has UVs ((0, 0) for a corner
    /// without one): triangulated, a vertex splits where its corners' UVs differ.
    fn polygon_mesh(&self) -> PolygonMesh {
        let mut mesh = PolygonMesh { positions: self.positions.clone(), ..Default::default() };
        let mut uvs = Vec::with_capacity(self.polygons.iter().map(|p| p.0.len()).sum());
        for (loop_, face_uvs) in &self.polygons {
            mesh.counts.push(loop_.len() as u32);
            mesh.indices.extend(loop_);
            for k in 0..loop_.len() {
                let uv = face_uvs.as_ref().map_or(-1, |u| u[k]);
                uvs.push(if uv >= 0 { self.uvs[uv as usize] } else { [0.0; 2] });
            }
        }
        if !self.uvs.is_empty() {
            mesh.uvs = Some(uvs);
        }
        mesh
    }

    /// For each triangle of its polygons triangulated as fans, its polygon's first Ptex face
    /// and how many it has ([`Faces::Of`]).
    fn ptex_faces(&self) -> Vec<[u32; 2]> {
        let mut faces = Vec::new();
        let mut ptex = 0u32;
        for (loop_, _) in &self.polygons {
            let subfaces = if loop_.len() == 4 { 1 } else { loop_.len() as u32 };
            faces.extend(std::iter::repeat_n([ptex, subfaces], loop_.len().saturating_sub(2)));
            ptex += subfaces;
        }
        faces
    }
}

/// A mesh as construction history builds it, before it is drawn.
enum Built {
    /// Polygons by Maya's numbers (stored meshes, `polyCube`, `polyCylinder`).
    Poly(PolyMesh),
    /// Polygons whose faces tress does not number as Maya does (`polySphere`, `polyTorus`,
    /// `polyPlane`, `polyCylinder` with caps of several rings).
    Primitive(Primitive),
}

impl Built {
    /// Moves its vertices by `m`.
    fn transform(&mut self, m: &Affine3A) {
        let (Built::Poly(p) | Built::Primitive(Primitive { mesh: p, .. })) = self;
        p.positions.iter_mut().for_each(|q| *q = m.transform_point3(*q));
    }

    /// Adds point tweaks by Maya vertex number; `false` (nothing moved) when tress does not
    /// know which of its vertices is which Maya vertex.
    fn tweak(&mut self, tweaks: &BTreeMap<usize, DVec3>) -> bool {
        let (Built::Poly(p) | Built::Primitive(Primitive { mesh: p, numbered: true, .. })) = self else {
            return false;
        };
        for (&i, d) in tweaks {
            if let Some(q) = p.positions.get_mut(i) {
                *q += d.as_vec3();
            }
        }
        true
    }

    /// Its polygons, with how many (Ptex) faces Maya gives it when tress does not number
    /// them as Maya does.
    fn finish(self) -> (PolyMesh, Option<u32>) {
        match self {
            Built::Poly(p) => (p, None),
            Built::Primitive(p) => (p.mesh, Some(p.faces)),
        }
    }
}

/// The polygons of a primitive node whose faces tress does not number as Maya does.
struct Primitive {
    /// Its polygons.
    mesh: PolyMesh,
    /// How many (Ptex) faces Maya gives it.
    faces: u32,
    /// Whether its vertices are numbered as Maya's (what point tweaks are indexed by).
    numbered: bool,
}

/// How a drawn mesh's triangles relate to the faces an XGen patch lists. XGen numbers
/// faces as Ptex does (its maps are Ptex files): a quad is one face, any other polygon of
/// `n` sides `n` faces, one per corner, in the mesh's face order (`test_0140`'s 20 × 20
/// sphere, 360 quads and 40 triangles, lists 480).
#[derive(Clone, Debug)]
enum Faces {
    /// For each triangle, its polygon's first Ptex face and how many it has (a mesh that
    /// stores its faces).
    Of(Vec<[u32; 2]>),
    /// Only how many Ptex faces the mesh has (built by a primitive node, whose faces tress
    /// does not number as Maya does).
    Count(u32),
}

/// The geometry a curve node stores (its last `.cc` block), if any.
fn cc_block(g: &Graph, n: usize) -> Option<&parse::Attr> {
    g.nodes[n].attrs.iter().rev().find(|a| a.name == "cc" || a.name == "cached")
}

/// Reads a `.cc` block: `degree spans form rational dimension`, the knot count and knots
/// (Maya leaves out the first and last knot of the full vector), the CV count and CVs.
fn nurbs_block(w: &[f64]) -> Result<Nurbs, String> {
    let int = |i: usize, what: &str| -> Result<usize, String> {
        let v = *w.get(i).ok_or_else(|| format!("the block ends before the {what}"))?;
        match v >= 0.0 && v.fract() == 0.0 && v <= MAX_CVS as f64 {
            true => Ok(v as usize),
            false => Err(format!("{what} {v} is not a count")),
        }
    };
    let degree = int(0, "degree")?;
    let spans = int(1, "span count")?;
    let rational = w.get(3).copied().unwrap_or(0.0) != 0.0;
    let dim = int(4, "dimension")?;
    if !(1..=7).contains(&degree) || !(2..=3).contains(&dim) {
        return Err(format!("degree {degree} (1 to 7) or dimension {dim} (2 or 3) not supported"));
    }
    let knots = int(5, "knot count")?;
    let cv_at = 6 + knots;
    let cvs = int(cv_at, "CV count")?;
    if cvs != spans + degree || knots != cvs + degree - 1 {
        return Err(format!(
            "{cvs} CVs and {knots} knots do not fit {spans} spans of degree {degree} (expected {} and {})",
            spans + degree,
            spans + 2 * degree - 1
        ));
    }
    let per = dim + usize::from(rational);
    let end = cv_at + 1 + cvs * per;
    if w.len() != end {
        return Err(format!("{} numbers where the header promises {end}", w.len()));
    }
    let inner = &w[6..cv_at];
    let mut full = Vec::with_capacity(knots + 2);
    full.push(inner[0]);
    full.extend_from_slice(inner);
    full.push(inner[knots - 1]);
    let cvs = w[cv_at + 1..]
        .chunks(per)
        .map(|c| {
            let (x, y, z) = (c[0] as f32, c[1] as f32, if dim == 3 { c[2] as f32 } else { 0.0 });
            let wt = if rational { c[per - 1] as f32 } else { 1.0 };
            Vec4::new(x * wt, y * wt, z * wt, wt)
        })
        .collect();
    let curve = Nurbs { degree, knots: full, cvs };
    curve.validate()?;
    Ok(curve)
}

// ----- hair system attributes -----

/// A hairSystem's render attributes (spec section 5), from the node defaults.
fn hair_attributes(g: &Graph, n: usize) -> Res<HairSystem> {
    let mut s = HairSystem::default();
    let f = |names: &[&str], d: f32| -> Res<f32> { Ok(scalar(g, n, names, d as f64)? as f32) };
    let count = |names: &[&str], d: u32| -> Res<u32> {
        let v = scalar(g, n, names, d as f64)?;
        match v >= 0.0 && v <= u32::MAX as f64 {
            true => Ok(v as u32),
            false => Err((attr(g, n, names).map_or(0, |a| a.line), format!("`{}` = {v} is not a count", names[1]))),
        }
    };
    s.hairs_per_clump = count(&["hpc", "hairsPerClump"], s.hairs_per_clump)?;
    s.sub_segments = count(&["ssg", "subSegments"], s.sub_segments)?;
    s.thinning = f(&["thn", "thinning"], s.thinning)?;
    s.clump_width = f(&["cwd", "clumpWidth"], s.clump_width)?;
    s.clump_twist = f(&["ctw", "clumpTwist"], s.clump_twist)?;
    s.bend_follow = f(&["bnf", "bendFollow"], s.bend_follow)?;
    s.hair_width = f(&["hwd", "hairWidth"], s.hair_width)?;
    s.curl = f(&["crl", "curl"], s.curl)?;
    s.curl_frequency = f(&["crf", "curlFrequency"], s.curl_frequency)?;
    s.noise = f(&["noi", "noise"], s.noise)?;
    s.noise_frequency = f(&["nof", "noiseFrequency"], s.noise_frequency)?;
    s.noise_frequency_u = f(&["nfu", "noiseFrequencyU"], s.noise_frequency_u)?;
    s.noise_frequency_v = f(&["nfv", "noiseFrequencyV"], s.noise_frequency_v)?;
    s.noise_frequency_w = f(&["nfw", "noiseFrequencyW"], s.noise_frequency_w)?;
    s.opacity = f(&["opc", "opacity"], s.opacity)?;
    s.translucence = f(&["tlc", "translucence"], s.translucence)?;
    s.specular_power = f(&["spp", "specularPower"], s.specular_power)?;
    s.diffuse_rand = f(&["dfr", "diffuseRand"], s.diffuse_rand)?;
    s.specular_rand = f(&["sra", "specularRand"], s.specular_rand)?;
    s.hue_rand = f(&["chr", "hueRand"], s.hue_rand)?;
    s.sat_rand = f(&["csr", "satRand"], s.sat_rand)?;
    s.val_rand = f(&["cvr", "valRand"], s.val_rand)?;
    let color = |names: &[&str], parts: &[[&str; 2]; 3], d: Vec3| -> Res<Vec3> {
        let mut v = vec3(g, n, names, parts, f64::NAN)?;
        for k in 0..3 {
            if v[k].is_nan() {
                v[k] = d[k] as f64;
            }
        }
        Ok(v.as_vec3())
    };
    s.hair_color = color(
        &["hcl", "hairColor"],
        &[["hcr", "hairColorR"], ["hcg", "hairColorG"], ["hcb", "hairColorB"]],
        s.hair_color,
    )?;
    s.specular_color = color(
        &["spc", "specularColor"],
        &[["spr", "specularColorR"], ["spg", "specularColorG"], ["spb", "specularColorB"]],
        s.specular_color,
    )?;
    s.noise_method = match scalar(g, n, &["nmt", "noiseMethod"], 0.0)? as i64 {
        0 => NoiseMethod::Random,
        1 => NoiseMethod::SurfaceUv,
        2 => NoiseMethod::ClumpUv,
        m => {
            return Err((
                attr(g, n, &["nmt", "noiseMethod"]).map_or(0, |a| a.line),
                format!("noise method {m} is not 0 to 2"),
            ))
        }
    };
    for (short, long, field) in [
        ("cws", "clumpWidthScale", &mut s.clump_width_scale),
        ("clc", "clumpCurl", &mut s.clump_curl),
        ("cfl", "clumpFlatness", &mut s.clump_flatness),
        ("hws", "hairWidthScale", &mut s.hair_width_scale),
        ("dsc", "displacementScale", &mut s.displacement_scale),
    ] {
        if let Some(keys) = ramp_keys(g, n, short, long, 1)? {
            *field = build_ramp(g, n, long, keys, |v| v[0] as f32)?;
        }
    }
    if let Some(keys) = ramp_keys(g, n, "hcs", "hairColorScale", 3)? {
        s.hair_color_scale = build_ramp(g, n, "hairColorScale", keys, |v| DVec3::new(v[0], v[1], v[2]).as_vec3())?;
    }
    Ok(s)
}

/// One ramp key as read: position, value components, interpolation enum.
type RawKey = (Option<f64>, Option<Vec<f64>>, Option<f64>);

/// Reads a ramp attribute's keys by index, written whole (`.cws[0:1] 0 1 3 1 0.2 3`:
/// position, value, interpolation) or by child (`.cws[0].cwsp`, `.cwsfv` or `.hcsc`,
/// `.cwsi`, or the long names `clumpWidthScale[0].clumpWidthScale_Position`, ...).
fn ramp_keys(g: &Graph, n: usize, short: &str, long: &str, k: usize) -> Res<Option<BTreeMap<usize, (RawKey, u32)>>> {
    let mut keys: BTreeMap<usize, (RawKey, u32)> = BTreeMap::new();
    let node = &g.nodes[n];
    // Children by short name (`cwsp`), long name (`clumpWidthScale_Position`), or, as MtoA
    // names its ramps' children, the short name with the long suffix (`wdthP_Position`).
    let value_children = [
        format!("{short}fv"),
        format!("{short}c"),
        format!("{long}_FloatValue"),
        format!("{long}_Color"),
        format!("{short}_FloatValue"),
        format!("{short}_Color"),
    ];
    for a in &node.attrs {
        let Some(base) = [short, long].into_iter().find(|b| a.name.starts_with(&format!("{b}["))) else { continue };
        let Some(close) = a.name.find(']') else { continue };
        let range = &a.name[..=close];
        let child = a.name[close + 1..].strip_prefix('.');
        let Some((start, end)) = element_range(range, base) else { continue };
        let bad = |m: &str| (a.line, format!("{}: `{}` {m}", node.name, a.name));
        let Value::Numbers(v) = &a.value else { return Err(bad("must be numbers")) };
        match child {
            None => {
                let count = end.map_or(1, |e| e.saturating_sub(start).saturating_add(1));
                if Some(v.len()) != count.checked_mul(k + 2) {
                    return Err(bad(&format!("needs {} numbers per key (position, value, interpolation)", k + 2)));
                }
                for (i, c) in v.chunks(k + 2).enumerate() {
                    keys.insert(start + i, ((Some(c[0]), Some(c[1..=k].to_vec()), Some(c[k + 1])), a.line));
                }
            }
            Some(child) => {
                let entry = &mut keys.entry(start).or_insert(((None, None, None), a.line)).0;
                if [format!("{short}p"), format!("{long}_Position"), format!("{short}_Position")]
                    .iter()
                    .any(|c| c == child)
                {
                    entry.0 = Some(*v.first().ok_or_else(|| bad("has no value"))?);
                } else if value_children.iter().any(|c| c == child) {
                    if v.len() != k {
                        return Err(bad(&format!("needs {k} number(s)")));
                    }
                    entry.1 = Some(v.clone());
                } else if [format!("{short}i"), format!("{long}_Interp"), format!("{short}_Interp")]
                    .iter()
                    .any(|c| c == child)
                {
                    entry.2 = Some(*v.first().ok_or_else(|| bad("has no value"))?);
                }
            }
        }
    }
    Ok((!keys.is_empty()).then_some(keys))
}

fn build_ramp<T: crate::hair_system::ramp::RampValue>(
    g: &Graph,
    n: usize,
    name: &str,
    keys: BTreeMap<usize, (RawKey, u32)>,
    value: impl Fn(&[f64]) -> T,
) -> Res<Ramp<T>> {
    let mut out = Vec::new();
    let mut line = g.nodes[n].line;
    for (i, ((pos, val, interp), l)) in keys {
        line = l;
        let bad = |m: String| (l, format!("{}: `{name}` key {i}: {m}", g.nodes[n].name));
        let val = val.ok_or_else(|| bad("no value".into()))?;
        // Ramps are kept in single precision, where 1e39 is infinite.
        if let Some(x) = val.iter().chain(&pos).find(|x| !(**x as f32).is_finite()) {
            return Err(bad(format!("{x} is beyond single precision")));
        }
        let interp = match interp.unwrap_or(1.0) as i64 {
            0 => Interp::None,
            1 => Interp::Linear,
            2 => Interp::Smooth,
            3 => Interp::Spline,
            m => return Err(bad(format!("interpolation {m} is not 0 to 3"))),
        };
        out.push(RampKey { position: pos.unwrap_or(0.0) as f32, value: value(&val), interp });
    }
    Ramp::new(out).map_err(|e| (line, format!("{}: `{name}` {e}", g.nodes[n].name)))
}

#[cfg(test)]
mod tests;
