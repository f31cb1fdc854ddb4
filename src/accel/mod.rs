//! Acceleration: one BVH per object over its primitives, and a top-level BVH over objects.
//! Answers closest-hit and any-hit (shadow) queries for the integrators, and multi-hit
//! queries for semi-transparent hair ([`Accel::intersect_k`], [`Accel::transmittance`]).
//! A strand set with level of detail keeps one BVH whose items carry their pruning group
//! ([`lod`]); every query sees it at the level of its ray's cone (`Object::traverse`).

/// Defines a query `$name` whose body is compiled twice, for AVX2 and FMA (`$avx2`) and
/// portably (`$portable`), and picks one at run time. A query's leaf tests are closures
/// handed to the traversal, and a closure is compiled with its enclosing function's target
/// features: written in the AVX2 copy, the leaf tests get 3-operand AVX code and inline
/// the AVX2 segment cull ([`segment::near8`]) and node tests, where the portable copy
/// called them (single camera rays on the hairy torus: -4.7 % instructions). Both copies
/// run the same operations, without fused multiply-adds unless written out, so they give
/// the same hits.
macro_rules! simd_query {
    ($(#[$attr:meta])* pub fn $name:ident / $avx2:ident / $portable:ident
        (&$self:ident $(, $arg:ident : $ty:ty)* $(,)?) -> $ret:ty $body:block) => {
        $(#[$attr])*
        pub fn $name(&$self $(, $arg: $ty)*) -> $ret {
            #[cfg(target_arch = "x86_64")]
            if std::is_x86_feature_detected!("avx2") && std::is_x86_feature_detected!("fma") {
                // SAFETY: the CPU has the features the copy is compiled for.
                return unsafe { $self.$avx2($($arg),*) };
            }
            $self.$portable($($arg),*)
        }

        #[cfg(target_arch = "x86_64")]
        #[target_feature(enable = "avx2,fma")]
        fn $avx2(&$self $(, $arg: $ty)*) -> $ret $body

        #[inline(always)]
        fn $portable(&$self $(, $arg: $ty)*) -> $ret $body
    };
}

pub mod bvh;
mod layers;
pub mod lod;

pub use layers::{
    LayerHit, StochasticTail, EXACT_SHADOW_TRANSMITTANCE, NEGLIGIBLE_TRANSMITTANCE, SMOOTH_EXACT_SHADOW_TRANSMITTANCE,
};

use crate::geometry::{segment, triangle, StrandSet, TriangleMesh};
use crate::math::{Aabb, Ray, RayCone, RayMask, Skip, PACKET};
use bvh::{BuildItem, Bvh, RayBoxTest};
use glam::Vec3;
use lod::{LodCamera, LodLeaf, LodParams, LodRay, StrandLod, Widen};
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
    /// The BVH over all primitives (for level of detail, items carry their group).
    bvh: Bvh,
    /// Pruning levels, for strand sets with level of detail.
    lod: Option<StrandLod>,
}

impl Object {
    /// The object's BVH.
    pub fn bvh(&self) -> &Bvh {
        &self.bvh
    }

    /// The object's pruning levels, when it is a strand set with level of detail.
    pub fn lod(&self) -> Option<&StrandLod> {
        self.lod.as_ref()
    }

    /// Bytes of the object's BVH.
    pub fn bvh_bytes(&self) -> usize {
        self.bvh.memory_bytes()
    }

    /// Bytes the object's BVH would take without level of detail (built to measure what
    /// the LOD's widened bounds add; the object's own BVH when it has none).
    pub fn plain_bvh_bytes(&self) -> usize {
        match self.lod {
            Some(_) => Bvh::build(build_items(&self.shape)).memory_bytes(),
            None => self.bvh.memory_bytes(),
        }
    }

    /// Factor the radius of a strand hit at `level` was widened by (1 without level of detail).
    pub fn radius_scale(&self, level: u32) -> f32 {
        self.lod.as_ref().map_or(1.0, |l| l.radius_scale(level))
    }

    /// Visits the leaves of the object's BVH that `test` enters before `*tmax`.
    /// `leaf(prims, widen, tmax)` tests a leaf's items, seeing segments at the ray's level
    /// of detail through `widen`, shortens `*tmax` on a hit and returns true to stop; so
    /// does this function.
    #[inline]
    pub(crate) fn traverse(
        &self,
        test: &RayBoxTest,
        ray: &LodRay,
        tmax: &mut f32,
        mut leaf: impl FnMut(&[u32], Widen, &mut f32) -> bool,
    ) -> bool {
        let mut stop = false;
        // Branch once per object: without level of detail, `widen` is a constant `None`
        // in the inlined leaf test, which is then the plain one.
        match &self.lod {
            None => self.bvh.traverse::<false>(test, tmax, |prims, _, t| {
                stop = leaf(prims, None, t);
                stop
            }),
            Some(lod) => {
                let view = lod.view(ray);
                self.bvh.traverse::<true>(test, tmax, |prims, tag, t| {
                    stop = leaf(prims, Some(&view.leaf(tag)), t);
                    stop
                })
            }
        }
        stop
    }

    /// Factor on the opacity of a strand hit at `level` (1 without level of detail):
    /// coarse strands drawn wider are as much more transparent ([`StrandLod::opacity`]);
    /// with a tent profile ([`LodParams::smooth`]), this is its peak.
    pub fn lod_opacity(&self, level: u32) -> f32 {
        self.lod.as_ref().map_or(1.0, |l| l.opacity(level))
    }

    /// [`Object::lod_opacity`] where the line from `origin` along `dir` meets the segment
    /// from point `prim` at parameter `along`: with a tent profile, it falls from the peak
    /// on the axis to 0 at the drawn radius, with the distance between the ray's line and
    /// the axis' (the ray then crosses the strand at that offset; a ray along the axis
    /// sees the peak).
    pub fn lod_opacity_at(&self, prim: u32, along: f32, level: u32, (origin, dir): (Vec3, Vec3)) -> f32 {
        let (Some(lod), Shape::Strands(s)) = (&self.lod, &self.shape) else { return 1.0 };
        lod.opacity_at(level, || {
            let (a, b) = (s.points[prim as usize], s.points[prim as usize + 1]);
            let (pa, pb) = (Vec3::new(a[0], a[1], a[2]), Vec3::new(b[0], b[1], b[2]));
            let normal = (pb - pa).cross(dir).normalize_or_zero();
            let radius = (a[3] + (b[3] - a[3]) * along) * lod.radius_scale(level);
            (pa - origin).dot(normal).abs() / radius
        })
    }

    /// The colour of a strand hit at `level`, its contrast reduced when the object's level
    /// of detail asks for it ([`StrandLod::color`]); unchanged without level of detail.
    pub fn lod_color(&self, level: u32, color: Option<Vec3>) -> Option<Vec3> {
        self.lod.as_ref().map_or(color, |l| l.color(level, color))
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
    /// Pruning level of a strand hit (0 without level of detail).
    pub level: u32,
    /// Factor the hit segment's radius was widened by for its level (1 at level 0).
    pub radius_scale: f32,
}

/// Which rays see an object, and whether camera rays see it as a holdout: the per-object
/// switches of Arnold's shapes (`visibility` camera and shadow rays, `matte`) and of
/// Cycles' objects (camera and shadow ray visibility, holdout).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Visibility {
    /// Camera rays see it; otherwise they pass through it, and only other rays (shadow,
    /// specular, indirect) meet it.
    pub camera: bool,
    /// It blocks shadow rays (casts shadows); otherwise shadow rays pass through it.
    pub shadows: bool,
    /// A holdout: where camera rays meet it first the pixel is black and transparent
    /// (alpha 0), yet it hides what lies behind it; other rays see it as usual.
    pub matte: bool,
}

impl Default for Visibility {
    /// Seen by every ray, not a holdout.
    fn default() -> Self {
        Visibility { camera: true, shadows: true, matte: false }
    }
}

/// Bits of an object's flags ([`Accel::set_visibility`]): a query for camera rays skips
/// objects with [`HIDDEN_FROM_CAMERA`], one for shadow rays those with [`CASTS_NO_SHADOWS`].
const HIDDEN_FROM_CAMERA: u8 = 1;
const CASTS_NO_SHADOWS: u8 = 2;
const MATTE: u8 = 4;

impl Visibility {
    /// The flag bits of an object seen so.
    fn bits(self) -> u8 {
        (!self.camera as u8 * HIDDEN_FROM_CAMERA)
            | (!self.shadows as u8 * CASTS_NO_SHADOWS)
            | (self.matte as u8 * MATTE)
    }

    /// The visibility of flag bits `bits`.
    fn from_bits(bits: u8) -> Visibility {
        Visibility {
            camera: bits & HIDDEN_FROM_CAMERA == 0,
            shadows: bits & CASTS_NO_SHADOWS == 0,
            matte: bits & MATTE != 0,
        }
    }
}

/// Every object of a scene with its BVH, under a top-level BVH.
#[derive(Clone, Debug, Default)]
pub struct Accel {
    /// The objects, in scene order.
    pub objects: Vec<Object>,
    /// Each object's visibility flags (`HIDDEN_FROM_CAMERA`, ...): one byte per object, read
    /// in the top-level leaves; empty while every object is seen by every ray.
    flags: Vec<u8>,
    /// Every object's flags or-ed: a query whose ray kind no object hides from looks at
    /// none of them.
    any_flags: u8,
    top: Bvh,
    /// Some strand set asks for smooth level of detail ([`Accel::smooth_layers`]).
    smooth: bool,
}

impl Accel {
    /// Builds a BVH per object (objects in parallel, and each build in parallel) and the
    /// top level over them.
    pub fn build(shapes: Vec<(Shape, u32)>) -> Accel {
        Accel::build_with_lod(shapes.into_iter().map(|(shape, material)| (shape, material, None)).collect())
    }

    /// Like [`Accel::build`], with level of detail for the strand sets given [`LodParams`]:
    /// their strands are pruned (ranks seeded by the object index) into groups, which
    /// their BVH's items carry. Meshes ignore the parameters.
    pub fn build_with_lod(shapes: Vec<(Shape, u32, Option<LodParams>)>) -> Accel {
        Accel::build_with_lod_for(shapes, None)
    }

    /// Like [`Accel::build_with_lod`], for rendering from `camera`: the strand sets' levels
    /// are bounded by what the camera sees of them ([`LodCamera`]), which keeps their BVH
    /// boxes tight near the camera.
    pub fn build_with_lod_for(shapes: Vec<(Shape, u32, Option<LodParams>)>, camera: Option<LodCamera>) -> Accel {
        let objects: Vec<Object> = shapes
            .into_par_iter()
            .enumerate()
            .map(|(i, (shape, material, params))| {
                let lod = match (&shape, params) {
                    (Shape::Strands(s), Some(p)) => {
                        StrandLod::build(s, p, lod_seed(i))
                            .map(|l| if let Some(c) = camera { l.for_camera(c) } else { l })
                    }
                    _ => None,
                };
                let items = match (&shape, &lod) {
                    (Shape::Strands(s), Some(l)) => l.items(s),
                    _ => build_items(&shape),
                };
                let bvh = Bvh::build(items);
                Object { shape, material, bvh, lod }
            })
            .collect();
        let top =
            Bvh::build(objects.iter().enumerate().map(|(i, o)| BuildItem::new(o.bvh.bounds(), i as u32)).collect());
        let smooth = objects.iter().any(|o| o.lod().is_some_and(|l| l.params().smooth && l.has_transparency()));
        Accel { objects, flags: Vec::new(), any_flags: 0, top, smooth }
    }

    /// Sets which rays see each object, in object order (objects past the end of
    /// `visibility` are seen by every ray, as every object is until set).
    pub fn set_visibility(&mut self, visibility: impl IntoIterator<Item = Visibility>) {
        let mut bits: Vec<u8> = visibility.into_iter().take(self.objects.len()).map(Visibility::bits).collect();
        bits.resize(self.objects.len(), 0);
        self.any_flags = bits.iter().fold(0, |a, &f| a | f);
        // Without flags the walks never read them: keep none.
        self.flags = if self.any_flags == 0 { Vec::new() } else { bits };
    }

    /// Which rays see object `object`.
    pub fn visibility(&self, object: u32) -> Visibility {
        Visibility::from_bits(self.flags.get(object as usize).copied().unwrap_or(0))
    }

    /// True when some object is a holdout ([`Visibility::matte`]).
    pub fn has_matte(&self) -> bool {
        self.any_flags & MATTE != 0
    }

    /// The flags whose objects a query skips: for camera rays (`camera`) those hidden from
    /// the camera, for shadow rays (`shadow`) those casting no shadows; 0 when no object
    /// has such a flag, so the walk never reads the flags.
    #[inline(always)]
    fn skipped_flags(&self, camera: bool, shadow: bool) -> u8 {
        let kind = (camera as u8 * HIDDEN_FROM_CAMERA) | (shadow as u8 * CASTS_NO_SHADOWS);
        self.any_flags & kind
    }

    /// True when a walk skipping objects with flags `skipped` skips object `object`.
    #[inline(always)]
    fn skips(&self, skipped: u8, object: u32) -> bool {
        skipped != 0 && self.flags[object as usize] & skipped != 0
    }

    /// Bounds of the whole scene.
    pub fn bounds(&self) -> Aabb {
        self.top.bounds()
    }

    /// Bytes held by all BVHs (top level included).
    pub fn bvh_bytes(&self) -> usize {
        self.top.memory_bytes() + self.objects.iter().map(|o| o.bvh.memory_bytes()).sum::<usize>()
    }

    simd_query! {
        /// The closest hit along the ray before `ray.tmax`, but on `ray.skip` (and, for a
        /// camera ray, on objects hidden from the camera).
        /// Strand sets with level of detail use the level of `ray.cone` at each distance.
        pub fn intersect / intersect_avx2 / intersect_portable(&self, ray: &Ray) -> Option<Hit> {
            let mut tmax = ray.tmax;
            let mut best = None;
            let skipped = self.skipped_flags(ray.camera, false);
            self.walk(ray.origin, ray.dir, (ray.cone, skipped), 0.0, &mut tmax, |object, o, prims, widen, tmax| {
                let skip = ray.skip.filter(|s| s.object == object);
                if let Some((prim, t, kind, level)) =
                    intersect_leaf(&o.shape, prims, LeafRay::new(ray.origin, ray.dir), *tmax, skip, false, widen)
                {
                    *tmax = t;
                    best = Some(Hit { t, object, prim, kind, level, radius_scale: o.radius_scale(level) });
                }
                false
            });
            best
        }
    }

    simd_query! {
        /// True when anything (but the skipped primitives and objects casting no shadows)
        /// lies on the segment from `origin` along unit `dir` up to distance `tmax`, with
        /// strands at full detail: a shadow ray's query.
        pub fn occluded / occluded_avx2 / occluded_portable(
            &self, origin: Vec3, dir: Vec3, tmax: f32, skip: Option<Skip>,
        ) -> bool {
            let mut t = tmax;
            let skipped = self.skipped_flags(false, true);
            self.walk(origin, dir, (RayCone::default(), skipped), 0.0, &mut t, |object, o, prims, widen, t| {
                let skip = skip.filter(|s| s.object == object);
                intersect_leaf(&o.shape, prims, LeafRay::new(origin, dir), *t, skip, true, widen).is_some()
            })
        }
    }

    /// Walks the leaves of the objects that the ray from `origin` along unit `dir`
    /// (footprint `cone`) enters between `tmin` and `*tmax`, nearest boxes first, under the top-level
    /// BVH, passing over the objects with any of the flags `skipped` ([`Accel::skipped_flags`]):
    /// `leaf(object, o, prims, widen, tmax)` as in [`Object::traverse`],
    /// returning true to stop. Returns whether a leaf stopped the walk. Every query
    /// (closest, any, K-nearest hits, transmittance) is this walk with its own leaf.
    #[inline(always)]
    fn walk(
        &self,
        origin: Vec3,
        dir: Vec3,
        (cone, skipped): (RayCone, u8),
        tmin: f32,
        tmax: &mut f32,
        mut leaf: impl FnMut(u32, &Object, &[u32], Widen, &mut f32) -> bool,
    ) -> bool {
        let test = RayBoxTest::new(origin, dir, tmin);
        let lod_ray = LodRay::new(origin, dir, cone);
        let mut stopped = false;
        self.top.traverse::<false>(&test, tmax, |objects, _, t| {
            for &object in objects {
                if self.skips(skipped, object) {
                    continue;
                }
                let o = &self.objects[object as usize];
                if o.traverse(&test, &lod_ray, t, |prims, widen, t| leaf(object, o, prims, widen, t)) {
                    stopped = true;
                    return true;
                }
            }
            false
        });
        stopped
    }
}

impl Accel {
    simd_query! {
        /// The closest hits of a packet of up to [`PACKET`] rays (`hits[i]` for `rays[i]`), the
        /// same as [`Accel::intersect`] gives each: rays that mostly cross the same boxes, like a
        /// pixel's samples, share the node visits ([`Bvh::traverse_packet`]) and the loading of
        /// strand leaves ([`segment::near8_packet`]).
        /// Rays past the first [`PACKET`], or past the end of `hits`, are not traced.
        pub fn intersect_packet / intersect_packet_avx2 / intersect_packet_portable(
            &self, rays: &[Ray], hits: &mut [Option<Hit>],
        ) -> () {
            let rays = &rays[..rays.len().min(hits.len()).min(PACKET)];
            let mut tmax = [0.0; PACKET];
            rays.iter().zip(&mut tmax).for_each(|(r, t)| *t = r.tmax);
            // The camera rays among them, looked at only when some object hides from them.
            let hidden = self.skipped_flags(true, false);
            let camera = match hidden {
                0 => 0,
                _ => rays.iter().enumerate().fold(0, |m, (i, r)| m | (r.camera as RayMask) << i),
            };
            self.walk_packet(rays, &mut tmax, (hidden, camera), |i, object, o, prims, widen, ray, tmax| {
                let skip = rays[i].skip.filter(|s| s.object == object);
                if let Some((prim, t, kind, level)) = intersect_leaf(&o.shape, prims, ray, *tmax, skip, false, widen) {
                    *tmax = t;
                    hits[i] = Some(Hit { t, object, prim, kind, level, radius_scale: o.radius_scale(level) });
                }
                false
            });
        }
    }

    simd_query! {
        /// Any-hit queries for a packet of up to [`PACKET`] shadow rays: bit i of the result is
        /// set when something but the ray's `skip` (and objects casting no shadows) lies on ray i
        /// before its `tmax`, strands with level of detail seen at the level of the ray's cone. For
        /// opaque scenes this is [`Accel::transmittance_cone`] being 0, for rays that start
        /// close together (a pixel's shadow rays towards one light) at a shared cost.
        pub fn occluded_packet / occluded_packet_avx2 / occluded_packet_portable(
            &self, rays: &[Ray],
        ) -> RayMask {
            let rays = &rays[..rays.len().min(PACKET)];
            let mut t = [0.0; PACKET];
            rays.iter().zip(&mut t).for_each(|(r, t)| *t = r.tmax);
            self.walk_packet(rays, &mut t, (self.skipped_flags(false, true), RayMask::MAX), |i, object, o, prims, widen, ray, t| {
                let skip = rays[i].skip.filter(|s| s.object == object);
                intersect_leaf(&o.shape, prims, ray, *t, skip, true, widen).is_some()
            })
        }
    }

    /// [`Accel::walk`] for a packet of up to [`PACKET`] rays with their `tmax`: the top
    /// level and every object are traversed by the packet; a leaf of an object with level of
    /// detail is tested ray by ray, each ray seeing it at its own level.
    /// The rays in `skipping` pass over the objects with any of the flags `skipped`
    /// ([`Accel::skipped_flags`]).
    /// `leaf(ray, object, o, prims, widen, leaf_ray, tmax)` tests a leaf for ray `ray`, and
    /// returns true when that ray is done; the result holds the rays a leaf stopped.
    #[inline(always)]
    fn walk_packet(
        &self,
        rays: &[Ray],
        tmax: &mut [f32; PACKET],
        (skipped, skipping): (u8, RayMask),
        mut leaf: impl FnMut(usize, u32, &Object, &[u32], Widen, LeafRay, &mut f32) -> bool,
    ) -> RayMask {
        let tests: [RayBoxTest; PACKET] = std::array::from_fn(|i| {
            rays.get(i).map_or(RayBoxTest::new(Vec3::ZERO, Vec3::X, 0.0), |r| RayBoxTest::new(r.origin, r.dir, 0.0))
        });
        let tests = &tests[..rays.len()];
        let mut stopped: RayMask = 0;
        self.top.traverse_packet::<false>(tests, RayMask::MAX, tmax, |objects, _, mut live, tmax| {
            for &object in objects {
                let seeing = if self.skips(skipped, object) { live & !skipping } else { live };
                if seeing == 0 {
                    continue;
                }
                let o = &self.objects[object as usize];
                let mut done = 0;
                match (&o.shape, &o.lod) {
                    // The packet shares the node tests (the boxes bound every level a ray
                    // may see); each ray tests a leaf at its own level.
                    (_, Some(lod)) => {
                        o.bvh.traverse_packet::<true>(tests, seeing, tmax, |prims, tag, entering, tmax| {
                            let mut done_here = 0;
                            for_each_ray(entering, |i| {
                                let r = &rays[i];
                                let view = lod.view(&LodRay::new(r.origin, r.dir, r.cone));
                                let ray = LeafRay::new(r.origin, r.dir);
                                if leaf(i, object, o, prims, Some(&view.leaf(tag)), ray, &mut tmax[i]) {
                                    done_here |= 1 << i;
                                }
                            });
                            done |= done_here;
                            done_here
                        })
                    }
                    (shape, None) => o.bvh.traverse_packet::<false>(tests, seeing, tmax, |prims, _, entering, tmax| {
                        // A strand leaf is loaded once and culled for all its rays.
                        let near = match shape {
                            Shape::Strands(s) => Some(segment::near8_packet(rays, entering, &s.points, prims, 1.0)),
                            Shape::Mesh(_) => None,
                        };
                        let mut done_here = 0;
                        for_each_ray(entering, |i| {
                            let ray = LeafRay { origin: rays[i].origin, dir: rays[i].dir, near: near.map(|n| n[i]) };
                            if ray.near != Some(0) && leaf(i, object, o, prims, None, ray, &mut tmax[i]) {
                                done_here |= 1 << i;
                            }
                        });
                        done |= done_here;
                        done_here
                    }),
                }
                stopped |= done;
                live &= !done;
            }
            stopped
        });
        stopped
    }
}

// A BVH leaf is culled for a packet by one `near8_packet`, which takes at most eight segments.
const _: () = assert!(bvh::MAX_LEAF <= 8);

/// Calls `f(i)` for every ray `i` in the mask, in order.
#[inline(always)]
fn for_each_ray(mut rays: RayMask, mut f: impl FnMut(usize)) {
    while rays != 0 {
        f(rays.trailing_zeros() as usize);
        rays &= rays - 1;
    }
}

fn build_items(shape: &Shape) -> Vec<BuildItem> {
    match shape {
        Shape::Mesh(m) => (0..m.indices.len() as u32)
            .map(|i| {
                let [a, b, c] = m.corners(i);
                BuildItem::new(Aabb::new(a.min(b).min(c), a.max(b).max(c)), i)
            })
            .collect(),
        Shape::Strands(s) => s
            .segment_starts()
            .into_iter()
            .map(|i| {
                let (min, max) = segment::bounds(s.points[i as usize], s.points[i as usize + 1]);
                BuildItem::new(Aabb::new(min, max), i)
            })
            .collect(),
    }
}

/// A ray as a leaf's test sees it.
#[derive(Clone, Copy, Debug)]
struct LeafRay {
    origin: Vec3,
    /// Unit direction.
    dir: Vec3,
    /// For a strand leaf (at most eight segments, full detail) traced by a packet, the bits
    /// [`segment::near8`] gives the ray, computed for the whole packet at once.
    near: Option<u32>,
}

impl LeafRay {
    /// The ray from `origin` along unit `dir`, its leaf's bound not yet computed.
    fn new(origin: Vec3, dir: Vec3) -> LeafRay {
        LeafRay { origin, dir, near: None }
    }
}

/// The nearest hit among a leaf's primitives before `tmax`, ignoring `skip`: (primitive,
/// distance, where, level); with `any`, the first hit found. Segments are tested four at a
/// time, their radii widened for the ray's level of detail by `widen`.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn intersect_leaf(
    shape: &Shape,
    prims: &[u32],
    ray: LeafRay,
    tmax: f32,
    skip: Option<Skip>,
    any: bool,
    widen: Widen,
) -> Option<(u32, f32, HitKind, u32)> {
    let skipped = |p: u32| skip.is_some_and(|s| (s.first..=s.last).contains(&p));
    let mut best = None;
    let mut tmax = tmax;
    match shape {
        Shape::Mesh(m) => {
            for &p in prims {
                if let Some(h) = triangle::intersect_triangle(ray.origin, ray.dir, 0.0, tmax, m.corners(p)) {
                    tmax = h.t;
                    best = Some((p, h.t, HitKind::Triangle { b1: h.b1, b2: h.b2 }, 0));
                    if any {
                        break;
                    }
                }
            }
        }
        // Two copies of the loop: at full detail `widen` is a constant there, and the
        // segments are tested as they are, without the level of detail's per-lane work.
        Shape::Strands(s) => match widen {
            None => return strand_leaf(s, prims, ray, tmax, skipped, any, None),
            Some(view) => return strand_leaf(s, prims, ray, tmax, skipped, any, Some(view)),
        },
    }
    best
}

