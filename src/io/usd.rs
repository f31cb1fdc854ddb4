//! USD scenes (`.usda` text, `.usdc` binary crate files, `.usdz` packages) in, through
//! the pure-Rust `openusd` crate (its 0.6 release: later ones need a newer Rust than
//! tress's toolchain), and `.usda` out ([`write_usd`]). The crate composes the stage
//! (sublayers, references, payloads, inherits, variants, instancing), resolves time
//! samples and evaluates transform stacks; this module turns the composed prims into
//! tress's scene at one time code (the `--frame`, else the stage's `startTimeCode`):
//!
//! - `BasisCurves`, `HermiteCurves` and `NurbsCurves` to strand sets ([`curves`]);
//! - `Mesh` and the gprims `Sphere`, `Cube`, `Cylinder`, `Cone`, `Capsule` to meshes,
//!   coloured by a bound `UsdPreviewSurface`'s `diffuseColor` or `displayColor`
//!   ([`shapes`]);
//! - `PointInstancer` prims to a copy of their prototype per instance ([`instancer`]);
//! - `Points` to meshes of small spheres, `widths` their diameters ([`points`]);
//! - `Camera` to the camera ([`camera`]), `--camera PATH` or the first one;
//! - UsdLux lights ([`lights`]);
//! - UsdSkel: meshes and curves bound to a skeleton are skinned at the time code
//!   (their blend shapes, then linear blend skinning, by the bound `SkelAnimation`,
//!   [`skel`]).
//!
//! `upAxis = "Z"` stages are turned Y-up; geometry stays in the stage's unit
//! (`metersPerUnit`), which tress, unitless, takes as its own. Everything else a stage
//! holds that draws or lights (other prim types, unread attributes, failed
//! composition arcs) is reported: one warning per kind with a count and the first prim.
//!
//! Every layer passes [`layer::prepare_layer`] first: its checks keep hostile text from
//! overflowing the crate parser's stack, and it rewrites the number forms the crate's
//! tokenizer refuses; binary layers pass [`crate_file::check`], and the stage is read inside
//! `catch_unwind`, so a damaged layer is an error, never an abort. Composition arcs that
//! lead back to their own prim, in one layer or through the files it names, are an error
//! naming the chain ([`arcs::check_cycles`]).

pub mod arcs;
pub mod blender;
pub mod camera;
pub mod crate_file;
pub mod crate_legacy;
pub mod curves;
mod export;
pub mod instancer;
pub mod layer;
pub mod lights;
pub mod points;
pub mod shapes;
pub mod skel;
pub mod values;
pub mod visibility;

pub use export::{usda_text, write_usd};

use super::imported::Imported;
use super::ImportOptions;
use crate::error::LoadError;
use crate::geometry::subdivision::FaceBudget;
use crate::scene::{Contents, HairEntry, HairSource, MaterialSource, MeshEntry, MeshSource};
use crate::shading::Material;
use glam::{Affine3A, DMat4, Vec3};
use openusd::schemas::geom::{Imageable, Visibility, Xformable};
use openusd::sdf;
use openusd::usd::{Prim, PrimPredicate, SchemaBase, SchemaKind, Stage, TimeCode};
use std::collections::{BTreeMap, HashMap};
use std::path::Path;
use values::Res;

/// Linear pieces per cubic segment (and per NURBS span).
pub const PIECES_PER_SEGMENT: usize = 8;

/// Prim types that only group, hold shading networks or render settings: read through
/// their children or by the prims that use them, never reported.
const STRUCTURE: [&str; 15] = [
    "",
    "Xform",
    "Scope",
    "Material",
    "Shader",
    "NodeGraph",
    "GeomSubset",
    "RenderSettings",
    "RenderProduct",
    "RenderVar",
    "Camera",
    "SkelRoot",
    "Skeleton",
    "SkelAnimation",
    "BlendShape",
];

/// What reading one file gathers as it goes: warnings counted by kind (each kind is
/// reported once, with how many prims it concerns and the first of them), and the faces
/// subdivision has made so far.
#[derive(Default)]
pub struct Notes(BTreeMap<String, (usize, String)>, pub FaceBudget);

impl Notes {
    /// Counts one prim under `what`.
    pub fn note(&mut self, what: String, prim: &Prim) {
        self.add(what, prim, 1);
    }

