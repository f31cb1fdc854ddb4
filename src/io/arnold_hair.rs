//! Arnold's hair shader, `standard_hair` (MtoA's `aiStandardHair` node in Maya files,
//! Arnold-USD's `arnold:standard_hair` shader in USD), as tress's materials. Both readers
//! fill a [`StandardHair`] by Arnold's parameter names and take its [`StandardHair::material`].
//!
//! Arnold's standard_hair is a Chiang et al. 2016 style fibre (d'Eon's longitudinal lobes;
//! Arnold Core user guide, "Standard Hair") plus a diffuse fibre lobe weighted by
//! `diffuse`; tress's `physical` material is the same model, so most parameters carry over:
//!
//! - `roughness` is β_m and `roughness_azimuthal` β_n when `roughness_anisotropic` is on,
//!   else β_n = β_m (the two roughnesses of Chiang §4.1; Blender Cycles' Principled Hair,
//!   built on the same paper with the same controls, maps them so too);
//! - `shift` is the cuticle tilt α in degrees, `ior` the index of refraction η;
//! - absorption: Arnold does not publish how `melanin` (0 to 1) and `melanin_redness`
//!   become σ_a. tress uses the mapping Blender Cycles documents for its Principled Hair
//!   (Blender manual, "Principled Hair BSDF": a concentration `−ln(max(1 − melanin, 1e-4))`,
//!   the fraction `melanin_redness` of it pheomelanin and the rest eumelanin), with tress's
//!   pigment coefficients (Chiang §4.1). `base × base_color`, when not white, adds the σ_a
//!   of Chiang §4.2's colour inversion, as Arnold's base colour "affects the secondary
//!   specular and transmission, just like melanin" (Arnold user guide) and Cycles adds its
//!   tint's;
//! - `diffuse` weighs Arnold's diffuse fibre (Zinke's model) against the physical lobes:
//!   a weight of 0.5 or more is drawn as tress's `diffuse` material on hair (Lambert on the
//!   fibre's cylinder, a diffuse fibre) of colour `diffuse × diffuse_color`, less as the
//!   physical fibre alone.
//!
//! Arnold 4's `hair` shader (the legacy one older files write: [`Hair`]) is Kajiya-Kay
//! shading (Arnold 4 node reference, "hair"), which tress's tube model is
//! ([`crate::shading::tube`]): `rootcolor` at the root blended to `tipcolor` at the tip
//! (baked into the strands' colours), a highlight of `spec × spec_color` and power
//! `spec_gloss`. Its second highlight, transmission, `spec_shift`, an `ambdiff` other than 1
//! (tube shading is the Kajiya-Kay diffuse, Arnold's `ambdiff` 1) and opacity are named
//! in its warning.
//!
//! What tress's model cannot hold (the lobe tints, per-strand randomization, emission,
//! opacity, ray-type weights, the dropped lobe of a mixed `diffuse`, connected textures)
//! is named in one warning per shader.

use super::arnold_graph::{self, Pattern};
use crate::math::Color;
use crate::shading::hair_bsdf::{
    color_from_sigma_a, sigma_a_from_color, sigma_a_from_melanin, Absorption, HairParams, PhysicalHair,
};
use crate::shading::tube::Tube;
use crate::shading::Material;

/// Smallest roughness the physical material takes.
const MIN_ROUGHNESS: f32 = 1e-3;
/// The melanin concentration `−ln(1 − melanin)` is capped where `1 − melanin` reaches this
/// (Cycles' floor): melanin 1 is a finite, very dark concentration.
const MELANIN_FLOOR: f32 = 1e-4;

