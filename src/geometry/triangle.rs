//! Ray / triangle intersection.

use glam::Vec3;

/// Where a ray meets a triangle.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TriangleHit {
    /// Distance along the ray.
    pub t: f32,
    /// Barycentric weight of the second corner.
    pub b1: f32,
    /// Barycentric weight of the third corner.
    pub b2: f32,
}

/// Moller and Trumbore 1997, "Fast, Minimum Storage Ray/Triangle Intersection": solves for
/// (t, b1, b2) by Cramer's rule without precomputing the plane. Both faces are hit.
#[inline]
pub fn intersect_triangle(origin: Vec3, dir: Vec3, tmin: f32, tmax: f32, [a, b, c]: [Vec3; 3]) -> Option<TriangleHit> {
    let e1 = b - a;
    let e2 = c - a;
    let p = dir.cross(e2);
    let det = e1.dot(p);
    // A ray in the triangle's plane (or a degenerate triangle) has det = 0.
    if det == 0.0 || !det.is_finite() {
        return None;
    }
    let inv = 1.0 / det;
    let s = origin - a;
    let b1 = s.dot(p) * inv;
    if !(0.0..=1.0).contains(&b1) {
        return None;
    }
    let q = s.cross(e1);
    let b2 = dir.dot(q) * inv;
    if b2 < 0.0 || b1 + b2 > 1.0 {
        return None;
    }
    let t = e2.dot(q) * inv;
    (t > tmin && t < tmax).then_some(TriangleHit { t, b1, b2 })
}

#[cfg(test)]
mod tests {
    use super::*;

    const TRI: [Vec3; 3] = [Vec3::new(0.0, 0.0, 0.0), Vec3::new(1.0, 0.0, 0.0), Vec3::new(0.0, 1.0, 0.0)];

    #[test]
    fn hits_inside_with_exact_barycentrics() {
        let h = intersect_triangle(Vec3::new(0.25, 0.5, 2.0), -Vec3::Z, 0.0, f32::INFINITY, TRI).unwrap();
        assert!((h.t - 2.0).abs() < 1e-6);
        assert!((h.b1 - 0.25).abs() < 1e-6 && (h.b2 - 0.5).abs() < 1e-6);
    }

    #[test]
    fn misses_outside_parallel_and_beyond_tmax() {
        assert!(intersect_triangle(Vec3::new(0.6, 0.6, 1.0), -Vec3::Z, 0.0, f32::INFINITY, TRI).is_none());
        assert!(intersect_triangle(Vec3::new(0.1, 0.1, 0.0), Vec3::X, 0.0, f32::INFINITY, TRI).is_none());
        assert!(intersect_triangle(Vec3::new(0.1, 0.1, 2.0), -Vec3::Z, 0.0, 1.5, TRI).is_none());
        let degenerate = [Vec3::ZERO, Vec3::X, Vec3::X * 2.0];
        assert!(intersect_triangle(Vec3::new(0.5, 0.0, 1.0), -Vec3::Z, 0.0, f32::INFINITY, degenerate).is_none());
    }
}
