//! Writing a [`Film`] to an image file.
//!
//! The format is chosen by the file extension, ignoring case:
//!
//! * `.png`: 8-bit RGB. The linear colour is clamped to [0, 1] and encoded with the sRGB transfer
//!   function ([`srgb_encode`]). Coverage and the AOVs are not stored.
//! * `.exr`: 32-bit float, lossless ZIP compression, with the channels
//!   * `R`, `G`, `B`: linear colour, exactly as stored in the film (the average over all samples),
//!   * `A`: coverage,
//!   * `Z`: depth along the camera ray, `+inf` where no sample hit anything,
//!   * `N.X`, `N.Y`, `N.Z`: shading normal (surfaces) or tangent (hair), zero where nothing was hit,
//!   * `objectId`, `strandId`: object and strand indices, `-1` where not applicable,
//!   * `strandAlong`, `rootUV.U`, `rootUV.V`, `clumpId`, `strandRandom`: on hair, the position
//!     along the strand (0 root, 1 tip), its root's surface UV, its clump (guide) index and its
//!     stable random value in [0, 1); `-1` where not applicable or unknown,
//!   * `lodLevel`: on hair, the level of detail the hit used (0 at full detail); `-1` elsewhere,
//!   * `coverage`: coverage again, as a single channel for tools that do not treat `A` as data,
//!   * `samples`: camera samples the pixel took (varies with adaptive supersampling).
//!
//! Infinite depth is written as `+inf`: EXR stores IEEE 754 floats bit for bit, so it round-trips
//! through the `exr` crate (and OpenEXR) unchanged, and it cannot be confused with a real distance.
//!
//! Writes are atomic: the image is encoded into a temporary file in the destination directory,
//! flushed and synced, then renamed over the target. A failed or interrupted write never leaves a
//! truncated image at the target path; an existing file there stays intact until the rename. (A
//! process killed mid-write can leave a hidden `.NAME.XXXXXX.tmp` file beside the target.)

use std::ffi::OsString;
use std::fs::File;
use std::io::{self, BufWriter, Write};
use std::path::{Path, PathBuf};

use exr::prelude::{
    AnyChannel, AnyChannels, AttributeValue, Encoding, FlatSamples, Image, Layer, LayerAttributes, SmallVec, Text,
    WritableImage,
};
use image::{ExtendedColorType, ImageEncoder};
use tempfile::NamedTempFile;

use super::Film;

/// File extensions [`write_image`] understands (lower case, without the dot).
const SUPPORTED_EXTENSIONS: &str = ".png, .exr";

/// Why an image could not be written. Every message names the output path.
#[derive(Debug, thiserror::Error)]
pub enum OutputError {
    /// The path has no extension, or one that names no supported format.
    #[error(
        "cannot write image `{}`: {} (supported: {SUPPORTED_EXTENSIONS})",
        path.display(),
        match extension {
            Some(extension) => format!("unsupported file extension `.{extension}`"),
            None => "the file name has no extension".to_string(),
        }
    )]
    UnsupportedExtension {
        /// The requested output path.
        path: PathBuf,
        /// The extension found, if any (as written, not lower-cased).
        extension: Option<String>,
    },

    /// The directory that should contain the output does not exist (or is not a directory).
    #[error("cannot write image `{}`: directory `{}` does not exist", path.display(), directory.display())]
    MissingDirectory {
        /// The requested output path.
        path: PathBuf,
        /// The directory that is missing.
        directory: PathBuf,
    },

    /// The film cannot be stored: it is empty, or its pixel count does not match its size.
    #[error("cannot write image `{}`: {reason}", path.display())]
    InvalidFilm {
        /// The requested output path.
        path: PathBuf,
        /// What is wrong with the film.
        reason: String,
    },

    /// A metadata attribute cannot be stored in the EXR header.
    #[error("cannot write image `{}`: invalid header attribute `{name}`: {reason}", path.display())]
    InvalidAttribute {
        /// The requested output path.
        path: PathBuf,
        /// The attribute's name.
        name: String,
        /// Why it was rejected.
        reason: String,
    },

    /// Creating, writing, syncing or renaming the file failed.
    #[error("cannot write image `{}`: {step}: {error}", path.display())]
    Write {
        /// The requested output path.
        path: PathBuf,
        /// Which step failed, e.g. "cannot create a temporary file in its directory".
        step: &'static str,
        /// The underlying I/O error.
        error: io::Error,
    },

    /// The image encoder rejected the image.
    #[error("cannot write image `{}`: {format} encoding failed: {message}", path.display())]
    Encode {
        /// The requested output path.
        path: PathBuf,
        /// `"PNG"` or `"EXR"`.
        format: &'static str,
        /// The encoder's description of the problem.
        message: String,
    },
}

