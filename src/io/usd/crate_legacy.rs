//! Binary crate layers of older versions, rewritten into forms the `openusd` crate reads:
//! the structural sections of versions 0.0.1 to 0.3.0 ([`upgrade`]) and the sample times
//! of versions before 0.7.0 ([`array_sample_times`]).
//!
//! USD's binary format compressed its structural sections in version 0.4.0; files written
//! before then (Pixar's Kitchen Set, most of the binary layers in USD's and Arnold-USD's
//! test suites) store them as plain arrays, which the crate does not read (it stops at an
//! unimplemented branch). Nothing else the crate reads changed between 0.0.1 and 0.4.0:
//! values keep the layout of their version (arrays with a rank and 32-bit sizes, integers
//! and floats uncompressed), which the crate reads for any version before 0.5.0. So
//! [`upgrade`] leaves every byte where it is, appends the six structural sections in the
//! 0.4.0 encoding and a table of contents pointing at them, and marks the file 0.4.0.
//!
//! The layouts are those of USD's `crateFile.cpp` (Pixar) and the USD Core Specification
//! §16.3:
//! - `TOKENS`: a count, a byte size, that many bytes of NUL-terminated strings; from
//!   0.4.0 the bytes LZ4-compressed (`TfFastCompression`: a chunk-count byte, 0 for one
//!   chunk, then an LZ4 block), after their uncompressed and compressed sizes.
//! - `STRINGS`: a count, then 32-bit token indices, in every version.
//! - `FIELDS`: a count, then 16-byte fields (4 bytes of padding, a token index, a value
//!   representation); from 0.4.0 the token indices as compressed integers, then the
//!   representations as one compressed block.
//! - `FIELDSETS`: a count, then 32-bit field indices; from 0.4.0 compressed integers.
//! - `PATHS`: a count, then the path tree depth first: per path a header (path index,
//!   element token index, bits has-child 1, has-sibling 2, is-property 4), 16 bytes with 4
//!   of leading padding in 0.0.1 and 12 bytes from 0.1.0; a path with both a child and a
//!   sibling is followed by the sibling's file offset, its child by its header. From
//!   0.4.0: the number of entries, then three compressed integer arrays in depth-first
//!   order: path indices, element token indices (negative for properties) and jumps (−2
//!   a leaf with no sibling, −1 a child only, 0 a sibling only, next; n > 0 a child next
//!   and a sibling n entries on).
//! - `SPECS`: a count, then per spec a path index, field set index and spec type, with 4
//!   bytes of leading padding in 0.0.1 (16 bytes; 12 from 0.1.0); from 0.4.0 three
//!   compressed integer arrays.
//!
//! Sample times: a time-sampled value starts with the representation of its times, a
//! vector of doubles (a count, 64-bit in every version, then the doubles). The crate reads
//! that vector as an array, whose count before 0.7.0 is 32 bits after a 32-bit rank
//! (before 0.5.0), so it finds no times and refuses the samples ("Invalid time samples
//! count"). [`array_sample_times`] appends each such vector as the double array the crate
//! also accepts for times and points the representation at it.
//!
//! Compressed integers (`integerCoding.cpp`) are a common value, two bits per integer
//! (0 the common value, 1, 2, 3 an 8-, 16- or 32-bit delta from the previous integer),
//! then the deltas; the whole LZ4-compressed as above. Here every delta is written in 32
//! bits with a common value of 0, which the reader decodes the same and LZ4 shrinks.

use super::crate_file::Bytes;

/// The first version with compressed structural sections.
pub const COMPRESSED_SECTIONS: [u8; 3] = [0, 4, 0];
/// The most one LZ4 chunk holds (`LZ4_MAX_INPUT_SIZE`); larger sections would need the
/// chunked form, which the crate does not read.
const MAX_CHUNK: usize = 0x7E00_0000;

