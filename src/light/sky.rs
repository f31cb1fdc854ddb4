//! A physical daylight sky: clear-sky radiance by the Hosek-Wilkie model (Hosek and
//! Wilkie 2012, "An Analytic Model for Full Spectral Sky-Dome Radiance", its RGB fit, as
//! the `hw-skymodel` crate evaluates it), a sun disk, and a ground below the horizon that
//! reflects the light falling on it. It is the sky Arnold's `physical_sky` shader draws
//! (which is also a Hosek-Wilkie sky), turned into the lights tress renders with: an
//! [`EnvironmentMap`] of the sky and ground, and a [`Light::Sun`].
//!
//! The model gives the sky's radiance and nothing of the sun; the sun's radiance here is
//! the direct normal irradiance of the ESRA clear-sky model (Rigollier, Bauer and Wald
//! 2000, eq. 2 to 4: Kasten-Young air mass, Rayleigh optical thickness, Linke turbidity
//! taken as the sky's turbidity) spread over the disk, reddened by Rayleigh scattering. Both are scaled to Arnold's units by factors fitted to Arnold's renders of
//! its own test scenes ([`SKY_SCALE`], [`SUN_SCALE`], [`GROUND_SCALE`]; docs/interop.md
//! has the figures).

use super::{EnvironmentMap, Light, MapPlacement};
use crate::math::Color;
use glam::Vec3;
use hw_skymodel::rgb::{Channel, SkyParams, SkyState};
use std::f32::consts::{FRAC_PI_2, PI};

/// Factor from the model's RGB radiance to Arnold's at `intensity` 1.
pub const SKY_SCALE: f32 = 0.00925;

/// Factor from the ESRA direct normal irradiance (in units of the solar constant) to the
/// sun's irradiance in Arnold's units at `intensity` 1.
pub const SUN_SCALE: f32 = 4.0;

/// Factor on the light a Lambertian ground of the sky's albedo reflects: Arnold's ground
/// is about twice that bright on average (and brighter looking away from the sun, which
/// this uniform ground leaves out).
pub const GROUND_SCALE: f32 = 2.0;

/// Size of the map the sky is drawn into: 0.7 degrees a pixel, enough for a sky whose
/// brightest feature (the circumsolar glow) spans several degrees; the sun itself is a
/// separate light.
const MAP_SIZE: (u32, u32) = (512, 256);

/// A physical sky in its own frame (+y up, the horizon the xz plane).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PhysicalSky {
    /// Unit direction towards the sun. Below the horizon the sky is lit as by a sun on it.
    pub sun: Vec3,
    /// Atmospheric turbidity: 1 (clear) to 10 (hazy); clamped to that range.
    pub turbidity: f32,
    /// Reflectance of the ground below the horizon (0 to 1 a channel).
    pub ground_albedo: Color,
    /// Factor on the sky's radiance.
    pub sky_tint: Color,
    /// Factor on the sun's radiance.
    pub sun_tint: Color,
    /// Angular diameter of the sun disk in degrees; no sun when 0 or less.
    pub sun_size: f32,
    /// Whether the sky (and the ground) shine; the sun alone when not.
    pub sky: bool,
    /// Factor on everything.
    pub intensity: f32,
}

impl PhysicalSky {
    /// Arnold's default height of the sun, in degrees.
    pub const DEFAULT_ELEVATION: f32 = 45.0;
    /// Arnold's default direction of the sun around the horizon, in degrees from +x
    /// towards +z.
    pub const DEFAULT_AZIMUTH: f32 = 90.0;

    /// Arnold's `physical_sky` defaults: the sun 45 degrees high, turbidity 3, ground
    /// albedo 0.1, a 0.51 degree sun, no tints, intensity 1.
    pub fn arnold_default() -> PhysicalSky {
        PhysicalSky {
            sun: sun_direction(PhysicalSky::DEFAULT_ELEVATION, PhysicalSky::DEFAULT_AZIMUTH),
            turbidity: 3.0,
            ground_albedo: Color::splat(0.1),
            sky_tint: Color::ONE,
            sun_tint: Color::ONE,
            sun_size: 0.51,
            sky: true,
            intensity: 1.0,
        }
    }

