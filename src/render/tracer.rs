//! The tracer every integrator traces with: it owns the world, the final gather's
//! irradiance cache and the task's tallies (as pbrt-v4's integrators own the scene), and
//! answers the queries they share: which light a ray sees, shadow rays, the layers of
//! semi-transparent hair along a ray.

use super::irradiance_cache::IrradianceCache;
use super::shadow::{PixelShadows, ShadowRay};
use super::{direct, final_gather, path, FirstHit};
use crate::accel::{LayerHit, StochasticTail};
use crate::light::Light;
use crate::math::rng::PixelSampler;
use crate::math::{Color, Ray};
use crate::world::{Integrator, World};

/// Per-task tallies, summed when the render ends.
#[derive(Clone, Copy, Debug, Default)]
pub struct Counters {
    /// Rays traced.
    pub rays: u64,
}

/// What the rest of its pixel tells of a camera ray before it is traced.
#[derive(Debug)]
pub enum CameraHint<'a> {
    /// Nothing: the ray is traced like any other.
    None,
    /// Its closest hit, traced with the pixel's other rays as a packet (only in scenes
    /// without semi-transparent strands, where every integrator starts with that query),
    /// and where the shadow rays from that hit go to be traced with the pixel's others
    /// (the direct integrator and the final gather defer them; the path tracer does not).
    Hit {
        /// The closest hit.
        hit: Option<crate::accel::Hit>,
        /// The pixel's deferred shadow rays, set to this ray's sample.
        shadows: &'a mut PixelShadows,
    },
    /// The pixel's previous sample met fur drawn semi-transparent for its level of detail
    /// first: likely so for this one too, so the closest-hit query that would come first
    /// is skipped (the samples of a pixel run in a fixed order: deterministic). The
    /// estimate is the same either way.
    LayersFirst,
}

/// Traces rays through one world for one task (one thread at a time), counting them.
#[derive(Debug)]
pub struct Tracer<'w> {
    /// What is traced.
    pub world: &'w World,
    /// The final gather's irradiance cache, when it has one.
    pub cache: Option<&'w IrradianceCache>,
    /// Tallies of what this tracer traced.
    pub counters: Counters,
}

impl<'w> Tracer<'w> {
    /// A tracer of `world`, without an irradiance cache (the final gather then gathers at
    /// every hit).
    pub fn new(world: &'w World) -> Tracer<'w> {
        Tracer { world, cache: None, counters: Counters::default() }
    }

    /// A tracer whose final gather reads `cache` on diffuse surfaces where a record serves.
    pub fn with_cache(world: &'w World, cache: Option<&'w IrradianceCache>) -> Tracer<'w> {
        Tracer { world, cache, counters: Counters::default() }
    }

    /// Radiance along a camera ray by the world's integrator, and the first hit for AOVs.
    pub fn trace_camera(&mut self, ray: &Ray, sampler: &mut PixelSampler) -> (Color, Option<FirstHit>) {
        self.trace_camera_hinted(ray, CameraHint::None, sampler)
    }

    /// [`Tracer::trace_camera`], with what the ray's pixel tells of it (`hint`).
    pub fn trace_camera_hinted(
        &mut self,
        ray: &Ray,
        hint: CameraHint,
        sampler: &mut PixelSampler,
    ) -> (Color, Option<FirstHit>) {
        match self.world.settings.integrator {
            Integrator::Direct => direct::trace_camera(self, ray, hint, sampler),
            Integrator::FinalGather => final_gather::trace_camera(self, ray, hint, sampler),
            Integrator::Path => path::trace_camera(self, ray, hint, sampler),
        }
    }

    /// The nearest light `ray` meets before distance `tmax` (area lights are not in the
    /// BVH): its distance, the radiance it sends back along the ray, and the light. A
    /// camera ray sees each light times its [`Light::camera_visibility`] and passes
    /// through one of weight 0, as Arnold's camera rays pass through its area lights.
    pub(super) fn light_along(&self, ray: &Ray, tmax: f32) -> Option<(f32, Color, &'w Light)> {
        self.world
            .lights
            .iter()
            .filter_map(|l| {
                let seen = if ray.camera { l.camera_visibility() } else { 1.0 };
                if seen <= 0.0 {
                    return None;
                }
                let (t, le) = l.emitted(ray.origin, ray.dir, tmax)?;
                Some((t, le * seen, l))
            })
            .min_by(|a, b| a.0.total_cmp(&b.0))
    }

    /// True when `hit`, the first hit of `ray`, is a holdout: a camera ray meeting a matte
    /// object ([`crate::accel::Visibility::matte`]), which leaves its sample black and
    /// uncovered (alpha 0) as Arnold's `matte` and Cycles' holdout do. Other rays see matte
    /// objects as any other.
    pub(super) fn holdout(&self, ray: &Ray, hit: &crate::accel::Hit) -> bool {
        ray.camera && self.world.accel.has_matte() && self.world.accel.visibility(hit.object).matte
    }

    /// The fraction of light `shadow` lets through (estimated through semi-transparent
    /// hair when it has a seed).
    pub(super) fn transmittance(&mut self, shadow: &ShadowRay) -> f32 {
        self.counters.rays += 1;
        let r = &shadow.ray;
        self.world.accel.transmittance_cone(r.origin, r.dir, r.tmax, r.skip, r.cone, shadow.seed)
    }
}

/// The hits along a ray through semi-transparent hair, front to back, found
/// `transparency_layers` at a time by [`crate::accel::Accel::intersect_k`]: each batch
/// continues behind the farthest hit of a full one. It ends where the query's list ends
/// (nothing more, or nothing that shows behind an opaque hit, a negligible transmittance
/// or the `tail` walk's stop); the caller stops earlier by its own rule. Its buffers are
/// kept from walk to walk ([`LayerWalk::restart`]).
#[derive(Debug, Default)]
pub(super) struct LayerWalk {
    tmin: f32,
    tail: Option<StochasticTail>,
    batch: Vec<LayerHit>,
    seen: Vec<LayerHit>,
    next: usize,
    /// Whether `batch` holds the query's answer for `tmin` yet.
    fetched: bool,
}

impl LayerWalk {
    /// A walk along a ray from distance `tmin` on, with the stochastic `tail` of a blend.
    pub fn new(tmin: f32, tail: Option<StochasticTail>, k: usize) -> LayerWalk {
        let mut walk = LayerWalk { batch: Vec::with_capacity(k), ..LayerWalk::default() };
        walk.restart(tmin, tail);
        walk
    }

    /// Starts another walk (along another ray) with the same buffers.
    pub fn restart(&mut self, tmin: f32, tail: Option<StochasticTail>) {
        (self.tmin, self.tail, self.next, self.fetched) = (tmin, tail, 0, false);
        self.seen.clear();
    }

    /// The next hit along `ray`, or `None` past the last.
    pub fn next(&mut self, tracer: &mut Tracer, ray: &Ray) -> Option<LayerHit> {
        let k = (tracer.world.settings.transparency_layers as usize).max(1);
        if self.fetched && self.next == self.batch.len() {
            if self.batch.len() < k {
                return None;
            }
            // Every hit collected let light through: continue behind the farthest.
            self.tmin = self.batch[k - 1].hit.t;
            self.seen.extend_from_slice(&self.batch);
            self.fetched = false;
            tracer.counters.rays += 1;
        }
        if !self.fetched {
            tracer.world.accel.intersect_k(ray, self.tmin, k, &self.seen, self.tail, &mut self.batch);
            (self.next, self.fetched) = (0, true);
        }
        let layer = self.batch.get(self.next).copied()?;
        self.next += 1;
        Some(layer)
    }
}
