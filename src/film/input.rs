//! Reading back the EXR files tress writes (whole images, farm tiles, checkpoints), so
//! they can be merged or resumed bit for bit.
//!
//! Only files with exactly tress's channels, as 32-bit floats in one flat layer, are
//! accepted. The header is checked before any pixel is decoded: the pixel data it
//! announces must fit in what the file's length can hold even at the best ratio deflate
//! compression reaches, so a forged header cannot make the reader allocate more than the
//! file's size justifies.

use std::io::Cursor;
use std::path::Path;

use exr::meta::attribute::{AttributeValue, SampleType};
use exr::prelude::{FlatSamples, ReadChannels, ReadLayers};

use super::{Film, CHANNELS};
use crate::error::LoadError;

/// An image read from an EXR file: the pixels of its data window and where that window
/// lies in the whole image (the display window).
#[derive(Clone, Debug, PartialEq)]
pub struct ExrFilm {
    /// The pixels of the data window.
    pub film: Film,
    /// Column and row of the data window's top-left pixel in the whole image.
    pub at: (u32, u32),
    /// Width and height of the whole image.
    pub full: (u32, u32),
    /// The header's text attributes (name, value), other than the standard ones.
    pub attributes: Vec<(String, String)>,
}

/// Upper bound on how many bytes deflate can expand one byte into (its best ratio is about
/// 1032:1), with room for the uncompressed parts of a file: the most a header may announce
/// per byte of the file, here and for the images [`crate::prepare`] reads.
pub(crate) const MAX_EXPANSION: u64 = 1100;

/// Largest side of an image, as [`crate::scene::Description::validate`] allows.
const MAX_SIDE: u32 = 65_536;

/// Decodes an EXR file written by tress; `path` is used only in messages.
pub fn decode_exr(bytes: &[u8], path: &Path) -> Result<ExrFilm, LoadError> {
    let bad = |m: String| LoadError::format(path, m);
    let meta = guarded(path, || exr::meta::MetaData::read_from_buffered(Cursor::new(bytes), false))?;
    let [header] = meta.headers.as_slice() else {
        return Err(bad(format!("the file has {} parts, but tress images have one", meta.headers.len())));
    };
    if header.deep {
        return Err(bad("the file holds deep data, which tress does not write".into()));
    }
    let mut names: Vec<String> = header.channels.list.iter().map(|c| c.name.to_string()).collect();
    names.sort();
    let mut expected: Vec<&str> = CHANNELS.iter().map(|c| c.0).collect();
    expected.sort();
    if names != expected {
        return Err(bad(format!("channels {} are not those tress writes ({})", names.join(", "), expected.join(", "))));
    }
    if let Some(c) = header.channels.list.iter().find(|c| c.sample_type != SampleType::F32 || c.sampling.area() != 1) {
        return Err(bad(format!("channel {} is not full-resolution 32-bit float", c.name)));
    }
    let size = header.layer_size;
    let announced = (size.0 as u128) * (size.1 as u128) * (CHANNELS.len() as u128) * 4;
    if announced > u128::from(MAX_EXPANSION) * bytes.len() as u128 {
        return Err(bad(format!(
            "the header announces a {}x{} image, more than a file of {} bytes can hold",
            size.0,
            size.1,
            bytes.len()
        )));
    }
    let display = header.shared_attributes.display_window;
    let position = header.own_attributes.layer_position;
    let (Ok(x), Ok(y), Ok(w), Ok(h), Ok(fw), Ok(fh)) = (
        u32::try_from(position.0),
        u32::try_from(position.1),
        u32::try_from(size.0),
        u32::try_from(size.1),
        u32::try_from(display.size.0),
        u32::try_from(display.size.1),
    ) else {
        return Err(bad("the data or display window is out of range".into()));
    };
    if display.position.0 != 0 || display.position.1 != 0 {
        return Err(bad("the display window does not start at (0, 0)".into()));
    }
    // The largest image tress renders; it also bounds what merging tiles allocates.
    if fw > MAX_SIDE || fh > MAX_SIDE {
        return Err(bad(format!("the {fw}x{fh} image is larger than tress renders ({MAX_SIDE} pixels a side)")));
    }
    let full = super::Region::full(fw, fh);
    if w == 0 || h == 0 || !full.contains(&super::Region { x, y, width: w, height: h }) {
        return Err(bad(format!("the {w}x{h} data window at ({x}, {y}) is not inside the {fw}x{fh} image")));
    }

    let image = guarded(path, || {
        exr::prelude::read()
            .no_deep_data()
            .largest_resolution_level()
            .all_channels()
            .first_valid_layer()
            .all_attributes()
            .non_parallel()
            .from_buffered(Cursor::new(bytes))
    })?;
    let layer = &image.layer_data;
    let mut film = Film::new(w, h);
    for (name, _, set) in CHANNELS {
        let channel = layer.channel_data.list.iter().find(|c| c.name == *name);
        let Some(FlatSamples::F32(samples)) = channel.map(|c| &c.sample_data) else {
            return Err(bad(format!("channel {name} is missing or not 32-bit float")));
        };
        if samples.len() != film.pixels.len() {
            return Err(bad(format!("channel {name} has {} samples for {} pixels", samples.len(), film.pixels.len())));
        }
        film.pixels.iter_mut().zip(samples).for_each(|(p, v)| set(p, *v));
    }
    let mut attributes: Vec<(String, String)> = layer
        .attributes
        .other
        .iter()
        .chain(&image.attributes.other)
        .filter_map(|(name, value)| match value {
            AttributeValue::Text(text) => Some((name.to_string(), text.to_string())),
            _ => None,
        })
        .collect();
    attributes.sort();
    Ok(ExrFilm { film, at: (x, y), full: (fw, fh), attributes })
}

