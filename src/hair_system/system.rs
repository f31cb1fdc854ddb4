//! [`HairSystem`]: the render attributes of Maya's `hairSystem` node that turn guide
//! curves into clumps of render hairs (thesis section 2.1.3; docs/maya-fur-hair.md
//! section 5). Names follow Maya's attribute names in snake case; the short name of each
//! (`.hpc`, `.cwd`, ...) is in its documentation, and defaults are the node defaults.

use super::ramp::{Ramp, RampValue};
use crate::math::Color;
use crate::shading::tube::Tube;
use glam::Vec3;

/// How the noise displacement varies between hairs (Maya's `noiseMethod`, `.nmt`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum NoiseMethod {
    /// Each hair wiggles on its own (0, the default).
    #[default]
    Random,
    /// A 3-D noise over the surface's U and V and along the hair: neighbouring hairs on the
    /// surface move together (1).
    SurfaceUv,
    /// A 3-D noise over the clump's cross-section and along the hair: hairs in a clump move
    /// together, clumps independently, whatever the surface's parameterisation (2).
    ClumpUv,
}

/// The hair-system attributes that shape, size and colour render hairs.
#[derive(Clone, Debug, PartialEq)]
pub struct HairSystem {
    /// `hairsPerClump` (`.hpc`, 10): render hairs around each guide.
    pub hairs_per_clump: u32,
    /// `subSegments` (`.ssg`, 0): extra points between guide points, on a smooth curve
    /// through them (uniform Catmull-Rom, a cubic Hermite spline).
    pub sub_segments: u32,
    /// `thinning` (`.thn`, 0): the fraction of hairs that are shorter; each such hair is cut
    /// at a uniformly random fraction of its guide's length.
    pub thinning: f32,
    /// `clumpWidth` (`.cwd`, 0.3): diameter of a clump's cross-section at the root.
    pub clump_width: f32,
    /// `clumpWidthScale` (`.cws`, flat 1): factor on `clump_width` from root to tip.
    pub clump_width_scale: Ramp<f32>,
    /// `clumpTwist` (`.ctw`, 0): rotation of the clump's cross-section about the guide, in
    /// turns (1 = 360°).
    pub clump_twist: f32,
    /// `clumpCurl` (`.clc`, 0.5 everywhere): how fast the clump's hairs wind about the guide
    /// from root to tip; 0.5 none, above 0.5 one way and below the other, 0 or 1 winding
    /// at 5 turns per hair length.
    pub clump_curl: Ramp<f32>,
    /// `clumpFlatness` (`.cfl`, 0 everywhere): squashes the clump's cross-section into a
    /// ribbon; 1 flat.
    pub clump_flatness: Ramp<f32>,
    /// `bendFollow` (`.bnf`, 1): 1 keeps the cross-section perpendicular to the guide all
    /// along; 0 keeps it perpendicular to the guide's root direction (the surface normal).
    pub bend_follow: f32,
    /// `hairWidth` (`.hwd`, 0.01): diameter of a render hair.
    pub hair_width: f32,
    /// `hairWidthScale` (`.hws`, flat 1): factor on `hair_width` from root to tip.
    pub hair_width_scale: Ramp<f32>,
    /// `displacementScale` (`.dsc`, flat 1): factor on curl and noise from root to tip.
    pub displacement_scale: Ramp<f32>,
    /// `curl` (`.crl`, 0): radius of each hair's own helix, in hair widths.
    pub curl: f32,
    /// `curlFrequency` (`.crf`, 10): turns of that helix per hair length.
    pub curl_frequency: f32,
    /// `noiseMethod` (`.nmt`, random).
    pub noise_method: NoiseMethod,
    /// `noise` (`.noi`, 0): amplitude of the Perlin noise displacement, in hair widths.
    pub noise: f32,
    /// `noiseFrequency` (`.nof`, 0.4): 10 × this noise features along a hair (0.4: four),
    /// and as many across the surface's UV square or a clump's width.
    pub noise_frequency: f32,
    /// `noiseFrequencyU` (`.nfu`, 1): factor on the frequency along U (smooth methods).
    pub noise_frequency_u: f32,
    /// `noiseFrequencyV` (`.nfv`, 1): factor on the frequency along V (smooth methods).
    pub noise_frequency_v: f32,
    /// `noiseFrequencyW` (`.nfw`, 1): factor on the frequency along the hair.
    pub noise_frequency_w: f32,
    /// `hairColor` (`.hcl`, (0.3, 0.25, 0.15)): linear RGB base colour.
    pub hair_color: Color,
    /// `hairColorScale` (`.hcs`, flat white): colour factor from root to tip.
    pub hair_color_scale: Ramp<Vec3>,
    /// `opacity` (`.opc`, 1), stored per point in the strands.
    pub opacity: f32,
    /// `translucence` (`.tlc`, 0.5): light passing through the hair.
    pub translucence: f32,
    /// `specularColor` (`.spc`, (0.35, 0.35, 0.3)).
    pub specular_color: Color,
    /// `specularPower` (`.spp`, 3).
    pub specular_power: f32,
    /// `diffuseRand` (`.dfr`, 0.2): per-hair brightness variation, ± this fraction.
    pub diffuse_rand: f32,
    /// `specularRand` (`.sra`, 0.4): per-hair specular variation.
    pub specular_rand: f32,
    /// `hueRand` (`.chr`, 0): per-hair hue shift, ± half this many turns of the hue circle.
    pub hue_rand: f32,
    /// `satRand` (`.csr`, 0): per-hair saturation variation, ± this fraction.
    pub sat_rand: f32,
    /// `valRand` (`.cvr`, 0): per-hair value (HSV) variation, ± this fraction.
    pub val_rand: f32,
}

