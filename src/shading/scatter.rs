//! Importance sampling of every material, for the path tracer and the final gather: a
//! direction drawn in proportion (roughly) to the material's response, its density, and
//! the weight `f |cos| / pdf` the path carries on.
//!
//! Surfaces draw cosine-weighted directions (Lambert exactly, Phong's diffuse part); hair
//! draws over the whole sphere around the fibre, never a hemisphere around a normal (the
//! thesis' final gather got this wrong for hair, section 3.4): the physical BSDF samples
//! its own lobes (Chiang et al. 2016 §4.3), the tube model samples the sphere uniformly.

use super::{Material, ShadingPoint};
use crate::math::rng::PixelSampler;
use crate::math::{frame, sampling, Color};
use glam::Vec3;
use std::f32::consts::PI;

/// A direction a path continues in.
#[derive(Clone, Copy, Debug)]
pub struct Scatter {
    /// Unit direction.
    pub dir: Vec3,
    /// `f |cos| / pdf`: the factor on the radiance brought back along `dir`.
    pub weight: Color,
    /// Solid-angle density of `dir`; infinite for specular (delta) directions.
    pub pdf: f32,
}

impl Scatter {
    /// True for a mirror or glass direction, which light sampling cannot find.
    pub fn is_specular(&self) -> bool {
        self.pdf == f32::INFINITY
    }
}

impl Material {
    /// Draws the direction a path continues in after arriving along `-wo`; `None` when
    /// the material scatters nothing there (always for an unlit surface). Uses up to four
    /// sampler dimensions.
    pub fn sample_scatter(&self, sp: &ShadingPoint, wo: Vec3, sampler: &mut PixelSampler) -> Option<Scatter> {
        match self {
            Material::Unlit { .. } | Material::UnlitTextured { .. } => None,
            Material::Mirror { .. } | Material::Glass { .. } => {
                let rays = self.specular(sp, wo);
                let lum = |c: Color| c.x + c.y + c.z;
                let total: f32 = rays.iter().flatten().map(|r| lum(r.weight)).sum();
                if total <= 0.0 {
                    return None;
                }
                // Pick reflection or refraction in proportion to its weight.
                let mut u = sampler.next_1d() * total;
                let mut chosen = None;
                for r in rays.iter().flatten() {
                    chosen = Some(r);
                    u -= lum(r.weight);
                    if u < 0.0 {
                        break;
                    }
                }
                let r = chosen?;
                Some(Scatter { dir: r.dir, weight: r.weight * (total / lum(r.weight)), pdf: f32::INFINITY })
            }
            _ => {
                let (dir, pdf) = match (self, sp.tangent) {
                    (Material::Physical(_), Some(_)) => self.sample_direction(sp, wo, sampler)?,
                    (_, Some(_)) => {
                        let (u, v) = sampler.next_2d();
                        (sampling::uniform_sphere(u, v), 1.0 / (4.0 * PI))
                    }
                    (_, None) => {
                        let (u, v) = sampler.next_2d();
                        let local = sampling::cosine_hemisphere(u, v);
                        let (b1, b2) = frame(sp.normal);
                        ((b1 * local.x + b2 * local.y + sp.normal * local.z).normalize(), local.z / PI)
                    }
                };
                if !(pdf > 0.0 && pdf.is_finite()) {
                    return None;
                }
                let weight = self.response(sp, wo, dir) / pdf;
                (weight.max_element() > 0.0 && weight.is_finite()).then_some(Scatter { dir, weight, pdf })
            }
        }
    }

    /// The density with which [`Material::sample_scatter`] picks `wi` (0 for specular
    /// materials, whose directions no other strategy finds, and for unlit ones, which
    /// draw none).
    pub fn scatter_pdf(&self, sp: &ShadingPoint, wo: Vec3, wi: Vec3) -> f32 {
        match (self, sp.tangent) {
            (
                Material::Mirror { .. }
                | Material::Glass { .. }
                | Material::Unlit { .. }
                | Material::UnlitTextured { .. },
                _,
            ) => 0.0,
            (Material::Physical(h), Some(t)) => h.pdf(sp.color, t, sp.normal, wo, wi),
            (_, Some(_)) => 1.0 / (4.0 * PI),
            (_, None) => sp.normal.dot(wi).max(0.0) / PI,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shading::hair_bsdf::{Absorption, HairParams, PhysicalHair};

    fn point(tangent: Option<Vec3>) -> ShadingPoint {
        ShadingPoint { p: Vec3::ZERO, normal: Vec3::Z, tangent, color: None, backface: false, strand: None, uv: None }
    }

    /// The mean of `weight` over many samples estimates the albedo (the integral of
    /// `f |cos|` over the sphere), and each sample's pdf is what `scatter_pdf` says.
    fn albedo(m: &Material, sp: &ShadingPoint, wo: Vec3) -> Color {
        let n = 20_000;
        let mut sum = Color::ZERO;
        for i in 0..n {
            let mut sampler = PixelSampler::new(1, 2, 3, i);
            if let Some(s) = m.sample_scatter(sp, wo, &mut sampler) {
                if !s.is_specular() {
                    let pdf = m.scatter_pdf(sp, wo, s.dir);
                    assert!((pdf - s.pdf).abs() <= 1e-3 * s.pdf, "{m:?}: {pdf} vs {}", s.pdf);
                }
                sum += s.weight;
            }
        }
        sum / n as f32
    }

    #[test]
    fn sampled_weights_integrate_to_the_albedo() {
        let wo = Vec3::new(0.3, 0.2, 0.9).normalize();
        let a = albedo(&Material::Diffuse { color: Color::splat(0.8) }, &point(None), wo);
        assert!((a.x - 0.8).abs() < 1e-3, "{a}");
        let white = PhysicalHair::new(HairParams { absorption: Absorption::Color(Color::ONE), ..Default::default() });
        let a = albedo(&Material::Physical(white.clone()), &point(Some(Vec3::X)), wo);
        assert!((a.x - 1.0).abs() < 0.02, "{a}");
        // The tube's uniform sampling agrees with its response integrated by quadrature.
        let tube = Material::Tube(crate::shading::tube::Tube {
            ambient: Color::ZERO,
            diffuse: Color::splat(0.5),
            specular: Color::splat(0.2),
            specular_power: 20.0,
        });
        let a = albedo(&tube, &point(Some(Vec3::X)), wo);
        let mut q = 0.0;
        let m = 400;
        for i in 0..m {
            for j in 0..m {
                let dir = sampling::uniform_sphere((i as f32 + 0.5) / m as f32, (j as f32 + 0.5) / m as f32);
                q += tube.response(&point(Some(Vec3::X)), wo, dir).x;
            }
        }
        let q = q * 4.0 * PI / (m * m) as f32;
        assert!((a.x - q).abs() < 0.02 * q, "{} vs {q}", a.x);
        // Glass keeps all energy: reflection and refraction weights sum to 1 on average.
        let a = albedo(&Material::Glass { ior: 1.5, color: Color::ONE }, &point(None), wo);
        assert!((a.x - 1.0).abs() < 1e-3, "{a}");
    }
}
