//! The direct-lighting (Whitted) integrator: lights with hard or soft shadows (partial
//! through semi-transparent hair), the constant environment as an ambient term and
//! environment maps sampled with MIS (`super::environment`), mirror reflection and
//! refraction up to the maximum depth, and semi-transparent hair blended in layers.
//! An unlit surface is its colour, lit by nothing ([`crate::shading::Material::Unlit`]).
//! The final gather reuses it with an indirect term ([`Indirect`]).

use super::interaction::{FirstHit, Interaction};
use super::shadow::{Shadows, SharedShadows};
use super::tracer::{CameraHint, LayerWalk, Tracer};
use crate::accel::{Hit, StochasticTail, NEGLIGIBLE_TRANSMITTANCE};
use crate::light::{Light, LightSample};
use crate::math::rng::PixelSampler;
use crate::math::{Color, Ray};

/// Transmittance below which the layers of semi-transparent hair behind are walked
/// stochastically instead of all shaded and blended (`trace`). A half: behind a
/// layer of 50 % (or denser) hair the rest is walked, so a camera ray shades at most two
/// layers. With the stochastic shadow transmittance of [`crate::accel::EXACT_SHADOW_TRANSMITTANCE`]
/// and one shadow ray per light shared by the layers (`SharedShadows`), 50 %-tip fur
/// renders in about 1.4 times the time of opaque fur instead of 3.2 times (`cargo bench
/// --bench transparency`; docs/performance.md, "Transparency").
pub const BLEND_TRANSMITTANCE: f32 = 0.5;

/// [`BLEND_TRANSMITTANCE`] where strands have smooth level of detail
/// ([`crate::accel::Accel::smooth_layers`]): a stochastic stop behind the blended layers
/// then changes a sample by at most a fifth of its light. (With
/// [`crate::accel::SMOOTH_EXACT_SHADOW_TRANSMITTANCE`]; measured there.)
pub const SMOOTH_BLEND_TRANSMITTANCE: f32 = 0.2;

/// What a ray the direct integrator traces stands for.
pub(super) struct Bounce<'a> {
    /// Scattering events before it (0 for camera rays).
    pub depth: u32,
    /// Whether lights and the environment seen along it count: not for a gathered ray,
    /// whose origin already sampled them.
    pub see_emitters: bool,
    /// What its pixel tells of a camera ray.
    pub hint: CameraHint<'a>,
}

impl<'a> Bounce<'a> {
    /// A camera ray, with what its pixel tells of it.
    pub fn camera(hint: CameraHint<'a>) -> Bounce<'a> {
        Bounce { depth: 0, see_emitters: true, hint }
    }

    /// A ray scattered at the `depth`-th hit of a path, seeing emitters or not.
    pub fn scattered(depth: u32, see_emitters: bool) -> Bounce<'static> {
        Bounce { depth, see_emitters, hint: CameraHint::None }
    }
}

/// [`trace`] for a camera ray, with what its pixel tells of it (`hint`).
pub(super) fn trace_camera(
    tracer: &mut Tracer,
    ray: &Ray,
    hint: CameraHint,
    sampler: &mut PixelSampler,
) -> (Color, Option<FirstHit>) {
    trace(tracer, ray, Bounce::camera(hint), sampler, &Whitted { see_emitters: true })
}

/// What an integrator adds to direct light at a hit; the direct integrator and the final
/// gather differ only here.
pub(super) trait Indirect: Sized {
    /// Whether specular rays see lights directly (see [`Whitted`]).
    fn specular_sees_emitters(&self) -> bool {
        true
    }
    /// Radiance arriving along a specular (mirror, glass) ray, `depth` bounces deep.
    fn specular(&self, tracer: &mut Tracer, ray: &Ray, depth: u32, sampler: &mut PixelSampler) -> Color {
        trace(tracer, ray, Bounce::scattered(depth, self.specular_sees_emitters()), sampler, self).0
    }
    /// Indirect light reflected towards `at.wo` at a hit `depth` bounces deep, besides the
    /// specular rays.
    fn diffuse(&self, tracer: &mut Tracer, at: &Interaction, depth: u32, sampler: &mut PixelSampler) -> Color;
}

/// The direct integrator adds specular rays only. Without `see_emitters` (light gathered
/// by the final gather), specular rays do not see lights either: no caustics, whose few
/// bright samples would be fireflies.
pub(super) struct Whitted {
    pub see_emitters: bool,
}

