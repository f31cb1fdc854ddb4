//! pbrt-v4 and pbrt-v3 scenes, the part hair scenes use (the pbrt-v4 file format; Pharr,
//! Jakob and Humphreys, *Physically Based Rendering*, 4th edition, appendix C and the
//! format's online reference; pbrt-v3's, 3rd edition, appendix B).
//!
//! Read: `LookAt`, `Translate`, `Scale`, `Rotate`, `Transform`, `ConcatTransform`,
//! `Identity`, `CoordinateSystem`/`CoordSysTransform`, `ReverseOrientation`,
//! `AttributeBegin`/`End` (and the older `TransformBegin`/`End`), `Include`/`Import`
//! (paths relative to the first file's directory, as pbrt resolves them), `Camera
//! "perspective"` (`fov` spanning the shorter image side, or the window `screenwindow` or
//! `frameaspectratio` give, for the file's image size and one given later alike; a window
//! off centre shifts the view) and
//! `"orthographic"` (the same window, in camera space units), `Film`
//! (`xresolution`, `yresolution`), `Sampler` (`pixelsamples`), `Integrator`, `LightSource` `distant`,
//! `infinite`, `point` and `spot`, `Material` and `MakeNamedMaterial`/`NamedMaterial`,
//! and `Shape` `curve`, `trianglemesh`, `loopsubdiv` (Loop subdivision at its `levels`,
//! v3's `nlevels`, its vertices on the limit surface, as pbrt evaluates it:
//! `geometry::loop_subdivision`), `plymesh`, `sphere`, `disk`, `cylinder` and
//! `bilinearmesh` (the last three as meshes, `surfaces.rs`).
//!
//! **Compressed files.** Any file read (the scene, its includes, PLY meshes) may be gzip
//! data, recognised by its magic bytes as pbrt does (`geometry/hair.pbrt.gz`).
//!
//! **Integrator.** pbrt's path tracers (`path`, `volpath`, `bdpt`, `mlt`, `sppm`,
//! `simplepath`, ...; `volpath` is pbrt's default) become tress's `path` integrator, whose
//! depth is pbrt's `maxdepth` (default 5) less one: pbrt counts the first scattering event,
//! tress the bounces after it. `directlighting` and `whitted` become `direct`; any other
//! is rendered by path tracing with a warning.
//!
//! **Exposure.** pbrt-v4 scales the image by its imaging ratio, exposure time × ISO / 100
//! (the camera's `shutterclose` − `shutteropen`, default 1, and Film `iso`, default 100);
//! pbrt-v3 by Film `scale`. Pixel values are linear in the lights' emission, so the import
//! multiplies every light by that factor.
//!
//! **Curves.** Each `Shape "curve"` (`bezier` or `bspline` basis, degree 2 or 3, types
//! `flat`, `cylinder` and `ribbon` alike) becomes one strand: every segment is sampled at
//! 2^`splitdepth` linear pieces (pbrt's own subdivision count; default 3) and the width
//! runs linearly from `width0` to `width1` (both default to `width`, 1) along the whole
//! curve, as in pbrt. Curves sharing a material form one strand set.
//!
//! **Hair material.** pbrt's `hair` is the model of Chiang et al. 2016, as is tress's
//! `physical` material, which takes its parameters: `beta_m`, `beta_n`, `alpha`, `eta`,
//! and the absorption from, in pbrt's order of precedence, `sigma_a` (as the colour
//! Chiang et al. §4.2 maps to it, which tress maps back), the colour (`reflectance` in v4,
//! `color` in v3), or `eumelanin` and `pheomelanin` (1.3 and 0 when nothing is given,
//! pbrt's default). The melanin concentrations are taken as they are: both renderers turn
//! them into absorption with the same RGB coefficients.
//!
//! **Other materials.** pbrt-v4 `diffuse` (`reflectance`) and pbrt-v3 `matte` (`Kd`) are
//! tress's diffuse material; `dielectric`, `thindielectric` and v3 `glass` (`eta` or
//! `index`) glass; `conductor`, v3 `mirror` (`Kr`) and `metal` a mirror; layered materials
//! (`coateddiffuse`, v3 `plastic`, `uber`, `substrate`, ...) their diffuse colour, with a
//! warning.
//!
//! **Lights.** `distant` (`L`, or v4's `illuminance`), `infinite` (constant `L`, or v4's
//! `illuminance`: E = π L), `point` and `spot` (`I`, or v4's `power`), each times
//! `scale`. Image-based infinite lights (`filename` in v4, an equal-area square;
//! `mapname` in v3, latitude-longitude; OpenEXR, PFM, Radiance HDR, PNG or JPEG) become
//! environment maps turned by the light's transform, times `L` and `scale` (or scaled to
//! v4's `illuminance`): `pbrt_to_map` has the mapping. The maps are read when the scene is
//! prepared; one that cannot be used is a constant sky of the light's colour, with a
//! warning naming the file.
//!
//! **Area lights.** `AreaLightSource "diffuse"` (pbrt-v3 also calls it `"area"`) turns
//! the shapes after it in its attribute block into emitting meshes, as a `Light::Mesh`
//! replaces an emitting mesh everywhere in tress: `L` × `scale`, or v4's `power` over π ×
//! the shape's area (per side), from the side pbrt's surface normal faces, or both with
//! `twosided` (Pharr et al. 4th ed. §12.5).
//!
//! **Handedness.** pbrt's camera space is left-handed, tress's right-handed: rendered
//! as they are, pbrt scenes would come out mirrored. The import mirrors the world about the
//! camera's vertical plane instead, so images match pbrt's.
//!
//! Everything else (textures, media, other area lights, object instances, other shapes and
//! cameras) is skipped with one warning per kind; spectra other than `rgb` become grey of
//! the same scale. Every parameter the import does not read is reported once per
//! directive and name, with the file and line of its first use and how often it recurs,
//! as pbrt reports unused parameters.

use super::imported::Imported;
use crate::error::LoadError;
use crate::geometry::curve::{cubic_point, CubicBasis};
use crate::geometry::loop_subdivision;
use crate::geometry::subdivision::{MAX_FACES_PER_FILE, MAX_FACES_PER_MESH};
use crate::geometry::{StrandSet, TriangleMesh};
use crate::light::{Light, MapPlacement};
use crate::scene::{
    CameraDesc, CameraProjection, EnvironmentFile, Film, FilmFit, HairEntry, HairSource, LightSource, MaterialSource,
    MeshEntry, MeshSource, Projection,
};
use crate::shading::hair_bsdf::{color_from_sigma_a, Absorption, HairParams, PhysicalHair};
use crate::shading::Material;
use crate::world::Integrator;
use glam::{Affine3A, DMat4, DVec3, Vec3};
use std::cell::Cell;
use std::collections::{BTreeMap, BTreeSet, HashMap};
use std::path::{Path, PathBuf};

/// Deepest nesting of `Include`/`Import`.
const MAX_INCLUDE_DEPTH: usize = 32;
/// Most `Include`/`Import`s in a scene, counting every inclusion of a file: nesting alone
/// bounds nothing, as a file including the next one twice doubles the work at each level.
const MAX_INCLUDES: usize = 10_000;
/// Most linear pieces per curve segment (`splitdepth` up to 6).
const MAX_SPLIT_DEPTH: u32 = 6;

/// Reads a `.pbrt` file and the files it includes.
pub fn read_pbrt(path: &Path) -> Result<Imported, LoadError> {
    let text = read_text(path)?;
    parse_pbrt(&text, path)
}

/// Reads pbrt text; `path` names it in messages and anchors relative paths.
pub fn parse_pbrt(text: &str, path: &Path) -> Result<Imported, LoadError> {
    let dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
    let mut p = Parser::new(dir);
    p.file(text, path, 0)?;
    p.finish()
}

/// The text of a pbrt file, decompressed first when it is gzip data (pbrt reads
/// `geometry.pbrt.gz` the same way).
fn read_text(path: &Path) -> Result<String, LoadError> {
    let bytes = super::gzip::read_file(path, crate::input_file::Kind::ImportedScene)?;
    String::from_utf8(bytes).map_err(|_| LoadError::format(path, "the file is not UTF-8 text"))
}

// ----- tokens -----

#[derive(Clone, Copy, Debug, PartialEq)]
enum Kind {
    Word,
    Str,
    Open,
    Close,
}

#[derive(Clone, Copy, Debug)]
struct Token<'a> {
    text: &'a str,
    kind: Kind,
    line: u32,
}

struct Lexer<'a> {
    src: &'a str,
    pos: usize,
    line: u32,
    peeked: Option<Token<'a>>,
}

impl<'a> Lexer<'a> {
    fn new(src: &'a str) -> Lexer<'a> {
        Lexer { src, pos: 0, line: 1, peeked: None }
    }

    fn peek(&mut self) -> Result<Option<Token<'a>>, (u32, String)> {
        if self.peeked.is_none() {
            self.peeked = self.lex()?;
        }
        Ok(self.peeked)
    }

