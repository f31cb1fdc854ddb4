//! USD text import and export: curves with their bases, widths and colours, meshes,
//! up axis, round trips, errors, and mutated input.

use super::*;
use crate::accel::Shape;
use crate::geometry::subdivision::MAX_FACES_PER_FILE;
use crate::geometry::{StrandSet, TriangleMesh};
use crate::io::arnold_hair::StandardHair;
use crate::io::ImportOptions;
use crate::light::Light;
use crate::scene::{HairSource, LightSource, MaterialSource};
use glam::Vec2;
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

pub(super) fn read_text(text: &str) -> Result<Imported, LoadError> {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("scene.usda");
    std::fs::write(&path, text).unwrap();
    read_usd(&path, &ImportOptions::default()).map_err(|e| {
        LoadError::format(Path::new("scene.usda"), e.to_string().replace(&*path.to_string_lossy(), "scene.usda"))
    })
}

fn strands(s: &Imported, i: usize) -> &StrandSet {
    let HairSource::Inline(set) = &s.contents.hair[i].source else { panic!() };
    set
}

#[test]
fn basis_curves_and_meshes_import_with_widths_and_colours() {
    let s = read_text(SCENE).unwrap();
    assert_eq!((s.contents.hair.len(), s.contents.meshes.len(), s.contents.lights.len()), (2, 1, 1));
    // Pinned cubic B-spline: 4 points + 2 phantoms = 3 segments, through both end points.
    let c = strands(&s, 0);
    assert_eq!(c.points.len(), 3 * PIECES_PER_SEGMENT + 1);
    let first = Vec3::from_slice(&c.points[0][..3]);
    let last = Vec3::from_slice(&c.points[c.points.len() - 1][..3]);
    assert!(first.length() < 1e-5 && (last - Vec3::new(0.0, 3.0, 0.0)).length() < 1e-5, "{first} {last}");
    // Widths follow the basis with the same phantoms: 0.2 at the root, 0 at the tip.
    assert!((c.points[0][3] - 0.1).abs() < 1e-6 && c.points[c.points.len() - 1][3].abs() < 1e-6);
    let MaterialSource::Inline(Material::Tube(t)) = &s.contents.hair[0].material else { panic!() };
    assert_eq!(t.diffuse, Vec3::new(0.6, 0.4, 0.2));
    assert!(c.colors.is_none());
    // The prim's parent moves it up by one.
    assert_eq!(s.contents.hair[0].transform.transform_point3(Vec3::ZERO), Vec3::Y);
    // Linear curves: their points, uniform widths, vertex colours.
    let l = strands(&s, 1);
    assert_eq!(l.offsets, vec![0, 2, 5]);
    assert_eq!(l.points[1], [1.0, 1.0, 0.0, 0.025]);
    assert_eq!(l.points[4], [2.0, 2.0, 0.0, 0.015]);
    assert_eq!(l.colors.as_ref().unwrap()[2], [0.0, 0.0, 1.0]);
    // The mesh: a quad as two triangles with face-varying UVs and its colour.
    let MeshSource::Inline(m) = &s.contents.meshes[0].source else { panic!() };
    assert_eq!((m.positions.len(), m.indices.len()), (4, 2));
    assert_eq!(m.uvs.as_ref().unwrap()[2], [1.0, 1.0]);
    assert_eq!(s.contents.meshes[0].material, Material::Diffuse { color: Vec3::splat(0.3) }.into());
    assert_eq!(s.contents.lights[0], Light::Distant { direction: Vec3::Z, irradiance: Vec3::splat(2.0) }.into());
}

#[test]
fn z_up_stages_are_turned_y_up() {
    let s = read_text(&SCENE.replace("upAxis = \"Y\"", "upAxis = \"Z\"")).unwrap();
    // The world's translate (0, 1, 0) in Z-up is (0, 0, −1) in Y-up.
    let p = s.contents.hair[0].transform.transform_point3(Vec3::ZERO);
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
    write_usd(&path, &shapes, &materials, &[]).unwrap();
    let s = read_usd(&path, &ImportOptions::default()).unwrap();
    let back = strands(&s, 0);
    assert_eq!(back.offsets, set.offsets);
    assert_eq!(back.points, set.points);
    assert_eq!(back.colors, set.colors);
    let MeshSource::Inline(m) = &s.contents.meshes[0].source else { panic!() };
    assert_eq!(m.indices.len(), mesh.indices.len());
    // Every original triangle comes back with the same corners.
    for (a, b) in m.indices.iter().zip(&mesh.indices) {
        assert_eq!(a.map(|i| m.positions[i as usize]), b.map(|i| mesh.positions[i as usize]));
    }
    assert_eq!(s.contents.meshes[0].material, Material::Diffuse { color: Vec3::new(0.2, 0.3, 0.4) }.into());
}

#[test]
fn export_then_import_keeps_visibility() {
    use crate::scene::Visibility;
    let mut set = StrandSet::new();
    set.push_strand([(Vec3::ZERO, 0.01), (Vec3::Y, 0.01)]);
    let mesh = TriangleMesh::sphere(1.0, 2);
    let seen = |camera, shadows, matte| Visibility { camera, shadows, matte };
    let cases = [seen(false, true, false), seen(true, false, true), seen(true, true, false), seen(false, false, true)];
    let shapes: Vec<_> = cases
        .iter()
        .enumerate()
        .map(|(i, _)| match i % 2 {
            0 => (Shape::Strands(set.clone()), 0),
            _ => (Shape::Mesh(mesh.clone()), 1),
        })
        .collect();
    let materials = vec![
        Material::Tube(crate::hair_system::HairSystem::default().tube()),
        Material::Diffuse { color: Vec3::splat(0.5) },
    ];
    let text = usda_text(&shapes, &materials, &cases).unwrap();
    // Only what differs from the default is written: the third shape has no Arnold primvars.
    assert_eq!(text.matches("primvars:arnold:").count(), 6, "{text}");
    let s = read_text(&text).unwrap();
    let hair: Vec<_> = s.contents.hair.iter().map(|h| h.visibility).collect();
    let meshes: Vec<_> = s.contents.meshes.iter().map(|m| m.visibility).collect();
    assert_eq!((hair, meshes), (vec![cases[0], cases[2]], vec![cases[1], cases[3]]));
    // Without visibility every shape is written seen by every ray.
    assert!(!usda_text(&shapes, &materials, &[]).unwrap().contains("arnold"));
}

#[test]
fn malformed_files_are_errors_with_lines_and_no_panic() {
    let e = read_text("#usda 1.0\ndef Xform \"A\"\n{\n    float x = \n}\n").unwrap_err().to_string();
    assert!(e.contains("line 5") || e.contains("line 4"), "{e}");
    // A prim whose data does not add up is skipped, named, and the rest still read.
    let s = read_text(&SCENE.replace("[4]", "[5]").replace("[0, 1, 2, 3]", "[0, 1, 2, 9]")).unwrap();
    let skipped: Vec<_> = s.warnings.iter().filter(|w| w.contains("inconsistent: skipped")).collect();
    assert_eq!(skipped.len(), 1, "{:?}", s.warnings);
    assert!(
        skipped[0].contains("(2; first: /World/Cubic: ") && skipped[0].contains("curveVertexCounts"),
        "{skipped:?}"
    );
    assert_eq!((s.contents.hair.len(), s.contents.meshes.len()), (1, 0));

    // Deep nesting would overflow the parser's stack: refused up front.
    let deep = format!("#usda 1.0\n{}{}", "def \"A\" {\n".repeat(100_000), "}\n".repeat(100_000));
    let e = read_text(&deep).unwrap_err().to_string();
    assert!(e.contains("nest deeper"), "{e}");
    let e = read_text("PXR-USDC binary").unwrap_err().to_string();
    assert!(e.contains("scene.usda") && e.contains("damaged binary USD layer"), "{e}");
    let e = read_text("\u{1}\u{2} binary").unwrap_err().to_string();
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
    assert_eq!(s.contents.hair[0].transform.transform_point3(Vec3::ZERO), Vec3::ZERO);
}

/// `text` with each edit `(at, op, c)` applied: byte `at` replaced by `c` (op 0), removed
/// (op 1) or preceded by `c` (op 2).
pub(super) fn mutated(text: &str, edits: &[(usize, u8, u8)]) -> String {
    let mut bytes = text.as_bytes().to_vec();
    for &(at, op, c) in edits {
        let at = at.min(bytes.len().saturating_sub(1));
        match op {
            0 => bytes[at] = c,
            1 => {
                bytes.remove(at);
            }
            _ => bytes.insert(at, c),
        }
    }
    String::from_utf8_lossy(&bytes).into_owned()
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 200, ..ProptestConfig::default() })]

    #[test]
    fn mutated_scenes_never_panic(edits in prop::collection::vec((0usize..SCENE.len(), 0u8..3, prop::sample::select(&b"0123456789-.e\"[](){} =\nab"[..])), 1..6)) {
        let _ = read_text(&mutated(SCENE, &edits));
    }

    #[test]
    fn random_text_never_panics(text in "#usda 1.0\n\\PC{0,200}") {
        let _ = read_text(&text);
    }
}

/// A stage of one prim block (and stage metadata `meta`), read with `options`.
fn read_with(meta: &str, body: &str, options: &ImportOptions) -> Result<Imported, LoadError> {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("scene.usda");
    std::fs::write(&path, format!("#usda 1.0\n(\n{meta}\n)\n{body}")).unwrap();
    read_usd(&path, options)
}

pub(super) fn read_body(body: &str) -> Imported {
    read_with("", body, &ImportOptions::default()).unwrap()
}

fn point(s: &StrandSet, i: usize) -> Vec3 {
    Vec3::from_slice(&s.points[i][..3])
}

#[test]
fn every_number_form_of_the_grammar_is_read() {
    let body = r#"def BasisCurves "C" {
        uniform token type = "linear"
        int[] curveVertexCounts = [3]
        point3f[] points = [(.5, -.25, 7.), (+.5e1, 2.E-1, -3.e0), (1e2, -0, 1.5)]
        float[] widths = [.1] (interpolation = "constant")
    }"#;
    let s = read_body(body);
    let c = strands(&s, 0);
    assert_eq!(point(c, 0), Vec3::new(0.5, -0.25, 7.0));
    assert_eq!(point(c, 1), Vec3::new(5.0, 0.2, -3.0));
    assert_eq!(point(c, 2), Vec3::new(100.0, 0.0, 1.5));
    assert_eq!(c.points[0][3], 0.05);
    // The crate alone refuses these forms: the rewrite is what reads them.
    let text = format!("#usda 1.0\n{body}");
    assert!(openusd::usda::parser::Parser::new(&text).parse().is_err());
    let fixed = layer::normalize_numbers(&text);
    assert!(openusd::usda::parser::Parser::new(&fixed).parse().is_ok());
    assert_eq!(fixed.lines().count(), text.lines().count());
}

#[test]
fn the_number_rewrite_leaves_strings_paths_comments_and_names_alone() {
    let text = "#usda 1.0\n# .5 and 7.\ndef \"A\" (doc = \"v7. .5\") { rel r = </A.b> asset a = @./t.5.png@ float x2.timeSamples = { 1.: .5 } }";
    let out = layer::normalize_numbers(text);
    assert_eq!(
        out,
        "#usda 1.0\n# .5 and 7.\ndef \"A\" (doc = \"v7. .5\") { rel r = </A.b> asset a = @./t.5.png@ float x2.timeSamples = { 1.0: 0.5 } }"
    );
}

#[test]
fn slash_comments_unsigned_arrays_and_asset_samples_are_read() {
    let body = r#"// Written by a tool that comments C-style: don't stop here.
def BasisCurves "C" { // the strands
        uniform token type = "linear"
        uint[] arnold:node_idxs = [0, 4000000000]
        uint64[] ids = [1]
        int[] curveVertexCounts = [2]
        point3f[] points = [(0, 0, 0), (0, 2, 0)] // root, tip
        float[] widths = [0.5] (interpolation = "constant")
        asset file.timeSamples = {
            1: @./a//b.ies@,
            2: @@,
            3: @@@c.vdb@@@,
        }
        rel r = </C>
    }"#;
    let s = read_body(body);
    let c = strands(&s, 0);
    assert_eq!((point(c, 0), point(c, 1)), (Vec3::ZERO, Vec3::new(0.0, 2.0, 0.0)));
    assert_eq!(c.points[0][3], 0.25);
    let text = format!("#usda 1.0\n{body}");
    let fixed = layer::grammar_gaps(&text);
    assert_eq!(fixed.lines().count(), text.lines().count());
    assert!(
        fixed.contains("{ #  the strands") && fixed.contains("\"./a//b.ies\"") && fixed.contains("\"\"\"c.vdb\"\"\""),
        "{fixed}"
    );
    // The crate alone refuses each form; the rewrite is what reads it.
    for one in [
        "def \"A\" { // note\n}",
        "def \"A\" { uint[] a = [1] }",
        "def \"A\" { matrix[] a = [] }",
        "def \"A\" { matrix[] a = [((1, 0, 0, 0), (0, 1, 0, 0), (0, 0, 1, 0), (0, 0, 0, 1))] }",
        "def \"A\" { asset a.timeSamples = { 1: @x.ies@ } }",
    ] {
        let text = format!("#usda 1.0\n{one}\n");
        assert!(openusd::usda::parser::Parser::new(&text).parse().is_err(), "{one}");
        assert!(openusd::usda::parser::Parser::new(&layer::grammar_gaps(&text)).parse().is_ok(), "{one}");
    }
}

