//! XGen collections (classic XGen): the collection file an `xgmPalette` names (`.xfn`, e.g.
//! `scene__collection9.xgen`, beside the `.ma`), approximated as Maya Fur.
//!
//! XGen generates a collection's strands at render time from that file and the
//! collection's folder (maps, guides, expressions); tress does not run XGen. It reads, per
//! `Description` section, the few values that fix how many strands grow and how big they
//! are, and grows them with [`crate::fur`] on the mesh each of the description's
//! `xgmSubdPatch` nodes is bound to (`mesh.o → patch.geo`), straight along the normal or
//! shaped by the patch's guides (read from the `.ma`, see the reader in `xgen.rs`):
//!
//! - `RandomGenerator` `density`: strands per unit area (scene units), so the fur's
//!   Density (strands over the whole mesh) is density × the mesh's world area;
//! - `SplinePrimitive` `length` and `width` (the strand's diameter, root and tip alike).
//!   Other primitives (cards, archives, spheres) are not strands and are left out, said;
//! - the FX modules that have a Maya Fur counterpart (cut, noise, clumping:
//!   [`CollectionDescription::apply_fx`]).
//!
//! The file is plain text: a section name on a line of its own (`Palette`, `Description`,
//! `SplinePrimitive`, `RandomGenerator`, `NoiseFXModule`, ...), then its attributes, one a
//! line, a tab, the key, tabs and the value, up to `endAttrs`. The sections after a
//! `Description` are its own until the next one. Values are SeExpr expressions; the slider
//! form XGen's UI writes (`$a=1.7000;#0.05,5.0\n$a`, the `\n` written as two characters)
//! and plain numbers are read, anything else (maps, other expressions) falls back to the
//! value a new description is written with, said.

use crate::fur::{FurDescription, Scalar};
use std::path::Path;

/// A description's `length` and `width` when its file's value cannot be read: the values
/// XGen writes for a new description (`$a=1.0000;...` and `$a=0.1000;...`), as the
/// untouched descriptions of the MtoA test files carry.
const NEW_LENGTH: f64 = 1.0;
/// See [`NEW_LENGTH`].
const NEW_WIDTH: f64 = 0.1;

/// The values of one `Description` of a collection file.
#[derive(Clone, Debug, PartialEq)]
pub struct CollectionDescription {
    /// The description's name (`Description` `name`), the `xgmDescription`'s transform in
    /// the `.ma`.
    pub name: String,
    /// Strands per unit area (`RandomGenerator` `density`), 0 when the file gives none.
    pub density: f64,
    /// Strand length (`SplinePrimitive` `length`).
    pub length: f64,
    /// Strand diameter (`SplinePrimitive` `width`).
    pub width: f64,
    /// `SplinePrimitive` `taper`: how much narrower the tip is than the root (negative:
    /// wider), 0 when unread.
    pub taper: f64,
    /// `SplinePrimitive` `taperStart`: the fraction of the length where the taper begins.
    pub taper_start: f64,
    /// `SplinePrimitive` `widthRamp`, a width multiplier along the strand: its points
    /// (position, value, interpolation of the span that follows), `None` when unread.
    pub width_ramp: Option<Vec<(f64, f64, u32)>>,
    /// The patches (`Patch` records of the description's `Patches`): the geometry's name
    /// and its face list (`faceIds`), if it has one.
    pub patches: Vec<Patch>,
    /// The primitive section of the description (`SplinePrimitive`, `CardPrimitive`,
    /// `ArchivePrimitive`, ...), if any.
    pub primitive: Option<String>,
    /// The FX modules of the description (`NoiseFXModule`, ...), in file order (XGen's
    /// stack, first computed first); [`CollectionDescription::apply_fx`] maps them.
    pub fx_modules: Vec<FxModule>,
    /// Attributes whose value reads a map (`map('${DESC}/...')`), as `Section.key`.
    pub maps: Vec<String>,
    /// Values that could not be read and fell back: `key (line N)`.
    pub fallbacks: Vec<String>,
}

