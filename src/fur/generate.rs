//! Growing fur on a triangle mesh from a [`FurDescription`].
//!
//! **Roots** (thesis section 2.1.5): each triangle gets `floor(e + r)` roots, where `e` is
//! its expected count (Density times its share of the surface's area) and `r` a random
//! fraction drawn from the triangle's own seed; each root is a uniform point by the
//! fold-over trick ([`sampling::triangle_fold`]). Root `k` of triangle `t` draws from a
//! random stream seeded by `(seed, t, k)` alone, so it keeps its place and its hair when
//! Density or any other triangle changes. The share is by true surface area
//! ([`Placement::Area`], the default) or, as Maya does, by UV area ([`Placement::Uv`]).
//! Baldness keeps a root's hair with probability equal to its value (mrLiquid's rule);
//! hairs of length 0 are not grown. Triangles a face mask ([`GrowOptions::grows_on`])
//! leaves out weigh nothing, so Density is spread over the others.
//!
//! **Shape** (specification section 3): a frame from the normal `N` and the surface's U
//! tangent `U0` (`V0 = N x U0`); Polar `p` turns `U0, V0` about `N` by `(p - 0.5) 2 pi` to
//! `A, B`; Inclination `i` leans the root direction from `N` toward `B` by `i pi / 2`;
//! Roll `r` turns the curl axis `-A` about the root direction by `(r - 0.5) pi`. Curl bends
//! the hair at the rate `2 pi (c(s) - 0.5)` per hair length, `c(s)` running from Base to
//! Tip Curl, so 0.5 is straight and 0 or 1 held along the hair make a half circle; values
//! above 0.5 bend toward `B` (with the lean), below 0.5 away from it. Each of the
//! `Segments` segments is `Length / Segments` long, in the direction at its midpoint, so
//! the hair keeps its length whatever the curl. Scraggle turns the direction toward a
//! smooth random direction (Perlin noise along the hair at `s * ScraggleFrequency`, two
//! components across the root frame's `A, B` plane, blended between a per-hair and a
//! shared field by Scraggle Correlation) by up to `Scraggle * pi` per hair length.
//!
//! **Clumping** (section 3.5): clump centres are scattered like roots, about
//! `ClumpingFrequency^2` over the surface; each grows a centre hair by the same rules, and
//! a hair moves toward the centre hair nearest its root by `Clumping * s^p`, with
//! `p = 10^(-ClumpShape / 10)` (`s` the fraction along the hair), so Clumping 1 brings
//! the tips onto the centre hair's tip. **Attraction** to guide curves follows clumping
//! ([`super::guides`]).
//!
//! **Width** runs linearly from Base to Tip Width, times the width profile when one is
//! given ([`GrowOptions::width_profile`]).
//!
//! Everything is a function of (seed, triangle, index), and hairs are written to fixed
//! places, so the result is the same for any number of threads.

use super::description::{ColorAttr, FurDescription, Scalar, MAX_DENSITY};
use super::guides::{Attractors, GuideField};
use super::maps::{Attributes, MapImage, SurfacePoint};
use super::FurError;
use crate::geometry::{StrandInfo, StrandSet, TriangleMesh};
use crate::math::noise::{perlin, Perlin};
use crate::math::rng::{hash_combine, GenRng};
use crate::math::{frame, sampling, Color};
use crate::shading::fur_tube::Fur;
use glam::{Quat, Vec3};
use rand::Rng;
use rayon::prelude::*;
use rstar::primitives::GeomWithData;
use rstar::RTree;
use std::f32::consts::{FRAC_PI_2, PI, TAU};

/// How roots are spread over the surface.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Placement {
    /// Uniform over the true surface area (default).
    #[default]
    Area,
    /// Uniform over the UV area, as Maya Fur does (denser where UVs are stretched).
    Uv,
}