    fn next(&mut self) -> Result<Option<Token<'a>>, (u32, String)> {
        match self.peeked.take() {
            Some(t) => Ok(Some(t)),
            None => self.lex(),
        }
    }

    fn lex(&mut self) -> Result<Option<Token<'a>>, (u32, String)> {
        let b = self.src.as_bytes();
        loop {
            match b.get(self.pos) {
                None => return Ok(None),
                Some(b'\n') => {
                    self.line += 1;
                    self.pos += 1;
                }
                Some(c) if c.is_ascii_whitespace() => self.pos += 1,
                Some(b'#') => {
                    while self.pos < b.len() && b[self.pos] != b'\n' {
                        self.pos += 1;
                    }
                }
                Some(&c) => {
                    let line = self.line;
                    let start = self.pos;
                    return Ok(Some(match c {
                        b'[' | b']' => {
                            self.pos += 1;
                            Token {
                                text: &self.src[start..start + 1],
                                kind: if c == b'[' { Kind::Open } else { Kind::Close },
                                line,
                            }
                        }
                        b'"' => {
                            let mut i = start + 1;
                            while i < b.len() && b[i] != b'"' {
                                if b[i] == b'\n' {
                                    return Err((line, "unterminated string".into()));
                                }
                                i += 1 + usize::from(b[i] == b'\\');
                            }
                            if i >= b.len() {
                                return Err((line, "unterminated string".into()));
                            }
                            self.pos = i + 1;
                            let text = self.src.get(start + 1..i).ok_or((line, "bad UTF-8 in a string".to_string()))?;
                            Token { text, kind: Kind::Str, line }
                        }
                        _ => {
                            while self.pos < b.len()
                                && !b[self.pos].is_ascii_whitespace()
                                && !matches!(b[self.pos], b'"' | b'[' | b']' | b'#')
                            {
                                self.pos += 1;
                            }
                            let text = self.src.get(start..self.pos).ok_or((line, "bad UTF-8".to_string()))?;
                            Token { text, kind: Kind::Word, line }
                        }
                    }));
                }
            }
        }
    }
}

// ----- parameters -----

/// One parameter of a directive: `"type name" value` or `"type name" [values]`.
#[derive(Clone, Debug)]
struct Param {
    ty: String,
    name: String,
    numbers: Vec<f64>,
    strings: Vec<String>,
    line: u32,
    /// Set when the importer reads the parameter; the others are reported (pbrt itself
    /// reports parameters nothing used).
    used: Cell<bool>,
}

struct Params {
    list: Vec<Param>,
    line: u32,
}

type Res<T> = Result<T, (u32, String)>;

impl Params {
    /// The last parameter called `name`, marked as used.
    fn get(&self, name: &str) -> Option<&Param> {
        let p = self.list.iter().rev().find(|p| p.name == name)?;
        p.used.set(true);
        Some(p)
    }

    /// True when the list has a parameter `name`, without marking it used.
    fn has(&self, name: &str) -> bool {
        self.list.iter().any(|p| p.name == name)
    }

    /// Marks parameters that change nothing in tress's image as used.
    fn ignore(&self, names: &[&str]) {
        for p in &self.list {
            if names.contains(&p.name.as_str()) {
                p.used.set(true);
            }
        }
    }

    fn floats(&self, name: &str) -> Option<&[f64]> {
        self.get(name).map(|p| p.numbers.as_slice())
    }

    fn float(&self, name: &str, default: f64) -> Res<f64> {
        match self.get(name) {
            None => Ok(default),
            Some(p) => match p.numbers.as_slice() {
                [v] => Ok(*v),
                _ => Err((p.line, format!("\"{}\" must be one number", p.name))),
            },
        }
    }

    fn int(&self, name: &str, default: i64) -> Res<i64> {
        let v = self.float(name, default as f64)?;
        match v.fract() == 0.0 && v.abs() < 1e15 {
            true => Ok(v as i64),
            false => Err((self.get(name).map_or(self.line, |p| p.line), format!("\"{name}\" must be an integer"))),
        }
    }

    fn string(&self, name: &str, default: &str) -> Res<String> {
        match self.get(name) {
            None => Ok(default.to_string()),
            Some(p) => match p.strings.as_slice() {
                [s] => Ok(s.clone()),
                _ => Err((p.line, format!("\"{}\" must be one string", p.name))),
            },
        }
    }

    fn boolean(&self, name: &str, default: bool) -> Res<bool> {
        match self.get(name) {
            None => Ok(default),
            Some(p) => match p.strings.as_slice() {
                [t] if t == "true" => Ok(true),
                [f] if f == "false" => Ok(false),
                _ => Err((p.line, format!("\"{}\" must be true or false", p.name))),
            },
        }
    }

    fn point3s(&self, name: &str) -> Res<Option<Vec<DVec3>>> {
        let Some(p) = self.get(name) else { return Ok(None) };
        if p.numbers.len() % 3 != 0 {
            return Err((p.line, format!("\"{}\" has {} numbers, not a multiple of 3", p.name, p.numbers.len())));
        }
        Ok(Some(p.numbers.chunks(3).map(|c| DVec3::new(c[0], c[1], c[2])).collect()))
    }

    /// A colour: `rgb` as is; `blackbody`, `spectrum` and named spectra as grey (their
    /// scale), noted in `warn`.
    fn color(&self, name: &str, default: Vec3, warn: &mut BTreeSet<String>) -> Res<Vec3> {
        let Some(p) = self.get(name) else { return Ok(default) };
        // Colours are kept in single precision: a number finite in f64 but past f32's
        // range (1e39) would become infinite there.
        if p.ty != "texture" && p.numbers.iter().any(|v| !(*v as f32).is_finite()) {
            return Err((p.line, format!("\"{} {}\" is beyond single precision", p.ty, p.name)));
        }
        match p.ty.as_str() {
            "rgb" | "color" => match p.numbers.as_slice() {
                [r, g, b] => Ok(DVec3::new(*r, *g, *b).as_vec3()),
                _ => Err((p.line, format!("\"rgb {}\" must be three numbers", p.name))),
            },
            "blackbody" => {
                warn.insert("blackbody spectra are rendered as white".into());
                Ok(Vec3::ONE)
            }
            "spectrum" => {
                warn.insert("spectra other than rgb are rendered as grey of their mean value".into());
                let values: Vec<f64> = p.numbers.chunks(2).filter_map(|c| c.get(1).copied()).collect();
                Ok(Vec3::splat(if values.is_empty() {
                    1.0
                } else {
                    (values.iter().sum::<f64>() / values.len() as f64) as f32
                }))
            }
            "float" => match p.numbers.as_slice() {
                [v] => Ok(Vec3::splat(*v as f32)),
                _ => Err((p.line, format!("\"{}\" must be one number", p.name))),
            },
            "texture" => {
                warn.insert("textures are not supported: materials use their default values".into());
                Ok(default)
            }
            t => Err((p.line, format!("\"{t} {}\" is not a colour", p.name))),
        }
    }
}

// ----- parser -----

#[derive(Clone)]
struct State {
    ctm: DMat4,
    material: usize,
    reverse: bool,
    /// The `AreaLightSource` the shapes that follow emit, in this attribute block.
    area_light: Option<AreaLight>,
}

/// A `diffuse` area light (Pharr et al. 4th ed. §12.5, "DiffuseAreaLight"): every shape
/// under it emits `radiance` from the side its surface normal faces, or from both sides.
#[derive(Clone, Copy)]
struct AreaLight {
    radiance: Vec3,
    two_sided: bool,
    /// pbrt-v4's `power`: the radiance is scaled so that each shape emits this many watts.
    power: Option<f32>,
}

struct Parser {
    dir: PathBuf,
    out: Imported,
    state: State,
    stack: Vec<State>,
    named_coords: HashMap<String, DMat4>,
    named_materials: HashMap<String, usize>,
    materials: Vec<Material>,
    /// Strands by material index, in order of first use.
    strands: Vec<(usize, StrandSet)>,
    camera_to_world: Option<DMat4>,
    /// `Camera "orthographic"`: parallel rays through a screen window measured in camera
    /// space units, rather than a perspective camera's `fov`.
    orthographic: bool,
    fov: f64,
    /// Half the width and height of the camera's screen window when the file sets one
    /// (`screenwindow`, `frameaspectratio`), in units of the tangent of half `fov`; else
    /// the window is 1 on the shorter image side, whatever the image size.
    screen: Option<[f64; 2]>,
    /// The centre of the camera's screen window in units of its half width and height
    /// (`screenwindow`; 0 when centred).
    screen_centre: [f64; 2],
    /// pbrt's imaging ratio (Film `iso` / 100 × the camera's exposure time × v3's Film
    /// `scale`): the factor between scene radiance and pixel values.
    image_scale: f64,
    /// The file being read, as messages name it.
    file_name: String,
    /// Where each of `out`'s lights was read: file (as messages name it) and line.
    light_at: Vec<(String, u32)>,
    /// Parameters nothing read, by directive and declaration: where each was first seen
    /// and how many times.
    unused: BTreeMap<(String, String), (String, u32, usize)>,
    warnings: BTreeSet<String>,
    /// The files being read, the outermost first, to name an include cycle.
    chain: Vec<PathBuf>,
    /// `Include`/`Import`s read so far, and their bytes, for [`MAX_INCLUDES`] and the
    /// size cap of one imported scene.
    includes: usize,
    included_bytes: u64,
    /// Names of the `ObjectBegin`s not yet ended, the outermost first.
    open_objects: Vec<String>,
    /// Triangles `loopsubdiv` shapes have made so far (bounded by `MAX_FACES_PER_FILE`).
    subdivided_faces: usize,
}

