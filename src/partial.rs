//! Parts of a render kept in files: checkpoints, interrupted renders and farm tiles.
//!
//! All three are EXR files with tress's usual channels (see [`crate::film`]) whose data
//! window is the part of the image they cover, and these header attributes:
//!
//! | attribute | value |
//! | --- | --- |
//! | `tressStatus` | `complete`, or `partial` when some tiles are missing |
//! | `tressTiles` | the finished 16x16 tiles of the data window, numbered row by row, as ranges (`0-15,17`) |
//! | `tressTileSize` | `16` |
//! | `tressRender` | a fingerprint of everything that decides the pixels (scene, geometry, settings, frame) |
//! | `tressTile` | `I/N` for the farm tile `I` of `N` (bands of rows, see [`Region::band`]) |
//! | `tressChecksum` | a hash of the tile list and every pixel, so an edited file is refused rather than resumed |
//!
//! Pixels of unfinished tiles are empty: black, coverage 0, depth `+inf`, ids -1. Because
//! every pixel depends only on (seed, pixel, sample), a render resumed from a checkpoint and
//! tiles merged into one image are bit for bit the single uninterrupted render.

use crate::accel::Shape;
use crate::error::LoadError;
use crate::film::{decode_exr, write_image_part, Film, OutputError, Region};
use crate::render::{tile_count_of, TileMask, TiledFilm, TILE};
use crate::world::World;
use std::hash::{Hash, Hasher};
use std::path::{Path, PathBuf};
use std::sync::Mutex;
use std::time::{Duration, Instant};

const STATUS: &str = "tressStatus";
const TILES: &str = "tressTiles";
const TILE_SIZE: &str = "tressTileSize";
const RENDER: &str = "tressRender";
const FARM_TILE: &str = "tressTile";
const CHECKSUM: &str = "tressChecksum";

/// A part of a render with what identifies it.
#[derive(Clone, Debug, PartialEq)]
pub struct Partial {
    /// The pixels of the part and its finished tiles.
    pub state: TiledFilm,
    /// Width and height of the whole image.
    pub full: (u32, u32),
    /// [`fingerprint`] of the render it belongs to.
    pub fingerprint: u64,
    /// Which farm tile it is, (I, N), if it is one.
    pub farm_tile: Option<(u32, u32)>,
}

impl Partial {
    /// True when every tile is finished.
    pub fn is_complete(&self) -> bool {
        self.state.done.is_full()
    }

    /// Writes the part to an EXR file, atomically.
    pub fn save(&self, path: &Path) -> Result<(), OutputError> {
        let status = if self.is_complete() { "complete" } else { "partial" };
        let tiles = self.state.done.to_ranges();
        let render = format!("{:016x}", self.fingerprint);
        let tile_size = TILE.to_string();
        let farm = self.farm_tile.map(|(i, n)| format!("{i}/{n}"));
        let checksum = format!("{:016x}", checksum(&tiles, &self.state.film));
        let mut attributes = vec![
            (STATUS, status),
            (TILES, tiles.as_str()),
            (TILE_SIZE, &tile_size),
            (RENDER, &render),
            (CHECKSUM, &checksum),
        ];
        if let Some(farm) = &farm {
            attributes.push((FARM_TILE, farm));
        }
        let r = self.state.region;
        write_image_part(path, &self.state.film, (r.x, r.y), self.full, &attributes)
    }

    /// Reads a part from an EXR file written by [`Partial::save`].
    pub fn load(path: &Path) -> Result<Partial, LoadError> {
        let bytes = crate::input_file::read(path, crate::input_file::Kind::PartialImage)?;
        Partial::decode(&bytes, path)
    }

