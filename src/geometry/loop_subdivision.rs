//! Loop subdivision of triangle meshes, for pbrt's `loopsubdiv` shape.
//!
//! Each level splits every triangle into four through a new point on each edge and moves
//! the old vertices (Loop 1987, "Smooth Subdivision Surfaces Based on Triangles"), with the
//! rules pbrt uses (Pharr, Jakob and Humphreys, *Physically Based Rendering*, 3rd ed.,
//! §3.8): an interior vertex of valence n moves to (1 − nβ) v + β Σ neighbours, with
//! Warren's β = 3/16 for n = 3 and 3/(8n) otherwise; a boundary vertex to
//! 3/4 v + 1/8 (b₀ + b₁), its two neighbours along the boundary; an interior edge's point
//! is 3/8 of each end plus 1/8 of each opposite vertex, a boundary edge's its midpoint.
//! After the last level every vertex is moved to its place on the limit surface:
//! interior ones by the same one-ring rule with γ = 1 / (n + 3/(8β)), boundary ones to
//! 3/5 v + 1/5 (b₀ + b₁). Edges of more than two triangles, and vertices on other than two
//! boundary edges, are treated as boundaries and corners (kept in place): pbrt assumes
//! manifold meshes.

use super::TriangleMesh;
use glam::Vec3;
use std::collections::HashMap;

/// `levels` of Loop subdivision of the triangles `indices` over `positions`, the vertices
/// then placed on the limit surface (see the module documentation), with smooth vertex
/// normals; levels past `max_triangles` are not applied. Returns the mesh and the levels
/// applied.
pub fn subdivide(positions: &[Vec3], indices: &[[u32; 3]], levels: u32, max_triangles: usize) -> (TriangleMesh, u32) {
    let (mut positions, mut indices) = (positions.to_vec(), indices.to_vec());
    let mut applied = 0;
    while applied < levels && indices.len().saturating_mul(4) <= max_triangles {
        (positions, indices) = refine(&positions, &indices);
        applied += 1;
    }
    let rings = Rings::new(positions.len(), &indices);
    let limit =
        (0..positions.len()).map(|v| rings.moved(&positions, v, |n| 1.0 / (n + 3.0 / (8.0 * beta(n))), 0.2)).collect();
    let mut mesh = TriangleMesh { positions: limit, normals: None, uvs: None, indices };
    // Smooth shading, as pbrt shades the limit surface by its normals (here each vertex's
    // area-weighted mean of its triangles' normals).
    let vertices: Vec<u32> = (0..mesh.positions.len() as u32).collect();
    mesh.normals = Some(mesh.smooth_normals(&vertices, vertices.len()));
    (mesh, applied)
}

/// Warren's weight of each neighbour of an interior vertex of valence `n`.
fn beta(n: f32) -> f32 {
    if n == 3.0 {
        3.0 / 16.0
    } else {
        3.0 / (8.0 * n)
    }
}

/// One level: old vertices moved and kept at their indices, edge points after them.
fn refine(positions: &[Vec3], indices: &[[u32; 3]]) -> (Vec<Vec3>, Vec<[u32; 3]>) {
    let rings = Rings::new(positions.len(), indices);
    let mut out: Vec<Vec3> = (0..positions.len()).map(|v| rings.moved(positions, v, beta, 0.125)).collect();
    let mut edge_points: HashMap<(u32, u32), u32> = HashMap::with_capacity(rings.edges.len());
    for (&(a, b), opposite) in &rings.edges {
        let (pa, pb) = (positions[a as usize], positions[b as usize]);
        out.push(match opposite.as_slice() {
            [c, d] => 0.375 * (pa + pb) + 0.125 * (positions[*c as usize] + positions[*d as usize]),
            _ => 0.5 * (pa + pb),
        });
        edge_points.insert((a, b), out.len() as u32 - 1);
    }
    let edge = |a: u32, b: u32| edge_points[&(a.min(b), a.max(b))];
    let mut triangles = Vec::with_capacity(4 * indices.len());
    for &[a, b, c] in indices {
        let (ab, bc, ca) = (edge(a, b), edge(b, c), edge(c, a));
        triangles.extend([[a, ab, ca], [ab, b, bc], [ca, bc, c], [ab, bc, ca]]);
    }
    (out, triangles)
}

/// A mesh's edges (each once, as (lower, higher) vertex) with the vertex opposite them in
/// each triangle, and each vertex's neighbours.
struct Rings {
    edges: HashMap<(u32, u32), Vec<u32>>,
    neighbours: Vec<Vec<u32>>,
    /// Each vertex's neighbours along boundary edges (edges of other than two triangles).
    boundary: Vec<Vec<u32>>,
}

