//! Multi-hit queries for semi-transparent hair (thesis section 2.2.8): the K nearest
//! partial hits of a ray in one traversal, and the transmittance along a shadow ray.
//!
//! The thesis' Turtle shot one new ray per transparent hit; here one traversal collects
//! every hit it needs, and the BVH keeps culling with the distance of the K-th nearest
//! hit (or of the hit where the list ends), so a stack of K hairs costs about one
//! traversal.

use super::lod::Widen;
use super::{for_each_group, Accel, Hit, HitKind, LeafRay, Object, Shape};
use crate::geometry::{segment, triangle, StrandSet};
use crate::math::rng::{hash_combine, unit_float};
use crate::math::{Ray, RayCone, Skip};
use glam::Vec3;

/// Transmittance below which a shadow ray counts as blocked and a stack of partial hits
/// stops: light attenuated below 1/1000 adds less than the 8-bit output resolves.
pub const NEGLIGIBLE_TRANSMITTANCE: f32 = 1e-3;

/// Transmittance down to which [`Accel::transmittance_estimate`] multiplies opacities in
/// exactly before it decides further hits stochastically. Lower is less noisy and slower:
/// deciding every hit stochastically doubles the mean error of the 4-sample fur golden
/// image (`tests/render.rs`); down to 0.4, its noise stays within that test's tolerance.
pub const EXACT_SHADOW_TRANSMITTANCE: f32 = 0.4;

/// One hit of a multi-hit query, with the opacity of the primitive there.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LayerHit {
    /// The hit.
    pub hit: Hit,
    /// Opacity at the hit: 1 for meshes and opaque strands, the strand's interpolated
    /// per-point opacity otherwise.
    pub opacity: f32,
}

/// [`EXACT_SHADOW_TRANSMITTANCE`] where strands have smooth level of detail
/// ([`Accel::smooth_layers`]): a shadow ray's estimate then jumps by at most a fifth of the
/// light where a hit behind turns from letting light through to blocking it as strands
/// slide. With the camera's blend alike (`SMOOTH_BLEND_TRANSMITTANCE` of the renderer),
/// the far fur of `scenes/lod_field.toml` flickers 1.08 times as much as 256 spp without
/// LOD at 0.2, 1.24 times at 0.35 (docs/performance.md, tuning constants).
pub const SMOOTH_EXACT_SHADOW_TRANSMITTANCE: f32 = 0.2;

/// Opacity of `object`'s primitive `prim` at a hit seen at `level` by the ray from
/// `origin` along `dir`: the strand's own opacity times its level of detail's.
#[inline]
fn seen_opacity(o: &Object, prim: u32, kind: HitKind, level: u32, ray: (Vec3, Vec3)) -> f32 {
    let own = opacity(&o.shape, prim, kind);
    match kind {
        HitKind::Segment { s: along, .. } => own * o.lod_opacity_at(prim, along, level, ray),
        _ => own,
    }
}

/// Opacity of `shape` at a hit on primitive `prim`.
#[inline]
fn opacity(shape: &Shape, prim: u32, kind: HitKind) -> f32 {
    match (shape, kind) {
        (Shape::Strands(s), HitKind::Segment { s: along, .. }) => s.opacity_at(prim, along).clamp(0.0, 1.0),
        _ => 1.0,
    }
}

/// Calls `found(prim, t, kind, level)` for every hit among a leaf's primitives with t in
/// (`tmin`, `tmax`), ignoring `skip`; returns true as soon as `found` does (to stop).
/// Segments are tested four at a time, like the closest-hit leaf test, widened by `widen`
/// for the ray's level of detail; without `normals` their hits carry a zero normal (shadow
/// rays need only where along the segment they are).
#[inline]
fn leaf_hits(
    shape: &Shape,
    prims: &[u32],
    (origin, dir): (Vec3, Vec3),
    (tmin, tmax): (f32, f32),
    (skip, normals): (Option<Skip>, bool),
    widen: Widen,
    mut found: impl FnMut(u32, f32, HitKind, u32) -> bool,
) -> bool {
    let skipped = |p: u32| skip.is_some_and(|s| (s.first..=s.last).contains(&p));
    match shape {
        Shape::Mesh(m) => {
            for &p in prims {
                if let Some(h) = triangle::intersect_triangle(origin, dir, tmin, tmax, m.corners(p)) {
                    if found(p, h.t, HitKind::Triangle { b1: h.b1, b2: h.b2 }, 0) {
                        return true;
                    }
                }
            }
        }
        // At full detail `widen` is a constant in the loop, as in the closest-hit test.
        Shape::Strands(s) => match widen {
            None => return strand_hits(s, prims, (origin, dir), (tmin, tmax), (skipped, normals), None, found),
            Some(view) => {
                return strand_hits(s, prims, (origin, dir), (tmin, tmax), (skipped, normals), Some(view), found)
            }
        },
    }
    false
}