/// `bytes` as the crate can read them: a crate file of a version before 0.4.0 rewritten
/// (see the module documentation), any other returned as it is. The error says what in
/// the old sections is impossible.
pub fn upgrade(bytes: Vec<u8>) -> Result<Vec<u8>, String> {
    let version = match bytes.get(8..11) {
        Some(v) => [v[0], v[1], v[2]],
        None => return Ok(bytes),
    };
    if version >= COMPRESSED_SECTIONS || version[0] != 0 {
        return Ok(bytes);
    }
    let damaged =
        |what: String| format!("damaged binary USD layer of crate version 0.{}.{}: {what}", version[1], version[2]);
    let sections = Legacy::read(&Bytes(&bytes), version == [0, 0, 1]).map_err(damaged)?;
    Ok(sections.append_to(bytes))
}

/// `bytes`, a checked crate file (see [`super::crate_file::check`]) of a version before
/// 0.7.0, with the times of its time-sampled values turned from vectors into arrays (see
/// the module documentation); a later version is returned as it is.
pub fn array_sample_times(mut bytes: Vec<u8>) -> Result<Vec<u8>, String> {
    const TIME_SAMPLES: u64 = 46;
    const DOUBLE: u64 = 9;
    const DOUBLE_VECTOR: u64 = 48;
    const ARRAY: u64 = 1 << 63;
    const INLINED: u64 = 1 << 62;
    let version = [bytes[8], bytes[9], bytes[10]];
    if version >= [0, 7, 0] {
        return Ok(bytes);
    }
    let file = super::crate_file::without_panicking(|| openusd::usdc::CrateFile::open(std::io::Cursor::new(&bytes)))
        .map_err(|m| format!("damaged binary USD layer: {m}"))?
        .map_err(|e| format!("damaged binary USD layer: {e:#}"))?;
    let kind = |rep: u64| (rep >> 48) & 0xff;
    let payload = |rep: u64| rep & ((1 << 48) - 1);
    // Each vector of times appended once, however many samples share it.
    let mut arrays: std::collections::HashMap<u64, u64> = Default::default();
    for field in &file.fields {
        let rep = field.value_rep.0;
        if kind(rep) != TIME_SAMPLES || rep & INLINED != 0 {
            continue;
        }
        let b = Bytes(&bytes);
        let at = payload(rep);
        let times_at = at.checked_add_signed(b.u64_at(at)? as i64).ok_or("a time sample offset out of range")?;
        let times = b.u64_at(times_at)?;
        if kind(times) != DOUBLE_VECTOR || times & (INLINED | ARRAY) != 0 {
            continue;
        }
        let vector = payload(times);
        let array = match arrays.get(&vector) {
            Some(&array) => array,
            None => {
                let count = b.u64_at(vector)?;
                let doubles = vector
                    .checked_add(8)
                    .zip(count.checked_mul(8))
                    .and_then(|(from, size)| Some(from..from.checked_add(size)?))
                    .and_then(|r| b.0.get(r.start as usize..r.end as usize))
                    .ok_or_else(|| format!("sample times at byte {vector} claim {count} times"))?
                    .to_vec();
                let count =
                    u32::try_from(count).map_err(|_| format!("sample times at byte {vector} claim {count} times"))?;
                bytes.resize(bytes.len().next_multiple_of(8), 0);
                let array = bytes.len() as u64;
                if version < [0, 5, 0] {
                    bytes.extend_from_slice(&1u32.to_le_bytes());
                }
                bytes.extend_from_slice(&count.to_le_bytes());
                bytes.extend_from_slice(&doubles);
                arrays.insert(vector, array);
                array
            }
        };
        let rep = ARRAY | DOUBLE << 48 | array;
        bytes[times_at as usize..times_at as usize + 8].copy_from_slice(&rep.to_le_bytes());
    }
    Ok(bytes)
}

