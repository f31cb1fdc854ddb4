//! Vectors, rays, ray cones, frames, random numbers, sampling warps, distributions and
//! gradient noise.

pub mod distribution;
pub mod noise;
mod ray;
pub mod rng;
pub mod sampling;

pub use glam::{Vec3, Vec3A};
pub use ray::{offset_origin, Ray, RayCone, RayMask, Skip, PACKET};

/// Linear RGB colour (scene-referred, not clamped).
pub type Color = glam::Vec3;

/// An orthonormal frame around a unit vector `n` (Duff et al. 2017, "Building an
/// orthonormal basis, revisited"), branch-free and continuous except at `n.z = -1`.
pub fn frame(n: Vec3) -> (Vec3, Vec3) {
    let sign = 1.0f32.copysign(n.z);
    let a = -1.0 / (sign + n.z);
    let b = n.x * n.y * a;
    (Vec3::new(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x), Vec3::new(b, sign + n.y * n.y * a, -n.y))
}

/// The orthogonal part of an affine map's linear part: its rotation, times the reflection
/// when it mirrors (glam puts a mirror's sign on the x scale). What turns things at
/// infinity, such as environment maps, which no translation or scale moves.
pub fn orthogonal_part(m: &glam::Affine3A) -> glam::Mat3 {
    let (scale, rotation, _) = m.to_scale_rotation_translation();
    glam::Mat3::from_quat(rotation) * glam::Mat3::from_diagonal(scale.signum())
}

/// Axis-aligned bounding box. Corners are SIMD vectors (`Vec3A`): BVH builds union millions
/// of boxes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Aabb {
    /// Minimum corner.
    pub min: Vec3A,
    /// Maximum corner.
    pub max: Vec3A,
}

impl Aabb {
    /// The empty box: the identity of [`Aabb::union`].
    pub const EMPTY: Aabb = Aabb { min: Vec3A::splat(f32::INFINITY), max: Vec3A::splat(f32::NEG_INFINITY) };

    /// The box between two corners.
    #[inline]
    pub fn new(min: Vec3, max: Vec3) -> Aabb {
        Aabb { min: min.into(), max: max.into() }
    }

    /// The smallest box holding both boxes.
    #[inline]
    pub fn union(self, o: Aabb) -> Aabb {
        Aabb { min: self.min.min(o.min), max: self.max.max(o.max) }
    }

    /// The smallest box holding this box and a point.
    #[inline]
    pub fn grow(self, p: Vec3A) -> Aabb {
        Aabb { min: self.min.min(p), max: self.max.max(p) }
    }

    /// Centre of the box.
    #[inline]
    pub fn center(&self) -> Vec3A {
        0.5 * (self.min + self.max)
    }

    /// Half the surface area (the SAH only needs ratios); 0 for an empty box.
    #[inline]
    pub fn half_area(&self) -> f32 {
        let d = (self.max - self.min).max(Vec3A::ZERO);
        d.x * d.y + d.y * d.z + d.z * d.x
    }

    /// True when the box holds no point.
    #[inline]
    pub fn is_empty(&self) -> bool {
        self.min.x > self.max.x || self.min.y > self.max.y || self.min.z > self.max.z
    }
}
