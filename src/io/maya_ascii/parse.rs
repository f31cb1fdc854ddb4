//! Maya ASCII text into a node graph.
//!
//! A `.ma` file is a MEL script of a few commands (docs/maya-fur-hair.md section 6):
//! `createNode TYPE -n NAME -p PARENT;` makes a node and selects it, `setAttr ".attr"
//! values;` sets an attribute of the selected node (or of `node.attr`), `connectAttr
//! "a.out" "b.in";` connects two plugs, `select -ne NAME;` selects an existing node, and
//! `currentUnit -a radian -l meter;` sets the angle and linear units. Every other command
//! (`requires`, `fileInfo`, `relationship`, `rename -uid`, ...) is skipped.
//!
//! Statements end with `;`; words are separated by white space; strings are double quoted
//! with backslash escapes; `//` and `/* */` are comments. Values are kept per `setAttr` and
//! only interpreted when an attribute is used (the typed getters of `Graph`), so an
//! unusual value on an attribute tress never reads is no error, while a malformed value on
//! one it reads is, with its line.

use std::collections::HashMap;

/// One word of a statement: its text as written (without quotes), whether it was quoted,
/// and its line.
#[derive(Clone, Copy, Debug)]
struct Word<'a> {
    text: &'a str,
    quoted: bool,
    line: u32,
}

impl Word<'_> {
    /// The text with backslash escapes resolved (only quoted words have escapes).
    fn unescaped(&self) -> String {
        if !(self.quoted && self.text.contains('\\')) {
            return self.text.to_string();
        }
        let mut out = String::with_capacity(self.text.len());
        let mut chars = self.text.chars();
        while let Some(c) = chars.next() {
            match (c, c == '\\') {
                (_, true) => match chars.next() {
                    Some('n') => out.push('\n'),
                    Some('t') => out.push('\t'),
                    Some(o) => out.push(o),
                    None => {}
                },
                (c, false) => out.push(c),
            }
        }
        out
    }

    /// True for an unquoted `-flag` (a minus followed by a letter, unlike `-0.5`).
    fn is_flag(&self) -> bool {
        !self.quoted
            && self.text.len() > 1
            && self.text.starts_with('-')
            && self.text.as_bytes()[1].is_ascii_alphabetic()
    }
}

/// Splits the text into statements of words.
struct Lexer<'a> {
    src: &'a str,
    pos: usize,
    line: u32,
}

impl<'a> Lexer<'a> {
    fn new(src: &'a str) -> Lexer<'a> {
        Lexer { src, pos: 0, line: 1 }
    }

    /// The next statement's words, or `None` at the end of the text.
    fn statement(&mut self) -> Result<Option<Vec<Word<'a>>>, (u32, String)> {
        let bytes = self.src.as_bytes();
        let mut words: Vec<Word<'a>> = Vec::new();
        loop {
            // Skip white space and comments.
            while self.pos < bytes.len() {
                match bytes[self.pos] {
                    b'\n' => {
                        self.line += 1;
                        self.pos += 1;
                    }
                    c if c.is_ascii_whitespace() => self.pos += 1,
                    b'/' if bytes.get(self.pos + 1) == Some(&b'/') => {
                        while self.pos < bytes.len() && bytes[self.pos] != b'\n' {
                            self.pos += 1;
                        }
                    }
                    b'/' if bytes.get(self.pos + 1) == Some(&b'*') => {
                        let start = self.line;
                        self.pos += 2;
                        loop {
                            match bytes.get(self.pos) {
                                None => return Err((start, "unterminated /* comment".into())),
                                Some(b'*') if bytes.get(self.pos + 1) == Some(&b'/') => {
                                    self.pos += 2;
                                    break;
                                }
                                Some(c) => {
                                    self.line += u32::from(*c == b'\n');
                                    self.pos += 1;
                                }
                            }
                        }
                    }
                    _ => break,
                }
            }
            let Some(&c) = bytes.get(self.pos) else {
                return match words.is_empty() {
                    true => Ok(None),
                    false => Err((words[0].line, "the last statement has no closing `;`".into())),
                };
            };
            match c {
                b';' => {
                    self.pos += 1;
                    if !words.is_empty() {
                        return Ok(Some(words));
                    }
                }
                b'"' => {
                    let line = self.line;
                    let start = self.pos + 1;
                    let mut i = start;
                    loop {
                        match bytes.get(i) {
                            None => return Err((line, "unterminated string".into())),
                            Some(b'\\') => i += 2,
                            Some(b'"') => break,
                            Some(b'\n') => {
                                self.line += 1;
                                i += 1;
                            }
                            Some(_) => i += 1,
                        }
                    }
                    let end = i.min(bytes.len());
                    words.push(Word { text: self.text(start, end)?, quoted: true, line });
                    self.pos = end + 1;
                }
                _ => {
                    let start = self.pos;
                    while self.pos < bytes.len()
                        && !bytes[self.pos].is_ascii_whitespace()
                        && bytes[self.pos] != b';'
                        && bytes[self.pos] != b'"'
                    {
                        self.pos += 1;
                    }
                    words.push(Word { text: self.text(start, self.pos)?, quoted: false, line: self.line });
                }
            }
        }
    }