/// Arnold's `standard_hair` parameters that tress reads, by Arnold's names, with Arnold's
/// defaults (as Arnold-USD writes every input of the shader).
#[derive(Clone, Debug, PartialEq)]
pub struct StandardHair {
    /// Weight of the base colour.
    pub base: f32,
    /// Colour the fibre's absorption gives (with melanin).
    pub base_color: Color,
    /// Pigment amount, 0 (white) to 1 (black).
    pub melanin: f32,
    /// Fraction of the melanin that is red pheomelanin.
    pub melanin_redness: f32,
    /// Per-strand variation of the melanin.
    pub melanin_randomize: f32,
    /// Longitudinal roughness.
    pub roughness: f32,
    /// Azimuthal roughness, used when `roughness_anisotropic` is on.
    pub roughness_azimuthal: f32,
    /// Whether `roughness_azimuthal` is used.
    pub roughness_anisotropic: bool,
    /// Index of refraction.
    pub ior: f32,
    /// Cuticle scale angle in degrees.
    pub shift: f32,
    /// Tint of the primary reflection (R).
    pub specular_tint: Color,
    /// Tint of the secondary reflection (TRT).
    pub specular2_tint: Color,
    /// Tint of the transmission (TT).
    pub transmission_tint: Color,
    /// Weight of the diffuse fibre lobe.
    pub diffuse: f32,
    /// Colour of the diffuse lobe.
    pub diffuse_color: Color,
    /// Opacity.
    pub opacity: Color,
    /// Weight of the emission.
    pub emission: f32,
    /// Colour of the emission.
    pub emission_color: Color,
    /// Weight on diffuse rays reaching the hair.
    pub indirect_diffuse: f32,
    /// Weight on specular rays reaching the hair.
    pub indirect_specular: f32,
}

impl Default for StandardHair {
    fn default() -> Self {
        StandardHair {
            base: 1.0,
            base_color: Color::ONE,
            melanin: 1.0,
            melanin_redness: 0.5,
            melanin_randomize: 0.0,
            roughness: 0.2,
            roughness_azimuthal: 0.2,
            roughness_anisotropic: false,
            ior: 1.55,
            shift: 3.0,
            specular_tint: Color::ONE,
            specular2_tint: Color::ONE,
            transmission_tint: Color::ONE,
            diffuse: 0.0,
            diffuse_color: Color::ONE,
            opacity: Color::ONE,
            emission: 0.0,
            emission_color: Color::ONE,
            indirect_diffuse: 1.0,
            indirect_specular: 1.0,
        }
    }
}

/// An Arnold shader tress maps to one of its materials: its parameters by Arnold's names,
/// set by the Maya and USD readers alike, and the material they give.
pub trait ArnoldShader: Default {
    /// The names of the parameters read, as Arnold spells them.
    const NAMES: &'static [&'static str];
    /// The parameters a colour map (a checkerboard) may drive, and what they colour
    /// ([`crate::io::arnold_surface::textured`]).
    const MAPS: &'static [(&'static str, crate::io::arnold_surface::Slot)] = &[];
    /// The parameter named `name` (one of [`ArnoldShader::NAMES`]).
    fn param(&mut self, name: &str) -> Option<Param<'_>>;
    /// The material standing in for the shader, and the warning naming what it leaves out
    /// (`shader` names the shader in it; `connected` lists the parameters driven by shading
    /// networks tress does not evaluate, whose own values were used).
    fn material(&self, shader: &str, connected: &[String]) -> (Material, Option<String>);
    /// The string parameter named `name`, for shaders that read one (an enum).
    fn text(&mut self, _name: &str) -> Option<&mut String> {
        None
    }
    /// The colour along a strand that the parameters in `varying` (networks varying along
    /// it, [`crate::io::arnold_graph`]) give the material's base colour, those parameters
    /// set to neutral values and taken from `varying`; what is left there is drawn in its
    /// mean. By default the parameters of [`ArnoldShader::MAPS`] multiply the base colour.
    fn along(&mut self, varying: &mut Vec<(&'static str, Pattern)>) -> Option<Pattern> {
        let names: Vec<&str> = Self::MAPS.iter().map(|(n, _)| *n).collect();
        arnold_graph::mapped(self, varying, &names)
    }
}

impl ArnoldShader for StandardHair {
    const NAMES: &'static [&'static str] = &StandardHair::NAMES;
    fn param(&mut self, name: &str) -> Option<Param<'_>> {
        StandardHair::param(self, name)
    }
    fn material(&self, shader: &str, connected: &[String]) -> (Material, Option<String>) {
        StandardHair::material(self, shader, connected)
    }
    /// A mostly diffuse fibre (drawn as a diffuse material) takes its colour along the
    /// strand from `diffuse_color` and `diffuse`; the physical fibre's absorption is one
    /// colour per shader, so its networks are drawn in their mean.
    fn along(&mut self, varying: &mut Vec<(&'static str, Pattern)>) -> Option<Pattern> {
        match self.diffuse >= 0.5 {
            true => arnold_graph::mapped(self, varying, &["diffuse_color", "diffuse"]),
            false => None,
        }
    }
}

