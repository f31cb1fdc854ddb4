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
//! - a spot light is a point in a cone of full angle `cone_angle`, falling off to dark
//!   over the `penumbra_angle` inside its edge ([`spot`]);
//! - a disk light of radius r is drawn as the square of its area, one-sided along its
//!   local −Z ([`disk`]); a cylinder light (its axis from `bottom` to `top`, emitting from
//!   its side) as a row of spheres of the side's area ([`cylinder`]);
//! - a sky dome's image is a latitude-longitude map laid out as OpenEXR's (the top row +Y,
//!   the left edge longitude +π, longitude 0 along +Z and π/2 along +X), tress's layout
//!   turned 180° about +Y, times the emission ([`latlong_map`]);
//! - a sky dome whose colour is a `physical_sky` shader is that sky ([`physical_sky`]).

use crate::light::{Light, MapPlacement, PhysicalSky};
use crate::scene::{EnvironmentFile, Projection};
use glam::{Affine3A, Vec3};
use std::f32::consts::{PI, TAU};

/// Most spheres a cylinder light is drawn with (a cylinder longer than this many diameters
/// gets spheres larger than its radius, so that their area still matches).
const MAX_CYLINDER_SPHERES: usize = 64;

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

/// A spot light at `position` shining along the unit `direction` with intensity
/// `emission` inside its cone of full angle `cone_angle` degrees, falling off to dark over
/// the `penumbra_angle` degrees inside the cone's edge (Arnold user guide, "Spot Light"),
/// with the inverse-square decay. A `radius` is drawn as a point of the same power: a disk
/// of that radius emits the point's power when `normalize`d, its area times more when not
/// (a radius of 0 is the point itself).
pub fn spot(
    position: Vec3,
    direction: Vec3,
    emission: Vec3,
    [radius, cone_angle, penumbra_angle]: [f32; 3],
    normalize: bool,
) -> Light {
    let emission = if normalize || radius <= 0.0 { emission } else { emission * PI * radius * radius };
    let outer = (0.5 * cone_angle).clamp(0.0, 90.0);
    let inner = (outer - penumbra_angle.max(0.0)).max(0.0);
    Light::Spot {
        position,
        direction,
        intensity: emission,
        cos_inner: inner.to_radians().cos(),
        cos_outer: outer.to_radians().cos(),
        decay: 2,
    }
}

/// A disk light of `radius` in the local XY plane of `transform`, shining along its local
/// −Z and emitting `emission` (over its area when `normalize`), drawn as the square of the
/// same area and emission; seen by camera rays with weight `camera_visibility`.
pub fn disk(transform: &Affine3A, radius: f32, emission: Vec3, normalize: bool, camera_visibility: f32) -> Light {
    let side = radius * PI.sqrt();
    rectangle(transform, [side, side], emission, normalize, camera_visibility)
}

/// A `w × h` rectangle centred in the local XY plane of `transform`, shining along its
/// local −Z with `emission` (over its placed area when `normalize`).
pub fn rectangle(
    transform: &Affine3A,
    [w, h]: [f32; 2],
    emission: Vec3,
    normalize: bool,
    camera_visibility: f32,
) -> Light {
    // Edges ordered so that edge_u × edge_v is the local −Z the light shines along.
    let corner = transform.transform_point3(Vec3::new(-0.5 * w, -0.5 * h, 0.0));
    let edge_u = transform.transform_vector3(Vec3::new(0.0, h, 0.0));
    let edge_v = transform.transform_vector3(Vec3::new(w, 0.0, 0.0));
    let area = edge_u.cross(edge_v).length();
    let radiance = if normalize && area > 0.0 { emission / area } else { emission };
    Light::Quad { corner, edge_u, edge_v, radiance, camera_visibility }
}

/// A cylinder light of `radius` about the segment from `bottom` to `top`, emitting
/// `emission` from its side (over the side's area when `normalize`), drawn as a row of
/// spheres along the axis: `length / 2·radius` such spheres have exactly its side's area
/// (n · 4πr² = 2πr · length); when the count is rounded to a whole number, their radius is
/// set so that their area (and so, at the cylinder's radiance, their power) is still the
/// side's. Seen by camera rays with weight `camera_visibility`.
pub fn cylinder(
    bottom: Vec3,
    top: Vec3,
    radius: f32,
    emission: Vec3,
    normalize: bool,
    camera_visibility: f32,
) -> Vec<Light> {
    let axis = top - bottom;
    let length = axis.length();
    let side = TAU * radius * length;
    let n = if radius > 0.0 {
        (length / (2.0 * radius)).round().clamp(1.0, MAX_CYLINDER_SPHERES as f32) as usize
    } else {
        1
    };
    // Spheres with the side's area in all: n · 4π r_s² = 2π r · length.
    let r = if side > 0.0 { (side / (4.0 * PI * n as f32)).sqrt() } else { radius };
    let radiance = if normalize && side > 0.0 { emission / side } else { emission };
    let step = axis / n as f32;
    (0..n)
        .map(|k| Light::Sphere { center: bottom + step * (k as f32 + 0.5), radius: r, radiance, camera_visibility })
        .collect()
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
