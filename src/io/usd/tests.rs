//! USD text import and export: curves with their bases, widths and colours, meshes,
//! up axis, round trips, errors, and mutated input.

use super::*;
use proptest::prelude::*;

const SCENE: &str = r#"#usda 1.0
(
    defaultPrim = "World"
    upAxis = "Y"
)
def Xform "World"
{
    double3 xformOp:translate = (0, 1, 0)
    uniform token[] xformOpOrder = ["xformOp:translate"]

    def BasisCurves "Cubic"
    {
        uniform token type = "cubic"
        uniform token basis = "bspline"
        uniform token wrap = "pinned"
        int[] curveVertexCounts = [4]
        point3f[] points = [(0, 0, 0), (0, 1, 0), (0, 2, 0), (0, 3, 0)]
        float[] widths = [0.2, 0.1, 0.1, 0.0] (interpolation = "vertex")
        color3f[] primvars:displayColor = [(0.6, 0.4, 0.2)] (interpolation = "constant")
    }
    def BasisCurves "Linear"
    {
        uniform token type = "linear"
        int[] curveVertexCounts = [2, 3]
        point3f[] points = [(1, 0, 0), (1, 1, 0), (2, 0, 0), (2, 1, 0), (2, 2, 0)]
        float[] widths = [0.05, 0.03] (interpolation = "uniform")
        color3f[] primvars:displayColor = [(1, 0, 0), (0, 1, 0), (0, 0, 1), (1, 1, 0), (0, 1, 1)] (interpolation = "vertex")
    }
    def Mesh "Ground" (
        prepend apiSchemas = []
    )
    {
        int[] faceVertexCounts = [4]
        int[] faceVertexIndices = [0, 1, 2, 3]
        point3f[] points = [(-1, 0, -1), (1, 0, -1), (1, 0, 1), (-1, 0, 1)]
        texCoord2f[] primvars:st = [(0, 0), (1, 0), (1, 1), (0, 1)] (interpolation = "faceVarying")
        color3f[] primvars:displayColor = [(0.3, 0.3, 0.3)]
    }
    def DistantLight "Sun"
    {
        float inputs:intensity = 2
    }
}
"#;

fn read_text(text: &str) -> Result<Imported, LoadError> {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("scene.usda");
    std::fs::write(&path, text).unwrap();
    read_usd(&path).map_err(|e| {
        LoadError::format(Path::new("scene.usda"), e.to_string().replace(&*path.to_string_lossy(), "scene.usda"))
    })
}

fn strands(s: &Imported, i: usize) -> &StrandSet {
    let HairSource::Inline(set) = &s.hair[i].source else { panic!() };
    set
}

#[test]
fn basis_curves_and_meshes_import_with_widths_and_colours() {
    let s = read_text(SCENE).unwrap();
    assert_eq!((s.hair.len(), s.meshes.len(), s.lights.len()), (2, 1, 1));
    // Pinned cubic B-spline: 4 points + 2 phantoms = 3 segments, through both end points.
    let c = strands(&s, 0);
    assert_eq!(c.points.len(), 3 * PIECES_PER_SEGMENT + 1);
    let first = Vec3::from_slice(&c.points[0][..3]);
    let last = Vec3::from_slice(&c.points[c.points.len() - 1][..3]);
    assert!(first.length() < 1e-5 && (last - Vec3::new(0.0, 3.0, 0.0)).length() < 1e-5, "{first} {last}");
    // Widths follow the basis with the same phantoms: 0.2 at the root, 0 at the tip.
    assert!((c.points[0][3] - 0.1).abs() < 1e-6 && c.points[c.points.len() - 1][3].abs() < 1e-6);
    let Material::Tube(t) = &s.hair[0].material else { panic!() };
    assert_eq!(t.diffuse, Vec3::new(0.6, 0.4, 0.2));
    assert!(c.colors.is_none());
    // The prim's parent moves it up by one.
    assert_eq!(s.hair[0].transform.transform_point3(Vec3::ZERO), Vec3::Y);
    // Linear curves: their points, uniform widths, vertex colours.
    let l = strands(&s, 1);
    assert_eq!(l.offsets, vec![0, 2, 5]);
    assert_eq!(l.points[1], [1.0, 1.0, 0.0, 0.025]);
    assert_eq!(l.points[4], [2.0, 2.0, 0.0, 0.015]);
    assert_eq!(l.colors.as_ref().unwrap()[2], [0.0, 0.0, 1.0]);
    // The mesh: a quad as two triangles with face-varying UVs and its colour.
    let MeshSource::Inline(m) = &s.meshes[0].source else { panic!() };
    assert_eq!((m.positions.len(), m.indices.len()), (4, 2));
    assert_eq!(m.uvs.as_ref().unwrap()[2], [1.0, 1.0]);
    assert_eq!(s.meshes[0].material, Material::Diffuse { color: Vec3::splat(0.3) });
    assert_eq!(s.lights[0], Light::Distant { direction: Vec3::Z, irradiance: Vec3::splat(2.0) });
}

#[test]
fn z_up_stages_are_turned_y_up() {
    let s = read_text(&SCENE.replace("upAxis = \"Y\"", "upAxis = \"Z\"")).unwrap();
    // The world's translate (0, 1, 0) in Z-up is (0, 0, −1) in Y-up.
    let p = s.hair[0].transform.transform_point3(Vec3::ZERO);
    assert!((p - Vec3::new(0.0, 0.0, -1.0)).length() < 1e-6, "{p}");
}