    fn text(&self, start: usize, end: usize) -> Result<&'a str, (u32, String)> {
        self.src.get(start..end).ok_or((self.line, "a word splits a UTF-8 character".into()))
    }
}

/// The value of one `setAttr`, kept as written until used.
#[derive(Clone, Debug, PartialEq)]
pub enum Value {
    /// Numbers (`yes`/`no`, `on`/`off`, `true`/`false` read as 1 and 0).
    Numbers(Vec<f64>),
    /// Strings (`-type "string"`, `"stringArray"` and `"componentList"`, the last two
    /// without their leading count; the quoted words of an XGen `"xgmSplineData"` block).
    Strings(Vec<String>),
    /// A `-type "nurbsCurve"` block: every word after the type, as numbers (`yes`/`no`
    /// included).
    Curve(Vec<f64>),
    /// A `-type "polyFaces"` block.
    Faces(Vec<Face>),
    /// Anything else: the type name, if any, and the line of the first word tress could not
    /// read as a number.
    Other(Option<String>, u32),
}

/// One face of a `polyFaces` block.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Face {
    /// Signed edge indices (`i` for edge `i`, `-i - 1` for it reversed) of the outer loop.
    pub edges: Vec<i64>,
    /// UV indices per corner of the outer loop, in UV set 0, when the face has them.
    pub uvs: Option<Vec<i64>>,
    /// The face has holes (`h` loops); only its outer loop is kept.
    pub holes: bool,
}

/// One `setAttr` of a node.
#[derive(Clone, Debug, PartialEq)]
pub struct Attr {
    /// Attribute path as written, without the leading `.` (`vt[0:3]`, `uvst[0].uvsp[0:3]`).
    pub name: String,
    /// Its value.
    pub value: Value,
    /// Line of the `setAttr`.
    pub line: u32,
}

/// A node made by `createNode` (or named by `select -ne`).
#[derive(Clone, Debug, PartialEq)]
pub struct Node {
    /// Node type (`mesh`, `transform`, `hairSystem`, ...); empty for a node only selected.
    pub kind: String,
    /// Its name.
    pub name: String,
    /// The parent named by `-p`, as written (a name or a `|`-separated DAG path).
    pub parent: Option<String>,
    /// Its attributes, in file order.
    pub attrs: Vec<Attr>,
    /// Line of its `createNode`.
    pub line: u32,
}

/// One `connectAttr` between plugs.
#[derive(Clone, Debug, PartialEq)]
pub struct Connection {
    /// Source node.
    pub src: usize,
    /// Source attribute (`oha`, `worldMatrix[0]`, ...).
    pub src_attr: String,
    /// Destination node.
    pub dst: usize,
    /// Destination attribute.
    pub dst_attr: String,
}

