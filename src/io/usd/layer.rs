//! What every layer goes through before the `openusd` crate reads it: checks that keep
//! hostile text from overflowing the crate parser's stack or sending its path walks round
//! forever, the parts of the USDA grammar the crate's parser does not accept (number forms,
//! legacy type names, `//` comments, unsigned arrays, asset-valued time samples), and the
//! file resolver that applies all of them to every layer a stage opens.

use openusd::ar;
use std::io;

/// Deepest nesting of `(`, `[` and `{` a text layer may have.
pub const MAX_NESTING: usize = 128;

/// The leading bytes of a binary crate layer (`.usdc`).
const USDC_MAGIC: &[u8] = b"PXR-USDC";
/// The leading bytes of a zip archive (a `.usdz` package).
const ZIP_MAGIC: &[u8] = b"PK\x03\x04";

/// What a layer's bytes are, by their leading bytes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum LayerKind {
    /// USD text (`#usda`).
    Text,
    /// A binary crate file.
    Crate,
    /// A zip package.
    Package,
}

/// Checks a layer's bytes and returns them as the crate should read them: text layers
/// rewritten by [`normalize_numbers`], [`legacy_type_names`] and [`grammar_gaps`] (line
/// numbers unchanged), binary crate files of older versions rewritten as
/// [`super::crate_legacy`] says (their sizes checked by [`super::crate_file::check`]), and
/// packages as they are (a package's layers checked by `check_package`).
pub fn prepare_layer(bytes: Vec<u8>) -> Result<(LayerKind, Vec<u8>), String> {
    if bytes.starts_with(USDC_MAGIC) {
        let bytes = super::crate_legacy::upgrade(bytes)?;
        super::crate_file::check(&bytes)?;
        return Ok((LayerKind::Crate, super::crate_legacy::array_sample_times(bytes)?));
    }
    if bytes.starts_with(ZIP_MAGIC) {
        check_package(&bytes)?;
        return Ok((LayerKind::Package, bytes));
    }
    let text = std::str::from_utf8(&bytes)
        .map_err(|_| "neither USD text nor a binary `PXR-USDC` layer nor a `.usdz` package".to_string())?;
    check_text(text)?;
    Ok((LayerKind::Text, grammar_gaps(&legacy_type_names(&normalize_numbers(text))).into_bytes()))
}

/// Checks a text layer before the crate parses it: a `#usda` header, at most
/// [`MAX_NESTING`] levels of brackets outside strings and comments, prim names that are
/// identifiers and path literals whose `}` close a `{`.
fn check_text(text: &str) -> Result<(), String> {
    if !text.trim_start().starts_with("#usda") {
        return Err("not a USD text layer: it does not start with `#usda`".into());
    }
    check_prim_names(text)?;
    let mut depth = 0usize;
    let mut fail = None;
    scan(text, |b, i, line| match b[i] {
        b'<' if fail.is_none() => fail = check_path_literal(b, i, line).err(),
        b'(' | b'[' | b'{' => {
            depth += 1;
            if depth > MAX_NESTING && fail.is_none() {
                fail = Some(format!("line {line}: brackets nest deeper than {MAX_NESTING} levels"));
            }
        }
        b')' | b']' | b'}' => depth = depth.saturating_sub(1),
        _ => {}
    });
    fail.map_or(Ok(()), Err)
}

/// Calls `visit(bytes, index, line)` for every byte of `text` outside comments, strings
/// (single, double and triple quoted) and asset paths (`@…@`, `@@@…@@@`); a path literal
/// (`<…>`) is visited at its `<` and skipped to its `>`, a `//` comment at its first `/`.
fn scan(text: &str, mut visit: impl FnMut(&[u8], usize, u32)) {
    let b = text.as_bytes();
    let (mut i, mut line) = (0usize, 1u32);
    let skip_quoted = |i: &mut usize, line: &mut u32, q: u8| {
        let triple = b.get(*i..*i + 3) == Some(&[q, q, q][..]);
        *i += if triple { 3 } else { 1 };
        while *i < b.len() {
            if b[*i] == b'\\' && q != b'@' {
                *i += 2;
                continue;
            }
            if b[*i] == b'\n' {
                *line += 1;
            }
            if b[*i] == q && (!triple || b.get(*i..*i + 3) == Some(&[q, q, q][..])) {
                *i += if triple { 3 } else { 1 };
                return;
            }
            *i += 1;
        }
    };
    while i < b.len() {
        match b[i] {
            b'\n' => line += 1,
            c @ (b'#' | b'/') if c == b'#' || b.get(i + 1) == Some(&b'/') => {
                if c == b'/' {
                    visit(b, i, line);
                }
                while i < b.len() && b[i] != b'\n' {
                    i += 1;
                }
                continue;
            }
            q @ (b'"' | b'\'' | b'@') => {
                skip_quoted(&mut i, &mut line, q);
                continue;
            }
            b'<' => {
                visit(b, i, line);
                // A path literal ends at `>`; one left open ends at the line's end.
                while i < b.len() && !matches!(b[i], b'>' | b'\n') {
                    i += 1;
                }
                if b.get(i) == Some(&b'>') {
                    i += 1;
                }
                continue;
            }
            _ => visit(b, i, line),
        }
        i += 1;
    }
}

