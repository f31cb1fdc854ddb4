//! Final gather (Turtle's global illumination, thesis section 2.2.7 and 3.4): direct light
//! plus one gathered bounce of indirect light. At a hit, `gather_rays` directions are drawn
//! by the material ([`Material::sample_scatter`]): cosine-weighted on surfaces, and on
//! hair over the whole sphere around the fibre weighted by the hair shading, never over a
//! hemisphere around a normal (which Turtle did, and which misses the light a strand
//! transmits from behind). Each gathered ray returns the direct light at the point it
//! reaches; lights and the environment it sees directly count nothing, since the direct
//! part of the shading already sampled them, nor do lights it sees through a mirror
//! (no caustics: a few very bright samples would be fireflies). With the irradiance cache
//! ([`IrradianceCache`]), diffuse surfaces read the gathered light from it where a record
//! serves, and gather anew elsewhere; hair always gathers anew.

use super::direct::{departure, trace_hinted, trace_with, At, CameraHint, Counters, FirstHit, Indirect, Whitted};
use super::irradiance_cache::{cached_albedo, IrradianceCache};
use crate::math::rng::PixelSampler;
use crate::math::{Color, Ray};
use crate::shading::Material;
use crate::world::World;

/// The final-gather integrator's indirect term, with the irradiance cache when there is one.
struct FinalGather<'a> {
    cache: Option<&'a IrradianceCache>,
}

impl Indirect for FinalGather<'_> {
    fn diffuse(
        &self,
        world: &World,
        at: &At,
        depth: u32,
        sampler: &mut PixelSampler,
        counters: &mut Counters,
    ) -> Color {
        if matches!(at.material, Material::Mirror { .. } | Material::Glass { .. }) {
            return Color::ZERO;
        }
        if let (Some(cache), Some(albedo)) = (self.cache, cached_albedo(at)) {
            if let Some(e) = cache.lookup(at.surface.sp.p, at.surface.sp.normal) {
                return albedo * e;
            }
        }
        let n = world.settings.gather_rays;
        let mut sum = Color::ZERO;
        for _ in 0..n {
            let Some(s) = at.material.sample_scatter(&at.surface.sp, at.wo, sampler) else { continue };
            let d = departure(at.surface, at.hit, s.dir, at.material.shades_whole_circle());
            let mut ray = Ray::new(d.origin, s.dir);
            ray.cone = at.cone.scattered(at.hit.t, s.pdf, n);
            sum += s.weight
                * trace_with(world, &ray, depth + 1, sampler, counters, &Whitted { see_emitters: false }, false).0;
        }
        sum / n as f32
    }
}

/// Radiance along a camera ray by final gathering, and the first hit for AOVs; diffuse
/// surfaces read `cache` where one of its records serves.
pub fn trace(
    world: &World,
    cache: Option<&IrradianceCache>,
    ray: &Ray,
    hint: CameraHint,
    sampler: &mut PixelSampler,
    counters: &mut Counters,
) -> (Color, Option<FirstHit>) {
    trace_hinted(world, ray, hint, sampler, counters, &FinalGather { cache })
}