/// Every node and connection of a file.
#[derive(Clone, Debug, Default)]
pub struct Graph {
    /// Nodes in file order.
    pub nodes: Vec<Node>,
    /// Connections in file order.
    pub connections: Vec<Connection>,
    /// Factor from the file's angle unit to radians (`currentUnit -a`).
    pub angle_to_radians: f64,
    /// Centimetres (Maya's internal unit) in one of the file's linear units
    /// (`currentUnit -l`): the file's values are in that unit.
    pub centimeters_per_unit: f64,
    /// Frames in a second of the file's time unit (`currentUnit -t`: `film` 24, `pal` 25,
    /// `ntsc` 30, ...): animation curves' key times count in that unit.
    pub frames_per_second: f64,
    by_name: HashMap<String, Vec<usize>>,
    /// Indices into `connections` by destination node and by source node, in file order,
    /// so that a node's connections cost their number, not the file's (`inputs_of`).
    by_dst: Vec<Vec<u32>>,
    by_src: Vec<Vec<u32>>,
    /// Files referenced with `file -r`, in file order.
    pub references: Vec<String>,
    /// The data type (`-type`) last given to each node's array attribute, by node and the
    /// attribute's name without its element range (`fc` for `.fc[0:499]`): Maya writes
    /// the type on the first chunk of a long array only, and the chunks after it (`setAttr
    /// ".fc[500:999]"` with no `-type`) hold data of the same type.
    array_types: HashMap<(usize, String), String>,
}

/// Most words one statement may hold (a 50-million-vertex mesh chunk is far beyond what
/// Maya writes: it splits arrays into chunks of a few thousand values).
const MAX_WORDS: usize = 50_000_000;

/// Reads the whole text; an error carries its line.
pub fn parse(text: &str) -> Result<Graph, (u32, String)> {
    let mut g = Graph {
        angle_to_radians: std::f64::consts::PI / 180.0,
        centimeters_per_unit: 1.0,
        frames_per_second: 24.0,
        ..Graph::default()
    };
    let mut lexer = Lexer::new(text);
    let mut current: Option<usize> = None;
    while let Some(words) = lexer.statement()? {
        if words.len() > MAX_WORDS {
            return Err((words[0].line, format!("a statement of more than {MAX_WORDS} words")));
        }
        let line = words[0].line;
        match words[0].text {
            "createNode" => current = Some(g.create_node(&words)?),
            "setAttr" => g.set_attr(&words, current)?,
            "connectAttr" => g.connect(&words)?,
            // `file -r ... "path";` references another scene; the file names it last.
            "file" if words.iter().any(|w| !w.quoted && matches!(w.text, "-r" | "-reference")) => {
                if let Some(path) = words[1..].iter().rev().find(|w| w.quoted) {
                    g.references.push(path.unescaped());
                }
            }
            "select" => {
                // `select -ne NAME` picks an existing (often a default) node for the setAttrs
                // that follow.
                if let Some(name) = words[1..].iter().find(|w| !w.is_flag()) {
                    current = Some(g.node_or_placeholder(&name.unescaped(), line));
                }
            }
            "currentUnit" => {
                if let Some(i) = words.iter().position(|w| w.text == "-a" || w.text == "-angle") {
                    match words.get(i + 1).map(|w| w.text) {
                        Some("degree" | "deg") => g.angle_to_radians = std::f64::consts::PI / 180.0,
                        Some("radian" | "rad") => g.angle_to_radians = 1.0,
                        Some(u) => return Err((line, format!("unknown angle unit `{u}`"))),
                        None => return Err((line, "`currentUnit -a` without a unit".into())),
                    }
                }
                if let Some(i) = words.iter().position(|w| w.text == "-l" || w.text == "-linear") {
                    g.centimeters_per_unit = match words.get(i + 1).map(|w| w.text) {
                        Some("millimeter" | "mm") => 0.1,
                        Some("centimeter" | "cm") => 1.0,
                        Some("meter" | "m") => 100.0,
                        Some("kilometer" | "km") => 1e5,
                        Some("inch" | "in") => 2.54,
                        Some("foot" | "ft") => 30.48,
                        Some("yard" | "yd") => 91.44,
                        Some(u) => return Err((line, format!("unknown linear unit `{u}`"))),
                        None => return Err((line, "`currentUnit -l` without a unit".into())),
                    };
                }
                if let Some(i) = words.iter().position(|w| w.text == "-t" || w.text == "-time") {
                    let unit = words
                        .get(i + 1)
                        .map(|w| w.text)
                        .ok_or((line, "`currentUnit -t` without a unit".to_string()))?;
                    g.frames_per_second = time_unit(unit).ok_or((line, format!("unknown time unit `{unit}`")))?;
                }
            }
            _ => {}
        }
    }
    g.index_connections();
    Ok(g)
}

