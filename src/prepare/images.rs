//! Raster images read as linear RGB floats: environment maps (OpenEXR, Radiance `.hdr`,
//! PFM) and textures (PNG, JPEG and the same high-dynamic-range formats).
//!
//! Eight-bit images (PNG, JPEG) hold sRGB-encoded colour: decoded to linear light for
//! colours ([`Encoding::Srgb`]), or read as they are for data such as roughness
//! ([`Encoding::Linear`]). Every size is checked before pixels are allocated: the header
//! must announce at most [`MAX_PIXELS`] pixels, and no more than the file's length can
//! hold, so a forged header cannot make a reader allocate unbounded memory.

use crate::error::LoadError;
use crate::film::{guarded_exr as guarded, MAX_EXPANSION};
use crate::shading::texture::Texture;
use std::io::Cursor;
use std::path::{Path, PathBuf};

/// Most pixels an image may have (a 16k x 8k environment map).
pub const MAX_PIXELS: u64 = crate::light::MAX_ENVIRONMENT_PIXELS;

/// How the values of 8-bit images are encoded (high-dynamic-range formats are linear).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Encoding {
    /// sRGB-encoded colour, decoded to linear values.
    Srgb,
    /// Values read as they are, scaled to [0, 1].
    Linear,
}

/// An image as linear RGB floats.
#[derive(Clone, Debug, PartialEq)]
pub struct RgbImage {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// Three floats a pixel, row by row from the top.
    pub rgb: Vec<f32>,
}

/// Textures decoded so far, by file and encoding: a file that several materials name is
/// decoded once and its pixels shared.
#[derive(Default)]
pub struct Textures(std::collections::HashMap<(PathBuf, Encoding), Texture>);

impl Textures {
    /// The texture of the image at `path` read with `encoding`, decoded on first use.
    pub fn get(&mut self, path: &Path, encoding: Encoding) -> Result<Texture, LoadError> {
        if let Some(t) = self.0.get(&(path.to_path_buf(), encoding)) {
            return Ok(t.clone());
        }
        let image = read_rgb(path, encoding)?;
        let t = Texture::from_pixels(image.width, image.height, &image.rgb).map_err(|m| LoadError::invalid(path, m))?;
        self.0.insert((path.to_path_buf(), encoding), t.clone());
        Ok(t)
    }
}

/// Reads an image as linear RGB, choosing the decoder by the file's extension.
pub fn read_rgb(path: &Path, encoding: Encoding) -> Result<RgbImage, LoadError> {
    let extension = path.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase);
    let bytes = crate::input_file::read(path, crate::input_file::Kind::Map)?;
    match extension.as_deref() {
        Some("exr") => decode_exr(&bytes, path),
        Some("pfm") => decode_pfm(&bytes, path),
        Some("hdr") => decode_with_image(&bytes, path, image::ImageFormat::Hdr, Encoding::Linear),
        Some("png") => decode_with_image(&bytes, path, image::ImageFormat::Png, encoding),
        Some("jpg" | "jpeg") => decode_with_image(&bytes, path, image::ImageFormat::Jpeg, encoding),
        _ => Err(LoadError::format(path, "unknown image format: expected .exr, .hdr, .pfm, .png or .jpg")),
    }
}

/// Checks a header's size against [`MAX_PIXELS`] and what `file_bytes` can hold at
/// `max_ratio` decoded bytes per file byte.
fn check_size(
    path: &Path,
    width: u64,
    height: u64,
    decoded_bytes: u64,
    file_bytes: usize,
    max_ratio: u64,
) -> Result<(), LoadError> {
    if width == 0 || height == 0 {
        return Err(LoadError::invalid(path, format!("the image is {width}x{height}: it has no pixels")));
    }
    if width.saturating_mul(height) > MAX_PIXELS {
        return Err(LoadError::invalid(
            path,
            format!("the {width}x{height} image is larger than tress reads ({MAX_PIXELS} pixels)"),
        ));
    }
    if decoded_bytes > max_ratio.saturating_mul(file_bytes as u64) {
        return Err(LoadError::format(
            path,
            format!("the header announces a {width}x{height} image, more than a file of {file_bytes} bytes can hold"),
        ));
    }
    Ok(())
}

