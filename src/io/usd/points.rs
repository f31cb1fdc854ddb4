//! UsdGeom `Points` prims to triangle meshes: a small sphere per point, `widths` its
//! diameter.
//!
//! tress has no sphere primitive. A strand segment is an open cylinder along its axis
//! ([`crate::geometry::StrandSet`]): one as short as it is wide looks like a square from the
//! side and like nothing end-on, so it cannot pass for a ball from every direction. An
//! icosphere can, and stays cheap: 80 triangles a point (the icosahedron subdivided once,
//! its silhouette within 6 % of the sphere's), or the bare icosahedron's 20 for prims of
//! many points, with vertex normals along the radius so it shades as a round ball.

use super::curves::FALLBACK_WIDTH;
use super::skel::Skinning;
use super::values::{floats, held_value, ints, value, vec3s, Res};
use super::Notes;
use crate::geometry::TriangleMesh;
use openusd::usd::{Prim, TimeCode};

/// The most triangles one `Points` prim may become: a prim whose points would need more
/// even as icosahedra (20 triangles each, so 250,000 points) is an error, not a mesh that
/// exhausts memory.
pub const MAX_TRIANGLES: usize = 5_000_000;

/// The points of a prim drawn with the finer spheres (80 triangles each) up to this many.
const FINE_POINTS: usize = 20_000;

/// A `Points` prim over [`MAX_TRIANGLES`].
#[derive(Debug)]
pub struct OverBudget(pub usize);

impl std::fmt::Display for OverBudget {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{} points, as spheres of 20 triangles, exceed the {MAX_TRIANGLES} triangles one Points prim may become",
            self.0
        )
    }
}

impl std::error::Error for OverBudget {}

/// A `Points` prim at `time` as one mesh of spheres: `points` (skinned first with `skin`),
/// `widths` their diameters (per point, or one for all; the schema's fallback of one unit
/// without them, said). When the prim's `ids` differ between the samples around `time`
/// (points born, dying or reordered), points and widths are held at the earlier sample
/// instead of blended, so no point is blended with another's position. `None` when there
/// is nothing to draw; an [`OverBudget`] error past [`MAX_TRIANGLES`].
pub fn read_points(
    prim: &Prim,
    time: TimeCode,
    skin: Option<&Skinning>,
    notes: &mut Notes,
) -> Res<Option<TriangleMesh>> {
    let ids = prim.attribute("ids");
    let reordered = match ids.bracketing_time_samples(time)? {
        Some((lo, hi)) if lo != hi => {
            let at = |t| -> Res<_> { ints(ids.get_at(TimeCode::new(t))?, "ids") };
            at(lo)? != at(hi)?
        }
        _ => false,
    };
    let get = |name: &str| -> Res<_> {
        let attr = prim.attribute(name);
        if reordered {
            held_value(&attr, time)
        } else {
            attr.get_at(time)
        }
    };
    let Some(mut points) = vec3s(get("points")?, "points")?.filter(|p| !p.is_empty()) else {
        return Ok(None);
    };
    if let Some(skin) = skin {
        skin.points(&mut points)?;
    }
    let n = points.len();
    let widths = match floats(get("widths")?, "widths")? {
        Some(w) if w.len() == n || w.len() == 1 => w,
        Some(w) => anyhow::bail!("{} `widths` for {n} points (one per point, or one for all)", w.len()),
        None => {
            notes.note(format!("Points without `widths`: drawn {FALLBACK_WIDTH} unit wide (USD's fallback)"), prim);
            vec![FALLBACK_WIDTH]
        }
    };
    anyhow::ensure!(widths.iter().all(|w| w.is_finite() && *w >= 0.0), "widths must be finite and not negative");
    if value(prim, "normals", time)?.is_some() {
        notes.note("`normals` on Points (oriented discs): drawn as spheres".into(), prim);
    }
    let width = |i: usize| widths[if widths.len() == 1 { 0 } else { i }];
    let drawn = (0..n).filter(|&i| width(i) > 0.0).count();
    let ball = TriangleMesh::icosphere(if drawn <= FINE_POINTS { 1 } else { 0 });
    if drawn.saturating_mul(ball.indices.len()) > MAX_TRIANGLES {
        return Err(OverBudget(drawn).into());
    }
    let mut mesh = TriangleMesh {
        positions: Vec::with_capacity(drawn * ball.positions.len()),
        normals: Some(Vec::with_capacity(drawn * ball.positions.len())),
        uvs: None,
        indices: Vec::with_capacity(drawn * ball.indices.len()),
    };
    let normals = mesh.normals.as_mut().expect("set above");
    for (i, p) in points.iter().enumerate().filter(|&(i, _)| width(i) > 0.0) {
        let base = mesh.positions.len() as u32;
        let r = 0.5 * width(i);
        mesh.positions.extend(ball.positions.iter().map(|v| *p + *v * r));
        normals.extend_from_slice(&ball.positions);
        mesh.indices.extend(ball.indices.iter().map(|t| t.map(|k| base + k)));
    }
    mesh.remove_unusable_triangles();
    if mesh.indices.is_empty() {
        return Ok(None);
    }
    mesh.validate().map_err(|e| anyhow::anyhow!("{e}"))?;
    Ok(Some(mesh))
}