/// The structural sections of an old crate file, decoded.
struct Legacy {
    /// The `TOKENS` section's strings, NUL-terminated, one after the other.
    token_bytes: Vec<u8>,
    token_count: u64,
    /// The negated index of the copy of token 0 that properties named by token 0 use.
    zero_copy: Option<u32>,
    /// Sections kept where they are (`STRINGS` and any the format does not know), with
    /// their start and size.
    kept: Vec<([u8; 16], u64, u64)>,
    field_tokens: Vec<u32>,
    field_reps: Vec<u64>,
    fieldsets: Vec<u32>,
    path_count: u64,
    /// The path tree in depth-first order: path index, element token (negative for a
    /// property) and jump, as 0.4.0 stores them.
    paths: [Vec<u32>; 3],
    specs: [Vec<u32>; 3],
}

impl Legacy {
    fn read(b: &Bytes, padded: bool) -> Result<Legacy, String> {
        let toc = b.u64_at(16)?;
        let count = b.u64_at(toc)?;
        if count == 0 || count >= 64 {
            return Err(format!("its table of contents claims {count} sections"));
        }
        let mut legacy = Legacy {
            token_bytes: Vec::new(),
            token_count: 0,
            zero_copy: None,
            kept: Vec::new(),
            field_tokens: Vec::new(),
            field_reps: Vec::new(),
            fieldsets: Vec::new(),
            path_count: 0,
            paths: Default::default(),
            specs: Default::default(),
        };
        // The sections come in any order, and paths need the tokens: read them first.
        let mut sections = Vec::new();
        for i in 0..count {
            let at = toc + 8 + 32 * i;
            let mut name = [0u8; 16];
            for (k, c) in name.iter_mut().enumerate() {
                *c = b.byte_at(at + k as u64)?;
            }
            let (start, size) = (b.u64_at(at + 16)?, b.u64_at(at + 24)?);
            if start.checked_add(size).is_none_or(|end| end > b.len()) {
                return Err(format!("section {} runs past the end of the file", name_of(&name)));
            }
            sections.push((name, start, size));
        }
        sections.sort_by_key(|(name, _, _)| name_of(name) != "TOKENS");
        for (name, start, size) in sections {
            let mut s = Cursor { b, name: name_of(&name), at: start, end: start + size };
            match s.name.as_str() {
                "TOKENS" => legacy.read_tokens(&mut s)?,
                "FIELDS" => {
                    for _ in 0..s.count(16)? {
                        s.u32()?;
                        legacy.field_tokens.push(s.u32()?);
                        legacy.field_reps.push(s.u64()?);
                    }
                }
                "FIELDSETS" => legacy.fieldsets = s.u32s()?,
                "PATHS" => legacy.read_paths(&mut s, padded)?,
                "SPECS" => {
                    for _ in 0..s.count(if padded { 16 } else { 12 })? {
                        if padded {
                            s.u32()?;
                        }
                        for list in &mut legacy.specs {
                            list.push(s.u32()?);
                        }
                    }
                }
                _ => legacy.kept.push((name, start, size)),
            }
        }
        Ok(legacy)
    }

    fn read_tokens(&mut self, s: &mut Cursor) -> Result<(), String> {
        self.token_count = s.u64()?;
        let size = s.u64()?;
        let bytes = s.take(size)?;
        let strings = bytes.iter().filter(|&&c| c == 0).count() as u64;
        if strings != self.token_count || bytes.last().is_some_and(|&c| c != 0) {
            return Err(format!("section TOKENS claims {} tokens and holds {strings}", self.token_count));
        }
        self.token_bytes = bytes.to_vec();
        Ok(())
    }

