//! Rendering: image tiles on all cores, each pixel's samples through an integrator.
//!
//! Random numbers come from (pixel, sample, dimension) only ([`PixelSampler`]), and each
//! pixel is written by exactly one task, so the image is bit-identical for any thread count.

mod direct;

pub use direct::{trace, Counters};

use crate::film::{Film, Pixel};
use crate::math::rng::PixelSampler;
use crate::scene::World;
use glam::Vec3;
use rayon::prelude::*;
use std::time::{Duration, Instant};

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
    let start = Instant::now();
    let (w, h) = (world.settings.width, world.settings.height);
    let tiles_x = w.div_ceil(TILE);
    let tiles = tile_count(w, h) as u32;
    let results: Vec<(Vec<Pixel>, u64)> = (0..tiles)
        .into_par_iter()
        .map(|tile| {
            let (x0, y0) = ((tile % tiles_x) * TILE, (tile / tiles_x) * TILE);
            let mut counters = Counters::default();
            let mut pixels = Vec::with_capacity((TILE * TILE) as usize);
            for y in y0..(y0 + TILE).min(h) {
                for x in x0..(x0 + TILE).min(w) {
                    pixels.push(render_pixel(world, x, y, &mut counters));
                }
            }
            if let Some(p) = progress {
                p.advance(1);
            }
            (pixels, counters.rays)
        })
        .collect();
    let mut film = Film::new(w, h);
    let mut rays = 0;
    for (tile, (pixels, tile_rays)) in results.into_iter().enumerate() {
        let tile = tile as u32;
        let (x0, y0) = ((tile % tiles_x) * TILE, (tile / tiles_x) * TILE);
        let tw = (x0 + TILE).min(w) - x0;
        for (i, p) in pixels.into_iter().enumerate() {
            let (x, y) = (x0 + i as u32 % tw, y0 + i as u32 / tw);
            film.pixels[(y * w + x) as usize] = p;
        }
        rays += tile_rays;
    }
    (film, RenderStats { rays, elapsed: start.elapsed() })
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
                if let Some(sp) = f.strand_point {
                    pixel.strand_along = sp.along;
                    pixel.root_uv = sp.root_uv.unwrap_or([-1.0, -1.0]);
                    pixel.clump_id = sp.clump.map_or(-1.0, |c| c as f32);
                    pixel.strand_random = sp.random;
                }
                pixel.lod_level = f.lod_level.map_or(-1.0, |l| l as f32);
            }
            hits += 1;
        }
    }
    pixel.color = sum / spp as f32;
    pixel.coverage = hits as f32 / spp as f32;
    pixel
}
