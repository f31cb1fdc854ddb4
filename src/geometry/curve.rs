//! Smooth curves as other tools store them (cubic Bézier, uniform B-spline and Catmull-Rom
//! segments; NURBS of any degree with their knots), evaluated so importers can sample them
//! into the linear segments tress renders.
//!
//! The cubic bases are the standard basis matrices (Bézier 1962; uniform cubic B-spline,
//! e.g. Piegl and Tiller, *The NURBS Book*, eq. 2.5 with uniform knots; Catmull and Rom
//! 1974 with tension 1/2). NURBS curves are evaluated by de Boor's algorithm (*The NURBS
//! Book*, algorithm A2.2 / section 2.3) on homogeneous points, so rational curves and
//! non-uniform or repeated knots come out exactly.

use glam::{Vec3, Vec4};

/// The basis of a cubic curve segment with four control points.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CubicBasis {
    /// Bézier: passes through the first and last point; consecutive segments share an end
    /// point (a step of 3 points).
    Bezier,
    /// Uniform cubic B-spline: C2, passes through no point in general (a step of 1).
    BSpline,
    /// Catmull-Rom: passes through the two middle points (a step of 1).
    CatmullRom,
}

impl CubicBasis {
    /// Control points between the starts of consecutive segments.
    pub fn step(self) -> usize {
        match self {
            CubicBasis::Bezier => 3,
            CubicBasis::BSpline | CubicBasis::CatmullRom => 1,
        }
    }

    /// Number of segments of a non-periodic curve with `points` control points (0 when
    /// there are too few, or when a Bézier curve's count is not 3k + 1).
    pub fn segments(self, points: usize) -> usize {
        match self {
            _ if points < 4 => 0,
            CubicBasis::Bezier if !(points - 1).is_multiple_of(3) => 0,
            b => (points - 4) / b.step() + 1,
        }
    }

    /// Weights of the four control points at `t` in [0, 1] along a segment.
    pub fn weights(self, t: f32) -> [f32; 4] {
        let (t2, t3) = (t * t, t * t * t);
        let s = 1.0 - t;
        match self {
            CubicBasis::Bezier => [s * s * s, 3.0 * s * s * t, 3.0 * s * t2, t3],
            CubicBasis::BSpline => [
                s * s * s / 6.0,
                (3.0 * t3 - 6.0 * t2 + 4.0) / 6.0,
                (-3.0 * t3 + 3.0 * t2 + 3.0 * t + 1.0) / 6.0,
                t3 / 6.0,
            ],
            CubicBasis::CatmullRom => [
                0.5 * (-t3 + 2.0 * t2 - t),
                0.5 * (3.0 * t3 - 5.0 * t2 + 2.0),
                0.5 * (-3.0 * t3 + 4.0 * t2 + t),
                0.5 * (t3 - t2),
            ],
        }
    }
}

/// Anything a curve can carry along its control points: positions, widths, colours.
pub trait Blend: Copy {
    /// `self * w`.
    fn scaled(self, w: f32) -> Self;
    /// `self + o`.
    fn plus(self, o: Self) -> Self;
}

impl Blend for f32 {
    fn scaled(self, w: f32) -> f32 {
        self * w
    }
    fn plus(self, o: f32) -> f32 {
        self + o
    }
}

impl Blend for Vec3 {
    fn scaled(self, w: f32) -> Vec3 {
        self * w
    }
    fn plus(self, o: Vec3) -> Vec3 {
        self + o
    }
}

/// The value at `t` of the segment with control values `p`.
pub fn cubic_point<T: Blend>(basis: CubicBasis, p: [T; 4], t: f32) -> T {
    let w = basis.weights(t);
    p[0].scaled(w[0]).plus(p[1].scaled(w[1])).plus(p[2].scaled(w[2])).plus(p[3].scaled(w[3]))
}

/// Samples a non-periodic cubic curve: `pieces` linear pieces per segment, so
/// `segments × pieces + 1` values, the first at the start of the first segment.
/// Returns an empty vector when `values` makes no segment.
pub fn sample_cubic<T: Blend>(basis: CubicBasis, values: &[T], pieces: usize) -> Vec<T> {
    let segments = basis.segments(values.len());
    let pieces = pieces.max(1);
    let mut out = Vec::with_capacity(segments * pieces + 1);
    for s in 0..segments {
        let i = s * basis.step();
        let p = [values[i], values[i + 1], values[i + 2], values[i + 3]];
        let first = if s == 0 { 0 } else { 1 };
        out.extend((first..=pieces).map(|k| cubic_point(basis, p, k as f32 / pieces as f32)));
    }
    out
}

/// A NURBS curve: degree, full knot vector (`cvs + degree + 1` knots) and homogeneous
/// control points (`[w x, w y, w z, w]`).
#[derive(Clone, Debug, PartialEq)]
pub struct Nurbs {
    /// Polynomial degree (1 = a polyline through the control points).
    pub degree: usize,
    /// Non-decreasing knots, `cvs.len() + degree + 1` of them.
    pub knots: Vec<f64>,
    /// Homogeneous control points.
    pub cvs: Vec<Vec4>,
}