/// One parameter of an Arnold shader ([`ArnoldShader`]), to be set from a file.
pub enum Param<'a> {
    /// A number.
    Float(&'a mut f32),
    /// A colour.
    Color(&'a mut Color),
    /// A switch.
    Bool(&'a mut bool),
}

impl Param<'_> {
    /// Whether the value set is infinite: a number in the file beyond single precision
    /// (1e39, finite as the double the file's text or a `double` attribute holds) is
    /// infinite once stored as f32, and NaN once a weight of 0 multiplies it, so readers
    /// refuse it, naming the shader and the parameter. (A NaN in the file is read as the
    /// parameter's low end, as a value out of range.)
    pub fn is_infinite(&self) -> bool {
        match self {
            Param::Float(x) => x.is_infinite(),
            Param::Color(c) => c.to_array().iter().any(|x| x.is_infinite()),
            Param::Bool(_) => false,
        }
    }
}

impl StandardHair {
    /// The names of the parameters read, as Arnold spells them.
    pub const NAMES: [&'static str; 20] = [
        "base",
        "base_color",
        "melanin",
        "melanin_redness",
        "melanin_randomize",
        "roughness",
        "roughness_azimuthal",
        "roughness_anisotropic",
        "ior",
        "shift",
        "specular_tint",
        "specular2_tint",
        "transmission_tint",
        "diffuse",
        "diffuse_color",
        "opacity",
        "emission",
        "emission_color",
        "indirect_diffuse",
        "indirect_specular",
    ];

    /// The parameter named `name` (one of [`StandardHair::NAMES`]).
    pub fn param(&mut self, name: &str) -> Option<Param<'_>> {
        use Param::{Bool, Color as C, Float};
        Some(match name {
            "base" => Float(&mut self.base),
            "base_color" => C(&mut self.base_color),
            "melanin" => Float(&mut self.melanin),
            "melanin_redness" => Float(&mut self.melanin_redness),
            "melanin_randomize" => Float(&mut self.melanin_randomize),
            "roughness" => Float(&mut self.roughness),
            "roughness_azimuthal" => Float(&mut self.roughness_azimuthal),
            "roughness_anisotropic" => Bool(&mut self.roughness_anisotropic),
            "ior" => Float(&mut self.ior),
            "shift" => Float(&mut self.shift),
            "specular_tint" => C(&mut self.specular_tint),
            "specular2_tint" => C(&mut self.specular2_tint),
            "transmission_tint" => C(&mut self.transmission_tint),
            "diffuse" => Float(&mut self.diffuse),
            "diffuse_color" => C(&mut self.diffuse_color),
            "opacity" => C(&mut self.opacity),
            "emission" => Float(&mut self.emission),
            "emission_color" => C(&mut self.emission_color),
            "indirect_diffuse" => Float(&mut self.indirect_diffuse),
            "indirect_specular" => Float(&mut self.indirect_specular),
            _ => return None,
        })
    }

    /// The physical fibre's parameters (see the module documentation), and the names of
    /// values clamped to the model's range.
    pub fn hair_params(&self) -> (HairParams, Vec<String>) {
        let mut clamped = Vec::new();
        let mut clamp = |name: &str, v: f32, lo: f32, hi: f32| {
            // NaN is not in any range either: it takes the low end.
            let c = if v.is_nan() { lo } else { v.clamp(lo, hi) };
            if c != v {
                clamped.push(format!("{name} {v} (clamped to {c})"));
            }
            c
        };
        let beta_m = clamp("roughness", self.roughness, MIN_ROUGHNESS, 1.0);
        let beta_n = match self.roughness_anisotropic {
            true => clamp("roughness_azimuthal", self.roughness_azimuthal, MIN_ROUGHNESS, 1.0),
            false => beta_m,
        };
        let melanin = clamp("melanin", self.melanin, 0.0, 1.0);
        let redness = clamp("melanin_redness", self.melanin_redness, 0.0, 1.0);
        // Blender Cycles' Principled Hair mapping (module documentation).
        let concentration = -(1.0 - melanin).max(MELANIN_FLOOR).ln();
        let (eumelanin, pheomelanin) = (concentration * (1.0 - redness), concentration * redness);
        let base = clamp("base", self.base, 0.0, 1.0);
        let tint = (self.base_color * base).clamp(Color::ZERO, Color::ONE);
        let absorption = match tint == Color::ONE {
            true => Absorption::Melanin { eumelanin, pheomelanin },
            false => {
                let sigma_a = sigma_a_from_melanin(eumelanin, pheomelanin) + sigma_a_from_color(tint, beta_n);
                Absorption::Color(color_from_sigma_a(sigma_a, beta_n))
            }
        };
        let params = HairParams {
            absorption,
            beta_m,
            beta_n,
            alpha_degrees: clamp("shift", self.shift, -30.0, 30.0),
            eta: clamp("ior", self.ior, 1.0, 10.0),
        };
        (params, clamped)
    }

    /// The material standing in for the shader, and the warning naming what it leaves
    /// out (`shader` names the shader in it; `connected` lists the parameters driven by
    /// shading networks tress does not evaluate, whose own values were used).
    pub fn material(&self, shader: &str, connected: &[String]) -> (Material, Option<String>) {
        let mut left_out: Vec<String> = Vec::new();
        let off = |c: Color, default: Color| c != default;
        let diffuse = if self.diffuse.is_nan() { 0.0 } else { self.diffuse.clamp(0.0, 1.0) };
        let material = if diffuse >= 0.5 {
            if diffuse < 1.0 {
                left_out.push(format!("diffuse {diffuse} (drawn as a diffuse fibre only, without the specular lobes)"));
            }
            Material::Diffuse { color: (self.diffuse_color * diffuse).clamp(Color::ZERO, Color::ONE) }
        } else {
            if diffuse > 0.0 {
                left_out.push(format!("diffuse {diffuse} (drawn without the diffuse lobe)"));
            }
            let (params, clamped) = self.hair_params();
            left_out.extend(clamped);
            for (name, c) in [
                ("specular_tint", self.specular_tint),
                ("specular2_tint", self.specular2_tint),
                ("transmission_tint", self.transmission_tint),
            ] {
                if off(c, Color::ONE) {
                    left_out.push(format!("{name} {}", fmt_color(c)));
                }
            }
            if self.melanin_randomize != 0.0 {
                left_out.push(format!("melanin_randomize {}", self.melanin_randomize));
            }
            if self.indirect_specular != 1.0 {
                left_out.push(format!("indirect_specular {}", self.indirect_specular));
            }
            Material::Physical(PhysicalHair::new(params))
        };
        if self.emission != 0.0 && off(self.emission_color, Color::ZERO) {
            left_out.push(format!("emission {} of colour {}", self.emission, fmt_color(self.emission_color)));
        }
        if off(self.opacity, Color::ONE) {
            left_out.push(format!("opacity {}", fmt_color(self.opacity)));
        }
        if self.indirect_diffuse != 1.0 {
            left_out.push(format!("indirect_diffuse {}", self.indirect_diffuse));
        }
        if !connected.is_empty() {
            left_out.push(format!("shading networks on {} (their own values used)", connected.join(", ")));
        }
        let warning = (!left_out.is_empty()).then(|| {
            format!("{shader}: Arnold standard_hair settings tress does not represent: {}", left_out.join(", "))
        });
        (material, warning)
    }
}

