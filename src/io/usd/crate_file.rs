//! Checks of binary crate layers (`.usdc`) before the `openusd` crate reads them.
//!
//! The crate's binary reader trusts the sizes and counts a file gives: it allocates a
//! buffer of whatever size a section header or an array announces before reading it, so a
//! damaged file can ask for terabytes, and Rust aborts the process when an allocation
//! fails (no error, no unwinding). Every size and count the reader allocates by is checked
//! here against the bytes that can hold it: the bootstrap header and table of contents,
//! each section's extent, the structural sections' element counts (compressed blocks at
//! most [`MAX_EXPANSION`] times their size), and every value the fields point to: array
//! lengths, time samples, dictionaries (nested at most [`MAX_VALUE_DEPTH`] deep, as the
//! crate reads them recursively), vectors and each list a list op's header announces.
//! Whatever passes, the stage read still runs inside `catch_unwind` (see the parent
//! module), for the reader's panics.
//!
//! The layout is the crate file format of USD (Pixar, `crateFile.cpp`, and the USD Core
//! Specification §16.3): an 88-byte bootstrap (`PXR-USDC`, version, offset of the table
//! of contents), the table (a count, then 16-byte names with start and size), sections
//! `TOKENS`, `STRINGS`, `FIELDS`, `FIELDSETS`, `PATHS`, `SPECS`, and values addressed by
//! 64-bit value representations (type in bits 48..56, array, inlined and compressed flags
//! in bits 63, 62, 61, a 48-bit payload offset).

use openusd::usdc::CrateFile;

/// The most a compressed block may expand: LZ4 expands at most about 255 times, and the
/// integer coding in front of it up to 16 times more for runs of one value.
pub const MAX_EXPANSION: u64 = 1 << 12;
/// Deepest nesting of time samples and dictionaries inside values.
pub const MAX_VALUE_DEPTH: usize = 32;
/// The oldest crate version the crate reads (older ones reach unimplemented code). Layers
/// opened as files are rewritten first by [`super::crate_legacy::upgrade`]; the layers
/// inside a `.usdz` package, which the crate reads from the package, are not.
const MIN_VERSION: [u8; 3] = [0, 4, 0];
const BOOTSTRAP_BYTES: u64 = 88;

/// Little-endian reads at checked offsets of the file.
pub(super) struct Bytes<'a>(pub(super) &'a [u8]);

impl Bytes<'_> {
    pub(super) fn len(&self) -> u64 {
        self.0.len() as u64
    }
    pub(super) fn u64_at(&self, at: u64) -> Result<u64, String> {
        let at = usize::try_from(at).map_err(|_| "an offset past the end of the file".to_string())?;
        match self.0.get(at..at.saturating_add(8)) {
            Some(b) => Ok(u64::from_le_bytes(b.try_into().expect("8 bytes"))),
            None => Err(format!("a value at byte {at} past the end of the file ({} bytes)", self.0.len())),
        }
    }
    pub(super) fn u32_at(&self, at: u64) -> Result<u64, String> {
        let at = usize::try_from(at).map_err(|_| "an offset past the end of the file".to_string())?;
        match self.0.get(at..at.saturating_add(4)) {
            Some(b) => Ok(u32::from_le_bytes(b.try_into().expect("4 bytes")) as u64),
            None => Err(format!("a value at byte {at} past the end of the file ({} bytes)", self.0.len())),
        }
    }
    pub(super) fn byte_at(&self, at: u64) -> Result<u8, String> {
        usize::try_from(at).ok().and_then(|at| self.0.get(at).copied()).ok_or_else(|| "a byte past the end".into())
    }
}

/// Checks a binary crate layer's sizes and counts (see the module documentation); the
/// error says which one is impossible.
pub fn check(bytes: &[u8]) -> Result<(), String> {
    let b = Bytes(bytes);
    let damaged = |what: String| format!("damaged binary USD layer: {what}");
    if b.len() < BOOTSTRAP_BYTES {
        return Err(damaged(format!("{} bytes, shorter than its header", b.len())));
    }
    let version = [bytes[8], bytes[9], bytes[10]];
    if version < MIN_VERSION {
        return Err(format!(
            "binary USD layer of crate version {}.{}.{}: versions before 0.4.0 are not read",
            version[0], version[1], version[2]
        ));
    }
    check_sections(&b).map_err(damaged)?;
    // The structure passed: let the crate decode it (lz4 and the integer coding), then
    // check the values its fields point to.
    let file = without_panicking(|| CrateFile::open(std::io::Cursor::new(bytes)))
        .map_err(|m| damaged(format!("its structural sections cannot be decoded ({m})")))?
        .map_err(|e| damaged(format!("{e:#}")))?;
    file.validate().map_err(|e| damaged(format!("{e:#}")))?;
    let values = Values { b: &b, version, reps_checked: std::cell::Cell::new(0) };
    for field in &file.fields {
        values.check(field.value_rep.0, 0).map_err(damaged)?;
    }
    Ok(())
}