    /// Walks the path tree from its first header, in the order 0.4.0 stores it: a path,
    /// its descendants, then its next sibling. Siblings that must wait for a subtree wait
    /// on a stack, each remembering the entry whose jump leads to it. At most as many
    /// headers as paths are read, so offsets that lead back cannot loop.
    fn read_paths(&mut self, s: &mut Cursor, padded: bool) -> Result<(), String> {
        const HAS_CHILD: u8 = 1;
        const HAS_SIBLING: u8 = 2;
        const IS_PROPERTY: u8 = 4;
        self.path_count = s.u64()?;
        let header = if padded { 16 } else { 12 };
        s.at_most(self.path_count, (s.end - s.at) / header, "paths")?;
        let (mut indices, mut tokens, mut jumps) = (Vec::new(), Vec::new(), Vec::<u32>::new());
        let mut waiting: Vec<(u64, usize)> = Vec::new();
        let mut at = s.at;
        loop {
            if indices.len() as u64 >= self.path_count {
                return Err(format!("its path tree holds more than the {} paths it claims", self.path_count));
            }
            let mut h = Cursor { b: s.b, name: s.name.clone(), at, end: s.end };
            if padded {
                h.u32()?;
            }
            let (index, token, bits) = (h.u32()?, h.u32()?, h.u32()? as u8);
            if u64::from(index) >= self.path_count || u64::from(token) >= self.token_count.max(1) {
                return Err(format!("a path header at byte {at} names path {index} and token {token}"));
            }
            let (child, sibling) = (bits & HAS_CHILD != 0, bits & HAS_SIBLING != 0);
            let this = indices.len();
            indices.push(index);
            // A property of token 0 cannot be negative: it is given a copy of that token
            // (appended, so no other index moves), as USD's writers avoid by keeping
            // token 0 for a sentinel.
            tokens.push(match (bits & IS_PROPERTY != 0, token) {
                (false, t) => t as i32 as u32,
                (true, 0) => self.token_zero_copy(),
                (true, t) => (t as i32).wrapping_neg() as u32,
            });
            jumps.push(match (child, sibling) {
                (false, false) => -2i32 as u32,
                (true, false) => -1i32 as u32,
                (false, true) => 0,
                (true, true) => {
                    waiting.push((h.u64()?, this));
                    0
                }
            });
            at = h.at;
            if !child && !sibling {
                let Some((sibling_at, from)) = waiting.pop() else { break };
                if sibling_at < s.at || sibling_at >= s.end {
                    return Err(format!("a path's sibling at byte {sibling_at} is outside section PATHS"));
                }
                jumps[from] = (indices.len() - from) as u32;
                at = sibling_at;
            }
        }
        self.paths = [indices, tokens, jumps];
        Ok(())
    }

    /// A copy of token 0 appended to the tokens (the first time it is asked for), so that
    /// a property can name it by a negative index.
    fn token_zero_copy(&mut self) -> u32 {
        if let Some(copy) = self.zero_copy {
            return copy;
        }
        let zero_end = self.token_bytes.iter().position(|&c| c == 0).map_or(0, |end| end + 1);
        self.token_bytes.extend_from_within(..zero_end);
        let copy = (self.token_count as i32).wrapping_neg() as u32;
        self.token_count += 1;
        self.zero_copy = Some(copy);
        copy
    }

