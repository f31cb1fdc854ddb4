//! Throughput benchmark: BVH build time, closest-hit (primary) and any-hit (shadow) rays
//! per second, and memory per hair segment, measured on a prepared world.

use crate::accel::{Accel, Shape};
use crate::math::rng::PixelSampler;
use crate::scene::World;
use glam::Vec3;
use rayon::prelude::*;
use std::time::{Duration, Instant};

/// Figures of one benchmark run.
#[derive(Clone, Debug)]
pub struct BenchReport {
    /// Threads used for the ray measurements.
    pub threads: usize,
    /// Camera rays traced.
    pub primary_rays: u64,
    /// Time to trace them.
    pub primary_time: Duration,
    /// Shadow rays traced (one per primary hit, towards the first light).
    pub shadow_rays: u64,
    /// Time to trace them.
    pub shadow_time: Duration,
}

impl BenchReport {
    /// Primary rays per second.
    pub fn primary_rate(&self) -> f64 {
        self.primary_rays as f64 / self.primary_time.as_secs_f64()
    }
    /// Shadow rays per second.
    pub fn shadow_rate(&self) -> f64 {
        self.shadow_rays as f64 / self.shadow_time.as_secs_f64()
    }
}

/// Memory of the hair in a scene: points, BVHs, and segments.
#[derive(Clone, Copy, Debug, Default)]
pub struct HairMemory {
    /// Hair segments.
    pub segments: u64,
    /// Bytes of strand arrays (points, offsets, colours).
    pub strand_bytes: u64,
    /// Bytes of the strand sets' BVHs.
    pub bvh_bytes: u64,
}

impl HairMemory {
    /// Measures the strand sets of `accel`.
    pub fn of(accel: &Accel) -> HairMemory {
        let mut m = HairMemory::default();
        for o in &accel.objects {
            if let Shape::Strands(s) = &o.shape {
                m.segments += s.segment_count() as u64;
                m.strand_bytes += s.memory_bytes() as u64;
                m.bvh_bytes += o.bvh().memory_bytes() as u64;
            }
        }
        m
    }

    /// Bytes per segment, strands and BVH together.
    pub fn bytes_per_segment(&self) -> f64 {
        (self.strand_bytes + self.bvh_bytes) as f64 / self.segments.max(1) as f64
    }
}

/// Traces the world's camera rays (every pixel, `spp` jittered samples, closest hit), then
/// one shadow ray per hit towards the direction of the first light, on the current rayon
/// pool. Shading is not measured.
pub fn trace_rays(world: &World, threads: usize) -> BenchReport {
    let (w, h, spp) = (world.settings.width, world.settings.height, world.settings.spp);
    let light_dir =
        world.lights.iter().find_map(|l| l.sample(Vec3::ZERO, None, (0.5, 0.5)).map(|s| s.dir)).unwrap_or(Vec3::Y);
    let start = Instant::now();
    let hits: Vec<Vec<Vec3>> = (0..h)
        .into_par_iter()
        .map(|y| {
            let mut row = Vec::new();
            for x in 0..w {
                for s in 0..spp {
                    let (jx, jy) = PixelSampler::new(world.settings.seed, x, y, s).next_2d();
                    let ray = world.camera.ray(x as f32 + jx, y as f32 + jy);
                    if let Some(hit) = world.accel.intersect(&ray) {
                        row.push(ray.at(hit.t));
                    }
                }
            }
            row
        })
        .collect();
    let primary_time = start.elapsed();
    let start = Instant::now();
    let shadow_rays: u64 = hits
        .par_iter()
        .map(|row| {
            for p in row {
                // A fixed relative offset is enough for a throughput measurement.
                let origin = *p + light_dir * (1e-4 * (1.0 + p.abs().max_element()));
                std::hint::black_box(world.accel.occluded(origin, light_dir, f32::INFINITY, None));
            }
            row.len() as u64
        })
        .sum();
    let shadow_time = start.elapsed();
    BenchReport { threads, primary_rays: (w * h * spp) as u64, primary_time, shadow_rays, shadow_time }
}
