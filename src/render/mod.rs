//! Rendering: image tiles on all cores, each pixel's samples through an integrator.
//!
//! Random numbers come from (pixel, sample, dimension) only ([`PixelSampler`]), and each
//! pixel is written by exactly one task, so the image is bit-identical for any thread count.

mod direct;
mod tiled;

pub use direct::{trace, Counters};
pub use tiled::{render_tiles, tile_count_of, AfterTile, Control, TileMask, TiledFilm};

use crate::film::{Film, Pixel};
use crate::math::rng::PixelSampler;
use crate::scene::World;
use glam::Vec3;
use std::time::Duration;

/// Side of the square image tiles rendered as one task.
pub const TILE: u32 = 16;

/// Totals of one render.
#[derive(Clone, Copy, Debug, Default)]
pub struct RenderStats {
    /// Rays traced: camera, shadow and specular.
    pub rays: u64,
    /// Wall-clock time of the render (not of preparing the scene).
    pub elapsed: Duration,
}

/// Something told of progress: called with the number of tiles finished since the last call.
pub trait Progress: Sync {
    /// `tiles` more tiles are done.
    fn advance(&self, tiles: u64);
}

impl Progress for indicatif::ProgressBar {
    fn advance(&self, tiles: u64) {
        self.inc(tiles);
    }
}

/// Number of tiles the image is cut into.
pub fn tile_count(width: u32, height: u32) -> u64 {
    (width.div_ceil(TILE) as u64) * (height.div_ceil(TILE) as u64)
}

/// Renders the world on the current rayon thread pool.
pub fn render(world: &World, progress: Option<&dyn Progress>) -> (Film, RenderStats) {
    let full = crate::film::Region::full(world.settings.width, world.settings.height);
    let (state, stats) = render_tiles(world, TiledFilm::new(full), &Control { progress, ..Control::default() });
    (state.film, stats)
}

/// All samples of one pixel, box-filtered; the AOVs come from the first sample that hit.
fn render_pixel(world: &World, x: u32, y: u32, counters: &mut Counters) -> Pixel {
    let spp = world.settings.spp;
    let mut pixel = Film::new(1, 1).pixels[0];
    let mut sum = Vec3::ZERO;
    let mut hits = 0u32;
    for s in 0..spp {
        let mut sampler = PixelSampler::new(world.settings.seed, x, y, s);
        let (jx, jy) = sampler.next_2d();
        let ray = world.camera.ray(x as f32 + jx, y as f32 + jy);
        let (color, first) = trace(world, &ray, 0, &mut sampler, counters);
        sum += color;
        if let Some(f) = first {
            if hits == 0 {
                pixel.depth = f.t;
                pixel.normal = f.normal;
                pixel.object_id = f.object as f32;
                pixel.strand_id = f.strand.map_or(-1.0, |s| s as f32);
            }
            hits += 1;
        }
    }
    pixel.color = sum / spp as f32;
    pixel.coverage = hits as f32 / spp as f32;
    pixel
}