    /// The file with the sections in the 0.4.0 encoding and a new table of contents after
    /// its last byte, marked version 0.4.0.
    fn append_to(self, mut file: Vec<u8>) -> Vec<u8> {
        let mut toc: Vec<([u8; 16], u64, u64)> = self.kept;
        let mut section = |file: &mut Vec<u8>, name: &str, body: Vec<u8>| {
            file.resize(file.len().next_multiple_of(8), 0);
            let mut padded = [0u8; 16];
            padded[..name.len()].copy_from_slice(name.as_bytes());
            toc.push((padded, file.len() as u64, body.len() as u64));
            file.extend_from_slice(&body);
        };
        let mut tokens = u64s(&[self.token_count, self.token_bytes.len() as u64]);
        tokens.extend(compressed(&self.token_bytes));
        section(&mut file, "TOKENS", tokens);
        let mut fields = u64s(&[self.field_tokens.len() as u64]);
        fields.extend(compressed(&encode_ints(&self.field_tokens)));
        fields.extend(compressed(&u64s(&self.field_reps)));
        section(&mut file, "FIELDS", fields);
        let mut fieldsets = u64s(&[self.fieldsets.len() as u64]);
        fieldsets.extend(compressed(&encode_ints(&self.fieldsets)));
        section(&mut file, "FIELDSETS", fieldsets);
        let mut paths = u64s(&[self.path_count, self.paths[0].len() as u64]);
        for list in &self.paths {
            paths.extend(compressed(&encode_ints(list)));
        }
        section(&mut file, "PATHS", paths);
        let mut specs = u64s(&[self.specs[0].len() as u64]);
        for list in &self.specs {
            specs.extend(compressed(&encode_ints(list)));
        }
        section(&mut file, "SPECS", specs);
        file.resize(file.len().next_multiple_of(8), 0);
        let toc_at = file.len() as u64;
        file.extend(u64s(&[toc.len() as u64]));
        for (name, start, size) in toc {
            file.extend_from_slice(&name);
            file.extend(u64s(&[start, size]));
        }
        file[8..11].copy_from_slice(&COMPRESSED_SECTIONS);
        file[16..24].copy_from_slice(&toc_at.to_le_bytes());
        file
    }
}

fn name_of(name: &[u8; 16]) -> String {
    String::from_utf8_lossy(name.split(|&c| c == 0).next().unwrap_or_default()).into_owned()
}

fn u64s(values: &[u64]) -> Vec<u8> {
    values.iter().flat_map(|v| v.to_le_bytes()).collect()
}

/// `bytes` as a block of `TfFastCompression`: its compressed size, then one chunk (a
/// leading 0) of LZ4.
fn compressed(bytes: &[u8]) -> Vec<u8> {
    let block = lz4_flex::block::compress(bytes);
    let mut out = u64s(&[block.len() as u64 + 1]);
    out.push(0);
    out.extend(block);
    out
}

/// 32-bit integers in USD's integer coding: a common value of 0, every delta 32 bits wide
/// (code 3), and the codes past the last integer 0.
fn encode_ints(values: &[u32]) -> Vec<u8> {
    if values.is_empty() {
        return Vec::new();
    }
    let mut out = vec![0u8; 4];
    out.extend((0..values.len().div_ceil(4)).map(|byte| {
        let in_byte = (values.len() - 4 * byte).min(4);
        (0..in_byte).fold(0u8, |codes, i| codes | 3 << (2 * i))
    }));
    let mut previous = 0u32;
    for &v in values {
        out.extend_from_slice(&v.wrapping_sub(previous).to_le_bytes());
        previous = v;
    }
    out
}

/// A reading position in one section of the old file.
struct Cursor<'a> {
    b: &'a Bytes<'a>,
    name: String,
    at: u64,
    end: u64,
}

impl Cursor<'_> {
    fn take(&mut self, size: u64) -> Result<&[u8], String> {
        if size > self.end - self.at || size > MAX_CHUNK as u64 {
            return Err(format!("section {} ends inside a {size}-byte item", self.name));
        }
        let (from, to) = (self.at as usize, (self.at + size) as usize);
        self.at += size;
        Ok(&self.b.0[from..to])
    }
    fn u32(&mut self) -> Result<u32, String> {
        Ok(u32::from_le_bytes(self.take(4)?.try_into().expect("4 bytes")))
    }
    fn u64(&mut self) -> Result<u64, String> {
        Ok(u64::from_le_bytes(self.take(8)?.try_into().expect("8 bytes")))
    }
    /// A count of items of `item` bytes each, which the rest of the section must hold.
    fn count(&mut self, item: u64) -> Result<u64, String> {
        let count = self.u64()?;
        self.at_most(count, (self.end - self.at) / item, "items")?;
        Ok(count)
    }
    fn u32s(&mut self) -> Result<Vec<u32>, String> {
        (0..self.count(4)?).map(|_| self.u32()).collect()
    }
    fn at_most(&self, count: u64, most: u64, what: &str) -> Result<(), String> {
        match count <= most {
            true => Ok(()),
            false => Err(format!("section {} claims {count} {what}, more than it can hold", self.name)),
        }
    }
}

