//! Environment maps read from the image files a description names ([`EnvironmentFile`]):
//! decoded, resampled when the image is an equal-area square, tinted, scaled and placed.
//!
//! The equal-area square is Clarberg's octahedral mapping of the sphere (Pharr, Jakob and
//! Humphreys, *Physically Based Rendering*, 4th ed., §3.8.3 "Equal-Area Mapping";
//! P. Clarberg, "Fast Equal-Area Mapping of the (Hemi)Sphere using SIMD", Journal of
//! Graphics Tools 13(3), 2008): every pixel subtends the same solid angle. It is resampled
//! to a latitude-longitude image twice as wide as high, whose pixel at (s, t) in the unit
//! square (t = 0 the top row) is the radiance from the direction
//! (sin θ cos φ, sin θ sin φ, cos θ) of the square's frame with φ = 2π s, θ = π t (the
//! layout of pbrt-v3's maps, 3rd ed., §12.6 "Infinite Area Lights").

use super::images::{read_rgb, Encoding, RgbImage};
use crate::error::LoadError;
use crate::light::EnvironmentMap;
use crate::math::Color;
use crate::scene::{EnvironmentFile, Projection};
use glam::Vec3;
use std::f32::consts::PI;

/// Longest side of the latitude-longitude image an equal-area map is resampled to (its
/// width; the height is half of it), within the environment map's pixel limit.
const MAX_RESAMPLED_HEIGHT: u32 = 8192;

/// The map of `file` (its pixels taken as sRGB when 8-bit), and a warning when its
/// projection cannot be followed (an equal-area map that is not square, read as
/// latitude-longitude). Errors name the file.
pub fn read(file: &EnvironmentFile) -> Result<(EnvironmentMap, Option<String>), LoadError> {
    let image = read_rgb(&file.path, Encoding::Srgb)?;
    let (map, note) = from_image(image, file).map_err(|m| LoadError::invalid(&file.path, m))?;
    Ok((map, note.map(|n| format!("{}: {n}", file.path.display()))))
}

/// The map of `file` from its decoded `image`: resampled as its projection says,
/// multiplied by the tint and, with an illuminance, by the factor that makes the upper
/// hemisphere give it, as pbrt-v4 does; placed as the file says.
fn from_image(image: RgbImage, file: &EnvironmentFile) -> Result<(EnvironmentMap, Option<String>), String> {
    let (mut latlong, note) = match file.projection {
        Projection::EqualArea if image.width == image.height => (resample_equal_area(&image), None),
        Projection::EqualArea => {
            let note = format!(
                "a pbrt-v4 image light's map is a square in the equal-area mapping; this one is {}x{}, read as \
                 latitude-longitude",
                image.width, image.height
            );
            (image, Some(note))
        }
        Projection::LatLong => (image, None),
    };
    let k = match file.illuminance {
        Some(e) => match upper_hemisphere_illuminance(&latlong) {
            up if up > 0.0 => e / up,
            _ => return Err("the map is black over its upper hemisphere: no scale gives it an illuminance".into()),
        },
        None => 1.0,
    };
    let tint = file.tint * k;
    if tint != Color::ONE {
        for px in latlong.rgb.chunks_exact_mut(3) {
            px[0] *= tint.x;
            px[1] *= tint.y;
            px[2] *= tint.z;
        }
    }
    let map = EnvironmentMap::placed(latlong.width, latlong.height, &latlong.rgb, file.placement)?;
    Ok((map, note))
}

