//! UsdGeom `PointInstancer`: each instance draws one of the instancer's prototypes (the
//! prim subtrees its `prototypes` relationship targets), moved by the instance's
//! transform. tress's acceleration structures hold no instances, so every instance is a
//! copy of its prototype's geometry; what that would take is checked against the
//! machine's memory before anything is copied.
//!
//! The instance transform follows `UsdGeomPointInstancer::ComputeInstanceTransformsAtTime`
//! (USD's schema documentation): scale, then orientation, then translation to the
//! instance's position, applied after the prototype root's own transform operations,
//! all in the instancer's space.

use super::values::{ints, quats, value, vec3s, Res};
use glam::{DMat4, DQuat, DVec3};
use openusd::sdf;
use openusd::usd::{Prim, TimeCode};

/// One instance: which prototype it draws and where.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Instance {
    /// Index into [`Instances::prototypes`].
    pub prototype: usize,
    /// Prototype-root-parent space to instancer space.
    pub matrix: DMat4,
}

/// What a `PointInstancer` prim draws at one time code.
#[derive(Debug, Default)]
pub struct Instances {
    /// The prototype roots, in the relationship's order.
    pub prototypes: Vec<sdf::Path>,
    /// The visible instances (those not listed in `invisibleIds`).
    pub instances: Vec<Instance>,
}

/// The instances of a `PointInstancer` prim at `time`. An error says why the instancer
/// cannot be drawn (arrays of different lengths, an index past the prototypes): USD's
/// renderers then draw none of it, and so does tress.
pub fn read(prim: &Prim, time: TimeCode) -> Res<Instances> {
    let prototypes = prim.relationship("prototypes").targets()?;
    let get = |name: &str| value(prim, name, time);
    let indices = ints(get("protoIndices")?, "protoIndices")?.unwrap_or_default();
    let n = indices.len();
    let positions = authored("positions", vec3s(get("positions")?, "positions")?, n)?;
    // `orientationsf`, when authored, wins over the half-precision `orientations`.
    let orientations = match authored("orientationsf", quats(get("orientationsf")?, "orientationsf")?, n)? {
        Some(q) => Some(q),
        None => authored("orientations", quats(get("orientations")?, "orientations")?, n)?,
    };
    let scales = authored("scales", vec3s(get("scales")?, "scales")?, n)?;
    let ids = authored("ids", ints(get("ids")?, "ids")?, n)?;
    let invisible: std::collections::HashSet<i64> =
        ints(get("invisibleIds")?, "invisibleIds")?.unwrap_or_default().into_iter().collect();
    let mut instances = Vec::with_capacity(n.min(1 << 20));
    for (i, &index) in indices.iter().enumerate() {
        let prototype = usize::try_from(index).ok().filter(|&p| p < prototypes.len()).ok_or_else(|| {
            anyhow::anyhow!("`protoIndices` entry {index} names none of its {} prototypes", prototypes.len())
        })?;
        // Without `ids`, an instance's id is its index.
        let id = ids.as_ref().map_or(i as i64, |ids| ids[i]);
        if invisible.contains(&id) {
            continue;
        }
        let q = orientations.as_ref().map_or(DQuat::IDENTITY, |o| o[i]);
        // A zero quaternion has no rotation to give; USD normalizes what it reads.
        let rotation = if q.length_squared() > 0.0 { q.normalize() } else { DQuat::IDENTITY };
        let scale = scales.as_ref().map_or(DVec3::ONE, |s| s[i].as_dvec3());
        let position = positions.as_ref().map_or(DVec3::ZERO, |p| p[i].as_dvec3());
        let matrix = DMat4::from_scale_rotation_translation(scale, rotation, position);
        if !matrix.is_finite() {
            anyhow::bail!("instance {i}'s transform is not finite");
        }
        instances.push(Instance { prototype, matrix });
    }
    Ok(Instances { prototypes, instances })
}

/// A per-instance array of an instancer with `n` instances: one that is absent or empty
/// is not authored, and the instances sit at the origin, unturned, unscaled, their ids
/// their indices (Arnold's reader draws such instancers; test files write
/// `quath[] orientations = []`). One of another length is an error.
fn authored<T>(what: &str, values: Option<Vec<T>>, n: usize) -> Res<Option<Vec<T>>> {
    match values {
        None => Ok(None),
        Some(v) if v.is_empty() => Ok(None),
        Some(v) if v.len() == n => Ok(Some(v)),
        Some(v) => anyhow::bail!("`{what}` has {} entries for {n} instances (`protoIndices`)", v.len()),
    }
}