/// [`leaf_hits`] on the segments of a strand set.
#[inline(always)]
fn strand_hits(
    s: &StrandSet,
    prims: &[u32],
    (origin, dir): (Vec3, Vec3),
    (tmin, tmax): (f32, f32),
    (skipped, normals): (impl Fn(u32) -> bool, bool),
    widen: Widen,
    mut found: impl FnMut(u32, f32, HitKind, u32) -> bool,
) -> bool {
    for_each_group(
        s,
        prims,
        LeafRay::new(origin, dir),
        skipped,
        widen,
        #[inline(always)]
        |ids, lanes| {
            let mut hits = segment::intersect_cylinder4(origin, dir, tmin, tmax, lanes.p0, lanes.p1);
            lanes.drop_hidden(&mut hits, widen);
            let mut mask = hits.mask;
            let (t, along) = (hits.t(), hits.s());
            while mask != 0 {
                let lane = mask.trailing_zeros() as usize;
                mask &= mask - 1;
                if !normals {
                    let (prim, along, level) = lanes.hit_on(s, ids, lane, along[lane], widen);
                    if found(prim, t[lane], HitKind::Segment { s: along, normal: Vec3::ZERO }, level) {
                        return true;
                    }
                } else if let Some(h) = hits.hit(lane) {
                    let (prim, along, level) = lanes.hit_on(s, ids, lane, h.s, widen);
                    if found(prim, h.t, HitKind::Segment { s: along, normal: h.normal }, level) {
                        return true;
                    }
                }
            }
            false
        },
    )
}

/// True when rays may see through some of the object's primitives: strands with per-point
/// opacity, or with level of detail that draws coarse strands semi-transparent
/// ([`super::lod::LodParams::spread`]). Everything else blocks at its first hit.
#[inline]
fn is_partial(o: &Object) -> bool {
    matches!(&o.shape, Shape::Strands(s) if s.opacity.is_some()) || o.lod().is_some_and(|l| l.has_transparency())
}

/// How a front-to-back blend treats the hits behind the first ones: blended exactly while
/// at least `blend` of the light is left, then walked stochastically, stopping at a hit
/// with probability equal to its opacity. The walk's random number at a hit comes from
/// the hit's primitive and `seed`, not from the order hits are found in, so the query
/// can stop looking behind the hit a walk will stop at, as behind an opaque one.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StochasticTail {
    /// Transmittance below which the walk turns stochastic.
    pub blend: f32,
    /// Seed of the walk's random numbers (one per ray).
    pub seed: u32,
}

impl StochasticTail {
    /// The uniform number in [0, 1) that decides whether the walk stops at `hit`.
    #[inline]
    pub fn draw(&self, hit: &Hit) -> f32 {
        stop_draw(self.seed, hit.object, hit.prim)
    }
}

/// The uniform number in [0, 1) that decides whether a stochastic walk seeded `seed`
/// stops at primitive `prim` of `object`: a hash, the same whenever the walk meets it.
#[inline]
fn stop_draw(seed: u32, object: u32, prim: u32) -> f32 {
    unit_float(hash_combine(&[seed, object, prim]))
}

/// Inserts `layer` into the hits `out` sorted by distance and keeps what a front-to-back
/// blend needs: at most `k` hits, none behind the first one where the transmittance
/// accumulated from the front falls below [`NEGLIGIBLE_TRANSMITTANCE`] (an opaque hit
/// among them) or where the `tail` walk stops. Returns the distance beyond which further
/// hits no longer matter, once there is one.
#[inline]
fn insert_layer(out: &mut Vec<LayerHit>, layer: LayerHit, k: usize, tail: Option<StochasticTail>) -> Option<f32> {
    let at = out.partition_point(|h| h.hit.t <= layer.hit.t);
    out.insert(at, layer);
    let (mut transmitted, mut carried) = (1.0f32, 1.0f32);
    let end = out
        .iter()
        .position(|h| {
            let stops = match tail {
                Some(tail) if carried < tail.blend => tail.draw(&h.hit) < h.opacity,
                _ => {
                    carried *= 1.0 - h.opacity;
                    false
                }
            };
            transmitted *= 1.0 - h.opacity;
            stops || transmitted < NEGLIGIBLE_TRANSMITTANCE
        })
        .map(|i| i + 1);
    out.truncate(end.unwrap_or(k).min(k));
    (end.is_some() || out.len() == k).then(|| out[out.len() - 1].hit.t)
}

