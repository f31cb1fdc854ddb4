//! A physically based hair BSDF: the near-field fibre model of Chiang, Bitterli, Tappan and
//! Burley 2016, "A Practical and Controllable Hair and Fur Model for Production Path
//! Tracing" (CGF 35(2), below "Chiang"), with the longitudinal lobes of d'Eon, Francois,
//! Hill, Letteri and Aubry 2011, "An Energy-Conserving Hair Reflectance Model" (EGSR,
//! "d'Eon"), and their sampling by d'Eon, Marschner and Hanika 2013, "Importance Sampling
//! for Physically-Based Hair Fiber Models" (SIGGRAPH Asia technical brief).
//!
//! **Local frame.** The fibre tangent is +x (root to tip); y and z span the normal plane.
//! A direction `w` has the longitudinal angle θ from the normal plane, `sin θ = w.x`, and
//! the azimuth `φ = atan2(w.z, w.y)`. Both `wo` (towards the viewer) and `wi` (towards the
//! light) point away from the fibre. [`FibreFrame`] builds this frame from a hit.
//!
//! **Near field.** The camera ray met the fibre at the offset `h = sin γ_o` across it
//! (γ_o: the signed angle, about +x, from the fibre normal at the hit to `wo`). Chiang
//! evaluates the azimuthal lobes for that `h` instead of integrating across the fibre.
//!
//! **Lobes** p = 0 (R), 1 (TT), 2 (TRT) and one residual lobe for all p >= 3:
//! `f(wo, wi) cos θ_i = Σ_p M_p(θ_o, θ_i) A_p(θ_o, h) N_p(φ_i - φ_o, h)`.
//! `M_p` integrates to 1 against `cos θ_i dθ_i`, `N_p` to 1 over φ, and with no absorption
//! `Σ_p A_p = 1`: the model conserves energy exactly (the white furnace).
//!
//! **Reciprocity.** The model is reciprocal on the specular cone (`θ_i = ±θ_o`) without
//! cuticle tilt, where the reversed path has the offset `-h`. Elsewhere it is not exactly:
//! Chiang evaluates the attenuation and the refraction with θ_o only, and the tilt shifts
//! θ_o only: for untilted blonde hair 4 % (β_m 0.1) to 14 % (β_m 0.3) of the scattered
//! energy differs between the two directions (see the tests). pbrt-v4's hair reciprocity
//! test is disabled, and Mitsuba 3 flags its hair BSDF non-symmetric.

use super::surface::fresnel_dielectric;
use crate::math::{frame, Color};
use glam::Vec3;
use std::f32::consts::{PI, TAU};

/// Lobes: R, TT, TRT and the residual for p >= 3.
const LOBES: usize = 4;

/// Absorption of eumelanin and pheomelanin per unit concentration, linear RGB, per fibre
/// radius: Chiang §4.1 (after d'Eon §6.1), the values pbrt-v4
/// (`HairBxDF::SigmaAFromConcentration`) and Mitsuba 3 (`hair`) use, so that the same
/// concentrations give the same hair in all three.
const EUMELANIN_SIGMA_A: Color = Color::new(0.419, 0.697, 1.37);
const PHEOMELANIN_SIGMA_A: Color = Color::new(0.187, 0.4, 1.05);

/// Smallest roughness used; values below it make the lobes narrower than `f32` resolves.
const MIN_BETA: f32 = 1e-3;

/// Where a fibre's absorption coefficient σ_a comes from.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Absorption {
    /// Pigment concentrations (d'Eon §6.1): 0 is white, about 0.3 blonde, 1.3 brown, 8 black.
    Melanin {
        /// Eumelanin (brown-black pigment).
        eumelanin: f32,
        /// Pheomelanin (red pigment).
        pheomelanin: f32,
    },
    /// A colour in [0, 1]³, the multiple-scattering albedo of a mass of such hair, inverted
    /// to σ_a by Chiang §4.2.
    Color(Color),
    /// The strand's own per-point colour (from a `.hair` file), inverted like [`Absorption::Color`].
    FromStrands,
}

