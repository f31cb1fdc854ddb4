use glam::Vec3;

/// A ray cone (Akenine-Moller et al. 2019, "Texture Level of Detail Strategies for
/// Real-Time Ray Tracing", Ray Tracing Gems ch. 20): the footprint of a ray is a cone
/// of `width` at the origin that grows by `spread` (radians, small-angle) per unit distance.
/// Later LOD reads the footprint at the hit distance from it.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct RayCone {
    /// Footprint width at the ray origin.
    pub width: f32,
    /// Spread angle: growth of the width per unit of distance.
    pub spread: f32,
}

impl RayCone {
    /// Footprint width at distance `t` along the ray.
    #[inline]
    pub fn width_at(&self, t: f32) -> f32 {
        (self.width + self.spread * t).abs()
    }

    /// The cone continued from a hit at distance `t` whose surface adds `surface_spread`
    /// (the curvature term beta of the paper; 0 for planar surfaces).
    #[inline]
    pub fn propagate(&self, t: f32, surface_spread: f32) -> RayCone {
        RayCone { width: self.width_at(t), spread: self.spread + surface_spread }
    }

    /// The cone of one of `n` rays scattered from a hit at distance `t`, its direction drawn
    /// with solid-angle density `pdf`: each ray stands for a solid angle `1 / (n pdf)`, a
    /// cone of full angle `sqrt(4 / (pi n pdf))` (path differentials from the sampling
    /// density, Suykens and Willems 2001). A specular (infinite `pdf`) ray keeps this
    /// cone's spread; a scattered cone never narrows.
    #[inline]
    pub fn scattered(&self, t: f32, pdf: f32, n: u32) -> RayCone {
        let spread = (4.0 / (std::f32::consts::PI * n.max(1) as f32 * pdf)).sqrt();
        let spread = if spread.is_finite() { spread.max(self.spread) } else { self.spread };
        RayCone { width: self.width_at(t), spread }
    }
}

/// Primitives a ray ignores: the segments `first..=last` of one object, the strand
/// segment a ray leaves from and its neighbours on the strand. A ray leaving a strand
/// starts on its circle at the hit, but the segment test takes the radius where the ray
/// passes closest to the axis: on a tapered segment, a ray leaving towards the thicker
/// end starts inside that radius and would hit its own segment again.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Skip {
    /// Object index.
    pub object: u32,
    /// First ignored primitive.
    pub first: u32,
    /// Last ignored primitive.
    pub last: u32,
}

/// A ray with its valid interval and its cone.
#[derive(Clone, Copy, Debug)]
pub struct Ray {
    /// Origin.
    pub origin: Vec3,
    /// Direction, unit length.
    pub dir: Vec3,
    /// Hits beyond this distance are ignored.
    pub tmax: f32,
    /// Footprint of the ray.
    pub cone: RayCone,
    /// The primitives it leaves from, which no query along it hits (`None` for camera
    /// rays and rays leaving surfaces, which start off the surface instead).
    pub skip: Option<Skip>,
    /// A camera ray (the camera makes them; every other ray is not): it passes through
    /// objects hidden from the camera, which every other ray sees.
    pub camera: bool,
}

impl Ray {
    /// A ray from `origin` along unit `dir`, unbounded, with a zero cone, not a camera ray.
    pub fn new(origin: Vec3, dir: Vec3) -> Ray {
        Ray { origin, dir, tmax: f32::INFINITY, cone: RayCone::default(), skip: None, camera: false }
    }

    /// Point at distance `t`.
    #[inline]
    pub fn at(&self, t: f32) -> Vec3 {
        self.origin + self.dir * t
    }
}

/// Moves a point off a surface along `n` (pointing to the side the new ray leaves on)
/// by a bound on the floating-point error of the point itself, as pbrt-v4 does
/// (Pharr et al., "Physically Based Rendering", 4th ed., section 6.8.6), rather than by a
/// fixed epsilon: the error of a coordinate computed in f32 grows with its magnitude,
/// so the offset scales with `max|p|`. `extra_error` adds a bound the caller knows
/// (for example the error of a reconstructed hair surface point).
#[inline]
pub fn offset_origin(p: Vec3, n: Vec3, extra_error: f32) -> Vec3 {
    // 2^-20 is about 8 ulps of f32 relative precision: the hit points we offset are
    // reconstructed from primitive data in a handful of operations.
    let err = p.abs().max_element() * (1.0 / 1_048_576.0) + extra_error + f32::MIN_POSITIVE;
    let mut q = p + n * err;
    // Round away from the surface so the offset is not lost to rounding.
    for i in 0..3 {
        if n[i] > 0.0 {
            q[i] = next_up(q[i]);
        } else if n[i] < 0.0 {
            q[i] = next_down(q[i]);
        }
    }
    q
}

#[inline]
fn next_up(x: f32) -> f32 {
    if x.is_infinite() && x > 0.0 {
        return x;
    }
    let x = if x == -0.0 { 0.0 } else { x };
    let b = x.to_bits();
    f32::from_bits(if x >= 0.0 { b + 1 } else { b - 1 })
}

#[inline]
fn next_down(x: f32) -> f32 {
    -next_up(-x)
}

/// Most rays traced together as one packet (a pixel's samples; [`crate::accel::Accel::intersect_packet`]).
pub const PACKET: usize = 16;

/// The rays of a packet as bits: bit i for ray i.
pub type RayMask = u16;
