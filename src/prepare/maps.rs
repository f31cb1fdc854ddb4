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

/// Decodes one map image to RGB texels as stored (colour maps stay sRGB-encoded; the fur
/// linearises them).
fn read_map_image(path: &Path) -> Result<MapImage, LoadError> {
    let img = map_reader(path)?.decode().map_err(|e| decode_error(path, e))?;
    let (width, height) = (img.width(), img.height());
    if width == 0 || height == 0 {
        return Err(LoadError::invalid(path, "map image is empty"));
    }
    let n = width as usize * height as usize;
    let what = || format!("the map {}", path.display());
    let mut texels =
        crate::memory::try_filled([0.0f32; 3], n, &what()).map_err(|e| LoadError::invalid(path, e.to_string()))?;
    // 8-bit images (the usual maps) convert straight to the texels kept, without a
    // floating-point copy of the whole image.
    match img {
        img if img.color().bytes_per_pixel() == img.color().channel_count() => {
            for (t, p) in texels.iter_mut().zip(img.into_rgb8().pixels()) {
                *t = p.0.map(|v| f32::from(v) / 255.0);
            }
        }
        img => {
            for (t, p) in texels.iter_mut().zip(img.into_rgb32f().pixels()) {
                *t = p.0;
            }
        }
    }
    Ok(MapImage { path: path.to_path_buf(), width, height, texels })
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
