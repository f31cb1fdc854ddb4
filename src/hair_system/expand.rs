//! Expanding guides into render hairs: each guide becomes a clump of `hairs_per_clump`
//! hairs (thesis section 2.1.3; docs/maya-fur-hair.md section 5.5).
//!
//! For each guide:
//! 1. **Sub-segments**: the guide is refined with a uniform Catmull-Rom spline (Catmull and
//!    Rom 1974), a cubic Hermite curve whose tangent at a point is half the chord between
//!    its neighbours (one-sided at the ends): `sub_segments` new points per segment, and
//!    the curve passes through every guide point (Maya: "hermite interpolation").
//! 2. **Frames**: a frame `(U, V)` perpendicular to the guide is carried along it by
//!    parallel transport (Hanson and Ma 1995, "Parallel Transport Approach to Curve
//!    Framing"), starting from a frame around the root direction (the surface normal for
//!    follicles).
//! 3. **Clump**: each hair draws a point of the unit disk (uniform, Shirley and Chiu's
//!    concentric map). Along the hair that point is squashed by `clump_flatness(s)`, turned
//!    by `clump_twist` plus the integral of the clump curl, and scaled to the clump radius
//!    `clump_width × clump_width_scale(s) / 2`; it is placed in the transported frame
//!    (weight `bend_follow`) and in the root frame (weight `1 − bend_follow`).
//! 4. **Curl and noise**: a helix of radius `curl × hair_width × displacement_scale(s)`
//!    with `curl_frequency` turns per hair, and Perlin noise (Perlin 2002, "Improving
//!    Noise") of amplitude `noise × hair_width × displacement_scale(s)`, both across the
//!    hair in the transported frame.
//! 5. **Thinning**: a `thinning` fraction of hairs ends at a uniformly random fraction of
//!    the guide's length (a cut point is interpolated there).
//! 6. **Width and colour**: radius `hair_width × hair_width_scale(s) / 2`; colour
//!    `base × hair_color_scale(s)` with the per-hair randomisation.
//!
//! `s` is the normalised arc length along the refined guide (0 root, 1 tip) for every hair
//! of the clump, so a thinned hair is its full-length sibling cut short. Each hair's random
//! numbers come from (seed, guide, hair), guides are expanded in parallel and concatenated
//! in guide order: the result does not depend on the thread count.

use super::color::Jitter;
use super::{Guides, HairSystem, NoiseMethod};
use crate::geometry::{StrandInfo, StrandSet};
use crate::math::noise::{perlin, Perlin};
use crate::math::rng::{hash_combine, GenRng};
use crate::math::{frame, sampling};
use glam::{Quat, Vec3};
use rand::{Rng, SeedableRng};
use rayon::prelude::*;
use std::f32::consts::TAU;

/// Most render points one hair system may create (32 bytes or so each with colours).
pub const MAX_RENDER_POINTS: u64 = 100_000_000;

/// Clump-curl winding rate at a ramp value of 0 or 1, in turns per hair length.
const CLUMP_CURL_TURNS: f32 = 5.0;
/// Noise features per hair length (and across the UV square or a clump) per unit of
/// `noise_frequency`: Maya's default 0.4 gives four.
const NOISE_FEATURES: f32 = 10.0;
/// Period of the noise lattice: per-hair and per-clump offsets are drawn in [0, this).
const NOISE_PERIOD: f32 = 256.0;

/// Where the render hairs' per-point colours come from.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum HairColors {
    /// `hair_color × hair_color_scale(s)`, randomised per hair.
    #[default]
    System,
    /// The guides' own per-point colours (a `.hair` file's colour array) instead of
    /// `hair_color`, then scaled and randomised the same way.
    Guides,
    /// No per-point colours: the material's colour.
    Material,
}