/// Arnold 4's legacy `hair` shader, by its parameter names and defaults (Arnold 4 node
/// reference, "hair"), drawn as tube shading (see the module documentation).
#[derive(Clone, Debug, PartialEq)]
pub struct Hair {
    /// Diffuse colour at the root.
    pub rootcolor: Color,
    /// Diffuse colour at the tip.
    pub tipcolor: Color,
    /// Blend of isotropic (0) and Kajiya-Kay (1) diffuse.
    pub ambdiff: f32,
    /// Weight of the primary highlight.
    pub spec: f32,
    /// Colour of the primary highlight.
    pub spec_color: Color,
    /// Angle the primary highlight is shifted by, in degrees.
    pub spec_shift: f32,
    /// Glossiness (power) of the primary highlight.
    pub spec_gloss: f32,
    /// Weight of the secondary highlight.
    pub spec2: f32,
    /// Weight of the transmission.
    pub transmission: f32,
    /// Opacity.
    pub opacity: Color,
}

impl Default for Hair {
    fn default() -> Self {
        Hair {
            rootcolor: Color::splat(0.1),
            tipcolor: Color::splat(0.5),
            ambdiff: 0.6,
            spec: 1.0,
            spec_color: Color::ONE,
            spec_shift: 0.0,
            spec_gloss: 10.0,
            spec2: 0.0,
            transmission: 0.0,
            opacity: Color::ONE,
        }
    }
}

