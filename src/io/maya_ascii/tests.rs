//! Maya ASCII import against a small scene written as Maya writes them: counts, attribute
//! values, node defaults, curve knots, line-numbered errors (random and mutated input: `tests/hostile.rs`).

use super::*;
use crate::fur::{ColorAttr, FurDescription, Scalar};
use crate::scene::LightSource;
use crate::shading::hair_bsdf::Absorption;

/// A small scene as Maya writes it: a 2 × 1 quad plane with UVs under a moved transform,
/// a hair system with three follicles (two with stored transforms and start curves of
/// degree 3 and 1, one placed by Maya from its UV), a FurDescription on the plane through
/// a FurFeedback, a camera, a light, a rig control circle and an unknown node.
const SCENE: &str = r#"//Maya ASCII 2020 scene
requires maya "2020";
currentUnit -l centimeter -a degree -t film;
createNode transform -n "plane1";
	setAttr ".t" -type "double3" 0 1 0 ;
createNode mesh -n "planeShape1" -p "plane1";
	setAttr -k off ".v";
	setAttr ".uvst[0].uvsn" -type "string" "map1";
	setAttr -s 6 ".uvst[0].uvsp[0:5]" -type "float2" 0 0 0.5 0 1 0 0 1 0.5 1 1 1;
	setAttr -s 6 ".vt[0:5]"  -2 0 1 0 0 1 2 0 1 -2 0 -1 0 0 -1 2 0 -1;
	setAttr -s 7 ".ed[0:6]"  0 1 0 1 2 0 3 4 0 4 5 0 0 3 0 1 4 0 2 5 0;
	setAttr -s 2 -ch 8 ".fc[0:1]" -type "polyFaces"
		f 4 0 5 -3 -5
		mu 0 4 0 1 4 3
		f 4 1 6 -4 -6
		mu 0 4 1 2 5 4 ;
createNode transform -n "hairSystem1";
createNode hairSystem -n "hairSystemShape1" -p "hairSystem1";
	setAttr ".hpc" 16;
	setAttr ".cwd" 0.2;
	setAttr ".hwd" 0.03;
	setAttr ".ssg" 2;
	setAttr -s 2 ".cws[0:1]"  0 1 3 1 0.2 3;
	setAttr ".clc[0]"  0 0.6 1;
	setAttr ".hcl" -type "float3" 0.5 0.3 0.1 ;
	setAttr ".hcs[0].hcsp" 0;
	setAttr ".hcs[0].hcsc" -type "float3" 0.5 0.5 0.5 ;
	setAttr ".hcs[0].hcsi" 1;
	setAttr ".hcs[1].hcsp" 1;
	setAttr ".hcs[1].hcsc" -type "float3" 1 1 1 ;
	setAttr ".nmt" 1;
createNode transform -n "hairSystem1Follicles";
createNode transform -n "follicle1" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -1 1 0 ;
createNode follicle -n "follicleShape1" -p "follicle1";
	setAttr ".pu" 0.25;
	setAttr ".pv" 0.5;
createNode transform -n "curve1" -p "follicle1";
createNode nurbsCurve -n "curveShape1" -p "curve1";
	setAttr ".cc" -type "nurbsCurve"
		3 2 0 no 3
		7 0 0 0 1 2 2 2
		5
		0 0 0
		0 0.5 0
		0 1 0.5
		0 1.5 0.5
		0 2 0
		;
createNode transform -n "follicle2" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 1 1 0 ;
createNode follicle -n "follicleShape2" -p "follicle2";
	setAttr ".pu" 0.75;
	setAttr ".pv" 0.5;
createNode transform -n "curve2" -p "follicle2";
createNode nurbsCurve -n "curveShape2" -p "curve2";
	setAttr ".cc" -type "nurbsCurve"
		1 3 0 no 3
		4 0 1 2 3
		4
		0 0 0
		0 1 0
		0.5 1 0
		0.5 2 0
		;
createNode transform -n "follicle3" -p "hairSystem1Follicles";
createNode follicle -n "follicleShape3" -p "follicle3";
	setAttr ".pu" 0.75;
	setAttr ".pv" 0.25;
createNode transform -n "curve3" -p "follicle3";
createNode nurbsCurve -n "curveShape3" -p "curve3";
	setAttr ".cc" -type "nurbsCurve"
		1 1 0 no 3
		2 0 1
		2
		0 0 0
		1 0 0
		;
createNode FurDescription -n "FurDescription1";
	setAttr ".d" 5000;
	setAttr ".dl" 0.4;
	setAttr ".dbw" 0.02;
	setAttr ".dbc" -type "float3" 0.6 0.4 0.2 ;
createNode transform -n "FurFeedback1";
createNode FurFeedback -n "FurFeedbackShape1" -p "FurFeedback1";
createNode transform -n "camera1";
	setAttr ".t" -type "double3" 0 3 10 ;
createNode camera -n "cameraShape1" -p "camera1";
	setAttr ".fl" 50;
	setAttr ".coi" 10;
createNode transform -n "directionalLight1";
	setAttr ".r" -type "double3" -90 0 0 ;
createNode directionalLight -n "directionalLightShape1" -p "directionalLight1";
	setAttr ".in" 2;
createNode transform -n "ctrl";
createNode nurbsCurve -n "ctrlShape" -p "ctrl";
	setAttr ".cc" -type "nurbsCurve"
		1 4 2 no 3
		5 0 1 2 3 4
		5
		1 0 0 0 0 1 -1 0 0 0 0 -1 1 0 0
		;
createNode polyCone -n "polyCone1";
createNode polyCone -n "polyCone2";
select -ne :defaultResolution;
	setAttr ".w" 320;
	setAttr ".h" 240;
connectAttr "planeShape1.o" "follicleShape1.inm";
connectAttr "planeShape1.o" "follicleShape2.inm";
connectAttr "planeShape1.o" "follicleShape3.inm";
connectAttr "planeShape1.wm" "follicleShape3.iwm";
connectAttr "follicleShape3.ot" "follicle3.t";
connectAttr "follicleShape3.or" "follicle3.r";
connectAttr "curveShape1.ws" "follicleShape1.sp";
connectAttr "curveShape2.ws" "follicleShape2.sp";
connectAttr "curveShape3.ws" "follicleShape3.sp";
connectAttr "follicleShape1.oha" "hairSystemShape1.ih[0]";
connectAttr "follicleShape2.oha" "hairSystemShape1.ih[1]";
connectAttr "follicleShape3.oha" "hairSystemShape1.ih[2]";
connectAttr "planeShape1.w" "FurFeedbackShape1.imsh";
connectAttr "FurDescription1.dl" "FurFeedbackShape1.dl";
"#;

fn read(text: &str) -> Result<Imported, LoadError> {
    parse_maya(text, Path::new("dir/scene.ma"))
}

fn close(a: Vec3, b: Vec3) -> bool {
    (a - b).length() < 1e-4
}

#[test]
fn a_scene_with_mesh_hair_system_and_fur_imports_with_its_counts_and_values() {
    let s = read(SCENE).unwrap();
    // The mesh: 6 vertices, 2 quads = 4 triangles, UVs, moved up by its transform.
    assert_eq!(s.contents.meshes.len(), 1);
    let MeshSource::Inline(m) = &s.contents.meshes[0].source else { panic!() };
    assert_eq!((m.positions.len(), m.indices.len()), (6, 4));
    assert!(m.uvs.is_some());
    assert!(close(s.contents.meshes[0].transform.transform_point3(Vec3::ZERO), Vec3::Y));
    // Faces keep Maya's winding: the plane faces +y... (its normals are not stored: flat).
    let [a, b, c] = m.corners(0);
    assert!(
        (b - a).cross(c - a).normalize().dot(Vec3::Y) > 0.99
            || (b - a).cross(c - a).normalize().dot(Vec3::NEG_Y) > 0.99
    );
    assert_eq!(s.contents.meshes[0].material, Material::Diffuse { color: Vec3::splat(0.4) }.into());

    // The hair system: three follicles, attributes from the file, the rest node defaults.
    assert_eq!(s.contents.hair_systems.len(), 1);
    let h = &s.contents.hair_systems[0];
    let GuideSource::Inline(g) = &h.guides else { panic!() };
    assert_eq!(g.curves.strand_count(), 3);
    assert_eq!(g.root_uv, Some(vec![[0.25, 0.5], [0.75, 0.5], [0.75, 0.25]]));
    let sys = &h.system;
    assert_eq!((sys.hairs_per_clump, sys.sub_segments, sys.clump_width, sys.hair_width), (16, 2, 0.2, 0.03));
    assert!((sys.clump_width_scale.eval(1.0) - 0.2).abs() < 1e-6);
    assert_eq!(sys.clump_width_scale.keys()[0].interp, Interp::Spline);
    assert_eq!(sys.clump_curl.eval(0.5), 0.6);
    assert_eq!(sys.hair_color, Vec3::new(0.5, 0.3, 0.1));
    assert!(close(sys.hair_color_scale.eval(0.5), Vec3::splat(0.75)));
    assert_eq!(sys.noise_method, NoiseMethod::SurfaceUv);
    let d = HairSystem::default();
    assert_eq!(
        (sys.thinning, sys.curl_frequency, sys.noise_frequency),
        (d.thinning, d.curl_frequency, d.noise_frequency)
    );
    assert_eq!(
        (sys.specular_color, sys.specular_power, sys.diffuse_rand),
        (d.specular_color, d.specular_power, d.diffuse_rand)
    );
    assert_eq!(sys.clump_flatness, d.clump_flatness);

    // The FurDescription: the file's values, node defaults elsewhere, grown on the plane.
    assert_eq!(s.contents.fur.len(), 1);
    let (f, d) = (&s.contents.fur[0], &s.contents.fur[0].description);
    assert_eq!(f.mesh, 0);
    assert_eq!((d.density, d[Scalar::Length].value, d[Scalar::BaseWidth].value), (5000, 0.4, 0.02));
    assert_eq!(d[ColorAttr::BaseColor].value, Vec3::new(0.6, 0.4, 0.2));
    let n = FurDescription::default();
    for a in [Scalar::TipWidth, Scalar::Inclination, Scalar::Scraggle, Scalar::ClumpingFrequency, Scalar::Polar] {
        assert_eq!(d[a], n[a], "{a:?}");
    }
    assert_eq!((d.segments, d.light_model), (n.segments, n.light_model));
    assert_eq!(d[ColorAttr::TipColor], n[ColorAttr::TipColor]);

    // Camera, light, resolution; the control circle is not hair; polyCone is reported once.
    let c = s.camera.as_ref().unwrap();
    assert!(close(c.eye, Vec3::new(0.0, 3.0, 10.0)) && close(c.target, Vec3::new(0.0, 3.0, 0.0)));
    // Horizontal fit: 2 atan(1.41732 × 25.4 / 2 / 50 / (320 / 240)).
    let vfov = 2.0 * (1.41732f32 * 25.4 / 100.0 / (4.0 / 3.0)).atan().to_degrees();
    assert!((c.vfov - vfov).abs() < 1e-3, "{}", c.vfov);
    assert_eq!(s.resolution, Some([320, 240]));
    assert_eq!(s.contents.lights.len(), 1);
    let LightSource::Inline(Light::Distant { direction, irradiance }) = s.contents.lights[0] else { panic!() };
    // Rotated −90° about X, the light's −Z points down: it comes from above.
    assert!(close(direction, Vec3::Y), "{direction}");
    assert!(close(irradiance, Vec3::splat(2.0 * PI)));
    assert!(s.contents.hair.is_empty());
    assert!(s.warnings.iter().any(|w| w.contains("polyCone (2)")), "{:?}", s.warnings);
    assert!(s.warnings.iter().any(|w| w.contains("1 closed")), "{:?}", s.warnings);
}

#[test]
fn nurbs_curves_honour_degree_and_knots() {
    let s = read(SCENE).unwrap();
    let GuideSource::Inline(g) = &s.contents.hair_systems[0].guides else { panic!() };
    let c = &g.curves;
    let strand = |i: usize| -> Vec<Vec3> { (c.offsets[i]..c.offsets[i + 1]).map(|p| c.position(p)).collect() };
    // Curve 1: degree 3, 2 spans, clamped knots 0 0 0 1 2 2 2: 2 × 8 + 1 samples, through
    // the end CVs, placed by follicle1 at (−1, 1, 0).
    let one = strand(0);
    assert_eq!(one.len(), 2 * SAMPLES_PER_SPAN + 1);
    let off = Vec3::new(-1.0, 1.0, 0.0);
    assert!(close(one[0], off) && close(one[16], off + Vec3::new(0.0, 2.0, 0.0)));
    // At the interior knot t = 1 of the full knot vector 0 0 0 0 1 2 2 2 2, the cubic
    // B-spline basis functions (Cox-de Boor recursion) are 1/4, 1/2, 1/4 on P1, P2, P3.
    let p = [Vec3::new(0.0, 0.5, 0.0), Vec3::new(0.0, 1.0, 0.5), Vec3::new(0.0, 1.5, 0.5)];
    let at_knot = p[0] / 4.0 + p[1] / 2.0 + p[2] / 4.0;
    assert!(close(one[8], off + at_knot), "{} vs {}", one[8], off + at_knot);
    // Curve 2: degree 1: exactly its CVs.
    let two = strand(1);
    let off = Vec3::new(1.0, 1.0, 0.0);
    let cvs = [Vec3::ZERO, Vec3::Y, Vec3::new(0.5, 1.0, 0.0), Vec3::new(0.5, 2.0, 0.0)];
    assert_eq!(two.len(), 4);
    assert!(two.iter().zip(cvs).all(|(a, b)| close(*a, off + b)));
    // Curve 3: its follicle is placed by Maya at UV (0.75, 0.25) of the plane (x = 1,
    // z = −0.5 in the plane's space, y = 1 after its transform) and its local X is the
    // normal, so the curve along X leaves along the plane's normal.
    let three = strand(2);
    assert!(close(three[0], Vec3::new(1.0, 1.0, 0.5)) || close(three[0], Vec3::new(1.0, 1.0, -0.5)), "{}", three[0]);
    let dir = (three[1] - three[0]).normalize();
    assert!(dir.y.abs() > 0.999, "{dir}");
}

#[test]
fn node_defaults_apply_when_the_file_sets_nothing() {
    let s = read(
        "createNode transform -n f;\ncreateNode follicle -n fs -p f;\ncreateNode transform -n c -p f;\n\
         createNode nurbsCurve -n cs -p c;\nsetAttr \".cc\" -type \"nurbsCurve\" 1 1 0 no 3 2 0 1 2 0 0 0 0 1 0;\n\
         createNode hairSystem -n hs;\ncreateNode FurDescription -n fd;\n\
         connectAttr \"cs.ws\" \"fs.sp\";\nconnectAttr \"fs.oha\" \"hs.ih[0]\";\n",
    )
    .unwrap();
    assert_eq!(s.contents.hair_systems[0].system, HairSystem::default());
    // The bare FurDescription is attached to no mesh: read, and reported as growing nothing.
    assert!(
        s.contents.fur.is_empty() && s.warnings.iter().any(|w| w.contains("fd") && w.contains("no mesh")),
        "{:?}",
        s.warnings
    );
    assert!(s.camera.is_none() && s.contents.lights.is_empty());
}

#[test]
fn procedural_meshes_maya_default_material_and_shading_groups() {
    let s = read(
        "createNode transform -n s;\ncreateNode mesh -n ss -p s;\ncreateNode polySphere -n ps;\nsetAttr \".r\" 2;\n\
         createNode lambert -n red;\nsetAttr \".c\" -type \"float3\" 1 0 0;\nsetAttr \".dc\" 0.5;\n\
         createNode shadingEngine -n redSG;\n\
         connectAttr \"ps.out\" \"ss.i\";\nconnectAttr \"red.oc\" \"redSG.ss\";\nconnectAttr \"ss.iog\" \"redSG.dsm\" -na;\n",
    )
    .unwrap();
    let MeshSource::Inline(m) = &s.contents.meshes[0].source else { panic!() };
    assert!(m.positions.iter().all(|p| (p.length() - 2.0).abs() < 1e-4));
    assert_eq!(s.contents.meshes[0].material, Material::Diffuse { color: Vec3::new(0.5, 0.0, 0.0) }.into());
}

/// A point light 4 units above the origin with the given `setAttr`s, and the irradiance it
/// gives a surface facing it at the origin.
fn point_light_irradiance(head: &str, attrs: &str) -> f32 {
    let s = read(&format!(
        "{head}createNode transform -n l;\nsetAttr \".t\" -type \"double3\" 0 4 0;\ncreateNode pointLight -n ls -p l;\n\
         setAttr \".in\" 2;\n{attrs}"
    ))
    .unwrap();
    let LightSource::Inline(Light::Point { position, .. }) = s.contents.lights[0] else {
        panic!("{:?}", s.contents.lights)
    };
    assert!(close(position, Vec3::new(0.0, 4.0, 0.0)));
    let LightSource::Inline(light) = &s.contents.lights[0] else { panic!() };
    light.sample(Vec3::ZERO, Some(Vec3::Y), (0.5, 0.5)).unwrap().value.x
}

#[test]
fn point_and_spot_lights_decay_as_maya_says_no_decay_by_default() {
    // Maya's intensity 2 lights a facing white Lambert to 2 at any distance without decay
    // (its default), 2 / d with linear decay, 2 / d² with quadratic (tress: π times that).
    let e = |attrs: &str| point_light_irradiance("", attrs) / PI;
    assert!((e("") - 2.0).abs() < 1e-5, "{}", e(""));
    assert!((e("setAttr \".de\" 1;\n") - 0.5).abs() < 1e-5);
    assert!((e("setAttr \".de\" 2;\n") - 2.0 / 16.0).abs() < 1e-5);
    assert!((e("setAttr \".de\" 3;\n") - 2.0 / 64.0).abs() < 1e-6);
    // Arnold's exposure doubles per stop.
    assert!((e("setAttr \".ai_exposure\" 2;\n") - 8.0).abs() < 1e-4);
    let spot =
        read("createNode transform -n l;\nsetAttr \".t\" -type \"double3\" 0 0 5;\ncreateNode spotLight -n ls -p l;\n")
            .unwrap();
    let LightSource::Inline(light) = &spot.contents.lights[0] else { panic!() };
    let s = light.sample(Vec3::ZERO, Some(Vec3::Z), (0.5, 0.5)).unwrap();
    assert!((s.value.x / PI - 1.0).abs() < 1e-5, "{}", s.value.x);
    let e = read("createNode pointLight -n p;\nsetAttr \".de\" 7;\n").unwrap_err().to_string();
    assert!(e.contains("line 1") && e.contains("decay rate 7"), "{e}");
}

