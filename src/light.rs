//! Lights: distant (sharp, or a disk of finite angular size for soft shadows), point,
//! spot, quad and sphere area lights, emitting triangle meshes ([`MeshLight`]), a constant
//! environment and an environment map ([`EnvironmentMap`]); a physical sky and sun
//! ([`PhysicalSky`]) becomes a map and a sun disk.

mod environment;
mod mesh;
mod sky;

pub use environment::{luminance, EnvironmentMap, MapPlacement, MAX_PIXELS as MAX_ENVIRONMENT_PIXELS};

pub use mesh::MeshLight;
pub use sky::{sun_direction, PhysicalSky};

use crate::math::{frame, sampling, Color};
use glam::Vec3;
use std::f32::consts::PI;

/// A light source. Quantities are linear RGB in the scene's units.
#[derive(Clone, Debug, PartialEq)]
pub enum Light {
    /// Parallel light from a direction (the sun).
    Distant {
        /// Unit direction towards the light.
        direction: Vec3,
        /// Irradiance on a surface facing the light.
        irradiance: Color,
    },
    /// A point emitting equally in all directions.
    Point {
        /// Position.
        position: Vec3,
        /// Radiant intensity (irradiance at unit distance).
        intensity: Color,
        /// How the irradiance falls off with distance `d`: as `1 / d^decay`. 2 is physical
        /// (the inverse-square law); Maya's lights also have 0 (no decay, its default), 1
        /// (linear) and 3 (cubic).
        decay: u8,
    },
    /// A point emitting in a cone, with a smooth falloff between two angles.
    Spot {
        /// Position.
        position: Vec3,
        /// Unit direction the spot points to.
        direction: Vec3,
        /// Intensity inside the inner cone.
        intensity: Color,
        /// Cosine of the inner cone half-angle (full intensity inside).
        cos_inner: f32,
        /// Cosine of the outer cone half-angle (dark outside).
        cos_outer: f32,
        /// The falloff with distance, as for [`Light::Point`].
        decay: u8,
    },
    /// A one-sided parallelogram emitting towards `edge_u x edge_v`.
    Quad {
        /// One corner.
        corner: Vec3,
        /// First edge from the corner.
        edge_u: Vec3,
        /// Second edge from the corner.
        edge_v: Vec3,
        /// Emitted radiance.
        radiance: Color,
        /// Weight camera rays see it with (Arnold's `camera`; 0, Arnold's default for area
        /// lights, lets them pass through it); every other ray sees it whole.
        camera_visibility: f32,
    },
    /// A sphere emitting uniformly from its surface.
    Sphere {
        /// Centre.
        center: Vec3,
        /// Radius.
        radius: f32,
        /// Emitted radiance.
        radiance: Color,
        /// Weight camera rays see it with, as for [`Light::Quad`].
        camera_visibility: f32,
    },
    /// Triangles emitting from their front faces (Arnold's mesh light).
    Mesh(MeshLight),
    /// A distant light of finite angular size (the sun as a disk), for soft shadows:
    /// uniform radiance over the cone of directions within its angular radius.
    Sun {
        /// Unit direction towards the disk's centre.
        direction: Vec3,
        /// Radiance of the disk.
        radiance: Color,
        /// Cosine of the disk's angular radius.
        cos_max: f32,
    },
    /// Constant radiance from every direction not blocked by geometry.
    Environment {
        /// Radiance.
        radiance: Color,
        /// Weight camera rays see it with (Arnold's `camera` on a sky dome): 1 shows it as
        /// it lights, 0 leaves a black background; every other ray sees it whole.
        camera_visibility: f32,
    },
    /// Radiance from every direction not blocked by geometry, read from an image
    /// (image-based lighting) and importance-sampled by its luminance.
    EnvironmentMap(EnvironmentMap),
}

/// Light arriving at a point from one sampled direction.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightSample {
    /// Unit direction towards the light.
    pub dir: Vec3,
    /// Distance to the light along `dir` (infinite for distant and environment lights).
    pub dist: f32,
    /// Incident radiance divided by the solid-angle pdf of `dir` (for delta lights, the
    /// irradiance on a surface facing the light): multiplied by a material's response and
    /// the visibility, it is an unbiased estimate of the reflected radiance.
    pub value: Color,
}