    /// The sky as an environment map placed by `placement` (which turns the sky's frame
    /// into the world and scales it), and the sun as a disk placed likewise. An error
    /// says which value cannot make a sky.
    pub fn lights(&self, placement: MapPlacement) -> Result<Vec<Light>, String> {
        let sun = self.sun.try_normalize().ok_or("the sun direction is not a direction")?;
        for (what, c) in
            [("ground albedo", self.ground_albedo), ("sky tint", self.sky_tint), ("sun tint", self.sun_tint)]
        {
            if !(c.is_finite() && c.min_element() >= 0.0) {
                return Err(format!("{what} {c} must be finite and not negative"));
            }
        }
        if !(self.intensity.is_finite() && self.intensity >= 0.0) {
            return Err(format!("intensity {} must be finite and not negative", self.intensity));
        }
        let elevation = sun.y.clamp(0.0, 1.0).asin();
        let turbidity = if self.turbidity.is_finite() { self.turbidity.clamp(1.0, 10.0) } else { 3.0 };
        let state = SkyState::new(&SkyParams {
            elevation: elevation.min(FRAC_PI_2),
            turbidity,
            albedo: self.ground_albedo.clamp(Color::ZERO, Color::ONE).to_array(),
        })
        .map_err(|e| e.to_string())?;
        let scale = SKY_SCALE * self.intensity;
        let sky = |d: Vec3| -> Color {
            // Zenith angle theta and angle to the sun gamma, as the model takes them.
            let theta = d.y.clamp(0.0, 1.0).acos();
            let gamma = d.dot(sun).clamp(-1.0, 1.0).acos();
            let rgb = Color::new(
                state.radiance(theta, gamma, Channel::R),
                state.radiance(theta, gamma, Channel::G),
                state.radiance(theta, gamma, Channel::B),
            );
            rgb.max(Color::ZERO) * self.sky_tint * scale
        };

        // The sun: ESRA's direct normal irradiance over the disk's solid angle, reddened by
        // Rayleigh scattering along its air mass.
        let cos_max = (0.5 * self.sun_size.clamp(0.0, 179.0)).to_radians().cos();
        let solid = 2.0 * PI * (1.0 - cos_max);
        let sun_irradiance =
            sun_colour(elevation) * self.sun_tint * (SUN_SCALE * self.intensity * direct_normal(elevation, turbidity));
        // In the world: turned and scaled as the map is.
        let sun_light = (self.sun_size > 0.0 && solid > 0.0 && sun.y > 0.0).then(|| Light::Sun {
            direction: placement.to_world(sun),
            radiance: sun_irradiance / solid * placement.scale(),
            cos_max,
        });

        // The ground: a diffuse plane lit by the sky above it and the sun, E / pi times its
        // albedo (times GROUND_SCALE). E is summed over the sky's pixels.
        let ground =
            self.ground_albedo * (GROUND_SCALE / PI) * (horizontal_irradiance(&sky) + sun_irradiance * sun.y.max(0.0));
        let map = EnvironmentMap::from_directions(MAP_SIZE.0, MAP_SIZE.1, placement, |d| {
            if d.y >= 0.0 {
                sky(d)
            } else {
                ground
            }
        })?;
        let map = self.sky.then_some(Light::EnvironmentMap(map));
        Ok(sun_light.into_iter().chain(map).collect())
    }
}

/// The unit direction towards a sun `elevation` degrees above the horizon and `azimuth`
/// degrees around it from +x towards +z, in a frame with +y up (Arnold's `physical_sky`
/// `elevation` and `azimuth` in its X, Y, Z frame).
pub fn sun_direction(elevation: f32, azimuth: f32) -> Vec3 {
    let (e, a) = (elevation.to_radians(), azimuth.to_radians());
    Vec3::new(e.cos() * a.cos(), e.sin(), e.cos() * a.sin())
}

/// Irradiance on a horizontal plane from the sky `radiance` over the upper hemisphere: a
/// midpoint sum over the map's rows and columns of L cos(theta) dω.
fn horizontal_irradiance(radiance: &impl Fn(Vec3) -> Color) -> Color {
    let (w, h) = (MAP_SIZE.0 as usize, MAP_SIZE.1 as usize / 2);
    let (d_theta, d_phi) = (FRAC_PI_2 / h as f32, 2.0 * PI / w as f32);
    let mut sum = Color::ZERO;
    for y in 0..h {
        let theta = (y as f32 + 0.5) * d_theta;
        let (sin_t, cos_t) = theta.sin_cos();
        for x in 0..w {
            let phi = (x as f32 + 0.5) * d_phi;
            sum += radiance(Vec3::new(sin_t * phi.cos(), cos_t, sin_t * phi.sin())) * (cos_t * sin_t);
        }
    }
    sum * (d_theta * d_phi)
}

/// Kasten and Young's (1989) relative optical air mass of a sun `elevation` radians high.
fn air_mass(elevation: f32) -> f32 {
    1.0 / (elevation.sin() + 0.50572 * (elevation.to_degrees() + 6.07995).powf(-1.6364))
}

/// The colour (unit luminance) of sunlight through `air_mass(elevation)` atmospheres:
/// Rayleigh optical thickness 0.0088 λ^-4.05 a unit air mass (λ in µm; Leckner 1978) at
/// wavelengths standing for R, G and B (610, 550, 465 nm), relative to green, whose
/// attenuation [`direct_normal`] already holds.
fn sun_colour(elevation: f32) -> Color {
    let m = air_mass(elevation.max(0.0));
    let tau = |micrometres: f32| 0.0088 * micrometres.powf(-4.05);
    let rgb = Color::new(tau(0.61), tau(0.55), tau(0.465)).map(|t| (-(t - tau(0.55)) * m).exp());
    rgb / super::luminance(rgb)
}

