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
//! - UsdLux lights ([`lights`]).
//!
//! `upAxis = "Z"` stages are turned Y-up; geometry stays in the stage's unit
//! (`metersPerUnit`), which tress, unitless, takes as its own. Everything else a stage
//! holds that draws or lights (other prim types, UsdSkel, unread attributes, failed
//! composition arcs) is reported: one warning per kind with a count and the first prim.
//!
//! Every layer passes [`layer::prepare_layer`] first: its checks keep hostile text from
//! overflowing the crate parser's stack, and it rewrites the number forms the crate's
//! tokenizer refuses. Composition arcs that lead back to their own prim are an error
//! naming the chain ([`check_arc_cycles`]).

pub mod camera;
pub mod curves;
mod export;
pub mod layer;
pub mod lights;
pub mod shapes;
pub mod values;

pub use export::{usda_text, write_usd};

use super::imported::Imported;
use super::ImportOptions;
use crate::error::LoadError;
use crate::scene::{MeshEntry, MeshSource};
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
const STRUCTURE: [&str; 11] = [
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
        check_arc_cycles(&String::from_utf8_lossy(&prepared)).map_err(|m| LoadError::format(path, m))?;
    }
    let resolver = layer::GuardedResolver::default();
    let missing = resolver.missing();
    let stage = Stage::builder().resolver(resolver).open(name).map_err(|e| {
        // The crate's stage errors do not carry the line; its parser does.
        let text = String::from_utf8_lossy(&prepared);
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
            arc_assets(&String::from_utf8_lossy(&prepared))
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
    out.warnings.extend(notes.lines());
    Ok(out)
}

/// Refuses a layer whose `inherits`, `specializes` or `references` to prims of the same
/// layer (`</Path>` without an asset) lead from a prim back to itself or its ancestors:
/// the crate's composition follows such chains without end. The error names the chain.
pub fn check_arc_cycles(text: &str) -> Result<(), String> {
    // Prim paths by nesting (`def`/`over`/`class` … `{`), and each prim's internal arcs.
    let mut arcs: BTreeMap<String, Vec<String>> = BTreeMap::new();
    let mut stack: Vec<(String, usize)> = Vec::new();
    let mut depth = 0usize;
    let mut pending: Option<String> = None;
    let mut current = String::new();
    for line in text.lines() {
        let words = line.trim_start();
        if let Some(rest) = ["def ", "over ", "class "].iter().find_map(|k| words.strip_prefix(k)) {
            if let Some(name) = rest.split('"').nth(1) {
                let parent = stack.last().map_or(String::new(), |(p, _)| p.clone());
                pending = Some(format!("{parent}/{name}"));
                current = pending.clone().unwrap_or_default();
            }
        }
        if !current.is_empty() {
            arcs.entry(current.clone()).or_default().extend(internal_arc_targets(line));
        }
        for c in line.bytes() {
            match c {
                b'{' => {
                    depth += 1;
                    if let Some(p) = pending.take() {
                        stack.push((p, depth));
                    }
                }
                b'}' => {
                    if stack.last().is_some_and(|(_, d)| *d == depth) {
                        stack.pop();
                        current = stack.last().map_or(String::new(), |(p, _)| p.clone());
                    }
                    depth = depth.saturating_sub(1);
                }
                _ => {}
            }
        }
    }
    // Depth-first search for a chain back to a prim or one of its ancestors.
    let inside = |a: &str, b: &str| a == b || a.starts_with(&format!("{b}/"));
    for start in arcs.keys() {
        let mut chain = vec![start.clone()];
        let mut seen = std::collections::BTreeSet::new();
        if let Some(c) = cycle_from(&arcs, &mut chain, &mut seen, &inside) {
            return Err(format!("composition arcs form a cycle: {}", c.join(" -> ")));
        }
    }
    Ok(())
}

/// The relative asset paths (`@./file.usda@`, not `@/abs@` nor search paths with a
/// scheme) that a layer's `references` and `payload` arcs name.
fn arc_assets(text: &str) -> Vec<String> {
    let mut out = Vec::new();
    for line in text.lines() {
        if !["references", "payload"].iter().any(|k| line.contains(k)) {
            continue;
        }
        for (k, part) in line.split('@').enumerate() {
            if k % 2 == 1 && !part.is_empty() && !part.contains("://") && !part.contains('$') {
                out.push(part.to_string());
            }
        }
    }
    out
}

/// The prim paths (`</Path>` with no asset before them) that the `inherits`,
/// `specializes`, `references` and `payload` arcs of one line name, except deleted ones.
fn internal_arc_targets(line: &str) -> Vec<String> {
    let mut out = Vec::new();
    for key in ["inherits", "specializes", "references", "payload"] {
        let mut from = 0;
        while let Some(at) = line[from..].find(key).map(|k| k + from) {
            from = at + key.len();
            let whole = !line[..at].ends_with(|c: char| c.is_ascii_alphanumeric() || c == '_' || c == ':');
            let assigns = line[from..].trim_start().starts_with('=');
            if !whole || !assigns || line[..at].trim_end().ends_with("delete") {
                continue;
            }
            // The arc's value runs to the closing `]`, or to the end of a single target.
            let value = &line[from..];
            let value = match value.trim_start()[1..].trim_start().starts_with('[') {
                true => value.split(']').next().unwrap_or(value),
                false => value.split('>').next().map_or(value, |v| &value[..(v.len() + 1).min(value.len())]),
            };
            let mut rest = value;
            while let Some(open) = rest.find('<') {
                let before = rest[..open].trim_end();
                let after = &rest[open + 1..];
                let Some(close) = after.find('>') else { break };
                if !before.ends_with('@') && after[..close].starts_with('/') {
                    out.push(after[..close].to_string());
                }
                rest = &after[close + 1..];
            }
        }
    }
    out
}

/// Follows `arcs` from the last prim of `chain`; the chain when it comes back inside one of
/// its prims.
fn cycle_from(
    arcs: &BTreeMap<String, Vec<String>>,
    chain: &mut Vec<String>,
    seen: &mut std::collections::BTreeSet<String>,
    inside: &dyn Fn(&str, &str) -> bool,
) -> Option<Vec<String>> {
    let last = chain.last()?.clone();
    // A prim's arcs and those of its ancestors both compose into it.
    let sources: Vec<&String> = arcs.keys().filter(|k| inside(&last, k)).collect();
    for src in sources {
        for target in &arcs[src] {
            if chain.iter().any(|c| inside(c, target) || inside(target, c)) {
                let mut c = chain.clone();
                c.push(target.clone());
                return Some(c);
            }
            if seen.insert(target.clone()) {
                chain.push(target.clone());
                if let Some(c) = cycle_from(arcs, chain, seen, inside) {
                    return Some(c);
                }
                chain.pop();
            }
        }
    }
    None
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
        if prim.attribute("skel:skeleton").get::<sdf::Value>().ok().flatten().is_some()
            || !prim.relationship("skel:skeleton").targets().unwrap_or_default().is_empty()
        {
            notes.note("UsdSkel skinning: drawn in the rest pose".into(), &prim);
        }
        let world = up_fix * world_matrix(stage, &path, time)?;
        let transform = Affine3A::from_mat4(world.as_mat4());
        if !transform.is_finite() {
            anyhow::bail!("{path}: its transform is not finite");
        }
        let what = |e: anyhow::Error| e.context(format!("{path}"));
        match kind.as_str() {
            "BasisCurves" | "NurbsCurves" => {
                let read = if kind == "BasisCurves" { curves::read_basis_curves } else { curves::read_nurbs_curves };
                if let Some(mut entry) = read(&prim, time, transform, notes).map_err(what)? {
                    if !has_display_color(&prim, time) {
                        if let (Some(c), Material::Tube(t)) =
                            (shapes::surface_color(&prim, time, notes)?, &mut entry.material)
                        {
                            (t.ambient, t.diffuse) = (c, c);
                        }
                    }
                    out.hair.push(entry);
                }
            }
            "Camera" => cameras.push((prim, transform)),
            "Mesh" => {
                let mesh = shapes::read_mesh(&prim, time).map_err(what)?;
                if token(values::value(&prim, "subdivisionScheme", time)?, "catmullClark") != "none" {
                    notes.note("subdivision surfaces: drawn as their control cage".into(), &prim);
                }
                push_mesh(out, mesh, shapes::surface_color(&prim, time, notes).map_err(what)?, transform);
            }
            k if shapes::GPRIMS.contains(&k) => {
                let mesh = shapes::read_gprim(&prim, k, time).map_err(what)?;
                push_mesh(out, mesh, shapes::surface_color(&prim, time, notes).map_err(what)?, transform);
            }
            light => out.lights.push(lights::read_light(&prim, light, &transform, time, notes).map_err(what)?),
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

fn push_mesh(out: &mut Imported, mesh: crate::geometry::TriangleMesh, color: Option<Vec3>, transform: Affine3A) {
    let material = Material::Diffuse { color: color.unwrap_or(Vec3::splat(0.5)) };
    out.meshes.push(MeshEntry { source: MeshSource::Inline(mesh), material, transform });
}

#[cfg(test)]
mod tests;
