//! Decoding the image files of fur attribute maps into [`MapImage`]s for [`crate::fur`].

use crate::error::LoadError;
use crate::fur::{image_map_paths, FurDescription, MapImage};
use std::path::Path;

/// Largest accepted map image side, in pixels.
pub const MAX_MAP_SIDE: u32 = 8192;

/// Decodes every image file the maps of `desc` name, each once.
///
/// Errors: a file that cannot be read or decoded, larger than [`MAX_MAP_SIDE`] a side, or
/// empty (each naming the file).
pub fn read_map_images(desc: &FurDescription) -> Result<Vec<MapImage>, LoadError> {
    image_map_paths(desc).into_iter().map(read_map_image).collect()
}

/// Bytes a map takes while it is decoded, per pixel: the decoder's 8-bit RGBA (4), its
/// RGB copy (3, when the file has alpha or one channel) and the floats kept (12), with room
/// for 16-bit files.
pub const DECODE_BYTES_PER_PIXEL: u64 = 32;

/// A reader of the map file at `path`, opened as an input file ([`crate::input_file`]:
/// regular files only, at most the map cap) with its format guessed from its first bytes
/// and the decoder's limits set.
fn map_reader(path: &Path) -> Result<image::ImageReader<std::io::BufReader<std::fs::File>>, LoadError> {
    let file = crate::input_file::open(path, crate::input_file::Kind::Map)?;
    let mut reader = image::ImageReader::new(std::io::BufReader::new(file))
        .with_guessed_format()
        .map_err(|e| LoadError::io(path, "read the map", e))?;
    let mut limits = image::Limits::default();
    limits.max_image_width = Some(MAX_MAP_SIDE);
    limits.max_image_height = Some(MAX_MAP_SIDE);
    limits.max_alloc = Some(u64::from(MAX_MAP_SIDE) * u64::from(MAX_MAP_SIDE) * DECODE_BYTES_PER_PIXEL);
    reader.limits(limits);
    Ok(reader)
}

fn too_large(path: &Path) -> LoadError {
    LoadError::invalid(path, format!("map is larger than {MAX_MAP_SIDE} pixels a side"))
}

fn decode_error(path: &Path, e: image::ImageError) -> LoadError {
    match e {
        image::ImageError::Limits(_) => too_large(path),
        e => LoadError::format(path, format!("cannot decode the map image: {e}")),
    }
}

/// The width and height of the map at `path`, from its header, for the memory estimate.
pub fn map_dimensions(path: &Path) -> Result<(u32, u32), LoadError> {
    let (w, h) = map_reader(path)?.into_dimensions().map_err(|e| decode_error(path, e))?;
    if w > MAX_MAP_SIDE || h > MAX_MAP_SIDE {
        return Err(too_large(path));
    }
    Ok((w, h))
}

/// Largest side, in texels, a fur map keeps once decoded. A map is sampled once per hair
/// root, bilinearly: a 2048 x 2048 map already holds a texel for each of 4 million roots, so
/// a larger one is averaged down to this size by whole blocks of texels (an 8192 x 8192
/// map keeps 50 MB of texels instead of 805 MB). The cap is fixed, not derived from the
/// fur's density, so a root keeps its hair when the density changes.
pub const MAX_KEPT_SIDE: u32 = 2048;

/// The block of texels (a side, `k`) averaged into one kept texel for a map of `width` by
/// `height`: 1 up to [`MAX_KEPT_SIDE`], else the smallest whole number that brings both
/// sides within it.
pub fn reduction(width: u32, height: u32) -> u32 {
    width.max(height).div_ceil(MAX_KEPT_SIDE).max(1)
}

/// Decodes one map image to RGB texels as stored (colour maps stay sRGB-encoded; the fur
/// linearises them), averaged down by [`reduction`] when the image is larger than
/// [`MAX_KEPT_SIDE`] a side.
fn read_map_image(path: &Path) -> Result<MapImage, LoadError> {
    let img = map_reader(path)?.decode().map_err(|e| decode_error(path, e))?;
    let (width, height) = (img.width(), img.height());
    if width == 0 || height == 0 {
        return Err(LoadError::invalid(path, "map image is empty"));
    }
    let what = format!("the map {}", path.display());
    let texels = match img {
        // 8-bit images (the usual maps) convert straight to the texels kept, without a
        // floating-point copy of the whole image.
        img if img.color().bytes_per_pixel() == img.color().channel_count() => {
            let rgb = img.into_rgb8();
            reduced(width, height, |x, y| rgb.get_pixel(x, y).0.map(|v| f32::from(v) / 255.0), &what)
        }
        img => {
            let rgb = img.into_rgb32f();
            reduced(width, height, |x, y| rgb.get_pixel(x, y).0, &what)
        }
    }
    .map_err(|e| LoadError::invalid(path, e.to_string()))?;
    let k = reduction(width, height);
    Ok(MapImage { path: path.to_path_buf(), width: width.div_ceil(k), height: height.div_ceil(k), texels })
}