/// Everything besides the description that decides the fur.
#[derive(Clone, Copy, Debug, Default)]
pub struct GrowOptions<'a> {
    /// Root placement.
    pub placement: Placement,
    /// Seed of every random decision.
    pub seed: u32,
    /// Guide curves and how they attract the fur.
    pub guides: Option<(&'a StrandSet, &'a Attractors)>,
    /// The description's image maps, decoded (every file [`super::image_map_paths`] lists).
    pub images: &'a [MapImage],
    /// Which triangles grow fur, one flag per triangle of the mesh; all when `None`.
    /// Density counts hairs over the triangles that grow.
    pub grows_on: Option<&'a [bool]>,
    /// A multiplier of the width along the hair: values at evenly spaced fractions from
    /// root (first) to tip (last), at least two, interpolated linearly; applied on top of
    /// Base and Tip Width.
    pub width_profile: Option<&'a [f32]>,
}

/// Grown fur: strands and the shading parameters that go with them.
#[derive(Clone, Debug, PartialEq)]
pub struct GrownFur {
    /// The hairs, root first, with per-point radius, colour and (when not all opaque)
    /// opacity, and per-strand root UV and clump (`u32::MAX` when a hair belongs to no
    /// clump or guide).
    pub strands: StrandSet,
    /// The fur material's parameters.
    pub shading: Fur,
}

/// Most points one fur may have (about 4 GiB with colours), so a typo cannot exhaust memory.
pub const MAX_POINTS: u64 = 1 << 27;

/// Turn of the direction at Scraggle 1, radians per hair length.
const SCRAGGLE_TURN: f32 = PI;

// Salts that keep the random streams of different purposes apart.
const ROOT_COUNT: u32 = 0x524f_4f54;
const ROOT: u32 = 0x524f_4f55;
const BALDNESS: u32 = 0x4241_4c44;
const SHAPE: u32 = 0x5348_4150;
const CLUMP_COUNT: u32 = 0x434c_554d;
const CLUMP: u32 = 0x434c_554e;
const CLUMP_SHAPE: u32 = 0x434c_5550;
const SCRAGGLE: u32 = 0x5343_5241;

/// The random stream of item `k` of triangle `tri` for one purpose.
fn stream(seed: u32, salt: u32, tri: u32, k: u32) -> GenRng {
    let hi = hash_combine(&[seed, salt, tri, k]) as u64;
    let lo = hash_combine(&[salt, seed, k, tri]) as u64;
    GenRng::new((hi << 32) | lo, 0xda3e_39cb_94b9_5bdb)
}

/// `floor(expected + r)` with `r` uniform in [0, 1) from the triangle's seed.
fn count(expected: f64, seed: u32, salt: u32, tri: u32) -> u32 {
    let r = hash_combine(&[seed, salt, tri]) as f64 / 4_294_967_296.0;
    (expected + r).floor().min(u32::MAX as f64) as u32
}

/// A root: triangle, index within it, barycentrics.
#[derive(Clone, Copy, Debug)]
struct Root {
    tri: u32,
    k: u32,
    b1: f32,
    b2: f32,
}

/// Per-triangle data: its placement weight and U tangent (if its UVs give one).
struct Triangle {
    weight: f64,
    dpdu: Option<Vec3>,
}

/// The surface at a root: position, unit normal, unit U tangent, UV.
struct RootFrame {
    p: Vec3,
    n: Vec3,
    u: Vec3,
    at: SurfacePoint,
}

/// The shape attributes of one hair, evaluated at its root.
struct ShapeParams {
    length: f32,
    inclination: f32,
    roll: f32,
    polar: f32,
    base_curl: f32,
    tip_curl: f32,
    scraggle: f32,
    scraggle_frequency: f32,
    scraggle_correlation: f32,
    offset: f32,
}

/// The read-only context every hair is grown in.
struct Grower<'a> {
    mesh: &'a TriangleMesh,
    attrs: Attributes<'a>,
    triangles: Vec<Triangle>,
    segments: usize,
    global_scale: f32,
    seed: u32,
    scraggle: Perlin,
    /// Fixed noise-domain offsets of the scraggle field all hairs share.
    shared_offset: [f32; 2],
}