impl Accel {
    /// True when some strand set has per-point opacity, so rays must look past hits.
    pub fn has_transparency(&self) -> bool {
        self.objects.iter().any(is_partial)
    }

    /// True when some strand set asks for smooth level of detail ([`LodParams::smooth`]):
    /// then camera rays blend semi-transparent layers exactly down to a lower
    /// transmittance, each blended layer traces its own shadow rays towards lights that
    /// need no sampling, and shadow rays multiply opacities exactly down to
    /// [`SMOOTH_EXACT_SHADOW_TRANSMITTANCE`]. Every stochastic decision a sample makes
    /// (where a walk stops, which layer's shadow ray stands for the others) toggles as
    /// strands slide under a fixed sample; these make its value change continuously.
    ///
    /// [`LodParams::smooth`]: super::lod::LodParams::smooth
    pub fn smooth_layers(&self) -> bool {
        self.smooth
    }

    /// True when some strand set has per-point opacity of its own (transparency that does
    /// not come from level of detail alone).
    pub fn has_strand_opacity(&self) -> bool {
        self.objects.iter().any(|o| matches!(&o.shape, Shape::Strands(s) if s.opacity.is_some()))
    }

    /// Opacity at a hit of [`Accel::intersect`]: 1 on meshes and opaque strands, else the
    /// strand's opacity there times that of its level of detail (the peak of a tent
    /// profile: below 1 exactly where the hit is semi-transparent).
    pub fn hit_opacity(&self, hit: &Hit) -> f32 {
        let o = &self.objects[hit.object as usize];
        opacity(&o.shape, hit.prim, hit.kind) * o.lod_opacity(hit.level)
    }

    /// The nearest hits along `ray` beyond `tmin` (but on `ray.skip` and, for a camera ray,
    /// on objects hidden from the camera), sorted by distance, into `out`
    /// (cleared first): at most `k` of them (at least one), ending early at the first
    /// opaque hit or at the first hit behind which less than [`NEGLIGIBLE_TRANSMITTANCE`]
    /// of the light is left (a blend stops there: what lies behind cannot show), or, with
    /// a `tail`, at the hit its walk stops at.
    ///
    /// One traversal of every object, nearest boxes first: an opaque hit (mesh, strand
    /// without opacity) ends the list like any hit that leaves negligible light, and once
    /// the list has ended or holds `k` hits the BVH visits only boxes nearer than its last.
    /// (A first pass for the nearest opaque hit alone, to cull the fur behind the surface
    /// it grows on from the start, cost 1.3 % more instructions on the furry pillow: the
    /// walk meets that surface early anyway, and a stochastic tail ends the list sooner.)
    ///
    /// To continue past a full list, call again with `tmin` at its last hit and the hits
    /// found so far in `exclude`: a primitive already counted is not counted again where
    /// the ray leaves it. Strand sets with level of detail are seen at the level of
    /// `ray.cone` at each distance.
    pub fn intersect_k(
        &self,
        ray: &Ray,
        tmin: f32,
        k: usize,
        exclude: &[LayerHit],
        tail: Option<StochasticTail>,
        out: &mut Vec<LayerHit>,
    ) {
        let k = k.max(1);
        out.clear();
        let mut cutoff = ray.tmax;
        let skipped = self.skipped_flags(ray.camera, false);
        self.walk(ray.origin, ray.dir, (ray.cone, skipped), tmin, &mut cutoff, |object, o, prims, widen, cutoff| {
            leaf_hits(
                &o.shape,
                prims,
                (ray.origin, ray.dir),
                (tmin, *cutoff),
                (ray.skip.filter(|s| s.object == object), true),
                widen,
                |prim, t, kind, level| {
                    if t >= *cutoff || exclude.iter().any(|e| e.hit.object == object && e.hit.prim == prim) {
                        return false;
                    }
                    let hit = Hit { t, object, prim, kind, level, radius_scale: o.radius_scale(level) };
                    let layer = LayerHit { hit, opacity: seen_opacity(o, prim, kind, level, (ray.origin, ray.dir)) };
                    if let Some(t) = insert_layer(out, layer, k, tail) {
                        *cutoff = t;
                    }
                    false
                },
            );
            false
        });
    }