/// Forms of USD's text grammar older layers and other tools write, which the crate's parser
/// refuses: each reads after the rewrite, to what USD's own parser makes of it.
#[test]
fn legacy_and_lenient_text_forms_are_read() {
    let body = r#"def BasisCurves "C" {
        config token type = "linear"
        int[] curveVertexCounts = [2]
        PointFloat[] points = [(0, 0, 0), (0, 2, 0)]
        float[] widths = [0.5] (interpolation = "constant")
        ColorFloat[] primvars:displayColor = [(0.25, 0.5, 1), (1, 1, 1)] (interpolation = "vertex")
        PointIndex[] ids = [7]
        Transform t = ((1, 0, 0, 0), (0, 1, 0, 0), (0, 0, 1, 0), (0, 0, 0, 1))
        asset tex = "./t.png"
        asset[] texs = ["a.png", "b.png"] (doc = "two")
    }"#;
    // A space and a tab after the header, as some writers leave them.
    let text = format!("#usda 1.0 \t\n{body}");
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("scene.usda");
    std::fs::write(&path, &text).unwrap();
    let s = read_usd(&path, &ImportOptions::default()).unwrap();
    let c = strands(&s, 0);
    assert_eq!((point(c, 0), point(c, 1)), (Vec3::ZERO, Vec3::new(0.0, 2.0, 0.0)));
    assert_eq!(c.colors.as_ref().unwrap()[0], [0.25, 0.5, 1.0]);
    let fixed = layer::grammar_gaps(&layer::legacy_type_names(&text));
    assert_eq!(fixed.lines().count(), text.lines().count());
    for form in ["#usda 1.0\n", "uniform token type", "asset tex = @./t.png@", "[@a.png@, @b.png@] (doc = \"two\")"] {
        assert!(fixed.contains(form), "{form}: {fixed}");
    }
    // The crate alone refuses each form; the rewrites are what read it. A word that is
    // not a type where it stands is left alone.
    for one in [
        "def \"A\" { config token a = \"x\" }",
        "def \"A\" { asset a = \"t.png\" }",
        "def \"A\" { asset[] a = [\"t.png\"] }",
        "def \"A\" { pathExpression e = \"/A//B* %:ref\" }",
        "def \"A\" { int a = 5.0 }",
        "def \"A\" { int2[] a = [(1.0, -2.00), (3, 4)] (elementSize = 1) }",
        "def \"A\" { PointIndex[] a = [1] }",
        "def \"A\" { VectorFloat v = (0, 0, 1) }",
        "def \"A\" { Point p = (0, 0, 1) }",
        "def \"A\" { Quath q = (1, 0, 0, 0) }",
        "def \"A\" { Frame f = ((1, 0, 0, 0), (0, 1, 0, 0), (0, 0, 1, 0), (0, 0, 0, 1)) }",
    ] {
        let text = format!("#usda 1.0\n{one}\n");
        let fixed = layer::grammar_gaps(&layer::legacy_type_names(&text));
        assert!(openusd::usda::parser::Parser::new(&text).parse().is_err(), "{one}");
        assert!(openusd::usda::parser::Parser::new(&fixed).parse().is_ok(), "{one}: {fixed}");
    }
    assert!(openusd::usda::parser::Parser::new("#usda 1.0 \ndef \"A\" {}\n").parse().is_err());
    // Only zero fractions of integer attributes go; a fraction, a double and a string stay.
    let ints = "#usda 1.0\ndef \"A\" { int a = 5.0 double d = 5.0 int b = 2.5 string s = \"5.0\" }\n";
    let fixed = layer::grammar_gaps(ints);
    assert!(fixed.contains("int a = 5 double d = 5.0 int b = 2.5 string s = \"5.0\""), "{fixed}");
    // Numbers at the very end of the text or of a line, whole or not.
    for end in ["int a = 5", "int a = 5.", "int a = 5.0", "int a = 5\n", "int a = 5.00\n", "int a = [1, 2.0]"] {
        let fixed = layer::grammar_gaps(&format!("#usda 1.0\n{end}"));
        let value = fixed.lines().nth(1).unwrap();
        assert!(!value.contains(".0"), "{end}: {fixed}");
    }
    // Samples of asset arrays, which the crate reads, are left as they are.
    let samples = "#usda 1.0\ndef \"A\" { asset[] a.timeSamples = { 1: [@x.png@, @y.png@] } }\n";
    assert_eq!(layer::grammar_gaps(samples), samples);
    assert!(openusd::usda::parser::Parser::new(samples).parse().is_ok());
    let kept = "#usda 1.0\ndef Transform \"Point\" { string config = \"Color\" token Normal = \"asset\" }\n";
    assert_eq!(layer::grammar_gaps(&layer::legacy_type_names(kept)), kept);
}

/// HermiteCurves are the cubic Hermite curves of their points and tangents: the middle of
/// a span is `(P0 + P1) / 2 + (T0 − T1) / 8`, and varying widths fall on the points.
#[test]
fn hermite_curves_follow_their_tangents() {
    let s = read_body(
        r#"def HermiteCurves "H" {
        int[] curveVertexCounts = [3]
        point3f[] points = [(0, 0, 0), (1, 1, 0), (2, 0, 0)]
        vector3f[] tangents = [(0, 1, 0), (1, 0, 0), (0, -1, 0)]
        float[] widths = [0, 0.5, 0] (interpolation = "varying")
    }"#,
    );
    let c = strands(&s, 0);
    let half = PIECES_PER_SEGMENT / 2;
    assert_eq!(c.points.len(), 2 * PIECES_PER_SEGMENT + 1);
    assert!(point(c, half).distance(Vec3::new(0.375, 0.625, 0.0)) < 1e-5, "{}", point(c, half));
    assert!(point(c, 3 * half).distance(Vec3::new(1.625, 0.625, 0.0)) < 1e-5, "{}", point(c, 3 * half));
    assert_eq!((point(c, PIECES_PER_SEGMENT), c.points[PIECES_PER_SEGMENT][3]), (Vec3::new(1.0, 1.0, 0.0), 0.25));
    // Without a tangent per point, drawn through the points, and said.
    let s = read_body(
        r#"def HermiteCurves "H" { int[] curveVertexCounts = [2] point3f[] points = [(0, 0, 0), (1, 1, 0)] }"#,
    );
    assert_eq!((point(strands(&s, 0), 0), point(strands(&s, 0), 1)), (Vec3::ZERO, Vec3::ONE.with_z(0.0)));
    assert!(s.warnings.iter().any(|w| w.contains("HermiteCurves with 0 `tangents` for 2 points")), "{:?}", s.warnings);
}

/// Value clips, as Houdini writes animation caches: the curves' `points` at each frame come
/// from the clip the `clips` metadata makes active then, through the manifest.
#[test]
fn value_clips_give_the_points_of_the_active_clip() {
    let dir = tempfile::tempdir().unwrap();
    let write = |name: &str, text: &str| std::fs::write(dir.path().join(name), format!("#usda 1.0\n{text}")).unwrap();
    write(
        "root.usda",
        r#"def BasisCurves "Hair" (
    clips = {
        dictionary default = {
            asset[] assetPaths = [@./clip1.usda@, @./clip2.usda@]
            asset manifestAssetPath = @./manifest.usda@
            string primPath = "/Hair"
            double2[] active = [(1, 0), (2, 1)]
            double2[] times = [(1, 1), (2, 2)]
        }
    }
) {
    uniform token type = "linear"
    int[] curveVertexCounts = [2]
    point3f[] points
}"#,
    );
    write("manifest.usda", "over \"Hair\" { point3f[] points }");
    write("clip1.usda", "over \"Hair\" { point3f[] points.timeSamples = { 1: [(0, 0, 0), (0, 1, 0)] } }");
    write("clip2.usda", "over \"Hair\" { point3f[] points.timeSamples = { 2: [(5, 0, 0), (5, 1, 0)] } }");
    let root = |frame| {
        let s = read_usd(
            &dir.path().join("root.usda"),
            &ImportOptions { frame: Some(frame), camera: None, ..Default::default() },
        )
        .unwrap();
        point(strands(&s, 0), 0)
    };
    assert_eq!((root(1), root(2)), (Vec3::ZERO, Vec3::new(5.0, 0.0, 0.0)));
}

const ANIMATED: &str = r#"def BasisCurves "Hair" {
    uniform token type = "linear"
    int[] curveVertexCounts.timeSamples = { 0: [2], 10: [2], 20: [3] }
    point3f[] points.timeSamples = {
        0: [(0, 0, 0), (0, 1, 0)],
        10: [(2, 0, 0), (2, 3, 0)],
        20: [(5, 0, 0), (5, 1, 0), (5, 2, 0)],
    }
    float[] widths.timeSamples = { 0: [0.1, 0.1], 10: [0.3, 0.3], 20: [0.2, 0.2, 0.2] }
}"#;

#[test]
fn time_samples_are_read_at_the_frame_and_interpolated_where_the_topology_stays() {
    let at = |frame: Option<u32>, meta: &str| {
        let s = read_with(meta, ANIMATED, &ImportOptions { frame, camera: None, ..Default::default() }).unwrap();
        strands(&s, 0).clone()
    };
    // Half way between samples of the same topology: points and widths blended.
    let c = at(Some(5), "");
    assert_eq!((point(&c, 0), point(&c, 1)), (Vec3::new(1.0, 0.0, 0.0), Vec3::new(1.0, 2.0, 0.0)));
    assert!((c.points[0][3] - 0.1).abs() < 1e-6, "{}", c.points[0][3]);
    // Between samples of different counts: the earlier sample, not a blend.
    let c = at(Some(15), "");
    assert_eq!(c.offsets, vec![0, 2]);
    assert_eq!(point(&c, 1), Vec3::new(2.0, 3.0, 0.0));
    // Without a frame: the stage's start time code.
    let c = at(None, "startTimeCode = 20");
    assert_eq!((c.offsets.clone(), point(&c, 2)), (vec![0, 3], Vec3::new(5.0, 2.0, 0.0)));
    assert_eq!(at(None, "").offsets, vec![0, 2]);
}

const CAMERAS: &str = r#"def Xform "Rig" {
    double3 xformOp:translate.timeSamples = { 0: (0, 0, 10), 10: (0, 0, 20) }
    uniform token[] xformOpOrder = ["xformOp:translate"]
    def Camera "Main" {
        float focalLength = 35
        float horizontalAperture = 36
        float verticalAperture = 24
        float2 clippingRange = (0.1, 1000)
    }
}
def Camera "Side" {
    float focalLength.timeSamples = { 0: 50, 10: 100 }
    double3 xformOp:translate = (10, 0, 0)
    float xformOp:rotateY = 90
    uniform token[] xformOpOrder = ["xformOp:translate", "xformOp:rotateY"]
}
def Sphere "Ball" {}
"#;

#[test]
fn cameras_give_the_view_field_of_view_and_image_aspect() {
    let s = read_with("", CAMERAS, &ImportOptions::default()).unwrap();
    let c = s.camera.clone().unwrap();
    assert!((c.eye - Vec3::new(0.0, 0.0, 10.0)).length() < 1e-5, "{}", c.eye);
    assert!((c.target - Vec3::new(0.0, 0.0, 9.0)).length() < 1e-5, "{}", c.target);
    assert!((c.up - Vec3::Y).length() < 1e-6);
    assert_eq!(s.resolution, Some([640, 427]));
    // The vertical aperture, widened to the rounded image's aspect.
    let want = 2.0 * (0.5 * 24.0f32.max(36.0 * 427.0 / 640.0) / 35.0).atan().to_degrees();
    assert!((c.vfov - want).abs() < 1e-3, "{} {want}", c.vfov);
    assert!(s.warnings.iter().any(|w| w.contains("2 cameras") && w.contains("/Rig/Main")), "{:?}", s.warnings);
    // Its clipping range is applied; the other camera has the schema's fallback.
    assert_eq!(c.clip, [0.1, 1000.0]);
    assert!(s.warnings.iter().all(|w| !w.contains("clippingRange")), "{:?}", s.warnings);
    // The rig moves: at frame 5 the camera is half way.
    let s = read_with("", CAMERAS, &ImportOptions { frame: Some(5), camera: None, ..Default::default() }).unwrap();
    assert!((s.camera.unwrap().eye.z - 15.0).abs() < 1e-4);
    // Picked by path, with its animated focal length and its turn: it looks along −X.
    let pick = |frame| ImportOptions { frame: Some(frame), camera: Some("/Side".into()), ..Default::default() };
    let s = read_with("", CAMERAS, &pick(10)).unwrap();
    let c = s.camera.unwrap();
    assert!((c.target - c.eye - Vec3::new(-1.0, 0.0, 0.0)).length() < 1e-5, "{} {}", c.eye, c.target);
    let want = 2.0 * (0.5f32 * 15.2908 / 100.0).atan().to_degrees();
    assert!((c.vfov - want).abs() < 1e-3, "{} {want}", c.vfov);
    assert_eq!(c.clip, [1.0, 1.0e6]);
    let e = read_with("", CAMERAS, &ImportOptions { frame: None, camera: Some("/Nope".into()), ..Default::default() })
        .unwrap_err();
    assert!(e.to_string().contains("/Nope") && e.to_string().contains("/Rig/Main, /Side"), "{e}");
}

#[test]
fn arnold_camera_primvars_place_and_zoom_a_camera_without_transform_ops() {
    // As Arnold-USD writes a camera: no xformOps, its place and lens in Arnold primvars
    // (the apertures over the default 50 mm say 60°; Arnold renders the primvar's 20°).
    let camera = r#"def Xform "Up" {
    double3 xformOp:translate = (0, 10, 0)
    uniform token[] xformOpOrder = ["xformOp:translate"]
    def Camera "Arnold" {
        float horizontalAperture = 57.735023
        float verticalAperture = 28.867512
        float[] primvars:arnold:fov = [20]
        vector3f[] primvars:arnold:position = [(0, 2, 6)]
        vector3f[] primvars:arnold:look_at = [(0, 2, 0)]
        vector3f[] primvars:arnold:up = [(0, 1, 0)]
    }
    def Camera "Placed" {
        vector3f[] primvars:arnold:position = [(5, 5, 5)]
        double3 xformOp:translate = (0, 0, 3)
        uniform token[] xformOpOrder = ["xformOp:translate"]
    }
}
"#;
    let pick = |path: &str| ImportOptions { frame: None, camera: Some(path.into()), ..Default::default() };
    let c = read_with("", camera, &pick("/Up/Arnold")).unwrap().camera.unwrap();
    assert!((c.eye - Vec3::new(0.0, 12.0, 6.0)).length() < 1e-5, "{}", c.eye);
    assert!((c.target - Vec3::new(0.0, 12.0, 5.0)).length() < 1e-5, "{}", c.target);
    // 20° across a 2:1 image: the vertical field of view is 2 atan(tan 10° / 2).
    let film = c.film.unwrap();
    let want = 2.0 * (10f32.to_radians().tan() / 2.0).atan().to_degrees();
    assert!((film.vfov(200, 100) - want).abs() < 1e-3, "{} {want}", film.vfov(200, 100));
    // A camera with transform operations of its own is placed by them, not the primvar.
    let c = read_with("", camera, &pick("/Up/Placed")).unwrap().camera.unwrap();
    assert!((c.eye - Vec3::new(0.0, 10.0, 3.0)).length() < 1e-5, "{}", c.eye);
}

#[test]
fn a_render_settings_resolution_widens_the_aperture_as_usd_fits_it() {
    let body = format!("{CAMERAS}\ndef RenderSettings \"R\" {{ uniform int2 resolution = (400, 400) }}");
    let s = read_with("", &body, &ImportOptions::default()).unwrap();
    assert_eq!(s.resolution, Some([400, 400]));
    // A square image of a 36 × 24 aperture: the vertical aperture grows to 36.
    let want = 2.0 * (18.0f32 / 35.0).atan().to_degrees();
    assert!((s.camera.unwrap().vfov - want).abs() < 1e-3);
}

#[test]
fn an_image_size_given_later_refits_the_horizontal_aperture() {
    // No RenderSettings: the film goes with the camera, so `-r` refits it.
    let c = read_with("", CAMERAS, &ImportOptions::default()).unwrap().camera.unwrap();
    for (w, h) in [(800, 400), (500, 500), (300, 600)] {
        let want = 2.0 * (0.5 * 36.0 / (w as f32 / h as f32) / 35.0).atan().to_degrees();
        let got = c.vfov_for(w, h);
        assert!((got - want).abs() < 1e-3, "{w}x{h}: {got} {want}");
    }
    // A 2:1 image of the 36 × 24 aperture keeps the 36 across: 18 mm high, not 24.
    assert!(c.vfov_for(800, 400) < 0.8 * 2.0 * (12.0f32 / 35.0).atan().to_degrees());
}