fn decode_exr(bytes: &[u8], path: &Path) -> Result<RgbImage, LoadError> {
    use exr::prelude::{ReadChannels, ReadLayers, ReadSpecificChannel};
    let meta = guarded(path, || exr::meta::MetaData::read_from_buffered(Cursor::new(bytes), false))?;
    let Some(header) = meta.headers.iter().find(|h| !h.deep) else {
        return Err(LoadError::format(path, "the file holds no flat image layer"));
    };
    let (w, h) = (header.layer_size.0 as u64, header.layer_size.1 as u64);
    let names: Vec<String> = header.channels.list.iter().map(|c| c.name.to_string()).collect();
    if !["R", "G", "B"].iter().all(|n| names.iter().any(|c| c == n)) {
        return Err(LoadError::invalid(
            path,
            format!("the image has channels {}; an RGB image needs R, G and B", names.join(", ")),
        ));
    }
    let per_pixel: u64 = header.channels.list.iter().map(|c| c.sample_type.bytes_per_sample() as u64).sum();
    check_size(path, w, h, (w * h).saturating_mul(per_pixel.max(1)), bytes.len(), MAX_EXPANSION)?;
    let image = guarded(path, || {
        exr::prelude::read()
            .no_deep_data()
            .largest_resolution_level()
            .specific_channels()
            .required("R")
            .required("G")
            .required("B")
            .collect_pixels(
                |size, _| (size.width(), vec![0.0f32; size.width() * size.height() * 3]),
                |(width, rgb): &mut (usize, Vec<f32>), at, (r, g, b): (f32, f32, f32)| {
                    let i = 3 * (at.y() * *width + at.x());
                    if let Some(p) = rgb.get_mut(i..i + 3) {
                        p.copy_from_slice(&[r, g, b]);
                    }
                },
            )
            .first_valid_layer()
            .all_attributes()
            .non_parallel()
            .from_buffered(Cursor::new(bytes))
    })?;
    let size = image.layer_data.size;
    Ok(RgbImage { width: size.0 as u32, height: size.1 as u32, rgb: image.layer_data.channel_data.pixels.1 })
}

/// Radiance `.hdr`, PNG and JPEG through the `image` crate, with its decoder limits set to
/// [`MAX_PIXELS`].
fn decode_with_image(
    bytes: &[u8],
    path: &Path,
    format: image::ImageFormat,
    encoding: Encoding,
) -> Result<RgbImage, LoadError> {
    let name = match format {
        image::ImageFormat::Hdr => "Radiance hdr",
        image::ImageFormat::Png => "png",
        _ => "jpeg",
    };
    let mut reader = image::ImageReader::new(Cursor::new(bytes));
    reader.set_format(format);
    let (w, h) =
        reader.into_dimensions().map_err(|e| LoadError::format(path, format!("not a readable {name} file: {e}")))?;
    // 8-bit formats decode to at most 4 bytes a pixel at up to MAX_EXPANSION per file byte;
    // Radiance files are run-length encoded, at most 4 bytes to a run of 127 pixels.
    let ratio = if format == image::ImageFormat::Hdr { 16 * 128 } else { MAX_EXPANSION };
    check_size(path, w as u64, h as u64, w as u64 * h as u64 * 4, bytes.len(), ratio)?;
    let mut reader = image::ImageReader::new(Cursor::new(bytes));
    reader.set_format(format);
    let mut limits = image::Limits::default();
    limits.max_image_width = Some(w);
    limits.max_image_height = Some(h);
    limits.max_alloc = Some(MAX_PIXELS * 16);
    reader.limits(limits);
    let decoded = reader.decode().map_err(|e| LoadError::format(path, format!("not a readable {name} file: {e}")))?;
    let rgb = if format == image::ImageFormat::Hdr {
        decoded.into_rgb32f().into_raw()
    } else {
        let table: Vec<f32> = (0..=255u8)
            .map(|v| match encoding {
                Encoding::Srgb => srgb_to_linear(v as f32 / 255.0),
                Encoding::Linear => v as f32 / 255.0,
            })
            .collect();
        decoded.into_rgb8().into_raw().into_iter().map(|v| table[v as usize]).collect()
    };
    Ok(RgbImage { width: w, height: h, rgb })
}

/// The sRGB transfer function inverted (IEC 61966-2-1).
fn srgb_to_linear(v: f32) -> f32 {
    if v <= 0.04045 {
        v / 12.92
    } else {
        ((v + 0.055) / 1.055).powf(2.4)
    }
}

