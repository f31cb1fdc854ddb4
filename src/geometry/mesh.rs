//! Triangle meshes.

use glam::Vec3;

/// An indexed triangle mesh with optional per-vertex normals and UVs.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct TriangleMesh {
    /// Vertex positions.
    pub positions: Vec<Vec3>,
    /// Optional per-vertex shading normals (same length as `positions`).
    pub normals: Option<Vec<Vec3>>,
    /// Optional per-vertex texture coordinates (same length as `positions`).
    pub uvs: Option<Vec<[f32; 2]>>,
    /// Vertex indices, three per triangle.
    pub indices: Vec<[u32; 3]>,
}

impl TriangleMesh {
    /// Corners of triangle `i`.
    #[inline]
    pub fn corners(&self, i: u32) -> [Vec3; 3] {
        let [a, b, c] = self.indices[i as usize];
        [self.positions[a as usize], self.positions[b as usize], self.positions[c as usize]]
    }

    /// Area of triangle `i`.
    pub fn area(&self, i: u32) -> f32 {
        let [a, b, c] = self.corners(i);
        0.5 * (b - a).cross(c - a).length()
    }

    /// Shading normal at barycentrics (`b1`, `b2`) of triangle `i`: interpolated vertex
    /// normals when present, else the geometric normal.
    pub fn shading_normal(&self, i: u32, b1: f32, b2: f32) -> Vec3 {
        let [a, b, c] = self.corners(i);
        let geometric = (b - a).cross(c - a).normalize_or(Vec3::Y);
        match &self.normals {
            Some(n) => {
                let [ia, ib, ic] = self.indices[i as usize];
                let v = n[ia as usize] * (1.0 - b1 - b2) + n[ib as usize] * b1 + n[ic as usize] * b2;
                v.try_normalize().unwrap_or(geometric)
            }
            None => geometric,
        }
    }

    /// Texture coordinates at barycentrics (`b1`, `b2`) of triangle `i`, and how many UV
    /// units one unit of length on the triangle spans (the square root of its UV area over
    /// its area: the ray-cone texture LOD's texel density, Akenine-Moller et al. 2019);
    /// `None` without UVs.
    pub fn uv_at(&self, i: u32, b1: f32, b2: f32) -> Option<([f32; 2], f32)> {
        let uvs = self.uvs.as_ref()?;
        let [ia, ib, ic] = self.indices[i as usize];
        let (ta, tb, tc) = (uvs[ia as usize], uvs[ib as usize], uvs[ic as usize]);
        let b0 = 1.0 - b1 - b2;
        let uv = [ta[0] * b0 + tb[0] * b1 + tc[0] * b2, ta[1] * b0 + tb[1] * b1 + tc[1] * b2];
        let uv_area = ((tb[0] - ta[0]) * (tc[1] - ta[1]) - (tc[0] - ta[0]) * (tb[1] - ta[1])).abs();
        let area = 2.0 * self.area(i);
        let density = if area > 0.0 { (uv_area / area).sqrt() } else { 0.0 };
        Some((uv, if density.is_finite() { density } else { 0.0 }))
    }

    /// Bytes held by the arrays of this mesh.
    pub fn memory_bytes(&self) -> usize {
        self.positions.len() * 12
            + self.normals.as_ref().map_or(0, |n| n.len() * 12)
            + self.uvs.as_ref().map_or(0, |u| u.len() * 8)
            + self.indices.len() * 12
    }

    /// Applies an affine transform to positions and normals.
    pub fn transform(&mut self, m: &glam::Affine3A) {
        for p in &mut self.positions {
            *p = m.transform_point3(*p);
        }
        if let Some(ns) = &mut self.normals {
            let nm = glam::Mat3::from(m.matrix3).inverse().transpose();
            for n in ns {
                *n = (nm * *n).normalize_or(Vec3::Y);
            }
        }
    }

    /// Removes the triangles with a corner that is missing, not finite or beyond
    /// [`super::MAX_COORDINATE`] (positions pushed past the float range by a transform);
    /// returns how many.
    pub fn remove_unusable_triangles(&mut self) -> usize {
        let before = self.indices.len();
        let positions = &self.positions;
        let usable = |p: &Vec3| p.is_finite() && p.abs().max_element() <= super::MAX_COORDINATE;
        self.indices.retain(|t| t.iter().all(|&v| positions.get(v as usize).is_some_and(usable)));
        before - self.indices.len()
    }

