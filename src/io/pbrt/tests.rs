//! pbrt-v4 import: camera, lights, curves against their control points, materials,
//! includes, line-numbered errors (random and mutated input: `tests/hostile.rs`).

use super::*;

const SCENE: &str = r#"# a small pbrt-v4 hair scene
LookAt 0 0 5   0 0 0   0 1 0
Camera "perspective" "float fov" [ 30 ]
Film "rgb" "integer xresolution" [ 64 ] "integer yresolution" [ 48 ] "string filename" "x.exr"
Sampler "zsobol" "integer pixelsamples" 4
Integrator "volpath" "integer maxdepth" [ 3 ]
WorldBegin
LightSource "distant" "point3 from" [ 0 0 0 ] "point3 to" [ 0 0 -1 ] "rgb L" [ 2 2 2 ]
LightSource "infinite" "rgb L" [ 0.1 0.2 0.3 ]
AttributeBegin
  Material "hair" "float eumelanin" 0.3 "float beta_m" 0.25
  Translate 0 -1 0
  Shape "curve" "point3 P" [ 0 0 0  0 1 0  0 2 0  0 3 0 ] "float width0" 0.1 "float width1" 0.02
  Shape "curve" "point3 P" [ 1 0 0  1 1 0  1 2 0  1 3 0  1 4 0 ] "string basis" "bspline" "float width" 0.05 "integer splitdepth" 2
AttributeEnd
AttributeBegin
  Material "diffuse" "rgb reflectance" [ 0.2 0.4 0.6 ]
  Shape "trianglemesh" "integer indices" [ 0 1 2  0 2 3 ]
      "point3 P" [ -2 -1 -2  2 -1 -2  2 -1 2  -2 -1 2 ]
AttributeEnd
"#;

fn read(text: &str) -> Result<Imported, LoadError> {
    parse_pbrt(text, Path::new("dir/scene.pbrt"))
}

#[test]
fn a_hair_scene_reads_camera_film_lights_curves_and_meshes() {
    let s = read(SCENE).unwrap();
    assert_eq!((s.resolution, s.spp, s.max_depth), (Some([64, 48]), Some(4), Some(3)));
    let c = s.camera.as_ref().unwrap();
    assert!((c.eye - Vec3::new(0.0, 0.0, 5.0)).length() < 1e-5 && (c.vfov - 30.0).abs() < 1e-5);
    assert_eq!(s.lights.len(), 2);
    let Light::Distant { direction, irradiance } = s.lights[0] else { panic!() };
    assert!((direction - Vec3::Z).length() < 1e-5 && irradiance == Vec3::splat(2.0));
    assert_eq!(s.lights[1], Light::Environment { radiance: Vec3::new(0.1, 0.2, 0.3) });
    assert_eq!((s.hair.len(), s.meshes.len()), (1, 1));
    assert_eq!(s.meshes[0].material, Material::Diffuse { color: Vec3::new(0.2, 0.4, 0.6) });
    let HairSource::Inline(set) = &s.hair[0].source else { panic!() };
    assert_eq!(set.strand_count(), 2);
    // Hair material: the physical model with the file's melanin and roughness, the rest
    // pbrt's defaults.
    let Material::Physical(h) = &s.hair[0].material else { panic!() };
    let want = HairParams {
        absorption: Absorption::Melanin { eumelanin: 0.3, pheomelanin: 0.0 },
        beta_m: 0.25,
        ..HairParams::default()
    };
    assert_eq!(*h.params(), want);
}

#[test]
fn curves_match_their_control_points() {
    let s = read(SCENE).unwrap();
    let HairSource::Inline(set) = &s.hair[0].source else { panic!() };
    // The Bézier curve of collinear, evenly spaced points is the segment itself: 2³ + 1
    // samples at y = −1 + 3 k / 8 (moved down by Translate), widths 0.1 → 0.02 linearly.
    assert_eq!(set.offsets[1], 9);
    for k in 0..9 {
        let p = set.points[k];
        let u = k as f32 / 8.0;
        assert!((Vec3::new(p[0], p[1], p[2]) - Vec3::new(0.0, -1.0 + 3.0 * u, 0.0)).length() < 1e-5, "{p:?}");
        assert!((p[3] - 0.5 * (0.1 + (0.02 - 0.1) * u)).abs() < 1e-6);
    }
    // The B-spline (2 segments, split depth 2) starts at (P0 + 4 P1 + P2) / 6 and ends at
    // (P2 + 4 P3 + P4) / 6.
    let b: Vec<Vec3> = (9..set.points.len()).map(|i| Vec3::from_slice(&set.points[i][..3])).collect();
    assert_eq!(b.len(), 2 * 4 + 1);
    assert!((b[0] - Vec3::new(1.0, 0.0, 0.0)).length() < 1e-5, "{}", b[0]);
    assert!((b[8] - Vec3::new(1.0, 2.0, 0.0)).length() < 1e-5, "{}", b[8]);
    assert!(set.points[9..].iter().all(|p| (p[3] - 0.025).abs() < 1e-6));
}