impl Indirect for Whitted {
    fn specular_sees_emitters(&self) -> bool {
        self.see_emitters
    }
    fn diffuse(&self, _: &mut Tracer, _: &Interaction, _: u32, _: &mut PixelSampler) -> Color {
        Color::ZERO
    }
}

/// Radiance along `ray` and its first hit, shading each hit with direct light plus what
/// `indirect` adds.
///
/// Semi-transparent hair (thesis section 2.2.8, fast transparency): one traversal collects
/// the `transparency_layers` nearest hits; they are shaded front to back and blended by
/// their opacity, `C = sum_i T_i a_i C_i` with `T_{i+1} = T_i (1 - a_i)`, stopping at an
/// opaque hit or a negligible `T`; only when every collected hit let enough light through
/// does the ray continue past them with another traversal ([`LayerWalk`]).
///
/// Once less than [`BLEND_TRANSMITTANCE`] ([`SMOOTH_BLEND_TRANSMITTANCE`] for smooth level
/// of detail) of the light is left, the layers behind (each
/// to be found and shaded, deeper in the hair) are no longer all shaded: the tail
/// is walked as in stochastic transparency (Enderton et al. 2010), stopping at layer `i`
/// with probability `a_i` and shading it with the whole remaining `T` ([`StochasticTail`]:
/// the multi-hit query stops looking behind that layer, too). The expected colour
/// is the blend's; the noise is bounded by that small `T`.
///
/// The layers shaded share one shadow ray per light ([`SharedShadows`]), traced once the
/// last layer is known.
pub(super) fn trace(
    tracer: &mut Tracer,
    ray: &Ray,
    bounce: Bounce,
    sampler: &mut PixelSampler,
    indirect: &impl Indirect,
) -> (Color, Option<FirstHit>) {
    let world = tracer.world;
    tracer.counters.rays += 1;
    let Bounce { depth, see_emitters, hint } = bounce;
    let emitted = |c: Color| if see_emitters { c } else { Color::ZERO };
    let tail = world.accel.has_transparency().then(|| StochasticTail {
        blend: blend_transmittance(tracer),
        seed: (sampler.next_1d() * 16_777_216.0) as u32,
    });
    // When only level of detail makes strands semi-transparent, one closest-hit traversal
    // comes first: most fur is drawn opaque, and an opaque nearest hit is all the blend
    // below would shade, so most rays pay no multi-hit query (16 spp on
    // scenes/lod_field.toml: 3.1 CPU s instead of 3.8). Strands with opacity of their own
    // skip it: there the nearest hit is mostly semi-transparent and the first traversal
    // would be paid twice (50 %-tip fur, `cargo bench --bench transparency`: 1.75x the
    // opaque render time with it, 1.4x without).
    // Where a ray most likely meets semi-transparent coarse fur first
    // ([`CameraHint::LayersFirst`]), the closest hit would be paid on top of the layers'
    // query: 10 k instructions of 30 k on such rays in scenes/lod_field.toml, where the
    // thin fur is drawn semi-transparent from 2 to 3 units on.
    let layers_first = matches!(hint, CameraHint::LayersFirst);
    let opaque_first = tail.is_none() || !layers_first && !world.accel.has_strand_opacity();
    let (hit, shadows) = match hint {
        // A packet traces any-hit queries: shadow rays wait for one only where no strand
        // is semi-transparent.
        CameraHint::Hit { hit, shadows } if opaque_first => match tail {
            None => (hit, Shadows::Deferred(shadows)),
            Some(_) => (hit, Shadows::Now),
        },
        _ if opaque_first => (world.accel.intersect(ray), Shadows::Now),
        _ => (None, Shadows::Now),
    };
    let tail = match tail {
        Some(tail) if !opaque_first || hit.is_some_and(|h| world.accel.hit_opacity(&h) < 1.0) => tail,
        _ => {
            if let Some((_, radiance, _)) = tracer.light_along(ray, hit.map_or(ray.tmax, |h| h.t)) {
                return (emitted(radiance), None);
            }
            let Some(hit) = hit else {
                return (emitted(super::environment::sky(world, ray.dir, depth == 0, |_| 1.0)), None);
            };
            if tracer.holdout(ray, &hit) {
                return (Color::ZERO, None);
            }
            let (color, first) = shade(tracer, ray, &hit, depth, sampler, indirect, shadows);
            return (color, Some(first));
        }
    };
    // After a closest hit, nothing lies nearer: the layers start just before it, and the
    // BVH boxes the ray leaves before that are not entered (lod_field.toml: -1.6 % instructions).
    let tmin = hit.map_or(0.0, |h| h.t * (1.0 - 4.0 * f32::EPSILON));
    let mut walk = LayerWalk::new(tmin, Some(tail), world.settings.transparency_layers as usize);
    // The layers count up to the nearest light along the ray, which hides what lies behind.
    let light = tracer.light_along(ray, ray.tmax).map(|(t, radiance, _)| (t, radiance));
    // `transmitted`: the light passing every layer so far; `carried`: the weight of what
    // is shaded next (equal to it while blending, frozen once the tail is walked).
    let (mut color, mut transmitted, mut carried, mut first) = (Color::ZERO, 1.0f32, 1.0f32, None);
    let mut shadows = SharedShadows::new(world.lights.len(), sampler);
    let color = loop {
        let Some(layer) = walk.next(tracer, ray).filter(|l| light.is_none_or(|(t, _)| l.hit.t < t)) else {
            let behind = light
                .map_or_else(|| super::environment::sky(world, ray.dir, depth == 0, |_| 1.0), |(_, radiance)| radiance);
            break color + carried * emitted(behind);
        };
        let a = layer.opacity;
        let blend = carried >= tail.blend;
        let last = transmitted * (1.0 - a) < NEGLIGIBLE_TRANSMITTANCE;
        if blend || last || tail.draw(&layer.hit) < a {
            // Blended by its opacity, or where the tail stops with all the light left.
            let weight = if blend { carried * a } else { carried };
            // A holdout layer adds black, and no coverage.
            if !tracer.holdout(ray, &layer.hit) {
                let shared = Shadows::Shared(&mut shadows, weight);
                let (c, f) = shade(tracer, ray, &layer.hit, depth, sampler, indirect, shared);
                first.get_or_insert(f);
                color += weight * c;
            }
            if !blend {
                break color;
            }
            carried *= 1.0 - a;
        }
        transmitted *= 1.0 - a;
        if transmitted < NEGLIGIBLE_TRANSMITTANCE {
            break color;
        }
    };
    (color + shadows.trace(tracer), first)
}