/// One FX module section of a description, as written.
#[derive(Clone, Debug, PartialEq)]
pub struct FxModule {
    /// The section's name: `NoiseFXModule`, `CutFXModule`, `ClumpingFXModule`, ...
    pub kind: String,
    /// Its attributes, key and value, in file order.
    pub attrs: Vec<(String, String)>,
}

impl FxModule {
    /// The module's `name` (its kind when it has none).
    pub fn name(&self) -> &str {
        self.value("name").unwrap_or(&self.kind)
    }

    fn value(&self, key: &str) -> Option<&str> {
        self.attrs.iter().find(|a| a.0 == key).map(|a| a.1.as_str())
    }

    /// Attribute `key` as a number ([`fx_number`]), `default` when absent; `Err` names it
    /// when it is an expression.
    fn number(&self, key: &str, default: f64) -> Result<f64, String> {
        match self.value(key) {
            None => Ok(default),
            Some(v) => fx_number(v).ok_or_else(|| format!("{key} an expression")),
        }
    }

    /// The mean of ramp attribute `key` over the strand and its value at the tip, (1, 1)
    /// when absent or not a ramp.
    fn ramp_mean_and_tip(&self, key: &str) -> (f64, f64) {
        match self.value(key).and_then(ramp) {
            Some(r) => {
                let n = PROFILE_POINTS - 1;
                let mean = (0..=n).map(|k| ramp_at(&r, k as f64 / n as f64)).sum::<f64>() / (n + 1) as f64;
                (mean, ramp_at(&r, 1.0))
            }
            None => (1.0, 1.0),
        }
    }
}

/// Most clumps across a description's mesh: Maya Fur's Clumping Frequency limit.
const MAX_CLUMPING_FREQUENCY: f64 = 1000.0;

/// One `Patch` record of a description: the geometry XGen grows it on and which faces.
#[derive(Clone, Debug, PartialEq)]
pub struct Patch {
    /// The geometry's name (the mesh's transform).
    pub name: String,
    /// The Maya face ids that grow strands (`faceIds COUNT ID...`); `None`: not given.
    pub faces: Option<Vec<u32>>,
}

/// Points of width profiles ([`CollectionDescription::width_profile`]), enough for the
/// ramps' smooth spans.
const PROFILE_POINTS: usize = 33;

