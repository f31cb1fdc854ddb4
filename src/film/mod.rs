//! The film: per-pixel colour and auxiliary outputs (AOVs), and writing them to files.

mod output;

pub use output::{check_output, srgb_encode, write_image, write_image_with, OutputError};

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
    /// Strand index at that hit when it is hair, -1 otherwise.
    pub strand_id: f32,
    /// Position along that strand, 0 at the root and 1 at the tip; -1 when not hair.
    pub strand_along: f32,
    /// Root UV of that strand on the surface it grows from; -1 when unknown or not hair.
    pub root_uv: [f32; 2],
    /// Clump (guide) index of that strand; -1 when unknown or not hair.
    pub clump_id: f32,
    /// The strand's stable random value in [0, 1); -1 when not hair.
    pub strand_random: f32,
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
            ..Default::default()
        };
        Film { width, height, pixels: vec![empty; width as usize * height as usize] }
    }
}