/// Expands `guides` into render hairs. Guides with fewer than two points or no length
/// give no hairs. Strand `g × hairs_per_clump + h` is hair `h` of guide `g` (until a guide
/// gives none); its [`StrandInfo`] clump is `g` and its root UV the guide's (none for
/// guides without a surface).
pub fn expand(system: &HairSystem, guides: &Guides, colors: HairColors, seed: u32) -> Result<StrandSet, String> {
    system.validate()?;
    let curves = &guides.curves;
    let count = curves.strand_count();
    if let Some(uv) = &guides.root_uv {
        if uv.len() != count {
            return Err(format!("{} root UVs for {count} guides", uv.len()));
        }
    }
    if system.noise > 0.0 && system.noise_method == NoiseMethod::SurfaceUv && guides.root_uv.is_none() {
        return Err("`noise_method = \"surface_uv\"` needs guides grown on a surface (follicles)".into());
    }
    if colors == HairColors::Guides && curves.colors.is_none() {
        return Err(
            "`colors = \"guides\"` needs guides with per-point colours (a .hair file with a colour array)".into()
        );
    }
    let steps = system.sub_segments as u64 + 1;
    let points: u64 =
        curves.offsets.windows(2).map(|w| ((w[1] - w[0]) as u64).saturating_sub(1) * steps + 2).sum::<u64>()
            * system.hairs_per_clump as u64;
    if points > MAX_RENDER_POINTS {
        return Err(format!(
            "{count} guides x {} hairs per clump would make {points} render points (at most {MAX_RENDER_POINTS})",
            system.hairs_per_clump
        ));
    }
    let noise = perlin(hash_combine(&[seed, 0x6e6f_6973]));
    let clumps: Vec<StrandSet> =
        (0..count as u32).into_par_iter().map(|g| expand_guide(system, guides, g, colors, seed, &noise)).collect();
    let mut out = StrandSet::new();
    let oom = |e: crate::memory::OutOfMemory| e.to_string();
    crate::memory::try_reserve(&mut out.points, points as usize, "the hair system's points").map_err(oom)?;
    crate::memory::try_reserve(&mut out.offsets, count * system.hairs_per_clump as usize, "the hair system's hairs")
        .map_err(oom)?;
    for c in &clumps {
        out.append(c);
    }
    Ok(out)
}

/// A guide refined and framed: everything the hairs of its clump share, per point.
struct Clump {
    /// Refined guide points.
    p: Vec<Vec3>,
    /// Normalised arc length.
    s: Vec<f32>,
    /// Transported frame.
    u: Vec<Vec3>,
    v: Vec<Vec3>,
    /// Cross-section angle: twist plus integrated clump curl.
    angle: Vec<f32>,
    /// Base colour (before the colour-scale ramp and jitter).
    color: Vec<Vec3>,
}

impl Clump {
    fn new(system: &HairSystem, guide: &[Vec3], colors: &[Vec3]) -> Option<Clump> {
        let (p, seg) = refine(guide, system.sub_segments);
        let mut s = Vec::with_capacity(p.len());
        let mut total = 0.0;
        s.push(0.0);
        for w in p.windows(2) {
            total += (w[1] - w[0]).length();
            s.push(total);
        }
        if !(total > 0.0 && total.is_finite()) {
            return None;
        }
        s.iter_mut().for_each(|x| *x /= total);
        let n = p.len();
        let mut t = Vec::with_capacity(n);
        for k in 0..n {
            let d = p[(k + 1).min(n - 1)] - p[k.saturating_sub(1)];
            t.push(d.try_normalize().unwrap_or_else(|| t.last().copied().unwrap_or(Vec3::Y)));
        }
        let (mut u, mut v) = (Vec::with_capacity(n), Vec::with_capacity(n));
        let (u0, _) = frame(t[0]);
        u.push(u0);
        v.push(t[0].cross(u0));
        for k in 1..n {
            let moved = Quat::from_rotation_arc(t[k - 1], t[k]) * u[k - 1];
            let uk = (moved - t[k] * t[k].dot(moved)).try_normalize().unwrap_or_else(|| frame(t[k]).0);
            u.push(uk);
            v.push(t[k].cross(uk));
        }
        let mut angle = Vec::with_capacity(n);
        angle.push(TAU * system.clump_twist);
        for k in 1..n {
            let rate = |x: f32| TAU * 2.0 * CLUMP_CURL_TURNS * (system.clump_curl.eval(x) - 0.5);
            let ds = s[k] - s[k - 1];
            angle.push(angle[k - 1] + 0.5 * (rate(s[k - 1]) + rate(s[k])) * ds);
        }
        let color = match colors {
            [] => vec![system.hair_color; n],
            c => seg.iter().map(|&(j, f)| c[j].lerp(c[(j + 1).min(c.len() - 1)], f)).collect(),
        };
        Some(Clump { p, s, u, v, angle, color })
    }