impl CollectionDescription {
    /// Maps the description's FX modules onto the Maya Fur `desc` grown on `area` (world
    /// units squared) with strands `length` long, and says per module what was applied and
    /// what not, in that order. With `guided`, the guides replace the strands' shape, so
    /// only a cut applies. Each module's `mask` (a number, 1 when absent) scales its
    /// effect; a module that is not `active`, or whose values are expressions other than
    /// numbers, sliders and `rand(a, b)` (read as its mean, (a + b) / 2), is not applied.
    ///
    /// - `CutFXModule`: Autodesk's Cut modifier "specifies the amount of the primitive to be
    ///   cut, starting at the tip": Length × (1 − mask × amount / length), at least 0.
    /// - `NoiseFXModule`: Autodesk's Noise modifier displaces the control vertices by up to
    ///   `magnitude` (times `magnitudeScale` along the strand; its mean is used), at
    ///   `frequency` cycles per unit length, `correlation` between neighbours. As Maya
    ///   Fur's Scraggle, which turns the strand by up to Scraggle × π over its length: a
    ///   steady turn at that rate moves the tip sideways by Scraggle × π × length / 2, so
    ///   Scraggle = 2 × mask × magnitude × mean scale / (π × length), at most 1; Scraggle
    ///   Frequency = frequency × length (kinks along the strand), Scraggle Correlation =
    ///   correlation.
    /// - `ClumpingFXModule`: `clump` pulls strands to clump centres scattered at
    ///   `ptDensity` per unit area, `clumpScale` the pull along the strand. As Maya Fur's
    ///   clumping (about Clumping Frequency² centres over the mesh, the pull Clumping ×
    ///   s^p at fraction s): Clumping Frequency = √(ptDensity × area), Clumping = mask ×
    ///   clump × clumpScale(tip), at most 1, and p such that s^p has the ramp's mean over
    ///   its tip value, 1 / (p + 1) (Clump Shape = −10 log10 p). Maya Fur has one level of
    ///   clumps: only the first clumping module applies.
    /// - Others (`CoilFXModule`: Maya Fur's curl bends a strand at most half a circle, no
    ///   coil) are not applied.
    pub fn apply_fx(
        &self,
        desc: &mut FurDescription,
        area: f64,
        length: f64,
        guided: bool,
    ) -> (Vec<String>, Vec<String>) {
        let (mut applied, mut not) = (Vec::new(), Vec::new());
        let mut clumped = false;
        for fx in &self.fx_modules {
            let name = fx.name();
            let kind = fx.kind.as_str();
            let skip = if fx.value("active") == Some("false") {
                Some("inactive".to_string())
            } else if guided && kind != "CutFXModule" {
                Some("the guides give the shape".to_string())
            } else if kind == "ClumpingFXModule" && clumped {
                Some("Maya Fur has one level of clumps".to_string())
            } else if !matches!(kind, "CutFXModule" | "NoiseFXModule" | "ClumpingFXModule") {
                Some("no Maya Fur counterpart".to_string())
            } else {
                None
            };
            if let Some(why) = skip {
                not.push(format!("{name} ({why})"));
                continue;
            }
            let done = (|| -> Result<String, String> {
                let mask = fx.number("mask", 1.0)?.clamp(0.0, 1.0);
                Ok(match kind {
                    "CutFXModule" => {
                        let cut = mask * fx.number("amount", 0.0)?.max(0.0);
                        let l = &mut desc[Scalar::Length].value;
                        *l *= (1.0 - cut / length.max(f64::MIN_POSITIVE)).max(0.0) as f32;
                        format!("{name} (cut {cut:.3} from the tip)")
                    }
                    "NoiseFXModule" => {
                        let (magnitude, frequency) = (fx.number("magnitude", 0.0)?, fx.number("frequency", 1.0)?);
                        let correlation = fx.number("correlation", 0.0)?;
                        let (mean, _) = fx.ramp_mean_and_tip("magnitudeScale");
                        let amplitude = (mask * magnitude * mean).abs();
                        let scraggle = (2.0 * amplitude / (std::f64::consts::PI * length)).min(1.0);
                        desc[Scalar::Scraggle].value = scraggle as f32;
                        desc[Scalar::ScraggleFrequency].value = (frequency.abs() * length).min(1000.0) as f32;
                        desc[Scalar::ScraggleCorrelation].value = correlation.clamp(0.0, 1.0) as f32;
                        format!("{name} (as Scraggle {scraggle:.2})")
                    }
                    _ => {
                        let (clump, density) = (fx.number("clump", 0.0)?, fx.number("ptDensity", 0.0)?);
                        let (mean, tip) = fx.ramp_mean_and_tip("clumpScale");
                        let amount = (mask * clump * tip).clamp(0.0, 1.0);
                        // 1 / (p + 1) = mean / tip.
                        let p = if mean > 0.0 { (tip / mean - 1.0).max(1e-6) } else { 1.0 };
                        let frequency = (density.max(0.0) * area).sqrt().min(MAX_CLUMPING_FREQUENCY);
                        desc[Scalar::Clumping].value = amount as f32;
                        desc[Scalar::ClumpingFrequency].value = frequency as f32;
                        desc[Scalar::ClumpShape].value = (-10.0 * p.log10()).clamp(-10.0, 10.0) as f32;
                        clumped = true;
                        format!("{name} (as Clumping {amount:.2}, {frequency:.0} clumps across)")
                    }
                })
            })();
            match done {
                Ok(a) => applied.push(a),
                Err(e) => not.push(format!("{name} ({e})")),
            }
        }
        (applied, not)
    }

