//! Where a ray met the world, as the integrators shade it ([`Interaction`]), and the one
//! place rays leaving a hit are made ([`Interaction::spawn_ray`], [`Interaction::shadow_ray`]).

use super::shadow::ShadowRay;
use crate::accel::{Hit, HitKind, Shape};
use crate::geometry::StrandPoint;
use crate::math::{offset_origin, Ray, RayCone, Skip};
use crate::shading::{Material, ShadingPoint, TexCoord};
use crate::world::World;
use glam::Vec3;

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

/// A hit being shaded: the shading point, the material, and what rays leaving it need.
pub(super) struct Interaction<'w> {
    pub sp: ShadingPoint,
    pub hit: Hit,
    pub material: &'w Material,
    /// Unit direction towards where the ray came from.
    pub wo: Vec3,
    /// The footprint of the ray that made the hit (rays leaving it continue it).
    pub cone: RayCone,
    /// For hair: axis point, radius and axis direction at the hit.
    hair: Option<(Vec3, f32, Vec3)>,
    /// Unit geometric normal facing the incoming ray.
    geometric: Vec3,
    /// For hair: the strand and what is known of it at the hit.
    strand_point: Option<StrandPoint>,
}

impl<'w> Interaction<'w> {
    /// The hit of `ray` on `world`, with the strand colour its level of detail gives.
    pub fn new(world: &'w World, ray: &Ray, hit: &Hit) -> Interaction<'w> {
        let object = &world.accel.objects[hit.object as usize];
        let material = &world.materials[object.material as usize];
        let (sp, hair, geometric, strand_point) = match (&object.shape, hit.kind) {
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
                (sp, None, geometric, None)
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
                    // A strand is textured by its root's UV, as Arnold textures a curve by
                    // its `uvs` and Maya a hair by its follicle's: one colour along it, so
                    // the lookup is a point (no footprint across the map).
                    uv: at.root_uv.map(|uv| TexCoord { uv, width: 0.0 }),
                };
                (sp, Some((axis_point, radius, axis)), normal, Some(at))
            }
            _ => unreachable!("hit kinds match their shapes"),
        };
        Interaction { sp, hit: *hit, material, wo: -ray.dir, cone: ray.cone, hair, geometric, strand_point }
    }

    /// True on a strand.
    pub fn on_hair(&self) -> bool {
        self.hair.is_some()
    }

    /// Width of the arriving ray's footprint (its cone) at the hit: about a pixel, seen there.
    pub fn footprint(&self) -> f32 {
        self.cone.width_at(self.hit.t)
    }

    /// The hit as the AOVs record it.
    pub fn first_hit(&self) -> FirstHit {
        FirstHit {
            t: self.hit.t,
            normal: self.sp.tangent.unwrap_or(self.sp.normal),
            object: self.hit.object,
            strand: self.strand_point.map(|p| p.strand),
            strand_point: self.strand_point,
            lod_level: self.strand_point.map(|_| self.hit.level),
        }
    }

    /// The ray leaving the hit along unit `dir` (continuation, gathered, specular and
    /// irradiance-cache rays), unbounded, with the arriving ray's cone carried to the hit;
    /// callers widen it for how the direction was drawn.
    ///
    /// - Surfaces: it starts off the plane by a bound on the point's floating-point error,
    ///   on the side `dir` leaves on.
    /// - Hair: it starts on the strand's circle at the hit, on the side facing `dir`, and
    ///   ignores the hit segment and its two neighbours ([`Ray::skip`]; a bent strand can
    ///   overlap them at the joints). For tube shading the point faces `dir` across the
    ///   axis, since the model shades the whole circle alike; for surface models it is the
    ///   hit itself. No fixed epsilon: radius 1e-4 strands seen from 1e3 units stay
    ///   acne-free. The skip matters on tapered segments, where a ray leaving towards the
    ///   thicker end starts inside the radius the segment test takes for it.
    pub fn spawn_ray(&self, dir: Vec3) -> Ray {
        let (origin, skip) = match self.hair {
            None => {
                let n = if self.geometric.dot(dir) >= 0.0 { self.geometric } else { -self.geometric };
                (offset_origin(self.sp.p, n, 0.0), None)
            }
            Some((axis_point, radius, axis)) => {
                let toward = (dir - axis * dir.dot(axis)).normalize_or(self.sp.normal);
                let whole_circle = self.material.shades_whole_circle();
                let n = if whole_circle || self.sp.normal.dot(dir) <= 0.0 { toward } else { self.sp.normal };
                let origin = offset_origin(axis_point + n * radius, n, radius * 1e-3);
                let (object, prim) = (self.hit.object, self.hit.prim);
                (origin, Some(Skip { object, first: prim.saturating_sub(1), last: prim + 1 }))
            }
        };
        Ray { skip, cone: self.cone.propagate(self.hit.t, 0.0), ..Ray::new(origin, dir) }
    }

    /// The shadow ray towards a light in unit direction `dir` at distance `dist` (infinite
    /// for distant lights and the environment), from where [`Interaction::spawn_ray`]
    /// starts, with the transmittance estimate's `seed` through semi-transparent hair.
    pub fn shadow_ray(&self, dir: Vec3, dist: f32, seed: Option<u32>) -> ShadowRay {
        // Stop short of the light by a relative margin so its own surface does not block.
        let tmax = if dist.is_finite() { dist * (1.0 - 1e-4) } else { f32::INFINITY };
        ShadowRay { ray: Ray { tmax, ..self.spawn_ray(dir) }, seed }
    }
}