#[test]
fn lights_follow_usdlux_units_and_shapes() {
    let body = r#"
def RectLight "Rect" {
    float inputs:width = 2
    float inputs:height = 1
    float inputs:intensity = 3
    bool inputs:normalize = 1
    double3 xformOp:translate = (0, 5, 0)
    float xformOp:rotateX = -90
    uniform token[] xformOpOrder = ["xformOp:translate", "xformOp:rotateX"]
}
def DiskLight "Disk" { float inputs:radius = 0.5  float inputs:intensity = 4  float inputs:exposure = 1 }
def SphereLight "Bulb" {
    float inputs:radius = 0.5
    float inputs:intensity = 10
    bool inputs:normalize = true
    color3f inputs:color = (1, 0.5, 0.25)
}
def DistantLight "Sun" { float inputs:angle = 2 float inputs:intensity = 5 }
def DistantLight "Key" { float inputs:angle = 0 float intensity = 2 }
def DomeLight "Sky" { float inputs:intensity = 0.5 asset inputs:texture:file = @sky.exr@ }
def DomeLight "Backdrop" { float inputs:intensity = 2 double primvars:arnold:camera = 0 }
"#;
    let s = read_body(body);
    assert_eq!(s.contents.lights.len(), 7);
    let LightSource::Inline(Light::Quad { corner, edge_u, edge_v, radiance, .. }) = s.contents.lights[0] else {
        panic!("{:?}", s.contents.lights[0])
    };
    // Normalized: the emission over the area (2); turned to face down from y = 5.
    assert!((radiance - Vec3::splat(1.5)).length() < 1e-6);
    assert!((edge_u.cross(edge_v).normalize() - Vec3::NEG_Y).length() < 1e-5, "{}", edge_u.cross(edge_v));
    assert!((corner + 0.5 * (edge_u + edge_v) - Vec3::new(0.0, 5.0, 0.0)).length() < 1e-5);
    let LightSource::Inline(Light::Quad { edge_u, edge_v, radiance, .. }) = s.contents.lights[1] else { panic!() };
    // A disk of radius 0.5 as a square of the same area, 4 × 2^1 bright.
    assert!((edge_u.cross(edge_v).length() - std::f32::consts::PI * 0.25).abs() < 1e-5);
    assert_eq!(radiance, Vec3::splat(8.0));
    let LightSource::Inline(Light::Sphere { radius, radiance, .. }) = s.contents.lights[2] else { panic!() };
    assert_eq!(radius, 0.5);
    assert!((radiance * std::f32::consts::PI - Vec3::new(10.0, 5.0, 2.5)).length() < 1e-4, "{radiance}");
    // A 2° sun: its irradiance (radiance × solid angle) is the intensity.
    let LightSource::Inline(Light::Sun { radiance, cos_max, .. }) = s.contents.lights[3] else { panic!() };
    assert!((cos_max - 1f32.to_radians().cos()).abs() < 1e-7);
    let irradiance = radiance * std::f32::consts::TAU * (1.0 - cos_max);
    assert!((irradiance - Vec3::splat(5.0)).length() < 1e-3, "{irradiance}");
    // A delta light, with an attribute spelled as before `inputs:`.
    assert_eq!(s.contents.lights[4], Light::Distant { direction: Vec3::Z, irradiance: Vec3::splat(2.0) }.into());
    assert_eq!(s.contents.lights[5], Light::Environment { radiance: Vec3::splat(0.5), camera_visibility: 1.0 }.into());
    // Its texture is missing: lit by its colour, said so with the file's name.
    assert!(s.warnings.iter().any(|w| w.contains("dome texture `sky.exr` is missing")), "{:?}", s.warnings);
    // Arnold-USD's camera weight: hidden from the camera, lighting as before.
    assert_eq!(s.contents.lights[6], Light::Environment { radiance: Vec3::splat(2.0), camera_visibility: 0.0 }.into());
}

#[test]
fn arnold_light_primvars_tress_cannot_apply_are_said_once_per_attribute() {
    let body = r#"
def RectLight "Rect" { float primvars:arnold:diffuse = 0  float primvars:arnold:camera = 0.5 }
def SphereLight "Bulb" {
    float primvars:arnold:diffuse = 0.5
    bool primvars:arnold:cast_shadows = 0
    bool primvars:arnold:visibility:camera = 0 (interpolation = "constant")
}
def DomeLight "Sky" { float primvars:arnold:camera = 0  float primvars:arnold:specular = 1 }
def DistantLight "Sun" { float primvars:arnold:camera = 0  uchar primvars:arnold:visibility = 0 }
"#;
    let s = read_body(body);
    let has = |needle: &str| s.warnings.iter().filter(|w| w.contains(needle)).collect::<Vec<_>>();
    // Each light is still read, lighting as it would without them.
    assert_eq!(s.contents.lights.len(), 4, "{:?}", s.warnings);
    assert_eq!(s.contents.lights[2], Light::Environment { radiance: Vec3::ONE, camera_visibility: 0.0 }.into());
    let diffuse = has("`primvars:arnold:diffuse` other than 1: not applied");
    assert_eq!(diffuse.len(), 1, "{:?}", s.warnings);
    assert!(diffuse[0].ends_with("(2; first: /Rect)"), "{diffuse:?}");
    // Camera weights are honoured (an area light's by default 0, as Arnold's), and a
    // specular weight of 1 is what tress does.
    assert!(has("`primvars:arnold:camera` other than 1").is_empty(), "{:?}", s.warnings);
    let seen = |i: usize| match &s.contents.lights[i] {
        LightSource::Inline(l) => l.camera_visibility(),
        other => panic!("{other:?}"),
    };
    assert_eq!((seen(0), seen(1), seen(3)), (0.5, 0.0, 1.0));
    assert!(has("primvars:arnold:specular").is_empty(), "{:?}", s.warnings);
    assert_eq!(has("`primvars:arnold:cast_shadows` off: their shadows are cast (1; first: /Bulb)").len(), 1);
    let rays = has("Arnold ray visibility primvars on lights: not applied");
    assert_eq!(rays.len(), 1, "{:?}", s.warnings);
    assert!(rays[0].ends_with("(2; first: /Bulb: primvars:arnold:visibility:camera)"), "{rays:?}");
}

#[test]
fn cylinder_lights_are_rows_of_spheres_with_their_side_area_and_power() {
    let body = r#"
def CylinderLight "Tube" {
    float inputs:length = 4
    float inputs:radius = 0.5
    float inputs:intensity = 3
    bool inputs:normalize = 1
    double3 xformOp:translate = (0, 2, 0)
    float xformOp:rotateZ = 90
    uniform token[] xformOpOrder = ["xformOp:translate", "xformOp:rotateZ"]
}
def CylinderLight "Stub" { float inputs:length = 1.5 float inputs:radius = 0.5 }
"#;
    let s = read_body(body);
    let spheres = |range: std::ops::Range<usize>| -> Vec<(Vec3, f32, Vec3)> {
        s.contents.lights[range]
            .iter()
            .map(|l| match l {
                LightSource::Inline(Light::Sphere { center, radius, radiance, .. }) => (*center, *radius, *radiance),
                other => panic!("{other:?}"),
            })
            .collect()
    };
    // 4 long, radius 0.5: four spheres of radius 0.5 (4 · 4π · 0.25 = 2π · 0.5 · 4), their
    // centres along the turned axis (+Y) from y = 0.5 to 3.5, radiance 3 over the side's 4π.
    assert_eq!(s.contents.lights.len(), 4 + 2);
    let tube = spheres(0..4);
    for (k, (c, r, radiance)) in tube.iter().enumerate() {
        assert!((*c - Vec3::new(0.0, 0.5 + k as f32, 0.0)).length() < 1e-5, "{c}");
        assert!((r - 0.5).abs() < 1e-6);
        assert!((*radiance - Vec3::splat(3.0 / (4.0 * std::f32::consts::PI))).length() < 1e-6);
    }
    // 1.5 long: rounded to two spheres, smaller so that their area is still the side's,
    // at the unnormalized radiance 1.
    let stub = spheres(4..6);
    let area: f32 = stub.iter().map(|(_, r, _)| 4.0 * std::f32::consts::PI * r * r).sum();
    assert!((area - std::f32::consts::TAU * 0.5 * 1.5).abs() < 1e-4, "{area}");
    assert!(stub.iter().all(|(_, _, l)| *l == Vec3::ONE));
    assert!((stub[0].0.x + 0.375).abs() < 1e-6 && (stub[1].0.x - 0.375).abs() < 1e-6);
}

#[test]
fn nurbs_curves_are_evaluated_with_their_knots() {
    // A clamped cubic with four points is the Bézier curve of those points.
    let body = r#"def NurbsCurves "N" {
        int[] curveVertexCounts = [4, 2]
        int[] order = [4, 2]
        double[] knots = [0, 0, 0, 0, 1, 1, 1, 1, 0, 0, 1, 1]
        point3f[] points = [(0, 0, 0), (0, 1, 0), (1, 1, 0), (1, 0, 0), (3, 0, 0), (3, 2, 0)]
        float[] widths = [0.4, 0.4, 0.0, 0.0, 0.2, 0.2] (interpolation = "vertex")
    }"#;
    let s = read_body(body);
    let c = strands(&s, 0);
    assert_eq!(c.offsets, vec![0, PIECES_PER_SEGMENT as u32 + 1, PIECES_PER_SEGMENT as u32 + 3]);
    let mid = point(c, PIECES_PER_SEGMENT / 2);
    // The Bézier midpoint (P0 + 3 P1 + 3 P2 + P3) / 8 = (0.5, 0.75, 0).
    assert!((mid - Vec3::new(0.5, 0.75, 0.0)).length() < 1e-5, "{mid}");
    // Widths through the same basis: (0.4 + 1.2 + 0 + 0) / 8 = 0.2 wide at the middle.
    assert!((c.points[PIECES_PER_SEGMENT / 2][3] - 0.1).abs() < 1e-6);
    assert_eq!(c.points[PIECES_PER_SEGMENT + 2], [3.0, 2.0, 0.0, 0.1]);
    // Orders that do not fit the knots: drawn through the points, as USD's renderer does.
    let s = read_body(&body.replace("[4, 2]\n        double", "[3, 2]\n        double"));
    let c = strands(&s, 0);
    assert_eq!(c.offsets, vec![0, 4, 6]);
    assert_eq!(point(c, 2), Vec3::new(1.0, 1.0, 0.0));
    assert!(s.warnings.iter().any(|w| w.contains("do not fit")), "{:?}", s.warnings);
}

#[test]
fn widths_follow_usd_conventions() {
    let curve = |widths: &str| {
        format!(
            "def BasisCurves \"C\" {{ uniform token type = \"linear\" int[] curveVertexCounts = [2, 2]
            point3f[] points = [(0, 0, 0), (0, 1, 0), (1, 0, 0), (1, 1, 0)] {widths} }}"
        )
    };
    // One value without interpolation: constant.
    let s = read_body(&curve("float[] widths = [0.5]"));
    assert!(strands(&s, 0).points.iter().all(|p| p[3] == 0.25));
    // No widths: USD's fallback of one unit, reported once for all the prims.
    let s = read_body(&format!("{}\n{}", curve(""), curve("").replace("\"C\"", "\"D\"")));
    assert!(strands(&s, 1).points.iter().all(|p| p[3] == 0.5));
    let w: Vec<_> = s.warnings.iter().filter(|w| w.contains("without `widths`")).collect();
    assert_eq!(w.len(), 1, "{:?}", s.warnings);
    assert!(w[0].contains("(2; first: /C)"), "{}", w[0]);
}

#[test]
fn gprims_become_meshes_of_their_size() {
    let body = r#"
def Sphere "S" { double radius = 2 }
def Cube "C" { double size = 3 }
def Cylinder "Y" { double radius = 0.5 double height = 4 uniform token axis = "Y" }
def Cone "K" {}
def Capsule "P" { double radius = 1 double height = 2 uniform token axis = "X" }
"#;
    let s = read_body(body);
    assert_eq!(s.contents.meshes.len(), 5);
    let bounds = |i: usize| {
        let MeshSource::Inline(m) = &s.contents.meshes[i].source else { panic!() };
        let lo = m.positions.iter().fold(Vec3::splat(f32::MAX), |a, p| a.min(*p));
        let hi = m.positions.iter().fold(Vec3::splat(f32::MIN), |a, p| a.max(*p));
        (lo, hi)
    };
    let close = |a: Vec3, b: Vec3| (a - b).length() < 1e-4;
    assert!(close(bounds(0).1, Vec3::splat(2.0)), "{:?}", bounds(0));
    assert!(close(bounds(1).0, Vec3::splat(-1.5)) && close(bounds(1).1, Vec3::splat(1.5)));
    assert!(close(bounds(2).1, Vec3::new(0.5, 2.0, 0.5)), "{:?}", bounds(2));
    // The cone stands along Z by default: radius 1, height 2.
    assert!(close(bounds(3).1, Vec3::new(1.0, 1.0, 1.0)) && close(bounds(3).0, Vec3::new(-1.0, -1.0, -1.0)));
    // The capsule: its hemispheres' centres 2 apart along X, radius 1.
    assert!(close(bounds(4).1, Vec3::new(2.0, 1.0, 1.0)), "{:?}", bounds(4));
}

#[test]
fn meshes_take_the_bound_preview_surface_colour_then_display_color() {
    let body = r#"
def Material "Red" {
    token outputs:surface.connect = </Red/Surface.outputs:surface>
    def Shader "Surface" {
        uniform token info:id = "UsdPreviewSurface"
        color3f inputs:diffuseColor = (0.8, 0.1, 0.1)
        token outputs:surface
    }
}
def Cube "Bound" (prepend apiSchemas = ["MaterialBindingAPI"]) {
    rel material:binding = </Red>
    color3f[] primvars:displayColor = [(0, 0, 1)]
}
def Cube "Plain" { color3f[] primvars:displayColor = [(0, 0, 1)] }
def Cube "Grey" {}
"#;
    let s = read_body(body);
    let colors: Vec<_> = s.contents.meshes.iter().map(|m| m.material.clone()).collect();
    assert_eq!(
        colors,
        vec![
            Material::Diffuse { color: Vec3::new(0.8, 0.1, 0.1) }.into(),
            Material::Diffuse { color: Vec3::new(0.0, 0.0, 1.0) }.into(),
            Material::Diffuse { color: Vec3::splat(0.5) }.into(),
        ]
    );
}

#[test]
fn stage_units_and_up_axis() {
    let body = r#"def Xform "W" { double3 xformOp:translate = (0, 0, 2) uniform token[] xformOpOrder = ["xformOp:translate"]
        def Sphere "S" { double radius = 1 } }"#;
    // Geometry stays in the stage's unit, and Z-up turns Y-up: +Z becomes +Y.
    let s = read_with("metersPerUnit = 0.01\nupAxis = \"Z\"", body, &ImportOptions::default()).unwrap();
    let p = s.contents.meshes[0].transform.transform_point3(Vec3::ZERO);
    assert!((p - Vec3::new(0.0, 2.0, 0.0)).length() < 1e-6, "{p}");
}

