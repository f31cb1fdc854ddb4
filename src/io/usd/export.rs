//! `tress export` to USD text: strand sets as linear `BasisCurves`, meshes as triangle
//! `Mesh`es, with their visibility as Arnold's primvars, which [`super::read_usd`] reads
//! back unchanged.

use super::values::Res;
use crate::accel::Shape;
use crate::error::LoadError;
use crate::scene::Visibility;
use crate::shading::Material;
use glam::Vec3;
use openusd::schemas::geom::{BasisCurves, Curves, Gprim, Mesh, PointBased};
use openusd::usd::{SchemaBase, Stage};
use openusd::{gf, sdf};
use std::path::Path;

/// Writes shapes (in world space) to a `.usda` file: strand sets as linear `BasisCurves`
/// with vertex widths (diameters) and colours, meshes as triangle `Mesh`es with their
/// normals, UVs and, for diffuse materials, `displayColor`. `visibility[i]` is shape
/// `i`'s (seen by every ray where missing): what differs from the default is written as
/// Arnold's primvars (`primvars:arnold:visibility:camera = 0`,
/// `primvars:arnold:visibility:shadow = 0`, `primvars:arnold:matte = 1`), which Arnold and
/// tress read. Strands with fewer than two points are left out (a linear curve needs two).
/// Written atomically, like [`crate::io::cem_hair::write_hair`].
pub fn write_usd(
    path: &Path,
    shapes: &[(Shape, u32)],
    materials: &[Material],
    visibility: &[Visibility],
) -> Result<(), LoadError> {
    let text = usda_text(shapes, materials, visibility)
        .map_err(|e| LoadError::invalid(path, format!("cannot write USD: {e:#}")))?;
    crate::io::write_atomically(path, text.as_bytes())
}

/// The `.usda` text [`write_usd`] writes.
pub fn usda_text(shapes: &[(Shape, u32)], materials: &[Material], visibility: &[Visibility]) -> Res<String> {
    let stage = Stage::builder().in_memory("tress.usda")?;
    stage.define_prim(sdf::path("/World")?)?.set_type_name("Xform")?;
    stage.set_default_prim("World")?;
    let v3 = |p: Vec3| gf::Vec3f { x: p.x, y: p.y, z: p.z };
    let vertex = || sdf::Value::Token("vertex".into());
    let (mut curves, mut meshes) = (0, 0);
    for (i, (shape, material)) in shapes.iter().enumerate() {
        let seen = visibility.get(i).copied().unwrap_or_default();
        let prim = match shape {
            Shape::Strands(s) => {
                let keep: Vec<usize> =
                    (0..s.strand_count()).filter(|&i| s.offsets[i + 1] >= s.offsets[i] + 2).collect();
                if keep.is_empty() {
                    continue;
                }
                curves += 1;
                let c = BasisCurves::define(&stage, sdf::path(format!("/World/Hair{curves}"))?)?;
                c.create_type_attr()?.set(sdf::Value::Token("linear".into()))?;
                let range = |i: usize| s.offsets[i] as usize..s.offsets[i + 1] as usize;
                let counts = keep.iter().map(|&i| (s.offsets[i + 1] - s.offsets[i]) as i32).collect();
                c.create_curve_vertex_counts_attr()?.set(sdf::Value::IntVec(counts))?;
                let pts =
                    keep.iter().flat_map(|&i| range(i)).map(|k| v3(Vec3::from_slice(&s.points[k][..3]))).collect();
                c.create_points_attr()?.set(sdf::Value::Vec3fVec(pts))?;
                let widths = keep.iter().flat_map(|&i| range(i)).map(|k| 2.0 * s.points[k][3]).collect();
                c.create_widths_attr()?.set(sdf::Value::FloatVec(widths))?.set_metadata("interpolation", vertex())?;
                if let Some(col) = &s.colors {
                    let col = keep.iter().flat_map(|&i| range(i)).map(|k| v3(Vec3::from(col[k]))).collect();
                    c.create_display_color_attr()?
                        .set(sdf::Value::Vec3fVec(col))?
                        .set_metadata("interpolation", vertex())?;
                } else if let Some(Material::Tube(t)) = materials.get(*material as usize) {
                    c.create_display_color_attr()?.set(sdf::Value::Vec3fVec(vec![v3(t.diffuse)]))?;
                }
                c.prim().clone()
            }
            Shape::Mesh(mesh) => {
                meshes += 1;
                let m = Mesh::define(&stage, sdf::path(format!("/World/Mesh{meshes}"))?)?;
                m.create_points_attr()?.set(sdf::Value::Vec3fVec(mesh.positions.iter().map(|p| v3(*p)).collect()))?;
                m.create_face_vertex_counts_attr()?.set(sdf::Value::IntVec(vec![3; mesh.indices.len()]))?;
                let idx = mesh.indices.iter().flatten().map(|&i| i as i32).collect();
                m.create_face_vertex_indices_attr()?.set(sdf::Value::IntVec(idx))?;
                m.create_subdivision_scheme_attr()?.set(sdf::Value::Token("none".into()))?;
                if let Some(n) = &mesh.normals {
                    m.create_normals_attr()?
                        .set(sdf::Value::Vec3fVec(n.iter().map(|p| v3(*p)).collect()))?
                        .set_metadata("interpolation", vertex())?;
                }
                if let Some(uv) = &mesh.uvs {
                    let st = uv.iter().map(|u| gf::Vec2f { x: u[0], y: u[1] }).collect();
                    m.prim()
                        .create_attribute("primvars:st", "texCoord2f[]")?
                        .set(sdf::Value::Vec2fVec(st))?
                        .set_metadata("interpolation", vertex())?;
                }
                if let Some(Material::Diffuse { color }) = materials.get(*material as usize) {
                    m.create_display_color_attr()?.set(sdf::Value::Vec3fVec(vec![v3(*color)]))?;
                }
                m.prim().clone()
            }
        };
        write_visibility(&prim, seen)?;
    }
    let text = stage.root_layer().export_to_string()?;
    Ok(text)
}

/// `seen`'s switches that differ from the default as Arnold's constant primvars on `prim`
/// (see [`super::visibility`]).
fn write_visibility(prim: &openusd::usd::Prim, seen: Visibility) -> Res<()> {
    let default = Visibility::default();
    let switches = [
        ("primvars:arnold:visibility:camera", seen.camera, default.camera),
        ("primvars:arnold:visibility:shadow", seen.shadows, default.shadows),
        ("primvars:arnold:matte", seen.matte, default.matte),
    ];
    for (name, value, fallback) in switches {
        if value != fallback {
            prim.create_attribute(name, "bool")?
                .set(sdf::Value::Bool(value))?
                .set_metadata("interpolation", sdf::Value::Token("constant".into()))?;
        }
    }
    Ok(())
}