/// The transmittance below which a camera ray's layers are walked stochastically.
fn blend_transmittance(tracer: &Tracer) -> f32 {
    if tracer.world.accel.smooth_layers() {
        SMOOTH_BLEND_TRANSMITTANCE
    } else {
        BLEND_TRANSMITTANCE
    }
}

/// Directions towards `light` from the hit and the light arriving along each (unshadowed,
/// MIS weights included), for next-event estimation: one sample, or two for an
/// environment map. `normal`: the surface normal lights sample the hemisphere over (none
/// for tube hair, lit from every side).
fn sample_light(
    light: &Light,
    at: &Interaction,
    normal: Option<glam::Vec3>,
    sampler: &mut PixelSampler,
) -> [Option<LightSample>; 2] {
    match *light {
        // A constant environment is best sampled by a material that can sample its own
        // response (the hair BSDF, whose lobes the sphere's uniform samples would miss).
        Light::Environment { radiance, .. } => [
            match at.material.sample_direction(&at.sp, at.wo, sampler) {
                Some((dir, pdf)) => Some(LightSample { dir, dist: f32::INFINITY, value: radiance / pdf }),
                None => light.sample(at.sp.p, normal, sampler.next_2d()),
            },
            None,
        ],
        Light::EnvironmentMap(ref map) => super::environment::map_samples(map, at.material, &at.sp, at.wo, sampler),
        _ => [light.sample(at.sp.p, normal, sampler.next_2d()), None],
    }
}

