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

/// Decodes one map image to RGB texels as stored (colour maps stay sRGB-encoded; the fur
/// linearises them).
fn read_map_image(path: &Path) -> Result<MapImage, LoadError> {
    let mut reader = image::ImageReader::open(path)
        .map_err(|e| LoadError::io(path, "read the map", e))?
        .with_guessed_format()
        .map_err(|e| LoadError::io(path, "read the map", e))?;
    let mut limits = image::Limits::default();
    limits.max_image_width = Some(MAX_MAP_SIDE);
    limits.max_image_height = Some(MAX_MAP_SIDE);
    reader.limits(limits);
    let img = reader.decode().map_err(|e| match e {
        image::ImageError::Limits(_) => {
            LoadError::invalid(path, format!("map is larger than {MAX_MAP_SIDE} pixels a side"))
        }
        e => LoadError::format(path, format!("cannot decode the map image: {e}")),
    })?;
    let (width, height) = (img.width(), img.height());
    if width == 0 || height == 0 {
        return Err(LoadError::invalid(path, "map image is empty"));
    }
    let texels = img.to_rgb32f().pixels().map(|p| p.0).collect();
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
