//! Cem Yuksel's HAIR file format (<http://www.cemyuksel.com/research/hairmodels/>).
//!
//! Layout, all little-endian: a 128-byte header
//!
//! | offset | size | field                                             |
//! |-------:|-----:|---------------------------------------------------|
//! |      0 |    4 | signature `"HAIR"`                                |
//! |      4 |    4 | `u32` number of strands                           |
//! |      8 |    4 | `u32` total number of points                      |
//! |     12 |    4 | `u32` flags: which arrays follow (bits 0 to 4)    |
//! |     16 |    4 | `u32` default segments per strand                 |
//! |     20 |    4 | `f32` default thickness                           |
//! |     24 |    4 | `f32` default transparency                        |
//! |     28 |   12 | `3 × f32` default colour                          |
//! |     40 |   88 | free-form information text                        |
//!
//! followed by the arrays whose flag bit is set, in this order: segments (`u16` per strand,
//! bit 0), points (`3 × f32` per point, bit 1), thickness (`f32` per point, bit 2),
//! transparency (`f32` per point, bit 3), colour (`3 × f32` per point, bit 4).
//!
//! How the file maps onto a [`StrandSet`]:
//! - a strand with `s` segments has `s + 1` points; without a segments array every strand has
//!   the header's default segment count;
//! - thickness is a diameter, so a point's radius is half of it; without a thickness array
//!   every point gets the default thickness;
//! - transparency `t` becomes opacity `1 - t`; without a transparency array the default
//!   applies, and a default of 0 gives no opacity array at all (fully opaque);
//! - without a colour array, `colors` is `None` and the header's default colour is ignored,
//!   so the scene's material decides the colour (exporters often leave the default as junk);
//! - a strand with 0 segments (a single point) is kept as a one-point strand: it takes no part
//!   in rendering (it has no segments) but keeping it preserves strand numbering, so per-strand
//!   data in other files still lines up;
//! - flag bits above bit 4 are ignored: they describe no array in the format.
//!
//! Reading is strict, because a bad hair file usually means a broken exporter and silently
//! rendering half of it hides that: the file length must equal exactly what the header's
//! counts and flags require (trailing bytes are an error too, since they almost always mean
//! the counts or flags are wrong), segment counts must add up to the point count, and every
//! value must be usable (finite coordinates, finite non-negative thickness, transparency in
//! [0, 1], finite non-negative colour). The length check happens before anything is
//! allocated, so a forged header cannot make the reader allocate more than the file's size
//! justifies.

use std::path::Path;

use crate::error::LoadError;
use crate::geometry::StrandSet;

/// Size of the fixed header.
const HEADER_SIZE: usize = 128;
/// Size of the free-form information text at the end of the header.
const INFO_SIZE: usize = 88;
const SIGNATURE: &[u8; 4] = b"HAIR";

const HAS_SEGMENTS: u32 = 1 << 0;
const HAS_POINTS: u32 = 1 << 1;
const HAS_THICKNESS: u32 = 1 << 2;
const HAS_TRANSPARENCY: u32 = 1 << 3;
const HAS_COLOR: u32 = 1 << 4;

/// Segment counts are stored as `u16`, which bounds the points per strand when writing.
const MAX_POINTS_PER_STRAND: usize = u16::MAX as usize + 1;

/// Information text written into the header of files we produce.
const INFO_TEXT: &[u8] = b"written by tress";

/// The fields of the 128-byte header (the information text is not needed).
struct Header {
    strands: u32,
    points: u32,
    flags: u32,
    default_segments: u32,
    default_thickness: f32,
    default_transparency: f32,
}

impl Header {
    /// Decodes the header; `bytes` must hold at least [`HEADER_SIZE`] bytes.
    fn decode(bytes: &[u8]) -> Header {
        Header {
            strands: u32_at(bytes, 4),
            points: u32_at(bytes, 8),
            flags: u32_at(bytes, 12),
            default_segments: u32_at(bytes, 16),
            default_thickness: f32_at(bytes, 20),
            default_transparency: f32_at(bytes, 24),
        }
    }

    fn has(&self, flag: u32) -> bool {
        self.flags & flag != 0
    }

    /// Bytes of per-point data for every point: the sum over the arrays present.
    fn bytes_per_point(&self) -> u64 {
        [(HAS_POINTS, 12), (HAS_THICKNESS, 4), (HAS_TRANSPARENCY, 4), (HAS_COLOR, 12)]
            .iter()
            .filter(|(flag, _)| self.has(*flag))
            .map(|(_, size)| size)
            .sum()
    }

    /// Bytes taken by the segments array.
    fn segment_bytes(&self) -> u64 {
        if self.has(HAS_SEGMENTS) {
            2 * u64::from(self.strands)
        } else {
            0
        }
    }

    /// Total file size the header's counts and flags require. Computed in u64, where it
    /// cannot overflow: at most 128 + 2 * 2^32 + 32 * 2^32 bytes.
    fn file_size(&self) -> u64 {
        HEADER_SIZE as u64 + self.segment_bytes() + self.bytes_per_point() * u64::from(self.points)
    }