    /// Checks indices are in range and positions finite; returns a description of the
    /// first problem found.
    pub fn validate(&self) -> Result<(), String> {
        let n = self.positions.len() as u32;
        if let Some(i) = self.positions.iter().position(|p| !p.is_finite()) {
            return Err(format!("vertex {i} is not finite"));
        }
        if let Some(t) = self.indices.iter().position(|t| t.iter().any(|&v| v >= n)) {
            return Err(format!("triangle {t} refers to a vertex past the {n} vertices"));
        }
        for (name, len) in
            [("normals", self.normals.as_ref().map(|v| v.len())), ("uvs", self.uvs.as_ref().map(|v| v.len()))]
        {
            if let Some(len) = len {
                if len != n as usize {
                    return Err(format!("{len} {name} for {n} vertices"));
                }
            }
        }
        Ok(())
    }

    /// Smooth vertex normals: for each vertex, the area-weighted mean of the normals of the
    /// triangles around the vertex of the source polygons it came from (`original[i]`, one
    /// of `sources`), so vertices split at UV seams share one normal.
    pub fn smooth_normals(&self, original: &[u32], sources: usize) -> Vec<Vec3> {
        let mut sum = vec![Vec3::ZERO; sources];
        for t in &self.indices {
            let [a, b, c] = t.map(|i| self.positions[i as usize]);
            let area_normal = (b - a).cross(c - a);
            for &i in t {
                sum[original[i as usize] as usize] += area_normal;
            }
        }
        original.iter().map(|&o| sum[o as usize].normalize_or(Vec3::Y)).collect()
    }

    /// The box around the vertices placed by `m`.
    pub fn bounds_under(&self, m: &glam::Affine3A) -> crate::math::Aabb {
        (self.positions.iter()).fold(crate::math::Aabb::EMPTY, |b, p| b.grow(m.transform_point3(*p).into()))
    }
}

/// Procedural meshes for built-in scenes and scene files.
impl TriangleMesh {
    /// A torus around the y axis (ring in the xz-plane) with `major` and `minor` radii,
    /// `nu` steps around the ring and `nv` around the tube; UVs run 0..1 along both.
    pub fn torus(major: f32, minor: f32, nu: u32, nv: u32) -> TriangleMesh {
        use std::f32::consts::TAU;
        let (nu, nv) = (nu.max(3), nv.max(3));
        let mut mesh = TriangleMesh::default();
        let (mut normals, mut uvs) = (Vec::new(), Vec::new());
        // One extra row and column so UVs do not wrap inside a triangle.
        for i in 0..=nu {
            let u = TAU * i as f32 / nu as f32;
            for j in 0..=nv {
                let v = TAU * j as f32 / nv as f32;
                let n = Vec3::new(v.cos() * u.cos(), v.sin(), v.cos() * u.sin());
                mesh.positions.push(Vec3::new(major * u.cos(), 0.0, major * u.sin()) + n * minor);
                normals.push(n);
                uvs.push([i as f32 / nu as f32, j as f32 / nv as f32]);
            }
        }
        let row = nv + 1;
        for i in 0..nu {
            for j in 0..nv {
                let (a, b, c, d) = (i * row + j, (i + 1) * row + j, (i + 1) * row + j + 1, i * row + j + 1);
                mesh.indices.push([a, d, c]);
                mesh.indices.push([a, c, b]);
            }
        }
        mesh.normals = Some(normals);
        mesh.uvs = Some(uvs);
        mesh
    }

    /// A UV sphere of `radius` around the origin.
    pub fn sphere(radius: f32, rings: u32) -> TriangleMesh {
        use std::f32::consts::{PI, TAU};
        let rings = rings.max(3);
        let segments = 2 * rings;
        let mut mesh = TriangleMesh::default();
        let (mut normals, mut uvs) = (Vec::new(), Vec::new());
        for i in 0..=rings {
            let theta = PI * i as f32 / rings as f32;
            for j in 0..=segments {
                let phi = TAU * j as f32 / segments as f32;
                let n = Vec3::new(theta.sin() * phi.cos(), theta.cos(), theta.sin() * phi.sin());
                mesh.positions.push(n * radius);
                normals.push(n);
                uvs.push([j as f32 / segments as f32, i as f32 / rings as f32]);
            }
        }
        let row = segments + 1;
        for i in 0..rings {
            for j in 0..segments {
                let (a, b, c, d) = (i * row + j, (i + 1) * row + j, (i + 1) * row + j + 1, i * row + j + 1);
                if i > 0 {
                    mesh.indices.push([a, d, b]);
                }
                if i + 1 < rings {
                    mesh.indices.push([d, c, b]);
                }
            }
        }
        mesh.normals = Some(normals);
        mesh.uvs = Some(uvs);
        mesh
    }