/// [`intersect_leaf`] on the segments of a strand set.
#[inline(always)]
fn strand_leaf(
    s: &StrandSet,
    prims: &[u32],
    ray: LeafRay,
    mut tmax: f32,
    skipped: impl Fn(u32) -> bool,
    any: bool,
    widen: Widen,
) -> Option<(u32, f32, HitKind, u32)> {
    let mut best = None;
    for_each_group(
        s,
        prims,
        ray,
        skipped,
        widen,
        #[inline(always)]
        |ids, lanes| exact4(s, (ray.origin, ray.dir), ids, lanes, any, widen, &mut tmax, &mut best),
    );
    best
}

/// Calls `test(ids, lanes)` on a leaf's segments (its item ids `prims`, minus the
/// `skipped` ones) in groups of up to four lanes of [`segment::intersect_cylinder4`], until
/// it returns true; returns whether it did. The whole leaf is first culled in one pass
/// ([`segment::near8`]), radii widened as far as the leaf's widest level of detail, and
/// only the segments the ray passes near are gathered, in leaf order (on the hairy torus
/// one in twenty for camera rays, one in eleven for shadow rays), their radii widened for
/// the ray. Only levels that draw chords of segment pairs skip the cull.
#[inline(always)]
fn for_each_group(
    s: &StrandSet,
    prims: &[u32],
    ray: LeafRay,
    skipped: impl Fn(u32) -> bool,
    widen: Widen,
    mut test: impl FnMut(&[u32], &Lanes4) -> bool,
) -> bool {
    let widest = match widen {
        None => 1.0,
        Some(LodLeaf { widest: Some(w), .. }) => *w,
        Some(_) => return prims.chunks(4).any(|chunk| test(chunk, &gather4(s, chunk, &skipped, widen))),
    };
    for leaf in prims.chunks(8) {
        // The segments' first points: the item ids themselves at full detail.
        let mut decoded = [0; 8];
        let firsts = match widen {
            None => leaf,
            Some(l) => {
                leaf.iter().zip(&mut decoded).for_each(|(&id, first)| *first = l.view.decode(id).0);
                &decoded[..leaf.len()]
            }
        };
        let mut near = match ray.near {
            Some(near) => near,
            None => segment::near8(ray.origin, ray.dir, &s.points, firsts, widest),
        };
        while near != 0 {
            let mut ids = [0; 4];
            let mut n = 0;
            while near != 0 && n < 4 {
                let lane = near.trailing_zeros() as usize;
                let id = leaf[lane];
                near &= near - 1;
                if !skipped(firsts[lane]) {
                    ids[n] = id;
                    n += 1;
                }
            }
            let ids = &ids[..n];
            if n > 0 && test(ids, &gather4(s, ids, |_| false, widen)) {
                return true;
            }
        }
    }
    false
}

