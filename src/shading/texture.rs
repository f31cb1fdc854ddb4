//! Image textures on meshes, looked up by UV and filtered by the ray's footprint: a mip-map
//! pyramid (Williams 1983, "Pyramidal Parametrics") read trilinearly at the level whose
//! texels match the footprint, the level chosen from the ray cone (Akenine-Moller et al.
//! 2019, "Texture Level of Detail Strategies for Real-Time Ray Tracing", Ray Tracing Gems
//! ch. 20, eq. 20.5: lambda = log2 of the footprint's width in texels).
//!
//! UVs follow the OBJ convention: (0, 0) is the image's bottom-left corner, v runs up; the
//! texture repeats outside [0, 1).
//!
//! A colour map ([`ColorMap`]) is such an image or a procedural checkerboard ([`Checker`],
//! Arnold's `checkerboard` shader), box-filtered over the same footprint in closed form.

use crate::math::Color;
use std::sync::Arc;

/// A texture: its mip-map pyramid, shared by clones.
#[derive(Clone)]
pub struct Texture {
    levels: Arc<Vec<Level>>,
}

/// One level of the pyramid.
#[derive(Clone, Debug, PartialEq)]
struct Level {
    width: usize,
    height: usize,
    /// Row by row from the top.
    texels: Vec<Color>,
}

impl std::fmt::Debug for Texture {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let base = &self.levels[0];
        f.debug_struct("Texture").field("width", &base.width).field("height", &base.height).finish()
    }
}

impl PartialEq for Texture {
    fn eq(&self, o: &Self) -> bool {
        Arc::ptr_eq(&self.levels, &o.levels) || self.levels == o.levels
    }
}

impl Texture {
    /// A texture of `width` x `height` texels, three linear floats each, row by row from the
    /// top. An error says what is wrong with the texels (the caller names the file).
    pub fn from_pixels(width: u32, height: u32, rgb: &[f32]) -> Result<Texture, String> {
        let (w, h) = (width as usize, height as usize);
        if w == 0 || h == 0 {
            return Err(format!("the image is {width}x{height}: a texture needs pixels"));
        }
        if rgb.len() != w * h * 3 {
            return Err(format!("{} values for {width}x{height} RGB pixels", rgb.len()));
        }
        if let Some(i) = rgb.iter().position(|v| !v.is_finite() || *v < 0.0) {
            return Err(format!(
                "pixel ({}, {}) has the value {}: texture values must be finite and not negative",
                (i / 3) % w,
                (i / 3) / w,
                rgb[i]
            ));
        }
        let texels = rgb.chunks_exact(3).map(|c| Color::new(c[0], c[1], c[2])).collect();
        let mut levels = vec![Level { width: w, height: h, texels }];
        while let Some(next) = levels.last().and_then(Level::halved) {
            levels.push(next);
        }
        Ok(Texture { levels: Arc::new(levels) })
    }

    /// Width and height of the full-resolution level.
    pub fn size(&self) -> (u32, u32) {
        (self.levels[0].width as u32, self.levels[0].height as u32)
    }

    /// The mean of all texels (the top of the pyramid).
    pub fn average(&self) -> Color {
        let top = self.levels.last().expect("a texture has a level");
        top.texels.iter().sum::<Color>() / top.texels.len() as f32
    }

    /// The texture at `uv`, filtered over a footprint `width` wide in UV units: trilinear
    /// between the two pyramid levels whose texels are nearest that width.
    pub fn lookup(&self, uv: [f32; 2], width: f32) -> Color {
        let base = &self.levels[0];
        let texels = width * base.width.max(base.height) as f32;
        let lambda = if texels > 1.0 && texels.is_finite() {
            texels.log2()
        } else if texels > 1.0 {
            f32::MAX
        } else {
            0.0
        };
        let top = (self.levels.len() - 1) as f32;
        let lambda = lambda.min(top);
        let lo = lambda.floor();
        let t = lambda - lo;
        let a = self.levels[lo as usize].bilinear(uv);
        if t == 0.0 {
            return a;
        }
        a * (1.0 - t) + self.levels[(lo as usize + 1).min(top as usize)].bilinear(uv) * t
    }
}

