//! `Mesh` prims and the gprims (`Sphere`, `Cube`, `Cylinder`, `Cone`, `Capsule`) to
//! triangle meshes, with their colour: the `diffuseColor` of a bound `UsdPreviewSurface`,
//! else `primvars:displayColor`; and the material of Arnold's `standard_hair` bound to
//! curves.

use super::skel::Skinning;
use super::values::{
    boolean, floats, interpolation, ints, number, short, token, value, vec3, vec3s, Interpolation, Res,
};
use super::visibility::{inherited, integer};
use super::Notes;
use crate::geometry::subdivision::{arnold_iterations, PolygonMesh, MAX_ITERATIONS};
use crate::geometry::TriangleMesh;
use crate::io::arnold_hair::{ArnoldShader, Param, StandardHair};
use crate::io::arnold_surface::{textured, Flat, Lambert, StandardSurface};
use crate::math::Color;
use crate::shading::texture::{Checker, ColorMap};
use crate::shading::Material;
use glam::{Mat3, Vec3};
use openusd::sdf;
use openusd::usd::{Prim, TimeCode};
use std::f32::consts::TAU;

/// The gprim types [`read_gprim`] reads.
pub const GPRIMS: [&str; 5] = ["Sphere", "Cube", "Cylinder", "Cone", "Capsule"];

/// Facets around a gprim's axis.
const AROUND: usize = 32;

/// A `Mesh` prim: `points`, `faceVertexCounts`, `faceVertexIndices` (polygons as fans;
/// faces of fewer than three vertices draw nothing), vertex `normals` and `primvars:st`
/// (vertex or face-varying, indexed or not). With `skin`, points and vertex normals are
/// skinned first. Subdivided as Arnold subdivides it (`primvars:arnold:subdiv_iterations`, ...).
pub fn read_mesh(prim: &Prim, time: TimeCode, skin: Option<&Skinning>, notes: &mut Notes) -> Res<TriangleMesh> {
    let mut positions = vec3s(value(prim, "points", time)?, "points")?.unwrap_or_default();
    if let Some(skin) = skin {
        skin.points(&mut positions)?;
    }
    let counts = ints(value(prim, "faceVertexCounts", time)?, "faceVertexCounts")?.unwrap_or_default();
    let indices = ints(value(prim, "faceVertexIndices", time)?, "faceVertexIndices")?.unwrap_or_default();
    let total: i64 = counts.iter().map(|&c| c.max(0)).sum();
    anyhow::ensure!(counts.iter().all(|&c| c >= 0), "`faceVertexCounts` has a negative count");
    anyhow::ensure!(
        total as usize == indices.len(),
        "`faceVertexCounts` sum to {total} but there are {} indices",
        indices.len()
    );
    let n = positions.len();
    anyhow::ensure!(indices.iter().all(|&i| i >= 0 && (i as usize) < n), "a face index is not one of the {n} points");
    let normals_attr = prim.attribute("normals");
    let mut normals = vec3s(normals_attr.get_at(time)?, "normals")?.filter(|v| {
        v.len() == n && interpolation(&normals_attr, Interpolation::Vertex).ok() == Some(Interpolation::Vertex)
    });
    if let (Some(skin), Some(normals)) = (skin, &mut normals) {
        skin.normals(normals)?;
    }
    // UVs: vertex (one per point) or face-varying (one per face corner), optionally indexed.
    let (uv_name, st) = uv_primvar(prim, time)?;
    let st_attr = prim.attribute(uv_name);
    anyhow::ensure!(normals.iter().flatten().all(|n| n.is_finite()), "`normals` must be finite");
    // An empty index array indexes nothing: the values are read in order.
    let st_indices =
        ints(value(prim, &format!("{uv_name}:indices"), time)?, "primvars:st:indices")?.filter(|ix| !ix.is_empty());
    interpolation(&st_attr, Interpolation::Vertex)?;
    let face_varying = matches!(st_attr.get_metadata::<sdf::Value>("interpolation")?, Some(sdf::Value::Token(t)) if t.as_str() == "faceVarying");
    // The UV of corner `k` (running over all faces) of point `p`.
    let uv_of = |k: usize, p: usize| -> Res<[f32; 2]> {
        let Some(st) = &st else { return Ok([0.0; 2]) };
        let slot = if face_varying { k } else { p };
        let slot = match &st_indices {
            Some(ix) => *ix.get(slot).ok_or_else(|| anyhow::anyhow!("`primvars:st:indices` is too short"))? as usize,
            None => slot,
        };
        Ok(*st.get(slot).ok_or_else(|| anyhow::anyhow!("`primvars:st` has no value {slot}"))?)
    };
    let mut polygons = PolygonMesh { positions, ..Default::default() };
    let mut uvs = Vec::new();
    let mut k = 0usize;
    for &c in &counts {
        if c >= 3 {
            polygons.counts.push(c as u32);
            for (j, &p) in indices.iter().enumerate().skip(k).take(c as usize) {
                polygons.indices.push(p as u32);
                if st.is_some() {
                    uvs.push(uv_of(j, p as usize)?);
                }
            }
        }
        k += c as usize;
    }
    if st.is_some() {
        polygons.uvs = Some(uvs);
    }
    let mesh = match subdivision(prim, time, notes)? {
        Some(iterations) => {
            (polygons.creases, polygons.corners) = creases(prim, time, n)?;
            let (refined, done) = notes.1.subdivide(&polygons, iterations);
            if let Some(stopped) = done.stopped() {
                notes.note(stopped, prim);
            }
            refined.triangulate(true).0
        }
        None => {
            let (mut mesh, original) = polygons.triangulate(false);
            if let Some(ns) = &normals {
                mesh.normals = Some(original.iter().map(|&o| ns[o as usize]).collect());
            }
            mesh
        }
    };
    mesh.validate().map_err(|e| anyhow::anyhow!("{e}"))?;
    Ok(mesh)
}