    /// Decodes the bytes of a file written by [`Partial::save`]; `path` is for messages.
    pub fn decode(bytes: &[u8], path: &Path) -> Result<Partial, LoadError> {
        let exr = decode_exr(bytes, path)?;
        let invalid = |m: String| LoadError::invalid(path, m);
        let attribute = |name: &str| {
            exr.attributes
                .iter()
                .find(|(n, _)| n == name)
                .map(|(_, v)| v.as_str())
                .ok_or_else(|| invalid(format!("no `{name}` attribute: not a tile or checkpoint written by tress")))
        };
        if attribute(TILE_SIZE)? != TILE.to_string() {
            return Err(invalid(format!("its tiles are not {TILE} pixels square")));
        }
        let fingerprint = u64::from_str_radix(attribute(RENDER)?, 16)
            .map_err(|_| invalid(format!("`{RENDER}` is not a fingerprint")))?;
        let region = Region { x: exr.at.0, y: exr.at.1, width: exr.film.width, height: exr.film.height };
        let done = TileMask::from_ranges(attribute(TILES)?, tile_count_of(region)).map_err(invalid)?;
        let written = u64::from_str_radix(attribute(CHECKSUM)?, 16)
            .map_err(|_| invalid(format!("`{CHECKSUM}` is not a checksum")))?;
        if written != checksum(attribute(TILES)?, &exr.film) {
            return Err(invalid(format!(
                "its tile list or pixels changed after tress wrote it (`{CHECKSUM}` does not match): render it afresh"
            )));
        }
        let complete = match attribute(STATUS)? {
            "complete" => true,
            "partial" => false,
            other => return Err(invalid(format!("unknown `{STATUS}` `{other}`"))),
        };
        if complete != done.is_full() {
            return Err(invalid(format!("`{STATUS}` contradicts `{TILES}`")));
        }
        let farm_tile = match exr.attributes.iter().find(|(n, _)| n == FARM_TILE) {
            None => None,
            Some((_, v)) => Some(parse_farm_tile(v).map_err(invalid)?),
        };
        if let Some((i, n)) = farm_tile {
            let band = Region::band(exr.full.0, exr.full.1, i, n).map_err(invalid)?;
            if band != region {
                return Err(invalid(format!("its data window is not the rows of tile {i}/{n}")));
            }
        }
        Ok(Partial { state: TiledFilm { region, film: exr.film, done }, full: exr.full, fingerprint, farm_tile })
    }

    /// Whether the parts fit together: film of the region's size, region inside the image,
    /// one mask entry per tile. [`Partial::decode`] only returns consistent parts.
    pub fn is_consistent(&self) -> bool {
        let s = &self.state;
        (s.film.width, s.film.height) == (s.region.width, s.region.height)
            && s.film.pixels.len() == s.region.pixel_count()
            && Region::full(self.full.0, self.full.1).contains(&s.region)
            && s.done.len() == tile_count_of(s.region)
    }
}

/// The hash [`Partial::save`] stores under `tressChecksum`: of the tile list as written and
/// every pixel's bits, so a file whose list claims tiles that were never rendered (black)
/// is refused by [`Partial::decode`].
fn checksum(tiles: &str, film: &Film) -> u64 {
    let mut h = std::collections::hash_map::DefaultHasher::new();
    tiles.hash(&mut h);
    for p in &film.pixels {
        let scalars = [
            p.coverage,
            p.depth,
            p.object_id,
            p.strand_id,
            p.strand_along,
            p.root_uv[0],
            p.root_uv[1],
            p.clump_id,
            p.strand_random,
            p.lod_level,
            p.samples,
        ];
        for x in p.color.to_array().into_iter().chain(p.normal.to_array()).chain(scalars) {
            h.write_u32(x.to_bits());
        }
    }
    h.finish()
}

/// The longest interval between checkpoints, in minutes (a year): longer is never.
pub const MAX_CHECKPOINT_MINUTES: f64 = 525_600.0;

/// Parses `--checkpoint-every`: a positive number of minutes up to
/// [`MAX_CHECKPOINT_MINUTES`].
pub fn parse_checkpoint_minutes(text: &str) -> Result<f64, String> {
    match text.trim().parse::<f64>() {
        Ok(m) if m > 0.0 && m <= MAX_CHECKPOINT_MINUTES => Ok(m),
        _ => Err(format!("`{text}` is not a number of minutes above 0 and at most {MAX_CHECKPOINT_MINUTES}")),
    }
}

/// Refuses files the render writes that are one file under two names (`x.exr`, `./x.exr`,
/// a symbolic or hard link): `names` are (how the file was given, e.g. `--checkpoint`,
/// path). Writing one would overwrite the other, and removing the checkpoint once the
/// image is written would delete the image.
pub fn check_distinct(names: &[(&str, &Path)]) -> Result<(), String> {
    for (i, (a_name, a)) in names.iter().enumerate() {
        for (b_name, b) in &names[i + 1..] {
            if same_file(a, b) {
                return Err(format!(
                    "{a_name} {} and {b_name} {} are the same file: give them different names",
                    a.display(),
                    b.display()
                ));
            }
        }
    }
    Ok(())
}

/// Whether two paths name one file: the same device and inode when both exist, else the
/// same directory (symbolic links resolved) and name.
pub fn same_file(a: &Path, b: &Path) -> bool {
    #[cfg(unix)]
    {
        use std::os::unix::fs::MetadataExt;
        if let (Ok(x), Ok(y)) = (std::fs::metadata(a), std::fs::metadata(b)) {
            return (x.dev(), x.ino()) == (y.dev(), y.ino());
        }
    }
    let resolved = |p: &Path| -> Option<PathBuf> {
        if let Ok(p) = std::fs::canonicalize(p) {
            return Some(p);
        }
        let dir = match p.parent() {
            Some(d) if !d.as_os_str().is_empty() => d,
            _ => Path::new("."),
        };
        Some(std::fs::canonicalize(dir).ok()?.join(p.file_name()?))
    };
    match (resolved(a), resolved(b)) {
        (Some(x), Some(y)) => x == y,
        _ => a == b,
    }
}