#[test]
fn the_image_is_not_mirrored() {
    // pbrt's LookAt with the default handedness puts world +x on the image's left when
    // looking down −z from +z; tress mirrors the world so it lands where pbrt puts it.
    let s = read(SCENE).unwrap();
    let (d, _) = s.into_description();
    let HairSource::Inline(set) = &d.hair[0].source else { panic!() };
    let right = (d.camera.target - d.camera.eye).cross(d.camera.up).normalize();
    // The B-spline curve at x = 1 in the file.
    let x = d.hair[0].transform.transform_point3(Vec3::from_slice(&set.points[9][..3]));
    assert!(x.dot(right) < 0.0, "{x} should be on the left");
}

#[test]
fn includes_named_materials_and_degree_two_curves() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("curves.pbrt"),
        "Shape \"curve\" \"point3 P\" [0 0 0 1 1 0 2 0 0] \"integer degree\" 2\n",
    )
    .unwrap();
    let main = dir.path().join("main.pbrt");
    std::fs::write(&main, "WorldBegin\nMakeNamedMaterial \"h\" \"string type\" \"hair\" \"rgb reflectance\" [0.5 0.4 0.3]\nNamedMaterial \"h\"\nInclude \"curves.pbrt\"\n").unwrap();
    let s = read_pbrt(&main).unwrap();
    let HairSource::Inline(set) = &s.hair[0].source else { panic!() };
    // A quadratic Bézier's midpoint is (P0 + 2 P1 + P2) / 4 = (1, 0.5, 0).
    let mid = set.points[4];
    assert!((Vec3::new(mid[0], mid[1], mid[2]) - Vec3::new(1.0, 0.5, 0.0)).length() < 1e-5, "{mid:?}");
    let Material::Physical(h) = &s.hair[0].material else { panic!() };
    assert_eq!(h.params().absorption, Absorption::Color(Vec3::new(0.5, 0.4, 0.3)));
    // An include cycle is an error, not a hang.
    std::fs::write(dir.path().join("loop.pbrt"), "Include \"loop.pbrt\"\n").unwrap();
    let e = read_pbrt(&dir.path().join("loop.pbrt")).unwrap_err().to_string();
    assert!(e.contains("include cycle"), "{e}");
}

#[test]
fn malformed_files_give_line_numbered_errors() {
    for (text, line) in [
        ("WorldBegin\n\nShape \"curve\" \"point3 P\" [0 0 0 1 1 1]\n", 3),
        ("LookAt 0 0 0 0 0 0 0 1 0\n", 1),
        ("WorldBegin\nShape \"trianglemesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0] \"integer indices\" [0 1 5]\n", 2),
        ("Translate 1 2\nWorldBegin\n", 2),
        ("\nAttributeEnd\n", 2),
        ("Shape \"curve\" \"point3 P\" [0 0 0 1 1 1 2 2 2 3 3 nan]\n", 1),
        ("Film \"rgb\" \"integer xresolution\" [0]\n", 1),
        ("Bogus 1\n", 1),
        ("Shape \"curve\" \"point3 P\" [0 0 0\n", 1),
        ("Material \"hair\" \"float beta_m\" 3\n", 1),
        ("WorldBegin\nShape \"curve\" \"point3 P\" [0 0 0 1 1 1 2 2 2 3 3 3] \"string basis\" \"hermite\"\n", 2),
    ] {
        let e = match read(text) {
            Ok(_) => panic!("no error for {text:?}"),
            Err(e) => e.to_string(),
        };
        assert!(e.starts_with(&format!("dir/scene.pbrt: line {line}:")), "{text:?}: {e}");
    }
}

#[test]
fn sigma_a_round_trips_through_the_physical_material() {
    // A σ_a given to pbrt reaches the BSDF unchanged (through Chiang's colour mapping).
    let s = read("Material \"hair\" \"rgb sigma_a\" [0.2 0.5 1.1] \"float beta_n\" 0.4\nShape \"curve\" \"point3 P\" [0 0 0 0 1 0 0 2 0 0 3 0]\n").unwrap();
    let Material::Physical(h) = &s.hair[0].material else { panic!() };
    let sigma = h.sigma_a(None);
    assert!((sigma - Vec3::new(0.2, 0.5, 1.1)).abs().max_element() < 1e-4, "{sigma}");
}
