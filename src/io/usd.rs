//! USD scenes (`.usda` text, `.usdc` binary crate files, `.usdz` packages) in, through
//! the pure-Rust `openusd` crate (its 0.6 release: later ones need a newer Rust than
//! tress's toolchain), and `.usda` out ([`write_usd`]). The crate composes the stage
//! (sublayers, references, payloads, inherits, variants, instancing), resolves time
//! samples and evaluates transform stacks; this module turns the composed prims into
//! tress's scene at one time code (the `--frame`, else the stage's `startTimeCode`):
//!
//! - `BasisCurves` and `NurbsCurves` to strand sets ([`curves`]);
//! - `Mesh` and the gprims `Sphere`, `Cube`, `Cylinder`, `Cone`, `Capsule` to meshes,
//!   coloured by a bound `UsdPreviewSurface`'s `diffuseColor` or `displayColor`
//!   ([`shapes`]);
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
pub mod camera;
pub mod crate_file;
pub mod curves;
mod export;
pub mod layer;
pub mod lights;
pub mod shapes;
pub mod skel;
pub mod values;

pub use export::{usda_text, write_usd};

use super::imported::Imported;
use super::ImportOptions;
use crate::error::LoadError;
use crate::scene::{MaterialSource, MeshEntry, MeshSource};
use crate::shading::Material;
use glam::{Affine3A, DMat4, Vec3};
use openusd::schemas::geom::{Imageable, Visibility, Xformable};
use openusd::sdf;
use openusd::usd::{Prim, PrimPredicate, SchemaBase, SchemaKind, Stage, TimeCode};
use std::collections::BTreeMap;
use std::path::Path;
use values::{token, Res};

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

/// Warnings counted by kind: each kind is reported once, with how many prims it concerns
/// and the first of them.
#[derive(Default)]
pub struct Notes(BTreeMap<String, (usize, String)>);

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
        let local = DMat4::from_cols_array(&x.local_to_parent_transform(time)?.0);
        m = if x.resets_xform_stack()? { local } else { m * local };
    }
    Ok(m)
}