#[test]
fn what_is_not_read_is_reported_once_per_kind_with_a_count() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("scene.usda");
    let text = r#"#usda 1.0
(
    subLayers = [@missing_layer.usda@]
)
def Volume "P1" {}
def Volume "P2" {}
def SkelRoot "Rig" {
    def Skeleton "Bones" {}
    def Mesh "Skin" (prepend apiSchemas = ["SkelBindingAPI"]) {
        rel skel:skeleton = </Rig/Bones>
        int[] faceVertexCounts = [3]
        int[] faceVertexIndices = [0, 1, 2]
        point3f[] points = [(0, 0, 0), (1, 0, 0), (0, 1, 0)]
    }
}
def Xform "Ref" (references = @gone.usda@) {}
"#;
    std::fs::write(&path, text).unwrap();
    let s = read_usd(&path, &ImportOptions::default()).unwrap();
    let has = |needle: &str| s.warnings.iter().filter(|w| w.contains(needle)).count();
    assert_eq!(has("`Volume` prims: not read (2; first: /P1)"), 1, "{:?}", s.warnings);
    // Skeletons are read by the prims bound to them; this binding lacks its influences.
    assert_eq!(has("`SkelRoot` prims") + has("`Skeleton` prims"), 0, "{:?}", s.warnings);
    assert_eq!(
        has("UsdSkel bindings that cannot be evaluated: drawn in the rest pose (1; first: /Rig/Skin: "),
        1,
        "{:?}",
        s.warnings
    );
    assert!(s.warnings.iter().any(|w| w.contains("composition") && w.contains("missing_layer")), "{:?}", s.warnings);
    assert!(
        s.warnings.iter().any(|w| w.contains("files that are missing") && w.contains("gone.usda")),
        "{:?}",
        s.warnings
    );
    assert_eq!(has("missing_layer"), 1, "{:?}", s.warnings);
    assert_eq!(s.contents.meshes.len(), 1);
}

#[test]
fn arcs_back_to_their_own_prim_are_an_error_naming_the_chain() {
    for (body, chain) in [
        ("def Xform \"A\" (inherits = </A>) {}", "/A -> /A"),
        ("def Xform \"A\" (prepend references = </B>) {}\ndef Xform \"B\" (specializes = </A>) {}", "/A -> /B -> /A"),
        ("def Xform \"A\" {\n def Xform \"C\" (inherits = </A>) {}\n}", "/A/C -> /A"),
    ] {
        let e = read_with("", body, &ImportOptions::default()).unwrap_err().to_string();
        assert!(e.contains("cycle") && e.contains(chain), "{body}: {e}");
    }
    // Arcs between distinct prims are fine.
    let s = read_body("class \"Base\" { double radius = 3 }\ndef Sphere \"S\" (inherits = </Base>) {}");
    assert_eq!(s.contents.meshes.len(), 1);
}

/// A dictionary in a prim's metadata (`customData`, `variants`) opens braces before the
/// prim's body; the prim's children are still its own, and a variant's arcs its prim's.
#[test]
fn arcs_under_dictionary_metadata_and_in_variants_belong_to_their_prim() {
    // `/i/a` references the root prim `/a`.
    let child = r#"#usda 1.0
over Xform "a"
{
}
over Xform "i" (
    customData = {
        string s = "x"
    }
)
{
    def Xform "a" (
        references = </a>
    )
    {
    }
}
"#;
    // A variant of `/world/opt` references its sibling.
    let variant = r#"#usda 1.0
def Xform "world"
{
    def Xform "target"
    {
    }
    def "opt" (
        variants = {
            string state = "unloaded"
        }
        add variantSets = "state"
    )
    {
        variantSet "state" = {
            "unloaded" {
            }
            "loaded" (
                references = </world/target>
            ) {
            }
        }
    }
}
"#;
    for text in [child, variant] {
        if let Err(e) = read_text(text) {
            panic!("{text}: {e}");
        }
    }
}

#[test]
fn cycles_under_dictionary_metadata_and_through_variants_are_still_errors() {
    let child = r#"def Xform "A" (
    customData = {
        string s = "} {"
        dictionary d = { int n = 1 }
    }
)
{
    def Xform "B" (
        references = </A>
    )
    {
    }
}"#;
    let variant = r#"def Xform "A" (
    variants = {
        string v = "on"
    }
    prepend variantSets = "v"
)
{
    variantSet "v" = {
        "on" (
            references = </A>
        ) {
        }
    }
}"#;
    for (body, chain) in [(child, "/A/B -> /A"), (variant, "/A -> /A")] {
        let e = read_with("", body, &ImportOptions::default()).unwrap_err().to_string();
        assert!(e.contains("composition arcs form a cycle") && e.contains(chain), "{body}: {e}");
    }
}

/// `text` written by the crate as a binary crate layer (`usdc`) or package (`usdz`).
fn binary_copy(text: &str, dir: &Path, ext: &str) -> std::path::PathBuf {
    let src = dir.join("src.usda");
    std::fs::write(&src, text).unwrap();
    let stage = Stage::open(src.to_str().unwrap()).unwrap();
    let out = dir.join(format!("scene.{ext}"));
    stage.root_layer().export(out.to_str().unwrap()).unwrap();
    out
}

#[test]
fn binary_crate_files_and_packages_read_like_text() {
    let dir = tempfile::tempdir().unwrap();
    let text = read_text(SCENE).unwrap();
    for ext in ["usdc", "usdz"] {
        let path = binary_copy(SCENE, dir.path(), ext);
        let bytes = std::fs::read(&path).unwrap();
        assert!(bytes.starts_with(if ext == "usdc" { b"PXR-USDC" } else { b"PK\x03\x04" }), "{ext}");
        let s = read_usd(&path, &ImportOptions::default()).unwrap();
        assert_eq!((s.contents.hair.len(), s.contents.meshes.len(), s.contents.lights.len()), (2, 1, 1), "{ext}");
        assert_eq!(strands(&s, 0).points, strands(&text, 0).points, "{ext}");
        assert_eq!(strands(&s, 1).colors, strands(&text, 1).colors, "{ext}");
    }
}

/// How many of the damaged copies of the binary layer `good` are refused: cut short every
/// `cut_step` bytes, and with each 8 bytes at a multiple of 4 replaced by a huge count, a
/// negative offset or zeros. Each is read as `path`; a refusal must be an error naming it
/// (a read is fine too), never a panic, an abort on an impossible allocation or a stack
/// overflow.
pub(super) fn damaged_copies_refused(good: &[u8], path: &Path, cut_step: usize) -> usize {
    let read = |bytes: &[u8]| {
        std::fs::write(path, bytes).unwrap();
        match read_usd(path, &ImportOptions::default()) {
            Ok(_) => true,
            Err(e) => {
                assert!(e.to_string().starts_with(&path.display().to_string()), "{e}");
                false
            }
        }
    };
    assert!(read(good));
    let mut refused = 0;
    for cut in (0..good.len()).step_by(cut_step) {
        refused += !read(&good[..cut]) as usize;
    }
    for at in (0..good.len().saturating_sub(8)).step_by(4) {
        for v in [1u64 << 40, u64::MAX, 0, 0x7fff_ffff_ffff] {
            let mut bad = good.to_vec();
            bad[at..at + 8].copy_from_slice(&v.to_le_bytes());
            refused += !read(&bad) as usize;
        }
    }
    refused
}

/// Damaged binary crate files are errors naming the file, never aborts.
#[test]
fn damaged_binary_crate_files_are_errors_not_aborts() {
    let dir = tempfile::tempdir().unwrap();
    let good = std::fs::read(binary_copy(&format!("{SCENE}\n{ANIMATED}"), dir.path(), "usdc")).unwrap();
    let path = dir.path().join("damaged.usdc");
    let refused = damaged_copies_refused(&good, &path, 13);
    assert!(refused > good.len() / 4, "{refused} of {} damaged files refused", good.len());
    // A file of this layout marked as an older version is refused as damaged, naming
    // the version it claims (its sections do not parse in that version's layout).
    let mut old = good.clone();
    old[8..11].copy_from_slice(&[0, 3, 0]);
    std::fs::write(&path, &old).unwrap();
    let e = read_usd(&path, &ImportOptions::default()).unwrap_err().to_string();
    assert!(e.contains("crate version 0.3.0"), "{e}");
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, ..ProptestConfig::default() })]

    /// The number, type-name and arc-cycle passes and the time-sample, camera and arc
    /// readers, given damaged input: errors, never a panic or a hang.
    #[test]
    fn mutated_new_forms_never_panic(edits in prop::collection::vec((0usize..ANIMATED.len(), prop::sample::select(&b"0123456789-.e<>/@[](){} =\nVec3fPoint"[..])), 1..6)) {
        let mut bytes = format!("{ANIMATED}\n{CAMERAS}\ndef Xform \"Z\" (inherits = </Rig>) {{}}").into_bytes();
        for (at, c) in edits {
            let at = at.min(bytes.len() - 1);
            bytes[at] = c;
        }
        let _ = read_with("", &String::from_utf8_lossy(&bytes), &ImportOptions { frame: Some(5), camera: None, ..Default::default() });
    }
}

#[test]
fn arcs_through_other_files_back_to_their_prim_are_an_error_naming_the_chain() {
    let dir = tempfile::tempdir().unwrap();
    let write = |name: &str, text: &str| {
        let p = dir.path().join(name);
        std::fs::write(&p, format!("#usda 1.0\n{text}")).unwrap();
        p
    };
    let read = |p: &Path| read_usd(p, &ImportOptions::default());
    // Sublayers that include each other.
    let a = write("a.usda", "(\n    subLayers = [\n        @./b.usda@\n    ]\n)\n");
    write("b.usda", "(\n    subLayers = [@a.usda@]\n)\n");
    let e = read(&a).unwrap_err().to_string();
    assert!(e.contains("sublayers form a cycle") && e.contains("a.usda -> ") && e.contains("b.usda -> "), "{e}");
    // References that come back to the prim they start from, one through a default prim.
    let a = write("ra.usda", "def Xform \"A\" (\n    references = @rb.usda@</B>\n) {}\n");
    write("rb.usda", "(\n    defaultPrim = \"B\"\n)\ndef Xform \"B\" (payload = @./ra.usda@</A>) {}\n");
    let e = read(&a).unwrap_err().to_string();
    assert!(e.contains("composition arcs form a cycle: /A -> ") && e.contains("rb.usda</B> -> /A"), "{e}");
    // Two prims of the same file, and one file referenced twice, are no cycle.
    let a = write(
        "fine.usda",
        "def \"A\" (references = @parts.usda@</Ball>) {}\ndef \"C\" (references = @parts.usda@</Ball>) {}\n\
         def Xform \"Y\" {}\n",
    );
    write("parts.usda", "def Sphere \"Ball\" (references = @fine.usda@</Y>) {}\n");
    let s = read(&a).unwrap();
    assert_eq!(s.contents.meshes.len(), 2, "{:?}", s.warnings);
}

#[test]
fn primvars_whose_count_does_not_fit_their_interpolation_are_refitted_or_left_out() {
    // Two curves of 4 points; widths authored as `constant` with one value per curve (as
    // Maya's exporter writes batches), and as `varying` with one value.
    let curves = |widths: &str| {
        format!(
            "def BasisCurves \"C\" {{\n    uniform token type = \"linear\"\n    int[] curveVertexCounts = [4, 4]\n    \
             point3f[] points = [(0,0,0),(0,1,0),(0,2,0),(0,3,0),(1,0,0),(1,1,0),(1,2,0),(1,3,0)]\n    {widths}\n}}\n"
        )
    };
    let radii = |s: &Imported| strands(s, 0).points.iter().map(|p| p[3]).collect::<Vec<_>>();
    let s = read_body(&curves("float[] widths = [0.2, 0.4] (interpolation = \"constant\")"));
    assert_eq!(radii(&s), [0.1, 0.1, 0.1, 0.1, 0.2, 0.2, 0.2, 0.2]);
    assert!(
        s.warnings.iter().any(|w| w.contains("widths whose count does not fit") && w.contains("Uniform")),
        "{:?}",
        s.warnings
    );
    let s = read_body(&curves("float[] widths = [0.2] (interpolation = \"varying\")"));
    assert!(radii(&s).iter().all(|&r| r == 0.1), "{:?}", radii(&s));
    // Three widths fit nothing: left out (the schema's fallback width), said so.
    let s = read_body(&curves("float[] widths = [0.2, 0.4, 0.6] (interpolation = \"vertex\")"));
    assert!(radii(&s).iter().all(|&r| r == 0.5), "{:?}", radii(&s));
    assert!(
        s.warnings.iter().any(|w| w.contains("widths whose count fits no interpolation (3 where Vertex needs 8)")),
        "{:?}",
        s.warnings
    );
}

#[test]
fn clipping_ranges_scale_with_the_camera_and_bad_ones_are_errors() {
    let cam = |xform: &str, range: &str| {
        format!(
            "def Camera \"C\" {{\n    {xform}\n    float2 clippingRange = {range}\n}}\ndef Sphere \"Ball\" {{ double3 xformOp:translate = (0, 0, -5)\n uniform token[] xformOpOrder = [\"xformOp:translate\"] }}"
        )
    };
    let scaled =
        cam("double3 xformOp:scale = (2, 2, 2)\n    uniform token[] xformOpOrder = [\"xformOp:scale\"]", "(0.5, 20)");
    let s = read_with("", &scaled, &ImportOptions::default()).unwrap();
    assert_eq!(s.camera.unwrap().clip, [1.0, 40.0]);
    // A Z-up stage turns the camera; its clip distances stay.
    let s = read_with("upAxis = \"Z\"", &cam("", "(0.5, 20)"), &ImportOptions::default()).unwrap();
    assert_eq!(s.camera.unwrap().clip, [0.5, 20.0]);
    for bad in ["(5, 1)", "(-1, 10)", "(0, 0)"] {
        let e = read_with("", &cam("", bad), &ImportOptions::default()).unwrap_err().to_string();
        assert!(e.contains("clippingRange") && e.contains("/C"), "{bad}: {e}");
    }
}