/// The illuminance a latitude-longitude map gives a surface facing its pole (the top row;
/// +z of pbrt's layout) (the upper hemisphere's ∫ Y cos θ dω), which pbrt-v4's `illuminance` parameter
/// sets. Pixel (i, j) spans dω = (2π / w)(π / h) sin θ.
fn upper_hemisphere_illuminance(image: &RgbImage) -> f32 {
    let (w, h) = (image.width as usize, image.height as usize);
    let d_omega = 2.0 * PI * PI / (w * h) as f32;
    let mut e = 0.0f64;
    for j in 0..h {
        let theta = PI * (j as f32 + 0.5) / h as f32;
        if theta >= 0.5 * PI {
            break;
        }
        let row: f32 = image.rgb[3 * j * w..3 * (j + 1) * w]
            .chunks_exact(3)
            .map(|c| crate::light::luminance(Vec3::new(c[0], c[1], c[2])))
            .sum();
        e += (row * theta.cos() * theta.sin() * d_omega) as f64;
    }
    e as f32
}

/// The point of the unit square that the equal-area octahedral mapping gives the unit
/// direction `d` (PBR 4th ed. §3.8.3, after Clarberg 2008): with r = √(1 − |z|) and
/// φ' = (2/π) atan(min(|x|, |y|) / max(|x|, |y|)) (1 − φ' when |x| < |y|), the upper
/// hemisphere fills the diamond |u| + |v| ≤ 1 with v = φ' r, u = r − v, the lower one the
/// four corners (u, v) ↦ (1 − v, 1 − u), and the signs of x and y pick the quadrant.
fn sphere_to_square(d: Vec3) -> [f32; 2] {
    let (x, y, z) = (d.x.abs(), d.y.abs(), d.z.abs());
    let r = (1.0 - z).max(0.0).sqrt();
    let (a, b) = (x.max(y), x.min(y));
    let mut phi = if a == 0.0 { 0.0 } else { (b / a).atan() * (2.0 / PI) };
    if x < y {
        phi = 1.0 - phi;
    }
    let mut v = phi * r;
    let mut u = r - v;
    if d.z < 0.0 {
        (u, v) = (1.0 - v, 1.0 - u);
    }
    [0.5 * (u.copysign(d.x) + 1.0), 0.5 * (v.copysign(d.y) + 1.0)]
}