/// Encodes a linear colour component as an 8-bit sRGB value.
///
/// The value is clamped to [0, 1] (NaN counts as 0), passed through the exact piecewise sRGB
/// transfer function (linear below 0.0031308, a 1/2.4 power above) and rounded to the nearest
/// integer: 0 -> 0, 0.5 -> 188, 1 -> 255.
pub fn srgb_encode(linear: f32) -> u8 {
    let c = if linear.is_nan() { 0.0 } else { f64::from(linear.clamp(0.0, 1.0)) };
    let encoded = if c <= 0.0031308 { 12.92 * c } else { 1.055 * c.powf(1.0 / 2.4) - 0.055 };
    (encoded * 255.0).round().clamp(0.0, 255.0) as u8
}

/// Writes `film` to `path`, choosing the format by the extension (`.png` or `.exr`, any case).
///
/// The same as [`write_image_with`] without header attributes; see the module documentation for
/// what each format contains.
pub fn write_image(path: &Path, film: &Film) -> Result<(), OutputError> {
    write_image_with(path, film, &[])
}

/// Writes `film` to `path` like [`write_image`], adding string `attributes` (name, value) to the
/// header of an EXR file (for example to mark a partial render).
///
/// PNG files ignore the attributes. EXR attribute names must be non-empty, at most 255 bytes, not
/// one of the names the EXR format reserves (such as `channels` or `comments`) and not repeated;
/// names and values may only contain characters U+0000..=U+00FF, which is all the `exr` crate's text can hold.
/// The file is replaced atomically: on error nothing is left at `path` (an existing file there
/// is untouched).
pub fn write_image_with(path: &Path, film: &Film, attributes: &[(&str, &str)]) -> Result<(), OutputError> {
    write_image_part(path, film, (0, 0), (film.width, film.height), attributes)
}

/// Writes `film` as the part of a larger `full` = (width, height) image whose top-left pixel
/// is at `at`, like [`write_image_with`] otherwise: in an EXR file the film is the data window
/// and `full` the display window, the standard way to store a crop (a farm tile, a region).
/// A PNG file can only hold a whole image.
pub fn write_image_part(
    path: &Path,
    film: &Film,
    at: (u32, u32),
    full: (u32, u32),
    attributes: &[(&str, &str)],
) -> Result<(), OutputError> {
    let format = Format::of(path)?;
    check_film(path, film)?;
    let part = Part { at, full };
    let invalid = |reason: String| Err(OutputError::InvalidFilm { path: path.to_owned(), reason });
    let fits = |at: u32, size: u32, full: u32| at.checked_add(size).is_some_and(|end| end <= full);
    // EXR stores positions as i32.
    if !fits(at.0, film.width, full.0) || !fits(at.1, film.height, full.1) || full.0.max(full.1) > i32::MAX as u32 {
        return invalid(format!(
            "a {}x{} film at ({}, {}) does not fit in a {}x{} image",
            film.width, film.height, at.0, at.1, full.0, full.1
        ));
    }
    if format == Format::Png && (at != (0, 0) || full != (film.width, film.height)) {
        return invalid("a PNG file can only hold a whole image, not a part of one: use .exr".into());
    }
    let directory = destination_directory(path)?;
    match format {
        Format::Png => {
            let rgb = png_bytes(film);
            write_atomically(path, &directory, |file| {
                image::codecs::png::PngEncoder::new(file)
                    .write_image(&rgb, film.width, film.height, ExtendedColorType::Rgb8)
                    .map_err(|error| match error {
                        image::ImageError::IoError(error) => write_error(path, WRITING)(error),
                        other => {
                            OutputError::Encode { path: path.to_owned(), format: "PNG", message: other.to_string() }
                        }
                    })
            })
        }
        Format::Exr => {
            let image = exr_image(path, film, &part, attributes)?;
            write_atomically(path, &directory, |file| {
                image.write().to_buffered(file).map_err(|error| match error {
                    exr::error::Error::Io(error) => write_error(path, WRITING)(error),
                    other => OutputError::Encode { path: path.to_owned(), format: "EXR", message: other.to_string() },
                })
            })
        }
    }
}