/// Frames a second of a Maya time unit (the `currentUnit -t` names, `Nfps` included).
fn time_unit(unit: &str) -> Option<f64> {
    Some(match unit {
        "hour" => 1.0 / 3600.0,
        "min" => 1.0 / 60.0,
        "sec" => 1.0,
        "millisec" => 1000.0,
        "game" => 15.0,
        "film" => 24.0,
        "pal" => 25.0,
        "ntsc" => 30.0,
        "show" => 48.0,
        "palf" => 50.0,
        "ntscf" => 60.0,
        // `23.976fps`, `29.97df` (drop frame: the same rate), ...
        u => u
            .strip_suffix("fps")
            .or_else(|| u.strip_suffix("df"))?
            .parse::<f64>()
            .ok()
            .filter(|f| f.is_finite() && *f > 0.0)?,
    })
}

/// The node part of a name or plug: the last component of a DAG path, without a leading
/// `:` (Maya's root namespace).
fn short_name(path: &str) -> &str {
    let last = path.rsplit('|').next().unwrap_or(path);
    last.strip_prefix(':').unwrap_or(last)
}

impl Graph {
    /// The node a name or DAG path refers to. Among nodes of the same name, a DAG path
    /// picks the one whose parents match it; otherwise the last one created.
    pub fn find(&self, path: &str) -> Option<usize> {
        let candidates = self.by_name.get(short_name(path))?;
        if candidates.len() == 1 || !path.contains('|') {
            return candidates.last().copied();
        }
        let parts: Vec<&str> = path.split('|').filter(|p| !p.is_empty()).collect();
        candidates
            .iter()
            .copied()
            .find(|&c| {
                let mut node = c;
                for part in parts.iter().rev().skip(1) {
                    match self.nodes[node].parent.as_deref().and_then(|p| self.find_simple(p)) {
                        Some(p) if self.nodes[p].name == short_name(part) => node = p,
                        _ => return false,
                    }
                }
                true
            })
            .or(candidates.last().copied())
    }

    /// Parent lookup without path matching (parents are found by name; a cycle of names
    /// cannot make this recurse).
    fn find_simple(&self, path: &str) -> Option<usize> {
        self.by_name.get(short_name(path)).and_then(|c| c.last().copied())
    }

    fn index_connections(&mut self) {
        self.by_dst = vec![Vec::new(); self.nodes.len()];
        self.by_src = vec![Vec::new(); self.nodes.len()];
        for (i, c) in self.connections.iter().enumerate() {
            self.by_dst[c.dst].push(i as u32);
            self.by_src[c.src].push(i as u32);
        }
    }

