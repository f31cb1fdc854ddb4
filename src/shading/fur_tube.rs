//! Fur shading, thesis section 2.1.8, eq. 2.4 to 2.7: the fur variant of tube shading.
//! It differs from the hair model (eq. 2.1 to 2.3, [`super::tube`]) by the diffuse factor
//! `D = 1 - (T.H)^4` (eq. 2.6), which dims the diffuse term where the half vector runs
//! along the strand. Colours vary from root to tip as Maya Fur's base and tip attributes
//! say, and the description's Light Model picks the terms.

use super::tube::Tube;
use crate::math::Color;
use glam::Vec3;

/// Maya Fur's Light Model (`.lmd`): which shading terms a fur description uses.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum LightModel {
    /// 0: the ambient colours only.
    Ambient,
    /// 1: ambient and diffuse.
    AmbientDiffuse,
    /// 2 (Maya's default): ambient, diffuse and specular.
    #[default]
    AmbientDiffuseSpecular,
    /// 3: specular only.
    Specular,
}

impl LightModel {
    /// The model for Maya's enum value, if it is one.
    pub fn from_index(i: i64) -> Option<LightModel> {
        [LightModel::Ambient, LightModel::AmbientDiffuse, LightModel::AmbientDiffuseSpecular, LightModel::Specular]
            .get(usize::try_from(i).ok()?)
            .copied()
    }

    fn has_ambient(self) -> bool {
        self != LightModel::Specular
    }

    fn has_diffuse(self) -> bool {
        matches!(self, LightModel::AmbientDiffuse | LightModel::AmbientDiffuseSpecular)
    }

    fn has_specular(self) -> bool {
        matches!(self, LightModel::AmbientDiffuseSpecular | LightModel::Specular)
    }
}

/// Parameters of the fur model for one strand set. Values that vary per strand (mapped or
/// noisy attributes) hold one entry per strand; uniform ones hold a single entry.
#[derive(Clone, Debug, PartialEq)]
pub struct Fur {
    /// Which terms are used.
    pub light_model: LightModel,
    /// Base and tip diffuse colour, used when the strands carry no per-point colours.
    pub diffuse: [Color; 2],
    /// Base and tip ambient colour (`C_ambient` of eq. 2.7), per strand or shared.
    pub ambient: Vec<[Color; 2]>,
    /// Specular colour (`C_spec` of eq. 2.5), per strand or shared.
    pub specular: Vec<Color>,
    /// Specular sharpness (`specPower` of eq. 2.5), per strand or shared.
    pub specular_sharpness: Vec<f32>,
}

/// Entry `strand` of a per-strand array, or its only entry when it is shared.
#[inline]
fn per_strand<T: Copy>(values: &[T], strand: u32) -> T {
    if values.len() == 1 {
        values[0]
    } else {
        values[strand as usize]
    }
}

impl Fur {
    /// Response to unit light from `wi` seen from `wo` on strand `strand` at fraction
    /// `along` of its length (0 root, 1 tip), with unit tangent `t`. `color` is the
    /// strand's diffuse colour at the point when the geometry has one.
    ///
    /// Eq. 2.4: `H = norm(L - rayDir)`; eq. 2.5: `S = (1 - (T.H)^2)^specPower`; eq. 2.6:
    /// `D = 1 - (T.H)^4`; eq. 2.7: `D C_diffuse Shade(P, T) + S C_specular`. As for tube
    /// shading, `Shade(P, T)` is the Lambert term averaged over the normals around `T`,
    /// `sin(T, L)`, and both terms carry `1 / pi` (see [`Tube::response`], which computes
    /// them once the diffuse colour is scaled by `D`). Eq. 2.5 and 2.7 both multiply by the
    /// specular colour; it is applied once.
    pub fn response(&self, strand: u32, along: f32, color: Option<Color>, t: Vec3, wo: Vec3, wi: Vec3) -> Color {
        let lm = self.light_model;
        let diffuse = if lm.has_diffuse() {
            let cos_th = t.dot((wi + wo).normalize_or_zero());
            let d = 1.0 - cos_th.powi(4);
            d * color.unwrap_or_else(|| self.diffuse[0].lerp(self.diffuse[1], along))
        } else {
            Color::ZERO
        };
        let specular = if lm.has_specular() { per_strand(&self.specular, strand) } else { Color::ZERO };
        let tube = Tube {
            ambient: Color::ZERO,
            diffuse,
            specular,
            specular_power: per_strand(&self.specular_sharpness, strand),
        };
        tube.response(None, t, wo, wi)
    }

