//! Image-based lighting: an equirectangular (latitude-longitude) environment map,
//! importance-sampled by a piecewise-constant distribution over its pixels' luminance
//! times sin(theta) (Pharr et al., PBR 3rd ed. section 14.2.4, "Infinite Area Lights").
//!
//! Directions map to the image as follows, with +y up: the top row looks straight up
//! (+y), the bottom row straight down; the image's centre column looks along -z and the
//! column a quarter of the width to its right along +x, so a viewer inside the sphere sees
//! the picture unmirrored. `rotation` turns the map about +y (counter-clockwise seen from
//! above, in degrees). Radiance is read bilinearly, wrapping around horizontally.

use crate::math::distribution::Distribution2D;
use crate::math::Color;
use glam::{Mat3, Vec3};
use std::f32::consts::PI;
use std::sync::Arc;

/// Largest number of pixels an environment map may have (an 16k x 8k map).
pub const MAX_PIXELS: u64 = 16_384 * 8_192;

/// An environment map: linear RGB radiance over the sphere of directions, with its
/// sampling distribution. Cheap to clone (the pixels are shared).
#[derive(Clone)]
pub struct EnvironmentMap {
    image: Arc<MapImage>,
    placement: MapPlacement,
}

/// How an environment map lies on the sphere of directions and how bright it is: its turn
/// (a rotation, or one with a reflection), a factor on every pixel, and the weight camera
/// rays see it with. A scene description
/// carries one for a map whose file is not read yet; the map read takes it as it is.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MapPlacement {
    /// World directions to the map's frame (the inverse of its turn).
    to_map: Mat3,
    /// Factor on every pixel (intensity times 2^exposure).
    scale: f32,
    /// Weight camera rays see the map with ([`crate::light::Light::camera_visibility`]).
    camera_visibility: f32,
}

impl MapPlacement {
    /// Turned by `rotation` degrees about +y and scaled by `intensity`.
    pub fn new(rotation: f32, intensity: f32) -> MapPlacement {
        MapPlacement { to_map: Mat3::from_rotation_y(-rotation.to_radians()), scale: intensity, camera_visibility: 1.0 }
    }

    /// Seen by camera rays with weight `w` (finite, not negative) instead of 1.
    pub fn seen_by_camera(self, w: f32) -> MapPlacement {
        MapPlacement { camera_visibility: w, ..self }
    }

    /// The weight camera rays see the map with.
    pub fn camera_visibility(self) -> f32 {
        self.camera_visibility
    }

    /// Turned by `rotation` after its own turn: an orthogonal matrix, a rotation or one with
    /// a reflection (a mirrored world mirrors its sky too).
    pub fn rotated(self, rotation: Mat3) -> MapPlacement {
        MapPlacement { to_map: self.to_map * rotation.transpose(), ..self }
    }

    /// The world direction of the map's own direction `d`.
    pub fn to_world(self, d: Vec3) -> Vec3 {
        self.to_map.transpose() * d
    }

    /// The factor on every pixel.
    pub fn scale(self) -> f32 {
        self.scale
    }

    /// Its factor multiplied by `k`.
    pub fn scaled(self, k: f32) -> MapPlacement {
        MapPlacement { scale: self.scale * k, ..self }
    }
}

/// The pixels and their distribution, shared by the clones of a map.
struct MapImage {
    width: usize,
    height: usize,
    /// Row by row from the top.
    pixels: Vec<Color>,
    /// Over (u, v) in the unit square, u along a row, v down the rows.
    distribution: Distribution2D,
    /// Mean radiance over the sphere of directions (each pixel weighted by its solid angle).
    mean: Color,
}

impl std::fmt::Debug for EnvironmentMap {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("EnvironmentMap")
            .field("width", &self.image.width)
            .field("height", &self.image.height)
            .field("placement", &self.placement)
            .finish()
    }
}

impl PartialEq for EnvironmentMap {
    fn eq(&self, o: &Self) -> bool {
        (Arc::ptr_eq(&self.image, &o.image) || self.image.pixels == o.image.pixels && self.image.width == o.image.width)
            && self.placement == o.placement
    }
}