#[test]
fn layers_of_another_unit_are_read_as_authored_and_said() {
    let dir = tempfile::tempdir().unwrap();
    let asset = |mpu: &str| {
        format!(
            "#usda 1.0\n(\n    defaultPrim = \"Hair\"\n    {mpu}\n)\ndef BasisCurves \"Hair\" {{\n    uniform token type = \"linear\"\n    int[] curveVertexCounts = [2]\n    point3f[] points = [(0, 0, 0), (0, 10, 0)]\n    float[] widths = [0.1] (interpolation = \"constant\")\n}}\n"
        )
    };
    std::fs::write(dir.path().join("mm.usda"), asset("metersPerUnit = 0.001")).unwrap();
    std::fs::write(dir.path().join("cm.usda"), asset("metersPerUnit = 0.01")).unwrap();
    // A new stage file each time: a rewritten one could be taken for the one already read.
    let count = std::cell::Cell::new(0);
    let stage = |mpu: &str, file: &str| {
        count.set(count.get() + 1);
        let path = dir.path().join(format!("stage{}.usda", count.get()));
        std::fs::write(
            &path,
            format!("#usda 1.0\n(\n    {mpu}\n)\ndef \"Groom\" (\n    references = @./{file}@\n) {{}}\n"),
        )
        .unwrap();
        read_usd(&path, &ImportOptions::default()).unwrap()
    };
    let height = |s: &Imported| match &s.contents.hair[0].source {
        HairSource::Inline(set) => set.points.iter().map(|p| p[1]).fold(0.0, f32::max),
        HairSource::File(_) => panic!("inline"),
    };
    // A millimetre asset in a metre stage: drawn 10 units tall, as USD composes it, and said.
    let s = stage("metersPerUnit = 1", "mm.usda");
    assert_eq!(height(&s), 10.0);
    let w: Vec<_> = s.warnings.iter().filter(|w| w.contains("metersPerUnit")).collect();
    assert!(w.len() == 1 && w[0].contains("mm.usda at 0.001") && w[0].contains("stage's 1"), "{:?}", s.warnings);
    // The same unit, or a stage without one taking UsdGeom's centimetres: nothing to say.
    for (mpu, file) in [("metersPerUnit = 0.001", "mm.usda"), ("", "cm.usda")] {
        let s = stage(mpu, file);
        assert_eq!(height(&s), 10.0);
        assert!(s.warnings.iter().all(|w| !w.contains("metersPerUnit")), "{mpu}: {:?}", s.warnings);
    }
}

#[test]
fn curves_take_the_bound_arnold_standard_hair() {
    // As Arnold-USD writes it: the material's `outputs:arnold:surface` leads to the shader,
    // a preview surface on `outputs:surface` is for other renderers.
    let body = r#"
def Material "Hair" {
    token outputs:arnold:surface.connect = </Hair/standard_hair>
    token outputs:surface.connect = </Hair/Preview.outputs:surface>
    def Shader "standard_hair" {
        uniform token info:id = "arnold:standard_hair"
        float inputs:melanin = 0.1
        color3f inputs:base_color = (1, 0, 0)
        float inputs:roughness = 0.3
        bool inputs:roughness_anisotropic = 1
        float inputs:roughness_azimuthal = 0.6
        color3f inputs:specular_tint = (0.5, 0.5, 0.5)
        token outputs:out
    }
    def Shader "Preview" {
        uniform token info:id = "UsdPreviewSurface"
        color3f inputs:diffuseColor = (0, 1, 0)
        token outputs:surface
    }
}
def BasisCurves "Bound" (prepend apiSchemas = ["MaterialBindingAPI"]) {
    rel material:binding = </Hair>
    uniform token type = "linear"
    int[] curveVertexCounts = [2]
    point3f[] points = [(0, 0, 0), (0, 1, 0)]
    float[] widths = [0.1] (interpolation = "constant")
}
def BasisCurves "Plain" {
    uniform token type = "linear"
    int[] curveVertexCounts = [2]
    point3f[] points = [(1, 0, 0), (1, 1, 0)]
    float[] widths = [0.1] (interpolation = "constant")
}
"#;
    let s = read_body(body);
    let expected = StandardHair {
        melanin: 0.1,
        base_color: Vec3::new(1.0, 0.0, 0.0),
        roughness: 0.3,
        roughness_anisotropic: true,
        roughness_azimuthal: 0.6,
        specular_tint: Vec3::splat(0.5),
        ..StandardHair::default()
    }
    .material("/Hair/standard_hair", &[]);
    assert!(matches!(expected.0, Material::Physical(_)), "{:?}", expected.0);
    assert_eq!(s.contents.hair[0].material, expected.0.into());
    // The tint tress cannot draw is said, naming the shader.
    let note = expected.1.expect("specular_tint is left out");
    let (shader, left_out) = note.split_once(": ").unwrap();
    assert!(
        s.warnings.iter().any(|w| w.contains(left_out) && w.contains(&format!("first: {shader}"))),
        "{:?}",
        s.warnings
    );
    // Unbound curves keep their tube shading.
    assert!(matches!(s.contents.hair[1].material, MaterialSource::Inline(Material::Tube(_))));
}

/// A two-joint skeleton under a moved `SkelRoot`: `A` at the origin, `B` one up, whose
/// animation turns `B` about Z from 0 at time 0 to 90 degrees at time 10. `{anim_on_skel}`
/// and `{anim_on_root}` place the `skel:animationSource` binding; `{prims}` are the skinned
/// prims, under an Xform whose transform skinning replaces.
const SKEL: &str = r#"def SkelRoot "Rig" {
    double3 xformOp:translate = (10, 0, 0)
    uniform token[] xformOpOrder = ["xformOp:translate"]
    {anim_on_root}
    def Skeleton "Skel" (prepend apiSchemas = ["SkelBindingAPI"]) {
        uniform token[] joints = ["A", "A/B"]
        uniform matrix4d[] bindTransforms = [((1,0,0,0),(0,1,0,0),(0,0,1,0),(0,0,0,1)), ((1,0,0,0),(0,1,0,0),(0,0,1,0),(0,1,0,1))]
        uniform matrix4d[] restTransforms = [((1,0,0,0),(0,1,0,0),(0,0,1,0),(0,0,0,1)), ((1,0,0,0),(0,1,0,0),(0,0,1,0),(0,1,0,1))]
        {anim_on_skel}
    }
    def SkelAnimation "Anim" {
        uniform token[] joints = ["A/B", "NotInTheSkeleton"]
        float3[] translations = [(0, 1, 0), (0, 0, 0)]
        quatf[] rotations.timeSamples = { 0: [(1, 0, 0, 0), (1, 0, 0, 0)], 10: [(0.70710678, 0, 0, 0.70710678), (1, 0, 0, 0)] }
        half3[] scales = [(1, 1, 1), (1, 1, 1)]
    }
    def Xform "Geo" {
        double3 xformOp:translate = (0, 0, 50)
        uniform token[] xformOpOrder = ["xformOp:translate"]
        {prims}
    }
}
"#;

/// Linear curves `name` of two points, (0, 1, 0) on joint B and (0, 2, 0) one above it,
/// bound to the skeleton with `extra` attributes.
fn skinned_curve(name: &str, extra: &str) -> String {
    format!(
        r#"def BasisCurves "{name}" (prepend apiSchemas = ["SkelBindingAPI"]) {{
            rel skel:skeleton = </Rig/Skel>
            uniform token type = "linear"
            int[] curveVertexCounts = [2]
            point3f[] points = [(0, 1, 0), (0, 2, 0)]
            float[] widths = [0.1] (interpolation = "constant")
            {extra}
        }}"#
    )
}

/// The SKEL stage with `prims`, the animation bound on the Skeleton, at `frame`.
fn read_skel(prims: &str, frame: u32) -> Imported {
    read_skel_with(prims, "rel skel:animationSource = </Rig/Anim>", "", frame)
}

fn read_skel_with(prims: &str, on_skel: &str, on_root: &str, frame: u32) -> Imported {
    let body = SKEL.replace("{prims}", prims).replace("{anim_on_skel}", on_skel).replace("{anim_on_root}", on_root);
    read_with("", &body, &ImportOptions { frame: Some(frame), camera: None, ..Default::default() }).unwrap()
}

/// The world positions of hair entry `i`'s points.
fn world_points(s: &Imported, i: usize) -> Vec<Vec3> {
    let e = &s.contents.hair[i];
    let set = strands(s, i);
    (0..set.points.len()).map(|k| e.transform.transform_point3(point(set, k))).collect()
}

fn assert_near(got: &[Vec3], want: &[Vec3], s: &Imported) {
    assert_eq!(got.len(), want.len());
    for (g, w) in got.iter().zip(want) {
        assert!((*g - *w).length() < 1e-4, "{got:?} != {want:?} ({:?})", s.warnings);
    }
}

#[test]
fn skinned_curves_follow_the_skeleton_animation_at_the_frame() {
    let h = std::f32::consts::FRAC_1_SQRT_2;
    let prim = skinned_curve(
        "Hair",
        r#"int[] primvars:skel:jointIndices = [1, 1] (interpolation = "vertex" elementSize = 1)
           float[] primvars:skel:jointWeights = [1, 1] (interpolation = "vertex" elementSize = 1)"#,
    );
    // The SkelRoot's (10, 0, 0) places the skeleton; the Xform's (0, 0, 50) above the
    // curves no longer applies. B turns the point above it about Z: 0, 45 (slerp) and 90
    // degrees; after the samples the pose is held.
    // At frame 3, 27 degrees: a slerp, where a normalised lerp would give 26.2.
    let (s27, c27) = 27f32.to_radians().sin_cos();
    let poses = [
        (0, Vec3::new(10.0, 2.0, 0.0)),
        (3, Vec3::new(10.0 - s27, 1.0 + c27, 0.0)),
        (5, Vec3::new(10.0 - h, 1.0 + h, 0.0)),
        (10, Vec3::new(9.0, 1.0, 0.0)),
        (20, Vec3::new(9.0, 1.0, 0.0)),
    ];
    for (frame, top) in poses {
        let s = read_skel(&prim, frame);
        assert_near(&world_points(&s, 0), &[Vec3::new(10.0, 1.0, 0.0), top], &s);
        assert!(!s.warnings.iter().any(|w| w.contains("rest pose")), "{:?}", s.warnings);
        // Widths stay as authored.
        assert!((strands(&s, 0).points[1][3] - 0.05).abs() < 1e-6);
        // Animation joints the skeleton does not have are left out, and said.
        assert!(
            s.warnings.iter().any(|w| w
                .contains("SkelAnimation joints that are not in the bound Skeleton: ignored (1; first: /Rig/Anim)")),
            "{:?}",
            s.warnings
        );
    }
    // Bound on the SkelRoot instead of the Skeleton (the older binding): the same pose.
    let s = read_skel_with(&prim, "", "rel skel:animationSource = </Rig/Anim>", 10);
    assert_near(&world_points(&s, 0), &[Vec3::new(10.0, 1.0, 0.0), Vec3::new(9.0, 1.0, 0.0)], &s);
    // Without an animation: the rest transforms, which are the bind pose.
    let s = read_skel_with(&prim, "", "", 10);
    assert_near(&world_points(&s, 0), &[Vec3::new(10.0, 1.0, 0.0), Vec3::new(10.0, 2.0, 0.0)], &s);
}

#[test]
fn skinning_blends_normalised_weights_and_takes_geom_bind_transforms_and_joint_subsets() {
    let at_10 = |extra: &str| world_points(&read_skel(&skinned_curve("Hair", extra), 10), 0);
    // Two influences a point, weights 1 and 1 normalised to a half each: half way between
    // the point held by A and the point turned by B.
    let two = at_10(
        r#"int[] primvars:skel:jointIndices = [0, 1, 0, 1] (interpolation = "vertex" elementSize = 2)
           float[] primvars:skel:jointWeights = [1, 1, 1, 1] (interpolation = "vertex" elementSize = 2)"#,
    );
    assert!((two[1] - Vec3::new(9.5, 1.5, 0.0)).length() < 1e-4, "{two:?}");
    // `skel:joints` maps index 0 onto the skeleton's `A/B`; constant influences move the
    // whole prim.
    let subset = at_10(
        r#"uniform token[] skel:joints = ["A/B"]
           int[] primvars:skel:jointIndices = [0] (interpolation = "constant" elementSize = 1)
           float[] primvars:skel:jointWeights = [1] (interpolation = "constant" elementSize = 1)"#,
    );
    assert!((subset[1] - Vec3::new(9.0, 1.0, 0.0)).length() < 1e-4, "{subset:?}");
    // A geomBindTransform one up puts the points on B and above it first.
    let bound = at_10(
        r#"matrix4d primvars:skel:geomBindTransform = ((1,0,0,0),(0,1,0,0),(0,0,1,0),(0,1,0,1))
           int[] primvars:skel:jointIndices = [1] (interpolation = "constant" elementSize = 1)
           float[] primvars:skel:jointWeights = [1] (interpolation = "constant" elementSize = 1)"#,
    );
    assert!((bound[0] - Vec3::new(9.0, 1.0, 0.0)).length() < 1e-4, "{bound:?}");
    assert!((bound[1] - Vec3::new(8.0, 1.0, 0.0)).length() < 1e-4, "{bound:?}");
}

#[test]
fn skinned_meshes_and_bindings_inherited_from_ancestors() {
    // The skeleton bound on the SkelRoot, the influences authored on the mesh.
    let mesh = r#"def Mesh "Skin" {
            int[] faceVertexCounts = [3]
            int[] faceVertexIndices = [0, 1, 2]
            point3f[] points = [(0, 1, 0), (0, 2, 0), (1, 1, 0)]
            normal3f[] normals = [(0, 1, 0), (0, 1, 0), (1, 0, 0)] (interpolation = "vertex")
            int[] primvars:skel:jointIndices = [0, 1, 1] (interpolation = "vertex" elementSize = 1)
            float[] primvars:skel:jointWeights = [1, 1, 1] (interpolation = "vertex" elementSize = 1)
        }"#;
    let curve = skinned_curve(
        "Hair",
        r#"int[] primvars:skel:jointIndices = [1] (interpolation = "constant" elementSize = 1)
           float[] primvars:skel:jointWeights = [1] (interpolation = "constant" elementSize = 1)"#,
    );
    let prims = format!("{mesh}\n{curve}");
    let s = read_skel_with(&prims, "rel skel:animationSource = </Rig/Anim>", "rel skel:skeleton = </Rig/Skel>", 10);
    // The skeleton is posed once for both prims: its animation's stray joint is said once.
    assert!(
        s.warnings
            .iter()
            .any(|w| w
                .contains("SkelAnimation joints that are not in the bound Skeleton: ignored (1; first: /Rig/Anim)")),
        "{:?}",
        s.warnings
    );
    assert_near(&world_points(&s, 0), &[Vec3::new(10.0, 1.0, 0.0), Vec3::new(9.0, 1.0, 0.0)], &s);
    let MeshEntry { source: MeshSource::Inline(m), transform, .. } = &s.contents.meshes[0] else { panic!() };
    let got: Vec<Vec3> = m.positions.iter().map(|p| transform.transform_point3(*p)).collect();
    assert_near(&got, &[Vec3::new(10.0, 1.0, 0.0), Vec3::new(9.0, 1.0, 0.0), Vec3::new(10.0, 2.0, 0.0)], &s);
    // Vertex normals turn with their points.
    let normals = m.normals.as_ref().expect("normals");
    assert_near(normals, &[Vec3::Y, -Vec3::X, Vec3::Y], &s);
}