#[cfg(test)]
mod tests {
    use crate::io::usd::read_usd;
    use crate::io::ImportOptions;
    use crate::scene::HairSource;

    const ARRAY: u64 = 1 << 63;
    const INLINED: u64 = 1 << 62;
    const TOKENS: [&str; 19] = [
        "points",
        "",
        "Hair",
        "BasisCurves",
        "curveVertexCounts",
        "primChildren",
        "specifier",
        "typeName",
        "properties",
        "default",
        "point3f[]",
        "int[]",
        "timeSamples",
        "type",
        "linear",
        "token",
        "variability",
        "Other",
        "Xform",
    ];
    /// The curves' points at time 1; at time 2 each is 1 further along x.
    const POINTS: [[f32; 3]; 4] = [[0.0, 0.0, 0.0], [0.0, 1.0, 0.0], [2.0, 0.0, 0.0], [2.0, 1.0, 0.5]];

    fn t(name: &str) -> u64 {
        TOKENS.iter().position(|&x| x == name).unwrap() as u64
    }
    fn rep(kind: u64, payload: u64) -> u64 {
        kind << 48 | payload
    }
    fn le32(values: &[u32]) -> Vec<u8> {
        values.iter().flat_map(|v| v.to_le_bytes()).collect()
    }
    /// `bytes` appended at the next multiple of 8; returns where they start.
    fn put(file: &mut Vec<u8>, bytes: &[u8]) -> u64 {
        file.resize(file.len().next_multiple_of(8), 0);
        file.extend_from_slice(bytes);
        (file.len() - bytes.len()) as u64
    }
    /// An array value as versions before 0.5.0 store it: a rank of 1, a 32-bit count.
    fn array(count: u32, data: &[u8]) -> Vec<u8> {
        [le32(&[1, count]), data.to_vec()].concat()
    }
    fn token_vector(names: &[&str]) -> Vec<u8> {
        let indices: Vec<u32> = names.iter().map(|n| t(n) as u32).collect();
        [(names.len() as u64).to_le_bytes().to_vec(), le32(&indices)].concat()
    }