    /// A unit icosphere around the origin: the regular icosahedron (12 vertices, 20
    /// triangles) with each triangle split into four `subdivisions` times, the new
    /// vertices pushed out onto the sphere; vertex normals are the positions. Triangles
    /// wind counter-clockwise seen from outside.
    pub fn icosphere(subdivisions: u32) -> TriangleMesh {
        // The icosahedron's vertices are the cyclic permutations of (±1, ±φ, 0).
        let t = (1.0 + 5f32.sqrt()) / 2.0;
        let mut positions: Vec<Vec3> = [
            (-1.0, t, 0.0),
            (1.0, t, 0.0),
            (-1.0, -t, 0.0),
            (1.0, -t, 0.0),
            (0.0, -1.0, t),
            (0.0, 1.0, t),
            (0.0, -1.0, -t),
            (0.0, 1.0, -t),
            (t, 0.0, -1.0),
            (t, 0.0, 1.0),
            (-t, 0.0, -1.0),
            (-t, 0.0, 1.0),
        ]
        .into_iter()
        .map(|(x, y, z)| Vec3::new(x, y, z).normalize())
        .collect();
        let mut indices: Vec<[u32; 3]> = vec![
            [0, 11, 5],
            [0, 5, 1],
            [0, 1, 7],
            [0, 7, 10],
            [0, 10, 11],
            [1, 5, 9],
            [5, 11, 4],
            [11, 10, 2],
            [10, 7, 6],
            [7, 1, 8],
            [3, 9, 4],
            [3, 4, 2],
            [3, 2, 6],
            [3, 6, 8],
            [3, 8, 9],
            [4, 9, 5],
            [2, 4, 11],
            [6, 2, 10],
            [8, 6, 7],
            [9, 8, 1],
        ];
        for _ in 0..subdivisions {
            let mut middles = std::collections::HashMap::new();
            let mut middle = |a: u32, b: u32, positions: &mut Vec<Vec3>| {
                *middles.entry((a.min(b), a.max(b))).or_insert_with(|| {
                    positions.push((positions[a as usize] + positions[b as usize]).normalize());
                    positions.len() as u32 - 1
                })
            };
            let mut finer = Vec::with_capacity(indices.len() * 4);
            for [a, b, c] in indices {
                let (ab, bc, ca) =
                    (middle(a, b, &mut positions), middle(b, c, &mut positions), middle(c, a, &mut positions));
                finer.extend([[a, ab, ca], [b, bc, ab], [c, ca, bc], [ab, bc, ca]]);
            }
            indices = finer;
        }
        TriangleMesh { normals: Some(positions.clone()), positions, uvs: None, indices }
    }

    /// A pillow: a square cushion of side `size` in the xz-plane, centred on the origin,
    /// whose top and bottom faces bulge to `thickness / 2` above and below it from a seam
    /// around the edge, as `(1 - x^2)^0.3 (1 - z^2)^0.3` over the square `[-1, 1]^2`.
    /// `n` steps a side; UVs run 0..1 along x and z on both faces; normals are the
    /// area-weighted face normals, so along the seam they point outward.
    pub fn pillow(size: f32, thickness: f32, n: u32) -> TriangleMesh {
        let n = n.max(2);
        let h = 0.5 * size;
        let bulge = |t: f32| (1.0 - t * t).max(0.0).powf(0.3);
        let mut mesh = TriangleMesh::default();
        let mut uvs = Vec::new();
        let coord = |i: u32| 2.0 * i as f32 / n as f32 - 1.0;
        let row = n + 1;
        // Top face: the full grid. Bottom face: its interior, sharing the seam vertices.
        for j in 0..=n {
            for i in 0..=n {
                let (x, z) = (coord(i), coord(j));
                mesh.positions.push(Vec3::new(x * h, 0.5 * thickness * bulge(x) * bulge(z), z * h));
                uvs.push([i as f32 / n as f32, j as f32 / n as f32]);
            }
        }
        let interior = |i: u32, j: u32| i > 0 && j > 0 && i < n && j < n;
        let mut bottom = vec![0u32; (row * row) as usize];
        for j in 0..=n {
            for i in 0..=n {
                let top = j * row + i;
                bottom[top as usize] = if interior(i, j) {
                    let p = mesh.positions[top as usize];
                    mesh.positions.push(Vec3::new(p.x, -p.y, p.z));
                    uvs.push(uvs[top as usize]);
                    mesh.positions.len() as u32 - 1
                } else {
                    top
                };
            }
        }
        for j in 0..n {
            for i in 0..n {
                let (a, b, c, d) = (j * row + i, j * row + i + 1, (j + 1) * row + i + 1, (j + 1) * row + i);
                // Diagonals point to the centre, so no corner triangle lies wholly on the
                // seam (a flat flap shared by both faces).
                let quad = if (i < n / 2) == (j < n / 2) { [[a, c, b], [a, d, c]] } else { [[a, d, b], [b, d, c]] };
                for [p, q, r] in quad {
                    mesh.indices.push([p, q, r]);
                    mesh.indices.push([r, q, p].map(|v| bottom[v as usize]));
                }
            }
        }
        let mut normals = vec![Vec3::ZERO; mesh.positions.len()];
        for t in 0..mesh.indices.len() as u32 {
            let [a, b, c] = mesh.corners(t);
            // The cross product's length is twice the area: an area-weighted sum.
            let face = (b - a).cross(c - a);
            for v in mesh.indices[t as usize] {
                normals[v as usize] += face;
            }
        }
        mesh.normals = Some(normals.into_iter().map(|n| n.normalize_or(Vec3::Y)).collect());
        mesh.uvs = Some(uvs);
        mesh
    }

