//! Follicles: guide hairs grown on a mesh, as Maya's Create Hair dialog places them
//! (docs/maya-fur-hair.md sections 1.2 and 5.4): on a U by V grid over the
//! surface's UV square, or at random points, with a number of points per hair and a length.
//!
//! Guides leave along the surface normal. Maya then gives them their rest shape by
//! simulation; tress has no dynamics, so `droop` bends them towards a `gravity` direction
//! (world −y by default; tilting it combs the hair) instead, and a guide never passes through the mesh it grows on: a step that would
//! enter it slides along the surface (projected onto the tangent plane at the hit), which
//! lays long hair over a scalp. Every random number comes from (seed, follicle index), so
//! the guides do not depend on the thread count.

use super::Guides;
use crate::accel::{Accel, Shape};
use crate::geometry::{StrandSet, TriangleMesh};
use crate::math::rng::{hash_combine, GenRng};
use crate::math::{frame, sampling, Ray};
use glam::{Quat, Vec3};
use rand::{Rng, SeedableRng};
use rayon::prelude::*;
use std::f32::consts::PI;

/// Where follicles go.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Placement {
    /// A `u` by `v` grid over the UV region, at the cell centres.
    Grid {
        /// Follicles along U.
        u: u32,
        /// Follicles along V.
        v: u32,
    },
    /// `count` follicles uniformly by surface area inside the UV region (thesis section
    /// 2.1.5's placement: a triangle by area, then a point by the fold-over trick).
    Random {
        /// Number of follicles.
        count: u32,
    },
}

/// What the Create Hair dialog asks, plus the rest shape tress gives guides.
#[derive(Clone, Debug, PartialEq)]
pub struct FollicleParams {
    /// Grid or random placement.
    pub placement: Placement,
    /// Grid jitter: each follicle moves by up to ± half a cell times this (0 to 1), as the
    /// dialog's "Randomization".
    pub randomization: f32,
    /// Lower corner of the UV region that grows hair.
    pub uv_min: [f32; 2],
    /// Upper corner of the UV region that grows hair.
    pub uv_max: [f32; 2],
    /// Points of each guide, root included (at least 2).
    pub points_per_hair: u32,
    /// Length of each guide.
    pub length: f32,
    /// Bend towards gravity: each step turns the guide towards `gravity` by `droop × π`
    /// radians per guide length (0 = straight along the normal).
    pub droop: f32,
    /// Unit direction `droop` bends towards (world −y unless combed another way).
    pub gravity: Vec3,
}

impl Default for FollicleParams {
    fn default() -> Self {
        FollicleParams {
            placement: Placement::Grid { u: 10, v: 10 },
            randomization: 0.0,
            uv_min: [0.0, 0.0],
            uv_max: [1.0, 1.0],
            points_per_hair: 10,
            length: 1.0,
            droop: 0.0,
            gravity: Vec3::NEG_Y,
        }
    }
}

/// Most follicles one entry may ask for.
pub const MAX_FOLLICLES: u64 = 10_000_000;
/// Most points per guide.
pub const MAX_POINTS_PER_HAIR: u32 = 10_000;
/// Attempts per random follicle to land inside the UV region before giving up.
const REGION_ATTEMPTS: u32 = 64;

