//! The mean radiance of an image-based infinite light's map, for the constant sky that
//! stands in for it: the image's average over the sphere of directions. pbrt-v4 maps
//! (`filename`) are square equal-area octahedral images (Clarberg 2008), whose pixels all
//! subtend the same solid angle, so the plain mean is the sphere's mean; pbrt-v3 maps
//! (`mapname`) are latitude-longitude images, whose rows are weighted by sin θ, the solid
//! angle of a row at polar angle θ.
//!
//! Read: OpenEXR (the first RGB(A) layer, through the `exr` crate) and PFM (`PF` colour
//! and `Pf` grey, either byte order).

use crate::error::LoadError;
use glam::Vec3;
use std::path::Path;

/// Largest map side read, in pixels.
pub const MAX_SKY_SIDE: usize = 16384;

/// How a map's pixels cover the sphere.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Projection {
    /// pbrt-v4's equal-area square: every pixel the same solid angle.
    EqualArea,
    /// pbrt-v3's latitude-longitude: rows from the pole at the top to the one at the bottom.
    LatLong,
}

/// The mean radiance over the sphere of the map at `path` (`.exr` or `.pfm`).
pub fn mean_radiance(path: &Path, projection: Projection) -> Result<Vec3, LoadError> {
    let ext = path.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase);
    let (width, height, pixels) = match ext.as_deref() {
        Some("exr") => read_exr(path)?,
        Some("pfm") => {
            let bytes = std::fs::read(path).map_err(|e| LoadError::io(path, "read the map", e))?;
            parse_pfm(&bytes).map_err(|m| LoadError::format(path, m))?
        }
        _ => return Err(LoadError::format(path, "unsupported environment map format: expected .exr or .pfm")),
    };
    let (mut sum, mut weights) = (glam::DVec3::ZERO, 0.0f64);
    for y in 0..height {
        let w = match projection {
            Projection::EqualArea => 1.0,
            Projection::LatLong => (std::f64::consts::PI * (y as f64 + 0.5) / height as f64).sin(),
        };
        for p in &pixels[y * width..(y + 1) * width] {
            sum += w * p.as_dvec3();
        }
        weights += w * width as f64;
    }
    let mean = (sum / weights).as_vec3();
    match mean.is_finite() && mean.min_element() >= 0.0 {
        true => Ok(mean),
        false => Err(LoadError::invalid(path, "the map has values that are not finite or are negative")),
    }
}

fn read_exr(path: &Path) -> Result<(usize, usize, Vec<Vec3>), LoadError> {
    let meta = exr::meta::MetaData::read_from_file(path, false)
        .map_err(|e| LoadError::format(path, format!("cannot read the OpenEXR map: {e}")))?;
    let size = meta.headers.first().map(|h| h.layer_size).ok_or_else(|| LoadError::format(path, "no image layer"))?;
    check_size(size.width(), size.height()).map_err(|m| LoadError::invalid(path, m))?;
    let image = exr::prelude::read_first_rgba_layer_from_file(
        path,
        |res, _| (vec![Vec3::ZERO; res.width() * res.height()], res.width()),
        |(px, w): &mut (Vec<Vec3>, usize), pos, (r, g, b, _): (f32, f32, f32, f32)| {
            px[pos.y() * *w + pos.x()] = Vec3::new(r, g, b)
        },
    )
    .map_err(|e| LoadError::format(path, format!("cannot decode the OpenEXR map: {e}")))?;
    let (w, h) = (image.layer_data.size.width(), image.layer_data.size.height());
    Ok((w, h, image.layer_data.channel_data.pixels.0))
}

fn check_size(width: usize, height: usize) -> Result<(), String> {
    match width > 0 && height > 0 && width <= MAX_SKY_SIDE && height <= MAX_SKY_SIDE {
        true => Ok(()),
        false => Err(format!("map of {width}x{height} pixels: sides must be 1 to {MAX_SKY_SIDE}")),
    }
}

