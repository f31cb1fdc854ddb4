//! Arnold's light conventions, shared by the readers of files Arnold renders (Arnold-USD's
//! UsdLux lights in [`super::usd::lights`], Arnold scene source files in [`super::ass`]):
//!
//! - every light emits `color × intensity × 2^exposure` ([`emission`]);
//! - a distant light's irradiance on a surface facing it is that emission, whatever its
//!   angular diameter `angle`, which only widens the disk and softens the shadows
//!   ([`distant`]);
//! - a point light of no radius is a point whose irradiance falls off with the square of
//!   the distance (Arnold's only decay); with a radius it is a sphere whose surface emits
//!   the emission, divided by the sphere's area when `normalize` is on ([`sphere`]);
//! - a sky dome's image is a latitude-longitude map laid out as OpenEXR's (the top row +Y,
//!   the left edge longitude +π, longitude 0 along +Z and π/2 along +X), tress's layout
//!   turned 180° about +Y, times the emission ([`latlong_map`]).

use crate::light::{Light, MapPlacement};
use crate::scene::{EnvironmentFile, Projection};
use glam::Vec3;

/// `color × intensity × 2^exposure`, or why it cannot light (not finite, or negative).
pub fn emission(color: Vec3, intensity: f32, exposure: f32) -> Result<Vec3, String> {
    let e = color * intensity * exposure.exp2();
    match e.is_finite() && e.min_element() >= 0.0 {
        true => Ok(e),
        false => Err("light colour × intensity × 2^exposure must be finite and not negative".into()),
    }
}

/// A distant light shining from `direction` (a unit vector towards the light) with
/// irradiance `emission`, as a disk of angular diameter `angle` degrees (a delta light when
/// 0 or less).
pub fn distant(direction: Vec3, emission: Vec3, angle: f32) -> Light {
    if angle > 0.0 && angle.is_finite() {
        let cos_max = (0.5 * angle.min(179.0)).to_radians().cos();
        // The disk's solid angle, 2π (1 − cos θ).
        let solid = std::f32::consts::TAU * (1.0 - cos_max);
        Light::Sun { direction, radiance: emission / solid, cos_max }
    } else {
        Light::Distant { direction, irradiance: emission }
    }
}

/// A sphere light of `radius` at `center` whose surface emits `emission` (over its area
/// when `normalize`), seen by camera rays with weight `camera_visibility`; a point of
/// intensity `emission` decaying quadratically when `radius` is 0.
pub fn sphere(center: Vec3, radius: f32, emission: Vec3, normalize: bool, camera_visibility: f32) -> Light {
    if radius <= 0.0 {
        return Light::Point { position: center, intensity: emission, decay: 2 };
    }
    let area = 4.0 * std::f32::consts::PI * radius * radius;
    let radiance = if normalize { emission / area } else { emission };
    Light::Sphere { center, radius, radiance, camera_visibility }
}

/// The sky dome image at `path` as an environment map in the dome's own frame, times
/// `emission` (which lights the scene instead when the file cannot be read).
pub fn latlong_map(path: std::path::PathBuf, emission: Vec3) -> EnvironmentFile {
    EnvironmentFile {
        path,
        projection: Projection::LatLong,
        tint: emission,
        illuminance: None,
        // OpenEXR's latitude-longitude layout is tress's turned 180° about +Y.
        placement: MapPlacement::new(180.0, 1.0),
        fallback: Some(emission),
    }
}
