//! The camera: a pinhole (perspective) or an orthographic projection, seeing all of its
//! screen or a window of it (an off-centre or resized part, as a shifted lens or a crop
//! gives).

use crate::math::{Ray, RayCone};
use glam::{Vec2, Vec3};

/// How the camera projects the scene onto its image.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Projection {
    /// Rays fan out from the eye over a vertical field of view in degrees.
    Perspective {
        /// The vertical field of view in degrees.
        vfov_deg: f32,
    },
    /// Rays run parallel to the view direction, from a window centred on the eye and
    /// perpendicular to it.
    Orthographic {
        /// The window's height in scene units (its width follows the image aspect).
        height: f32,
    },
}

/// A camera looking from `eye` towards `target`.
#[derive(Clone, Debug)]
pub struct Camera {
    eye: Vec3,
    /// Direction to the image centre.
    forward: Vec3,
    /// Offset to the right image edge: at unit distance for a pinhole, on the window for an
    /// orthographic camera.
    right: Vec3,
    /// Offset to the top image edge, as `right`.
    up: Vec3,
    /// Parallel rays from a window instead of a pinhole.
    orthographic: bool,
    /// The part of the screen the image sees: its centre and half size, in screen
    /// coordinates where −1..1 spans the whole screen on each axis (`right`, `up`).
    window_centre: Vec2,
    window_half: Vec2,
    width: u32,
    height: u32,
    /// The footprint of every camera ray cone: a pixel's angle for a pinhole, a pixel's size
    /// for an orthographic camera.
    pixel_cone: RayCone,
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
    /// Orthographic window without a finite positive height.
    #[error("orthographic view height {0} is not a finite positive length")]
    BadOrthoHeight(f32),
    /// Zero-sized image.
    #[error("resolution {0}x{1} has no pixels")]
    EmptyImage(u32, u32),
    /// Clipping distances that leave nothing to see.
    #[error("camera clip [{0}, {1}] is not a range from a finite near distance >= 0 to a larger far one")]
    BadClip(f32, f32),
    /// A screen window without a finite positive size on each axis.
    #[error(
        "camera screen window {0} to {1} is not a window from a finite lower-left corner to a finite upper-right one"
    )]
    BadWindow(Vec2, Vec2),
}

