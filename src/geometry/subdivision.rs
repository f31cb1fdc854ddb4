//! Catmull-Clark subdivision of polygon meshes, for the subdivision surfaces of scene files
//! (Arnold's `subdiv_type` `catclark` with `subdiv_iterations`).
//!
//! Each iteration replaces every n-sided face by n quads, through a face point (the
//! face's centroid), an edge point per edge and a moved vertex point per vertex (Catmull
//! and Clark 1978, "Recursively generated B-spline surfaces on arbitrary topological
//! meshes"). Sharp features follow DeRose, Kass and Truong 1998, "Subdivision Surfaces in
//! Character Animation", section 3:
//! - a crease of sharpness `s` uses the sharp rules (edge midpoint; vertex on two sharp
//!   edges `(a + 6v + b) / 8`; vertex on three or more, or a corner, fixed) for the first
//!   `floor(s)` iterations, a blend for the fraction left, then the smooth rules; its two
//!   halves carry `s - 1` to the next level. USD counts a sharpness of 10 or more as
//!   infinitely sharp;
//! - boundary edges (one face) and non-manifold edges (three faces or more) are infinitely
//!   sharp, and a boundary vertex of a single face is a corner: USD's default boundary
//!   interpolation `edgeAndCorner`.
//!
//! Face-varying texture coordinates are interpolated linearly over each face (Arnold's
//! `subdiv_uv_smoothing` `linear`; its default pins the corners and smooths the rest,
//! which differs only inside UV charts' interiors by a fraction of a texel on usual maps).

use super::TriangleMesh;
use glam::Vec3;
use std::collections::HashMap;

/// Sharpness from which USD (`UsdGeomMesh`'s `creaseSharpnesses`, `cornerSharpnesses`)
/// counts a crease or corner as infinitely sharp.
pub const INFINITELY_SHARP: f32 = 10.0;

/// A polygon mesh: faces as runs of vertex indices, optional texture coordinates per face
/// corner, and the sharpness of creased edges and corner vertices.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct PolygonMesh {
    /// Vertex positions.
    pub positions: Vec<Vec3>,
    /// Vertices of each face, in order.
    pub counts: Vec<u32>,
    /// The vertices of every face, face after face (`counts` long runs).
    pub indices: Vec<u32>,
    /// Texture coordinates of each face corner (as long as `indices`), if any.
    pub uvs: Option<Vec<[f32; 2]>>,
    /// Creased edges (their two vertices, either order) and their sharpness.
    pub creases: Vec<([u32; 2], f32)>,
    /// Corner vertices and their sharpness.
    pub corners: Vec<(u32, f32)>,
}

/// What [`PolygonMesh::subdivide`] did.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Subdivided {
    /// Iterations applied.
    pub iterations: u32,
    /// Iterations asked for.
    pub asked: u32,
}

/// Most iterations Arnold's `subdiv_iterations` holds (a byte); readers refuse a count past
/// it ([`arnold_iterations`]).
pub const MAX_ITERATIONS: u32 = 255;

/// Faces one subdivided mesh may have: an iteration past it is not applied (Arnold applies
/// `subdiv_iterations` uniformly, 4 times the faces per iteration).
pub const MAX_FACES_PER_MESH: usize = 2_000_000;

/// Faces the subdivision of all of a file's meshes may make together: a few lines of text
/// asking for many iterations on many meshes must not exhaust memory.
pub const MAX_FACES_PER_FILE: usize = 8_000_000;

/// An authored iteration count as Arnold holds it: `None` when it is not 0 to
/// [`MAX_ITERATIONS`].
pub fn arnold_iterations(authored: impl TryInto<u32>) -> Option<u32> {
    authored.try_into().ok().filter(|&i| i <= MAX_ITERATIONS)
}

/// The faces the subdivision of one file's meshes has made so far, which
/// [`MAX_FACES_PER_FILE`] bounds; each mesh is also bounded by [`MAX_FACES_PER_MESH`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct FaceBudget {
    /// Faces made so far.
    pub used: usize,
}

