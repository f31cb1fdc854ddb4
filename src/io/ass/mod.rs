//! Arnold scene source files (`.ass`, and the same gzipped, `.ass.gz`, recognised by its
//! magic bytes) as a scene: the text is parsed into nodes ([`parse`]) and the nodes tress
//! draws are read by Arnold's parameter names and defaults (Arnold user guide, node
//! reference):
//!
//! - `options`: `xres` × `yres` the image size; `AA_samples` A gives A² camera samples per
//!   pixel, as Arnold takes; `GI_diffuse_depth` and `GI_specular_depth`, the bounces Arnold
//!   follows after the camera hit, give tress's `max_depth` their larger one; `camera` names
//!   the camera (else `--camera NAME`, else the first camera node).
//! - `persp_camera`: `matrix` (Arnold's row vectors: the translation is the last row), the
//!   camera looking down its local −Z with +Y up; `fov`, Arnold's horizontal field of view
//!   fitted to the image width; `near_clip`, `far_clip`; `screen_window_min`/`max`, the
//!   part of the screen the image sees (−1..1 on each axis is the whole field of view), and
//!   `lens_shift`, which moves that window. `ortho_camera`: its screen window, in world
//!   units, on the camera's x axis and the same in units of the image's height over its
//!   width on its y axis.
//! - lights, by Arnold's conventions ([`super::arnold_light`]): `distant_light` (shining
//!   along its local −Z, `angle`), `point_light` (`position` or `matrix`, `radius`,
//!   `normalize`), `quad_light` (`vertices`, one-sided towards the side its vertices wind
//!   counter-clockwise around, per unit area when `normalize`; with `portal` on, a light
//!   portal that emits nothing itself and lets in the sky domes of `portal_mode`
//!   `interior_only`, Arnold's default, which then light through their portals only),
//!   `spot_light` (`cone_angle`, `penumbra_angle`;
//!   a `radius` drawn as a point of the same power), `disk_light` (`position`, `direction`,
//!   `radius`), `cylinder_light` (`bottom`, `top`, `radius`), `skydome_light` (colour, or
//!   a linked `image` node's `filename` as a latitude-longitude map, × intensity ×
//!   2^exposure; `camera` its weight for camera rays; `portal_mode`). Arnold adds no light
//!   of its own, so a file without lights renders black
//!   ([`Imported::no_default_light`]).
//! - `usd` procedurals (`filename`, relative to the `.ass` file; `matrix`; `frame`;
//!   `shader`, which every surface in the file is drawn with, as Arnold does; `operator`:
//!   the `disable` operators it leads to, directly or through `merge` nodes, hide the
//!   prims their `selection` patterns match; the stage is read in its own axes, as Arnold
//!   reads it, whatever its `upAxis`) and
//!   `procedural` nodes naming another `.ass` or USD file: listed in [`AssScene`]'s
//!   `procedurals` for the reader dispatch ([`super::read_imported_with`]) to read and
//!   place, so that this reader reads no other format itself.
//!
//! Every other node type and every parameter not read is reported, one warning per node
//! type with a count and the first node.

pub mod parse;
mod shapes;

use self::parse::{Atom, Node, Param};
use super::arnold_light;
use super::imported::Imported;
use crate::error::LoadError;
use crate::geometry::subdivision::FaceBudget;
use crate::io::arnold_graph;
use crate::io::arnold_hair::{ArnoldShader, Hair, StandardHair};
use crate::io::arnold_surface::{Flat, Lambert, Standard, StandardSurface, Utility};
use crate::light::{Light, MapPlacement};
use crate::scene::{CameraDesc, CameraProjection, LightSource};
use glam::{Affine3A, DMat4, Vec2, Vec3};
use std::collections::{BTreeMap, HashMap};
use std::path::{Path, PathBuf};

/// A geometry file a `usd` or `procedural` node pulls in, to be read by the reader of its
/// format and placed.
#[derive(Clone, Debug)]
pub struct Procedural {
    /// The file, resolved against the `.ass` file's directory.
    pub path: PathBuf,
    /// Its placement (the node's `matrix`, under a `ginstance`'s when instanced).
    pub transform: Affine3A,
    /// The frame to read it at (`frame`), when given as a whole number.
    pub frame: Option<u32>,
    /// The node's name, for messages.
    pub node: String,
    /// The node's `shader`, which Arnold draws every surface the file holds with.
    pub shader: Option<crate::shading::Material>,
    /// The selections of the `disable` operators its `operator` leads to (directly or
    /// through `merge` nodes): the prims Arnold does not draw.
    pub disabled: Vec<String>,
}

