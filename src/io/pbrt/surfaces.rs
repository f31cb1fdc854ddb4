//! pbrt's parametric shapes other than spheres, as triangle meshes: `disk`, `cylinder`
//! (Pharr et al., 4th ed., §6.3 and §6.2: a partial disk or cylinder about the z axis,
//! swept over `phimax` degrees) and `bilinearmesh` (§6.6: patches of four corners
//! `p00 p10 p01 p11`, each the surface `lerp(v, lerp(u, p00, p10), lerp(u, p01, p11))`).
//! Backdrops and floors of hair scenes are made of these.

use super::{Params, Res};
use crate::geometry::TriangleMesh;
use glam::DVec3;

/// Steps along a swept angle of 360°, fewer for a partial sweep.
const FULL_TURN_STEPS: f64 = 64.0;
/// Steps along each side of a patch that is not flat.
const CURVED_PATCH_STEPS: u32 = 8;

/// A grid of `nu` × `nv` quads over `point(u, v)`, u and v in [0, 1], with normals from
/// `normal(u, v)` when given.
fn grid(
    nu: u32,
    nv: u32,
    point: impl Fn(f64, f64) -> DVec3,
    normal: Option<&dyn Fn(f64, f64) -> DVec3>,
) -> TriangleMesh {
    let mut mesh = TriangleMesh::default();
    let mut normals = Vec::new();
    for j in 0..=nv {
        for i in 0..=nu {
            let (u, v) = (f64::from(i) / f64::from(nu), f64::from(j) / f64::from(nv));
            mesh.positions.push(point(u, v).as_vec3());
            if let Some(n) = normal {
                normals.push(n(u, v).normalize_or(DVec3::Z).as_vec3());
            }
            mesh.uvs.get_or_insert_with(Vec::new).push([u as f32, v as f32]);
        }
    }
    let row = nu + 1;
    for j in 0..nv {
        for i in 0..nu {
            let (a, b, c, d) = (j * row + i, j * row + i + 1, (j + 1) * row + i + 1, (j + 1) * row + i);
            mesh.indices.push([a, b, c]);
            mesh.indices.push([a, c, d]);
        }
    }
    if normal.is_some() {
        mesh.normals = Some(normals);
    }
    mesh
}

/// The swept angle `phimax` in radians, in (0, 2π], and the steps along it.
fn sweep(p: &Params) -> Res<(f64, u32)> {
    let phimax = p.float("phimax", 360.0)?;
    if !(phimax > 0.0 && phimax.is_finite()) {
        return Err((p.line, format!("phimax {phimax} must be positive")));
    }
    let phimax = phimax.min(360.0);
    Ok((phimax.to_radians(), (FULL_TURN_STEPS * phimax / 360.0).ceil().max(1.0) as u32))
}

/// A `disk`: radius `radius` (1) down to `innerradius` (0), at height `height` (0).
pub(super) fn disk(p: &Params) -> Res<TriangleMesh> {
    let (r, ri, h) = (p.float("radius", 1.0)?, p.float("innerradius", 0.0)?, p.float("height", 0.0)?);
    if !(r.is_finite() && ri.is_finite() && h.is_finite() && r > 0.0 && (0.0..r).contains(&ri)) {
        return Err((p.line, format!("disk radius {r} and inner radius {ri} must be 0 <= inner < radius")));
    }
    let (phimax, steps) = sweep(p)?;
    let point = |u: f64, v: f64| {
        let (phi, rad) = (u * phimax, r + (ri - r) * v);
        DVec3::new(rad * phi.cos(), rad * phi.sin(), h)
    };
    Ok(grid(steps, 1, point, Some(&|_, _| DVec3::Z)))
}

/// A `cylinder`: radius `radius` (1) from `zmin` (-1) to `zmax` (1).
pub(super) fn cylinder(p: &Params) -> Res<TriangleMesh> {
    let (r, z0, z1) = (p.float("radius", 1.0)?, p.float("zmin", -1.0)?, p.float("zmax", 1.0)?);
    if !(r.is_finite() && z0.is_finite() && z1.is_finite() && r > 0.0 && z0 != z1) {
        return Err((p.line, format!("cylinder radius {r} must be positive and zmin {z0} differ from zmax {z1}")));
    }
    let (phimax, steps) = sweep(p)?;
    let point = |u: f64, v: f64| {
        let phi = u * phimax;
        DVec3::new(r * phi.cos(), r * phi.sin(), z0 + (z1 - z0) * v)
    };
    let normal = |u: f64, _: f64| {
        let phi = u * phimax;
        DVec3::new(phi.cos(), phi.sin(), 0.0)
    };
    Ok(grid(steps, 1, point, Some(&normal)))
}

