//! Piecewise-constant distributions in one and two dimensions, sampled by inverting their
//! cumulative distribution (Pharr et al., PBR 3rd ed. sections 13.3.1 and 13.6.7; pbrt-v4's
//! `PiecewiseConstant1D` and `PiecewiseConstant2D`; 4th ed. section 2.4.2 for the marginal
//! and conditional densities). An environment map samples its pixels this way.

/// A piecewise-constant density on [0, 1) made of `n` equal cells with non-negative weights.
#[derive(Clone, Debug, PartialEq)]
pub struct Distribution1D {
    /// The cell weights as given (negative and non-finite values read as 0).
    func: Vec<f32>,
    /// `cdf[i]`: the probability of the cells before `i`; `n + 1` entries, the last 1.
    cdf: Vec<f32>,
    /// Integral of the weights over [0, 1): their mean.
    integral: f32,
}

impl Distribution1D {
    /// The distribution of `weights` (at least one cell). All-zero weights give the
    /// uniform density, so that sampling still works (with a zero [`integral`](Self::integral)).
    pub fn new(weights: &[f32]) -> Distribution1D {
        let func: Vec<f32> = if weights.is_empty() { vec![0.0] } else { weights.to_vec() };
        let func: Vec<f32> = func.into_iter().map(|w| if w.is_finite() && w > 0.0 { w } else { 0.0 }).collect();
        let n = func.len();
        // Summed in f64: a large map's cells differ by many orders of magnitude.
        let mut cdf = Vec::with_capacity(n + 1);
        let mut sum = 0.0f64;
        cdf.push(0.0f64);
        for &w in &func {
            sum += w as f64;
            cdf.push(sum);
        }
        let integral = (sum / n as f64) as f32;
        let cdf: Vec<f32> = if sum > 0.0 {
            cdf.iter().map(|c| (c / sum) as f32).collect()
        } else {
            (0..=n).map(|i| i as f32 / n as f32).collect()
        };
        Distribution1D { func, cdf, integral }
    }

    /// Number of cells.
    pub fn len(&self) -> usize {
        self.func.len()
    }

    /// Always false: a distribution has at least one cell.
    pub fn is_empty(&self) -> bool {
        self.func.is_empty()
    }

    /// Mean of the weights (their integral over [0, 1)).
    pub fn integral(&self) -> f32 {
        self.integral
    }

    /// Draws `x` in [0, 1) from the density for `u` in [0, 1): returns `x`, its density
    /// and the cell it lies in. A zero-probability cell is never returned.
    pub fn sample(&self, u: f32) -> (f32, f32, usize) {
        let n = self.func.len();
        // The last cell whose cdf start is <= u, among cells of non-zero probability.
        let i = (self.cdf.partition_point(|&c| c <= u).saturating_sub(1)).min(n - 1);
        let (lo, hi) = (self.cdf[i], self.cdf[i + 1]);
        // Kept inside the cell, so that `pdf(x)` finds the cell again.
        let du = if hi > lo { ((u - lo) / (hi - lo)).clamp(0.0, 0.999) } else { 0.5 };
        let x = (i as f32 + du) / n as f32;
        (x, self.pdf_of_cell(i), i)
    }

    /// Density at `x` in [0, 1).
    pub fn pdf(&self, x: f32) -> f32 {
        let n = self.func.len();
        let i = ((x * n as f32) as usize).min(n - 1);
        self.pdf_of_cell(i)
    }

    fn pdf_of_cell(&self, i: usize) -> f32 {
        if self.integral > 0.0 {
            self.func[i] / self.integral
        } else {
            1.0
        }
    }
}

/// A piecewise-constant density on [0, 1)^2 over a `width` x `height` grid of weights:
/// a marginal distribution over rows and a conditional one along each row.
#[derive(Clone, Debug, PartialEq)]
pub struct Distribution2D {
    rows: Vec<Distribution1D>,
    marginal: Distribution1D,
}

impl Distribution2D {
    /// The distribution of `weights`, row by row (`weights[y * width + x]`; `width` and
    /// `height` at least 1 and `weights.len() == width * height`).
    pub fn new(weights: &[f32], width: usize, height: usize) -> Distribution2D {
        let (width, height) = (width.max(1), height.max(1));
        let rows: Vec<Distribution1D> = (0..height)
            .map(|y| Distribution1D::new(weights.get(y * width..(y + 1) * width).unwrap_or(&[0.0])))
            .collect();
        let marginal = Distribution1D::new(&rows.iter().map(Distribution1D::integral).collect::<Vec<_>>());
        Distribution2D { rows, marginal }
    }

