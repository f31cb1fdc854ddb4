//! Ray / hair segment intersection.
//!
//! A segment joins two control points `p0`, `p1` given as `[x, y, z, radius]`; the radius
//! varies linearly along the axis. The surface is an open tube (side surface only, no end
//! caps): at a strand's joints the neighbouring segment covers the gap.
//!
//! Two tests are offered:
//! * [`intersect_cylinder`], the thesis' test (Rydgard 2007, section 2.1.6, after Cychosz and
//!   Waggenspack 1994, "Intersecting a ray with a cylinder", Graphics Gems IV): an infinite
//!   cylinder whose single radius is the one at the axis parameter where the ray line comes
//!   closest to the axis line (a "faked" varying radius), clipped to the segment.
//! * [`intersect_cone`], the exact truncated cone, as one quadratic.
//!
//! Both solve in a frame centred on `p0`, starting from a point of the ray placed next to
//! the segment without rounding error (see `Local::new`): hair radii can be 1e-4 while the
//! ray origin is 1e3 units away, where one f32 ulp (6e-5) is most of a radius.
//!
//! Neither test assumes more of `dir` than that it is the ray's direction: `t` is the ray
//! parameter, so the hit point is `origin + t * dir` exactly even if `dir` is off unit
//! length by rounding. For the most precise hit point far from the ray origin (where `t`
//! itself carries an ulp of `t`), rebuild it from `s` and `normal` on the segment.

// The tests below are written `!(x > 0.0)` on purpose: a NaN must fail them and be rejected.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use crate::math::{Ray, RayMask, PACKET};
use glam::Vec3;
use wide::{bytemuck, f32x4, u32x4};

/// Where a ray meets a segment.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SegmentHit {
    /// Distance along the ray (ray direction is unit length).
    pub t: f32,
    /// Parameter along the axis, 0 at p0 and 1 at p1.
    pub s: f32,
    /// Unit outward normal of the true surface at the hit (perpendicular to the axis for the
    /// cylinder test; the cone's slanted normal for the cone test).
    pub normal: Vec3,
}

/// The thesis' test (Rydgard 2007 section 2.1.6, after Cychosz & Waggenspack, "Intersecting
/// a ray with a cylinder", Graphics Gems IV): intersect the infinite cylinder around the axis
/// with the radius taken at the axis parameter of closest approach between ray line and axis
/// line (the "faked" varying radius), keep hits whose axis parameter lies in [0, 1] and whose
/// t lies in (tmin, tmax). Returns the nearest.
///
/// The closest-approach parameter is clamped to [0, 1] so the radius stays between the end
/// radii. A ray parallel to the axis never meets the side and returns `None`.
#[inline]
pub fn intersect_cylinder(
    origin: Vec3,
    dir: Vec3,
    tmin: f32,
    tmax: f32,
    p0: [f32; 4],
    p1: [f32; 4],
) -> Option<SegmentHit> {
    // One implementation serves one segment and four: the others lanes hold no surface.
    let hits = intersect_cylinder4(origin, dir, tmin, tmax, lane0(p0), lane0(p1));
    hits.nearest().and_then(|lane| hits.hit(lane))
}

/// A point `[x, y, z, radius]` in lane 0 of a four-lane test, the other lanes empty.
#[inline(always)]
fn lane0(p: [f32; 4]) -> [f32x4; 4] {
    [f32x4::new(p), f32x4::ZERO, f32x4::ZERO, f32x4::ZERO]
}

/// The cylinder test of [`intersect_cylinder`] on four segments at once (lanes of 4-wide
/// SIMD), for BVH leaves: `p0[i]` and `p1[i]` are the end points `[x, y, z, radius]` of
/// lane `i`'s segment. A lane whose segment is all zeros holds no surface.
/// Always inlined: its arguments and result are a few hundred bytes, which a call would copy.
#[inline(always)]
pub fn intersect_cylinder4(origin: Vec3, dir: Vec3, tmin: f32, tmax: f32, p0: [f32x4; 4], p1: [f32x4; 4]) -> Hits4 {
    let miss = Hits4 { mask: 0, t: f32x4::ZERO, s: f32x4::ZERO, u: f32x4::ZERO, g: None };
    // Most segments of a leaf pass far from the ray: the cheap bound drops whole groups of
    // four before the exact frame is built.
    let near = Candidates::new(origin, dir, p0, p1);
    if near.near().to_bitmask() == 0 {
        return miss;
    }
    let (g, mut valid) = Local4::from_candidates(origin, dir, near);
    if valid.to_bitmask() == 0 {
        return miss;
    }
    // Cychosz & Waggenspack's n = dir x axis vanishes exactly when the ray is parallel to the
    // axis; |dir x axis|^2 = |axis|^2 |d_perp|^2, so d_perp carries the same test.
    let aa = g.dp.length_squared();
    valid &= aa.simd_gt(f32x4::ZERO);
    let inv_aa = f32x4::ONE / aa;
    let b = g.cp.dot(g.dp);
    // Closest approach of the ray line to the axis line: minimising |cp + u dp|^2 gives
    // u* = -b / aa (Cychosz & Waggenspack's t along the ray); its axis parameter is s*.
    let s_star = g.sc - b * inv_aa * g.sd;
    let rho = g.r0 + g.dr * s_star.fast_max(f32x4::ZERO).fast_min(f32x4::ONE);
    valid &= rho.simd_gt(f32x4::ZERO);
    // Quadratic aa u^2 + 2 b u + cc = 0 for |cp + u dp| = rho. Its discriminant b^2 - aa cc is
    // formed as aa rho^2 - |cp x dp|^2 (Lagrange's identity): |cp x dp|^2 / aa is the squared
    // distance between the lines, Cychosz & Waggenspack's d, so the test reads
    // aa (rho^2 - d^2) >= 0 and never subtracts two large nearly equal squares. This is the
    // form Haines et al. recommend for spheres (Ray Tracing Gems 2019, ch. 7).
    let disc = aa * rho * rho - g.cross2;
    valid &= disc.simd_ge(f32x4::ZERO);
    if valid.to_bitmask() == 0 {
        return miss;
    }
    let cc = g.cp.length_squared() - rho * rho;
    // Stable roots (Press et al., Numerical Recipes, section 5.6; Haines et al. 2019): with the
    // half coefficient b, q = -0.5 (B + sign(B) sqrt(B^2 - 4 A C)) becomes
    // q = -(b + sign(b) sqrt(disc)), a sum of two terms of one sign; then u = q / aa and cc / q.
    let q = -(b + disc.fast_max(f32x4::ZERO).sqrt().copysign(b));
    let u1 = q * inv_aa;
    // q = 0 only for a tangent ray with b = 0: then the double root is u1 = 0.
    let u2 = q.simd_ne(f32x4::ZERO).select(cc / q, u1);
    let (near, far) = (u1.fast_min(u2), u1.fast_max(u2));
    // Open tube: if the front root falls outside the segment or the ray interval, the back
    // wall seen through the open end may still be hit.
    let accept = |u: f32x4| {
        let t = g.t0 + u;
        let s = g.sc + u * g.sd;
        t.simd_gt(f32x4::splat(tmin))
            & t.simd_lt(f32x4::splat(tmax))
            & s.simd_ge(f32x4::ZERO)
            & s.simd_le(f32x4::ONE)
            & t.is_finite()
    };
    let near_ok = accept(near);
    let far_ok = accept(far);
    let u = near_ok.select(near, far);
    let mask = (valid & (near_ok | far_ok)).to_bitmask();
    Hits4 { mask, t: g.t0 + u, s: g.sc + u * g.sd, u, g: Some(g) }
}

/// Which of up to eight segments of `points` the ray line may pass near enough to hit: bit
/// `i` is set when segment `i`, joining `points[firsts[i]]` and `points[firsts[i] + 1]`,
/// its radii multiplied by `radius_scale`, survives the cheap bound of
/// [`intersect_cylinder4`] (the first stage of its test, the same arithmetic, the same
/// result). Level of detail passes the widest factor any of the segments is drawn with: the
/// bound only grows with the radius, so no segment it clears could be hit wider. A BVH leaf's segments are culled in one 8-wide pass on x86-64
/// CPUs with AVX2 (detected at run time), two 4-wide passes elsewhere; only the few
/// survivors go on to the exact test. A cleared bit means the exact test would not hit.
///
/// Panics if `firsts` holds more than eight segments or one whose points are out of bounds.
#[inline(always)]
pub fn near8(origin: Vec3, dir: Vec3, points: &[[f32; 4]], firsts: &[u32], radius_scale: f32) -> u32 {
    assert!(firsts.len() <= 8, "near8 takes at most eight segments");
    #[cfg(target_arch = "x86_64")]
    if std::is_x86_feature_detected!("avx2") {
        // SAFETY: the CPU has the features `near8_avx2` is compiled for.
        return unsafe { near8_avx2(origin, dir, points, firsts, radius_scale) };
    }
    let mut near = 0;
    for (half, group) in firsts.chunks(4).enumerate() {
        let (mut p0, mut p1) = ([f32x4::ZERO; 4], [f32x4::ZERO; 4]);
        let scaled = |[x, y, z, r]: [f32; 4]| f32x4::new([x, y, z, r * radius_scale]);
        for (lane, &first) in group.iter().enumerate() {
            p0[lane] = scaled(points[first as usize]);
            p1[lane] = scaled(points[first as usize + 1]);
        }
        near |= (Candidates::new(origin, dir, p0, p1).near().to_bitmask() & 0xf) << (4 * half);
    }
    near
}