/// A PFM image: `PF` (RGB) or `Pf` (grey), its size, a scale whose sign is the byte order
/// (negative: little-endian), then the floats.
fn parse_pfm(bytes: &[u8]) -> Result<(usize, usize, Vec<Vec3>), String> {
    let mut fields = Vec::new();
    let mut at = 0;
    // The three header fields are separated by white space; one white-space byte ends them.
    while fields.len() < 4 {
        while at < bytes.len() && bytes[at].is_ascii_whitespace() {
            at += 1;
        }
        let start = at;
        while at < bytes.len() && !bytes[at].is_ascii_whitespace() {
            at += 1;
        }
        if start == at || at - start > 32 {
            return Err("not a PFM file: its header is incomplete".into());
        }
        fields.push(std::str::from_utf8(&bytes[start..at]).map_err(|_| "not a PFM file".to_string())?);
    }
    at += 1;
    let channels = match fields[0] {
        "PF" => 3,
        "Pf" => 1,
        _ => return Err("not a PFM file: it does not start with PF or Pf".into()),
    };
    let dim = |s: &str| s.parse::<usize>().map_err(|_| format!("PFM size `{s}` is not a number"));
    let (width, height) = (dim(fields[1])?, dim(fields[2])?);
    check_size(width, height)?;
    let scale: f32 = fields[3].parse().map_err(|_| format!("PFM scale `{}` is not a number", fields[3]))?;
    let need = width * height * channels * 4;
    let data = bytes.get(at..at + need).ok_or(format!("PFM data too short: {width}x{height} needs {need} bytes"))?;
    let float = |c: &[u8]| {
        let b = [c[0], c[1], c[2], c[3]];
        if scale < 0.0 {
            f32::from_le_bytes(b)
        } else {
            f32::from_be_bytes(b)
        }
    };
    let values: Vec<f32> = data.chunks_exact(4).map(float).collect();
    let pixels = match channels {
        3 => values.chunks_exact(3).map(Vec3::from_slice).collect(),
        _ => values.iter().map(|&v| Vec3::splat(v)).collect(),
    };
    Ok((width, height, pixels))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pfm(width: usize, rows: &[Vec3]) -> Vec<u8> {
        let mut out = format!("PF\n{width} {}\n-1.0\n", rows.len() / width).into_bytes();
        for p in rows {
            for c in p.to_array() {
                out.extend(c.to_le_bytes());
            }
        }
        out
    }

    #[test]
    fn equal_area_maps_average_plainly_and_lat_long_maps_by_solid_angle() {
        let dir = tempfile::tempdir().unwrap();
        // Two rows: a bright top row over a dark bottom one, 4 pixels wide.
        let mut px = vec![Vec3::new(4.0, 2.0, 1.0); 4];
        px.extend(vec![Vec3::ZERO; 4]);
        let path = dir.path().join("sky.pfm");
        std::fs::write(&path, pfm(4, &px)).unwrap();
        assert_eq!(mean_radiance(&path, Projection::EqualArea).unwrap(), Vec3::new(2.0, 1.0, 0.5));
        // Both rows have weight sin(π/4) = sin(3π/4): the mean is the same.
        let m = mean_radiance(&path, Projection::LatLong).unwrap();
        assert!((m - Vec3::new(2.0, 1.0, 0.5)).length() < 1e-5, "{m}");
        // Three rows: the equator row weighs sin(π/2) = 1, the polar rows sin(π/6) = 1/2.
        let rows = [Vec3::ZERO, Vec3::ONE, Vec3::ZERO].iter().flat_map(|&p| [p; 2]).collect::<Vec<_>>();
        std::fs::write(&path, pfm(2, &rows)).unwrap();
        let m = mean_radiance(&path, Projection::LatLong).unwrap();
        assert!((m.x - 0.5).abs() < 1e-5, "{m}");
        assert!((mean_radiance(&path, Projection::EqualArea).unwrap().x - 1.0 / 3.0).abs() < 1e-6);
    }

    #[test]
    fn exr_maps_are_read() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("sky.exr");
        exr::prelude::write_rgb_file(&path, 4, 2, |x, y| {
            if y == 0 && x < 2 {
                (8.0f32, 4.0f32, 0.0f32)
            } else {
                (0.0, 0.0, 0.0)
            }
        })
        .unwrap();
        assert_eq!(mean_radiance(&path, Projection::EqualArea).unwrap(), Vec3::new(2.0, 1.0, 0.0));
    }

    #[test]
    fn broken_maps_are_errors_naming_the_file() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("bad.pfm");
        for bytes in [&b"PF\n4 2\n-1.0\n\x00\x00"[..], b"P6\n1 1\n255\n\x00\x00\x00", b"PF\n999999 2\n-1\n", b"PF"] {
            std::fs::write(&path, bytes).unwrap();
            let e = mean_radiance(&path, Projection::EqualArea).unwrap_err().to_string();
            assert!(e.contains("bad.pfm"), "{e}");
        }
        let e = mean_radiance(&dir.path().join("missing.exr"), Projection::EqualArea).unwrap_err().to_string();
        assert!(e.contains("missing.exr"), "{e}");
        let e = mean_radiance(&dir.path().join("x.hdr"), Projection::LatLong).unwrap_err().to_string();
        assert!(e.contains("x.hdr") && e.contains(".exr or .pfm"), "{e}");
    }
}