    /// Counts one prim under `what`, the first named with `why`.
    pub fn note_why(&mut self, what: String, prim: &Prim, why: &str) {
        let e = self.0.entry(what).or_insert_with(|| (0, format!("{}: {why}", prim.path())));
        e.0 += 1;
    }

    /// Counts `n` items of `prim` under `what`.
    pub fn add(&mut self, what: String, prim: &Prim, n: usize) {
        let e = self.0.entry(what).or_insert_with(|| (0, prim.path().to_string()));
        e.0 += n;
    }

    /// One line per kind: `what (N; first: /path)`, or `what (N)` without a first prim.
    fn lines(self) -> Vec<String> {
        let line = |(what, (n, first)): (String, (usize, String))| match first.is_empty() {
            true if n == 1 => what,
            true => format!("{what} ({n})"),
            false => format!("{what} ({n}; first: {first})"),
        };
        self.0.into_iter().map(line).collect()
    }
}

/// Reads a USD file (`.usda`, `.usdc`, `.usdz` or `.usd`, and the layers it composes) at
/// the options' frame, with the options' camera.
pub fn read_usd(path: &Path, options: &ImportOptions) -> Result<Imported, LoadError> {
    let bytes = crate::input_file::read(path, crate::input_file::Kind::ImportedScene)?;
    let (kind, prepared) = layer::prepare_layer(bytes).map_err(|m| LoadError::format(path, m))?;
    let name = path.to_str().ok_or_else(|| LoadError::format(path, "the path is not UTF-8"))?;
    if kind == layer::LayerKind::Text {
        arcs::check_cycles(path, &String::from_utf8_lossy(&prepared)).map_err(|m| LoadError::format(path, m))?;
    }
    // The layers passed their checks; a panic of the crate's reader past them is an error
    // naming the file, not the end of the process.
    crate_file::without_panicking(|| read_composed(path, name, kind, &prepared, options))
        .map_err(|m| LoadError::format(path, format!("the USD reader failed on this stage (a damaged layer?): {m}")))?
}

/// The stage of the checked root layer `prepared` (of kind `kind`), composed and read.
fn read_composed(
    path: &Path,
    name: &str,
    kind: layer::LayerKind,
    prepared: &[u8],
    options: &ImportOptions,
) -> Result<Imported, LoadError> {
    let resolver = layer::GuardedResolver::default();
    let missing = resolver.missing();
    let stage = Stage::builder().resolver(resolver).open(name).map_err(|e| {
        // The crate's stage errors do not carry the line; its parser does.
        let text = String::from_utf8_lossy(prepared);
        let mut parser = openusd::usda::parser::Parser::new(&text);
        match (kind, parser.parse(), parser.last_error_highlight()) {
            (layer::LayerKind::Text, Err(_), Some(h)) => LoadError::format(path, format!("line {}: {e:#}", h.line)),
            _ => LoadError::format(path, format!("{e:#}")),
        }
    })?;
    let mut out = Imported::default();
    let mut notes = Notes::default();
    let mut errors = String::new();
    for e in stage.composition_errors() {
        let text = e.to_string();
        errors.push_str(&text);
        notes.0.entry(format!("composition problem: {text}")).or_insert((0, String::new())).0 += 1;
    }
    let mut missing = missing.lock().map(|m| m.clone()).unwrap_or_default();
    if kind == layer::LayerKind::Text {
        let dir = path.parent().unwrap_or(Path::new("."));
        missing.extend(
            arcs::file_assets(&String::from_utf8_lossy(prepared))
                .into_iter()
                .map(|a| dir.join(a))
                .filter(|p| !p.exists())
                .map(|p| p.display().to_string()),
        );
    }
    for asset in missing {
        // A missing sublayer is already a composition problem; a missing reference is not.
        let file = Path::new(&asset).file_name().map_or(asset.clone(), |f| f.to_string_lossy().to_string());
        if !errors.contains(&file) {
            let n = notes.0.entry("referenced or payload files that are missing: not drawn".into());
            n.or_insert((0, asset)).0 += 1;
        }
    }
    read_stage(&stage, options, &mut out, &mut notes).map_err(|e| LoadError::invalid(path, format!("{e:#}")))?;
    note_other_units(&stage, &mut notes);
    out.warnings.extend(notes.lines());
    Ok(out)
}