/// [`near8`] for a packet of rays (`rays[i]` for the rays `i` in `mask`; bit i of a
/// [`RayMask`]): the same bits for each ray as [`near8`] gives it alone, with the
/// segments loaded and transposed once for all of them on AVX2 CPUs.
///
/// Panics like [`near8`], or if `mask` names a ray past the end of `rays`.
#[inline]
pub fn near8_packet(
    rays: &[Ray],
    mut mask: RayMask,
    points: &[[f32; 4]],
    firsts: &[u32],
    radius_scale: f32,
) -> [u32; PACKET] {
    assert!(firsts.len() <= 8, "near8 takes at most eight segments");
    let mut near = [0; PACKET];
    #[cfg(target_arch = "x86_64")]
    if std::is_x86_feature_detected!("avx2") {
        // SAFETY: the CPU has the features `near8_each_avx2` is compiled for.
        unsafe {
            near8_each_avx2(
                points,
                firsts,
                radius_scale,
                mask,
                |i| (rays[i].origin, rays[i].dir),
                |i, bits| near[i] = bits,
            )
        };
        return near;
    }
    while mask != 0 {
        let i = mask.trailing_zeros() as usize;
        mask &= mask - 1;
        near[i] = near8(rays[i].origin, rays[i].dir, points, firsts, radius_scale);
    }
    near
}

/// [`near8`]'s one 8-wide pass: [`Candidates::new`] written with AVX2 intrinsics, operation
/// for operation (no fused multiply-adds), so both give the same bits.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn near8_avx2(origin: Vec3, dir: Vec3, points: &[[f32; 4]], firsts: &[u32], radius_scale: f32) -> u32 {
    let mut near = 0;
    near8_each_avx2(points, firsts, radius_scale, 1, |_| (origin, dir), |_, bits| near = bits);
    near
}

/// [`near8_avx2`] for the rays `i` in `rays` (origin and direction `ray(i)`): the eight
/// segments are loaded and transposed once, then `near(i, bits)` gets each ray's bits.
/// One function with straight-line code (the closures hold no intrinsics): helpers with
/// AVX2 of their own would not be inlined, and pass their registers through memory.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn near8_each_avx2(
    points: &[[f32; 4]],
    firsts: &[u32],
    radius_scale: f32,
    mut rays: RayMask,
    ray: impl Fn(usize) -> (Vec3, Vec3),
    mut near: impl FnMut(usize, u32),
) {
    use std::arch::x86_64::*;
    // Straight-line code, no helper closures: those would be compiled without AVX2 and called.
    // Both end points of each segment; all zeros (no surface) past the last segment.
    let mut ends = [[[0.0f32; 4]; 8]; 2];
    for (i, &first) in firsts.iter().enumerate() {
        ends[0][i] = points[first as usize];
        ends[1][i] = points[first as usize + 1];
    }
    // Structure of arrays: x, y, z and radius of one end of the eight segments, segment i
    // in lane i (a 4x4 transpose in each 128-bit half: segments 0-3 and 4-7).
    let mut soa = [[_mm256_setzero_ps(); 4]; 2];
    for (end, points) in ends.iter().enumerate() {
        let row = |k: usize| _mm256_set_m128(bytemuck::cast(points[k + 4]), bytemuck::cast(points[k]));
        let (r0, r1, r2, r3) = (row(0), row(1), row(2), row(3));
        let (t0, t1) = (_mm256_unpacklo_ps(r0, r1), _mm256_unpackhi_ps(r0, r1));
        let (t2, t3) = (_mm256_unpacklo_ps(r2, r3), _mm256_unpackhi_ps(r2, r3));
        soa[end] = [
            _mm256_shuffle_ps::<0x44>(t0, t2),
            _mm256_shuffle_ps::<0xee>(t0, t2),
            _mm256_shuffle_ps::<0x44>(t1, t3),
            _mm256_shuffle_ps::<0xee>(t1, t3),
        ];
    }
    let [[x0, y0, z0, r0], [x1, y1, z1, r1]] = soa;
    let (r0, r1) = (_mm256_mul_ps(r0, _mm256_set1_ps(radius_scale)), _mm256_mul_ps(r1, _mm256_set1_ps(radius_scale)));
    let zero = _mm256_setzero_ps();
    let valid = _mm256_and_ps(
        _mm256_and_ps(_mm256_cmp_ps::<_CMP_GE_OQ>(r0, zero), _mm256_cmp_ps::<_CMP_GE_OQ>(r1, zero)),
        _mm256_cmp_ps::<_CMP_GT_OQ>(_mm256_add_ps(r0, r1), zero),
    );
    let (ax, ay, az) = (_mm256_sub_ps(x1, x0), _mm256_sub_ps(y1, y0), _mm256_sub_ps(z1, z0));
    let l2 = _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(ax, ax), _mm256_mul_ps(ay, ay)), _mm256_mul_ps(az, az));
    let valid = _mm256_and_ps(valid, _mm256_cmp_ps::<_CMP_GT_OQ>(l2, zero));
    let rmax = _mm256_max_ps(r0, r1);
    let rmax2 = _mm256_mul_ps(rmax, rmax);
    let sign = _mm256_set1_ps(-0.0);
    while rays != 0 {
        let i = rays.trailing_zeros() as usize;
        rays &= rays - 1;
        let (origin, dir) = ray(i);
        let (dx, dy, dz) = (_mm256_set1_ps(dir.x), _mm256_set1_ps(dir.y), _mm256_set1_ps(dir.z));
        let nx = _mm256_sub_ps(_mm256_mul_ps(dy, az), _mm256_mul_ps(dz, ay));
        let ny = _mm256_sub_ps(_mm256_mul_ps(dz, ax), _mm256_mul_ps(dx, az));
        let nz = _mm256_sub_ps(_mm256_mul_ps(dx, ay), _mm256_mul_ps(dy, ax));
        let wx = _mm256_sub_ps(_mm256_set1_ps(origin.x), x0);
        let wy = _mm256_sub_ps(_mm256_set1_ps(origin.y), y0);
        let wz = _mm256_sub_ps(_mm256_set1_ps(origin.z), z0);
        let n2 = _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(nx, nx), _mm256_mul_ps(ny, ny)), _mm256_mul_ps(nz, nz));
        let w_inf = _mm256_max_ps(
            _mm256_max_ps(_mm256_andnot_ps(sign, wx), _mm256_andnot_ps(sign, wy)),
            _mm256_andnot_ps(sign, wz),
        );
        let n_inf = _mm256_max_ps(
            _mm256_max_ps(_mm256_andnot_ps(sign, nx), _mm256_andnot_ps(sign, ny)),
            _mm256_andnot_ps(sign, nz),
        );
        let e = _mm256_mul_ps(_mm256_mul_ps(_mm256_set1_ps(3.0 / 262_144.0), w_inf), n_inf);
        let wn = _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(wx, nx), _mm256_mul_ps(wy, ny)), _mm256_mul_ps(wz, nz));
        let m = _mm256_sub_ps(_mm256_andnot_ps(sign, wn), e);
        let bound = _mm256_mul_ps(_mm256_mul_ps(rmax2, n2), _mm256_set1_ps(1.0 + 1.0 / 512.0));
        let far = _mm256_and_ps(
            _mm256_cmp_ps::<_CMP_GT_OQ>(m, zero),
            _mm256_cmp_ps::<_CMP_GT_OQ>(_mm256_mul_ps(m, m), bound),
        );
        near(i, _mm256_movemask_ps(_mm256_andnot_ps(far, valid)) as u32);
    }
}

/// The result of [`intersect_cylinder4`]: which lanes hit, and where.
pub struct Hits4 {
    /// Bit `i` set when lane `i` hits.
    pub mask: u32,
    t: f32x4,
    s: f32x4,
    u: f32x4,
    /// The frames, when some lane may hit (a miss returns without copying them).
    g: Option<Local4>,
}

