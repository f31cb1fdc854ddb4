//! XGen collections (classic XGen): the collection file an `xgmPalette` names (`.xfn`, e.g.
//! `scene__collection9.xgen`, beside the `.ma`), approximated as Maya Fur.
//!
//! XGen generates a collection's strands at render time from that file and the
//! collection's folder (maps, guides, expressions); tress does not run XGen. It reads, per
//! `Description` section, the few values that fix how many strands grow and how big they
//! are, and grows them with [`crate::fur`] on the mesh each of the description's
//! `xgmSubdPatch` nodes is bound to (`mesh.o → patch.geo`), straight along the normal:
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

/// Reads the text of a collection file; `path` names it in messages. Errors (a value out of
/// range, an attribute outside any section) name the file and the line.
pub fn parse_collection(text: &str, path: &Path) -> Result<Vec<CollectionDescription>, String> {
    let mut out: Vec<CollectionDescription> = Vec::new();
    let mut section: Option<String> = None;
    for (i, raw) in text.lines().enumerate() {
        let line = i + 1;
        let at = |msg: String| format!("{}: line {line}: {msg}", path.display());
        let trimmed = raw.trim();
        if trimmed.is_empty() || trimmed.starts_with('#') {
            continue;
        }
        if !raw.starts_with('\t') && !raw.starts_with(' ') {
            // A section name, or a one-line record (`FileVersion 18`, `Patches ...`).
            let name = trimmed.split_whitespace().next().unwrap_or_default().to_string();
            if name == "Description" {
                out.push(CollectionDescription {
                    name: String::new(),
                    density: 0.0,
                    length: NEW_LENGTH,
                    width: NEW_WIDTH,
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
