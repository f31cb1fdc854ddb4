//! The direct-lighting (Whitted) integrator: lights with hard shadows, the environment as
//! an ambient term, and mirror reflection and refraction up to the maximum depth.

use crate::accel::{Hit, HitKind, Shape, Skip};
use crate::geometry::StrandPoint;
use crate::light::{Light, LightSample};
use crate::math::rng::PixelSampler;
use crate::math::{offset_origin, Color, Ray};
use crate::scene::World;
use crate::shading::{Material, ShadingPoint};
use glam::Vec3;

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
}

/// Where a shadow or secondary ray starts and which primitives it must ignore.
struct Departure {
    origin: Vec3,
    skip: Option<Skip>,
}

/// Hit details the integrator needs beyond the shading point.
struct Surface {
    sp: ShadingPoint,
    /// For hair: axis point, radius and axis direction at the hit.
    hair: Option<(Vec3, f32, Vec3)>,
    /// Unit geometric normal facing the incoming ray.
    geometric: Vec3,
}

/// Radiance arriving along `ray`, and the first hit for AOVs.
pub fn trace(
    world: &World,
    ray: &Ray,
    depth: u32,
    sampler: &mut PixelSampler,
    counters: &mut Counters,
) -> (Color, Option<FirstHit>) {
    counters.rays += 1;
    let (hit, passed, moved) = first_opaque_hit(world, ray, sampler, counters);
    let t_hit = hit.map_or(ray.tmax, |h| passed + h.t);
    // Area lights are not in the BVH; a ray sees one if it meets it before any geometry.
    let seen_light =
        world.lights.iter().filter_map(|l| l.emitted(ray.origin, ray.dir, t_hit)).min_by(|a, b| a.0.total_cmp(&b.0));
    if let Some((_, radiance)) = seen_light {
        return (radiance, None);
    }
    let Some(hit) = hit else {
        return (world.background, None);
    };
    let ray = &moved;
    let object = &world.accel.objects[hit.object as usize];
    let material = &world.materials[object.material as usize];
    let surface = surface_at(&object.shape, &hit, ray);
    let sp = &surface.sp;
    let wo = -ray.dir;
    let first = FirstHit {
        t: passed + hit.t,
        normal: sp.tangent.unwrap_or(sp.normal),
        object: hit.object,
        strand: match &object.shape {
            Shape::Strands(s) => Some(s.strand_of(hit.prim)),
            Shape::Mesh(_) => None,
        },
        strand_point: match (&object.shape, hit.kind) {
            (Shape::Strands(s), HitKind::Segment { s: along, .. }) => Some(s.strand_point(hit.prim, along)),
            _ => None,
        },
    };

    let mut color = material.ambient(sp, world.background);
    let tube_hair = material.has_ambient_term(sp);
    for light in &world.lights {
        if tube_hair && light.background() != Color::ZERO {
            continue; // the tube model's ambient term already stands for the environment
        }
        let normal = if tube_hair { None } else { Some(sp.normal) };
        let ls = match *light {
            // A constant environment is best sampled by a material that can sample its own
            // response (the hair BSDF, whose lobes the sphere's uniform samples would miss).
            Light::Environment { radiance } => match material.sample_direction(sp, wo, sampler) {
                Some((dir, pdf)) => Some(LightSample { dir, dist: f32::INFINITY, value: radiance / pdf }),
                None => light.sample(sp.p, normal, sampler.next_2d()),
            },
            _ => light.sample(sp.p, normal, sampler.next_2d()),
        };
        let Some(ls) = ls else { continue };
        let f = material.response(sp, wo, ls.dir);
        if f.max_element() <= 0.0 {
            continue;
        }
        let d = departure(&surface, &hit, ls.dir, matches!(material, Material::Tube(_) | Material::Fur(_)));
        counters.rays += 1;
        // Stop short of the light by a relative margin so its own surface does not block.
        let tmax = if ls.dist.is_finite() { ls.dist * (1.0 - 1e-4) } else { f32::INFINITY };
        if !world.accel.occluded(d.origin, ls.dir, tmax, d.skip) {
            color += f * ls.value;
        }
    }

    if depth < world.settings.max_depth {
        for r in material.specular(sp, wo).into_iter().flatten() {
            let d = departure(&surface, &hit, r.dir, false);
            let mut next = Ray::new(d.origin, r.dir);
            // Planar approximation: curvature would widen the cone (Akenine-Moller et al.
            // 2021 add it from the normal's screen-space derivatives; we have none yet).
            next.cone = ray.cone.propagate(hit.t, 0.0);
            color += r.weight * trace(world, &next, depth + 1, sampler, counters).0;
        }
    }
    (color, Some(first))
}