/// Notes the composed layers (sublayers, references, payloads: those the traversal
/// loaded) whose `metersPerUnit` differs from the root layer's. UsdGeom keeps linear units
/// stage-wide and composition does not rescale: bringing a layer of another unit into the
/// stage's is the assembler's corrective transform, authored in the stage. So the layer
/// is read as authored, as USD's renderers draw it, and said.
fn note_other_units(stage: &Stage, notes: &mut Notes) {
    let mpu = |l: &sdf::Layer| match l.pseudo_root()?.get::<sdf::Value>("metersPerUnit")? {
        sdf::Value::Double(x) => Some(x),
        sdf::Value::Float(x) => Some(f64::from(x)),
        sdf::Value::Int(x) => Some(f64::from(x)),
        _ => None,
    };
    let root_id = stage.root_layer().identifier().to_owned();
    // UsdGeom's fallback: centimetres.
    let root = mpu(&stage.root_layer()).unwrap_or(0.01);
    for id in stage.layer_identifiers().into_iter().filter(|id| *id != root_id) {
        let Some(theirs) = stage.layer(&id).and_then(|l| mpu(&l)) else { continue };
        if (theirs - root).abs() > 1e-5 * theirs.abs().max(root.abs()) {
            let e = notes.0.entry(format!(
                "composed layers whose metersPerUnit differs from the stage's {root}: read as authored, \
                 not rescaled (USD leaves that to a corrective transform in the stage)"
            ));
            let first = Path::new(&id).file_name().map_or(id.clone(), |f| f.to_string_lossy().into_owned());
            e.or_insert((0, format!("{first} at {theirs}"))).0 += 1;
        }
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

/// Checks that every `xformOpOrder` entry of a prim is `!resetXformStack!` or an
/// (optionally `!invert!`ed) property name, identifiers joined by `:`: the crate makes an
/// attribute path of each entry, and one holding a `}` (`xformOp:tr}anslate`) sends its
/// ancestor walk round forever, like a path literal with a stray `}`.
fn check_op_order(x: &AnyPrim) -> Res<()> {
    for op in x.xform_op_order()?.unwrap_or_default() {
        let name = op.strip_prefix("!invert!").unwrap_or(&op);
        if op != "!resetXformStack!" && !name.split(':').all(layer::is_identifier) {
            anyhow::bail!("{}: xformOpOrder entry \"{op}\" is not a property name", x.0.path());
        }
    }
    Ok(())
}

/// The prim's local-to-world matrix at `time`: its ancestors' transform ops, outermost
/// first, up to one that resets the stack.
fn world_matrix(stage: &Stage, path: &sdf::Path, time: TimeCode) -> Res<DMat4> {
    matrix_below(stage, path, None, time)
}

/// The prim's matrix into the space of its ancestor `above` (the world with `None`): the
/// transform ops of the prims between them, outermost first, up to one that resets the
/// stack.
fn matrix_below(stage: &Stage, path: &sdf::Path, above: Option<&sdf::Path>, time: TimeCode) -> Res<DMat4> {
    let mut chain = vec![path.clone()];
    while let Some(p) = chain.last().and_then(|p| p.parent()) {
        if p.as_str() == "/" || p.as_str().is_empty() || Some(&p) == above {
            break;
        }
        chain.push(p);
    }
    let mut m = DMat4::IDENTITY;
    for p in chain.iter().rev() {
        let x = AnyPrim(stage.prim(p.clone()));
        check_op_order(&x)?;
        let local = DMat4::from_cols_array(&x.local_to_parent_transform(time)?.0);
        m = if x.resets_xform_stack()? { local } else { m * local };
    }
    Ok(m)
}

/// A finite matrix as the transform of a scene entry.
fn affine(m: DMat4, path: &sdf::Path) -> Res<Affine3A> {
    let transform = Affine3A::from_mat4(m.as_mat4());
    if !transform.is_finite() {
        anyhow::bail!("{path}: its transform is not finite");
    }
    Ok(transform)
}

/// The composed stage at the options' time code into `out`.
fn read_stage(stage: &Stage, options: &ImportOptions, out: &mut Imported, notes: &mut Notes) -> Res<()> {
    let time = TimeCode::new(options.frame.map_or_else(|| stage.start_time_code(), f64::from));
    // Arnold's `usd` procedural reads a stage in its own axes, whatever its `upAxis`.
    let z_up = !options.stage_axes
        && matches!(stage.stage_metadata("upAxis")?, Some(sdf::Value::Token(t)) if t.as_str() == "Z");
    // Z up to Y up: (x, y, z) -> (x, z, -y).
    let up_fix = if z_up { DMat4::from_rotation_x(-std::f64::consts::FRAC_PI_2) } else { DMat4::IDENTITY };
    let mut paths = Vec::new();
    stage.traverse(PrimPredicate::DEFAULT_PROXIES, |p| paths.push(p.clone()))?;
    let mut cameras = Vec::new();
    let mut poses = skel::Poses::default();
    // A PointInstancer's own subtree (where its prototypes usually live) is drawn through
    // its instances only, as in USD's renderers.
    let mut instancer_below: Option<String> = None;
    let order: HashMap<&str, usize> = paths.iter().enumerate().map(|(i, p)| (p.as_str(), i)).collect();
    let hidden: Vec<wildmatch::WildMatch> = options.hidden.iter().map(|p| wildmatch::WildMatch::new(p)).collect();
    for path in &paths {
        if instancer_below.as_ref().is_some_and(|below| path.as_str().starts_with(below.as_str())) {
            continue;
        }
        if hidden.iter().any(|h| h.matches(path.as_str())) {
            continue;
        }
        let prim = stage.prim(path.clone());
        let kind = prim.type_name()?.map(|t| t.as_str().to_string()).unwrap_or_default();
        if kind == "RenderSettings" && out.resolution.is_none() {
            out.resolution = render_resolution(&prim, time)?;
        }
        let drawable = is_drawable(&kind);
        if !drawable
            && !matches!(kind.as_str(), "Camera" | "PointInstancer")
            && !lights::LIGHT_TYPES.contains(&kind.as_str())
        {
            if !STRUCTURE.contains(&kind.as_str()) {
                notes.note(format!("`{kind}` prims: not read"), &prim);
            }
            continue;
        }
        if kind == "PointInstancer" {
            instancer_below = Some(format!("{path}/"));
        }
        if kind != "Camera" && AnyPrim(prim.clone()).compute_visibility()? == Visibility::Invisible {
            continue;
        }
        if kind == "PointInstancer" {
            let world = up_fix * world_matrix(stage, path, time)?;
            let stage_prims = StagePrims { stage, paths: &paths, order: &order, time };
            stage_prims.instance(&prim, world, 0, &mut out.contents, notes)?;
            continue;
        }
        let skin = match drawable {
            true => skel::skinning(&prim, time, &mut poses, notes)?,
            false => None,
        };
        // Skinned points are in the Skeleton's space: its transform places them, the prim's
        // own no longer applies (UsdSkel, "Schemas In-Depth").
        let mut world =
            up_fix * skin.as_ref().map_or_else(|| world_matrix(stage, path, time), |s| Ok(s.skel_to_world))?;
        if let (Some(s), true) = (&skin, shapes::GPRIMS.contains(&kind.as_str())) {
            // Gprims have no points: a rigid binding moves them whole; influences per point
            // cannot apply.
            match s.rigid() {
                Some(m) => world *= m,
                None => {
                    notes.note("UsdSkel per-point influences on gprims: drawn in the rest pose".into(), &prim);
                    world = up_fix * world_matrix(stage, path, time)?;
                }
            }
        }
        let skin = skin.filter(|_| !shapes::GPRIMS.contains(&kind.as_str()));
        let transform = affine(world, path)?;
        match kind.as_str() {
            "Camera" => cameras.push((prim, transform)),
            light if lights::LIGHT_TYPES.contains(&light) => out.contents.lights.extend(
                lights::read_light(&prim, light, &transform, time, z_up, notes)
                    .map_err(|e| e.context(format!("{path}")))?,
            ),
            _ => read_drawable(&prim, &kind, transform, skin.as_ref(), time, &mut out.contents, notes)?,
        }
    }
    let chosen = match &options.camera {
        Some(want) => {
            let found = cameras.iter().find(|(p, _)| p.path().as_str() == want.as_str());
            let names: Vec<String> = cameras.iter().map(|(p, _)| p.path().to_string()).collect();
            Some(found.ok_or_else(|| {
                anyhow::anyhow!(
                    "no camera `{want}` in the stage (its cameras: {})",
                    if names.is_empty() { "none".to_string() } else { names.join(", ") }
                )
            })?)
        }
        None => cameras.first(),
    };
    if let Some((prim, transform)) = chosen {
        if options.camera.is_none() && cameras.len() > 1 {
            out.warnings.push(format!(
                "{} cameras: rendering through {} (choose another with --camera PATH)",
                cameras.len(),
                prim.path()
            ));
        }
        let (camera, size) = camera::read_camera(prim, transform, time, out.resolution)
            .map_err(|e| e.context(format!("{}", prim.path())))?;
        out.camera = Some(camera);
        out.resolution = Some(size);
    }
    Ok(())
}

/// Whether prims of type `kind` draw geometry tress reads: curves, meshes and gprims.
fn is_drawable(kind: &str) -> bool {
    matches!(kind, "BasisCurves" | "HermiteCurves" | "NurbsCurves" | "Mesh" | "Points")
        || shapes::GPRIMS.contains(&kind)
}

/// A curves, mesh, points or gprim prim (of type `kind`) into `contents`, placed by `transform`;
/// with `skin`, its points skinned first. Inconsistent data skips the prim ([`skip`]).
fn read_drawable(
    prim: &Prim,
    kind: &str,
    transform: Affine3A,
    skin: Option<&skel::Skinning>,
    time: TimeCode,
    contents: &mut Contents,
    notes: &mut Notes,
) -> Res<()> {
    let what = |e: anyhow::Error| e.context(format!("{}", prim.path()));
    if kind == "Mesh" && lights::is_mesh_light(prim, time) {
        return push_mesh_light(prim, transform, skin, time, contents, notes);
    }
    let Some(visibility) = visibility::read(prim, time, notes).map_err(what)? else {
        return Ok(());
    };
    match kind {
        "BasisCurves" | "HermiteCurves" | "NurbsCurves" => {
            let read = match kind {
                "BasisCurves" => curves::read_basis_curves,
                "HermiteCurves" => curves::read_hermite_curves,
                _ => curves::read_nurbs_curves,
            };
            let mut entry = match read(prim, time, transform, skin, notes) {
                Ok(Some(entry)) => entry,
                Ok(None) => return Ok(()),
                Err(e) => {
                    skip(notes, prim, e);
                    return Ok(());
                }
            };
            // Arnold's shader, when bound, is what Arnold draws the curves with: its hair
            // shader, or a surface shader shading them as the tubes they are.
            if let Some(material) = shapes::bound_standard_hair(prim, time, notes)? {
                entry.material = material.into();
            } else if let Some(material) = shapes::bound_arnold_surface(prim, time, notes)? {
                entry.material = material.into();
            } else if !has_display_color(prim, time) {
                if let (Some(c), MaterialSource::Inline(Material::Tube(t))) =
                    (shapes::surface_color(prim, time, notes)?, &mut entry.material)
                {
                    (t.ambient, t.diffuse) = (c, c);
                }
            }
            contents.hair.push(HairEntry { visibility, ..entry });
        }
        "Mesh" => {
            let mesh = match shapes::read_mesh(prim, time, skin, notes) {
                Ok(mesh) => mesh,
                Err(e) => {
                    skip(notes, prim, e);
                    return Ok(());
                }
            };
            // No face of three vertices or more (none authored, or all of one or two).
            if mesh.indices.is_empty() {
                notes.note("meshes without faces of three or more vertices: not drawn".into(), prim);
                return Ok(());
            }
            push_mesh(contents, mesh, surface_material(prim, time, notes).map_err(what)?, transform, visibility);
        }
        "Points" => {
            let mesh = match points::read_points(prim, time, skin, notes) {
                Ok(Some(mesh)) => mesh,
                Ok(None) => return Ok(()),
                // A prim too large to draw is the file's error, not a skipped prim.
                Err(e) if e.is::<points::OverBudget>() => return Err(what(e)),
                Err(e) => {
                    skip(notes, prim, e);
                    return Ok(());
                }
            };
            push_mesh(contents, mesh, surface_material(prim, time, notes).map_err(what)?, transform, visibility);
        }
        gprim => {
            let mesh = match shapes::read_gprim(prim, gprim, time) {
                Ok(mesh) => mesh,
                Err(e) => {
                    skip(notes, prim, e);
                    return Ok(());
                }
            };
            push_mesh(contents, mesh, surface_material(prim, time, notes).map_err(what)?, transform, visibility);
        }
    }
    Ok(())
}

/// The Arnold mesh light of the Mesh `prim` ([`lights::read_mesh_light`]) into `contents`
/// in place of the mesh; inconsistent data skips it ([`skip`]).
fn push_mesh_light(
    prim: &Prim,
    transform: Affine3A,
    skin: Option<&skel::Skinning>,
    time: TimeCode,
    contents: &mut Contents,
    notes: &mut Notes,
) -> Res<()> {
    let mesh = match shapes::read_mesh(prim, time, skin, notes) {
        Ok(mesh) => mesh,
        Err(e) => {
            skip(notes, prim, e);
            return Ok(());
        }
    };
    let camera = visibility::read(prim, time, notes)?.is_some_and(|v| v.camera);
    match lights::read_mesh_light(prim, &mesh, &transform, camera, time, notes) {
        Ok(light) => contents.lights.extend(light),
        Err(e) => skip(notes, prim, e),
    }
    Ok(())
}

/// PointInstancers nest at most this deep (a prototype holding an instancer whose
/// prototype holds one, ...); deeper ones, and prototypes that hold their own instancer,
/// are reported and not drawn.
const MAX_INSTANCER_DEPTH: usize = 8;

/// The traversed prims of a stage at one time code, for drawing PointInstancer
/// prototypes: the traversal is depth-first, so a prototype's subtree is the run of paths
/// after its root that lie under it.
struct StagePrims<'a> {
    stage: &'a Stage,
    paths: &'a [sdf::Path],
    order: &'a HashMap<&'a str, usize>,
    time: TimeCode,
}

impl StagePrims<'_> {
    /// The instances of the PointInstancer `prim`, whose space is `world`, into
    /// `contents`: each prototype read once, then copied per instance.
    fn instance(&self, prim: &Prim, world: DMat4, depth: usize, contents: &mut Contents, notes: &mut Notes) -> Res<()> {
        let read = match instancer::read(prim, self.time) {
            Ok(read) => read,
            Err(e) => {
                skip(notes, prim, e);
                return Ok(());
            }
        };
        let mut prototypes = Vec::with_capacity(read.prototypes.len());
        for root in &read.prototypes {
            prototypes.push(self.prototype(prim, root, depth, notes)?);
        }
        let bytes: u64 = read.instances.iter().map(|i| contents_bytes(&prototypes[i.prototype])).sum();
        if let Some(free) = crate::memory::available().filter(|&free| bytes > free / 2) {
            anyhow::bail!(
                "{}: its {} instances are {} of copied geometry, more than half the {} of memory free \
                 (tress copies every instance)",
                prim.path(),
                read.instances.len(),
                crate::stats::human_bytes(bytes),
                crate::stats::human_bytes(free)
            );
        }
        for instance in &read.instances {
            let m = affine(world * instance.matrix, prim.path())?;
            let prototype = &prototypes[instance.prototype];
            contents.hair.extend(prototype.hair.iter().map(|e| HairEntry { transform: m * e.transform, ..e.clone() }));
            contents
                .meshes
                .extend(prototype.meshes.iter().map(|e| MeshEntry { transform: m * e.transform, ..e.clone() }));
        }
        Ok(())
    }

    /// The drawables of the prototype rooted at `root` (of the instancer `instancer`), in
    /// the space of the root's parent.
    fn prototype(&self, instancer: &Prim, root: &sdf::Path, depth: usize, notes: &mut Notes) -> Res<Contents> {
        let mut contents = Contents::default();
        let Some(&start) = self.order.get(root.as_str()) else {
            let why = format!("{root} is not a defined, active prim");
            notes.note_why("PointInstancer prototypes that are not drawable prims: not drawn".into(), instancer, &why);
            return Ok(contents);
        };
        let parent = root.parent();
        let under = format!("{root}/");
        let mut skip_below: Option<String> = None;
        for path in self.paths[start..].iter().take_while(|p| *p == root || p.as_str().starts_with(&under)) {
            if skip_below.as_ref().is_some_and(|below| path.as_str().starts_with(below.as_str())) {
                continue;
            }
            let prim = self.stage.prim(path.clone());
            let kind = prim.type_name()?.map(|t| t.as_str().to_string()).unwrap_or_default();
            if kind == "PointInstancer" {
                skip_below = Some(format!("{path}/"));
            }
            if AnyPrim(prim.clone()).compute_visibility()? == Visibility::Invisible {
                continue;
            }
            let m = matrix_below(self.stage, path, parent.as_ref(), self.time)?;
            if kind == "PointInstancer" {
                if depth + 1 >= MAX_INSTANCER_DEPTH || instancer.path().as_str().starts_with(&under) {
                    notes.note(
                        "PointInstancers nested too deep, or inside their own prototype: not drawn".into(),
                        &prim,
                    );
                } else {
                    self.instance(&prim, m, depth + 1, &mut contents, notes)?;
                }
            } else if is_drawable(&kind) {
                read_drawable(&prim, &kind, affine(m, path)?, None, self.time, &mut contents, notes)?;
            } else if !STRUCTURE.contains(&kind.as_str()) {
                notes.note(format!("`{kind}` prims inside PointInstancer prototypes: not read"), &prim);
            }
        }
        Ok(contents)
    }
}