impl Hits4 {
    /// Ray distances of the four lanes (meaningful where `mask` is set).
    #[inline]
    pub fn t(&self) -> [f32; 4] {
        self.t.to_array()
    }

    /// Axis parameters of the four lanes (meaningful where `mask` is set).
    #[inline]
    pub fn s(&self) -> [f32; 4] {
        self.s.to_array()
    }

    /// The hitting lane with the smallest distance.
    #[inline]
    pub fn nearest(&self) -> Option<usize> {
        let t = self.t.to_array();
        let mut best: Option<usize> = None;
        let mut mask = self.mask;
        while mask != 0 {
            let i = mask.trailing_zeros() as usize;
            mask &= mask - 1;
            if best.is_none_or(|b| t[i] < t[b]) {
                best = Some(i);
            }
        }
        best
    }

    /// The full hit of lane `lane`, with its unit normal; `None` if the lane missed or the
    /// normal cannot be formed at extreme scales.
    #[inline]
    pub fn hit(&self, lane: usize) -> Option<SegmentHit> {
        if self.mask & (1 << lane) == 0 {
            return None;
        }
        let g = self.g.as_ref()?.lane(lane);
        let u = self.u.to_array()[lane];
        // The cylinder's normal is the radial direction of the hit, perpendicular to the axis.
        finish(self.t.to_array()[lane], self.s.to_array()[lane], g.cp + g.dp * u)
    }
}

/// Exact ray / truncated-cone test (the side surface of the cone frustum whose radius goes
/// linearly from r0 at p0 to r1 at p1), solved as one quadratic; nearest root with s in [0, 1]
/// and t in (tmin, tmax).
#[inline]
pub fn intersect_cone(origin: Vec3, dir: Vec3, tmin: f32, tmax: f32, p0: [f32; 4], p1: [f32; 4]) -> Option<SegmentHit> {
    let (g4, valid) = Local4::new(origin, dir, lane0(p0), lane0(p1));
    if valid.to_bitmask() & 1 == 0 {
        return None;
    }
    let g = g4.lane(0);
    // Along the ray X(u) = c + u dir the axis parameter is s(u) = sc + u sd and the cone's
    // radius rho(u) = rho_c + k u. The side surface is |X_perp| = rho, that is
    // |cp + u dp|^2 = (rho_c + k u)^2, a quadratic aa u^2 + 2 b u + cc = 0 with:
    let k = g.dr * g.sd;
    let rho_c = g.r0 + g.dr * g.sc;
    let aa = g.dp.length_squared() - k * k;
    let b = g.cp.dot(g.dp) - k * rho_c;
    let cc = g.cp.length_squared() - rho_c * rho_c;
    // b^2 - aa cc expands (Lagrange's identity again) to |rho_c dp - k cp|^2 - |cp x dp|^2: a
    // difference of two squared lengths of short vectors instead of products of large terms.
    // For k = 0 it is the cylinder's aa rho^2 - |cp x dp|^2 (Cychosz & Waggenspack's d).
    let disc = (g.dp * rho_c - g.cp * k).length_squared() - g.cross2;
    if !(disc >= 0.0) {
        return None;
    }
    // Stable roots as in the cylinder test. aa can be 0 (ray parallel to a generator line of
    // the cone: one root, cc / q, survives) or negative (ray steeper than the cone: a root may
    // lie on the mirrored nappe beyond the apex, which is outside s in [0, 1] because both end
    // radii are non-negative).
    let q = -(b + disc.sqrt().copysign(b));
    let aq = aa * q;
    let (u1, u2) = if aq.is_normal() {
        // One division for both roots: q / aa = q^2 / (aa q) and cc / q = cc aa / (aa q).
        let inv = 1.0 / aq;
        (q * q * inv, cc * aa * inv)
    } else {
        // aa = 0 or q = 0 (or an extreme scale): a zero denominator yields an infinite or
        // NaN root, which the range tests below reject; a finite one is still a true root.
        (q / aa, cc / q)
    };
    let (near, far) = if u1 <= u2 { (u1, u2) } else { (u2, u1) };
    let accept = |u: f32| -> Option<SegmentHit> {
        let t = g.t0 + u;
        let s = g.sc + u * g.sd;
        if !(t > tmin && t < tmax && (0.0..=1.0).contains(&s)) {
            return None;
        }
        let rho = g.r0 + g.dr * s;
        // rho = 0 is the apex of a tapered tip: no tangent plane, not a hit.
        if !(rho > 0.0) {
            return None;
        }
        // Gradient of |X_perp|^2 - rho(s)^2 with s = X.axis / L^2: 2 X_perp - 2 rho dr axis / L^2,
        // the radial direction tilted against the widening of the cone.
        finish(t, s, g.cp + g.dp * u - g.a * (rho * g.dr * g.inv_l2))
    };
    accept(near).or_else(|| accept(far))
}

/// Axis-aligned bounds of the segment (both end spheres), as (min, max).
///
/// The hull of the two end spheres holds the cone frustum. The cylinder test's radius can
/// exceed the cone's near the thinner end by at most |r1 - r0|, so its hits may poke out of
/// these bounds by that much (a sliver for hair, where radii barely change per segment).
#[inline]
pub fn bounds(p0: [f32; 4], p1: [f32; 4]) -> (Vec3, Vec3) {
    let (c0, c1) = (Vec3::new(p0[0], p0[1], p0[2]), Vec3::new(p1[0], p1[1], p1[2]));
    // f32::max ignores NaN, so a NaN radius counts as 0.
    let (r0, r1) = (Vec3::splat(p0[3].max(0.0)), Vec3::splat(p1[3].max(0.0)));
    ((c0 - r0).min(c1 - r1), (c0 + r0).max(c1 + r1))
}

/// The ray and one segment in a frame centred on `p0`: one lane of [`Local4`].
struct Local {
    /// Ray parameter of `c`, the point of the ray next to the segment (see `Local4::new`).
    t0: f32,
    /// Axis `p1 - p0`.
    a: Vec3,
    /// 1 / |a|^2.
    inv_l2: f32,
    /// Axis parameters of the point `c` and of the direction: s(u) = sc + u sd.
    sc: f32,
    sd: f32,
    /// Components of `c` (relative to p0) and of the direction perpendicular to the axis.
    cp: Vec3,
    dp: Vec3,
    /// |cp x dp|^2: |dp|^2 times the squared distance between the ray line and the axis line.
    cross2: f32,
    /// Radius at p0 and its change over the segment.
    r0: f32,
    dr: f32,
}

/// Three-vectors of four lanes.
#[derive(Clone, Copy)]
struct V4 {
    x: f32x4,
    y: f32x4,
    z: f32x4,
}

impl V4 {
    #[inline(always)]
    fn splat(v: Vec3) -> V4 {
        V4 { x: f32x4::splat(v.x), y: f32x4::splat(v.y), z: f32x4::splat(v.z) }
    }
    #[inline(always)]
    fn dot(self, o: V4) -> f32x4 {
        self.x * o.x + self.y * o.y + self.z * o.z
    }
    #[inline(always)]
    fn length_squared(self) -> f32x4 {
        self.dot(self)
    }
    #[inline(always)]
    fn cross(self, o: V4) -> V4 {
        V4 { x: self.y * o.z - self.z * o.y, y: self.z * o.x - self.x * o.z, z: self.x * o.y - self.y * o.x }
    }
    #[inline(always)]
    fn add(self, o: V4) -> V4 {
        V4 { x: self.x + o.x, y: self.y + o.y, z: self.z + o.z }
    }
    #[inline(always)]
    fn sub(self, o: V4) -> V4 {
        V4 { x: self.x - o.x, y: self.y - o.y, z: self.z - o.z }
    }
    #[inline(always)]
    fn scale(self, k: f32x4) -> V4 {
        V4 { x: self.x * k, y: self.y * k, z: self.z * k }
    }
    #[inline(always)]
    fn lane(self, i: usize) -> Vec3 {
        Vec3::new(self.x.to_array()[i], self.y.to_array()[i], self.z.to_array()[i])
    }
}

/// The ray and four segments, each in a frame centred on its `p0`.
#[derive(Clone, Copy)]
struct Local4 {
    t0: f32x4,
    a: V4,
    inv_l2: f32x4,
    sc: f32x4,
    sd: f32x4,
    cp: V4,
    dp: V4,
    cross2: f32x4,
    r0: f32x4,
    dr: f32x4,
}