impl FaceBudget {
    /// [`PolygonMesh::subdivide`] within the budget, counting the faces it makes.
    pub fn subdivide(&mut self, mesh: &PolygonMesh, iterations: u32) -> (PolygonMesh, Subdivided) {
        let left = MAX_FACES_PER_FILE.saturating_sub(self.used);
        let (refined, done) = mesh.subdivide(iterations, MAX_FACES_PER_MESH.min(left));
        if done.iterations > 0 {
            self.used += refined.counts.len();
        }
        (refined, done)
    }
}

impl Subdivided {
    /// What a reader says of a mesh the budget stopped short of its iterations, if it did.
    pub fn stopped(&self) -> Option<String> {
        (self.iterations < self.asked).then(|| {
            format!(
                "subdivision stopped before an iteration past {MAX_FACES_PER_MESH} faces per mesh or \
                 {MAX_FACES_PER_FILE} per file"
            )
        })
    }
}

impl PolygonMesh {
    /// Checks that the counts cover the indices, every index is a vertex, every face has
    /// at least three vertices and the UVs (if any) are one per corner.
    pub fn validate(&self) -> Result<(), String> {
        let total: u64 = self.counts.iter().map(|&c| c as u64).sum();
        if total != self.indices.len() as u64 {
            return Err(format!("face counts sum to {total} but there are {} indices", self.indices.len()));
        }
        if let Some(f) = self.counts.iter().position(|&c| c < 3) {
            return Err(format!("face {f} has fewer than 3 vertices"));
        }
        let n = self.positions.len();
        if let Some(&i) = self.indices.iter().find(|&&i| i as usize >= n) {
            return Err(format!("a face uses vertex {i} of {n}"));
        }
        if let Some(uvs) = &self.uvs {
            if uvs.len() != self.indices.len() {
                return Err(format!("{} texture coordinates for {} face corners", uvs.len(), self.indices.len()));
            }
        }
        Ok(())
    }

    /// The faces the next iteration makes: one quad per face corner.
    pub fn refined_face_count(&self) -> usize {
        self.indices.len()
    }

    /// Applies up to `iterations` Catmull-Clark iterations, stopping before one that would
    /// make more than `max_faces` faces. The mesh must be valid ([`PolygonMesh::validate`]).
    pub fn subdivide(&self, iterations: u32, max_faces: usize) -> (PolygonMesh, Subdivided) {
        let mut mesh = self.clone();
        let mut done = 0;
        while done < iterations && mesh.refined_face_count() <= max_faces {
            mesh = mesh.refine();
            done += 1;
        }
        (mesh, Subdivided { iterations: done, asked: iterations })
    }

