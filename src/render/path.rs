//! Unidirectional path tracing for reference images (Veach 1997; Pharr et al., PBR 4th ed.
//! ch. 13): next-event estimation at every vertex, multiple importance sampling (power
//! heuristic, Veach & Guibas 1995) between light sampling and material sampling for lights
//! a ray can hit (quad, sphere, sun), the physical hair BSDF's own sampling on hair, and
//! Russian roulette once a path's throughput falls below 1.
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

use super::direct::{departure, surface_at, CameraHint, Counters, FirstHit};
use crate::accel::{Hit, LayerHit, NEGLIGIBLE_TRANSMITTANCE};
use crate::light::Light;
use crate::math::rng::PixelSampler;
use crate::math::sampling::power_heuristic;
use crate::math::{Color, Ray};
use crate::world::World;

/// True for lights a material-sampled ray can hit, which MIS weighs.
fn hittable(light: &Light) -> bool {
    matches!(light, Light::Quad { .. } | Light::Sphere { .. } | Light::Sun { .. } | Light::EnvironmentMap(_))
}

/// What a ray that meets nothing brings back: the constant environment, and the maps
/// weighted against the light sampling that found them already when a material drew
/// the ray (density `scatter_pdf`).
fn sky(world: &World, dir: glam::Vec3, scatter_pdf: Option<f32>) -> Color {
    super::environment::sky(world, dir, |map_pdf| scatter_pdf.map_or(1.0, |pdf| power_heuristic(pdf, map_pdf)))
}

/// The hit a path stops at: the nearest opaque hit, or a partial one chosen with
/// probability equal to its opacity, front to back; a ray never goes past a stack of
/// partial hits that lets less than [`NEGLIGIBLE_TRANSMITTANCE`] through (a bias below
/// that fraction, where the multi-hit query stops looking).
fn next_hit(
    world: &World,
    ray: &Ray,
    sampler: &mut PixelSampler,
    layers: &mut Vec<LayerHit>,
    seen: &mut Vec<LayerHit>,
) -> Option<Hit> {
    if !world.accel.has_transparency() {
        return world.accel.intersect(ray);
    }
    let k = world.settings.transparency_layers as usize;
    seen.clear();
    let mut tmin = 0.0;
    loop {
        world.accel.intersect_k(ray, tmin, k, seen, None, layers);
        let mut transmitted = 1.0f32;
        for l in layers.iter() {
            transmitted *= 1.0 - l.opacity;
            // The list ends where less than NEGLIGIBLE_TRANSMITTANCE passes: stop there.
            if transmitted < NEGLIGIBLE_TRANSMITTANCE || sampler.next_1d() < l.opacity {
                return Some(l.hit);
            }
        }
        if layers.len() < k {
            return None;
        }
        tmin = layers[k - 1].hit.t;
        seen.extend_from_slice(layers);
    }
}

/// Radiance along a camera ray by path tracing, and the first hit for AOVs.
/// `hint` may hold the camera ray's closest hit, already traced ([`CameraHint::Hit`]).
pub fn trace(
    world: &World,
    ray: &Ray,
    hint: CameraHint,
    sampler: &mut PixelSampler,
    counters: &mut Counters,
) -> (Color, Option<FirstHit>) {
    let (mut layers, mut seen) = (Vec::new(), Vec::new());
    let mut ray = *ray;
    let (mut radiance, mut beta) = (Color::ZERO, Color::ONE);
    let mut first = None;
    // Density of the material sample that made `ray`; `None` for camera and specular rays,
    // whose emitters light sampling cannot find.
    let mut scatter_pdf: Option<f32> = None;
    let mut vertex = 0u32;
    loop {
        counters.rays += 1;
        let hit = match &hint {
            CameraHint::Hit { hit, .. } if vertex == 0 => *hit,
            _ => next_hit(world, &ray, sampler, &mut layers, &mut seen),
        };
        let t_hit = hit.map_or(ray.tmax, |h| h.t);
        let seen_light = world
            .lights
            .iter()
            .filter_map(|l| l.emitted(ray.origin, ray.dir, t_hit).map(|(t, le)| (t, le, l)))
            .min_by(|a, b| a.0.total_cmp(&b.0));
        if let Some((_, le, light)) = seen_light {
            let w = scatter_pdf.map_or(1.0, |pdf| power_heuristic(pdf, light.pdf(ray.origin, ray.dir)));
            radiance += beta * le * w;
            if hit.is_none() {
                // The sun is a disk in the sky: the environment shines there too.
                radiance += beta * sky(world, ray.dir, scatter_pdf);
            }
            break;
        }
        let Some(hit) = hit else {
            radiance += beta * sky(world, ray.dir, scatter_pdf);
            break;
        };
        if vertex > world.settings.max_depth {
            break;
        }
        let object = &world.accel.objects[hit.object as usize];
        let material = &world.materials[object.material as usize];
        let surface = surface_at(object, &hit, &ray);
        let sp = &surface.sp;
        let wo = -ray.dir;
        let tube = material.shades_whole_circle();
        if vertex == 0 {
            first = Some(surface.first_hit(&hit));
        }

        // Next-event estimation: one sample of every light but the constant environment.
        for light in world.lights.iter().filter(|l| l.background() == Color::ZERO) {
            let Some(ls) = light.sample(sp.p, Some(sp.normal), sampler.next_2d()) else { continue };
            let f = material.response(sp, wo, ls.dir);
            if f.max_element() <= 0.0 {
                continue;
            }
            let d = departure(&surface, &hit, ls.dir, tube);
            counters.rays += 1;
            let tmax = if ls.dist.is_finite() { ls.dist * (1.0 - 1e-4) } else { f32::INFINITY };
            let cone = ray.cone.propagate(hit.t, 0.0);
            let transmitted = world.accel.transmittance_cone(d.origin, ls.dir, tmax, d.skip, cone, None);
            if transmitted > 0.0 {
                let w = if hittable(light) {
                    power_heuristic(light.pdf(sp.p, ls.dir), material.scatter_pdf(sp, wo, ls.dir))
                } else {
                    1.0
                };
                radiance += beta * f * ls.value * (transmitted * w);
            }
        }

        let Some(s) = material.sample_scatter(sp, wo, sampler) else { break };
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
        let d = departure(&surface, &hit, s.dir, tube);
        let mut next = Ray::new(d.origin, s.dir);
        next.cone = ray.cone.scattered(hit.t, s.pdf, 1);
        ray = next;
        vertex += 1;
    }
    (radiance, first)
}
