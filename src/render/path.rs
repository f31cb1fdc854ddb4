//! Unidirectional path tracing for reference images (Veach 1997; Pharr et al., PBR 4th ed.
//! ch. 13): next-event estimation at every vertex, multiple importance sampling (power
//! heuristic, Veach & Guibas 1995) between light sampling and material sampling for lights
//! a ray can hit (quad, sphere, sun), the physical hair BSDF's own sampling on hair, and
//! Russian roulette once a path's throughput falls below 1. A path ends at an unlit surface
//! with its colour ([`crate::shading::Material::Unlit`]), which lights every surface whose
//! paths reach it.
//!
//! The constant environment is reached by material sampling only (cosine- or
//! BSDF-weighted directions already sample it well); an environment map is sampled at
//! every vertex too, and MIS weighs the two. Semi-transparent hair is crossed
//! stochastically: a ray stops at a partial hit with probability equal to its opacity
//! (unbiased; shadow rays use the exact transmittance). The tube model has no physical
//! meaning for paths: its ambient term is dropped and its response sampled uniformly.
//!
//! `max_depth` counts scattering vertices after the first: with 0, the camera hit's direct
//! light only (the direct integrator's image); with 1, one bounce of indirect light.
//!
//! Path regularization (Kaplanyan and Dachsbacher 2013, "Path Space Regularization for
//! Holistic and Robust Light Transport"): with `indirect_hair_roughness` above 0, physical
//! hair at every vertex after the camera hit has its lobes widened to at least that
//! roughness, for its light samples, its evaluation and its sampling alike. The narrow TT
//! and TRT peaks that line up with a small bright light (an environment map's sun) from deep
//! inside light hair are the noise of such scenes; widened, they carry the same energy over
//! more directions. The camera hit keeps its sharp highlights; the bias is a slightly
//! softer multiple scattering.

use super::interaction::{FirstHit, Interaction};
use super::tracer::{CameraHint, LayerWalk, Tracer};
use crate::accel::{Hit, NEGLIGIBLE_TRANSMITTANCE};
use crate::light::Light;
use crate::math::rng::PixelSampler;
use crate::math::sampling::power_heuristic;
use crate::math::{Color, Ray};
use crate::shading::Material;
use crate::world::World;

/// True for lights a material-sampled ray can hit, which MIS weighs.
fn hittable(light: &Light) -> bool {
    matches!(
        light,
        Light::Quad { .. } | Light::Sphere { .. } | Light::Mesh(_) | Light::Sun { .. } | Light::EnvironmentMap(_)
    )
}

/// What a ray that meets nothing brings back: the constant environment, and the maps
/// weighted against the light sampling that found them already when a material drew
/// the ray (density `scatter_pdf`); as a camera ray sees them for the path's first ray
/// (`vertex` 0).
fn sky(world: &World, dir: glam::Vec3, vertex: u32, scatter_pdf: Option<f32>) -> Color {
    let mis = |map_pdf| scatter_pdf.map_or(1.0, |pdf| power_heuristic(pdf, map_pdf));
    super::environment::sky(world, dir, vertex == 0, mis)
}

/// The hit a path stops at: the nearest opaque hit, or a partial one chosen with
/// probability equal to its opacity, front to back; a ray never goes past a stack of
/// partial hits that lets less than [`NEGLIGIBLE_TRANSMITTANCE`] through (a bias below
/// that fraction, where the multi-hit query stops looking).
fn next_hit(tracer: &mut Tracer, ray: &Ray, sampler: &mut PixelSampler, walk: &mut LayerWalk) -> Option<Hit> {
    if !tracer.world.accel.has_transparency() {
        return tracer.world.accel.intersect(ray);
    }
    walk.restart(0.0, None);
    let mut transmitted = 1.0f32;
    while let Some(l) = walk.next(tracer, ray) {
        transmitted *= 1.0 - l.opacity;
        // The list ends where less than NEGLIGIBLE_TRANSMITTANCE passes: stop there.
        if transmitted < NEGLIGIBLE_TRANSMITTANCE || sampler.next_1d() < l.opacity {
            return Some(l.hit);
        }
    }
    None
}