impl Light {
    /// True for lights that reach a point from one direction only (distant, point, spot):
    /// their light needs no sampling, so a sample of it varies only with its shadow ray.
    pub fn is_singular(&self) -> bool {
        matches!(self, Light::Distant { .. } | Light::Point { .. } | Light::Spot { .. })
    }

    /// Samples the light as seen from `p`. `normal` is the shading normal of a surface
    /// (the environment then samples the cosine-weighted hemisphere around it) or `None`
    /// for hair (the whole sphere). Returns `None` when no light arrives.
    pub fn sample(&self, p: Vec3, normal: Option<Vec3>, (u, v): (f32, f32)) -> Option<LightSample> {
        let s = match *self {
            Light::Distant { direction, irradiance } => {
                LightSample { dir: direction, dist: f32::INFINITY, value: irradiance }
            }
            Light::Point { position, intensity, decay } => {
                let (dir, dist) = towards(p, position)?;
                LightSample { dir, dist, value: intensity / dist.powi(i32::from(decay)) }
            }
            Light::Spot { position, direction, intensity, cos_inner, cos_outer, decay } => {
                let (dir, dist) = towards(p, position)?;
                let cos = -dir.dot(direction);
                let falloff = smoothstep(cos_outer, cos_inner, cos);
                LightSample { dir, dist, value: intensity * falloff / dist.powi(i32::from(decay)) }
            }
            Light::Quad { corner, edge_u, edge_v, radiance, .. } => {
                let q = corner + edge_u * u + edge_v * v;
                let (dir, dist) = towards(p, q)?;
                let n = edge_u.cross(edge_v);
                let area = n.length();
                let cos_light = -dir.dot(n) / area;
                if cos_light <= 0.0 {
                    return None;
                }
                // Uniform on the area: pdf_solid_angle = dist^2 / (area * cos_light).
                LightSample { dir, dist, value: radiance * (area * cos_light / (dist * dist)) }
            }
            Light::Sphere { center, radius, radiance, .. } => {
                let (axis, dc) = towards(p, center)?;
                if dc <= radius {
                    return None;
                }
                // Uniform over the cone of directions the sphere subtends (PBR 4th ed. 6.2.4).
                let sin_max = radius / dc;
                let cos_max = (1.0 - sin_max * sin_max).max(0.0).sqrt();
                let local = sampling::uniform_cone(u, v, cos_max);
                let (b1, b2) = frame(axis);
                let dir = (b1 * local.x + b2 * local.y + axis * local.z).normalize();
                // Distance to the near side of the sphere along dir.
                let b = dir.dot(center - p);
                let dist = b - (radius * radius - (dc * dc - b * b)).max(0.0).sqrt();
                LightSample { dir, dist, value: radiance * (2.0 * PI * (1.0 - cos_max)) }
            }
            Light::Mesh(ref mesh) => mesh.sample(p, (u, v))?,
            Light::Sun { direction, radiance, cos_max } => {
                let local = sampling::uniform_cone(u, v, cos_max);
                let (b1, b2) = frame(direction);
                let dir = (b1 * local.x + b2 * local.y + direction * local.z).normalize();
                LightSample { dir, dist: f32::INFINITY, value: radiance * (2.0 * PI * (1.0 - cos_max)) }
            }
            Light::Environment { radiance, .. } => match normal {
                Some(n) => {
                    let local = sampling::cosine_hemisphere(u, v);
                    let (b1, b2) = frame(n);
                    let dir = (b1 * local.x + b2 * local.y + n * local.z).normalize();
                    let cos = local.z;
                    if cos <= 0.0 {
                        return None;
                    }
                    LightSample { dir, dist: f32::INFINITY, value: radiance * (PI / cos) }
                }
                None => LightSample {
                    dir: sampling::uniform_sphere(u, v),
                    dist: f32::INFINITY,
                    value: radiance * (4.0 * PI),
                },
            },
            // The whole sphere by the map's distribution, whatever the normal.
            Light::EnvironmentMap(ref map) => {
                let (dir, pdf, radiance) = map.sample((u, v))?;
                LightSample { dir, dist: f32::INFINITY, value: radiance / pdf }
            }
        };
        (s.value.max_element() > 0.0 && s.value.is_finite()).then_some(s)
    }