impl FollicleParams {
    /// Checks the parameters; errors name the key.
    pub fn validate(&self) -> Result<(), String> {
        let count = match self.placement {
            Placement::Grid { u, v } => u as u64 * v as u64,
            Placement::Random { count } => count as u64,
        };
        if count == 0 || count > MAX_FOLLICLES {
            return Err(format!("follicle count {count} must be 1 to {MAX_FOLLICLES}"));
        }
        if self.points_per_hair < 2 || self.points_per_hair > MAX_POINTS_PER_HAIR {
            return Err(format!("`points_per_hair` = {} must be 2 to {MAX_POINTS_PER_HAIR}", self.points_per_hair));
        }
        if !(self.length.is_finite() && self.length > 0.0) {
            return Err(format!("`length` = {} must be finite and positive", self.length));
        }
        if !(self.randomization.is_finite() && (0.0..=1.0).contains(&self.randomization)) {
            return Err(format!("`randomization` = {} must be between 0 and 1", self.randomization));
        }
        if !(self.droop.is_finite() && (0.0..=100.0).contains(&self.droop)) {
            return Err(format!("`droop` = {} must be between 0 and 100", self.droop));
        }
        if !(self.gravity.is_finite() && (self.gravity.length() - 1.0).abs() < 1e-3) {
            return Err(format!("`gravity` {} must be a finite non-zero direction", self.gravity));
        }
        let (a, b) = (self.uv_min, self.uv_max);
        if !(a.iter().chain(&b).all(|x| x.is_finite()) && a[0] < b[0] && a[1] < b[1]) {
            return Err(format!("`uv_range` {a:?} to {b:?} must be finite with min < max"));
        }
        Ok(())
    }

    fn full_uv_square(&self) -> bool {
        self.uv_min == [0.0, 0.0] && self.uv_max == [1.0, 1.0]
    }
}

/// A hair root on a mesh.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Follicle {
    /// Root position.
    pub position: Vec3,
    /// Unit surface normal there.
    pub normal: Vec3,
    /// Surface UV there (`[-1, -1]` on a mesh without UVs).
    pub uv: [f32; 2],
}

/// Places follicles on `mesh` (deterministic from `seed`). Grid cells whose centre no
/// triangle covers in UV space get no follicle.
pub fn place_follicles(mesh: &TriangleMesh, params: &FollicleParams, seed: u32) -> Result<Vec<Follicle>, String> {
    params.validate()?;
    if mesh.indices.is_empty() {
        return Err("the mesh has no triangles".into());
    }
    match params.placement {
        Placement::Grid { u, v } => {
            let uvs = mesh.uvs.as_ref().ok_or("grid placement needs a mesh with UVs")?;
            let lookup = UvLookup::new(mesh, uvs);
            let (lo, hi) = (params.uv_min, params.uv_max);
            let cells: Vec<(u32, u32)> = (0..v).flat_map(|j| (0..u).map(move |i| (i, j))).collect();
            Ok(cells
                .par_iter()
                .filter_map(|&(i, j)| {
                    let mut rng = GenRng::seed_from_u64(hash_combine(&[seed, i, j]) as u64);
                    let mut jitter = || params.randomization * (rng.random::<f32>() - 0.5);
                    let x = (i as f32 + 0.5 + jitter()) / u as f32;
                    let y = (j as f32 + 0.5 + jitter()) / v as f32;
                    let uv = [lo[0] + x * (hi[0] - lo[0]), lo[1] + y * (hi[1] - lo[1])];
                    let (tri, b1, b2) = lookup.find(uv)?;
                    Some(follicle_at(mesh, tri, b1, b2))
                })
                .collect())
        }
        Placement::Random { count } => {
            if mesh.uvs.is_none() && !params.full_uv_square() {
                return Err("a `uv_range` needs a mesh with UVs".into());
            }
            let sampler = AreaSampler::new(mesh);
            (0..count)
                .into_par_iter()
                .map(|i| {
                    let mut rng = GenRng::seed_from_u64(hash_combine(&[seed, i]) as u64);
                    for _ in 0..REGION_ATTEMPTS {
                        let tri = sampler.pick(rng.random());
                        let (b1, b2) = sampling::triangle_fold(rng.random(), rng.random());
                        let f = follicle_at(mesh, tri, b1, b2);
                        if mesh.uvs.is_none() || in_region(f.uv, params) {
                            return Ok(f);
                        }
                    }
                    Err(format!(
                        "follicle {}: no point of the mesh inside `uv_range` after {REGION_ATTEMPTS} tries \
                         (is the region on the mesh's UVs?)",
                        i + 1
                    ))
                })
                .collect()
        }
    }
}