/// Rewrites the number forms the USDA grammar allows but the crate's tokenizer refuses
/// (`.5`, `-.5`, `7.`, `7.e3`) to ones it reads (`0.5`, `-0.5`, `7.0`, `7.0e3`), outside
/// strings, comments and paths. Only digits are inserted, so every line keeps its number.
pub fn normalize_numbers(text: &str) -> String {
    let b = text.as_bytes();
    // Where to insert a `0`: before a `.` that starts a number, after one that ends its
    // digits.
    let mut zeros: Vec<usize> = Vec::new();
    let starts_token =
        |i: usize| i == 0 || !(b[i - 1].is_ascii_alphanumeric() || matches!(b[i - 1], b'_' | b':' | b'.'));
    let mut digits_from: Option<usize> = None;
    scan(text, |b, i, _| {
        let c = b[i];
        if c.is_ascii_digit() {
            if digits_from.is_none()
                && (starts_token(i) || (i > 0 && matches!(b[i - 1], b'+' | b'-') && starts_token(i - 1)))
            {
                digits_from = Some(i);
            }
            return;
        }
        let in_number = digits_from.take().is_some();
        if c != b'.' {
            return;
        }
        let next_digit = b.get(i + 1).is_some_and(u8::is_ascii_digit);
        if in_number && !next_digit {
            // `7.` or `7.e3`: the fraction needs a digit.
            zeros.push(i + 1);
        } else if !in_number && next_digit {
            let signed = i > 0 && matches!(b[i - 1], b'+' | b'-') && starts_token(i - 1);
            if starts_token(i) || signed {
                // `.5` or `-.5`: the integer part needs a digit.
                zeros.push(i);
            }
        }
    });
    if zeros.is_empty() {
        return text.to_string();
    }
    let mut out = String::with_capacity(text.len() + zeros.len());
    let mut last = 0;
    for z in zeros {
        out.push_str(&text[last..z]);
        out.push('0');
        last = z;
    }
    out.push_str(&text[last..]);
    out
}

/// Type names older layers use (USD's `Sdf` value type aliases, as Houdini and early
/// exporters write them; the parser of USD's text format still registers them) and the
/// names the crate knows them by.
const TYPE_ALIASES: [(&str, &str); 40] = [
    ("Vec2i", "int2"),
    ("Vec3i", "int3"),
    ("Vec4i", "int4"),
    ("Vec2h", "half2"),
    ("Vec3h", "half3"),
    ("Vec4h", "half4"),
    ("Vec2f", "float2"),
    ("Vec3f", "float3"),
    ("Vec4f", "float4"),
    ("Vec2d", "double2"),
    ("Vec3d", "double3"),
    ("Vec4d", "double4"),
    ("Point", "point3d"),
    ("PointHalf", "point3h"),
    ("PointFloat", "point3f"),
    ("PointDouble", "point3d"),
    ("Normal", "normal3d"),
    ("NormalHalf", "normal3h"),
    ("NormalFloat", "normal3f"),
    ("NormalDouble", "normal3d"),
    ("Vector", "vector3d"),
    ("VectorFloat", "vector3f"),
    ("Color", "color3d"),
    ("ColorHalf", "color3h"),
    ("ColorFloat", "color3f"),
    ("ColorDouble", "color3d"),
    ("Color4Half", "color4h"),
    ("Color4Float", "color4f"),
    ("Color4Double", "color4d"),
    ("Quath", "quath"),
    ("Quatf", "quatf"),
    ("Quatd", "quatd"),
    ("Matrix2d", "matrix2d"),
    ("Matrix3d", "matrix3d"),
    ("Matrix4d", "matrix4d"),
    ("Frame", "frame4d"),
    ("Transform", "matrix4d"),
    ("PointIndex", "int"),
    ("EdgeIndex", "int"),
    ("FaceIndex", "int"),
];