impl ArnoldShader for Hair {
    const NAMES: &'static [&'static str] = &[
        "rootcolor",
        "tipcolor",
        "ambdiff",
        "spec",
        "spec_color",
        "spec_shift",
        "spec_gloss",
        "spec2",
        "transmission",
        "opacity",
    ];

    fn param(&mut self, name: &str) -> Option<Param<'_>> {
        use Param::{Color as C, Float};
        Some(match name {
            "rootcolor" => C(&mut self.rootcolor),
            "tipcolor" => C(&mut self.tipcolor),
            "ambdiff" => Float(&mut self.ambdiff),
            "spec" => Float(&mut self.spec),
            "spec_color" => C(&mut self.spec_color),
            "spec_shift" => Float(&mut self.spec_shift),
            "spec_gloss" => Float(&mut self.spec_gloss),
            "spec2" => Float(&mut self.spec2),
            "transmission" => Float(&mut self.transmission),
            "opacity" => C(&mut self.opacity),
            _ => return None,
        })
    }

    /// Tube shading of the root colour (the colour along the strands coming from
    /// [`ArnoldShader::along`]).
    fn material(&self, shader: &str, connected: &[String]) -> (Material, Option<String>) {
        let finite = |c: Color| Color::from_array(c.to_array().map(|x| if x.is_finite() { x.max(0.0) } else { 0.0 }));
        let diffuse = finite(self.rootcolor);
        let power = if self.spec_gloss.is_finite() { self.spec_gloss.clamp(0.0, 1.0e4) } else { 10.0 };
        let tube =
            Tube { ambient: diffuse, diffuse, specular: finite(self.spec_color * self.spec), specular_power: power };
        let mut left_out = Vec::new();
        for (name, v, default) in [
            ("ambdiff", self.ambdiff, 1.0),
            ("spec_shift", self.spec_shift, 0.0),
            ("spec2", self.spec2, 0.0),
            ("transmission", self.transmission, 0.0),
        ] {
            if v != default {
                left_out.push(format!("{name} {v}"));
            }
        }
        if self.opacity != Color::ONE {
            left_out.push(format!("opacity {}", fmt_color(self.opacity)));
        }
        if !connected.is_empty() {
            left_out.push(format!("shading networks on {} (their own values used)", connected.join(", ")));
        }
        let warning = (!left_out.is_empty())
            .then(|| format!("{shader}: Arnold hair settings tress does not represent: {}", left_out.join(", ")));
        (Material::Tube(tube), warning)
    }

    /// The root colour blended to the tip colour, each a constant or a network.
    fn along(&mut self, varying: &mut Vec<(&'static str, Pattern)>) -> Option<Pattern> {
        let mut take = |name: &str, own: Color| match varying.iter().position(|(n, _)| *n == name) {
            Some(i) => varying.remove(i).1,
            None => Pattern::Constant(own),
        };
        let (root, tip) = (take("rootcolor", self.rootcolor), take("tipcolor", self.tipcolor));
        let along = Pattern::root_to_tip(root, tip);
        if along.constant().is_some() {
            return None;
        }
        (self.rootcolor, self.tipcolor) = (Color::ONE, Color::ONE);
        Some(along)
    }
}