    /// The width along the strand as a multiplier of `width`, at `PROFILE_POINTS` (33) evenly
    /// spaced fractions root to tip, or `None` when it is 1 throughout. Autodesk's XGen
    /// Spline attributes: Taper "controls the width of the tip relative to the root;
    /// positive values make the tip narrower than the root, negative wider", Taper Start
    /// "where the tapering begins, 0 (root) to 1 (tip)", and the Width Ramp multiplies the
    /// width along the strand. tress reads the taper as a linear change from `taperStart`
    /// to the tip, where the width is `1 - taper` times the root's:
    /// `ramp(s) × (1 − taper × max(0, (s − taperStart) / (1 − taperStart)))`, clamped at 0.
    pub fn width_profile(&self) -> Option<Vec<f32>> {
        let flat = self.width_ramp.as_ref().is_none_or(|r| r.iter().all(|p| p.1 == 1.0));
        if self.taper == 0.0 && flat {
            return None;
        }
        let start = self.taper_start.clamp(0.0, 1.0);
        Some(
            (0..PROFILE_POINTS)
                .map(|k| {
                    let s = k as f64 / (PROFILE_POINTS - 1) as f64;
                    let along = if start < 1.0 { ((s - start) / (1.0 - start)).max(0.0) } else { 0.0 };
                    let ramp = self.width_ramp.as_deref().map_or(1.0, |r| ramp_at(r, s));
                    (ramp * (1.0 - self.taper * along)).max(0.0) as f32
                })
                .collect(),
        )
    }
}

/// SeExpr's curve at `s`: before the first point and after the last the end values; each
/// span interpolated as its first point says (0 none: the first point's value, 1 linear,
/// 2 smooth: smoothstep; the spline kinds, 3 and 4, linearly, which the reader notes).
fn ramp_at(points: &[(f64, f64, u32)], s: f64) -> f64 {
    let Some(first) = points.first() else { return 1.0 };
    if s <= first.0 {
        return first.1;
    }
    for w in points.windows(2) {
        let ((p0, v0, kind), (p1, v1, _)) = (w[0], w[1]);
        if s < p1 {
            let t = if p1 > p0 { (s - p0) / (p1 - p0) } else { 1.0 };
            let t = match kind {
                0 => 0.0,
                2 => t * t * (3.0 - 2.0 * t),
                _ => t,
            };
            return v0 + (v1 - v0) * t;
        }
    }
    points[points.len() - 1].1
}

/// A SeExpr ramp as XGen writes it, `rampUI(POS,VALUE,INTERP:POS,VALUE,INTERP...)`, its
/// points sorted by position; `None` when the value is not one.
fn ramp(value: &str) -> Option<Vec<(f64, f64, u32)>> {
    let inner = value.trim().strip_prefix("rampUI(")?.strip_suffix(')')?;
    let mut points = Vec::new();
    for p in inner.split(':') {
        let f: Vec<&str> = p.split(',').map(str::trim).collect();
        let [pos, v, kind] = f.as_slice() else { return None };
        let (pos, v, kind) = (pos.parse::<f64>().ok()?, v.parse::<f64>().ok()?, kind.parse::<u32>().ok()?);
        if !(pos.is_finite() && v.is_finite()) {
            return None;
        }
        points.push((pos, v, kind));
    }
    points.sort_by(|a, b| a.0.total_cmp(&b.0));
    (!points.is_empty()).then_some(points)
}