/// The texels of a `width` by `height` image whose texel at column `x`, row `y` is
/// `texel(x, y)`, each block of [`reduction`] texels a side averaged into one (blocks at
/// the right and bottom edges may be partial: they average what they hold).
fn reduced(
    width: u32,
    height: u32,
    texel: impl Fn(u32, u32) -> [f32; 3],
    what: &str,
) -> Result<Vec<[f32; 3]>, crate::memory::OutOfMemory> {
    let k = reduction(width, height);
    let (w, h) = (width.div_ceil(k), height.div_ceil(k));
    let mut texels = crate::memory::try_filled([0.0f32; 3], w as usize * h as usize, what)?;
    for (i, t) in texels.iter_mut().enumerate() {
        let (bx, by) = (i as u32 % w * k, i as u32 / w * k);
        let (xs, ys) = (bx..(bx + k).min(width), by..(by + k).min(height));
        let n = (xs.len() * ys.len()) as f32;
        let mut sum = [0.0f32; 3];
        for y in ys {
            for x in xs.clone() {
                let p = texel(x, y);
                (0..3).for_each(|c| sum[c] += p[c]);
            }
        }
        *t = sum.map(|v| v / n);
    }
    Ok(texels)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fur::{ColorAttr, MapSource, Scalar};

    #[test]
    fn maps_decode_once_each_as_stored() {
        let dir = tempfile::tempdir().unwrap();
        let grey = dir.path().join("grey.png");
        image::save_buffer(&grey, &[128, 128, 128, 0, 0, 255], 2, 1, image::ColorType::Rgb8).unwrap();
        let mut d = FurDescription::default();
        d[Scalar::Roll].map = Some(MapSource::Image(grey.clone()));
        d[ColorAttr::BaseColor].map = Some(MapSource::Image(grey.clone()));
        let images = read_map_images(&d).unwrap();
        assert_eq!(images.len(), 1, "one file used twice is decoded once");
        let i = &images[0];
        assert_eq!((i.path.as_path(), i.width, i.height), (grey.as_path(), 2, 1));
        assert_eq!(i.texels, [[128.0 / 255.0; 3], [0.0, 0.0, 1.0]], "texels as stored, not linearised");
    }

    #[test]
    fn maps_larger_than_kept_are_averaged_down_by_whole_blocks() {
        assert_eq!((reduction(1, 1), reduction(MAX_KEPT_SIDE, 7), reduction(MAX_KEPT_SIDE + 1, 1)), (1, 1, 2));
        assert_eq!(reduction(8192, 8192), 4);
        let dir = tempfile::tempdir().unwrap();
        // 2049 x 2 texels, a column of 0 then 255 repeating: blocks of 2 x 2 average to
        // one half, and the last, partial column (index 2048, value 0) stays 0.
        let (w, h) = (MAX_KEPT_SIDE + 1, 2);
        let pixels: Vec<u8> = (0..w * h).flat_map(|i| [if i % w % 2 == 1 { 255 } else { 0 }; 3]).collect();
        let wide = dir.path().join("wide.png");
        image::save_buffer(&wide, &pixels, w, h, image::ColorType::Rgb8).unwrap();
        let mut d = FurDescription::default();
        d[Scalar::Length].map = Some(MapSource::Image(wide));
        let i = &read_map_images(&d).unwrap()[0];
        assert_eq!((i.width, i.height), (MAX_KEPT_SIDE / 2 + 1, 1));
        assert!(i.texels[..i.texels.len() - 1].iter().all(|t| *t == [0.5; 3]), "{:?}", &i.texels[..4]);
        assert_eq!(i.texels.last(), Some(&[0.0; 3]));
    }

    #[test]
    fn bad_map_files_are_errors_naming_the_file() {
        let dir = tempfile::tempdir().unwrap();
        let err = |name: &str| {
            let mut d = FurDescription::default();
            d[Scalar::Length].map = Some(MapSource::Image(dir.path().join(name)));
            read_map_images(&d).unwrap_err().to_string()
        };
        let e = err("absent.png");
        assert!(e.contains("absent.png"), "{e}");
        std::fs::write(dir.path().join("junk.png"), b"not an image").unwrap();
        let e = err("junk.png");
        assert!(e.contains("junk.png") && e.contains("decode"), "{e}");
    }
}