/// Places follicles and grows a guide from each (see the module documentation).
pub fn grow_guides(mesh: &TriangleMesh, params: &FollicleParams, seed: u32) -> Result<Guides, String> {
    let follicles = place_follicles(mesh, params, seed)?;
    // Collision queries against the growth mesh reuse the renderer's BVH.
    let accel = Accel::build(vec![(Shape::Mesh(mesh.clone()), 0)]);
    let curves: Vec<Vec<Vec3>> = follicles.par_iter().map(|f| grow(&accel, mesh, f, params)).collect();
    let mut set = StrandSet::new();
    for c in curves {
        set.push_strand(c.into_iter().map(|p| (p, 0.0)));
    }
    let root_uv = mesh.uvs.as_ref().map(|_| follicles.iter().map(|f| f.uv).collect());
    Ok(Guides { curves: set, root_uv })
}

/// Where a follicle placed by UV lands.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct UvPlacement {
    /// The follicle (world space, as the mesh is).
    pub follicle: Follicle,
    /// The triangle it lies on.
    pub triangle: u32,
    /// How far the UV asked for is from that triangle's UVs: 0 when the triangle covers
    /// it, else the follicle is at the nearest point of the mesh's UVs.
    pub uv_distance: f32,
}

/// The follicle at each of `uvs` on `mesh`. Maya's follicles are placed this way, by
/// `parameterU` and `parameterV` (docs/maya-fur-hair.md section 5.4); a UV that no triangle
/// covers (a gap between a sphere's pole triangles, a point off a cut-out layout) takes the
/// nearest point of the UV layout. `None` only where no triangle has UVs of any area.
pub fn follicles_at_uvs(mesh: &TriangleMesh, uvs: &[[f32; 2]]) -> Result<Vec<Option<UvPlacement>>, String> {
    let mesh_uvs = mesh.uvs.as_ref().ok_or("placing follicles by UV needs a mesh with UVs")?;
    if mesh.indices.is_empty() {
        return Err("the mesh has no triangles".into());
    }
    let lookup = UvLookup::new(mesh, mesh_uvs);
    let place = |(triangle, b1, b2, uv_distance)| UvPlacement {
        follicle: follicle_at(mesh, triangle, b1, b2),
        triangle,
        uv_distance,
    };
    Ok(uvs
        .iter()
        .map(|&uv| lookup.find(uv).map(|(t, b1, b2)| (t, b1, b2, 0.0)).or_else(|| lookup.nearest(uv)).map(place))
        .collect())
}

fn in_region(uv: [f32; 2], p: &FollicleParams) -> bool {
    (p.uv_min[0]..=p.uv_max[0]).contains(&uv[0]) && (p.uv_min[1]..=p.uv_max[1]).contains(&uv[1])
}

fn follicle_at(mesh: &TriangleMesh, tri: u32, b1: f32, b2: f32) -> Follicle {
    let [a, b, c] = mesh.corners(tri);
    let position = a * (1.0 - b1 - b2) + b * b1 + c * b2;
    let uv = match &mesh.uvs {
        Some(uvs) => {
            let [ia, ib, ic] = mesh.indices[tri as usize].map(|i| uvs[i as usize]);
            [0, 1].map(|k| ia[k] * (1.0 - b1 - b2) + ib[k] * b1 + ic[k] * b2)
        }
        None => [-1.0, -1.0],
    };
    Follicle { position, normal: mesh.shading_normal(tri, b1, b2), uv }
}