    /// Integral of the weights over the unit square (their mean).
    pub fn integral(&self) -> f32 {
        self.marginal.integral()
    }

    /// Draws a point `[x, y]` of the unit square for `(u, v)` in [0, 1)^2, with its density
    /// with respect to area: the row from the marginal (by `v`), then `x` along it (by `u`).
    pub fn sample(&self, (u, v): (f32, f32)) -> ([f32; 2], f32) {
        let (y, pdf_y, row) = self.marginal.sample(v);
        let (x, pdf_x, _) = self.rows[row].sample(u);
        ([x, y], pdf_x * pdf_y)
    }

    /// Density at `[x, y]` with respect to area.
    pub fn pdf(&self, [x, y]: [f32; 2]) -> f32 {
        let h = self.rows.len();
        let row = ((y * h as f32) as usize).min(h - 1);
        // p(x, y) = f(x, y) / integral: the row's conditional times the marginal.
        self.rows[row].pdf(x) * self.marginal.pdf(y)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_dimension_samples_cells_by_weight_and_inverts_the_cdf() {
        let d = Distribution1D::new(&[1.0, 0.0, 3.0]);
        assert!((d.integral() - 4.0 / 3.0).abs() < 1e-6);
        // pdf = w / mean: 0.75, 0, 2.25 on cells of width 1/3.
        assert!((d.pdf(0.1) - 0.75).abs() < 1e-6 && d.pdf(0.5) == 0.0 && (d.pdf(0.9) - 2.25).abs() < 1e-6);
        // The first quarter of u maps onto cell 0, the rest onto cell 2; never cell 1.
        let (x, pdf, cell) = d.sample(0.125);
        assert_eq!(cell, 0);
        assert!((x - 1.0 / 6.0).abs() < 1e-6 && (pdf - 0.75).abs() < 1e-6);
        for k in 0..1000 {
            let (x, pdf, cell) = d.sample(k as f32 / 1000.0);
            assert_ne!(cell, 1, "u = {}", k as f32 / 1000.0);
            assert!((0.0..1.0).contains(&x) && pdf > 0.0);
            assert_eq!(d.pdf(x), pdf);
        }
        // Zero weights sample uniformly instead of failing.
        let z = Distribution1D::new(&[0.0, f32::NAN, -1.0]);
        assert_eq!(z.integral(), 0.0);
        assert_eq!(z.sample(0.5).2, 1);
    }

    /// The histogram of many samples matches the weights: the fraction in each cell is
    /// its weight over the sum, to within a few standard deviations.
    #[test]
    fn two_dimensions_sample_each_cell_in_proportion_to_its_weight() {
        let (w, h) = (5, 4);
        let weights: Vec<f32> = (0..w * h).map(|i| ((i * 7) % 5) as f32 + if i == 3 { 40.0 } else { 0.0 }).collect();
        let total: f32 = weights.iter().sum();
        let d = Distribution2D::new(&weights, w, h);
        assert!((d.integral() - total / (w * h) as f32).abs() < 1e-4);
        let n = 200u32;
        let mut counts = vec![0u32; w * h];
        for i in 0..n {
            for j in 0..n {
                let ([x, y], pdf) = d.sample(((i as f32 + 0.5) / n as f32, (j as f32 + 0.5) / n as f32));
                let cell = (y * h as f32) as usize * w + (x * w as f32) as usize;
                assert_eq!(pdf, d.pdf([x, y]));
                assert!((pdf - weights[cell] / d.integral()).abs() < 1e-3 * pdf);
                counts[cell] += 1;
            }
        }
        let samples = (n * n) as f32;
        for (c, &wt) in counts.iter().zip(&weights) {
            let p = wt / total;
            let sigma = (samples * p * (1.0 - p)).sqrt().max(1.0);
            assert!((*c as f32 - samples * p).abs() < 4.0 * sigma + 2.0 * n as f32 / 100.0, "{c} vs {}", samples * p);
        }
    }
}