/// The Catmull-Clark iterations Arnold applies to a `Mesh` prim, as Arnold-USD's reader
/// decides them (`ReadMesh` in its `read_geometry.cpp`): `primvars:arnold:subdiv_iterations`
/// (on the prim or inherited as a constant primvar; 0, no subdivision, when not authored),
/// of the type `primvars:arnold:subdiv_type` (`catclark` or 1, `linear` or 2, `none` or 0)
/// or else the prim's `subdivisionScheme` (`catmullClark`, the fallback; `bilinear`;
/// `none`). `None`: drawn as authored. Linear subdivision keeps flat faces as they are and
/// is drawn as authored. A mesh whose scheme asks for subdivision that Arnold does not
/// apply is counted in a note: other renderers draw it smooth.
fn subdivision(prim: &Prim, time: TimeCode, notes: &mut Notes) -> Res<Option<u32>> {
    let scheme = token(value(prim, "subdivisionScheme", time)?, "catmullClark");
    let iterations = match inherited(prim, "primvars:arnold:subdiv_iterations", time)? {
        None => 0,
        Some(v) => match integer(&v).map(|i| (i, arnold_iterations(i))) {
            Some((_, Some(iterations))) => iterations,
            other => {
                let shown = other.map_or_else(|| short(&v), |(i, _)| i.to_string());
                notes.note_why(
                    format!("`primvars:arnold:subdiv_iterations` that are not 0 to {MAX_ITERATIONS}: not subdivided"),
                    prim,
                    &shown,
                );
                return Ok(None);
            }
        },
    };
    if iterations == 0 {
        if scheme != "none" {
            notes.note(
                "subdivision surfaces without `primvars:arnold:subdiv_iterations`: drawn as their control cage, as Arnold draws them"
                    .into(),
                prim,
            );
        }
        return Ok(None);
    }
    let kind = match inherited(prim, "primvars:arnold:subdiv_type", time)? {
        Some(sdf::Value::String(s)) => s,
        Some(sdf::Value::Token(t)) => t.as_str().to_string(),
        Some(v) => match integer(&v) {
            Some(0) => "none".into(),
            Some(1) => "catclark".into(),
            Some(2) => "linear".into(),
            _ => short(&v),
        },
        None => match scheme.as_str() {
            "catmullClark" => "catclark".into(),
            "bilinear" => "linear".into(),
            other => other.into(),
        },
    };
    match kind.as_str() {
        "catclark" => Ok(Some(iterations)),
        "none" | "linear" => Ok(None),
        other => {
            notes.note(format!("subdivision `{other}`: not applied, drawn as the control cage"), prim);
            Ok(None)
        }
    }
}