/// Checks, before a long render, that an image could be written to `path`: a supported
/// extension and an existing directory.
pub fn check_output(path: &Path) -> Result<(), OutputError> {
    Format::of(path)?;
    destination_directory(path).map(|_| ())
}

/// Where a film lies in the image it is part of: its top-left pixel and the whole size.
struct Part {
    at: (u32, u32),
    full: (u32, u32),
}

/// The file formats [`write_image`] can produce.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Format {
    Png,
    Exr,
}

impl Format {
    /// The format named by `path`'s extension.
    fn of(path: &Path) -> Result<Format, OutputError> {
        let extension = path.extension();
        match extension.and_then(|e| e.to_str()).map(str::to_ascii_lowercase).as_deref() {
            Some("png") => Ok(Format::Png),
            Some("exr") => Ok(Format::Exr),
            _ => Err(OutputError::UnsupportedExtension {
                path: path.to_owned(),
                extension: extension.map(|e| e.to_string_lossy().into_owned()),
            }),
        }
    }
}

/// Rejects films no image file can hold.
fn check_film(path: &Path, film: &Film) -> Result<(), OutputError> {
    let invalid = |reason: String| Err(OutputError::InvalidFilm { path: path.to_owned(), reason });
    if film.width == 0 || film.height == 0 {
        return invalid(format!("the film is empty ({}x{} pixels)", film.width, film.height));
    }
    let expected = film.width as u64 * film.height as u64;
    if film.pixels.len() as u64 != expected {
        return invalid(format!(
            "the film is {}x{} but holds {} pixels instead of {expected}",
            film.width,
            film.height,
            film.pixels.len()
        ));
    }
    Ok(())
}

/// The directory `path` goes into, which must exist.
fn destination_directory(path: &Path) -> Result<PathBuf, OutputError> {
    let directory = match path.parent() {
        Some(parent) if !parent.as_os_str().is_empty() => parent.to_owned(),
        _ => PathBuf::from("."),
    };
    if directory.is_dir() {
        Ok(directory)
    } else {
        Err(OutputError::MissingDirectory { path: path.to_owned(), directory })
    }
}

/// Runs `encode` on a buffered temporary file in `directory`, then flushes, syncs and renames it
/// to `path`. The temporary file is deleted if any step fails.
fn write_atomically(
    path: &Path,
    directory: &Path,
    encode: impl FnOnce(&mut BufWriter<&mut File>) -> Result<(), OutputError>,
) -> Result<(), OutputError> {
    // A dot-prefixed name next to the target, so a leftover from a crash is recognisable.
    let mut prefix = OsString::from(".");
    prefix.push(path.file_name().unwrap_or_default());
    prefix.push(".");
    let mut builder = tempfile::Builder::new();
    builder.prefix(&prefix).suffix(".tmp");
    // Temporary files default to mode 0600; ask for 0666 so the result gets the permissions of
    // an ordinarily created file (the umask still applies).
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        builder.permissions(std::fs::Permissions::from_mode(0o666));
    }
    let mut temp: NamedTempFile =
        builder.tempfile_in(directory).map_err(write_error(path, "cannot create a temporary file in its directory"))?;
    // Held until the file is renamed or deleted: it tells this live temporary file from
    // the leftovers of killed runs, which are removed now.
    temp.as_file().lock().map_err(write_error(path, "cannot lock the temporary file"))?;
    remove_stale_temporaries(directory, &prefix, temp.path());

    let mut writer = BufWriter::new(temp.as_file_mut());
    encode(&mut writer)?;
    writer.flush().map_err(write_error(path, WRITING))?;
    drop(writer);
    temp.as_file().sync_all().map_err(write_error(path, "cannot sync the temporary file to disk"))?;
    temp.persist(path).map_err(|error| write_error(path, "cannot rename the temporary file over it")(error.error))?;
    Ok(())
}

