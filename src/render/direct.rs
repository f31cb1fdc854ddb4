//! The direct-lighting (Whitted) integrator: lights with hard or soft shadows (partial
//! through semi-transparent hair), the constant environment as an ambient term and
//! environment maps sampled with MIS (`super::environment`), mirror reflection and
//! refraction up to the maximum depth, and semi-transparent hair blended in layers.
//! The final gather reuses it with an indirect term ([`Indirect`]).

use crate::accel::{Hit, HitKind, Object, Shape, Skip, StochasticTail, NEGLIGIBLE_TRANSMITTANCE};
use crate::geometry::StrandPoint;
use crate::light::{Light, LightSample};
use crate::math::rng::PixelSampler;
use crate::math::{offset_origin, Color, Ray, RayCone, RayMask, PACKET};
use crate::shading::{Material, ShadingPoint, TexCoord};
use crate::world::World;
use glam::Vec3;
use smallvec::SmallVec;

/// Transmittance below which the layers of semi-transparent hair behind are walked
/// stochastically instead of all shaded and blended (`trace_with`). A half: behind a
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

/// Per-task tallies, summed when the render ends.
#[derive(Clone, Copy, Debug, Default)]
pub struct Counters {
    /// Rays traced.
    pub rays: u64,
}

/// What the first hit of a camera ray was, for the AOVs.
#[derive(Clone, Copy, Debug)]
pub struct FirstHit {
    /// Distance along the ray.
    pub t: f32,
    /// Shading normal (surfaces) or tangent (hair).
    pub normal: Vec3,
    /// Object index.
    pub object: u32,
    /// Strand index when the object is hair.
    pub strand: Option<u32>,
    /// Per-strand data at the hit when the object is hair.
    pub strand_point: Option<StrandPoint>,
    /// Level of detail of the hit when the object is hair (0 without level of detail).
    pub lod_level: Option<u32>,
}

/// Where a shadow or secondary ray starts and which primitives it must ignore.
pub(super) struct Departure {
    pub origin: Vec3,
    pub skip: Option<Skip>,
}

/// Hit details the integrator needs beyond the shading point.
pub(super) struct Surface {
    pub sp: ShadingPoint,
    /// For hair: axis point, radius and axis direction at the hit.
    pub hair: Option<(Vec3, f32, Vec3)>,
    /// Unit geometric normal facing the incoming ray.
    pub geometric: Vec3,
    /// For hair: the strand and what is known of it at the hit.
    pub strand_point: Option<StrandPoint>,
}

impl Surface {
    /// The hit as the AOVs record it.
    pub fn first_hit(&self, hit: &Hit) -> FirstHit {
        FirstHit {
            t: hit.t,
            normal: self.sp.tangent.unwrap_or(self.sp.normal),
            object: hit.object,
            strand: self.strand_point.map(|p| p.strand),
            strand_point: self.strand_point,
            lod_level: self.strand_point.map(|_| hit.level),
        }
    }
}

/// Radiance arriving along `ray`, and the first hit for AOVs.
pub fn trace(
    world: &World,
    ray: &Ray,
    depth: u32,
    sampler: &mut PixelSampler,
    counters: &mut Counters,
) -> (Color, Option<FirstHit>) {
    trace_with(world, ray, depth, sampler, counters, &Whitted { see_emitters: true }, true)
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
        hit: Option<Hit>,
        /// The pixel's deferred shadow rays, set to this ray's sample.
        shadows: &'a mut PixelShadows,
    },
    /// The pixel's previous sample met fur drawn semi-transparent for its level of detail
    /// first: likely so for this one too, so the closest-hit query that would come first
    /// is skipped (the samples of a pixel run in a fixed order: deterministic). The
    /// estimate is the same either way.
    LayersFirst,
}

/// [`trace`] for a camera ray, with what its pixel tells of it (`hint`).
pub(super) fn trace_camera(
    world: &World,
    ray: &Ray,
    hint: CameraHint,
    sampler: &mut PixelSampler,
    counters: &mut Counters,
) -> (Color, Option<FirstHit>) {
    trace_hinted(world, ray, hint, sampler, counters, &Whitted { see_emitters: true })
}