impl Grower<'_> {
    /// Where attributes are evaluated for a root.
    fn point(&self, root: &Root) -> SurfacePoint {
        let (tri, b1, b2) = (root.tri, root.b1, root.b2);
        let uv = match &self.mesh.uvs {
            Some(uvs) => {
                let [ua, ub, uc] = self.mesh.indices[tri as usize].map(|i| uvs[i as usize]);
                let w0 = 1.0 - b1 - b2;
                [ua[0] * w0 + ub[0] * b1 + uc[0] * b2, ua[1] * w0 + ub[1] * b1 + uc[1] * b2]
            }
            None => [0.0; 2],
        };
        SurfacePoint { tri, b1, b2, uv }
    }

    /// Position, normal and U tangent at a root.
    fn frame(&self, root: &Root) -> RootFrame {
        let at = self.point(root);
        let (tri, b1, b2) = (root.tri, root.b1, root.b2);
        let [a, b, c] = self.mesh.corners(tri);
        let p = a * (1.0 - b1 - b2) + b * b1 + c * b2;
        let n = self.mesh.shading_normal(tri, b1, b2);
        // U0 = dP/du projected onto the tangent plane (spec section 3.1); without usable
        // UVs, a frame continuous over the sphere of normals except at one pole.
        let u = self.triangles[tri as usize]
            .dpdu
            .and_then(|d| (d - n * d.dot(n)).try_normalize())
            .unwrap_or_else(|| frame(n).0);
        RootFrame { p, n, u, at }
    }

    fn shape_params(&self, at: &SurfacePoint) -> ShapeParams {
        let s = |a: Scalar| self.attrs.scalar(a, at);
        ShapeParams {
            length: s(Scalar::Length) * self.global_scale,
            inclination: s(Scalar::Inclination),
            roll: s(Scalar::Roll),
            polar: s(Scalar::Polar),
            base_curl: s(Scalar::BaseCurl),
            tip_curl: s(Scalar::TipCurl),
            scraggle: s(Scalar::Scraggle),
            scraggle_frequency: s(Scalar::ScraggleFrequency),
            scraggle_correlation: s(Scalar::ScraggleCorrelation),
            offset: s(Scalar::Offset) * self.global_scale,
        }
    }

    /// Scraggle direction in the root's A, B plane at `x` along the noise: two Perlin
    /// values from rows `offset[1]` and `offset[1] + 17.31` of the field.
    fn scraggle_vector(&self, x: f32, offset: [f32; 2]) -> (f32, f32) {
        let at = |row: f32| self.scraggle.get_noise_2d(x + offset[0], offset[1] + row);
        (at(0.0), at(17.31))
    }

    /// Writes the `segments + 1` points of a hair growing from `f` into `out`.
    fn shape(&self, f: &RootFrame, h: &ShapeParams, rng: &mut GenRng, out: &mut [Vec3]) {
        let segments = self.segments;
        let ds = 1.0 / segments as f32;
        let step = h.length * ds;
        // Spec section 3.2: polar about N, inclination toward B, roll about the root
        // direction.
        let polar = Quat::from_axis_angle(f.n, (h.polar - 0.5) * TAU);
        let (a, b) = (polar * f.u, polar * f.n.cross(f.u));
        let (sin_i, cos_i) = (h.inclination * FRAC_PI_2).sin_cos();
        let h0 = f.n * cos_i + b * sin_i;
        let mut axis = Quat::from_axis_angle(h0, (h.roll - 0.5) * PI) * -a;
        let mut t = h0;
        // Curl angle turned from the root to fraction s: the integral of
        // 2 pi (c(s) - 0.5) with c linear from base to tip (spec section 3.3).
        let curl = |s: f32| TAU * ((h.base_curl - 0.5) * s + 0.5 * (h.tip_curl - h.base_curl) * s * s);
        let scraggle = h.scraggle > 0.0;
        let own_offset = if scraggle { [rng.random::<f32>() * 1024.0, rng.random::<f32>() * 1024.0] } else { [0.0; 2] };
        // Scraggle turns by the same angle at every segment.
        let (sin_s, cos_s) = (h.scraggle * SCRAGGLE_TURN * ds).sin_cos();
        let mut x = f.p + f.n * h.offset;
        out[0] = x;
        let mut turned = 0.0;
        for (i, point) in out[1..].iter_mut().enumerate() {
            let s_mid = (i as f32 + 0.5) * ds;
            let angle = curl(s_mid);
            // Rodrigues' rotation about the curl axis, which stays perpendicular to t.
            let (sin_c, cos_c) = (angle - turned).sin_cos();
            t = t * cos_c + axis.cross(t) * sin_c;
            turned = angle;
            if scraggle {
                let xs = s_mid * h.scraggle_frequency;
                let c = h.scraggle_correlation;
                // Only the fields that contribute are evaluated: noise is most of the cost.
                let own = if c < 1.0 { self.scraggle_vector(xs, own_offset) } else { (0.0, 0.0) };
                let shared = if c > 0.0 { self.scraggle_vector(xs, self.shared_offset) } else { (0.0, 0.0) };
                let r = a * (own.0 + (shared.0 - own.0) * c) + b * (own.1 + (shared.1 - own.1) * c);
                if let Some(toward) = (r - t * t.dot(r)).try_normalize() {
                    // Turn t toward `toward`, about n = t x toward, and the curl axis alike.
                    let n = t.cross(toward);
                    t = t * cos_s + toward * sin_s;
                    axis = axis * cos_s + n.cross(axis) * sin_s + n * n.dot(axis) * (1.0 - cos_s);
                }
            }
            t = t.normalize();
            // Keep the curl axis a unit vector perpendicular to t against rounding drift.
            axis = (axis - t * t.dot(axis)).try_normalize().unwrap_or(axis);
            x += t * step;
            *point = x;
        }
    }

    /// The roots of triangle `tri` for `expected` hairs, before any culling.
    fn roots(&self, tri: u32, expected: f64, count_salt: u32, root_salt: u32) -> impl Iterator<Item = Root> + '_ {
        let seed = self.seed;
        (0..count(expected, seed, count_salt, tri)).map(move |k| {
            let mut rng = stream(seed, root_salt, tri, k);
            let (b1, b2) = sampling::triangle_fold(rng.random(), rng.random());
            Root { tri, k, b1, b2 }
        })
    }
}

