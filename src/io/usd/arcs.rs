//! Composition arcs as the text layers write them, read before the `openusd` crate
//! composes the stage: the crate follows `subLayers`, `references`, `payload`, `inherits`
//! and `specializes` arcs that lead back to where they started without end (a stack
//! overflow), so such cycles, within one layer or through the files it names, are errors
//! naming the chain. Binary layers are not scanned (their arcs are the crate's to follow).

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// Most layer files one check reads.
const MAX_LAYERS: usize = 4096;

/// One arc: the layer file it names (`None`: the layer it is in) and the prim (`None`:
/// that layer's `defaultPrim`).
#[derive(Clone, Debug, PartialEq)]
struct Arc {
    asset: Option<String>,
    prim: Option<String>,
}

/// What one text layer says about composition.
#[derive(Debug, Default)]
struct LayerArcs {
    /// Each prim's arcs, by prim path.
    prims: BTreeMap<String, Vec<Arc>>,
    /// Its `subLayers`, as written.
    sublayers: Vec<String>,
    /// Its `defaultPrim`.
    default_prim: Option<String>,
}

#[derive(Clone, Debug, PartialEq)]
enum Token {
    Word(String),
    Str(String),
    Asset(String),
    Path(String),
    Punct(u8),
}

/// The layer's tokens: words, strings, asset paths (`@…@`, `@@@…@@@`), path literals
/// (`<…>`) and punctuation; comments and numbers' signs are dropped.
fn tokens(text: &str) -> Vec<Token> {
    let b = text.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    let until = |i: usize, end: &[u8]| {
        let rest = &b[i.min(b.len())..];
        rest.windows(end.len()).position(|w| w == end).map_or(b.len(), |p| i + p)
    };
    while i < b.len() {
        let c = b[i];
        match c {
            b'#' => i = until(i, b"\n"),
            b'"' | b'\'' => {
                let triple = b.get(i..i + 3) == Some(&[c, c, c][..]);
                let (start, end) =
                    if triple { (i + 3, until(i + 3, &[c, c, c])) } else { (i + 1, string_end(b, i + 1, c)) };
                out.push(Token::Str(String::from_utf8_lossy(&b[start..end.min(b.len())]).into_owned()));
                i = end + if triple { 3 } else { 1 };
            }
            b'@' => {
                let triple = b.get(i..i + 3) == Some(&b"@@@"[..]);
                let (start, end) = if triple { (i + 3, until(i + 3, b"@@@")) } else { (i + 1, until(i + 1, b"@")) };
                out.push(Token::Asset(String::from_utf8_lossy(&b[start..end.min(b.len())]).into_owned()));
                i = end + if triple { 3 } else { 1 };
            }
            b'<' => {
                let end = until(i + 1, b">").min(until(i + 1, b"\n"));
                out.push(Token::Path(String::from_utf8_lossy(&b[i + 1..end.min(b.len())]).into_owned()));
                i = end + 1;
            }
            c if c.is_ascii_alphanumeric() || c == b'_' => {
                let start = i;
                while i < b.len() && (b[i].is_ascii_alphanumeric() || matches!(b[i], b'_' | b':' | b'.')) {
                    i += 1;
                }
                out.push(Token::Word(String::from_utf8_lossy(&b[start..i]).into_owned()));
            }
            c if c.is_ascii_whitespace() => i += 1,
            c => {
                out.push(Token::Punct(c));
                i += 1;
            }
        }
    }
    out
}

/// Where a single-quoted or double-quoted string opened before `i` ends (backslash escapes).
fn string_end(b: &[u8], mut i: usize, q: u8) -> usize {
    while i < b.len() && b[i] != q && b[i] != b'\n' {
        i += if b[i] == b'\\' { 2 } else { 1 };
    }
    i.min(b.len())
}

const ARC_KEYS: [&str; 5] = ["inherits", "specializes", "references", "payload", "subLayers"];

/// What an open bracket holds. Prims are told from the dictionaries, lists and variant sets
/// around them by where their `{` opens, not by depth alone: a `customData` or `variants`
/// dictionary in a prim's metadata opens a `{` before the prim's body does.
enum Frame {
    /// A prim's body, or one of its variants' (whose child prims and arcs compose into
    /// the prim, so are counted as its own).
    Body(String),
    /// The variants of one of the prim's variant sets: `variantSet "name" = { … }`.
    Variants(String),
    /// The metadata `( … )` of a prim or variant (of the prim it belongs to), or of the
    /// layer (`None`): where arcs are written.
    Meta(Option<String>),
    /// A dictionary, list, tuple or property's metadata.
    Other,
}