    /// The clump's quantities at parameter `f` between refined points `k` and `k + 1`.
    fn at(&self, k: usize, f: f32) -> (Vec3, f32, Vec3, Vec3, f32, Vec3) {
        if f == 0.0 {
            return (self.p[k], self.s[k], self.u[k], self.v[k], self.angle[k], self.color[k]);
        }
        let lerp = |a: f32, b: f32| a + (b - a) * f;
        let u = self.u[k].lerp(self.u[k + 1], f).normalize_or(self.u[k]);
        let v = self.v[k].lerp(self.v[k + 1], f).normalize_or(self.v[k]);
        (
            self.p[k].lerp(self.p[k + 1], f),
            lerp(self.s[k], self.s[k + 1]),
            u,
            v,
            lerp(self.angle[k], self.angle[k + 1]),
            self.color[k].lerp(self.color[k + 1], f),
        )
    }
}

/// Uniform Catmull-Rom refinement: `sub` points inserted per segment. Returns the points
/// and, for each, the guide segment and the fraction along it (for interpolating colours).
pub fn refine(p: &[Vec3], sub: u32) -> (Vec<Vec3>, Vec<(usize, f32)>) {
    let n = p.len();
    let steps = sub as usize + 1;
    let mut out = Vec::with_capacity((n - 1) * steps + 1);
    let mut seg = Vec::with_capacity(out.capacity());
    let tangent = |i: usize| match i {
        0 => p[1] - p[0],
        i if i == n - 1 => p[n - 1] - p[n - 2],
        i => 0.5 * (p[i + 1] - p[i - 1]),
    };
    for j in 0..n - 1 {
        let (m0, m1) = (tangent(j), tangent(j + 1));
        for k in 0..steps {
            let t = k as f32 / steps as f32;
            let (t2, t3) = (t * t, t * t * t);
            out.push(
                p[j] * (2.0 * t3 - 3.0 * t2 + 1.0)
                    + m0 * (t3 - 2.0 * t2 + t)
                    + p[j + 1] * (3.0 * t2 - 2.0 * t3)
                    + m1 * (t3 - t2),
            );
            seg.push((j, t));
        }
    }
    out.push(p[n - 1]);
    seg.push((n - 1, 0.0));
    (out, seg)
}