/// Rec. 709 luminance of a linear RGB colour.
pub fn luminance(c: Color) -> f32 {
    0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z
}

impl EnvironmentMap {
    /// A map of `width` x `height` pixels, `rgb` holding three linear floats a pixel, row
    /// by row from the top; turned by `rotation` degrees about +y and scaled by
    /// `intensity`. An error says what is wrong with the pixels (the caller names the file).
    pub fn from_pixels(
        width: u32,
        height: u32,
        rgb: &[f32],
        rotation: f32,
        intensity: f32,
    ) -> Result<EnvironmentMap, String> {
        if !rotation.is_finite() {
            return Err(format!("rotation {rotation} is not a finite number"));
        }
        EnvironmentMap::placed(width, height, rgb, MapPlacement::new(rotation, intensity))
    }

    /// [`EnvironmentMap::from_pixels`], placed by `placement`.
    pub fn placed(width: u32, height: u32, rgb: &[f32], placement: MapPlacement) -> Result<EnvironmentMap, String> {
        let pixels = width as u64 * height as u64;
        if width == 0 || height == 0 {
            return Err(format!("the image is {width}x{height}: an environment map needs pixels"));
        }
        if pixels > MAX_PIXELS {
            return Err(format!(
                "the {width}x{height} image is larger than an environment map may be ({MAX_PIXELS} pixels)"
            ));
        }
        if rgb.len() as u64 != pixels * 3 {
            return Err(format!("{} values for {width}x{height} RGB pixels", rgb.len()));
        }
        if let Some(i) = rgb.iter().position(|v| !v.is_finite() || *v < 0.0) {
            return Err(format!(
                "pixel ({}, {}) has the value {}: radiance must be finite and not negative",
                (i / 3) % width as usize,
                (i / 3) / width as usize,
                rgb[i]
            ));
        }
        if !(placement.scale.is_finite() && placement.scale >= 0.0) {
            return Err(format!("intensity {} must be finite and not negative", placement.scale));
        }
        if !(placement.camera_visibility.is_finite() && placement.camera_visibility >= 0.0) {
            return Err(format!("camera visibility {} must be finite and not negative", placement.camera_visibility));
        }
        if !placement.to_map.is_finite() {
            return Err("the map's turn is not finite".into());
        }
        let (w, h) = (width as usize, height as usize);
        let pixels: Vec<Color> = rgb.chunks_exact(3).map(|c| Color::new(c[0], c[1], c[2])).collect();
        let distribution = Distribution2D::new(&sampling_weights(&pixels, w, h), w, h);
        let mean = mean_radiance(&pixels, w, h);
        let image = Arc::new(MapImage { width: w, height: h, pixels, distribution, mean });
        Ok(EnvironmentMap { image, placement })
    }

    /// A `width` x `height` map whose pixel looks along a direction `d` of the map's own
    /// frame (+y up, the layout above) holds `radiance(d)`: how a sky model becomes a map.
    pub fn from_directions(
        width: u32,
        height: u32,
        placement: MapPlacement,
        radiance: impl Fn(Vec3) -> Color,
    ) -> Result<EnvironmentMap, String> {
        let mut rgb = Vec::with_capacity(width as usize * height as usize * 3);
        for y in 0..height {
            for x in 0..width {
                let uv = [(x as f32 + 0.5) / width as f32, (y as f32 + 0.5) / height as f32];
                rgb.extend_from_slice(&radiance(from_uv(uv).0).to_array());
            }
        }
        EnvironmentMap::placed(width, height, &rgb, placement)
    }

    /// The same map turned by `rotation`, applied after its own: an orthogonal matrix, a
    /// rotation or one with a reflection (a mirrored world mirrors its sky too).
    pub fn rotated(&self, rotation: Mat3) -> EnvironmentMap {
        EnvironmentMap { placement: self.placement.rotated(rotation), ..self.clone() }
    }