impl Parser {
    fn new(dir: PathBuf) -> Parser {
        Parser {
            dir,
            out: Imported::default(),
            state: State { ctm: DMat4::IDENTITY, material: 0, reverse: false, area_light: None },
            stack: Vec::new(),
            named_coords: HashMap::new(),
            named_materials: HashMap::new(),
            // pbrt's default material is diffuse with reflectance 0.5.
            materials: vec![Material::Diffuse { color: Vec3::splat(0.5) }],
            strands: Vec::new(),
            camera_to_world: None,
            orthographic: false,
            fov: 90.0,
            screen: None,
            screen_centre: [0.0, 0.0],
            image_scale: 1.0,
            file_name: String::new(),
            light_at: Vec::new(),
            unused: BTreeMap::new(),
            warnings: BTreeSet::new(),
            chain: Vec::new(),
            includes: 0,
            included_bytes: 0,
            open_objects: Vec::new(),
            subdivided_faces: 0,
        }
    }

    fn file(&mut self, text: &str, path: &Path, depth: usize) -> Result<(), LoadError> {
        self.chain.push(std::fs::canonicalize(path).unwrap_or_else(|_| path.to_path_buf()));
        let read = self.file_body(text, path, depth);
        self.chain.pop();
        read
    }

    fn file_body(&mut self, text: &str, path: &Path, depth: usize) -> Result<(), LoadError> {
        let at = |(line, msg): (u32, String)| LoadError::format(path, format!("line {line}: {msg}"));
        let parent = std::mem::replace(&mut self.file_name, path.display().to_string());
        let mut lex = Lexer::new(text);
        while let Some(t) = lex.next().map_err(at)? {
            if t.kind != Kind::Word {
                return Err(at((t.line, format!("expected a directive, found `{}`", t.text))));
            }
            if matches!(t.text, "Include" | "Import") {
                let name = string_arg(&mut lex, t).map_err(at)?;
                if depth >= MAX_INCLUDE_DEPTH {
                    return Err(at((t.line, format!("includes nest deeper than {MAX_INCLUDE_DEPTH} (a cycle?)"))));
                }
                let child = self.dir.join(&name);
                let canonical = std::fs::canonicalize(&child).unwrap_or_else(|_| child.clone());
                if let Some(start) = self.chain.iter().position(|p| *p == canonical) {
                    let names: Vec<String> =
                        self.chain[start..].iter().chain([&canonical]).map(|p| p.display().to_string()).collect();
                    return Err(at((t.line, format!("include cycle: {}", names.join(" includes ")))));
                }
                self.includes += 1;
                if self.includes > MAX_INCLUDES {
                    return Err(at((
                        t.line,
                        format!("more than {MAX_INCLUDES} includes in all (files including each other repeatedly?)"),
                    )));
                }
                let text = read_text(&child)?;
                self.included_bytes += text.len() as u64;
                let cap = crate::input_file::Kind::ImportedScene.cap();
                if self.included_bytes > cap {
                    return Err(at((
                        t.line,
                        format!("the included files hold more than {} in all", crate::stats::human_bytes(cap)),
                    )));
                }
                self.file(&text, &child, depth + 1)?;
                continue;
            }
            self.directive(&mut lex, t).map_err(at)?;
        }
        self.file_name = parent;
        Ok(())
    }

    /// Notes every parameter of `p` that nothing read, for one warning per directive kind
    /// and parameter.
    fn check_used(&mut self, directive: &str, kind: &str, p: &Params) {
        for q in p.list.iter().filter(|q| !q.used.get()) {
            let decl = match q.ty.is_empty() {
                true => q.name.clone(),
                false => format!("{} {}", q.ty, q.name),
            };
            let key = (format!("{directive} \"{kind}\""), decl);
            // An included file is named; the file read is named by every warning already.
            let file = if self.chain.len() > 1 { self.file_name.clone() } else { String::new() };
            self.unused.entry(key).or_insert_with(|| (file, q.line, 0)).2 += 1;
        }
    }