    /// Radiance a ray from `origin` along `dir` sees on this light before distance `tmax`,
    /// with the distance of that point; only area lights can be seen this way.
    pub fn emitted(&self, origin: Vec3, dir: Vec3, tmax: f32) -> Option<(f32, Color)> {
        match *self {
            Light::Quad { corner, edge_u, edge_v, radiance, .. } => {
                let n = edge_u.cross(edge_v);
                let denom = dir.dot(n);
                if denom >= 0.0 {
                    return None;
                }
                let t = (corner - origin).dot(n) / denom;
                let q = origin + dir * t - corner;
                let (uu, vv) = (edge_u.length_squared(), edge_v.length_squared());
                let (a, b) = (q.dot(edge_u) / uu, q.dot(edge_v) / vv);
                // Edges need not be orthogonal; solve the 2x2 system for exact coordinates.
                let uv = edge_u.dot(edge_v);
                let det = uu * vv - uv * uv;
                let (a, b) = if uv.abs() > 1e-6 * det.abs().sqrt() {
                    let (qa, qb) = (a * uu, b * vv);
                    ((qa * vv - qb * uv) / det, (qb * uu - qa * uv) / det)
                } else {
                    (a, b)
                };
                ((0.0..=1.0).contains(&a) && (0.0..=1.0).contains(&b) && t > 0.0 && t < tmax).then_some((t, radiance))
            }
            Light::Sphere { center, radius, radiance, .. } => {
                let oc = origin - center;
                let b = oc.dot(dir);
                let c = oc.length_squared() - radius * radius;
                let disc = b * b - c;
                if disc < 0.0 {
                    return None;
                }
                let t = -b - disc.sqrt();
                (t > 0.0 && t < tmax).then_some((t, radiance))
            }
            Light::Mesh(ref mesh) => mesh.emitted(origin, dir, tmax),
            // Infinitely far: seen only by a ray that meets nothing.
            Light::Sun { direction, radiance, cos_max } => {
                (tmax == f32::INFINITY && dir.dot(direction) >= cos_max).then_some((f32::INFINITY, radiance))
            }
            _ => None,
        }
    }

    /// Solid-angle density with which [`Light::sample`] picks `dir` from `p`, for
    /// multiple importance sampling against a material's own sampling; 0 for lights no
    /// ray can hit (delta lights) and for the constant environment, which a path tracer
    /// reaches by material sampling alone.
    pub fn pdf(&self, p: Vec3, dir: Vec3) -> f32 {
        match *self {
            Light::EnvironmentMap(ref map) => map.pdf(dir),
            Light::Mesh(ref mesh) => mesh.pdf(p, dir),
            Light::Quad { edge_u, edge_v, .. } => match self.emitted(p, dir, f32::INFINITY) {
                Some((t, _)) => {
                    let n = edge_u.cross(edge_v);
                    let cos_light = -dir.dot(n) / n.length();
                    if cos_light > 0.0 {
                        t * t / (n.length() * cos_light)
                    } else {
                        0.0
                    }
                }
                None => 0.0,
            },
            Light::Sphere { center, radius, .. } => {
                let dc = p.distance(center);
                if dc <= radius || self.emitted(p, dir, f32::INFINITY).is_none() {
                    return 0.0;
                }
                let sin_max = radius / dc;
                let cos_max = (1.0 - sin_max * sin_max).max(0.0).sqrt();
                1.0 / (2.0 * PI * (1.0 - cos_max))
            }
            Light::Sun { direction, cos_max, .. } if dir.dot(direction) >= cos_max => {
                1.0 / (2.0 * PI * (1.0 - cos_max))
            }
            _ => 0.0,
        }
    }

    /// A distant light of `irradiance` on a surface facing it, spread over a disk of
    /// `angular_diameter` radians: [`Light::Sun`] whose radiance gives that irradiance
    /// (E = pi L sin^2(radius)), or a sharp [`Light::Distant`] for a zero diameter.
    pub fn distant(direction: Vec3, irradiance: Color, angular_diameter: f32) -> Light {
        let radius = 0.5 * angular_diameter;
        if radius <= 0.0 {
            return Light::Distant { direction, irradiance };
        }
        let sin = radius.min(0.5 * PI).sin();
        Light::Sun { direction, radiance: irradiance / (PI * sin * sin), cos_max: radius.min(0.5 * PI).cos() }
    }