impl Level {
    /// The next level: each texel the mean of the 2x2 (at an odd edge, 2x1 or 1x1) texels
    /// it covers; `None` once the level is one texel.
    fn halved(&self) -> Option<Level> {
        if self.width == 1 && self.height == 1 {
            return None;
        }
        let (w, h) = (self.width.div_ceil(2), self.height.div_ceil(2));
        let mut texels = Vec::with_capacity(w * h);
        for y in 0..h {
            for x in 0..w {
                let (xs, ys) = (2 * x..(2 * x + 2).min(self.width), 2 * y..(2 * y + 2).min(self.height));
                let n = (xs.len() * ys.len()) as f32;
                let sum: Color =
                    ys.flat_map(|yy| xs.clone().map(move |xx| (xx, yy))).map(|(xx, yy)| self.at(xx, yy)).sum();
                texels.push(sum / n);
            }
        }
        Some(Level { width: w, height: h, texels })
    }

    fn at(&self, x: usize, y: usize) -> Color {
        self.texels[y * self.width + x]
    }

    /// Bilinear between texel centres, repeating the image.
    fn bilinear(&self, [u, v]: [f32; 2]) -> Color {
        let (u, v) = (u.rem_euclid(1.0), (1.0 - v).rem_euclid(1.0));
        let (x, y) = (u * self.width as f32 - 0.5, v * self.height as f32 - 0.5);
        let (x0, y0) = (x.floor(), y.floor());
        let (fx, fy) = (x - x0, y - y0);
        let wrap = |i: f32, n: usize| (i as i64).rem_euclid(n as i64) as usize;
        let (xa, xb) = (wrap(x0, self.width), wrap(x0 + 1.0, self.width));
        let (ya, yb) = (wrap(y0, self.height), wrap(y0 + 1.0, self.height));
        let top = self.at(xa, ya) * (1.0 - fx) + self.at(xb, ya) * fx;
        let bottom = self.at(xa, yb) * (1.0 - fx) + self.at(xb, yb) * fx;
        top * (1.0 - fy) + bottom * fy
    }
}

/// A colour by UV: an image ([`Texture`]) or a procedural checkerboard ([`Checker`]).
#[derive(Clone, Debug, PartialEq)]
pub enum ColorMap {
    /// An image, mip-mapped.
    Image(Texture),
    /// Two colours in alternating cells.
    Checker(Checker),
}

impl ColorMap {
    /// The colour at `uv`, filtered over a footprint `width` wide in UV units.
    pub fn lookup(&self, uv: [f32; 2], width: f32) -> Color {
        match self {
            ColorMap::Image(t) => t.lookup(uv, width),
            ColorMap::Checker(c) => c.lookup(uv, width),
        }
    }

    /// The mean colour over the whole map (what a surface without UVs shows).
    pub fn average(&self) -> Color {
        match self {
            ColorMap::Image(t) => t.average(),
            ColorMap::Checker(c) => c.average(),
        }
    }
}

/// A checkerboard in UV space, as Arnold's `checkerboard` shader draws it (Arnold user
/// guide, "Checkerboard"): `u_frequency` and `v_frequency` count periods of two cells per
/// UV unit (Arnold's default of 1 draws 2 × 2 cells over the unit square), and the cell of
/// `uv` is `(floor(2 (u × u_frequency + u_offset)), floor(2 (v × v_frequency + v_offset)))`,
/// `color2` where the two cell numbers sum to an even number (the cell at the UV origin),
/// `color1` where odd: so Arnold's reference renders of its test suite draw it (a plane
/// with default frequencies shows four cells, `color1` at u < 1/2 < v). `contrast` scales
/// both colours' distance from their mean (1 keeps them, 0 draws the mean).
#[derive(Clone, Debug, PartialEq)]
pub struct Checker {
    /// Colour of the odd cells.
    pub color1: Color,
    /// Colour of the even cells (the cell at the UV origin).
    pub color2: Color,
    /// Periods (two cells) per UV unit along u.
    pub u_frequency: f32,
    /// Periods (two cells) per UV unit along v.
    pub v_frequency: f32,
    /// Shift along u, in periods.
    pub u_offset: f32,
    /// Shift along v, in periods.
    pub v_offset: f32,
    /// Contrast between the colours.
    pub contrast: f32,
}