    /// The names of the arrays present, for messages.
    fn array_names(&self) -> String {
        let names = [
            (HAS_SEGMENTS, "segments"),
            (HAS_POINTS, "points"),
            (HAS_THICKNESS, "thickness"),
            (HAS_TRANSPARENCY, "transparency"),
            (HAS_COLOR, "colour"),
        ];
        let present: Vec<&str> = names.iter().filter(|(f, _)| self.has(*f)).map(|(_, n)| *n).collect();
        match present.as_slice() {
            [] => "no arrays".to_string(),
            [one] => format!("{one} array"),
            [rest @ .., last] => format!("{} and {last} arrays", rest.join(", ")),
        }
    }
}

fn u32_at(bytes: &[u8], at: usize) -> u32 {
    let mut word = [0; 4];
    word.copy_from_slice(&bytes[at..at + 4]);
    u32::from_le_bytes(word)
}

fn f32_at(bytes: &[u8], at: usize) -> f32 {
    f32::from_bits(u32_at(bytes, at))
}

/// Reads a `.hair` file into a [`StrandSet`].
///
/// See the [module documentation](self) for how the file's arrays and defaults map onto the
/// set and which files are rejected.
pub fn read_hair(path: &Path) -> Result<StrandSet, LoadError> {
    let bytes = crate::input_file::read(path, crate::input_file::Kind::Geometry)?;
    parse_hair(&bytes, path)
}

/// Decodes the bytes of a `.hair` file; `path` is used only in error messages.
///
/// Never panics, and allocates only after checking that the data is as long as the header
/// claims, so memory use stays proportional to `bytes.len()` whatever the header says.
pub fn parse_hair(bytes: &[u8], path: &Path) -> Result<StrandSet, LoadError> {
    let format_error = |message: String| LoadError::format(path, message);
    let invalid = |message: String| LoadError::invalid(path, message);

    if bytes.len() < HEADER_SIZE {
        return Err(format_error(format!(
            "file is {} bytes long, shorter than the {HEADER_SIZE}-byte hair header",
            bytes.len()
        )));
    }
    if &bytes[..4] != SIGNATURE {
        return Err(format_error(format!(
            "not a hair file: it starts with {:?} instead of the \"HAIR\" signature",
            String::from_utf8_lossy(&bytes[..4])
        )));
    }
    let header = Header::decode(bytes);
    if !header.has(HAS_POINTS) {
        return Err(format_error(format!(
            "header flags (0x{:x}) say the file has no points array, so there are no strand positions",
            header.flags
        )));
    }
    check_length(&header, bytes.len() as u64).map_err(format_error)?;

    // From here on every array lies inside `bytes`, so the slicing below cannot fail and
    // every allocation is bounded by the file's length.
    let strand_count = header.strands as usize;
    let point_count = header.points as usize;
    let mut at = HEADER_SIZE;
    let mut take = |len: usize| {
        let slice = &bytes[at..at + len];
        at += len;
        slice
    };

    let offsets = if header.has(HAS_SEGMENTS) {
        offsets_from_segments(take(2 * strand_count), header.points).map_err(format_error)?
    } else {
        offsets_from_default(&header).map_err(format_error)?
    };

    let mut points = Vec::with_capacity(point_count);
    for (i, p) in take(12 * point_count).chunks_exact(12).enumerate() {
        let xyz = [f32_at(p, 0), f32_at(p, 4), f32_at(p, 8)];
        if !xyz.iter().all(|c| c.is_finite()) {
            return Err(invalid(format!(
                "point {i} (strand {}) has a non-finite coordinate ({}, {}, {})",
                strand_of(&offsets, i),
                xyz[0],
                xyz[1],
                xyz[2]
            )));
        }
        points.push([xyz[0], xyz[1], xyz[2], 0.0]);
    }

    let thickness_ok = |t: f32| t.is_finite() && t >= 0.0;
    if header.has(HAS_THICKNESS) {
        for (i, word) in take(4 * point_count).chunks_exact(4).enumerate() {
            let t = f32_at(word, 0);
            if !thickness_ok(t) {
                return Err(invalid(format!(
                    "point {i} (strand {}) has thickness {t}; thickness must be a finite number >= 0",
                    strand_of(&offsets, i)
                )));
            }
            points[i][3] = 0.5 * t;
        }
    } else {
        let t = header.default_thickness;
        if !thickness_ok(t) && point_count > 0 {
            return Err(invalid(format!(
                "the header's default thickness is {t} and there is no thickness array; \
                 thickness must be a finite number >= 0"
            )));
        }
        for p in &mut points {
            p[3] = 0.5 * t;
        }
    }

    let transparency_ok = |t: f32| (0.0..=1.0).contains(&t);
    let opacity = if header.has(HAS_TRANSPARENCY) {
        let mut opacity = Vec::with_capacity(point_count);
        for (i, word) in take(4 * point_count).chunks_exact(4).enumerate() {
            let t = f32_at(word, 0);
            if !transparency_ok(t) {
                return Err(invalid(format!(
                    "point {i} (strand {}) has transparency {t}, outside [0, 1]",
                    strand_of(&offsets, i)
                )));
            }
            opacity.push(1.0 - t);
        }
        Some(opacity)
    } else {
        let t = header.default_transparency;
        // A default of exactly 0 means opaque, which is what no opacity array means.
        if t == 0.0 || point_count == 0 {
            None
        } else if transparency_ok(t) {
            Some(vec![1.0 - t; point_count])
        } else {
            return Err(invalid(format!(
                "the header's default transparency is {t}, outside [0, 1], and there is no transparency array"
            )));
        }
    };

    let colors = if header.has(HAS_COLOR) {
        let mut colors = Vec::with_capacity(point_count);
        for (i, c) in take(12 * point_count).chunks_exact(12).enumerate() {
            let rgb = [f32_at(c, 0), f32_at(c, 4), f32_at(c, 8)];
            if !rgb.iter().all(|v| v.is_finite() && *v >= 0.0) {
                return Err(invalid(format!(
                    "point {i} (strand {}) has colour ({}, {}, {}); colour components must be finite and >= 0",
                    strand_of(&offsets, i),
                    rgb[0],
                    rgb[1],
                    rgb[2]
                )));
            }
            colors.push(rgb);
        }
        Some(colors)
    } else {
        None
    };

    Ok(StrandSet { points, offsets, colors, opacity, strand_info: None, file_order: None })
}