impl Rings {
    fn new(vertices: usize, indices: &[[u32; 3]]) -> Rings {
        let mut edges: HashMap<(u32, u32), Vec<u32>> = HashMap::with_capacity(3 * indices.len() / 2);
        for &[a, b, c] in indices {
            for (p, q, opposite) in [(a, b, c), (b, c, a), (c, a, b)] {
                edges.entry((p.min(q), p.max(q))).or_default().push(opposite);
            }
        }
        let (mut neighbours, mut boundary) = (vec![Vec::new(); vertices], vec![Vec::new(); vertices]);
        for (&(a, b), opposite) in &edges {
            neighbours[a as usize].push(b);
            neighbours[b as usize].push(a);
            if opposite.len() != 2 {
                boundary[a as usize].push(b);
                boundary[b as usize].push(a);
            }
        }
        Rings { edges, neighbours, boundary }
    }

    /// Vertex `v` moved by the interior rule of weight `weight(valence)` per neighbour, or
    /// on a boundary by `boundary_weight` per boundary neighbour; corners stay.
    fn moved(&self, positions: &[Vec3], v: usize, weight: impl Fn(f32) -> f32, boundary_weight: f32) -> Vec3 {
        let p = positions[v];
        let at = |k: &u32| positions[*k as usize];
        match (self.boundary[v].as_slice(), self.neighbours[v].len()) {
            (_, 0) => p,
            ([], n) => {
                let w = weight(n as f32);
                (1.0 - n as f32 * w) * p + w * self.neighbours[v].iter().map(at).sum::<Vec3>()
            }
            ([b0, b1], _) => (1.0 - 2.0 * boundary_weight) * p + boundary_weight * (at(b0) + at(b1)),
            _ => p,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A regular octahedron (valence 4 everywhere): the surface stays closed (each edge in
    /// two triangles) and symmetric (the six old vertices equally far from the centre), and
    /// an old vertex's limit position is the same after any number of levels: by the
    /// valence-4 limit rule, γ = 1 / (4 + 3 / (8 × 3/32)) = 1/8, so (1, 0, 0), whose four
    /// neighbours cancel, has its limit at (1/2, 0, 0).
    #[test]
    fn a_closed_mesh_subdivides_to_a_closed_symmetric_surface_with_exact_limits() {
        let p = [Vec3::X, -Vec3::X, Vec3::Y, -Vec3::Y, Vec3::Z, -Vec3::Z];
        let t = [[0, 2, 4], [2, 1, 4], [1, 3, 4], [3, 0, 4], [2, 0, 5], [1, 2, 5], [3, 1, 5], [0, 3, 5]];
        let (mesh, levels) = subdivide(&p, &t, 3, 1 << 20);
        assert_eq!((levels, mesh.indices.len(), mesh.positions.len()), (3, 8 * 64, 6 + 12 + 48 + 192));
        let r: Vec<f32> = mesh.positions.iter().map(|q| q.length()).collect();
        assert!(r.iter().all(|&r| r > 0.4 && r <= 0.5 + 1e-6), "{r:?}");
        assert!(r[..6].iter().all(|&x| (x - r[0]).abs() < 1e-6), "{:?}", &r[..6]);
        let rings = Rings::new(mesh.positions.len(), &mesh.indices);
        assert!(rings.edges.values().all(|o| o.len() == 2));
        for levels in [0, 1, 3] {
            let q = subdivide(&p, &t, levels, 1 << 20).0.positions[0];
            assert!((q - Vec3::new(0.5, 0.0, 0.0)).length() < 1e-6, "{levels}: {q}");
        }
    }

    /// A flat open mesh stays flat, its boundary vertices move along the boundary by the
    /// boundary rules, and the triangle budget stops the levels.
    #[test]
    fn boundaries_follow_the_boundary_rules_and_the_budget_stops_levels() {
        let p = [Vec3::ZERO, Vec3::X, Vec3::new(1.0, 1.0, 0.0), Vec3::Y];
        let t = [[0, 1, 2], [0, 2, 3]];
        let (mesh, levels) = subdivide(&p, &t, 2, 1 << 20);
        assert_eq!((levels, mesh.indices.len()), (2, 32));
        assert!(mesh.positions.iter().all(|q| q.z == 0.0));
        // Vertex 1 is a boundary vertex between 0 and 2 (the diagonal is interior):
        // 3/4 (1, 0) + 1/8 ((0, 0) + (1, 1)) = (0.875, 0.125) after one level.
        // Then its limit: 3/5 of that plus 1/5 of each boundary neighbour, the midpoints
        // (1/2, 0) and (1, 1/2): (0.825, 0.175).
        let once = subdivide(&p, &t, 1, 1 << 20).0;
        assert!((once.positions[1] - Vec3::new(0.825, 0.175, 0.0)).length() < 1e-6, "{}", once.positions[1]);
        let (_, stopped) = subdivide(&p, &t, 5, 2 * 16);
        assert_eq!(stopped, 2);
    }
}