/// An equal-area square resampled to a latitude-longitude image in pbrt-v3's layout,
/// 2n × n for an n × n square (capped), each pixel the square's bilinear value in the
/// direction of its centre.
fn resample_equal_area(square: &RgbImage) -> RgbImage {
    let n = square.width as usize;
    let h = square.height.min(MAX_RESAMPLED_HEIGHT) as usize;
    let w = 2 * h;
    let at = |x: usize, y: usize| {
        let i = 3 * (y * n + x);
        Vec3::new(square.rgb[i], square.rgb[i + 1], square.rgb[i + 2])
    };
    let lookup = |[u, v]: [f32; 2]| {
        let (x, y) = (u * n as f32 - 0.5, v * n as f32 - 0.5);
        let (x0, y0) = (x.floor(), y.floor());
        let (fx, fy) = (x - x0, y - y0);
        let c = |i: f32| (i.max(0.0) as usize).min(n - 1);
        let (xa, xb, ya, yb) = (c(x0), c(x0 + 1.0), c(y0), c(y0 + 1.0));
        (at(xa, ya) * (1.0 - fx) + at(xb, ya) * fx) * (1.0 - fy) + (at(xa, yb) * (1.0 - fx) + at(xb, yb) * fx) * fy
    };
    let mut rgb = Vec::with_capacity(3 * w * h);
    for j in 0..h {
        let theta = PI * (j as f32 + 0.5) / h as f32;
        for i in 0..w {
            let phi = 2.0 * PI * (i as f32 + 0.5) / w as f32;
            let d = Vec3::new(theta.sin() * phi.cos(), theta.sin() * phi.sin(), theta.cos());
            rgb.extend(lookup(sphere_to_square(d)).to_array());
        }
    }
    RgbImage { width: w as u32, height: h as u32, rgb }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::light::MapPlacement;
    use glam::Mat3;

    /// The map of a pbrt image light of colour `tint` whose light frame is turned by
    /// `light_to_world`.
    fn environment_map(
        image: &RgbImage,
        projection: Projection,
        tint: Vec3,
        illuminance: Option<f32>,
        light_to_world: Mat3,
    ) -> Result<(EnvironmentMap, Option<String>), String> {
        let turn = light_to_world * crate::io::pbrt::pbrt_to_map().transpose();
        let file = EnvironmentFile {
            path: "map.exr".into(),
            projection,
            tint,
            illuminance,
            placement: MapPlacement::new(0.0, 1.0).rotated(turn),
            fallback: None,
        };
        from_image(image.clone(), &file)
    }

    /// The inverse mapping, from PBR 4th ed. §3.8.3: with u, v in [−1, 1], the signed
    /// distance 1 − |u| − |v| to the diamond's edge gives r and the hemisphere, and
    /// φ = (π/4)((|v| − |u|) / r + 1).
    fn square_to_sphere([s, t]: [f32; 2]) -> Vec3 {
        let (u, v) = (2.0 * s - 1.0, 2.0 * t - 1.0);
        let (up, vp) = (u.abs(), v.abs());
        let signed = 1.0 - (up + vp);
        let r = 1.0 - signed.abs();
        let phi = if r == 0.0 { 1.0 } else { (vp - up) / r + 1.0 } * (PI / 4.0);
        let z = (1.0 - r * r).copysign(signed);
        let k = r * (2.0 - r * r).max(0.0).sqrt();
        Vec3::new(phi.cos().copysign(u) * k, phi.sin().copysign(v) * k, z)
    }

    #[test]
    fn the_equal_area_mapping_puts_the_axes_where_pbrt_does_and_round_trips() {
        let close = |a: [f32; 2], b: [f32; 2]| (a[0] - b[0]).abs() < 1e-6 && (a[1] - b[1]).abs() < 1e-6;
        assert!(close(sphere_to_square(Vec3::Z), [0.5, 0.5]));
        assert!(close(sphere_to_square(Vec3::X), [1.0, 0.5]));
        assert!(close(sphere_to_square(-Vec3::X), [0.0, 0.5]));
        assert!(close(sphere_to_square(Vec3::Y), [0.5, 1.0]));
        assert!(close(sphere_to_square(-Vec3::Y), [0.5, 0.0]));
        // The lower pole is every corner.
        let c = sphere_to_square(-Vec3::Z);
        assert!(c.iter().all(|v| *v == 0.0 || *v == 1.0), "{c:?}");
        for i in 0..200 {
            let h = |k: u32| crate::math::rng::unit_float(crate::math::rng::hash_combine(&[i, k]));
            let d = crate::math::sampling::uniform_sphere(h(0), h(1));
            let back = square_to_sphere(sphere_to_square(d));
            assert!((back - d).length() < 1e-4, "{d} -> {back}");
        }
    }

    #[test]
    fn equal_areas_of_the_square_are_equal_solid_angles() {
        // Uniform directions land uniformly on the square: each of 4 × 4 cells gets 1/16.
        let mut cells = [0u32; 16];
        let n = 64_000;
        for i in 0..n {
            let h = |k: u32| crate::math::rng::unit_float(crate::math::rng::hash_combine(&[i, k, 7]));
            let [u, v] = sphere_to_square(crate::math::sampling::uniform_sphere(h(0), h(1)));
            cells[((v * 4.0) as usize).min(3) * 4 + ((u * 4.0) as usize).min(3)] += 1;
        }
        for c in cells {
            // 4000 expected, standard deviation about 61.
            assert!((c as i32 - 4000).abs() < 300, "{cells:?}");
        }
    }

    fn image(w: u32, h: u32, f: impl Fn(u32, u32) -> [f32; 3]) -> RgbImage {
        let mut rgb = Vec::new();
        for y in 0..h {
            for x in 0..w {
                rgb.extend(f(x, y));
            }
        }
        RgbImage { width: w, height: h, rgb }
    }

    #[test]
    fn maps_shine_from_the_directions_pbrt_gives_their_pixels() {
        // A v3 map bright in the column s = 1/4 near the equator: pbrt's light-space +y.
        let v3 = image(16, 8, |x, y| if x == 4 && (y == 3 || y == 4) { [10.0, 5.0, 1.0] } else { [0.0; 3] });
        let (map, note) = environment_map(&v3, Projection::LatLong, Vec3::ONE, None, Mat3::IDENTITY).unwrap();
        assert!(note.is_none());
        let towards = |map: &EnvironmentMap, d: Vec3| map.radiance(d.normalize()).x;
        // Column 4's centre: φ = 2π × 4.5 / 16, a little past +y.
        let near_y = Vec3::new(-0.2, 1.0, 0.0);
        assert!(towards(&map, near_y) > 1.0, "{}", towards(&map, near_y));
        for other in [Vec3::X, -Vec3::X, -Vec3::Y, Vec3::Z, -Vec3::Z] {
            assert_eq!(towards(&map, other), 0.0, "{other}");
        }
        // Turned by the light's transform: +y of the light is world +z after 90° about x.
        let turn = Mat3::from_rotation_x(0.5 * PI);
        let (turned, _) = environment_map(&v3, Projection::LatLong, Vec3::ONE, None, turn).unwrap();
        assert!(towards(&turned, turn * near_y) > 1.0);
        assert_eq!(towards(&turned, near_y), 0.0);
        // A v4 square bright at (1, 1/2): light-space +x. Scaled by the light's colour.
        let v4 = image(8, 8, |x, y| if x == 7 && (y == 3 || y == 4) { [2.0, 2.0, 2.0] } else { [0.0; 3] });
        let (map, _) =
            environment_map(&v4, Projection::EqualArea, Vec3::new(1.0, 0.5, 0.0), None, Mat3::IDENTITY).unwrap();
        assert_eq!(map.size(), (16, 8));
        let c = map.radiance(Vec3::X);
        assert!(c.x > 0.5 && (c.y - 0.5 * c.x).abs() < 1e-5 && c.z == 0.0, "{c}");
        for other in [-Vec3::X, Vec3::Y, -Vec3::Y, Vec3::Z, -Vec3::Z] {
            assert_eq!(towards(&map, other), 0.0, "{other}");
        }
        // A v4 map that is not square is read as latitude-longitude, said so.
        let (_, note) = environment_map(&v3, Projection::EqualArea, Vec3::ONE, None, Mat3::IDENTITY).unwrap();
        assert!(note.unwrap().contains("16x8"));
    }

    #[test]
    fn resampling_keeps_a_uniform_map_uniform_and_its_illuminance_pi() {
        let grey = image(32, 32, |_, _| [0.25, 0.25, 0.25]);
        let latlong = resample_equal_area(&grey);
        assert_eq!((latlong.width, latlong.height), (64, 32));
        assert!(latlong.rgb.iter().all(|v| (*v - 0.25).abs() < 1e-6));
        // E = π L for a constant sky of luminance L, to the midpoint rule's accuracy.
        let e = upper_hemisphere_illuminance(&latlong);
        assert!((e - 0.25 * PI).abs() < 2e-3, "{e}");
        // pbrt-v4's `illuminance` scales the map to give it: here 2, so L = 2 / π.
        let (map, _) = environment_map(&grey, Projection::EqualArea, Vec3::ONE, Some(2.0), Mat3::IDENTITY).unwrap();
        let l = map.radiance(Vec3::new(0.3, 0.5, 0.8).normalize()).x;
        assert!((l - 2.0 / PI).abs() < 2e-3, "{l}");
        let black = image(4, 4, |_, _| [0.0; 3]);
        assert!(environment_map(&black, Projection::EqualArea, Vec3::ONE, Some(1.0), Mat3::IDENTITY).is_err());
    }
}
