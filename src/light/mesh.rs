//! A triangle mesh that emits light (Arnold's `mesh_light`): uniform radiance from the
//! front of every triangle, sampled by area.

use super::LightSample;
use crate::accel::bvh::{BuildItem, Bvh, RayBoxTest};
use crate::geometry::triangle::intersect_triangle;
use crate::math::{Aabb, Color};
use glam::{Affine3A, Vec3};

/// Triangles emitting `radiance` from their front face, the side `(b - a) × (c - a)`
/// points to (the winding the mesh is drawn with).
#[derive(Clone, Debug)]
pub struct MeshLight {
    // Corners, one triangle per index (structure of arrays).
    a: Vec<Vec3>,
    b: Vec<Vec3>,
    c: Vec<Vec3>,
    /// Running sum of the triangles' areas: `cumulative[i]` is the area of triangles
    /// `0..=i`, the last entry the total (sampling by area inverts it by binary search).
    cumulative: Vec<f32>,
    bvh: Bvh,
    radiance: Color,
    camera_visibility: f32,
}

/// Two mesh lights are equal when they emit the same from the same triangles (the
/// hierarchy is derived from those).
impl PartialEq for MeshLight {
    fn eq(&self, o: &MeshLight) -> bool {
        (&self.a, &self.b, &self.c, self.radiance, self.camera_visibility)
            == (&o.a, &o.b, &o.c, o.radiance, o.camera_visibility)
    }
}

impl MeshLight {
    /// The light of `triangles` (corners, front face by winding) emitting `radiance`,
    /// seen by camera rays with weight `camera_visibility` (as [`super::Light::Quad`]).
    /// Triangles of zero or non-finite area are left out; `None` when none is left.
    pub fn new(
        triangles: impl IntoIterator<Item = [Vec3; 3]>,
        radiance: Color,
        camera_visibility: f32,
    ) -> Option<Self> {
        let (mut a, mut b, mut c, mut cumulative) = (Vec::new(), Vec::new(), Vec::new(), Vec::new());
        let mut total = 0.0f32;
        for [p, q, r] in triangles {
            let area = 0.5 * (q - p).cross(r - p).length();
            if !(area > 0.0 && area.is_finite()) {
                continue;
            }
            total += area;
            a.push(p);
            b.push(q);
            c.push(r);
            cumulative.push(total);
        }
        if cumulative.is_empty() || !total.is_finite() {
            return None;
        }
        let items = (0..a.len())
            .map(|i| BuildItem::new(Aabb::new(a[i].min(b[i]).min(c[i]), a[i].max(b[i]).max(c[i])), i as u32))
            .collect();
        Some(MeshLight { a, b, c, cumulative, bvh: Bvh::build(items), radiance, camera_visibility })
    }

    /// Number of emitting triangles.
    pub fn triangle_count(&self) -> usize {
        self.a.len()
    }

    /// Total emitting area.
    pub fn area(&self) -> f32 {
        self.cumulative.last().copied().unwrap_or(0.0)
    }

    /// Emitted radiance.
    pub fn radiance(&self) -> Color {
        self.radiance
    }

    /// The same light emitting `radiance` instead.
    pub fn with_radiance(&self, radiance: Color) -> MeshLight {
        MeshLight { radiance, ..self.clone() }
    }

    /// Weight camera rays see it with.
    pub fn camera_visibility(&self) -> f32 {
        self.camera_visibility
    }

    /// The light moved by `m`. A mirroring `m` (negative determinant) would turn the
    /// winding's normal to the back, so the winding is reversed to keep the same side lit.
    pub fn transformed(&self, m: &Affine3A) -> MeshLight {
        let mirror = m.matrix3.determinant() < 0.0;
        let corners = (0..self.a.len()).map(|i| {
            let [p, q, r] = [self.a[i], self.b[i], self.c[i]].map(|v| m.transform_point3(v));
            if mirror {
                [p, r, q]
            } else {
                [p, q, r]
            }
        });
        MeshLight::new(corners, self.radiance, self.camera_visibility).unwrap_or_else(|| self.clone())
    }

    /// A point of the mesh uniform by area, from `p`: triangle by `u` (by area, then `u`
    /// rescaled within it), point in it by the square-root warp (PBR 4th ed. A.5.4).
    pub(super) fn sample(&self, p: Vec3, (u, v): (f32, f32)) -> Option<LightSample> {
        let total = self.area();
        let x = u * total;
        let i = self.cumulative.partition_point(|&c| c <= x).min(self.cumulative.len() - 1);
        let start = if i == 0 { 0.0 } else { self.cumulative[i - 1] };
        let u = ((x - start) / (self.cumulative[i] - start)).clamp(0.0, 1.0);
        let su = u.sqrt();
        let (a, e1, e2) = (self.a[i], self.b[i] - self.a[i], self.c[i] - self.a[i]);
        let q = a + e1 * (su * (1.0 - v)) + e2 * (su * v);
        let (dir, dist) = super::towards(p, q)?;
        let n = e1.cross(e2).normalize();
        let cos_light = -dir.dot(n);
        if cos_light <= 0.0 {
            return None;
        }
        // Uniform on the area: pdf_solid_angle = dist^2 / (total * cos_light).
        Some(LightSample { dir, dist, value: self.radiance * (total * cos_light / (dist * dist)) })
    }

    /// The nearest front face a ray from `origin` along `dir` meets before `tmax`: its
    /// distance and the cosine between the ray and the face's normal (positive).
    fn hit(&self, origin: Vec3, dir: Vec3, tmax: f32) -> Option<(f32, f32)> {
        let mut best = None;
        let mut limit = tmax;
        self.bvh.traverse::<false>(&RayBoxTest::new(origin, dir, 0.0), &mut limit, |ids, _, limit| {
            for &id in ids {
                let i = id as usize;
                let [a, b, c] = [self.a[i], self.b[i], self.c[i]];
                // Back faces are skipped by the sign alone; the cosine (a normalisation)
                // is only needed for the face hit.
                let n = (b - a).cross(c - a);
                if dir.dot(n) >= 0.0 {
                    continue;
                }
                if let Some(h) = intersect_triangle(origin, dir, 0.0, *limit, [a, b, c]) {
                    *limit = h.t;
                    best = Some((h.t, -dir.dot(n.normalize())));
                }
            }
            false
        });
        best
    }

    /// Radiance a ray sees on the mesh before `tmax`, with its distance.
    pub(super) fn emitted(&self, origin: Vec3, dir: Vec3, tmax: f32) -> Option<(f32, Color)> {
        self.hit(origin, dir, tmax).map(|(t, _)| (t, self.radiance))
    }

    /// Solid-angle density of [`MeshLight::sample`] picking `dir` from `p`, by the nearest
    /// front face along it (the face [`MeshLight::emitted`] sees).
    pub(super) fn pdf(&self, p: Vec3, dir: Vec3) -> f32 {
        match self.hit(p, dir, f32::INFINITY) {
            Some((t, cos)) => t * t / (self.area() * cos),
            None => 0.0,
        }
    }
}