/// Parameters of the physical hair material, as a scene states them.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HairParams {
    /// Where σ_a comes from.
    pub absorption: Absorption,
    /// Longitudinal roughness β_m in (0, 1].
    pub beta_m: f32,
    /// Azimuthal roughness β_n in (0, 1].
    pub beta_n: f32,
    /// Cuticle scale tilt α in degrees; positive tilts the R highlight towards the tip.
    pub alpha_degrees: f32,
    /// Index of refraction of the fibre, at least 1.
    pub eta: f32,
}

impl Default for HairParams {
    fn default() -> Self {
        HairParams {
            absorption: Absorption::Melanin { eumelanin: 1.3, pheomelanin: 0.0 },
            beta_m: 0.3,
            beta_n: 0.3,
            alpha_degrees: 2.0,
            eta: 1.55,
        }
    }
}

impl HairParams {
    /// Checks every value for the range the model is defined on.
    pub fn validate(&self) -> Result<(), String> {
        let ok = |x: f32, lo: f32, hi: f32| x.is_finite() && x >= lo && x <= hi;
        match self.absorption {
            Absorption::Melanin { eumelanin, pheomelanin } => {
                if !(ok(eumelanin, 0.0, 1e4) && ok(pheomelanin, 0.0, 1e4)) {
                    return Err("`eumelanin` and `pheomelanin` must be finite and not negative".into());
                }
            }
            Absorption::Color(c) => {
                if !c.to_array().iter().all(|&x| ok(x, 0.0, 1.0)) {
                    return Err("`color` components must be between 0 and 1".into());
                }
            }
            Absorption::FromStrands => {}
        }
        if !(self.beta_m > 0.0 && self.beta_m <= 1.0 && self.beta_n > 0.0 && self.beta_n <= 1.0) {
            return Err("`beta_m` and `beta_n` must be in (0, 1]".into());
        }
        if !ok(self.alpha_degrees, -30.0, 30.0) {
            return Err("`alpha` must be between -30 and 30 degrees".into());
        }
        if !ok(self.eta, 1.0, 10.0) {
            return Err("`eta` must be between 1 and 10".into());
        }
        Ok(())
    }
}

/// The physical hair material: the parameters and what follows from them alone.
#[derive(Clone, Debug, PartialEq)]
pub struct PhysicalHair {
    params: HairParams,
    /// Longitudinal variance v_p per lobe.
    v: [f32; LOBES],
    /// `ln(1 / (2 v sinh(1/v))) + 1/v` per lobe: the log of M_p's normalisation.
    ln_norm: [f32; LOBES],
    /// Logistic scale s of the azimuthal lobes.
    s: f32,
    /// 1 / the logistic's mass on [-π, π], which is tanh(π / 2s).
    trim: f32,
    /// (sin, cos) of the longitudinal shift of θ_o for R, TT and TRT.
    shift: [(f32, f32); 3],
    /// σ_a for melanin or colour absorption (unused for per-strand colours).
    sigma_a: Color,
}

/// One sampled direction.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HairSample {
    /// Unit direction towards the light, in the local frame.
    pub wi: Vec3,
    /// `f(wo, wi) |cos θ_i|`, as [`HairBsdf::eval`] returns it.
    pub value: Color,
    /// Solid-angle density of `wi`, as [`HairBsdf::pdf`] returns it.
    pub pdf: f32,
}

impl PhysicalHair {
    /// The material for `params` (assumed valid, see [`HairParams::validate`]; roughness
    /// below 0.001 acts as 0.001).
    pub fn new(params: HairParams) -> PhysicalHair {
        let beta_m = params.beta_m.clamp(MIN_BETA, 1.0);
        let beta_n = params.beta_n.clamp(MIN_BETA, 1.0);
        let (v, ln_norm, s, trim) = lobe_widths(beta_m, beta_n);
        // Cuticle tilt (Marschner et al. 2003's lobe shifts): the R highlight moves by 2α, TT by -α
        // and TRT by -3α (their α_TT = -α_R / 2, α_TRT = -3 α_R / 2). Shifting θ_o by the
        // opposite amount moves the lobe's peak in θ_i by that much.
        let alpha = params.alpha_degrees.to_radians();
        let shift = [-2.0 * alpha, alpha, 3.0 * alpha].map(|a| a.sin_cos());
        let sigma_a = match params.absorption {
            Absorption::Melanin { eumelanin, pheomelanin } => sigma_a_from_melanin(eumelanin, pheomelanin),
            Absorption::Color(c) => sigma_a_from_color(c, beta_n),
            Absorption::FromStrands => Color::ZERO,
        };
        PhysicalHair { params, v, ln_norm, s, trim, shift, sigma_a }
    }