    /// The ambient colour at fraction `along` of strand `strand`, root to tip (zero when
    /// the light model has no ambient term).
    pub fn ambient_color(&self, strand: u32, along: f32) -> Color {
        if !self.light_model.has_ambient() {
            return Color::ZERO;
        }
        let [base, tip] = per_strand(&self.ambient, strand);
        base.lerp(tip, along)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f32::consts::PI;

    fn fur(light_model: LightModel) -> Fur {
        Fur {
            light_model,
            diffuse: [Color::ONE, Color::ONE],
            ambient: vec![[Color::new(0.2, 0.0, 0.0), Color::new(0.0, 0.0, 0.4)]],
            specular: vec![Color::ZERO],
            specular_sharpness: vec![10.0],
        }
    }

    #[test]
    fn diffuse_is_the_tube_term_times_one_minus_t_dot_h_to_the_fourth() {
        let f = fur(LightModel::AmbientDiffuse);
        let t = Vec3::X;
        let (wo, wi) = (Vec3::new(0.6, 0.8, 0.0), Vec3::new(0.8, 0.0, 0.6));
        let h = (wi + wo).normalize();
        let expected = (1.0 - t.dot(h).powi(4)) * (1.0 - t.dot(wi).powi(2)).sqrt() / PI;
        let got = f.response(0, 0.5, None, t, wo, wi);
        assert!((got - Color::splat(expected)).abs().max_element() < 1e-6, "{got} vs {expected}");
        // With H along T the diffuse term vanishes (D = 0), unlike tube shading.
        let along = Vec3::new(1.0, 1.0, 0.0).normalize();
        let w2 = Vec3::new(1.0, -1.0, 0.0).normalize();
        assert!(f.response(0, 0.5, None, t, along, w2).max_element() < 1e-6);
    }

    #[test]
    fn light_model_selects_terms_and_colours_run_root_to_tip() {
        let mut f = fur(LightModel::Specular);
        f.specular = vec![Color::ONE];
        let (wo, wi) = (Vec3::new(0.5, 0.0, 0.866), Vec3::new(-0.5, 0.0, 0.866));
        // H is normal to T: the specular peak, 1 / pi; no diffuse, no ambient.
        assert!((f.response(0, 0.0, None, Vec3::X, wo, wi) - Color::splat(1.0 / PI)).abs().max_element() < 1e-5);
        assert_eq!(f.ambient_color(0, 0.3), Color::ZERO);
        let f = fur(LightModel::Ambient);
        assert_eq!(f.response(0, 0.0, None, Vec3::X, wo, wi), Color::ZERO);
        let mid = f.ambient_color(0, 0.5);
        assert!((mid - Color::new(0.1, 0.0, 0.2)).abs().max_element() < 1e-6);
        // Per-strand arrays are indexed by strand.
        let mut f = fur(LightModel::AmbientDiffuseSpecular);
        f.ambient = vec![[Color::ZERO; 2], [Color::ONE; 2]];
        assert_eq!(f.ambient_color(1, 0.7), Color::ONE);
        assert_eq!(LightModel::from_index(2), Some(LightModel::AmbientDiffuseSpecular));
        assert_eq!(LightModel::from_index(4), None);
    }
}