#[test]
fn export_then_import_keeps_points_widths_and_colours() {
    let mut set = StrandSet::new();
    set.push_strand([
        (Vec3::new(0.1, 0.2, 0.3), 0.01),
        (Vec3::new(0.4, 0.5, 0.6), 0.02),
        (Vec3::new(0.7, 0.8, 0.9), 0.005),
    ]);
    set.push_strand([(Vec3::new(-1.0, 2.5, 1e-3), 0.25), (Vec3::new(3.0, -2.0, 7.0), 0.0)]);
    set.colors = Some(vec![[0.1, 0.2, 0.3], [0.4, 0.5, 0.6], [0.7, 0.8, 0.9], [1.0, 0.0, 0.5], [0.25, 0.75, 1.0]]);
    let mesh = TriangleMesh::sphere(1.5, 4);
    let shapes = vec![(Shape::Strands(set.clone()), 0), (Shape::Mesh(mesh.clone()), 1)];
    let materials = vec![
        Material::Tube(crate::hair_system::HairSystem::default().tube()),
        Material::Diffuse { color: Vec3::new(0.2, 0.3, 0.4) },
    ];
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("out.usda");
    write_usd(&path, &shapes, &materials).unwrap();
    let s = read_usd(&path).unwrap();
    let back = strands(&s, 0);
    assert_eq!(back.offsets, set.offsets);
    assert_eq!(back.points, set.points);
    assert_eq!(back.colors, set.colors);
    let MeshSource::Inline(m) = &s.meshes[0].source else { panic!() };
    assert_eq!(m.indices.len(), mesh.indices.len());
    // Every original triangle comes back with the same corners.
    for (a, b) in m.indices.iter().zip(&mesh.indices) {
        assert_eq!(a.map(|i| m.positions[i as usize]), b.map(|i| mesh.positions[i as usize]));
    }
    assert_eq!(s.meshes[0].material, Material::Diffuse { color: Vec3::new(0.2, 0.3, 0.4) });
}

#[test]
fn malformed_files_are_errors_with_lines_and_no_panic() {
    let e = read_text("#usda 1.0\ndef Xform \"A\"\n{\n    float x = \n}\n").unwrap_err().to_string();
    assert!(e.contains("line 5") || e.contains("line 4"), "{e}");
    let e = read_text(&SCENE.replace("[4]", "[5]")).unwrap_err().to_string();
    assert!(e.contains("/World/Cubic") && e.contains("curveVertexCounts"), "{e}");
    let e = read_text(&SCENE.replace("[0.05, 0.03]", "[0.05]")).unwrap_err().to_string();
    assert!(e.contains("widths"), "{e}");
    let e = read_text(&SCENE.replace("[0, 1, 2, 3]", "[0, 1, 2, 9]")).unwrap_err().to_string();
    assert!(e.contains("/World/Ground"), "{e}");
    // Deep nesting would overflow the parser's stack: refused up front.
    let deep = format!("#usda 1.0\n{}{}", "def \"A\" {\n".repeat(100_000), "}\n".repeat(100_000));
    let e = read_text(&deep).unwrap_err().to_string();
    assert!(e.contains("nest deeper"), "{e}");
    let e = read_text("PXR-USDC binary").unwrap_err().to_string();
    assert!(e.contains("#usda"), "{e}");
}

#[test]
fn prim_names_that_are_not_identifiers_are_errors_not_a_stack_overflow() {
    // Found by `mutated_scenes_never_panic`: the crate recursed without end on this path.
    let e = read_text(&SCENE.replace("\"World\"\n{", "\"Wor}d\"\n{")).unwrap_err().to_string();
    assert!(e.contains("line 6") && e.contains("not an identifier"), "{e}");
    assert!(read_text(&SCENE.replace("\"World\"\n{", "\"_World2\"\n{")).is_ok());
}

#[test]
fn braces_in_property_names_and_paths_are_errors_not_a_hang() {
    // Found by `mutated_scenes_never_panic`: the crate's ancestor walk of the attribute
    // path `/World.xformOp:tr}anslate` went round forever.
    let e = read_text(&SCENE.replace("[\"xformOp:translate\"]", "[\"xformOp:tr}anslate\"]")).unwrap_err().to_string();
    assert!(e.contains("/World") && e.contains("xformOp:tr}anslate"), "{e}");
    // The same walk from a composition arc's path.
    for arc in ["inherits = </A}>", "references = </A}>", "specializes = </A.b}c>"] {
        let e = read_text(&SCENE.replace("prepend apiSchemas = []", arc)).unwrap_err().to_string();
        assert!(e.contains("line 30") && e.contains("closes no"), "{arc}: {e}");
    }
    // Variant selections, inverted ops and a reset stack stay readable.
    let fine = SCENE
        .replace("int[] faceVertexCounts", "rel proxyPrim = </World{v=a}Cubic>\n        int[] faceVertexCounts")
        .replace(
            "[\"xformOp:translate\"]",
            "[\"!resetXformStack!\", \"xformOp:translate\", \"!invert!xformOp:translate\"]",
        );
    let s = read_text(&fine).unwrap();
    assert_eq!(s.hair[0].transform.transform_point3(Vec3::ZERO), Vec3::ZERO);
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 200, ..ProptestConfig::default() })]

    #[test]
    fn mutated_scenes_never_panic(edits in prop::collection::vec((0usize..SCENE.len(), 0u8..3, prop::sample::select(&b"0123456789-.e\"[](){} =\nab"[..])), 1..6)) {
        let mut bytes = SCENE.as_bytes().to_vec();
        for (at, op, c) in edits {
            let at = at.min(bytes.len().saturating_sub(1));
            match op {
                0 => bytes[at] = c,
                1 => { bytes.remove(at); }
                _ => bytes.insert(at, c),
            }
        }
        let _ = read_text(&String::from_utf8_lossy(&bytes));
    }

    #[test]
    fn random_text_never_panics(text in "#usda 1.0\n\\PC{0,200}") {
        let _ = read_text(&text);
    }
}