/// Rewrites `TYPE_ALIASES` where they stand as an attribute's type: a word (outside
/// strings, comments and paths) followed by an optional `[]`, spaces and the attribute's
/// name. Line numbers stay.
pub fn legacy_type_names(text: &str) -> String {
    let b = text.as_bytes();
    let ident = |c: u8| c.is_ascii_alphanumeric() || c == b'_';
    let mut edits: Vec<(usize, usize, &str)> = Vec::new();
    scan(text, |b, i, _| {
        if !b[i].is_ascii_uppercase() || (i > 0 && (ident(b[i - 1]) || b[i - 1] == b':')) {
            return;
        }
        let word = b[i..].iter().take_while(|&&c| ident(c)).count();
        let Some(&(from, to)) = TYPE_ALIASES.iter().find(|(from, _)| from.as_bytes() == &b[i..i + word]) else {
            return;
        };
        let mut j = i + from.len();
        if b[j..].starts_with(b"[]") {
            j += 2;
        }
        let spaces = b[j..].iter().take_while(|&&c| c == b' ' || c == b'\t').count();
        if spaces > 0 && b.get(j + spaces).is_some_and(|&c| c.is_ascii_alphabetic() || c == b'_') {
            edits.push((i, i + from.len(), to));
        }
    });
    let mut out = String::with_capacity(b.len());
    let mut last = 0;
    for (from, to, with) in edits {
        out.push_str(&text[last..from]);
        out.push_str(with);
        last = to;
    }
    out.push_str(&text[last..]);
    out
}

/// Value types the crate cannot parse and the type it reads their values as: tress reads
/// no unsigned array, so widening one keeps the layer readable and loses nothing it uses;
/// `matrix[]`, as Arnold's USD writer names an array of 4 × 4 double matrices, is
/// `matrix4d[]`; a `pathExpression` (a collection's membership, written as a string;
/// tress reads no collections) is a `string`.
const TYPE_STAND_INS: [(&str, &str); 4] =
    [("uint[]", "int64[]"), ("uint64[]", "int64[]"), ("matrix[]", "matrix4d[]"), ("pathExpression", "string")];