    /// Radiance of the constant environment seen along any unblocked ray (zero for other
    /// lights, the environment map included: see [`Light::sky`]).
    pub fn background(&self) -> Color {
        match *self {
            Light::Environment { radiance, .. } => radiance,
            _ => Color::ZERO,
        }
    }

    /// Weight camera rays see this light with where they meet it: an environment's or an
    /// area light's own, 1 for every other light.
    pub fn camera_visibility(&self) -> f32 {
        match *self {
            Light::Environment { camera_visibility, .. }
            | Light::Quad { camera_visibility, .. }
            | Light::Sphere { camera_visibility, .. } => camera_visibility,
            Light::EnvironmentMap(ref map) => map.camera_visibility(),
            Light::Mesh(ref mesh) => mesh.camera_visibility(),
            _ => 1.0,
        }
    }

    /// Radiance the tube and fur models' ambient term takes from this light: the constant
    /// environment's, or an environment map's mean over the sphere; zero for other lights.
    pub fn ambient(&self) -> Color {
        match *self {
            Light::Environment { radiance, .. } => radiance,
            Light::EnvironmentMap(ref map) => map.mean_radiance(),
            _ => Color::ZERO,
        }
    }

    /// Radiance an unblocked ray along `dir` sees of this light when it is an environment
    /// (constant or mapped); zero for other lights.
    pub fn sky(&self, dir: Vec3) -> Color {
        match *self {
            Light::Environment { radiance, .. } => radiance,
            Light::EnvironmentMap(ref map) => map.radiance(dir),
            _ => Color::ZERO,
        }
    }
}

fn towards(p: Vec3, q: Vec3) -> Option<(Vec3, f32)> {
    let d = q - p;
    let dist = d.length();
    (dist > 0.0 && dist.is_finite()).then(|| (d / dist, dist))
}