/// Runs `f`, turning a panic into an error with its message, and without the panic
/// message on standard error (the error says it). The panic hook is process-wide: it is
/// swapped for the call's duration, when only the reading thread runs tress code.
pub fn without_panicking<T>(f: impl FnOnce() -> T) -> Result<T, String> {
    let hook = std::panic::take_hook();
    std::panic::set_hook(Box::new(|_| {}));
    let result = std::panic::catch_unwind(std::panic::AssertUnwindSafe(f));
    std::panic::set_hook(hook);
    result.map_err(|p| match (p.downcast_ref::<&str>(), p.downcast_ref::<String>()) {
        (Some(s), _) => s.to_string(),
        (_, Some(s)) => s.clone(),
        _ => "no message".to_string(),
    })
}

/// The table of contents and the structural sections' counts.
fn check_sections(b: &Bytes) -> Result<(), String> {
    let toc = b.u64_at(16)?;
    let count = b.u64_at(toc)?;
    if count == 0 || count >= 64 {
        return Err(format!("its table of contents claims {count} sections"));
    }
    let table_end = toc + 8 + 32 * count;
    if table_end > b.len() {
        return Err("its table of contents runs past the end of the file".into());
    }
    for i in 0..count {
        let at = toc + 8 + 32 * i;
        let name: Vec<u8> = (0..16).map(|k| b.byte_at(at + k).unwrap_or(0)).take_while(|&c| c != 0).collect();
        let name = String::from_utf8_lossy(&name).to_string();
        let (start, size) = (b.u64_at(at + 16)?, b.u64_at(at + 24)?);
        let end = start.checked_add(size).filter(|&e| e <= b.len());
        let Some(end) = end else {
            return Err(format!("section {name} ({size} bytes at {start}) runs past the end of the file"));
        };
        let mut s = Section { b, name: &name, at: start, end };
        match name.as_str() {
            "TOKENS" => {
                let tokens = s.u64()?;
                let uncompressed = s.u64()?;
                let compressed = s.block()?;
                s.expands(uncompressed, 1, compressed)?;
                s.at_most(tokens, uncompressed.saturating_add(1), "tokens")?;
            }
            "STRINGS" => {
                let strings = s.u64()?;
                s.at_most(strings, (s.end - s.at) / 4, "strings")?;
            }
            "FIELDS" => {
                let fields = s.u64()?;
                let indices = s.block()?;
                s.expands(fields, 4, indices)?;
                let reps = s.block()?;
                s.expands(fields, 8, reps)?;
            }
            "FIELDSETS" => {
                let sets = s.u64()?;
                let ints = s.block()?;
                s.expands(sets, 4, ints)?;
            }
            "PATHS" => {
                let paths = s.u64()?;
                s.at_most(paths, MAX_EXPANSION * size, "paths")?;
                let encoded = s.u64()?;
                for _ in 0..3 {
                    let ints = s.block()?;
                    s.expands(encoded, 4, ints)?;
                }
            }
            "SPECS" => {
                let specs = s.u64()?;
                for _ in 0..3 {
                    let ints = s.block()?;
                    s.expands(specs, 4, ints)?;
                }
            }
            _ => {}
        }
    }
    Ok(())
}

/// A cursor in one section.
struct Section<'a> {
    b: &'a Bytes<'a>,
    name: &'a str,
    at: u64,
    end: u64,
}

impl Section<'_> {
    fn u64(&mut self) -> Result<u64, String> {
        if self.at + 8 > self.end {
            return Err(format!("section {} ends inside a count", self.name));
        }
        let v = self.b.u64_at(self.at)?;
        self.at += 8;
        Ok(v)
    }
    /// A compressed block: its size, then that many bytes, which must be in the section.
    fn block(&mut self) -> Result<u64, String> {
        let size = self.u64()?;
        if size > self.end - self.at {
            return Err(format!("section {} has a {size}-byte block in {} bytes", self.name, self.end - self.at));
        }
        self.at += size;
        Ok(size)
    }
    /// `count` items of `item` bytes must fit what `compressed` bytes can expand to.
    fn expands(&self, count: u64, item: u64, compressed: u64) -> Result<(), String> {
        let most = MAX_EXPANSION.saturating_mul(compressed.max(1)).saturating_add(64);
        match count.checked_mul(item).is_some_and(|n| n <= most) {
            true => Ok(()),
            false => Err(format!("section {} claims {count} items in {compressed} compressed bytes", self.name)),
        }
    }
    fn at_most(&self, count: u64, most: u64, what: &str) -> Result<(), String> {
        match count <= most {
            true => Ok(()),
            false => Err(format!("section {} claims {count} {what}, more than it can hold", self.name)),
        }
    }
}