/// The creases and corners of a mesh of `points` points: `creaseIndices` in runs of
/// `creaseLengths` vertices, `creaseSharpnesses` one per run or one per edge of the runs,
/// `cornerIndices` with one `cornerSharpnesses` each (`UsdGeomMesh`).
#[allow(clippy::type_complexity)]
fn creases(prim: &Prim, time: TimeCode, points: usize) -> Res<(Vec<([u32; 2], f32)>, Vec<(u32, f32)>)> {
    let list = |name: &str| -> Res<Vec<i64>> { Ok(ints(value(prim, name, time)?, name)?.unwrap_or_default()) };
    let sharpness = |name: &str| -> Res<Vec<f32>> {
        let s = floats(value(prim, name, time)?, name)?.unwrap_or_default();
        anyhow::ensure!(s.iter().all(|x| x.is_finite()), "`{name}` must be finite");
        Ok(s)
    };
    let vertex = |i: i64, name: &str| -> Res<u32> {
        anyhow::ensure!(i >= 0 && (i as usize) < points, "`{name}` uses point {i} of {points}");
        Ok(i as u32)
    };
    let (indices, lengths, sharp) = (list("creaseIndices")?, list("creaseLengths")?, sharpness("creaseSharpnesses")?);
    anyhow::ensure!(lengths.iter().all(|&l| l >= 0), "`creaseLengths` has a negative length");
    let total: i64 = lengths.iter().sum();
    anyhow::ensure!(
        total as usize == indices.len(),
        "`creaseLengths` sum to {total} but there are {} `creaseIndices`",
        indices.len()
    );
    let edges: i64 = lengths.iter().map(|&l| (l - 1).max(0)).sum();
    let per_edge = sharp.len() as i64 == edges && sharp.len() != lengths.len();
    anyhow::ensure!(
        sharp.len() == lengths.len() || per_edge,
        "{} `creaseSharpnesses` for {} creases of {edges} edges",
        sharp.len(),
        lengths.len()
    );
    let mut creases = Vec::new();
    let (mut at, mut edge) = (0usize, 0usize);
    for (c, &l) in lengths.iter().enumerate() {
        for j in at..(at + l as usize).saturating_sub(1) {
            let e = [vertex(indices[j], "creaseIndices")?, vertex(indices[j + 1], "creaseIndices")?];
            creases.push((e, if per_edge { sharp[edge] } else { sharp[c] }));
            edge += 1;
        }
        at += l as usize;
    }
    let (corner_indices, corner_sharp) = (list("cornerIndices")?, sharpness("cornerSharpnesses")?);
    anyhow::ensure!(
        corner_indices.len() == corner_sharp.len(),
        "{} `cornerSharpnesses` for {} `cornerIndices`",
        corner_sharp.len(),
        corner_indices.len()
    );
    let corners = corner_indices
        .iter()
        .zip(corner_sharp)
        .map(|(&i, s)| Ok((vertex(i, "cornerIndices")?, s)))
        .collect::<Res<_>>()?;
    Ok((creases, corners))
}

