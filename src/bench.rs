//! Throughput benchmark, laid out to sit beside the Embree baseline in `bench/embree/`:
//! BVH build time, memory by part, and closest-hit (primary) and any-hit (shadow) rays per
//! second for given thread counts, by wall clock and by CPU time (the machine is shared,
//! so CPU-time rates are the steadier figure).
//!
//! The camera rays are exactly those of the Embree program: pixel `(x, y)`, sample `s`,
//! jittered by `hash(key)`, `hash(key + 1)` with `key = ((y * w + x) * spp + s) * 2`; shadow
//! rays start at each primary hit moved 2e-5 along the geometric normal facing the viewer
//! and go towards the distant light.

use crate::accel::{Hit, HitKind, Shape};
use crate::light::Light;
use crate::math::rng::hash_u32;
use crate::math::{Ray, PACKET};
use crate::stats::process_cpu_time;
use crate::world::World;
use glam::Vec3;
use rayon::prelude::*;
use std::time::{Duration, Instant};

/// Shadow-ray origin offset of the Embree baseline (`kEps` in bench.cpp).
const SHADOW_EPS: f32 = 2e-5;

/// Rays traced in one measurement and the time they took.
#[derive(Clone, Copy, Debug)]
pub struct Rate {
    /// Rays traced.
    pub rays: u64,
    /// Wall-clock time.
    pub wall: Duration,
    /// CPU time of the whole process over the same span.
    pub cpu: Duration,
    /// Threads used.
    pub threads: usize,
}

impl Rate {
    /// Million rays per second of wall-clock time.
    pub fn mrays(&self) -> f64 {
        self.rays as f64 / self.wall.as_secs_f64() / 1e6
    }

    /// Million rays per second of CPU time, times the thread count: what the threads would
    /// reach on an idle machine.
    pub fn mrays_cpu(&self) -> f64 {
        self.rays as f64 / self.cpu.as_secs_f64().max(1e-9) * self.threads as f64 / 1e6
    }
}

fn measure<T>(threads: usize, f: impl FnOnce() -> (T, u64)) -> (T, Rate) {
    let (c0, t0) = (process_cpu_time(), Instant::now());
    let (out, rays) = f();
    (out, Rate { rays, wall: t0.elapsed(), cpu: process_cpu_time().saturating_sub(c0), threads })
}

/// The Embree program's jitter in [0, 1) for a key.
#[inline]
fn u01(key: u32) -> f32 {
    (hash_u32(key) >> 8) as f32 * (1.0 / 16_777_216.0)
}

/// How the benchmark hands rays to the acceleration structure.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Tracing {
    /// One ray at a time ([`Accel::intersect`], [`Accel::occluded`]), like the Embree
    /// program's `rtcIntersect1` / `rtcOccluded1`.
    ///
    /// [`Accel::intersect`]: crate::accel::Accel::intersect
    /// [`Accel::occluded`]: crate::accel::Accel::occluded
    Single,
    /// A pixel's samples (shadow rays: 16 consecutive origins) as one packet
    /// ([`Accel::intersect_packet`], [`Accel::occluded_packet`]): the same rays and hits.
    ///
    /// [`Accel::intersect_packet`]: crate::accel::Accel::intersect_packet
    /// [`Accel::occluded_packet`]: crate::accel::Accel::occluded_packet
    Packet,
}

impl std::str::FromStr for Tracing {
    type Err = String;

    /// `single` or `packet`.
    fn from_str(s: &str) -> Result<Tracing, String> {
        match s {
            "single" => Ok(Tracing::Single),
            "packet" => Ok(Tracing::Packet),
            _ => Err(format!("`{s}` is not single or packet")),
        }
    }
}

/// The shadow-ray origin for the closest hit of `ray`: the hit point moved off the surface
/// along the geometric normal facing the viewer.
fn shadow_origin(world: &World, ray: &Ray, hit: &Hit) -> Vec3 {
    let n = match hit.kind {
        HitKind::Segment { normal, .. } => normal,
        HitKind::Triangle { .. } => match &world.accel.objects[hit.object as usize].shape {
            Shape::Mesh(m) => {
                let [a, b, c] = m.corners(hit.prim);
                (b - a).cross(c - a).normalize_or_zero()
            }
            Shape::Strands(_) => Vec3::ZERO,
        },
    };
    let n = if n.dot(ray.dir) > 0.0 { -n } else { n };
    ray.at(hit.t) + n * SHADOW_EPS
}

/// Traces every camera ray (closest hit) on the current rayon pool; returns the shadow-ray
/// origins of the hits and the rate.
pub fn trace_primary(world: &World, threads: usize, tracing: Tracing) -> (Vec<Vec3>, Rate) {
    let (w, h, spp) = (world.settings.width, world.settings.height, world.settings.spp);
    measure(threads, || {
        let origins: Vec<Vec3> = (0..h)
            .into_par_iter()
            .flat_map_iter(|y| {
                let mut row = Vec::new();
                let mut hits = Vec::new();
                for x in 0..w {
                    let rays: Vec<Ray> = (0..spp)
                        .map(|s| {
                            let key = ((y * w + x) * spp + s).wrapping_mul(2);
                            world.camera.ray(x as f32 + u01(key), y as f32 + u01(key + 1))
                        })
                        .collect();
                    hits.clear();
                    hits.resize(rays.len(), None);
                    match tracing {
                        Tracing::Single => rays.iter().zip(&mut hits).for_each(|(r, h)| *h = world.accel.intersect(r)),
                        Tracing::Packet => rays
                            .chunks(PACKET)
                            .zip(hits.chunks_mut(PACKET))
                            .for_each(|(r, h)| world.accel.intersect_packet(r, h)),
                    }
                    row.extend(
                        rays.iter().zip(&hits).filter_map(|(r, h)| h.as_ref().map(|h| shadow_origin(world, r, h))),
                    );
                }
                row
            })
            .collect();
        (origins, (w * h * spp) as u64)
    })
}

/// Traces one any-hit ray per origin towards `light` on the current rayon pool; returns
/// how many were blocked and the rate.
pub fn trace_shadow(world: &World, origins: &[Vec3], light: Vec3, threads: usize, tracing: Tracing) -> (u64, Rate) {
    measure(threads, || {
        let blocked = origins
            .par_chunks(4096)
            .map(|chunk| match tracing {
                Tracing::Single => {
                    chunk.iter().filter(|&&o| world.accel.occluded(o, light, f32::INFINITY, None)).count() as u64
                }
                Tracing::Packet => chunk
                    .chunks(PACKET)
                    .map(|o| {
                        let rays: smallvec::SmallVec<[Ray; PACKET]> = o.iter().map(|&o| Ray::new(o, light)).collect();
                        world.accel.occluded_packet(&rays).count_ones() as u64
                    })
                    .sum(),
            })
            .sum();
        (blocked, origins.len() as u64)
    })
}

/// Direction towards the first distant light of a world (straight up when there is none).
pub fn light_direction(world: &World) -> Vec3 {
    world
        .lights
        .iter()
        .find_map(|l| match l {
            Light::Distant { direction, .. } => Some(*direction),
            _ => None,
        })
        .unwrap_or(Vec3::Y)
}