impl Nurbs {
    /// Checks the counts and that the knots are finite and non-decreasing with a
    /// non-empty domain.
    pub fn validate(&self) -> Result<(), String> {
        let (p, n) = (self.degree, self.cvs.len());
        if p == 0 {
            return Err("degree 0 curves have no segments".into());
        }
        if n < p + 1 {
            return Err(format!("a degree-{p} curve needs at least {} control points, it has {n}", p + 1));
        }
        if self.knots.len() != n + p + 1 {
            return Err(format!(
                "{} knots for {n} control points of degree {p} (expected {})",
                self.knots.len(),
                n + p + 1
            ));
        }
        if self.knots.iter().any(|k| !k.is_finite()) || self.knots.windows(2).any(|w| w[1] < w[0]) {
            return Err("knots must be finite and non-decreasing".into());
        }
        if self.cvs.iter().any(|c| !c.is_finite() || c.w <= 0.0) {
            return Err("control points must be finite with positive weights".into());
        }
        let (a, b) = self.domain();
        if b <= a {
            return Err("the knots leave the curve an empty parameter range".into());
        }
        Ok(())
    }

    /// The parameter range the curve is defined on, `[t_p, t_n]`.
    pub fn domain(&self) -> (f64, f64) {
        (self.knots[self.degree], self.knots[self.cvs.len()])
    }

    /// The point at parameter `t` (clamped to the domain), by de Boor's algorithm.
    pub fn point(&self, t: f64) -> Vec3 {
        let p = self.degree;
        let (a, b) = self.domain();
        let t = t.clamp(a, b);
        // The knot span k with t_k <= t < t_{k+1}, inside [p, n - 1].
        let n = self.cvs.len();
        let k = (self.knots[..n].partition_point(|&x| x <= t).saturating_sub(1)).clamp(p, n - 1);
        let mut d: Vec<Vec4> = self.cvs[k - p..=k].to_vec();
        for r in 1..=p {
            for j in (r..=p).rev() {
                let i = j + k - p;
                let (lo, hi) = (self.knots[i], self.knots[i + p + 1 - r]);
                let alpha = if hi > lo { ((t - lo) / (hi - lo)) as f32 } else { 0.0 };
                d[j] = d[j - 1] * (1.0 - alpha) + d[j] * alpha;
            }
        }
        d[p].truncate() / d[p].w
    }

    /// Distinct knot values inside the domain, in order: the ends of the curve's spans.
    pub fn span_ends(&self) -> Vec<f64> {
        let (a, b) = self.domain();
        let mut out: Vec<f64> = Vec::new();
        for &k in &self.knots[self.degree..=self.cvs.len()] {
            if k >= a && k <= b && out.last() != Some(&k) {
                out.push(k);
            }
        }
        out
    }