    fn directive(&mut self, lex: &mut Lexer, t: Token) -> Res<()> {
        let line = t.line;
        match t.text {
            "Identity" => self.state.ctm = DMat4::IDENTITY,
            "Translate" => {
                let v = numbers(lex, 3, t)?;
                self.apply(DMat4::from_translation(DVec3::new(v[0], v[1], v[2])));
            }
            "Scale" => {
                let v = numbers(lex, 3, t)?;
                self.apply(DMat4::from_scale(DVec3::new(v[0], v[1], v[2])));
            }
            "Rotate" => {
                let v = numbers(lex, 4, t)?;
                let axis = DVec3::new(v[1], v[2], v[3])
                    .try_normalize()
                    .ok_or((line, "Rotate about a zero axis".to_string()))?;
                self.apply(DMat4::from_axis_angle(axis, v[0].to_radians()));
            }
            "LookAt" => {
                let v = numbers(lex, 9, t)?;
                let (eye, look, up) =
                    (DVec3::new(v[0], v[1], v[2]), DVec3::new(v[3], v[4], v[5]), DVec3::new(v[6], v[7], v[8]));
                let dir = (look - eye).try_normalize().ok_or((line, "LookAt: eye and target coincide".to_string()))?;
                let right = up
                    .normalize_or_zero()
                    .cross(dir)
                    .try_normalize()
                    .ok_or((line, "LookAt: up is parallel to the view".to_string()))?;
                let new_up = dir.cross(right);
                // pbrt's LookAt: camera-from-world, camera x = right, y = up, z = forward.
                let camera_to_world =
                    DMat4::from_cols(right.extend(0.0), new_up.extend(0.0), dir.extend(0.0), eye.extend(1.0));
                self.apply(camera_to_world.inverse());
            }
            "Transform" | "ConcatTransform" => {
                let v = numbers(lex, 16, t)?;
                let m = DMat4::from_cols_slice(&v);
                if t.text == "Transform" {
                    self.state.ctm = m;
                } else {
                    self.apply(m);
                }
            }
            "CoordinateSystem" => {
                let name = string_arg(lex, t)?;
                self.named_coords.insert(name, self.state.ctm);
            }
            "CoordSysTransform" => {
                let name = string_arg(lex, t)?;
                match self.named_coords.get(&name) {
                    Some(m) => self.state.ctm = *m,
                    None => return Err((line, format!("CoordSysTransform \"{name}\": no such coordinate system"))),
                }
            }
            "ReverseOrientation" => self.state.reverse = !self.state.reverse,
            "AttributeBegin" | "TransformBegin" => {
                if self.stack.len() > 10_000 {
                    return Err((line, "AttributeBegin nests too deep".into()));
                }
                self.stack.push(self.state.clone());
            }
            "AttributeEnd" | "TransformEnd" => {
                let s = self.stack.pop().ok_or((line, format!("{} without a matching begin", t.text)))?;
                if t.text == "TransformEnd" {
                    self.state.ctm = s.ctm;
                } else {
                    self.state = s;
                }
            }
            "WorldBegin" => {
                self.named_coords.insert("world".into(), DMat4::IDENTITY);
                self.state.ctm = DMat4::IDENTITY;
            }
            "WorldEnd" => {}
            "Camera" => {
                let (kind, p) = named(lex, t)?;
                self.named_coords.insert("camera".into(), self.state.ctm.inverse());
                if self.state.ctm.determinant().abs() < 1e-12 {
                    return Err((line, "the camera transform is singular".into()));
                }
                let c2w = self.state.ctm.inverse();
                // The camera is kept in single precision: an eye finite in f64 but past
                // f32's range (`LookAt 1e39 ...`) would become infinite there.
                let eye = c2w.transform_point3(DVec3::ZERO);
                if !(eye.as_vec3().is_finite() && (eye + c2w.transform_vector3(DVec3::Z)).as_vec3().is_finite()) {
                    return Err((line, "the camera's position is beyond single precision".into()));
                }
                self.camera_to_world = Some(c2w);
                self.orthographic = kind == "orthographic";
                if !self.orthographic && kind != "perspective" {
                    self.warnings.insert(format!("camera \"{kind}\" is rendered as a perspective camera"));
                }
                // An orthographic camera has no `fov`: one given is reported unused, as pbrt does.
                if !self.orthographic {
                    self.fov = p.float("fov", 90.0)?;
                    if !(self.fov > 0.0 && self.fov < 180.0) {
                        return Err((line, format!("fov {} is not between 0 and 180", self.fov)));
                    }
                }
                self.screen_centre = [0.0, 0.0];
                self.screen = self.screen_window(&p)?;
                if !self.aperture().iter().all(|a| a.is_finite() && *a > 0.0) {
                    return Err((line, "the camera's screen window is beyond single precision".into()));
                }
                // pbrt-v4's exposure time is the shutter interval (Pharr et al. 4th ed. §5.4.2).
                let exposure = p.float("shutterclose", 1.0)? - p.float("shutteropen", 0.0)?;
                if !(exposure.is_finite() && exposure > 0.0) {
                    return Err((line, format!("the shutter interval {exposure} must be positive")));
                }
                self.image_scale *= exposure;
                self.check_image_scale(line)?;
                // tress's camera is a pinhole, as pbrt's thin lens of radius 0 (its default),
                // whose focus distance changes nothing; a wider lens is said once, its focus
                // distance with it.
                if p.float("lensradius", 0.0)? > 0.0 {
                    self.warnings.insert("camera `lensradius`: depth of field is not applied (rendered sharp)".into());
                }
                p.ignore(&["focaldistance"]);
                self.check_used("Camera", &kind, &p);
            }
            "Film" => {
                let (kind, p) = named(lex, t)?;
                let (w, h) = (p.int("xresolution", 1280)?, p.int("yresolution", 720)?);
                if !(1..=65536).contains(&w) || !(1..=65536).contains(&h) {
                    return Err((line, format!("resolution {w}x{h} is out of range")));
                }
                self.out.resolution = Some([w as u32, h as u32]);
                // pbrt-v4's sensor: imaging ratio = exposure time × ISO / 100 (PixelSensor);
                // pbrt-v3's film multiplies by its `scale`.
                let (iso, scale) = (p.float("iso", 100.0)?, p.float("scale", 1.0)?);
                if !(iso.is_finite() && iso > 0.0 && scale.is_finite() && scale > 0.0) {
                    return Err((line, format!("Film iso {iso} and scale {scale} must be positive")));
                }
                self.image_scale *= iso / 100.0 * scale;
                self.check_image_scale(line)?;
                // pbrt-v4 scales a sample whose largest channel is above it down to it,
                // tress's `max_sample_value` (applied to the samples as tress renders them,
                // the lights already scaled by the sensor as pbrt's sample values are).
                if p.get("maxcomponentvalue").is_some() {
                    let max = p.float("maxcomponentvalue", f64::INFINITY)?;
                    if max.is_nan() || max <= 0.0 {
                        return Err((line, format!("Film maxcomponentvalue {max} must be positive")));
                    }
                    self.out.max_sample_value = Some(max as f32);
                }
                // Where pbrt writes its image: nothing to do with tress's.
                p.ignore(&["filename"]);
                self.check_used("Film", &kind, &p);
            }
            "Sampler" => {
                let (kind, p) = named(lex, t)?;
                if p.get("pixelsamples").is_some() {
                    let n = p.int("pixelsamples", 16)?;
                    self.out.spp = Some(n.clamp(1, 1 << 20) as u32);
                }
                // The sampler's seed picks a noise pattern, not a look.
                p.ignore(&["seed"]);
                self.check_used("Sampler", &kind, &p);
            }
            "Integrator" => {
                let (kind, p) = named(lex, t)?;
                self.integrator(&kind, &p)?;
                self.check_used("Integrator", &kind, &p);
            }
            "Material" => {
                let (kind, p) = named(lex, t)?;
                self.state.material = self.material(&kind, &p)?;
                self.check_used("Material", &kind, &p);
            }
            "MakeNamedMaterial" => {
                let (name, p) = named(lex, t)?;
                let kind = p.string("type", "")?;
                let m = self.material(&kind, &p)?;
                self.named_materials.insert(name, m);
                self.check_used("Material", &kind, &p);
            }
            "NamedMaterial" => {
                let name = string_arg(lex, t)?;
                self.state.material = *self
                    .named_materials
                    .get(&name)
                    .ok_or((line, format!("NamedMaterial \"{name}\" is not defined")))?;
            }
            "LightSource" => {
                let (kind, p) = named(lex, t)?;
                if self.light(&kind, &p)? {
                    self.check_used("LightSource", &kind, &p);
                }
            }
            "Shape" => {
                let (kind, p) = named(lex, t)?;
                if self.shape(&kind, &p)? {
                    self.check_used("Shape", &kind, &p);
                }
            }
            // Instancing is not supported (an object's shapes are read where they stand),
            // but an object that instances itself, directly or through one it is inside,
            // is an error in any reader: named, not skipped.
            "ObjectBegin" | "ObjectInstance" => {
                let name = string_arg(lex, t)?;
                if t.text == "ObjectBegin" {
                    self.open_objects.push(name);
                } else if let Some(i) = self.open_objects.iter().position(|o| *o == name) {
                    let chain: Vec<String> = self.open_objects[i..].iter().map(|o| format!("\"{o}\"")).collect();
                    return Err((line, format!("object cycle: {} instances \"{name}\"", chain.join(" contains "))));
                }
                self.warnings.insert(format!("`{}` is not supported: skipped", t.text));
            }
            "ObjectEnd" => {
                self.open_objects.pop();
                self.warnings.insert(format!("`{}` is not supported: skipped", t.text));
            }
            "AreaLightSource" => {
                let (kind, p) = named(lex, t)?;
                self.state.area_light = self.area_light(&kind, &p)?;
                if self.state.area_light.is_some() {
                    self.check_used("AreaLightSource", &kind, &p);
                }
            }
            "Texture" | "MakeNamedMedium" | "PixelFilter" | "Accelerator" | "ColorSpace" | "Option" | "Attribute"
            | "MediumInterface" => {
                let _ = rest_params(lex)?;
                self.warnings.insert(format!("`{}` is not supported: skipped", t.text));
            }
            "TransformTimes" | "ActiveTransform" => {
                let _ = rest_params(lex)?;
                self.warnings.insert(format!("`{}` is not supported: skipped", t.text));
            }
            other => return Err((line, format!("unknown directive `{other}`"))),
        }
        Ok(())
    }

    /// The camera's screen window as half its width and height, when `p` sets one:
    /// `screenwindow` (x min, x max, y min, y max), else `frameaspectratio` f, whose
    /// window is [-f, f] × [-1, 1] when f > 1 and [-1, 1] × [-1/f, 1/f] otherwise, as pbrt
    /// builds it. The centre of a `screenwindow` goes to `screen_centre`.
    fn screen_window(&mut self, p: &Params) -> Res<Option<[f64; 2]>> {
        let line = p.line;
        if let Some(w) = p.floats("screenwindow") {
            let &[x0, x1, y0, y1] = w else {
                return Err((line, format!("\"screenwindow\" has {} numbers, not 4", w.len())));
            };
            if !(w.iter().all(|v| v.is_finite()) && x1 > x0 && y1 > y0) {
                return Err((line, format!("screenwindow [{x0} {x1} {y0} {y1}] is not a window")));
            }
            self.screen_centre = [(x0 + x1) / (x1 - x0), (y0 + y1) / (y1 - y0)];
            return Ok(Some([0.5 * (x1 - x0), 0.5 * (y1 - y0)]));
        }
        if !p.has("frameaspectratio") {
            return Ok(None);
        }
        let f = p.float("frameaspectratio", 1.0)?;
        match f.is_finite() && f > 0.0 {
            true => Ok(Some(if f > 1.0 { [f, 1.0] } else { [1.0, 1.0 / f] })),
            false => Err((line, format!("frameaspectratio {f} must be finite and positive"))),
        }
    }

    /// The camera's film aperture (width, height): for a perspective camera in units of
    /// its distance, for an orthographic one in scene units.
    ///
    /// pbrt maps its screen window onto the image (Pharr et al. 4th ed. §5.2): by default
    /// [-1, 1] on the shorter image side, the longer side following the image's aspect. A
    /// perspective camera's `fov` spans the window's extent of 2, so its film is an
    /// aperture of 2 tan(fov / 2) times the window; an orthographic camera's window is
    /// measured in camera space (§5.2.1), whose units are the lengths of the camera's axes
    /// in the scene (a `Scale` before `Camera` changes them). Either is overscanned: the
    /// shorter side fits, for the file's image size and one given later alike.
    fn aperture(&self) -> [f32; 2] {
        let [sx, sy] = self.screen.unwrap_or([1.0, 1.0]);
        let [kx, ky] = match (self.orthographic, self.camera_to_world) {
            (true, Some(c2w)) => [c2w.transform_vector3(DVec3::X).length(), c2w.transform_vector3(DVec3::Y).length()],
            (true, None) => [1.0, 1.0],
            (false, _) => [(0.5 * self.fov.to_radians()).tan(); 2],
        };
        [(2.0 * sx * kx) as f32, (2.0 * sy * ky) as f32]
    }

    /// The imaging ratio scales the lights in single precision: one past f32's range (or
    /// below its smallest number) would make them infinite (or black).
    fn check_image_scale(&self, line: u32) -> Res<()> {
        let k = self.image_scale as f32;
        match k.is_finite() && k > 0.0 {
            true => Ok(()),
            false => Err((
                line,
                "the imaging ratio (Film iso / 100 × scale × the camera's shutter interval) is beyond single precision"
                    .into(),
            )),
        }
    }

    fn apply(&mut self, m: DMat4) {
        self.state.ctm *= m;
    }

    /// The integrator: pbrt's path tracers (`path`, `volpath`, `bdpt`, `mlt`, `sppm`, ...)
    /// become tress's path tracer, the direct-lighting ones its direct integrator.
    fn integrator(&mut self, kind: &str, p: &Params) -> Res<()> {
        let depth = p.int("maxdepth", 5)?.clamp(0, 65) as u32;
        let integrator = match kind {
            "path" | "volpath" | "bdpt" | "mlt" | "sppm" | "simplepath" | "simplevolpath" | "lightpath"
            | "randomwalk" => Integrator::Path,
            "directlighting" | "whitted" => Integrator::Direct,
            other => {
                self.warnings.insert(format!("integrator \"{other}\" is not one tress has: rendered by path tracing"));
                Integrator::Path
            }
        };
        self.set_integrator(integrator, depth);
        Ok(())
    }