/// A gprim of `kind` as a triangle mesh with the schema's attributes and fallbacks
/// (`Sphere` radius 1; `Cube` size 2; `Cylinder` and `Cone` radius 1, height 2, axis Z;
/// `Capsule` radius 0.5, height 1 between its hemispheres' centres, axis Z).
pub fn read_gprim(prim: &Prim, kind: &str, time: TimeCode) -> Res<TriangleMesh> {
    let num = |name: &str, d: f64| -> Res<f32> {
        let x = number(value(prim, name, time)?, name)?.unwrap_or(d) as f32;
        anyhow::ensure!((0.0..1e30).contains(&x), "`{name}` must be finite and not negative");
        Ok(x)
    };
    let axis = token(value(prim, "axis", time)?, "Z");
    let mut mesh = match kind {
        "Sphere" => TriangleMesh::sphere(num("radius", 1.0)?, AROUND as u32 / 2),
        "Cube" => cube(num("size", 2.0)?),
        "Cylinder" => {
            let (r, h) = (num("radius", 1.0)?, 0.5 * num("height", 2.0)?);
            revolve(&[(0.0, -h), (r, -h), (r, h), (0.0, h)])
        }
        "Cone" => {
            let (r, h) = (num("radius", 1.0)?, 0.5 * num("height", 2.0)?);
            revolve(&[(0.0, -h), (r, -h), (0.0, h)])
        }
        _ => {
            let (r, h) = (num("radius", 0.5)?, 0.5 * num("height", 1.0)?);
            let quarter = AROUND / 4;
            let mut profile = Vec::new();
            for i in 0..=quarter {
                let a = (i as f32 / quarter as f32) * TAU / 4.0;
                profile.push((r * a.sin(), -h - r * a.cos()));
            }
            for i in 0..=quarter {
                let a = (i as f32 / quarter as f32) * TAU / 4.0;
                profile.push((r * a.cos(), h + r * a.sin()));
            }
            revolve(&profile)
        }
    };
    // The profiles stand along Y; the schema's axis turns them.
    let turn = match axis.as_str() {
        "X" => Mat3::from_rotation_z(-TAU / 4.0),
        "Y" => Mat3::IDENTITY,
        _ => Mat3::from_rotation_x(TAU / 4.0),
    };
    if kind != "Sphere" && kind != "Cube" {
        mesh.transform(&glam::Affine3A::from_mat3(turn));
    }
    mesh.remove_unusable_triangles();
    Ok(mesh)
}

/// A cube of edge `size` centred on the origin, two triangles a face.
fn cube(size: f32) -> TriangleMesh {
    let h = 0.5 * size;
    let mut mesh = TriangleMesh::default();
    for axis in 0..3 {
        for sign in [-1.0f32, 1.0] {
            let n = Vec3::from_array(std::array::from_fn(|k| if k == axis { sign } else { 0.0 }));
            let u = Vec3::from_array(std::array::from_fn(|k| if k == (axis + 1) % 3 { 1.0 } else { 0.0 }));
            let v = n.cross(u);
            let base = mesh.positions.len() as u32;
            for (a, b) in [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
                mesh.positions.push((n + u * a + v * b) * h);
            }
            mesh.indices.push([base, base + 1, base + 2]);
            mesh.indices.push([base, base + 2, base + 3]);
        }
    }
    mesh
}

/// The surface swept by a profile of `(radius, height)` points turned about the Y axis,
/// its faces facing outwards.
fn revolve(profile: &[(f32, f32)]) -> TriangleMesh {
    let mut mesh = TriangleMesh::default();
    for &(r, y) in profile {
        for j in 0..AROUND {
            let a = j as f32 / AROUND as f32 * TAU;
            mesh.positions.push(Vec3::new(r * a.cos(), y, -r * a.sin()));
        }
    }
    let at = |i: usize, j: usize| (i * AROUND + j % AROUND) as u32;
    for i in 0..profile.len().saturating_sub(1) {
        for j in 0..AROUND {
            mesh.indices.push([at(i, j), at(i, j + 1), at(i + 1, j + 1)]);
            mesh.indices.push([at(i, j), at(i + 1, j + 1), at(i + 1, j)]);
        }
    }
    mesh
}

/// A prim's texture coordinates as Arnold-USD reads them: `primvars:st`, else
/// `primvars:uv` (what Arnold's own USD writer names them); the primvar's name and its
/// values (the first two coordinates of 3-vectors), unindexed, when authored.
pub fn uv_primvar(prim: &Prim, time: TimeCode) -> Res<(&'static str, Option<Vec<[f32; 2]>>)> {
    let name = match value(prim, "primvars:st", time)?.is_some() || value(prim, "primvars:uv", time)?.is_none() {
        true => "primvars:st",
        false => "primvars:uv",
    };
    let st: Option<Vec<[f32; 2]>> = match value(prim, name, time)? {
        None => None,
        Some(sdf::Value::Vec2fVec(v)) => Some(v.iter().map(|p| [p.x, p.y]).collect()),
        Some(sdf::Value::Vec2dVec(v)) => Some(v.iter().map(|p| [p.x as f32, p.y as f32]).collect()),
        // Houdini and Arnold write UVs as 3-vectors too (`float3[] primvars:uv`): the
        // third coordinate is unused.
        Some(sdf::Value::Vec3fVec(v)) => Some(v.iter().map(|p| [p.x, p.y]).collect()),
        Some(sdf::Value::Vec3dVec(v)) => Some(v.iter().map(|p| [p.x as f32, p.y as f32]).collect()),
        Some(other) => anyhow::bail!("`{name}` is not an array of 2- or 3-vectors: {}", short(&other)),
    };
    // Finite in the file (1e39 as a double) is not always finite in single precision.
    anyhow::ensure!(st.iter().flatten().flatten().all(|x| x.is_finite()), "`{name}` must be finite");
    Ok((name, st))
}