/// Bytes of the strand sets and meshes held inline in `contents`.
fn contents_bytes(contents: &Contents) -> u64 {
    let hair = contents.hair.iter().map(|e| match &e.source {
        HairSource::Inline(set) => set.memory_bytes(),
        HairSource::File(_) => 0,
    });
    let meshes = contents.meshes.iter().map(|e| match &e.source {
        MeshSource::Inline(mesh) => mesh.memory_bytes(),
        MeshSource::File(_) => 0,
    });
    hair.chain(meshes).map(|b| b as u64).sum()
}

/// Counts a curves, mesh or gprim prim whose data is inconsistent (counts that do not add
/// up to its points, indices out of range, ...) as skipped: the rest of the stage still
/// renders, as in USD's own renderers. The warning names the first such prim and why.
fn skip(notes: &mut Notes, prim: &Prim, e: anyhow::Error) {
    let first = format!("{}: {e:#}", prim.path());
    notes.0.entry("prims whose data is inconsistent: skipped".into()).or_insert((0, first)).0 += 1;
}

/// Whether a curves prim authors its own `primvars:displayColor` (which wins over a bound
/// material's colour for strands, as it is per strand or point).
fn has_display_color(prim: &Prim, time: TimeCode) -> bool {
    values::value(prim, "primvars:displayColor", time).ok().flatten().is_some()
}

