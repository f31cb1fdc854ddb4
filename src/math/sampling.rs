//! Warps from the unit square to directions and points (Pharr et al., PBR 4th ed., ch. A.5).

use glam::Vec3;
use std::f32::consts::PI;

/// Uniform direction on the unit sphere; pdf = 1 / (4 pi).
pub fn uniform_sphere(u: f32, v: f32) -> Vec3 {
    let z = 1.0 - 2.0 * u;
    let r = (1.0 - z * z).max(0.0).sqrt();
    let phi = 2.0 * PI * v;
    Vec3::new(r * phi.cos(), r * phi.sin(), z)
}

/// Cosine-weighted direction on the hemisphere around +z; pdf = cos(theta) / pi.
pub fn cosine_hemisphere(u: f32, v: f32) -> Vec3 {
    let (x, y) = concentric_disk(u, v);
    Vec3::new(x, y, (1.0 - x * x - y * y).max(0.0).sqrt())
}

/// Uniform point on the unit disk by Shirley and Chiu's concentric mapping.
pub fn concentric_disk(u: f32, v: f32) -> (f32, f32) {
    let (a, b) = (2.0 * u - 1.0, 2.0 * v - 1.0);
    if a == 0.0 && b == 0.0 {
        return (0.0, 0.0);
    }
    let (r, theta) = if a.abs() > b.abs() { (a, PI / 4.0 * (b / a)) } else { (b, PI / 2.0 - PI / 4.0 * (a / b)) };
    (r * theta.cos(), r * theta.sin())
}

/// Uniform direction in the cone of half-angle acos(`cos_max`) around +z;
/// pdf = 1 / (2 pi (1 - cos_max)).
pub fn uniform_cone(u: f32, v: f32, cos_max: f32) -> Vec3 {
    let cos_t = 1.0 - u * (1.0 - cos_max);
    let sin_t = (1.0 - cos_t * cos_t).max(0.0).sqrt();
    let phi = 2.0 * PI * v;
    Vec3::new(sin_t * phi.cos(), sin_t * phi.sin(), cos_t)
}

/// Uniform barycentric coordinates (b1, b2) in a triangle by the fold-over trick of
/// thesis section 2.1.5: a point in the unit square, reflected into the lower triangle.
pub fn triangle_fold(u: f32, v: f32) -> (f32, f32) {
    if u + v > 1.0 {
        (1.0 - u, 1.0 - v)
    } else {
        (u, v)
    }
}

/// Veach's power heuristic (beta = 2) for one sample of each of two strategies: the weight
/// of a sample drawn with density `pdf` when the other strategy has density `other` there
/// (Veach and Guibas 1995; PBR 4th ed. section 2.2.3). A delta (infinite) `pdf` weighs 1.
pub fn power_heuristic(pdf: f32, other: f32) -> f32 {
    let (a, b) = (pdf * pdf, other * other);
    if a + b > 0.0 && (a + b).is_finite() {
        a / (a + b)
    } else if pdf.is_infinite() {
        1.0
    } else {
        0.0
    }
}