/// Reads the text of a collection file; `path` names it in messages. Errors (a value out of
/// range, an attribute outside any section) name the file and the line.
pub fn parse_collection(text: &str, path: &Path) -> Result<Vec<CollectionDescription>, String> {
    let mut out: Vec<CollectionDescription> = Vec::new();
    let mut section: Option<String> = None;
    // The description a `Patches` record names, which its `Patch` records belong to.
    let mut owner: Option<usize> = None;
    for (i, raw) in text.lines().enumerate() {
        let line = i + 1;
        let at = |msg: String| format!("{}: line {line}: {msg}", path.display());
        let trimmed = raw.trim();
        if trimmed.is_empty() || trimmed.starts_with('#') {
            continue;
        }
        if !raw.starts_with('\t') && !raw.starts_with(' ') {
            // A section name, or a one-line record (`FileVersion 18`, `Patches ...`).
            let mut words = trimmed.split_whitespace();
            let name = words.next().unwrap_or_default().to_string();
            if name == "Patches" {
                let of = words.next().unwrap_or_default();
                owner = out.iter().position(|d| d.name == of);
            } else if name == "Patch" {
                if let Some(d) = owner.and_then(|k| out.get_mut(k)) {
                    d.patches.push(Patch { name: String::new(), faces: None });
                }
            } else if name == "Description" {
                out.push(CollectionDescription {
                    name: String::new(),
                    density: 0.0,
                    length: NEW_LENGTH,
                    width: NEW_WIDTH,
                    taper: 0.0,
                    taper_start: 0.0,
                    width_ramp: None,
                    patches: Vec::new(),
                    primitive: None,
                    fx_modules: Vec::new(),
                    maps: Vec::new(),
                    fallbacks: Vec::new(),
                });
            } else if let Some(d) = out.last_mut() {
                if name.ends_with("FXModule") {
                    d.fx_modules.push(FxModule { kind: name.clone(), attrs: Vec::new() });
                } else if name.ends_with("Primitive") {
                    d.primitive = Some(name.clone());
                }
            }
            section = Some(name);
            continue;
        }
        let (key, value) = match trimmed.split_once(['\t', ' ']) {
            Some((k, v)) => (k, v.trim()),
            None => (trimmed, ""),
        };
        if key == "endAttrs" {
            section = None;
            continue;
        }
        if section.as_deref() == Some("Patch") {
            let Some(patch) = owner.and_then(|k| out.get_mut(k)).and_then(|d| d.patches.last_mut()) else { continue };
            match key {
                "name" => patch.name = value.to_string(),
                "faceIds" => patch.faces = Some(face_ids(value).map_err(at)?),
                _ => {}
            }
            continue;
        }
        let (Some(s), Some(d)) = (section.as_deref(), out.last_mut()) else { continue };
        // SeExpr comments start at `#` (XGen writes a slider's range there).
        // The renderers' sections (previews' colours) make no strands.
        if !s.ends_with("Renderer") && value.split('#').next().is_some_and(|v| v.contains("map(")) {
            d.maps.push(format!("{s}.{key}"));
        }
        if s.ends_with("FXModule") {
            if let Some(fx) = d.fx_modules.last_mut() {
                fx.attrs.push((key.to_string(), value.to_string()));
            }
            continue;
        }
        match (s, key) {
            ("Description", "name") => d.name = value.to_string(),
            ("RandomGenerator", "density") => {
                d.density = number(value).ok_or_else(|| at(format!("`density` `{value}` is not a number")))?;
                if !(d.density.is_finite() && d.density >= 0.0) {
                    return Err(at(format!("`density` {} is not a density", d.density)));
                }
            }
            (_, "length" | "width") if s.ends_with("Primitive") => match number(value) {
                Some(v) if v.is_finite() && v >= 0.0 => {
                    *if key == "length" { &mut d.length } else { &mut d.width } = v;
                }
                Some(v) => return Err(at(format!("`{key}` {v} is negative or not finite"))),
                None => d.fallbacks.push(format!("{key} (line {line})")),
            },
            ("SplinePrimitive", "taper" | "taperStart") => match number(value) {
                Some(v) if v.is_finite() => *if key == "taper" { &mut d.taper } else { &mut d.taper_start } = v,
                Some(v) => return Err(at(format!("`{key}` {v} is not finite"))),
                None => d.fallbacks.push(format!("{key} (line {line}, 0 used)")),
            },
            ("SplinePrimitive", "widthRamp") => match ramp(value) {
                Some(r) => {
                    if r.iter().any(|p| p.2 > 2) {
                        d.fallbacks.push(format!("widthRamp's spline spans (line {line}, linear used)"));
                    }
                    d.width_ramp = Some(r);
                }
                None => d.fallbacks.push(format!("widthRamp (line {line}, 1 used)")),
            },
            _ => {}
        }
    }
    for (k, d) in out.iter().enumerate() {
        if d.name.is_empty() {
            return Err(format!("{}: description {} has no name", path.display(), k + 1));
        }
    }
    Ok(out)
}