#[test]
fn the_linear_unit_sets_the_distance_maya_decays_light_over() {
    // Maya measures the decay distance in centimetres: 4 m is 400 cm.
    let e = |head: &str| point_light_irradiance(head, "setAttr \".de\" 2;\n") / PI;
    assert!((e("currentUnit -l meter -a degree;\n") - 2.0 / (400.0f32 * 400.0)).abs() < 1e-9);
    assert!((e("currentUnit -l millimeter;\n") - 2.0 / (0.4f32 * 0.4)).abs() < 1e-4);
    assert!((e("currentUnit -l centimeter;\n") - 2.0 / 16.0).abs() < 1e-6);
    // No decay is the same in every unit.
    assert!((point_light_irradiance("currentUnit -l inch;\n", "") / PI - 2.0).abs() < 1e-5);
    let e = read("currentUnit -l parsec;\n").unwrap_err().to_string();
    assert!(e.contains("line 1") && e.contains("parsec"), "{e}");
}

#[test]
fn free_curves_take_the_hair_systems_width_or_one_relative_to_the_scene() {
    let curve = |name: &str, scale: f64| {
        format!(
            "createNode transform -n {name};\ncreateNode nurbsCurve -n {name}s -p {name};\n\
             setAttr \".cc\" -type \"nurbsCurve\" 1 1 0 no 3 2 0 1 2 0 0 0 0 {scale} 0;\n"
        )
    };
    let radii = |s: &Imported| {
        let HairSource::Inline(set) = &s.contents.hair[0].source else { panic!() };
        set.points.iter().map(|p| p[3]).collect::<Vec<_>>()
    };
    // A groom modelled in millimetres (a curve 300 units long): hairs a thousandth of the
    // scene wide, not an absolute 0.01, and said so.
    let s = read(&curve("c", 300.0)).unwrap();
    assert!(radii(&s).iter().all(|r| (r - 0.5 * 0.3).abs() < 1e-4), "{:?}", radii(&s));
    assert!(s.warnings.iter().any(|w| w.contains("1 curve(s)") && w.contains("no width")), "{:?}", s.warnings);
    let s = read(&curve("c", 3.0)).unwrap();
    assert!(radii(&s).iter().all(|r| (r - 0.5 * 0.003).abs() < 1e-6));
    // With a hair system in the file, its hair width.
    let s = read(&format!("{}createNode hairSystem -n hs;\nsetAttr \".hwd\" 0.04;\n", curve("c", 300.0))).unwrap();
    assert!(radii(&s).iter().all(|r| (r - 0.02).abs() < 1e-7), "{:?}", radii(&s));
}

#[test]
fn malformed_lines_are_errors_naming_file_and_line() {
    for (text, line) in [
        ("createNode mesh -n m;\nsetAttr \".vt[0:1]\" 0 0 0 1 0;\nsetAttr \".ed[0]\" 0 1 0;\nsetAttr \".fc[0]\" -type \"polyFaces\" f 3 0 0 0;\n", 2),
        ("createNode nurbsCurve -n c;\nsetAttr \".cc\" -type \"nurbsCurve\" 3 1 0 no 3 4 0 0 1 1 4 0 0 0 1 0 0;\ncreateNode hairSystem;\n", 2),
        ("createNode transform -n t;\n\n\nsetAttr \".t\" -type \"double3\" 1 2;\ncreateNode pointLight -p t;\n", 4),
        ("createNode transform -n t;\nsetAttr \".s\" -type \"double3\" 1e300 1 1;\ncreateNode pointLight -p t;\n", 3),
        ("createNode hairSystem -n h;\nsetAttr \".cws[0:1]\" 0 1 3 1;\n", 2),
        ("createNode hairSystem -n h;\nsetAttr \".hpc\" -4;\ncreateNode follicle -n f;\n", 2),
        ("requires maya \"2020\";\ncreateNode mesh -n \"m;\n", 2),
        ("createNode camera -n c;\nsetAttr \".fl\" \"long\";\n", 2),
    ] {
        let e = match read(text) {
            Ok(_) => panic!("no error for {text:?}"),
            Err(e) => e.to_string(),
        };
        assert!(e.starts_with("dir/scene.ma: line "), "{e}");
        assert!(e.contains(&format!("line {line}:")), "expected line {line}: {e}");
    }
}

#[test]
fn the_example_scene_imports() {
    let s = read(include_str!("../../../scenes/maya_hair.ma")).unwrap();
    assert_eq!(s.contents.meshes.len(), 2);
    assert_eq!(s.contents.hair_systems.len(), 1);
    assert_eq!(s.contents.fur.len(), 1);
    assert!(s.camera.is_some() && !s.contents.lights.is_empty());
}

#[test]
fn a_camera_is_chosen_by_its_transform_or_shape_name() {
    let two = "createNode transform -n \"near\";\n\tsetAttr \".t\" -type \"double3\" 0 0 4 ;\n\
               createNode camera -n \"nearShape\" -p \"near\";\n\
               createNode transform -n \"far\";\n\tsetAttr \".t\" -type \"double3\" 0 0 40 ;\n\
               createNode camera -n \"farShape\" -p \"far\";\n";
    let eye = |camera: Option<&str>| {
        parse_maya_with(two, Path::new("dir/two.ma"), camera, None).map(|s| s.camera.unwrap().eye.z)
    };
    assert_eq!(eye(None).unwrap(), 4.0);
    assert_eq!(eye(Some("far")).unwrap(), 40.0);
    assert_eq!(eye(Some("farShape")).unwrap(), 40.0);
    let e = eye(Some("side")).unwrap_err().to_string();
    assert!(e.starts_with("dir/two.ma") && e.contains("no camera `side`") && e.contains("near, far"), "{e}");
}

#[test]
fn cameras_clip_at_their_near_and_far_planes_in_the_files_unit() {
    let clip = |head: &str, attrs: &str| {
        let text = format!(
            "{head}createNode transform -n \"cam\";\n\tsetAttr \".s\" -type \"double3\" 3 3 3 ;\n\
             createNode camera -n \"camShape\" -p \"cam\";\n{attrs}"
        );
        read(&text).map(|s| s.camera.unwrap().clip)
    };
    // Set planes are in the file's unit, stretched by the camera's scale of 3.
    assert_eq!(clip("", "\tsetAttr \".ncp\" 0.5;\n\tsetAttr \".fcp\" 200;\n").unwrap(), [1.5, 600.0]);
    assert_eq!(clip("", "\tsetAttr \".nearClipPlane\" 2;\n").unwrap(), [6.0, 30_000.0]);
    // The node defaults, 0.1 and 10000 cm, in metres.
    let [near, far] = clip("currentUnit -l meter;\n", "").unwrap();
    assert!((near - 0.003).abs() < 1e-7 && (far - 300.0).abs() < 1e-3, "{near} {far}");
    let e = clip("", "\tsetAttr \".ncp\" 10;\n\tsetAttr \".fcp\" 1;\n").unwrap_err().to_string();
    assert!(e.contains("line 3") && e.contains("clip planes"), "{e}");
}

#[test]
fn poly_spheres_have_mayas_uv_layout_so_every_follicle_finds_its_place() {
    use crate::hair_system::follicles::follicles_at_uvs;
    let m = poly_sphere(2.0, 20, 20).polygon_mesh().triangulate(true).0;
    assert!(m.positions.iter().all(|p| (p.length() - 2.0).abs() < 1e-5));
    // Between the pole fans' triangles the layout has gaps, as Maya's has: a follicle
    // there (the MtoA hair tests put one at (0.09375, 0.03125)) takes the nearest UV, on
    // the fan beside it; one inside a fan ((0.03125, 0.03125)) is on it.
    let found = follicles_at_uvs(&m, &[[0.03125, 0.03125], [0.09375, 0.03125], [0.3, 0.5]]).unwrap();
    let d: Vec<f32> = found.iter().map(|f| f.unwrap().uv_distance).collect();
    assert!(d[0] == 0.0 && d[1] > 0.0 && d[1] < 0.01 && d[2] == 0.0, "{d:?}");
    let at = |uv: [f32; 2]| follicles_at_uvs(&m, &[uv]).unwrap()[0].unwrap().follicle;
    assert!(at([0.09375, 0.03125]).position.y < -1.9);
    // v runs from the −Y pole up; u = 0.5 is the vertex at azimuth 360° × 11 / 20 from +X
    // towards −Z.
    assert!(at([0.03125, 0.03125]).position.y < -1.9);
    assert!(at([0.5, 0.97]).position.y > 1.9);
    let a = (198.0f32).to_radians();
    let p = at([0.5, 0.5]);
    assert!((p.position - Vec3::new(2.0 * a.cos(), 0.0, -2.0 * a.sin())).length() < 1e-4, "{}", p.position);
    assert!(p.normal.dot(p.position.normalize()) > 0.999);
    // Faces are wound outwards.
    for t in 0..m.indices.len() as u32 {
        let [a, b, c] = m.corners(t);
        assert!((b - a).cross(c - a).dot(a + b + c) > 0.0, "triangle {t}");
    }
}

#[test]
fn deformed_shapes_are_drawn_once_in_their_rest_pose_and_intermediate_shapes_never() {
    // A skinned curve and mesh as Maya writes them: the deformed shapes store no geometry
    // (a skinCluster computes it from the intermediate `…Orig` shape through groupParts),
    // and a leftover intermediate curve feeds nothing.
    let text = r#"//Maya ASCII 2020 scene
createNode transform -n "crv";
	setAttr ".t" -type "double3" 0 5 0 ;
createNode nurbsCurve -n "crvShape" -p "crv";
	setAttr -k off ".v";
createNode nurbsCurve -n "crvShapeOrig" -p "crv";
	setAttr -k off ".v";
	setAttr ".io" yes;
	setAttr ".cc" -type "nurbsCurve"
		1 1 0 no 3
		2 0 1
		2
		0 0 0
		0 2 0
		;
createNode nurbsCurve -n "crvShape1Orig" -p "crv";
	setAttr ".io" yes;
	setAttr ".cc" -type "nurbsCurve"
		1 1 0 no 3
		2 0 1
		2
		1 0 0
		1 2 0
		;
createNode transform -n "box";
createNode mesh -n "boxShape" -p "box";
createNode mesh -n "boxShapeOrig" -p "box";
	setAttr ".io" yes;
	setAttr -s 3 ".vt[0:2]"  0 0 0 1 0 0 0 1 0;
	setAttr -s 3 ".ed[0:2]"  0 1 0 1 2 0 2 0 0;
	setAttr -s 1 ".fc[0]" -type "polyFaces"
		f 3 0 1 2 ;
createNode groupParts -n "groupParts1";
createNode skinCluster -n "skinCluster1";
createNode tweak -n "tweak1";
createNode skinCluster -n "skinCluster2";
connectAttr "crvShapeOrig.ws" "groupParts1.ig";
connectAttr "groupParts1.og" "tweak1.ip[0].ig";
connectAttr "tweak1.og[0]" "skinCluster1.ip[0].ig";
connectAttr "skinCluster1.og[0]" "crvShape.cr";
connectAttr "boxShapeOrig.w" "skinCluster2.ip[0].ig";
connectAttr "skinCluster2.og[0]" "boxShape.i";
"#;
    let s = read(text).unwrap();
    assert_eq!(s.contents.hair.len(), 1);
    let HairSource::Inline(set) = &s.contents.hair[0].source else { panic!("inline") };
    assert_eq!(set.strand_count(), 1, "only the deformed curve, once");
    let ends = [set.points[0], *set.points.last().unwrap()].map(|p| Vec3::from_slice(&p[..3]));
    assert!(close(ends[0], Vec3::new(0.0, 5.0, 0.0)) && close(ends[1], Vec3::new(0.0, 7.0, 0.0)), "{ends:?}");
    assert_eq!(s.contents.meshes.len(), 1, "only the deformed mesh, once");
    let MeshSource::Inline(m) = &s.contents.meshes[0].source else { panic!("inline") };
    assert_eq!(m.positions.len(), 3);
    let w: Vec<_> = s.warnings.iter().filter(|w| w.contains("rest pose")).collect();
    assert!(
        w.len() == 1 && w[0].starts_with("2 deformed shape(s)") && w[0].contains("skinCluster, tweak"),
        "{:?}",
        s.warnings
    );
    // Without the deformation chain the deformed shapes have nothing to draw, and the
    // intermediate shapes still are not drawn.
    let cut: String = text.lines().filter(|l| !l.starts_with("connectAttr")).collect::<Vec<_>>().join("\n");
    let s = read(&cut).unwrap();
    assert!(s.contents.hair.is_empty() && s.contents.meshes.is_empty(), "{:?}", s.contents.hair.len());
}

#[test]
fn arnolds_sky_dome_is_a_sky_of_its_colour_intensity_and_exposure() {
    let dome = |attrs: &str| {
        read(&format!(
            "//Maya ASCII 2020 scene\nrequires \"mtoa\" \"4.0.0\";\ncreateNode transform -n \"aiSkyDomeLight1\";\n\
             createNode aiSkyDomeLight -n \"aiSkyDomeLightShape1\" -p \"aiSkyDomeLight1\";\n\
             \tsetAttr -k off \".v\";\n{attrs}createNode file -n \"file1\";\n"
        ))
        .unwrap()
    };
    // Colour (`sc`) 0.5 0.25 1 × intensity 2 × 2^1.
    let s = dome(
        "\tsetAttr \".sc\" -type \"float3\" 0.5 0.25 1 ;\n\tsetAttr \".intensity\" 2;\n\tsetAttr \".ai_exposure\" 1;\n",
    );
    assert_eq!(
        s.contents.lights,
        vec![Light::Environment { radiance: Vec3::new(2.0, 1.0, 4.0), camera_visibility: 1.0 }.into()]
    );
    assert!(s.warnings.iter().all(|w| !w.contains("aiSkyDomeLight (")), "a node tress reads: {:?}", s.warnings);
    // Node defaults: white at intensity 1.
    assert_eq!(
        dome("").contents.lights,
        vec![Light::Environment { radiance: Vec3::ONE, camera_visibility: 1.0 }.into()]
    );
    // A texture on its colour is said, and the constant colour lights.
    let s = dome("connectAttr \"file1.oc\" \"aiSkyDomeLightShape1.sc\";\n");
    assert_eq!(s.contents.lights.len(), 1);
    assert!(s.warnings.iter().any(|w| w.contains("aiSkyDomeLightShape1") && w.contains("texture")), "{:?}", s.warnings);
    // A hidden dome lights nothing.
    assert!(dome("\tsetAttr \".v\" no;\n").contents.lights.is_empty());
    // A dome hidden from the camera (`camera` 0, as MtoA writes it) still lights; a weight
    // in between is kept; a negative one is an error naming the node and its line.
    for (w, weight) in [("0", 0.0), ("0.25", 0.25)] {
        let s = dome(&format!("\tsetAttr \".camera\" {w};\n"));
        assert_eq!(
            s.contents.lights,
            vec![Light::Environment { radiance: Vec3::ONE, camera_visibility: weight }.into()]
        );
    }
    let e = read(
        "//Maya ASCII 2020 scene\ncreateNode transform -n \"d\";\n\
         createNode aiSkyDomeLight -n \"dShape\" -p \"d\";\n\tsetAttr \".camera\" -1;\n",
    )
    .unwrap_err()
    .to_string();
    assert!(e.contains("dShape") && e.contains("camera") && e.contains("line 3"), "{e}");
}

#[test]
fn lights_of_a_file_arnold_renders_light_as_arnold_does() {
    let arnold = "select -ne :defaultRenderGlobals;\n\tsetAttr \".ren\" -type \"string\" \"arnold\";\n";
    // Arnold's point light decays quadratically by default, whatever Maya's decay rate, and
    // lights a facing surface to I / d² (no π: Arnold's diffuse divides by π as tress's).
    let e = |attrs: &str| point_light_irradiance(arnold, attrs);
    assert!((e("") - 2.0 / 16.0).abs() < 1e-6, "{}", e(""));
    assert!((e("setAttr \".de\" 1;\n") - 2.0 / 16.0).abs() < 1e-6);
    assert!((e("setAttr \".ai_decay_type\" 0;\n") - 2.0).abs() < 1e-5);
    // Exposure in stops; the distance in centimetres as Maya's.
    assert!((e("setAttr \".ai_exposure\" 3;\n") - 16.0 / 16.0).abs() < 1e-5);
    let m = point_light_irradiance(&format!("currentUnit -l meter;\n{arnold}"), "");
    assert!((m - 2.0 / (400.0f32 * 400.0)).abs() < 1e-9, "{m}");
    // Maya's own renderer for the same light: no decay and π.
    assert!((point_light_irradiance("", "") / PI - 2.0).abs() < 1e-5);
    // A directional light: irradiance I under Arnold, π I under Maya's renderer.
    let sun = |head: &str| {
        let s = read(&format!("{head}createNode directionalLight -n d;\n\tsetAttr \".in\" 3;\n")).unwrap();
        let LightSource::Inline(Light::Distant { irradiance, .. }) = s.contents.lights[0] else {
            panic!("{:?}", s.contents.lights)
        };
        irradiance.x
    };
    assert!((sun(arnold) - 3.0).abs() < 1e-6 && (sun("") - 3.0 * PI).abs() < 1e-5);
    // Arnold's quad light (`aiAreaLight`), 4 units wide in metres: its intensity × 2^exposure
    // spread over its area in square centimetres, unless normalize is off.
    let quad = |attrs: &str| {
        let s = read(&format!(
            "currentUnit -l meter;\ncreateNode transform -n q;\n\tsetAttr \".s\" -type \"double3\" 2 1 1;\n\
             createNode aiAreaLight -n qs -p q;\n\tsetAttr \".sc\" -type \"float3\" 1 0.5 0;\n\tsetAttr \".intensity\" 8;\n{attrs}"
        ))
        .unwrap();
        let LightSource::Inline(Light::Quad { edge_u, edge_v, radiance, camera_visibility, .. }) = s.contents.lights[0]
        else {
            panic!("{:?}", s.contents.lights)
        };
        assert!((edge_u.cross(edge_v).length() - 8.0).abs() < 1e-5);
        (radiance, camera_visibility)
    };
    let area_cm2 = 8.0 * 100.0 * 100.0;
    let (radiance, seen) = quad("\tsetAttr \".ai_exposure\" 1;\n");
    assert!((radiance - Vec3::new(16.0, 8.0, 0.0) / area_cm2).length() < 1e-9);
    assert_eq!(quad("\tsetAttr \".ai_normalize\" 0;\n").0, Vec3::new(8.0, 4.0, 0.0));
    // Hidden from the camera, as Arnold's area lights are, unless `ai_camera` shows it.
    assert_eq!((seen, quad("\tsetAttr \".ai_camera\" 1;\n").1), (0.0, 1.0));
}