/// What an integrator adds to direct light at a hit; the direct integrator and the final
/// gather differ only here.
pub(super) trait Indirect: Sized {
    /// Whether specular rays see lights directly (see [`Whitted`]).
    fn specular_sees_emitters(&self) -> bool {
        true
    }
    /// Radiance arriving along a specular (mirror, glass) ray, `depth` bounces deep.
    fn specular(
        &self,
        world: &World,
        ray: &Ray,
        depth: u32,
        sampler: &mut PixelSampler,
        counters: &mut Counters,
    ) -> Color {
        trace_with(world, ray, depth, sampler, counters, self, self.specular_sees_emitters()).0
    }
    /// Indirect light reflected towards `-ray.dir` at a hit, besides the specular rays.
    fn diffuse(&self, world: &World, at: &At, depth: u32, sampler: &mut PixelSampler, counters: &mut Counters)
        -> Color;
}

/// A hit being shaded, as [`Indirect::diffuse`] sees it.
pub(super) struct At<'a> {
    pub surface: &'a Surface,
    pub hit: &'a Hit,
    pub material: &'a Material,
    pub wo: Vec3,
    /// The footprint of the ray that made the hit (gathered rays continue it).
    pub cone: RayCone,
    /// Width of the ray's footprint (its cone) at the hit: about a pixel, seen there.
    pub footprint: f32,
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
    fn diffuse(&self, _: &World, _: &At, _: u32, _: &mut PixelSampler, _: &mut Counters) -> Color {
        Color::ZERO
    }
}

/// Radiance along `ray` and its first hit, shading each hit with direct light plus what
/// `indirect` adds. Without `see_emitters`, lights and the environment seen along the ray
/// itself count nothing (a gathered ray, whose origin already sampled them).
///
/// Semi-transparent hair (thesis section 2.2.8, fast transparency): one traversal collects
/// the `transparency_layers` nearest hits; they are shaded front to back and blended by
/// their opacity, `C = sum_i T_i a_i C_i` with `T_{i+1} = T_i (1 - a_i)`, stopping at an
/// opaque hit or a negligible `T`; only when every collected hit let enough light through
/// does the ray continue past them with another traversal.
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
pub(super) fn trace_with(
    world: &World,
    ray: &Ray,
    depth: u32,
    sampler: &mut PixelSampler,
    counters: &mut Counters,
    indirect: &impl Indirect,
    see_emitters: bool,
) -> (Color, Option<FirstHit>) {
    trace_from(world, ray, CameraHint::None, depth, sampler, counters, indirect, see_emitters)
}

/// [`trace_with`] for a camera ray (depth 0, emitters seen), with what its pixel tells of it.
pub(super) fn trace_hinted(
    world: &World,
    ray: &Ray,
    hint: CameraHint,
    sampler: &mut PixelSampler,
    counters: &mut Counters,
    indirect: &impl Indirect,
) -> (Color, Option<FirstHit>) {
    trace_from(world, ray, hint, 0, sampler, counters, indirect, true)
}