/// The colour a prim is drawn in: the `diffuseColor` of the `UsdPreviewSurface` its bound
/// material's surface output leads to (`material:binding`), else its constant
/// `primvars:displayColor` (the mean of a varying one); `None` without either.
pub fn surface_color(prim: &Prim, time: TimeCode, notes: &mut Notes) -> Res<Option<Vec3>> {
    if let Some(c) = bound_diffuse(prim, time, notes)? {
        return Ok(Some(c));
    }
    let Some(c) = vec3s(value(prim, "primvars:displayColor", time)?, "primvars:displayColor")? else {
        return Ok(None);
    };
    if c.is_empty() || c.iter().any(|c| !c.is_finite() || c.min_element() < 0.0) {
        return Ok(None);
    }
    if c.len() > 1 {
        notes.note("varying `displayColor` on surfaces: drawn in its mean colour".into(), prim);
    }
    Ok(Some(c.iter().sum::<Vec3>() / c.len() as f32))
}

/// The material of Arnold's hair shader (Arnold-USD's `arnold:standard_hair`) bound to
/// `prim`, followed from its material's `outputs:arnold:surface` (what Arnold renders)
/// or else `outputs:surface`; `None` when neither leads to one. Inputs are read by
/// Arnold's parameter names (`inputs:melanin`), Arnold's defaults for those not written;
/// what tress's model cannot hold is said in one note per shader.
pub fn bound_standard_hair(prim: &Prim, time: TimeCode, notes: &mut Notes) -> Res<Option<Material>> {
    bound_arnold::<StandardHair>(prim, "arnold:standard_hair", time, notes)
}

/// The material of Arnold's surface shader bound to `prim` (`arnold:standard_surface`,
/// `arnold:lambert` or `arnold:flat`), as [`bound_standard_hair`] finds and reads it
/// ([`crate::io::arnold_surface`]).
pub fn bound_arnold_surface(prim: &Prim, time: TimeCode, notes: &mut Notes) -> Res<Option<Material>> {
    const IDS: [&str; 4] = ["arnold:standard_surface", "arnold:lambert", "arnold:flat", "arnold:checkerboard"];
    Ok(match bound_arnold_shader(prim, &IDS, time)? {
        Some((shader, 0)) => Some(arnold_material::<StandardSurface>(&shader, time, notes)?),
        Some((shader, 1)) => Some(arnold_material::<Lambert>(&shader, time, notes)?),
        Some((shader, 2)) => Some(arnold_material::<Flat>(&shader, time, notes)?),
        // A texture as the surface shader: Arnold draws its colour unlit, as `flat` would.
        Some((shader, _)) => {
            Some(Material::UnlitTextured { color: ColorMap::Checker(checker(&shader, time, notes)?), tint: Vec3::ONE })
        }
        None => None,
    })
}

/// The material of the Arnold shader of type `id` bound to `prim`, by `S`'s parameters.
fn bound_arnold<S: ArnoldShader>(prim: &Prim, id: &str, time: TimeCode, notes: &mut Notes) -> Res<Option<Material>> {
    match bound_arnold_shader(prim, &[id], time)? {
        Some((shader, _)) => Ok(Some(arnold_material::<S>(&shader, time, notes)?)),
        None => Ok(None),
    }
}

/// The shader `prim`'s material leads to from `outputs:arnold:surface` (what Arnold
/// renders), else `outputs:surface`, when its type is one of `ids`: the shader and the
/// index of its type.
fn bound_arnold_shader(prim: &Prim, ids: &[&str], time: TimeCode) -> Res<Option<(Prim, usize)>> {
    let Some(material) = bound_material(prim)? else { return Ok(None) };
    for output in ["outputs:arnold:surface", "outputs:surface"] {
        let Some(shader) = connected_shader(&material, output)? else { continue };
        let id = token(value(&shader, "info:id", time)?, "");
        if let Some(k) = ids.iter().position(|i| *i == id) {
            return Ok(Some((shader, k)));
        }
    }
    Ok(None)
}