    /// A crate file of `version` in that version's layout (16-byte path and spec records
    /// in 0.0.1, 12-byte ones later) as USD wrote them: `/Hair`, linear BasisCurves of
    /// two 2-point curves whose points are sampled at times 1 and 2, and an empty `/Other`
    /// Xform beside it. Token 0 names a property (files of that time had no sentinel).
    fn legacy_file(version: [u8; 3]) -> Vec<u8> {
        let padded = version == [0, 0, 1];
        let mut file = vec![0u8; 88];
        file[..8].copy_from_slice(b"PXR-USDC");
        file[8..11].copy_from_slice(&version);
        // Values.
        let children = rep(41, put(&mut file, &token_vector(&["Hair", "Other"])));
        let properties = rep(41, put(&mut file, &token_vector(&["points", "curveVertexCounts", "type"])));
        let counts = ARRAY | rep(3, put(&mut file, &array(2, &le32(&[2, 2]))));
        let times = put(&mut file, &[2u64.to_le_bytes(), 1f64.to_le_bytes(), 2f64.to_le_bytes()].concat());
        let floats = |shift: f32| -> Vec<u8> {
            POINTS.iter().flat_map(|p| [p[0] + shift, p[1], p[2]]).flat_map(f32::to_le_bytes).collect()
        };
        let at_1 = ARRAY | rep(24, put(&mut file, &array(4, &floats(0.0))));
        let at_2 = ARRAY | rep(24, put(&mut file, &array(4, &floats(1.0))));
        // Time samples: an offset to the times' representation, which follows, then an
        // offset to the count and the values' representations, which follow.
        let samples = [8i64.to_le_bytes(), rep(48, times).to_le_bytes(), 8i64.to_le_bytes()].concat();
        let samples = [samples, 2u64.to_le_bytes().to_vec(), at_1.to_le_bytes().to_vec(), at_2.to_le_bytes().to_vec()];
        let samples = rep(46, put(&mut file, &samples.concat()));
        let token = |name: &str| INLINED | rep(11, t(name));
        let fields = [
            (t("primChildren"), children),
            (t("specifier"), INLINED | rep(42, 0)),
            (t("typeName"), token("BasisCurves")),
            (t("properties"), properties),
            (t("typeName"), token("point3f[]")),
            (t("timeSamples"), samples),
            (t("typeName"), token("int[]")),
            (t("default"), counts),
            (t("typeName"), token("token")),
            (t("default"), token("linear")),
            (t("variability"), INLINED | rep(44, 1)),
            (t("typeName"), token("Xform")),
        ];
        const END: u32 = u32::MAX;
        let fieldsets = [0, END, 1, 2, 3, END, 4, 5, END, 6, 7, END, 8, 9, 10, END, 1, 11, END];
        // Path index, field set, spec type (pseudo-root 7, prim 6, attribute 1).
        let specs = [[0, 0, 7], [1, 2, 6], [2, 6, 1], [3, 9, 1], [4, 12, 1], [5, 16, 6]];
        // Structural sections.
        let mut toc = Vec::new();
        let tokens: Vec<u8> = TOKENS.iter().flat_map(|t| [t.as_bytes(), &[0]].concat()).collect();
        let body = [(TOKENS.len() as u64).to_le_bytes().to_vec(), (tokens.len() as u64).to_le_bytes().to_vec(), tokens];
        toc.push(("TOKENS", put(&mut file, &body.concat()), file.len()));
        toc.push(("STRINGS", put(&mut file, &0u64.to_le_bytes()), file.len()));
        let mut body = (fields.len() as u64).to_le_bytes().to_vec();
        for (token, value) in fields {
            body.extend([le32(&[0, token as u32]), value.to_le_bytes().to_vec()].concat());
        }
        toc.push(("FIELDS", put(&mut file, &body), file.len()));
        let body = [(fieldsets.len() as u64).to_le_bytes().to_vec(), le32(&fieldsets)].concat();
        toc.push(("FIELDSETS", put(&mut file, &body), file.len()));
        // The path tree: the root, its child /Hair (with a sibling, /Other, whose offset
        // follows /Hair's record), /Hair's three properties, then /Other.
        let start = put(&mut file, &6u64.to_le_bytes());
        let header = |file: &mut Vec<u8>, index: u32, token: u64, bits: u8| {
            if padded {
                file.extend(le32(&[0]));
            }
            file.extend([le32(&[index, token as u32]), vec![bits, 0, 0, 0]].concat());
        };
        header(&mut file, 0, t(""), 1);
        header(&mut file, 1, t("Hair"), 3);
        let sibling_offset = file.len();
        file.extend(0i64.to_le_bytes());
        header(&mut file, 2, t("points"), 6);
        header(&mut file, 3, t("curveVertexCounts"), 6);
        header(&mut file, 4, t("type"), 4);
        let other = file.len() as u64;
        file[sibling_offset..sibling_offset + 8].copy_from_slice(&other.to_le_bytes());
        header(&mut file, 5, t("Other"), 0);
        toc.push(("PATHS", start, file.len()));
        let mut body = (specs.len() as u64).to_le_bytes().to_vec();
        for spec in specs {
            body.extend(le32(&if padded { vec![0, spec[0], spec[1], spec[2]] } else { spec.to_vec() }));
        }
        toc.push(("SPECS", put(&mut file, &body), file.len()));
        let toc_at = put(&mut file, &(toc.len() as u64).to_le_bytes());
        for (name, start, end) in toc {
            let mut padded_name = [0u8; 16];
            padded_name[..name.len()].copy_from_slice(name.as_bytes());
            file.extend(padded_name);
            file.extend([start.to_le_bytes(), (end as u64 - start).to_le_bytes()].concat());
        }
        file[16..24].copy_from_slice(&toc_at.to_le_bytes());
        file
    }