/// Clump centre hairs, and for each triangle the centres that may be nearest to a point
/// of it.
struct Clumps {
    /// Centre hairs, `segments + 1` points each.
    points: Vec<Vec3>,
    /// Surface points the centre hairs grow from.
    roots: Vec<Vec3>,
    /// Per triangle, the candidate centres.
    candidates: Vec<Vec<u32>>,
}

impl Clumps {
    /// The centre nearest to surface point `p` of triangle `tri` (lowest index on ties).
    fn nearest(&self, tri: u32, p: Vec3) -> Option<u32> {
        let distance = |c: &u32| (self.roots[*c as usize] - p).length_squared();
        self.candidates[tri as usize].iter().copied().min_by(|a, b| distance(a).total_cmp(&distance(b)))
    }
}

fn clumps(g: &Grower, total_weight: f64) -> Clumps {
    let np = g.segments + 1;
    let roots: Vec<Root> = (0..g.triangles.len() as u32)
        .into_par_iter()
        .flat_map_iter(|tri| {
            // The frequency at the triangle's centroid sets its clump count.
            let centroid = g.point(&Root { tri, k: 0, b1: 1.0 / 3.0, b2: 1.0 / 3.0 });
            let freq = g.attrs.scalar(Scalar::ClumpingFrequency, &centroid) as f64;
            let expected = freq * freq * g.triangles[tri as usize].weight / total_weight;
            g.roots(tri, expected, CLUMP_COUNT, CLUMP)
        })
        .collect();
    let mut points = vec![Vec3::ZERO; roots.len() * np];
    let surface: Vec<Vec3> = points
        .par_chunks_mut(np)
        .zip(roots.par_iter())
        .map(|(out, root)| {
            let f = g.frame(root);
            let h = g.shape_params(&f.at);
            g.shape(&f, &h, &mut stream(g.seed, CLUMP_SHAPE, root.tri, root.k), out);
            f.p
        })
        .collect();
    let tree =
        RTree::bulk_load(surface.iter().enumerate().map(|(i, p)| GeomWithData::new(p.to_array(), i as u32)).collect());
    // A point p of a triangle lies within r (the farthest corner) of its centroid c. Its
    // nearest centre is no farther from p than c's nearest centre, at d from c, so it lies
    // within d + 2r of c: those are the candidates.
    let candidates = (0..g.mesh.indices.len() as u32)
        .into_par_iter()
        .map(|tri| {
            let corners = g.mesh.corners(tri);
            let c = (corners[0] + corners[1] + corners[2]) / 3.0;
            let r = corners.iter().map(|v| (*v - c).length()).fold(0.0, f32::max);
            let Some(nearest) = tree.nearest_neighbor(c.to_array()) else { return Vec::new() };
            let d = (Vec3::from(*nearest.geom()) - c).length();
            // A relative margin keeps rounding from dropping the true nearest.
            let reach = (d + 2.0 * r) * (1.0 + 1e-4) + 1e-6;
            let mut ids: Vec<u32> = tree.locate_within_distance(c.to_array(), reach * reach).map(|g| g.data).collect();
            ids.sort_unstable();
            ids
        })
        .collect();
    Clumps { points, roots: surface, candidates }
}