/// Four segments in structure-of-arrays form, with the lanes that may be hit: the first,
/// cheap stage of [`Local4::new`].
struct Candidates {
    q0: V4,
    a: V4,
    l2: f32x4,
    r0: f32x4,
    r1: f32x4,
    /// `n = dir x a`, its squared length and the larger radius, shared with the exact stage.
    n: V4,
    n2: f32x4,
    rmax: f32x4,
    /// Lanes holding a surface.
    valid: f32x4,
    /// Lanes whose axis line the ray line surely passes too far from to hit.
    far: f32x4,
}

impl Candidates {
    /// Loads four segments and culls degenerate ones and those whose axis line the ray line
    /// passes farther from than the larger radius, by a conservative bound computed from the
    /// plainly rounded offset `origin - p0`.
    ///
    /// The exact stage culls a lane when `m^2 > rmax^2 |n|^2 (1 + 2^-10)` with `m = c.n`
    /// computed from the exactly placed point `c`. Here `m` is `w.n` with `w = origin - p0`
    /// rounded: `c - w` lies along `dir`, perpendicular to `n`, so both are the same value
    /// up to rounding, which is below `2^-21 |w| |n|` for the two of them together (one
    /// rounding per component of `w`, three per dot product; `c` is no longer than `w`).
    /// Subtracting `e = 3 * 2^-18 |w|_inf |n|_inf`, eight times that bound, and comparing
    /// against a threshold widened by another 2^-10 culls only lanes the exact stage would
    /// cull: the result is the same, bit for bit, and groups of four far segments skip the
    /// TwoSum transform, the division and the frame.
    #[inline(always)]
    fn new(origin: Vec3, dir: Vec3, p0: [f32x4; 4], p1: [f32x4; 4]) -> Candidates {
        // Structure of arrays: component k of the four points.
        let ([x0, y0, z0, r0], [x1, y1, z1, r1]) = (f32x4::transpose(p0), f32x4::transpose(p1));
        let (q0, q1) = (V4 { x: x0, y: y0, z: z0 }, V4 { x: x1, y: y1, z: z1 });
        // Zero radius at both ends, a negative radius or NaN: no surface. A single zero end
        // is a tapered tip and stays valid. (Comparisons with NaN are false.)
        let mut valid = r0.simd_ge(f32x4::ZERO) & r1.simd_ge(f32x4::ZERO) & (r0 + r1).simd_gt(f32x4::ZERO);
        let a = q1.sub(q0);
        let l2 = a.length_squared();
        valid &= l2.simd_gt(f32x4::ZERO); // zero-length segment: no axis, no side surface
        let n = V4::splat(dir).cross(a);
        let w = V4::splat(origin).sub(q0);
        let n2 = n.length_squared();
        let inf_norm = |v: V4| v.x.abs().fast_max(v.y.abs()).fast_max(v.z.abs());
        let e = f32x4::splat(3.0 / 262_144.0) * inf_norm(w) * inf_norm(n);
        let m = w.dot(n).abs() - e;
        let rmax = r0.fast_max(r1);
        let far = m.simd_gt(f32x4::ZERO) & (m * m).simd_gt(rmax * rmax * n2 * f32x4::splat(1.0 + 1.0 / 512.0));
        Candidates { q0, a, l2, r0, r1, n, n2, rmax, valid, far }
    }

    /// Lanes holding a surface the ray line may come near enough to hit.
    #[inline(always)]
    fn near(&self) -> f32x4 {
        self.valid & !self.far
    }
}

impl Local4 {
    /// The frames of four segments and the mask of lanes that may hit: degenerate segments
    /// and segments the ray line passes too far from are culled.
    #[inline(always)]
    fn new(origin: Vec3, dir: Vec3, p0: [f32x4; 4], p1: [f32x4; 4]) -> (Local4, f32x4) {
        Local4::from_candidates(origin, dir, Candidates::new(origin, dir, p0, p1))
    }

    /// The exact stage of [`Local4::new`].
    ///
    /// Translating the origin to p0's frame (`origin - p0`) in f32 would already round away
    /// up to half an ulp of |origin|, 3e-5 at 1e3 units, and stepping along the ray would
    /// round the products `t dir` as much again. Instead the offset is kept exact as a sum
    /// hi + lo (Knuth's TwoSum, TAOCP vol. 2, section 4.2.2), the step t0 is cut to 12
    /// significant bits and the direction split into two parts of at most 12 bits (the
    /// splitting of Dekker 1971, "A floating-point technique for extending the available
    /// precision"), so the products t0 * dir_hi and t0 * dir_lo are exact. The point `c` of
    /// the ray at t0 then lies within 2^-11 |t0| of the ray point nearest p0 and is accurate
    /// to f32 precision *of its own small size*, about 2^-35 |t0|, instead of 2^-24 |origin|.
    /// Everything after works with lengths of the segment's scale; the only loss left is the
    /// rounding of t = t0 + u itself. Cost: about 35 extra flops, no division.
    #[inline(always)]
    fn from_candidates(origin: Vec3, dir: Vec3, k: Candidates) -> (Local4, f32x4) {
        let mut valid = k.near();
        let Candidates { q0, a, l2, r0, r1, n, n2, rmax, .. } = k;
        let (hx, lx) = two_sum(f32x4::splat(origin.x), -q0.x);
        let (hy, ly) = two_sum(f32x4::splat(origin.y), -q0.y);
        let (hz, lz) = two_sum(f32x4::splat(origin.z), -q0.z);
        let (hi, lo) = (V4 { x: hx, y: hy, z: hz }, V4 { x: lx, y: ly, z: lz });
        let d = V4::splat(dir);
        let t0 = high12(-hi.dot(d));
        let dh_s = Vec3::new(high12_1(dir.x), high12_1(dir.y), high12_1(dir.z));
        // dl is exact and has at most 12 significant bits too. hi + t0 dh cancels exactly
        // (Sterbenz's lemma) where both are large; what is left, and t0 dl + lo, are small,
        // so their rounding errors are small too.
        let (dh, dl) = (V4::splat(dh_s), V4::splat(dir - dh_s));
        let c = hi.add(dh.scale(t0)).add(dl.scale(t0).add(lo));

        // Cychosz & Waggenspack's early out: with n = dir x a, the distance between the ray
        // line and the axis line is |c.n| / |n|; beyond the larger radius neither surface is
        // met. Compared squared, without a division; the 2^-10 of slack keeps rounding from
        // culling a grazing hit that the full test would find. (A ray parallel to the axis
        // has n = 0 and passes on.)
        let m = c.dot(n);
        valid &= !(m * m).simd_gt(rmax * rmax * n2 * f32x4::splat(1.0 + 1.0 / 1024.0));

        let inv_l2 = f32x4::ONE / l2;
        valid &= inv_l2.is_finite();
        let sc = c.dot(a) * inv_l2;
        let sd = d.dot(a) * inv_l2;
        let (cp, dp) = (c.sub(a.scale(sc)), d.sub(a.scale(sd)));
        // |cp x dp|^2: the perpendicular parts' cross product is the component of c x dir
        // along the axis, so its squared length is (c.(dir x a))^2 / |a|^2 = m^2 / l2.
        let g = Local4 { t0, a, inv_l2, sc, sd, cp, dp, cross2: m * m * inv_l2, r0, dr: r1 - r0 };
        (g, valid)
    }

    /// Lane `i` as a scalar frame.
    #[inline]
    fn lane(&self, i: usize) -> Local {
        let at = |v: f32x4| v.to_array()[i];
        Local {
            t0: at(self.t0),
            a: self.a.lane(i),
            inv_l2: at(self.inv_l2),
            sc: at(self.sc),
            sd: at(self.sd),
            cp: self.cp.lane(i),
            dp: self.dp.lane(i),
            cross2: at(self.cross2),
            r0: at(self.r0),
            dr: at(self.dr),
        }
    }
}

/// The hit with its normal made unit length, or `None` if it is not finite (extreme scales).
#[inline(always)]
fn finish(t: f32, s: f32, n: Vec3) -> Option<SegmentHit> {
    let mut n = n;
    let mut len2 = n.length_squared();
    // Squares of lengths below ~1e-15 or above ~1e15 (radii at such world scales) leave the
    // normal f32 range and lose the unit length: rescale first (rarely taken).
    if !((1e-30..=1e30).contains(&len2)) {
        let m = n.abs().max_element();
        if !(m > 0.0 && m.is_finite()) {
            return None;
        }
        n *= 1.0 / m;
        len2 = n.length_squared();
    }
    let normal = n * (1.0 / len2.sqrt());
    (t.is_finite() && normal.is_finite()).then_some(SegmentHit { t, s, normal })
}

/// a + b exactly as (sum, error) (Knuth's TwoSum: no precondition on magnitudes).
#[inline(always)]
fn two_sum(a: f32x4, b: f32x4) -> (f32x4, f32x4) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