    /// The first point of each strand read from `bytes` at `frame`.
    fn roots(bytes: &[u8], frame: u32) -> Result<Vec<[f32; 3]>, String> {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("old.usd");
        std::fs::write(&path, bytes).unwrap();
        let s = read_usd(&path, &ImportOptions { frame: Some(frame), camera: None, ..Default::default() })
            .map_err(|e| e.to_string())?;
        let HairSource::Inline(set) = &s.contents.hair[0].source else { panic!() };
        Ok(set.offsets[..set.offsets.len() - 1]
            .iter()
            .map(|&o| {
                let p = set.points[o as usize];
                [p[0], p[1], p[2]]
            })
            .collect())
    }

    /// Crate files of 0.0.1 (the layout of Pixar's Kitchen Set) and of 0.1.0 to 0.3.0
    /// read, with their curves where the file puts them at each sampled time.
    #[test]
    fn old_crate_versions_read_with_their_time_samples() {
        for version in [[0, 0, 1], [0, 1, 0], [0, 2, 0], [0, 3, 0]] {
            let file = legacy_file(version);
            assert_eq!(roots(&file, 1), Ok(vec![POINTS[0], POINTS[2]]), "{version:?}");
            assert_eq!(roots(&file, 2), Ok(vec![[1.0, 0.0, 0.0], [3.0, 0.0, 0.0]]), "{version:?}");
        }
    }

    /// The `openusd` crate alone cannot read such a file, nor its sample times once the
    /// structure is rewritten: each rewrite is needed.
    #[test]
    fn both_rewrites_are_needed() {
        let file = legacy_file([0, 0, 1]);
        let opened = |bytes: &[u8]| {
            super::super::crate_file::without_panicking(|| {
                let mut crate_file = openusd::usdc::CrateFile::open(std::io::Cursor::new(bytes))?;
                let fields = crate_file.fields.clone();
                fields.iter().try_for_each(|f| crate_file.value(f.value_rep).map(|_| ()))
            })
            .map_err(|_| ())
            .and_then(|r| r.map_err(|_| ()))
        };
        assert!(opened(&file).is_err());
        let upgraded = super::upgrade(file).unwrap();
        assert!(opened(&upgraded).is_err(), "the crate reads vectors of sample times");
        assert_eq!(opened(&super::array_sample_times(upgraded).unwrap()), Ok(()));
    }

    /// Damaged old files: truncated anywhere, or any 8 bytes replaced by a huge count, a
    /// negative offset or zeros, they are errors naming the file (or still read), never a
    /// panic, an abort or a loop; path trees whose sibling offsets lead back are refused.
    #[test]
    fn damaged_old_crate_files_are_errors() {
        let good = legacy_file([0, 0, 1]);
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("damaged.usd");
        let refused = crate::io::usd::tests::damaged_copies_refused(&good, &path, 1);
        assert!(refused > good.len(), "{refused} damaged files refused");
        // /Other's sibling offset pointed back at the root's record: a loop, refused.
        let paths = good.windows(8).position(|w| w == b"PATHS\0\0\0").unwrap();
        let toc_paths_start = u64::from_le_bytes(good[paths + 16..paths + 24].try_into().unwrap()) as usize;
        let mut looped = good.clone();
        let sibling_offset = toc_paths_start + 8 + 2 * 16;
        looped[sibling_offset..sibling_offset + 8].copy_from_slice(&(toc_paths_start as u64 + 8).to_le_bytes());
        std::fs::write(&path, &looped).unwrap();
        let e = read_usd(&path, &ImportOptions::default()).unwrap_err().to_string();
        assert!(e.contains("crate version 0.0.1") && e.contains("path"), "{e}");
    }
}