    /// The connections into `node`, in file order.
    pub fn inputs_of(&self, node: usize) -> impl Iterator<Item = &Connection> + '_ {
        self.by_dst.get(node).into_iter().flatten().map(|&i| &self.connections[i as usize])
    }

    /// The connections out of `node`, in file order.
    pub fn outputs_of(&self, node: usize) -> impl Iterator<Item = &Connection> + '_ {
        self.by_src.get(node).into_iter().flatten().map(|&i| &self.connections[i as usize])
    }

    /// The connections into and out of `node`, in file order (a connection of the node to
    /// itself once).
    pub fn connections_of(&self, node: usize) -> impl Iterator<Item = &Connection> + '_ {
        let (dst, src) = (
            self.by_dst.get(node).map_or(&[][..], Vec::as_slice),
            self.by_src.get(node).map_or(&[][..], Vec::as_slice),
        );
        let (mut i, mut j) = (0, 0);
        std::iter::from_fn(move || {
            let next = match (dst.get(i), src.get(j)) {
                (Some(&a), Some(&b)) if a == b => {
                    (i, j) = (i + 1, j + 1);
                    a
                }
                (Some(&a), Some(&b)) if a < b => {
                    i += 1;
                    a
                }
                (_, Some(&b)) => {
                    j += 1;
                    b
                }
                (Some(&a), None) => {
                    i += 1;
                    a
                }
                (None, None) => return None,
            };
            Some(&self.connections[next as usize])
        })
    }

    /// The node's parent, if it has one the file created.
    pub fn parent(&self, node: usize) -> Option<usize> {
        let p = self.nodes[node].parent.as_deref()?;
        self.find(p).filter(|&p| p != node)
    }

    fn node_or_placeholder(&mut self, name: &str, line: u32) -> usize {
        match self.find(name) {
            Some(i) => i,
            None => {
                self.add(Node { kind: String::new(), name: short_name(name).into(), parent: None, attrs: vec![], line })
            }
        }
    }

    fn add(&mut self, node: Node) -> usize {
        let i = self.nodes.len();
        self.by_name.entry(node.name.clone()).or_default().push(i);
        self.nodes.push(node);
        i
    }

    fn create_node(&mut self, words: &[Word]) -> Result<usize, (u32, String)> {
        let line = words[0].line;
        let (mut kind, mut name, mut parent) = (None, None, None);
        let mut i = 1;
        while i < words.len() {
            let w = &words[i];
            match w.text {
                "-n" | "-name" | "-p" | "-parent" if !w.quoted => {
                    let v = words.get(i + 1).ok_or((w.line, format!("`createNode {}` needs a value", w.text)))?;
                    match w.text {
                        "-n" | "-name" => name = Some(v.unescaped()),
                        _ => parent = Some(v.unescaped()),
                    }
                    i += 2;
                }
                _ if w.is_flag() => i += 1,
                _ if kind.is_none() => {
                    kind = Some(w.unescaped());
                    i += 1;
                }
                _ => return Err((w.line, format!("unexpected `{}` in createNode", w.text))),
            }
        }
        let kind = kind.ok_or((line, "createNode without a node type".to_string()))?;
        let name = name.unwrap_or_else(|| format!("{kind}{}", self.nodes.len() + 1));
        Ok(self.add(Node { kind, name: short_name(&name).into(), parent, attrs: Vec::new(), line }))
    }

    fn set_attr(&mut self, words: &[Word], current: Option<usize>) -> Result<(), (u32, String)> {
        let line = words[0].line;
        let mut type_name = None;
        let mut plug = None;
        let mut values = Vec::new();
        let mut i = 1;
        while i < words.len() {
            let w = words[i];
            if w.is_flag() {
                // Flags with one argument; the others (-av, -c, ...) stand alone.
                let takes = matches!(
                    w.text,
                    "-k" | "-keyable"
                        | "-l"
                        | "-lock"
                        | "-s"
                        | "-size"
                        | "-ch"
                        | "-capacityHint"
                        | "-cb"
                        | "-channelBox"
                        | "-type"
                        | "-typ"
                        | "-caching"
                        | "-ca"
                );
                if matches!(w.text, "-type" | "-typ") {
                    type_name = words.get(i + 1).map(|t| t.unescaped());
                }
                i += if takes { 2 } else { 1 };
                continue;
            }
            if plug.is_none() {
                plug = Some(w.unescaped());
            } else {
                values.push(w);
            }
            i += 1;
        }
        let plug = plug.ok_or((line, "setAttr without an attribute".to_string()))?;
        let (node, name) = match plug.strip_prefix('.') {
            Some(attr) => {
                (current.ok_or((line, format!("setAttr \"{plug}\" before any createNode")))?, attr.to_string())
            }
            None => {
                let (n, a) =
                    plug.split_once('.').ok_or((line, format!("setAttr \"{plug}\": expected node.attribute")))?;
                (self.node_or_placeholder(n, line), a.to_string())
            }
        };
        if values.is_empty() && type_name.is_none() {
            // Flags only (`setAttr -k off ".v";`): no value to keep.
            return Ok(());
        }
        if let Some((array, _)) = name.strip_suffix(']').and_then(|n| n.rsplit_once('[')) {
            let key = (node, array.to_string());
            match &type_name {
                Some(t) => {
                    self.array_types.insert(key, t.clone());
                }
                None => type_name = self.array_types.get(&key).cloned(),
            }
        }
        let value = read_value(type_name.as_deref(), &values, line)?;
        self.nodes[node].attrs.push(Attr { name, value, line });
        Ok(())
    }

    fn connect(&mut self, words: &[Word]) -> Result<(), (u32, String)> {
        let line = words[0].line;
        let plugs: Vec<String> = words[1..].iter().filter(|w| !w.is_flag()).map(|w| w.unescaped()).collect();
        let [src, dst] = match plugs.as_slice() {
            [a, b, ..] => [a, b],
            _ => return Err((line, "connectAttr needs a source and a destination".into())),
        };
        let split = |p: &str| -> Result<(String, String), (u32, String)> {
            let (n, a) = p.split_once('.').ok_or((line, format!("connectAttr \"{p}\": expected node.attribute")))?;
            Ok((n.to_string(), a.to_string()))
        };
        let ((sn, sa), (dn, da)) = (split(src)?, split(dst)?);
        let src = self.node_or_placeholder(&sn, line);
        let dst = self.node_or_placeholder(&dn, line);
        self.connections.push(Connection { src, src_attr: sa, dst, dst_attr: da });
        Ok(())
    }
}