/// Portable float maps: a text header `PF` (RGB) or `Pf` (grey), the width and height,
/// and a scale whose sign gives the byte order (negative: little-endian); then the
/// pixels as 32-bit floats, rows from the bottom up.
fn decode_pfm(bytes: &[u8], path: &Path) -> Result<RgbImage, LoadError> {
    let bad = |m: &str| LoadError::format(path, format!("not a readable pfm file: {m}"));
    // Three whitespace-separated header fields after the magic, the last followed by one
    // whitespace byte.
    let mut fields = Vec::new();
    let mut at = 0usize;
    while fields.len() < 4 {
        while at < bytes.len() && bytes[at].is_ascii_whitespace() {
            at += 1;
        }
        let start = at;
        while at < bytes.len() && !bytes[at].is_ascii_whitespace() {
            at += 1;
        }
        if start == at || at - start > 32 {
            return Err(bad("the header is incomplete"));
        }
        fields.push(std::str::from_utf8(&bytes[start..at]).map_err(|_| bad("the header is not text"))?);
    }
    let data = bytes.get(at + 1..).ok_or_else(|| bad("the header is incomplete"))?;
    let channels = match fields[0] {
        "PF" => 3,
        "Pf" => 1,
        _ => return Err(bad("it does not start with PF or Pf")),
    };
    let (Ok(w), Ok(h), Ok(scale)) = (fields[1].parse::<u64>(), fields[2].parse::<u64>(), fields[3].parse::<f32>())
    else {
        return Err(bad("the width, height or scale is not a number"));
    };
    if !(scale.is_finite() && scale != 0.0) {
        return Err(bad("the scale must be a finite, non-zero number"));
    }
    check_size(path, w, h, 0, 0, 0)?;
    let expected = w * h * channels * 4;
    if (data.len() as u64) < expected {
        return Err(LoadError::format(
            path,
            format!(
                "the header announces {w}x{h} pixels ({expected} bytes) but the file holds {} bytes of them",
                data.len()
            ),
        ));
    }
    let little = scale < 0.0;
    let (w, h, channels) = (w as usize, h as usize, channels as usize);
    let value = |i: usize| {
        let b: [u8; 4] = data[4 * i..4 * i + 4].try_into().expect("four bytes");
        if little {
            f32::from_le_bytes(b)
        } else {
            f32::from_be_bytes(b)
        }
    };
    let mut rgb = Vec::with_capacity(w * h * 3);
    for row in (0..h).rev() {
        for x in 0..w {
            let i = (row * w + x) * channels;
            match channels {
                3 => rgb.extend_from_slice(&[value(i), value(i + 1), value(i + 2)]),
                _ => rgb.extend_from_slice(&[value(i); 3]),
            }
        }
    }
    Ok(RgbImage { width: w as u32, height: h as u32, rgb })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `path` read as a latitude-longitude environment map.
    fn read_environment(path: &Path) -> Result<crate::light::EnvironmentMap, LoadError> {
        let file = crate::scene::EnvironmentFile {
            path: path.to_path_buf(),
            projection: crate::scene::Projection::LatLong,
            tint: glam::Vec3::ONE,
            illuminance: None,
            placement: crate::light::MapPlacement::new(0.0, 1.0),
            fallback: None,
        };
        super::super::environment::read(&file).map(|(map, _)| map)
    }

    fn pfm(w: u32, h: u32, values: &[f32]) -> Vec<u8> {
        let mut bytes = format!("PF\n{w} {h}\n-1.0\n").into_bytes();
        values.iter().for_each(|v| bytes.extend_from_slice(&v.to_le_bytes()));
        bytes
    }

    #[test]
    fn pfm_rows_run_from_the_bottom() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("map.pfm");
        // Bottom row red, top row blue.
        std::fs::write(&path, pfm(2, 2, &[1., 0., 0., 1., 0., 0., 0., 0., 1., 0., 0., 1.])).unwrap();
        let image = read_rgb(&path, Encoding::Linear).unwrap();
        assert_eq!((image.width, image.height), (2, 2));
        assert_eq!(&image.rgb[..3], &[0.0, 0.0, 1.0]);
        assert_eq!(&image.rgb[9..], &[1.0, 0.0, 0.0]);
        // Big-endian grey.
        let mut be = b"Pf 1 1 1.0\n".to_vec();
        be.extend_from_slice(&0.25f32.to_be_bytes());
        std::fs::write(&path, be).unwrap();
        assert_eq!(read_rgb(&path, Encoding::Linear).unwrap().rgb, vec![0.25; 3]);
    }

    #[test]
    fn exr_hdr_and_png_decode_to_linear_rgb() {
        let dir = tempfile::tempdir().unwrap();
        let exr = dir.path().join("map.exr");
        exr::prelude::write_rgb_file(&exr, 3, 2, |x, y| (x as f32, y as f32, 2.5f32)).unwrap();
        let image = read_rgb(&exr, Encoding::Srgb).unwrap();
        assert_eq!((image.width, image.height), (3, 2));
        assert_eq!(&image.rgb[3 * 5..], &[2.0, 1.0, 2.5]);

        let hdr = dir.path().join("map.hdr");
        let pixels = vec![image::Rgb([4.0f32, 0.5, 0.125]); 6];
        let mut out = std::fs::File::create(&hdr).unwrap();
        image::codecs::hdr::HdrEncoder::new(&mut out).encode(&pixels, 3, 2).unwrap();
        drop(out);
        let image = read_rgb(&hdr, Encoding::Srgb).unwrap();
        assert_eq!(&image.rgb[..3], &[4.0, 0.5, 0.125]);

        let png = dir.path().join("tex.png");
        image::RgbImage::from_pixel(2, 2, image::Rgb([255, 188, 0])).save(&png).unwrap();
        let srgb = read_rgb(&png, Encoding::Srgb).unwrap();
        // sRGB 188 is linear 0.5 (to three digits).
        assert!((srgb.rgb[1] - 0.5029).abs() < 1e-3 && srgb.rgb[0] == 1.0 && srgb.rgb[2] == 0.0, "{:?}", srgb.rgb);
        assert!((read_rgb(&png, Encoding::Linear).unwrap().rgb[1] - 188.0 / 255.0).abs() < 1e-6);
    }

    /// Each bad file gives an error naming it and what is wrong.
    #[test]
    fn bad_files_are_errors_naming_the_file() {
        let dir = tempfile::tempdir().unwrap();
        let case = |name: &str, bytes: &[u8], expected: &str| {
            let path = dir.path().join(name);
            std::fs::write(&path, bytes).unwrap();
            let e = read_environment(&path).unwrap_err().to_string();
            assert!(e.starts_with(&path.display().to_string()) && e.contains(expected), "{name}: {e}");
        };
        case("garbage.exr", b"not an exr", "not a readable exr file");
        case("garbage.hdr", b"#?RADIANCE\nnonsense", "not a readable Radiance hdr file");
        case("map.tiff", b"II*\0", "unknown image format");
        case("short.pfm", &pfm(4, 4, &[1.0; 5]), "header announces 4x4 pixels");
        case("huge.pfm", b"PF\n100000 100000\n-1\n", "larger than tress reads");
        case("magic.pfm", b"P6\n1 1\n255\nabc", "does not start with PF");
        case("cut.pfm", b"PF\n1", "header is incomplete");
        case("nan.pfm", &pfm(1, 1, &[1.0, f32::NAN, 1.0]), "pixel (0, 0)");
        let grey = dir.path().join("grey.exr");
        let channel = exr::prelude::AnyChannel::new("Y", exr::prelude::FlatSamples::F32(vec![0.5; 4]));
        let layer = exr::prelude::Layer::new(
            (2, 2),
            exr::prelude::LayerAttributes::default(),
            exr::prelude::Encoding::FAST_LOSSLESS,
            exr::prelude::AnyChannels::sort(smallvec::smallvec![channel]),
        );
        use exr::prelude::WritableImage;
        exr::prelude::Image::from_layer(layer).write().to_file(&grey).unwrap();
        let e = read_environment(&grey).unwrap_err().to_string();
        assert!(e.contains("grey.exr") && e.contains("needs R, G and B"), "{e}");
        let missing = dir.path().join("missing.exr");
        let e = read_environment(&missing).unwrap_err().to_string();
        assert!(e.contains("missing.exr: could not open the file"), "{e}");
        let e = read_environment(dir.path()).unwrap_err().to_string();
        assert!(e.contains("not a regular file"), "{e}");
    }
}