/// Rewrites forms of the USDA grammar (Pixar's `Sdf` text format) the crate's parser
/// rejects, outside strings and paths, so the rest of the layer reads:
/// - spaces or tabs after the `#usda 1.0` header (the crate wants the line break right
///   after the version) are dropped;
/// - `//` line comments (the format's lexer skips `#`, `//` and `/* */` comments; the
///   crate only `#` and `/* */`) become `# ` comments;
/// - `uint[]` and `uint64[]` attributes become `int64[]`, `matrix[]` ones `matrix4d[]`,
///   `pathExpression` ones `string`;
/// - the legacy variability `config` becomes `uniform`, as USD's parser converts it;
/// - an `asset` or `asset[]` attribute's values written as strings (`"tex.png"`, which
///   USD's parser takes as asset paths) become asset paths `@tex.png@`;
/// - integer attributes' values written with a zero fraction (`int n = 5.0`, which USD's
///   parser reads as 5) lose it;
/// - the `@path@` samples of an `asset` attribute's `.timeSamples` (an IES profile or a
///   volume file per frame; the crate reads no asset there) become the strings `"path"`.
///
/// No edit adds or removes a line break, so errors keep their line numbers.
pub fn grammar_gaps(text: &str) -> String {
    let ident = |c: u8| c.is_ascii_alphanumeric() || c == b'_' || c == b':';
    let mut edits: Vec<(usize, usize, String)> = Vec::new();
    let header = &text[..text.find('\n').unwrap_or(text.len())];
    let header = header.strip_suffix('\r').unwrap_or(header);
    let kept = header.trim_end_matches([' ', '\t']).len();
    if header.starts_with("#usda") && kept < header.len() {
        edits.push((kept, header.len(), String::new()));
    }
    let mut asset_blocks: Vec<usize> = Vec::new();
    let end_of_line = |b: &[u8], i: usize| b[i..].iter().position(|&c| c == b'\n').map_or(b.len(), |n| i + n);
    scan(text, |b, i, _| {
        if b[i] == b'/' && b.get(i + 1) == Some(&b'/') {
            edits.push((i, i + 2, "# ".into()));
            return;
        }
        if i > 0 && ident(b[i - 1]) {
            return;
        }
        for (from, to) in TYPE_STAND_INS {
            if b[i..].starts_with(from.as_bytes()) && b.get(i + from.len()).is_some_and(|c| c.is_ascii_whitespace()) {
                edits.push((i, i + from.len(), to.into()));
            }
        }
        let space = |at: usize| b.get(at).is_some_and(|c| *c == b' ' || *c == b'\t');
        if b[i..].starts_with(b"config") && space(i + 6) {
            // Only as a variability: a type and the attribute's name follow.
            let next = i + 6 + b[i + 6..].iter().take_while(|&&c| c == b' ' || c == b'\t').count();
            if b.get(next).is_some_and(|c| c.is_ascii_alphabetic()) {
                edits.push((i, i + 6, "uniform".into()));
            }
        }
        // An integer attribute's value on its declaration's line, written with a zero
        // fraction (`int length = 5.0`).
        let word = b[i..].iter().take_while(|&&c| c.is_ascii_alphanumeric() || c == b'[' || c == b']').count();
        if INTEGER_TYPES.contains(&&b[i..i + word]) && space(i + word) {
            edits.extend(whole_numbers(b, i + word, end_of_line(b, i)));
        }
        let array = b[i..].starts_with(b"asset[]");
        if b[i..].starts_with(b"asset") && (space(i + 5) || array && space(i + 7)) {
            let line_end = end_of_line(b, i);
            let decl_at = i + if array { 7 } else { 5 };
            let decl: String = String::from_utf8_lossy(&b[decl_at..line_end]).split_whitespace().collect();
            if decl.contains(".timeSamples={") {
                // `asset NAME.timeSamples = {` on one line (the crate reads arrays of asset
                // paths as samples: `asset[]` ones stay).
                if array {
                    return;
                }
                asset_blocks.push(decl_at + b[decl_at..line_end].iter().position(|&c| c == b'{').unwrap_or(0));
            } else if decl.starts_with(|c: char| c.is_ascii_alphabetic() || c == '_') {
                edits.extend(quoted_assets(b, decl_at, line_end));
            }
        }
    });
    let b = text.as_bytes();
    for open in asset_blocks {
        // Inside the block only times, `:`, `,`, `None` and the asset paths stand.
        let mut j = open + 1;
        while j < b.len() && b[j] != b'}' {
            if b[j] != b'@' {
                j += 1;
                continue;
            }
            let delim = if b[j..].starts_with(b"@@@") { 3 } else { 1 };
            let body = j + delim;
            let Some(len) = b[body..].windows(delim).position(|w| w.iter().all(|&c| c == b'@')) else { break };
            let path = &b[body..body + len];
            // A path holding what a string would read otherwise is left for the crate to refuse.
            if !path.iter().any(|&c| matches!(c, b'"' | b'\\' | b'\n')) {
                let quote = "\"".repeat(delim);
                edits.push((j, body, quote.clone()));
                edits.push((body + len, body + len + delim, quote));
            }
            j = body + len + delim;
        }
    }
    if edits.is_empty() {
        return text.to_string();
    }
    edits.sort_by_key(|e| e.0);
    let mut out = String::with_capacity(text.len());
    let mut last = 0;
    for (from, to, with) in edits {
        out.push_str(&text[last..from]);
        out.push_str(&with);
        last = to;
    }
    out.push_str(&text[last..]);
    out
}

/// Where an attribute's value starts on its declaration's line `b[from..line_end]`: after
/// its `=`, if it has one there.
fn value_start(b: &[u8], from: usize, line_end: usize) -> Option<usize> {
    b[from..line_end].iter().position(|&c| c == b'=').map(|eq| from + eq + 1)
}

/// Integer value types (scalars, tuples and their arrays), whose values USD's parser reads
/// from numbers written with a zero fraction (`5.0`) and the crate's does not.
const INTEGER_TYPES: [&[u8]; 10] =
    [b"int", b"int[]", b"int2", b"int2[]", b"int3", b"int3[]", b"int4", b"int4[]", b"int64", b"int64[]"];