    /// One Catmull-Clark iteration. New vertices: the old vertices moved, then one per
    /// edge, then one per face; face `f`'s corner `k` becomes the quad (vertex `k`, the
    /// point of the edge leaving it, the face point, the point of the edge arriving at it),
    /// so the winding is kept.
    fn refine(&self) -> PolygonMesh {
        let nv = self.positions.len();
        let p = &self.positions;
        let starts: Vec<usize> = self
            .counts
            .iter()
            .scan(0usize, |s, &c| {
                let start = *s;
                *s += c as usize;
                Some(start)
            })
            .collect();
        let face = |f: usize| &self.indices[starts[f]..starts[f] + self.counts[f] as usize];
        let face_points: Vec<Vec3> = (0..self.counts.len())
            .map(|f| face(f).iter().map(|&i| p[i as usize]).sum::<Vec3>() / self.counts[f] as f32)
            .collect();

        // Edges, each once, with the faces around them.
        let mut edge_of: HashMap<[u32; 2], u32> = HashMap::new();
        let mut edges: Vec<[u32; 2]> = Vec::new();
        let mut edge_faces: Vec<u32> = Vec::new();
        let mut edge_face_sum: Vec<Vec3> = Vec::new();
        let mut corner_edge = vec![0u32; self.indices.len()];
        for (f, &start) in starts.iter().enumerate() {
            let v = face(f);
            for k in 0..v.len() {
                let key = sorted([v[k], v[(k + 1) % v.len()]]);
                let e = *edge_of.entry(key).or_insert_with(|| {
                    edges.push(key);
                    edge_faces.push(0);
                    edge_face_sum.push(Vec3::ZERO);
                    (edges.len() - 1) as u32
                });
                edge_faces[e as usize] += 1;
                edge_face_sum[e as usize] += face_points[f];
                corner_edge[start + k] = e;
            }
        }
        let authored: HashMap<[u32; 2], f32> =
            self.creases.iter().filter(|(_, s)| *s > 0.0).map(|&(e, s)| (sorted(e), s)).collect();
        // Boundary and non-manifold edges are infinitely sharp.
        let sharpness: Vec<f32> = (edges.iter().zip(&edge_faces))
            .map(|(e, &faces)| if faces != 2 { f32::INFINITY } else { authored.get(e).copied().unwrap_or(0.0) })
            .collect();

        let edge_points: Vec<Vec3> = (0..edges.len())
            .map(|e| {
                let [a, b] = edges[e];
                let mid = 0.5 * (p[a as usize] + p[b as usize]);
                let s = sharpness[e];
                if s >= 1.0 {
                    return mid;
                }
                let smooth = (p[a as usize] + p[b as usize] + edge_face_sum[e]) / (2 + edge_faces[e]) as f32;
                smooth.lerp(mid, s)
            })
            .collect();

        // Per vertex: its faces (count and sum of face points), its edges (count and sum
        // of midpoints), and its sharp edges (count, sum of far ends, sum of sharpness).
        let mut faces_at = vec![(0u32, Vec3::ZERO); nv];
        for (f, fp) in face_points.iter().enumerate() {
            for &i in face(f) {
                faces_at[i as usize].0 += 1;
                faces_at[i as usize].1 += *fp;
            }
        }
        let mut edges_at = vec![(0u32, Vec3::ZERO); nv];
        let mut sharp_at = vec![(0u32, Vec3::ZERO, 0.0f32); nv];
        for (e, &[a, b]) in edges.iter().enumerate() {
            let mid = 0.5 * (p[a as usize] + p[b as usize]);
            for (v, other) in [(a, b), (b, a)] {
                edges_at[v as usize].0 += 1;
                edges_at[v as usize].1 += mid;
                if sharpness[e] > 0.0 {
                    let s = &mut sharp_at[v as usize];
                    s.0 += 1;
                    s.1 += p[other as usize];
                    s.2 += sharpness[e].min(1.0);
                }
            }
        }
        let corner_sharpness: HashMap<u32, f32> =
            self.corners.iter().filter(|(_, s)| *s > 0.0).map(|&(v, s)| (v, s)).collect();
        let vertex_points = (0..nv).map(|v| {
            let (faces, face_sum) = faces_at[v];
            let (n, mid_sum) = edges_at[v];
            if faces == 0 || n == 0 {
                return p[v];
            }
            let n_f = n as f32;
            let smooth = (face_sum / faces as f32 + 2.0 * mid_sum / n_f + (n_f - 3.0) * p[v]) / n_f;
            let (sharp, far_sum, strength) = sharp_at[v];
            // A boundary vertex of one face is a corner (`edgeAndCorner`).
            let boundary_corner = faces == 1 && n == 2;
            let corner = corner_sharpness.get(&(v as u32)).copied().unwrap_or(0.0);
            let (rule, weight) = if corner > 0.0 || sharp > 2 || boundary_corner {
                (p[v], if boundary_corner || sharp > 2 { 1.0 } else { corner.min(1.0) })
            } else if sharp == 2 {
                ((far_sum + 6.0 * p[v]) / 8.0, strength / 2.0)
            } else {
                return smooth;
            };
            smooth.lerp(rule, weight.min(1.0))
        });

        let positions: Vec<Vec3> = vertex_points.chain(edge_points).chain(face_points.iter().copied()).collect();
        let (first_edge, first_face) = (nv as u32, (nv + edges.len()) as u32);
        let mut indices = Vec::with_capacity(4 * self.indices.len());
        let mut uvs = self.uvs.as_ref().map(|_| Vec::with_capacity(4 * self.indices.len()));
        for (f, &start) in starts.iter().enumerate() {
            let v = face(f);
            let n = v.len();
            let face_uv = self.uvs.as_ref().map(|u| mean(&u[start..start + n]));
            for k in 0..n {
                let prev = (k + n - 1) % n;
                indices.extend([
                    v[k],
                    first_edge + corner_edge[start + k],
                    first_face + f as u32,
                    first_edge + corner_edge[start + prev],
                ]);
                if let (Some(out), Some(u), Some(centre)) = (&mut uvs, &self.uvs, face_uv) {
                    let (here, next, before) = (u[start + k], u[start + (k + 1) % n], u[start + prev]);
                    out.extend([here, mean(&[here, next]), centre, mean(&[before, here])]);
                }
            }
        }
        // Authored creases pass to both halves of their edge, one level softer.
        let mut creases = Vec::new();
        for (e, &[a, b]) in edges.iter().enumerate() {
            if let Some(&s) = authored.get(&[a, b]) {
                let child = if s >= INFINITELY_SHARP { s } else { s - 1.0 };
                if child > 0.0 {
                    creases.push(([a, first_edge + e as u32], child));
                    creases.push(([first_edge + e as u32, b], child));
                }
            }
        }
        let corners = (self.corners.iter())
            .filter_map(|&(v, s)| {
                let child = if s >= INFINITELY_SHARP { s } else { s - 1.0 };
                (child > 0.0).then_some((v, child))
            })
            .collect();
        PolygonMesh { positions, counts: vec![4; self.indices.len()], indices, uvs, creases, corners }
    }

