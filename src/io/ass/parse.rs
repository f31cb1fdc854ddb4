//! The text of an Arnold scene source (`.ass`) file as nodes of parameters (Arnold user
//! guide, "Arnold Scene Source (.ass) file format"): `#` comments to the end of the line;
//! nodes `type { name value ... }`; a value either the tokens left on the parameter's line
//! (and on the lines after it that start with a number, as a `matrix` writes its rows),
//! or an array `count keys TYPE` followed by count × keys elements of TYPE, on as many
//! lines as they take. Tokens are numbers, quoted strings and bare words (`on`, node names,
//! enums). An array's type may carry an encoding prefix (`b85VECTOR`, `b64VECTOR`): its
//! elements are then one block of encoded data. Every malformed input is an
//! error naming the line; counts are checked against the bytes left before anything is
//! allocated for them.

use std::fmt;

/// A value token.
#[derive(Clone, Debug, PartialEq)]
pub enum Atom {
    /// A finite number.
    Num(f64),
    /// A quoted string, without its quotes.
    Str(String),
    /// A bare word (`on`, a node name, an enum).
    Word(String),
}

impl Atom {
    /// The atom as a name or string: a quoted string or a bare word.
    pub fn text(&self) -> Option<&str> {
        match self {
            Atom::Str(s) | Atom::Word(s) => Some(s),
            Atom::Num(_) => None,
        }
    }
}

impl fmt::Display for Atom {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Atom::Num(x) => write!(f, "{x}"),
            Atom::Str(s) => write!(f, "\"{s}\""),
            Atom::Word(s) => f.write_str(s),
        }
    }
}

/// One parameter of a node.
#[derive(Clone, Debug, PartialEq)]
pub struct Param {
    /// Its name.
    pub name: String,
    /// The line it starts on.
    pub line: usize,
    /// Its values: of the first motion key only for an array with several.
    pub values: Vec<Atom>,
    /// The element type an array declares (`VECTOR`, `UINT`, ...), `None` for a plain
    /// value.
    pub array: Option<String>,
}

/// One node: its type, its `name` (empty when it has none, as `options`) and parameters.
#[derive(Clone, Debug, PartialEq)]
pub struct Node {
    /// Its type (`polymesh`, `persp_camera`).
    pub kind: String,
    /// Its `name` parameter.
    pub name: String,
    /// The line its type is on.
    pub line: usize,
    /// Its parameters in file order (`name` and `declare` lines left out).
    pub params: Vec<Param>,
}

impl Node {
    /// The parameter named `name`, if the node has it.
    pub fn param(&self, name: &str) -> Option<&Param> {
        self.params.iter().find(|p| p.name == name)
    }
}

/// A parse error: the line and what is wrong there.
#[derive(Clone, Debug, PartialEq)]
pub struct ParseError {
    /// 1-based line.
    pub line: usize,
    /// What is wrong.
    pub message: String,
}

impl fmt::Display for ParseError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "line {}: {}", self.line, self.message)
    }
}

fn err<T>(line: usize, message: impl Into<String>) -> Result<T, ParseError> {
    Err(ParseError { line, message: message.into() })
}

/// A token: a brace, a quoted string or a bare word (a number, a name, or an encoded
/// array's data, which the parser tells apart).
#[derive(Clone, Debug, PartialEq)]
enum Tok<'a> {
    Open,
    Close,
    Str(&'a str),
    Bare(&'a str),
}

/// A token with its line and whether a line ended before it.
type Lexed<'a> = (Tok<'a>, usize, bool);

struct Lexer<'a> {
    text: &'a str,
    at: usize,
    line: usize,
}

impl<'a> Lexer<'a> {
    /// Skips blanks and comments; returns whether a line ended on the way.
    fn skip(&mut self) -> bool {
        let bytes = self.text.as_bytes();
        let mut newline = false;
        while self.at < bytes.len() {
            match bytes[self.at] {
                b'\n' => {
                    self.line += 1;
                    newline = true;
                    self.at += 1;
                }
                b' ' | b'\t' | b'\r' => self.at += 1,
                b'#' => {
                    while self.at < bytes.len() && bytes[self.at] != b'\n' {
                        self.at += 1;
                    }
                }
                _ => break,
            }
        }
        newline
    }