/// The edits that drop the zero fraction of the numbers in an attribute's value on
/// `b[from..line_end]` (after its `=`, as far as numbers, signs, spaces, commas and
/// brackets go): `5.0` and `-3.00` become `5` and `-3`; other numbers stay, for the
/// parser to judge.
fn whole_numbers(b: &[u8], from: usize, line_end: usize) -> Vec<(usize, usize, String)> {
    let Some(mut j) = value_start(b, from, line_end) else { return Vec::new() };
    let mut edits = Vec::new();
    let in_value = |c: u8| c.is_ascii_digit() || b" \t.,+-eE()[]".contains(&c);
    while j < line_end && in_value(b[j]) {
        if b[j].is_ascii_digit() && !b[j - 1].is_ascii_alphanumeric() && b[j - 1] != b'.' {
            let dot = j + b[j..line_end].iter().take_while(|c| c.is_ascii_digit()).count();
            if dot < line_end && b[dot] == b'.' {
                let end = dot + 1 + b[dot + 1..line_end].iter().take_while(|&&c| c == b'0').count();
                if end > dot + 1 && b.get(end).is_none_or(|c| !c.is_ascii_alphanumeric() && *c != b'.') {
                    edits.push((dot, end, String::new()));
                }
                j = end;
            } else {
                j = dot;
            }
            continue;
        }
        j += 1;
    }
    edits
}

/// The edits that make asset paths of the plain strings in an attribute's value on
/// `b[from..line_end]` (after its `=`, up to the metadata's `(` or the line's end): each
/// `"` of a one-line string holding no `@`, `\` or `'` becomes `@`.
fn quoted_assets(b: &[u8], from: usize, line_end: usize) -> Vec<(usize, usize, String)> {
    let Some(mut j) = value_start(b, from, line_end) else { return Vec::new() };
    let mut edits = Vec::new();
    while j < line_end {
        match b[j] {
            b'(' | b'#' | b'@' => break,
            b'"' if b[j..].starts_with(b"\"\"\"") => break,
            b'"' => {
                let Some(len) = b[j + 1..line_end].iter().position(|&c| c == b'"') else { break };
                let body = &b[j + 1..j + 1 + len];
                if body.iter().any(|c| matches!(c, b'@' | b'\\' | b'\'')) {
                    break;
                }
                edits.push((j, j + 1, "@".into()));
                edits.push((j + 1 + len, j + 2 + len, "@".into()));
                j += len + 2;
            }
            _ => j += 1,
        }
    }
    edits
}

/// Checks that every prim a layer defines (`def`, `over` or `class`, then an optional type,
/// then the quoted name) is named by an identifier (a letter or `_`, then letters, digits
/// or `_`), as USD requires: the crate recurses without end on a prim path holding other
/// characters (a name like `"Wor}d"` overflowed the stack).
fn check_prim_names(text: &str) -> Result<(), String> {
    for (n, line) in text.lines().enumerate() {
        let words = line.trim_start();
        let Some(rest) = ["def ", "over ", "class "].iter().find_map(|k| words.strip_prefix(k)) else { continue };
        // The name is the first quoted string; a line without one is left to the parser.
        let Some(name) = rest.split('"').nth(1) else { continue };
        if !is_identifier(name) {
            return Err(format!("line {}: prim name \"{name}\" is not an identifier (letters, digits and _)", n + 1));
        }
    }
    Ok(())
}

/// Whether `name` is an identifier: a letter or `_`, then letters, digits or `_`.
pub fn is_identifier(name: &str) -> bool {
    let mut chars = name.chars();
    chars.next().is_some_and(|c| c.is_ascii_alphabetic() || c == '_')
        && chars.all(|c| c.is_ascii_alphanumeric() || c == '_')
}

/// Checks the path literal opening at `b[at]` (a `<`, up to the next `>`): every `}` in it
/// must close a variant selection's `{`. The crate's `Path::parent` returns a path ending in
/// a `}` without a `{` unchanged, so walking the ancestors of `</A}>` never ends.
fn check_path_literal(b: &[u8], at: usize, line: u32) -> Result<(), String> {
    let mut open = false;
    // Stopping at the next `<` or line end keeps the whole check linear in the text.
    for &c in b[at + 1..].iter().take_while(|&&c| !matches!(c, b'>' | b'<' | b'\n')) {
        match c {
            b'{' => open = true,
            b'}' if !open => return Err(format!("line {line}: path has a `}}` that closes no variant selection `{{`")),
            b'}' => open = false,
            _ => {}
        }
    }
    Ok(())
}