    /// The mesh as triangles: polygons as fans, one vertex per distinct (vertex, UV)
    /// corner, and with `smooth`, vertex normals that are the area-weighted mean of the
    /// normals of the triangles around each vertex (across UV seams too). With the vertex
    /// of `positions` each triangle-mesh vertex is.
    pub fn triangulate(&self, smooth: bool) -> (TriangleMesh, Vec<u32>) {
        let mut mesh = TriangleMesh::default();
        let mut uvs = Vec::new();
        let mut original = Vec::new();
        let mut corners: HashMap<(u32, [u32; 2]), u32> = HashMap::new();
        let mut k = 0usize;
        for &c in &self.counts {
            let ids: Vec<u32> = (0..c as usize)
                .map(|j| {
                    let v = self.indices[k + j];
                    let uv = self.uvs.as_ref().map(|u| u[k + j]);
                    let key = (v, uv.map_or([u32::MAX; 2], |u| u.map(f32::to_bits)));
                    *corners.entry(key).or_insert_with(|| {
                        mesh.positions.push(self.positions[v as usize]);
                        uvs.push(uv.unwrap_or([0.0; 2]));
                        original.push(v);
                        (mesh.positions.len() - 1) as u32
                    })
                })
                .collect();
            k += c as usize;
            for j in 1..ids.len().saturating_sub(1) {
                mesh.indices.push([ids[0], ids[j], ids[j + 1]]);
            }
        }
        if self.uvs.is_some() {
            mesh.uvs = Some(uvs);
        }
        if smooth {
            mesh.normals = Some(mesh.smooth_normals(&original, self.positions.len()));
        }
        (mesh, original)
    }
}

/// The pair in increasing order (an edge's key, whichever way a face runs along it).
fn sorted([a, b]: [u32; 2]) -> [u32; 2] {
    if a <= b {
        [a, b]
    } else {
        [b, a]
    }
}

/// The mean of texture coordinates.
fn mean(uvs: &[[f32; 2]]) -> [f32; 2] {
    let n = uvs.len() as f32;
    let [u, v] = uvs.iter().fold([0.0, 0.0], |[a, b], [u, v]| [a + u, b + v]);
    [u / n, v / n]
}

