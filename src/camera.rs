//! The perspective camera.

use crate::math::{Ray, RayCone};
use glam::Vec3;

/// A pinhole camera looking from `eye` towards `target`.
#[derive(Clone, Debug)]
pub struct Camera {
    eye: Vec3,
    /// Direction to the image centre.
    forward: Vec3,
    /// Offset to the right image edge, at unit distance.
    right: Vec3,
    /// Offset to the top image edge, at unit distance.
    up: Vec3,
    width: u32,
    height: u32,
    /// Angle a pixel subtends: the spread of every camera ray cone.
    pixel_spread: f32,
    /// Clipping distances along `forward`: rays start on the near plane and end on the far.
    near: f32,
    far: f32,
}

/// Why a camera cannot be built.
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum CameraError {
    /// The eye, the target or the up vector has a NaN or an infinite coordinate.
    #[error("the camera position is not finite (eye {0}, target {1}, up {2})")]
    NotFinite(Vec3, Vec3, Vec3),
    /// Eye and target coincide.
    #[error("eye and target are the same point")]
    NoDirection,
    /// Up is parallel to the view direction.
    #[error("the up vector is parallel to the view direction")]
    UpParallel,
    /// Field of view out of range.
    #[error("vertical field of view {0} is not between 0 and 180 degrees")]
    BadFov(f32),
    /// Zero-sized image.
    #[error("resolution {0}x{1} has no pixels")]
    EmptyImage(u32, u32),
    /// Clipping distances that leave nothing to see.
    #[error("camera clip [{0}, {1}] is not a range from a finite near distance >= 0 to a larger far one")]
    BadClip(f32, f32),
}

impl Camera {
    /// A camera with a vertical field of view `vfov_deg` for a `width` x `height` image.
    pub fn new(
        eye: Vec3,
        target: Vec3,
        up: Vec3,
        vfov_deg: f32,
        width: u32,
        height: u32,
    ) -> Result<Camera, CameraError> {
        // Divided by its largest component first, so a camera 1e30 away from its target
        // does not overflow the squared length.
        if !(eye.is_finite() && target.is_finite() && up.is_finite()) {
            return Err(CameraError::NotFinite(eye, target, up));
        }
        let view = target - eye;
        let forward = (view / view.abs().max_element()).try_normalize().ok_or(CameraError::NoDirection)?;
        let right = forward.cross(up).try_normalize().ok_or(CameraError::UpParallel)?;
        if !(vfov_deg > 0.0 && vfov_deg < 180.0) {
            return Err(CameraError::BadFov(vfov_deg));
        }
        if width == 0 || height == 0 {
            return Err(CameraError::EmptyImage(width, height));
        }
        let half_h = (vfov_deg.to_radians() * 0.5).tan();
        let half_w = half_h * width as f32 / height as f32;
        let true_up = right.cross(forward);
        Ok(Camera {
            eye,
            forward,
            right: right * half_w,
            up: true_up * half_h,
            width,
            height,
            // Akenine-Moller et al. 2019, eq. 20.30: gamma_0 = atan(2 tan(fov/2) / height).
            pixel_spread: (2.0 * half_h / height as f32).atan(),
            near: 0.0,
            far: f32::INFINITY,
        })
    }

    /// This camera seeing only what lies between `near` and `far` along its view direction.
    pub fn clipped(self, near: f32, far: f32) -> Result<Camera, CameraError> {
        if !(near >= 0.0 && near.is_finite() && far > near) {
            return Err(CameraError::BadClip(near, far));
        }
        Ok(Camera { near, far, ..self })
    }

    /// How far along a camera ray of direction `dir` it starts: where it crosses the near
    /// clipping plane (0 without clipping). A hit's distance from the eye is this plus the
    /// ray's own hit distance.
    pub fn clip_start(&self, dir: Vec3) -> f32 {
        if self.near == 0.0 {
            0.0
        } else {
            self.near / dir.dot(self.forward)
        }
    }

    /// Image width in pixels.
    pub fn width(&self) -> u32 {
        self.width
    }

    /// Image height in pixels.
    pub fn height(&self) -> u32 {
        self.height
    }

    /// The angle a pixel subtends: the spread of every camera ray's cone.
    pub fn pixel_spread(&self) -> f32 {
        self.pixel_spread
    }

    /// The ray through image position (`x`, `y`) in pixels from the top-left corner.
    pub fn ray(&self, x: f32, y: f32) -> Ray {
        let sx = 2.0 * x / self.width as f32 - 1.0;
        let sy = 1.0 - 2.0 * y / self.height as f32;
        let dir = (self.forward + self.right * sx + self.up * sy).normalize();
        // The clipping planes are perpendicular to `forward`: along `dir` they are
        // 1 / cos(dir, forward) times farther.
        let start = self.clip_start(dir);
        let mut ray = Ray::new(self.eye + dir * start, dir);
        ray.tmax = (self.far - self.near) / dir.dot(self.forward);
        ray.cone = RayCone { width: self.pixel_spread * start, spread: self.pixel_spread };
        ray.camera = true;
        ray
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn clipped_rays_run_from_the_near_plane_to_the_far_plane() {
        let eye = Vec3::new(1.0, 2.0, 3.0);
        let camera = Camera::new(eye, Vec3::new(1.0, 2.0, -7.0), Vec3::Y, 60.0, 40, 30).unwrap();
        let forward = Vec3::NEG_Z;
        let plain = camera.clone().ray(3.0, 27.0);
        assert_eq!((plain.origin, plain.tmax), (eye, f32::INFINITY));
        let clipped = camera.clipped(0.5, 4.0).unwrap();
        for (x, y) in [(20.0, 15.0), (0.0, 0.0), (39.0, 2.0), (3.0, 27.0)] {
            let ray = clipped.ray(x, y);
            // Both ends on the planes perpendicular to the view direction.
            assert!(((ray.origin - eye).dot(forward) - 0.5).abs() < 1e-5);
            assert!(((ray.at(ray.tmax) - eye).dot(forward) - 4.0).abs() < 1e-5);
            assert!((clipped.clip_start(ray.dir) - (ray.origin - eye).length()).abs() < 1e-5);
            // The footprint is the cone's width where the ray now starts.
            assert!((ray.cone.width - clipped.pixel_spread() * clipped.clip_start(ray.dir)).abs() < 1e-7);
        }
        assert_eq!(clipped.clone().ray(3.0, 27.0).dir, plain.dir);
        for (near, far) in [(-1.0, 2.0), (2.0, 2.0), (f32::INFINITY, f32::INFINITY), (f32::NAN, 1.0), (0.0, f32::NAN)] {
            assert_eq!(
                clipped.clone().clipped(near, far).unwrap_err().to_string(),
                CameraError::BadClip(near, far).to_string()
            );
        }
    }
}