    /// pbrt's `maxdepth` counts every scattering event, the first included: a path of
    /// maxdepth 1 is direct light only, which is tress's path depth 0. For Whitted-style
    /// integrators both count specular bounces.
    fn set_integrator(&mut self, integrator: Integrator, maxdepth: u32) {
        let depth = match integrator {
            Integrator::Path => {
                if maxdepth == 0 {
                    self.warnings
                        .insert("maxdepth 0 shows only light sources in pbrt: rendered with direct light".into());
                }
                maxdepth.saturating_sub(1)
            }
            _ => maxdepth,
        };
        self.out.integrator = Some(integrator);
        self.out.max_depth = Some(depth.min(64));
    }

    /// A material of pbrt-v4 (`diffuse`, `dielectric`, `conductor`, `hair`, ...) or pbrt-v3
    /// (`matte`, `plastic`, `glass`, `mirror`, `metal`, `hair`, ...): what tress has for it.
    fn material(&mut self, kind: &str, p: &Params) -> Res<usize> {
        let w = &mut self.warnings;
        let grey = |v: f32| Vec3::splat(v);
        let approximate = |w: &mut BTreeSet<String>, what: &str| {
            w.insert(format!("material \"{kind}\" is rendered as {what}"));
        };
        let m = match kind {
            "hair" => Material::Physical(hair_material(p, w)?),
            "diffuse" => Material::Diffuse { color: p.color("reflectance", grey(0.5), w)? },
            // pbrt-v3's Lambertian material.
            "matte" => Material::Diffuse { color: p.color("Kd", grey(0.5), w)? },
            "coateddiffuse" | "diffusetransmission" => {
                approximate(w, "its diffuse reflectance");
                let d = if kind == "coateddiffuse" { 0.5 } else { 0.25 };
                Material::Diffuse { color: p.color("reflectance", grey(d), w)? }
            }
            // pbrt-v3's layered materials: their diffuse part (pbrt-v3's defaults).
            "plastic" | "uber" | "translucent" | "substrate" | "kdsubsurface" => {
                approximate(w, "its diffuse colour Kd");
                let d = if matches!(kind, "substrate" | "kdsubsurface") { 0.5 } else { 0.25 };
                Material::Diffuse { color: p.color("Kd", grey(d), w)? }
            }
            "disney" => {
                approximate(w, "its diffuse colour");
                Material::Diffuse { color: p.color("color", grey(0.5), w)? }
            }
            "dielectric" | "thindielectric" | "glass" => {
                // pbrt-v3's glass calls the index of refraction `index`.
                let eta = match p.has("eta") {
                    true => p.float("eta", 1.5)?,
                    false => p.float("index", 1.5)?,
                };
                if !(eta.is_finite() && eta >= 1.0) {
                    return Err((p.line, format!("eta {eta} must be at least 1")));
                }
                if !(eta as f32).is_finite() {
                    return Err((p.line, "eta is beyond single precision".into()));
                }
                Material::Glass { ior: eta as f32, color: Vec3::ONE }
            }
            "conductor" | "coatedconductor" | "metal" => {
                if !p.has("reflectance") {
                    approximate(w, "a grey mirror (tress has no conductor with eta and k)");
                }
                Material::Mirror { color: p.color("reflectance", grey(0.9), w)? }
            }
            "mirror" => Material::Mirror { color: p.color("Kr", grey(0.9), w)? },
            "" | "none" | "interface" => Material::Diffuse { color: grey(0.5) },
            _ => {
                approximate(w, "its diffuse colour");
                let name = ["reflectance", "Kd", "color"].into_iter().find(|n| p.has(n)).unwrap_or("reflectance");
                Material::Diffuse { color: p.color(name, grey(0.5), w)? }
            }
        };
        let finite = |c: Vec3| c.is_finite() && c.min_element() >= 0.0;
        let ok = match &m {
            Material::Diffuse { color } | Material::Mirror { color } => finite(*color),
            _ => true,
        };
        if !ok {
            return Err((p.line, format!("material \"{kind}\": colours must be finite and not negative")));
        }
        // MakeNamedMaterial's `type` is read by the caller.
        p.ignore(&["type"]);
        self.materials.push(m);
        Ok(self.materials.len() - 1)
    }

    /// A light source; false when its kind is skipped (its parameters are then not
    /// reported one by one).
    fn light(&mut self, kind: &str, p: &Params) -> Res<bool> {
        let w = &mut self.warnings;
        // pbrt-v4's `scale` is a number; pbrt-v3's a spectrum (`"color scale" [12 12 12]`).
        let scale = p.color("scale", Vec3::ONE, w)?;
        let ctm = self.state.ctm;
        let point = |name: &str, d: DVec3| -> Res<Vec3> {
            let v = p.point3s(name)?.and_then(|v| v.first().copied()).unwrap_or(d);
            let at = ctm.transform_point3(v).as_vec3();
            match at.is_finite() {
                true => Ok(at),
                false => Err((p.line, format!("light \"{kind}\": \"{name}\" is beyond single precision"))),
            }
        };
        // pbrt-v4's photometric alternatives to `scale` (Pharr et al. 4th ed. §12.1-12.5):
        // a point light's power spreads over 4π sr, a spot's over its cone, a distant or
        // infinite light's illuminance is the irradiance it gives a surface facing it.
        let positive = |name: &str| positive(p, &format!("light \"{kind}\""), name);
        // pbrt-v3's lights take `samples` (shadow rays per shading point): noise, not look.
        p.ignore(&["samples", "nsamples"]);
        let light = match kind {
            "distant" => {
                let (from, to) = (point("from", DVec3::ZERO)?, point("to", DVec3::Z)?);
                let direction = (from - to).try_normalize().ok_or((p.line, "distant light: from = to".to_string()))?;
                let e = positive("illuminance")?.unwrap_or(1.0);
                Light::Distant { direction, irradiance: p.color("L", Vec3::ONE, w)? * scale * e }.into()
            }
            "infinite" => {
                // An image map: v4 `filename` (equal-area square), v3 `mapname` (lat-long).
                let map = match (p.has("filename"), p.has("mapname")) {
                    (true, _) => Some((p.string("filename", "")?, Projection::EqualArea)),
                    (_, true) => Some((p.string("mapname", "")?, Projection::LatLong)),
                    _ => None,
                };
                let colour = p.color("L", Vec3::ONE, w)? * scale;
                let illuminance = positive("illuminance")?;
                match map {
                    // Read by `prepare`; a file it cannot use becomes a constant sky of
                    // the light's colour, with a warning.
                    Some((file, projection)) => {
                        let to_world = crate::math::orthogonal_part(&glam::Affine3A::from_mat4(ctm.as_mat4()));
                        LightSource::File(EnvironmentFile {
                            path: self.dir.join(&file),
                            projection,
                            tint: colour,
                            illuminance,
                            placement: MapPlacement::new(0.0, 1.0).rotated(to_world * pbrt_to_map().transpose()),
                            fallback: Some(colour),
                        })
                    }
                    // A constant sky of radiance L gives a facing surface E = π L.
                    None => LightSource::Inline(Light::Environment {
                        radiance: colour * illuminance.map_or(1.0, |e| e / std::f32::consts::PI),
                        camera_visibility: 1.0,
                    }),
                }
            }
            "point" => {
                let k = positive("power")?.map_or(1.0, |phi| phi / (4.0 * std::f32::consts::PI));
                Light::Point {
                    position: point("from", DVec3::ZERO)?,
                    intensity: p.color("I", Vec3::ONE, w)? * scale * k,
                    decay: 2,
                }
                .into()
            }
            "spot" => {
                let (from, to) = (point("from", DVec3::ZERO)?, point("to", DVec3::Z)?);
                let direction = (to - from).try_normalize().ok_or((p.line, "spot light: from = to".to_string()))?;
                let cone = p.float("coneangle", 30.0)?.clamp(0.0, 180.0);
                let delta = p.float("conedelta", 5.0)?.clamp(0.0, cone);
                let (cos_inner, cos_outer) =
                    (((cone - delta) as f32).to_radians().cos(), (cone as f32).to_radians().cos());
                // pbrt-v4's spot power: I = Φ / (2π (1 − (cos_start + cos_end) / 2)).
                let k = positive("power")?.map_or(1.0, |phi| {
                    phi / (2.0 * std::f32::consts::PI * (1.0 - 0.5 * (cos_inner + cos_outer))).max(1e-6)
                });
                Light::Spot {
                    position: from,
                    direction,
                    intensity: p.color("I", Vec3::ONE, w)? * scale * k,
                    cos_inner,
                    cos_outer,
                    decay: 2,
                }
                .into()
            }
            other => {
                w.insert(format!("light \"{other}\" is not supported: skipped"));
                return Ok(false);
            }
        };
        if emission(&light).is_some_and(|c| !(c.is_finite() && c.min_element() >= 0.0)) {
            return Err((p.line, format!("light \"{kind}\": its emission must be finite and not negative")));
        }
        self.out.contents.lights.push(light);
        self.light_at.push((self.file_name.clone(), p.line));
        Ok(true)
    }