#[cfg(test)]
mod tests {
    use super::super::tests::{mutated, read_body, read_text};
    use glam::Vec3;
    use proptest::prelude::*;

    /// The world positions of the first point of every strand set, and the centres of the
    /// meshes' bounds, as the importer placed them.
    fn placed(s: &super::super::Imported) -> (Vec<Vec3>, Vec<Vec3>) {
        let hair = s.contents.hair.iter().map(|e| {
            let crate::scene::HairSource::Inline(set) = &e.source else { panic!("inline strands") };
            e.transform.transform_point3(Vec3::from_slice(&set.points[0][..3]))
        });
        let meshes = s.contents.meshes.iter().map(|e| {
            let crate::scene::MeshSource::Inline(m) = &e.source else { panic!("inline mesh") };
            let (lo, hi) = m.positions.iter().fold((Vec3::MAX, Vec3::MIN), |(lo, hi), p| (lo.min(*p), hi.max(*p)));
            e.transform.transform_point3(0.5 * (lo + hi))
        });
        (hair.collect(), meshes.collect())
    }

    fn close(a: Vec3, b: Vec3) -> bool {
        (a - b).length() < 1e-4
    }

    /// Two prototypes, one under a translated root, and three instances, one scaled,
    /// turned and moved, under a translated instancer.
    const TREES: &str = r#"#usda 1.0
def PointInstancer "Trees" {
    double3 xformOp:translate = (0, 5, 0)
    uniform token[] xformOpOrder = ["xformOp:translate"]
    rel prototypes = [</Trees/Protos/Hair>, </Trees/Protos/Box>]
    int[] protoIndices = [0, 0, 1]
    point3f[] positions = [(0, 0, 0), (10, 0, 0), (-3, 0, 0)]
    quath[] orientations = [(1, 0, 0, 0), (0.70710678, 0, 0.70710678, 0), (1, 0, 0, 0)]
    float3[] scales = [(1, 1, 1), (2, 2, 2), (1, 1, 1)]
    def Scope "Protos" {
        def BasisCurves "Hair" {
            double3 xformOp:translate = (0, 0, 2)
            uniform token[] xformOpOrder = ["xformOp:translate"]
            uniform token type = "linear"
            int[] curveVertexCounts = [2]
            point3f[] points = [(1, 0, 0), (1, 1, 0)]
        }
        def Cube "Box" { double size = 1 }
    }
}
"#;

    proptest! {
        #![proptest_config(ProptestConfig { cases: 100, ..ProptestConfig::default() })]

        #[test]
        fn mutated_instancers_never_panic(edits in prop::collection::vec((0usize..TREES.len(), 0u8..3, prop::sample::select(&b"0123456789-.e\"[](){} =\nab<>/"[..])), 1..6)) {
            let _ = read_text(&mutated(TREES, &edits));
        }
    }

    #[test]
    fn each_instance_draws_its_prototype_scaled_rotated_then_moved() {
        // Prototype 0, a curve whose first point is (1, 0, 0) under a root translated by
        // (0, 0, 2); prototype 1, a cube. Instance 1 scales by 2, turns 90 degrees about +Y
        // ((w, x, y, z) = (cos 45, 0, sin 45, 0)) and moves to (10, 0, 0); the instancer
        // itself sits at y = 5.
        let s = read_text(TREES).unwrap();
        let (hair, meshes) = placed(&s);
        // The prototypes under the instancer are not drawn by themselves.
        assert_eq!((hair.len(), meshes.len()), (2, 1), "{hair:?} {meshes:?}");
        assert!(close(hair[0], Vec3::new(1.0, 5.0, 2.0)), "{:?}", hair[0]);
        // (1, 0, 2) scaled by 2 is (2, 0, 4); turned 90 degrees about +Y, x -> -z and
        // z -> x: (4, 0, -2); moved: (14, 5, -2).
        assert!(close(hair[1], Vec3::new(14.0, 5.0, -2.0)), "{:?}", hair[1]);
        assert!(close(meshes[0], Vec3::new(-3.0, 5.0, 0.0)), "{:?}", meshes[0]);
    }