/// The exact test of up to four segments (`lanes`, gathered from the item ids `ids` of `s`) for
/// [`strand_leaf`]: a hit before `*tmax` becomes `*best` and shortens `*tmax`. True when the
/// search is over (an any-hit query hit).
#[inline(always)]
#[allow(clippy::too_many_arguments)]
fn exact4(
    s: &StrandSet,
    (origin, dir): (Vec3, Vec3),
    ids: &[u32],
    lanes: &Lanes4,
    any: bool,
    widen: Widen,
    tmax: &mut f32,
    best: &mut Option<(u32, f32, HitKind, u32)>,
) -> bool {
    let mut hits = segment::intersect_cylinder4(origin, dir, 0.0, *tmax, lanes.p0, lanes.p1);
    lanes.drop_hidden(&mut hits, widen);
    if any && hits.mask != 0 {
        // Any lane's hit will do: skip forming the normal.
        let lane = hits.mask.trailing_zeros() as usize;
        let (prim, _, level) = lanes.hit_on(s, ids, lane, 0.0, widen);
        *best = Some((prim, hits.t()[lane], HitKind::Segment { s: 0.0, normal: Vec3::ZERO }, level));
        return true;
    }
    if let Some(lane) = hits.nearest() {
        if let Some(h) = hits.hit(lane) {
            *tmax = h.t;
            let (prim, along, level) = lanes.hit_on(s, ids, lane, h.s, widen);
            *best = Some((prim, h.t, HitKind::Segment { s: along, normal: h.normal }, level));
        }
    }
    false
}