/// Removes the temporary files named `prefix*.tmp` in `directory` that no live writer
/// holds locked: what a run killed while writing left behind. A file another process is
/// writing right now stays. Failures are ignored: a leftover is only clutter.
fn remove_stale_temporaries(directory: &Path, prefix: &OsString, own: &Path) {
    let Ok(entries) = std::fs::read_dir(directory) else { return };
    let prefix = prefix.as_encoded_bytes();
    for entry in entries.flatten() {
        let name = entry.file_name();
        let bytes = name.as_encoded_bytes();
        // The random part is never empty: a name of exactly `prefix.tmp` is not ours.
        if !(bytes.len() > prefix.len() + 4 && bytes.starts_with(prefix) && bytes.ends_with(b".tmp")) {
            continue;
        }
        let candidate = entry.path();
        if candidate == own || !entry.file_type().is_ok_and(|t| t.is_file()) {
            continue;
        }
        if let Ok(file) = File::open(&candidate) {
            if file.try_lock().is_ok() {
                let _ = std::fs::remove_file(&candidate);
            }
        }
    }
}

/// The step of [`OutputError::Write`] for failures while writing the encoded bytes.
const WRITING: &str = "cannot write the temporary file";

/// Turns an I/O error of `step` into an [`OutputError::Write`] for `path`.
fn write_error<'a>(path: &'a Path, step: &'static str) -> impl FnOnce(io::Error) -> OutputError + 'a {
    move |error| OutputError::Write { path: path.to_owned(), step, error }
}

/// The film's colour as 8-bit sRGB, three bytes per pixel, rows from the top.
fn png_bytes(film: &Film) -> Vec<u8> {
    film.pixels.iter().flat_map(|p| [srgb_encode(p.color.x), srgb_encode(p.color.y), srgb_encode(p.color.z)]).collect()
}