/// Most semi-transparent strand points one ray passes before it stops at the next hit.
const MAX_PASSES: u32 = 64;

/// The first hit along `ray` that stops it. A strand point of opacity `a` (from the strand
/// set's per-point opacity) stops the ray with probability `a`, else the ray goes on past
/// that segment: stochastic transparency (Enderton et al. 2010), which averages to
/// `a * front + (1 - a) * behind` over a pixel's samples without sorting hits. Returns the
/// hit, the distance already travelled and the ray it lies on (starting at the last
/// passed point, with its cone widened to there). Shadow rays treat strands as opaque.
fn first_opaque_hit(
    world: &World,
    ray: &Ray,
    sampler: &mut PixelSampler,
    counters: &mut Counters,
) -> (Option<Hit>, f32, Ray) {
    let (mut current, mut passed) = (*ray, 0.0);
    let mut hit = world.accel.intersect(ray);
    for _ in 0..MAX_PASSES {
        let Some(h) = hit else { break };
        let opacity = match (&world.accel.objects[h.object as usize].shape, h.kind) {
            (Shape::Strands(s), HitKind::Segment { s: at, .. }) => s.opacity_at(h.prim, at),
            _ => 1.0,
        };
        if opacity >= 1.0 || sampler.next_1d() < opacity {
            break;
        }
        passed += h.t;
        current = Ray {
            origin: ray.at(passed),
            dir: ray.dir,
            tmax: ray.tmax - passed,
            cone: ray.cone.propagate(passed, 0.0),
        };
        let skip = Skip { object: h.object, first: h.prim.saturating_sub(1), last: h.prim + 1 };
        counters.rays += 1;
        hit = world.accel.intersect_skipping(&current, Some(skip));
    }
    (hit, passed, current)
}

/// Builds the shading point from a hit.
fn surface_at(shape: &Shape, hit: &Hit, ray: &Ray) -> Surface {
    match (shape, hit.kind) {
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
            let sp = ShadingPoint { p, normal, tangent: None, color: None, backface, strand: None };
            Surface { sp, hair: None, geometric }
        }
        (Shape::Strands(strands), HitKind::Segment { s, normal }) => {
            let i = hit.prim as usize;
            let (p0, p1) = (strands.points[i], strands.points[i + 1]);
            let (a0, a1) = (Vec3::new(p0[0], p0[1], p0[2]), Vec3::new(p1[0], p1[1], p1[2]));
            let axis_point = a0.lerp(a1, s);
            let radius = p0[3] + (p1[3] - p0[3]) * s;
            let axis = (a1 - a0).normalize_or(Vec3::Y);
            // Reconstruct the hit on the surface from the segment itself: its error is
            // relative to the segment's coordinates, not to the ray's length.
            let p = axis_point + normal * radius;
            let tangent = strands.tangent(hit.prim, s);
            let at = strands.strand_point(hit.prim, s);
            let sp = ShadingPoint {
                p,
                normal,
                tangent: Some(tangent),
                color: strands.color(hit.prim, s),
                backface: false,
                strand: Some((at.strand, at.along)),
            };
            Surface { sp, hair: Some((axis_point, radius, axis)), geometric: normal }
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
fn departure(surface: &Surface, hit: &Hit, dir: Vec3, tube: bool) -> Departure {
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