/// The render hairs of guide `g`.
fn expand_guide(
    system: &HairSystem,
    guides: &Guides,
    g: u32,
    colors: HairColors,
    seed: u32,
    noise: &Perlin,
) -> StrandSet {
    let curves = &guides.curves;
    let (a, b) = (curves.offsets[g as usize] as usize, curves.offsets[g as usize + 1] as usize);
    let guide: Vec<Vec3> = (a..b).map(|i| curves.position(i as u32)).collect();
    let guide_colors = match (colors, &curves.colors) {
        (HairColors::Guides, Some(c)) => c[a..b].iter().map(|&c| Vec3::from(c)).collect(),
        _ => Vec::new(),
    };
    let mut out = StrandSet::new();
    if colors != HairColors::Material {
        out.colors = Some(Vec::new());
    }
    if system.opacity < 1.0 {
        out.opacity = Some(Vec::new());
    }
    let mut info = StrandInfo::default();
    let clump = if guide.len() >= 2 { Clump::new(system, &guide, &guide_colors) } else { None };
    if let Some(clump) = clump {
        let root_uv = guides.root_uv.as_ref().map(|uv| uv[g as usize]);
        let mut clump_rng = GenRng::seed_from_u64(hash_combine(&[seed, g, u32::MAX]) as u64);
        let clump_offset = [clump_rng.random::<f32>() * NOISE_PERIOD, clump_rng.random::<f32>() * NOISE_PERIOD];
        for h in 0..system.hairs_per_clump {
            let mut rng = GenRng::seed_from_u64(hash_combine(&[seed, g, h]) as u64);
            let hair = Hair::draw(&mut rng, system);
            let noise_base = match system.noise_method {
                NoiseMethod::Random => hair.noise_offset,
                NoiseMethod::SurfaceUv => {
                    // Checked above: surface-UV noise needs the guides' UVs.
                    let root_uv = root_uv.unwrap_or_default();
                    [root_uv[0] * system.noise_frequency_u, root_uv[1] * system.noise_frequency_v]
                        .map(|x| x * system.noise_frequency * NOISE_FEATURES)
                }
                NoiseMethod::ClumpUv => {
                    let d = [hair.disk.0 * system.noise_frequency_u, hair.disk.1 * system.noise_frequency_v];
                    [0, 1].map(|i| clump_offset[i] + d[i] * system.noise_frequency * NOISE_FEATURES)
                }
            };
            let mut points = Vec::with_capacity(clump.p.len() + 1);
            let mut hair_colors = Vec::with_capacity(clump.p.len() + 1);
            for k in 0..clump.p.len() {
                if clump.s[k] > hair.end {
                    // Cut between k - 1 and k, where s = end.
                    let f = (hair.end - clump.s[k - 1]) / (clump.s[k] - clump.s[k - 1]);
                    if f > 0.0 {
                        let at = clump.at(k - 1, f);
                        let (pt, c) = hair_point(system, &at, &hair, noise_base, noise, clump.u[0], clump.v[0]);
                        points.push(pt);
                        hair_colors.push(c);
                    }
                    break;
                }
                let (pt, c) = hair_point(system, &clump.at(k, 0.0), &hair, noise_base, noise, clump.u[0], clump.v[0]);
                points.push(pt);
                hair_colors.push(c);
            }
            if let Some(c) = &mut out.colors {
                c.extend(hair_colors.iter().map(|c| c.to_array()));
            }
            if let Some(o) = &mut out.opacity {
                o.extend(std::iter::repeat_n(system.opacity, points.len()));
            }
            out.push_strand(points);
            // Without the guides' UVs the strands have none (rather than a made-up one
            // that would texture them).
            info.root_uv.extend(root_uv);
            info.clump.push(g);
        }
    }
    out.strand_info = Some(info);
    out
}

/// One hair's random choices, drawn in a fixed order from its own stream.
struct Hair {
    /// Point of the unit disk: its place in the clump's cross-section.
    disk: (f32, f32),
    /// Where it ends, as a fraction of the guide's length.
    end: f32,
    /// Phase of its curl helix.
    phase: f32,
    /// Its own offset into the noise lattice (random noise method).
    noise_offset: [f32; 2],
    jitter: Jitter,
}

impl Hair {
    fn draw(rng: &mut GenRng, sys: &HairSystem) -> Hair {
        let disk = sampling::concentric_disk(rng.random(), rng.random());
        let thinned = rng.random::<f32>() < sys.thinning;
        let cut = rng.random::<f32>();
        let phase = rng.random::<f32>() * TAU;
        let noise_offset = [rng.random::<f32>() * NOISE_PERIOD, rng.random::<f32>() * NOISE_PERIOD];
        let u = [rng.random(), rng.random(), rng.random(), rng.random()];
        let jitter = Jitter::new(u, sys.diffuse_rand, sys.hue_rand, sys.sat_rand, sys.val_rand);
        Hair { disk, end: if thinned { cut } else { 1.0 }, phase, noise_offset, jitter }
    }
}