#[test]
fn gprims_with_a_rigid_binding_move_whole() {
    let ball = |influences: &str| {
        format!(
            r#"def Sphere "Ball" (prepend apiSchemas = ["SkelBindingAPI"]) {{
                rel skel:skeleton = </Rig/Skel>
                double radius = 0.5
                matrix4d primvars:skel:geomBindTransform = ((1,0,0,0),(0,1,0,0),(0,0,1,0),(0,2,0,1))
                {influences}
            }}"#
        )
    };
    // Its centre, one above joint B at bind time, turns with B to (-1, 1, 0) in the
    // skeleton's space, (9, 1, 0) in the world.
    let s = read_skel(
        &ball(
            r#"int[] primvars:skel:jointIndices = [1] (interpolation = "constant" elementSize = 1)
               float[] primvars:skel:jointWeights = [1] (interpolation = "constant" elementSize = 1)"#,
        ),
        10,
    );
    let centre = s.contents.meshes[0].transform.transform_point3(Vec3::ZERO);
    assert!((centre - Vec3::new(9.0, 1.0, 0.0)).length() < 1e-4, "{centre} {:?}", s.warnings);
    // Per-point influences have no points to apply to: the rest pose, said.
    let s = read_skel(
        &ball(
            r#"int[] primvars:skel:jointIndices = [1, 1] (interpolation = "vertex" elementSize = 1)
               float[] primvars:skel:jointWeights = [1, 1] (interpolation = "vertex" elementSize = 1)"#,
        ),
        10,
    );
    let centre = s.contents.meshes[0].transform.transform_point3(Vec3::ZERO);
    assert!((centre - Vec3::new(10.0, 0.0, 50.0)).length() < 1e-4, "{centre} {:?}", s.warnings);
    assert!(
        s.warnings
            .iter()
            .any(|w| w.contains("rest pose") && w.contains("per-point joint influences on a prim without points")),
        "{:?}",
        s.warnings
    );
}

#[test]
fn bad_skinning_data_is_one_warning_and_the_rest_pose() {
    let cases = [
        (
            r#"int[] primvars:skel:jointIndices = [1, 5] (interpolation = "vertex" elementSize = 1)
            float[] primvars:skel:jointWeights = [1, 1] (interpolation = "vertex" elementSize = 1)"#,
            "joint index 5 is not one of the 2 joints",
        ),
        (
            r#"int[] primvars:skel:jointIndices = [1, 1, 1] (interpolation = "vertex" elementSize = 1)
            float[] primvars:skel:jointWeights = [1, 1, 1] (interpolation = "vertex" elementSize = 1)"#,
            "3 joint influences where vertex interpolation with elementSize 1 needs 2",
        ),
        (
            r#"int[] primvars:skel:jointIndices = [1, 1] (interpolation = "vertex" elementSize = 1)
            float[] primvars:skel:jointWeights = [1] (interpolation = "vertex" elementSize = 1)"#,
            "2 joint indices and 1 weights",
        ),
        (
            r#"int[] primvars:skel:jointIndices = [1, 1] (interpolation = "vertex" elementSize = 1)
            float[] primvars:skel:jointWeights = [nan, 1] (interpolation = "vertex" elementSize = 1)"#,
            "negative or not finite",
        ),
        (
            r#"int[] primvars:skel:jointIndices = [1, 1] (interpolation = "vertex" elementSize = 1)
            float[] primvars:skel:jointWeights = [0, 1] (interpolation = "vertex" elementSize = 1)"#,
            "the joint weights of point 0 sum to 0",
        ),
        (
            r#"uniform token[] skel:joints = ["A/C"]
            int[] primvars:skel:jointIndices = [0] (interpolation = "constant" elementSize = 1)
            float[] primvars:skel:jointWeights = [1] (interpolation = "constant" elementSize = 1)"#,
            "`skel:joints` names `A/C`",
        ),
        ("", "without `primvars:skel:jointIndices`"),
    ];
    for (extra, why) in cases {
        let s = read_skel(&skinned_curve("Hair", extra), 10);
        let rest = s.warnings.iter().filter(|w| w.contains("drawn in the rest pose")).collect::<Vec<_>>();
        assert_eq!(rest.len(), 1, "{:?}", s.warnings);
        assert!(rest[0].contains("first: /Rig/Geo/Hair: ") && rest[0].contains(why), "{why}: {:?}", s.warnings);
        // The rest pose: the points as authored, under their own transforms.
        assert_near(&world_points(&s, 0), &[Vec3::new(10.0, 1.0, 50.0), Vec3::new(10.0, 2.0, 50.0)], &s);
    }
    let influences = r#"int[] primvars:skel:jointIndices = [1] (interpolation = "constant" elementSize = 1)
        float[] primvars:skel:jointWeights = [1] (interpolation = "constant" elementSize = 1)"#;
    // Targets that are missing or of the wrong type, animation arrays of the wrong size.
    let s = read_skel(
        &skinned_curve("Hair", &format!("rel skel:skeleton = </Rig/Nothing>\n{influences}"))
            .replace("rel skel:skeleton = </Rig/Skel>", ""),
        10,
    );
    assert!(s.warnings.iter().any(|w| w.contains("targets /Rig/Nothing, which is not a Skeleton")), "{:?}", s.warnings);
    let s = read_skel_with(&skinned_curve("Hair", influences), "rel skel:animationSource = </Rig/Geo>", "", 10);
    assert!(
        s.warnings.iter().any(|w| w.contains("targets /Rig/Geo, which is not a SkelAnimation")),
        "{:?}",
        s.warnings
    );
    let body = SKEL.replace("float3[] translations = [(0, 1, 0), (0, 0, 0)]", "float3[] translations = [(0, 1, 0)]");
    let body = body
        .replace("{prims}", &skinned_curve("Hair", influences))
        .replace("{anim_on_skel}", "rel skel:animationSource = </Rig/Anim>")
        .replace("{anim_on_root}", "");
    let s = read_with("", &body, &ImportOptions { frame: Some(10), camera: None, ..Default::default() }).unwrap();
    assert!(s.warnings.iter().any(|w| w.contains("/Rig/Anim: 1 `translations` for 2 joints")), "{:?}", s.warnings);
    // Blend shapes that cannot be applied are said, the skinning still done.
    let s =
        read_skel(&skinned_curve("Hair", &format!("uniform token[] skel:blendShapes = [\"Smile\"]\n{influences}")), 10);
    assert!(
        s.warnings.iter().any(|w| w.contains("blend shapes that cannot be applied: skinned without them")
            && w.contains("1 `skel:blendShapes` for 0 `skel:blendShapeTargets`")),
        "{:?}",
        s.warnings
    );
    assert_near(&world_points(&s, 0), &[Vec3::new(10.0, 1.0, 0.0), Vec3::new(9.0, 1.0, 0.0)], &s);
}

/// The SKEL stage whose animation weighs blend shapes `Up`, `Sparse` and `Tween` (and one
/// no prim uses) with samples at 0, 10 and 20, and the curve `Hair` on joint B with the
/// targets `shapes` (BlendShape prims under it).
fn blend_shape_stage(shapes: &str, frame: u32) -> Imported {
    let anim = r#"half3[] scales = [(1, 1, 1), (1, 1, 1)]
        uniform token[] blendShapes = ["Unused", "Tween", "Sparse", "Up"]
        float[] blendShapeWeights.timeSamples = { 0: [0, 0, 0, 0], 10: [1, 0.25, 1, 0.5], 20: [1, 0.75, 0.5, 1] }"#;
    let hair = skinned_curve(
        "Hair",
        &format!(
            r#"int[] primvars:skel:jointIndices = [1] (interpolation = "constant" elementSize = 1)
            float[] primvars:skel:jointWeights = [1] (interpolation = "constant" elementSize = 1)
            uniform token[] skel:blendShapes = ["Up", "Sparse", "Tween"]
            rel skel:blendShapeTargets = [</Rig/Geo/Hair/Up>, </Rig/Geo/Hair/Sparse>, </Rig/Geo/Hair/Tween>]
            {shapes}"#
        ),
    );
    let body = SKEL
        .replace("half3[] scales = [(1, 1, 1), (1, 1, 1)]", anim)
        .replace("{prims}", &hair)
        .replace("{anim_on_skel}", "rel skel:animationSource = </Rig/Anim>")
        .replace("{anim_on_root}", "");
    read_with("", &body, &ImportOptions { frame: Some(frame), camera: None, ..Default::default() }).unwrap()
}

/// `Up` moves both points along +x, `Sparse` (`pointIndices`) the second along +z, `Tween`
/// the first along +z by 1, with an inbetween of 3 at weight 0.5.
const BLEND_SHAPES: &str = r#"
    def BlendShape "Up" { uniform vector3f[] offsets = [(1, 0, 0), (1, 0, 0)] }
    def BlendShape "Sparse" {
        uniform vector3f[] offsets = [(0, 0, 2)]
        uniform int[] pointIndices = [1]
    }
    def BlendShape "Tween" {
        uniform vector3f[] offsets = [(0, 0, 1), (0, 0, 0)]
        uniform vector3f[] inbetweens:half = [(0, 0, 3), (0, 0, 0)] (weight = 0.5)
    }"#;

#[test]
fn blend_shapes_move_rest_points_by_the_animation_weights_before_skinning() {
    // Joint B turns the rest space 90 degrees about Z at frame 10 and after, about (0, 1, 0),
    // and the SkelRoot moves it to x = 10: (x, y, z) is drawn at (11 - y, 1 + x, z). Offsets
    // along x therefore rise along y: they were added before the skinning.
    let skinned = |p: Vec3| Vec3::new(11.0 - p.y, 1.0 + p.x, p.z);
    let rest = [Vec3::new(0.0, 1.0, 0.0), Vec3::new(0.0, 2.0, 0.0)];
    // (frame, Up, Sparse, Tween's offset of the first point): at 10, Up 0.5 moves half its
    // offset and Tween at 0.25 is half way from rest to the inbetween (1.5, where the
    // primary alone would give 0.25); at 20, Tween at 0.75 is half way from the inbetween
    // to the primary (2); at 15 the weights are blended between the samples (Tween 0.5:
    // the inbetween itself).
    for (frame, up, sparse, tween) in [(10, 0.5, 1.0, 1.5), (20, 1.0, 0.5, 2.0), (15, 0.75, 0.75, 3.0)] {
        let s = blend_shape_stage(BLEND_SHAPES, frame);
        let want = [skinned(rest[0] + Vec3::new(up, 0.0, tween)), skinned(rest[1] + Vec3::new(up, 0.0, 2.0 * sparse))];
        assert_near(&world_points(&s, 0), &want, &s);
        assert!(!s.warnings.iter().any(|w| w.contains("blend shape")), "{:?}", s.warnings);
    }
    // At 0 every weight is 0: the skinned rest points.
    let s = blend_shape_stage(BLEND_SHAPES, 0);
    assert_near(&world_points(&s, 0), &[Vec3::new(10.0, 1.0, 0.0), Vec3::new(10.0, 2.0, 0.0)], &s);
    // Bad targets: said, and the prim skinned without its blend shapes.
    let bad = [
        (BLEND_SHAPES.replace("pointIndices = [1]", "pointIndices = [2]"), "point index 2 is not one of the 2 points"),
        (
            BLEND_SHAPES.replace("offsets = [(0, 0, 2)]", "offsets = [(0, 0, 2), (0, 0, 2)]"),
            "/Rig/Geo/Hair/Sparse: 2 `offsets` for 1 points",
        ),
        (
            BLEND_SHAPES.replace("def BlendShape \"Up\"", "def Xform \"Up\""),
            "names /Rig/Geo/Hair/Up, which is not a BlendShape",
        ),
        (
            BLEND_SHAPES.replace("inbetweens:half = [(0, 0, 3), (0, 0, 0)]", "inbetweens:half = [(0, 0, 3)]"),
            "1 `inbetweens:half` for 2 points",
        ),
    ];
    for (shapes, why) in bad {
        let s = blend_shape_stage(&shapes, 10);
        assert!(
            s.warnings
                .iter()
                .any(|w| w.contains("blend shapes that cannot be applied: skinned without them") && w.contains(why)),
            "{why}: {:?}",
            s.warnings
        );
        assert_near(&world_points(&s, 0), &[Vec3::new(10.0, 1.0, 0.0), Vec3::new(9.0, 1.0, 0.0)], &s);
    }
    // An inbetween without a weight is skipped and said: Tween at 0.25 is then a quarter of
    // the primary.
    let s = blend_shape_stage(&BLEND_SHAPES.replace(" (weight = 0.5)", ""), 10);
    assert!(s.warnings.iter().any(|w| w.contains("inbetween shapes without a weight")), "{:?}", s.warnings);
    assert_near(&world_points(&s, 0)[..1], &[skinned(rest[0] + Vec3::new(0.5, 0.0, 0.25))], &s);
}

#[test]
fn blend_shape_normal_offsets_turn_mesh_normals() {
    // A triangle on joint A (the identity) whose normals (0, 0, 1) the shape's normal
    // offsets (1, 0, -1) at weight 0.5 turn to (0.5, 0, 0.5), renormalised.
    let mesh = r#"def Mesh "Tri" (prepend apiSchemas = ["SkelBindingAPI"]) {
        rel skel:skeleton = </Rig/Skel>
        int[] faceVertexCounts = [3]
        int[] faceVertexIndices = [0, 1, 2]
        point3f[] points = [(0, 0, 0), (1, 0, 0), (0, 1, 0)]
        normal3f[] normals = [(0, 0, 1), (0, 0, 1), (0, 0, 1)] (interpolation = "vertex")
        int[] primvars:skel:jointIndices = [0] (interpolation = "constant" elementSize = 1)
        float[] primvars:skel:jointWeights = [1] (interpolation = "constant" elementSize = 1)
        uniform token[] skel:blendShapes = ["Up"]
        rel skel:blendShapeTargets = </Rig/Geo/Tri/Up>
        def BlendShape "Up" {
            uniform vector3f[] offsets = [(0, 0, 0), (0, 0, 0), (0, 0, 0)]
            uniform vector3f[] normalOffsets = [(1, 0, -1), (1, 0, -1), (1, 0, -1)]
        }
    }"#;
    let anim = r#"half3[] scales = [(1, 1, 1), (1, 1, 1)]
        uniform token[] blendShapes = ["Up"]
        float[] blendShapeWeights = [0.5]"#;
    let body = SKEL
        .replace("half3[] scales = [(1, 1, 1), (1, 1, 1)]", anim)
        .replace("{prims}", mesh)
        .replace("{anim_on_skel}", "rel skel:animationSource = </Rig/Anim>")
        .replace("{anim_on_root}", "");
    let s = read_with("", &body, &ImportOptions { frame: Some(10), camera: None, ..Default::default() }).unwrap();
    let MeshSource::Inline(m) = &s.contents.meshes[0].source else { panic!("an inline mesh") };
    let h = std::f32::consts::FRAC_1_SQRT_2;
    for n in m.normals.as_ref().expect("normals") {
        assert!((*n - Vec3::new(h, 0.0, h)).length() < 1e-5, "{n:?} ({:?})", s.warnings);
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, ..ProptestConfig::default() })]

    /// The skinning reader given damaged skeletons, animations and influences: warnings or
    /// errors, never a panic.
    #[test]
    fn mutated_skinned_scenes_never_panic(edits in prop::collection::vec((0usize..2000, prop::sample::select(&b"0123456789-.e<>/[](){} =\nnan"[..])), 1..6)) {
        let prim = skinned_curve("Hair", r#"int[] primvars:skel:jointIndices = [0, 1, 0, 1] (interpolation = "vertex" elementSize = 2)
            float[] primvars:skel:jointWeights = [1, 1, 1, 1] (interpolation = "vertex" elementSize = 2)"#);
        let body = SKEL.replace("{prims}", &prim).replace("{anim_on_skel}", "rel skel:animationSource = </Rig/Anim>").replace("{anim_on_root}", "");
        let mut bytes = body.into_bytes();
        for (at, c) in edits {
            let at = at % bytes.len();
            bytes[at] = c;
        }
        let _ = read_with("", &String::from_utf8_lossy(&bytes), &ImportOptions { frame: Some(5), camera: None, ..Default::default() });
    }
}