    /// An `AreaLightSource`: `diffuse` or `area` (`L` × `scale`, `twosided`, v4's `power`); other
    /// kinds are reported and their shapes drawn unlit.
    fn area_light(&mut self, kind: &str, p: &Params) -> Res<Option<AreaLight>> {
        // pbrt-v3 names the diffuse area light `area` too.
        if kind != "diffuse" && kind != "area" {
            self.warnings.insert(format!("area light \"{kind}\" is not supported: its shapes are drawn, not lit"));
            return Ok(None);
        }
        p.ignore(&["samples", "nsamples"]);
        let w = &mut self.warnings;
        let radiance = p.color("L", Vec3::ONE, w)? * p.color("scale", Vec3::ONE, w)?;
        if !(radiance.is_finite() && radiance.min_element() >= 0.0) {
            return Err((p.line, "area light \"diffuse\": its emission must be finite and not negative".into()));
        }
        if p.has("filename") {
            w.insert("area lights' image textures (`filename`) are not applied: they emit `L`".into());
        }
        let two_sided = p.boolean("twosided", false)?;
        Ok(Some(AreaLight { radiance, two_sided, power: positive(p, "area light \"diffuse\"", "power")? }))
    }

    /// The mesh of a shape under an area light, placed by `to_world`, as the light it is (it replaces the shape, as an emitting mesh does in tress). The side it
    /// emits from is pbrt's surface normal: the one the shape's vertex normals face when it
    /// has them (spheres, disks and cylinders face out), else the triangles' winding, a
    /// mirroring transform turning it; `ReverseOrientation` turns it again.
    fn push_area_light(&mut self, light: AreaLight, mesh: &TriangleMesh, to_world: Affine3A, line: u32) -> Res<()> {
        let normal_to_world = to_world.matrix3.inverse().transpose();
        let mirror = to_world.matrix3.determinant() < 0.0;
        let mut triangles = Vec::with_capacity(mesh.indices.len() * if light.two_sided { 2 } else { 1 });
        for (i, corners) in mesh.indices.iter().enumerate() {
            let [a, b, c] = mesh.corners(i as u32).map(|q| to_world.transform_point3(q));
            let winding = (b - a).cross(c - a);
            let facing = match &mesh.normals {
                Some(n) => normal_to_world * corners.iter().map(|&k| n[k as usize]).sum::<Vec3>(),
                None if mirror => -winding,
                None => winding,
            };
            let front = (winding.dot(facing) >= 0.0) != self.state.reverse;
            triangles.push(if front { [a, b, c] } else { [a, c, b] });
            if light.two_sided {
                triangles.push(if front { [a, c, b] } else { [a, b, c] });
            }
        }
        let Some(mut emitter) = crate::light::MeshLight::new(triangles, light.radiance, 1.0) else {
            self.warnings.insert("area lights on shapes of no area: not lit".into());
            return Ok(());
        };
        if let Some(power) = light.power {
            // Φ = π A L per side (a Lambertian emitter), A the shape's area.
            let sides = if light.two_sided { 2.0 } else { 1.0 };
            let area = emitter.area() / sides;
            let radiance = light.radiance * power / (std::f32::consts::PI * sides * area);
            if !radiance.is_finite() {
                return Err((line, "area light \"diffuse\": its power over its shape's area is not finite".into()));
            }
            emitter = emitter.with_radiance(radiance);
        }
        self.out.contents.lights.push(LightSource::Inline(Light::Mesh(emitter)));
        self.light_at.push((self.file_name.clone(), line));
        Ok(())
    }

    /// A shape; false when its kind is skipped.
    fn shape(&mut self, kind: &str, p: &Params) -> Res<bool> {
        let ctm = self.state.ctm;
        let transform = Affine3A::from_mat4(ctm.as_mat4());
        if !transform.is_finite() {
            return Err((p.line, "the shape's transform is not finite".into()));
        }
        let material = MaterialSource::Inline(self.materials[self.state.material].clone());
        match kind {
            "curve" => {
                if self.state.area_light.is_some() {
                    self.warnings.insert("area lights on curves are not supported (nor in pbrt): drawn unlit".into());
                }
                let strand = curve(p, &ctm)?;
                let m = self.state.material;
                let set = match self.strands.iter_mut().find(|(k, _)| *k == m) {
                    Some((_, s)) => s,
                    None => {
                        self.strands.push((m, StrandSet::new()));
                        &mut self.strands.last_mut().expect("just pushed").1
                    }
                };
                crate::memory::try_reserve(&mut set.points, strand.len(), "the curves' points")
                    .map_err(|e| (p.line, e.to_string()))?;
                set.push_strand(strand);
            }
            "trianglemesh" => self.push_mesh(triangle_mesh(p)?, material, transform, p.line)?,
            "loopsubdiv" => {
                let cage = triangle_mesh(p)?;
                // v4 names the level count `levels`, v3 `nlevels`; both default to 3.
                let levels = p.int(if p.has("nlevels") { "nlevels" } else { "levels" }, 3)?.clamp(0, 32) as u32;
                let room = MAX_FACES_PER_MESH.min(MAX_FACES_PER_FILE.saturating_sub(self.subdivided_faces));
                let (mesh, applied) = loop_subdivision::subdivide(&cage.positions, &cage.indices, levels, room);
                if applied < levels {
                    self.warnings.insert(format!(
                        "loopsubdiv: levels past {MAX_FACES_PER_MESH} triangles per mesh or {MAX_FACES_PER_FILE} \
                         per file are not applied"
                    ));
                }
                self.subdivided_faces += mesh.indices.len();
                self.push_mesh(mesh, material, transform, p.line)?;
            }
            "plymesh" => {
                let file = p.string("filename", "")?;
                let path = self.dir.join(&file);
                // pbrt reads `.ply.gz` too.
                let bytes = super::gzip::read_file(&path, crate::input_file::Kind::Geometry)
                    .map_err(|e| (p.line, e.to_string()))?;
                let mesh = super::ply::parse_ply(&bytes, &path).map_err(|e| (p.line, e.to_string()))?;
                self.push_mesh(mesh, material, transform, p.line)?;
            }
            "disk" | "cylinder" | "bilinearmesh" => {
                let mesh = match kind {
                    "disk" => surfaces::disk(p)?,
                    "cylinder" => surfaces::cylinder(p)?,
                    _ => surfaces::bilinear_mesh(p)?,
                };
                self.push_mesh(mesh, material, transform, p.line)?;
            }
            "sphere" => {
                let r = p.float("radius", 1.0)?;
                if !(r.is_finite() && r > 0.0) {
                    return Err((p.line, format!("sphere radius {r} must be positive")));
                }
                if !((r as f32).is_finite() && r as f32 > 0.0) {
                    return Err((p.line, "sphere radius is beyond single precision".into()));
                }
                self.push_mesh(TriangleMesh::sphere(r as f32, 48), material, transform, p.line)?;
            }
            other => {
                self.warnings.insert(format!("shape \"{other}\" is not supported: skipped"));
                return Ok(false);
            }
        }
        Ok(true)
    }

    /// A shape's mesh into the scene: drawn with `material`, or under an area light, that
    /// light.
    fn push_mesh(&mut self, mesh: TriangleMesh, material: MaterialSource, transform: Affine3A, line: u32) -> Res<()> {
        match self.state.area_light {
            Some(light) => self.push_area_light(light, &mesh, transform, line),
            None => {
                self.out.contents.meshes.push(MeshEntry {
                    source: MeshSource::Inline(mesh),
                    material,
                    transform,
                    visibility: Default::default(),
                });
                Ok(())
            }
        }
    }