    /// The same map with its radiance multiplied by `k` (finite, not negative).
    pub fn scaled(&self, k: f32) -> EnvironmentMap {
        EnvironmentMap { placement: self.placement.scaled(k), ..self.clone() }
    }

    /// The weight camera rays see the map with.
    pub fn camera_visibility(&self) -> f32 {
        self.placement.camera_visibility
    }

    /// Width and height in pixels.
    pub fn size(&self) -> (u32, u32) {
        (self.image.width as u32, self.image.height as u32)
    }

    /// Mean radiance over the sphere of directions: the constant environment that sends the
    /// same total light. The tube and fur models' ambient term stands for it (thesis eq. 2.3).
    pub fn mean_radiance(&self) -> Color {
        self.image.mean * self.placement.scale
    }

    /// Radiance arriving from the unit direction `dir` (pointing away from the scene).
    pub fn radiance(&self, dir: Vec3) -> Color {
        let [u, v] = to_uv(self.placement.to_map * dir);
        self.lookup(u, v) * self.placement.scale
    }

    /// Bilinear lookup at (u, v): pixel centres at half-integers, wrapping in u.
    fn lookup(&self, u: f32, v: f32) -> Color {
        let img = &*self.image;
        let (x, y) = (u * img.width as f32 - 0.5, v * img.height as f32 - 0.5);
        let (x0, y0) = (x.floor(), y.floor());
        let (fx, fy) = (x - x0, y - y0);
        let wrap = |x: i64| x.rem_euclid(img.width as i64) as usize;
        let clamp = |y: i64| y.clamp(0, img.height as i64 - 1) as usize;
        let (xa, xb, ya, yb) = (wrap(x0 as i64), wrap(x0 as i64 + 1), clamp(y0 as i64), clamp(y0 as i64 + 1));
        let at = |x: usize, y: usize| img.pixels[y * img.width + x];
        (at(xa, ya) * (1.0 - fx) + at(xb, ya) * fx) * (1.0 - fy) + (at(xa, yb) * (1.0 - fx) + at(xb, yb) * fx) * fy
    }

    /// Draws a direction towards the map for `u` in [0, 1)^2, in proportion to the
    /// distribution: returns the direction, its solid-angle density and the radiance from
    /// it. `None` where the map is black everywhere.
    pub fn sample(&self, u: (f32, f32)) -> Option<(Vec3, f32, Color)> {
        let img = &*self.image;
        if img.distribution.integral() <= 0.0 || self.placement.scale <= 0.0 {
            return None;
        }
        let (uv, pdf_uv) = img.distribution.sample(u);
        let (local, sin_theta) = from_uv(uv);
        // p(w) = p(u, v) / (2 pi^2 sin(theta)): the Jacobian of (u, v) -> (phi, theta) -> w.
        let pdf = pdf_uv / (2.0 * PI * PI * sin_theta);
        if !(sin_theta > 0.0 && pdf.is_finite() && pdf > 0.0) {
            return None;
        }
        let dir = self.placement.to_map.transpose() * local;
        Some((dir, pdf, self.lookup(uv[0], uv[1]) * self.placement.scale))
    }

    /// Solid-angle density with which [`EnvironmentMap::sample`] picks `dir`.
    pub fn pdf(&self, dir: Vec3) -> f32 {
        let img = &*self.image;
        if img.distribution.integral() <= 0.0 || self.placement.scale <= 0.0 {
            return 0.0;
        }
        let local = self.placement.to_map * dir;
        let sin_theta = (1.0 - local.y * local.y).max(0.0).sqrt();
        if sin_theta <= 0.0 {
            return 0.0;
        }
        img.distribution.pdf(to_uv(local)) / (2.0 * PI * PI * sin_theta)
    }
}