fn smoothstep(lo: f32, hi: f32, x: f32) -> f32 {
    if hi <= lo {
        return if x >= hi { 1.0 } else { 0.0 };
    }
    let t = ((x - lo) / (hi - lo)).clamp(0.0, 1.0);
    t * t * (3.0 - 2.0 * t)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Irradiance on a point facing a light, estimated by averaging `value * cos`.
    fn irradiance(light: &Light, p: Vec3, n: Vec3, samples: u32) -> Color {
        let mut sum = Color::ZERO;
        for i in 0..samples {
            for j in 0..samples {
                let u = ((i as f32 + 0.5) / samples as f32, (j as f32 + 0.5) / samples as f32);
                if let Some(s) = light.sample(p, Some(n), u) {
                    sum += s.value * s.dir.dot(n).max(0.0);
                }
            }
        }
        sum / (samples * samples) as f32
    }

    #[test]
    fn sphere_light_irradiance_matches_closed_form() {
        // A sphere of radiance L seen straight on gives E = pi L sin^2(theta_max).
        let light = Light::Sphere {
            center: Vec3::new(0.0, 0.0, 4.0),
            radius: 1.0,
            radiance: Color::ONE,
            camera_visibility: 1.0,
        };
        let e = irradiance(&light, Vec3::ZERO, Vec3::Z, 64).x;
        let expected = PI * (1.0f32 / 16.0);
        assert!((e - expected).abs() < 0.01 * expected, "{e} vs {expected}");
    }

    /// A square of side 2 at height `h` over the origin as two triangles wound to face
    /// down (−Z), emitting radiance 1.
    fn square_mesh(h: f32) -> MeshLight {
        let c = |x: f32, y: f32| Vec3::new(x, y, h);
        let tris = [[c(-1.0, -1.0), c(-1.0, 1.0), c(1.0, 1.0)], [c(-1.0, -1.0), c(1.0, 1.0), c(1.0, -1.0)]];
        MeshLight::new(tris, Color::ONE, 1.0).unwrap()
    }

    #[test]
    fn mesh_light_irradiance_matches_closed_form_on_its_front_only() {
        // The quad's closed form (Lambert's formula for a rectangle) under the square.
        let h = 1.5f32;
        let light = Light::Mesh(square_mesh(h));
        let e = irradiance(&light, Vec3::ZERO, Vec3::Z, 128).x;
        let s = 1.0 / (1.0 + h * h).sqrt();
        let expected = 4.0 * s * s.atan();
        assert!((e - expected).abs() < 0.01 * expected, "{e} vs {expected}");
        // One-sided: nothing reaches a point above it facing down.
        assert_eq!(irradiance(&light, Vec3::new(0.0, 0.0, 2.0 * h), -Vec3::Z, 16), Color::ZERO);
        // A small square far away: E ≈ L A cos / d^2.
        let far = Light::Mesh(square_mesh(40.0));
        let e = irradiance(&far, Vec3::ZERO, Vec3::Z, 32).x;
        assert!((e - 4.0 / 1600.0).abs() < 0.01 * 4.0 / 1600.0, "{e}");
    }

    #[test]
    fn mesh_light_is_seen_from_its_front_with_the_density_it_samples() {
        let mesh = square_mesh(1.5);
        let light = Light::Mesh(mesh.clone());
        let up = Vec3::new(0.3, 0.2, 1.0).normalize();
        let (t, l) = light.emitted(Vec3::ZERO, up, f32::INFINITY).unwrap();
        assert!((t - 1.5 / up.z).abs() < 1e-4 && l == Color::ONE);
        assert!(light.emitted(Vec3::new(0.0, 0.0, 3.0), -up, f32::INFINITY).is_none(), "back face");
        assert!(light.emitted(Vec3::ZERO, up, 1.0).is_none(), "beyond tmax");
        // pdf = d^2 / (A cos): area 4, cos = up.z.
        let expected = t * t / (4.0 * up.z);
        assert!((light.pdf(Vec3::ZERO, up) - expected).abs() < 1e-4 * expected);
        // Mirrored, the same physical side stays lit: the square now under the origin at
        // z = -1.5 faces it (up).
        let flipped = Light::Mesh(mesh.transformed(&glam::Affine3A::from_scale(Vec3::new(1.0, 1.0, -1.0))));
        assert!(flipped.emitted(Vec3::ZERO, -up, f32::INFINITY).is_some());
        assert!(flipped.emitted(Vec3::new(0.0, 0.0, -3.0), up, f32::INFINITY).is_none());
    }

    #[test]
    fn mesh_light_of_no_area_is_none() {
        let p = Vec3::ONE;
        assert!(MeshLight::new([[p, p, p], [p, Vec3::ZERO, 2.0 * p]], Color::ONE, 1.0).is_none());
        assert!(MeshLight::new([[Vec3::ZERO, Vec3::X, Vec3::splat(f32::NAN)]], Color::ONE, 1.0).is_none());
    }

    #[test]
    fn quad_light_irradiance_matches_closed_form() {
        // Irradiance under the centre of a square of side 2 at height h (Lambert's formula
        // for a rectangle): E = 4 L (a / sqrt(a^2+h^2)) atan(a / sqrt(a^2+h^2)) for a = 1.
        let h = 1.5f32;
        let light = Light::Quad {
            corner: Vec3::new(-1.0, -1.0, h),
            edge_u: Vec3::new(0.0, 2.0, 0.0),
            edge_v: Vec3::new(2.0, 0.0, 0.0),
            radiance: Color::ONE,
            camera_visibility: 1.0,
        };
        let e = irradiance(&light, Vec3::ZERO, Vec3::Z, 128).x;
        let s = 1.0 / (1.0 + h * h).sqrt();
        let expected = 4.0 * s * (s).atan() * 1.0;
        assert!((e - expected).abs() < 0.01 * expected, "{e} vs {expected}");
    }

    #[test]
    fn sun_gives_its_irradiance_and_its_pdf_matches_its_samples() {
        let light = Light::distant(Vec3::Z, Color::splat(2.0), 4f32.to_radians());
        let e = irradiance(&light, Vec3::ZERO, Vec3::Z, 64).x;
        assert!((e - 2.0).abs() < 2e-3, "{e}");
        for (u, v) in [(0.1, 0.2), (0.7, 0.9), (0.5, 0.5)] {
            let s = light.sample(Vec3::ZERO, None, (u, v)).unwrap();
            let Light::Sun { radiance, .. } = light else { panic!("a sun") };
            // value = L / pdf for a uniform light.
            assert!((radiance.x / light.pdf(Vec3::ZERO, s.dir) - s.value.x).abs() < 1e-3 * s.value.x);
            assert_eq!(light.emitted(Vec3::ZERO, s.dir, f32::INFINITY).map(|e| e.1), Some(radiance));
        }
        assert_eq!(light.pdf(Vec3::ZERO, Vec3::X), 0.0);
        assert_eq!(
            Light::distant(Vec3::Z, Color::ONE, 0.0),
            Light::Distant { direction: Vec3::Z, irradiance: Color::ONE }
        );
    }

    #[test]
    fn area_light_pdf_matches_their_samples() {
        let lights = [
            Light::Quad {
                corner: Vec3::new(-1.0, -0.5, 2.0),
                edge_u: Vec3::new(0.0, 1.5, 0.3),
                edge_v: Vec3::new(2.0, 0.0, 0.0),
                radiance: Color::ONE,
                camera_visibility: 1.0,
            },
            Light::Sphere {
                center: Vec3::new(0.5, 0.0, 3.0),
                radius: 0.7,
                radiance: Color::ONE,
                camera_visibility: 1.0,
            },
        ];
        for light in &lights {
            for (u, v) in [(0.1, 0.2), (0.7, 0.9), (0.5, 0.5), (0.95, 0.05)] {
                let s = light.sample(Vec3::ZERO, None, (u, v)).unwrap();
                let pdf = light.pdf(Vec3::ZERO, s.dir);
                assert!((1.0 / pdf - s.value.x).abs() < 2e-3 * s.value.x, "{light:?}: {} vs {}", 1.0 / pdf, s.value.x);
            }
            assert_eq!(light.pdf(Vec3::ZERO, -Vec3::Z), 0.0);
        }
    }

    #[test]
    fn point_and_spot_lights_fall_off_with_their_decay() {
        let p = Vec3::new(0.0, 0.0, 4.0);
        for decay in 0..=3u8 {
            let point = Light::Point { position: p, intensity: Color::splat(8.0), decay };
            let spot = Light::Spot {
                position: p,
                direction: -Vec3::Z,
                intensity: Color::splat(8.0),
                cos_inner: 0.9,
                cos_outer: 0.8,
                decay,
            };
            for light in [point, spot] {
                let s = light.sample(Vec3::ZERO, Some(Vec3::Z), (0.5, 0.5)).unwrap();
                assert_eq!((s.dir, s.dist), (Vec3::Z, 4.0));
                assert!((s.value.x - 8.0 / 4f32.powi(i32::from(decay))).abs() < 1e-5, "{light:?}: {}", s.value.x);
            }
        }
    }

    #[test]
    fn environment_irradiance_is_pi_times_radiance() {
        let light = Light::Environment { radiance: Color::splat(0.5), camera_visibility: 1.0 };
        let e = irradiance(&light, Vec3::ZERO, Vec3::new(0.0, 0.6, 0.8), 32).x;
        assert!((e - 0.5 * PI).abs() < 1e-3 * PI, "{e}");
    }

    #[test]
    fn emitted_finds_area_lights_and_respects_tmax() {
        let quad = Light::Quad {
            corner: Vec3::new(-1.0, -1.0, 2.0),
            edge_u: Vec3::new(0.0, 2.0, 0.0),
            edge_v: Vec3::new(2.0, 0.0, 0.0),
            radiance: Color::ONE,
            camera_visibility: 1.0,
        };
        assert_eq!(quad.emitted(Vec3::ZERO, Vec3::Z, 10.0).map(|h| h.0), Some(2.0));
        assert!(quad.emitted(Vec3::ZERO, Vec3::Z, 1.0).is_none());
        let sphere = Light::Sphere {
            center: Vec3::new(0.0, 0.0, 5.0),
            radius: 1.0,
            radiance: Color::ONE,
            camera_visibility: 1.0,
        };
        assert_eq!(sphere.emitted(Vec3::ZERO, Vec3::Z, 10.0).map(|h| h.0), Some(4.0));
    }
}