#[test]
fn curves_arnold_renders_take_arnolds_width() {
    let open = |name: &str, parent: &str, attrs: &str| {
        format!(
            "createNode transform -n {name} {parent};\ncreateNode nurbsCurve -n {name}s -p {name};\n{attrs}\
             setAttr \".cc\" -type \"nurbsCurve\" 1 1 0 no 3 2 0 1 2 0 0 0 0 30 0;\n"
        )
    };
    let closed = |name: &str, attrs: &str| {
        format!(
            "createNode transform -n {name};\ncreateNode nurbsCurve -n {name}s -p {name};\n{attrs}\
             setAttr \".cc\" -type \"nurbsCurve\" 1 3 1 no 3 4 0 1 2 3 4 0 0 0 1 0 0 1 1 0 0 0 0;\n"
        )
    };
    let text = |unit: &str| {
        [
            format!("currentUnit -l {unit};\n"),
            open("own", "", "setAttr \".cwdth\" 0.5;\n"),
            "createNode transform -n col;\ncreateNode aiCurveCollector -n cols -p col;\nsetAttr \".aiCurveWidth\" 0.2;\n\
             createNode transform -n grp -p col;\n"
                .to_string(),
            open("collected", "-p grp", ""),
            open("marked", "", "setAttr \".rcurve\" yes;\n"),
            open("plain", "", ""),
            closed("ring", "setAttr \".rcurve\" yes;\n"),
            closed("control", ""),
        ]
        .concat()
    };
    let radii = |s: &Imported| {
        let HairSource::Inline(set) = &s.contents.hair[0].source else { panic!("inline") };
        (0..set.strand_count()).map(|i| set.points[set.offsets[i] as usize][3]).collect::<Vec<_>>()
    };
    let s = read(&text("centimeter")).unwrap();
    let r = radii(&s);
    // Own width 0.5, the collector's 0.2, MtoA's default 0.01, a thousandth of the scene (30
    // units tall) for the plain curve, and the closed render curve at 0.01.
    let want = [0.25, 0.1, 0.005, 0.5 * 0.03, 0.005];
    assert_eq!(r.len(), want.len(), "{r:?}");
    assert!(r.iter().zip(want).all(|(a, b)| (a - b).abs() < 1e-3 * b), "{r:?}");
    assert!(s.warnings.iter().any(|w| w.starts_with("1 curve(s) outside hair systems")), "{:?}", s.warnings);
    assert!(s.warnings.iter().any(|w| w.contains("skipped 1 closed")), "{:?}", s.warnings);
    assert!(s.warnings.iter().all(|w| !w.contains("aiCurveCollector")), "a node tress reads: {:?}", s.warnings);
    // MtoA's widths are centimetres whatever the file's unit.
    let r = radii(&read(&text("meter")).unwrap());
    assert!((r[0] - 0.0025).abs() < 1e-8 && (r[1] - 0.001).abs() < 1e-8, "{r:?}");
}

/// A curve shape `name` built by a `makeNurbCircle` node with `attrs`, marked for Arnold.
fn circle_scene(name: &str, attrs: &str) -> String {
    format!(
        "createNode transform -n {name};\ncreateNode nurbsCurve -n {name}Shape -p {name};\n\tsetAttr \".rcurve\" yes;\n\
         createNode makeNurbCircle -n make_{name};\n{attrs}connectAttr \"make_{name}.oc\" \"{name}Shape.cr\";\n"
    )
}

fn strands(s: &Imported) -> Vec<Vec<Vec3>> {
    let HairSource::Inline(set) = &s.contents.hair[0].source else { panic!("inline") };
    (0..set.strand_count())
        .map(|i| {
            let (a, b) = (set.offsets[i] as usize, set.offsets[i + 1] as usize);
            set.points[a..b].iter().map(|p| Vec3::new(p[0], p[1], p[2])).collect()
        })
        .collect()
}

#[test]
fn make_nurb_circle_builds_the_curve_maya_writes_for_it() {
    // Maya's default circle from the menu (normal +Y, radius 1, 8 sections) as Maya writes
    // its `.cc`, beside the same circle built from its history node.
    let written = "createNode transform -n written;\ncreateNode nurbsCurve -n writtenShape -p written;\n\
        \tsetAttr \".rcurve\" yes;\n\tsetAttr \".cc\" -type \"nurbsCurve\"\n\t\t3 8 2 no 3\n\
        \t\t13 -2 -1 0 1 2 3 4 5 6 7 8 9 10\n\t\t11\n\
        \t\t0.78361162489122504 4.7982373409884682e-17 -0.78361162489122382\n\
        \t\t6.7857323231109134e-17 6.7857323231109146e-17 -1.1081941875543879\n\
        \t\t-0.78361162489122427 4.7982373409884713e-17 -0.78361162489122427\n\
        \t\t-1.1081941875543879 1.9663354616187859e-32 -3.2112695072372299e-16\n\
        \t\t-0.78361162489122449 -4.7982373409884694e-17 0.78361162489122405\n\
        \t\t-1.1100856969603225e-16 -6.7857323231109171e-17 1.1081941875543883\n\
        \t\t0.78361162489122382 -4.7982373409884719e-17 0.78361162489122438\n\
        \t\t1.1081941875543879 -3.6446300679047921e-32 5.9521325992805852e-16\n\
        \t\t0.78361162489122504 4.7982373409884682e-17 -0.78361162489122382\n\
        \t\t6.7857323231109134e-17 6.7857323231109146e-17 -1.1081941875543879\n\
        \t\t-0.78361162489122427 4.7982373409884713e-17 -0.78361162489122427\n\t\t;\n";
    let built = circle_scene("built", "\tsetAttr \".nr\" -type \"double3\" 0 1 0 ;\n");
    let s = read(&format!("{written}{built}")).unwrap();
    let c = strands(&s);
    assert_eq!(c.len(), 2, "{:?}", s.warnings);
    assert_eq!(c[0].len(), 8 * SAMPLES_PER_SPAN + 1);
    assert_eq!(c[0].len(), c[1].len());
    assert!(c[0].iter().zip(&c[1]).all(|(a, b)| (*a - *b).length() < 1e-5), "{:?}\n{:?}", c[0], c[1]);
    assert!(s.warnings.iter().all(|w| !w.contains("makeNurbCircle")), "{:?}", s.warnings);
}

#[test]
fn make_nurb_circle_lies_at_its_radius_in_the_plane_of_its_normal() {
    let attrs = "\tsetAttr \".c\" -type \"double3\" 1 2 3 ;\n\tsetAttr \".nr\" -type \"double3\" 1 1 0 ;\n\
                 \tsetAttr \".r\" 2.5;\n\tsetAttr \".s\" 12;\n";
    let s = read(&circle_scene("ring", attrs)).unwrap();
    let c = &strands(&s)[0];
    let (center, normal) = (Vec3::new(1.0, 2.0, 3.0), Vec3::new(1.0, 1.0, 0.0).normalize());
    assert_eq!(c.len(), 12 * SAMPLES_PER_SPAN + 1);
    assert!(close(c[0], c[c.len() - 1]), "a closed circle");
    for (i, p) in c.iter().enumerate() {
        let d = *p - center;
        assert!(d.dot(normal).abs() < 1e-5, "point {i} {p} off the plane");
        // On the circle at each knot; a 12-span cubic strays 0.05 % between them.
        let r = d.length();
        match i % SAMPLES_PER_SPAN {
            0 => assert!((r - 2.5).abs() < 1e-5, "knot point {i} at radius {r}"),
            _ => assert!((r - 2.5).abs() < 2.5 * 5e-4, "point {i} at radius {r}"),
        }
    }
    // An arc of 90° (in the file's degrees) with one linear section per 15°: an open curve
    // whose corners are on the circle, drawn without being marked for Arnold.
    let arc = circle_scene("arc", "\tsetAttr \".sw\" 90;\n\tsetAttr \".d\" 1;\n\tsetAttr \".s\" 6;\n")
        .replace("\tsetAttr \".rcurve\" yes;\n", "");
    let s = read(&arc).unwrap();
    let c = &strands(&s)[0];
    assert_eq!(c.len(), 7);
    assert!(c.iter().all(|p| (p.length() - 1.0).abs() < 1e-5 && p.z.abs() < 1e-6), "{c:?}");
    assert!(close(c[0], Vec3::X) && close(c[6], Vec3::Y), "from the first point +X, turning about +Z: {c:?}");
    // A full circle not marked for Arnold is a rig control.
    let control = circle_scene("control", "").replace("\tsetAttr \".rcurve\" yes;\n", "");
    let s = read(&control).unwrap();
    assert!(s.contents.hair.is_empty());
    assert!(s.warnings.iter().any(|w| w.contains("skipped 1 closed")), "{:?}", s.warnings);
}

#[test]
fn make_nurb_circle_refuses_or_clamps_bad_values() {
    let err = |attrs: &str| read(&circle_scene("c", attrs)).unwrap_err().to_string();
    assert!(err("\tsetAttr \".r\" 0;\n").contains("radius 0"), "{}", err("\tsetAttr \".r\" 0;\n"));
    assert!(err("\tsetAttr \".d\" 2;\n").contains("degree 2"));
    assert!(err("\tsetAttr \".nr\" -type \"double3\" 0 0 0 ;\n").contains("no direction"));
    assert!(err("\tsetAttr \".sw\" 0;\n").contains("sweep"));
    assert!(err("\tsetAttr \".r\" nan;\n").contains("line 5"));
    for (sections, want) in [("-3", 3), ("1e12", history::MAX_SECTIONS)] {
        let s = read(&circle_scene("c", &format!("\tsetAttr \".s\" {sections};\n"))).unwrap();
        assert_eq!(strands(&s)[0].len(), want * SAMPLES_PER_SPAN + 1);
        assert!(s.warnings.iter().any(|w| w.contains("clamped")), "{:?}", s.warnings);
    }
    // With its tolerance used, the fewest sections keeping within it.
    let s = read(&circle_scene("c", "\tsetAttr \".ut\" yes;\n\tsetAttr \".tol\" 0.001;\n")).unwrap();
    let c = &strands(&s)[0];
    let sections = (c.len() - 1) / SAMPLES_PER_SPAN;
    assert!(c.iter().all(|p| (p.length() - 1.0).abs() <= 0.001 + 1e-6));
    assert!((4..=12).contains(&sections), "{sections}");
    // History tress cannot evaluate is said, not silently dropped.
    let s =
        read("createNode nurbsCurve -n shape;\ncreateNode rebuildCurve -n rb;\nconnectAttr \"rb.oc\" \"shape.cr\";\n")
            .unwrap();
    assert!(s.warnings.iter().any(|w| w.contains("1 curve(s) built by history") && w.contains("rebuildCurve")));
}

#[test]
fn a_curve_collectors_width_profile_scales_widths_root_to_tip() {
    // A five-point polyline under a collector 0.2 wide whose profile falls linearly from 1
    // at the root to 0.2 at the tip, written whole, then by child as MtoA names them.
    let curve = "createNode transform -n grp -p col;\ncreateNode transform -n c1 -p grp;\n\
                 createNode nurbsCurve -n c1s -p c1;\n\
                 setAttr \".cc\" -type \"nurbsCurve\" 1 4 0 no 3 5 0 1 2 3 4 5 0 0 0 0 1 0 0 2 0 0 3 0 0 4 0;\n";
    let head = "createNode transform -n col;\ncreateNode aiCurveCollector -n cols -p col;\n\
                setAttr \".aiCurveWidth\" 0.2;\n";
    let whole = "setAttr -s 2 \".wdthP[0:1]\" 0 1 1 1 0.2 1;\n";
    let by_child = "setAttr \".wdthP[0].wdthP_Position\" 0;\nsetAttr \".wdthP[0].wdthP_FloatValue\" 1;\n\
                    setAttr \".wdthP[0].wdthP_Interp\" 1;\nsetAttr \".wdthP[1].wdthP_Position\" 1;\n\
                    setAttr \".wdthP[1].wdthP_FloatValue\" 0.2;\nsetAttr \".wdthP[1].wdthP_Interp\" 1;\n";
    for profile in [whole, by_child] {
        let s = read(&format!("{head}{profile}{curve}")).unwrap();
        let HairSource::Inline(set) = &s.contents.hair[0].source else { panic!("inline") };
        let r: Vec<f32> = set.points.iter().map(|p| p[3]).collect();
        let want: Vec<f32> = (0..5).map(|k| 0.1 * (1.0 - 0.8 * k as f32 / 4.0)).collect();
        assert!(r.iter().zip(&want).all(|(a, b)| (a - b).abs() < 1e-6), "{r:?} {want:?}");
    }
    // Without a profile the width is the same all along.
    let s = read(&format!("{head}{curve}")).unwrap();
    let HairSource::Inline(set) = &s.contents.hair[0].source else { panic!("inline") };
    assert!(set.points.iter().all(|p| (p[3] - 0.1).abs() < 1e-6));
    // A curve drawn as the hair system draws its hairs narrows along the system's
    // `hairWidthScale` as its hairs do.
    let text = "createNode hairSystem -n hs;\nsetAttr \".hwd\" 0.04;\nsetAttr -s 2 \".hws[0:1]\" 0 1 1 1 0.5 1;\n\
                createNode transform -n c1;\ncreateNode nurbsCurve -n c1s -p c1;\n\
                setAttr \".cc\" -type \"nurbsCurve\" 1 1 0 no 3 2 0 1 2 0 0 0 0 1 0;\n";
    let s = read(text).unwrap();
    let HairSource::Inline(set) = &s.contents.hair[0].source else { panic!("inline") };
    assert!((set.points[0][3] - 0.02).abs() < 1e-6 && (set.points[1][3] - 0.01).abs() < 1e-6, "{:?}", set.points);
}

/// `.csd` of an `xgmSplineBase` holding `strands`, as quoted words.
fn spline_data_words(strands: &[&[[f32; 3]]], widths: Option<&[f32]>) -> String {
    let words = xgen::tests::value(strands, widths, 70);
    words.iter().map(|w| format!("\"{}\"", w.replace('"', "\\\""))).collect::<Vec<_>>().join("\n")
}

#[test]
fn xgen_interactive_grooms_are_drawn_from_the_spline_data_in_the_file() {
    let a: &[[f32; 3]] = &[[0.0, 0.0, 0.0], [0.0, 0.5, 0.0], [0.0, 1.0, 0.0]];
    let b: &[[f32; 3]] = &[[1.0, 0.0, 0.0], [1.0, 0.5, 0.2], [1.0, 1.0, 0.4]];
    let groom = |description: &str| {
        format!(
            "createNode transform -n description1;\ncreateNode xgmSplineDescription -n description1_Shape -p description1;\n\
             {description}createNode xgmSplineBase -n description1_base;\n\
             \tsetAttr \".csd\" -type \"xgmSplineData\" {};\ncreateNode xgmModifierSculpt -n sculpt;\n\
             connectAttr \"description1_base.osd\" \"sculpt.isd\";\nconnectAttr \"sculpt.osd\" \"description1_Shape.isd\";\n",
            spline_data_words(&[a, b], Some(&[1.0, 1.0, 0.5, 2.0, 2.0, 2.0]))
        )
    };
    // Width scale 0.1, a width ramp from 1 at the root to 0.5 at the tip, and the per-CV widths.
    let s = read(&groom("\tsetAttr \".w\" 0.1;\n\tsetAttr -s 2 \".wdr[0:1]\" 0 1 1 1 0.5 1;\n")).unwrap();
    let c = strands(&s);
    assert_eq!(c.len(), 2);
    assert_eq!(c[1], b.iter().map(|p| Vec3::from_array(*p)).collect::<Vec<_>>());
    let HairSource::Inline(set) = &s.contents.hair[0].source else { panic!("inline") };
    let r: Vec<f32> = set.points.iter().map(|p| p[3]).collect();
    let want = [0.05, 0.0375, 0.0125, 0.1, 0.075, 0.05];
    assert!(r.iter().zip(want).all(|(a, b)| (a - b).abs() < 1e-6), "{r:?}");
    assert!(s.warnings.iter().any(|w| w.contains("before its modifiers (xgmModifierSculpt)")), "{:?}", s.warnings);
    assert!(s.warnings.iter().all(|w| !w.contains("xgmSplineBase")), "{:?}", s.warnings);
    // Without a width scale, one relative to the scene, said.
    let s = read(&groom("")).unwrap();
    assert!(s.warnings.iter().any(|w| w.contains("set no width scale")), "{:?}", s.warnings);
    // A hidden description draws nothing; damaged data is an error naming the base node.
    assert!(read(&groom("\tsetAttr \".v\" no;\n")).unwrap().contents.hair.is_empty());
    let damaged = groom("").replace("\"Group\"", "\"Grope\"");
    let e = read(&damaged).unwrap_err().to_string();
    assert!(e.contains("xgmSplineBase description1_base") && e.contains("line 4"), "{e}");
    // A classic XGen collection's strands live in files beside the scene: said, naming them.
    let classic = "createNode xgmPalette -n collection1;\n\tsetAttr \".xfn\" -type \"string\" \"scene__collection1.xgen\";\n\
                   createNode transform -n description2 -p collection1;\ncreateNode xgmDescription -n description2Shape -p description2;\n";
    let s = read(classic).unwrap();
    assert!(
        s.warnings
            .iter()
            .any(|w| w.contains("collection1 (descriptions: description2Shape)")
                && w.contains("`scene__collection1.xgen`")),
        "{:?}",
        s.warnings
    );
}