/// What the tokens since the last bracket began, awaiting the `{` of its body.
enum Opening {
    /// A prim spec: `def Type "Name"`.
    Prim(String),
    /// A variant set of this prim: `variantSet "name" =`.
    VariantSet(String),
    /// A variant, of a variant set of this prim: `"name"`.
    Variant(String),
}

/// The composition arcs of a text layer.
fn parse(text: &str) -> LayerArcs {
    let t = tokens(text);
    let mut out = LayerArcs::default();
    let mut frames: Vec<Frame> = Vec::new();
    let mut opening: Option<Opening> = None;
    let mut i = 0;
    while i < t.len() {
        // The prim whose body the token is directly in (`""`: the layer's root).
        let body = match frames.last() {
            None => Some(""),
            Some(Frame::Body(p)) => Some(p.as_str()),
            Some(_) => None,
        };
        match (&t[i], frames.last()) {
            (Token::Word(w), _) if matches!(w.as_str(), "def" | "over" | "class") => {
                // `def Type "Name"` or `def "Name"`.
                let name = match (t.get(i + 1), t.get(i + 2)) {
                    (Some(Token::Str(s)), _) | (Some(Token::Word(_)), Some(Token::Str(s))) => Some(s),
                    _ => None,
                };
                if let (Some(parent), Some(name)) = (body, name) {
                    opening = Some(Opening::Prim(format!("{parent}/{name}")));
                }
            }
            (Token::Word(w), Some(Frame::Body(p))) if w == "variantSet" => {
                opening = Some(Opening::VariantSet(p.clone()));
            }
            (Token::Str(_), Some(Frame::Variants(p))) => opening = Some(Opening::Variant(p.clone())),
            (Token::Word(w), Some(Frame::Meta(None))) if w == "defaultPrim" => {
                if let (Some(Token::Punct(b'=')), Some(Token::Str(s))) = (t.get(i + 1), t.get(i + 2)) {
                    out.default_prim = Some(s.clone());
                }
            }
            (Token::Word(w), Some(Frame::Meta(holder)))
                if ARC_KEYS.contains(&w.as_str()) && t.get(i + 1) == Some(&Token::Punct(b'=')) =>
            {
                let deleted = i > 0 && t[i - 1] == Token::Word("delete".into());
                let (arcs, next) = arc_value(&t, i + 2);
                match (w.as_str(), holder) {
                    _ if deleted => {}
                    ("subLayers", None) => out.sublayers.extend(arcs.into_iter().filter_map(|a| a.asset)),
                    ("subLayers", Some(_)) => {}
                    (_, Some(p)) => out.prims.entry(p.clone()).or_default().extend(arcs),
                    (_, None) => {}
                }
                i = next;
                continue;
            }
            (Token::Punct(b'('), top) => {
                // The opening stays: its body's `{` follows the metadata.
                let frame = match (top, &opening) {
                    (None | Some(Frame::Body(_)), Some(Opening::Prim(p)))
                    | (Some(Frame::Variants(_)), Some(Opening::Variant(p))) => Frame::Meta(Some(p.clone())),
                    (None, None) => Frame::Meta(None),
                    _ => Frame::Other,
                };
                frames.push(frame);
            }
            (Token::Punct(b'{'), top) => {
                let frame = match (top, &opening) {
                    (None | Some(Frame::Body(_)), Some(Opening::Prim(p)))
                    | (Some(Frame::Variants(_)), Some(Opening::Variant(p))) => Frame::Body(p.clone()),
                    (Some(Frame::Body(_)), Some(Opening::VariantSet(p))) => Frame::Variants(p.clone()),
                    _ => Frame::Other,
                };
                if !matches!(frame, Frame::Other) {
                    opening = None;
                }
                frames.push(frame);
            }
            (Token::Punct(b'['), _) => frames.push(Frame::Other),
            (Token::Punct(b')' | b']' | b'}'), _) => {
                frames.pop();
            }
            _ => {}
        }
        i += 1;
    }
    out
}