    /// The same fibre with lobes no narrower than those of roughness `min_roughness`
    /// (β_m and β_n each raised to it), for path regularization (Kaplanyan and
    /// Dachsbacher 2013, "Path Space Regularization for Holistic and Robust Light
    /// Transport"): the absorption, the attenuations `A_p` and the lobes' centres stay,
    /// so the widened lobes still integrate to the fibre's albedo, and evaluation, density
    /// and sampling stay consistent. `None` when both roughnesses are already that large.
    pub fn widened(&self, min_roughness: f32) -> Option<PhysicalHair> {
        let (beta_m, beta_n) = (self.params.beta_m.clamp(MIN_BETA, 1.0), self.params.beta_n.clamp(MIN_BETA, 1.0));
        let min = min_roughness.min(1.0);
        if beta_m >= min && beta_n >= min {
            return None;
        }
        let (v, ln_norm, s, trim) = lobe_widths(beta_m.max(min), beta_n.max(min));
        Some(PhysicalHair { v, ln_norm, s, trim, ..self.clone() })
    }

    /// The parameters the material was made from.
    pub fn params(&self) -> &HairParams {
        &self.params
    }

    /// True when σ_a comes from the strands' colours, which must then exist.
    pub fn needs_strand_colors(&self) -> bool {
        self.params.absorption == Absorption::FromStrands
    }

    /// σ_a at a point of a strand whose colour there is `strand_color`. Only
    /// [`Absorption::FromStrands`] uses it; a strand without colour is then white.
    pub fn sigma_a(&self, strand_color: Option<Color>) -> Color {
        match self.params.absorption {
            Absorption::FromStrands => {
                sigma_a_from_color(strand_color.unwrap_or(Color::ONE), self.params.beta_n.clamp(MIN_BETA, 1.0))
            }
            _ => self.sigma_a,
        }
    }

    /// The colour the absorption stands for (the inverse of Chiang's mapping): what the
    /// material shows as a Lambertian surface when it is put on a mesh.
    pub fn surface_color(&self, strand_color: Option<Color>) -> Color {
        color_from_sigma_a(self.sigma_a(strand_color), self.params.beta_n.clamp(MIN_BETA, 1.0))
    }

    /// The BSDF at a hit `h` across the fibre (clamped to [-1, 1]) with absorption `sigma_a`.
    pub fn at(&self, sigma_a: Color, h: f32) -> HairBsdf<'_> {
        let h = if h.is_nan() { 0.0 } else { h.clamp(-1.0, 1.0) };
        HairBsdf { hair: self, sigma_a: sigma_a.max(Color::ZERO), h }
    }

    /// `f(wo, wi) |cos θ_i|` in world space, on a strand with unit `tangent` hit where the
    /// fibre's normal is `normal`; `strand_color` feeds [`Absorption::FromStrands`].
    pub fn response(&self, strand_color: Option<Color>, tangent: Vec3, normal: Vec3, wo: Vec3, wi: Vec3) -> Color {
        let fr = FibreFrame::new(tangent, normal, wo);
        self.at(self.sigma_a(strand_color), fr.h).eval(fr.to_local(wo), fr.to_local(wi))
    }

    /// [`HairBsdf::sample`] in world space (arguments as for [`PhysicalHair::response`]):
    /// the direction `wi` and its solid-angle density.
    pub fn sample(
        &self,
        strand_color: Option<Color>,
        tangent: Vec3,
        normal: Vec3,
        wo: Vec3,
        u: [f32; 4],
    ) -> Option<(Vec3, f32)> {
        let fr = FibreFrame::new(tangent, normal, wo);
        let s = self.at(self.sigma_a(strand_color), fr.h).sample(fr.to_local(wo), u)?;
        Some((fr.to_world(s.wi), s.pdf))
    }
}

