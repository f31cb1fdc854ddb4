//! Surface reflection models: Lambert, Phong, mirror and dielectric.

use super::SpecularRay;
use crate::math::Color;
use glam::Vec3;
use std::f32::consts::PI;

/// Lambertian BRDF times the cosine: `albedo / pi * max(0, n.wi)`.
pub fn lambert(albedo: Color, n: Vec3, wi: Vec3) -> Color {
    albedo * (n.dot(wi).max(0.0) / PI)
}

/// Lambert plus the energy-normalised Phong lobe (Lafortune and Willems 1994, "Using the
/// modified Phong reflectance model for physically based rendering"):
/// `ks (n + 2) / (2 pi) cos^n(alpha)`, alpha between `wi` and the mirror direction of `wo`.
pub fn phong(kd: Color, ks: Color, exponent: f32, n: Vec3, wo: Vec3, wi: Vec3) -> Color {
    let cos_i = n.dot(wi);
    if cos_i <= 0.0 {
        return Color::ZERO;
    }
    let cos_a = reflect(wo, n).dot(wi).max(0.0);
    let lobe = (exponent + 2.0) / (2.0 * PI) * cos_a.powf(exponent);
    (kd / PI + ks * lobe) * cos_i
}

/// Mirror direction of `wo` (pointing away from the surface) about `n`.
pub fn reflect(wo: Vec3, n: Vec3) -> Vec3 {
    2.0 * wo.dot(n) * n - wo
}

/// Fresnel reflectance of a smooth dielectric for unpolarised light (PBR 4th ed. 9.3.5).
/// `cos_i` is measured on the incident side; `eta` = n_transmitted / n_incident.
pub fn fresnel_dielectric(cos_i: f32, eta: f32) -> f32 {
    let cos_i = cos_i.clamp(0.0, 1.0);
    let sin2_t = (1.0 - cos_i * cos_i) / (eta * eta);
    if sin2_t >= 1.0 {
        return 1.0;
    }
    let cos_t = (1.0 - sin2_t).sqrt();
    let r_par = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    let r_perp = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    0.5 * (r_par * r_par + r_perp * r_perp)
}

/// Reflection and refraction of a smooth dielectric of index `ior`; `n` faces `wo` and
/// `inside` tells that the ray arrives from within the medium.
pub fn dielectric(ior: f32, tint: Color, n: Vec3, inside: bool, wo: Vec3) -> [Option<SpecularRay>; 2] {
    let eta = if inside { 1.0 / ior } else { ior };
    let cos_i = wo.dot(n).max(0.0);
    let f = fresnel_dielectric(cos_i, eta);
    let reflected = SpecularRay { dir: reflect(wo, n), weight: Color::splat(f), transmitted: false };
    if f >= 1.0 {
        return [Some(reflected), None];
    }
    // Snell's law in vector form.
    let sin2_t = (1.0 - cos_i * cos_i) / (eta * eta);
    let cos_t = (1.0 - sin2_t).max(0.0).sqrt();
    let dir = (-wo / eta + n * (cos_i / eta - cos_t)).normalize();
    [Some(reflected), Some(SpecularRay { dir, weight: tint * (1.0 - f), transmitted: true })]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fresnel_at_normal_incidence_and_total_internal_reflection() {
        // ((n - 1) / (n + 1))^2 = 0.04 for n = 1.5.
        assert!((fresnel_dielectric(1.0, 1.5) - 0.04).abs() < 1e-6);
        // From glass to air beyond the critical angle (asin(1/1.5) ~ 41.8 deg).
        assert_eq!(fresnel_dielectric(50f32.to_radians().cos(), 1.0 / 1.5), 1.0);
    }

    #[test]
    fn refraction_obeys_snell() {
        let n = Vec3::Z;
        let theta_i = 30f32.to_radians();
        let wo = Vec3::new(theta_i.sin(), 0.0, theta_i.cos());
        let rays = dielectric(1.5, Color::ONE, n, false, wo);
        let t = rays[1].unwrap().dir;
        let sin_t = (t.x * t.x + t.y * t.y).sqrt();
        assert!((theta_i.sin() - 1.5 * sin_t).abs() < 1e-5);
        assert!(t.z < 0.0 && t.x < 0.0);
        assert!((rays[0].unwrap().weight.x + rays[1].unwrap().weight.x - 1.0).abs() < 1e-6);
    }

    #[test]
    fn lambert_white_furnace() {
        // Integrating the response over the hemisphere (uniform sampling) gives the albedo.
        let n = Vec3::Z;
        let mut sum = 0.0;
        let k = 256;
        for i in 0..k {
            for j in 0..k {
                let d = crate::math::sampling::uniform_sphere((i as f32 + 0.5) / k as f32, (j as f32 + 0.5) / k as f32);
                sum += lambert(Color::ONE, n, d).x * 4.0 * PI;
            }
        }
        let mean = sum / (k * k) as f32;
        assert!((mean - 1.0).abs() < 1e-3, "{mean}");
    }

    #[test]
    fn phong_lobe_does_not_create_energy() {
        let n = Vec3::Z;
        let wo = Vec3::new(0.3, 0.0, 0.954).normalize();
        let k = 256;
        let mut sum = 0.0;
        for i in 0..k {
            for j in 0..k {
                let d = crate::math::sampling::uniform_sphere((i as f32 + 0.5) / k as f32, (j as f32 + 0.5) / k as f32);
                sum += phong(Color::ZERO, Color::ONE, 20.0, n, wo, d).x * 4.0 * PI;
            }
        }
        let mean = sum / (k * k) as f32;
        assert!(mean <= 1.0 && mean > 0.8, "{mean}");
    }
}