/// The arcs of a value starting at token `i` (a list in `[ ]` or one item), and the index
/// after it.
fn arc_value(t: &[Token], mut i: usize) -> (Vec<Arc>, usize) {
    let list = t.get(i) == Some(&Token::Punct(b'['));
    if list {
        i += 1;
    }
    let mut arcs = Vec::new();
    while i < t.len() {
        match &t[i] {
            Token::Asset(a) => {
                let prim = match t.get(i + 1) {
                    Some(Token::Path(p)) => {
                        i += 1;
                        Some(p.clone())
                    }
                    _ => None,
                };
                arcs.push(Arc { asset: (!a.is_empty()).then(|| a.clone()), prim });
            }
            Token::Path(p) => arcs.push(Arc { asset: None, prim: Some(p.clone()) }),
            Token::Punct(b']') if list => return (arcs, i + 1),
            // A layer offset or other item syntax: skipped.
            Token::Punct(b'(') => {
                while i < t.len() && t[i] != Token::Punct(b')') {
                    i += 1;
                }
            }
            _ if !list => {
                let next = i + usize::from(arcs.is_empty());
                return (arcs, next);
            }
            _ => {}
        }
        i += 1;
        if !list && !arcs.is_empty() {
            return (arcs, i);
        }
    }
    (arcs, i)
}

/// Layers read so far, by canonical path.
struct Layers {
    read: BTreeMap<PathBuf, Option<LayerArcs>>,
}

impl Layers {
    /// The arcs of the text layer at `path` (`None` for one that is missing, binary or
    /// unreadable: the crate reports those).
    fn get(&mut self, path: &Path) -> Result<Option<&LayerArcs>, String> {
        if !self.read.contains_key(path) {
            if self.read.len() >= MAX_LAYERS {
                return Err(format!("more than {MAX_LAYERS} layer files in one stage"));
            }
            let layer = crate::input_file::read(path, crate::input_file::Kind::ImportedScene)
                .ok()
                .and_then(|b| String::from_utf8(b).ok())
                .filter(|t| t.trim_start().starts_with("#usda"))
                .map(|t| parse(&t));
            self.read.insert(path.to_path_buf(), layer);
        }
        Ok(self.read[path].as_ref())
    }
}

fn canonical(dir: &Path, asset: &str) -> PathBuf {
    let p = dir.join(asset);
    std::fs::canonicalize(&p).unwrap_or(p)
}

/// A prim of a layer stack (the stack's root layer, canonical), as a node of the search.
type Node = (PathBuf, String);

/// Refuses a stage whose composition arcs, from the root layer `root` (its text `text`)
/// through the text layers it names, lead from a prim back to itself or an ancestor, or
/// whose sublayers include each other. The error names the chain: prims of the root layer
/// as `/Path`, others as `file</Path>`.
pub fn check_cycles(root: &Path, text: &str) -> Result<(), String> {
    let root = std::fs::canonicalize(root).unwrap_or_else(|_| root.to_path_buf());
    let mut layers = Layers { read: BTreeMap::new() };
    layers.read.insert(root.clone(), Some(parse(text)));
    let mut stacks: BTreeMap<PathBuf, Vec<PathBuf>> = BTreeMap::new();
    let stack = layer_stack(&mut layers, &root, &mut Vec::new(), &mut stacks)?;
    let name = |(file, prim): &Node| match *file == root {
        true => prim.clone(),
        false => format!("{}<{prim}>", file.display()),
    };
    let mut starts = BTreeSet::new();
    for layer in &stack {
        if let Some(l) = layers.get(layer)? {
            starts.extend(l.prims.keys().cloned());
        }
    }
    let mut seen = BTreeSet::new();
    for prim in starts {
        let mut chain = vec![(root.clone(), prim)];
        if let Some(c) = cycle_from(&mut layers, &mut stacks, &mut chain, &mut seen)? {
            return Err(format!(
                "composition arcs form a cycle: {}",
                c.iter().map(name).collect::<Vec<_>>().join(" -> ")
            ));
        }
    }
    Ok(())
}

/// The layers of the stack rooted at `file`, strongest first, its sublayers' cycles an
/// error.
fn layer_stack(
    layers: &mut Layers,
    file: &Path,
    visiting: &mut Vec<PathBuf>,
    stacks: &mut BTreeMap<PathBuf, Vec<PathBuf>>,
) -> Result<Vec<PathBuf>, String> {
    if let Some(s) = stacks.get(file) {
        return Ok(s.clone());
    }
    if let Some(at) = visiting.iter().position(|v| v == file) {
        let chain: Vec<String> =
            visiting[at..].iter().chain([&file.to_path_buf()]).map(|p| p.display().to_string()).collect();
        return Err(format!("sublayers form a cycle: {}", chain.join(" -> ")));
    }
    let dir = file.parent().unwrap_or(Path::new(".")).to_path_buf();
    let subs = layers.get(file)?.map(|l| l.sublayers.clone()).unwrap_or_default();
    visiting.push(file.to_path_buf());
    let mut stack = vec![file.to_path_buf()];
    for s in subs {
        stack.extend(layer_stack(layers, &canonical(&dir, &s), visiting, stacks)?);
    }
    visiting.pop();
    stacks.insert(file.to_path_buf(), stack.clone());
    Ok(stack)
}