/// Checks the text layers stored in a `.usdz` package (a zip archive whose entries are
/// stored uncompressed, as the package format requires) with the same checks as a text
/// layer file, walking the archive's local file headers.
fn check_package(bytes: &[u8]) -> Result<(), String> {
    let u16_at = |i: usize| bytes.get(i..i + 2).map(|s| u16::from_le_bytes([s[0], s[1]]) as usize);
    let u32_at = |i: usize| bytes.get(i..i + 4).map(|s| u32::from_le_bytes([s[0], s[1], s[2], s[3]]) as usize);
    let mut at = 0usize;
    while bytes.get(at..at + 4) == Some(ZIP_MAGIC) {
        let bad = || "a .usdz package whose archive is cut short".to_string();
        let method = u16_at(at + 8).ok_or_else(bad)?;
        let size = u32_at(at + 18).ok_or_else(bad)?;
        let (name_len, extra_len) = (u16_at(at + 26).ok_or_else(bad)?, u16_at(at + 28).ok_or_else(bad)?);
        let name_at = at + 30;
        let data_at = name_at + name_len + extra_len;
        let name = bytes.get(name_at..name_at + name_len).ok_or_else(bad)?;
        let name = String::from_utf8_lossy(name).to_string();
        let data = bytes.get(data_at..data_at + size).ok_or_else(bad)?;
        if method != 0 {
            return Err(format!("package entry `{name}` is compressed (.usdz entries must be stored)"));
        }
        if data.starts_with(USDC_MAGIC) {
            super::crate_file::check(data).map_err(|m| format!("package entry `{name}`: {m}"))?;
        } else if name.ends_with(".usda") || name.ends_with(".usd") {
            let text = std::str::from_utf8(data).map_err(|_| format!("package entry `{name}` is not UTF-8 text"))?;
            if text.trim_start().starts_with("#usda") {
                check_text(text).map_err(|m| format!("package entry `{name}`: {m}"))?;
            }
        }
        at = data_at + size;
    }
    Ok(())
}

/// The default file resolver, with every layer it opens passed through [`prepare_layer`],
/// and the asset paths it could not resolve kept (the crate drops a reference to a
/// missing file without a word).
pub struct GuardedResolver {
    inner: ar::DefaultResolver,
    missing: MissingAssets,
}

/// The asset paths a [`GuardedResolver`] could not resolve, shared with its user.
pub type MissingAssets = std::sync::Arc<std::sync::Mutex<std::collections::BTreeSet<String>>>;

impl Default for GuardedResolver {
    fn default() -> Self {
        GuardedResolver { inner: ar::DefaultResolver::new(), missing: Default::default() }
    }
}

impl GuardedResolver {
    /// Where the asset paths that resolve to no file are kept.
    pub fn missing(&self) -> MissingAssets {
        self.missing.clone()
    }
}

impl ar::Resolver for GuardedResolver {
    fn create_identifier(&self, asset_path: &str, anchor: Option<&ar::ResolvedPath>) -> String {
        self.inner.create_identifier(asset_path, anchor)
    }
    fn resolve(&self, asset_path: &str) -> Option<ar::ResolvedPath> {
        let r = self.inner.resolve(asset_path);
        if r.is_none() {
            if let Ok(mut m) = self.missing.lock() {
                m.insert(asset_path.to_string());
            }
        }
        r
    }
    fn resolve_for_new_asset(&self, asset_path: &str) -> Option<ar::ResolvedPath> {
        self.inner.resolve_for_new_asset(asset_path)
    }
    fn open_asset(&self, resolved: &ar::ResolvedPath) -> io::Result<Box<dyn ar::Asset>> {
        // A layer on disk is opened as every input file is (a regular file, at most the
        // cap of an imported scene); a layer inside a package is the resolver's to read.
        let bytes = match std::fs::metadata(&**resolved) {
            Ok(_) => crate::input_file::read(resolved, crate::input_file::Kind::ImportedScene)
                .map_err(|e| io::Error::new(io::ErrorKind::InvalidData, e.to_string()))?,
            Err(_) => self.inner.open_asset(resolved)?.read_all()?,
        };
        let (_, bytes) = prepare_layer(bytes)
            .map_err(|m| io::Error::new(io::ErrorKind::InvalidData, format!("{}: {m}", resolved.display())))?;
        Ok(Box::new(io::Cursor::new(bytes)))
    }
    fn identity(&self) -> String {
        self.inner.identity()
    }
}