/// Asserts that `m` is the unit cube [-0.5, 0.5]³ after two Catmull-Clark iterations, as
/// the importers' tests read it: 6 × 4² quads, smooth shaded, inside the cage, every
/// corner pulled in past the 5/18-per-axis point of the first iteration.
#[cfg(test)]
pub(crate) fn assert_cube_subdivided_twice(m: &TriangleMesh) {
    assert_eq!(m.indices.len(), 2 * 6 * 16);
    assert!(m.normals.is_some());
    let extent = m.positions.iter().fold(0.0f32, |e, p| e.max(p.abs().max_element()));
    assert!(extent < 0.5 && extent > 0.4, "{extent}");
    let corner = m.positions.iter().map(|p| p.x + p.y + p.z).fold(f32::MIN, f32::max);
    assert!(corner < 3.0 * 5.0 / 18.0, "{corner}");
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The cube [-0.5, 0.5]³ with outward faces.
    fn cube() -> PolygonMesh {
        let positions = (0..8)
            .map(|i| Vec3::new((i & 1) as f32 - 0.5, ((i >> 1) & 1) as f32 - 0.5, ((i >> 2) & 1) as f32 - 0.5))
            .collect();
        let faces = [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]];
        PolygonMesh {
            positions,
            counts: vec![4; 6],
            indices: faces.iter().flatten().copied().collect(),
            ..Default::default()
        }
    }

    /// Every edge of a refined mesh, with how many faces use it.
    fn edge_uses(m: &PolygonMesh) -> HashMap<[u32; 2], u32> {
        let mut uses = HashMap::new();
        let mut k = 0;
        for &c in &m.counts {
            let f = &m.indices[k..k + c as usize];
            for j in 0..f.len() {
                *uses.entry(sorted([f[j], f[(j + 1) % f.len()]])).or_insert(0) += 1;
            }
            k += c as usize;
        }
        uses
    }

    #[test]
    fn a_cube_corner_moves_as_catmull_and_clark_give() {
        // Corner (0.5, 0.5, 0.5): valence 3, face points (0.5, 0, 0) ..., edge midpoints
        // (0.5, 0.5, 0) ...: (Q + 2R + (n - 3)V) / n = (1/6 + 2/3) / 3 = 5/18 per axis.
        let (m, done) = cube().subdivide(1, usize::MAX);
        assert_eq!(done, Subdivided { iterations: 1, asked: 1 });
        assert!((m.positions[7] - Vec3::splat(5.0 / 18.0)).abs().max_element() < 1e-6, "{}", m.positions[7]);
        // Edge (0.5, 0.5, ±0.5)'s point: (v0 + v1 + f0 + f1) / 4 = (0.375, 0.375, 0).
        let e = m.positions[8..8 + 12].iter().find(|p| p.z.abs() < 1e-6 && p.x > 0.0 && p.y > 0.0).unwrap();
        assert!((*e - Vec3::new(0.375, 0.375, 0.0)).length() < 1e-6, "{e}");
        assert_eq!((m.positions.len(), m.counts.len()), (8 + 12 + 6, 24));
        // Still closed: every edge between two faces.
        assert!(edge_uses(&m).values().all(|&u| u == 2));
    }

    #[test]
    fn repeated_subdivision_converges_inside_the_cage_and_stays_symmetric() {
        let (m, _) = cube().subdivide(4, usize::MAX);
        assert_eq!(m.counts.len(), 6 * 4usize.pow(4));
        // A convex cage's surface lies strictly inside it, and the cube's rounds off
        // without collapsing: every point between 0.3 and 0.5 from the centre.
        assert!(m.positions.iter().all(|p| p.abs().max_element() < 0.5));
        assert!(m.positions.iter().all(|p| p.length() > 0.3 && p.length() < 0.5));
        // Mirror symmetry: for each point, its mirror through x = 0 is a point too.
        for p in &m.positions {
            let q = Vec3::new(-p.x, p.y, p.z);
            assert!(m.positions.iter().any(|o| (*o - q).length() < 1e-5), "{p}");
        }
    }

    #[test]
    fn a_flat_grid_stays_flat_and_its_interior_stays_regular() {
        // 4 x 4 quads in the plane z = 0: Catmull-Clark reproduces linear functions, so the
        // interior stays on the plane and an interior vertex of a regular grid stays put.
        let mut m = PolygonMesh::default();
        for j in 0..5 {
            for i in 0..5 {
                m.positions.push(Vec3::new(i as f32, j as f32, 0.0));
            }
        }
        for j in 0..4 {
            for i in 0..4 {
                let v = j * 5 + i;
                m.indices.extend([v, v + 1, v + 6, v + 5]);
                m.counts.push(4);
            }
        }
        let (r, _) = m.subdivide(2, usize::MAX);
        assert!(r.positions.iter().all(|p| p.z == 0.0));
        assert_eq!(r.positions[12], Vec3::new(2.0, 2.0, 0.0));
        // Corners of the boundary stay (`edgeAndCorner`), boundary edges stay straight.
        for corner in [0, 4, 20, 24] {
            assert_eq!(r.positions[corner], m.positions[corner]);
        }
        assert!(r.positions.iter().all(|p| p.x >= 0.0 && p.x <= 4.0 && p.y >= 0.0 && p.y <= 4.0));
        let on_bottom: Vec<f32> = r.positions.iter().filter(|p| p.y == 0.0).map(|p| p.x).collect();
        assert_eq!(on_bottom.len(), 4 * 4 + 1, "{on_bottom:?}");
    }

    #[test]
    fn infinitely_sharp_creases_keep_the_cube_a_cube() {
        // Every edge creased for good: every vertex is on three sharp edges, a corner.
        let mut sharp = cube();
        sharp.creases = edge_uses(&cube().clone()).keys().map(|&e| (e, INFINITELY_SHARP)).collect();
        let (m, _) = sharp.subdivide(3, usize::MAX);
        // Corners stay, edges stay straight, faces stay flat: every point is on the cage.
        assert_eq!(m.positions[7], Vec3::splat(0.5));
        assert!(m.positions.iter().all(|p| (p.abs().max_element() - 0.5).abs() < 1e-6), "a point left the cube");
        // A crease of sharpness 1 is sharp for one iteration only: the edge point is the
        // midpoint, then the surface rounds.
        let mut once = cube();
        once.creases = vec![([3, 7], 1.0)];
        let (m1, _) = once.subdivide(1, usize::MAX);
        let smooth = cube().subdivide(1, usize::MAX).0;
        let mid = Vec3::new(0.5, 0.5, 0.0);
        assert!(m1.positions.iter().any(|p| (*p - mid).length() < 1e-6));
        assert!(!smooth.positions.iter().any(|p| (*p - mid).length() < 1e-6));
        assert!(m1.creases.is_empty(), "{:?}", m1.creases);
    }

    #[test]
    fn an_n_gon_becomes_n_quads_with_linear_uvs() {
        let m = PolygonMesh {
            positions: vec![Vec3::ZERO, Vec3::X, Vec3::new(1.0, 1.0, 0.0), Vec3::Y, Vec3::new(0.5, 1.5, 0.0)],
            counts: vec![5],
            indices: vec![0, 1, 2, 4, 3],
            uvs: Some(vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.5, 1.5], [0.0, 1.0]]),
            ..Default::default()
        };
        m.validate().unwrap();
        let (r, _) = m.subdivide(1, usize::MAX);
        r.validate().unwrap();
        assert_eq!(r.counts, vec![4; 5]);
        let uvs = r.uvs.as_ref().unwrap();
        // Corner 1's quad: its own UV, the mid of edge 1-2, the face's mean, the mid of 0-1.
        assert_eq!(&uvs[4..8], &[[1.0, 0.0], [1.0, 0.5], [0.5, 0.7], [0.5, 0.0]]);
        // Triangulated: 2 triangles per quad, and the normals of a flat face all +z.
        let t = r.triangulate(true).0;
        assert_eq!(t.indices.len(), 10);
        assert!(t.normals.unwrap().iter().all(|n| (*n - Vec3::Z).length() < 1e-5));
    }

    #[test]
    fn the_face_budget_stops_before_an_iteration_that_would_exceed_it() {
        // 6 quads -> 24 -> 96 -> 384: a budget of 100 allows two iterations of five.
        let (m, done) = cube().subdivide(5, 100);
        assert_eq!(done, Subdivided { iterations: 2, asked: 5 });
        assert_eq!(m.counts.len(), 96);
        assert_eq!(cube().subdivide(0, 100).0, cube());
    }

    #[test]
    fn validation_names_what_is_wrong() {
        let mut m = cube();
        m.counts[0] = 2;
        assert!(m.validate().unwrap_err().contains("sum to 22"), "{:?}", m.validate());
        let mut m = cube();
        m.indices[3] = 8;
        assert_eq!(m.validate().unwrap_err(), "a face uses vertex 8 of 8");
    }
}