    /// The fraction of light that passes from `origin` along unit `dir` up to distance
    /// `tmax`, ignoring `skip` and objects casting no shadows ([`super::Visibility::shadows`]):
    /// the product of `1 - opacity` over every hit (thesis section
    /// 2.2.8's transparency, applied to shadow rays so hair casts partial shadows). Meshes
    /// and opaque strands block; a product below [`NEGLIGIBLE_TRANSMITTANCE`] counts as 0.
    ///
    /// The product does not depend on the order hits are found in, so one unordered
    /// traversal of every object suffices; an opaque hit (opacity 1) ends it like an
    /// any-hit query. (An any-hit pass over the opaque objects first cost 3.7 % more
    /// instructions on the furry pillow, and 4.3 % on opaque fur, whose shadow rays then
    /// walked the top-level BVH twice.) Strands are seen at full detail.
    pub fn transmittance(&self, origin: Vec3, dir: Vec3, tmax: f32, skip: Option<Skip>) -> f32 {
        self.transmittance_cone(origin, dir, tmax, skip, RayCone::default(), None)
    }

    /// An unbiased estimate of [`Accel::transmittance`] that, like an opaque any-hit
    /// query, can stop at the first hit that blocks: opacities are multiplied in exactly
    /// while at least [`EXACT_SHADOW_TRANSMITTANCE`] of the light is left, then each
    /// further semi-transparent hit blocks the ray with probability equal to its opacity
    /// (stochastic transparency, Enderton et al. 2010, applied to shadow rays), decided by
    /// a hash of `seed` and the primitive. Which hits are multiplied in depends only on
    /// the opacities and the traversal order, and the draws are independent per primitive
    /// and of that order, so the expectation is the exact product; the estimate is 0 or
    /// the product of the exact part.
    ///
    /// Through dense fur most shadow rays stop after a few hits instead of walking every
    /// layer until the product is negligible.
    pub fn transmittance_estimate(&self, origin: Vec3, dir: Vec3, tmax: f32, skip: Option<Skip>, seed: u32) -> f32 {
        self.transmittance_cone(origin, dir, tmax, skip, RayCone::default(), Some(seed))
    }