#[test]
fn follicles_without_a_start_curve_use_their_output_curve_or_give_no_hair() {
    let system = "createNode transform -n hs;\ncreateNode hairSystem -n hss -p hs;\n";
    let follicle = |n: u32, out: &str| {
        format!(
            "createNode transform -n f{n};\ncreateNode follicle -n f{n}s -p f{n};\n\tsetAttr \".pu\" 0.5;\n\
             connectAttr \"f{n}s.oha\" \"hss.ih[{n}]\";\n{out}"
        )
    };
    // The output curve Maya computed, stored in the file: the follicle's guide.
    let out = "createNode transform -n oc1;\ncreateNode nurbsCurve -n oc1s -p oc1;\n\
               \tsetAttr \".cc\" -type \"nurbsCurve\" 1 1 0 no 3 2 0 1 2 0 0 0 0 3 0;\n\
               connectAttr \"f0s.oc\" \"oc1s.cr\";\n";
    let s = read(&format!("{system}{}{}", follicle(0, out), follicle(1, ""))).unwrap();
    let GuideSource::Inline(g) = &s.contents.hair_systems[0].guides else { panic!("inline") };
    assert_eq!(g.curves.strand_count(), 1);
    let tip = g.curves.points[1];
    assert_eq!((tip[0], tip[1], tip[2]), (0.0, 3.0, 0.0));
    assert_eq!(g.root_uv.as_ref().unwrap()[0], [0.5, 0.0]);
    assert!(s.contents.hair.is_empty(), "the output curve is not drawn again as a free curve");
    assert!(
        s.warnings.iter().any(|w| w.contains("1 follicle(s) without a start, rest or output curve")),
        "{:?}",
        s.warnings
    );
    // A hair system without follicles says so.
    let s = read(system).unwrap();
    assert!(s.warnings.iter().any(|w| w.contains("hss: the hair system has no follicles")), "{:?}", s.warnings);
}

/// A file Arnold renders: an `aiStandardHair` (`ai_`-style and long names, a colour by
/// component, a ramp on its base colour) on a collector's curve, the same shader through a
/// set override on a second curve, another shader type on a third, and a fourth curve
/// with no shader.
const ARNOLD_CURVES: &str = r#"select -ne :defaultRenderGlobals;
	setAttr ".ren" -type "string" "arnold";
createNode aiStandardHair -n "brown";
	setAttr ".melanin" 0.5;
	setAttr ".melaninRedness" 0.25;
	setAttr ".roughness" 0.4;
	setAttr ".roughness_azimuthal" 0.6;
	setAttr ".roughness_anisotropic" yes;
	setAttr ".ior" 1.4;
	setAttr ".shift" 5;
	setAttr ".specular_tintG" 0.5;
createNode ramp -n "ramp1";
createNode aiUtility -n "flat";
createNode transform -n "col";
createNode aiCurveCollector -n "cols" -p "col";
createNode transform -n "a" -p "col";
createNode nurbsCurve -n "as" -p "a";
	setAttr ".cc" -type "nurbsCurve" 1 1 0 no 3 2 0 1 2 0 0 0 0 1 0;
createNode transform -n "b";
createNode nurbsCurve -n "bs" -p "b";
	setAttr ".cc" -type "nurbsCurve" 1 1 0 no 3 2 0 1 2 1 0 0 1 1 0;
createNode transform -n "c";
createNode nurbsCurve -n "cs" -p "c";
	setAttr ".cc" -type "nurbsCurve" 1 1 0 no 3 2 0 1 2 2 0 0 2 1 0;
createNode transform -n "d";
createNode nurbsCurve -n "ds" -p "d";
	setAttr ".cc" -type "nurbsCurve" 1 1 0 no 3 2 0 1 2 3 0 0 3 1 0;
createNode objectSet -n "set1";
connectAttr "brown.out" "cols.aiCurveShader";
connectAttr "ramp1.oc" "brown.base_color";
connectAttr "b.iog" "set1.dsm" -na;
connectAttr "brown.out" "set1.ai_curve_shader";
connectAttr "flat.out" "cs.ai_curve_shader";
"#;

#[test]
fn arnold_standard_hair_on_curves_becomes_the_physical_material_with_its_values() {
    let s = read(ARNOLD_CURVES).unwrap();
    let hair = &s.contents.hair;
    // The brown shader's two curves, then tube shading (the unread shader), then Arnold's
    // default standard_hair: one entry per material, strands in file order.
    assert_eq!(hair.len(), 3, "{hair:?}");
    let strands = |i: usize| {
        let HairSource::Inline(set) = &hair[i].source else { panic!("inline") };
        set.strand_count()
    };
    assert_eq!((strands(0), strands(1), strands(2)), (2, 1, 1));
    let crate::scene::MaterialSource::Inline(Material::Physical(brown)) = &hair[0].material else {
        panic!("{:?}", hair[0].material)
    };
    let p = brown.params();
    assert_eq!((p.beta_m, p.beta_n, p.eta, p.alpha_degrees), (0.4, 0.6, 1.4, 5.0));
    // Melanin 0.5 is the concentration ln 2, a quarter of it pheomelanin.
    let Absorption::Melanin { eumelanin, pheomelanin } = p.absorption else { panic!("{:?}", p.absorption) };
    assert!((eumelanin - 0.75 * 2f32.ln()).abs() < 1e-6 && (pheomelanin - 0.25 * 2f32.ln()).abs() < 1e-6);
    assert!(matches!(hair[1].material, crate::scene::MaterialSource::Inline(Material::Tube(_))));
    let crate::scene::MaterialSource::Inline(Material::Physical(default)) = &hair[2].material else { panic!() };
    assert_eq!(default.params().beta_m, 0.2);
    // One warning for what the brown shader holds that tress cannot (named once though
    // two curves use it), one for the unread type.
    let brown_w: Vec<&String> = s.warnings.iter().filter(|w| w.starts_with("brown:")).collect();
    assert_eq!(brown_w.len(), 1, "{:?}", s.warnings);
    assert!(brown_w[0].contains("specular_tint (1, 0.5, 1)") && brown_w[0].contains("base_color"), "{brown_w:?}");
    assert!(s.warnings.iter().any(|w| w.contains("aiUtility (1)")), "{:?}", s.warnings);
    assert!(s.warnings.iter().all(|w| !w.contains("aiStandardHair (")), "a type tress reads: {:?}", s.warnings);
}

#[test]
fn curves_and_hair_systems_without_an_arnold_shader_keep_their_shading_unless_arnold_renders() {
    // Without Arnold (no `currentRenderer`), shaders aside: today's tube shading.
    let plain: String = ARNOLD_CURVES.lines().skip(2).map(|l| format!("{l}\n")).collect();
    let s = read(&plain).unwrap();
    assert!(matches!(
        s.contents.hair.last().unwrap().material,
        crate::scene::MaterialSource::Inline(Material::Tube(_))
    ));
    let tubes = s
        .contents
        .hair
        .iter()
        .filter(|h| matches!(h.material, crate::scene::MaterialSource::Inline(Material::Tube(_))));
    assert_eq!(tubes.count(), 1, "the unread and the unassigned curves share the tube entry");
    // A hair system: tube shading in Maya; under Arnold, MtoA's own standard_hair, a diffuse
    // fibre of the hair colour; with `aiOverrideHair` and an aiStandardHair, that shader.
    let system = |head: &str, tail: &str| {
        let text = format!(
            "{head}createNode transform -n h;\ncreateNode hairSystem -n hs -p h;\n\tsetAttr \".hcl\" -type \"float3\" 0.5 0.3 0.1 ;\n{tail}\
             createNode transform -n f;\ncreateNode follicle -n fs -p f;\ncreateNode transform -n g;\n\
             createNode nurbsCurve -n gs -p g;\n\tsetAttr \".cc\" -type \"nurbsCurve\" 1 1 0 no 3 2 0 1 2 0 0 0 0 1 0;\n\
             connectAttr \"fs.oha\" \"hs.ih[0]\";\nconnectAttr \"gs.ws\" \"fs.sp\";\n"
        );
        let s = read(&text).unwrap();
        s.contents.hair_systems[0].material.clone()
    };
    let arnold = "select -ne :defaultRenderGlobals;\n\tsetAttr \".ren\" -type \"string\" \"arnold\";\n";
    assert!(matches!(system("", ""), crate::scene::MaterialSource::Inline(Material::Tube(_))));
    assert_eq!(system(arnold, ""), Material::Diffuse { color: Vec3::new(0.5, 0.3, 0.1) }.into());
    let over = "\tsetAttr \".ai_override_hair\" yes;\ncreateNode aiStandardHair -n sh;\n\tsetAttr \".melanin\" 0;\n\
                connectAttr \"sh.out\" \"hs.ai_hair_shader\";\n";
    let crate::scene::MaterialSource::Inline(Material::Physical(h)) = system(arnold, over) else { panic!() };
    assert_eq!(h.params().absorption, Absorption::Melanin { eumelanin: 0.0, pheomelanin: 0.0 });
}

/// A 4 × 2 plane one unit up, under an XGen collection whose description's patch is bound
/// to it, and the collection file the palette names, written beside the scene.
const XGEN_SCENE: &str = r#"//Maya ASCII 2017 scene
createNode transform -n "plane1";
	setAttr ".t" -type "double3" 0 1 0 ;
createNode mesh -n "planeShape1" -p "plane1";
	setAttr -s 6 ".uvst[0].uvsp[0:5]" -type "float2" 0 0 0.5 0 1 0 0 1 0.5 1 1 1;
	setAttr -s 6 ".vt[0:5]"  -2 0 1 0 0 1 2 0 1 -2 0 -1 0 0 -1 2 0 -1;
	setAttr -s 7 ".ed[0:6]"  0 1 0 1 2 0 3 4 0 4 5 0 0 3 0 1 4 0 2 5 0;
	setAttr -s 2 -ch 8 ".fc[0:1]" -type "polyFaces"
		f 4 0 5 -3 -5
		mu 0 4 0 1 4 3
		f 4 1 6 -4 -6
		mu 0 4 1 2 5 4 ;
createNode xgmPalette -n "collection1";
	setAttr ".xfn" -type "string" "scene__collection1.xgen";
createNode transform -n "description1" -p "collection1";
createNode xgmDescription -n "description1Shape" -p "description1";
createNode transform -n "plane1_description1" -p "description1";
createNode xgmSubdPatch -n "plane1_description1Shape" -p "plane1_description1";
connectAttr "planeShape1.o" "plane1_description1Shape.geo";
connectAttr "plane1.m" "plane1_description1Shape.t";
"#;

fn xgen_file(density: &str) -> String {
    xgen_text(density, "", "", "")
}

/// A collection file for [`XGEN_SCENE`]: `spline` adds lines to the `SplinePrimitive`,
/// `fx` sections after the Noise module, `patch` lines to the plane's `Patch` record.
fn xgen_text(density: &str, spline: &str, fx: &str, patch: &str) -> String {
    format!(
        "FileVersion 18\n\nPalette\n\tname\t\t\tcollection1\n\tendAttrs\n\nDescription\n\tname\t\t\tdescription1\n\
         \tendAttrs\n\nSplinePrimitive\n\tlength\t\t\t$a=0.7500;#0.05,5.0\\n$a\n\twidth\t\t\t$a=0.0200;#0.005,0.5\\n$a\n\
         {spline}\tendAttrs\n\nNoiseFXModule\n\tname\t\t\tNoise1\n\tendAttrs\n\n{fx}RandomGenerator\n\tdensity\t\t\t{density}\n\
         \tmask\t\t\tmap('${{DESC}}/density/') # painted\n\tendAttrs\n\nPatches\tdescription1\t0\nPatch\tSubd\n\tname\t\tplane1\n\
         {patch}endObject\nendPatches\n"
    )
}

/// Grows a fur entry as the renderer would, on its mesh placed in the world.
fn grow_entry(s: &Imported, f: &crate::scene::FurEntry) -> crate::fur::GrownFur {
    let MeshSource::Inline(m) = &s.contents.meshes[f.mesh].source else { panic!("inline") };
    let mut mesh = m.clone();
    mesh.transform(&s.contents.meshes[f.mesh].transform);
    let options = crate::fur::GrowOptions {
        placement: f.placement,
        seed: f.seed,
        guides: None,
        images: &[],
        grows_on: f.grows_on.as_deref(),
        width_profile: f.width_profile.as_deref(),
    };
    crate::fur::grow(&mesh, &f.description, options).unwrap()
}

#[test]
fn xgen_collections_grow_their_density_and_length_on_the_bound_mesh() {
    let dir = tempfile::tempdir().unwrap();
    let ma = dir.path().join("scene.ma");
    std::fs::write(&ma, XGEN_SCENE).unwrap();
    // Without the collection file: the warning names it, nothing grows.
    let s = read_maya(&ma, None, None).unwrap();
    assert!(s.contents.fur.is_empty());
    assert!(
        s.warnings.iter().any(|w| w.contains("scene__collection1.xgen") && w.contains("not found")),
        "{:?}",
        s.warnings
    );

    std::fs::write(dir.path().join("scene__collection1.xgen"), xgen_file("$a=100.0;#1,1000\\n$a")).unwrap();
    let s = read_maya(&ma, None, None).unwrap();
    assert_eq!(s.contents.fur.len(), 1, "{:?}", s.warnings);
    let f = &s.contents.fur[0];
    // 100 strands per unit area on the plane's 8.
    assert_eq!(f.description.density, 800);
    assert_eq!((f.description[Scalar::Length].value, f.description[Scalar::BaseWidth].value), (0.75, 0.02));
    let w = s.warnings.iter().find(|w| w.contains("description1: approximated")).expect("one warning for it");
    assert!(
        w.contains("Noise1 (as Scraggle 0.00)") && w.contains("RandomGenerator.mask") && w.contains("no guides"),
        "{w}"
    );

    let grown = grow_entry(&s, f);
    let n = grown.strands.strand_count();
    assert!((760..=840).contains(&n), "{n} strands for 800 expected");
    for k in 0..n {
        let (a, b) = (grown.strands.offsets[k] as usize, grown.strands.offsets[k + 1] as usize);
        let (root, tip) = (grown.strands.points[a], grown.strands.points[b - 1]);
        // Roots on the plane (y = 1, inside its 4 × 2), straight up by the length.
        assert!((root[1] - 1.0).abs() < 1e-5 && root[0].abs() <= 2.0 + 1e-5 && root[2].abs() <= 1.0 + 1e-5, "{root:?}");
        let d = Vec3::new(tip[0] - root[0], tip[1] - root[1], tip[2] - root[2]);
        assert!((d.length() - 0.75).abs() < 1e-3 && d.normalize().y.abs() > 0.999, "{d:?}");
    }

    // A density that is not a number: a warning naming the file and line, no strands, no panic.
    std::fs::write(dir.path().join("scene__collection1.xgen"), xgen_file("lots")).unwrap();
    let s = read_maya(&ma, None, None).unwrap();
    assert!(s.contents.fur.is_empty());
    assert!(
        s.warnings.iter().any(|w| w.contains("scene__collection1.xgen: line 21") && w.contains("density")),
        "{:?}",
        s.warnings
    );
}

// ----- animation curves -----

/// The value at `t` of an `animCurveTL` whose attributes are `body`, in a file of `head`
/// (`currentUnit ...`).
fn curve_at(head: &str, body: &str, t: f64) -> f64 {
    let g = parse::parse(&format!("{head}createNode animCurveTL -n c;\n{body}")).unwrap();
    let units = anim::Units { fps: g.frames_per_second, internal_per_file: g.centimeters_per_unit };
    anim::Curve::read(&g, 0, units).unwrap().eval(t)
}

#[test]
fn linear_and_stepped_keys_evaluate_exactly() {
    let keys = "\tsetAttr -s 2 \".ktv[0:1]\"  1 0 11 10;\n";
    let linear = format!("\tsetAttr \".tan\" 2;\n{keys}");
    for (t, v) in [(1.0, 0.0), (4.0, 3.0), (8.5, 7.5), (11.0, 10.0)] {
        assert_eq!(curve_at("", &linear, t), v);
    }
    // Step holds the key's value to the next key; step next takes the next one's.
    let step = format!("{linear}\tsetAttr -s 2 \".kot[0:1]\"  5 5;\n");
    assert_eq!((curve_at("", &step, 10.9), curve_at("", &step, 11.0)), (0.0, 10.0));
    let next = format!("{linear}\tsetAttr \".kot[0]\"  17;\n");
    assert_eq!((curve_at("", &next, 1.0), curve_at("", &next, 1.1)), (0.0, 10.0));
}

#[test]
fn flat_tangents_have_no_slope_at_keys_and_pass_the_middle_at_half() {
    let flat = "\tsetAttr \".tan\" 3;\n\tsetAttr -s 2 \".ktv[0:1]\"  0 0 10 1;\n";
    assert!((curve_at("", flat, 5.0) - 0.5).abs() < 1e-12);
    let h = 1e-4;
    assert!((curve_at("", flat, h) / h).abs() < 1e-3);
    assert!(((1.0 - curve_at("", flat, 10.0 - h)) / h).abs() < 1e-3);
    // Auto (Maya's default) flattens the first and last key as well.
    let auto = "\tsetAttr \".tan\" 18;\n\tsetAttr -s 2 \".ktv[0:1]\"  0 0 10 1;\n";
    assert!((curve_at("", auto, 2.0) - curve_at("", flat, 2.0)).abs() < 1e-12);
}