/// What a `.hair` file's header says the file holds, for estimates made before reading it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct HairCounts {
    /// Number of strands.
    pub strands: u32,
    /// Number of points.
    pub points: u32,
    /// Whether the file has per-point colours.
    pub colors: bool,
    /// Whether reading it gives per-point opacity.
    pub opacity: bool,
}

/// Reads only the 128-byte header of a `.hair` file (the rest is checked when it is read).
pub fn read_hair_counts(path: &Path) -> Result<HairCounts, LoadError> {
    use std::io::Read;
    let mut bytes = [0u8; HEADER_SIZE];
    let mut file = crate::input_file::open(path, crate::input_file::Kind::Geometry)?;
    file.read_exact(&mut bytes).map_err(|e| LoadError::io(path, "read the hair header", e))?;
    if &bytes[..4] != SIGNATURE {
        return Err(LoadError::format(path, "not a hair file: it does not start with the \"HAIR\" signature"));
    }
    let h = Header::decode(&bytes);
    Ok(HairCounts {
        strands: h.strands,
        points: h.points,
        colors: h.has(HAS_COLOR),
        opacity: h.has(HAS_TRANSPARENCY) || h.default_transparency != 0.0,
    })
}

/// Checks the data length against what the header requires, before anything is allocated.
fn check_length(header: &Header, len: u64) -> Result<(), String> {
    let need = header.file_size();
    if len < need {
        let before_points = HEADER_SIZE as u64 + header.segment_bytes();
        return Err(if len < before_points {
            format!(
                "header says {} strands, whose segments array needs {} bytes, but the file holds only {} bytes \
                 after the header",
                header.strands,
                header.segment_bytes(),
                len - HEADER_SIZE as u64
            )
        } else {
            format!(
                "header says {} points but the file holds only {} (with the {} the header's flags declare, \
                 the file should be {need} bytes long but is {len})",
                header.points,
                (len - before_points) / header.bytes_per_point(),
                header.array_names()
            )
        });
    }
    if len > need {
        return Err(format!(
            "file has {} trailing bytes after the {need} bytes its header describes ({} strands, {} points; {}); \
             the header's counts or flags are probably wrong",
            len - need,
            header.strands,
            header.points,
            header.array_names()
        ));
    }
    Ok(())
}

/// Strand offsets from the segments array; the counts must add up to `points` exactly.
fn offsets_from_segments(segments: &[u8], points: u32) -> Result<Vec<u32>, String> {
    let strands = segments.len() / 2;
    let mut offsets = Vec::with_capacity(strands + 1);
    offsets.push(0);
    let mut total: u64 = 0;
    for (i, s) in segments.chunks_exact(2).enumerate() {
        total += u64::from(u16::from_le_bytes([s[0], s[1]])) + 1;
        if total > u64::from(points) {
            return Err(format!(
                "segment counts run past the {points} points the header declares: strand {i} of {strands} \
                 would end at point {total}"
            ));
        }
        // Cannot truncate: total <= points, a u32.
        offsets.push(total as u32);
    }
    if total != u64::from(points) {
        return Err(format!(
            "segment counts of the {strands} strands account for only {total} of the {points} points the header \
             declares"
        ));
    }
    Ok(offsets)
}

/// Strand offsets when there is no segments array: every strand has the default count.
fn offsets_from_default(header: &Header) -> Result<Vec<u32>, String> {
    let per_strand = u64::from(header.default_segments) + 1;
    // At most (2^32 - 1) * 2^32, so this cannot overflow a u64.
    let needed = u64::from(header.strands) * per_strand;
    if needed != u64::from(header.points) {
        return Err(format!(
            "there is no segments array, so each of the {} strands has the default {} segments ({needed} points \
             in all), but the header declares {} points",
            header.strands, header.default_segments, header.points
        ));
    }
    // Each strand has at least one point, so strands <= points and this is bounded by the
    // points array already known to be in the file.
    Ok((0..=u64::from(header.strands)).map(|s| (s * per_strand) as u32).collect())
}