/// A `faceIds` value: the count, then that many face ids.
fn face_ids(value: &str) -> Result<Vec<u32>, String> {
    let mut words = value.split_whitespace();
    let count: usize = match words.next().map(str::parse) {
        Some(Ok(n)) => n,
        _ => return Err(format!("`faceIds` `{value}` does not start with a count")),
    };
    let ids: Vec<u32> = words
        .map(|w| w.parse().map_err(|_| format!("`faceIds` holds `{w}`, not a face id")))
        .collect::<Result<_, _>>()?;
    if ids.len() != count {
        return Err(format!("`faceIds` promises {count} faces and lists {}", ids.len()));
    }
    Ok(ids)
}

/// An FX module's value: a number ([`number`]), or SeExpr's `rand(a, b)` read as its mean.
fn fx_number(value: &str) -> Option<f64> {
    let v = value.split('#').next().unwrap_or_default().trim();
    if let Some(args) = v.strip_prefix("rand(").and_then(|r| r.strip_suffix(')')) {
        let (a, b) = args.split_once(',')?;
        let (a, b) = (a.trim().parse::<f64>().ok()?, b.trim().parse::<f64>().ok()?);
        return Some(0.5 * (a + b)).filter(|m| m.is_finite());
    }
    number(value).filter(|x| x.is_finite())
}

/// A plain number, or the slider form XGen's UI writes, `$a=NUMBER;#MIN,MAX\n$a` (the
/// `\n` as two characters, or a real newline).
fn number(value: &str) -> Option<f64> {
    if let Ok(v) = value.parse::<f64>() {
        return Some(v);
    }
    let rest = value.strip_prefix('$')?;
    let (var, rest) = rest.split_once('=')?;
    let (num, rest) = rest.split_once(';')?;
    let (_, tail) = rest.split_once("\\n").or_else(|| rest.split_once('\n'))?;
    if !var.chars().all(|c| c.is_ascii_alphanumeric() || c == '_') || tail.trim() != format!("${var}") {
        return None;
    }
    num.trim().parse().ok()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn slider_and_plain_values_are_read_others_fall_back() {
        assert_eq!(number("200.0"), Some(200.0));
        assert_eq!(number("$a=1.7000;#0.05,5.0\\n$a"), Some(1.7));
        assert_eq!(number("$w=0.0450;#0.005,0.5\n$w"), Some(0.045));
        assert_eq!(number("$a=1.0;#0,1\\n$a*2"), None);
        assert_eq!(number("map('${DESC}/groom/length/')"), None);
        let text = "Palette\n\tname\t\t\tc\n\tendAttrs\n\nDescription\n\tname\t\t\td1\n\tendAttrs\n\
                    SplinePrimitive\n\tlength\t\t\tmap('${DESC}/len/')\n\twidth\t\t\t$a=0.2;#0,1\\n$a\n\tendAttrs\n\
                    NoiseFXModule\n\tname\t\t\tNoise1\n\tendAttrs\n\
                    RandomGenerator\n\tdensity\t\t\t12.5\n\tendAttrs\n";
        let d = parse_collection(text, Path::new("c.xgen")).unwrap();
        assert_eq!(d.len(), 1);
        assert_eq!((d[0].name.as_str(), d[0].density, d[0].length, d[0].width), ("d1", 12.5, NEW_LENGTH, 0.2));
        assert_eq!(d[0].fx_modules[0].kind, "NoiseFXModule");
        assert_eq!(d[0].fx_modules[0].name(), "Noise1");
        assert_eq!(d[0].primitive.as_deref(), Some("SplinePrimitive"));
        assert_eq!(d[0].maps, vec!["SplinePrimitive.length".to_string()]);
        assert_eq!(d[0].fallbacks, vec!["length (line 9)".to_string()]);
    }

    #[test]
    fn malformed_values_name_the_file_and_line() {
        let e = parse_collection("Description\n\tname\td\nRandomGenerator\n\tdensity\tlots\n", Path::new("c.xgen"))
            .unwrap_err();
        assert!(e.contains("c.xgen") && e.contains("line 4") && e.contains("density"), "{e}");
        let e = parse_collection("Description\n\tname\td\nSplinePrimitive\n\n\tlength\t-3\n", Path::new("c.xgen"))
            .unwrap_err();
        assert!(e.contains("line 5") && e.contains("length"), "{e}");
    }
}