/// What an `.ass` file gives: its scene, and the files its procedurals pull in.
#[derive(Debug, Default)]
pub struct AssScene {
    /// The camera, settings, lights and geometry of the file itself.
    pub imported: Imported,
    /// The procedurals, to be read and appended to `imported`.
    pub procedurals: Vec<Procedural>,
}

/// An error at a line of the file.
type Res<T> = Result<T, (usize, String)>;

/// Warnings counted by kind: how many nodes each concerns and the first of them.
#[derive(Default)]
struct Notes(BTreeMap<String, (usize, String)>);

impl Notes {
    fn note(&mut self, what: impl Into<String>, node: &Node) {
        self.0.entry(what.into()).or_insert((0, node_label(node))).0 += 1;
    }

    fn lines(self) -> Vec<String> {
        self.0.into_iter().map(|(what, (n, first))| format!("{what} ({n}; first: {first})")).collect()
    }
}

fn node_label(node: &Node) -> String {
    match node.name.is_empty() {
        true => format!("{} at line {}", node.kind, node.line),
        false => node.name.clone(),
    }
}

/// Node types that set up Arnold's output (drivers, filters, colour management) or are
/// read through the nodes that use them.
const OUTPUT: [&str; 3] = ["driver_", "_filter", "color_manager"];

/// Reads the `.ass` file at `path` (gzipped or not) through the camera named `camera`
/// (`None`: the one `options` names, else the first).
pub fn read_ass(path: &Path, camera: Option<&str>) -> Result<AssScene, LoadError> {
    let bytes = super::gzip::read_file(path, crate::input_file::Kind::ImportedScene)?;
    let text = String::from_utf8(bytes).map_err(|_| LoadError::format(path, "the file is not UTF-8 text"))?;
    parse_ass(&text, path, camera)
}

/// The scene of the `.ass` text `text`, read as the file `path` (which names it in errors
/// and resolves the files its procedurals and images name).
pub fn parse_ass(text: &str, path: &Path, camera: Option<&str>) -> Result<AssScene, LoadError> {
    let nodes = parse::parse(text).map_err(|e| LoadError::format(path, e.to_string()))?;
    let dir = path.parent().unwrap_or(Path::new("."));
    read_nodes(&nodes, dir, camera).map_err(|(line, m)| LoadError::invalid(path, format!("line {line}: {m}")))
}

