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
//!   Other primitives (cards, archives, spheres) are not strands and are left out, said.
//!
//! The file is plain text: a section name on a line of its own (`Palette`, `Description`,
//! `SplinePrimitive`, `RandomGenerator`, `NoiseFXModule`, ...), then its attributes, one a
//! line, a tab, the key, tabs and the value, up to `endAttrs`. The sections after a
//! `Description` are its own until the next one. Values are SeExpr expressions; the slider
//! form XGen's UI writes (`$a=1.7000;#0.05,5.0\n$a`, the `\n` written as two characters)
//! and plain numbers are read, anything else (maps, other expressions) falls back to the
//! value a new description is written with, said.

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
    /// The FX modules of the description (`NoiseFXModule`, ...), not applied.
    pub fx_modules: Vec<String>,
    /// Attributes whose value reads a map (`map('${DESC}/...')`), as `Section.key`.
    pub maps: Vec<String>,
    /// Values that could not be read and fell back: `key (line N)`.
    pub fallbacks: Vec<String>,
}

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
                    d.fx_modules.push(name.clone());
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
        assert_eq!(d[0].fx_modules, vec!["NoiseFXModule".to_string()]);
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