impl PhysicalHair {
    /// [`HairBsdf::pdf`] in world space (arguments as for [`PhysicalHair::response`]): the
    /// density with which [`PhysicalHair::sample`] picks `wi`, for multiple importance sampling.
    pub fn pdf(&self, strand_color: Option<Color>, tangent: Vec3, normal: Vec3, wo: Vec3, wi: Vec3) -> f32 {
        let fr = FibreFrame::new(tangent, normal, wo);
        self.at(self.sigma_a(strand_color), fr.h).pdf(fr.to_local(wo), fr.to_local(wi))
    }
}

/// The lobes' widths for roughnesses `beta_m` and `beta_n` in [0.001, 1]: the longitudinal
/// variance v_p per lobe, the log of each M_p's normalisation, the logistic scale s and
/// the inverse of its mass on [-π, π].
fn lobe_widths(beta_m: f32, beta_n: f32) -> ([f32; LOBES], [f32; LOBES], f32, f32) {
    // Chiang §4.1: the variance that makes β_m look alike for every lobe; TT is
    // narrower and TRT wider, following Marschner et al. 2003's lobe widths.
    let v0 = (0.726 * beta_m + 0.812 * beta_m.powi(2) + 3.7 * beta_m.powi(20)).powi(2);
    let v = [v0, 0.25 * v0, 4.0 * v0, 4.0 * v0];
    // 2 v sinh(1/v) = v e^(1/v) (1 - e^(-2/v)); its exponential part goes with I0 in
    // `longitudinal`, so neither overflows for small v.
    let ln_norm = v.map(|v| -v.ln() - (-(-2.0 / v).exp_m1()).ln());
    // Chiang §4.1: logistic scale from β_n.
    let s = (PI / 8.0).sqrt() * (0.265 * beta_n + 1.194 * beta_n.powi(2) + 5.372 * beta_n.powi(22));
    (v, ln_norm, s, 1.0 / (PI / (2.0 * s)).tanh())
}

/// The denominator of Chiang §4.2's colour inversion: a fit of how much a colour darkens per unit of √σ_a.
/// Chiang §4.2's polynomial in β_n relating a colour to σ_a.
pub fn color_polynomial(beta_n: f32) -> f32 {
    let b = beta_n;
    5.969 - 0.215 * b + 2.532 * b.powi(2) - 10.73 * b.powi(3) + 5.574 * b.powi(4) + 0.245 * b.powi(5)
}

/// Chiang §4.2: σ_a = (ln C / poly(β_n))², C clamped to [1e-4, 1] (a black or
/// brighter-than-white colour has no finite or meaningful σ_a).
pub fn sigma_a_from_color(color: Color, beta_n: f32) -> Color {
    let k = color_polynomial(beta_n);
    Color::from_array(color.to_array().map(|c| (c.clamp(1e-4, 1.0).ln() / k).powi(2)))
}

/// Chiang §4.2 inverted, C = exp(−√σ_a · poly(β_n)): the colour whose absorption is
/// `sigma_a` (what [`sigma_a_from_color`] turns back into it, down to its 1e-4 floor).
pub fn color_from_sigma_a(sigma_a: Color, beta_n: f32) -> Color {
    let k = color_polynomial(beta_n);
    Color::from_array(sigma_a.to_array().map(|s| (-s.max(0.0).sqrt() * k).exp()))
}

/// σ_a of the pigment concentrations (d'Eon §6.1, with Chiang §4.1's coefficients).
pub fn sigma_a_from_melanin(eumelanin: f32, pheomelanin: f32) -> Color {
    EUMELANIN_SIGMA_A * eumelanin + PHEOMELANIN_SIGMA_A * pheomelanin
}

/// The frame of a fibre at a hit, and the hit's offset `h` across the fibre.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FibreFrame {
    x: Vec3,
    y: Vec3,
    z: Vec3,
    /// Offset across the fibre, `sin γ_o`, in [-1, 1].
    pub h: f32,
}