/// A colour as `(r, g, b)` in warnings.
pub(crate) fn fmt_color(c: Color) -> String {
    format!("({}, {}, {})", c.x, c.y, c.z)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn physical(m: &Material) -> &HairParams {
        match m {
            Material::Physical(h) => h.params(),
            other => panic!("not physical: {other:?}"),
        }
    }

    #[test]
    fn arnolds_defaults_are_a_dark_physical_fibre_with_nothing_left_out() {
        let (m, w) = StandardHair::default().material("s", &[]);
        assert_eq!(w, None);
        let p = physical(&m);
        assert_eq!((p.beta_m, p.beta_n, p.alpha_degrees, p.eta), (0.2, 0.2, 3.0, 1.55));
        // Melanin 1 is the capped concentration −ln(1e-4), half of it red.
        let Absorption::Melanin { eumelanin, pheomelanin } = p.absorption else { panic!() };
        assert!((eumelanin - 0.5 * 9.2103).abs() < 1e-3 && (pheomelanin - eumelanin).abs() < 1e-6);
    }

    #[test]
    fn melanin_and_redness_split_into_the_two_pigments() {
        let s = StandardHair { melanin: 0.5, melanin_redness: 0.25, ..Default::default() };
        let Absorption::Melanin { eumelanin, pheomelanin } = s.hair_params().0.absorption else { panic!() };
        let c = 2f32.ln();
        assert!((eumelanin - 0.75 * c).abs() < 1e-6 && (pheomelanin - 0.25 * c).abs() < 1e-6);
        let white = StandardHair { melanin: 0.0, ..Default::default() }.hair_params().0;
        assert_eq!(white.absorption, Absorption::Melanin { eumelanin: 0.0, pheomelanin: 0.0 });
    }

    #[test]
    fn a_base_colour_adds_its_absorption_to_the_melanins() {
        let s = StandardHair { melanin: 0.0, base_color: Color::new(0.6, 0.3, 0.1), ..Default::default() };
        let p = s.hair_params().0;
        // With no melanin the colour is the base colour itself (Chiang's inversion round trip).
        let Absorption::Color(c) = p.absorption else { panic!() };
        assert!((c - Color::new(0.6, 0.3, 0.1)).abs().max_element() < 1e-4, "{c}");
        // Melanin darkens it further; `base` 0 is black.
        let darker = StandardHair { melanin: 0.3, ..s.clone() }.hair_params().0;
        let Absorption::Color(d) = darker.absorption else { panic!() };
        assert!(d.max_element() < c.max_element() && (d.cmplt(c)).all(), "{d} {c}");
        let none = StandardHair { base: 0.0, ..s }.hair_params().0;
        let Absorption::Color(n) = none.absorption else { panic!() };
        assert!(n.max_element() < 1e-3, "{n}");
    }

    #[test]
    fn roughness_is_beta_m_and_the_azimuthal_one_beta_n_only_when_anisotropic() {
        let s = StandardHair { roughness: 0.4, roughness_azimuthal: 0.7, ..Default::default() };
        assert_eq!(s.hair_params().0.beta_n, 0.4);
        let a = StandardHair { roughness_anisotropic: true, ..s }.hair_params().0;
        assert_eq!((a.beta_m, a.beta_n), (0.4, 0.7));
    }

    #[test]
    fn a_mostly_diffuse_shader_is_a_diffuse_fibre_and_what_is_lost_is_named() {
        let s = StandardHair { diffuse: 1.0, diffuse_color: Color::new(0.5, 0.4, 0.3), ..Default::default() };
        assert_eq!(s.material("h", &[]), (Material::Diffuse { color: Color::new(0.5, 0.4, 0.3) }, None));
        let (m, w) = StandardHair { diffuse: 0.2, specular_tint: Color::new(1.0, 0.5, 0.5), shift: 45.0, ..s }
            .material("aiStandardHair1", &["base_color".to_string()]);
        assert!(matches!(m, Material::Physical(_)));
        let w = w.unwrap();
        for part in
            ["aiStandardHair1", "diffuse 0.2", "specular_tint (1, 0.5, 0.5)", "shift 45 (clamped to 30)", "base_color"]
        {
            assert!(w.contains(part), "{w}");
        }
    }
}