/// Parses `I/N` with `I < N`.
pub fn parse_farm_tile(text: &str) -> Result<(u32, u32), String> {
    let bad = || format!("`{text}` is not a tile I/N with 0 <= I < N");
    let (i, n) = text.split_once('/').ok_or_else(bad)?;
    let (i, n) = (i.trim().parse::<u32>().map_err(|_| bad())?, n.trim().parse::<u32>().map_err(|_| bad())?);
    if i >= n {
        return Err(bad());
    }
    Ok((i, n))
}

/// A fingerprint of everything that decides a render's pixels: camera, settings (but the
/// thread count, which does not change them), lights, materials and every number of the
/// geometry. Parts of one render share it; a checkpoint or tile of another render, or of
/// another build of tress, has another. (`DefaultHasher` with its fixed keys: stable within
/// a build, which is all a checkpoint needs.)
pub fn fingerprint(world: &World) -> u64 {
    let mut h = std::collections::hash_map::DefaultHasher::new();
    env!("CARGO_PKG_VERSION").hash(&mut h);
    let settings = crate::world::RenderSettings { threads: 0, ..world.settings.clone() };
    format!("{:?}{settings:?}{:?}{:?}", world.camera, world.lights, world.materials).hash(&mut h);
    let floats = |h: &mut std::collections::hash_map::DefaultHasher, v: &mut dyn Iterator<Item = f32>| {
        v.for_each(|x| h.write_u32(x.to_bits()));
    };
    for (i, o) in world.accel.objects.iter().enumerate() {
        o.material.hash(&mut h);
        // Only where set, so the scenes without flags keep their fingerprints.
        let visibility = world.accel.visibility(i as u32);
        if visibility != crate::accel::Visibility::default() {
            format!("{visibility:?}").hash(&mut h);
        }
        match &o.shape {
            Shape::Mesh(m) => {
                floats(&mut h, &mut m.positions.iter().flat_map(|p| p.to_array()));
                floats(&mut h, &mut m.normals.iter().flatten().flat_map(|p| p.to_array()));
                floats(&mut h, &mut m.uvs.iter().flatten().flatten().copied());
                m.indices.hash(&mut h);
            }
            Shape::Strands(s) => {
                floats(&mut h, &mut s.points.iter().flatten().copied());
                s.offsets.hash(&mut h);
                floats(&mut h, &mut s.colors.iter().flatten().flatten().copied());
                floats(&mut h, &mut s.opacity.iter().flatten().copied());
                format!("{:?}", s.strand_info).hash(&mut h);
                // Which file strand each stored one is: per-strand random values follow it.
                s.file_order.hash(&mut h);
            }
            #[allow(unreachable_patterns)]
            other => format!("{other:?}").hash(&mut h),
        }
    }
    h.finish()
}

/// Saves a render's state to a checkpoint file every so often, from whichever worker
/// finishes a tile when one is due (the others carry on rendering).
pub struct Checkpointer {
    path: PathBuf,
    every: Duration,
    template: Partial,
    last: Mutex<Instant>,
}

impl Checkpointer {
    /// Saves to `path` every `every`, as parts like `template` (whose state is replaced).
    pub fn new(path: PathBuf, every: Duration, template: Partial) -> Checkpointer {
        Checkpointer { path, every, template, last: Mutex::new(Instant::now()) }
    }

    /// The checkpoint file.
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// Saves `state` if a checkpoint is due and no other thread is saving one; `None` when
    /// nothing was due.
    pub fn maybe_save(&self, state: &Mutex<TiledFilm>) -> Option<Result<(), OutputError>> {
        let mut last = self.last.try_lock().ok()?;
        if last.elapsed() < self.every {
            return None;
        }
        let snapshot = state.lock().unwrap_or_else(|e| e.into_inner()).clone();
        let result = self.save(snapshot);
        *last = Instant::now();
        Some(result)
    }

    /// Saves `state` now.
    pub fn save(&self, state: TiledFilm) -> Result<(), OutputError> {
        Partial { state, ..self.template.clone() }.save(&self.path)
    }
}

/// Why farm tiles cannot be merged.
#[derive(Debug, thiserror::Error)]
#[error("{0}")]
pub struct MergeError(pub String);