impl FibreFrame {
    /// The frame with `tangent` as +x. `normal` is the fibre surface normal at the hit and
    /// `wo` points back along the camera ray; `h` is the sine of the signed angle from
    /// the normal to `wo` about +x, both projected on the normal plane (0 when either lies
    /// along the tangent).
    pub fn new(tangent: Vec3, normal: Vec3, wo: Vec3) -> FibreFrame {
        let x = tangent.normalize_or(Vec3::X);
        let (y, _) = frame(x);
        let z = x.cross(y);
        let n = (normal - x * normal.dot(x)).normalize_or_zero();
        let w = (wo - x * wo.dot(x)).normalize_or_zero();
        FibreFrame { x, y, z, h: x.dot(n.cross(w)).clamp(-1.0, 1.0) }
    }

    /// World direction to the local frame.
    pub fn to_local(&self, w: Vec3) -> Vec3 {
        Vec3::new(w.dot(self.x), w.dot(self.y), w.dot(self.z))
    }

    /// Local direction to world space.
    pub fn to_world(&self, w: Vec3) -> Vec3 {
        self.x * w.x + self.y * w.y + self.z * w.z
    }
}

/// The BSDF of one hit: the material, σ_a and the offset `h`. Directions are local
/// (see the module documentation) and need not be normalised exactly.
#[derive(Clone, Copy, Debug)]
pub struct HairBsdf<'a> {
    hair: &'a PhysicalHair,
    sigma_a: Color,
    h: f32,
}

/// Everything that depends on `wo` only.
struct Outgoing {
    /// (sin, cos) of θ_o shifted for each lobe's tilt.
    theta: [(f32, f32); LOBES],
    /// φ_o.
    phi_o: f32,
    /// Azimuthal lobe centres Φ(p, h) for R, TT, TRT.
    centre: [f32; 3],
    /// Attenuation A_p per lobe.
    a: [Color; LOBES],
    /// Probability of sampling each lobe.
    weight: [f32; LOBES],
}

