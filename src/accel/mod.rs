//! Acceleration: one BVH per object over its primitives, and a top-level BVH over objects.
//! Answers closest-hit and any-hit (shadow) queries for the integrators, and multi-hit
//! queries for semi-transparent hair ([`Accel::intersect_k`], [`Accel::transmittance`]).

pub mod bvh;
mod layers;

pub use layers::{LayerHit, StochasticTail, EXACT_SHADOW_TRANSMITTANCE, NEGLIGIBLE_TRANSMITTANCE};

use crate::geometry::{segment, triangle, StrandSet, TriangleMesh};
use crate::math::{Aabb, Ray};
use bvh::{BuildItem, Bvh, RayBoxTest};
use glam::Vec3;
use rayon::prelude::*;
use wide::f32x4;

/// The geometry of one object.
#[derive(Clone, Debug)]
pub enum Shape {
    /// A triangle mesh.
    Mesh(TriangleMesh),
    /// A set of hair strands.
    Strands(StrandSet),
}

impl Shape {
    /// Number of primitives (triangles or segments).
    pub fn primitive_count(&self) -> usize {
        match self {
            Shape::Mesh(m) => m.indices.len(),
            Shape::Strands(s) => s.segment_count(),
        }
    }

    /// Bytes held by the shape's own arrays (not its BVH).
    pub fn memory_bytes(&self) -> usize {
        match self {
            Shape::Mesh(m) => m.memory_bytes(),
            Shape::Strands(s) => s.memory_bytes(),
        }
    }
}

/// A shape with its BVH and the index of its material.
#[derive(Clone, Debug)]
pub struct Object {
    /// The geometry.
    pub shape: Shape,
    /// Index into the world's materials.
    pub material: u32,
    bvh: Bvh,
}

impl Object {
    /// The object's BVH.
    pub fn bvh(&self) -> &Bvh {
        &self.bvh
    }
}

/// What was hit on a primitive.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum HitKind {
    /// A triangle, at barycentrics (b1, b2).
    Triangle {
        /// Weight of the second corner.
        b1: f32,
        /// Weight of the third corner.
        b2: f32,
    },
    /// A hair segment, at axis parameter `s`, with the true surface normal there.
    Segment {
        /// Parameter along the segment axis, 0 at its first point.
        s: f32,
        /// Outward normal of the segment surface.
        normal: Vec3,
    },
}

/// The closest hit along a ray.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hit {
    /// Distance along the ray.
    pub t: f32,
    /// Object index.
    pub object: u32,
    /// Triangle index, or the first point of the hit segment.
    pub prim: u32,
    /// Where on the primitive.
    pub kind: HitKind,
}

/// Primitives a shadow ray must ignore: the segments `first..=last` of one object (the
/// hit segment and its neighbours on the strand a shadow ray starts from).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Skip {
    /// Object index.
    pub object: u32,
    /// First ignored primitive.
    pub first: u32,
    /// Last ignored primitive.
    pub last: u32,
}

/// Every object of a scene with its BVH, under a top-level BVH.
#[derive(Clone, Debug, Default)]
pub struct Accel {
    /// The objects, in scene order.
    pub objects: Vec<Object>,
    top: Bvh,
}

impl Accel {
    /// Builds a BVH per object (objects in parallel, and each build in parallel) and the
    /// top level over them.
    pub fn build(shapes: Vec<(Shape, u32)>) -> Accel {
        let objects: Vec<Object> = shapes
            .into_par_iter()
            .map(|(shape, material)| {
                let bvh = Bvh::build(build_items(&shape));
                Object { shape, material, bvh }
            })
            .collect();
        let top = Bvh::build(
            objects.iter().enumerate().map(|(i, o)| BuildItem { bounds: o.bvh.bounds(), id: i as u32 }).collect(),
        );
        Accel { objects, top }
    }

    /// Bounds of the whole scene.
    pub fn bounds(&self) -> Aabb {
        self.top.bounds()
    }

    /// Bytes held by all BVHs (top level included).
    pub fn bvh_bytes(&self) -> usize {
        self.top.memory_bytes() + self.objects.iter().map(|o| o.bvh.memory_bytes()).sum::<usize>()
    }

    /// The closest hit along the ray before `ray.tmax`.
    pub fn intersect(&self, ray: &Ray) -> Option<Hit> {
        self.intersect_among(ray, |_| true)
    }