/// A render hair's point (with radius) and colour at one place along its clump.
fn hair_point(
    sys: &HairSystem,
    &(guide, s, u, v, angle, base): &(Vec3, f32, Vec3, Vec3, f32, Vec3),
    hair: &Hair,
    noise_base: [f32; 2],
    noise: &Perlin,
    u0: Vec3,
    v0: Vec3,
) -> ((Vec3, f32), Vec3) {
    let radius = 0.5 * sys.clump_width * sys.clump_width_scale.eval(s);
    let (x, y) = (hair.disk.0, hair.disk.1 * (1.0 - sys.clump_flatness.eval(s)));
    let (sin, cos) = angle.sin_cos();
    let (x, y) = (radius * (x * cos - y * sin), radius * (x * sin + y * cos));
    let mut p = guide + sys.bend_follow * (x * u + y * v) + (1.0 - sys.bend_follow) * (x * u0 + y * v0);
    let displacement = sys.hair_width * sys.displacement_scale.eval(s);
    if sys.curl > 0.0 {
        let (sin, cos) = (hair.phase + TAU * sys.curl_frequency * s).sin_cos();
        p += sys.curl * displacement * (cos * u + sin * v);
    }
    if sys.noise > 0.0 {
        let w = s * sys.noise_frequency * sys.noise_frequency_w * NOISE_FEATURES;
        let [nx, ny] = noise_base;
        let n1 = noise.get_noise_3d(nx, ny, w);
        // A second lattice region, far from the first, for the other direction.
        let n2 = noise.get_noise_3d(nx + 101.5, ny + 57.25, w + 33.75);
        p += sys.noise * displacement * (n1 * u + n2 * v);
    }
    let width = 0.5 * sys.hair_width * sys.hair_width_scale.eval(s);
    let color = hair.jitter.apply(base * sys.hair_color_scale.eval(s));
    ((p, width), color)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::hair_system::ramp::{Interp, Ramp, RampKey};
    use crate::math::Color;

    /// `n` guides: straight up (even ones) or bending over in a quarter circle (odd ones),
    /// `points` points each, spaced along x.
    fn guides(n: u32, points: u32) -> Guides {
        let mut curves = StrandSet::new();
        for g in 0..n {
            let x = g as f32 * 2.0;
            curves.push_strand((0..points).map(|k| {
                let t = k as f32 / (points - 1) as f32;
                let p = if g % 2 == 0 {
                    Vec3::new(x, t, 0.0)
                } else {
                    let a = t * std::f32::consts::FRAC_PI_2;
                    Vec3::new(x + 1.0 - a.cos(), a.sin(), 0.0)
                };
                (p, 0.0)
            }));
        }
        Guides::from_curves(curves)
    }

    fn linear(keys: &[(f32, f32)]) -> Ramp<f32> {
        Ramp::new(keys.iter().map(|&(position, value)| RampKey { position, value, interp: Interp::Linear }).collect())
            .unwrap()
    }

    fn strand(set: &StrandSet, i: usize) -> Vec<Vec3> {
        (set.offsets[i]..set.offsets[i + 1]).map(|k| set.position(k)).collect()
    }

    #[test]
    fn clump_hairs_stay_within_the_clump_width_of_their_guide() {
        let g = guides(4, 12);
        for (bend_follow, flatness, curl) in [(1.0, 0.0, 0.5), (0.0, 0.0, 0.9), (0.4, 0.7, 0.2)] {
            let sys = HairSystem {
                hairs_per_clump: 200,
                clump_width: 0.3,
                clump_width_scale: linear(&[(0.0, 1.0), (1.0, 0.2)]),
                clump_twist: 0.3,
                clump_curl: Ramp::constant(curl),
                clump_flatness: Ramp::constant(flatness),
                bend_follow,
                ..Default::default()
            };
            let out = expand(&sys, &g, HairColors::System, 1).unwrap();
            assert_eq!(out.strand_count(), 800);
            let mut widest = 0.0f32;
            for h in 0..out.strand_count() {
                let guide = strand(&g.curves, h / 200);
                let hair = strand(&out, h);
                assert_eq!(hair.len(), guide.len());
                for (k, (p, q)) in hair.iter().zip(&guide).enumerate() {
                    let s = k as f32 / 11.0;
                    let limit = 0.5 * 0.3 * (1.0 - 0.8 * s);
                    let d = (*p - *q).length();
                    assert!(d <= limit * 1.0001 + 1e-6, "hair {h} point {k}: {d} > {limit}");
                    widest = widest.max(d / limit);
                }
            }
            // The hairs fill the clump, not just its middle.
            assert!(widest > 0.95, "{widest}");
        }
    }

    #[test]
    fn clump_curl_winds_hairs_about_the_guide_by_the_documented_rate() {
        // A straight guide: the transported frame is constant, so the offset turns by the
        // integrated curl alone. 0.75 everywhere: 2.5 turns root to tip, tip offset = -root.
        let g = guides(1, 41);
        for (curl, sign) in [(0.75, -1.0), (0.5, 1.0), (1.0, 1.0)] {
            let sys = HairSystem { hairs_per_clump: 5, clump_curl: Ramp::constant(curl), ..Default::default() };
            let out = expand(&sys, &g, HairColors::Material, 3).unwrap();
            for h in 0..5 {
                let hair = strand(&out, h);
                let root = hair[0] - Vec3::ZERO;
                let tip = hair[40] - Vec3::Y;
                assert!((tip - sign * root).length() < 1e-3 * root.length().max(1e-3), "curl {curl}: {root} {tip}");
            }
        }
    }

    #[test]
    fn thinning_shortens_the_given_fraction() {
        let g = guides(500, 8);
        for thinning in [0.0, 0.3, 1.0] {
            let sys = HairSystem { hairs_per_clump: 20, thinning, clump_width: 0.0, ..Default::default() };
            let out = expand(&sys, &g, HairColors::Material, 9).unwrap();
            assert_eq!(out.strand_count(), 10_000);
            let mut short = 0;
            let mut lengths = 0.0;
            for h in 0..out.strand_count() {
                let guide = strand(&g.curves, h / 20);
                let hair = strand(&out, h);
                let full = (*hair.last().unwrap() - *guide.last().unwrap()).length() < 1e-5;
                if !full {
                    short += 1;
                    let len: f32 = hair.windows(2).map(|w| (w[1] - w[0]).length()).sum();
                    let total: f32 = guide.windows(2).map(|w| (w[1] - w[0]).length()).sum();
                    lengths += len / total;
                }
            }
            // Binomial: sigma = sqrt(n p (1 - p)) = 45.8 at p = 0.3.
            let expected = thinning * 10_000.0;
            assert!((short as f32 - expected).abs() <= 4.0 * 45.9, "thinning {thinning}: {short} short hairs");
            if short > 0 {
                // Cut at a uniform fraction: mean 1/2, sigma of the mean < 0.3 / sqrt(3000).
                let mean = lengths / short as f32;
                assert!((mean - 0.5).abs() < 0.03, "mean length {mean}");
            }
        }
    }

    #[test]
    fn sub_segments_interpolate_through_the_guide_points() {
        // Points on a unit circle: the refined curve passes through them and stays much
        // closer to the circle than the chords do.
        let guide: Vec<Vec3> = (0..9)
            .map(|k| {
                let a = k as f32 * 0.4;
                Vec3::new(a.cos(), a.sin(), 0.0)
            })
            .collect();
        for sub in [1, 3, 7] {
            let (p, seg) = refine(&guide, sub);
            assert_eq!(p.len(), 8 * (sub as usize + 1) + 1);
            for (j, q) in guide.iter().enumerate() {
                assert_eq!(p[j * (sub as usize + 1)], *q, "guide point {j}");
                assert_eq!(seg[j * (sub as usize + 1)], (j, 0.0));
            }
            // Chord midpoints are 1 - cos(0.2) = 0.0199 inside; interior spans of the
            // spline stay within 0.002 (the one-sided end tangents are less accurate).
            for q in &p[sub as usize + 1..p.len() - sub as usize - 1] {
                assert!((q.length() - 1.0).abs() < 0.002, "{}", q.length());
            }
        }
        // Render hairs get the refined points.
        let sys = HairSystem { hairs_per_clump: 2, sub_segments: 3, clump_width: 0.0, ..Default::default() };
        let mut curves = StrandSet::new();
        curves.push_strand(guide.iter().map(|&p| (p, 0.0)));
        let out = expand(&sys, &Guides::from_curves(curves), HairColors::Material, 0).unwrap();
        let hair = strand(&out, 1);
        assert_eq!(hair.len(), 33);
        for (j, q) in guide.iter().enumerate() {
            assert!((hair[4 * j] - *q).length() < 1e-6);
        }
    }

    #[test]
    fn widths_colours_and_strand_info_follow_the_attributes() {
        let mut g = guides(3, 11);
        g.root_uv = Some(vec![[0.1, 0.2], [0.3, 0.4], [0.5, 0.6]]);
        let sys = HairSystem {
            hairs_per_clump: 4,
            hair_width: 0.02,
            hair_width_scale: linear(&[(0.0, 1.0), (1.0, 0.5)]),
            hair_color: Color::new(0.4, 0.2, 0.1),
            hair_color_scale: Ramp::new(vec![
                RampKey { position: 0.0, value: Vec3::splat(0.5), interp: Interp::Linear },
                RampKey { position: 1.0, value: Vec3::ONE, interp: Interp::Linear },
            ])
            .unwrap(),
            diffuse_rand: 0.0,
            opacity: 0.5,
            ..Default::default()
        };
        let out = expand(&sys, &g, HairColors::System, 0).unwrap();
        let colors = out.colors.as_ref().unwrap();
        for h in 0..out.strand_count() {
            let first = out.offsets[h] as usize;
            for k in 0..11 {
                let s = k as f32 / 10.0;
                assert!((out.points[first + k][3] - 0.01 * (1.0 - 0.5 * s)).abs() < 1e-6);
                let want = Vec3::new(0.4, 0.2, 0.1) * (0.5 + 0.5 * s);
                assert!((Vec3::from(colors[first + k]) - want).length() < 1e-5);
            }
        }
        assert!(out.opacity.as_ref().unwrap().iter().all(|&o| o == 0.5));
        let info = out.strand_info.as_ref().unwrap();
        assert_eq!(info.clump, vec![0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2]);
        assert_eq!(info.root_uv[5], [0.3, 0.4]);
        // Brightness randomisation: per hair, within ± diffuse_rand, and not all equal.
        let sys = HairSystem { diffuse_rand: 0.2, hairs_per_clump: 50, ..sys };
        let out = expand(&sys, &g, HairColors::System, 0).unwrap();
        let roots: Vec<f32> = (0..out.strand_count())
            .map(|h| out.colors.as_ref().unwrap()[out.offsets[h] as usize][0] / (0.4 * 0.5))
            .collect();
        assert!(roots.iter().all(|&b| (0.8 - 1e-5..=1.2 + 1e-5).contains(&b)));
        assert!(roots.iter().any(|&b| b < 0.9) && roots.iter().any(|&b| b > 1.1));
        assert!(expand(&sys, &g, HairColors::Material, 0).unwrap().colors.is_none());
    }

    #[test]
    fn curl_and_noise_displace_by_their_documented_amounts() {
        let g = guides(2, 30);
        let base = HairSystem { hairs_per_clump: 6, clump_width: 0.2, ..Default::default() };
        let plain = expand(&base, &g, HairColors::Material, 5).unwrap();
        // Curl: a helix of radius curl x hair_width about the clumped hair.
        let curly = expand(&HairSystem { curl: 3.0, ..base.clone() }, &g, HairColors::Material, 5).unwrap();
        for (p, q) in plain.points.iter().zip(&curly.points) {
            let d = (Vec3::from_slice(p) - Vec3::from_slice(q)).length();
            assert!((d - 0.03).abs() < 1e-4, "{d}");
        }
        for method in [NoiseMethod::Random, NoiseMethod::ClumpUv] {
            let sys = HairSystem { noise: 4.0, noise_method: method, ..base.clone() };
            let noisy = expand(&sys, &g, HairColors::Material, 5).unwrap();
            let d: Vec<f32> = plain
                .points
                .iter()
                .zip(&noisy.points)
                .map(|(p, q)| (Vec3::from_slice(p) - Vec3::from_slice(q)).length())
                .collect();
            // Each of the two noise components is within [-1, 1]: at most sqrt(2) x 0.04.
            assert!(d.iter().all(|&d| d <= 0.0566), "{method:?}");
            assert!(d.iter().sum::<f32>() / d.len() as f32 > 0.004, "{method:?}: noise had no effect");
        }
    }

    #[test]
    fn same_hair_on_any_number_of_threads_and_a_new_seed_changes_it() {
        let mut g = guides(40, 10);
        g.root_uv = Some((0..40).map(|i| [i as f32 / 40.0, 0.5]).collect());
        let sys = HairSystem {
            hairs_per_clump: 30,
            sub_segments: 2,
            thinning: 0.4,
            curl: 1.0,
            noise: 2.0,
            noise_method: NoiseMethod::SurfaceUv,
            hue_rand: 0.2,
            ..Default::default()
        };
        let run = |threads: usize, seed: u32| {
            let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
            pool.install(|| expand(&sys, &g, HairColors::System, seed).unwrap())
        };
        let one = run(1, 4);
        assert_eq!(one, run(2, 4));
        assert_eq!(one, run(3, 4));
        assert_ne!(one.points, run(2, 5).points);
    }

    #[test]
    fn bad_input_is_a_clear_error() {
        let g = guides(2, 5);
        let e = expand(&HairSystem { thinning: f32::NAN, ..Default::default() }, &g, HairColors::System, 0);
        assert!(e.unwrap_err().contains("thinning"));
        let huge = HairSystem { hairs_per_clump: 100_000, sub_segments: 64, ..Default::default() };
        let e = expand(&huge, &guides(100, 50), HairColors::System, 0).unwrap_err();
        assert!(e.contains("render points"), "{e}");
        let e = expand(
            &HairSystem { noise: 1.0, noise_method: NoiseMethod::SurfaceUv, ..Default::default() },
            &g,
            HairColors::System,
            0,
        );
        assert!(e.unwrap_err().contains("surface_uv"));
        assert!(expand(&HairSystem::default(), &g, HairColors::Guides, 0).unwrap_err().contains("colours"));
        // Degenerate guides (one point, or all points equal) give no hairs but keep numbering.
        let mut curves = StrandSet::new();
        curves.push_strand([(Vec3::ZERO, 0.0)]);
        curves.push_strand([(Vec3::ONE, 0.0), (Vec3::ONE, 0.0)]);
        curves.push_strand([(Vec3::ZERO, 0.0), (Vec3::Y, 0.0)]);
        let out = expand(&HairSystem::default(), &Guides::from_curves(curves), HairColors::System, 0).unwrap();
        assert_eq!(out.strand_count(), 10);
        assert!(out.strand_info.unwrap().clump.iter().all(|&c| c == 2));
        assert_eq!(out.colors.unwrap().len(), out.points.len());
    }
}