    fn finish(mut self) -> Result<Imported, LoadError> {
        if self.out.integrator.is_none() {
            // pbrt's default integrator is a path tracer with maxdepth 5.
            self.set_integrator(Integrator::Path, 5);
        }
        if self.image_scale != 1.0 {
            let k = self.image_scale as f32;
            for (l, (file, line)) in self.out.contents.lights.iter().zip(&self.light_at) {
                if emission(l).is_some_and(|c| !(c * k).is_finite()) {
                    return Err(LoadError::format(
                        Path::new(file),
                        format!("line {line}: the light's emission × the imaging ratio is beyond single precision"),
                    ));
                }
            }
            for l in &mut self.out.contents.lights {
                match l {
                    LightSource::Inline(l) => scale_emission(l, k),
                    LightSource::File(f) => {
                        f.placement = f.placement.scaled(k);
                        f.fallback = f.fallback.map(|c| c * k);
                    }
                }
            }
        }
        for ((directive, decl), (file, line, count)) in std::mem::take(&mut self.unused) {
            let more = match count {
                1 => String::new(),
                n => format!(" (and {} more times)", n - 1),
            };
            let at = match file.is_empty() {
                true => format!("line {line}"),
                false => format!("{file}: line {line}"),
            };
            self.warnings.insert(format!("{at}: {directive}: parameter \"{decl}\" is not used{more}"));
        }
        for (m, set) in std::mem::take(&mut self.strands) {
            self.out.contents.hair.push(HairEntry {
                source: HairSource::Inline(set),
                material: self.materials[m].clone().into(),
                transform: Affine3A::IDENTITY,
                radius_scale: 1.0,
                file_colors: true,
                lod: None,
                visibility: Default::default(),
            });
        }
        if let Some(c2w) = self.camera_to_world {
            let eye = c2w.transform_point3(DVec3::ZERO);
            let forward = c2w.transform_vector3(DVec3::Z).normalize_or(DVec3::Z);
            let up = c2w.transform_vector3(DVec3::Y).normalize_or(DVec3::Y);
            let right = c2w.transform_vector3(DVec3::X).normalize_or(DVec3::X);
            let [w, h] = self.out.resolution.unwrap_or([1280, 720]);
            let film = Film { aperture: self.aperture(), fit: FilmFit::Overscan };
            let projection = match self.orthographic {
                true => CameraProjection::Orthographic { height: film.fitted_height(w, h) },
                false => CameraProjection::Perspective,
            };
            self.out.camera = Some(CameraDesc {
                eye: eye.as_vec3(),
                target: (eye + forward).as_vec3(),
                up: up.as_vec3(),
                vfov: film.vfov(w, h),
                projection,
                film: Some(film),
                window: {
                    let centre = glam::DVec2::from(self.screen_centre).as_vec2();
                    crate::scene::FULL_SCREEN.map(|corner| corner + centre)
                },
                ..Default::default()
            });
            // pbrt shows camera +x on the right of the image; a right-handed camera shows
            // forward × up there. When the two differ, mirror the world about the plane
            // through the eye spanned by forward and up.
            if forward.cross(up).dot(right) < 0.0 {
                let n = right.as_vec3();
                let mirror = Affine3A::from_translation(eye.as_vec3())
                    * Affine3A::from_mat3(glam::Mat3::IDENTITY - 2.0 * outer(n, n))
                    * Affine3A::from_translation(-eye.as_vec3());
                let camera = self.out.camera.take();
                self.out.transform(&mirror);
                self.out.camera = camera;
            }
        }
        self.out.warnings.extend(self.warnings);
        Ok(self.out)
    }
}

/// The emission of a light as [`Parser::light`] makes it (its colour: irradiance, radiance,
/// intensity or a map's tint), to check it is finite and not negative.
fn emission(light: &LightSource) -> Option<Vec3> {
    match light {
        LightSource::Inline(
            Light::Distant { irradiance: c, .. }
            | Light::Environment { radiance: c, .. }
            | Light::Point { intensity: c, .. }
            | Light::Spot { intensity: c, .. },
        )
        | LightSource::File(EnvironmentFile { tint: c, .. }) => Some(*c),
        _ => None,
    }
}

/// Multiplies a light's emission by `k` (pbrt's imaging ratio: every pixel value is linear
/// in the emission, so scaling the lights scales the image).
fn scale_emission(l: &mut Light, k: f32) {
    match l {
        Light::Distant { irradiance: c, .. }
        | Light::Point { intensity: c, .. }
        | Light::Spot { intensity: c, .. }
        | Light::Quad { radiance: c, .. }
        | Light::Sphere { radiance: c, .. }
        | Light::Sun { radiance: c, .. }
        | Light::Environment { radiance: c, .. } => *c *= k,
        Light::EnvironmentMap(map) => *map = map.scaled(k),
        Light::Mesh(mesh) => *mesh = mesh.with_radiance(mesh.radiance() * k),
    }
}

/// A light's parameter `name` that must be a positive number when given (pbrt-v4's
/// photometric alternatives to `scale`), in single precision; `what` names the light in
/// the error.
fn positive(p: &Params, what: &str, name: &str) -> Res<Option<f32>> {
    if !p.has(name) {
        return Ok(None);
    }
    match p.float(name, 0.0)? {
        v if !(v.is_finite() && v > 0.0) => Err((p.line, format!("{what}: {name} {v} must be positive"))),
        v if (v as f32).is_finite() && v as f32 > 0.0 => Ok(Some(v as f32)),
        _ => Err((p.line, format!("{what}: {name} is beyond single precision"))),
    }
}

/// The change of axes from pbrt's light frame to tress's map frame: (x, y, z) ↦ (−y, z, x).
///
/// pbrt-v3 (`mapname`) reads its map as a latitude-longitude image in the light's frame, +z
/// up: the pixel at (s, t) in the unit square (t = 0 the top row) is the radiance from the
/// direction (sin θ cos φ, sin θ sin φ, cos θ) with φ = 2π s, θ = π t (Pharr, Jakob and
/// Humphreys, *Physically Based Rendering*, 3rd ed., §12.6 "Infinite Area Lights"); pbrt-v4
/// (`filename`) a square in the equal-area octahedral mapping (4th ed., §3.8.3), which
/// `prepare` resamples to that layout ([`crate::scene::Projection::EqualArea`]). tress's
/// environment maps have +y up, the image's centre column along −z and the column a
/// quarter to its right along +x: a direction (x, y, z) of pbrt's light frame is (−y, z, x)
/// in the map's frame at the same pixel, an orthogonal change of axes (with a reflection:
/// pbrt's φ turns counter-clockwise about +z, tress's columns clockwise about +y), handed
/// to the map as part of its turn, so latitude-longitude maps are not resampled.
pub(crate) fn pbrt_to_map() -> glam::Mat3 {
    glam::Mat3::from_cols(Vec3::Z, -Vec3::X, Vec3::Y)
}

fn outer(a: Vec3, b: Vec3) -> glam::Mat3 {
    glam::Mat3::from_cols(a * b.x, a * b.y, a * b.z)
}

/// `n` numbers after a directive, bare or in brackets.
fn numbers(lex: &mut Lexer, n: usize, t: Token) -> Res<Vec<f64>> {
    let mut out = Vec::with_capacity(n);
    let bracket = matches!(lex.peek()?, Some(Token { kind: Kind::Open, .. }));
    if bracket {
        lex.next()?;
    }
    while out.len() < n {
        match lex.next()? {
            Some(w @ Token { kind: Kind::Word, .. }) => out.push(parse_number(w)?),
            Some(o) => return Err((o.line, format!("{}: expected {n} numbers, found `{}`", t.text, o.text))),
            None => return Err((t.line, format!("{}: expected {n} numbers", t.text))),
        }
    }
    if bracket {
        match lex.next()? {
            Some(Token { kind: Kind::Close, .. }) => {}
            _ => return Err((t.line, format!("{}: expected `]` after {n} numbers", t.text))),
        }
    }
    Ok(out)
}

fn parse_number(w: Token) -> Res<f64> {
    w.text.parse::<f64>().ok().filter(|v| v.is_finite()).ok_or((w.line, format!("`{}` is not a finite number", w.text)))
}

fn string_arg(lex: &mut Lexer, t: Token) -> Res<String> {
    match lex.next()? {
        Some(s @ Token { kind: Kind::Str, .. }) => Ok(s.text.to_string()),
        _ => Err((t.line, format!("{} needs a quoted name", t.text))),
    }
}

/// A directive's quoted name and its parameter list.
fn named(lex: &mut Lexer, t: Token) -> Res<(String, Params)> {
    let name = string_arg(lex, t)?;
    let mut p = rest_params(lex)?;
    p.line = t.line;
    Ok((name, p))
}

/// Parameters up to the next directive.
fn rest_params(lex: &mut Lexer) -> Res<Params> {
    let mut list = Vec::new();
    let mut line = 0;
    loop {
        let decl = match lex.peek()? {
            Some(d @ Token { kind: Kind::Str, .. }) => d,
            Some(Token { kind: Kind::Word, text, line: l })
                if !text.starts_with(|c: char| c.is_ascii_alphabetic()) || text == "true" || text == "false" =>
            {
                return Err((l, format!("`{text}` outside a parameter list")))
            }
            _ => break,
        };
        lex.next()?;
        line = decl.line;
        let mut parts = decl.text.split_whitespace();
        let (ty, name) = match (parts.next(), parts.next(), parts.next()) {
            (Some(ty), Some(name), None) => (ty.to_string(), name.to_string()),
            _ => {
                // A lone string here is a stray positional argument (e.g. Texture's class).
                list.push(Param {
                    ty: String::new(),
                    name: decl.text.to_string(),
                    numbers: vec![],
                    strings: vec![],
                    line,
                    used: Cell::new(false),
                });
                continue;
            }
        };
        let mut p = Param { ty, name, numbers: Vec::new(), strings: Vec::new(), line, used: Cell::new(false) };
        let value = |tok: Token, p: &mut Param| -> Res<()> {
            match tok.kind {
                Kind::Str => p.strings.push(tok.text.to_string()),
                Kind::Word if tok.text == "true" || tok.text == "false" => p.strings.push(tok.text.to_string()),
                Kind::Word => p.numbers.push(parse_number(tok)?),
                _ => return Err((tok.line, format!("unexpected `{}`", tok.text))),
            }
            Ok(())
        };
        match lex.next()? {
            Some(Token { kind: Kind::Open, .. }) => loop {
                match lex.next()? {
                    Some(Token { kind: Kind::Close, .. }) => break,
                    Some(tok) => value(tok, &mut p)?,
                    None => return Err((line, format!("\"{}\": `[` is never closed", decl.text))),
                }
            },
            Some(tok) => value(tok, &mut p)?,
            None => return Err((line, format!("\"{}\" has no value", decl.text))),
        }
        list.push(p);
    }
    Ok(Params { list, line })
}