/// The value representations' checks.
struct Values<'a> {
    b: &'a Bytes<'a>,
    version: [u8; 3],
    /// Representations checked so far, bounded so a file whose values point at each other
    /// cannot keep the check busy.
    reps_checked: std::cell::Cell<u64>,
}

const ARRAY: u64 = 1 << 63;
const INLINED: u64 = 1 << 62;
const COMPRESSED: u64 = 1 << 61;

impl Values<'_> {
    fn check(&self, rep: u64, depth: usize) -> Result<(), String> {
        let n = self.reps_checked.get() + 1;
        self.reps_checked.set(n);
        if n > 64 * self.b.len() || depth > MAX_VALUE_DEPTH {
            return Err(format!("values nest or refer to each other more than {MAX_VALUE_DEPTH} levels deep"));
        }
        if rep & INLINED != 0 {
            return Ok(());
        }
        let payload = rep & ((1 << 48) - 1);
        let kind = (rep >> 48) & 0xff;
        if rep & ARRAY != 0 {
            if payload == 0 {
                return Ok(());
            }
            let at = if self.version < [0, 5, 0] { payload + 4 } else { payload };
            let count = if self.version < [0, 7, 0] { self.b.u32_at(at)? } else { self.b.u64_at(at)? };
            let room = self.b.len().saturating_sub(at);
            let most = if rep & COMPRESSED != 0 { MAX_EXPANSION.saturating_mul(room) } else { room };
            return match count <= most {
                true => Ok(()),
                false => Err(format!("an array at byte {payload} claims {count} elements")),
            };
        }
        let bounded = |count: u64, item: u64, what: &str| self.fits(count, item, payload, payload, what).map(|_| ());
        match kind {
            // Time samples: an offset to the times' representation, then an offset to
            // the count and representations of the values.
            46 => {
                let times_at = self.offset(payload)?;
                self.check(self.b.u64_at(times_at)?, depth + 1)?;
                let values_at = self.offset(times_at + 8)?;
                let count = self.b.u64_at(values_at)?;
                bounded(count, 8, "time samples")?;
                for i in 0..count {
                    self.check(self.b.u64_at(values_at + 8 + 8 * i)?, depth + 1)?;
                }
                Ok(())
            }
            31 => self.dictionary(payload, depth).map(|_| ()),
            32..=39 | 54 | 55 => self.list_op(kind, payload, depth),
            // Vectors and the variant selection map: a count first.
            40 | 41 | 45 | 48 | 49 | 50 => bounded(self.b.u64_at(payload)?, 4, "a vector"),
            _ => Ok(()),
        }
    }

    /// A dictionary at `at`: a count, then per entry a string index and an offset to the
    /// value's representation, the next entry after it. Returns where it ends.
    fn dictionary(&self, at: u64, depth: usize) -> Result<u64, String> {
        let count = self.b.u64_at(at)?;
        self.fits(count, 12, at, at, "a dictionary")?;
        let mut at = at + 8;
        for _ in 0..count {
            let rep_at = self.offset(at + 4)?;
            self.check(self.b.u64_at(rep_at)?, depth + 1)?;
            at = rep_at + 8;
        }
        Ok(at)
    }

    /// A list op of value type `kind` at `at`: a header byte of flags, then, only for the
    /// lists the flags say are present, a `u64` count and that many items, in the order
    /// `crateFile.cpp` writes them (explicit, added, prepended, appended, deleted,
    /// ordered). A flag byte alone is a valid list op (an explicit empty list, `= None`
    /// in text), so no count is read where the flags announce none.
    fn list_op(&self, kind: u64, at: u64, depth: usize) -> Result<(), String> {
        const HAS_EXPLICIT: u8 = 1 << 1;
        const HAS_ADDED: u8 = 1 << 2;
        const HAS_DELETED: u8 = 1 << 3;
        const HAS_ORDERED: u8 = 1 << 4;
        const HAS_PREPENDED: u8 = 1 << 5;
        const HAS_APPENDED: u8 = 1 << 6;
        let header = self.b.byte_at(at)?;
        // Item sizes: indices of tokens, strings and paths and 32-bit integers take 4
        // bytes, 64-bit ones 8; a payload is an asset-path string and a prim path index,
        // with a 16-byte layer offset from version 0.8.0; a reference has the offset and
        // a custom-data dictionary after them, so its items are walked one by one.
        let item = match kind {
            37 | 39 => 8,
            55 if self.version >= [0, 8, 0] => 24,
            55 => 8,
            35 => 24,
            _ => 4,
        };
        let start = at;
        let mut at = at + 1;
        for list in [HAS_EXPLICIT, HAS_ADDED, HAS_PREPENDED, HAS_APPENDED, HAS_DELETED, HAS_ORDERED] {
            if header & list == 0 {
                continue;
            }
            let count = self.b.u64_at(at)?;
            at += 8;
            let bytes = self.fits(count, item, at, start, "a list op")?;
            if kind == 35 {
                for _ in 0..count {
                    at = self.dictionary(at + 24, depth + 1)?;
                }
            } else {
                at += bytes;
            }
        }
        Ok(())
    }

    /// The bytes `count` items of `item` bytes take from `at`, when the file holds them;
    /// otherwise an error naming `what` starts at byte `start` and the count it claims.
    fn fits(&self, count: u64, item: u64, at: u64, start: u64, what: &str) -> Result<u64, String> {
        count
            .checked_mul(item)
            .filter(|&n| n <= self.b.len().saturating_sub(at))
            .ok_or_else(|| format!("{what} at byte {start} claims {count} entries"))
    }

    /// The position an `i64` offset at `at` leads to (the crate's recursive offsets are
    /// relative to where they are stored).
    fn offset(&self, at: u64) -> Result<u64, String> {
        let off = self.b.u64_at(at)? as i64;
        at.checked_add_signed(off)
            .filter(|&p| p + 8 <= self.b.len())
            .ok_or_else(|| format!("an offset at byte {at} leads outside the file"))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `list_op` (a list op's bytes) at byte 8 of a file, checked as a value of `kind`.
    fn check_list_op(kind: u64, list_op: &[u8]) -> Result<(), String> {
        let mut file = vec![0u8; 8];
        file.extend_from_slice(list_op);
        let b = Bytes(&file);
        let values = Values { b: &b, version: [0, 9, 0], reps_checked: std::cell::Cell::new(0) };
        values.check(kind << 48 | 8, 0)
    }

    fn le(words: &[u64], bytes: usize) -> Vec<u8> {
        words.iter().flat_map(|w| w.to_le_bytes()[..bytes].to_vec()).collect()
    }

    /// Only the lists a list op's header announces have a count: an explicit empty list
    /// (`= None`) is the header byte alone, whatever bytes follow it (here eight 0xff,
    /// which read as a count would claim 2⁶⁴ − 1 entries).
    #[test]
    fn list_ops_have_counts_only_for_the_lists_their_header_announces() {
        for kind in [32, 34, 35, 37, 55] {
            assert_eq!(check_list_op(kind, &[&[0x01][..], &[0xff; 8]].concat()), Ok(()), "type {kind}");
        }
        // Added (two token indices), then deleted (one): each count is read after the
        // items before it, and a deleted list claiming 2⁴⁰ entries is refused.
        let tokens = |deleted: u64| [vec![0x0c], le(&[2], 8), le(&[5, 6], 4), le(&[deleted], 8), le(&[7], 4)].concat();
        assert_eq!(check_list_op(32, &tokens(1)), Ok(()));
        let e = check_list_op(32, &tokens(1 << 40)).unwrap_err();
        assert_eq!(e, format!("a list op at byte 8 claims {} entries", 1u64 << 40));
        // 64-bit integers take 8 bytes: two of them fit 16 bytes, three do not.
        let int64s = |count: u64| [vec![0x02], le(&[count], 8), le(&[1, 2], 8)].concat();
        assert_eq!(check_list_op(37, &int64s(2)), Ok(()));
        assert!(check_list_op(37, &int64s(3)).is_err());
        // A prepended reference (asset path, prim path, layer offset and a custom-data
        // dictionary of no entries), then an appended one whose dictionary claims 2⁴⁰
        // entries: the walk goes through the first reference to find the second.
        let reference = |entries: u64| [le(&[1], 4), le(&[2], 4), vec![0; 16], le(&[entries], 8)].concat();
        let references = |entries: u64| {
            [vec![0x60], le(&[1], 8), reference(0), le(&[1], 8), reference(entries), vec![0; 16]].concat()
        };
        assert_eq!(check_list_op(35, &references(0)), Ok(()));
        assert!(check_list_op(35, &references(1 << 40)).unwrap_err().contains("dictionary"));
    }
}