/// Assembles the farm tiles `0/N` to `N-1/N` of one render (in any order) into the whole
/// image. Refuses partial tiles, tiles of different renders, and missing or repeated tiles.
pub fn merge(parts: &[(PathBuf, Partial)]) -> Result<Film, MergeError> {
    let err = |m: String| Err(MergeError(m));
    let Some((first_path, first)) = parts.first() else { return err("no tiles to merge".into()) };
    let Some((_, n)) = first.farm_tile else {
        return err(format!("{}: not a farm tile (rendered without --tile)", first_path.display()));
    };
    let mut seen: Vec<Option<&Path>> = vec![None; n as usize];
    for (path, p) in parts {
        let name = path.display();
        let Some((i, count)) = p.farm_tile else { return err(format!("{name}: not a farm tile")) };
        if count != n {
            return err(format!("{name} is tile {i}/{count}, but {} is one of {n}", first_path.display()));
        }
        if p.fingerprint != first.fingerprint || p.full != first.full {
            return err(format!(
                "{name} is from another render than {} (scene, settings or frame differ)",
                first_path.display()
            ));
        }
        if !p.is_complete() {
            return err(format!(
                "{name}: tile {i}/{n} is partial ({} of {} tiles): finish it by rendering it again with its checkpoint",
                p.state.done.count(),
                p.state.done.len()
            ));
        }
        if let Some(other) = seen[i as usize].replace(path) {
            return err(format!("tile {i}/{n} is given twice: {} and {name}", other.display()));
        }
    }
    let missing: Vec<String> =
        seen.iter().enumerate().filter(|(_, s)| s.is_none()).map(|(i, _)| i.to_string()).collect();
    if !missing.is_empty() {
        return err(format!("tiles {} of {n} are missing", missing.join(", ")));
    }
    let mut film = Film::new(first.full.0, first.full.1);
    for (_, p) in parts {
        film.paste(p.state.region.x, p.state.region.y, &p.state.film);
    }
    Ok(film)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::film::Pixel;

    fn part(i: u32, n: u32, fingerprint: u64) -> Partial {
        let region = Region::band(20, 35, i, n).unwrap();
        let mut state = TiledFilm::new(region);
        for (k, p) in state.film.pixels.iter_mut().enumerate() {
            *p = Pixel { coverage: (region.y * 20) as f32 + k as f32, ..*p };
        }
        (0..state.done.len()).for_each(|t| state.done.set(t));
        Partial { state, full: (20, 35), fingerprint, farm_tile: Some((i, n)) }
    }

    #[test]
    fn parts_round_trip_through_files() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("t.exr");
        let mut p = part(1, 3, 0xdead_beef_0123_4567);
        p.state.done = TileMask::from_ranges("1", p.state.done.len()).unwrap();
        p.save(&path).unwrap();
        assert_eq!(Partial::load(&path).unwrap(), p);
        p.state.done = TileMask::from_ranges("0-1", 2).unwrap();
        p.save(&path).unwrap();
        let back = Partial::load(&path).unwrap();
        assert!(back.is_complete() && back.is_consistent());
        assert_eq!(back, p);
    }

    #[test]
    fn merge_assembles_tiles_in_any_order() {
        let dir = tempfile::tempdir().unwrap();
        let parts: Vec<_> = [2, 0, 1].iter().map(|&i| (dir.path().join(format!("{i}.exr")), part(i, 3, 7))).collect();
        let film = merge(&parts).unwrap();
        assert_eq!((film.width, film.height), (20, 35));
        assert!(film.pixels.iter().enumerate().all(|(k, p)| p.coverage == k as f32));
    }

    #[test]
    fn merge_refuses_what_does_not_fit() {
        let p = |i, n, f| (PathBuf::from(format!("t{i}.exr")), part(i, n, f));
        let e = |parts: &[(PathBuf, Partial)]| merge(parts).unwrap_err().to_string();
        assert!(e(&[p(0, 2, 1)]).contains("tiles 1 of 2 are missing"));
        assert!(e(&[p(0, 2, 1), p(0, 2, 1)]).contains("given twice"));
        assert!(e(&[p(0, 2, 1), p(1, 2, 9)]).contains("another render"));
        assert!(e(&[p(0, 2, 1), p(1, 3, 1)]).contains("one of 2"));
        let mut partial = p(1, 2, 1);
        partial.1.state.done = TileMask::new(partial.1.state.done.len());
        assert!(e(&[p(0, 2, 1), partial]).contains("partial (0 of 4 tiles)"));
        assert!(e(&[]).contains("no tiles"));
    }

    #[test]
    fn farm_tiles_parse() {
        assert_eq!(parse_farm_tile("3/8"), Ok((3, 8)));
        for bad in ["8/8", "1", "a/2", "-1/2", "1/0"] {
            assert!(parse_farm_tile(bad).is_err(), "{bad}");
        }
    }
}