/// The 12 leading significant bits of each lane (see [`high12_1`]).
#[inline(always)]
fn high12(x: f32x4) -> f32x4 {
    let bits: u32x4 = bytemuck::cast(x);
    bytemuck::cast(bits & u32x4::splat(0xffff_f000))
}

/// `x` with its mantissa cut to the leading 12 significant bits (the sign, the exponent and
/// the top 11 stored bits), so that `x - high12(x)` is exact and also has at most 12 bits: a
/// product of two such parts has at most 24 bits and is exact in f32. Dekker (1971) splits by
/// Veltkamp's rounding trick (three operations); truncating with a mask is one.
#[inline(always)]
fn high12_1(x: f32) -> f32 {
    f32::from_bits(x.to_bits() & 0xffff_f000)
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    type Test = fn(Vec3, Vec3, f32, f32, [f32; 4], [f32; 4]) -> Option<SegmentHit>;
    const TESTS: [(&str, Test); 2] = [("cylinder", intersect_cylinder), ("cone", intersect_cone)];
    const INF: f32 = f32::INFINITY;

    fn pt(p: Vec3, r: f32) -> [f32; 4] {
        [p.x, p.y, p.z, r]
    }

    fn close(a: f32, b: f32, tol: f32) -> bool {
        (a - b).abs() <= tol
    }

    /// A small deterministic generator (64-bit LCG, Knuth's MMIX constants; high bits only).
    struct Lcg(u64);
    impl Lcg {
        fn f(&mut self) -> f32 {
            self.0 = self.0.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            (self.0 >> 40) as f32 / (1u64 << 24) as f32
        }
        fn range(&mut self, lo: f32, hi: f32) -> f32 {
            lo + (hi - lo) * self.f()
        }
        fn unit(&mut self) -> Vec3 {
            loop {
                let v = Vec3::new(self.range(-1.0, 1.0), self.range(-1.0, 1.0), self.range(-1.0, 1.0));
                let l = v.length();
                if l > 0.1 && l <= 1.0 {
                    return v / l;
                }
            }
        }
    }

    /// A unit vector perpendicular to `v`.
    fn perp(v: Vec3) -> Vec3 {
        // Duff et al. 2017 (as `math::frame`), first tangent only.
        let n = v.normalize();
        let sign = 1.0f32.copysign(n.z);
        let a = -1.0 / (sign + n.z);
        Vec3::new(1.0 + sign * n.x * n.x * a, sign * n.x * n.y * a, -sign * n.x)
    }

    /// Reference: the exact cone (radius linear in s) in f64, by the textbook quadratic after
    /// moving the origin to the ray point nearest p0 (all in f64, exact enough).
    fn reference_cone(o: Vec3, d: Vec3, p0: [f32; 4], p1: [f32; 4]) -> Option<(f64, f64)> {
        let (o, d) = (o.as_dvec3(), d.as_dvec3());
        let q0 = DVec3::new(p0[0] as f64, p0[1] as f64, p0[2] as f64);
        let q1 = DVec3::new(p1[0] as f64, p1[1] as f64, p1[2] as f64);
        let (r0, r1) = (p0[3] as f64, p1[3] as f64);
        let axis = q1 - q0;
        let l2 = axis.length_squared();
        let w = o - q0;
        let t0 = -w.dot(d) / d.length_squared();
        let c = w + d * t0;
        // |X|^2 - (X.a)^2/L^2 - (r0 + dr X.a/L^2)^2 = 0 with X = c + u d.
        let (ca, da, dr) = (c.dot(axis) / l2, d.dot(axis) / l2, r1 - r0);
        let qa = d.length_squared() - da * da * l2 - dr * dr * da * da;
        let qb = 2.0 * (c.dot(d) - ca * da * l2 - dr * da * (r0 + dr * ca));
        let qc = c.length_squared() - ca * ca * l2 - (r0 + dr * ca).powi(2);
        let disc = qb * qb - 4.0 * qa * qc;
        if disc < 0.0 {
            return None;
        }
        let mut roots = [(-qb - disc.sqrt()) / (2.0 * qa), (-qb + disc.sqrt()) / (2.0 * qa)];
        roots.sort_by(|x, y| x.partial_cmp(y).unwrap());
        roots
            .into_iter()
            .map(|u| (t0 + u, ca + u * da))
            .find(|&(t, s)| t > 0.0 && (0.0..=1.0).contains(&s) && r0 + dr * s > 0.0)
    }

    /// Signed distance of `x` from the cone surface (f64), measured perpendicular to the axis
    /// times the cosine of the slant (exact for points near the surface).
    fn cone_distance(x: DVec3, p0: [f32; 4], p1: [f32; 4]) -> f64 {
        let q0 = DVec3::new(p0[0] as f64, p0[1] as f64, p0[2] as f64);
        let q1 = DVec3::new(p1[0] as f64, p1[1] as f64, p1[2] as f64);
        let axis = q1 - q0;
        let l = axis.length();
        let s = (x - q0).dot(axis) / (l * l);
        let radial = (x - q0 - axis * s).length();
        let slope = (p1[3] as f64 - p0[3] as f64) / l;
        (radial - (p0[3] as f64 + slope * s * l)) / (1.0 + slope * slope).sqrt()
    }

    fn assert_finite(h: &SegmentHit) {
        assert!(h.t.is_finite() && h.s.is_finite() && h.normal.is_finite(), "{h:?}");
        assert!(close(h.normal.length(), 1.0, 1e-5), "{h:?}");
    }

    /// Segments of the tests: along +z and along a skew direction (f32 rounding then makes the
    /// analytic values exact only to a few ulps).
    fn frames() -> [(Vec3, Vec3); 2] {
        [(Vec3::ZERO, Vec3::Z), (Vec3::new(0.3, -0.2, 0.5), Vec3::new(1.0, 2.0, -0.5).normalize())]
    }

    #[test]
    fn perpendicular_hit_through_axis() {
        let (r, len, dist) = (0.1f32, 2.0f32, 5.0f32);
        for (base, axis) in frames() {
            let (p0, p1) = (pt(base, r), pt(base + axis * len, r));
            let side = perp(axis);
            for s0 in [0.1f32, 0.5, 0.9] {
                let on_axis = base + axis * (len * s0);
                let dir = -side;
                for (name, test) in TESTS {
                    let h =
                        test(on_axis - dir * dist, dir, 0.0, INF, p0, p1).unwrap_or_else(|| panic!("{name} s0={s0}"));
                    assert_finite(&h);
                    assert!(close(h.t, dist - r, 2e-6), "{name}: {h:?}");
                    assert!(close(h.s, s0, 2e-6), "{name}: {h:?}");
                    assert!(h.normal.abs_diff_eq(-dir, 1e-5), "{name}: {h:?}");
                }
            }
        }
    }

    #[test]
    fn miss_by_a_hair() {
        let (r, len, dist) = (0.1f32, 2.0f32, 5.0f32);
        for (base, axis) in frames() {
            let (p0, p1) = (pt(base, r), pt(base + axis * len, r));
            let side = perp(axis);
            let dir = axis.cross(side);
            let centre = base + axis * (0.5 * len) - dir * dist;
            for (name, test) in TESTS {
                assert!(test(centre + side * (r * (1.0 + 1e-3)), dir, 0.0, INF, p0, p1).is_none(), "{name}");
                let h = test(centre + side * (r * (1.0 - 1e-3)), dir, 0.0, INF, p0, p1).expect(name);
                assert_finite(&h);
                // Chord half-length sqrt(r^2 - delta^2) with delta = r (1 - 1e-3).
                let half = r * (1.0 - (1.0 - 1e-3f32).powi(2)).sqrt();
                assert!(close(h.t, dist - half, 1e-5), "{name}: {h:?} vs {}", dist - half);
            }
        }
    }

    #[test]
    fn grazing_hit_is_finite_and_on_the_surface() {
        let (r, len, dist) = (0.1f32, 2.0f32, 5.0f32);
        for (base, axis) in frames() {
            let (p0, p1) = (pt(base, r), pt(base + axis * len, r));
            let side = perp(axis);
            let dir = axis.cross(side);
            let o = base + axis * (0.3 * len) - dir * dist + side * (r * (1.0 - 1e-4));
            let half_f64 = r as f64 * (1.0 - (1.0 - 1e-4f64).powi(2)).sqrt();
            for (name, test) in TESTS {
                let h = test(o, dir, 0.0, INF, p0, p1).expect(name);
                assert_finite(&h);
                // Near tangency t is ill-conditioned: dt/d(delta) = delta / half ~ 70.
                assert!((h.t as f64 - (dist as f64 - half_f64)).abs() < 1e-4, "{name}: {h:?}");
                assert!(close(h.s, 0.3, 1e-5), "{name}: {h:?}");
                // Normal nearly along `side`, and perpendicular to the axis (constant radius).
                assert!(h.normal.dot(side) > 0.999 && h.normal.dot(axis).abs() < 1e-5, "{name}: {h:?}");
                let x = o.as_dvec3() + dir.as_dvec3() * h.t as f64;
                assert!(cone_distance(x, p0, p1).abs() < 1e-5, "{name}: {}", cone_distance(x, p0, p1));
            }
        }
    }

    #[test]
    fn open_ends_and_rays_along_the_axis() {
        let (r, len, dist) = (0.1f32, 2.0f32, 5.0f32);
        for (base, axis) in frames() {
            let (p0, p1) = (pt(base, r), pt(base + axis * len, r));
            let dir = -perp(axis);
            let at = |s: f32| base + axis * (len * s) - dir * dist;
            for (name, test) in TESTS {
                assert!(test(at(-0.01), dir, 0.0, INF, p0, p1).is_none(), "{name} s<0");
                assert!(test(at(1.01), dir, 0.0, INF, p0, p1).is_none(), "{name} s>1");
                let h = test(at(0.999), dir, 0.0, INF, p0, p1).expect(name);
                assert!(close(h.s, 0.999, 2e-6) && close(h.t, dist - r, 2e-6), "{name}: {h:?}");
                let h = test(at(0.0005), dir, 0.0, INF, p0, p1).expect(name);
                assert!(close(h.s, 0.0005, 2e-6), "{name}: {h:?}");
                // Along the axis, on it and inside the tube off it, from either end: the side
                // is never met and the ends are open.
                let off = perp(axis) * (0.5 * r);
                for o in [base - axis, base - axis + off, base + axis * (len + 1.0) + off] {
                    for d in [axis, -axis] {
                        assert!(test(o, d, -INF, INF, p0, p1).is_none(), "{name} along axis {o} {d}");
                    }
                }
            }
        }
    }

    #[test]
    fn back_wall_through_the_open_end() {
        // Tube along z over [0, 1], radius 0.1. The ray enters the infinite cylinder at
        // x = -0.1 above the top (s = 1.2: no cap there), leaves at x = 0.1 with s = 0.7.
        let (p0, p1) = ([0.0, 0.0, 0.0, 0.1], [0.0, 0.0, 1.0, 0.1]);
        let raw = Vec3::new(0.4, 0.0, -1.0);
        let (o, dir) = (Vec3::new(-0.3, 0.0, 1.7), raw.normalize());
        for (name, test) in TESTS {
            let h = test(o, dir, 0.0, INF, p0, p1).expect(name);
            assert!(close(h.t, raw.length(), 2e-6) && close(h.s, 0.7, 2e-6), "{name}: {h:?}");
            // Outward (away from the axis) even though the ray sees the inside.
            assert!(h.normal.abs_diff_eq(Vec3::X, 1e-5), "{name}: {h:?}");
        }
    }

    #[test]
    fn degenerate_segments_never_hit_and_never_nan() {
        let mut rng = Lcg(7);
        let p = Vec3::new(0.1, 0.2, 0.3);
        let cases: [([f32; 4], [f32; 4]); 5] = [
            (pt(p, 0.1), pt(p, 0.1)),             // zero length
            (pt(p, 0.0), pt(p, 0.0)),             // zero length, zero radius
            (pt(p, 0.0), pt(p + Vec3::Z, 0.0)),   // zero radius
            (pt(p, -0.1), pt(p + Vec3::Z, -0.1)), // negative radius
            (pt(p, 0.1), pt(p + Vec3::Z, -0.1)),  // one negative end
        ];
        for (p0, p1) in cases {
            for _ in 0..2000 {
                // Rays through the (would-be) segment from all directions.
                let d = rng.unit();
                let o = p + Vec3::Z * rng.f() + rng.unit() * (0.1 * rng.f()) - d * 3.0;
                for (name, test) in TESTS {
                    assert!(test(o, d, -INF, INF, p0, p1).is_none(), "{name} {p0:?} {p1:?}");
                }
            }
        }
    }

    #[test]
    fn tapered_tip_hits_but_not_at_its_apex() {
        let (p0, p1) = ([0.0, 0.0, 0.0, 0.1], [0.0, 0.0, 1.0, 0.0]);
        // Perpendicular at s = 0.5: radius 0.05.
        let h = intersect_cone(Vec3::new(3.0, 0.0, 0.5), -Vec3::X, 0.0, INF, p0, p1).unwrap();
        assert!(close(h.t, 3.0 - 0.05, 1e-6) && close(h.s, 0.5, 1e-6), "{h:?}");
        let h = intersect_cylinder(Vec3::new(3.0, 0.0, 0.5), -Vec3::X, 0.0, INF, p0, p1).unwrap();
        assert!(close(h.t, 3.0 - 0.05, 1e-6), "{h:?}");
        for (name, test) in TESTS {
            // Straight down onto the apex along the axis.
            assert!(test(Vec3::new(0.0, 0.0, 2.0), -Vec3::Z, 0.0, INF, p0, p1).is_none(), "{name}");
        }
    }

    #[test]
    fn varying_radius() {
        // r0 = 0.1, r1 = 0.3 over length 2: slope m = dr / L = 0.1.
        let (r0, r1, len, dist) = (0.1f32, 0.3f32, 2.0f32, 5.0f32);
        let m = (r1 - r0) / len;
        for (base, axis) in frames() {
            let (p0, p1) = (pt(base, r0), pt(base + axis * len, r1));
            let side = perp(axis);
            for s0 in [0.25f32, 0.75] {
                let rs = r0 + (r1 - r0) * s0;
                // A ray perpendicular to the axis keeps its axial position, so it meets the
                // cone exactly where the radius is r(s0): t = dist - r(s0), s = s0. The cone's
                // outward normal tilts from the radial direction -dir towards -axis by the
                // slant angle: n = (-dir - m axis) cos(slant), cos(slant) = 1 / sqrt(1 + m^2).
                let dir = -side;
                let o = base + axis * (len * s0) - dir * dist;
                let h = intersect_cone(o, dir, 0.0, INF, p0, p1).unwrap();
                assert_finite(&h);
                assert!(close(h.t, dist - rs, 4e-6) && close(h.s, s0, 2e-6), "cone s0={s0}: {h:?}");
                let n = (-dir - axis * m) / (1.0 + m * m).sqrt();
                assert!(h.normal.abs_diff_eq(n, 1e-5), "cone normal {h:?} vs {n}");
                // The faked radius is the one at the closest approach s* = s0: the same t,
                // but the normal stays perpendicular to the axis.
                let h = intersect_cylinder(o, dir, 0.0, INF, p0, p1).unwrap();
                assert!(close(h.t, dist - rs, 1e-5) && close(h.s, s0, 2e-6), "cylinder s0={s0}: {h:?}");
                assert!(h.normal.abs_diff_eq(-dir, 1e-5), "cylinder normal {h:?}");

                // A ray along the cone's inward normal, aimed at the surface point at s0 from
                // `dist` away, meets it at t = dist, s = s0, where its normal is -dir.
                let n_side = (side - axis * m) / (1.0 + m * m).sqrt();
                let (o, dir) = (base + axis * (len * s0) + side * rs + n_side * dist, -n_side);
                let h = intersect_cone(o, dir, 0.0, INF, p0, p1).unwrap();
                assert!(close(h.t, dist, 1e-5) && close(h.s, s0, 1e-5), "cone oblique s0={s0}: {h:?}");
                assert!(h.normal.abs_diff_eq(-dir, 1e-5), "cone oblique normal {h:?}");
                // The cylinder takes its radius where this tilted ray crosses the axis line, at
                // axial position s0 L + m rs: rho = rs (1 + m^2). Closing in radially at
                // 1 / sqrt(1 + m^2) per unit length, the ray meets that cylinder at
                // t = dist - m^2 rs sqrt(1 + m^2), axial position s0 L - m^3 rs.
                let h = intersect_cylinder(o, dir, 0.0, INF, p0, p1).unwrap();
                let t_cyl = dist - m * m * rs * (1.0 + m * m).sqrt();
                assert!(close(h.t, t_cyl, 1e-5), "cylinder oblique s0={s0}: {h:?} vs t {t_cyl}");
                assert!(close(h.s, s0 - m * m * m * rs / len, 1e-5), "cylinder oblique s0={s0}: {h:?}");
                assert!(h.normal.abs_diff_eq(side, 1e-5), "cylinder oblique normal {h:?}");
            }
        }
    }

    #[test]
    fn respects_tmin_and_tmax() {
        // Through the axis of a tube of radius 0.1 from 5 away: roots at 4.9 and 5.1.
        let (p0, p1) = ([0.0, 0.0, 0.0, 0.1], [0.0, 0.0, 1.0, 0.1]);
        let (o, d) = (Vec3::new(5.0, 0.0, 0.5), -Vec3::X);
        for (name, test) in TESTS {
            assert!(close(test(o, d, 0.0, INF, p0, p1).unwrap().t, 4.9, 1e-6), "{name}");
            assert!(test(o, d, 0.0, 4.89, p0, p1).is_none(), "{name} tmax before the front");
            // Front wall excluded by tmin: the back wall (seen from inside) is next, normal
            // still outward, now along the ray.
            let h = test(o, d, 4.95, INF, p0, p1).expect(name);
            assert!(close(h.t, 5.1, 1e-6) && h.normal.abs_diff_eq(-Vec3::X, 1e-6), "{name}: {h:?}");
            assert!(test(o, d, 4.95, 5.09, p0, p1).is_none(), "{name} both excluded");
            assert!(test(o, d, 5.11, INF, p0, p1).is_none(), "{name} tmin after the back");
            // The interval is open.
            let t_front = test(o, d, 0.0, INF, p0, p1).unwrap().t;
            assert!(test(o, d, 0.0, t_front, p0, p1).is_none(), "{name} tmax is exclusive");
            assert!(test(o, -d, 0.0, INF, p0, p1).is_none(), "{name} behind the origin");
        }
    }

    #[test]
    fn cylinder_and_cone_agree_on_thin_segments() {
        let mut rng = Lcg(0x5eed);
        let n = 20_000;
        let (mut cone_hits, mut hit_miss, mut t_off, mut unexplained) = (0, 0, 0, 0);
        let mut worst_dt_over_r = 0.0f32;
        for _ in 0..n {
            let p0 = Vec3::new(rng.range(-1.0, 1.0), rng.range(-1.0, 1.0), rng.range(-1.0, 1.0));
            let axis = rng.unit();
            let len = rng.range(0.5, 2.0);
            // radius / length below 0.05, with a hair-like taper of up to 25 % per segment.
            let r0 = len * rng.range(0.002, 0.04);
            let r1 = r0 * rng.range(0.8, 1.25);
            let (rmax, dr) = (r0.max(r1), (r1 - r0).abs());
            let (a, b) = (pt(p0, r0), pt(p0 + axis * len, r1));
            // Aim at a point around the segment, from a random direction, 5 units away.
            let d = rng.unit();
            let target = p0 + axis * (len * rng.range(-0.05, 1.05)) + rng.unit() * (1.5 * rmax * rng.f());
            let o = target - d * 5.0;
            let hc = intersect_cylinder(o, d, 0.0, INF, a, b);
            let hk = intersect_cone(o, d, 0.0, INF, a, b);
            cone_hits += hk.is_some() as usize;

            // Where the two may legitimately differ. At a hit at s the faked radius is off the
            // cone's by err = |dr| |clamp(s*) - s|. A radial error err moves a hit along the ray
            // by about err / |dir.n| and along the axis by err |cos theta| / |dir.n| (theta the
            // angle between ray and axis). So a disagreement must be (1) a hit/miss one in the
            // silhouette band, where the ray line passes the axis line within |dr| of the
            // radius at s*; (2) a t difference on the same wall of at most about err / |dir.n|
            // (large only for grazing or near-parallel rays); or (3) a hit on different walls,
            // or a hit/miss one, where a hit lies within that axial shift of an open end.
            // Margins of 2 on all bands.
            let (dd, ax) = (d.as_dvec3(), (axis * len).as_dvec3());
            let w = (o - p0).as_dvec3();
            let s_star = closest_params(w, dd, ax).0.clamp(0.0, 1.0);
            let dist_line = w.dot(dd.cross(ax)).abs() / dd.cross(ax).length();
            let silhouette = (dist_line - (r0 as f64 + (r1 - r0) as f64 * s_star)).abs() <= 2.0 * dr as f64;
            let cos = d.dot(axis).abs() as f64;
            let near_end = |h: &SegmentHit| {
                let shift = 2.0 * dr as f64 * cos / (d.dot(h.normal).abs() as f64 * len as f64);
                (h.s as f64).min(1.0 - h.s as f64) <= shift + 1e-3
            };
            match (hc, hk) {
                (Some(c), Some(k)) => {
                    let dt = (c.t - k.t).abs();
                    worst_dt_over_r = worst_dt_over_r.max(dt / rmax);
                    if dt > 0.5 * rmax {
                        t_off += 1;
                        let same_wall = (d.dot(c.normal) < 0.0) == (d.dot(k.normal) < 0.0);
                        let err = dr as f64 * (s_star - k.s as f64).abs();
                        let g = d.dot(c.normal).abs().min(d.dot(k.normal).abs()) as f64;
                        let explained = if same_wall {
                            dt as f64 <= 2.0 * err / g + 0.01 * rmax as f64 || silhouette
                        } else {
                            near_end(&c) || near_end(&k)
                        };
                        unexplained += !explained as usize;
                    }
                }
                (None, None) => {}
                (Some(h), None) | (None, Some(h)) => {
                    hit_miss += 1;
                    unexplained += !(silhouette || near_end(&h)) as usize;
                }
            }
        }
        let frac = (hit_miss + t_off) as f64 / n as f64;
        let msg = format!(
            "{n} rays, {cone_hits} cone hits: hit/miss disagreements {hit_miss}, both hit but t differs by \
             more than r/2 {t_off}: disagreement fraction {:.3} %, {unexplained} not explained by the faked radius \
             (worst |dt| / r {worst_dt_over_r:.2})",
            100.0 * frac
        );
        eprintln!("{msg}");
        assert!(cone_hits > n / 3, "{msg}");
        assert!(frac < 0.01, "{msg}");
        assert_eq!(unexplained, 0, "{msg}");
    }

    /// Parameters (s along `ax` from the ray's origin frame, u along `d`) of the closest points
    /// of the lines w + u d and s ax.
    fn closest_params(w: DVec3, d: DVec3, ax: DVec3) -> (f64, f64) {
        let (dd, da, aa, wd, wa) = (d.dot(d), d.dot(ax), ax.dot(ax), w.dot(d), w.dot(ax));
        let den = dd * aa - da * da;
        if den <= 0.0 {
            return (0.0, 0.0);
        }
        ((wa * dd - wd * da) / den, (wa * da - wd * aa) / den)
    }

    #[test]
    fn far_ray_origin_keeps_hair_precision() {
        let mut rng = Lcg(42);
        let r = 1e-4f32;
        let base = Vec3::new(0.31, -0.17, 0.05);
        let axis = Vec3::new(0.4, 0.7, -0.2).normalize() * 0.01; // radius / length = 0.01
        let (p0, p1) = (pt(base, r), pt(base + axis, r));
        let (mut worst_t, mut worst_rebuilt, mut worst_ray_point, mut hits) = (0f64, 0f64, 0f64, 0);
        for _ in 0..500 {
            let target = base + axis * rng.range(0.05, 0.95) + perp(axis) * (r * rng.range(-0.9, 0.9));
            let o = rng.unit() * 1000.0;
            let d = (target - o).normalize();
            let Some((t_ref, s_ref)) = reference_cone(o, d, p0, p1) else { continue };
            let x_ref = o.as_dvec3() + d.as_dvec3() * t_ref;
            for (name, test) in TESTS {
                // Constant radius: the faked and the exact surface coincide.
                let h = test(o, d, 0.0, INF, p0, p1).unwrap_or_else(|| panic!("{name}: missed, ref t {t_ref}"));
                assert_finite(&h);
                hits += 1;
                let dt = (h.t as f64 - t_ref).abs();
                // One radius width is 2e-4; t itself is only stored to half an ulp of 1e3 (3e-5).
                assert!(dt < 1e-4, "{name}: t {} vs {t_ref}", h.t);
                worst_t = worst_t.max(dt);
                // The hit rebuilt on the segment from s and the normal lies on the exact ray.
                let rebuilt = p0_vec(p0).as_dvec3() + axis.as_dvec3() * h.s as f64 + h.normal.as_dvec3() * r as f64;
                let e = (rebuilt - x_ref).length();
                assert!(e < 1e-5, "{name}: rebuilt point off by {e}");
                assert!((h.s as f64 - s_ref).abs() * 0.01 < 1e-5, "{name}: s {} vs {s_ref}", h.s);
                worst_rebuilt = worst_rebuilt.max(e);
                // origin + t dir is off the surface by at most the rounding of t to f32.
                let x = o.as_dvec3() + d.as_dvec3() * h.t as f64;
                let off = cone_distance(x, p0, p1).abs();
                let ulp = (h.t.to_bits() + 1) as f64;
                let half_ulp = (f32::from_bits(ulp as u32) - h.t) as f64 * 0.5;
                assert!(off < 1e-5 + half_ulp, "{name}: ray point off the surface by {off}");
                worst_ray_point = worst_ray_point.max(off);
            }
        }
        eprintln!("far origin: {hits} hits, worst |t - t_ref| {worst_t:.2e}, rebuilt point {worst_rebuilt:.2e}, origin + t dir off surface {worst_ray_point:.2e}");
        assert!(hits > 800);
    }

    #[test]
    fn cheap_bound_culls_only_what_the_exact_test_culls() {
        // Rays aimed within 0.3 % of the larger radius (just inside and just outside it) from
        // near and far, at scales from 1e-3 to 1e3: a lane the cheap bound drops must also be
        // dropped by the exact test. Rays passing at three radii from up to the segment's
        // scale away must all be dropped by the bound.
        let mut rng = Lcg(7);
        let (mut dropped, mut kept_far) = (0, 0);
        for i in 0..40_000 {
            let clear = i % 2 == 1;
            let scale = 10f32.powf(rng.range(-3.0, 3.0));
            let base = rng.unit() * scale * rng.range(0.0, 2.0);
            let axis = rng.unit() * scale * 0.05;
            let r = scale * 0.002 * rng.range(0.1, 1.0);
            let (p0, p1) = (pt(base, r), pt(base + axis, r * rng.range(0.2, 1.0)));
            let (miss, far) = if clear {
                (rng.range(3.0, 4.0), rng.range(-3.0, 0.0))
            } else {
                (rng.range(0.998, 1.003), rng.range(-1.0, 4.0))
            };
            let target = base + axis * rng.range(-0.2, 1.2) + perp(axis) * (r * miss);
            // A clear ray runs perpendicular to the axis and to its offset, so the lines pass
            // three radii apart; a grazing one comes from any direction.
            let from = if clear { axis.cross(perp(axis)).normalize() } else { rng.unit() };
            let o = target + from * scale * 10f32.powf(far);
            let d = (target - o).normalize();
            let k = Candidates::new(o, d, lane0(p0), lane0(p1));
            let cheap = k.near().to_bitmask() & 1 != 0;
            let exact = Local4::from_candidates(o, d, Candidates { far: f32x4::ZERO, ..k }).1.to_bitmask() & 1 != 0;
            assert!(cheap || !exact, "the bound culled a lane the exact test keeps: o {o:?} d {d:?} {p0:?} {p1:?}");
            assert!(!(clear && cheap), "a ray three radii away passed the bound: o {o:?} d {d:?} {p0:?} {p1:?}");
            dropped += usize::from(!cheap && !clear);
            kept_far += usize::from(cheap && !exact);
        }
        eprintln!("grazing rays: the bound dropped {dropped}, kept {kept_far} that the exact test dropped");
    }

    #[test]
    fn near8_gives_the_bits_of_the_four_wide_bound() {
        // Leaves of one to eight segments, some degenerate (zero length, zero or NaN radius)
        // and some far, against rays from near and far, radii widened by a random factor
        // half of the time: near8's one 8-wide pass (AVX2 on this machine) must keep exactly
        // the lanes `Candidates` keeps on the widened segments, four at a time; so must
        // near8_packet for each ray of a packet.
        let mut rng = Lcg(11);
        let mut kept = 0;
        for _ in 0..20_000 {
            let scale = 10f32.powf(rng.range(-2.0, 2.0));
            let count = 1 + (rng.f() * 8.0) as usize % 8;
            let points: Vec<[f32; 4]> = (0..2 * count)
                .map(|_| {
                    let r = match (rng.f() * 20.0) as u32 {
                        0 => 0.0,
                        1 => f32::NAN,
                        _ => scale * 0.01 * rng.range(0.1, 1.0),
                    };
                    pt(rng.unit() * scale * rng.range(0.0, 0.2), r)
                })
                .collect();
            let firsts: Vec<u32> = (0..count as u32).map(|i| 2 * i).collect();
            let target = p0_vec(points[0]) + rng.unit() * scale * 0.02;
            let o = target + rng.unit() * scale * 10f32.powf(rng.range(-1.0, 2.0));
            let d = (target - o).normalize();
            let widen = if rng.f() < 0.5 { 1.0 } else { 10f32.powf(rng.range(0.0, 1.5)) };
            let widened = |[x, y, z, r]: [f32; 4]| f32x4::new([x, y, z, r * widen]);
            let mut expected = 0;
            for (half, group) in firsts.chunks(4).enumerate() {
                let (mut p0, mut p1) = ([f32x4::ZERO; 4], [f32x4::ZERO; 4]);
                for (lane, &f) in group.iter().enumerate() {
                    (p0[lane], p1[lane]) = (widened(points[f as usize]), widened(points[f as usize + 1]));
                }
                expected |= (Candidates::new(o, d, p0, p1).near().to_bitmask() & 0xf) << (4 * half);
            }
            assert_eq!(near8(o, d, &points, &firsts, widen), expected, "o {o:?} d {d:?} {points:?} x{widen}");
            // As the third ray of a packet (the others elsewhere), with the leaf loaded once.
            let rays = [Ray::new(o, d); 4];
            let packet = near8_packet(&rays, 0b1100, &points, &firsts, widen);
            assert_eq!((packet[0], packet[2], packet[3]), (0, expected, expected));
            kept += expected.count_ones();
        }
        assert!(kept > 1000, "too few segments near the rays to test anything: {kept}");
    }

    fn p0_vec(p: [f32; 4]) -> Vec3 {
        Vec3::new(p[0], p[1], p[2])
    }

    #[test]
    fn cone_hits_lie_on_the_surface_inside_bounds() {
        let mut rng = Lcg(99);
        let mut hits = 0;
        for _ in 0..5000 {
            let p0 = Vec3::new(rng.range(-1.0, 1.0), rng.range(-1.0, 1.0), rng.range(-1.0, 1.0));
            let axis = rng.unit() * rng.range(0.2, 2.0);
            let (a, b) = (pt(p0, rng.range(0.0, 0.2)), pt(p0 + axis, rng.range(0.01, 0.2)));
            let d = rng.unit();
            let o = p0 + axis * rng.f() + rng.unit() * 0.2 - d * rng.range(0.0, 4.0);
            let Some(h) = intersect_cone(o, d, 0.0, INF, a, b) else { continue };
            hits += 1;
            assert_finite(&h);
            let x = o.as_dvec3() + d.as_dvec3() * h.t as f64;
            assert!(cone_distance(x, a, b).abs() < 1e-5, "{h:?} off by {}", cone_distance(x, a, b));
            let (lo, hi) = bounds(a, b);
            assert!(
                x.cmpge(lo.as_dvec3() - 1e-5).all() && x.cmple(hi.as_dvec3() + 1e-5).all(),
                "{x} outside {lo} {hi}"
            );
            // Outward: away from the axis.
            let rel = x - p0.as_dvec3();
            let radial = rel - axis.as_dvec3() * (rel.dot(axis.as_dvec3()) / axis.as_dvec3().length_squared());
            assert!(radial.dot(h.normal.as_dvec3()) > 0.0, "{h:?}");
            let r_ref = reference_cone(o, d, a, b).unwrap();
            assert!((h.t as f64 - r_ref.0).abs() < 1e-5, "{h:?} vs {r_ref:?}");
        }
        assert!(hits > 1000, "{hits}");
    }

    #[test]
    fn bounds_hold_both_end_spheres() {
        let (lo, hi) = bounds([0.0, 1.0, 2.0, 0.5], [3.0, -1.0, 2.0, 0.25]);
        assert_eq!(lo, Vec3::new(-0.5, -1.25, 1.5));
        assert_eq!(hi, Vec3::new(3.25, 1.5, 2.5));
    }

    #[test]
    fn extreme_inputs_give_finite_results_or_none() {
        let mut rng = Lcg(1234);
        let scale = |rng: &mut Lcg| 10f32.powf(rng.range(-30.0, 30.0));
        for _ in 0..20_000 {
            let sp = scale(&mut rng);
            let p0 = rng.unit() * sp * rng.f();
            let p1 = p0 + rng.unit() * scale(&mut rng);
            let (a, b) = (pt(p0, scale(&mut rng) * rng.f()), pt(p1, scale(&mut rng) * rng.f()));
            let d = rng.unit();
            let o = p0 + rng.unit() * scale(&mut rng) - d * scale(&mut rng);
            for (name, test) in TESTS {
                if let Some(h) = test(o, d, 0.0, INF, a, b) {
                    assert_finite(&h);
                    assert!(h.t > 0.0 && (0.0..=1.0).contains(&h.s), "{name}: {h:?}");
                }
            }
        }
    }
}