impl Checker {
    /// Its numeric parameters by Arnold's names, for readers to fill.
    pub fn numbers_mut(&mut self) -> [(&'static str, &mut f32); 5] {
        [
            ("u_frequency", &mut self.u_frequency),
            ("v_frequency", &mut self.v_frequency),
            ("u_offset", &mut self.u_offset),
            ("v_offset", &mut self.v_offset),
            ("contrast", &mut self.contrast),
        ]
    }
}

impl Default for Checker {
    /// Arnold's defaults: white and black cells, two of each over the unit square.
    fn default() -> Self {
        Checker {
            color1: Color::ONE,
            color2: Color::ZERO,
            u_frequency: 1.0,
            v_frequency: 1.0,
            u_offset: 0.0,
            v_offset: 0.0,
            contrast: 1.0,
        }
    }
}

impl Checker {
    /// The two colours after the contrast, about their mean.
    fn colors(&self) -> (Color, Color) {
        let mean = (self.color1 + self.color2) * 0.5;
        (mean + (self.color1 - mean) * self.contrast, mean + (self.color2 - mean) * self.contrast)
    }

    /// The mean of the two colours: what a footprint covering many cells sees.
    pub fn average(&self) -> Color {
        let (a, b) = self.colors();
        (a + b) * 0.5
    }

