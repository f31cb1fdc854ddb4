//! Final gather (Turtle's global illumination, thesis section 2.2.7 and 3.4): direct light
//! plus one gathered bounce of indirect light. At a hit, `gather_rays` directions are drawn
//! by the material ([`Material::sample_scatter`]): cosine-weighted on surfaces, and on
//! hair over the whole sphere around the fibre weighted by the hair shading, never over a
//! hemisphere around a normal (which Turtle did, and which misses the light a strand
//! transmits from behind). Each gathered ray returns the direct light at the point it
//! reaches; lights and the environment it sees directly count nothing, since the direct
//! part of the shading already sampled them, nor do lights it sees through a mirror
//! (no caustics: a few very bright samples would be fireflies). An unlit surface it
//! reaches returns its colour, which no light sample counted: unlit surfaces light their
//! neighbours through the gathered bounce (and the irradiance cache's records), as
//! Arnold's `flat` shader does under global illumination. With the irradiance cache
//! ([`IrradianceCache`]), diffuse surfaces read the gathered light from it where a record
//! serves, and gather anew elsewhere; hair always gathers anew.

use super::direct::{trace, Bounce, Indirect, Whitted};
use super::interaction::{FirstHit, Interaction};
use super::irradiance_cache::{cached_albedo, IrradianceCache};
use super::tracer::{CameraHint, Tracer};
use crate::math::rng::PixelSampler;
use crate::math::{Color, Ray};
use crate::shading::Material;

/// The final-gather integrator's indirect term, with the irradiance cache when there is one.
struct FinalGather<'a> {
    cache: Option<&'a IrradianceCache>,
}

impl Indirect for FinalGather<'_> {
    fn diffuse(&self, tracer: &mut Tracer, at: &Interaction, depth: u32, sampler: &mut PixelSampler) -> Color {
        if matches!(at.material, Material::Mirror { .. } | Material::Glass { .. }) {
            return Color::ZERO;
        }
        if let (Some(cache), Some(albedo)) = (self.cache, cached_albedo(at)) {
            if let Some(e) = cache.lookup(at.sp.p, at.sp.normal) {
                return albedo * e;
            }
        }
        let n = tracer.world.settings.gather_rays;
        let mut sum = Color::ZERO;
        for _ in 0..n {
            let Some(s) = at.material.sample_scatter(&at.sp, at.wo, sampler) else { continue };
            let ray = Ray { cone: at.cone.scattered(at.hit.t, s.pdf, n), ..at.spawn_ray(s.dir) };
            let gathered = Bounce::scattered(depth + 1, false);
            sum += s.weight * trace(tracer, &ray, gathered, sampler, &Whitted { see_emitters: false }).0;
        }
        sum / n as f32
    }
}

/// Radiance along a camera ray by final gathering, and the first hit for AOVs; diffuse
/// surfaces read the tracer's irradiance cache where one of its records serves.
pub(super) fn trace_camera(
    tracer: &mut Tracer,
    ray: &Ray,
    hint: CameraHint,
    sampler: &mut PixelSampler,
) -> (Color, Option<FirstHit>) {
    let gather = FinalGather { cache: tracer.cache };
    trace(tracer, ray, Bounce::camera(hint), sampler, &gather)
}