impl HairBsdf<'_> {
    /// `f(wo, wi) |cos θ_i|`: the radiance towards `wo` per unit radiance arriving from
    /// `wi` per unit solid angle (the BSDF times the fibre's projected-area cosine, which
    /// stays finite where `f` alone diverges, at `wi = ±x`). Integrates over the sphere
    /// to the fibre's albedo: 1 without absorption.
    pub fn eval(&self, wo: Vec3, wi: Vec3) -> Color {
        let out = self.outgoing(wo);
        let d = self.densities(&out, wi);
        (0..LOBES).map(|p| out.a[p] * d[p]).sum()
    }

    /// Solid-angle density with which [`HairBsdf::sample`] picks `wi`.
    pub fn pdf(&self, wo: Vec3, wi: Vec3) -> f32 {
        let out = self.outgoing(wo);
        let d = self.densities(&out, wi);
        (0..LOBES).map(|p| out.weight[p] * d[p]).sum()
    }

    /// Samples `wi` from four uniform numbers in [0, 1): a lobe chosen by its attenuation,
    /// θ_i from its longitudinal lobe (d'Eon et al. 2013), φ_i from its logistic (uniform
    /// for the residual lobe). `None` when the fibre scatters nothing.
    pub fn sample(&self, wo: Vec3, u: [f32; 4]) -> Option<HairSample> {
        let out = self.outgoing(wo);
        let mut p = LOBES - 1;
        let mut cumulative = 0.0;
        for (i, w) in out.weight.iter().enumerate() {
            cumulative += w;
            if u[0] < cumulative {
                p = i;
                break;
            }
        }
        if out.weight[p] <= 0.0 {
            return None;
        }
        // θ_i: the lobe is a von Mises-Fisher distribution of concentration 1/v around the
        // mirror of the (shifted) outgoing direction, projected on the fibre axis
        // (d'Eon et al. 2013): sample the cosine c of the angle to that
        // direction, then an azimuth ψ about it.
        let v = self.hair.v[p];
        let (sin_o, cos_o) = out.theta[p];
        let u1 = u[1].max(1e-5);
        let c = (1.0 + v * (u1 + (1.0 - u1) * (-2.0 / v).exp()).ln()).clamp(-1.0, 1.0);
        let sin_c = (1.0 - c * c).max(0.0).sqrt();
        let sin_i = (-c * sin_o + sin_c * (TAU * u[2]).cos() * cos_o).clamp(-1.0, 1.0);
        let cos_i = (1.0 - sin_i * sin_i).max(0.0).sqrt();
        let dphi = match p {
            3 => TAU * u[3],
            _ => out.centre[p] + sample_trimmed_logistic(u[3], self.hair.s),
        };
        let (sp, cp) = (out.phi_o + dphi).sin_cos();
        let wi = Vec3::new(sin_i, cos_i * cp, cos_i * sp);
        let d = self.densities(&out, wi);
        let pdf: f32 = (0..LOBES).map(|q| out.weight[q] * d[q]).sum();
        let value: Color = (0..LOBES).map(|q| out.a[q] * d[q]).sum();
        (pdf > 0.0 && pdf.is_finite()).then_some(HairSample { wi, value, pdf })
    }

    fn outgoing(&self, wo: Vec3) -> Outgoing {
        let eta = self.hair.params.eta;
        let h = self.h;
        let sin_o = wo.x.clamp(-1.0, 1.0);
        let cos_o = (1.0 - sin_o * sin_o).max(0.0).sqrt();
        let phi_o = wo.z.atan2(wo.y);
        // Inside the fibre: Bravais' index η' = sqrt(η² - sin²θ_o) / cos θ_o for the
        // projected refraction (Marschner et al. 2003), so sin γ_t = h / η', written
        // without the division by cos θ_o that fails along the tangent.
        let gamma_o = h.asin();
        let sin_gt = (h * cos_o / (eta * eta - sin_o * sin_o).max(1e-12).sqrt()).clamp(-1.0, 1.0);
        let gamma_t = sin_gt.asin();
        let cos_gt = (1.0 - sin_gt * sin_gt).max(0.0).sqrt();
        let sin_t = sin_o / eta;
        let cos_t = (1.0 - sin_t * sin_t).max(1e-12).sqrt();
        // One crossing of the fibre (radius 1) is 2 cos γ_t / cos θ_t long (Chiang §3).
        // A grazing hit (|h| = 1) crosses nothing: no absorption, even if σ_a is infinite.
        let length = 2.0 * cos_gt / cos_t;
        let transmittance = if length > 0.0 { (-self.sigma_a * length).exp() } else { Color::ONE };
        // Fresnel at the real angle of incidence, cos = cos θ_o cos γ_o (Chiang §3).
        let f = fresnel_dielectric(cos_o * (1.0 - h * h).max(0.0).sqrt(), eta);
        // Chiang §3: A_0 = f, A_p = (1 - f)² f^(p-1) T^p, and the residual sums
        // the geometric series of all p >= 3.
        let a0 = Color::splat(f);
        let a1 = transmittance * (1.0 - f) * (1.0 - f);
        let a2 = a1 * transmittance * f;
        let residual = Color::from_array([0, 1, 2].map(|k| {
            let ft = f * transmittance[k];
            if ft < 1.0 {
                a2[k] * ft / (1.0 - ft)
            } else {
                0.0 // only when f = 1, where (1 - f)² makes every A_p >= 1 vanish
            }
        }));
        let a = [a0, a1, a2, residual];
        let mean = a.map(|c| c.element_sum() / 3.0);
        let total: f32 = mean.iter().sum();
        let weight = if total > 0.0 { mean.map(|m| m / total) } else { [0.0; LOBES] };
        let mut theta = [(sin_o, cos_o); LOBES];
        for (t, (ss, cs)) in theta.iter_mut().zip(self.hair.shift) {
            // sin and cos of θ_o + shift; |cos| keeps a lobe shifted past the pole valid.
            *t = (sin_o * cs + cos_o * ss, (cos_o * cs - sin_o * ss).abs());
        }
        // Chiang §3 (after Marschner et al. 2003): the exit azimuth after p internal
        // paths, Φ(p, h) = 2 p γ_t - 2 γ_o + p π.
        let centre = [0.0, 1.0, 2.0].map(|p| 2.0 * p * gamma_t - 2.0 * gamma_o + p * PI);
        Outgoing { theta, phi_o, centre, a, weight }
    }

    /// `M_p(θ_o, θ_i) N_p(φ)` for each lobe: each one a density over the sphere.
    fn densities(&self, out: &Outgoing, wi: Vec3) -> [f32; LOBES] {
        let sin_i = wi.x.clamp(-1.0, 1.0);
        let cos_i = (1.0 - sin_i * sin_i).max(0.0).sqrt();
        let phi = wi.z.atan2(wi.y) - out.phi_o;
        let mut d = [0.0; LOBES];
        for (p, dp) in d.iter_mut().enumerate() {
            let (sin_o, cos_o) = out.theta[p];
            let m = longitudinal(self.hair.v[p], self.hair.ln_norm[p], sin_i, cos_i, sin_o, cos_o);
            let n = match p {
                3 => 1.0 / TAU, // Chiang §3: the residual lobe is azimuthally uniform
                _ => logistic(wrap_angle(phi - out.centre[p]), self.hair.s) * self.hair.trim,
            };
            *dp = m * n;
        }
        d
    }
}