/// One guide: `points_per_hair` points `length / (points − 1)` apart, leaving along the
/// normal, turning towards gravity by the droop, sliding along the mesh where a step would
/// enter it.
fn grow(accel: &Accel, mesh: &TriangleMesh, f: &Follicle, params: &FollicleParams) -> Vec<Vec3> {
    let n = params.points_per_hair as usize;
    let step = params.length / (n - 1) as f32;
    let turn = params.droop * PI * step / params.length;
    let down = params.gravity;
    let mut points = Vec::with_capacity(n);
    let (mut p, mut d) = (f.position, f.normal);
    points.push(p);
    for _ in 1..n {
        if turn > 0.0 {
            let angle = d.dot(down).clamp(-1.0, 1.0).acos();
            let axis = d.cross(down).try_normalize().unwrap_or_else(|| frame(d).0);
            d = (Quat::from_axis_angle(axis, angle.min(turn)) * d).normalize();
        }
        let mut advance = step;
        if let Some((_, n_hit)) = entering(accel, mesh, p, d, step) {
            d = (d - n_hit * n_hit.dot(d)).try_normalize().unwrap_or_else(|| frame(n_hit).0);
            // On a concave part the slid step may still enter: stop short of the surface.
            if let Some((t, _)) = entering(accel, mesh, p, d, step) {
                advance = 0.9 * t;
            }
        }
        p += d * advance;
        points.push(p);
    }
    points
}

/// Distance and outward shading normal where a step from `p` along `d` enters the mesh
/// (hits a face from its front), if it does.
fn entering(accel: &Accel, mesh: &TriangleMesh, p: Vec3, d: Vec3, step: f32) -> Option<(f32, Vec3)> {
    let hit = accel.intersect(&Ray { tmax: step, ..Ray::new(p, d) })?;
    let crate::accel::HitKind::Triangle { b1, b2 } = hit.kind else { return None };
    let n = mesh.shading_normal(hit.prim, b1, b2);
    (n.dot(d) < 0.0).then_some((hit.t, n))
}

/// Picks triangles with probability proportional to their area.
struct AreaSampler {
    cdf: Vec<f64>,
}

impl AreaSampler {
    fn new(mesh: &TriangleMesh) -> AreaSampler {
        let mut total = 0.0;
        let cdf = (0..mesh.indices.len() as u32)
            .map(|i| {
                total += mesh.area(i) as f64;
                total
            })
            .collect();
        AreaSampler { cdf }
    }

    fn pick(&self, u: f64) -> u32 {
        let x = u * self.cdf.last().copied().unwrap_or(0.0);
        self.cdf.partition_point(|&c| c <= x).min(self.cdf.len() - 1) as u32
    }
}

/// Finds the triangle covering a UV point: a uniform grid over the UV bounds listing the
/// triangles whose UV box overlaps each cell.
struct UvLookup<'a> {
    mesh: &'a TriangleMesh,
    uvs: &'a [[f32; 2]],
    min: [f32; 2],
    size: [f32; 2],
    res: usize,
    cells: Vec<Vec<u32>>,
}