/// The scene of parsed `nodes`; `dir` resolves the files they name.
fn read_nodes(nodes: &[Node], dir: &Path, camera: Option<&str>) -> Res<AssScene> {
    let mut reader = Reader {
        nodes,
        dir,
        by_name: HashMap::new(),
        notes: Notes::default(),
        out: AssScene::default(),
        shapes: HashMap::new(),
        faces: FaceBudget::default(),
        portals: Vec::new(),
        domes: Vec::new(),
    };
    for (i, n) in nodes.iter().enumerate() {
        if !n.name.is_empty() {
            reader.by_name.entry(n.name.as_str()).or_insert(i);
        }
    }
    let options = nodes.iter().find(|n| n.kind == "options");
    if let Some(o) = options {
        reader.options(o)?;
    }
    let wanted = camera.map(str::to_string).or_else(|| options.and_then(|o| text(o, "camera")));
    reader.camera(wanted.as_deref(), camera.is_some())?;
    for (i, node) in nodes.iter().enumerate() {
        let used: &[&str] = match node.kind.as_str() {
            "options" => &OPTIONS_READ,
            "persp_camera" | "ortho_camera" => &CAMERA_READ,
            "distant_light" | "point_light" | "quad_light" | "skydome_light" | "spot_light" | "disk_light"
            | "cylinder_light" => {
                reader.light(node)?;
                &LIGHT_READ
            }
            "usd" | "procedural" => {
                reader.procedural(node, matrix(node)?)?;
                &PROCEDURAL_READ
            }
            "polymesh" => {
                reader.shape(i)?;
                &shapes::POLYMESH_READ
            }
            "curves" => {
                reader.shape(i)?;
                &shapes::CURVES_READ
            }
            "sphere" => {
                reader.shape(i)?;
                &shapes::SPHERE_READ
            }
            "ginstance" => {
                reader.ginstance(node)?;
                &shapes::GINSTANCE_READ
            }
            "standard_surface" => <StandardSurface as ArnoldShader>::NAMES,
            "lambert" => <Lambert as ArnoldShader>::NAMES,
            "flat" => <Flat as ArnoldShader>::NAMES,
            "standard" => <Standard as ArnoldShader>::NAMES,
            "utility" => <Utility as ArnoldShader>::NAMES,
            kind if arnold_graph::READ.iter().any(|(k, _)| *k == kind) => {
                arnold_graph::READ.iter().find(|(k, _)| *k == kind).map_or(&[], |(_, names)| *names)
            }
            // Read through the procedurals whose `operator` leads to them.
            "disable" => &["selection", "enable"],
            "merge" => &["inputs"],
            "standard_hair" => &StandardHair::NAMES,
            "hair" => <Hair as ArnoldShader>::NAMES,
            "image" => &["filename"],
            "physical_sky" => &arnold_light::PHYSICAL_SKY_READ,
            kind => {
                let what = match OUTPUT.iter().any(|o| kind.starts_with(o) || kind.ends_with(o)) {
                    true => format!("`{kind}` nodes: not read (tress writes its own image: -o, --filter)"),
                    false if kind == "photometric_light" => {
                        format!("`{kind}` nodes: not read (tress reads no IES profiles; they do not light)")
                    }
                    false => format!("`{kind}` nodes: not read"),
                };
                reader.notes.note(what, node);
                continue;
            }
        };
        let unread: Vec<&str> = node.params.iter().map(|p| p.name.as_str()).filter(|p| !used.contains(p)).collect();
        if !unread.is_empty() {
            let mut unread = unread;
            unread.dedup();
            reader.notes.note(format!("`{}` parameters not read: {}", node.kind, unread.join(", ")), node);
        }
    }
    reader.resolve_portals();
    let mut out = reader.out;
    // Arnold adds no light of its own: a file without lights renders black.
    out.imported.no_default_light = true;
    out.imported.warnings.extend(reader.notes.lines());
    Ok(out)
}

/// The parameters read of each node type (others are reported).
const OPTIONS_READ: [&str; 6] = ["xres", "yres", "camera", "AA_samples", "GI_diffuse_depth", "GI_specular_depth"];
const CAMERA_READ: [&str; 10] = [
    "matrix",
    "position",
    "look_at",
    "up",
    "fov",
    "near_clip",
    "far_clip",
    "screen_window_min",
    "screen_window_max",
    "lens_shift",
];
const LIGHT_READ: [&str; 19] = [
    "matrix",
    "color",
    "intensity",
    "exposure",
    "angle",
    "radius",
    "position",
    "normalize",
    "vertices",
    "camera",
    "format",
    "portal",
    "portal_mode",
    "cone_angle",
    "penumbra_angle",
    "cosine_power",
    "bottom",
    "top",
    "direction",
];
const PROCEDURAL_READ: [&str; 6] = ["filename", "matrix", "frame", "visibility", "shader", "operator"];

struct Reader<'a> {
    nodes: &'a [Node],
    dir: &'a Path,
    by_name: HashMap<&'a str, usize>,
    notes: Notes,
    out: AssScene,
    /// Shapes read so far by node index (`None`: the node draws nothing), for ginstances.
    shapes: HashMap<usize, Option<shapes::Shape>>,
    /// Faces subdivision has made so far in the file.
    faces: FaceBudget,
    /// The light portals (`quad_light`s with `portal` on): a corner and two edges, the
    /// quad facing into the room.
    portals: Vec<(Vec3, Vec3, Vec3)>,
    /// The indices in the lights of the sky domes whose `portal_mode` is `interior_only`.
    domes: Vec<usize>,
}

/// The values of parameter `name`, if the node sets it.
fn values<'n>(node: &'n Node, name: &str) -> Option<(&'n [Atom], usize)> {
    node.param(name).map(|p: &Param| (p.values.as_slice(), p.line))
}

/// A number parameter (a flag reads as 1 or 0), `default` when not set.
fn num(node: &Node, name: &str, default: f64) -> Res<f64> {
    let Some((v, line)) = values(node, name) else { return Ok(default) };
    match v.first() {
        Some(Atom::Num(x)) => Ok(*x),
        Some(a) => match flag_word(a) {
            Some(b) => Ok(f64::from(u8::from(b))),
            None => Err((line, format!("`{}` `{name}` is {a}, not a number", node_label(node)))),
        },
        None => Err((line, format!("`{}` `{name}` has no value", node_label(node)))),
    }
}