#[test]
fn spline_tangents_match_the_hermite_curve_of_maya_s_rule() {
    // Slopes: 1 at the first key (its segment's), (0 − 0)/20 = 0 in the middle, −1 at the
    // last. On [0, 10] at s = 1/4: h10·1·10 + h01·10 with h10 = 0.140625, h01 = 0.15625.
    let spline = "\tsetAttr \".tan\" 9;\n\tsetAttr -s 3 \".ktv[0:2]\"  0 0 10 10 20 0;\n";
    assert!((curve_at("", spline, 2.5) - 2.96875).abs() < 1e-12);
    assert!((curve_at("", spline, 5.0) - 6.25).abs() < 1e-12);
    assert!((curve_at("", spline, 15.0) - 6.25).abs() < 1e-12);
    // Keys 0, 10, 10: spline gives the middle key slope 10/20 and overshoots 10 after it;
    // plateau (and auto) flatten it, clamped makes its side towards the equal key linear.
    let keys = "\tsetAttr -s 3 \".ktv[0:2]\"  0 0 10 10 20 10;\n";
    let highest = |tan: u32| {
        let body = format!("\tsetAttr \".tan\" {tan};\n{keys}");
        (100..=200).map(|i| curve_at("", &body, f64::from(i) * 0.1)).fold(f64::MIN, f64::max)
    };
    assert!(highest(9) > 10.1, "{}", highest(9));
    for tan in [10, 16, 18] {
        assert!((highest(tan) - 10.0).abs() < 1e-12, "{tan}: {}", highest(tan));
    }
}

#[test]
fn infinity_cycles_offsets_oscillates_and_extends() {
    let keys = "\tsetAttr \".tan\" 2;\n\tsetAttr -s 2 \".ktv[0:1]\"  0 0 10 10;\n";
    let at = |pre: u32, post: u32, t: f64| {
        curve_at("", &format!("{keys}\tsetAttr \".pre\" {pre};\n\tsetAttr \".pst\" {post};\n"), t)
    };
    assert_eq!((at(0, 0, -5.0), at(0, 0, 15.0)), (0.0, 10.0));
    assert_eq!((at(1, 1, -5.0), at(1, 1, 15.0)), (-5.0, 15.0));
    assert_eq!((at(3, 3, -5.0), at(3, 3, 15.0), at(3, 3, 32.0)), (5.0, 5.0, 2.0));
    assert_eq!((at(4, 4, -5.0), at(4, 4, 15.0), at(4, 4, 32.0)), (-5.0, 15.0, 32.0));
    for (t, v) in [(12.0, 8.0), (22.0, 2.0), (-2.0, 2.0)] {
        assert!((at(5, 5, t) - v).abs() < 1e-12, "{t}: {}", at(5, 5, t));
    }
}

#[test]
fn stored_tangents_are_seconds_and_internal_units() {
    // Out tangent of key 0: x = 1 s, y = 48 cm: 48 cm a second, 2 cm a frame at 24 fps,
    // 1.92 at 25; in a file in metres 0.48 m a second.
    let body = "\tsetAttr \".tan\" 2;\n\tsetAttr -s 2 \".ktv[0:1]\"  0 0 24 24;\n\tsetAttr \".kot[0]\" 1;\n\
                \tsetAttr \".kox[0]\" 1;\n\tsetAttr \".koy[0]\" 48;\n";
    let h = 1e-5;
    let slope = |head: &str| curve_at(head, body, h) / h;
    assert!((slope("currentUnit -t film;\n") - 2.0).abs() < 1e-3);
    assert!((slope("currentUnit -t pal;\n") - 1.92).abs() < 1e-3);
    assert!((slope("currentUnit -l meter -t film;\n") - 0.02).abs() < 1e-3);
    // Weighted: the same handle as a Bézier control point a third of the way along it.
    let weighted = format!("{body}\tsetAttr \".wgt\" yes;\n");
    assert!((curve_at("currentUnit -t film;\n", &weighted, h) / h - 2.0).abs() < 1e-2);
}

/// A camera `cam` 10 units up +z, looking down −z, its transform driven by `curves`.
fn animated_camera(curves: &str, frame: Option<u32>) -> crate::scene::CameraDesc {
    let text = format!(
        "currentUnit -l centimeter -a degree -t film;\ncreateNode transform -n cam;\n\
         \tsetAttr \".t\" -type \"double3\" 0 0 10 ;\ncreateNode camera -n camShape -p cam;\n{curves}"
    );
    parse_maya_with(&text, Path::new("dir/anim.ma"), None, frame).unwrap().camera.unwrap()
}

#[test]
fn animation_curves_move_the_camera_at_the_frame() {
    let tz = "createNode animCurveTL -n cam_translateZ;\n\tsetAttr \".tan\" 2;\n\
              \tsetAttr -s 2 \".ktv[0:1]\"  1 10 11 20;\nconnectAttr \"cam_translateZ.o\" \"cam.translateZ\";\n";
    assert_eq!(animated_camera(tz, Some(1)).eye.z, 10.0);
    assert_eq!(animated_camera(tz, Some(6)).eye.z, 15.0);
    // Without a frame: the saved current time, else the playback start, else frame 1.
    assert_eq!(animated_camera(&format!("{tz}select -ne :time1;\n\tsetAttr \".o\" 11;\n"), None).eye.z, 20.0);
    let playback = "createNode script -n \"sceneConfigurationScriptNode\";\n\
                    \tsetAttr \".b\" -type \"string\" \"playbackOptions -min 6 -max 24 -ast 1 -aet 48 \";\n";
    assert_eq!(animated_camera(&format!("{tz}{playback}"), None).eye.z, 15.0);
    assert_eq!(animated_camera(tz, None).eye.z, 10.0);
    // An angle curve in degrees turns the camera a quarter turn about y: it looks along −x.
    let ry = "createNode animCurveTA -n cam_rotateY;\n\tsetAttr \".tan\" 2;\n\
              \tsetAttr -s 2 \".ktv[0:1]\"  1 0 11 90;\nconnectAttr \"cam_rotateY.o\" \"cam.ry\";\n";
    let c = animated_camera(ry, Some(11));
    assert!(close((c.target - c.eye).normalize(), Vec3::NEG_X), "{:?}", c.target - c.eye);
    let c = animated_camera(ry, Some(6));
    assert!(close((c.target - c.eye).normalize(), Vec3::new(-1.0, 0.0, -1.0).normalize()));
    // The focal length, animated, narrows the view.
    let fl = "createNode animCurveTU -n camShape_focalLength;\n\tsetAttr \".tan\" 2;\n\
              \tsetAttr -s 2 \".ktv[0:1]\"  1 35 2 70;\nconnectAttr \"camShape_focalLength.o\" \"camShape.fl\";\n";
    assert!(animated_camera(fl, Some(2)).vfov < 0.6 * animated_camera(fl, Some(1)).vfov);
}

#[test]
fn bad_curves_and_other_drivers_are_warnings_naming_line_and_node() {
    let warnings = |curves: &str| {
        let text = format!("createNode transform -n cam;\ncreateNode camera -n camShape -p cam;\n{curves}");
        parse_maya_with(&text, Path::new("dir/anim.ma"), None, Some(5)).unwrap().warnings
    };
    let curve = |ktv: &str| {
        format!("createNode animCurveTL -n bad;\n\tsetAttr \".ktv[0:1]\" {ktv};\nconnectAttr \"bad.o\" \"cam.tx\";\n")
    };
    for (ktv, says) in [
        ("1 0 2", "not time/value pairs"),
        ("1 0 nan 1", "must be numbers"),
        ("2 0 1 1", "do not increase"),
        ("1 0 1 1", "do not increase"),
    ] {
        let w = warnings(&curve(ktv));
        assert!(w.iter().any(|w| w.contains("line 4") && w.contains("animCurveTL bad") && w.contains(says)), "{w:?}");
    }
    // Other drivers and attributes tress does not read: one warning per kind, counted.
    let others = "createNode expression -n e1;\nconnectAttr \"e1.out[0]\" \"cam.tx\";\n\
                  createNode expression -n e2;\nconnectAttr \"e2.out[0]\" \"cam.ty\";\n\
                  createNode animCurveUL -n driven;\nconnectAttr \"driven.o\" \"cam.tz\";\n\
                  createNode pointConstraint -n pc -p cam;\nconnectAttr \"pc.ctx\" \"cam.tx\";\n\
                  createNode lambert -n l;\ncreateNode animCurveTU -n lc;\n\tsetAttr \".ktv[0]\" 1 1;\n\
                  connectAttr \"lc.o\" \"l.itr\";\n";
    let w = warnings(others);
    for says in ["expressions (2)", "driven keys (animCurveU*) (1)", "constraints (1)", "lambert.itr (1)"] {
        assert!(w.iter().any(|w| w.contains(says)), "{says}: {w:?}");
    }
}

#[test]
fn xgen_grooms_follow_their_animated_mesh() {
    let a: &[[f32; 3]] = &[[0.0, 1.0, 0.0], [0.0, 2.0, 0.0]];
    // Saved at frame 5, when the sphere stood at x = 4: the splines are there in world space.
    let text = format!(
        "currentUnit -l centimeter -a degree -t film;\ncreateNode transform -n ball;\n\
         createNode mesh -n ballShape -p ball;\ncreateNode polySphere -n ps;\nconnectAttr \"ps.out\" \"ballShape.i\";\n\
         createNode animCurveTL -n ball_tx;\n\tsetAttr \".tan\" 2;\n\tsetAttr -s 2 \".ktv[0:1]\"  1 0 5 4;\n\
         connectAttr \"ball_tx.o\" \"ball.tx\";\nselect -ne :time1;\n\tsetAttr \".o\" 5;\n\
         createNode transform -n d;\ncreateNode xgmSplineDescription -n dShape -p d;\n\tsetAttr \".w\" 0.1;\n\
         createNode xgmSplineBase -n base;\n\tsetAttr \".csd\" -type \"xgmSplineData\" {};\n\
         connectAttr \"base.osd\" \"dShape.isd\";\nconnectAttr \"ballShape.w\" \"base.bm[0]\";\n",
        spline_data_words(&[&a.iter().map(|p| [p[0] + 4.0, p[1], p[2]]).collect::<Vec<_>>()], None)
    );
    let root = |frame| {
        let s = parse_maya_with(&text, Path::new("dir/groom.ma"), None, frame).unwrap();
        strands(&s)[0][0]
    };
    assert!(close(root(None), Vec3::new(4.0, 1.0, 0.0)));
    assert!(close(root(Some(5)), Vec3::new(4.0, 1.0, 0.0)));
    assert!(close(root(Some(1)), Vec3::new(0.0, 1.0, 0.0)), "{}", root(Some(1)));
    assert!(close(root(Some(3)), Vec3::new(2.0, 1.0, 0.0)));
}

#[test]
fn xgen_face_lists_taper_and_width_ramp_shape_the_strands() {
    let dir = tempfile::tempdir().unwrap();
    let ma = dir.path().join("scene.ma");
    std::fs::write(&ma, XGEN_SCENE).unwrap();
    let write = |spline: &str, patch: &str| {
        let text = xgen_text("100.0", spline, "", patch);
        std::fs::write(dir.path().join("scene__collection1.xgen"), text).unwrap();
    };
    // Only face 1 (x from 0 to 2) is listed: 100 per unit area on its 4.
    write("", "\tfaceIds\t\t1\t 1\n");
    let s = read_maya(&ma, None, None).unwrap();
    let f = &s.contents.fur[0];
    assert_eq!(f.description.density, 400, "{:?}", s.warnings);
    let grown = grow_entry(&s, f);
    let n = grown.strands.strand_count();
    assert!((370..=430).contains(&n), "{n} strands for 400 expected");
    for k in 0..n {
        let root = grown.strands.points[grown.strands.offsets[k] as usize];
        assert!(root[0] >= -1e-5 && root[0] <= 2.0 + 1e-5, "a root off the listed face: {root:?}");
    }
    // Every face listed: the whole mesh, as without a list.
    write("", "\tfaceIds\t\t2\t 0 1\n");
    let s = read_maya(&ma, None, None).unwrap();
    assert_eq!((s.contents.fur[0].description.density, s.contents.fur[0].grows_on.as_ref()), (800, None));
    // A face list that does not hold what it promises: the file and line named, no panic.
    write("", "\tfaceIds\t\t3\t 0 1\n");
    let s = read_maya(&ma, None, None).unwrap();
    assert!(s.contents.fur.is_empty());
    assert!(
        s.warnings.iter().any(|w| w.contains("scene__collection1.xgen: line 28") && w.contains("faceIds")),
        "{:?}",
        s.warnings
    );

    // Taper 0.5 from half way, and a width ramp falling linearly from 1 to 0.5: the width
    // is 0.02 to the middle times the ramp (0.75 there), then the taper takes off up to
    // half at the tip, 0.5 × 0.5 of the root's.
    write(
        "\ttaper\t\t\t$a=0.5000;#-1.0,1.0\\n$a\n\ttaperStart\t\t$a=0.5000;#0.0,1.0\\n$a\n\
           \twidthRamp\t\trampUI(0.0,1.0,1:1.0,0.5,1)\n",
        "",
    );
    let s = read_maya(&ma, None, None).unwrap();
    let grown = grow_entry(&s, &s.contents.fur[0]);
    let (a, b) = (grown.strands.offsets[0] as usize, grown.strands.offsets[1] as usize);
    let radius: Vec<f32> = grown.strands.points[a..b].iter().map(|p| p[3]).collect();
    let mid = radius.len() / 2;
    assert!((radius[0] - 0.01).abs() < 1e-6, "{radius:?}");
    assert!((radius[mid] - 0.0075).abs() < 1e-6, "{radius:?}");
    assert!((radius[radius.len() - 1] - 0.0025).abs() < 1e-6, "{radius:?}");
    let w = s.warnings.iter().find(|w| w.contains("description1: approximated")).unwrap();
    assert!(w.contains("taper 0.5 from 0.5, width ramp") && !w.contains("face list"), "{w}");
}

#[test]
fn meshes_take_their_ai_standard_surface() {
    let text = "createNode transform -n p;\ncreateNode mesh -n ps -p p;\ncreateNode polySphere -n sph;\n\
                connectAttr \"sph.out\" \"ps.i\";\ncreateNode aiStandardSurface -n gold;\n\
                \tsetAttr \".metalness\" 1;\n\tsetAttr \".base\" 1;\n\tsetAttr \".base_color\" -type \"float3\" 1 0.8 0.3 ;\n\
                \tsetAttr \".coat\" 1;\ncreateNode shadingEngine -n goldSG;\nconnectAttr \"gold.oc\" \"goldSG.ss\";\n\
                connectAttr \"ps.iog\" \"goldSG.dsm\" -na;\n";
    let s = read(text).unwrap();
    let want = StandardSurface {
        metalness: 1.0,
        base: 1.0,
        base_color: Vec3::new(1.0, 0.8, 0.3),
        coat: 1.0,
        ..StandardSurface::default()
    }
    .material("gold", &[]);
    assert_eq!(s.contents.meshes[0].material, want.0.into());
    assert!(s.warnings.iter().any(|w| w.contains("gold: Arnold standard_surface") && w.contains("coat 1")));
}

#[test]
fn arnold_shader_values_beyond_single_precision_are_errors_naming_the_shader() {
    // A base colour of 1e39 under a base weight of 0 would be inf × 0, NaN: refused, naming
    // the node, the parameter and the line of its setAttr; hair shaders alike.
    let surface = "createNode transform -n p;\ncreateNode mesh -n ps -p p;\ncreateNode polySphere -n sph;\n\
                   connectAttr \"sph.out\" \"ps.i\";\ncreateNode aiStandardSurface -n gold;\n\
                   \tsetAttr \".base\" 0;\n\tsetAttr \".base_color\" -type \"float3\" 1e39 0.8 0.3 ;\n\
                   createNode shadingEngine -n goldSG;\nconnectAttr \"gold.oc\" \"goldSG.ss\";\n\
                   connectAttr \"ps.iog\" \"goldSG.dsm\" -na;\n";
    let e = read(surface).unwrap_err().to_string();
    assert_eq!(e, "dir/scene.ma: line 7: gold: `base_color` is beyond single precision", "{e}");
    assert!(read(&surface.replace("1e39", "1e30")).is_ok());
    let hair = ARNOLD_CURVES
        .replace("\tsetAttr \".ior\" 1.4;", "\tsetAttr \".ior\" 1.4;\n\tsetAttr \".diffuseColorR\" -1e39;");
    let e = read(&hair).unwrap_err().to_string();
    assert!(e.starts_with("dir/scene.ma: line 10: brown: `diffuse_color` is beyond single precision"), "{e}");
}

#[test]
fn meshes_take_their_ai_flat_colour_unlit() {
    let text = "createNode transform -n p;\ncreateNode mesh -n ps -p p;\ncreateNode polySphere -n sph;\n\
                connectAttr \"sph.out\" \"ps.i\";\ncreateNode aiFlat -n green;\n\
                \tsetAttr \".color\" -type \"float3\" 0 1 0 ;\ncreateNode shadingEngine -n greenSG;\n\
                connectAttr \"green.oc\" \"greenSG.ss\";\nconnectAttr \"ps.iog\" \"greenSG.dsm\" -na;\n";
    let s = read(text).unwrap();
    assert_eq!(s.contents.meshes[0].material, Material::Unlit { color: Vec3::new(0.0, 1.0, 0.0) }.into());
    // Drawn as Arnold draws it, and a known node type: nothing to say.
    assert!(s.warnings.iter().all(|w| !w.contains("aiFlat") && !w.contains("green")), "{:?}", s.warnings);
}