impl<'a> UvLookup<'a> {
    fn new(mesh: &'a TriangleMesh, uvs: &'a [[f32; 2]]) -> UvLookup<'a> {
        let res = ((mesh.indices.len() as f64).sqrt().ceil() as usize).clamp(1, 1024);
        let (mut min, mut max) = ([f32::INFINITY; 2], [f32::NEG_INFINITY; 2]);
        for t in &mesh.indices {
            for &i in t {
                for k in 0..2 {
                    min[k] = min[k].min(uvs[i as usize][k]);
                    max[k] = max[k].max(uvs[i as usize][k]);
                }
            }
        }
        let size = [0, 1].map(|k| (max[k] - min[k]).max(f32::MIN_POSITIVE));
        let mut lookup = UvLookup { mesh, uvs, min, size, res, cells: vec![Vec::new(); res * res] };
        for (t, tri) in mesh.indices.iter().enumerate() {
            let c = tri.map(|i| uvs[i as usize]);
            let lo = lookup.cell([c[0][0].min(c[1][0]).min(c[2][0]), c[0][1].min(c[1][1]).min(c[2][1])]);
            let hi = lookup.cell([c[0][0].max(c[1][0]).max(c[2][0]), c[0][1].max(c[1][1]).max(c[2][1])]);
            for y in lo.1..=hi.1 {
                for x in lo.0..=hi.0 {
                    lookup.cells[y * res + x].push(t as u32);
                }
            }
        }
        lookup
    }

    fn cell(&self, uv: [f32; 2]) -> (usize, usize) {
        let f = |k: usize| (((uv[k] - self.min[k]) / self.size[k] * self.res as f32) as usize).min(self.res - 1);
        (f(0), f(1))
    }

    /// The triangle whose UVs come nearest `uv`, with the barycentrics of the nearest
    /// point and its distance: the cells in rings around `uv`'s, until no nearer
    /// triangle can be in the next ring.
    fn nearest(&self, uv: [f32; 2]) -> Option<(u32, f32, f32, f32)> {
        let clamped = [0, 1].map(|k| uv[k].clamp(self.min[k], self.min[k] + self.size[k]));
        // Distance from `uv` to the UV bounds, which every triangle's point is beyond.
        let outside = ((uv[0] - clamped[0]).powi(2) + (uv[1] - clamped[1]).powi(2)).sqrt();
        let (cx, cy) = self.cell(clamped);
        let cell = self.size[0].min(self.size[1]) / self.res as f32;
        let mut best: Option<(u32, f32, f32, f32)> = None;
        let mut seen = vec![false; self.mesh.indices.len()];
        for ring in 0..self.res {
            // Every point of a cell of this ring is at least this far from `uv`.
            let reach = outside.max(ring.saturating_sub(1) as f32 * cell);
            if best.is_some_and(|b| b.3 <= reach) {
                break;
            }
            let (lo_x, hi_x) = (cx.saturating_sub(ring), (cx + ring).min(self.res - 1));
            let (lo_y, hi_y) = (cy.saturating_sub(ring), (cy + ring).min(self.res - 1));
            for y in lo_y..=hi_y {
                for x in lo_x..=hi_x {
                    if x.abs_diff(cx) != ring && y.abs_diff(cy) != ring {
                        continue;
                    }
                    for &t in &self.cells[y * self.res + x] {
                        if std::mem::replace(&mut seen[t as usize], true) {
                            continue;
                        }
                        let c = self.mesh.indices[t as usize].map(|i| self.uvs[i as usize]);
                        if let Some((b1, b2, d)) = closest_in_triangle(uv, c) {
                            if best.is_none_or(|b| d < b.3) {
                                best = Some((t, b1, b2, d));
                            }
                        }
                    }
                }
            }
        }
        best
    }

    /// The first triangle (by index) whose UV triangle holds `uv`, with the barycentrics.
    fn find(&self, uv: [f32; 2]) -> Option<(u32, f32, f32)> {
        if !(0..2).all(|k| uv[k] >= self.min[k] && uv[k] <= self.min[k] + self.size[k]) {
            return None;
        }
        let (x, y) = self.cell(uv);
        self.cells[y * self.res + x].iter().find_map(|&t| {
            let [a, b, c] = self.mesh.indices[t as usize].map(|i| self.uvs[i as usize]);
            let (e1, e2, p) = ([b[0] - a[0], b[1] - a[1]], [c[0] - a[0], c[1] - a[1]], [uv[0] - a[0], uv[1] - a[1]]);
            let det = e1[0] * e2[1] - e1[1] * e2[0];
            if det == 0.0 {
                return None;
            }
            let b1 = (p[0] * e2[1] - p[1] * e2[0]) / det;
            let b2 = (e1[0] * p[1] - e1[1] * p[0]) / det;
            const EPS: f32 = 1e-6;
            (b1 >= -EPS && b2 >= -EPS && b1 + b2 <= 1.0 + EPS).then_some((t, b1.max(0.0), b2.max(0.0)))
        })
    }
}