/// The film as a single-layer EXR image with `attributes` in its header, its data window
/// placed in the display window as `part` says.
fn exr_image(
    path: &Path,
    film: &Film,
    part: &Part,
    attributes: &[(&str, &str)],
) -> Result<Image<Layer<AnyChannels<FlatSamples>>>, OutputError> {
    let mut layer_attributes = LayerAttributes {
        software_name: Some(Text::from(concat!("tress ", env!("CARGO_PKG_VERSION")))),
        ..LayerAttributes::default()
    };
    for &(name, value) in attributes {
        let invalid = |reason: &str| OutputError::InvalidAttribute {
            path: path.to_owned(),
            name: name.to_owned(),
            reason: reason.to_owned(),
        };
        let text_name = Text::new_or_none(name).ok_or_else(|| invalid("the name has characters beyond U+00FF"))?;
        let text_value = Text::new_or_none(value).ok_or_else(|| invalid("the value has characters beyond U+00FF"))?;
        if text_name.as_slice().is_empty() {
            return Err(invalid("the name is empty"));
        }
        if text_name.as_slice().len() > 255 {
            return Err(invalid("the name is longer than 255 bytes"));
        }
        if exr::meta::header::standard_names::ALL.contains(&text_name.as_slice()) {
            return Err(invalid("the name is reserved by the EXR format"));
        }
        if layer_attributes.other.insert(text_name, AttributeValue::Text(text_value)).is_some() {
            return Err(invalid("the name is given more than once"));
        }
    }

    let channels: SmallVec<[AnyChannel<FlatSamples>; 4]> = super::CHANNELS
        .iter()
        .map(|(name, get, _)| AnyChannel::new(*name, FlatSamples::F32(film.pixels.iter().map(get).collect())))
        .collect();
    let size = (film.width as usize, film.height as usize);
    layer_attributes.layer_position = exr::math::Vec2(part.at.0 as i32, part.at.1 as i32);
    let layer = Layer::new(size, layer_attributes, Encoding::SMALL_LOSSLESS, AnyChannels::sort(channels));
    let display = exr::meta::attribute::IntegerBounds::from_dimensions((part.full.0 as usize, part.full.1 as usize));
    Ok(Image::new(exr::meta::header::ImageAttributes::new(display), layer))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::film::Pixel;
    use glam::Vec3;

    /// A 4x3 film whose pixels all differ, with a mix of hits and misses.
    fn test_film() -> Film {
        let mut film = Film::new(4, 3);
        let linear = [0.0, 1.0, 0.5, 0.0031308, 0.25, 2.0, -1.0, 0.001, 0.75, 0.04, 0.9, 0.1];
        for (i, pixel) in film.pixels.iter_mut().enumerate() {
            let v = linear[i];
            pixel.color = Vec3::new(v, linear[(i + 1) % 12], linear[(i + 5) % 12]);
            if i % 3 != 0 {
                *pixel = Pixel {
                    color: pixel.color,
                    coverage: i as f32 / 12.0,
                    depth: 1.5 + i as f32 * 0.37,
                    normal: Vec3::new(0.6, -0.8, i as f32 * 1e-3),
                    object_id: (i % 4) as f32,
                    strand_id: if i % 2 == 0 { 1000.0 + i as f32 } else { -1.0 },
                    strand_along: i as f32 / 16.0,
                    root_uv: [i as f32 * 0.05, 1.0 - i as f32 * 0.05],
                    clump_id: (i / 2) as f32,
                    strand_random: 0.125 * (i % 8) as f32,
                    lod_level: (i % 5) as f32,
                    samples: (i * 3) as f32,
                };
            }
        }
        film
    }

    fn dir_entries(dir: &Path) -> Vec<String> {
        let mut names: Vec<String> =
            std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
        names.sort();
        names
    }

    #[test]
    fn srgb_known_values() {
        assert_eq!(srgb_encode(0.0), 0);
        assert_eq!(srgb_encode(1.0), 255);
        assert_eq!(srgb_encode(0.5), 188);
        assert_eq!(srgb_encode(0.18), 118);
        // Both branches meet at the boundary: 12.92 * 0.0031308 * 255 = 10.31.
        assert_eq!(srgb_encode(0.0031308), 10);
        assert_eq!(srgb_encode(0.0031307), 10);
        assert_eq!(srgb_encode(0.0031309), 10);
        assert_eq!(srgb_encode(0.001), 3);
        // Out of range and NaN clamp.
        assert_eq!(srgb_encode(-0.5), 0);
        assert_eq!(srgb_encode(7.0), 255);
        assert_eq!(srgb_encode(f32::INFINITY), 255);
        assert_eq!(srgb_encode(f32::NAN), 0);
    }

    #[test]
    fn srgb_is_monotonic() {
        let mut previous = 0;
        for i in 0..=10_000 {
            let value = srgb_encode(i as f32 / 10_000.0);
            assert!(value >= previous);
            previous = value;
        }
        assert_eq!(previous, 255);
    }

    #[test]
    fn png_round_trip() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("out.PNG");
        let film = test_film();
        write_image(&path, &film).unwrap();

        let decoded = image::open(&path).unwrap();
        assert_eq!(decoded.color(), image::ColorType::Rgb8);
        let rgb = decoded.to_rgb8();
        assert_eq!((rgb.width(), rgb.height()), (4, 3));
        for (i, pixel) in film.pixels.iter().enumerate() {
            let (x, y) = (i as u32 % 4, i as u32 / 4);
            let expected = [srgb_encode(pixel.color.x), srgb_encode(pixel.color.y), srgb_encode(pixel.color.z)];
            assert_eq!(rgb.get_pixel(x, y).0, expected, "pixel ({x}, {y})");
        }
        // The known values in the first pixels of row 0.
        assert_eq!(rgb.get_pixel(0, 0).0[0], 0);
        assert_eq!(rgb.get_pixel(1, 0).0[0], 255);
        assert_eq!(rgb.get_pixel(2, 0).0[0], 188);
        assert_eq!(rgb.get_pixel(3, 0).0[0], 10);
        assert_eq!(dir_entries(dir.path()), ["out.PNG"]);
    }

    #[test]
    fn exr_round_trip() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("out.exr");
        let film = test_film();
        write_image_with(&path, &film, &[("tressStatus", "partial"), ("tressSamples", "17 of 64")]).unwrap();

        let image = exr::prelude::read_first_flat_layer_from_file(&path).unwrap();
        let layer = &image.layer_data;
        assert_eq!((layer.size.width(), layer.size.height()), (4, 3));

        let channel = |name: &str| -> Vec<f32> {
            let found = layer.channel_data.list.iter().find(|c| c.name == *name);
            match &found.unwrap_or_else(|| panic!("missing channel {name}")).sample_data {
                FlatSamples::F32(samples) => samples.clone(),
                other => panic!("channel {name} is not f32: {other:?}"),
            }
        };
        let expect = |name: &str, value: fn(&Pixel) -> f32| {
            let got = channel(name);
            let want: Vec<f32> = film.pixels.iter().map(value).collect();
            let bits = |v: &[f32]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
            assert_eq!(bits(&got), bits(&want), "channel {name}");
        };
        expect("R", |p| p.color.x);
        expect("G", |p| p.color.y);
        expect("B", |p| p.color.z);
        expect("A", |p| p.coverage);
        expect("Z", |p| p.depth);
        expect("N.X", |p| p.normal.x);
        expect("N.Y", |p| p.normal.y);
        expect("N.Z", |p| p.normal.z);
        expect("objectId", |p| p.object_id);
        expect("strandId", |p| p.strand_id);
        expect("strandAlong", |p| p.strand_along);
        expect("rootUV.U", |p| p.root_uv[0]);
        expect("rootUV.V", |p| p.root_uv[1]);
        expect("clumpId", |p| p.clump_id);
        expect("strandRandom", |p| p.strand_random);
        expect("lodLevel", |p| p.lod_level);
        expect("coverage", |p| p.coverage);
        expect("samples", |p| p.samples);
        assert_eq!(layer.channel_data.list.len(), 18);
        assert_eq!(channel("Z")[0], f32::INFINITY);

        let attribute = |name: &str| match layer.attributes.other.get(&Text::from(name)) {
            Some(AttributeValue::Text(text)) => text.to_string(),
            other => panic!("attribute {name}: {other:?}"),
        };
        assert_eq!(attribute("tressStatus"), "partial");
        assert_eq!(attribute("tressSamples"), "17 of 64");
        assert_eq!(dir_entries(dir.path()), ["out.exr"]);
    }

    #[test]
    fn png_ignores_attributes() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("a.png");
        write_image_with(&path, &test_film(), &[("tressStatus", "partial")]).unwrap();
        assert_eq!(image::open(&path).unwrap().to_rgb8().dimensions(), (4, 3));
    }

    #[test]
    fn bad_attributes_are_rejected_and_leave_nothing() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("a.exr");
        let film = test_film();
        for attributes in [
            &[("channels", "x")][..],
            &[("", "x")][..],
            &[("name\u{263a}", "x")][..],
            &[("ok", "\u{263a}")][..],
            &[("twice", "1"), ("twice", "2")][..],
        ] {
            let error = write_image_with(&path, &film, attributes).unwrap_err();
            assert!(matches!(error, OutputError::InvalidAttribute { .. }), "{error:?}");
            assert!(error.to_string().contains(&path.display().to_string()), "{error}");
        }
        let long = "n".repeat(256);
        assert!(write_image_with(&path, &film, &[(&long, "x")]).is_err());
        // 32..=255-byte names need the EXR "long names" flag, which the exr crate sets itself.
        let long = "n".repeat(200);
        write_image_with(&path, &film, &[(&long, "x")]).unwrap();
        std::fs::remove_file(&path).unwrap();
        assert!(dir_entries(dir.path()).is_empty());
    }

    #[test]
    fn unknown_extension_is_an_error_naming_the_file() {
        let dir = tempfile::tempdir().unwrap();
        for name in ["picture.jpg", "picture", "picture.png.bak"] {
            let path = dir.path().join(name);
            let error = write_image(&path, &test_film()).unwrap_err();
            assert!(matches!(error, OutputError::UnsupportedExtension { .. }), "{error:?}");
            let message = error.to_string();
            assert!(message.contains(&path.display().to_string()), "{message}");
            assert!(message.contains(".png") && message.contains(".exr"), "{message}");
        }
        assert!(dir_entries(dir.path()).is_empty());
    }

    #[test]
    fn missing_directory_is_an_error_and_leaves_nothing() {
        let dir = tempfile::tempdir().unwrap();
        let missing = dir.path().join("no/such/dir");
        for name in ["out.png", "out.exr"] {
            let path = missing.join(name);
            let error = write_image(&path, &test_film()).unwrap_err();
            assert!(matches!(error, OutputError::MissingDirectory { .. }), "{error:?}");
            assert!(error.to_string().contains(&path.display().to_string()), "{error}");
            assert!(!path.exists());
        }
        assert!(dir_entries(dir.path()).is_empty());
    }

    #[test]
    fn overwrite_replaces_and_leaves_no_temporary_files() {
        let dir = tempfile::tempdir().unwrap();
        for name in ["out.png", "out.exr"] {
            let path = dir.path().join(name);
            std::fs::write(&path, b"old contents").unwrap();
            write_image(&path, &test_film()).unwrap();
            let contents = std::fs::read(&path).unwrap();
            assert_ne!(contents, b"old contents");
            let magic: &[u8] = if name.ends_with("png") { b"\x89PNG" } else { &[0x76, 0x2f, 0x31, 0x01] };
            assert!(contents.starts_with(magic), "{name}");
        }
        assert_eq!(dir_entries(dir.path()), ["out.exr", "out.png"]);
    }

    #[test]
    fn failed_write_keeps_the_existing_file() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("out.exr");
        std::fs::write(&path, b"old contents").unwrap();
        let error = write_image_with(&path, &test_film(), &[("compression", "none")]).unwrap_err();
        assert!(matches!(error, OutputError::InvalidAttribute { .. }), "{error:?}");
        let error = write_image(&path, &Film { width: 4, height: 3, pixels: vec![] }).unwrap_err();
        assert!(matches!(error, OutputError::InvalidFilm { .. }), "{error:?}");
        assert!(error.to_string().contains(&path.display().to_string()), "{error}");
        assert_eq!(std::fs::read(&path).unwrap(), b"old contents");
        assert_eq!(dir_entries(dir.path()), ["out.exr"]);
    }

    #[test]
    fn empty_film_is_rejected() {
        let dir = tempfile::tempdir().unwrap();
        let error = write_image(&dir.path().join("e.png"), &Film::new(0, 5)).unwrap_err();
        assert!(matches!(error, OutputError::InvalidFilm { .. }), "{error:?}");
        assert!(dir_entries(dir.path()).is_empty());
    }

    #[test]
    fn bare_file_name_goes_into_the_current_directory() {
        assert_eq!(destination_directory(Path::new("x.png")).unwrap(), PathBuf::from("."));
    }

    #[cfg(unix)]
    #[test]
    fn output_gets_ordinary_file_permissions() {
        use std::os::unix::fs::PermissionsExt;
        let dir = tempfile::tempdir().unwrap();
        let ordinary = dir.path().join("ordinary");
        std::fs::write(&ordinary, b"x").unwrap();
        let path = dir.path().join("out.png");
        write_image(&path, &test_film()).unwrap();
        let mode = |p: &Path| std::fs::metadata(p).unwrap().permissions().mode() & 0o777;
        assert_eq!(mode(&path), mode(&ordinary));
    }

    #[test]
    fn encoder_failure_leaves_nothing() {
        // An encoder that fails midway must not leave the temporary file or a target behind.
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("x.png");
        let result = write_atomically(&path, dir.path(), |file| {
            file.write_all(b"partial").unwrap();
            Err(OutputError::Encode { path: path.clone(), format: "PNG", message: "boom".into() })
        });
        assert!(result.is_err());
        assert!(dir_entries(dir.path()).is_empty());
    }
}