#[test]
fn xgen_guides_shape_the_strands_at_their_length() {
    let dir = tempfile::tempdir().unwrap();
    let ma = dir.path().join("scene.ma");
    // One guide at the plane's centre, up half a unit then half a unit along +X.
    let guide = "createNode transform -n \"g1\" -p \"plane1_description1\";\n\
                 createNode xgmSplineGuide -n \"g1Shape\" -p \"g1\";\ncreateNode xgmMakeGuide -n \"mg1\";\n\
                 \tsetAttr \".cgm\" -type \"pointArray\" 3 0 1 0 1 0 1.5 0 1 0.5 1.5 0 1 ;\n\
                 connectAttr \"mg1.os\" \"g1Shape.is\";\n";
    std::fs::write(&ma, format!("{XGEN_SCENE}{guide}")).unwrap();
    std::fs::write(dir.path().join("scene__collection1.xgen"), xgen_file("20.0")).unwrap();
    let s = read_maya(&ma, None, None).unwrap();
    let f = &s.contents.fur[0];
    // The description's length scales the guide's.
    assert_eq!(f.description[Scalar::Length].value, 0.75);
    let Some((crate::scene::HairSource::Inline(set), attractors)) = &f.guides else { panic!("guides") };
    let MeshSource::Inline(m) = &s.contents.meshes[f.mesh].source else { panic!("inline") };
    let mut mesh = m.clone();
    mesh.transform(&s.contents.meshes[f.mesh].transform);
    let options = crate::fur::GrowOptions { guides: Some((set, attractors)), ..Default::default() };
    let grown = crate::fur::grow(&mesh, &f.description, options).unwrap();
    assert!(grown.strands.strand_count() > 100);
    for k in 0..grown.strands.strand_count() {
        let (a, b) = (grown.strands.offsets[k] as usize, grown.strands.offsets[k + 1] as usize);
        let (root, tip) = (grown.strands.position(a as u32), grown.strands.position(b as u32 - 1));
        let mid = grown.strands.position(((a + b) / 2) as u32);
        // Every strand follows the bend at 0.75 of the guide's size: tip = root + 0.75 (0.5,
        // 0.5, 0), the middle at the elbow.
        assert!((root.y - 1.0).abs() < 1e-5, "{root}");
        assert!((tip - root - Vec3::new(0.375, 0.375, 0.0)).length() < 1e-3, "{root} -> {tip}");
        // (The guide is resampled by arc length, which rounds the elbow off a little.)
        assert!((mid - root - Vec3::new(0.0, 0.375, 0.0)).length() < 0.02, "{root} mid {mid}");
    }
    let w = s.warnings.iter().find(|w| w.contains("description1: approximated")).unwrap();
    assert!(w.contains("1 guide(s) on 1 of its 1 patch(es)") && !w.contains("along the normal"), "{w}");
}

/// Reads [`XGEN_SCENE`] with a collection file whose FX sections are `fx`, and grows its
/// fur: the warning on the description and the strands.
fn xgen_fx(fx: &str) -> (String, crate::geometry::StrandSet) {
    let dir = tempfile::tempdir().unwrap();
    let ma = dir.path().join("scene.ma");
    std::fs::write(&ma, XGEN_SCENE).unwrap();
    std::fs::write(dir.path().join("scene__collection1.xgen"), xgen_text("50.0", "", fx, "")).unwrap();
    let s = read_maya(&ma, None, None).unwrap();
    let w = s.warnings.iter().find(|w| w.contains("description1: approximated")).unwrap().clone();
    (w, grow_entry(&s, &s.contents.fur[0]).strands)
}

/// Each strand's root and tip.
fn roots_and_tips(set: &crate::geometry::StrandSet) -> Vec<(Vec3, Vec3)> {
    (0..set.strand_count()).map(|k| (set.position(set.offsets[k]), set.position(set.offsets[k + 1] - 1))).collect()
}

#[test]
fn xgen_cut_shortens_the_strands_and_coils_are_named() {
    let cut = "CutFXModule\n\tactive\t\t\ttrue\n\tmask\t\t\t0.8\n\tname\t\t\tCut1\n\tamount\t\t\trand(0.2,0.3)\n\tendAttrs\n\n\
               CoilFXModule\n\tname\t\t\tCoil1\n\tcount\t\t\t0.1\n\tradius\t\t\t0.1\n\tendAttrs\n\n";
    let (w, set) = xgen_fx(cut);
    // 0.75 long, less 0.8 × the mean of rand(0.2, 0.3): 0.55, straight up.
    assert!(set.strand_count() > 300);
    for (root, tip) in roots_and_tips(&set) {
        assert!((tip - root - Vec3::new(0.0, 0.55, 0.0)).length() < 1e-4, "{root} -> {tip}");
    }
    assert!(
        w.contains("FX modules applied as Maya Fur: Noise1 (as Scraggle 0.00), Cut1 (cut 0.200 from the tip)"),
        "{w}"
    );
    assert!(w.contains("FX modules not applied: Coil1 (no Maya Fur counterpart)"), "{w}");
    // An expression the reader cannot evaluate leaves its module out, said.
    let (w, set) = xgen_fx("CutFXModule\n\tname\t\t\tCut1\n\tamount\t\t\t$a*2\n\tendAttrs\n\n");
    assert!(w.contains("Cut1 (amount an expression)"), "{w}");
    assert!(roots_and_tips(&set).iter().all(|(r, t)| ((*t - *r).length() - 0.75).abs() < 1e-4));
}

#[test]
fn xgen_noise_bends_and_clumping_gathers_the_strands() {
    // Noise of magnitude 0.3 (its scale 0.5 to 1 along the strand, mean 0.75) on strands
    // 0.75 long: Scraggle 2 × 0.225 / (π 0.75) = 0.19.
    let noise = "NoiseFXModule\n\tname\t\t\tNoise2\n\tmagnitude\t\t0.3\n\tfrequency\t\t2.0\n\
                 \tmagnitudeScale\t\trampUI(0.0,0.5,1:1.0,1.0,1)\n\tendAttrs\n\n";
    let (w, set) = xgen_fx(noise);
    assert!(w.contains("Noise2 (as Scraggle 0.19)"), "{w}");
    let pairs = roots_and_tips(&set);
    let sideways =
        pairs.iter().map(|(r, t)| Vec3::new(t.x - r.x, 0.0, t.z - r.z).length()).sum::<f32>() / pairs.len() as f32;
    assert!(sideways > 0.03, "tips {sideways} off the normal on average");
    // Clumping 1 at the tip: every tip on its clump centre's, about √(2 × 8) = 4 squared
    // clumps over the 8-unit plane.
    let clump = "ClumpingFXModule\n\tname\t\t\tClumping1\n\tclump\t\t\t1.0\n\tptDensity\t\t2.0\n\
                 \tclumpScale\t\trampUI(0.0,0.0,1:1.0,1.0,1)\n\tendAttrs\n\n";
    let (w, set) = xgen_fx(clump);
    assert!(w.contains("Clumping1 (as Clumping 1.00, 4 clumps across)"), "{w}");
    let pairs = roots_and_tips(&set);
    let mut tips: Vec<[i64; 3]> =
        pairs.iter().map(|(_, t)| [t.x, t.y, t.z].map(|c| (c * 1e4).round() as i64)).collect();
    tips.sort_unstable();
    tips.dedup();
    assert!(pairs.len() > 300 && tips.len() <= 40 && tips.len() >= 4, "{} tips of {}", tips.len(), pairs.len());
}

#[test]
fn face_chunks_after_the_first_take_its_polyfaces_type() {
    // Maya writes `-type "polyFaces"` on the first chunk of a long face list only
    // (`.fc[0:499]`, then `.fc[500:999]` with no type): the plane's two quads in two chunks.
    let mesh = |second: &str| {
        format!(
            "createNode mesh -n m;\n\tsetAttr -s 6 \".vt[0:5]\" -2 0 1 0 0 1 2 0 1 -2 0 -1 0 0 -1 2 0 -1;\n\
             \tsetAttr -s 7 \".ed[0:6]\" 0 1 0 1 2 0 3 4 0 4 5 0 0 3 0 1 4 0 2 5 0;\n\
             \tsetAttr \".fc[0]\" -type \"polyFaces\"\n\t\tf 4 0 5 -3 -5 ;\n\
             \tsetAttr \".fc[1]\"{second}\n\t\tf 4 1 6 -4 -6 ;\n"
        )
    };
    for second in ["", " -type \"polyFaces\""] {
        let s = read(&mesh(second)).unwrap();
        let MeshSource::Inline(m) = &s.contents.meshes[0].source else { panic!() };
        assert_eq!((m.positions.len(), m.indices.len()), (6, 4), "{second:?}");
    }
    // A face list never given its type is still an error naming its line, and so is a
    // malformed chunk that inherits the type.
    let untyped = "createNode mesh -n m;\nsetAttr \".vt[0:1]\" 0 0 0 1 0 0;\nsetAttr \".fc[0]\"\n f 1 0;\n";
    let e = read(untyped).unwrap_err().to_string();
    assert!(e.starts_with("dir/scene.ma: line 3:") && e.contains("polyFaces"), "{e}");
    let e = read(&mesh("").replace("f 4 1 6", "f 9 1 6")).unwrap_err().to_string();
    assert!(e.starts_with("dir/scene.ma: line 7:") && e.contains("polyFaces"), "{e}");
}

#[test]
fn geometry_beyond_single_precision_is_an_error_naming_the_attribute() {
    // Finite in double precision, infinite once stored as f32: UVs and vertices alike.
    for (from, to) in [("0 0 0.5 0 1 0", "0 0 1e39 0 1 0"), ("-2 0 1 0 0 1", "-2 0 1 0 -1e39 1")] {
        assert!(SCENE.contains(from));
        let e = read(&SCENE.replacen(from, to, 1)).unwrap_err().to_string();
        assert!(e.contains("planeShape1") && e.contains("beyond single precision"), "{e}");
    }
    // A follicle Maya places from its UV (it stores no transform): the UV is searched in
    // single precision, so one past it is an error naming the follicle and its line.
    let placed = "createNode follicle -n \"follicleShape3\" -p \"follicle3\";\n\tsetAttr \".pu\" 0.75;";
    assert!(SCENE.contains(placed));
    let line = SCENE[..SCENE.find(placed).unwrap()].lines().count() + 1;
    let e = read(&SCENE.replacen(placed, &placed.replace("0.75", "1e39"), 1)).unwrap_err().to_string();
    assert!(
        e.starts_with(&format!(
            "dir/scene.ma: line {line}: follicle follicleShape3: its UV (`pu`, `pv`) is beyond single precision"
        )),
        "{e}"
    );
}

#[test]
fn point_tweaks_move_stored_and_primitive_vertices() {
    let positions = |s: &Imported| {
        let MeshSource::Inline(m) = &s.contents.meshes[0].source else { panic!() };
        m.positions.clone()
    };
    // The 2 × 1 plane (vertices -2 0 1, 0 0 1, 2 0 1, -2 0 -1, 0 0 -1, 2 0 -1): vertices 1
    // and 2 tweaked whole, vertex 4 by one component and vertex 5 by one then another
    // (the later one wins), vertex 1's x component last of all.
    let plane = "createNode mesh -n m;\n\tsetAttr -s 6 \".vt[0:5]\" -2 0 1 0 0 1 2 0 1 -2 0 -1 0 0 -1 2 0 -1;\n\
                 \tsetAttr -s 7 \".ed[0:6]\" 0 1 0 1 2 0 3 4 0 4 5 0 0 3 0 1 4 0 2 5 0;\n\
                 \tsetAttr -s 2 \".fc[0:1]\" -type \"polyFaces\" f 4 0 5 -3 -5 f 4 1 6 -4 -6 ;\n\
                 \tsetAttr -s 2 \".pt[1:2]\" -type \"float3\" 0 1 0 0 0 3;\n\tsetAttr \".pt[4].py\" 0.5;\n\
                 \tsetAttr \".pnts[5].pntz\" 7;\n\tsetAttr \".pt[5].pz\" -2;\n\tsetAttr \".pt[1].px\" 0.25;\n";
    let p = positions(&read(plane).unwrap());
    let want =
        [[-2.0, 0.0, 1.0], [0.25, 1.0, 1.0], [2.0, 0.0, 4.0], [-2.0, 0.0, -1.0], [0.0, 0.5, -1.0], [2.0, 0.0, -3.0]];
    for w in want {
        assert!(p.iter().any(|q| close(*q, Vec3::from(w))), "{w:?} not in {p:?}");
    }
    assert_eq!(p.len(), 6);
    // A polySphere of 4 columns and 3 rows (radius 1), Maya's numbering: the rings from the
    // bottom, each from azimuth 90° (from +X towards -Z), then the -Y and the +Y pole.
    // Vertex 0 is the first of the bottom ring, at latitude -30°, (0, -0.5, -0.866); vertex 5
    // the second of the top ring, at azimuth 180°, (-0.866, 0.5, 0); vertex 8 the bottom
    // pole, 9 the top one. Tweaked, all move, vertex 0 on both sides of the UV seam and each
    // pole in all 4 of its fan's copies.
    let sphere =
        "createNode transform -n p;\ncreateNode mesh -n ps -p p;\n\tsetAttr \".pt[0]\" -type \"float3\" 1 0 0;\n\
                  \tsetAttr \".pt[9].py\" 1;\n\tsetAttr \".pnts[8].pnty\" -1;\n\tsetAttr \".pt[5].pz\" 2;\n\
                  createNode polySphere -n sph;\n\tsetAttr \".sa\" 4;\n\tsetAttr \".sh\" 3;\n\
                  connectAttr \"sph.out\" \"ps.i\";\n";
    let p = positions(&read(sphere).unwrap());
    let ring = 0.75f32.sqrt();
    let moved = Vec3::new(1.0, -0.5, -ring);
    assert_eq!(p.iter().filter(|q| close(**q, moved)).count(), 2, "{p:?}");
    assert!(!p.iter().any(|q| close(*q, moved - Vec3::X)), "{p:?}");
    assert_eq!(p.iter().filter(|q| close(**q, 2.0 * Vec3::Y)).count(), 4, "{p:?}");
    assert_eq!(p.iter().filter(|q| close(**q, -2.0 * Vec3::Y)).count(), 4, "{p:?}");
    assert_eq!(p.iter().filter(|q| close(**q, Vec3::new(-ring, 0.5, 2.0))).count(), 1, "{p:?}");
    assert!(p.iter().all(|q| q.length() < 1.0 + 1e-6
        || [moved, 2.0 * Vec3::Y, -2.0 * Vec3::Y, Vec3::new(-ring, 0.5, 2.0)].iter().any(|m| close(*q, *m))));
    // Animated (Maya keys each component on its own curve), the tweak is the curve's value
    // at the frame: vertex 4, the first of the top ring (0, 0.5, -0.866), 0 up at frame 1,
    // 2 at frame 11, 1 at frame 6.
    let keyed = format!(
        "{sphere}createNode animCurveTL -n ps_pnts_4__pnty;\n\tsetAttr \".tan\" 2;\n\
         \tsetAttr -s 2 \".ktv[0:1]\"  1 0 11 2;\nconnectAttr \"ps_pnts_4__pnty.o\" \"ps.pt[4].py\";\n"
    );
    for (frame, up) in [(1, 0.0), (6, 1.0), (11, 2.0)] {
        let s = parse_maya_with(&keyed, Path::new("dir/anim.ma"), None, Some(frame)).unwrap();
        assert!(s.warnings.iter().all(|w| !w.contains("mesh.pt")), "{:?}", s.warnings);
        let p = positions(&s);
        assert_eq!(p.iter().filter(|q| close(**q, Vec3::new(0.0, 0.5 + up, -ring))).count(), 2, "{frame}: {p:?}");
    }
    // On a primitive whose vertices tress does not number as Maya (a plane drawn as one
    // quad), the tweaks are said, not applied.
    let s = read(&sphere.replace("polySphere", "polyPlane")).unwrap();
    assert!(s.warnings.iter().any(|w| w.contains("ps: the point tweaks of 4 vertices")), "{:?}", s.warnings);
    // A tweak that is not one number per component is an error with its line.
    let e = read(&plane.replace("\".pt[4].py\" 0.5", "\".pt[4].py\" 0.5 1")).unwrap_err().to_string();
    assert!(e.starts_with("dir/scene.ma: line 6:"), "{e}");
}

#[test]
fn render_stats_and_arnold_matte_set_each_shapes_visibility() {
    let sphere = |name: &str, attrs: &str| {
        format!(
            "createNode transform -n {name};\ncreateNode mesh -n {name}s -p {name};\n{attrs}\
             createNode polySphere -n {name}p;\nconnectAttr \"{name}p.out\" \"{name}s.i\";\n"
        )
    };
    let curve = |name: &str, parent: &str| {
        format!(
            "createNode transform -n {name} {parent};\ncreateNode nurbsCurve -n {name}s -p {name};\n\
             setAttr \".cc\" -type \"nurbsCurve\" 1 1 0 no 3 2 0 1 2 0 0 0 0 1 0;\nsetAttr \".rcurve\" yes;\n"
        )
    };
    let text = [
        sphere("plain", ""),
        sphere("unseen", "setAttr \".vis\" no;\n"),
        sphere("shadowless", "setAttr \".castsShadows\" no;\n"),
        sphere("holdout", "setAttr \".aiMatte\" yes;\nsetAttr \".csh\" no;\n"),
        "createNode transform -n col;\ncreateNode aiCurveCollector -n cols -p col;\nsetAttr \".aiMatte\" yes;\n".into(),
        curve("collected", "-p col"),
        curve("free", ""),
    ]
    .concat();
    let s = read(&text).unwrap();
    let v = |camera, shadows, matte| Visibility { camera, shadows, matte };
    let meshes: Vec<Visibility> = s.contents.meshes.iter().map(|m| m.visibility).collect();
    assert_eq!(meshes, [v(true, true, false), v(false, true, false), v(true, false, false), v(true, false, true)]);
    // The collector's curves are matte, the free one is not: one strand set each.
    let mut hair: Vec<(usize, Visibility)> = s
        .contents
        .hair
        .iter()
        .map(|h| match &h.source {
            HairSource::Inline(set) => (set.strand_count(), h.visibility),
            HairSource::File(_) => panic!("inline"),
        })
        .collect();
    hair.sort_by_key(|h| h.1.matte);
    assert_eq!(hair, [(1, v(true, true, false)), (1, v(true, true, true))]);
}