    /// The closest hit along the ray before `ray.tmax` on the objects `among` accepts.
    #[inline]
    fn intersect_among(&self, ray: &Ray, among: impl Fn(&Object) -> bool) -> Option<Hit> {
        let test = RayBoxTest::new(ray.origin, ray.dir);
        let mut tmax = ray.tmax;
        let mut best = None;
        self.top.traverse(&test, &mut tmax, |objects, tmax| {
            for &object in objects {
                let o = &self.objects[object as usize];
                if !among(o) {
                    continue;
                }
                o.bvh.traverse(&test, tmax, |prims, tmax| {
                    if let Some((prim, t, kind)) =
                        intersect_leaf(&o.shape, prims, ray.origin, ray.dir, *tmax, None, false)
                    {
                        *tmax = t;
                        best = Some(Hit { t, object, prim, kind });
                    }
                    false
                });
            }
            false
        });
        best
    }

    /// True when anything (but the skipped primitives) lies on the segment from `origin`
    /// along unit `dir` up to distance `tmax`.
    pub fn occluded(&self, origin: Vec3, dir: Vec3, tmax: f32, skip: Option<Skip>) -> bool {
        self.occluded_among(origin, dir, tmax, skip, |_| true)
    }

    /// [`Accel::occluded`] by the objects `among` accepts only.
    #[inline]
    fn occluded_among(
        &self,
        origin: Vec3,
        dir: Vec3,
        tmax: f32,
        skip: Option<Skip>,
        among: impl Fn(&Object) -> bool,
    ) -> bool {
        let test = RayBoxTest::new(origin, dir);
        let mut t = tmax;
        let mut blocked = false;
        self.top.traverse(&test, &mut t, |objects, t| {
            for &object in objects {
                let o = &self.objects[object as usize];
                if !among(o) {
                    continue;
                }
                let skip = skip.filter(|s| s.object == object);
                o.bvh.traverse(&test, t, |prims, t| {
                    blocked = intersect_leaf(&o.shape, prims, origin, dir, *t, skip, true).is_some();
                    blocked
                });
                if blocked {
                    return true;
                }
            }
            false
        });
        blocked
    }
}

fn build_items(shape: &Shape) -> Vec<BuildItem> {
    match shape {
        Shape::Mesh(m) => (0..m.indices.len() as u32)
            .map(|i| {
                let [a, b, c] = m.corners(i);
                BuildItem { bounds: Aabb::new(a.min(b).min(c), a.max(b).max(c)), id: i }
            })
            .collect(),
        Shape::Strands(s) => s
            .segment_starts()
            .into_iter()
            .map(|i| {
                let (min, max) = segment::bounds(s.points[i as usize], s.points[i as usize + 1]);
                BuildItem { bounds: Aabb::new(min, max), id: i }
            })
            .collect(),
    }
}

/// The nearest hit among a leaf's primitives before `tmax`, ignoring `skip`: (primitive,
/// distance, where); with `any`, the first hit found. Segments are tested four at a time.
#[inline(always)]
fn intersect_leaf(
    shape: &Shape,
    prims: &[u32],
    origin: Vec3,
    dir: Vec3,
    tmax: f32,
    skip: Option<Skip>,
    any: bool,
) -> Option<(u32, f32, HitKind)> {
    let skipped = |p: u32| skip.is_some_and(|s| (s.first..=s.last).contains(&p));
    let mut best = None;
    let mut tmax = tmax;
    match shape {
        Shape::Mesh(m) => {
            for &p in prims {
                if let Some(h) = triangle::intersect_triangle(origin, dir, 0.0, tmax, m.corners(p)) {
                    tmax = h.t;
                    best = Some((p, h.t, HitKind::Triangle { b1: h.b1, b2: h.b2 }));
                    if any {
                        break;
                    }
                }
            }
        }
        Shape::Strands(s) => {
            for chunk in prims.chunks(4) {
                let (p0, p1) = gather4(s, chunk, skipped);
                let hits = segment::intersect_cylinder4(origin, dir, 0.0, tmax, p0, p1);
                if any && hits.mask != 0 {
                    // Any lane's hit will do: skip forming the normal.
                    let lane = hits.mask.trailing_zeros() as usize;
                    return Some((chunk[lane], hits.t()[lane], HitKind::Segment { s: 0.0, normal: Vec3::ZERO }));
                }
                if let Some(lane) = hits.nearest() {
                    if let Some(h) = hits.hit(lane) {
                        tmax = h.t;
                        best = Some((chunk[lane], h.t, HitKind::Segment { s: h.s, normal: h.normal }));
                    }
                }
            }
        }
    }
    best
}