/// Up to four segments of a leaf as the lanes of [`segment::intersect_cylinder4`].
struct Lanes4 {
    /// End points `[x, y, z, radius]`, radii widened for the ray's level of detail.
    p0: [f32x4; 4],
    p1: [f32x4; 4],
    /// With level of detail only: each lane's segment (its first point), level, the
    /// distance from which a hit on it does not count (its pruning group is hidden there),
    /// and whether it stands for its pair of segments (a simplified level).
    prim: [u32; 4],
    level: [u32; 4],
    cut: [f32; 4],
    paired: [bool; 4],
}

impl Lanes4 {
    /// The segment (its first point) of `s`, the parameter along it and the level of a
    /// hit at parameter `along` on lane `lane`, gathered from the item ids `ids` with
    /// `widen`. A hit on a segment standing for its pair is put on the one of the two
    /// where shading finds the strand ([`lod::unsimplify`]).
    #[inline(always)]
    fn hit_on(&self, s: &StrandSet, ids: &[u32], lane: usize, along: f32, widen: Widen) -> (u32, f32, u32) {
        match widen {
            None => (ids[lane], along, 0),
            Some(_) if self.paired[lane] => {
                let (prim, along) = lod::unsimplify(&s.points, self.prim[lane], along);
                (prim, along, self.level[lane])
            }
            Some(_) => (self.prim[lane], along, self.level[lane]),
        }
    }