#[test]
fn a_camera_target_or_near_plane_beyond_single_precision_is_an_error_naming_the_camera() {
    let cam = |t: &str, attrs: &str| {
        read(&format!(
            "createNode transform -n cam;\n\tsetAttr \".t\" -type \"double3\" 0 0 {t} ;\n\
             createNode camera -n camShape -p cam;\n{attrs}"
        ))
    };
    assert!(cam("0", "\tsetAttr \".coi\" 1e30;\n\tsetAttr \".fcp\" 1e30;\n").is_ok());
    // A far plane past single precision is no far plane.
    let far = cam("0", "\tsetAttr \".fcp\" 1e39;\n").unwrap().camera.unwrap().clip[1];
    assert_eq!(far, f32::INFINITY);
    // Each finite in double precision; the target 1e39 away, or past the eye at -3e38 along
    // the view (-z), and the near plane are infinite in single precision.
    for (t, attrs) in [
        ("0", "\tsetAttr \".coi\" 1e39;\n"),
        ("-3e38", "\tsetAttr \".coi\" 3e38;\n"),
        ("0", "\tsetAttr \".ncp\" 1e39;\n\tsetAttr \".fcp\" 2e39;\n"),
    ] {
        let e = cam(t, attrs).unwrap_err().to_string();
        assert!(
            e.starts_with("dir/scene.ma: line 3:") && e.contains("camShape") && e.contains("single precision"),
            "{e}"
        );
    }
}

#[test]
fn a_curve_width_negative_or_beyond_single_precision_is_an_error_naming_the_attribute() {
    let curve = |head: &str, attrs: &str| {
        read(&format!(
            "{head}createNode transform -n c;\ncreateNode nurbsCurve -n cs -p c;\n{attrs}\
             setAttr \".cc\" -type \"nurbsCurve\" 1 1 0 no 3 2 0 1 2 0 0 0 0 30 0;\n"
        ))
    };
    assert!(curve("", "setAttr \".cwdth\" 1e30;\n").is_ok());
    // 1e38 cm is 1e39 mm: beyond single precision in the file's unit.
    for (head, w, line) in [("", "-1", 3), ("", "1e39", 3), ("currentUnit -l millimeter;\n", "1e38", 4)] {
        let e = curve(head, &format!("setAttr \".cwdth\" {w};\n")).unwrap_err().to_string();
        assert!(e.contains(&format!("line {line}:")) && e.contains("cs") && e.contains("cwdth"), "{e}");
    }
    // A collector's width profile of 1e39.
    let e = read(
        "createNode transform -n col;\ncreateNode aiCurveCollector -n cols -p col;\n\
         setAttr -s 2 \".wdthP[0:1]\" 0 1 1 1 1e39 1;\ncreateNode transform -n c -p col;\n\
         createNode nurbsCurve -n cs -p c;\nsetAttr \".cc\" -type \"nurbsCurve\" 1 1 0 no 3 2 0 1 2 0 0 0 0 30 0;\n",
    )
    .unwrap_err()
    .to_string();
    assert!(e.contains("line 3:") && e.contains("cols") && e.contains("widthProfile"), "{e}");
}

#[test]
fn light_and_colour_beyond_single_precision_are_errors_naming_the_node() {
    // 2e38 fits single precision; π × 2e38, the irradiance Maya's renderer gives, does not.
    let e = read("createNode directionalLight -n d;\n\tsetAttr \".in\" 2e38;\n").unwrap_err().to_string();
    assert!(e.contains("line 1:") && e.contains("light d") && e.contains("single precision"), "{e}");
    // A Lambert's colour 1e20 × diffuse 1e20.
    let e = read(
        "createNode transform -n s;\ncreateNode mesh -n ss -p s;\ncreateNode polySphere -n ps;\n\
         createNode lambert -n red;\nsetAttr \".c\" -type \"float3\" 1e20 0 0;\nsetAttr \".dc\" 1e20;\n\
         createNode shadingEngine -n redSG;\n\
         connectAttr \"ps.out\" \"ss.i\";\nconnectAttr \"red.oc\" \"redSG.ss\";\nconnectAttr \"ss.iog\" \"redSG.dsm\" -na;\n",
    )
    .unwrap_err()
    .to_string();
    assert!(e.contains("line 4:") && e.contains("red") && e.contains("single precision"), "{e}");
}

#[test]
fn poly_cubes_have_mayas_vertex_numbers_face_order_and_uv_cross() {
    // A 2 × 4 × 6 box of 2 × 2 × 2 faces (half sizes 1, 2, 3), Maya's numbering: a strip of
    // rows of 3 vertices around X (up the front, back over the top, down the back, under the
    // bottom), then the +X side's inner vertex (24) and the −X side's (25). Tweaked: 4, the
    // front's centre (0, 0, 3), 10, the top's (0, 2, 0), 24 (1, 0, 0) and 25 (−1, 0, 0).
    let cube = |attrs: &str| {
        format!(
            "createNode transform -n c;\ncreateNode mesh -n cs -p c;\n\
             \tsetAttr \".pt[4]\" -type \"float3\" 0 0 1;\n\tsetAttr \".pt[10].py\" 1;\n\
             \tsetAttr \".pt[24].px\" 1;\n\tsetAttr \".pnts[25].pntx\" -1;\n\
             createNode polyCube -n pc;\n{attrs}connectAttr \"pc.out\" \"cs.i\";\n"
        )
    };
    let sized = "\tsetAttr \".w\" 2;\n\tsetAttr \".h\" 4;\n\tsetAttr \".d\" 6;\n\
                 \tsetAttr \".sw\" 2;\n\tsetAttr \".sh\" 2;\n\tsetAttr \".sd\" 2;\n";
    let s = read(&cube(sized)).unwrap();
    assert!(s.warnings.iter().all(|w| !w.contains("polyCube") && !w.contains("tweak")), "{:?}", s.warnings);
    let MeshSource::Inline(m) = &s.contents.meshes[0].source else { panic!() };
    // 24 quads; 26 Maya vertices, 4 of them moved.
    assert_eq!(m.indices.len(), 48);
    let mut distinct: Vec<Vec3> = Vec::new();
    for &p in &m.positions {
        if !distinct.iter().any(|&q| close(p, q)) {
            distinct.push(p);
        }
    }
    assert_eq!(distinct.len(), 26);
    let moved =
        [Vec3::new(0.0, 0.0, 4.0), Vec3::new(0.0, 3.0, 0.0), Vec3::new(2.0, 0.0, 0.0), Vec3::new(-2.0, 0.0, 0.0)];
    for w in moved {
        assert!(distinct.iter().any(|&q| close(q, w)), "{w} not in {distinct:?}");
    }
    let half = Vec3::new(1.0, 2.0, 3.0);
    for &p in distinct.iter().filter(|&&p| !moved.iter().any(|&w| close(p, w))) {
        // Every other vertex on the box's surface, on its 3 × 3 × 3 lattice.
        let on_face = (0..3).any(|k| (p[k].abs() - half[k]).abs() < 1e-6);
        let on_grid = (0..3).all(|k| [-1.0, 0.0, 1.0].iter().any(|t| (p[k] - t * half[k]).abs() < 1e-6));
        assert!(on_face && on_grid && p.abs().cmple(half + 1e-6).all(), "{p}");
    }
    // Maya's face order: face 0 the front's bottom-left quad (vertices 0, 1, 4, 3), face 16
    // the first of the +X side (its bottom row, from −Z: vertices 23, 20, 17, 24).
    let tri = |t: usize| m.indices[t].map(|i| m.positions[i as usize]);
    let want0 = [Vec3::new(-1.0, -2.0, 3.0), Vec3::new(0.0, -2.0, 3.0), Vec3::new(0.0, 0.0, 4.0)];
    let want32 = [Vec3::new(1.0, -2.0, 0.0), Vec3::new(1.0, -2.0, -3.0), Vec3::new(1.0, 0.0, -3.0)];
    assert!((0..3).all(|k| close(tri(0)[k], want0[k]) && close(tri(32)[k], want32[k])), "{:?} {:?}", tri(0), tri(32));
    // UVs: the cross, each side a quarter: the front's centre at (0.5, 0.125), the +X
    // side's at (0.75, 0.125), the −X side's at (0.25, 0.125), the top's at (0.5, 0.375).
    let uvs = m.uvs.as_ref().unwrap();
    let uv_of =
        |w: Vec3| m.positions.iter().zip(uvs).filter(|(p, _)| close(**p, w)).map(|(_, uv)| *uv).collect::<Vec<_>>();
    assert_eq!(uv_of(moved[0]), [[0.5, 0.125]]);
    assert_eq!(uv_of(moved[1]), [[0.5, 0.375]]);
    assert_eq!(uv_of(moved[2]), [[0.75, 0.125]]);
    assert_eq!(uv_of(moved[3]), [[0.25, 0.125]]);
    // Wound outwards (the untweaked Maya default cube: 8 corners at ±0.5, 12 triangles).
    let s = read("createNode mesh -n cs;\ncreateNode polyCube -n pc;\nconnectAttr \"pc.out\" \"cs.i\";\n").unwrap();
    let MeshSource::Inline(m) = &s.contents.meshes[0].source else { panic!() };
    assert_eq!(m.indices.len(), 12);
    assert!(m.positions.iter().all(|p| (p.abs() - Vec3::splat(0.5)).abs().max_element() < 1e-6));
    for t in 0..12 {
        let [a, b, c] = m.corners(t);
        assert!((b - a).cross(c - a).dot(a + b + c) > 0.0, "triangle {t} faces in");
    }
    // No UVs with `createUVs` 0; the axis turns the box's height from Y to X.
    let s =
        read(&cube(&format!("{sized}\tsetAttr \".cuv\" 0;\n\tsetAttr \".ax\" -type \"double3\" 1 0 0;\n"))).unwrap();
    let MeshSource::Inline(m) = &s.contents.meshes[0].source else { panic!() };
    assert!(m.uvs.is_none());
    let extent = m.positions.iter().fold(Vec3::ZERO, |e, p| e.max(p.abs()));
    // (The tweaks go on after the turn: vertex 4 still sticks out to z = 4.)
    assert!(close(extent, Vec3::new(2.0, 1.0, 4.0)), "{extent}");
    // A size that is not positive is an error naming the node.
    let e = read(&cube("\tsetAttr \".d\" -1;\n")).unwrap_err().to_string();
    assert!(e.contains("pc") && e.contains("depth"), "{e}");
}

#[test]
fn transform_geometry_moves_the_geometry_flowing_through_it() {
    // polyCube → groupParts → transformGeometry (× 2, then 1 up) → mesh, vertex 0 tweaked
    // 1 down: the default cube's vertex 0 (−0.5, −0.5, 0.5) lands at (−1, 0, 1), then the
    // tweak takes it to (−1, −1, 1); the other corners span y 0 to 2.
    let scene = |extra: &str| {
        format!(
            "createNode transform -n c;\ncreateNode mesh -n cs -p c;\n\tsetAttr \".pt[0]\" -type \"float3\" 0 -1 0;\n\
             createNode polyCube -n pc;\ncreateNode groupParts -n gp;\ncreateNode transformGeometry -n tg;\n\
             \tsetAttr \".txf\" -type \"matrix\" 2 0 0 0 0 2 0 0 0 0 2 0 0 1 0 1;\n{extra}\
             connectAttr \"pc.out\" \"gp.ig\";\nconnectAttr \"gp.og\" \"tg.ig\";\nconnectAttr \"tg.og\" \"cs.i\";\n"
        )
    };
    let s = read(&scene("")).unwrap();
    assert!(
        s.warnings.iter().all(|w| !w.contains("transformGeometry") && !w.contains("rest pose")),
        "{:?}",
        s.warnings
    );
    let MeshSource::Inline(m) = &s.contents.meshes[0].source else { panic!() };
    let p = &m.positions;
    assert!(p.iter().any(|&q| close(q, Vec3::new(-1.0, -1.0, 1.0))), "{p:?}");
    assert!(!p.iter().any(|&q| close(q, Vec3::new(-1.0, 0.0, 1.0))), "{p:?}");
    let others = p.iter().filter(|q| !close(**q, Vec3::new(-1.0, -1.0, 1.0)));
    assert!(others.clone().all(|q| (q.x.abs() - 1.0).abs() < 1e-6 && (q.y - 1.0).abs() <= 1.0 + 1e-6), "{p:?}");
    assert!(others.clone().any(|q| q.y > 1.99) && others.clone().any(|q| q.y < 0.01));
    // invertTransform: the inverse (p − (0, 1, 0)) / 2: vertex 1 (0.5, −0.5, 0.5) at (0.25, −0.75, 0.25).
    let s = read(&scene("\tsetAttr \".itf\" yes;\n")).unwrap();
    let MeshSource::Inline(m) = &s.contents.meshes[0].source else { panic!() };
    assert!(m.positions.iter().any(|&q| close(q, Vec3::new(0.25, -0.75, 0.25))), "{:?}", m.positions);
    // Through it from history tress cannot build, the warning names where the history starts.
    let s = read(&scene("").replace("polyCube", "polyCone")).unwrap();
    assert!(s.contents.meshes.is_empty());
    assert!(s.warnings.iter().any(|w| w.contains("mesh cs is built by a `polyCone` node")), "{:?}", s.warnings);
    // A matrix of the wrong size, or not affine, is an error naming the node and its line.
    for bad in ["2 0 0 0 0 2 0 0 0 0 2 0 0 1 0", "2 0 0 0 0 2 0 0 0 0 2 0 0 1 0 2"] {
        let text = scene("").replace("2 0 0 0 0 2 0 0 0 0 2 0 0 1 0 1", bad);
        let e = read(&text).unwrap_err().to_string();
        assert!(e.starts_with("dir/scene.ma: line 7:") && e.contains("transformGeometry tg"), "{e}");
    }
}

#[test]
fn a_face_of_fewer_than_three_edges_is_an_error_and_empty_faces_no_mesh() {
    // Found by the hostile proptest: `f 4 0 2 -4 -2` with three bytes deleted is `f 2 -4 -2`.
    assert!(SCENE.contains("f 4 0 5 -3 -5"));
    let e = read(&SCENE.replacen("f 4 0 5 -3 -5", "f 2 0 5", 1)).unwrap_err().to_string();
    assert!(e.starts_with("dir/scene.ma: line 13:") && e.contains("face of 2 edges"), "{e}");
    let s = read(
        "createNode mesh -n m;\nsetAttr \".vt[0:2]\" 0 0 0 1 0 0 0 1 0;\n\
         setAttr \".ed[0:2]\" 0 1 0 1 2 0 2 0 0;\nsetAttr \".fc[0]\" -type \"polyFaces\" ;\n",
    )
    .unwrap();
    assert!(s.contents.meshes.is_empty());
}

#[test]
fn delete_component_removes_faces_by_mayas_numbers() {
    // A default cube (faces: 0 front +Z, 1 top +Y, 2 back −Z, 3 bottom −Y, 4 +X, 5 −X)
    // through one or two deleteComponent nodes, the shape's vertex 0 (−0.5, −0.5, 0.5)
    // tweaked 1 down.
    let scene = |first: &str, second: Option<&str>| {
        let (nodes, links) = match second {
            Some(c) => (
                format!("createNode deleteComponent -n dc2;\n\tsetAttr \".dc\" -type \"componentList\" 1 \"{c}\";\n"),
                "connectAttr \"dc.og\" \"dc2.ig\";\nconnectAttr \"dc2.og\" \"cs.i\";\n",
            ),
            None => (String::new(), "connectAttr \"dc.og\" \"cs.i\";\n"),
        };
        format!(
            "createNode transform -n c;\ncreateNode mesh -n cs -p c;\n\tsetAttr \".pt[0]\" -type \"float3\" 0 -1 0;\n\
             createNode polyCube -n pc;\ncreateNode deleteComponent -n dc;\n\
             \tsetAttr \".dc\" -type \"componentList\" {first};\n{nodes}\
             connectAttr \"pc.out\" \"dc.ig\";\n{links}"
        )
    };
    let mesh = |s: &Imported| {
        let MeshSource::Inline(m) = &s.contents.meshes[0].source else { panic!() };
        m.clone()
    };
    // The plane of each triangle: the axis and side all three corners share.
    let sides = |m: &TriangleMesh| -> Vec<(usize, bool)> {
        (0..m.indices.len() as u32)
            .map(|t| {
                let c = m.corners(t);
                let k = (0..3).find(|&k| c.iter().all(|p| (p[k] - c[0][k]).abs() < 1e-6)).unwrap();
                (k, c[0][k] > 0.0)
            })
            .collect()
    };
    // f[0:1] and f[4] (as test_0033): the back, bottom and −X faces are left. Vertex 3
    // (0.5, 0.5, 0.5) is on none of them: Maya deletes it and numbers the vertices anew,
    // so the tweak is not applied, and said.
    let s = read(&scene("2 \"f[0:1]\" \"f[4]\"", None)).unwrap();
    let m = mesh(&s);
    assert_eq!(m.indices.len(), 6);
    let mut got = sides(&m);
    got.dedup();
    assert_eq!(got, [(2, false), (1, false), (0, false)]);
    assert!(m.positions.iter().all(|p| p.abs().max_element() < 0.5 + 1e-6));
    assert!(s.warnings.iter().any(|w| w.contains("point tweaks of 1 vertices are not applied")), "{:?}", s.warnings);
    // Two deletions of f[0]: the second counts the faces left, its face 0 the old face 1
    // (the top). Every vertex still on a face: the tweak lands on vertex 0.
    let s = read(&scene("1 \"f[0]\"", Some("f[0]"))).unwrap();
    assert!(s.warnings.iter().all(|w| !w.contains("deleteComponent") && !w.contains("tweak")), "{:?}", s.warnings);
    assert!(mesh(&s).positions.iter().any(|&p| close(p, Vec3::new(-0.5, -1.5, 0.5))), "{:?}", mesh(&s).positions);
    // (Untweaked, each triangle lies on a side of the box.)
    let untweaked = scene("1 \"f[0]\"", Some("f[0]")).replace("\tsetAttr \".pt[0]\" -type \"float3\" 0 -1 0;\n", "");
    let m = mesh(&read(&untweaked).unwrap());
    assert_eq!(
        sides(&m),
        [(2, false), (2, false), (1, false), (1, false), (0, true), (0, true), (0, false), (0, false)]
    );
    // f[*]: every face, nothing to draw.
    let s = read(&scene("1 \"f[*]\"", None)).unwrap();
    assert!(s.contents.meshes.is_empty());
    assert!(s.warnings.iter().any(|w| w.contains("mesh cs") && w.contains("every face")), "{:?}", s.warnings);
    // Vertices and edges are not deleted (Maya merges faces): the cube whole, the node named.
    let s = read(&scene("1 \"vtx[0]\"", None)).unwrap();
    assert_eq!(mesh(&s).indices.len(), 12);
    assert!(s.warnings.iter().any(|w| w.contains("deleteComponent dc") && w.contains("vtx[0]")), "{:?}", s.warnings);
    // Nor faces of a sphere, whose faces tress does not number as Maya does.
    let s = read(&scene("1 \"f[0]\"", None).replace("polyCube", "polySphere")).unwrap();
    assert_eq!(mesh(&s).indices.len(), 760);
    assert!(
        s.warnings.iter().any(|w| w.contains("deleteComponent dc") && w.contains("polySphere")),
        "{:?}",
        s.warnings
    );
    // Bad components are errors naming the node and its line, a huge range included
    // (refused, not allocated).
    for bad in
        ["1 \"f[5:2]\"", "1 \"f[6]\"", "1 \"f[0:18446744073709551615]\"", "1 \"f[0:99999999999999999999]\"", "1 \"f[\""]
    {
        let e = read(&scene(bad, None)).unwrap_err().to_string();
        assert!(e.starts_with("dir/scene.ma: line 6:") && e.contains("deleteComponent dc"), "{bad}: {e}");
    }
    let e = read(&scene("1 \"f[0]\"", None).replace("-type \"componentList\" 1 \"f[0]\"", "3")).unwrap_err();
    assert!(e.to_string().contains("component list"), "{e}");
}