    /// Bytes not yet read.
    fn left(&self) -> usize {
        self.text.len() - self.at
    }

    /// The next token; `None` at the end.
    fn next(&mut self) -> Result<Option<Lexed<'a>>, ParseError> {
        let newline = self.skip();
        let bytes = self.text.as_bytes();
        if self.at >= bytes.len() {
            return Ok(None);
        }
        let line = self.line;
        let tok = match bytes[self.at] {
            b'{' => {
                self.at += 1;
                Tok::Open
            }
            b'}' => {
                self.at += 1;
                Tok::Close
            }
            b'"' => {
                // A quote inside a string is escaped with a backslash (`\"`), kept as written.
                let start = self.at + 1;
                let mut end = start;
                loop {
                    match bytes.get(end) {
                        None => return err(line, "a quoted string is not closed"),
                        Some(b'\\') => end += 2,
                        Some(b'"') => break,
                        Some(_) => end += 1,
                    }
                }
                let s = &self.text[start..end.min(bytes.len())];
                self.line += s.matches('\n').count();
                self.at = end + 1;
                Tok::Str(s)
            }
            _ => {
                let start = self.at;
                while self.at < bytes.len()
                    && !matches!(bytes[self.at], b' ' | b'\t' | b'\r' | b'\n' | b'{' | b'}' | b'"' | b'#')
                {
                    self.at += 1;
                }
                let word = &self.text[start..self.at];
                if let Some(c) = word.chars().find(|c| c.is_control()) {
                    return err(line, format!("unexpected character {c:?}"));
                }
                Tok::Bare(word)
            }
        };
        Ok(Some((tok, line, newline)))
    }
}

/// A bare token: a number when it starts like one (it must then be a finite one), else a
/// word.
fn atom(word: &str, line: usize) -> Result<Atom, ParseError> {
    let first = word.as_bytes()[0];
    if first.is_ascii_digit() || matches!(first, b'-' | b'+' | b'.') {
        return match word.parse::<f64>() {
            Ok(x) if x.is_finite() => Ok(Atom::Num(x)),
            Ok(_) => err(line, format!("`{word}` is not a finite number")),
            // A name may start like a number (`0test`); used as a number, it is an error then.
            Err(_) => Ok(Atom::Word(word.to_string())),
        };
    }
    if matches!(word.to_ascii_lowercase().as_str(), "nan" | "inf" | "infinity") {
        return err(line, format!("`{word}` is not a finite number"));
    }
    Ok(Atom::Word(word.to_string()))
}

/// A token as a value.
fn value(t: Tok<'_>, line: usize) -> Result<Atom, ParseError> {
    match t {
        Tok::Str(s) => Ok(Atom::Str(s.to_string())),
        Tok::Bare(w) => atom(w, line),
        other => err(line, format!("expected a value, found {}", describe(&other))),
    }
}

/// Numbers per element of an array type (Arnold's `AI_TYPE_*` names).
fn components(ty: &str) -> Option<usize> {
    Some(match ty {
        "BYTE" | "INT" | "UINT" | "BOOLEAN" | "FLOAT" | "STRING" | "NODE" | "POINTER" | "ENUM" | "CLOSURE" => 1,
        "VECTOR2" | "POINT2" => 2,
        "VECTOR" | "POINT" | "RGB" => 3,
        "RGBA" => 4,
        "MATRIX" => 16,
        _ => return None,
    })
}