/// Follows the arcs from the last node of `chain`; the chain when it comes back inside one
/// of its prims.
fn cycle_from(
    layers: &mut Layers,
    stacks: &mut BTreeMap<PathBuf, Vec<PathBuf>>,
    chain: &mut Vec<Node>,
    seen: &mut BTreeSet<Node>,
) -> Result<Option<Vec<Node>>, String> {
    let inside = |a: &str, b: &str| a == b || a.starts_with(&format!("{b}/"));
    let (file, prim) = chain.last().expect("a chain is never empty").clone();
    // The prim's arcs and its ancestors', in every layer of the stack.
    let mut targets = Vec::new();
    for layer in layer_stack(layers, &file, &mut Vec::new(), stacks)? {
        let dir = layer.parent().unwrap_or(Path::new(".")).to_path_buf();
        let Some(l) = layers.get(&layer)? else { continue };
        for (holder, arcs) in &l.prims {
            if inside(&prim, holder) {
                targets.extend(arcs.iter().map(|a| (a.clone(), dir.clone())));
            }
        }
    }
    for (arc, dir) in targets {
        let target_file = arc.asset.as_deref().map_or(file.clone(), |a| canonical(&dir, a));
        let target_prim = match arc.prim {
            Some(p) => p,
            None => match layers.get(&target_file)?.and_then(|l| l.default_prim.clone()) {
                Some(d) => format!("/{d}"),
                None => continue,
            },
        };
        let node = (target_file, target_prim);
        if chain.iter().any(|(f, p)| *f == node.0 && (inside(p, &node.1) || inside(&node.1, p))) {
            let mut c = chain.clone();
            c.push(node);
            return Ok(Some(c));
        }
        if seen.insert(node.clone()) {
            chain.push(node);
            if let Some(c) = cycle_from(layers, stacks, chain, seen)? {
                return Ok(Some(c));
            }
            chain.pop();
        }
    }
    Ok(None)
}

/// The relative asset paths that a layer's `references`, `payload` and `subLayers` arcs
/// name (not absolute paths, search paths with a scheme, or expressions), for the warnings
/// about missing files.
pub fn file_assets(text: &str) -> Vec<String> {
    let l = parse(text);
    let arcs = l.prims.values().flatten().filter_map(|a| a.asset.clone());
    arcs.chain(l.sublayers)
        .filter(|a| !a.contains("://") && !a.contains('$') && !a.starts_with('`'))
        .collect::<BTreeSet<_>>()
        .into_iter()
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn arcs_are_read_from_metadata_lists_across_lines() {
        let l = parse(
            "#usda 1.0\n(\n    defaultPrim = \"Root\"\n    subLayers = [\n        @./a.usda@,\n        @b.usda@ (offset = 2)\n    ]\n)\n\
             def Xform \"Root\" (\n    prepend references = [\n        @c.usda@</X>,\n        </Local>\n    ]\n    inherits = </Base>\n) {\n\
             \x20   def \"Child\" (payload = @d.usda@) { string doc = \"references = @no.usda@\" }\n}\n\
             over \"Gone\" (delete references = @e.usda@) {}\n",
        );
        assert_eq!(l.default_prim.as_deref(), Some("Root"));
        assert_eq!(l.sublayers, ["./a.usda", "b.usda"]);
        let arc = |a: Option<&str>, p: Option<&str>| Arc { asset: a.map(str::to_string), prim: p.map(str::to_string) };
        assert_eq!(
            l.prims["/Root"],
            [arc(Some("c.usda"), Some("/X")), arc(None, Some("/Local")), arc(None, Some("/Base"))]
        );
        assert_eq!(l.prims["/Root/Child"], [arc(Some("d.usda"), None)]);
        assert!(!l.prims.contains_key("/Gone"), "{:?}", l.prims);
    }
}
