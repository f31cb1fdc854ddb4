//! Rendering part of an image, tile by tile, so a render can stop at any moment, be saved
//! and resumed, or be split over machines: every pixel depends only on (seed, pixel,
//! sample), so any set of tiles, rendered in any order or process, gives the same pixels.

use super::{render_pixel, Counters, IrradianceCache, PixelShadows, Progress, RenderStats, Tracer, TILE};
use crate::film::{Film, Region};
use crate::world::{Integrator, World};
use rayon::prelude::*;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Mutex;
use std::time::Instant;

/// A set of tile indices: which tiles of a region are finished.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TileMask {
    bits: Vec<u64>,
    len: u32,
}

impl TileMask {
    /// No tile of `len` done.
    pub fn new(len: u32) -> TileMask {
        TileMask { bits: vec![0; len.div_ceil(64) as usize], len }
    }

    /// Number of tiles the mask is about.
    pub fn len(&self) -> u32 {
        self.len
    }

    /// True when the mask is about no tile at all.
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// Marks tile `i` done.
    pub fn set(&mut self, i: u32) {
        self.bits[(i / 64) as usize] |= 1 << (i % 64);
    }

    /// Whether tile `i` is done.
    pub fn get(&self, i: u32) -> bool {
        self.bits[(i / 64) as usize] & (1 << (i % 64)) != 0
    }

    /// Number of tiles done.
    pub fn count(&self) -> u32 {
        self.bits.iter().map(|b| b.count_ones()).sum()
    }

    /// True when every tile is done.
    pub fn is_full(&self) -> bool {
        self.count() == self.len
    }

    /// The tiles done as comma-separated ranges, e.g. `0-15,17,20-31` (empty when none).
    pub fn to_ranges(&self) -> String {
        let mut out = Vec::new();
        let mut i = 0;
        while i < self.len {
            if !self.get(i) {
                i += 1;
                continue;
            }
            let start = i;
            while i < self.len && self.get(i) {
                i += 1;
            }
            out.push(if i - 1 == start { start.to_string() } else { format!("{start}-{}", i - 1) });
        }
        out.join(",")
    }

    /// Parses [`TileMask::to_ranges`] text for `len` tiles; ranges must ascend without
    /// overlapping and stay below `len`.
    pub fn from_ranges(text: &str, len: u32) -> Result<TileMask, String> {
        let mut mask = TileMask::new(len);
        let mut next = 0u64;
        for part in text.split(',').filter(|p| !p.is_empty()) {
            let (a, b) = part.split_once('-').unwrap_or((part, part));
            let number = |s: &str| s.parse::<u32>().map_err(|_| format!("`{part}` is not a tile range"));
            let (a, b) = (number(a)?, number(b)?);
            if u64::from(a) < next || b < a || b >= len {
                return Err(format!("tile range `{part}` is out of order or past the {len} tiles"));
            }
            (a..=b).for_each(|i| mask.set(i));
            next = u64::from(b) + 1;
        }
        Ok(mask)
    }
}

/// The pixels of a region of the image and which of its tiles are finished. Tiles are
/// [`TILE`] pixels square, numbered row by row from the region's top-left corner.
#[derive(Clone, Debug, PartialEq)]
pub struct TiledFilm {
    /// The region of the image this covers.
    pub region: Region,
    /// Its pixels (`region.width` x `region.height`); unfinished tiles hold empty pixels
    /// (black, coverage 0).
    pub film: Film,
    /// Finished tiles.
    pub done: TileMask,
}

impl TiledFilm {
    /// Nothing rendered yet.
    pub fn new(region: Region) -> TiledFilm {
        TiledFilm { region, film: Film::new(region.width, region.height), done: TileMask::new(tile_count_of(region)) }
    }

    /// Tile `t` of the region, in image coordinates.
    pub fn tile(&self, t: u32) -> Region {
        tile_of(self.region, t)
    }
}

/// Tile `t` of `region` (numbered row by row), in image coordinates.
fn tile_of(r: Region, t: u32) -> Region {
    let tiles_x = r.width.div_ceil(TILE);
    let (x, y) = ((t % tiles_x) * TILE, (t / tiles_x) * TILE);
    Region { x: r.x + x, y: r.y + y, width: TILE.min(r.width - x), height: TILE.min(r.height - y) }
}

/// Number of tiles in a region.
pub fn tile_count_of(region: Region) -> u32 {
    region.width.div_ceil(TILE) * region.height.div_ceil(TILE)
}

/// A hook called after each finished tile with the render's state.
pub type AfterTile<'a> = dyn Fn(&Mutex<TiledFilm>) + Sync + 'a;

