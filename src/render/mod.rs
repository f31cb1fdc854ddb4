//! Rendering: image tiles on all cores, each pixel's samples through an integrator.
//!
//! Random numbers come from (pixel, sample, dimension) only ([`PixelSampler`]), and each
//! pixel is written by exactly one task, so the image is bit-identical for any thread count.

mod adaptive;
mod direct;
mod environment;
mod final_gather;
mod interaction;
mod irradiance_cache;
mod path;
mod shadow;
mod tiled;
mod tracer;

pub use direct::BLEND_TRANSMITTANCE;
pub use interaction::FirstHit;
pub use irradiance_cache::IrradianceCache;
pub use shadow::PixelShadows;
pub use tiled::{render_tiles, tile_count_of, AfterTile, Control, TileMask, TiledFilm};
pub use tracer::{CameraHint, Counters, Tracer};

use crate::accel::Hit;
use crate::film::{Film, Pixel};
use crate::math::rng::PixelSampler;
use crate::math::{Color, Ray, PACKET};
use crate::world::World;
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
    /// Records in the final gather's irradiance cache (0 without one).
    pub irradiance_records: u64,
}

/// Something told of progress: called with the tiles finished since the last call and the
/// rays they traced.
pub trait Progress: Sync {
    /// `tiles` more tiles are done, which traced `rays` rays.
    fn advance(&self, tiles: u64, rays: u64);
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

/// Per-ray values of one batch of a pixel's samples: on the stack up to a packet's worth.
type PixelRays<T> = smallvec::SmallVec<[T; PACKET]>;

/// The closest hits of a pixel's camera rays, traced as packets ([`crate::accel::Accel::intersect_packet`]:
/// the same hits as one by one, for less work), when every integrator starts with exactly
/// that query (in scenes without semi-transparent strands) and there are enough rays
/// ([`shadow::MIN_PACKET`]). `None` otherwise.
fn camera_hits(world: &World, rays: &[Ray]) -> Option<PixelRays<Option<Hit>>> {
    if world.accel.has_transparency() || rays.len() < shadow::MIN_PACKET {
        return None;
    }
    let mut hits: PixelRays<Option<Hit>> = smallvec::smallvec![None; rays.len()];
    rays.chunks(PACKET).zip(hits.chunks_mut(PACKET)).for_each(|(r, h)| world.accel.intersect_packet(r, h));
    Some(hits)
}

/// All samples of one pixel, placed by the pixel filter (filter importance sampling, so each
/// counts with weight 1); the AOVs come from the first sample that hit.
/// With adaptive sampling the pixel takes `min_spp` samples, then more in batches of
/// `min_spp` while they disagree ([`adaptive::Spread`]), up to `max_spp`; sample `s` is
/// the same whatever the batches, so a pixel refined to `n` samples equals a fixed-rate
/// render at `n`.
///
/// `shadows` holds the shadow rays of a batch of samples traced as packets (empty between
/// calls; one per task spares allocating its arrays per pixel).
fn render_pixel(tracer: &mut Tracer, (x, y): (u32, u32), shadows: &mut PixelShadows) -> Pixel {
    let world = tracer.world;
    let (min, max, threshold) = match world.settings.adaptive {
        Some(a) => (a.min_spp, a.max_spp, Some(a.threshold)),
        None => (world.settings.spp, world.settings.spp, None),
    };
    let mut pixel = Film::new(1, 1).pixels[0];
    let mut sum = Vec3::ZERO;
    let mut hits = 0u32;
    let mut spread = adaptive::Spread::default();
    let mut taken = 0;
    // Whether the previous sample met fur drawn semi-transparent for its level of detail first.
    let mut layers_first = false;
    while taken < max {
        let batch = min.min(max - taken);
        let (mut samplers, mut rays) = (PixelRays::<PixelSampler>::new(), PixelRays::<Ray>::new());
        for s in taken..taken + batch {
            let mut sampler = PixelSampler::new(world.settings.seed, x, y, s);
            let (jx, jy) = world.settings.filter.place(sampler.next_2d());
            rays.push(world.camera.ray(x as f32 + jx, y as f32 + jy));
            samplers.push(sampler);
        }
        let known = camera_hits(world, &rays);
        // With known hits, the batch's shadow rays are traced together once it is shaded:
        // colours are final only then, the AOVs are known at once.
        let (mut colors, mut keys) = (PixelRays::<Color>::new(), PixelRays::<Option<(u32, Option<u32>)>>::new());
        for (i, (ray, mut sampler)) in rays.iter().zip(samplers).enumerate() {
            let hint = match &known {
                Some(hits) => CameraHint::Hit { hit: hits[i], shadows: shadows.for_sample(i) },
                None if layers_first => CameraHint::LayersFirst,
                None => CameraHint::None,
            };
            let (color, first) = tracer.trace_camera_hinted(ray, hint, &mut sampler);
            layers_first = first.is_some_and(|f| {
                f.lod_level.is_some_and(|l| world.accel.objects[f.object as usize].lod_opacity(l) < 1.0)
            });
            colors.push(color);
            keys.push(first.map(|f| (f.object, f.strand)));
            if let Some(f) = first {
                if hits == 0 {
                    pixel.depth = f.t + world.camera.clip_start(ray.dir);
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
        shadows.trace(tracer, &mut colors);
        for (&color, &key) in colors.iter().zip(&keys) {
            let color = clamped(color, world.settings.max_sample_value);
            sum += color;
            spread.add(color, key);
        }
        taken += batch;
        if !threshold.is_some_and(|t| spread.needs_more(t)) {
            break;
        }
    }
    pixel.color = sum / taken as f32;
    pixel.coverage = hits as f32 / taken as f32;
    pixel.samples = taken as f32;
    pixel
}

/// `color` scaled down, hue kept, so that its largest channel is at most `max`: what
/// pbrt-v4's RGBFilm does to each sample before adding it to its pixel
/// (`maxComponentValue`; Pharr, Jakob and Humphreys, PBR 4th ed., section 5.4.5). Per
/// sample, so the image does not depend on how pixels are split between threads.
fn clamped(color: Color, max: f32) -> Color {
    let m = color.max_element();
    if m > max {
        color * (max / m)
    } else {
        color
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::accel::lod::LodParams;

    /// A pixel traced with packets (its camera rays, then its shadow rays light by light)
    /// gets the colour, bit for bit, of its samples traced one by one with every shadow ray
    /// traced at once: on the demo (hair, meshes, a distant light and the environment), and
    /// with opaque level of detail, whose shadow rays take their level from their cones.
    #[test]
    fn packets_render_pixels_as_single_rays_do() {
        for lod in [None, Some(LodParams::default())] {
            let world = crate::test_worlds::demo(3000, 1, (48, 36, 8), lod);
            assert!(!world.accel.has_transparency());
            let (mut hair, mut shadowed) = (0, 0);
            for (x, y) in (0..36).flat_map(|y| (0..48).map(move |x| (x, y))) {
                let mut tracer = Tracer::new(&world);
                let packed = render_pixel(&mut tracer, (x, y), &mut PixelShadows::default());
                let mut sum = Vec3::ZERO;
                for s in 0..8 {
                    let mut sampler = PixelSampler::new(world.settings.seed, x, y, s);
                    let (jx, jy) = world.settings.filter.place(sampler.next_2d());
                    let ray = world.camera.ray(x as f32 + jx, y as f32 + jy);
                    let (color, first) = tracer.trace_camera(&ray, &mut sampler);
                    sum += color;
                    hair += first.is_some_and(|f| f.strand.is_some()) as u32;
                    // Black where a hit's every shadow ray was blocked and nothing else lit it.
                    shadowed += (first.is_some() && color.max_element() < 0.05) as u32;
                }
                let single = sum / 8.0;
                assert_eq!(packed.color.to_array().map(f32::to_bits), single.to_array().map(f32::to_bits), "{x} {y}");
            }
            assert!(hair > 1000 && shadowed > 100, "the test needs hair and shadows: {hair}, {shadowed}");
        }
    }
}