/// A finite f32 parameter.
fn num32(node: &Node, name: &str, default: f32) -> Res<f32> {
    let x = num(node, name, f64::from(default))? as f32;
    match x.is_finite() {
        true => Ok(x),
        false => Err((node.param(name).map_or(node.line, |p| p.line), format!("`{name}` is beyond single precision"))),
    }
}

fn flag_word(a: &Atom) -> Option<bool> {
    match a.text()? {
        "on" | "true" => Some(true),
        "off" | "false" => Some(false),
        _ => None,
    }
}

/// A switch, `default` when not set.
fn flag(node: &Node, name: &str, default: bool) -> Res<bool> {
    Ok(num(node, name, f64::from(u8::from(default)))? != 0.0)
}

/// A string or name parameter.
fn text(node: &Node, name: &str) -> Option<String> {
    values(node, name).and_then(|(v, _)| v.first().and_then(Atom::text)).map(str::to_string)
}

/// The numbers of parameter `name` (of the first motion key), all of them finite in
/// single precision.
fn numbers(node: &Node, name: &str) -> Res<Option<Vec<f32>>> {
    let Some((v, line)) = values(node, name) else { return Ok(None) };
    let mut out = Vec::with_capacity(v.len());
    for a in v {
        match a {
            Atom::Num(x) if (*x as f32).is_finite() => out.push(*x as f32),
            other => return Err((line, format!("`{}` `{name}`: {other} is not a finite number", node_label(node)))),
        }
    }
    Ok(Some(out))
}

/// A colour (`RGB`, or the colour of an `RGBA`): `Err` with the linked node's name when
/// the parameter is linked to a node.
fn color(node: &Node, name: &str, default: Vec3) -> Res<Result<Vec3, String>> {
    let Some((v, line)) = values(node, name) else { return Ok(Ok(default)) };
    if let Some(Atom::Str(s) | Atom::Word(s)) = v.first() {
        return Ok(Err(s.clone()));
    }
    let c = numbers(node, name)?.unwrap_or_default();
    match c.len() {
        1 => Ok(Ok(Vec3::splat(c[0]))),
        3 | 4 => Ok(Ok(Vec3::new(c[0], c[1], c[2]))),
        n => Err((line, format!("`{}` `{name}` has {n} numbers, not a colour", node_label(node)))),
    }
}

/// A shader node's parameters for the Arnold code shared with other readers (whose errors
/// the caller places at the node's line).
impl arnold_light::Params for Node {
    fn number(&self, name: &str, default: f32) -> Result<f32, String> {
        num32(self, name, default).map_err(at_line)
    }

    fn triple(&self, name: &str, default: Vec3) -> Result<Vec3, String> {
        match color(self, name, default).map_err(at_line)? {
            Ok(c) => Ok(c),
            Err(link) => Err(format!("`{}` `{name}` is linked to `{link}`, which is not read", node_label(self))),
        }
    }

    fn boolean(&self, name: &str, default: bool) -> Result<bool, String> {
        flag(self, name, default).map_err(at_line)
    }
}

/// A reader error's message, without its line.
fn at_line((_, message): (usize, String)) -> String {
    message
}

/// A point parameter, `default` when not set.
fn point(node: &Node, name: &str, default: Vec3) -> Res<Vec3> {
    match numbers(node, name)? {
        None => Ok(default),
        Some(p) if p.len() == 3 => Ok(Vec3::new(p[0], p[1], p[2])),
        Some(p) => Err((
            node.param(name).map_or(node.line, |p| p.line),
            format!("`{}` `{name}` has {} numbers, not a point", node_label(node), p.len()),
        )),
    }
}

/// The node's `matrix` (the first motion key), identity when not set.
fn matrix(node: &Node) -> Res<Affine3A> {
    let Some(m) = numbers(node, "matrix")? else { return Ok(Affine3A::IDENTITY) };
    let line = node.param("matrix").map_or(node.line, |p| p.line);
    if m.len() < 16 {
        return Err((line, format!("`{}` `matrix` has {} numbers, not 16", node_label(node), m.len())));
    }
    // Arnold's row vectors: each written row is a column of the column-vector matrix.
    let mut a = [0.0f64; 16];
    for (d, s) in a.iter_mut().zip(&m) {
        *d = f64::from(*s);
    }
    let t = Affine3A::from_mat4(DMat4::from_cols_array(&a).as_mat4());
    match t.is_finite() {
        true => Ok(t),
        false => Err((line, format!("`{}` `matrix` is not finite", node_label(node)))),
    }
}