/// d'Eon's normalised longitudinal lobe
/// `M = csch(1/v) / (2v) exp(-sin θ_i sin θ_o / v) I0(cos θ_i cos θ_o / v)`,
/// in log space so that small variances neither overflow I0 nor sinh:
/// `ln M = ln(I0(a) e^-a) + (cos(θ_i + θ_o) - 1) / v + ln_norm`, with `a = cos θ_i cos θ_o / v`
/// and `ln_norm = -ln v - ln(1 - e^(-2/v))`.
fn longitudinal(v: f32, ln_norm: f32, sin_i: f32, cos_i: f32, sin_o: f32, cos_o: f32) -> f32 {
    let a = cos_i * cos_o / v;
    (ln_i0_scaled(a) + (cos_i * cos_o - sin_i * sin_o - 1.0) / v + ln_norm).exp()
}

/// `ln(I0(x) e^-x)` for x >= 0: the polynomial fits of Abramowitz and Stegun 9.8.1 (x below
/// 3.75, error 1.6e-7) and 9.8.2 (above, relative error 1.9e-7), the second written for
/// `sqrt(x) e^-x I0(x)` so that it never overflows.
fn ln_i0_scaled(x: f32) -> f32 {
    if x < 3.75 {
        let t = (x / 3.75) * (x / 3.75);
        let i0 = 1.0
            + t * (3.515_622_9
                + t * (3.089_942_4 + t * (1.206_749_2 + t * (0.265_973_2 + t * (0.036_076_8 + t * 0.004_581_3)))));
        i0.ln() - x
    } else {
        let t = 3.75 / x;
        let p = 0.398_942_3
            + t * (0.013_285_92
                + t * (0.002_253_19
                    + t * (-0.001_575_65
                        + t * (0.009_162_81
                            + t * (-0.020_577_06 + t * (0.026_355_37 + t * (-0.016_476_33 + t * 0.003_923_77)))))));
        p.ln() - 0.5 * x.ln()
    }
}

/// The logistic density of scale `s` (Chiang §4.1), written with e^(-|x|/s) so that it
/// cannot overflow. Chiang restricts it to [-π, π] and renormalises it ("trimmed").
fn logistic(x: f32, s: f32) -> f32 {
    let e = (-x.abs() / s).exp();
    e / (s * (1.0 + e) * (1.0 + e))
}

/// Inverts the trimmed logistic's distribution function at `u`.
fn sample_trimmed_logistic(u: f32, s: f32) -> f32 {
    let cdf = |x: f32| 1.0 / (1.0 + (-x / s).exp());
    let (lo, hi) = (cdf(-PI), cdf(PI));
    let q = lo + u * (hi - lo);
    (-s * (1.0 / q - 1.0).ln()).clamp(-PI, PI)
}

/// The angle in [-π, π] equal to `x` modulo 2π.
fn wrap_angle(x: f32) -> f32 {
    x - TAU * (x / TAU).round()
}

#[cfg(test)]
mod tests;