    /// The checkerboard at `uv`, box-filtered over a square footprint `width` wide in UV
    /// units. The filter is exact and separable: the box mean of the odd cells along one
    /// axis is the difference of the running integral of the 0/1 square wave across the
    /// box over its width; the odd cells of the board are those odd along
    /// exactly one axis, so with independent fractions `a` and `b` along u and v their
    /// share is `a + b − 2ab`. A zero width reads the cell itself.
    pub fn lookup(&self, [u, v]: [f32; 2], width: f32) -> Color {
        let (a, b) = (
            odd_fraction(2.0 * (u * self.u_frequency + self.u_offset), 2.0 * width * self.u_frequency.abs()),
            odd_fraction(2.0 * (v * self.v_frequency + self.v_offset), 2.0 * width * self.v_frequency.abs()),
        );
        let odd = a + b - 2.0 * a * b;
        let (c1, c2) = self.colors();
        c2 * (1.0 - odd) + c1 * odd
    }
}

/// The share of odd cells (`floor(x)` odd) in a box `width` cells wide centred on `x`: 0
/// or 1 for a zero width, 1/2 for a wide one. Computed in f64: the running integral grows
/// with `x`, and in single precision its difference would lose the fraction far from
/// the origin.
fn odd_fraction(x: f32, width: f32) -> f32 {
    if !(x.is_finite() && width.is_finite()) {
        return 0.5;
    }
    let x = x as f64;
    // A footprint far below a cell (or none) reads the cell.
    if width <= 1e-6 {
        return x.floor().rem_euclid(2.0) as f32;
    }
    // The integral of the odd-cell indicator from 0 to t: one per two cells, plus the
    // part of an odd cell t is in.
    let integral = |t: f64| (t / 2.0).floor() + (2.0 * (t / 2.0 - (t / 2.0).floor()) - 1.0).max(0.0);
    let w = width as f64;
    ((integral(x + w / 2.0) - integral(x - w / 2.0)) / w).clamp(0.0, 1.0) as f32
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A checkerboard of 1-texel black and white squares.
    fn checker(n: u32) -> Texture {
        let rgb: Vec<f32> = (0..n * n).flat_map(|i| [((i % n + i / n) % 2) as f32; 3]).collect();
        Texture::from_pixels(n, n, &rgb).unwrap()
    }

    #[test]
    fn a_sharp_lookup_reads_the_texel_and_v_runs_up() {
        // 2x2: top row red, green; bottom row blue, white.
        let rgb = [1., 0., 0., 0., 1., 0., 0., 0., 1., 1., 1., 1.];
        let t = Texture::from_pixels(2, 2, &rgb).unwrap();
        assert_eq!(t.lookup([0.25, 0.75], 0.0), Color::new(1.0, 0.0, 0.0));
        assert_eq!(t.lookup([0.75, 0.75], 0.0), Color::new(0.0, 1.0, 0.0));
        assert_eq!(t.lookup([0.25, 0.25], 0.0), Color::new(0.0, 0.0, 1.0));
        // Repeats: one unit over is the same texel.
        assert_eq!(t.lookup([1.25, -0.75], 0.0), Color::new(0.0, 0.0, 1.0));
        assert_eq!(t.average(), Color::splat(0.5));
    }

    /// Seen from far, a footprint covering many texels averages them: a checkerboard reads
    /// as grey, and the filtered value changes smoothly with the width.
    #[test]
    fn wide_footprints_average_the_texels() {
        let t = checker(64);
        let sharp: Vec<f32> = (0..64).map(|i| t.lookup([(i as f32 + 0.5) / 64.0, 0.5 / 64.0], 0.0).x).collect();
        assert!(sharp.iter().all(|&v| v == 0.0 || v == 1.0));
        for width in [8.0 / 64.0, 0.5, 4.0] {
            for i in 0..50 {
                let uv = [i as f32 * 0.0173, i as f32 * 0.031];
                let v = t.lookup(uv, width).x;
                assert!((v - 0.5).abs() < 0.02, "width {width}: {v}");
            }
        }
        // Between levels the lookup blends: a footprint of 1.5 texels is not the sharp value.
        let mid = t.lookup([0.5 / 64.0, 0.5 / 64.0], 1.5 / 64.0).x;
        assert!(mid > 0.05 && mid < 0.95, "{mid}");
    }

    /// The cell of `floor(2 (u f_u + o_u)) + floor(2 (v f_v + o_v))`: even cells `color2`,
    /// odd ones `color1`; offsets and frequencies move the cells; contrast pulls both to their mean;
    /// a footprint covering many cells reads the mean, and half a cell across an edge reads
    /// the two halves' mean.
    #[test]
    fn checker_cells_follow_frequency_and_offset() {
        let (red, blue) = (Color::new(1.0, 0.0, 0.0), Color::new(0.0, 0.0, 1.0));
        let c = Checker { color1: red, color2: blue, u_frequency: 4.0, v_frequency: 2.0, ..Default::default() };
        // Cells 1/8 wide along u, 1/4 along v.
        assert_eq!(c.lookup([0.05, 0.1], 0.0), blue); // cell (0, 0)
        assert_eq!(c.lookup([0.2, 0.1], 0.0), red); // (1, 0)
        assert_eq!(c.lookup([0.2, 0.3], 0.0), blue); // (1, 1)
        assert_eq!(c.lookup([0.05, 0.3], 0.0), red); // (0, 1)
        assert_eq!(c.lookup([-0.05, 0.1], 0.0), red); // (-1, 0)
                                                      // Half a period is one cell: the colours swap; a whole period changes nothing.
        assert_eq!(Checker { u_offset: 0.5, ..c.clone() }.lookup([0.05, 0.1], 0.0), red);
        assert_eq!(Checker { u_offset: 1.0, ..c.clone() }.lookup([0.05, 0.1], 0.0), blue);
        let quarter = Checker { v_offset: 0.25, ..c.clone() };
        assert_eq!(c.lookup([0.05, 0.15], 0.0), blue); // 2 × 0.15 × 2 = 0.6: cell 0
        assert_eq!(quarter.lookup([0.05, 0.15], 0.0), red); // 2 × (0.3 + 0.25) = 1.1: cell 1
        let grey = Checker { contrast: 0.0, ..c.clone() };
        assert_eq!(grey.lookup([0.1, 0.1], 0.0), Color::new(0.5, 0.0, 0.5));
        assert_eq!(c.average(), Color::new(0.5, 0.0, 0.5));
        for uv in [[0.13, 0.71], [0.5, 0.5], [-3.2, 7.9]] {
            assert!((c.lookup(uv, 10.0) - c.average()).abs().max_element() < 0.02, "{uv:?}");
        }
        // Centred on the edge u = 1/8, a quarter cell wide along u (1/32 UV), well inside v.
        let edge = c.lookup([0.125, 0.1], 1.0 / 32.0);
        assert!((edge - Color::new(0.5, 0.0, 0.5)).abs().max_element() < 1e-4, "{edge}");
        // Through the colour map.
        assert_eq!(ColorMap::Checker(c).lookup([0.2, 0.1], 0.0), red);
    }

    #[test]
    fn odd_sizes_build_a_pyramid_that_keeps_the_mean() {
        let rgb: Vec<f32> = (0..5 * 3).flat_map(|i| [i as f32, 1.0, 0.0]).collect();
        let t = Texture::from_pixels(5, 3, &rgb).unwrap();
        assert_eq!(t.levels.len(), 4); // 5x3, 3x2, 2x1, 1x1
        assert!(t.levels.last().unwrap().texels.len() == 1);
        assert!(t.average().y == 1.0 && t.average().x > 0.0);
        assert!(Texture::from_pixels(1, 1, &[f32::INFINITY, 0.0, 0.0]).unwrap_err().contains("pixel (0, 0)"));
        assert!(Texture::from_pixels(0, 1, &[]).is_err());
    }
}