impl Default for HairSystem {
    fn default() -> Self {
        HairSystem {
            hairs_per_clump: 10,
            sub_segments: 0,
            thinning: 0.0,
            clump_width: 0.3,
            clump_width_scale: Ramp::constant(1.0),
            clump_twist: 0.0,
            clump_curl: Ramp::constant(0.5),
            clump_flatness: Ramp::constant(0.0),
            bend_follow: 1.0,
            hair_width: 0.01,
            hair_width_scale: Ramp::constant(1.0),
            displacement_scale: Ramp::constant(1.0),
            curl: 0.0,
            curl_frequency: 10.0,
            noise_method: NoiseMethod::Random,
            noise: 0.0,
            noise_frequency: 0.4,
            noise_frequency_u: 1.0,
            noise_frequency_v: 1.0,
            noise_frequency_w: 1.0,
            hair_color: Color::new(0.3, 0.25, 0.15),
            hair_color_scale: Ramp::constant(Vec3::ONE),
            opacity: 1.0,
            translucence: 0.5,
            specular_color: Color::new(0.35, 0.35, 0.3),
            specular_power: 3.0,
            diffuse_rand: 0.2,
            specular_rand: 0.4,
            hue_rand: 0.0,
            sat_rand: 0.0,
            val_rand: 0.0,
        }
    }
}

/// Upper bound on `hairs_per_clump`, so a typo cannot ask for unbounded memory.
pub const MAX_HAIRS_PER_CLUMP: u32 = 100_000;
/// Upper bound on `sub_segments`.
pub const MAX_SUB_SEGMENTS: u32 = 64;

impl HairSystem {
    /// The tube material (thesis section 2.1.8) the hair-system shading attributes
    /// describe: diffuse and ambient `hair_color` (per-point colours replace it), specular
    /// `specular_color` with `specular_power`. The tube model has no terms for
    /// `translucence`, `specular_rand` or `opacity`.
    pub fn tube(&self) -> Tube {
        Tube {
            ambient: self.hair_color,
            diffuse: self.hair_color,
            specular: self.specular_color,
            specular_power: self.specular_power,
        }
    }

