//! Pixel reconstruction filters, applied by filter importance sampling (Ernst et al. 2006,
//! "Filter Importance Sampling"; pbrt-v4 section 8.8): each camera sample of a pixel is
//! placed around the pixel centre with the filter's distribution and counts with weight 1
//! for that pixel alone. A pixel still depends only on (seed, pixel, sample), so tiles,
//! checkpoints and farm parts stay independent and the image is the same for any thread
//! count; neighbouring pixels see overlapping areas, which smooths the image as a
//! filtered reconstruction does.

use statrs::function::erf::{erf, erf_inv};
use std::f64::consts::SQRT_2;

/// How the samples of a pixel are spread over the image.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub enum PixelFilter {
    /// Uniform over the pixel's square: every sample counts for its pixel only.
    #[default]
    Box,
    /// A Gaussian of standard deviation `sigma` pixels around the pixel centre, cut at
    /// `radius` pixels along each axis (separable).
    Gaussian {
        /// Half width of the support, in pixels.
        radius: f32,
        /// Standard deviation, in pixels.
        sigma: f32,
    },
}

impl PixelFilter {
    /// The Gaussian's radius when none is given, in pixels (pbrt-v4's default).
    pub const GAUSSIAN_RADIUS: f32 = 1.5;

    /// The Gaussian of `radius` pixels with the usual `sigma = radius / 3` (pbrt-v4's
    /// default: radius [`PixelFilter::GAUSSIAN_RADIUS`], sigma 0.5).
    pub fn gaussian(radius: f32) -> PixelFilter {
        PixelFilter::Gaussian { radius, sigma: radius / 3.0 }
    }

    /// Checks the values, naming the wrong one.
    pub fn validate(&self) -> Result<(), String> {
        match *self {
            PixelFilter::Box => Ok(()),
            PixelFilter::Gaussian { radius, sigma } => {
                if !(radius.is_finite() && (0.5..=8.0).contains(&radius)) {
                    return Err(format!("filter `radius` {radius} must be between 0.5 and 8 pixels"));
                }
                if !(sigma.is_finite() && sigma >= 0.05 && sigma <= 2.0 * radius) {
                    return Err(format!("filter `sigma` {sigma} must be at least 0.05 and at most twice the radius"));
                }
                Ok(())
            }
        }
    }

    /// Where a sample drawn from uniform `(u, v)` in [0, 1)^2 lies, in pixels from the
    /// pixel's top-left corner (the box returns `(u, v)` itself; the Gaussian may leave the
    /// pixel by up to `radius - 1/2`).
    pub fn place(&self, (u, v): (f32, f32)) -> (f32, f32) {
        match *self {
            PixelFilter::Box => (u, v),
            PixelFilter::Gaussian { radius, sigma } => {
                (0.5 + truncated_gaussian(u, radius, sigma), 0.5 + truncated_gaussian(v, radius, sigma))
            }
        }
    }
}

/// The inverse CDF of a Gaussian of deviation `sigma` cut to [-`radius`, `radius`]: for
/// uniform `u`, `x = sigma sqrt(2) erf^-1((2u - 1) erf(radius / (sigma sqrt(2))))`. It is
/// monotonic, so stratified `u` give stratified offsets.
fn truncated_gaussian(u: f32, radius: f32, sigma: f32) -> f32 {
    let s = sigma as f64 * SQRT_2;
    let edge = erf(radius as f64 / s);
    let x = s * erf_inv((2.0 * u as f64 - 1.0) * edge);
    (x as f32).clamp(-radius, radius)
}

impl std::str::FromStr for PixelFilter {
    type Err = String;