/// [`trace_with`], with a camera ray's [`CameraHint`].
#[allow(clippy::too_many_arguments)]
fn trace_from(
    world: &World,
    ray: &Ray,
    hint: CameraHint,
    depth: u32,
    sampler: &mut PixelSampler,
    counters: &mut Counters,
    indirect: &impl Indirect,
    see_emitters: bool,
) -> (Color, Option<FirstHit>) {
    counters.rays += 1;
    // Area lights are not in the BVH; a ray sees one if it meets it before any geometry.
    let seen_light = |tmax: f32| {
        world.lights.iter().filter_map(|l| l.emitted(ray.origin, ray.dir, tmax)).min_by(|a, b| a.0.total_cmp(&b.0))
    };
    let emitted = |c: Color| if see_emitters { c } else { Color::ZERO };
    let tail = world
        .accel
        .has_transparency()
        .then(|| StochasticTail { blend: blend_transmittance(world), seed: (sampler.next_1d() * 16_777_216.0) as u32 });
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
            if let Some((_, radiance)) = seen_light(hit.map_or(ray.tmax, |h| h.t)) {
                return (emitted(radiance), None);
            }
            let Some(hit) = hit else {
                return (emitted(super::environment::sky(world, ray.dir, |_| 1.0)), None);
            };
            let (color, first) = shade(world, ray, &hit, depth, sampler, counters, indirect, shadows);
            return (color, Some(first));
        }
    };
    let k = world.settings.transparency_layers as usize;
    let (mut layers, mut seen) = (Vec::with_capacity(k), Vec::new());
    // `transmitted`: the light passing every layer so far; `carried`: the weight of what
    // is shaded next (equal to it while blending, frozen once the tail is walked).
    // After a closest hit, nothing lies nearer: the layers start just before it, and the
    // BVH boxes the ray leaves before that are not entered (lod_field.toml: -1.6 % instructions).
    let tmin = hit.map_or(0.0, |h| h.t * (1.0 - 4.0 * f32::EPSILON));
    let (mut color, mut transmitted, mut carried, mut first, mut tmin) = (Color::ZERO, 1.0f32, 1.0f32, None, tmin);
    let mut shadows = SharedShadows::new(world.lights.len(), sampler);
    let color = 'layers: loop {
        world.accel.intersect_k(ray, tmin, k, &seen, Some(tail), &mut layers);
        // Lights count up to where the collected hits may hide what lies behind them.
        let light = match layers.last() {
            Some(l) if layers.len() == k || l.opacity >= 1.0 => seen_light(l.hit.t),
            _ => seen_light(ray.tmax),
        };
        for layer in layers.iter().take_while(|l| light.is_none_or(|(t, _)| l.hit.t < t)) {
            let a = layer.opacity;
            let blend = carried >= tail.blend;
            let last = transmitted * (1.0 - a) < NEGLIGIBLE_TRANSMITTANCE;
            if blend || last || tail.draw(&layer.hit) < a {
                // Blended by its opacity, or where the tail stops with all the light left.
                let weight = if blend { carried * a } else { carried };
                let shared = Shadows::Shared(&mut shadows, weight);
                let (c, f) = shade(world, ray, &layer.hit, depth, sampler, counters, indirect, shared);
                first.get_or_insert(f);
                color += weight * c;
                if !blend {
                    break 'layers color;
                }
                carried *= 1.0 - a;
            }
            transmitted *= 1.0 - a;
            if transmitted < NEGLIGIBLE_TRANSMITTANCE {
                break 'layers color;
            }
        }
        if let Some((_, radiance)) = light {
            break 'layers color + carried * emitted(radiance);
        }
        if layers.len() < k {
            break 'layers color + carried * emitted(super::environment::sky(world, ray.dir, |_| 1.0));
        }
        // Every hit collected let light through: continue behind the farthest.
        tmin = layers[k - 1].hit.t;
        seen.extend_from_slice(&layers);
        counters.rays += 1;
    };
    (color + shadows.trace(world, counters), first)
}

/// The transmittance below which a camera ray's layers are walked stochastically.
fn blend_transmittance(world: &World) -> f32 {
    if world.accel.smooth_layers() {
        SMOOTH_BLEND_TRANSMITTANCE
    } else {
        BLEND_TRANSMITTANCE
    }
}

/// A shadow ray towards a light.
#[derive(Clone, Copy)]
struct ShadowRay {
    origin: Vec3,
    dir: Vec3,
    tmax: f32,
    skip: Option<Skip>,
    /// The footprint it starts with (level of detail).
    cone: RayCone,
    /// Seed of the stochastic transmittance estimate, when hair is semi-transparent.
    seed: Option<u32>,
}

impl ShadowRay {
    /// The light it lets through (estimated through semi-transparent hair).
    fn trace(&self, world: &World, counters: &mut Counters) -> f32 {
        counters.rays += 1;
        world.accel.transmittance_cone(self.origin, self.dir, self.tmax, self.skip, self.cone, self.seed)
    }
}