#[test]
fn poly_cylinders_have_mayas_vertex_numbers_face_order_and_uvs() {
    // Maya's default cylinder (radius 1, height 2, 20 sides, one row) with caps of
    // triangles (`sc` 1): 20 × 2 ring vertices, vertex j at the azimuth 18° (j + 1) from +X
    // towards −Z, then the bottom and the top centre (40, 41). Vertex 0 tweaked 1 out
    // along X, the top centre 1 up.
    let scene = |attrs: &str| {
        format!(
            "createNode transform -n c;\ncreateNode mesh -n cs -p c;\n\
             \tsetAttr \".pt[0]\" -type \"float3\" 1 0 0;\n\tsetAttr \".pt[41].py\" 1;\n\
             createNode polyCylinder -n pc;\n{attrs}connectAttr \"pc.out\" \"cs.i\";\n"
        )
    };
    let s = read(&scene("\tsetAttr \".sc\" 1;\n")).unwrap();
    assert!(s.warnings.iter().all(|w| !w.contains("polyCylinder") && !w.contains("tweak")), "{:?}", s.warnings);
    let MeshSource::Inline(m) = &s.contents.meshes[0].source else { panic!() };
    // 20 side quads, 20 + 20 cap triangles.
    assert_eq!(m.indices.len(), 80);
    let a = 18f32.to_radians();
    let v0 = Vec3::new(a.cos() + 1.0, -1.0, -a.sin());
    let v1 = Vec3::new((2.0 * a).cos(), -1.0, -(2.0 * a).sin());
    let (v20, v21) = (Vec3::new(a.cos(), 1.0, -a.sin()), Vec3::new((2.0 * a).cos(), 1.0, -(2.0 * a).sin()));
    // Face 0: vertices 0, 1, 21, 20 (UVs 20, 21, 42, 41 of the side grid).
    let tri = |t: usize| m.indices[t].map(|i| m.positions[i as usize]);
    assert!(close(tri(0)[0], v0) && close(tri(0)[1], v1) && close(tri(0)[2], v21), "{:?}", tri(0));
    assert!(close(tri(1)[2], v20), "{:?}", tri(1));
    let uv = |t: usize, k: usize| m.uvs.as_ref().unwrap()[m.indices[t][k] as usize];
    assert_eq!(uv(0, 0), [0.375, 0.3125]);
    assert!((uv(0, 2)[0] - 0.3875).abs() < 1e-6 && (uv(0, 2)[1] - 0.68843985).abs() < 1e-6);
    // Face 20, the first of the bottom cap: vertices 1, 0 and the centre; face 40, the
    // first of the top: 20, 21 and the (tweaked) centre, UV (0.5, 0.8375).
    let want20 = [v1, v0, Vec3::new(0.0, -1.0, 0.0)];
    let want40 = [v20, v21, Vec3::new(0.0, 2.0, 0.0)];
    assert!(
        (0..3).all(|k| close(tri(40)[k], want20[k]) && close(tri(60)[k], want40[k])),
        "{:?} {:?}",
        tri(40),
        tri(60)
    );
    assert_eq!(uv(60, 2), [0.5, 0.8375]);
    // The bottom cap's UV circle: vertex 0 at (0.5 + 0.15625 cos 18°, 0.15625 − 0.15625 sin 18°).
    assert!((uv(40, 1)[0] - (0.5 + 0.15625 * a.cos())).abs() < 1e-6);
    assert!((uv(40, 1)[1] - 0.15625 * (1.0 - a.sin())).abs() < 1e-6);
    // Outwards, smooth.
    assert!(m.normals.is_some());
    for t in 0..80 {
        let [p, q, r] = m.corners(t);
        assert!((q - p).cross(r - p).dot(p + q + r) > 0.0, "triangle {t} faces in");
    }
    // Node defaults (`sc` 0): each cap one polygon of 20 sides (18 triangles), no centres;
    // sizes, rows and the axis.
    let s = read(&scene("\tsetAttr \".r\" 2;\n\tsetAttr \".h\" 0.5;\n\tsetAttr \".sh\" 3;\n\tsetAttr \".ax\" -type \"double3\" 1 0 0;\n"))
        .unwrap();
    let MeshSource::Inline(m) = &s.contents.meshes[0].source else { panic!() };
    assert_eq!(m.indices.len(), 20 * 3 * 2 + 2 * 18);
    // Height along X (±0.25), radius 2; vertex 0 (at the bottom, x −0.25) tweaked to 0.75.
    let extent = m.positions.iter().fold(Vec3::ZERO, |e, p| e.max(p.abs()));
    assert!(close(extent, Vec3::new(0.75, 2.0, 2.0)), "{extent}");
    // Caps of more rings: drawn, their tweaks not applied (numbering unknown), said.
    let s = read(&scene("\tsetAttr \".sc\" 3;\n")).unwrap();
    assert_eq!(s.contents.meshes.len(), 1);
    assert!(s.warnings.iter().any(|w| w.contains("point tweaks of 2 vertices are not applied")), "{:?}", s.warnings);
    // A radius that is not positive is an error naming the node.
    let e = read(&scene("\tsetAttr \".r\" 0;\n")).unwrap_err().to_string();
    assert!(e.contains("pc") && e.contains("radius"), "{e}");
}

#[test]
fn an_orthographic_camera_renders_when_it_is_the_renderable_one() {
    // Maya's startup cameras: persp made non-renderable, top (orthographic) renderable.
    let text = "createNode transform -s -n \"persp\";\n\tsetAttr \".t\" -type \"double3\" 0 0 9 ;\n\
                createNode camera -s -n \"perspShape\" -p \"persp\";\n\tsetAttr \".rnd\" no;\n\
                createNode transform -s -n \"top\";\n\tsetAttr \".t\" -type \"double3\" 0 100 0 ;\n\
                \tsetAttr \".r\" -type \"double3\" -90 0 0 ;\n\
                createNode camera -s -n \"topShape\" -p \"top\";\n\tsetAttr \".ow\" 12;\n\tsetAttr \".o\" yes;\n";
    let c = read(text).unwrap().camera.unwrap();
    assert!(close(c.eye, Vec3::new(0.0, 100.0, 0.0)), "{}", c.eye);
    assert!(close((c.target - c.eye).normalize(), Vec3::NEG_Y));
    // The orthographic width spans the image width.
    assert!((c.ortho_height_for(640, 480).unwrap() - 9.0).abs() < 1e-5);
    // A renderable perspective camera is preferred to it.
    let both = text.replace("\tsetAttr \".rnd\" no;\n", "");
    assert_eq!(read(&both).unwrap().camera.unwrap().ortho_height_for(640, 480), None);
}

/// UV values and the UV index of each face corner, face by face.
type FaceUvs<'a> = (&'a [[f32; 2]], &'a [&'a [u32]]);

/// A stored mesh `ms` under transform `m`, as Maya writes one: its vertices, its edges (each
/// once, in the order the faces meet them) and its faces as signed edge loops, with a UV
/// index per face corner when `uvs` are given; `attrs` set on the shape.
fn stored_mesh_text(positions: &[[f32; 3]], faces: &[&[u32]], uvs: Option<FaceUvs>, attrs: &str) -> String {
    let mut edges: Vec<[u32; 2]> = Vec::new();
    let mut loops = String::new();
    for (f, face) in faces.iter().enumerate() {
        let signed: Vec<String> = (0..face.len())
            .map(|k| {
                let (a, b) = (face[k], face[(k + 1) % face.len()]);
                match edges.iter().position(|e| *e == [a, b] || *e == [b, a]) {
                    Some(e) if edges[e] == [a, b] => e.to_string(),
                    Some(e) => (-(e as i64) - 1).to_string(),
                    None => {
                        edges.push([a, b]);
                        (edges.len() - 1).to_string()
                    }
                }
            })
            .collect();
        loops += &format!("\n\t\tf {} {}", face.len(), signed.join(" "));
        if let Some((_, ids)) = uvs {
            let ids: Vec<String> = ids[f].iter().map(u32::to_string).collect();
            loops += &format!("\n\t\tmu 0 {} {}", ids.len(), ids.join(" "));
        }
    }
    let join = |v: Vec<String>| v.join(" ");
    let vt = join(positions.iter().flatten().map(f32::to_string).collect());
    let ed = join(edges.iter().map(|[a, b]| format!("{a} {b} 0")).collect());
    let uv = match uvs {
        Some((values, _)) => format!(
            "\tsetAttr \".uvst[0].uvsp[0:{}]\" -type \"float2\" {};\n",
            values.len() - 1,
            join(values.iter().flatten().map(f32::to_string).collect())
        ),
        None => String::new(),
    };
    format!(
        "createNode transform -n m;\ncreateNode mesh -n ms -p m;\n{uv}\tsetAttr \".vt[0:{}]\" {vt};\n\
         \tsetAttr \".ed[0:{}]\" {ed};\n\tsetAttr \".fc[0:{}]\" -type \"polyFaces\"{loops};\n{attrs}",
        positions.len() - 1,
        edges.len() - 1,
        faces.len() - 1
    )
}

/// The cube [−0.5, 0.5]³ as a stored mesh, faces wound outwards, with `attrs`.
fn cube_text(attrs: &str) -> String {
    let positions: Vec<[f32; 3]> =
        (0..8).map(|i| [(i & 1) as f32 - 0.5, ((i >> 1) & 1) as f32 - 0.5, ((i >> 2) & 1) as f32 - 0.5]).collect();
    let faces: [&[u32]; 6] = [&[0, 2, 3, 1], &[4, 5, 7, 6], &[0, 1, 5, 4], &[2, 6, 7, 3], &[0, 4, 6, 2], &[1, 3, 7, 5]];
    stored_mesh_text(&positions, &faces, None, attrs)
}

fn inline_mesh(s: &Imported) -> &TriangleMesh {
    match &s.contents.meshes[0].source {
        MeshSource::Inline(m) => m,
        other => panic!("{other:?}"),
    }
}

#[test]
fn arnold_subdivision_attributes_subdivide_maya_meshes() {
    // Without `aiSubdivType` (or with 0): the cage, 6 quads, flat.
    for attrs in ["", "\tsetAttr \".ai_subdiv_type\" 0;\n\tsetAttr \".ai_subdiv_iterations\" 3;\n"] {
        let s = read(&cube_text(attrs)).unwrap();
        assert_eq!(inline_mesh(&s).indices.len(), 12, "{attrs}");
        assert!(inline_mesh(&s).normals.is_none());
    }
    // Catmull-Clark, 2 iterations: 6 × 4² quads inside the cage, smooth shaded; every corner
    // pulled in past the 5/18-per-axis point of the first iteration.
    let s = read(&cube_text("\tsetAttr \".ai_subdiv_type\" 1;\n\tsetAttr \".aiSubdivIterations\" 2;\n")).unwrap();
    crate::geometry::subdivision::assert_cube_subdivided_twice(inline_mesh(&s));
    assert!(s.warnings.iter().all(|w| !w.contains("ubdiv")), "{:?}", s.warnings);
    // Arnold's default of one iteration when only the type is set: 24 quads.
    let once = read(&cube_text("\tsetAttr \".ai_subdiv_type\" 1;\n")).unwrap();
    assert_eq!(inline_mesh(&once).indices.len(), 2 * 24);
    // A mesh a primitive node builds is subdivided too: polyCube's 6 faces, once.
    let built = "createNode transform -n c;\ncreateNode mesh -n cs -p c;\n\tsetAttr \".ai_subdiv_type\" 1;\n\
                 createNode polyCube -n pc;\nconnectAttr \"pc.out\" \"cs.i\";\n";
    let s = read(built).unwrap();
    assert_eq!(inline_mesh(&s).indices.len(), 2 * 24);
    // Linear subdivision is drawn as the cage, said once with a count.
    let linear = format!(
        "{}{}",
        cube_text("\tsetAttr \".ai_subdiv_type\" 2;\n"),
        cube_text("\tsetAttr \".ai_subdiv_type\" 2;\n")
            .replace("-n m;", "-n m2;")
            .replace("-n ms -p m;", "-n ms2 -p m2;")
    );
    let s = read(&linear).unwrap();
    assert_eq!(s.contents.meshes.len(), 2);
    assert!(s.contents.meshes.iter().all(|e| matches!(&e.source, MeshSource::Inline(m) if m.indices.len() == 12)));
    let said: Vec<&String> = s.warnings.iter().filter(|w| w.contains("linear")).collect();
    assert!(said.len() == 1 && said[0].contains("(2; first: ms)"), "{:?}", s.warnings);
}

#[test]
fn absurd_subdivision_iterations_are_capped_with_a_warning() {
    // More than Arnold's byte holds: not subdivided, said with the value.
    let s = read(&cube_text("\tsetAttr \".ai_subdiv_type\" 1;\n\tsetAttr \".ai_subdiv_iterations\" 300;\n")).unwrap();
    assert_eq!(inline_mesh(&s).indices.len(), 12);
    assert!(s.warnings.iter().any(|w| w.contains("not 0 to 255") && w.contains("ms: 300")), "{:?}", s.warnings);
    // Arnold's largest count stops at the face budget shared with the USD reader, said
    // once: 6 × 4⁹ quads, as a tenth iteration would make 6 × 4¹⁰, past 2,000,000.
    let s = read(&cube_text("\tsetAttr \".ai_subdiv_type\" 1;\n\tsetAttr \".ai_subdiv_iterations\" 255;\n")).unwrap();
    assert_eq!(inline_mesh(&s).indices.len(), 2 * 6 * 4usize.pow(9));
    let said: Vec<&String> = s.warnings.iter().filter(|w| w.contains("subdivision stopped")).collect();
    assert!(said.len() == 1 && said[0].contains("2000000 faces per mesh"), "{:?}", s.warnings);
}

#[test]
fn per_face_vertex_uvs_are_kept_and_split_vertices_where_they_differ() {
    // Two quads side by side sharing the edge 1-4; the right quad's UVs are a separate
    // island (u + 2) so its corners on the shared edge have other UVs than the left's.
    let positions =
        [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [2.0, 0.0, 0.0], [0.0, 0.0, -1.0], [1.0, 0.0, -1.0], [2.0, 0.0, -1.0]];
    let faces: [&[u32]; 2] = [&[0, 1, 4, 3], &[1, 2, 5, 4]];
    let uv_values = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0], [2.0, 0.0], [3.0, 0.0], [3.0, 1.0], [2.0, 1.0]];
    let uv_ids: [&[u32]; 2] = [&[0, 1, 2, 3], &[4, 5, 6, 7]];
    let s = read(&stored_mesh_text(&positions, &faces, Some((&uv_values, &uv_ids)), "")).unwrap();
    let m = inline_mesh(&s);
    // 6 positions, 2 of them with two UVs each: 8 vertices, each keeping its corner's UV.
    assert_eq!((m.positions.len(), m.indices.len()), (8, 4));
    let uvs = m.uvs.as_ref().unwrap();
    for (p, uv) in m.positions.iter().zip(uvs) {
        let right = uv[0] >= 2.0;
        let expected = [p.x + if right { 1.0 } else { 0.0 }, -p.z];
        assert_eq!(*uv, expected, "{p}");
    }
    // The same UV values under other indices are one corner: no split.
    let shared: [&[u32]; 2] = [&[0, 1, 2, 3], &[4, 5, 6, 7]];
    let same = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0], [1.0, 0.0], [2.0, 0.0], [2.0, 1.0], [1.0, 1.0]];
    let s = read(&stored_mesh_text(&positions, &faces, Some((&same, &shared)), "")).unwrap();
    assert_eq!(inline_mesh(&s).positions.len(), 6);
    // Subdivided, the UVs follow each face linearly: the left island stays in u 0 to 1.
    let s =
        read(&stored_mesh_text(&positions, &faces, Some((&uv_values, &uv_ids)), "\tsetAttr \".ai_subdiv_type\" 1;\n"))
            .unwrap();
    let m = inline_mesh(&s);
    assert_eq!(m.indices.len(), 2 * 8);
    let uvs = m.uvs.as_ref().unwrap();
    assert!(uvs.iter().all(|uv| (0.0..=1.0).contains(&uv[0]) || (2.0..=3.0).contains(&uv[0])), "{uvs:?}");
    assert!(uvs.contains(&[0.5, 0.5]) && uvs.contains(&[2.5, 0.5]), "{uvs:?}");
}