/// The material standing in for the Arnold shader `shader`, its inputs read by `S`'s
/// parameter names; what it leaves out is said in one note.
fn arnold_material<S: ArnoldShader>(shader: &Prim, time: TimeCode, notes: &mut Notes) -> Res<Material> {
    let mut params = S::default();
    let mut connected = Vec::new();
    for &name in S::NAMES {
        let input = format!("inputs:{name}");
        if shader.attribute(&input).has_authored_connections()? {
            connected.push(name.to_string());
        }
        let v = value(shader, &input, time)?;
        let what = format!("{}.{input}", shader.path());
        match params.param(name) {
            Some(Param::Float(f)) => *f = number(v, &what)?.map_or(*f, |x| x as f32),
            Some(Param::Color(c)) => *c = vec3(v, &what)?.unwrap_or(*c),
            Some(Param::Bool(b)) => *b = boolean(v, *b),
            None => {}
        }
        anyhow::ensure!(!params.param(name).is_some_and(|p| p.is_infinite()), "`{what}` is beyond single precision");
    }
    // The first mapped parameter driven by a checkerboard is drawn with it: the material
    // is made with that parameter at 1 and the map applied; where the map cannot colour the
    // material, the parameter takes the map's mean instead.
    let mut map = None;
    for &(name, slot) in S::MAPS {
        let Some(at) = connected.iter().position(|c| c == name) else { continue };
        let Some((checker, channel)) = connected_checker(shader, name, time, notes)? else { continue };
        connected.remove(at);
        map = Some((name, slot, checker, channel));
        break;
    }
    let path = shader.path().to_string();
    let material = |params: &S, connected: &[String]| params.material(&path, connected);
    let (material, left_out) = match map {
        None => material(&params, &connected),
        Some((name, slot, checker, channel)) => {
            set_param(&mut params, name, Color::ONE);
            let (neutral, left_out) = material(&params, &connected);
            match textured(&neutral, slot, ColorMap::Checker(checker.clone())) {
                Some(m) => (m, left_out),
                None => {
                    notes.note(format!("checkerboards on `{name}` of a material they cannot colour (metal, glass, an emission on a lit surface): drawn in their mean colour"), shader);
                    let mean = checker.average();
                    set_param(
                        &mut params,
                        name,
                        match channel {
                            Some(k) => Color::splat(mean[k]),
                            None => mean,
                        },
                    );
                    material(&params, &connected)
                }
            }
        }
    };
    if let Some(left_out) = left_out {
        // Counted by what is left out, the first shader named: copies of one material
        // (per instance, per asset) give one warning, not one each.
        let what = left_out.strip_prefix(&format!("{path}: ")).unwrap_or(&left_out);
        notes.note(what.to_string(), shader);
    }
    Ok(material)
}

/// Sets parameter `name` of `params` to `c` (a number to its red channel).
fn set_param<S: ArnoldShader>(params: &mut S, name: &str, c: Color) {
    match params.param(name) {
        Some(Param::Float(f)) => *f = c.x,
        Some(Param::Color(v)) => *v = c,
        _ => {}
    }
}

/// The checkerboard input `name` of `shader` is connected to, when its source is an
/// `arnold:checkerboard` shader, with the channel its output reads (`outputs:r`, `g`,
/// `b`: that channel, as a grey checkerboard; any other output: the colour). A number
/// parameter connected to the whole colour reads its red channel, as Arnold does.
fn connected_checker(
    shader: &Prim,
    name: &str,
    time: TimeCode,
    notes: &mut Notes,
) -> Res<Option<(Checker, Option<usize>)>> {
    let Some(target) = shader.attribute(format!("inputs:{name}")).connections()?.into_iter().next() else {
        return Ok(None);
    };
    let source = shader.stage().prim(target.prim_path());
    if token(value(&source, "info:id", time)?, "") != "arnold:checkerboard" {
        return Ok(None);
    }
    let mut c = checker(&source, time, notes)?;
    let output = target.to_string();
    let channel = ["r", "g", "b"].iter().position(|k| output.ends_with(&format!("outputs:{k}")));
    if let Some(k) = channel {
        (c.color1, c.color2) = (Color::splat(c.color1[k]), Color::splat(c.color2[k]));
    }
    Ok(Some((c, channel)))
}