/// Where [`shade`] sends the shadow rays of a hit.
enum Shadows<'a> {
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
    skips: Vec<Option<Skip>>,
    /// Per ray, its sample and the light it adds when nothing blocks it.
    adds: Vec<(u32, Color)>,
}

impl PixelShadows {
    /// Sets the sample whose shadow rays come next; returns `self` for a [`CameraHint`].
    pub fn for_sample(&mut self, sample: usize) -> &mut PixelShadows {
        self.sample = sample as u32;
        self
    }

    fn push(&mut self, light: usize, value: Color, shadow: &ShadowRay) {
        if self.lights.len() <= light {
            self.lights.resize_with(light + 1, LightRays::default);
        }
        let rays = &mut self.lights[light];
        rays.rays.push(Ray { origin: shadow.origin, dir: shadow.dir, tmax: shadow.tmax, cone: shadow.cone });
        rays.skips.push(shadow.skip);
        rays.adds.push((self.sample, value));
    }

    /// Traces the kept rays, light by light in the order of the samples, [`PACKET`] at a
    /// time (fewer than [`MIN_PACKET`] one by one), adding the light of each unblocked one
    /// to `colors[sample]`; then forgets them.
    pub fn trace(&mut self, world: &World, colors: &mut [Color], counters: &mut Counters) {
        for light in &mut self.lights {
            counters.rays += light.rays.len() as u64;
            let chunks = light.rays.chunks(PACKET).zip(light.skips.chunks(PACKET)).zip(light.adds.chunks(PACKET));
            for ((rays, skips), adds) in chunks {
                let blocked = if rays.len() >= MIN_PACKET {
                    world.accel.occluded_packet(rays, skips)
                } else {
                    rays.iter().zip(skips).enumerate().fold(0, |mask, (i, (r, &skip))| {
                        let open = world.accel.transmittance_cone(r.origin, r.dir, r.tmax, skip, r.cone, None);
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
            light.skips.clear();
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
/// With smooth level of detail ([`crate::accel::Accel::smooth_layers`]), [`shade`] offers
/// no singular light ([`crate::light::Light::is_singular`]): every layer traces its own
/// shadow ray to it. A pick toggles to another layer, whose shadow may differ entirely, as
/// strands slide under a fixed sample; that made most of the far fur's flicker in a camera
/// move (docs/performance.md, tried and not kept).
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
    fn new(lights: usize, sampler: &mut PixelSampler) -> SharedShadows {
        let u = sampler.next_1d();
        let mut picks: SmallVec<[Pick; 4]> = smallvec::smallvec![Pick::default(); lights];
        for (l, pick) in picks.iter_mut().enumerate() {
            pick.u = (u + l as f32 * 0.618_034).fract();
        }
        SharedShadows { picks }
    }

    /// Offers the unshadowed light `value` that light number `light` sends along `shadow`.
    fn offer(&mut self, light: usize, value: Color, shadow: ShadowRay) {
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
    fn trace(&self, world: &World, counters: &mut Counters) -> Color {
        let mut color = Color::ZERO;
        for pick in &self.picks {
            let Some((value, weight, shadow)) = pick.chosen else { continue };
            let transmitted = shadow.trace(world, counters);
            if transmitted > 0.0 {
                color += value * (pick.total / weight * transmitted);
            }
        }
        color
    }
}

/// Direct light at one hit, the specular rays and what `indirect` adds; and the hit's
/// description for the AOVs. With `shared` shadows and the hit's blend weight, the direct
/// light is offered to them instead of added (the caller traces their shadow rays); with
/// deferred shadows, kept for the pixel's packets.
#[allow(clippy::too_many_arguments)]
fn shade(
    world: &World,
    ray: &Ray,
    hit: &Hit,
    depth: u32,
    sampler: &mut PixelSampler,
    counters: &mut Counters,
    indirect: &impl Indirect,
    mut shadows: Shadows,
) -> (Color, FirstHit) {
    let object = &world.accel.objects[hit.object as usize];
    let material = &world.materials[object.material as usize];
    let surface = surface_at(object, hit, ray);
    let sp = &surface.sp;
    let wo = -ray.dir;
    let first = surface.first_hit(hit);

    let mut color = material.ambient(sp, world.background);
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
        let samples = match *light {
            // A constant environment is best sampled by a material that can sample its own
            // response (the hair BSDF, whose lobes the sphere's uniform samples would miss).
            Light::Environment { radiance } => [
                match material.sample_direction(sp, wo, sampler) {
                    Some((dir, pdf)) => Some(LightSample { dir, dist: f32::INFINITY, value: radiance / pdf }),
                    None => light.sample(sp.p, normal, sampler.next_2d()),
                },
                None,
            ],
            Light::EnvironmentMap(ref map) => super::environment::map_samples(map, material, sp, wo, sampler),
            _ => [light.sample(sp.p, normal, sampler.next_2d()), None],
        };
        for ls in samples.into_iter().flatten() {
            let f = material.response(sp, wo, ls.dir);
            if f.max_element() <= 0.0 {
                continue;
            }
            let d = departure(&surface, hit, ls.dir, material.shades_whole_circle());
            // Stop short of the light by a relative margin so its own surface does not block.
            let tmax = if ls.dist.is_finite() { ls.dist * (1.0 - 1e-4) } else { f32::INFINITY };
            // Hair lets light through by its opacity; meshes and opaque strands block it. The
            // estimate stops at the first hits like an opaque shadow ray, most of the time.
            // The shadow ray starts with the camera ray's footprint at the hit (level of detail).
            let cone = ray.cone.propagate(hit.t, 0.0);
            let shadow = ShadowRay { origin: d.origin, dir: ls.dir, tmax, skip: d.skip, cone, seed: shadow_seed };
            match &mut shadows {
                // Smooth level of detail: each layer its own shadow ray to a singular light.
                Shadows::Shared(shared, weight) if !(world.accel.smooth_layers() && light.is_singular()) => {
                    shared.offer(index, *weight * (f * ls.value), shadow)
                }
                Shadows::Deferred(pixel) => pixel.push(index, f * ls.value, &shadow),
                Shadows::Now | Shadows::Shared(..) => {
                    let transmitted = shadow.trace(world, counters);
                    if transmitted > 0.0 {
                        color += f * ls.value * transmitted;
                    }
                }
            }
        }
    }

    if depth < world.settings.max_depth {
        for r in material.specular(sp, wo).into_iter().flatten() {
            let d = departure(&surface, hit, r.dir, false);
            let mut next = Ray::new(d.origin, r.dir);
            // Planar approximation: curvature would widen the cone (Akenine-Moller et al.
            // 2021 add it from the normal's screen-space derivatives; we have none yet).
            next.cone = ray.cone.propagate(hit.t, 0.0);
            color += r.weight * indirect.specular(world, &next, depth + 1, sampler, counters);
        }
    }
    let at = At { surface: &surface, hit, material, wo, cone: ray.cone, footprint: ray.cone.width_at(hit.t) };
    color += indirect.diffuse(world, &at, depth, sampler, counters);
    (color, first)
}

/// Builds the shading point from a hit on `object`, with the strand colour its level of
/// detail gives.
pub(super) fn surface_at(object: &Object, hit: &Hit, ray: &Ray) -> Surface {
    match (&object.shape, hit.kind) {
        (Shape::Mesh(mesh), HitKind::Triangle { b1, b2 }) => {
            let [a, b, c] = mesh.corners(hit.prim);
            // Interpolating the corners is more precise than origin + t * dir far away.
            let p = a * (1.0 - b1 - b2) + b * b1 + c * b2;
            let mut geometric = (b - a).cross(c - a).normalize_or(Vec3::Y);
            let mut normal = mesh.shading_normal(hit.prim, b1, b2);
            let backface = geometric.dot(ray.dir) > 0.0;
            if backface {
                geometric = -geometric;
                normal = -normal;
            }
            if normal.dot(geometric) < 0.0 {
                // An interpolated normal may face away at grazing angles; keep it usable.
                normal = geometric;
            }
            // The footprint on the surface: the cone's width, stretched at grazing angles.
            let uv = mesh.uv_at(hit.prim, b1, b2).map(|(uv, density)| {
                let stretch = 1.0 / geometric.dot(ray.dir).abs().max(0.05);
                TexCoord { uv, width: ray.cone.width_at(hit.t) * stretch * density }
            });
            let sp = ShadingPoint { p, normal, tangent: None, color: None, backface, strand: None, uv };
            Surface { sp, hair: None, geometric, strand_point: None }
        }
        (Shape::Strands(strands), HitKind::Segment { s, normal }) => {
            let i = hit.prim as usize;
            let (p0, p1) = (strands.points[i], strands.points[i + 1]);
            let (a0, a1) = (Vec3::new(p0[0], p0[1], p0[2]), Vec3::new(p1[0], p1[1], p1[2]));
            let axis_point = a0.lerp(a1, s);
            // Widened for the level of detail the hit used.
            let radius = (p0[3] + (p1[3] - p0[3]) * s) * hit.radius_scale;
            let axis = (a1 - a0).normalize_or(Vec3::Y);
            // Reconstruct the hit on the surface from the segment itself: its error is
            // relative to the segment's coordinates, not to the ray's length.
            let p = axis_point + normal * radius;
            // One search for the strand serves the tangent, shading and the AOVs.
            let (at, tangent) = strands.hit_point(hit.prim, s);
            let sp = ShadingPoint {
                p,
                normal,
                tangent: Some(tangent),
                color: object.lod_color(hit.level, strands.color(hit.prim, s)),
                backface: false,
                strand: Some((at.strand, at.along)),
                uv: None,
            };
            Surface { sp, hair: Some((axis_point, radius, axis)), geometric: normal, strand_point: Some(at) }
        }
        _ => unreachable!("hit kinds match their shapes"),
    }
}

/// Where a ray towards `dir` leaves the hit point without hitting it again.
///
/// - Surfaces: the point moved off the plane by a bound on its floating-point error, to the
///   side `dir` leaves on.
/// - Hair: the ray starts on the strand's circle at the hit, on the side facing `dir`, and
///   ignores the hit segment and its two neighbours (which a bent strand can overlap at the
///   joints). For tube shading the point faces `dir` across the axis, since the model
///   shades the whole circle alike; for surface models it is the hit itself. No fixed
///   epsilon: radius 1e-4 strands seen from 1e3 units stay acne-free.
pub(super) fn departure(surface: &Surface, hit: &Hit, dir: Vec3, tube: bool) -> Departure {
    match surface.hair {
        None => {
            let n = if surface.geometric.dot(dir) >= 0.0 { surface.geometric } else { -surface.geometric };
            Departure { origin: offset_origin(surface.sp.p, n, 0.0), skip: None }
        }
        Some((axis_point, radius, axis)) => {
            let toward = (dir - axis * dir.dot(axis)).normalize_or(surface.sp.normal);
            let n = if tube || surface.sp.normal.dot(dir) <= 0.0 { toward } else { surface.sp.normal };
            let origin = offset_origin(axis_point + n * radius, n, radius * 1e-3);
            let skip = Skip { object: hit.object, first: hit.prim.saturating_sub(1), last: hit.prim + 1 };
            Departure { origin, skip: Some(skip) }
        }
    }
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
        let whitted = Whitted { see_emitters: true };
        let (mut semi, mut opaque) = (0, 0);
        for (x, y) in (0..54).flat_map(|y| (0..96).map(move |x| (x, y))) {
            let ray = world.camera.ray(x as f32 + 0.5, y as f32 + 0.5);
            let run = |layers_first| {
                let mut sampler = PixelSampler::new(7, x, y, 0);
                let hint = if layers_first { CameraHint::LayersFirst } else { CameraHint::None };
                trace_hinted(&world, &ray, hint, &mut sampler, &mut Counters::default(), &whitted)
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