/// The point of the 2-D triangle `c` nearest `p`: its barycentrics (of `c[1]`, `c[2]`) and
/// distance; `None` for a triangle of no area.
fn closest_in_triangle(p: [f32; 2], c: [[f32; 2]; 3]) -> Option<(f32, f32, f32)> {
    let v = |a: [f32; 2], b: [f32; 2]| glam::Vec2::new(b[0] - a[0], b[1] - a[1]);
    let (e1, e2, q) = (v(c[0], c[1]), v(c[0], c[2]), v(c[0], p));
    let det = e1.perp_dot(e2);
    if det == 0.0 || !det.is_finite() {
        return None;
    }
    let (b1, b2) = (q.perp_dot(e2) / det, e1.perp_dot(q) / det);
    if b1 >= 0.0 && b2 >= 0.0 && b1 + b2 <= 1.0 {
        return Some((b1, b2, 0.0));
    }
    // Outside: the nearest point is on an edge; (b1, b2) of each edge's end points.
    let edges = [((0.0, 0.0), (1.0, 0.0)), ((1.0, 0.0), (0.0, 1.0)), ((0.0, 1.0), (0.0, 0.0))];
    edges
        .iter()
        .map(|&((a1, a2), (z1, z2))| {
            let (a, z) = (e1 * a1 + e2 * a2, e1 * z1 + e2 * z2);
            let t = ((q - a).dot(z - a) / (z - a).length_squared()).clamp(0.0, 1.0);
            let (b1, b2) = (a1 + (z1 - a1) * t, a2 + (z2 - a2) * t);
            (b1, b2, (a + (z - a) * t - q).length())
        })
        .min_by(|x, y| x.2.total_cmp(&y.2))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn grid(u: u32, v: u32) -> FollicleParams {
        FollicleParams { placement: Placement::Grid { u, v }, ..Default::default() }
    }

    #[test]
    fn grid_places_u_times_v_follicles_at_cell_centres() {
        let plane = TriangleMesh::plane(2.0);
        let f = place_follicles(&plane, &grid(4, 5), 0).unwrap();
        assert_eq!(f.len(), 20);
        // Plane UV (0, 0) is corner (-1, -1) and U runs along x, V along z.
        assert!((f[0].position - Vec3::new(-0.75, 0.0, -0.8)).length() < 1e-5, "{}", f[0].position);
        assert_eq!(f[0].uv, [0.125, 0.1]);
        assert!(f.iter().all(|f| (f.normal - Vec3::Y).length() < 1e-6));
        let torus = TriangleMesh::torus(1.0, 0.35, 96, 48);
        assert_eq!(place_follicles(&torus, &grid(30, 12), 0).unwrap().len(), 360);
        // A UV region: all follicles inside it.
        let params = FollicleParams { uv_min: [0.0, 0.5], uv_max: [0.5, 1.0], ..grid(3, 3) };
        let f = place_follicles(&plane, &params, 0).unwrap();
        assert_eq!(f.len(), 9);
        assert!(f.iter().all(|f| f.position.x < 0.0 && f.position.z > 0.0));
    }

    #[test]
    fn random_placement_counts_and_is_uniform_by_area() {
        // A plane of two unequal halves in one mesh: a 1x1 square and a 3x1 one.
        let mut mesh = TriangleMesh::plane(1.0);
        let mut big = TriangleMesh::plane(1.0);
        big.transform(&glam::Affine3A::from_scale_rotation_translation(
            Vec3::new(3.0, 1.0, 1.0),
            Quat::IDENTITY,
            Vec3::new(3.0, 0.0, 0.0),
        ));
        let base = mesh.positions.len() as u32;
        mesh.positions.extend(big.positions);
        mesh.uvs.as_mut().unwrap().extend(big.uvs.unwrap());
        mesh.normals.as_mut().unwrap().extend(big.normals.unwrap());
        mesh.indices.extend(big.indices.iter().map(|t| t.map(|i| i + base)));
        let params = FollicleParams { placement: Placement::Random { count: 4000 }, ..Default::default() };
        let f = place_follicles(&mesh, &params, 7).unwrap();
        assert_eq!(f.len(), 4000);
        // Expected 3/4 on the big half; binomial sigma = sqrt(4000 * 3/16) ≈ 27.
        let big_count = f.iter().filter(|f| f.position.x > 1.0).count() as f64;
        assert!((big_count - 3000.0).abs() < 5.0 * 27.4, "{big_count}");
    }

    #[test]
    fn placement_is_deterministic_and_depends_on_the_seed() {
        let sphere = TriangleMesh::sphere(1.0, 24);
        for placement in [Placement::Random { count: 500 }, Placement::Grid { u: 20, v: 10 }] {
            let params = FollicleParams { placement, randomization: 0.8, ..Default::default() };
            let a = place_follicles(&sphere, &params, 3).unwrap();
            let b = rayon::ThreadPoolBuilder::new()
                .num_threads(1)
                .build()
                .unwrap()
                .install(|| place_follicles(&sphere, &params, 3).unwrap());
            assert_eq!(a, b);
            assert_ne!(a, place_follicles(&sphere, &params, 4).unwrap());
        }
    }

    #[test]
    fn guides_have_the_asked_points_and_length_and_stay_outside_the_mesh() {
        let sphere = TriangleMesh::sphere(1.0, 32);
        for droop in [0.0, 2.0] {
            let params = FollicleParams { points_per_hair: 12, length: 1.5, droop, ..grid(12, 6) };
            let g = grow_guides(&sphere, &params, 1).unwrap();
            assert_eq!(g.curves.strand_count(), 72);
            assert_eq!(g.curves.points.len(), 72 * 12);
            for s in 0..g.curves.strand_count() {
                let (a, b) = (g.curves.offsets[s], g.curves.offsets[s + 1]);
                let len: f32 = (a..b - 1).map(|i| (g.curves.position(i + 1) - g.curves.position(i)).length()).sum();
                assert!(len <= 1.5 + 1e-4 && len > 1.0, "strand {s}: length {len}");
                for i in a..b {
                    // The tessellated sphere's faces lie within 0.5 % inside the unit sphere.
                    assert!(g.curves.position(i).length() > 0.99, "strand {s} enters the sphere");
                }
            }
            if droop == 0.0 {
                // Straight along the normal: the tip is at radius 1 + length.
                let tip = g.curves.position(g.curves.offsets[1] - 1).length();
                assert!((tip - 2.5).abs() < 0.01, "{tip}");
            }
        }
    }

    #[test]
    fn bad_parameters_are_errors_naming_the_key() {
        let plane = TriangleMesh::plane(1.0);
        let bad = |p: FollicleParams| place_follicles(&plane, &p, 0).unwrap_err();
        assert!(bad(FollicleParams { points_per_hair: 1, ..Default::default() }).contains("points_per_hair"));
        assert!(bad(FollicleParams { length: f32::NAN, ..Default::default() }).contains("length"));
        assert!(bad(grid(0, 3)).contains("count"));
        assert!(bad(grid(100_000, 100_000)).contains("count"));
        assert!(
            bad(FollicleParams { uv_min: [0.5, 0.0], uv_max: [0.5, 1.0], ..Default::default() }).contains("uv_range")
        );
        let no_uv = TriangleMesh { uvs: None, ..TriangleMesh::plane(1.0) };
        assert!(place_follicles(&no_uv, &grid(2, 2), 0).unwrap_err().contains("UVs"));
        // A region the mesh's UVs do not reach: a clear error, not a hang.
        let off = FollicleParams {
            placement: Placement::Random { count: 3 },
            uv_min: [2.0, 2.0],
            uv_max: [3.0, 3.0],
            ..Default::default()
        };
        assert!(bad(off).contains("uv_range"));
    }
}