/// An `arnold:checkerboard` shader's inputs, Arnold's defaults for those not written.
/// Its antialiasing controls are not read (tress filters it over the ray's footprint),
/// nor other UV sets than the mesh's own, nor shading networks on its inputs: each said
/// in one note.
fn checker(shader: &Prim, time: TimeCode, notes: &mut Notes) -> Res<Checker> {
    let mut c = Checker::default();
    for (name, slot) in [("color1", &mut c.color1), ("color2", &mut c.color2)] {
        let what = format!("{}.inputs:{name}", shader.path());
        *slot = vec3(value(shader, &format!("inputs:{name}"), time)?, &what)?.unwrap_or(*slot);
        anyhow::ensure!(slot.is_finite(), "`{what}` must be finite");
    }
    for (name, slot) in c.numbers_mut() {
        let what = format!("{}.inputs:{name}", shader.path());
        *slot = number(value(shader, &format!("inputs:{name}"), time)?, &what)?.map_or(*slot, |x| x as f32);
        anyhow::ensure!(slot.is_finite(), "`{what}` must be finite");
    }
    let f = |name: &str, default: f64| -> Res<bool> {
        Ok(number(value(shader, &format!("inputs:{name}"), time)?, name)?.is_some_and(|x| x != default))
    };
    if f("filter_strength", 1.0)? || f("filter_offset", 0.0)? {
        notes.note(
            "checkerboard `filter_strength` / `filter_offset`: filtered over the ray's footprint instead".into(),
            shader,
        );
    }
    if !token(value(shader, "inputs:uvset", time)?, "").is_empty() {
        notes.note("checkerboard `uvset`: the mesh's own UVs used".into(), shader);
    }
    for name in ["color1", "color2", "u_frequency", "v_frequency", "u_offset", "v_offset", "contrast"] {
        if shader.attribute(format!("inputs:{name}")).has_authored_connections()? {
            notes.note("shading networks on checkerboard inputs: their own values used".into(), shader);
        }
    }
    Ok(c)
}

/// The material `prim` is bound to (`material:binding`), if any.
fn bound_material(prim: &Prim) -> Res<Option<Prim>> {
    let target = prim.relationship("material:binding").targets()?.into_iter().next();
    Ok(target.map(|path| prim.stage().prim(path)))
}

/// The shader `material`'s `output` is connected to, if any.
pub(super) fn connected_shader(material: &Prim, output: &str) -> Res<Option<Prim>> {
    let target = material.attribute(output).connections()?.into_iter().next();
    Ok(target.map(|path| material.stage().prim(path.prim_path())))
}

/// The `diffuseColor` of the preview surface bound to `prim`, following the material's
/// `outputs:surface` connection to its shader.
fn bound_diffuse(prim: &Prim, time: TimeCode, notes: &mut Notes) -> Res<Option<Vec3>> {
    let Some(material) = bound_material(prim)? else { return Ok(None) };
    let shader = match connected_shader(&material, "outputs:surface")? {
        Some(shader) => shader,
        None => {
            notes.note("materials without a connected `outputs:surface`: not read".into(), prim);
            return Ok(None);
        }
    };
    let id = token(value(&shader, "info:id", time)?, "");
    if id != "UsdPreviewSurface" {
        let what = if id.is_empty() { "a shader without `info:id`".to_string() } else { format!("`{id}` shaders") };
        notes.note(format!("materials with {what}: not read"), prim);
        return Ok(None);
    }
    let diffuse = shader.attribute("inputs:diffuseColor");
    let authored = vec3(diffuse.get_at(time)?, "inputs:diffuseColor")?;
    if diffuse.has_authored_connections()? {
        notes.note("textured `diffuseColor` of preview surfaces: textures are not read".into(), prim);
        if authored.is_none() {
            return Ok(None);
        }
    }
    // The preview surface's own fallback is 0.18 grey.
    let c = authored.unwrap_or(Vec3::splat(0.18));
    anyhow::ensure!(
        c.is_finite() && c.min_element() >= 0.0,
        "{}: `diffuseColor` must be finite and not negative",
        shader.path()
    );
    Ok(Some(c))
}