/// The end points of up to four segments (given by their first points) as the lanes of
/// [`segment::intersect_cylinder4`]; skipped and missing lanes stay empty (no surface).
#[inline(always)]
fn gather4(s: &StrandSet, firsts: &[u32], skipped: impl Fn(u32) -> bool) -> ([f32x4; 4], [f32x4; 4]) {
    let (mut p0, mut p1) = ([f32x4::ZERO; 4], [f32x4::ZERO; 4]);
    for (lane, &p) in firsts.iter().enumerate() {
        if !skipped(p) {
            p0[lane] = f32x4::new(s.points[p as usize]);
            p1[lane] = f32x4::new(s.points[p as usize + 1]);
        }
    }
    (p0, p1)
}

/// One primitive's hit before `tmax`: (distance, where).
#[cfg(test)]
fn intersect_primitive(shape: &Shape, prim: u32, origin: Vec3, dir: Vec3, tmax: f32) -> Option<(f32, HitKind)> {
    intersect_leaf(shape, &[prim], origin, dir, tmax, None, false).map(|(_, t, k)| (t, k))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::rng::GenRng;
    use rand::{Rng, SeedableRng};

    fn random_vec(rng: &mut GenRng, scale: f32) -> Vec3 {
        Vec3::new(rng.random::<f32>() - 0.5, rng.random::<f32>() - 0.5, rng.random::<f32>() - 0.5) * scale
    }

    /// Random triangles and random strands in a box, as two objects.
    fn random_scene(rng: &mut GenRng) -> Accel {
        let mut mesh = TriangleMesh::default();
        for i in 0..2000u32 {
            let c = random_vec(rng, 4.0);
            for _ in 0..3 {
                mesh.positions.push(c + random_vec(rng, 0.3));
            }
            mesh.indices.push([3 * i, 3 * i + 1, 3 * i + 2]);
        }
        let mut strands = StrandSet::new();
        for _ in 0..500 {
            let mut p = random_vec(rng, 4.0);
            let n = rng.random_range(2..8);
            let pts: Vec<(Vec3, f32)> = (0..n)
                .map(|_| {
                    p += random_vec(rng, 0.2);
                    (p, rng.random_range(0.001..0.02))
                })
                .collect();
            strands.push_strand(pts);
        }
        Accel::build(vec![(Shape::Mesh(mesh), 0), (Shape::Strands(strands), 1)])
    }

    fn brute_force(accel: &Accel, ray: &Ray) -> Option<(f32, u32, u32)> {
        let mut best: Option<(f32, u32, u32)> = None;
        for (oi, o) in accel.objects.iter().enumerate() {
            let prims: Vec<u32> = match &o.shape {
                Shape::Mesh(m) => (0..m.indices.len() as u32).collect(),
                Shape::Strands(s) => s.segment_starts(),
            };
            for p in prims {
                let tmax = best.map_or(ray.tmax, |b| b.0);
                if let Some((t, _)) = intersect_primitive(&o.shape, p, ray.origin, ray.dir, tmax) {
                    best = Some((t, oi as u32, p));
                }
            }
        }
        best
    }

    #[test]
    fn closest_hit_and_any_hit_equal_brute_force() {
        let mut rng = GenRng::seed_from_u64(7);
        let accel = random_scene(&mut rng);
        let mut hits = 0;
        for _ in 0..4000 {
            let origin = random_vec(&mut rng, 10.0);
            let target = random_vec(&mut rng, 3.0);
            let ray = Ray::new(origin, (target - origin).normalize());
            let expected = brute_force(&accel, &ray);
            let got = accel.intersect(&ray).map(|h| (h.t, h.object, h.prim));
            assert_eq!(got, expected, "ray {ray:?}");
            hits += expected.is_some() as u32;
            let blocked = accel.occluded(ray.origin, ray.dir, 5.0, None);
            assert_eq!(blocked, expected.is_some_and(|e| e.0 < 5.0));
        }
        assert!(hits > 500, "the test needs rays that hit: {hits}");
    }

    #[test]
    fn skip_ignores_the_named_segments_only() {
        let mut strands = StrandSet::new();
        strands.push_strand([(Vec3::new(-1.0, 0.0, 0.0), 0.1), (Vec3::ZERO, 0.1), (Vec3::new(1.0, 0.0, 0.0), 0.1)]);
        let accel = Accel::build(vec![(Shape::Strands(strands), 0)]);
        let (o, d) = (Vec3::new(-0.5, 1.0, 0.0), -Vec3::Y);
        assert!(accel.occluded(o, d, 10.0, None));
        assert!(!accel.occluded(o, d, 10.0, Some(Skip { object: 0, first: 0, last: 0 })));
        assert!(accel.occluded(o, d, 10.0, Some(Skip { object: 0, first: 1, last: 1 })));
    }
}