/// A number as Maya writes it, booleans included.
fn number(text: &str) -> Option<f64> {
    match text {
        "yes" | "on" | "true" => Some(1.0),
        "no" | "off" | "false" => Some(0.0),
        _ => text.parse::<f64>().ok().filter(|v| v.is_finite()),
    }
}

fn read_value(type_name: Option<&str>, words: &[Word], line: u32) -> Result<Value, (u32, String)> {
    let numbers = |words: &[Word]| -> Result<Vec<f64>, u32> {
        words.iter().map(|w| if w.quoted { None } else { number(w.text) }.ok_or(w.line)).collect()
    };
    Ok(match type_name {
        Some("string" | "stringArray" | "componentList" | "xgmSplineData") => {
            let counted = matches!(type_name, Some("stringArray" | "componentList"));
            let start = usize::from(counted && words.first().is_some_and(|w| !w.quoted));
            Value::Strings(words[start..].iter().map(|w| w.unescaped()).collect())
        }
        Some("nurbsCurve") => {
            Value::Curve(numbers(words).map_err(|l| (l, "nurbsCurve data must be numbers".to_string()))?)
        }
        Some("polyFaces") => Value::Faces(faces(words)?),
        _ => match numbers(words) {
            Ok(v) => Value::Numbers(v),
            Err(bad) => Value::Other(type_name.map(str::to_string), bad.max(line)),
        },
    })
}