/// Runs the exr crate on untrusted bytes (`path` names them in errors). It is not known to
/// panic on bad input, but a bad file must never take the program down, so a panic in it
/// becomes an error too.
pub(crate) fn guarded<T>(path: &Path, f: impl FnOnce() -> exr::error::Result<T>) -> Result<T, LoadError> {
    match std::panic::catch_unwind(std::panic::AssertUnwindSafe(f)) {
        Ok(Ok(v)) => Ok(v),
        Ok(Err(e)) => Err(LoadError::format(path, format!("not a readable exr file: {e}"))),
        Err(_) => Err(LoadError::format(path, "not a readable exr file: the decoder failed on it")),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::film::{write_image_part, Pixel};
    use glam::Vec3;

    fn film() -> Film {
        let mut f = Film::new(5, 3);
        for (i, p) in f.pixels.iter_mut().enumerate() {
            if i % 2 == 0 {
                *p = Pixel {
                    color: Vec3::new(i as f32 * 0.1, -0.0, 1e-40),
                    coverage: 0.25,
                    depth: 3.5,
                    normal: Vec3::new(0.0, 1.0, -0.0),
                    object_id: 2.0,
                    strand_id: 77.0,
                    ..*p
                };
            }
        }
        f
    }

    #[test]
    fn a_part_round_trips_bit_for_bit() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("part.exr");
        write_image_part(&path, &film(), (3, 4), (9, 8), &[("tressTile", "1/3")]).unwrap();
        let back = decode_exr(&std::fs::read(&path).unwrap(), &path).unwrap();
        assert_eq!((back.at, back.full), ((3, 4), (9, 8)));
        let bits =
            |f: &Film| f.pixels.iter().flat_map(|p| CHANNELS.map(|(_, get, _)| get(p).to_bits())).collect::<Vec<_>>();
        assert_eq!(bits(&back.film), bits(&film()));
        assert_eq!(back.attributes, vec![("tressTile".to_string(), "1/3".to_string())]);
    }

    #[test]
    fn parts_that_do_not_fit_are_refused_when_writing() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("part.exr");
        let e = write_image_part(&path, &film(), (5, 4), (9, 8), &[]).unwrap_err().to_string();
        assert!(e.contains("does not fit in a 9x8 image"), "{e}");
        let png = dir.path().join("part.png");
        let e = write_image_part(&png, &film(), (1, 0), (9, 8), &[]).unwrap_err().to_string();
        assert!(e.contains("PNG file can only hold a whole image"), "{e}");
        assert!(!path.exists() && !png.exists());
    }

    #[test]
    fn foreign_and_forged_files_are_errors() {
        let path = Path::new("x.exr");
        let e = decode_exr(b"not an exr file at all", path).unwrap_err().to_string();
        assert!(e.starts_with("x.exr: not a readable exr file"), "{e}");
        // An RGBA image from another tool.
        let dir = tempfile::tempdir().unwrap();
        let other = dir.path().join("rgba.exr");
        exr::prelude::write_rgba_file(&other, 4, 4, |_, _| (0.5f32, 0.5f32, 0.5f32, 1.0f32)).unwrap();
        let e = decode_exr(&std::fs::read(&other).unwrap(), path).unwrap_err().to_string();
        assert!(e.contains("are not those tress writes"), "{e}");
        // A header announcing far more pixels than the file could hold.
        let small = dir.path().join("small.exr");
        write_image_part(&small, &film(), (0, 0), (5, 3), &[]).unwrap();
        let mut bytes = std::fs::read(&small).unwrap();
        let window = bytes.windows(10).position(|w| w == b"dataWindow").unwrap();
        // box2i after the name, the type "box2i\0" and the size: xMin yMin xMax yMax.
        let max = window + 11 + 6 + 4 + 8;
        bytes[max..max + 4].copy_from_slice(&1_000_000i32.to_le_bytes());
        let e = decode_exr(&bytes, path).unwrap_err().to_string();
        assert!(e.contains("more than a file of") || e.contains("not inside"), "{e}");
    }
}
