//! The film: per-pixel colour and auxiliary outputs (AOVs), and writing them to files.

mod filter;
mod input;
mod output;
mod region;

pub use filter::PixelFilter;
pub use input::{decode_exr, ExrFilm};
pub(crate) use input::{guarded as guarded_exr, MAX_EXPANSION};
pub use output::{check_output, srgb_encode, write_image, write_image_part, write_image_with, OutputError};
pub use region::Region;

use glam::Vec3;

/// What one pixel's samples add up to, averaged over the samples.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Pixel {
    /// Linear RGB radiance.
    pub color: Vec3,
    /// Fraction of samples that hit geometry (the alpha channel).
    pub coverage: f32,
    /// Distance along the camera ray to the first hit of the pixel's first sample that hit
    /// anything (infinite when none did).
    pub depth: f32,
    /// Shading normal (surfaces) or tangent (hair) at that hit, zero when none.
    pub normal: Vec3,
    /// Object index at that hit, -1 when none.
    pub object_id: f32,
    /// Strand index at that hit when it is hair (as its file or generator numbers it,
    /// whatever order the set is stored in), -1 otherwise.
    pub strand_id: f32,
    /// Position along that strand, 0 at the root and 1 at the tip; -1 when not hair.
    pub strand_along: f32,
    /// Root UV of that strand on the surface it grows from; -1 when unknown or not hair.
    pub root_uv: [f32; 2],
    /// Clump (guide) index of that strand; -1 when unknown or not hair.
    pub clump_id: f32,
    /// The strand's stable random value in [0, 1); -1 when not hair.
    pub strand_random: f32,
    /// Level of detail the hit used (0 for hair without it); -1 when not hair (thesis
    /// fig. 2.5).
    pub lod_level: f32,
    /// Camera samples taken in the pixel (more where adaptive supersampling refined).
    pub samples: f32,
}

/// An image being rendered: `width * height` pixels, row by row from the top.
#[derive(Clone, Debug, PartialEq)]
pub struct Film {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// Pixels, row-major from the top-left corner.
    pub pixels: Vec<Pixel>,
}

impl Film {
    /// A black film.
    pub fn new(width: u32, height: u32) -> Film {
        let empty = Pixel {
            depth: f32::INFINITY,
            object_id: -1.0,
            strand_id: -1.0,
            strand_along: -1.0,
            root_uv: [-1.0, -1.0],
            clump_id: -1.0,
            strand_random: -1.0,
            lod_level: -1.0,
            ..Default::default()
        };
        Film { width, height, pixels: vec![empty; width as usize * height as usize] }
    }

    /// Copies `part`, whose top-left pixel goes to (`x`, `y`) of this film; whatever of it
    /// falls outside is dropped.
    pub fn paste(&mut self, x: u32, y: u32, part: &Film) {
        let w = part.width.min(self.width.saturating_sub(x)) as usize;
        for row in 0..part.height.min(self.height.saturating_sub(y)) {
            let src = (row * part.width) as usize;
            let dst = ((y + row) * self.width + x) as usize;
            self.pixels[dst..dst + w].copy_from_slice(&part.pixels[src..src + w]);
        }
    }

    /// The pixels of `region` (which must lie inside the film) as a film of their own.
    pub fn crop(&self, region: Region) -> Film {
        let mut pixels = Vec::with_capacity(region.pixel_count());
        for y in region.y..region.y + region.height {
            let start = (y * self.width + region.x) as usize;
            pixels.extend_from_slice(&self.pixels[start..start + region.width as usize]);
        }
        Film { width: region.width, height: region.height, pixels }
    }
}

/// An EXR channel: its name, how it is taken from a pixel and how it is put back.
pub type Channel = (&'static str, fn(&Pixel) -> f32, fn(&mut Pixel, f32));

/// The EXR channels, which are also the AOVs by name. `A` and `coverage` hold the same
/// value; a reader takes `A`.
pub const CHANNELS: [Channel; 18] = [
    ("R", |p| p.color.x, |p, v| p.color.x = v),
    ("G", |p| p.color.y, |p, v| p.color.y = v),
    ("B", |p| p.color.z, |p, v| p.color.z = v),
    ("A", |p| p.coverage, |p, v| p.coverage = v),
    ("Z", |p| p.depth, |p, v| p.depth = v),
    ("N.X", |p| p.normal.x, |p, v| p.normal.x = v),
    ("N.Y", |p| p.normal.y, |p, v| p.normal.y = v),
    ("N.Z", |p| p.normal.z, |p, v| p.normal.z = v),
    ("objectId", |p| p.object_id, |p, v| p.object_id = v),
    ("strandId", |p| p.strand_id, |p, v| p.strand_id = v),
    ("strandAlong", |p| p.strand_along, |p, v| p.strand_along = v),
    ("rootUV.U", |p| p.root_uv[0], |p, v| p.root_uv[0] = v),
    ("rootUV.V", |p| p.root_uv[1], |p, v| p.root_uv[1] = v),
    ("clumpId", |p| p.clump_id, |p, v| p.clump_id = v),
    ("strandRandom", |p| p.strand_random, |p, v| p.strand_random = v),
    ("lodLevel", |p| p.lod_level, |p, v| p.lod_level = v),
    ("coverage", |p| p.coverage, |_, _| ()),
    ("samples", |p| p.samples, |p, v| p.samples = v),
];

#[cfg(test)]
mod tests {
    use super::*;

    fn numbered(w: u32, h: u32) -> Film {
        let mut f = Film::new(w, h);
        f.pixels.iter_mut().enumerate().for_each(|(i, p)| p.coverage = i as f32);
        f
    }

    #[test]
    fn crop_then_paste_restores_the_pixels() {
        let full = numbered(7, 5);
        let region = Region { x: 2, y: 1, width: 4, height: 3 };
        let part = full.crop(region);
        assert_eq!(part.pixels[0].coverage, 9.0);
        assert_eq!(part.pixels[11].coverage, 3.0 * 7.0 + 5.0);
        let mut back = Film::new(7, 5);
        back.paste(2, 1, &part);
        for (i, p) in back.pixels.iter().enumerate() {
            let (x, y) = (i as u32 % 7, i as u32 / 7);
            let inside = (2..6).contains(&x) && (1..4).contains(&y);
            assert_eq!(p.coverage, if inside { i as f32 } else { 0.0 }, "pixel {x},{y}");
        }
        // Overhanging parts are clipped, not a panic.
        back.paste(5, 4, &part);
        assert_eq!(back.pixels[4 * 7 + 6].coverage, 10.0);
    }
}