    /// Clears the lanes of `hits` that lie where their group is hidden (none at full
    /// detail, `widen` being `None`: then the lanes are not looked at).
    #[inline(always)]
    fn drop_hidden(&self, hits: &mut segment::Hits4, widen: Widen) {
        if widen.is_none() {
            return;
        }
        let t = hits.t();
        for (lane, (&t, &cut)) in t.iter().zip(&self.cut).enumerate() {
            if t >= cut {
                hits.mask &= !(1 << lane);
            }
        }
    }
}

/// The segments of up to four leaf items of `s` (BVH item ids, which carry the pruning
/// group when `widen` is given) as seen by the ray: skipped, missing and culled lanes stay
/// empty (no surface).
#[inline(always)]
fn gather4(s: &StrandSet, ids: &[u32], skipped: impl Fn(u32) -> bool, widen: Widen) -> Lanes4 {
    let mut lanes = Lanes4 {
        p0: [f32x4::ZERO; 4],
        p1: [f32x4::ZERO; 4],
        prim: [0; 4],
        level: [0; 4],
        cut: [f32::INFINITY; 4],
        paired: [false; 4],
    };
    for (lane, &id) in ids.iter().enumerate() {
        match widen {
            None => {
                if !skipped(id) {
                    lanes.p0[lane] = f32x4::new(s.points[id as usize]);
                    lanes.p1[lane] = f32x4::new(s.points[id as usize + 1]);
                }
            }
            Some(LodLeaf { view, .. }) => {
                let (p, group) = view.decode(id);
                lanes.prim[lane] = p;
                if skipped(p) {
                    continue;
                }
                let Some(end) = view.segment_end(&s.points, p, group) else { continue };
                let (a, b) = (s.points[p as usize], s.points[end as usize]);
                if let Some((scale, level, cut)) = view.segment(p, a, b, group) {
                    lanes.p0[lane] = f32x4::new([a[0], a[1], a[2], a[3] * scale]);
                    lanes.p1[lane] = f32x4::new([b[0], b[1], b[2], b[3] * scale]);
                    (lanes.level[lane], lanes.cut[lane], lanes.paired[lane]) = (level, cut, end > p + 1);
                }
            }
        }
    }
    lanes
}