    /// A square of side `size` in the xz-plane, centred on the origin, facing +y.
    pub fn plane(size: f32) -> TriangleMesh {
        let h = 0.5 * size;
        TriangleMesh {
            positions: vec![Vec3::new(-h, 0.0, -h), Vec3::new(h, 0.0, -h), Vec3::new(h, 0.0, h), Vec3::new(-h, 0.0, h)],
            normals: Some(vec![Vec3::Y; 4]),
            uvs: Some(vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]),
            indices: vec![[0, 2, 1], [0, 3, 2]],
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn icospheres_are_closed_face_outwards_and_lie_on_the_unit_sphere() {
        for (subdivisions, vertices, triangles) in [(0, 12, 20), (1, 42, 80), (2, 162, 320)] {
            let m = TriangleMesh::icosphere(subdivisions);
            m.validate().unwrap();
            assert_eq!((m.positions.len(), m.indices.len()), (vertices, triangles));
            assert!(m.positions.iter().all(|p| (p.length() - 1.0).abs() < 1e-6));
            // Every edge is shared by two triangles, walked in opposite directions.
            let mut edges = std::collections::HashMap::new();
            for t in &m.indices {
                for k in 0..3 {
                    *edges.entry((t[k], t[(k + 1) % 3])).or_insert(0) += 1;
                }
            }
            assert!(edges.iter().all(|(&(a, b), &n)| n == 1 && edges.get(&(b, a)) == Some(&1)));
            for i in 0..m.indices.len() as u32 {
                let [a, b, c] = m.corners(i);
                assert!((b - a).cross(c - a).dot(a + b + c) > 0.0, "triangle {i} faces inwards");
            }
        }
    }

    #[test]
    fn procedural_meshes_are_valid_and_have_the_right_area() {
        use std::f32::consts::PI;
        let total = |m: &TriangleMesh| (0..m.indices.len() as u32).map(|i| m.area(i)).sum::<f32>();
        let torus = TriangleMesh::torus(1.0, 0.35, 96, 48);
        torus.validate().unwrap();
        let exact = 4.0 * PI * PI * 0.35;
        assert!((total(&torus) - exact).abs() < 0.01 * exact);
        let sphere = TriangleMesh::sphere(2.0, 48);
        sphere.validate().unwrap();
        assert!((total(&sphere) - 16.0 * PI).abs() < 0.01 * 16.0 * PI);
        let plane = TriangleMesh::plane(3.0);
        assert!((total(&plane) - 9.0).abs() < 1e-5);
        let pillow = TriangleMesh::pillow(2.0, 0.6, 40);
        pillow.validate().unwrap();
        // Two faces of at least the square's area each, closed along the seam.
        assert!(total(&pillow) > 8.0 && total(&pillow) < 10.0, "{}", total(&pillow));
        let top = pillow.positions.iter().map(|p| p.y).fold(0.0f32, f32::max);
        assert!((top - 0.3).abs() < 1e-6);
        // Triangles face outward along the given normals.
        for m in [&torus, &sphere, &plane, &pillow] {
            for i in 0..m.indices.len() as u32 {
                let [a, b, c] = m.corners(i);
                let ng = (b - a).cross(c - a);
                assert!(ng.dot(m.shading_normal(i, 1.0 / 3.0, 1.0 / 3.0)) > 0.0, "triangle {i} faces inward");
            }
        }
    }
}