/// Reads a `polyFaces` block: `f N e…` starts a face, `h N e…` adds a hole, `mu SET N uv…`
/// gives the UVs of the last loop; `fc` and `mc` (colours) are skipped.
fn faces(words: &[Word]) -> Result<Vec<Face>, (u32, String)> {
    let mut out: Vec<Face> = Vec::new();
    let mut i = 0;
    let int = |i: usize| -> Result<i64, (u32, String)> {
        let w = words.get(i).ok_or((words.last().map_or(0, |w| w.line), "polyFaces block ends early".to_string()))?;
        w.text.parse::<i64>().map_err(|_| (w.line, format!("polyFaces: `{}` is not an integer", w.text)))
    };
    let count = |i: usize| -> Result<usize, (u32, String)> {
        let n = int(i)?;
        if n < 0 || n as usize > words.len() {
            return Err((words[i].line, format!("polyFaces: count {n} does not fit the block")));
        }
        Ok(n as usize)
    };
    // The last loop read: 0 = none, 1 = outer (`f`), 2 = hole (`h`).
    let mut last = 0;
    while i < words.len() {
        let w = words[i];
        match w.text {
            "f" | "h" => {
                let n = count(i + 1)?;
                if w.text == "f" && n < 3 {
                    return Err((w.line, format!("polyFaces: a face of {n} edges (a face has at least 3)")));
                }
                let edges = (0..n).map(|k| int(i + 2 + k)).collect::<Result<Vec<_>, _>>()?;
                if w.text == "f" {
                    out.push(Face { edges, uvs: None, holes: false });
                    last = 1;
                } else {
                    out.last_mut().ok_or((w.line, "polyFaces: a hole before any face".to_string()))?.holes = true;
                    last = 2;
                }
                i += 2 + n;
            }
            "mu" => {
                let set = int(i + 1)?;
                let n = count(i + 2)?;
                let uvs = (0..n).map(|k| int(i + 3 + k)).collect::<Result<Vec<_>, _>>()?;
                if let (0, 1, Some(face)) = (set, last, out.last_mut()) {
                    face.uvs = Some(uvs);
                }
                i += 3 + n;
            }
            "mc" => i += 3 + count(i + 2)?,
            "fc" => i += 2 + count(i + 1)?,
            _ => return Err((w.line, format!("polyFaces: unexpected `{}`", w.text))),
        }
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn statements_words_strings_and_comments() {
        let g = parse(
            "//Maya ASCII 2020 scene\nrequires maya \"2020\";\n/* a\nblock */ createNode transform -n \"a|b\\\"c\";\n\
             \tsetAttr \".t\" -type \"double3\" 1 -2.5 3e1 ;\ncreateNode mesh -n \"m\" -p \"b\\\"c\";\n\
             setAttr -k off \".v\" no;\nconnectAttr \"m.o\" \"other.i\" -na;\n",
        )
        .unwrap();
        assert_eq!(g.nodes.len(), 3);
        assert_eq!(g.nodes[0].name, "b\"c");
        assert_eq!(g.nodes[0].attrs[0].value, Value::Numbers(vec![1.0, -2.5, 30.0]));
        assert_eq!(g.nodes[0].line, 4);
        assert_eq!(g.nodes[1].attrs[0], Attr { name: "v".into(), value: Value::Numbers(vec![0.0]), line: 7 });
        assert_eq!(g.parent(1), Some(0));
        assert_eq!(g.connections[0].src, 1);
        assert_eq!(g.nodes[2].name, "other");
    }

    #[test]
    fn faces_read_edges_uvs_and_holes() {
        let g = parse(
            "createNode mesh -n m;\nsetAttr -s 2 \".fc[0:1]\" -type \"polyFaces\" f 3 0 1 -3 mu 0 3 0 1 2 \
             f 4 0 1 2 3 h 3 4 5 6 mu 0 3 1 2 3 mc 0 3 0 1 2;\n",
        )
        .unwrap();
        let Value::Faces(f) = &g.nodes[0].attrs[0].value else { panic!() };
        assert_eq!(f[0], Face { edges: vec![0, 1, -3], uvs: Some(vec![0, 1, 2]), holes: false });
        assert_eq!((f[1].edges.len(), f[1].uvs.clone(), f[1].holes), (4, None, true));
    }

    #[test]
    fn errors_carry_lines() {
        assert_eq!(parse("createNode mesh;\nsetAttr \".a\" 1").unwrap_err().0, 2);
        assert_eq!(parse("\n\ncreateNode \"mesh;\n").unwrap_err().0, 3);
        assert_eq!(parse("setAttr \".a\" 1;").unwrap_err().0, 1);
        assert_eq!(parse("createNode;\n").unwrap_err().0, 1);
        assert_eq!(parse("createNode m -n;\n").unwrap_err().0, 1);
        assert_eq!(parse("createNode mesh;\n\nsetAttr \".fc[0]\" -type \"polyFaces\" f 9 1;\n").unwrap_err().0, 3);
        assert_eq!(parse("currentUnit -a grad;").unwrap_err().0, 1);
        // An odd value on some attribute is kept, with its line, not an error.
        let g = parse("createNode x;\nsetAttr \".a\" -type \"double4\" 1 \"vtx[0]\";").unwrap();
        assert_eq!(g.nodes[0].attrs[0].value, Value::Other(Some("double4".into()), 2));
        // A component list is its components, without the count Maya writes first.
        let g = parse("createNode x;\nsetAttr \".dc\" -type \"componentList\" 2 \"f[0:1]\" \"f[4]\";").unwrap();
        assert_eq!(g.nodes[0].attrs[0].value, Value::Strings(vec!["f[0:1]".into(), "f[4]".into()]));
    }
}