/// The weight of each pixel in the sampling distribution: the mean luminance of the
/// bilinear radiance over the pixel (so that no direction with light has zero density),
/// times sin(theta) at the row's centre (the solid angle a pixel of that row spans).
fn sampling_weights(pixels: &[Color], w: usize, h: usize) -> Vec<f32> {
    let lum: Vec<f32> = pixels.iter().map(|&c| luminance(c).max(0.0)).collect();
    let at = |x: i64, y: i64| lum[y.clamp(0, h as i64 - 1) as usize * w + x.rem_euclid(w as i64) as usize];
    // The bilinear interpolant averaged over a pixel weighs the pixel 9/16, its four edge
    // neighbours 3/32 each and its corner neighbours 1/64 each.
    let mut weights = Vec::with_capacity(w * h);
    for y in 0..h as i64 {
        let sin_theta = (PI * (y as f32 + 0.5) / h as f32).sin();
        for x in 0..w as i64 {
            let edges = at(x - 1, y) + at(x + 1, y) + at(x, y - 1) + at(x, y + 1);
            let corners = at(x - 1, y - 1) + at(x + 1, y - 1) + at(x - 1, y + 1) + at(x + 1, y + 1);
            weights.push((at(x, y) * (9.0 / 16.0) + edges * (3.0 / 32.0) + corners * (1.0 / 64.0)) * sin_theta);
        }
    }
    weights
}

/// The mean of the pixels over the sphere: a pixel of row y spans the solid angle
/// (2 pi / w) (cos theta_y - cos theta_(y+1)), and the sphere 4 pi.
fn mean_radiance(pixels: &[Color], w: usize, h: usize) -> Color {
    let mut sum = glam::DVec3::ZERO;
    for (y, row) in pixels.chunks_exact(w).enumerate() {
        let (t0, t1) = (std::f64::consts::PI * y as f64 / h as f64, std::f64::consts::PI * (y + 1) as f64 / h as f64);
        let row_sum: glam::DVec3 = row.iter().map(|c| c.as_dvec3()).sum();
        sum += row_sum * (t0.cos() - t1.cos());
    }
    (sum * (2.0 * std::f64::consts::PI / w as f64) / (4.0 * std::f64::consts::PI)).as_vec3()
}

/// (u, v) in the unit square of a direction in the map's frame.
fn to_uv(d: Vec3) -> [f32; 2] {
    let theta = d.y.clamp(-1.0, 1.0).acos();
    // phi = 2 pi (u + 1/4) with d = (sin theta cos phi, cos theta, sin theta sin phi).
    let phi = d.z.atan2(d.x);
    let u = (phi / (2.0 * PI) - 0.25).rem_euclid(1.0);
    [u.min(1.0 - f32::EPSILON / 2.0), (theta / PI).min(1.0 - f32::EPSILON / 2.0)]
}