// ----- shapes -----

/// A curve's strand in world space: (position, radius) points.
fn curve(p: &Params, ctm: &DMat4) -> Res<Vec<(Vec3, f32)>> {
    let cps = p.point3s("P")?.ok_or((p.line, "curve without \"point3 P\"".to_string()))?;
    // Flat, cylinder and ribbon curves are all drawn as tubes.
    p.ignore(&["type"]);
    let degree = p.int("degree", 3)?;
    let basis = p.string("basis", "bezier")?;
    let split = p.int("splitdepth", 3)?.clamp(0, MAX_SPLIT_DEPTH as i64) as u32;
    let pieces = 1usize << split;
    let width = p.float("width", 1.0)?;
    let (w0, w1) = (p.float("width0", width)?, p.float("width1", width)?);
    if !(w0.is_finite() && w1.is_finite() && w0 >= 0.0 && w1 >= 0.0) {
        return Err((p.line, format!("curve widths {w0} and {w1} must be finite and not negative")));
    }
    let n = cps.len();
    // Every segment as a cubic with its basis (quadratics raised to cubic Béziers).
    let segments: Vec<(CubicBasis, [DVec3; 4])> = match (basis.as_str(), degree) {
        ("bezier", 3) if n >= 4 && (n - 1) % 3 == 0 => (0..(n - 1) / 3)
            .map(|s| (CubicBasis::Bezier, [cps[3 * s], cps[3 * s + 1], cps[3 * s + 2], cps[3 * s + 3]]))
            .collect(),
        ("bezier", 2) if n >= 3 && (n - 1) % 2 == 0 => {
            (0..(n - 1) / 2).map(|s| (CubicBasis::Bezier, raise(cps[2 * s], cps[2 * s + 1], cps[2 * s + 2]))).collect()
        }
        ("bspline", 3) if n >= 4 => {
            (0..n - 3).map(|s| (CubicBasis::BSpline, [cps[s], cps[s + 1], cps[s + 2], cps[s + 3]])).collect()
        }
        // A uniform quadratic B-spline segment is the quadratic Bézier from the midpoints of
        // its control polygon's legs through its middle point.
        ("bspline", 2) if n >= 3 => (0..n - 2)
            .map(|s| {
                (CubicBasis::Bezier, raise(0.5 * (cps[s] + cps[s + 1]), cps[s + 1], 0.5 * (cps[s + 1] + cps[s + 2])))
            })
            .collect(),
        ("bezier" | "bspline", 2 | 3) => {
            return Err((p.line, format!("a degree-{degree} {basis} curve cannot have {n} control points")))
        }
        (b, d) => {
            return Err((
                p.line,
                format!("curve basis \"{b}\" of degree {d} is not supported (bezier or bspline, 2 or 3)"),
            ))
        }
    };
    let scale = ctm.determinant().abs().cbrt();
    let total = (segments.len() * pieces) as f64;
    let mut out: Vec<(Vec3, f32)> = Vec::new();
    crate::memory::try_reserve(&mut out, segments.len() * pieces + 1, "the curve's pieces")
        .map_err(|e| (p.line, e.to_string()))?;
    for (s, (b, c)) in segments.iter().enumerate() {
        let c = c.map(|q| ctm.transform_point3(q).as_vec3());
        for k in usize::from(s > 0)..=pieces {
            let u = (s * pieces + k) as f64 / total;
            let radius = 0.5 * (w0 + (w1 - w0) * u) * scale;
            out.push((cubic_point(*b, c, k as f32 / pieces as f32), radius as f32));
        }
    }
    if out.iter().any(|(q, r)| !q.is_finite() || !r.is_finite()) {
        return Err((p.line, "curve points must be finite".into()));
    }
    Ok(out)
}

/// The cubic Bézier control points of a quadratic Bézier (degree elevation).
fn raise(a: DVec3, b: DVec3, c: DVec3) -> [DVec3; 4] {
    [a, a + (b - a) * (2.0 / 3.0), c + (b - c) * (2.0 / 3.0), c]
}

fn triangle_mesh(p: &Params) -> Res<TriangleMesh> {
    let positions = p.point3s("P")?.ok_or((p.line, "trianglemesh without \"point3 P\"".to_string()))?;
    let n = positions.len();
    let indices: Vec<f64> = match p.floats("indices") {
        Some(i) => i.to_vec(),
        None if n == 3 => vec![0.0, 1.0, 2.0],
        None => return Err((p.line, "trianglemesh without \"integer indices\" (only 3 points may omit them)".into())),
    };
    if !indices.len().is_multiple_of(3) {
        return Err((p.line, format!("{} indices is not a multiple of 3", indices.len())));
    }
    let mut tris = Vec::with_capacity(indices.len() / 3);
    for c in indices.chunks(3) {
        let mut t = [0u32; 3];
        for k in 0..3 {
            if !(c[k] >= 0.0 && c[k].fract() == 0.0 && (c[k] as usize) < n) {
                return Err((p.line, format!("index {} is not one of the {n} points", c[k])));
            }
            t[k] = c[k] as u32;
        }
        tris.push(t);
    }
    if tris.is_empty() {
        return Err((p.line, "trianglemesh has no triangles (\"integer indices\" is empty)".into()));
    }
    let normals = match p.point3s("N")? {
        Some(v) if v.len() == n => Some(v.iter().map(|q| q.as_vec3()).collect()),
        Some(v) => return Err((p.line, format!("{} normals for {n} points", v.len()))),
        None => None,
    };
    let uvs = match p.floats("uv").or_else(|| p.floats("st")) {
        Some(v) if v.len() == 2 * n => Some(v.chunks(2).map(|c| [c[0] as f32, c[1] as f32]).collect()),
        Some(v) => return Err((p.line, format!("{} uv numbers for {n} points", v.len()))),
        None => None,
    };
    // Finite in double precision (1e39) is not always finite in single precision, where
    // the mesh keeps its normals and UVs.
    let finite = |name: &str, ok: bool| match ok {
        true => Ok(()),
        false => Err((
            p.get(name).map_or(p.line, |q| q.line),
            format!("trianglemesh: \"{name}\" is beyond single precision"),
        )),
    };
    finite("N", normals.iter().flatten().all(|n: &Vec3| n.is_finite()))?;
    finite(
        if p.floats("uv").is_some() { "uv" } else { "st" },
        uvs.iter().flatten().flatten().all(|x: &f32| x.is_finite()),
    )?;
    let mesh = TriangleMesh { positions: positions.iter().map(|q| q.as_vec3()).collect(), normals, uvs, indices: tris };
    mesh.validate().map_err(|e| (p.line, format!("trianglemesh: {e}")))?;
    Ok(mesh)
}

// ----- hair material -----

/// The physical hair material standing in for pbrt's `hair` (see the module documentation).
fn hair_material(p: &Params, w: &mut BTreeSet<String>) -> Res<PhysicalHair> {
    let defaults = HairParams::default();
    let beta = |name: &str, d: f32| -> Res<f32> {
        let v = p.float(name, d as f64)?;
        match (0.0..=1.0).contains(&v) {
            // pbrt allows 0; tress's model needs a little roughness.
            true => Ok((v as f32).max(1e-3)),
            false => Err((p.get(name).map_or(p.line, |q| q.line), format!("{name} {v} must be between 0 and 1"))),
        }
    };
    let (beta_m, beta_n) = (beta("beta_m", defaults.beta_m)?, beta("beta_n", defaults.beta_n)?);
    let absorption = if p.get("sigma_a").is_some() {
        let s = p.color("sigma_a", Vec3::ZERO, w)?;
        let c = color_from_sigma_a(s, beta_n);
        if c.min_element() < 1e-4 {
            w.insert("sigma_a beyond what a colour can carry (very dark hair) is clamped".into());
        }
        Absorption::Color(c.clamp(Vec3::ZERO, Vec3::ONE))
    } else if let Some(name) = ["reflectance", "color"].into_iter().find(|n| p.has(n)) {
        // pbrt-v4 calls the colour `reflectance`, pbrt-v3 `color`.
        Absorption::Color(p.color(name, Vec3::splat(0.5), w)?.clamp(Vec3::ZERO, Vec3::ONE))
    } else {
        let melanin = |name: &str, d: f64| -> Res<f32> { Ok(p.float(name, d)? as f32) };
        let given = p.get("eumelanin").is_some() || p.get("pheomelanin").is_some();
        Absorption::Melanin {
            eumelanin: melanin("eumelanin", if given { 0.0 } else { 1.3 })?,
            pheomelanin: melanin("pheomelanin", 0.0)?,
        }
    };
    let params = HairParams {
        absorption,
        beta_m,
        beta_n,
        alpha_degrees: p.float("alpha", defaults.alpha_degrees as f64)? as f32,
        eta: p.float("eta", defaults.eta as f64)? as f32,
    };
    params.validate().map_err(|e| (p.line, format!("hair material: {e}")))?;
    Ok(PhysicalHair::new(params))
}

mod surfaces;

#[cfg(test)]
mod tests;