impl Camera {
    /// A camera with `projection` for a `width` x `height` image.
    pub fn new(
        eye: Vec3,
        target: Vec3,
        up: Vec3,
        projection: Projection,
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
        if width == 0 || height == 0 {
            return Err(CameraError::EmptyImage(width, height));
        }
        let (half_h, orthographic) = match projection {
            Projection::Perspective { vfov_deg } if vfov_deg > 0.0 && vfov_deg < 180.0 => {
                ((vfov_deg.to_radians() * 0.5).tan(), false)
            }
            Projection::Perspective { vfov_deg } => return Err(CameraError::BadFov(vfov_deg)),
            Projection::Orthographic { height } if height.is_finite() && height > 0.0 => (0.5 * height, true),
            Projection::Orthographic { height } => return Err(CameraError::BadOrthoHeight(height)),
        };
        let half_w = half_h * width as f32 / height as f32;
        let true_up = right.cross(forward);
        let pixel = 2.0 * half_h / height as f32;
        Ok(Camera {
            eye,
            forward,
            right: right * half_w,
            up: true_up * half_h,
            orthographic,
            window_centre: Vec2::ZERO,
            window_half: Vec2::ONE,
            width,
            height,
            pixel_cone: if orthographic {
                // Parallel rays: every footprint is a pixel wide, at any distance.
                RayCone { width: pixel, spread: 0.0 }
            } else {
                // Akenine-Moller et al. 2019, eq. 20.30: gamma_0 = atan(2 tan(fov/2) / height).
                RayCone { width: 0.0, spread: pixel.atan() }
            },
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

    /// This camera's image seeing only the window from `min` to `max` of its screen, in
    /// screen coordinates where −1..1 spans the whole screen on each axis (Arnold's
    /// `screen_window_min`/`max`): a window off the centre shifts the view as a shifted lens
    /// does (the view direction, and so the perspective, is kept), a smaller one magnifies.
    pub fn windowed(self, min: Vec2, max: Vec2) -> Result<Camera, CameraError> {
        let size = max - min;
        if !(min.is_finite() && max.is_finite() && size.is_finite() && size.min_element() > 0.0) {
            return Err(CameraError::BadWindow(min, max));
        }
        let half = 0.5 * size;
        // A pixel now spans `half.y` of what it did.
        let cone = self.pixel_cone;
        let pixel_cone = match self.orthographic {
            true => RayCone { width: cone.width * half.y, spread: 0.0 },
            false => RayCone { width: 0.0, spread: (cone.spread.tan() * half.y).atan() },
        };
        Ok(Camera { window_centre: 0.5 * (min + max), window_half: half, pixel_cone, ..self })
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

    /// The cone of a camera ray at the eye (or the window): its width there (0 for a
    /// pinhole, a pixel's size for an orthographic camera) and its spread (the angle a
    /// pixel subtends, 0 for an orthographic camera).
    pub fn pixel_cone(&self) -> RayCone {
        self.pixel_cone
    }

    /// The ray through image position (`x`, `y`) in pixels from the top-left corner.
    pub fn ray(&self, x: f32, y: f32) -> Ray {
        let sx = self.window_centre.x + self.window_half.x * (2.0 * x / self.width as f32 - 1.0);
        let sy = self.window_centre.y + self.window_half.y * (1.0 - 2.0 * y / self.height as f32);
        let offset = self.right * sx + self.up * sy;
        let (origin, dir) = if self.orthographic {
            (self.eye + offset, self.forward)
        } else {
            (self.eye, (self.forward + offset).normalize())
        };
        // The clipping planes are perpendicular to `forward`: along `dir` they are
        // 1 / cos(dir, forward) times farther.
        let start = self.clip_start(dir);
        let mut ray = Ray::new(origin + dir * start, dir);
        ray.tmax = (self.far - self.near) / dir.dot(self.forward);
        let cone = self.pixel_cone;
        ray.cone = RayCone { width: cone.width + cone.spread * start, spread: cone.spread };
        ray.camera = true;
        ray
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const PERSPECTIVE_60: Projection = Projection::Perspective { vfov_deg: 60.0 };

    #[test]
    fn clipped_rays_run_from_the_near_plane_to_the_far_plane() {
        let eye = Vec3::new(1.0, 2.0, 3.0);
        let camera = Camera::new(eye, Vec3::new(1.0, 2.0, -7.0), Vec3::Y, PERSPECTIVE_60, 40, 30).unwrap();
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
            assert!((ray.cone.width - clipped.pixel_cone().spread * clipped.clip_start(ray.dir)).abs() < 1e-7);
        }
        assert_eq!(clipped.clone().ray(3.0, 27.0).dir, plain.dir);
        for (near, far) in [(-1.0, 2.0), (2.0, 2.0), (f32::INFINITY, f32::INFINITY), (f32::NAN, 1.0), (0.0, f32::NAN)] {
            assert_eq!(
                clipped.clone().clipped(near, far).unwrap_err().to_string(),
                CameraError::BadClip(near, far).to_string()
            );
        }
    }

    #[test]
    fn a_windowed_camera_sees_through_its_image_centre_what_the_whole_screen_shows_at_the_window_centre() {
        let eye = Vec3::new(1.0, 2.0, 3.0);
        let (w, h) = (40, 30);
        for projection in [PERSPECTIVE_60, Projection::Orthographic { height: 2.0 }] {
            let whole = Camera::new(eye, Vec3::new(4.0, 2.0, -7.0), Vec3::Y, projection, w, h).unwrap();
            // The window −0.2..1 across, −1..0.5 up: centred on screen (0.4, −0.25), which the
            // whole screen shows at pixel (0.7 w, 0.625 h) from the top left.
            let (min, max) = (Vec2::new(-0.2, -1.0), Vec2::new(1.0, 0.5));
            let shifted = whole.clone().windowed(min, max).unwrap();
            let (a, b) = (shifted.ray(20.0, 15.0), whole.ray(28.0, 18.75));
            assert!((a.dir - b.dir).length() < 1e-6 && (a.origin - b.origin).length() < 1e-5, "{a:?} {b:?}");
            // Its corners are the window's: the top-left one is screen (−0.2, 0.5).
            let (a, b) = (shifted.ray(0.0, 0.0), whole.ray(16.0, 7.5));
            assert!((a.dir - b.dir).length() < 1e-6 && (a.origin - b.origin).length() < 1e-5, "{a:?} {b:?}");
            // A pixel is 0.75 of a whole-screen pixel high.
            let (cw, cs) = (shifted.pixel_cone(), whole.pixel_cone());
            assert!((cw.width - 0.75 * cs.width).abs() < 1e-6);
            assert!((cw.spread.tan() - 0.75 * cs.spread.tan()).abs() < 1e-6);
            for (min, max) in [(Vec2::ONE, Vec2::ONE), (Vec2::ZERO, Vec2::new(1.0, -1.0)), (Vec2::NAN, Vec2::ONE)] {
                let e = whole.clone().windowed(min, max).unwrap_err();
                assert_eq!(e.to_string(), CameraError::BadWindow(min, max).to_string());
            }
        }
    }

    #[test]
    fn orthographic_rays_are_parallel_from_a_window_of_the_given_size() {
        let eye = Vec3::new(1.0, 2.0, 3.0);
        // A 4 x 2 unit window (8 x 4 pixels), looking down -z with y up: +x on the right.
        let ortho = Projection::Orthographic { height: 2.0 };
        let camera = Camera::new(eye, eye - Vec3::Z, Vec3::Y, ortho, 8, 4).unwrap().clipped(0.5, 4.0).unwrap();
        let corner = camera.ray(0.0, 0.0);
        assert_eq!(corner.dir, Vec3::NEG_Z);
        assert!((corner.origin - Vec3::new(-1.0, 3.0, 2.5)).length() < 1e-6, "{}", corner.origin);
        let centre = camera.ray(4.0, 2.0);
        assert!((centre.origin - Vec3::new(1.0, 2.0, 2.5)).length() < 1e-6);
        assert!((centre.tmax - 3.5).abs() < 1e-6);
        let right = camera.ray(8.0, 2.0);
        assert!((right.origin - Vec3::new(3.0, 2.0, 2.5)).length() < 1e-6);
        // Every footprint is a pixel (half a unit) wide, however far the ray goes.
        for ray in [corner, centre, right] {
            assert_eq!((ray.cone.width, ray.cone.spread), (0.5, 0.0));
        }
        assert_eq!(camera.clip_start(Vec3::NEG_Z), 0.5);
        for height in [0.0, -1.0, f32::NAN, f32::INFINITY] {
            let err = Camera::new(eye, eye - Vec3::Z, Vec3::Y, Projection::Orthographic { height }, 8, 4).unwrap_err();
            assert_eq!(err.to_string(), CameraError::BadOrthoHeight(height).to_string());
        }
    }
}