/// The direction in the map's frame at (u, v), and sin(theta) there.
fn from_uv([u, v]: [f32; 2]) -> (Vec3, f32) {
    let (theta, phi) = (PI * v, 2.0 * PI * (u + 0.25));
    let (sin_t, cos_t) = theta.sin_cos();
    (Vec3::new(sin_t * phi.cos(), cos_t, sin_t * phi.sin()), sin_t)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::sampling;

    /// A map with a smooth gradient, a bright spot and a black band.
    fn test_map(rotation: f32) -> EnvironmentMap {
        let (w, h) = (64u32, 32u32);
        let mut rgb = Vec::new();
        for y in 0..h {
            for x in 0..w {
                let (fx, fy) = (x as f32 / w as f32, y as f32 / h as f32);
                let mut c = [0.2 + fx, 0.5 * (1.0 - fy), 0.3];
                if (20..24).contains(&x) && (8..11).contains(&y) {
                    c = [40.0, 30.0, 20.0];
                }
                if (26..28).contains(&y) {
                    c = [0.0; 3];
                }
                rgb.extend_from_slice(&c);
            }
        }
        EnvironmentMap::from_pixels(w, h, &rgb, rotation, 1.5).unwrap()
    }

    #[test]
    fn directions_and_image_coordinates_invert_each_other() {
        for (u, v) in [(0.1, 0.2), (0.5, 0.5), (0.9, 0.95), (0.75, 0.3)] {
            let (d, _) = from_uv([u, v]);
            let [u2, v2] = to_uv(d);
            assert!((u - u2).abs() < 1e-5 && (v - v2).abs() < 1e-5, "{u} {v} -> {u2} {v2}");
        }
        // The documented frame: centre column along -z, a quarter to the right along +x.
        let (centre, _) = from_uv([0.5, 0.5]);
        assert!(centre.distance(-Vec3::Z) < 1e-5, "{centre}");
        let (right, _) = from_uv([0.75, 0.5]);
        assert!(right.distance(Vec3::X) < 1e-5, "{right}");
        assert!(from_uv([0.3, 0.0]).0.distance(Vec3::Y) < 1e-5);
    }

    /// Chi-square test of the sampling against the density: directions drawn by `sample`
    /// fall in the cells of a grid over the sphere (uniform in cos(theta) and phi, about
    /// the +z axis so the grid does not line up with the map's pixels) as often as the
    /// density, integrated over each cell, predicts; and every sample's value is its
    /// radiance, with the density `pdf` reports.
    #[test]
    fn samples_follow_the_density_they_report() {
        let map = test_map(37.0);
        let (nt, np) = (16usize, 32usize);
        let cell = |d: Vec3| {
            let t = (((1.0 - d.z) * 0.5 * nt as f32) as usize).min(nt - 1);
            let p = ((d.y.atan2(d.x) / (2.0 * PI)).rem_euclid(1.0) * np as f32) as usize;
            t * np + p.min(np - 1)
        };
        // Expected fraction per cell: the density integrated over the cell (each cell has
        // solid angle 4 pi / (nt np)), by a fine grid of points.
        let mut expected = vec![0.0f64; nt * np];
        let k = 600;
        for i in 0..k {
            for j in 0..k {
                let d = sampling::uniform_sphere((i as f32 + 0.5) / k as f32, (j as f32 + 0.5) / k as f32);
                expected[cell(d)] += map.pdf(d) as f64 * 4.0 * PI as f64 / (k * k) as f64;
            }
        }
        let total: f64 = expected.iter().sum();
        assert!((total - 1.0).abs() < 2e-3, "the density integrates to {total}");
        let n = 200_000u32;
        let mut counts = vec![0u32; nt * np];
        let mut rng = crate::math::rng::GenRng::new(7, 11);
        use rand::Rng;
        // A direction rounded across a pixel edge on its way to the sphere and back finds
        // the neighbouring pixel's density: rare, and counted.
        let mut elsewhere = 0;
        for _ in 0..n {
            let (d, pdf, radiance) = map.sample((rng.random::<f32>(), rng.random::<f32>())).unwrap();
            assert!((d.length() - 1.0).abs() < 1e-4);
            elsewhere += ((map.pdf(d) - pdf).abs() > 2e-3 * pdf) as u32;
            assert!((map.radiance(d) - radiance).abs().max_element() <= 1e-3 * radiance.max_element() + 1e-5);
            counts[cell(d)] += 1;
        }
        assert!(elsewhere < n / 2000, "{elsewhere} samples of {n} report another density than pdf()");
        // Cells expected to hold fewer than 5 samples are pooled, as the test requires.
        let (mut chi2, mut dof, mut pooled_e, mut pooled_o) = (0.0f64, 0u32, 0.0f64, 0.0f64);
        for (e, &o) in expected.iter().zip(&counts) {
            let e = e * n as f64;
            if e < 5.0 {
                pooled_e += e;
                pooled_o += o as f64;
                continue;
            }
            chi2 += (o as f64 - e).powi(2) / e;
            dof += 1;
        }
        if pooled_e > 0.0 {
            chi2 += (pooled_o - pooled_e).powi(2) / pooled_e.max(1.0);
            dof += 1;
        }
        // The 0.999 quantile of chi-square with `dof - 1` degrees of freedom.
        use statrs::distribution::{ChiSquared, ContinuousCDF};
        let limit = ChiSquared::new((dof - 1) as f64).unwrap().inverse_cdf(0.999);
        assert!(chi2 < limit, "chi-square {chi2} over {dof} cells, limit {limit}");
    }

    /// Estimating the light a map sends over the sphere with its own samples (radiance over
    /// density) gives what integrating its radiance over a fine grid gives.
    #[test]
    fn sampling_estimates_the_integral_of_the_radiance() {
        let map = test_map(0.0);
        let k = 800;
        let mut grid = Color::ZERO;
        for i in 0..k {
            for j in 0..k {
                let d = sampling::uniform_sphere((i as f32 + 0.5) / k as f32, (j as f32 + 0.5) / k as f32);
                grid += map.radiance(d);
            }
        }
        let grid = grid * (4.0 * PI / (k * k) as f32);
        let n = 400;
        let mut sampled = Color::ZERO;
        for i in 0..n {
            for j in 0..n {
                let (_, pdf, l) = map.sample(((i as f32 + 0.5) / n as f32, (j as f32 + 0.5) / n as f32)).unwrap();
                sampled += l / pdf;
            }
        }
        let sampled = sampled / (n * n) as f32;
        assert!((sampled - grid).abs().max_element() < 0.01 * grid.max_element(), "{sampled} vs {grid}");
        // The mean radiance is that integral over 4 pi (pixels against their bilinear
        // interpolant: equal up to the smoothing of the bright spot's edge).
        let mean = map.mean_radiance();
        let expected = grid / (4.0 * PI);
        assert!((mean - expected).abs().max_element() < 0.01 * expected.max_element(), "{mean} vs {expected}");
        let twice = map.scaled(2.0);
        assert!((twice.mean_radiance() - 2.0 * mean).abs().max_element() < 1e-6);
    }

    /// A map turned by an angle shows along the turned direction what the unturned map
    /// shows along the original one, with the same density.
    #[test]
    fn rotation_turns_the_map_about_up() {
        let map = test_map(0.0);
        let turned = test_map(90.0);
        for d in [Vec3::new(0.3, 0.2, -0.9).normalize(), Vec3::new(-0.5, -0.4, 0.7).normalize()] {
            let r = Mat3::from_rotation_y(90f32.to_radians()) * d;
            assert!((turned.radiance(r) - map.radiance(d)).abs().max_element() < 1e-4);
            assert!((turned.pdf(r) - map.pdf(d)).abs() < 1e-3 * map.pdf(d));
        }
        // Counter-clockwise seen from above: what the unturned map shows along -z, the
        // turned one shows along -x.
        assert!((Mat3::from_rotation_y(90f32.to_radians()) * -Vec3::Z).distance(-Vec3::X) < 1e-6);
        // `rotated` composes with the map's own rotation.
        let twice = map.rotated(Mat3::from_rotation_y(90f32.to_radians()));
        let d = Vec3::new(0.1, 0.5, 0.8).normalize();
        assert!((twice.radiance(d) - turned.radiance(d)).abs().max_element() < 1e-4);
    }

    #[test]
    fn unusable_pixels_are_refused() {
        assert!(EnvironmentMap::from_pixels(0, 4, &[], 0.0, 1.0).unwrap_err().contains("needs pixels"));
        assert!(EnvironmentMap::from_pixels(2, 1, &[1.0; 5], 0.0, 1.0).unwrap_err().contains("5 values"));
        let e = EnvironmentMap::from_pixels(2, 1, &[1.0, 1.0, 1.0, 1.0, f32::NAN, 1.0], 0.0, 1.0).unwrap_err();
        assert!(e.contains("pixel (1, 0)"), "{e}");
        assert!(EnvironmentMap::from_pixels(1, 1, &[1.0; 3], 0.0, -1.0).is_err());
        assert!(EnvironmentMap::from_pixels(100_000, 100_000, &[], 0.0, 1.0).unwrap_err().contains("larger"));
        // A black map has nothing to sample.
        let black = EnvironmentMap::from_pixels(4, 2, &[0.0; 24], 0.0, 1.0).unwrap();
        assert!(black.sample((0.3, 0.3)).is_none());
        assert_eq!(black.pdf(Vec3::X), 0.0);
    }
}
