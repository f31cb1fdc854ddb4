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
//!   turned 180° about +Y, times the emission ([`latlong_map`]);
//! - a sky dome whose colour is a `physical_sky` shader is that sky ([`physical_sky`]).

use crate::light::{Light, MapPlacement, PhysicalSky};
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

/// A node's parameters as a reader finds them: its value, or the default when unset; an
/// error says why the value is not one.
pub trait Params {
    /// A number.
    fn number(&self, name: &str, default: f32) -> Result<f32, String>;
    /// Three numbers (a colour or a vector).
    fn triple(&self, name: &str, default: Vec3) -> Result<Vec3, String>;
    /// A boolean.
    fn boolean(&self, name: &str, default: bool) -> Result<bool, String>;
}

/// The parameters of Arnold's `physical_sky` that [`physical_sky`] reads.
pub const PHYSICAL_SKY_READ: [&str; 15] = [
    "enable_sky",
    "turbidity",
    "ground_albedo",
    "use_degrees",
    "elevation",
    "azimuth",
    "sun_direction",
    "enable_sun",
    "sun_size",
    "intensity",
    "sky_tint",
    "sun_tint",
    "X",
    "Y",
    "Z",
];

/// Arnold's `physical_sky` shader (Arnold user guide, "Physical Sky"): the sun at
/// `elevation` and `azimuth` degrees when `use_degrees` (else along `sun_direction`), in
/// the frame of the `X`, `Y`, `Z` axes; `turbidity`, `ground_albedo`, `sun_size` (degrees),
/// `enable_sun`, `enable_sky`, the tints and `intensity`, with Arnold's defaults.
pub fn physical_sky(p: &impl Params) -> Result<PhysicalSky, String> {
    let d = PhysicalSky::arnold_default();
    let local = match p.boolean("use_degrees", true)? {
        true => crate::light::sun_direction(p.number("elevation", 45.0)?, p.number("azimuth", 90.0)?),
        false => p.triple("sun_direction", Vec3::Y)?,
    };
    let (x, y, z) = (p.triple("X", Vec3::X)?, p.triple("Y", Vec3::Y)?, p.triple("Z", Vec3::Z)?);
    let sun = (x * local.x + y * local.y + z * local.z)
        .try_normalize()
        .ok_or("physical_sky: the sun direction in the X, Y, Z frame is not a direction")?;
    let sun_size = match p.boolean("enable_sun", true)? {
        true => p.number("sun_size", d.sun_size)?,
        false => 0.0,
    };
    Ok(PhysicalSky {
        sun,
        turbidity: p.number("turbidity", d.turbidity)?,
        ground_albedo: p.triple("ground_albedo", d.ground_albedo)?,
        sky_tint: p.triple("sky_tint", d.sky_tint)?,
        sun_tint: p.triple("sun_tint", d.sun_tint)?,
        sun_size,
        sky: p.boolean("enable_sky", true)?,
        intensity: p.number("intensity", d.intensity)?,
    })
}