    /// Samples the curve: every span end (so a degree-1 curve gives back its control
    /// points) and `pieces − 1` evenly spaced parameters inside each span.
    pub fn sample(&self, pieces: usize) -> Vec<Vec3> {
        let ends = self.span_ends();
        let pieces = if self.degree == 1 { 1 } else { pieces.max(1) };
        let mut out = Vec::with_capacity((ends.len().saturating_sub(1)) * pieces + 1);
        for (s, w) in ends.windows(2).enumerate() {
            let first = if s == 0 { 0 } else { 1 };
            for j in first..=pieces {
                out.push(self.point(w[0] + (w[1] - w[0]) * j as f64 / pieces as f64));
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: Vec3, b: Vec3) -> bool {
        (a - b).length() < 1e-5
    }

    #[test]
    fn every_basis_sums_to_one() {
        for basis in [CubicBasis::Bezier, CubicBasis::BSpline, CubicBasis::CatmullRom] {
            for i in 0..=10 {
                let s: f32 = basis.weights(i as f32 / 10.0).iter().sum();
                assert!((s - 1.0).abs() < 1e-6, "{basis:?}");
            }
        }
    }

    #[test]
    fn bezier_and_catmull_rom_interpolate_their_points() {
        let p = [Vec3::ZERO, Vec3::X, Vec3::new(2.0, 1.0, 0.0), Vec3::new(3.0, 0.0, 1.0)];
        assert!(close(cubic_point(CubicBasis::Bezier, p, 0.0), p[0]));
        assert!(close(cubic_point(CubicBasis::Bezier, p, 1.0), p[3]));
        // The Bézier midpoint, (P0 + 3 P1 + 3 P2 + P3) / 8.
        let mid = (p[0] + 3.0 * p[1] + 3.0 * p[2] + p[3]) / 8.0;
        assert!(close(cubic_point(CubicBasis::Bezier, p, 0.5), mid));
        assert!(close(cubic_point(CubicBasis::CatmullRom, p, 0.0), p[1]));
        assert!(close(cubic_point(CubicBasis::CatmullRom, p, 1.0), p[2]));
        // The uniform B-spline starts at (P0 + 4 P1 + P2) / 6.
        assert!(close(cubic_point(CubicBasis::BSpline, p, 0.0), (p[0] + 4.0 * p[1] + p[2]) / 6.0));
    }

    #[test]
    fn segment_counts_follow_the_step() {
        assert_eq!(CubicBasis::Bezier.segments(7), 2);
        assert_eq!(CubicBasis::Bezier.segments(6), 0);
        assert_eq!(CubicBasis::BSpline.segments(6), 3);
        assert_eq!(CubicBasis::CatmullRom.segments(3), 0);
        let v: Vec<f32> = (0..7).map(|i| i as f32).collect();
        assert_eq!(sample_cubic(CubicBasis::Bezier, &v, 4).len(), 9);
        // Collinear evenly spaced points stay on their line.
        let s = sample_cubic(CubicBasis::Bezier, &v, 4);
        assert!((s[4] - 3.0).abs() < 1e-6 && (s[8] - 6.0).abs() < 1e-6);
    }

    fn nurbs(degree: usize, knots: &[f64], cvs: &[Vec3]) -> Nurbs {
        Nurbs { degree, knots: knots.to_vec(), cvs: cvs.iter().map(|c| c.extend(1.0)).collect() }
    }

    #[test]
    fn clamped_cubic_nurbs_is_a_bezier_curve() {
        let p = [Vec3::ZERO, Vec3::Y, Vec3::new(1.0, 2.0, 0.0), Vec3::new(2.0, 2.0, 1.0)];
        let c = nurbs(3, &[0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0], &p);
        c.validate().unwrap();
        for i in 0..=8 {
            let t = i as f32 / 8.0;
            assert!(close(c.point(t as f64), cubic_point(CubicBasis::Bezier, p, t)), "t = {t}");
        }
    }

    #[test]
    fn a_double_knot_makes_a_quadratic_pass_through_its_control_point() {
        let p = [Vec3::ZERO, Vec3::Y, Vec3::new(1.0, 1.0, 0.0), Vec3::new(2.0, 0.0, 0.0), Vec3::new(2.0, 1.0, 0.0)];
        let c = nurbs(2, &[0.0, 0.0, 0.0, 1.0, 1.0, 2.0, 2.0, 2.0], &p);
        c.validate().unwrap();
        assert!(close(c.point(1.0), p[2]));
        assert_eq!(c.span_ends(), vec![0.0, 1.0, 2.0]);
        let s = c.sample(4);
        assert_eq!(s.len(), 9);
        assert!(close(s[4], p[2]) && close(s[0], p[0]) && close(s[8], p[4]));
        // With uniform knots the same points give a curve that misses P2.
        let u = nurbs(2, &[0.0, 0.0, 0.0, 1.0, 2.0, 3.0, 3.0, 3.0], &p);
        assert!((u.sample(4).iter().map(|q| (*q - p[2]).length()).fold(f32::INFINITY, f32::min)) > 0.1);
    }

    #[test]
    fn degree_one_samples_are_the_control_points() {
        let p = [Vec3::ZERO, Vec3::X, Vec3::new(1.0, 1.0, 0.0)];
        let c = nurbs(1, &[0.0, 0.0, 1.0, 3.0, 3.0], &p);
        c.validate().unwrap();
        let s = c.sample(8);
        assert_eq!(s.len(), 3);
        assert!(s.iter().zip(p).all(|(a, b)| close(*a, b)));
    }

    #[test]
    fn rational_quadratic_draws_a_circle_arc() {
        // A quarter circle: weights 1, cos 45°, 1 (The NURBS Book, section 7.2).
        let w = std::f32::consts::FRAC_1_SQRT_2;
        let c = Nurbs {
            degree: 2,
            knots: vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0],
            cvs: vec![Vec4::new(1.0, 0.0, 0.0, 1.0), Vec4::new(w, w, 0.0, w), Vec4::new(0.0, 1.0, 0.0, 1.0)],
        };
        c.validate().unwrap();
        for q in c.sample(16) {
            assert!((q.length() - 1.0).abs() < 1e-5, "{q}");
        }
    }

    #[test]
    fn bad_curves_are_rejected() {
        let p = [Vec3::ZERO, Vec3::X, Vec3::Y];
        assert!(nurbs(2, &[0.0, 0.0, 0.0, 1.0, 1.0], &p).validate().is_err());
        assert!(nurbs(2, &[0.0, 0.0, 0.0, 1.0, 1.0, 0.5], &p).validate().is_err());
        assert!(nurbs(3, &[0.0; 7], &p).validate().is_err());
        assert!(nurbs(2, &[0.0; 6], &p).validate().is_err());
        assert!(nurbs(0, &[0.0, 1.0, 2.0, 3.0], &p).validate().is_err());
    }
}