/// Placement weight and U tangent of every triangle; triangles `grows_on` leaves out weigh
/// nothing, so they get no roots.
fn triangles(mesh: &TriangleMesh, placement: Placement, grows_on: Option<&[bool]>) -> Vec<Triangle> {
    (0..mesh.indices.len() as u32)
        .into_par_iter()
        .map(|tri| {
            let [a, b, c] = mesh.corners(tri);
            let (e1, e2) = (b - a, c - a);
            let (weight, dpdu) = match &mesh.uvs {
                Some(uvs) => {
                    let [ia, ib, ic] = mesh.indices[tri as usize].map(|i| uvs[i as usize]);
                    let (du1, dv1, du2, dv2) = (ib[0] - ia[0], ib[1] - ia[1], ic[0] - ia[0], ic[1] - ia[1]);
                    let det = du1 * dv2 - du2 * dv1;
                    let dpdu = (det != 0.0).then(|| (e1 * dv2 - e2 * dv1) / det).filter(|d| d.is_finite());
                    let uv_area = 0.5 * det.abs() as f64;
                    (if placement == Placement::Uv { uv_area } else { mesh.area(tri) as f64 }, dpdu)
                }
                None => (mesh.area(tri) as f64, None),
            };
            let grows = grows_on.is_none_or(|g| g[tri as usize]);
            Triangle { weight: if weight.is_finite() && grows { weight } else { 0.0 }, dpdu }
        })
        .collect()
}

/// The width profile `w` (evenly spaced from root to tip) at fraction `f`, linearly.
fn profile_at(w: &[f32], f: f32) -> f32 {
    let x = f.clamp(0.0, 1.0) * (w.len() - 1) as f32;
    let i = (x as usize).min(w.len() - 2);
    w[i] + (w[i + 1] - w[i]) * (x - i as f32)
}

/// Per-strand values besides the points.
#[derive(Clone, Copy, Default)]
struct StrandExtra {
    uv: [f32; 2],
    clump: u32,
    ambient: [Color; 2],
    specular: Color,
    sharpness: f32,
}