/// A `RenderSettings` prim's `resolution` (`int2`), when it has a usable one.
fn render_resolution(prim: &Prim, time: TimeCode) -> Res<Option<[u32; 2]>> {
    Ok(match values::value(prim, "resolution", time)? {
        Some(sdf::Value::Vec2i(v)) if (1..=65536).contains(&v.x) && (1..=65536).contains(&v.y) => {
            Some([v.x as u32, v.y as u32])
        }
        _ => None,
    })
}

/// A surface prim's material: Arnold's surface shader bound to it
/// ([`shapes::bound_arnold_surface`]), else Lambert of its surface colour
/// ([`shapes::surface_color`], 0.5 grey without one).
fn surface_material(prim: &Prim, time: TimeCode, notes: &mut Notes) -> Res<Material> {
    if let Some(m) = shapes::bound_arnold_surface(prim, time, notes)? {
        return Ok(m);
    }
    let color = shapes::surface_color(prim, time, notes)?;
    Ok(Material::Diffuse { color: color.unwrap_or(Vec3::splat(0.5)) })
}

fn push_mesh(
    contents: &mut Contents,
    mesh: crate::geometry::TriangleMesh,
    material: Material,
    transform: Affine3A,
    visibility: crate::scene::Visibility,
) {
    contents.meshes.push(MeshEntry {
        source: MeshSource::Inline(mesh),
        material: material.into(),
        transform,
        visibility,
    });
}

#[cfg(test)]
mod tests;