/// The seed of the pruning ranks of object `object`.
fn lod_seed(object: usize) -> u32 {
    crate::math::rng::hash_combine(&[0x10d, object as u32])
}

/// One primitive's hit before `tmax`: (distance, where).
#[cfg(test)]
fn intersect_primitive(shape: &Shape, prim: u32, origin: Vec3, dir: Vec3, tmax: f32) -> Option<(f32, HitKind)> {
    intersect_leaf(shape, &[prim], LeafRay::new(origin, dir), tmax, None, false, None).map(|(_, t, k, _)| (t, k))
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
            // The query's copy compiled without AVX2 gives the same hit, bit for bit.
            assert_eq!(accel.intersect_portable(&ray), accel.intersect(&ray), "ray {ray:?}");
            hits += expected.is_some() as u32;
            let blocked = accel.occluded(ray.origin, ray.dir, 5.0, None);
            assert_eq!(blocked, expected.is_some_and(|e| e.0 < 5.0));
        }
        assert!(hits > 500, "the test needs rays that hit: {hits}");
    }

    #[test]
    fn packets_find_the_hits_of_single_rays() {
        let mut rng = GenRng::seed_from_u64(11);
        let plain = random_scene(&mut rng);
        // The same objects, the strands with level of detail (leaves tested ray by ray).
        let shapes = plain.objects.iter().map(|o| (o.shape.clone(), o.material, Some(LodParams::default())));
        let lod = Accel::build_with_lod(shapes.collect());
        let (mut hits, mut blocked) = (0, 0);
        for accel in [&plain, &lod] {
            for p in 0..300 {
                // A pixel's worth of rays from one eye (coherent), or scattered ones.
                let eye = random_vec(&mut rng, 12.0);
                let target = random_vec(&mut rng, 3.0);
                let n = rng.random_range(1..=PACKET);
                let rays: Vec<Ray> = (0..n)
                    .map(|_| {
                        let origin = if p % 3 == 0 { random_vec(&mut rng, 12.0) } else { eye };
                        let mut ray = Ray::new(origin, (target + random_vec(&mut rng, 0.05) - origin).normalize());
                        ray.cone = RayCone { width: 0.0, spread: 0.002 };
                        ray
                    })
                    .collect();
                let mut got = vec![None; n];
                accel.intersect_packet(&rays, &mut got);
                // Shadow rays: the same rays up to a distance, some skipping a segment.
                let mut shadows = rays.clone();
                shadows.iter_mut().enumerate().for_each(|(i, r)| r.tmax = 2.0 + i as f32);
                for (i, r) in shadows.iter_mut().enumerate() {
                    r.skip =
                        got[i].filter(|_| i % 2 == 0).map(|h| Skip { object: h.object, first: h.prim, last: h.prim });
                }
                let occluded = accel.occluded_packet(&shadows);
                for (i, ray) in rays.iter().enumerate() {
                    assert_eq!(got[i], accel.intersect(ray), "ray {i} of packet {p}");
                    let skip = shadows[i].skip;
                    let expected =
                        accel.transmittance_cone(ray.origin, ray.dir, shadows[i].tmax, skip, ray.cone, None) == 0.0;
                    assert_eq!(occluded >> i & 1 == 1, expected, "shadow ray {i} of packet {p}");
                    hits += got[i].is_some() as u32;
                    blocked += expected as u32;
                }
            }
        }
        assert!(hits > 1000 && blocked > 500, "the test needs rays that hit: {hits}, {blocked}");
    }

    /// Camera rays pass through objects hidden from the camera and shadow rays through those
    /// casting no shadows, one by one, in packets and in the multi-hit queries alike; other
    /// rays see both.
    #[test]
    fn queries_skip_the_objects_their_rays_do_not_see() {
        let mut rng = GenRng::seed_from_u64(5);
        let mut accel = random_scene(&mut rng);
        let all = accel.clone();
        let alone = |i: usize| Accel::build(vec![(all.objects[i].shape.clone(), 0)]);
        let (mesh, strands) = (alone(0), alone(1));
        let hidden = Visibility { camera: false, ..Visibility::default() };
        let shadowless = Visibility { shadows: false, ..Visibility::default() };
        accel.set_visibility([hidden, shadowless]);
        assert_eq!((accel.visibility(0), accel.visibility(1)), (hidden, shadowless));
        let (mut camera_hits, mut blocked) = (0, 0);
        for _ in 0..300 {
            let (eye, target) = (random_vec(&mut rng, 12.0), random_vec(&mut rng, 3.0));
            let rays: Vec<Ray> =
                (0..PACKET).map(|_| Ray::new(eye, (target + random_vec(&mut rng, 0.5) - eye).normalize())).collect();
            let cameras: Vec<Ray> = rays.iter().map(|r| Ray { camera: true, ..*r }).collect();
            let mut packet = vec![None; PACKET];
            accel.intersect_packet(&cameras, &mut packet);
            let occluded_packet = accel.occluded_packet(&rays);
            let mut layers = Vec::new();
            for (i, (ray, camera)) in rays.iter().zip(&cameras).enumerate() {
                // Not a camera ray: every object, as without flags.
                assert_eq!(accel.intersect(ray), all.intersect(ray));
                // A camera ray: the strands only.
                let hit = accel.intersect(camera);
                let expected = strands.intersect(ray).map(|h| Hit { object: 1, ..h });
                assert_eq!(hit, expected, "ray {i}");
                assert_eq!(packet[i], hit, "ray {i}");
                accel.intersect_k(camera, 0.0, 4, &[], None, &mut layers);
                assert_eq!(layers.first().map(|l| l.hit), hit, "ray {i}");
                camera_hits += hit.is_some() as u32;
                // A shadow ray: the mesh only.
                let occluded = accel.occluded(ray.origin, ray.dir, f32::INFINITY, None);
                assert_eq!(occluded, mesh.occluded(ray.origin, ray.dir, f32::INFINITY, None), "ray {i}");
                assert_eq!(occluded, accel.transmittance(ray.origin, ray.dir, f32::INFINITY, None) == 0.0);
                assert_eq!(occluded, occluded_packet >> i & 1 == 1, "ray {i}");
                blocked += occluded as u32;
            }
        }
        assert!(camera_hits > 200 && blocked > 200, "the test needs hits: {camera_hits}, {blocked}");
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
        // A ray's own skip holds for the closest hit, the packets and the layers alike.
        for (first, hit) in [(0, false), (1, true)] {
            let ray = Ray { skip: Some(Skip { object: 0, first, last: first }), ..Ray::new(o, d) };
            assert_eq!(accel.intersect(&ray).is_some(), hit, "skip {first}");
            let mut got = [None; 4];
            accel.intersect_packet(&[ray; 4], &mut got);
            assert_eq!(got[0].is_some(), hit, "skip {first}, packet");
            assert_eq!(accel.occluded_packet(&[ray; 4]) & 1 == 1, hit, "skip {first}, packet");
            let mut layers = Vec::new();
            accel.intersect_k(&ray, 0.0, 4, &[], None, &mut layers);
            assert_eq!(!layers.is_empty(), hit, "skip {first}, layers");
        }
    }
}
