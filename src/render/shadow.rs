//! Shadow rays: traced at once, shared by the layers a camera ray blends
//! ([`SharedShadows`]), or kept with the rest of a pixel's to be traced as packets
//! ([`PixelShadows`]).

use super::tracer::Tracer;
use crate::math::rng::PixelSampler;
use crate::math::{Color, Ray, RayMask, PACKET};
use smallvec::SmallVec;

/// A shadow ray towards a light: a ray up to just before the light, ignoring what it
/// leaves from ([`Ray::skip`]), with the footprint it starts with (level of detail).
#[derive(Clone, Copy, Debug)]
pub(super) struct ShadowRay {
    pub ray: Ray,
    /// Seed of the stochastic transmittance estimate through semi-transparent hair
    /// ([`crate::accel::Accel::transmittance_estimate`]); `None` for the exact product.
    pub seed: Option<u32>,
}

/// Where the direct integrator's shading sends the shadow rays of a hit.
pub(super) enum Shadows<'a> {
    /// Traced at once.
    Now,
    /// Offered to the rays the layers of a camera ray share, with the hit's blend weight.
    Shared(&'a mut SharedShadows, f32),
    /// Kept with the pixel's others, to be traced as packets.
    Deferred(&'a mut PixelShadows),
}

/// Fewest rays worth tracing as a packet: render instructions on the hairy torus
/// (docs/performance.md) fall by 2 % at 4 camera rays a pixel, 8 % at 8 and 11 % at 16,
/// and rise by 7 % at 2, where a packet's fixed work per node is shared by too few rays.
pub const MIN_PACKET: usize = 4;

/// The shadow rays of a pixel's camera hits (in scenes without semi-transparent strands,
/// where a shadow ray is an any-hit query), kept while the pixel's samples are shaded and
/// then traced as packets, one light at a time: a pixel's shadow rays towards one light
/// start close together and mostly cross the same boxes, like its camera rays
/// ([`crate::accel::Accel::occluded_packet`]). Each adds its light to its sample's colour
/// unless blocked, as it would have added it traced at once. One serves all the pixels a
/// task renders, so its arrays are allocated once.
#[derive(Debug, Default)]
pub struct PixelShadows {
    /// The sample being shaded.
    sample: u32,
    /// Per light, its rays in the order they came.
    lights: Vec<LightRays>,
}

/// The deferred shadow rays towards one light, in flat arrays that packets read as they are.
#[derive(Debug, Default)]
struct LightRays {
    rays: Vec<Ray>,
    /// Per ray, its sample and the light it adds when nothing blocks it.
    adds: Vec<(u32, Color)>,
}

impl PixelShadows {
    /// Sets the sample whose shadow rays come next; returns `self` for a
    /// [`super::CameraHint`].
    pub fn for_sample(&mut self, sample: usize) -> &mut PixelShadows {
        self.sample = sample as u32;
        self
    }

    /// Keeps `shadow`, which adds `value` of light number `light` unless blocked.
    pub(super) fn push(&mut self, light: usize, value: Color, shadow: &ShadowRay) {
        if self.lights.len() <= light {
            self.lights.resize_with(light + 1, LightRays::default);
        }
        let rays = &mut self.lights[light];
        rays.rays.push(shadow.ray);
        rays.adds.push((self.sample, value));
    }

    /// Traces the kept rays, light by light in the order of the samples, [`PACKET`] at a
    /// time (fewer than `MIN_PACKET` one by one), adding the light of each unblocked one
    /// to `colors[sample]`; then forgets them.
    pub fn trace(&mut self, tracer: &mut Tracer, colors: &mut [Color]) {
        let accel = &tracer.world.accel;
        for light in &mut self.lights {
            tracer.counters.rays += light.rays.len() as u64;
            for (rays, adds) in light.rays.chunks(PACKET).zip(light.adds.chunks(PACKET)) {
                let blocked = if rays.len() >= MIN_PACKET {
                    accel.occluded_packet(rays)
                } else {
                    rays.iter().enumerate().fold(0, |mask, (i, r)| {
                        let open = accel.transmittance_cone(r.origin, r.dir, r.tmax, r.skip, r.cone, None);
                        mask | (((open == 0.0) as RayMask) << i)
                    })
                };
                for (i, &(sample, value)) in adds.iter().enumerate() {
                    if blocked >> i & 1 == 0 {
                        colors[sample as usize] += value;
                    }
                }
            }
            light.rays.clear();
            light.adds.clear();
        }
    }
}

/// One shadow ray per light for all the layers a camera ray shades, instead of one per
/// layer and light: the layers of one pixel lie close together and mostly see a light
/// alike. Each layer offers the unshadowed light `c_i` it reflects (weighted by its blend
/// weight); one offer per light is kept, chosen with probability `p_i` proportional to
/// the sum of its channels by weighted reservoir sampling (Chao 1982), and only its shadow
/// ray is traced. `c_j V_j / p_j` has the expectation `sum_i c_i V_i`, the blend of every
/// layer shadowed on its own: a one-sample estimator over the layers (Veach 1997, section
/// 9.2.4). One sample dimension decides the choice, rescaled from offer to offer, so it
/// is stratified across a pixel's samples and does not depend on how many hits one
/// traversal collects.
///
/// With smooth level of detail ([`crate::accel::Accel::smooth_layers`]), the shading
/// offers no singular light ([`crate::light::Light::is_singular`]): every layer traces its
/// own shadow ray to it. A pick toggles to another layer, whose shadow may differ entirely,
/// as strands slide under a fixed sample; that made most of the far fur's flicker in a
/// camera move (docs/performance.md, tried and not kept).
pub(super) struct SharedShadows {
    /// Per light; inline for the usual few lights, so a camera ray allocates nothing.
    picks: SmallVec<[Pick; 4]>,
}

/// The offers made for one light so far: their total weight, the one kept, and the
/// uniform number that decides the next.
#[derive(Clone, Copy, Default)]
struct Pick {
    u: f32,
    total: f32,
    /// Unshadowed light, its weight and its shadow ray.
    chosen: Option<(Color, f32, ShadowRay)>,
}

impl SharedShadows {
    /// One sample dimension decides every pick: light `l` starts from it shifted by `l`
    /// times the golden ratio (mod 1), which keeps each light's numbers stratified.
    pub fn new(lights: usize, sampler: &mut PixelSampler) -> SharedShadows {
        let u = sampler.next_1d();
        let mut picks: SmallVec<[Pick; 4]> = smallvec::smallvec![Pick::default(); lights];
        for (l, pick) in picks.iter_mut().enumerate() {
            pick.u = (u + l as f32 * 0.618_034).fract();
        }
        SharedShadows { picks }
    }

    /// Offers the unshadowed light `value` that light number `light` sends along `shadow`.
    pub fn offer(&mut self, light: usize, value: Color, shadow: ShadowRay) {
        let weight = value.element_sum();
        if weight <= 0.0 || !weight.is_finite() {
            return;
        }
        let pick = &mut self.picks[light];
        pick.total += weight;
        // Keep this offer with probability p = weight / total (the first one always).
        // Given the outcome, u rescaled to [0, 1) is uniform again and decides the next
        // offer: one stratified number serves them all.
        let p = weight / pick.total;
        if pick.u < p {
            pick.chosen = Some((value, weight, shadow));
            pick.u /= p;
        } else {
            pick.u = (pick.u - p) / (1.0 - p);
        }
        pick.u = pick.u.min(1.0 - f32::EPSILON / 2.0); // the largest float below 1
    }

    /// Traces the kept shadow rays: the light reflected by every layer offered, estimated.
    pub fn trace(&self, tracer: &mut Tracer) -> Color {
        let mut color = Color::ZERO;
        for pick in &self.picks {
            let Some((value, weight, shadow)) = pick.chosen else { continue };
            let transmitted = tracer.transmittance(&shadow);
            if transmitted > 0.0 {
                color += value * (pick.total / weight * transmitted);
            }
        }
        color
    }
}