/// Parses the text of a `.ass` file into its nodes.
pub fn parse(text: &str) -> Result<Vec<Node>, ParseError> {
    let mut p = Parser {
        lx: Lexer { text, at: 0, line: 1 },
        ahead: None,
        // Encoded arrays may repeat a value many times in a few bytes; all the arrays of a
        // file together may hold this many values, which a real file of its size never
        // reaches (its index lists do not compress that way).
        budget: text.len().saturating_mul(8).saturating_add(1 << 20),
    };
    let mut nodes = Vec::new();
    while let Some(node) = p.node()? {
        nodes.push(node);
    }
    Ok(nodes)
}

struct Parser<'a> {
    lx: Lexer<'a>,
    /// A token read ahead (the next parameter's name, found while reading a value).
    ahead: Option<Lexed<'a>>,
    /// Values arrays may still hold.
    budget: usize,
}

impl<'a> Parser<'a> {
    fn next(&mut self) -> Result<Option<Lexed<'a>>, ParseError> {
        match self.ahead.take() {
            Some(t) => Ok(Some(t)),
            None => self.lx.next(),
        }
    }

    /// The next node, `None` at the end of the text.
    fn node(&mut self) -> Result<Option<Node>, ParseError> {
        let Some((tok, line, _)) = self.next()? else { return Ok(None) };
        let kind = match tok {
            Tok::Bare(w) if atom(w, line).is_ok_and(|a| matches!(a, Atom::Word(_))) => w.to_string(),
            other => return err(line, format!("expected a node type, found {}", describe(&other))),
        };
        match self.next()? {
            Some((Tok::Open, _, _)) => {}
            _ => return err(line, format!("node type `{kind}` is not followed by `{{`")),
        }
        let mut node = Node { kind, name: String::new(), line, params: Vec::new() };
        // User data the node declares: its values are not parameters.
        let mut user: Vec<String> = Vec::new();
        loop {
            let (tok, pline, _) = match self.next()? {
                None => return err(self.lx.line, format!("node `{}` (line {line}) is not closed by `}}`", node.kind)),
                Some(t) => t,
            };
            let name = match tok {
                Tok::Close => break,
                Tok::Bare(w) if atom(w, pline).is_ok_and(|a| matches!(a, Atom::Word(_))) => w.to_string(),
                other => return err(pline, format!("expected a parameter name, found {}", describe(&other))),
            };
            let param = self.param(name, pline)?;
            match param.name.as_str() {
                "name" => match param.values.first().and_then(Atom::text) {
                    Some(n) if param.values.len() == 1 => node.name = n.to_string(),
                    _ => return err(pline, "`name` is not followed by one name"),
                },
                "declare" => {
                    if let Some(Atom::Word(w)) = param.values.first() {
                        user.push(w.clone());
                    }
                }
                n if user.iter().any(|u| u == n) => {}
                _ => node.params.push(param),
            }
        }
        Ok(Some(node))
    }

    /// The value of parameter `name` (on line `line`, its name just read).
    fn param(&mut self, name: String, line: usize) -> Result<Param, ParseError> {
        // The rest of the line: a plain value, or an array's header.
        let mut head: Vec<Lexed<'a>> = Vec::new();
        loop {
            match self.lx.next()? {
                Some((t @ (Tok::Str(_) | Tok::Bare(_)), l, false)) => head.push((t, l, false)),
                other => {
                    self.ahead = other;
                    break;
                }
            }
            if let Some(header) = array_header(&head) {
                let (count, keys, ty, encoding) =
                    header.map_err(|m| ParseError { line, message: format!("`{name}`: {m}") })?;
                return self.array(name, line, count, keys, &ty, encoding);
            }
        }
        let mut values = Vec::with_capacity(head.len());
        for (t, l, _) in head {
            values.push(value(t, l)?);
        }
        // Lines after it that start with a number continue it (a matrix's rows).
        while let Some((Tok::Bare(w), l, true)) = self.ahead {
            let Ok(first @ Atom::Num(_)) = atom(w, l) else { break };
            values.push(first);
            self.ahead = None;
            loop {
                match self.lx.next()? {
                    Some((t @ (Tok::Str(_) | Tok::Bare(_)), l, false)) => values.push(value(t, l)?),
                    other => {
                        self.ahead = other;
                        break;
                    }
                }
            }
        }
        Ok(Param { name, line, values, array: None })
    }

    /// An array of `count` × `keys` elements of `ty` after its header, as text values or
    /// in the `encoding` given (one token of `b85` data, or `b64` data on as many lines as
    /// its length takes).
    fn array(
        &mut self,
        name: String,
        line: usize,
        count: usize,
        keys: usize,
        ty: &str,
        encoding: Option<Encoding>,
    ) -> Result<Param, ParseError> {
        let per = components(ty).expect("checked by array_header");
        let too_long = || ParseError {
            line,
            message: format!("`{name}`: an array of {count} × {keys} {ty} holds more values than the file can"),
        };
        let total = count.checked_mul(keys).and_then(|n| n.checked_mul(per)).ok_or_else(too_long)?;
        if total > self.budget || encoding.is_none() && total > self.lx.left() / 2 + 1 {
            return Err(too_long());
        }
        self.budget -= total;
        let mut values = Vec::with_capacity(count * per);
        if let Some(encoding) = encoding {
            // Base64 has a known length (four characters to three bytes, the padding
            // optional), which Arnold may break over lines; base85 compresses runs, so its
            // data is the one token.
            let wanted = match encoding {
                Encoding::B85 => 1,
                Encoding::B64 => (encoded::bytes_of(ty, total) * 4).div_ceil(3),
            };
            let mut data = String::new();
            while data.len() < wanted {
                match self.lx.next()? {
                    Some((Tok::Bare(d), _, _)) => data.push_str(d),
                    Some((t, l, _)) => {
                        return err(l, format!("`{name}`: expected encoded {ty} data, found {}", describe(&t)))
                    }
                    None => return err(self.lx.line, format!("`{name}`: the file ends before its encoded data")),
                }
            }
            let numbers = encoded::decode(&data, encoding, ty, total)
                .map_err(|m| ParseError { line, message: format!("`{name}`: {m}") })?;
            values.extend(numbers.into_iter().take(count * per).map(Atom::Num));
        } else {
            let mut read = 0;
            while read < total {
                match self.next()? {
                    Some((t @ (Tok::Str(_) | Tok::Bare(_)), l, _)) => {
                        if read < count * per {
                            let a = value(t, l)?;
                            if !matches!(ty, "STRING" | "NODE" | "POINTER" | "ENUM")
                                && !matches!(a, Atom::Num(_))
                                && !is_flag(&a)
                            {
                                return err(l, format!("`{name}`: {a} in an array of {ty}"));
                            }
                            values.push(a);
                        }
                        read += 1;
                    }
                    Some((t, l, _)) => {
                        return err(l, format!("`{name}`: {read} of {total} values, then {}", describe(&t)))
                    }
                    None => {
                        return err(self.lx.line, format!("`{name}`: the file ends after {read} of {total} values"))
                    }
                }
            }
        }
        Ok(Param { name, line, values, array: Some(ty.to_string()) })
    }
}