/// Direct light at one hit, the specular rays and what `indirect` adds; and the hit's
/// description for the AOVs. With `shared` shadows and the hit's blend weight, the direct
/// light is offered to them instead of added (the caller traces their shadow rays); with
/// deferred shadows, kept for the pixel's packets.
fn shade(
    tracer: &mut Tracer,
    ray: &Ray,
    hit: &Hit,
    depth: u32,
    sampler: &mut PixelSampler,
    indirect: &impl Indirect,
    mut shadows: Shadows,
) -> (Color, FirstHit) {
    let world = tracer.world;
    let at = Interaction::new(world, ray, hit);
    let (sp, material) = (&at.sp, at.material);
    let first = at.first_hit();
    // An unlit surface shows its colour to every ray, gathered ones too (light sampling
    // never finds it, so nothing counts it twice), and reflects nothing.
    if let Some(radiance) = material.unlit_radiance(sp) {
        return (radiance, first);
    }

    let mut color = material.ambient(sp, world.ambient);
    let tube_hair = material.has_ambient_term(sp);
    // Shadow rays through semi-transparent hair are estimated: unbiased, and they stop
    // early in dense fur (`Accel::transmittance_estimate`). The seed is a hash, not a
    // sample dimension, so the following dimensions keep their values.
    let shadow_seed = world.accel.has_transparency().then(|| sampler.hash());
    for (index, light) in world.lights.iter().enumerate() {
        if tube_hair && light.background() != Color::ZERO {
            continue; // the tube model's ambient term already stands for the environment
        }
        let normal = if tube_hair { None } else { Some(sp.normal) };
        for ls in sample_light(light, &at, normal, sampler).into_iter().flatten() {
            let f = material.response(sp, at.wo, ls.dir);
            if f.max_element() <= 0.0 {
                continue;
            }
            // Hair lets light through by its opacity; meshes and opaque strands block it. The
            // estimate stops at the first hits like an opaque shadow ray, most of the time.
            // The shadow ray starts with the camera ray's footprint at the hit (level of detail).
            let shadow = at.shadow_ray(ls.dir, ls.dist, shadow_seed);
            match &mut shadows {
                // Smooth level of detail: each layer its own shadow ray to a singular light.
                Shadows::Shared(shared, weight) if !(world.accel.smooth_layers() && light.is_singular()) => {
                    shared.offer(index, *weight * (f * ls.value), shadow)
                }
                Shadows::Deferred(pixel) => pixel.push(index, f * ls.value, &shadow),
                Shadows::Now | Shadows::Shared(..) => {
                    let transmitted = tracer.transmittance(&shadow);
                    if transmitted > 0.0 {
                        color += f * ls.value * transmitted;
                    }
                }
            }
        }
    }

    if depth < world.settings.max_depth {
        for r in material.specular(sp, at.wo).into_iter().flatten() {
            // Planar approximation: curvature would widen the cone (Akenine-Moller et al.
            // 2021 add it from the normal's screen-space derivatives; we have none yet).
            let next = at.spawn_ray(r.dir);
            color += r.weight * indirect.specular(tracer, &next, depth + 1, sampler);
        }
    }
    color += indirect.diffuse(tracer, &at, depth, sampler);
    (color, first)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The prediction only chooses the queries: a ray that meets semi-transparent coarse fur
    /// first renders bit for bit the same when it skips the closest-hit query, and one that
    /// meets opaque geometry first keeps its first hit.
    #[test]
    fn skipping_the_closest_hit_changes_no_semi_transparent_ray() {
        let world = crate::test_worlds::scene_file("lod_field.toml", (96, 54));
        let (mut semi, mut opaque) = (0, 0);
        for (x, y) in (0..54).flat_map(|y| (0..96).map(move |x| (x, y))) {
            let ray = world.camera.ray(x as f32 + 0.5, y as f32 + 0.5);
            let run = |layers_first| {
                let mut sampler = PixelSampler::new(7, x, y, 0);
                let hint = if layers_first { CameraHint::LayersFirst } else { CameraHint::None };
                trace_camera(&mut Tracer::new(&world), &ray, hint, &mut sampler)
            };
            let ((color, first), (skipped, skipped_first)) = (run(false), run(true));
            let Some(first) = first else { continue };
            let lod_opacity = world.accel.objects[first.object as usize].lod_opacity(first.lod_level.unwrap_or(0));
            if lod_opacity < 1.0 {
                semi += 1;
                assert_eq!(color.to_array().map(f32::to_bits), skipped.to_array().map(f32::to_bits), "pixel {x} {y}");
            } else {
                opaque += 1;
                let f = skipped_first.expect("the same first hit");
                assert_eq!((f.object, f.t.to_bits()), (first.object, first.t.to_bits()), "pixel {x} {y}");
            }
        }
        assert!(semi > 50 && opaque > 50, "{semi} semi-transparent and {opaque} opaque first hits");
    }
}