    /// Checks every attribute is finite and in its range; the error names the attribute.
    pub fn validate(&self) -> Result<(), String> {
        let range = |name: &str, v: f32, lo: f32, hi: f32| -> Result<(), String> {
            match v.is_finite() && v >= lo && v <= hi {
                true => Ok(()),
                false if hi == f32::INFINITY => Err(format!("`{name}` = {v} must be finite and at least {lo}")),
                false => Err(format!("`{name}` = {v} must be between {lo} and {hi}")),
            }
        };
        const ANY: f32 = f32::INFINITY;
        if self.hairs_per_clump == 0 || self.hairs_per_clump > MAX_HAIRS_PER_CLUMP {
            return Err(format!("`hairs_per_clump` = {} must be 1 to {MAX_HAIRS_PER_CLUMP}", self.hairs_per_clump));
        }
        if self.sub_segments > MAX_SUB_SEGMENTS {
            return Err(format!("`sub_segments` = {} must be at most {MAX_SUB_SEGMENTS}", self.sub_segments));
        }
        range("thinning", self.thinning, 0.0, 1.0)?;
        range("clump_width", self.clump_width, 0.0, ANY)?;
        range("clump_twist", self.clump_twist, -1e6, 1e6)?;
        range("bend_follow", self.bend_follow, 0.0, 1.0)?;
        range("hair_width", self.hair_width, 0.0, ANY)?;
        range("curl", self.curl, 0.0, ANY)?;
        range("curl_frequency", self.curl_frequency, 0.0, 1e6)?;
        range("noise", self.noise, 0.0, ANY)?;
        range("noise_frequency", self.noise_frequency, 0.0, 1e6)?;
        range("noise_frequency_u", self.noise_frequency_u, 0.0, 1e6)?;
        range("noise_frequency_v", self.noise_frequency_v, 0.0, 1e6)?;
        range("noise_frequency_w", self.noise_frequency_w, 0.0, 1e6)?;
        range("opacity", self.opacity, 0.0, 1.0)?;
        range("translucence", self.translucence, 0.0, 1.0)?;
        range("specular_power", self.specular_power, 0.0, ANY)?;
        range("diffuse_rand", self.diffuse_rand, 0.0, 1.0)?;
        range("specular_rand", self.specular_rand, 0.0, 1.0)?;
        range("hue_rand", self.hue_rand, 0.0, 1.0)?;
        range("sat_rand", self.sat_rand, 0.0, 1.0)?;
        range("val_rand", self.val_rand, 0.0, 1.0)?;
        for (name, c) in [("hair_color", self.hair_color), ("specular_color", self.specular_color)] {
            for v in c.to_array() {
                range(name, v, 0.0, ANY)?;
            }
        }
        ramp_range("clump_width_scale", &self.clump_width_scale, 0.0, ANY)?;
        ramp_range("clump_curl", &self.clump_curl, 0.0, 1.0)?;
        ramp_range("clump_flatness", &self.clump_flatness, 0.0, 1.0)?;
        ramp_range("hair_width_scale", &self.hair_width_scale, 0.0, ANY)?;
        ramp_range("displacement_scale", &self.displacement_scale, 0.0, ANY)?;
        for (i, k) in self.hair_color_scale.keys().iter().enumerate() {
            if !(k.value.is_finite_value() && k.value.min_element() >= 0.0) {
                return Err(format!("`hair_color_scale` key {}: colour must be finite and not negative", i + 1));
            }
        }
        Ok(())
    }
}

/// Checks a scalar ramp's values lie in [lo, hi]; the error names the ramp and key.
fn ramp_range(name: &str, ramp: &Ramp<f32>, lo: f32, hi: f32) -> Result<(), String> {
    for (i, k) in ramp.keys().iter().enumerate() {
        if !(k.value.is_finite() && k.value >= lo && k.value <= hi) {
            return Err(format!("`{name}` key {}: value {} must be between {lo} and {hi}", i + 1, k.value));
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::hair_system::ramp::{Interp, RampKey};

    #[test]
    fn defaults_are_valid_and_bad_values_name_the_attribute() {
        HairSystem::default().validate().unwrap();
        let bad = |f: fn(&mut HairSystem)| {
            let mut s = HairSystem::default();
            f(&mut s);
            s.validate().unwrap_err()
        };
        assert!(bad(|s| s.thinning = 1.5).contains("thinning"));
        assert!(bad(|s| s.clump_width = f32::NAN).contains("clump_width"));
        assert!(bad(|s| s.hair_width = -0.1).contains("hair_width"));
        assert!(bad(|s| s.hairs_per_clump = 0).contains("hairs_per_clump"));
        assert!(bad(|s| s.sub_segments = 1000).contains("sub_segments"));
        assert!(bad(|s| s.hair_color = Color::new(0.1, f32::INFINITY, 0.1)).contains("hair_color"));
        let e = bad(|s| {
            s.clump_flatness = Ramp::new(vec![
                RampKey { position: 0.0, value: 0.0, interp: Interp::Linear },
                RampKey { position: 1.0, value: 2.0, interp: Interp::Linear },
            ])
            .unwrap()
        });
        assert!(e.contains("clump_flatness") && e.contains("key 2"), "{e}");
    }
}