/// What a tiled render is told and tells while it runs.
#[derive(Clone, Copy, Default)]
pub struct Control<'a> {
    /// Told of every finished tile.
    pub progress: Option<&'a dyn Progress>,
    /// When it becomes true, tiles in flight are abandoned (checked before every pixel) and
    /// no new tile starts; the result holds the tiles finished until then.
    pub cancel: Option<&'a AtomicBool>,
    /// Called after each finished tile with the state (for checkpoints); it may lock it.
    pub after_tile: Option<&'a AfterTile<'a>>,
}

/// Renders the tiles of `state` not yet done, on the current rayon pool, until all are done
/// or `control.cancel` is set. The world's settings give the whole image's size; the
/// region must lie inside it.
pub fn render_tiles(world: &World, state: TiledFilm, control: &Control) -> (TiledFilm, RenderStats) {
    let start = Instant::now();
    let todo: Vec<u32> = (0..state.done.len()).filter(|&t| !state.done.get(t)).collect();
    let cancelled = || control.cancel.is_some_and(|c| c.load(Ordering::Relaxed));
    let region = state.region;
    let shared = Mutex::new(state);
    // The irradiance cache's pre-pass covers the whole image whatever the tiles, so every
    // set of tiles reads the same cache.
    let mut pre_pass = Counters::default();
    let cache = match (world.settings.integrator, world.settings.irradiance_cache) {
        (Integrator::FinalGather, Some(settings)) if !todo.is_empty() => {
            Some(IrradianceCache::build(world, settings, &mut pre_pass))
        }
        _ => None,
    };
    let rays: u64 = todo
        .into_par_iter()
        .map(|t| {
            if cancelled() {
                return 0;
            }
            let tile = tile_of(region, t);
            let mut tracer = Tracer::with_cache(world, cache.as_ref());
            let mut shadows = PixelShadows::default();
            let mut pixels = Film::new(tile.width, tile.height);
            for (i, p) in pixels.pixels.iter_mut().enumerate() {
                if cancelled() {
                    return 0;
                }
                let (x, y) = (tile.x + i as u32 % tile.width, tile.y + i as u32 / tile.width);
                *p = render_pixel(&mut tracer, (x, y), &mut shadows);
            }
            {
                let mut s = lock(&shared);
                s.film.paste(tile.x - region.x, tile.y - region.y, &pixels);
                s.done.set(t);
            }
            if let Some(p) = control.progress {
                p.advance(1, tracer.counters.rays);
            }
            if let Some(after) = control.after_tile {
                after(&shared);
            }
            tracer.counters.rays
        })
        .sum();
    let state = shared.into_inner().unwrap_or_else(|e| e.into_inner());
    let irradiance_records = cache.as_ref().map_or(0, |c| c.len() as u64);
    (state, RenderStats { rays: rays + pre_pass.rays, elapsed: start.elapsed(), irradiance_records })
}

/// Locks the state; a panic elsewhere cannot leave it half-written (tiles are pasted whole
/// under the lock), so a poisoned lock is still usable.
fn lock(m: &Mutex<TiledFilm>) -> std::sync::MutexGuard<'_, TiledFilm> {
    m.lock().unwrap_or_else(|e| e.into_inner())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ranges_round_trip() {
        let mut m = TileMask::new(200);
        for i in [0, 1, 2, 5, 64, 65, 66, 130, 199] {
            m.set(i);
        }
        let text = m.to_ranges();
        assert_eq!(text, "0-2,5,64-66,130,199");
        assert_eq!(TileMask::from_ranges(&text, 200).unwrap(), m);
        assert_eq!(m.count(), 9);
        assert!(!m.is_full());
        assert_eq!(TileMask::from_ranges("", 3).unwrap(), TileMask::new(3));
        assert!(TileMask::from_ranges("0-2", 3).unwrap().is_full());
        for bad in ["0-3", "2-1", "1,0", "0-1,1", "x", "1-", "-1", "99999999999"] {
            assert!(TileMask::from_ranges(bad, 3).is_err(), "{bad}");
        }
    }

    #[test]
    fn tiles_cover_the_region_once() {
        let s = TiledFilm::new(Region { x: 5, y: 7, width: 40, height: 17 });
        assert_eq!(s.done.len(), 3 * 2);
        let mut covered = vec![0; 40 * 17];
        for t in 0..s.done.len() {
            let r = s.tile(t);
            assert!(s.region.contains(&r));
            for y in r.y..r.y + r.height {
                for x in r.x..r.x + r.width {
                    covered[((y - 7) * 40 + x - 5) as usize] += 1;
                }
            }
        }
        assert!(covered.iter().all(|&c| c == 1));
    }
}