impl Reader<'_> {
    fn options(&mut self, o: &Node) -> Res<()> {
        let whole = |name: &str, default: f64, max: f64| -> Res<u32> {
            let x = num(o, name, default)?;
            match x.fract() == 0.0 && (0.0..=max).contains(&x) {
                true => Ok(x as u32),
                false => Err((
                    o.param(name).map_or(o.line, |p| p.line),
                    format!("options `{name}` {x} is not a whole number from 0 to {max}"),
                )),
            }
        };
        // Arnold's defaults: 320 × 240, 3 AA samples, one diffuse and one specular bounce.
        let (w, h) = (whole("xres", 320.0, 65536.0)?, whole("yres", 240.0, 65536.0)?);
        if w > 0 && h > 0 {
            self.out.imported.resolution = Some([w, h]);
        }
        let aa = num(o, "AA_samples", 3.0)?.round().clamp(1.0, 1024.0) as u32;
        self.out.imported.spp = Some(aa * aa);
        let depth = whole("GI_diffuse_depth", 1.0, 1024.0)?.max(whole("GI_specular_depth", 1.0, 1024.0)?);
        self.out.imported.max_depth = Some(depth);
        Ok(())
    }

    /// The camera named `wanted` (an error listing the cameras when `required` and there is
    /// none of that name), else the first.
    fn camera(&mut self, wanted: Option<&str>, required: bool) -> Res<()> {
        let cameras: Vec<&Node> = self.nodes.iter().filter(|n| n.kind.ends_with("_camera")).collect();
        let chosen = match wanted {
            Some(w) => match cameras.iter().find(|c| c.name == w) {
                Some(c) => Some(*c),
                None if required => {
                    let names: Vec<&str> = cameras.iter().map(|c| c.name.as_str()).collect();
                    let list = if names.is_empty() { "none".to_string() } else { names.join(", ") };
                    return Err((1, format!("no camera `{w}` in the file (its cameras: {list})")));
                }
                None => cameras.first().copied(),
            },
            None => cameras.first().copied(),
        };
        let Some(c) = chosen else { return Ok(()) };
        if cameras.len() > 1 && wanted.is_none() {
            self.out.imported.warnings.push(format!(
                "{} cameras: rendering through {} (choose another with --camera NAME)",
                cameras.len(),
                c.name
            ));
        }
        // Arnold's cameras before its `matrix` (and files still written so) are placed by
        // `position`, `look_at` and `up`; the matrix wins when both are given. Only a matrix
        // can scale the camera (and so its clipping range): the look-at direction is a unit.
        let (eye, forward, up) = match c.param("matrix") {
            None if c.param("position").is_some() || c.param("look_at").is_some() => {
                let eye = point(c, "position", Vec3::ZERO)?;
                (eye, (point(c, "look_at", Vec3::NEG_Z)? - eye).normalize_or_zero(), point(c, "up", Vec3::Y)?)
            }
            _ => {
                let m = matrix(c)?;
                (m.transform_point3(Vec3::ZERO), m.transform_vector3(Vec3::NEG_Z), m.transform_vector3(Vec3::Y))
            }
        };
        if !(forward.length() > 0.0 && up.cross(forward).length() > 0.0) {
            return Err((c.line, format!("camera `{}`: its placement gives no view and up directions", c.name)));
        }
        let [w, h] = self.out.imported.resolution.unwrap_or([320, 240]);
        let aspect = h as f32 / w as f32;
        let window = |name: &str, d: f32| -> Res<[f32; 2]> {
            match numbers(c, name)? {
                None => Ok([d, d]),
                Some(v) if v.len() == 2 => Ok([v[0], v[1]]),
                Some(v) => Err((c.line, format!("camera `{}` `{name}` has {} numbers, not 2", c.name, v.len()))),
            }
        };
        let (min, max) = (window("screen_window_min", -1.0)?, window("screen_window_max", 1.0)?);
        // `lens_shift` moves the frame's centre in screen units, +1 to the right or bottom
        // edge (Arnold user guide, "Perspective Camera"); without lens distortion that is the
        // window moved the other way up.
        let shift = match c.kind.as_str() {
            "persp_camera" => window("lens_shift", 0.0)?,
            _ => [0.0, 0.0],
        };
        let shift = Vec2::new(shift[0], -shift[1]);
        let screen = [Vec2::from(min) + shift, Vec2::from(max) + shift];
        let (projection, film) = match c.kind.as_str() {
            "persp_camera" => {
                let fov = num32(c, "fov", 54.43)?;
                let film = super::usd::camera::arnold_fov_film(fov, aspect)
                    .map_err(|e| (c.line, format!("camera `{}` `fov` {e}", c.name)))?;
                (CameraProjection::Perspective, film)
            }
            "ortho_camera" => {
                let film = super::usd::camera::ARNOLD_ORTHO_FILM;
                (CameraProjection::Orthographic { height: film.fitted_height(w, h) }, film)
            }
            other => {
                self.notes.note(format!("`{other}` cameras: drawn as a perspective camera of their fov"), c);
                let fov = num32(c, "fov", 54.43)?.clamp(1.0, 179.0);
                (CameraProjection::Perspective, super::usd::camera::arnold_fov_film(fov, aspect).expect("clamped"))
            }
        };
        if !(screen[0].is_finite() && screen[1].is_finite() && (screen[1] - screen[0]).min_element() > 0.0) {
            return Err((c.line, format!("camera `{}`: its screen window has no width or no height", c.name)));
        }
        // Arnold's defaults: clipping from 1e-4 to 1e30, along the view.
        let (near, far) = (num32(c, "near_clip", 1e-4)?, num32(c, "far_clip", 1e30)?);
        if !(near >= 0.0 && far > near) {
            return Err((c.line, format!("camera `{}`: clip range {near} to {far} is not a range", c.name)));
        }
        let stretch = forward.length();
        let vfov = match projection {
            CameraProjection::Perspective => film.vfov(w, h),
            _ => CameraDesc::default().vfov,
        };
        self.out.imported.camera = Some(CameraDesc {
            eye,
            target: eye + forward.normalize(),
            up: up.normalize(),
            vfov,
            projection,
            film: Some(film),
            clip: [near * stretch, far * stretch],
            window: screen,
        });
        Ok(())
    }

    fn light(&mut self, node: &Node) -> Res<()> {
        let m = matrix(node)?;
        let what = |e: String| (node.line, format!("light `{}`: {e}", node_label(node)));
        let (base, linked) = match color(node, "color", Vec3::ONE)? {
            Ok(c) => (c, None),
            Err(link) => (Vec3::ONE, Some(link)),
        };
        let emission = arnold_light::emission(base, num32(node, "intensity", 1.0)?, num32(node, "exposure", 0.0)?)
            .map_err(what)?;
        let normalize = flag(node, "normalize", true)?;
        let linked_node = linked.as_deref().and_then(|l| self.by_name.get(l).map(|&i| &self.nodes[i]));
        if linked.is_some() && node.kind != "skydome_light" {
            self.notes.note("light colours linked to shaders: lit by white × intensity", node);
        }
        let light = match node.kind.as_str() {
            "distant_light" => {
                let direction = m.transform_vector3(Vec3::Z).normalize_or(Vec3::Y);
                arnold_light::distant(direction, emission, num32(node, "angle", 0.0)?)
            }
            "point_light" => {
                let radius = num32(node, "radius", 0.0)?.max(0.0) * m.matrix3.determinant().abs().cbrt();
                let camera = num32(node, "camera", 0.0)?.max(0.0);
                arnold_light::sphere(
                    m.transform_point3(point(node, "position", Vec3::ZERO)?),
                    radius,
                    emission,
                    normalize,
                    camera,
                )
            }
            "spot_light" => {
                let position = m.transform_point3(point(node, "position", Vec3::ZERO)?);
                let direction = m.transform_vector3(Vec3::NEG_Z).normalize_or(Vec3::NEG_Z);
                let radius = num32(node, "radius", 0.0)?.max(0.0) * m.matrix3.determinant().abs().cbrt();
                if radius > 0.0 {
                    self.notes.note("spot light radii: drawn as a point of the same power", node);
                }
                if num32(node, "cosine_power", 0.0)? != 0.0 {
                    self.notes.note("spot light `cosine_power` other than 0: not applied", node);
                }
                let (cone, penumbra) = (num32(node, "cone_angle", 65.0)?, num32(node, "penumbra_angle", 0.0)?);
                arnold_light::spot(position, direction, emission, [radius, cone, penumbra], normalize)
            }
            "disk_light" => {
                // Arnold places a disk by its `position` and `direction` under the matrix;
                // its radius is not scaled (Arnold node reference, `disk_light`).
                let centre = m.transform_point3(point(node, "position", Vec3::ZERO)?);
                let back = -m.transform_vector3(point(node, "direction", Vec3::NEG_Z)?).normalize_or(Vec3::NEG_Z);
                let (a, b) = back.any_orthonormal_pair();
                let (a, b) = if a.cross(b).dot(back) > 0.0 { (a, b) } else { (b, a) };
                let frame = Affine3A::from_cols(a.into(), b.into(), back.into(), centre.into());
                let radius = num32(node, "radius", 0.5)?.max(0.0);
                arnold_light::disk(&frame, radius, emission, normalize, num32(node, "camera", 0.0)?.max(0.0))
            }
            "cylinder_light" => {
                // The axis from `bottom` to `top` under the matrix; the radius not scaled
                // (Arnold node reference, `disk_light`: "we don't handle scaling in disk and
                // cylinder lights").
                let (bottom, top) = (point(node, "bottom", Vec3::NEG_Y)?, point(node, "top", Vec3::Y)?);
                let radius = num32(node, "radius", 1.0)?.max(0.0);
                let camera = num32(node, "camera", 0.0)?.max(0.0);
                let (bottom, top) = (m.transform_point3(bottom), m.transform_point3(top));
                for light in arnold_light::cylinder(bottom, top, radius, emission, normalize, camera) {
                    self.out.imported.contents.lights.push(LightSource::Inline(light));
                }
                return Ok(());
            }
            "quad_light" => {
                // Arnold's default quad: the unit square −1..1 in the local XY plane.
                let v = match numbers(node, "vertices")? {
                    Some(v) if v.len() == 12 => v,
                    None => vec![-1.0, -1.0, 0.0, -1.0, 1.0, 0.0, 1.0, 1.0, 0.0, 1.0, -1.0, 0.0],
                    Some(v) => return Err(what(format!("`vertices` has {} numbers, not 4 points", v.len()))),
                };
                let p: Vec<Vec3> = v.chunks(3).map(|c| m.transform_point3(Vec3::new(c[0], c[1], c[2]))).collect();
                if (p[0] + p[2] - p[1] - p[3]).length() > 1e-4 * (p[2] - p[0]).length() {
                    self.notes.note(
                        "quad lights that are not parallelograms: drawn as the parallelogram of three corners",
                        node,
                    );
                }
                let (edge_u, edge_v) = (p[3] - p[0], p[1] - p[0]);
                if flag(node, "portal", false)? {
                    // A portal emits nothing: it lets its sky domes in (`resolve_portals`).
                    self.portals.push((p[0], edge_u, edge_v));
                    return Ok(());
                }
                let area = edge_u.cross(edge_v).length();
                let radiance = if normalize && area > 0.0 { emission / area } else { emission };
                Light::Quad {
                    corner: p[0],
                    edge_u,
                    edge_v,
                    radiance,
                    camera_visibility: num32(node, "camera", 0.0)?.max(0.0),
                }
            }
            _ => {
                let camera = num32(node, "camera", 1.0)?.max(0.0);
                let mode = text(node, "portal_mode").unwrap_or_else(|| "interior_only".into());
                if mode == "interior_only" {
                    self.domes.push(self.out.imported.contents.lights.len());
                }
                let format = text(node, "format").unwrap_or_else(|| "latlong".into());
                if let Some(sky) = linked_node.filter(|n| n.kind == "physical_sky") {
                    let sky = arnold_light::physical_sky(sky).map_err(|e| (sky.line, e))?;
                    // The dome's colour is the sky: its intensity and exposure scale it.
                    let placement = MapPlacement::new(0.0, emission.x)
                        .rotated(crate::math::orthogonal_part(&m))
                        .seen_by_camera(camera);
                    let lights = sky.lights(placement).map_err(what)?;
                    self.out.imported.contents.lights.extend(lights.into_iter().map(LightSource::Inline));
                    return Ok(());
                }
                match linked_node.filter(|n| n.kind == "image").and_then(|n| text(n, "filename")) {
                    Some(file) if format == "latlong" => {
                        let mut map = arnold_light::latlong_map(self.dir.join(file), emission);
                        map.placement = map.placement.rotated(crate::math::orthogonal_part(&m)).seen_by_camera(camera);
                        self.out.imported.contents.lights.push(LightSource::File(map));
                        return Ok(());
                    }
                    _ => {
                        if linked.is_some() {
                            self.notes.note("sky dome colours linked to nodes other than a latitude-longitude image: lit by white × intensity", node);
                        }
                        Light::Environment { radiance: emission, camera_visibility: camera }
                    }
                }
            }
        };
        self.out.imported.contents.lights.push(LightSource::Inline(light));
        Ok(())
    }

    /// Sky domes and their portals. With portals, a dome of `portal_mode` `interior_only`
    /// (Arnold's default) lights nothing outside them (Arnold user guide, "Light Portal"):
    /// its light comes in through the portals only, which is what quads of the dome's
    /// radiance facing in give (exact for a uniform dome); a textured dome's portals take
    /// its colour × intensity. Other modes keep the dome whole, the portals only guiding
    /// Arnold's sampling.
    fn resolve_portals(&mut self) {
        if self.portals.is_empty() {
            return;
        }
        let lights = &mut self.out.imported.contents.lights;
        let mut domes: Vec<(Vec3, f32)> = Vec::new();
        for &i in self.domes.iter().rev() {
            let dome = match &lights[i] {
                LightSource::Inline(Light::Environment { radiance, camera_visibility }) => {
                    (*radiance, *camera_visibility)
                }
                LightSource::File(map) => {
                    self.out.imported.warnings.push(
                        "sky dome images seen through light portals: the portals emit the dome's colour × intensity"
                            .into(),
                    );
                    (map.tint, map.placement.camera_visibility())
                }
                // Another kind of sky is kept whole.
                _ => continue,
            };
            lights.remove(i);
            domes.push(dome);
        }
        for &(corner, edge_u, edge_v) in &self.portals {
            for &(radiance, camera_visibility) in &domes {
                lights.push(LightSource::Inline(Light::Quad { corner, edge_u, edge_v, radiance, camera_visibility }));
            }
        }
    }

    /// A `usd` or `procedural` node, placed by `transform`.
    fn procedural(&mut self, node: &Node, transform: Affine3A) -> Res<()> {
        if num(node, "visibility", 255.0)? == 0.0 {
            return Ok(());
        }
        let Some(file) = text(node, "filename").filter(|f| !f.is_empty()) else {
            self.notes.note("procedurals without a `filename`: not drawn", node);
            return Ok(());
        };
        let frame = match num(node, "frame", f64::NAN) {
            Ok(f) if f.fract() == 0.0 && (0.0..=f64::from(u32::MAX)).contains(&f) => Some(f as u32),
            Ok(f) if f.is_nan() => None,
            _ => {
                self.notes.note("procedural frames that are not whole numbers: read at the file's start", node);
                None
            }
        };
        let shader = node.param("shader").is_some().then(|| self.surface(node));
        let mut disabled = Vec::new();
        if let Some(operator) = text(node, "operator") {
            self.disabled_by(node, &operator, 0, &mut disabled)?;
        }
        self.out.procedurals.push(Procedural {
            path: self.dir.join(file),
            transform,
            frame,
            node: node_label(node),
            shader,
            disabled,
        });
        Ok(())
    }

    /// The selections of the enabled `disable` operators the operator `name`, named by
    /// `procedural`, leads to: itself, or the `inputs` of a `merge`, followed at most 16
    /// deep. Other operators are reported, not applied.
    fn disabled_by(&mut self, procedural: &Node, name: &str, depth: usize, out: &mut Vec<String>) -> Res<()> {
        let Some(&i) = self.by_name.get(name) else {
            self.notes.note(format!("procedural operators that name no node: not applied ({name})"), procedural);
            return Ok(());
        };
        let node = &self.nodes[i];
        if depth > 16 {
            return Err((node.line, format!("operator `{name}`: operators nest deeper than 16 or form a cycle")));
        }
        match node.kind.as_str() {
            "disable" if flag(node, "enable", true)? => {
                out.extend(text(node, "selection").iter().flat_map(|s| s.split_whitespace().map(str::to_string)));
            }
            "disable" => {}
            "merge" => {
                let inputs: Vec<String> = values(node, "inputs")
                    .map(|(v, _)| v.iter().filter_map(Atom::text).map(str::to_string).collect())
                    .unwrap_or_default();
                for input in inputs {
                    self.disabled_by(procedural, &input, depth + 1, out)?;
                }
            }
            kind => self.notes.note(format!("`{kind}` operators on procedurals: not applied"), node),
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests;