fn is_flag(a: &Atom) -> bool {
    matches!(a, Atom::Word(w) if matches!(w.as_str(), "on" | "off" | "true" | "false"))
}

/// How an array's elements are written: as text, or encoded.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Encoding {
    /// `b85TYPE`: Arnold's base 85.
    B85,
    /// `b64TYPE`: base64 of the elements' bytes.
    B64,
}

/// An array header: its count, keys, element type and encoding.
type Header = (usize, usize, String, Option<Encoding>);

/// `count keys TYPE` (or `b85TYPE`, `b64TYPE`, encoded) at the start of a value: an array
/// header, or why it is a malformed one.
fn array_header(head: &[Lexed<'_>]) -> Option<Result<Header, String>> {
    let [(Tok::Bare(n), _, _), (Tok::Bare(k), _, _), (Tok::Bare(ty), _, _)] = head else { return None };
    let (encoding, ty) = match (ty.strip_prefix("b85"), ty.strip_prefix("b64")) {
        (Some(t), _) => (Some(Encoding::B85), t),
        (_, Some(t)) => (Some(Encoding::B64), t),
        _ => (None, *ty),
    };
    components(ty)?;
    if n.parse::<f64>().is_err() || k.parse::<f64>().is_err() {
        return None;
    }
    let whole = |s: &str| s.parse::<u64>().ok().and_then(|x| usize::try_from(x).ok());
    Some(match (whole(n), whole(k)) {
        (Some(n), Some(k)) => Ok((n, k.max(1), ty.to_string(), encoding)),
        _ => Err(format!("array counts `{n} {k}` are not whole numbers")),
    })
}

fn describe(t: &Tok<'_>) -> String {
    match t {
        Tok::Open => "`{`".into(),
        Tok::Close => "`}`".into(),
        Tok::Str(s) => format!("\"{s}\""),
        Tok::Bare(w) => format!("`{w}`"),
    }
}

/// Arnold's encodings of arrays in `.ass` files. Both give 32-bit words, from which every
/// type is read the same way: floats are the words' bits; bytes pack four to a word,
/// lowest first (memory order on the little-endian machines Arnold runs on).
///
/// - `b85`: each word in five characters of base 85 from `$` (0) to `x` (84), most
///   significant first; `z` is the word 0 and `y` the word of 1.0f, and `!` followed by a
///   word and a count is that word repeated count times; the last one to three bytes take
///   one character more than bytes. Integer arrays start with a letter telling their
///   packing: `B` 8 bits, `C` 16, `E` 32, `F` three 10-bit values to a word, lowest first.
/// - `b64`: the elements' bytes as they lie in memory (little-endian, an integer in 32
///   bits, a byte or boolean in one) in standard base64 (RFC 4648), the padding optional.
mod encoded {
    use super::Encoding;

    /// The bytes `total` values of `ty` take in memory (as `b64` writes them).
    pub(super) fn bytes_of(ty: &str, total: usize) -> usize {
        match ty {
            "BYTE" | "BOOLEAN" => total,
            _ => total.saturating_mul(4),
        }
    }

    /// The word of five base-85 digits.
    fn word(d: &[u8]) -> Result<u32, String> {
        let mut v: u64 = 0;
        for &c in d {
            if !(b'$'..=b'x').contains(&c) {
                return Err(format!("`{}` is not encoded data", c as char));
            }
            v = v * 85 + u64::from(c - b'$');
        }
        u32::try_from(v).map_err(|_| "encoded data holds a word past 32 bits".to_string())
    }

    /// The words of `b85` `data`, at most `max` of them.
    fn b85_words(data: &[u8], max: usize) -> Result<Vec<u32>, String> {
        let mut out = Vec::new();
        let mut i = 0;
        let full = |out: &Vec<u32>, n: usize| match out.len().checked_add(n) {
            Some(t) if t <= max => Ok(()),
            _ => Err(format!("encoded data holds more than the {max} words its array declares")),
        };
        while i < data.len() {
            match data[i] {
                b'z' | b'y' => {
                    full(&out, 1)?;
                    out.push(if data[i] == b'z' { 0 } else { 1.0f32.to_bits() });
                    i += 1;
                }
                b'!' => {
                    let (Some(w), Some(n)) = (data.get(i + 1..i + 6), data.get(i + 6..i + 11)) else {
                        return Err("encoded data ends inside a repeat".into());
                    };
                    let (w, n) = (word(w)?, word(n)? as usize);
                    full(&out, n)?;
                    out.extend(std::iter::repeat_n(w, n));
                    i += 11;
                }
                _ => {
                    full(&out, 1)?;
                    match data.get(i..i + 5) {
                        Some(d) => out.push(word(d)?),
                        None => {
                            // The last 1 to 3 bytes, in one more character than bytes (as
                            // Ascii85 ends): padded with the highest digit, the leading
                            // bytes of the word are the bytes, in memory order.
                            let d = &data[i..];
                            if d.len() < 2 {
                                return Err("encoded data ends inside a word".into());
                            }
                            let mut padded = [b'x'; 5];
                            padded[..d.len()].copy_from_slice(d);
                            let be = word(&padded).unwrap_or(u32::MAX).to_be_bytes();
                            let mut bytes = [0u8; 4];
                            bytes[..d.len() - 1].copy_from_slice(&be[..d.len() - 1]);
                            out.push(u32::from_le_bytes(bytes));
                        }
                    }
                    i += 5;
                }
            }
        }
        Ok(out)
    }

    /// The little-endian words of `b64` `data`, which must hold `bytes` bytes.
    fn b64_words(data: &str, bytes: usize) -> Result<Vec<u32>, String> {
        let raw = crate::io::decode_base64(data).map_err(|e| format!("encoded data is not base64: {e}"))?;
        if raw.len() != bytes {
            return Err(format!("encoded data holds {} bytes where the array declares {bytes}", raw.len()));
        }
        Ok(raw
            .chunks(4)
            .map(|c| {
                let mut w = [0u8; 4];
                w[..c.len()].copy_from_slice(c);
                u32::from_le_bytes(w)
            })
            .collect())
    }

    /// The `total` values of an array of `ty` in `data`, encoded by `encoding`.
    pub(super) fn decode(data: &str, encoding: Encoding, ty: &str, total: usize) -> Result<Vec<f64>, String> {
        let words_of = |data: &str, max: usize| match encoding {
            Encoding::B85 => b85_words(data.as_bytes(), max),
            Encoding::B64 => b64_words(data, bytes_of(ty, total)),
        };
        let out: Vec<f64> = match ty {
            "FLOAT" | "VECTOR" | "VECTOR2" | "POINT" | "POINT2" | "RGB" | "RGBA" | "MATRIX" => {
                let w = words_of(data, total)?;
                let mut out = Vec::with_capacity(w.len());
                for x in w {
                    let f = f32::from_bits(x);
                    if !f.is_finite() {
                        return Err(format!("encoded {ty} data holds {f}"));
                    }
                    out.push(f64::from(f));
                }
                out
            }
            "BYTE" | "BOOLEAN" => fields(&words_of(data, total.div_ceil(4))?, 8),
            "INT" | "UINT" => {
                // `b85` integers start with their packing; `b64` ones are 32-bit words.
                let (bits, words) = match encoding {
                    Encoding::B64 => (32, words_of(data, total)?),
                    Encoding::B85 => {
                        let Some((&packing, rest)) = data.as_bytes().split_first() else {
                            return Err("encoded data is empty".into());
                        };
                        let (bits, per_word) = match packing {
                            b'B' => (8, 4),
                            b'C' => (16, 2),
                            b'E' => (32, 1),
                            b'F' => (10, 3),
                            other => return Err(format!("integer packing `{}` is not one tress reads", other as char)),
                        };
                        (bits, b85_words(rest, total.div_ceil(per_word))?)
                    }
                };
                let mut v = fields(&words, bits);
                if ty == "INT" && bits == 32 {
                    v.iter_mut().for_each(|x| *x = f64::from(*x as u32 as i32));
                }
                v
            }
            other => return Err(format!("{other} arrays cannot be encoded")),
        };
        if out.len() < total {
            return Err(format!("encoded data holds {} values where the array declares {total}", out.len()));
        }
        Ok(out)
    }

    /// The `bits`-wide fields of each word, lowest first (as many as fit).
    fn fields(words: &[u32], bits: u32) -> Vec<f64> {
        let per = 32 / bits;
        let mask = if bits == 32 { u32::MAX } else { (1 << bits) - 1 };
        words.iter().flat_map(|&w| (0..per).map(move |k| f64::from((w >> (k * bits)) & mask))).collect()
    }
}