/// A `bilinearmesh`: `P` and `indices` (four per patch; four points may omit them).
pub(super) fn bilinear_mesh(p: &Params) -> Res<TriangleMesh> {
    let points = p.point3s("P")?.ok_or((p.line, "bilinearmesh without \"point3 P\"".to_string()))?;
    let n = points.len();
    let indices: Vec<f64> = match p.floats("indices") {
        Some(i) => i.to_vec(),
        None if n == 4 => vec![0.0, 1.0, 2.0, 3.0],
        None => return Err((p.line, "bilinearmesh without \"integer indices\" (only 4 points may omit them)".into())),
    };
    if !indices.len().is_multiple_of(4) {
        return Err((p.line, format!("{} indices is not a multiple of 4", indices.len())));
    }
    let mut mesh = TriangleMesh::default();
    for c in indices.chunks(4) {
        let mut q = [DVec3::ZERO; 4];
        for k in 0..4 {
            if !(c[k] >= 0.0 && c[k].fract() == 0.0 && (c[k] as usize) < n) {
                return Err((p.line, format!("index {} is not one of the {n} points", c[k])));
            }
            q[k] = points[c[k] as usize];
        }
        let [p00, p10, p01, p11] = q;
        // Flat patches are two triangles; twisted ones a finer grid on the surface.
        let flat = (p11 - p00).dot((p10 - p00).cross(p01 - p00)).abs()
            <= 1e-9 * (p10 - p00).length() * (p01 - p00).length() * (p11 - p00).length();
        let steps = if flat { 1 } else { CURVED_PATCH_STEPS };
        let patch = grid(steps, steps, |u, v| p00.lerp(p10, u).lerp(p01.lerp(p11, u), v), None);
        let base = mesh.positions.len() as u32;
        mesh.positions.extend(patch.positions);
        mesh.indices.extend(patch.indices.iter().map(|t| t.map(|i| i + base)));
    }
    mesh.remove_unusable_triangles();
    if mesh.indices.is_empty() {
        return Err((p.line, "bilinearmesh: every patch is degenerate".into()));
    }
    Ok(mesh)
}

#[cfg(test)]
mod tests {
    use super::super::parse_pbrt;
    use crate::scene::MeshSource;
    use std::path::Path;

    /// The area of each mesh of a scene of one shape, in the shape's own space.
    fn areas(shape: &str) -> Vec<f32> {
        let s = parse_pbrt(&format!("WorldBegin\n{shape}\n"), Path::new("t.pbrt")).unwrap();
        assert!(s.warnings.iter().all(|w| !w.contains("not supported") && !w.contains("not used")), "{:?}", s.warnings);
        s.contents
            .meshes
            .iter()
            .map(|e| match &e.source {
                MeshSource::Inline(m) => (0..m.indices.len() as u32).map(|i| m.area(i)).sum(),
                MeshSource::File(_) => panic!("inline"),
            })
            .collect()
    }

    #[test]
    fn disks_cylinders_and_bilinear_patches_cover_their_areas() {
        use std::f32::consts::PI;
        // A half annulus: π (4 - 1) / 2, within the chords' shortfall.
        let a =
            areas("Shape \"disk\" \"float radius\" 2 \"float innerradius\" 1 \"float phimax\" 180 \"float height\" 3");
        assert!((a[0] - 1.5 * PI).abs() < 0.01 * 1.5 * PI, "{a:?}");
        // A quarter of a cylinder of radius 1 and height 20, as the pbrt-v4 bunny-fur backdrop.
        let a = areas("Shape \"cylinder\" \"float radius\" 1 \"float phimax\" 90 \"float zmin\" -10 \"float zmax\" 10");
        assert!((a[0] - 10.0 * PI).abs() < 0.01 * 10.0 * PI, "{a:?}");
        // A flat 20 × 10 patch without indices.
        let a = areas("Shape \"bilinearmesh\" \"point3 P\" [ -10 0 -2  10 0 -2  -10 10 -2  10 10 -2 ]");
        assert!((a[0] - 200.0).abs() < 1e-3, "{a:?}");
        // A twisted patch (a hyperbolic paraboloid z = xy over the unit square): larger
        // than its flat shadow, as the surface is (1.0 + 0.28 over the exact integral).
        let a =
            areas("Shape \"bilinearmesh\" \"point3 P\" [ 0 0 0  1 0 0  0 1 0  1 1 1 ] \"integer indices\" [ 0 1 2 3 ]");
        assert!(a[0] > 1.2 && a[0] < 1.35, "{a:?}");
    }

    #[test]
    fn bad_surfaces_are_errors_naming_the_line() {
        for shape in [
            "Shape \"disk\" \"float radius\" 1 \"float innerradius\" 2",
            "Shape \"cylinder\" \"float zmin\" 1 \"float zmax\" 1",
            "Shape \"cylinder\" \"float phimax\" -5",
            "Shape \"bilinearmesh\" \"point3 P\" [ 0 0 0  1 0 0  0 1 0 ]",
            "Shape \"bilinearmesh\" \"point3 P\" [ 0 0 0  1 0 0  0 1 0  1 1 0 ] \"integer indices\" [ 0 1 2 7 ]",
        ] {
            let e = parse_pbrt(&format!("WorldBegin\n{shape}\n"), Path::new("t.pbrt")).unwrap_err().to_string();
            assert!(e.contains("t.pbrt") && e.contains("line 2"), "{shape}: {e}");
        }
    }
}