/// Grows the fur `desc` describes on `mesh` (in the space the fur should be in).
///
/// Errors: an invalid description, maps missing from the decoded images or mismatched, UV placement or maps on
/// a mesh without UVs (or with no UV area), unusable guides, or more than [`MAX_POINTS`]
/// points.
pub fn grow(mesh: &TriangleMesh, desc: &FurDescription, options: GrowOptions) -> Result<GrownFur, FurError> {
    desc.validate().map_err(FurError::Invalid)?;
    mesh.validate().map_err(|e| FurError::Invalid(format!("mesh: {e}")))?;
    if options.placement == Placement::Uv && mesh.uvs.is_none() {
        return Err(FurError::Invalid("the mesh has no UVs, which placement = \"uv\" needs".into()));
    }
    let segments = desc.segments as usize;
    let np = segments + 1;
    let bound = (desc.density.min(MAX_DENSITY) as u64 + mesh.indices.len() as u64) * np as u64;
    if bound > MAX_POINTS {
        return Err(FurError::Invalid(format!(
            "density {} with {} segments may need {bound} points, more than the limit of {MAX_POINTS}",
            desc.density, desc.segments
        )));
    }
    let seed = options.seed;
    let attrs = Attributes::resolve(desc, mesh, options.images, seed)?;
    let guides = match options.guides {
        Some((strands, attractors)) => {
            Some(GuideField::new(strands, attractors).map_err(|e| FurError::Invalid(format!("guides: {e}")))?)
        }
        None => None,
    };
    if let Some(g) = options.grows_on {
        if g.len() != mesh.indices.len() {
            return Err(FurError::Invalid(format!(
                "the face mask has {} flags for {} triangles",
                g.len(),
                mesh.indices.len()
            )));
        }
    }
    if let Some(w) = options.width_profile {
        if w.len() < 2 || !w.iter().all(|v| v.is_finite() && *v >= 0.0) {
            return Err(FurError::Invalid(format!(
                "the width profile needs at least two finite values >= 0, it has {w:?}"
            )));
        }
    }
    let triangles = triangles(mesh, options.placement, options.grows_on);
    let total_weight: f64 = triangles.iter().map(|t| t.weight).sum();
    if options.placement == Placement::Uv && total_weight <= 0.0 {
        return Err(FurError::Invalid("the mesh's UVs cover no area, so placement = \"uv\" cannot place roots".into()));
    }
    let scraggle_seed = hash_combine(&[seed, SCRAGGLE]);
    let shared_offset = [(scraggle_seed & 0xffff) as f32 / 64.0, (scraggle_seed >> 16) as f32 / 64.0];
    let g = Grower {
        mesh,
        attrs,
        triangles,
        segments,
        global_scale: desc.global_scale,
        seed,
        scraggle: perlin(scraggle_seed),
        shared_offset,
    };
    let density = desc.density as f64;

    // Roots, culled by baldness and zero length, in (triangle, index) order.
    let roots: Vec<Root> = if total_weight > 0.0 {
        (0..g.triangles.len() as u32)
            .into_par_iter()
            .flat_map_iter(|tri| {
                let expected = density * g.triangles[tri as usize].weight / total_weight;
                g.roots(tri, expected, ROOT_COUNT, ROOT)
            })
            .filter(|root| {
                let at = g.point(root);
                let keep = stream(seed, BALDNESS, root.tri, root.k).random::<f32>();
                keep < g.attrs.scalar(Scalar::Baldness, &at) && g.attrs.scalar(Scalar::Length, &at) > 0.0
            })
            .collect()
    } else {
        Vec::new()
    };

    let clumps = (!g.attrs.scalar_is_zero(Scalar::Clumping)).then(|| clumps(&g, total_weight.max(f64::MIN_POSITIVE)));

    let n = roots.len();
    let oom = |e: crate::memory::OutOfMemory| FurError::Invalid(e.to_string());
    let mut points = crate::memory::try_filled([0.0f32; 4], n * np, "the fur's points").map_err(oom)?;
    let mut colors = crate::memory::try_filled([0.0f32; 3], n * np, "the fur's colours").map_err(oom)?;
    let mut opacity = crate::memory::try_filled(0.0f32, n * np, "the fur's opacities").map_err(oom)?;
    let mut extra = crate::memory::try_filled(StrandExtra::default(), n, "the fur's hairs").map_err(oom)?;
    points
        .par_chunks_mut(np)
        .zip(colors.par_chunks_mut(np))
        .zip(opacity.par_chunks_mut(np))
        .zip(extra.par_iter_mut())
        .zip(roots.par_iter())
        .with_min_len(64)
        .for_each_init(
            || vec![Vec3::ZERO; np],
            |hair, ((((points, colors), opacity), extra), root)| {
                let f = g.frame(root);
                let at = &f.at;
                let h = g.shape_params(at);
                g.shape(&f, &h, &mut stream(seed, SHAPE, root.tri, root.k), hair);
                let mut clump = u32::MAX;
                if let Some(c) = &clumps {
                    if let Some(nearest) = c.nearest(root.tri, f.p) {
                        clump = nearest;
                        let amount = g.attrs.scalar(Scalar::Clumping, at);
                        let p = 10f32.powf(-g.attrs.scalar(Scalar::ClumpShape, at) / 10.0);
                        let centre = &c.points[clump as usize * np..][..np];
                        for (i, (x, cx)) in hair.iter_mut().zip(centre).enumerate().skip(1) {
                            let s = i as f32 / segments as f32;
                            *x = x.lerp(*cx, amount * s.powf(p));
                        }
                    }
                }
                if let Some(field) = &guides {
                    let attraction = g.attrs.scalar(Scalar::Attraction, at);
                    let nearest = field.attract(hair, h.length, attraction);
                    if clump == u32::MAX {
                        clump = nearest.unwrap_or(u32::MAX);
                    }
                }
                let s = |a: Scalar| g.attrs.scalar(a, at);
                let c = |a: ColorAttr| g.attrs.color(a, at);
                let half = 0.5 * g.global_scale;
                let (w0, w1) = (s(Scalar::BaseWidth) * half, s(Scalar::TipWidth) * half);
                let (o0, o1) = (s(Scalar::BaseOpacity), s(Scalar::TipOpacity));
                let (c0, c1) = (c(ColorAttr::BaseColor), c(ColorAttr::TipColor));
                for (i, x) in hair.iter().enumerate() {
                    let f = i as f32 / segments as f32;
                    let profile = options.width_profile.map_or(1.0, |w| profile_at(w, f));
                    points[i] = [x.x, x.y, x.z, (w0 + (w1 - w0) * f) * profile];
                    colors[i] = c0.lerp(c1, f).to_array();
                    opacity[i] = o0 + (o1 - o0) * f;
                }
                *extra = StrandExtra {
                    uv: at.uv,
                    clump,
                    ambient: [c(ColorAttr::BaseAmbientColor), c(ColorAttr::TipAmbientColor)],
                    specular: c(ColorAttr::SpecularColor),
                    sharpness: s(Scalar::SpecularSharpness),
                };
            },
        );

    // Shading values: one shared entry when uniform, else one per strand.
    let everywhere = SurfacePoint { tri: 0, b1: 0.0, b2: 0.0, uv: [0.0; 2] };
    let uniform = |a: ColorAttr| g.attrs.color_is_uniform(a) || n == 0;
    let ambient = match uniform(ColorAttr::BaseAmbientColor) && uniform(ColorAttr::TipAmbientColor) {
        true => vec![[ColorAttr::BaseAmbientColor, ColorAttr::TipAmbientColor].map(|a| g.attrs.color(a, &everywhere))],
        false => extra.iter().map(|e| e.ambient).collect(),
    };
    let specular = match uniform(ColorAttr::SpecularColor) {
        true => vec![g.attrs.color(ColorAttr::SpecularColor, &everywhere)],
        false => extra.iter().map(|e| e.specular).collect(),
    };
    let specular_sharpness = match g.attrs.scalar_is_uniform(Scalar::SpecularSharpness) || n == 0 {
        true => vec![g.attrs.scalar(Scalar::SpecularSharpness, &everywhere)],
        false => extra.iter().map(|e| e.sharpness).collect(),
    };
    let shading = Fur {
        light_model: desc.light_model,
        diffuse: [desc[ColorAttr::BaseColor].value, desc[ColorAttr::TipColor].value],
        ambient,
        specular,
        specular_sharpness,
    };
    let opaque = g.attrs.scalar_is_uniform(Scalar::BaseOpacity)
        && g.attrs.scalar_is_uniform(Scalar::TipOpacity)
        && desc[Scalar::BaseOpacity].value == 1.0
        && desc[Scalar::TipOpacity].value == 1.0;
    let strands = StrandSet {
        points,
        offsets: (0..=n as u32).map(|i| i * np as u32).collect(),
        colors: Some(colors),
        opacity: (!opaque).then_some(opacity),
        strand_info: Some(StrandInfo {
            root_uv: extra.iter().map(|e| e.uv).collect(),
            clump: extra.iter().map(|e| e.clump).collect(),
        }),
        file_order: None,
    };
    Ok(GrownFur { strands, shading })
}