/// The composed stage at the options' time code into `out`.
fn read_stage(stage: &Stage, options: &ImportOptions, out: &mut Imported, notes: &mut Notes) -> Res<()> {
    let time = TimeCode::new(options.frame.map_or_else(|| stage.start_time_code(), f64::from));
    let z_up = matches!(stage.stage_metadata("upAxis")?, Some(sdf::Value::Token(t)) if t.as_str() == "Z");
    // Z up to Y up: (x, y, z) -> (x, z, -y).
    let up_fix = if z_up { DMat4::from_rotation_x(-std::f64::consts::FRAC_PI_2) } else { DMat4::IDENTITY };
    let mut paths = Vec::new();
    stage.traverse(PrimPredicate::DEFAULT_PROXIES, |p| paths.push(p.clone()))?;
    let mut cameras = Vec::new();
    let mut poses = skel::Poses::default();
    for path in paths {
        let prim = stage.prim(path.clone());
        let kind = prim.type_name()?.map(|t| t.as_str().to_string()).unwrap_or_default();
        if kind == "RenderSettings" && out.resolution.is_none() {
            out.resolution = render_resolution(&prim, time)?;
        }
        let readable = matches!(kind.as_str(), "BasisCurves" | "NurbsCurves" | "Mesh" | "Camera")
            || shapes::GPRIMS.contains(&kind.as_str())
            || lights::LIGHT_TYPES.contains(&kind.as_str());
        if !readable {
            if !STRUCTURE.contains(&kind.as_str()) {
                notes.note(format!("`{kind}` prims: not read"), &prim);
            }
            continue;
        }
        if kind != "Camera" && AnyPrim(prim.clone()).compute_visibility()? == Visibility::Invisible {
            continue;
        }
        let skin = match kind.as_str() {
            "Camera" => None,
            k if lights::LIGHT_TYPES.contains(&k) => None,
            _ => skel::skinning(&prim, time, &mut poses, notes)?,
        };
        // Skinned points are in the Skeleton's space: its transform places them, the prim's
        // own no longer applies (UsdSkel, "Schemas In-Depth").
        let mut world =
            up_fix * skin.as_ref().map_or_else(|| world_matrix(stage, &path, time), |s| Ok(s.skel_to_world))?;
        if let (Some(s), true) = (&skin, shapes::GPRIMS.contains(&kind.as_str())) {
            // Gprims have no points: a rigid binding moves them whole; influences per point
            // cannot apply.
            match s.rigid() {
                Some(m) => world *= m,
                None => {
                    notes.note("UsdSkel per-point influences on gprims: drawn in the rest pose".into(), &prim);
                    world = up_fix * world_matrix(stage, &path, time)?;
                }
            }
        }
        let skin = skin.filter(|_| !shapes::GPRIMS.contains(&kind.as_str()));
        let transform = Affine3A::from_mat4(world.as_mat4());
        if !transform.is_finite() {
            anyhow::bail!("{path}: its transform is not finite");
        }
        let what = |e: anyhow::Error| e.context(format!("{path}"));
        match kind.as_str() {
            "BasisCurves" | "NurbsCurves" => {
                let read = if kind == "BasisCurves" { curves::read_basis_curves } else { curves::read_nurbs_curves };
                let read = match read(&prim, time, transform, skin.as_ref(), notes) {
                    Ok(read) => read,
                    Err(e) => {
                        skip(notes, &prim, e);
                        continue;
                    }
                };
                if let Some(mut entry) = read {
                    // Arnold's hair shader, when bound, is what Arnold draws the curves with.
                    if let Some(material) = shapes::bound_standard_hair(&prim, time, notes)? {
                        entry.material = material.into();
                    } else if !has_display_color(&prim, time) {
                        if let (Some(c), MaterialSource::Inline(Material::Tube(t))) =
                            (shapes::surface_color(&prim, time, notes)?, &mut entry.material)
                        {
                            (t.ambient, t.diffuse) = (c, c);
                        }
                    }
                    out.contents.hair.push(entry);
                }
            }
            "Camera" => cameras.push((prim, transform)),
            "Mesh" => {
                let mesh = match shapes::read_mesh(&prim, time, skin.as_ref()) {
                    Ok(mesh) => mesh,
                    Err(e) => {
                        skip(notes, &prim, e);
                        continue;
                    }
                };
                if token(values::value(&prim, "subdivisionScheme", time)?, "catmullClark") != "none" {
                    notes.note("subdivision surfaces: drawn as their control cage".into(), &prim);
                }
                push_mesh(out, mesh, surface_material(&prim, time, notes).map_err(what)?, transform);
            }
            k if shapes::GPRIMS.contains(&k) => {
                let mesh = match shapes::read_gprim(&prim, k, time) {
                    Ok(mesh) => mesh,
                    Err(e) => {
                        skip(notes, &prim, e);
                        continue;
                    }
                };
                push_mesh(out, mesh, surface_material(&prim, time, notes).map_err(what)?, transform);
            }
            light => out
                .contents
                .lights
                .extend(lights::read_light(&prim, light, &transform, time, z_up, notes).map_err(what)?),
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
        let (camera, size) = camera::read_camera(prim, transform, time, out.resolution, notes)
            .map_err(|e| e.context(format!("{}", prim.path())))?;
        out.camera = Some(camera);
        out.resolution = Some(size);
    }
    Ok(())
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

/// A surface prim's material: Arnold's `standard_surface` bound to it, else Lambert of its
/// surface colour ([`shapes::surface_color`], 0.5 grey without one).
fn surface_material(prim: &Prim, time: TimeCode, notes: &mut Notes) -> Res<Material> {
    if let Some(m) = shapes::bound_standard_surface(prim, time, notes)? {
        return Ok(m);
    }
    let color = shapes::surface_color(prim, time, notes)?;
    Ok(Material::Diffuse { color: color.unwrap_or(Vec3::splat(0.5)) })
}

fn push_mesh(out: &mut Imported, mesh: crate::geometry::TriangleMesh, material: Material, transform: Affine3A) {
    out.contents.meshes.push(MeshEntry {
        source: MeshSource::Inline(mesh),
        material: material.into(),
        transform,
        visibility: Default::default(),
    });
}

#[cfg(test)]
mod tests;