#[test]
fn meshes_take_the_bound_arnold_standard_surface() {
    let body = r#"
def Material "Glass" {
    token outputs:arnold:surface.connect = </Glass/standard_surface>
    def Shader "standard_surface" {
        uniform token info:id = "arnold:standard_surface"
        float inputs:transmission = 1
        float inputs:specular_IOR = 1.33
        float inputs:specular_roughness = 0
        token outputs:out
    }
}
def Mesh "Bound" (prepend apiSchemas = ["MaterialBindingAPI"]) {
    rel material:binding = </Glass>
    int[] faceVertexCounts = [3]
    int[] faceVertexIndices = [0, 1, 2]
    point3f[] points = [(0, 0, 0), (1, 0, 0), (0, 1, 0)]
}
def Mesh "Plain" {
    int[] faceVertexCounts = [3]
    int[] faceVertexIndices = [0, 1, 2]
    point3f[] points = [(0, 0, 1), (1, 0, 1), (0, 1, 1)]
}
"#;
    let s = read_body(body);
    let glass = Material::Glass { ior: 1.33, color: Vec3::ONE };
    assert_eq!(s.contents.meshes[0].material, glass.into());
    assert_eq!(s.contents.meshes[1].material, Material::Diffuse { color: Vec3::splat(0.5) }.into());
}

#[test]
fn arnold_shader_inputs_beyond_single_precision_are_errors_naming_the_input() {
    // A `double` weight or a `color3d` finite in the file, infinite as f32: a colour of
    // 1e39 under a weight of 0 would be NaN. Refused, naming the shader prim and input.
    let stage = |inputs: &str| {
        format!(
            "def Material \"M\" {{\n    token outputs:arnold:surface.connect = </M/s>\n    def Shader \"s\" {{\n        \
             uniform token info:id = \"arnold:lambert\"\n        {inputs}\n        token outputs:out\n    }}\n}}\n\
             def Mesh \"Bound\" (prepend apiSchemas = [\"MaterialBindingAPI\"]) {{\n    rel material:binding = </M>\n    \
             int[] faceVertexCounts = [3]\n    int[] faceVertexIndices = [0, 1, 2]\n    \
             point3f[] points = [(0, 0, 0), (1, 0, 0), (0, 1, 0)]\n}}\n"
        )
    };
    for (inputs, what) in [
        ("double inputs:Kd = 0\n        color3d inputs:Kd_color = (1e39, 0, 0)", "/M/s.inputs:Kd_color"),
        ("double inputs:Kd = -1e39", "/M/s.inputs:Kd"),
    ] {
        let e = read_text(&format!("#usda 1.0\n{}", stage(inputs))).unwrap_err().to_string();
        assert!(e.contains(&format!("`{what}` is beyond single precision")), "{inputs}: {e}");
    }
    let s = read_body(&stage("double inputs:Kd = 1\n        color3d inputs:Kd_color = (1e30, 0, 0)"));
    assert_eq!(s.contents.meshes[0].material, Material::Diffuse { color: Vec3::new(1.0, 0.0, 0.0) }.into());
}

#[test]
fn meshes_take_the_bound_arnold_lambert_and_flat_colours() {
    let mesh = |name: &str, material: &str| {
        format!(
            "def Mesh \"{name}\" (prepend apiSchemas = [\"MaterialBindingAPI\"]) {{\n    rel material:binding = </{material}>\n    \
             int[] faceVertexCounts = [3]\n    int[] faceVertexIndices = [0, 1, 2]\n    \
             point3f[] points = [(0, 0, 0), (1, 0, 0), (0, 1, 0)]\n}}\n"
        )
    };
    let body = format!(
        r#"
def Material "Clay" {{
    token outputs:arnold:surface.connect = </Clay/lambert>
    def Shader "lambert" {{
        uniform token info:id = "arnold:lambert"
        float inputs:Kd = 0.5
        color3f inputs:Kd_color = (1, 0.5, 0)
    }}
}}
def Material "Green" {{
    float4 outputs:arnold:surface.connect = </Green/flat0.outputs:rgb>
    def Shader "flat0" {{
        uniform token info:id = "arnold:flat"
        color3f inputs:color = (0, 1, 0)
        vector3f outputs:rgb
    }}
}}
{}{}"#,
        mesh("A", "Clay"),
        mesh("B", "Green")
    );
    let s = read_body(&body);
    assert_eq!(s.contents.meshes[0].material, Material::Diffuse { color: Vec3::new(0.5, 0.25, 0.0) }.into());
    assert_eq!(s.contents.meshes[1].material, Material::Unlit { color: Vec3::new(0.0, 1.0, 0.0) }.into());
    // Both shaders are drawn as Arnold draws them: neither warns.
    assert!(s.warnings.iter().all(|w| !w.contains("/Clay") && !w.contains("/Green")), "{:?}", s.warnings);
}

#[test]
fn points_become_spheres_of_their_widths() {
    let body = r#"
def Points "Dots" {
    point3f[] points.timeSamples = { 0: [(0, 0, 0), (10, 0, 0)], 10: [(0, 10, 0), (10, 10, 0)] }
    float[] widths = [2, 4] (interpolation = "vertex")
    int64[] ids.timeSamples = { 0: [1, 2], 10: [1, 2] }
    color3f[] primvars:displayColor = [(1, 0, 0)]
}
def Points "Reborn" {
    point3f[] points.timeSamples = { 0: [(0, 0, 5)], 10: [(0, 10, 5)] }
    int64[] ids.timeSamples = { 0: [7], 10: [8] }
}
"#;
    let s = read_with("", body, &ImportOptions { frame: Some(5), camera: None, ..Default::default() }).unwrap();
    assert_eq!(s.contents.meshes.len(), 2, "{:?}", s.warnings);
    let MeshSource::Inline(m) = &s.contents.meshes[0].source else { panic!("an inline mesh") };
    // Two balls of 42 vertices, 80 triangles each, around the points blended half way
    // (their ids stay), radii half the widths.
    assert_eq!((m.positions.len(), m.indices.len()), (84, 160));
    for (ball, (centre, r)) in [(Vec3::new(0.0, 5.0, 0.0), 1.0), (Vec3::new(10.0, 5.0, 0.0), 2.0)].iter().enumerate() {
        for p in &m.positions[ball * 42..(ball + 1) * 42] {
            assert!(((*p - *centre).length() - r).abs() < 1e-4, "{p:?}");
        }
    }
    assert_eq!(s.contents.meshes[0].material, Material::Diffuse { color: Vec3::new(1.0, 0.0, 0.0) }.into());
    // A point whose id changes between the samples is another point: held at the earlier
    // sample, not blended; without widths it is one unit wide, said once with the count.
    let MeshSource::Inline(m) = &s.contents.meshes[1].source else { panic!("an inline mesh") };
    assert!(m.positions.iter().all(|p| ((*p - Vec3::new(0.0, 0.0, 5.0)).length() - 0.5).abs() < 1e-4));
    assert!(
        s.warnings
            .iter()
            .any(|w| w.contains("Points without `widths`: drawn 1 unit wide (USD's fallback) (1; first: /Reborn)")),
        "{:?}",
        s.warnings
    );
    assert!(!s.warnings.iter().any(|w| w.contains("not read")), "{:?}", s.warnings);
    // Widths that do not fit: skipped, said.
    let s = read_body(
        r#"def Points "Bad" { point3f[] points = [(0, 0, 0), (1, 0, 0), (2, 0, 0)]
        float[] widths = [1, 1] }"#,
    );
    assert!(s.contents.meshes.is_empty());
    assert!(s.warnings.iter().any(|w| w.contains("/Bad: 2 `widths` for 3 points")), "{:?}", s.warnings);
}

#[test]
fn a_points_prim_over_the_triangle_budget_is_an_error_naming_the_file() {
    let n = points::MAX_TRIANGLES / 20 + 1;
    let pts = vec!["(0, 0, 0)"; n].join(", ");
    let body = format!("def Points \"Cloud\" {{ point3f[] points = [{pts}]\n float[] widths = [0.1] }}");
    let Err(e) = read_with("", &body, &ImportOptions::default()) else { panic!("over the budget") };
    let e = e.to_string();
    assert!(e.contains("scene.usda") && e.contains("/Cloud") && e.contains("exceed the 5000000 triangles"), "{e}");
}

#[test]
fn mesh_uvs_and_normals_beyond_single_precision_skip_the_mesh_naming_them() {
    // 1e39 is infinite as a `texCoord2f` or `normal3f`; as a double it is finite but
    // infinite once stored in single precision.
    let uv = "texCoord2f[] primvars:st = [(0, 0), (1, 0), (1, 1), (0, 1)]";
    let normals =
        "normal3f[] normals = [(0, 1, 0), (0, 1, 0), (0, 1, 0), (0, 1e39, 0)] (interpolation = \"vertex\")\n        ";
    assert!(SCENE.contains(uv));
    for (from, to, names) in [
        (uv, uv.replace("(1, 1)", "(1e39, 1)"), "primvars:st"),
        (uv, uv.replace("texCoord2f", "texCoord2d").replace("(1, 1)", "(1e39, 1)"), "primvars:st"),
        (uv, format!("{normals}{uv}"), "normals"),
    ] {
        let s = read_text(&SCENE.replacen(from, &to, 1)).unwrap();
        assert!(s.contents.meshes.is_empty(), "{to}");
        let w = s.warnings.iter().find(|w| w.contains("inconsistent: skipped")).expect("a warning");
        assert!(w.contains("/World/Ground") && w.contains(names), "{w}");
    }
}

#[test]
fn curves_sampled_beyond_single_precision_are_skipped_naming_the_prim() {
    // Each control point fits single precision; the Catmull-Rom curve through them
    // overshoots to 1.25 × 3e38 halfway between the middle two, which does not.
    let curves = |x: &str| {
        format!(
            "#usda 1.0\ndef BasisCurves \"Over\"\n{{\n    uniform token type = \"cubic\"\n    \
             uniform token basis = \"catmullRom\"\n    int[] curveVertexCounts = [4]\n    \
             point3f[] points = [(-{x}, 0, 0), ({x}, 0, 0), ({x}, 0, 0), (-{x}, 0, 0)]\n}}\n"
        )
    };
    assert_eq!(read_text(&curves("1e30")).unwrap().contents.hair.len(), 1);
    let s = read_text(&curves("3e38")).unwrap();
    assert!(s.contents.hair.is_empty());
    let w = s.warnings.iter().find(|w| w.contains("inconsistent: skipped")).expect("a warning");
    assert!(w.contains("/Over") && w.contains("single precision"), "{w}");
}

/// A unit cube `Mesh` prim under an Xform `Parent` whose extra attributes are
/// `parent_attrs`, with `mesh_attrs` on the mesh.
fn cube_stage(parent_attrs: &str, mesh_attrs: &str) -> String {
    format!(
        r#"def Xform "Parent" {{
        {parent_attrs}
        def Mesh "Cube" {{
            int[] faceVertexCounts = [4, 4, 4, 4, 4, 4]
            int[] faceVertexIndices = [0, 1, 3, 2, 2, 3, 5, 4, 4, 5, 7, 6, 6, 7, 1, 0, 1, 7, 5, 3, 6, 0, 2, 4]
            point3f[] points = [(-0.5, -0.5, 0.5), (0.5, -0.5, 0.5), (-0.5, 0.5, 0.5), (0.5, 0.5, 0.5), (-0.5, 0.5, -0.5), (0.5, 0.5, -0.5), (-0.5, -0.5, -0.5), (0.5, -0.5, -0.5)]
            {mesh_attrs}
        }}
    }}"#
    )
}

#[test]
fn meshes_are_subdivided_as_arnold_subdivides_them() {
    let mesh = |s: &Imported| match &s.contents.meshes[0].source {
        MeshSource::Inline(m) => m.clone(),
        other => panic!("{other:?}"),
    };
    // Without Arnold's iterations: the cage, faceted, said once (Arnold draws it so).
    let cage = read_body(&cube_stage("", ""));
    assert_eq!(mesh(&cage).indices.len(), 12);
    assert!(mesh(&cage).normals.is_none());
    assert!(
        cage.warnings.iter().any(|w| w.contains("without `primvars:arnold:subdiv_iterations`")),
        "{:?}",
        cage.warnings
    );
    // Two iterations inherited from the parent (a constant primvar), the type by the
    // fallback scheme `catmullClark`: 6 × 4² quads, smooth normals, every corner pulled in
    // to the 5/18-per-axis point after the first iteration and further after the second.
    let iterations = "int primvars:arnold:subdiv_iterations = 2 (interpolation = \"constant\")";
    let smooth = read_body(&cube_stage(iterations, ""));
    crate::geometry::subdivision::assert_cube_subdivided_twice(&mesh(&smooth));
    assert!(smooth.warnings.iter().all(|w| !w.contains("subdiv")), "{:?}", smooth.warnings);
    // `subdiv_type` wins over the scheme: `linear` (or 2) and `none` (or 0) draw the cage,
    // and so does the scheme `none` or `bilinear` without a type.
    for attrs in [
        "string primvars:arnold:subdiv_type = \"linear\"",
        "int primvars:arnold:subdiv_type = 0",
        "uniform token subdivisionScheme = \"bilinear\"",
    ] {
        let s = read_body(&cube_stage(iterations, attrs));
        assert_eq!(mesh(&s).indices.len(), 12, "{attrs}");
    }
    let typed = read_body(&cube_stage(
        iterations,
        "int primvars:arnold:subdiv_type = 1\nuniform token subdivisionScheme = \"none\"",
    ));
    assert_eq!(mesh(&typed).indices.len(), 2 * 6 * 16);
    // Infinitely sharp creases on every edge around the top face keep it flat at y = 0.5.
    let creased = read_body(&cube_stage(
        iterations,
        "int[] creaseIndices = [2, 3, 5, 4, 2]\nint[] creaseLengths = [5]\nfloat[] creaseSharpnesses = [10]",
    ));
    let top = mesh(&creased).positions.iter().filter(|p| (p.y - 0.5).abs() < 1e-6).count();
    assert!(top >= 5 * 5, "{top} points on the top face");
    assert!(mesh(&smooth).positions.iter().all(|p| p.y < 0.5 - 1e-3));
}