    /// [`Accel::transmittance`], or with a `seed` [`Accel::transmittance_estimate`], for a
    /// shadow ray with footprint `cone`: strand sets with level of detail are pruned as a
    /// ray with that cone sees them (thesis section 2.2.2: shadow rays need a level too).
    pub fn transmittance_cone(
        &self,
        origin: Vec3,
        dir: Vec3,
        tmax: f32,
        skip: Option<Skip>,
        cone: RayCone,
        seed: Option<u32>,
    ) -> f32 {
        let mut t = tmax;
        let mut transmitted = 1.0f32;
        let exact = if self.smooth { SMOOTH_EXACT_SHADOW_TRANSMITTANCE } else { EXACT_SHADOW_TRANSMITTANCE };
        let skipped = self.skipped_flags(false, true);
        let blocked = self.walk(origin, dir, (cone, skipped), 0.0, &mut t, |object, o, prims, widen, t| {
            let skip = skip.filter(|s| s.object == object);
            leaf_hits(&o.shape, prims, (origin, dir), (0.0, *t), (skip, false), widen, |prim, _, kind, level| {
                let a = seen_opacity(o, prim, kind, level, (origin, dir));
                match seed {
                    Some(seed) if transmitted < exact => stop_draw(seed, object, prim) < a,
                    _ => {
                        transmitted *= 1.0 - a;
                        transmitted < NEGLIGIBLE_TRANSMITTANCE
                    }
                }
            })
        });
        if blocked {
            transmitted = 0.0;
        }
        transmitted
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::{StrandSet, TriangleMesh};
    use crate::math::rng::GenRng;
    use rand::{Rng, SeedableRng};

    /// `n` parallel strands of opacity `a` crossing the y axis at y = 1, 2, ..., n.
    fn layers(n: u32, a: f32) -> StrandSet {
        let mut s = StrandSet::new();
        for i in 0..n {
            let y = 1.0 + i as f32;
            s.push_strand([(Vec3::new(-1.0, y, 0.0), 0.05), (Vec3::new(1.0, y, 0.0), 0.05)]);
        }
        s.opacity = Some(vec![a; 2 * n as usize]);
        s
    }

    #[test]
    fn transmittance_through_n_strands_is_one_minus_a_to_the_n() {
        for (n, a) in [(1, 0.5), (3, 0.5), (5, 0.3), (8, 0.2)] {
            let accel = Accel::build(vec![(Shape::Strands(layers(n, a)), 0)]);
            let t = accel.transmittance(Vec3::ZERO, Vec3::Y, f32::INFINITY, None);
            let want = (1.0 - a).powi(n as i32);
            assert!((t - want).abs() < 1e-5, "n {n}, a {a}: {t} vs {want}");
            // Stopping before the last strand leaves it out.
            let t = accel.transmittance(Vec3::ZERO, Vec3::Y, n as f32 - 0.5, None);
            assert!((t - (1.0 - a).powi(n as i32 - 1)).abs() < 1e-5);
        }
    }

    #[test]
    fn the_stochastic_estimate_averages_to_one_minus_a_to_the_n() {
        const RAYS: u32 = 20_000;
        for (n, a) in [(1, 0.5), (3, 0.5), (5, 0.3), (8, 0.2), (4, 0.8)] {
            let accel = Accel::build(vec![(Shape::Strands(layers(n, a)), 0)]);
            let mut sum = 0.0f64;
            for seed in 0..RAYS {
                let t = accel.transmittance_estimate(Vec3::ZERO, Vec3::Y, f32::INFINITY, None, seed);
                // Blocked, or the product of the hits taken exactly: those down to the
                // first that leaves less than EXACT_SHADOW_TRANSMITTANCE.
                let exact = (1..=n as i32).map(|i| (1.0 - a).powi(i)).find(|&p| p < EXACT_SHADOW_TRANSMITTANCE);
                let passed = exact.unwrap_or((1.0 - a).powi(n as i32));
                assert!(t == 0.0 || (t - passed).abs() < 1e-6, "n {n}, a {a}: {t} vs {passed}");
                sum += t as f64;
                // The strands behind the end of the ray do not count.
                let short = accel.transmittance_estimate(Vec3::ZERO, Vec3::Y, 0.5, None, seed);
                assert_eq!(short, 1.0);
            }
            let (mean, want) = (sum as f32 / RAYS as f32, (1.0 - a).powi(n as i32));
            // Four standard deviations of the mean of RAYS values in [0, 1] averaging `want`
            // (their variance is at most want (1 - want)).
            let tolerance = 1e-5 + 4.0 * (want * (1.0 - want) / RAYS as f32).sqrt();
            assert!((mean - want).abs() < tolerance, "n {n}, a {a}: {mean} vs {want}");
        }
        // Meshes block every time.
        let accel = Accel::build(vec![(Shape::Strands(layers(2, 0.5)), 0), (Shape::Mesh(TriangleMesh::plane(4.0)), 1)]);
        assert!((0..100)
            .all(|seed| accel.transmittance_estimate(Vec3::new(0.0, 5.0, 0.0), -Vec3::Y, 9.0, None, seed) == 0.0));
    }

    #[test]
    fn meshes_and_opaque_strands_block_and_skip_is_honoured() {
        let mut strands = layers(2, 1.0);
        strands.opacity = None;
        let mesh = TriangleMesh::plane(4.0);
        let accel = Accel::build(vec![(Shape::Strands(strands), 0)]);
        assert_eq!(accel.transmittance(Vec3::ZERO, Vec3::Y, f32::INFINITY, None), 0.0);
        let accel = Accel::build(vec![(Shape::Strands(layers(2, 0.5)), 0), (Shape::Mesh(mesh), 1)]);
        // The plane lies at y = 0 (through the origin); start above it, looking down.
        assert_eq!(accel.transmittance(Vec3::new(0.0, 5.0, 0.0), -Vec3::Y, f32::INFINITY, None), 0.0);
        let skip = Skip { object: 0, first: 0, last: 0 };
        let t = accel.transmittance(Vec3::new(0.0, 5.0, 0.0), -Vec3::Y, 4.5, Some(skip));
        assert!((t - 0.5).abs() < 1e-6, "{t}");
    }

    #[test]
    fn k_nearest_hits_are_sorted_and_stop_at_opaque_hits() {
        let mut strands = layers(6, 0.25);
        // The fourth strand (points 6, 7) is opaque.
        strands.opacity.as_mut().unwrap()[6..8].fill(1.0);
        let accel = Accel::build(vec![(Shape::Strands(strands), 0)]);
        let mut out = Vec::new();
        let ray = Ray::new(Vec3::ZERO, Vec3::Y);
        accel.intersect_k(&ray, 0.0, 8, &[], None, &mut out);
        let ts: Vec<f32> = out.iter().map(|h| h.hit.t).collect();
        assert_eq!(out.len(), 4, "{ts:?}");
        assert!(ts.windows(2).all(|w| w[0] < w[1]));
        assert!((ts[0] - 0.95).abs() < 1e-4 && (ts[3] - 3.95).abs() < 1e-4, "{ts:?}");
        assert_eq!(out[3].opacity, 1.0);
        accel.intersect_k(&ray, 0.0, 2, &[], None, &mut out);
        assert_eq!(out.len(), 2);
        // Continuing past the second hit finds the third and the opaque fourth.
        let (t2, seen) = (out[1].hit.t, out.clone());
        accel.intersect_k(&ray, t2, 8, &seen, None, &mut out);
        assert_eq!(out.len(), 2);
        assert!((out[0].hit.t - 2.95).abs() < 1e-4);
    }

    #[test]
    fn a_stochastic_tail_ends_the_list_where_its_walk_stops() {
        let accel = Accel::build(vec![(Shape::Strands(layers(8, 0.5)), 0)]);
        let ray = Ray::new(Vec3::ZERO, Vec3::Y);
        let mut out = Vec::new();
        let mut lengths = [0; 9];
        for seed in 0..200 {
            let tail = StochasticTail { blend: 0.3, seed };
            accel.intersect_k(&ray, 0.0, 8, &[], Some(tail), &mut out);
            // Two layers are blended (light left 1, then 1/2), then the walk stops at the
            // first hit whose draw is below 1/2.
            let mut all = Vec::new();
            accel.intersect_k(&ray, 0.0, 8, &[], None, &mut all);
            let want =
                all.iter().enumerate().skip(2).find(|(_, h)| tail.draw(&h.hit) < 0.5).map_or(all.len(), |(i, _)| i + 1);
            assert_eq!(out, all[..want], "seed {seed}");
            lengths[out.len()] += 1;
        }
        // The walk stops at the third layer about half the time, at the fourth a quarter.
        assert!((80..120).contains(&lengths[3]) && (30..70).contains(&lengths[4]), "{lengths:?}");
    }

    #[test]
    fn k_nearest_equal_brute_force_on_random_strands() {
        let mut rng = GenRng::seed_from_u64(3);
        let mut strands = StrandSet::new();
        let v = |rng: &mut GenRng| Vec3::new(rng.random(), rng.random(), rng.random()) * 4.0 - 2.0;
        for _ in 0..400 {
            let (a, b) = (v(&mut rng), v(&mut rng));
            strands.push_strand([(a, 0.02), (a.lerp(b, 0.5), 0.02), (b, 0.02)]);
        }
        strands.opacity = Some((0..strands.points.len()).map(|_| rng.random_range(0.1..0.95)).collect());
        let accel = Accel::build(vec![(Shape::Strands(strands.clone()), 0)]);
        let (mut out, mut checked, mut cut) = (Vec::new(), 0, 0);
        for _ in 0..500 {
            let origin = v(&mut rng) * 3.0;
            let ray = Ray::new(origin, (v(&mut rng) * 0.3 - origin).normalize());
            let mut all: Vec<(f32, f32)> = strands
                .segment_starts()
                .into_iter()
                .filter_map(|p| {
                    let (p0, p1) = (strands.points[p as usize], strands.points[p as usize + 1]);
                    segment::intersect_cylinder(ray.origin, ray.dir, 0.0, f32::INFINITY, p0, p1)
                        .map(|h| (h.t, strands.opacity_at(p, h.s)))
                })
                .collect();
            all.sort_by(|a, b| a.0.total_cmp(&b.0));
            // The five nearest, up to the one behind which a negligible part of the light is left.
            let mut transmitted = 1.0f32;
            let mut want = Vec::new();
            for &(t, a) in all.iter().take(5) {
                want.push(t);
                transmitted *= 1.0 - a;
                if transmitted < NEGLIGIBLE_TRANSMITTANCE {
                    cut += 1;
                    break;
                }
            }
            accel.intersect_k(&ray, 0.0, 5, &[], None, &mut out);
            let got: Vec<f32> = out.iter().map(|h| h.hit.t).collect();
            assert_eq!(got, want);
            checked += (all.len() > 5) as u32;
        }
        assert!(checked > 20, "the test needs rays through many strands: {checked}");
        assert!(cut > 0, "the test needs stacks that stop the light before the fifth hit");
    }
}