/// The strand that owns point `i`, for messages.
fn strand_of(offsets: &[u32], i: usize) -> usize {
    offsets.partition_point(|&o| o as usize <= i).saturating_sub(1)
}

/// Describes the first reason `strands` cannot be expressed as a hair file at all, if any:
/// inconsistent offsets or optional arrays, or a strand too long for a `u16` segment count.
fn structure_problem(strands: &StrandSet) -> Option<String> {
    let n = strands.points.len();
    if strands.offsets.is_empty() {
        return (n != 0).then(|| format!("there are {n} points but no strand offsets"));
    }
    if strands.offsets[0] != 0 {
        return Some(format!("strand offsets start at {}, not 0", strands.offsets[0]));
    }
    for (s, w) in strands.offsets.windows(2).enumerate() {
        if w[1] < w[0] {
            return Some(format!("strand {s} ends (point {}) before it starts (point {})", w[1], w[0]));
        }
        let len = (w[1] - w[0]) as usize;
        if len > MAX_POINTS_PER_STRAND {
            return Some(format!(
                "strand {s} has {len} points; hair files allow at most {MAX_POINTS_PER_STRAND} points per strand"
            ));
        }
    }
    let last = *strands.offsets.last().unwrap_or(&0) as usize;
    if last != n {
        return Some(format!("strand offsets end at point {last} but there are {n} points"));
    }
    if let Some(c) = &strands.colors {
        if c.len() != n {
            return Some(format!("there are {} colours for {n} points", c.len()));
        }
    }
    if let Some(o) = &strands.opacity {
        if o.len() != n {
            return Some(format!("there are {} opacities for {n} points", o.len()));
        }
    }
    None
}

/// Describes the first value that [`parse_hair`] would reject once written, if any.
fn value_problem(strands: &StrandSet) -> Option<String> {
    let owner = |i: usize| strand_of(&strands.offsets, i);
    for (i, p) in strands.points.iter().enumerate() {
        if !p[..3].iter().all(|c| c.is_finite()) {
            return Some(format!("point {i} (strand {}) has a non-finite position", owner(i)));
        }
        // The thickness written is twice the radius, which must stay finite too.
        if !(p[3] >= 0.0 && (2.0 * p[3]).is_finite()) {
            return Some(format!("point {i} (strand {}) has radius {}", owner(i), p[3]));
        }
    }
    if let Some((i, o)) = strands.opacity.iter().flatten().enumerate().find(|(_, o)| !(0.0..=1.0).contains(*o)) {
        return Some(format!("point {i} (strand {}) has opacity {o}, outside [0, 1]", owner(i)));
    }
    if let Some(i) = strands.colors.iter().flatten().position(|c| !c.iter().all(|v| v.is_finite() && *v >= 0.0)) {
        return Some(format!("point {i} (strand {}) has a non-finite or negative colour", owner(i)));
    }
    None
}

/// Encodes `strands` as the bytes of a `.hair` file.
///
/// The file always has segments, points and thickness arrays (thickness = 2 × radius), plus
/// a transparency array (1 − opacity) if the set has opacities and a colour array if it has
/// colours. Strands with no points are left out, since the format cannot express them (a
/// strand has segments + 1 points). Values are written as they are, even non-finite ones;
/// [`write_hair`] checks them first.
///
/// # Panics
///
/// If the set is inconsistent (offsets not starting at 0, decreasing, or not ending at the
/// point count; colour or opacity arrays of the wrong length) or a strand has more than
/// 65,536 points, which a `u16` segment count cannot describe.
pub fn encode_hair(strands: &StrandSet) -> Vec<u8> {
    if let Some(problem) = structure_problem(strands) {
        panic!("cannot encode these strands as a hair file: {problem}");
    }
    // Segment counts of the strands that have points; empty strands are dropped.
    let segments: Vec<u16> =
        strands.offsets.windows(2).filter(|w| w[1] > w[0]).map(|w| (w[1] - w[0] - 1) as u16).collect();
    let n = strands.points.len();

    let mut flags = HAS_SEGMENTS | HAS_POINTS | HAS_THICKNESS;
    if strands.opacity.is_some() {
        flags |= HAS_TRANSPARENCY;
    }
    if strands.colors.is_some() {
        flags |= HAS_COLOR;
    }
    let per_point = 16 + if strands.opacity.is_some() { 4 } else { 0 } + if strands.colors.is_some() { 12 } else { 0 };
    let mut out = Vec::with_capacity(HEADER_SIZE + 2 * segments.len() + per_point * n);

    // The defaults are unused by our reader when the arrays are present, but other readers
    // may show them, so make them representative: the first strand's and point's values.
    let default_color = strands.colors.as_ref().and_then(|c| c.first().copied()).unwrap_or([1.0; 3]);
    out.extend_from_slice(SIGNATURE);
    out.extend_from_slice(&(segments.len() as u32).to_le_bytes());
    out.extend_from_slice(&(n as u32).to_le_bytes());
    out.extend_from_slice(&flags.to_le_bytes());
    out.extend_from_slice(&u32::from(segments.first().copied().unwrap_or(0)).to_le_bytes());
    out.extend_from_slice(&strands.points.first().map_or(0.0, |p| 2.0 * p[3]).to_le_bytes());
    out.extend_from_slice(&0.0f32.to_le_bytes());
    for c in default_color {
        out.extend_from_slice(&c.to_le_bytes());
    }
    let mut info = [0u8; INFO_SIZE];
    info[..INFO_TEXT.len()].copy_from_slice(INFO_TEXT);
    out.extend_from_slice(&info);
    debug_assert_eq!(out.len(), HEADER_SIZE);

    for s in &segments {
        out.extend_from_slice(&s.to_le_bytes());
    }
    for p in &strands.points {
        for c in &p[..3] {
            out.extend_from_slice(&c.to_le_bytes());
        }
    }
    for p in &strands.points {
        out.extend_from_slice(&(2.0 * p[3]).to_le_bytes());
    }
    for o in strands.opacity.iter().flatten() {
        out.extend_from_slice(&(1.0 - o).to_le_bytes());
    }
    for rgb in strands.colors.iter().flatten() {
        for c in rgb {
            out.extend_from_slice(&c.to_le_bytes());
        }
    }
    out
}