#[test]
fn bad_subdivision_attributes_are_named() {
    let iterations = "int primvars:arnold:subdiv_iterations = 1";
    for (attrs, message) in [
        (
            "int[] creaseIndices = [2, 3]\nint[] creaseLengths = [3]\nfloat[] creaseSharpnesses = [10]",
            "`creaseLengths` sum to 3",
        ),
        (
            "int[] creaseIndices = [2, 9]\nint[] creaseLengths = [2]\nfloat[] creaseSharpnesses = [10]",
            "`creaseIndices` uses point 9 of 8",
        ),
        (
            "int[] creaseIndices = [2, 3]\nint[] creaseLengths = [2]\nfloat[] creaseSharpnesses = [1, 2, 3]",
            "3 `creaseSharpnesses` for 1 creases",
        ),
        (
            "int[] cornerIndices = [1, 2]\nfloat[] cornerSharpnesses = [1]",
            "1 `cornerSharpnesses` for 2 `cornerIndices`",
        ),
        ("int[] cornerIndices = [1]\nfloat[] cornerSharpnesses = [1e39]", "`cornerSharpnesses` must be finite"),
    ] {
        let s = read_body(&cube_stage("", &format!("{iterations}\n{attrs}")));
        assert!(s.contents.meshes.is_empty(), "{attrs}");
        assert!(
            s.warnings.iter().any(|w| w.contains(message) && w.contains("/Parent/Cube")),
            "{attrs}: {:?}",
            s.warnings
        );
    }
    // Iterations Arnold's byte cannot hold: not subdivided, said with the value.
    let s = read_body(&cube_stage("", "int primvars:arnold:subdiv_iterations = 300"));
    let MeshSource::Inline(m) = &s.contents.meshes[0].source else { panic!() };
    assert_eq!(m.indices.len(), 12);
    assert!(s.warnings.iter().any(|w| w.contains("not 0 to 255") && w.contains("300")), "{:?}", s.warnings);
    // Arnold's largest count stops at the face budget, said once: 6 × 4⁹ quads, as the
    // tenth iteration would make 6 × 4¹⁰, past 2,000,000.
    let s = read_body(&cube_stage("", "int primvars:arnold:subdiv_iterations = 255"));
    let MeshSource::Inline(m) = &s.contents.meshes[0].source else { panic!() };
    assert_eq!(m.indices.len(), 2 * 6 * 4usize.pow(9));
    assert!(s.warnings.iter().any(|w| w.contains("subdivision stopped")), "{:?}", s.warnings);
    // A file's meshes share one budget: with 100 faces of it left, a cube gets two
    // iterations (6 -> 24 -> 96), not 255.
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("cube.usda");
    std::fs::write(&path, format!("#usda 1.0\n{}", cube_stage("", "int primvars:arnold:subdiv_iterations = 255")))
        .unwrap();
    let stage = Stage::open(path.to_str().unwrap()).unwrap();
    let prim = stage.prim(sdf::path("/Parent/Cube").unwrap());
    let mut notes = Notes(Default::default(), FaceBudget { used: MAX_FACES_PER_FILE - 100 });
    let m = shapes::read_mesh(&prim, TimeCode::new(0.0), None, &mut notes).unwrap();
    assert_eq!(m.indices.len(), 2 * 96);
    assert_eq!(notes.1.used, MAX_FACES_PER_FILE - 4);
    assert!(notes.lines().iter().any(|w| w.contains("per file")));
}

#[test]
fn meshes_without_faces_are_said_and_not_drawn() {
    for faces in [
        "int[] faceVertexCounts = []\nint[] faceVertexIndices = []",
        "int[] faceVertexCounts = [2, 1]\nint[] faceVertexIndices = [0, 1, 2]",
    ] {
        let s =
            read_body(&format!("def Mesh \"M\" {{\n{faces}\npoint3f[] points = [(0, 0, 0), (1, 0, 0), (0, 1, 0)]\n}}"));
        assert!(s.contents.meshes.is_empty(), "{faces}");
        assert!(s.warnings.iter().any(|w| w.contains("meshes without faces") && w.contains("/M")), "{:?}", s.warnings);
    }
}

#[test]
fn orthographic_cameras_take_arnolds_screen_window_or_the_apertures_in_tenths() {
    let camera = |attrs: &str| {
        let text = format!(
            "def Camera \"Top\" {{\n    token projection = \"orthographic\"\n{attrs}}}\ndef Sphere \"Ball\" {{}}\n"
        );
        let s = read_with("", &text, &ImportOptions::default()).unwrap();
        let [w, h] = s.resolution.unwrap();
        (s.camera.unwrap(), [w, h], s.warnings)
    };
    // The schema's apertures, in tenths of a unit: a window 3 x 2 units.
    let (c, [w, h], _) = camera("    float horizontalAperture = 30\n    float verticalAperture = 20\n");
    assert!(matches!(c.projection, crate::scene::CameraProjection::Orthographic { .. }));
    assert_eq!([w, h], [640, 427]);
    assert!((c.ortho_height_for(w, h).unwrap() - 3.0 * 427.0 / 640.0).abs() < 1e-5);
    // Arnold's screen window wins: the window −0.8..0.8 of a screen 2 units wide, its
    // height following the image (as -r refits it).
    let window = "    float2[] primvars:arnold:screen_window_max = [(0.8, 0.8)]\n    float2[] primvars:arnold:screen_window_min = [(-0.8, -0.8)]\n";
    let (c, _, warnings) = camera(window);
    assert!((c.ortho_height_for(200, 100).unwrap() - 1.0).abs() < 1e-6);
    assert_eq!(c.window, [Vec2::splat(-0.8), Vec2::splat(0.8)]);
    assert!(warnings.iter().all(|w| !w.contains("orthographic")), "{warnings:?}");
    // Off the axis and not square, as set (the other corner Arnold's default).
    let (c, _, _) = camera("    float2[] primvars:arnold:screen_window_max = [(3, 0.5)]\n");
    assert_eq!(c.window, [Vec2::NEG_ONE, Vec2::new(3.0, 0.5)]);
    // Perspective aperture offsets shift the window by twice the offset over the aperture.
    let text = "def Camera \"C\" {\n    float horizontalAperture = 20\n    float verticalAperture = 10\n    \
                float horizontalApertureOffset = 5\n    float verticalApertureOffset = -1\n}\n";
    let c = read_with("", text, &ImportOptions::default()).unwrap().camera.unwrap();
    assert_eq!(c.window, [Vec2::new(-0.5, -1.2), Vec2::new(1.5, 0.8)]);
    // A projection that is neither is refused, named.
    let text = "def Camera \"Top\" {\n    token projection = \"fisheye\"\n}\n";
    let e = read_with("", text, &ImportOptions::default()).unwrap_err().to_string();
    assert!(e.contains("fisheye"), "{e}");
}

/// A stage as Blender's USD exporter writes one (root layer `doc`, a Z-up root Xform,
/// objects as Xforms over their data prims): a sun of strength 3 and 2° diameter, and a
/// particle system's hair (linear curves, no widths); `doc` is its layer's `doc` line.
fn blender_stage(doc: &str) -> String {
    format!(
        r#"#usda 1.0
(
    defaultPrim = "root"
    {doc}
    metersPerUnit = 1
    upAxis = "Z"
)

def Xform "root"
{{
    def Xform "Head"
    {{
        def BasisCurves "hair"
        {{
            uniform token basis = "catmullRom"
            int[] curveVertexCounts = [3, 3]
            point3f[] points = [(0, 0, 0.5), (0, 0, 0.7), (0, 0, 0.9), (0.5, 0, 0), (0.7, 0, 0), (0.9, 0, 0)]
            color3f[] primvars:displayColor = [(0.8, 0.8, 0.8)]
            uniform token type = "linear"
            uniform token wrap = "pinned"
        }}
    }}

    def Xform "Sun"
    {{
        float3 xformOp:rotateXYZ = (0, -0, 0)
        float3 xformOp:scale = (1, 1, 1)
        double3 xformOp:translate = (0, 0, 0)
        uniform token[] xformOpOrder = ["xformOp:translate", "xformOp:rotateXYZ", "xformOp:scale"]

        def DistantLight "Sun"
        {{
            float inputs:angle = 1
            bool inputs:enableColorTemperature = 1
            float inputs:intensity = 0.75
            bool inputs:normalize = 1
        }}
    }}
}}
"#
    )
}

#[test]
fn blender_stages_light_suns_and_draw_hair_without_widths_as_blender_does() {
    let sun = |s: &Imported| {
        let LightSource::Inline(Light::Sun { radiance, cos_max, .. }) = s.contents.lights[0] else {
            panic!("{:?}", s.contents.lights)
        };
        // Irradiance is radiance × the disk's solid angle, 2π (1 − cos θ).
        (radiance.x * std::f32::consts::TAU * (1.0 - cos_max), cos_max.acos().to_degrees())
    };
    let s = read_text(&blender_stage("doc = \"Blender v5.0.1\"")).unwrap();
    // The sun's strength, 4 × the intensity written, over its diameter, 2 × the angle.
    let (irradiance, half_angle) = sun(&s);
    assert!((irradiance - 3.0).abs() < 1e-3 && (half_angle - 1.0).abs() < 1e-3, "{irradiance} {half_angle}");
    // The two strands, Blender's default radius of 0.01 all along; said once.
    let hair = strands(&s, 0);
    assert_eq!(hair.strand_count(), 2);
    assert!(hair.points.iter().all(|p| (p[3] - 0.01).abs() < 1e-7), "{:?}", hair.points);
    assert!(
        s.warnings.iter().any(|w| w.contains("0.02 unit wide (Blender's default curve radius)")),
        "{:?}",
        s.warnings
    );
    // Every Blender light enables the temperature, which is the default, white 6500 K.
    assert!(s.warnings.iter().all(|w| !w.contains("colorTemperature")), "{:?}", s.warnings);
    // The same prims from any other writer are read as UsdLux and UsdGeom say.
    let s = read_text(&blender_stage("doc = \"Written by hand\"")).unwrap();
    let (irradiance, half_angle) = sun(&s);
    assert!((irradiance - 0.75).abs() < 1e-3 && (half_angle - 0.5).abs() < 1e-3, "{irradiance} {half_angle}");
    assert!(strands(&s, 0).points.iter().all(|p| p[3] == 0.5));
    // A temperature of its own is reported, not applied.
    let warm =
        blender_stage("").replace("bool inputs:enable", "float inputs:colorTemperature = 3000\n bool inputs:enable");
    let s = read_text(&warm).unwrap();
    assert!(s.warnings.iter().any(|w| w.contains("`colorTemperature` other than 6500 K")), "{:?}", s.warnings);
}

#[test]
fn blender_stages_in_centimetres_keep_their_normalized_lights_power() {
    // Blender's exporter converting to centimetres: metersPerUnit 0.01, a scale of 100 on
    // the root, the power (π × intensity) of a 0.1 m bulb left as written.
    let body = |doc: &str| {
        let meta = format!("{doc}\nmetersPerUnit = 0.01\nupAxis = \"Z\"");
        let body = r#"
def Xform "root" {
    float3 xformOp:scale = (100, 100, 100)
    uniform token[] xformOpOrder = ["xformOp:scale"]
    def SphereLight "Point" { float inputs:intensity = 10 bool inputs:normalize = 1 float inputs:radius = 0.1 }
}"#;
        let s = read_with(&meta, body, &ImportOptions::default()).unwrap();
        let LightSource::Inline(Light::Sphere { radius, radiance, .. }) = s.contents.lights[0] else { panic!() };
        (radius, radiance.x)
    };
    // Its 0.1 m radius is 10 of the stage's centimetres; its intensity is spread over 4π (0.1 m)².
    let (radius, radiance) = body("doc = \"Blender v4.5.0\"");
    assert!((radius - 10.0).abs() < 1e-4, "{radius}");
    let expected = 10.0 / (4.0 * std::f32::consts::PI * 0.01);
    assert!((radiance / expected - 1.0).abs() < 1e-4, "{radiance} vs {expected}");
    // Any other writer's: over its area in the stage's units, as UsdLux's renderers spread it.
    let (_, radiance) = body("");
    let expected = 10.0 / (4.0 * std::f32::consts::PI * 100.0);
    assert!((radiance / expected - 1.0).abs() < 1e-4, "{radiance} vs {expected}");
}

#[test]
fn a_dome_whose_arnold_shaders_graph_is_a_physical_sky_is_that_sky() {
    let body = r#"
def Scope "materials" {
    def ArnoldNodeGraph "graph" {
        token outputs:color.connect = </materials/graph/sky.outputs:shader>
        def Shader "sky" {
            uniform token info:id = "arnold:physical_sky"
            float inputs:elevation = 90
            float inputs:sun_size = 1
            token outputs:shader
        }
    }
}
def DomeLight "Dome" {
    float inputs:intensity = 0.5
    string primvars:arnold:shaders = "/materials/graph" (interpolation = "constant")
}
def DomeLight "Plain" { float inputs:intensity = 0.5 }
"#;
    let s = read_body(body);
    assert_eq!(s.contents.lights.len(), 3, "{:?}", s.contents.lights);
    let LightSource::Inline(Light::Sun { direction, .. }) = s.contents.lights[0] else {
        panic!("{:?}", s.contents.lights[0])
    };
    assert!(direction.abs_diff_eq(Vec3::Y, 1e-5), "{direction}");
    let LightSource::Inline(Light::EnvironmentMap(ref map)) = s.contents.lights[1] else { panic!() };
    // A blue sky: bluer up than at the horizon's ground.
    let zenith = map.radiance(Vec3::new(0.3, 1.0, 0.0).normalize());
    assert!(zenith.z > zenith.x && zenith.z > 0.0, "{zenith}");
    assert_eq!(s.contents.lights[2], Light::Environment { radiance: Vec3::splat(0.5), camera_visibility: 1.0 }.into());
}

#[test]
fn a_sphere_light_shaped_by_a_cone_is_arnolds_spot_light() {
    let body = r#"
def SphereLight "Spot" (prepend apiSchemas = ["ShapingAPI"]) {
    float inputs:intensity = 4
    float inputs:radius = 0
    float inputs:shaping:cone:angle = 30
    float inputs:shaping:cone:softness = 0.5
    float inputs:shaping:focus = 2
    float xformOp:rotateX = -90
    uniform token[] xformOpOrder = ["xformOp:rotateX"]
}
def RectLight "Rect" (prepend apiSchemas = ["ShapingAPI"]) { float inputs:shaping:cone:angle = 30 }
"#;
    let s = read_body(body);
    let LightSource::Inline(Light::Spot { direction, intensity, cos_inner, cos_outer, .. }) = s.contents.lights[0]
    else {
        panic!("{:?}", s.contents.lights[0])
    };
    // Turned from −Z to shine down; Arnold's cone of twice the half-angle, its penumbra
    // the cone times the softness inside the edge: full light within 0°, dark past 30°.
    assert!(direction.abs_diff_eq(Vec3::NEG_Y, 1e-5), "{direction}");
    assert_eq!(intensity, Vec3::splat(4.0));
    assert!((cos_outer - 30f32.to_radians().cos()).abs() < 1e-6 && (cos_inner - 1.0).abs() < 1e-6);
    assert!(matches!(s.contents.lights[1], LightSource::Inline(Light::Quad { .. })));
    let w = &s.warnings;
    assert!(w.iter().any(|w| w.contains("`focus`: not applied")), "{w:?}");
    assert!(w.iter().any(|w| w.contains("cones on lights other than sphere lights")), "{w:?}");
}