/// Direct normal irradiance of a clear sky, as a fraction of the solar constant, for a sun
/// `elevation` radians high through air of Linke `turbidity` (ESRA model, Rigollier et al.
/// 2000, eqs. 2-4; air mass by Kasten and Young 1989, without the altitude correction).
fn direct_normal(elevation: f32, turbidity: f32) -> f32 {
    let degrees = elevation.to_degrees();
    if degrees <= 0.0 {
        return 0.0;
    }
    let m = air_mass(elevation);
    let rayleigh = if m <= 20.0 {
        1.0 / (6.6296 + m * (1.7513 + m * (-0.1202 + m * (0.0065 - 0.00013 * m))))
    } else {
        1.0 / (10.4 + 0.718 * m)
    };
    (-0.8662 * turbidity * m * rayleigh).exp()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn lights_of(sky: PhysicalSky) -> (Option<Light>, EnvironmentMap) {
        let mut lights = sky.lights(MapPlacement::new(0.0, 1.0)).unwrap();
        let Some(Light::EnvironmentMap(map)) = lights.pop() else { panic!("no map") };
        (lights.pop(), map)
    }

    #[test]
    fn sun_direction_follows_elevation_and_azimuth() {
        assert!(sun_direction(90.0, 0.0).abs_diff_eq(Vec3::Y, 1e-6));
        assert!(sun_direction(0.0, 0.0).abs_diff_eq(Vec3::X, 1e-6));
        assert!(sun_direction(0.0, 90.0).abs_diff_eq(Vec3::Z, 1e-6));
        let d = sun_direction(30.0, 45.0);
        assert!((d.length() - 1.0).abs() < 1e-6 && (d.y - 0.5).abs() < 1e-6);
    }

    #[test]
    fn the_sky_is_brightest_near_the_sun_and_bluer_than_the_sun() {
        let sky = PhysicalSky::arnold_default();
        let (sun, map) = lights_of(sky);
        let near = map.radiance((sky.sun + Vec3::Y * 0.05).normalize());
        let away = map.radiance((-sky.sun + Vec3::Y * 2.0).normalize());
        assert!(near.y > 2.0 * away.y, "near the sun {near}, away {away}");
        assert!(away.z > away.x, "the sky away from the sun is blue: {away}");
        let Some(Light::Sun { direction, radiance, .. }) = sun else { panic!("no sun") };
        assert!(direction.abs_diff_eq(sky.sun, 1e-5));
        assert!(radiance.x > radiance.z, "the sun is warmer than the sky: {radiance}");
    }

    #[test]
    fn the_ground_reflects_the_light_falling_on_it() {
        let dark = PhysicalSky { ground_albedo: Color::ZERO, ..PhysicalSky::arnold_default() };
        assert_eq!(lights_of(dark).1.radiance(-Vec3::Y), Color::ZERO);
        let (one, two) = (
            PhysicalSky::arnold_default(),
            PhysicalSky { ground_albedo: Color::splat(0.2), ..PhysicalSky::arnold_default() },
        );
        let (g1, g2) = (lights_of(one).1.radiance(-Vec3::Y), lights_of(two).1.radiance(-Vec3::Y));
        // Twice the albedo reflects about twice the light (the model's sky changes a little
        // with the albedo too).
        assert!((g2.y / g1.y - 2.0).abs() < 0.2, "{g1} {g2}");
    }

    #[test]
    fn a_low_sun_is_dimmer_and_redder_than_a_high_one() {
        assert!(direct_normal(10f32.to_radians(), 3.0) < direct_normal(60f32.to_radians(), 3.0));
        assert!(direct_normal(45f32.to_radians(), 6.0) < direct_normal(45f32.to_radians(), 2.0));
        assert_eq!(direct_normal(-0.1, 3.0), 0.0);
        let sun_of = |elevation: f32| match lights_of(PhysicalSky {
            sun: sun_direction(elevation, 0.0),
            ..PhysicalSky::arnold_default()
        })
        .0
        {
            Some(Light::Sun { radiance, .. }) => radiance,
            _ => panic!("no sun"),
        };
        let (low, high) = (sun_of(5.0), sun_of(60.0));
        assert!(low.z / low.x < high.z / high.x, "low {low}, high {high}");
        let set = PhysicalSky { sun: sun_direction(-5.0, 0.0), ..PhysicalSky::arnold_default() };
        assert!(lights_of(set).0.is_none(), "a sun below the horizon does not shine");
    }

    #[test]
    fn values_that_cannot_make_a_sky_are_errors() {
        let bad = PhysicalSky { intensity: f32::NAN, ..PhysicalSky::arnold_default() };
        assert!(bad.lights(MapPlacement::new(0.0, 1.0)).unwrap_err().contains("intensity"));
        let bad = PhysicalSky { sun: Vec3::ZERO, ..PhysicalSky::arnold_default() };
        assert!(bad.lights(MapPlacement::new(0.0, 1.0)).is_err());
        let bad = PhysicalSky { sky_tint: Color::new(1.0, -1.0, 0.0), ..PhysicalSky::arnold_default() };
        assert!(bad.lights(MapPlacement::new(0.0, 1.0)).unwrap_err().contains("sky tint"));
    }
}