    /// `box`, `gaussian` (radius [`PixelFilter::GAUSSIAN_RADIUS`]) or `gaussian:RADIUS`,
    /// as the command line and scene files name filters; the values are checked.
    fn from_str(s: &str) -> Result<PixelFilter, String> {
        let f = match s.split_once(':') {
            None if s == "box" => PixelFilter::Box,
            None if s == "gaussian" => PixelFilter::gaussian(PixelFilter::GAUSSIAN_RADIUS),
            Some(("gaussian", r)) => {
                PixelFilter::gaussian(r.parse().map_err(|_| format!("`{r}` is not a radius in pixels"))?)
            }
            _ => return Err(format!("unknown filter `{s}` (box, gaussian or gaussian:RADIUS)")),
        };
        f.validate()?;
        Ok(f)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn filters_are_named_as_the_command_line_and_scene_files_name_them() {
        assert_eq!("box".parse(), Ok(PixelFilter::Box));
        assert_eq!("gaussian".parse(), Ok(PixelFilter::Gaussian { radius: 1.5, sigma: 0.5 }));
        assert_eq!("gaussian:3".parse(), Ok(PixelFilter::Gaussian { radius: 3.0, sigma: 1.0 }));
        for bad in ["gauss", "gaussian:x", "gaussian:100", "box:2"] {
            assert!(bad.parse::<PixelFilter>().is_err(), "{bad}");
        }
    }
    use statrs::distribution::{Continuous, ContinuousCDF, Normal};

    #[test]
    fn the_box_keeps_the_sample_where_it_was() {
        for (u, v) in [(0.0, 0.0), (0.25, 0.75), (0.999, 0.5)] {
            assert_eq!(PixelFilter::Box.place((u, v)), (u, v));
        }
    }

    #[test]
    fn gaussian_offsets_have_the_truncated_gaussian_moments() {
        // Midpoint quadrature of the inverse CDF over u: the mean and variance of the
        // offsets must be those of the truncated normal, sigma^2 (1 - 2 z phi(z) /
        // (2 Phi(z) - 1)) with z = radius / sigma.
        for (radius, sigma) in [(1.5f32, 0.5f32), (2.0, 1.0), (1.0, 2.0)] {
            let f = PixelFilter::Gaussian { radius, sigma };
            let n = 200_000;
            let (mut sum, mut sq) = (0.0f64, 0.0f64);
            for i in 0..n {
                let u = (i as f32 + 0.5) / n as f32;
                let (x, _) = f.place((u, 0.5));
                let dx = x as f64 - 0.5;
                assert!(dx.abs() <= radius as f64, "offset {dx} beyond radius {radius}");
                sum += dx;
                sq += dx * dx;
            }
            let normal = Normal::new(0.0, 1.0).unwrap();
            let z = (radius / sigma) as f64;
            let want = (sigma as f64).powi(2) * (1.0 - 2.0 * z * normal.pdf(z) / (2.0 * normal.cdf(z) - 1.0));
            assert!((sum / n as f64).abs() < 1e-4, "mean {}", sum / n as f64);
            let var = sq / n as f64;
            assert!((var - want).abs() < 2e-3 * want, "radius {radius} sigma {sigma}: variance {var}, want {want}");
        }
    }

    #[test]
    fn the_gaussian_centre_is_the_pixel_centre_and_it_is_monotonic() {
        let f = PixelFilter::gaussian(1.5);
        assert!((f.place((0.5, 0.5)).0 - 0.5).abs() < 1e-6);
        let xs: Vec<f32> = (0..1000).map(|i| f.place((i as f32 / 1000.0, 0.0)).0).collect();
        assert!(xs.windows(2).all(|w| w[0] <= w[1]));
        assert!(xs[0] >= -1.0 && xs[999] <= 2.0);
    }

    #[test]
    fn bad_filters_are_named() {
        assert!(PixelFilter::Box.validate().is_ok());
        assert!(PixelFilter::gaussian(1.5).validate().is_ok());
        for (f, key) in [
            (PixelFilter::gaussian(0.1), "radius"),
            (PixelFilter::gaussian(f32::NAN), "radius"),
            (PixelFilter::Gaussian { radius: 1.5, sigma: 0.0 }, "sigma"),
            (PixelFilter::Gaussian { radius: 1.5, sigma: f32::INFINITY }, "sigma"),
        ] {
            let e = f.validate().unwrap_err();
            assert!(e.contains(key), "{e}");
        }
    }
}