    #[test]
    fn invisible_ids_and_prototypes_hide_instances_and_outside_prototypes_still_draw() {
        // Ids 7 and 8 draw the cube outside the instancer (which also draws by itself);
        // id 8 is invisible. Prototype 1 is invisible, so its instance draws nothing.
        let body = r#"
def Cube "Outside" { double size = 1 }
def PointInstancer "Set" {
    rel prototypes = [</Outside>, </Set/Hidden>]
    int[] protoIndices = [0, 0, 1]
    int64[] ids = [7, 8, 9]
    int64[] invisibleIds = [8]
    point3f[] positions = [(5, 0, 0), (6, 0, 0), (7, 0, 0)]
    def Sphere "Hidden" { token visibility = "invisible" }
}
"#;
        let (_, meshes) = placed(&read_body(body));
        assert_eq!(meshes.len(), 2, "{meshes:?}");
        assert!(close(meshes[0], Vec3::ZERO) && close(meshes[1], Vec3::new(5.0, 0.0, 0.0)), "{meshes:?}");
    }

    #[test]
    fn nested_instancers_multiply_and_self_instancing_stops_with_a_warning() {
        // An outer instancer of 3 copies of an inner one of 2 cubes: 6 cubes. A third
        // instancer names its own parent as prototype: reported, not followed.
        let body = r#"
def PointInstancer "Outer" {
    rel prototypes = [</Outer/Inner>]
    int[] protoIndices = [0, 0, 0]
    point3f[] positions = [(0, 0, 0), (0, 10, 0), (0, 20, 0)]
    def PointInstancer "Inner" {
        rel prototypes = [</Outer/Inner/Box>]
        int[] protoIndices = [0, 0]
        point3f[] positions = [(0, 0, 0), (1, 0, 0)]
        def Cube "Box" { double size = 0.5 }
    }
}
def Xform "Loop" {
    def PointInstancer "Self" {
        rel prototypes = [</Loop>]
        int[] protoIndices = [0]
        point3f[] positions = [(0, 0, 0)]
    }
}
"#;
        let s = read_body(body);
        let (_, meshes) = placed(&s);
        assert_eq!(meshes.len(), 6, "{meshes:?}");
        assert!(meshes.iter().any(|m| close(*m, Vec3::new(1.0, 20.0, 0.0))), "{meshes:?}");
        assert!(
            s.warnings.iter().any(|w| w.contains("inside their own prototype") && w.contains("/Loop/Self")),
            "{:?}",
            s.warnings
        );
    }

    #[test]
    fn absent_and_empty_arrays_leave_instances_at_the_origin_unturned() {
        let body = r#"
def PointInstancer "Bare" {
    rel prototypes = [</Bare/Box>]
    int[] protoIndices = [0, 0]
    quath[] orientations = []
    float3[] scales = []
    def Cube "Box" { double size = 2 }
}
"#;
        let s = read_body(body);
        let (_, meshes) = placed(&s);
        assert_eq!(meshes.len(), 2, "{:?}", s.warnings);
        assert!(meshes.iter().all(|m| close(*m, Vec3::ZERO)), "{meshes:?}");
    }

    #[test]
    fn inconsistent_instancers_are_skipped_naming_the_instancer() {
        for (arrays, why) in [
            ("int[] protoIndices = [0, 0]\n point3f[] positions = [(0, 0, 0)]", "`positions` has 1 entries for 2 instances"),
            ("int[] protoIndices = [3]\n point3f[] positions = [(0, 0, 0)]", "entry 3 names none of its 1 prototypes"),
            ("int[] protoIndices = [0]\n point3f[] positions = [(0, 0, 0)]\n float3[] scales = [(1, 1, 1), (2, 2, 2)]", "`scales` has 2"),
            ("int[] protoIndices = [0]\n point3f[] positions = [(1e39, 0, 0)]", "not finite"),
        ] {
            let body = format!(
                "def PointInstancer \"Bad\" {{\n rel prototypes = [</Bad/Box>]\n {arrays}\n def Cube \"Box\" {{}}\n}}\n"
            );
            let s = read_body(&body);
            assert!(s.contents.meshes.is_empty(), "{arrays}");
            assert!(s.warnings.iter().any(|w| w.contains("/Bad: ") && w.contains(why)), "{arrays}: {:?}", s.warnings);
        }
    }
}