/// Writes `strands` to a `.hair` file at `path` (see [`encode_hair`] for the contents).
///
/// Refuses sets that [`read_hair`] would reject (non-finite positions, negative radii,
/// opacity outside [0, 1], negative or non-finite colours) or that the format cannot hold,
/// naming the offending point or strand. The file is written to a temporary file in the same
/// directory and then renamed over `path`, so a crash or full disk never leaves a
/// half-written file under the final name.
pub fn write_hair(path: &Path, strands: &StrandSet) -> Result<(), LoadError> {
    if let Some(problem) = structure_problem(strands).or_else(|| value_problem(strands)) {
        return Err(LoadError::invalid(path, format!("cannot write these strands: {problem}")));
    }
    super::write_atomically(path, &encode_hair(strands))?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Vec3;
    use proptest::prelude::*;
    use std::path::PathBuf;

    /// Builds a header with the given counts and flags; defaults are thickness 0.1,
    /// transparency 0, colour grey, 1 segment.
    fn header(strands: u32, points: u32, flags: u32) -> Vec<u8> {
        let mut h = Vec::with_capacity(HEADER_SIZE);
        h.extend_from_slice(b"HAIR");
        for v in [strands, points, flags, 1] {
            h.extend_from_slice(&v.to_le_bytes());
        }
        for v in [0.1f32, 0.0, 0.5, 0.5, 0.5] {
            h.extend_from_slice(&v.to_le_bytes());
        }
        h.resize(HEADER_SIZE, 0);
        h
    }

    fn push_f32s(out: &mut Vec<u8>, values: &[f32]) {
        for v in values {
            out.extend_from_slice(&v.to_le_bytes());
        }
    }

    fn sample() -> StrandSet {
        let mut s = StrandSet::new();
        s.push_strand([(Vec3::new(0.0, 0.0, 0.0), 0.01), (Vec3::new(0.0, 1.0, 0.0), 0.02)]);
        s.push_strand([(Vec3::new(5.0, -1.5, 2.0), 0.5)]); // 0 segments
        s.push_strand((0..6).map(|i| (Vec3::new(i as f32, 0.5 * i as f32, -1e-3), 0.001 * i as f32)));
        s.push_strand((0..300).map(|i| (Vec3::splat(i as f32 * 0.1), 0.004)));
        s
    }

    fn with_extras(mut s: StrandSet) -> StrandSet {
        let n = s.points.len();
        s.colors = Some((0..n).map(|i| [i as f32 / n as f32, 0.25, 1.0]).collect());
        s.opacity = Some((0..n).map(|i| [1.0, 0.75, 0.5, 0.25, 0.0, 0.3][i % 6]).collect());
        s
    }

    const NAME: &str = "bad.hair";

    /// Parses `bytes` expecting failure; checks the message names the file and contains every
    /// fragment in `expect`.
    fn expect_error(bytes: &[u8], expect: &[&str]) -> String {
        let err = parse_hair(bytes, Path::new(NAME)).expect_err("parse should fail");
        let msg = err.to_string();
        assert!(msg.starts_with("bad.hair: "), "message does not name the file: {msg}");
        for e in expect {
            assert!(msg.contains(e), "message {msg:?} lacks {e:?}");
        }
        msg
    }

    #[test]
    fn round_trip_through_a_file() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("fur.hair");
        let original = with_extras(sample());
        write_hair(&path, &original).unwrap();
        let back = read_hair(&path).unwrap();
        assert_eq!(back.offsets, original.offsets);
        assert_eq!(back.points, original.points, "positions and radii are exact");
        assert_eq!(back.colors, original.colors);
        let (a, b) = (back.opacity.clone().unwrap(), original.opacity.unwrap());
        assert_eq!(a.len(), b.len());
        // 1 - (1 - o) need not be exactly o in floating point.
        assert!(a.iter().zip(&b).all(|(x, y)| (x - y).abs() < 1e-6));
        assert_eq!(back.strand_count(), 4);
        assert_eq!(back.segment_count(), 1 + 5 + 299);
        // Only the temporary file's rename should have touched the directory.
        assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 1);
    }

    #[test]
    fn round_trip_without_optional_arrays() {
        let original = sample();
        let back = parse_hair(&encode_hair(&original), Path::new("x.hair")).unwrap();
        assert_eq!(back, original);
        assert!(back.colors.is_none() && back.opacity.is_none());
    }

    #[test]
    fn empty_sets_round_trip() {
        for s in [StrandSet::new(), StrandSet::default()] {
            let bytes = encode_hair(&s);
            assert_eq!(bytes.len(), HEADER_SIZE);
            assert_eq!(parse_hair(&bytes, Path::new("e.hair")).unwrap(), StrandSet::new());
        }
    }

    #[test]
    fn strands_without_points_are_dropped_when_encoding() {
        let mut s = sample();
        s.offsets.insert(1, 0); // an empty first strand
        let back = parse_hair(&encode_hair(&s), Path::new("x.hair")).unwrap();
        assert_eq!(back, sample());
    }

    #[test]
    fn overwrites_an_existing_file() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("fur.hair");
        std::fs::write(&path, b"old contents").unwrap();
        write_hair(&path, &sample()).unwrap();
        assert_eq!(read_hair(&path).unwrap(), sample());
    }

    /// A file written by an independent encoder (a Python script following the published
    /// layout), so the reader is not only checked against our own writer.
    #[test]
    fn reads_reference_file() {
        let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/data/two_strands.hair");
        let s = read_hair(&path).unwrap();
        assert_eq!(s.offsets, vec![0, 3, 5]);
        assert_eq!(s.points[0], [0.0, 0.0, 0.0, 0.05]);
        assert_eq!(s.points[4], [1.0, 2.0, 0.5, 0.025]);
        assert_eq!(s.colors.as_ref().unwrap()[1], [0.5, 0.25, 0.125]);
        assert!(s.opacity.is_none());
    }

    #[test]
    fn defaults_apply_without_arrays() {
        // 2 strands of the default 1 segment: 4 points, only the points array.
        let mut bytes = header(2, 4, HAS_POINTS);
        push_f32s(&mut bytes, &[0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 1.0, 0.0, 0.0, 1.0, 1.0, 0.0]);
        // Default transparency 0.25.
        bytes[24..28].copy_from_slice(&0.25f32.to_le_bytes());
        let s = parse_hair(&bytes, Path::new("d.hair")).unwrap();
        assert_eq!(s.offsets, vec![0, 2, 4]);
        assert!(s.points.iter().all(|p| p[3] == 0.05), "radius is half the default thickness");
        assert_eq!(s.opacity, Some(vec![0.75; 4]));
        assert_eq!(s.colors, None, "the default colour is not applied");
        assert_eq!(s.position(3), Vec3::new(1.0, 1.0, 0.0));
    }

    #[test]
    fn zero_segment_strands_are_kept() {
        let mut bytes = header(3, 4, HAS_SEGMENTS | HAS_POINTS);
        for s in [0u16, 1, 0] {
            bytes.extend_from_slice(&s.to_le_bytes());
        }
        push_f32s(&mut bytes, &[0.0; 12]);
        let s = parse_hair(&bytes, Path::new("z.hair")).unwrap();
        assert_eq!(s.offsets, vec![0, 1, 3, 4]);
        assert_eq!(s.strand_count(), 3);
        assert_eq!(s.segment_count(), 1);
        assert_eq!(s.segment_starts(), vec![1]);
    }

    #[test]
    fn rejects_short_files() {
        expect_error(b"", &["0 bytes", "shorter than the 128-byte hair header"]);
        expect_error(&header(0, 0, HAS_POINTS)[..100], &["100 bytes", "shorter than the 128-byte"]);
    }

    #[test]
    fn rejects_wrong_signature() {
        let mut bytes = header(0, 0, HAS_POINTS);
        bytes[..4].copy_from_slice(b"PLY\n");
        expect_error(&bytes, &["not a hair file", "\"HAIR\" signature"]);
    }

    #[test]
    fn rejects_missing_points_array() {
        let bytes = header(0, 0, HAS_SEGMENTS | HAS_THICKNESS);
        expect_error(&bytes, &["no points array", "0x5"]);
    }

    #[test]
    fn rejects_truncated_point_data() {
        // Header says 1000 points of one segment each... with thickness, 16 bytes per point.
        let mut bytes = header(500, 1000, HAS_POINTS | HAS_THICKNESS);
        bytes.resize(HEADER_SIZE + 812 * 16 + 5, 0);
        expect_error(&bytes, &["header says 1000 points but the file holds only 812", "points and thickness arrays"]);
    }

    #[test]
    fn rejects_truncated_segments_array() {
        let mut bytes = header(100, 200, HAS_SEGMENTS | HAS_POINTS);
        bytes.resize(HEADER_SIZE + 50, 0);
        expect_error(&bytes, &["100 strands", "200 bytes", "only 50 bytes"]);
    }

    #[test]
    fn rejects_trailing_bytes() {
        let mut bytes = encode_hair(&sample());
        bytes.extend_from_slice(&[0; 7]);
        expect_error(&bytes, &["7 trailing bytes", "counts or flags"]);
    }

    #[test]
    fn huge_counts_do_not_overflow_or_allocate() {
        for flags in [HAS_POINTS, 0x1f, 0xffff_ffff] {
            let bytes = header(u32::MAX, u32::MAX, flags);
            expect_error(&bytes, &["header says 4294967295", "holds only 0"]);
        }
        // Default segments near u32::MAX without a segments array.
        let mut bytes = header(u32::MAX, 0, HAS_POINTS);
        bytes[16..20].copy_from_slice(&u32::MAX.to_le_bytes());
        expect_error(&bytes, &["4294967295 strands", "default 4294967295 segments", "declares 0 points"]);
    }

    #[test]
    fn rejects_segments_past_the_point_count() {
        let mut bytes = header(2, 3, HAS_SEGMENTS | HAS_POINTS);
        for s in [1u16, 5] {
            bytes.extend_from_slice(&s.to_le_bytes());
        }
        push_f32s(&mut bytes, &[0.0; 9]);
        expect_error(&bytes, &["run past the 3 points", "strand 1 of 2"]);
    }

    #[test]
    fn rejects_segments_short_of_the_point_count() {
        let mut bytes = header(2, 5, HAS_SEGMENTS | HAS_POINTS);
        for s in [1u16, 1] {
            bytes.extend_from_slice(&s.to_le_bytes());
        }
        push_f32s(&mut bytes, &[0.0; 15]);
        expect_error(&bytes, &["account for only 4 of the 5 points"]);
    }

    #[test]
    fn rejects_default_segments_mismatch() {
        let mut bytes = header(2, 5, HAS_POINTS);
        push_f32s(&mut bytes, &[0.0; 15]);
        expect_error(&bytes, &["no segments array", "default 1 segments (4 points", "declares 5 points"]);
    }

    /// Encodes `sample()` with `edit` applied (bypassing write_hair's checks) and returns the
    /// parse error message.
    fn error_after(edit: impl FnOnce(&mut StrandSet), expect: &[&str]) {
        let mut s = with_extras(sample());
        edit(&mut s);
        expect_error(&encode_hair(&s), expect);
    }

    #[test]
    fn rejects_non_finite_points() {
        error_after(|s| s.points[3][1] = f32::NAN, &["point 3 (strand 2)", "non-finite coordinate", "NaN"]);
        error_after(|s| s.points[0][2] = f32::INFINITY, &["point 0 (strand 0)", "inf"]);
    }

    #[test]
    fn rejects_bad_thickness() {
        error_after(|s| s.points[2][3] = -0.5, &["point 2 (strand 1)", "thickness -1", ">= 0"]);
        error_after(|s| s.points[4][3] = f32::NAN, &["point 4", "thickness NaN"]);
        error_after(|s| s.points[4][3] = f32::MAX, &["point 4", "thickness inf"]);
        let mut bytes = header(1, 2, HAS_POINTS);
        push_f32s(&mut bytes, &[0.0; 6]);
        bytes[20..24].copy_from_slice(&(-1.0f32).to_le_bytes());
        expect_error(&bytes, &["default thickness is -1", "no thickness array"]);
    }

    #[test]
    fn rejects_bad_transparency() {
        // Opacity -0.5 is written as transparency 1.5.
        error_after(|s| s.opacity.as_mut().unwrap()[5] = -0.5, &["point 5", "transparency 1.5", "outside [0, 1]"]);
        error_after(|s| s.opacity.as_mut().unwrap()[0] = f32::NAN, &["point 0", "transparency NaN"]);
        let mut bytes = header(1, 2, HAS_POINTS);
        push_f32s(&mut bytes, &[0.0; 6]);
        bytes[24..28].copy_from_slice(&f32::NAN.to_le_bytes());
        expect_error(&bytes, &["default transparency is NaN", "no transparency array"]);
    }

    #[test]
    fn rejects_bad_colour() {
        error_after(|s| s.colors.as_mut().unwrap()[7][1] = f32::NAN, &["point 7 (strand 2)", "colour (", "NaN"]);
        error_after(|s| s.colors.as_mut().unwrap()[1][0] = -1.0, &["point 1", "colour (-1,"]);
    }

    #[test]
    fn read_names_a_missing_file() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("missing.hair");
        let msg = read_hair(&path).unwrap_err().to_string();
        assert!(msg.contains("missing.hair") && msg.contains("could not open the file"), "{msg}");
    }

    #[test]
    fn write_refuses_unreadable_sets() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("out.hair");
        let mut s = sample();
        s.points[1][0] = f32::NAN;
        let msg = write_hair(&path, &s).unwrap_err().to_string();
        assert!(msg.contains("out.hair") && msg.contains("point 1 (strand 0) has a non-finite position"), "{msg}");

        let mut s = sample();
        s.push_strand((0..MAX_POINTS_PER_STRAND + 1).map(|_| (Vec3::ZERO, 0.1)));
        let msg = write_hair(&path, &s).unwrap_err().to_string();
        assert!(msg.contains("strand 4 has 65537 points"), "{msg}");

        let mut s = with_extras(sample());
        s.opacity.as_mut().unwrap()[2] = 1.5;
        let msg = write_hair(&path, &s).unwrap_err().to_string();
        assert!(msg.contains("opacity 1.5"), "{msg}");
        assert!(!path.exists(), "nothing is written on refusal");
    }

    #[test]
    fn writes_the_longest_strand_allowed() {
        let mut s = StrandSet::new();
        s.push_strand((0..MAX_POINTS_PER_STRAND).map(|i| (Vec3::new(i as f32, 0.0, 0.0), 0.1)));
        let back = parse_hair(&encode_hair(&s), Path::new("long.hair")).unwrap();
        assert_eq!(back.offsets, vec![0, MAX_POINTS_PER_STRAND as u32]);
    }

    /// Properties every successfully parsed set must have.
    fn assert_sane(s: &StrandSet) {
        assert!(s.points.iter().all(|p| p.iter().all(|c| c.is_finite()) && p[3] >= 0.0));
        assert_eq!(s.offsets.first(), Some(&0));
        assert!(s.offsets.windows(2).all(|w| w[0] < w[1]));
        assert_eq!(*s.offsets.last().unwrap() as usize, s.points.len());
        if let Some(c) = &s.colors {
            assert_eq!(c.len(), s.points.len());
        }
        if let Some(o) = &s.opacity {
            assert_eq!(o.len(), s.points.len());
            assert!(o.iter().all(|o| (0.0..=1.0).contains(o)));
        }
    }

    fn valid_file() -> Vec<u8> {
        let mut s = StrandSet::new();
        s.push_strand([(Vec3::ZERO, 0.1), (Vec3::ONE, 0.2), (Vec3::X, 0.3)]);
        s.push_strand([(Vec3::Y, 0.0)]);
        s.push_strand([(Vec3::Z, 0.05), (Vec3::NEG_ONE, 0.05)]);
        encode_hair(&with_extras(s))
    }

    /// Random valid sets: 0 to 8 strands of 1 to 12 points, with or without each optional array.
    fn strand_sets() -> impl Strategy<Value = StrandSet> {
        let point = (prop::array::uniform3(-1e6f32..1e6), 0f32..1.0, prop::array::uniform3(0f32..4.0), 0f32..=1.0);
        let strand = prop::collection::vec(point, 1..12);
        (prop::collection::vec(strand, 0..8), any::<bool>(), any::<bool>()).prop_map(|(strands, colors, opacity)| {
            let mut s = StrandSet::new();
            let (mut c, mut o) = (Vec::new(), Vec::new());
            for strand in strands {
                s.push_strand(strand.iter().map(|(p, r, _, _)| (Vec3::from(*p), *r)));
                c.extend(strand.iter().map(|(_, _, rgb, _)| *rgb));
                o.extend(strand.iter().map(|(_, _, _, a)| *a));
            }
            s.colors = colors.then_some(c);
            s.opacity = opacity.then_some(o);
            s
        })
    }

    proptest! {
        #[test]
        fn encoding_round_trips(s in strand_sets()) {
            let back = parse_hair(&encode_hair(&s), Path::new("prop.hair")).unwrap();
            prop_assert_eq!(&back.points, &s.points);
            prop_assert_eq!(&back.offsets, &s.offsets);
            prop_assert_eq!(&back.colors, &s.colors);
            prop_assert_eq!(back.opacity.is_some(), s.opacity.is_some());
            for (a, b) in back.opacity.iter().flatten().zip(s.opacity.iter().flatten()) {
                prop_assert!((a - b).abs() < 1e-6);
            }
        }

        #[test]
        fn random_bytes_never_panic(mut bytes in proptest::collection::vec(any::<u8>(), 0..400), signed in any::<bool>()) {
            if signed && bytes.len() >= 4 {
                // Most random data fails at the signature; get past it half the time.
                bytes[..4].copy_from_slice(SIGNATURE);
            }
            if let Ok(s) = parse_hair(&bytes, Path::new("random.hair")) {
                assert_sane(&s);
            }
        }

        #[test]
        fn mutated_files_never_panic(
            flips in proptest::collection::vec((any::<proptest::sample::Index>(), 0u8..8), 0..8),
            words in proptest::collection::vec((any::<proptest::sample::Index>(), any::<u32>()), 0..3),
            truncate in proptest::option::of(any::<proptest::sample::Index>()),
        ) {
            let mut bytes = valid_file();
            for (at, bit) in flips {
                let i = at.index(bytes.len());
                bytes[i] ^= 1 << bit;
            }
            // Whole random words, aimed at the header fields half of the time.
            for (at, value) in words {
                let i = at.index(bytes.len() / 4) * 4;
                let i = if value & 1 == 0 { i % 40 } else { i };
                bytes[i..i + 4].copy_from_slice(&value.to_le_bytes());
            }
            if let Some(at) = truncate {
                bytes.truncate(at.index(bytes.len() + 1));
            }
            if let Ok(s) = parse_hair(&bytes, Path::new("mutated.hair")) {
                assert_sane(&s);
            }
        }
    }
}