/// Next-event estimation at a path vertex of throughput `beta`, added to `radiance`: one
/// sample of every light but the constant environment (which material sampling reaches), shadowed,
/// weighted by MIS against the material sample for lights that sample can hit.
/// `material` is the hit's, regularized or not.
fn next_event(
    tracer: &mut Tracer,
    at: &Interaction,
    material: &Material,
    beta: Color,
    sampler: &mut PixelSampler,
    radiance: &mut Color,
) {
    let sp = &at.sp;
    for light in tracer.world.lights.iter().filter(|l| l.background() == Color::ZERO) {
        let Some(ls) = light.sample(sp.p, Some(sp.normal), sampler.next_2d()) else { continue };
        let f = material.response(sp, at.wo, ls.dir);
        if f.max_element() <= 0.0 {
            continue;
        }
        let transmitted = tracer.transmittance(&at.shadow_ray(ls.dir, ls.dist, None));
        if transmitted > 0.0 {
            let w = if hittable(light) {
                power_heuristic(light.pdf(sp.p, ls.dir), material.scatter_pdf(sp, at.wo, ls.dir))
            } else {
                1.0
            };
            *radiance += beta * f * ls.value * (transmitted * w);
        }
    }
}

/// Radiance along a camera ray by path tracing, and the first hit for AOVs.
/// `hint` may hold the camera ray's closest hit, already traced ([`CameraHint::Hit`]).
pub(super) fn trace_camera(
    tracer: &mut Tracer,
    ray: &Ray,
    hint: CameraHint,
    sampler: &mut PixelSampler,
) -> (Color, Option<FirstHit>) {
    let world = tracer.world;
    let mut walk = LayerWalk::default();
    let mut ray = *ray;
    let (mut radiance, mut beta) = (Color::ZERO, Color::ONE);
    let mut first = None;
    // Density of the material sample that made `ray`; `None` for camera and specular rays,
    // whose emitters light sampling cannot find.
    let mut scatter_pdf: Option<f32> = None;
    let mut vertex = 0u32;
    loop {
        tracer.counters.rays += 1;
        let hit = match &hint {
            CameraHint::Hit { hit, .. } if vertex == 0 => *hit,
            _ => next_hit(tracer, &ray, sampler, &mut walk),
        };
        if let Some((_, le, light)) = tracer.light_along(&ray, hit.map_or(ray.tmax, |h| h.t)) {
            let w = scatter_pdf.map_or(1.0, |pdf| power_heuristic(pdf, light.pdf(ray.origin, ray.dir)));
            radiance += beta * le * w;
            if hit.is_none() {
                // The sun is a disk in the sky: the environment shines there too.
                radiance += beta * sky(world, ray.dir, vertex, scatter_pdf);
            }
            break;
        }
        let Some(hit) = hit else {
            radiance += beta * sky(world, ray.dir, vertex, scatter_pdf);
            break;
        };
        // A holdout: black, and no coverage.
        if vertex > world.settings.max_depth || tracer.holdout(&ray, &hit) {
            break;
        }
        let at = Interaction::new(world, &ray, &hit);
        if vertex == 0 {
            first = Some(at.first_hit());
        }
        // An unlit surface ends the path with its colour: it reflects nothing, and no
        // light sampling finds it, so it takes no MIS weight.
        if let Some(le) = at.material.unlit_radiance(&at.sp) {
            radiance += beta * le;
            break;
        }
        // Path regularization past the camera hit (see the module documentation).
        let widened = match world.settings.indirect_hair_roughness {
            r if vertex > 0 && r > 0.0 => at.material.regularized(r),
            _ => None,
        };
        let material = widened.as_ref().unwrap_or(at.material);
        next_event(tracer, &at, material, beta, sampler, &mut radiance);

        let Some(s) = material.sample_scatter(&at.sp, at.wo, sampler) else { break };
        beta *= s.weight;
        scatter_pdf = (!s.is_specular()).then_some(s.pdf);
        // Russian roulette (PBR 4th ed. 13.1.1): paths that carry little go on rarely,
        // with their weight raised to keep the estimate unbiased.
        let max = beta.max_element();
        if vertex >= 2 && max < 1.0 {
            let q = (1.0 - max).max(0.0);
            if sampler.next_1d() < q {
                break;
            }
            beta /= 1.0 - q;
        }
        ray = Ray { cone: ray.cone.scattered(hit.t, s.pdf, 1), ..at.spawn_ray(s.dir) };
        vertex += 1;
    }
    (radiance, first)
}
