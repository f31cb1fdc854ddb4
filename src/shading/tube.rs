//! Tube shading for hair, thesis section 2.1.8 (eq. 2.1 to 2.3), a Kajiya-Kay style model
//! (Kajiya and Kay 1989) driven by the strand tangent instead of a surface normal, so the
//! shading is smooth along and uniform across a strand.

use crate::math::Color;
use glam::Vec3;
use std::f32::consts::PI;

/// Parameters of the tube model.
#[derive(Clone, Debug, PartialEq)]
pub struct Tube {
    /// Ambient colour, multiplied by the environment radiance (the `C_ambient` of eq. 2.3).
    pub ambient: Color,
    /// Diffuse colour (`C_diffuse`).
    pub diffuse: Color,
    /// Specular colour (`C_specular`).
    pub specular: Color,
    /// Specular power (`specPower` of eq. 2.2).
    pub specular_power: f32,
}

impl Default for Tube {
    /// A mid-grey strand (ambient as diffuse) with a soft white highlight.
    fn default() -> Self {
        Tube {
            ambient: Color::splat(0.5),
            diffuse: Color::splat(0.5),
            specular: Color::splat(0.3),
            specular_power: 40.0,
        }
    }
}

impl Tube {
    /// Response to unit light from `wi` seen from `wo`, on a strand with unit tangent `t`.
    ///
    /// - Diffuse: the thesis passes the tangent to Turtle's Lambert `Shade(P, T)`, which it
    ///   calls "not actually correct". We use what it approximates, the Lambert term averaged
    ///   over the disk of normals around the tangent (Kajiya and Kay): `C_d sin(T, L) / pi`.
    /// - Specular, eq. 2.1 and 2.2: `H = norm(L - rayDir)` (rayDir = `-wo`) and
    ///   `C_s (1 - (T.H)^2)^specPower / pi`. The `1 / pi` for both keeps the response in the
    ///   same units as a Lambertian surface, so hair and surfaces balance under one light.
    ///
    /// `color` replaces the diffuse colour (per-strand colours from a `.hair` file).
    pub fn response(&self, color: Option<Color>, t: Vec3, wo: Vec3, wi: Vec3) -> Color {
        let cos_tl = t.dot(wi);
        let sin_tl = (1.0 - cos_tl * cos_tl).max(0.0).sqrt();
        let h = (wi + wo).normalize_or_zero();
        let cos_th = t.dot(h);
        let spec = (1.0 - cos_th * cos_th).max(0.0).powf(self.specular_power);
        (color.unwrap_or(self.diffuse) * sin_tl + self.specular * spec) / PI
    }

    /// The ambient colour; follows the strand colour when the geometry has one, in the same
    /// proportion as the material's ambient to diffuse colours.
    pub fn ambient_color(&self, color: Option<Color>) -> Color {
        match color {
            Some(c) => c * (self.ambient / self.diffuse.max(Color::splat(1e-6))).min(Color::splat(1.0e3)),
            None => self.ambient,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tube() -> Tube {
        Tube { ambient: Color::ZERO, diffuse: Color::ONE, specular: Color::ONE, specular_power: 40.0 }
    }

    #[test]
    fn diffuse_term_is_sine_of_tangent_and_light() {
        let t = Tube { specular: Color::ZERO, ..tube() };
        let wi = Vec3::new(0.6, 0.8, 0.0);
        let r = t.response(None, Vec3::X, Vec3::Z, wi).x;
        assert!((r - 0.8 / PI).abs() < 1e-6);
        assert_eq!(t.response(None, Vec3::X, Vec3::Z, Vec3::X).x, 0.0);
    }

    #[test]
    fn specular_peaks_where_half_vector_is_normal_to_tangent() {
        let t = Tube { diffuse: Color::ZERO, ..tube() };
        // wo and wi mirror each other about the plane normal to T: H is perpendicular to T.
        let wo = Vec3::new(0.5, 0.0, 0.866);
        let wi = Vec3::new(-0.5, 0.0, 0.866);
        assert!((t.response(None, Vec3::X, wo, wi).x - 1.0 / PI).abs() < 1e-5);
        // Tilting the light along the tangent moves H off the normal plane: falls off fast.
        let wi2 = Vec3::new(0.2, 0.0, 0.98).normalize();
        assert!(t.response(None, Vec3::X, wo, wi2).x < 0.2 / PI);
    }

    #[test]
    fn strand_colour_replaces_diffuse() {
        let t = Tube { specular: Color::ZERO, ..tube() };
        let c = Color::new(0.5, 0.25, 0.0);
        let r = t.response(Some(c), Vec3::X, Vec3::Z, Vec3::Y);
        assert!((r - c / PI).abs().max_element() < 1e-6);
    }
}
