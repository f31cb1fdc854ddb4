//! pbrt-v4 import: camera, lights, curves against their control points, materials,
//! includes, line-numbered errors (random and mutated input: `tests/hostile.rs`).

use super::*;
use crate::scene::MaterialSource;

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
    // volpath with maxdepth 3: path tracing with two bounces after the first hit.
    assert_eq!((s.resolution, s.spp, s.max_depth), (Some([64, 48]), Some(4), Some(2)));
    assert_eq!(s.integrator, Some(Integrator::Path));
    let c = s.camera.as_ref().unwrap();
    assert!((c.eye - Vec3::new(0.0, 0.0, 5.0)).length() < 1e-5 && (c.vfov - 30.0).abs() < 1e-5);
    assert_eq!(s.contents.lights.len(), 2);
    let LightSource::Inline(Light::Distant { direction, irradiance }) = s.contents.lights[0] else { panic!() };
    assert!((direction - Vec3::Z).length() < 1e-5 && irradiance == Vec3::splat(2.0));
    assert_eq!(
        s.contents.lights[1],
        Light::Environment { radiance: Vec3::new(0.1, 0.2, 0.3), camera_visibility: 1.0 }.into()
    );
    assert_eq!((s.contents.hair.len(), s.contents.meshes.len()), (1, 1));
    assert_eq!(s.contents.meshes[0].material, Material::Diffuse { color: Vec3::new(0.2, 0.4, 0.6) }.into());
    let HairSource::Inline(set) = &s.contents.hair[0].source else { panic!() };
    assert_eq!(set.strand_count(), 2);
    // Hair material: the physical model with the file's melanin and roughness, the rest
    // pbrt's defaults.
    let MaterialSource::Inline(Material::Physical(h)) = &s.contents.hair[0].material else { panic!() };
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
    let HairSource::Inline(set) = &s.contents.hair[0].source else { panic!() };
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
    let HairSource::Inline(set) = &d.contents.hair[0].source else { panic!() };
    let right = (d.camera.target - d.camera.eye).cross(d.camera.up).normalize();
    // The B-spline curve at x = 1 in the file.
    let x = d.contents.hair[0].transform.transform_point3(Vec3::from_slice(&set.points[9][..3]));
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
    let HairSource::Inline(set) = &s.contents.hair[0].source else { panic!() };
    // A quadratic Bézier's midpoint is (P0 + 2 P1 + P2) / 4 = (1, 0.5, 0).
    let mid = set.points[4];
    assert!((Vec3::new(mid[0], mid[1], mid[2]) - Vec3::new(1.0, 0.5, 0.0)).length() < 1e-5, "{mid:?}");
    let MaterialSource::Inline(Material::Physical(h)) = &s.contents.hair[0].material else { panic!() };
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
    let MaterialSource::Inline(Material::Physical(h)) = &s.contents.hair[0].material else { panic!() };
    let sigma = h.sigma_a(None);
    assert!((sigma - Vec3::new(0.2, 0.5, 1.1)).abs().max_element() < 1e-4, "{sigma}");
}

fn gzip(bytes: &[u8]) -> Vec<u8> {
    use std::io::Write;
    let mut e = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::default());
    e.write_all(bytes).unwrap();
    e.finish().unwrap()
}

#[test]
fn gzipped_includes_and_ply_meshes_are_read_by_their_magic_bytes() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::create_dir(dir.path().join("geometry")).unwrap();
    let curves = "Shape \"curve\" \"point3 P\" [0 0 0 0 1 0 0 2 0 0 3 0] \"float width\" 0.1\n".repeat(3);
    std::fs::write(dir.path().join("geometry/hair.pbrt.gz"), gzip(curves.as_bytes())).unwrap();
    let ply = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n\
               element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
    // A gzipped PLY under a name that does not say so.
    std::fs::write(dir.path().join("geometry/tri.ply"), gzip(ply.as_bytes())).unwrap();
    let main = dir.path().join("scene.pbrt");
    std::fs::write(
        &main,
        "WorldBegin\nMaterial \"hair\"\nInclude \"geometry/hair.pbrt.gz\"\nShape \"plymesh\" \"string filename\" \"geometry/tri.ply\"\n",
    )
    .unwrap();
    let s = read_pbrt(&main).unwrap();
    let HairSource::Inline(set) = &s.contents.hair[0].source else { panic!() };
    assert_eq!(set.strand_count(), 3);
    let MeshSource::Inline(m) = &s.contents.meshes[0].source else { panic!() };
    assert_eq!(m.indices.len(), 1);
    // A damaged gzip include names the included file.
    let mut bad = gzip(curves.as_bytes());
    bad.truncate(bad.len() - 9);
    std::fs::write(dir.path().join("geometry/hair.pbrt.gz"), bad).unwrap();
    let e = read_pbrt(&main).unwrap_err().to_string();
    assert!(e.contains("hair.pbrt.gz") && e.contains("gzip"), "{e}");
}

#[test]
fn integrators_map_to_path_tracing_with_pbrt_depth_or_to_direct_light() {
    let depth = |text: &str| {
        let s = read(text).unwrap();
        (s.integrator.unwrap(), s.max_depth.unwrap(), s.warnings)
    };
    for kind in ["path", "volpath", "bdpt", "mlt", "sppm", "simplepath"] {
        let (i, d, w) = depth(&format!("Integrator \"{kind}\" \"integer maxdepth\" 32\n"));
        assert_eq!((i, d), (Integrator::Path, 31), "{kind}");
        assert!(w.is_empty(), "{kind}: {w:?}");
    }
    // pbrt's default: volpath (v4) or path (v3) with maxdepth 5.
    assert_eq!(depth("WorldBegin\n").0, Integrator::Path);
    assert_eq!(depth("WorldBegin\n").1, 4);
    // maxdepth 1 is direct light only.
    assert_eq!(depth("Integrator \"path\" \"integer maxdepth\" 1\n").1, 0);
    assert_eq!(depth("Integrator \"directlighting\"\n").0, Integrator::Direct);
    assert_eq!(depth("Integrator \"whitted\" \"integer maxdepth\" 3\n").1, 3);
    let (i, _, w) = depth("Integrator \"ambientocclusion\"\n");
    assert_eq!(i, Integrator::Path);
    assert!(w.iter().any(|w| w.contains("\"ambientocclusion\"")), "{w:?}");
    // The description renders with them.
    let (d, _) = read("Integrator \"bdpt\" \"integer maxdepth\" 8\n").unwrap().into_description();
    assert_eq!((d.settings.integrator, d.settings.max_depth), (Integrator::Path, 7));
}

#[test]
fn film_iso_shutter_and_v3_scale_scale_every_light_as_pbrt_scales_the_image() {
    let lights =
        "WorldBegin\nLightSource \"distant\" \"rgb L\" [1 2 3]\nLightSource \"infinite\" \"rgb L\" [0.5 0.5 0.5]\n\
                  LightSource \"point\" \"rgb I\" [4 4 4]\n";
    let at = |head: &str| read(&format!("{head}{lights}")).unwrap().contents.lights;
    let plain = at("");
    assert_eq!(plain[0], Light::Distant { direction: -Vec3::Z, irradiance: Vec3::new(1.0, 2.0, 3.0) }.into());
    // Imaging ratio = exposure time × ISO / 100.
    for (head, k) in [
        ("Film \"rgb\" \"float iso\" 400\n", 4.0),
        ("Camera \"perspective\" \"float shutteropen\" 0 \"float shutterclose\" 0.5\n", 0.5),
        ("Film \"rgb\" \"float iso\" 200\nCamera \"perspective\" \"float shutterclose\" 0.25\n", 0.5),
        ("Film \"image\" \"float scale\" 3\n", 3.0),
    ] {
        let scaled = at(head);
        for (a, b) in plain.iter().zip(&scaled) {
            let (LightSource::Inline(mut a), LightSource::Inline(b)) = (a.clone(), b.clone()) else { panic!() };
            scale_emission(&mut a, k);
            assert_eq!(a, b, "{head}");
        }
    }
    let e = read("Film \"rgb\" \"float iso\" -1\n").unwrap_err().to_string();
    assert!(e.contains("line 1") && e.contains("iso"), "{e}");
}

#[test]
fn photometric_light_parameters_follow_pbrt_v4() {
    let s =
        read("LightSource \"point\" \"float power\" 100\nLightSource \"distant\" \"float illuminance\" 3\n").unwrap();
    let LightSource::Inline(Light::Point { intensity, .. }) = s.contents.lights[0] else { panic!() };
    assert!((intensity.x - 100.0 / (4.0 * std::f32::consts::PI)).abs() < 1e-4, "{intensity}");
    let LightSource::Inline(Light::Distant { irradiance, .. }) = s.contents.lights[1] else { panic!() };
    assert_eq!(irradiance, Vec3::splat(3.0));
}

fn hair_of(text: &str) -> (HairParams, Vec<String>) {
    let s = read(&format!("{text}\nShape \"curve\" \"point3 P\" [0 0 0 0 1 0 0 2 0 0 3 0]\n")).unwrap();
    let MaterialSource::Inline(Material::Physical(h)) = &s.contents.hair[0].material else { panic!("{text}") };
    (*h.params(), s.warnings)
}

#[test]
fn every_hair_parametrization_of_pbrt_v3_and_v4() {
    // v3 calls the colour `color`, v4 `reflectance`; "color" is v3's synonym of "rgb".
    for text in [
        "Material \"hair\" \"rgb color\" [0.6 0.4 0.2]",
        "Material \"hair\" \"color color\" [0.6 0.4 0.2]",
        "Material \"hair\" \"rgb reflectance\" [0.6 0.4 0.2]",
    ] {
        let (h, w) = hair_of(text);
        assert_eq!(h.absorption, Absorption::Color(Vec3::new(0.6, 0.4, 0.2)), "{text}");
        assert!(w.is_empty(), "{text}: {w:?}");
    }
    // Melanin: the other concentration defaults to 0; neither given is pbrt's 1.3 brown.
    let melanin = |text: &str| hair_of(text).0.absorption;
    assert_eq!(
        melanin("Material \"hair\" \"float pheomelanin\" 0.8"),
        Absorption::Melanin { eumelanin: 0.0, pheomelanin: 0.8 }
    );
    assert_eq!(
        melanin("Material \"hair\" \"float eumelanin\" 8"),
        Absorption::Melanin { eumelanin: 8.0, pheomelanin: 0.0 }
    );
    assert_eq!(melanin("Material \"hair\""), Absorption::Melanin { eumelanin: 1.3, pheomelanin: 0.0 });
    // The roughnesses, tilt and index of refraction, v3 or v4 alike.
    let (h, _) =
        hair_of("Material \"hair\" \"float beta_m\" 0.1 \"float beta_n\" 0.7 \"float alpha\" 0 \"float eta\" 1.6");
    assert_eq!((h.beta_m, h.beta_n, h.alpha_degrees, h.eta), (0.1, 0.7, 0.0, 1.6));
    // sigma_a wins over a colour, as in pbrt, and the ignored colour is reported.
    let (h, w) = hair_of("Material \"hair\" \"rgb sigma_a\" [0.3 0.3 0.3] \"rgb color\" [0.9 0.1 0.1]");
    let Absorption::Color(c) = h.absorption else { panic!() };
    assert!((c.x - c.y).abs() < 1e-6 && c.x < 0.9, "{c}");
    assert!(w.iter().any(|w| w.contains("\"rgb color\" is not used")), "{w:?}");
}

#[test]
fn diffuse_colours_of_v3_and_v4_materials() {
    let mesh = "Shape \"trianglemesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0]\n";
    let material = |m: &str| {
        let s = read(&format!("WorldBegin\n{m}\n{mesh}")).unwrap();
        let MaterialSource::Inline(m) = s.contents.meshes[0].material.clone() else { panic!("{m}") };
        (m, s.warnings)
    };
    let rgb = Vec3::new(0.1, 0.5, 0.9);
    for m in [
        "Material \"matte\" \"rgb Kd\" [0.1 0.5 0.9]",
        "Material \"matte\" \"color Kd\" [0.1 0.5 0.9]",
        "Material \"diffuse\" \"rgb reflectance\" [0.1 0.5 0.9]",
        "MakeNamedMaterial \"m\" \"string type\" \"matte\" \"rgb Kd\" [0.1 0.5 0.9]\nNamedMaterial \"m\"",
    ] {
        let (got, w) = material(m);
        assert_eq!(got, Material::Diffuse { color: rgb }, "{m}");
        assert!(w.is_empty(), "{m}: {w:?}");
    }
    // pbrt-v3's defaults: matte 0.5, plastic 0.25.
    assert_eq!(material("Material \"matte\"").0, Material::Diffuse { color: Vec3::splat(0.5) });
    let (plastic, w) = material("Material \"plastic\" \"rgb Kd\" [0.1 0.5 0.9] \"rgb Ks\" [1 1 1]");
    assert_eq!(plastic, Material::Diffuse { color: rgb });
    assert!(w.iter().any(|w| w.contains("\"plastic\" is rendered as its diffuse colour Kd")), "{w:?}");
    assert!(w.iter().any(|w| w.contains("\"rgb Ks\" is not used")), "{w:?}");
    assert_eq!(material("Material \"glass\" \"float index\" 1.33").0, Material::Glass { ior: 1.33, color: Vec3::ONE });
    assert_eq!(
        material("Material \"mirror\" \"rgb Kr\" [0.5 0.5 0.5]").0,
        Material::Mirror { color: Vec3::splat(0.5) }
    );
    // A textured colour falls back to the default, with a warning, not an error.
    let (m, w) = material("Material \"matte\" \"texture Kd\" \"checks\"");
    assert_eq!(m, Material::Diffuse { color: Vec3::splat(0.5) });
    assert!(w.iter().any(|w| w.contains("textures")), "{w:?}");
}

#[test]
fn unused_and_unknown_parameters_are_reported_once_with_file_and_line() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("spheres.pbrt"),
        "Shape \"sphere\" \"float radius\" 1 \"float zmin\" -0.5\n\nShape \"sphere\" \"float zmin\" 0 \"float bogus\" 2\n",
    )
    .unwrap();
    let main = dir.path().join("main.pbrt");
    std::fs::write(
        &main,
        "Film \"rgb\" \"string filename\" \"out.exr\" \"float maxcomponentvalue\" 10 \"float diagonal\" 35\nWorldBegin\nInclude \"spheres.pbrt\"\n",
    )
    .unwrap();
    let s = read_pbrt(&main).unwrap();
    let sub = dir.path().join("spheres.pbrt").display().to_string();
    let of = |needle: &str| s.warnings.iter().filter(|w| w.contains(needle)).cloned().collect::<Vec<_>>();
    assert_eq!(
        of("zmin"),
        [format!("{sub}: line 1: Shape \"sphere\": parameter \"float zmin\" is not used (and 1 more times)")]
    );
    assert_eq!(of("bogus"), [format!("{sub}: line 3: Shape \"sphere\": parameter \"float bogus\" is not used")]);
    // The file read is named once, by the caller's prefix.
    assert_eq!(of("diagonal").len(), 1);
    assert!(of("diagonal")[0].starts_with("line 1: Film \"rgb\""), "{:?}", of("diagonal"));
    // Parameters tress reads, and the output file name, are not reported: the film's
    // sample clamp is applied, as tress's `max_sample_value`.
    assert!(of("radius").is_empty() && of("filename").is_empty(), "{:?}", s.warnings);
    assert!(of("maxcomponentvalue").is_empty(), "{:?}", s.warnings);
    assert_eq!(s.max_sample_value, Some(10.0));
    assert_eq!(s.into_description().0.settings.max_sample_value, 10.0);
}

#[test]
fn image_infinite_lights_become_environment_maps_scaled_like_every_light() {
    let dir = tempfile::tempdir().unwrap();
    // A 2 × 2 square PFM map of one colour (PFM rows run from the bottom up).
    let mut map = b"PF\n2 2\n-1.0\n".to_vec();
    for _ in 0..4 {
        for v in [4.0f32, 8.0, 12.0] {
            map.extend(v.to_le_bytes());
        }
    }
    std::fs::write(dir.path().join("sky.pfm"), map).unwrap();
    let main = dir.path().join("s.pbrt");
    std::fs::write(&main, "Film \"rgb\" \"float iso\" 200\nWorldBegin\nLightSource \"infinite\" \"string filename\" \"sky.pfm\" \"float scale\" 0.5\n").unwrap();
    let s = read_pbrt(&main).unwrap();
    assert!(s.warnings.is_empty(), "{:?}", s.warnings);
    // The file is named, for `prepare` to read (tests/environment_files.rs renders such maps).
    let [LightSource::File(f)] = &s.contents.lights[..] else { panic!("{:?}", s.contents.lights) };
    assert_eq!((&f.path, f.projection, f.illuminance), (&dir.path().join("sky.pfm"), Projection::EqualArea, None));
    // Scale 0.5 × imaging ratio 2 on the map's (4, 8, 12), from every direction; the
    // fallback sky is the light's colour, scaled alike.
    let tinted = Vec3::new(4.0, 8.0, 12.0) * f.tint;
    let m = crate::light::EnvironmentMap::placed(1, 1, &tinted.to_array(), f.placement).unwrap();
    for d in [Vec3::X, Vec3::Y, -Vec3::Z, Vec3::new(1.0, -2.0, 3.0).normalize()] {
        assert!((m.radiance(d) - Vec3::new(4.0, 8.0, 12.0)).abs().max_element() < 1e-4, "{d}: {}", m.radiance(d));
    }
    assert_eq!(f.fallback, Some(Vec3::ONE));
    // pbrt-v3's `mapname` is latitude-longitude.
    std::fs::write(&main, "WorldBegin\nLightSource \"infinite\" \"string mapname\" \"gone.exr\"\n").unwrap();
    let s = read_pbrt(&main).unwrap();
    let [LightSource::File(f)] = &s.contents.lights[..] else { panic!("{:?}", s.contents.lights) };
    assert_eq!((f.projection, f.fallback), (Projection::LatLong, Some(Vec3::ONE)));
}

#[test]
fn pbrt_v3_light_scales_are_spectra() {
    // pbrt-v3's bunny-fur scene: `"color scale" [12 12 12]` on an infinite light.
    let s = read("WorldBegin\nLightSource \"infinite\" \"rgb L\" [0.5 0.5 0.5] \"color scale\" [12 6 3]\n").unwrap();
    assert_eq!(
        s.contents.lights[0],
        Light::Environment { radiance: Vec3::new(6.0, 3.0, 1.5), camera_visibility: 1.0 }.into()
    );
    let s = read("WorldBegin\nLightSource \"point\" \"float scale\" 2\n").unwrap();
    let LightSource::Inline(Light::Point { intensity, .. }) = s.contents.lights[0] else { panic!() };
    assert_eq!(intensity, Vec3::splat(2.0));
    let e = read("WorldBegin\nLightSource \"point\" \"rgb scale\" [1 2]\n").unwrap_err().to_string();
    assert!(e.contains("line 2") && e.contains("scale"), "{e}");
}

#[test]
fn a_pinhole_cameras_focus_distance_is_not_reported_a_lens_is() {
    let warnings = |camera: &str| read(&format!("Camera \"perspective\" {camera}\nWorldBegin\n")).unwrap().warnings;
    // pbrt-v4's hair scenes: a focus distance with the lens commented out.
    assert!(warnings("\"float fov\" 32 \"float focaldistance\" 21").is_empty());
    let w = warnings("\"float lensradius\" 0.2 \"float focaldistance\" 21");
    assert!(w.len() == 1 && w[0].contains("lensradius") && w[0].contains("depth of field"), "{w:?}");
}

#[test]
fn a_camera_beyond_single_precision_is_an_error_naming_its_line() {
    // Finite in double precision, infinite once the camera is kept in f32.
    for look in ["LookAt 1e39 0 5  0 0 0  0 1 0", "Translate 3e38 0 0\nTranslate 3e38 0 0"] {
        let e = read(&format!("{look}\nCamera \"perspective\"\nWorldBegin\n")).unwrap_err().to_string();
        assert!(e.contains("beyond single precision") && e.contains("line"), "{look}: {e}");
    }
}

#[test]
fn colours_lights_and_sizes_beyond_single_precision_are_errors_naming_their_line() {
    // Each value is finite in double precision and infinite (or 0) once kept in f32; the
    // error names its line (the third, after the camera and WorldBegin) and what is wrong.
    let head = "Camera \"perspective\"\nWorldBegin\n";
    for (directive, what) in [
        ("Material \"diffuse\" \"rgb reflectance\" [ 1e39 0.5 0.5 ]", "\"rgb reflectance\" is beyond single precision"),
        ("Material \"coateddiffuse\" \"float reflectance\" 1e39", "\"float reflectance\" is beyond"),
        ("Material \"hair\" \"spectrum sigma_a\" [ 400 1e39 700 1 ]", "\"spectrum sigma_a\" is beyond"),
        ("Material \"dielectric\" \"float eta\" 1e39", "eta is beyond single precision"),
        ("LightSource \"point\" \"rgb I\" [ 1e39 1 1 ]", "\"rgb I\" is beyond single precision"),
        // A colour of 1e39 times a scale of 0 is not NaN light: the colour is refused.
        ("LightSource \"distant\" \"rgb L\" [ 1e39 1 1 ] \"float scale\" 0", "\"rgb L\" is beyond"),
        ("LightSource \"point\" \"point3 from\" [ 1e39 0 0 ]", "light \"point\": \"from\" is beyond"),
        ("LightSource \"spot\" \"point3 to\" [ 0 -1e39 0 ]", "light \"spot\": \"to\" is beyond"),
        ("LightSource \"distant\" \"point3 from\" [ 0 0 1e39 ]", "light \"distant\": \"from\" is beyond"),
        ("LightSource \"point\" \"float power\" 1e39", "light \"point\": power is beyond single precision"),
        ("LightSource \"distant\" \"float illuminance\" 1e-50", "illuminance is beyond single precision"),
        (
            "LightSource \"infinite\" \"string filename\" \"sky.exr\" \"float illuminance\" 1e39",
            "light \"infinite\": illuminance is beyond",
        ),
        // Finite colours whose product overflows are refused too.
        ("LightSource \"point\" \"rgb I\" [ 3e38 1 1 ] \"rgb scale\" [ 3e38 1 1 ]", "emission must be finite"),
        ("Shape \"sphere\" \"float radius\" 1e39", "sphere radius is beyond single precision"),
    ] {
        let e = read(&format!("{head}{directive}\n")).unwrap_err().to_string();
        assert!(e.starts_with("dir/scene.pbrt: line 3: ") && e.contains(what), "{directive}: {e}");
    }
    // The camera's screen window and the imaging ratio, on the Camera and Film lines.
    let film = |film: &str, camera: &str| read(&format!("{film}\n{camera}\nWorldBegin\n")).unwrap_err().to_string();
    let e = film("", "Camera \"perspective\" \"float screenwindow\" [ -1e39 1e39 -1 1 ]");
    assert!(e.starts_with("dir/scene.pbrt: line 2: the camera's screen window is beyond single precision"), "{e}");
    let e = film("Film \"rgb\" \"float iso\" 1e42", "Camera \"perspective\"");
    assert!(e.starts_with("dir/scene.pbrt: line 1: the imaging ratio") && e.contains("beyond single precision"), "{e}");
    let e = film("Film \"rgb\" \"float iso\" 1e30", "Camera \"perspective\" \"float shutterclose\" 1e30");
    assert!(e.starts_with("dir/scene.pbrt: line 2: the imaging ratio"), "{e}");
    // Each finite, the light times the imaging ratio is not: named by the light's line.
    let e = film(
        "Film \"rgb\" \"float iso\" 1e30",
        "Camera \"perspective\"\nWorldBegin\n\nLightSource \"point\" \"rgb I\" [ 1e30 1 1 ]",
    );
    assert!(e.starts_with("dir/scene.pbrt: line 5: the light's emission × the imaging ratio"), "{e}");
    // In range, nothing changes.
    let s = read(&format!("Film \"rgb\" \"float iso\" 1e30\n{head}LightSource \"point\" \"rgb I\" [ 1e-20 1 1 ]\n"))
        .unwrap();
    assert_eq!(s.contents.lights.len(), 1);
}

/// pbrt's `fov` spans the shorter image side (its screen window is [-1, 1] there, Pharr et
/// al. 4th ed. §5.2), so an image of another size (`-r`) refits the vertical field of
/// view: a 40° fov is the vertical one at 2:1 and 1:1, and at 1:2 the horizontal one,
/// the vertical one 2 atan(2 tan 20°). A screen window of its own is what `fov` spans.
#[test]
fn the_field_of_view_spans_the_shorter_side_of_any_image_size() {
    let camera = |params: &str| {
        let text = format!("Camera \"perspective\" \"float fov\" 40 {params}\nFilm \"rgb\" \"integer xresolution\" 200 \"integer yresolution\" 100\nWorldBegin\n");
        read(&text).unwrap()
    };
    let s = camera("");
    let c = s.camera.unwrap();
    let t = 20f32.to_radians().tan();
    let tall = 2.0 * (2.0 * t).atan().to_degrees();
    assert!((c.vfov - 40.0).abs() < 1e-4, "{}", c.vfov);
    for ([w, h], want) in [([200, 100], 40.0), ([100, 100], 40.0), ([100, 200], tall)] {
        assert!((c.vfov_for(w, h) - want).abs() < 1e-3, "{w}x{h}: {} {want}", c.vfov_for(w, h));
    }
    assert!(s.warnings.is_empty(), "{:?}", s.warnings);
    // A window twice as high as wide: `fov` spans its width of 2, so a 1:2 image sees
    // 2 atan(2 tan 20°) vertically, a square one that window overscanned to its height.
    let s = camera("\"float screenwindow\" [-1 1 -2 2]");
    let c = s.camera.unwrap();
    for ([w, h], want) in [([100, 200], tall), ([100, 100], tall), ([200, 100], tall)] {
        assert!((c.vfov_for(w, h) - want).abs() < 1e-3, "{w}x{h}: {} {want}", c.vfov_for(w, h));
    }
    assert!(s.warnings.is_empty(), "{:?}", s.warnings);
    // A frame aspect ratio of 1/2 is that window too; an off-centre window shifts the
    // view by its centre over its half size: [0, 2] across is a half width to the right.
    let c = camera("\"float frameaspectratio\" 0.5").camera.unwrap();
    assert!((c.vfov_for(100, 200) - tall).abs() < 1e-3, "{}", c.vfov_for(100, 200));
    assert_eq!(c.window, crate::scene::FULL_SCREEN);
    let s = camera("\"float screenwindow\" [0 2 -1 3]");
    let corners = [glam::Vec2::new(0.0, -0.5), glam::Vec2::new(2.0, 1.5)];
    assert!(s.warnings.is_empty() && s.camera.unwrap().window == corners, "{:?}", s.warnings);
    for bad in
        ["\"float screenwindow\" [1 -1 -1 1]", "\"float screenwindow\" [-1 1 -1]", "\"float frameaspectratio\" 0"]
    {
        let text = format!("Camera \"perspective\" {bad}\nWorldBegin\n");
        let e = read(&text).unwrap_err().to_string();
        assert!(e.contains("line 1") && (e.contains("screenwindow") || e.contains("frameaspectratio")), "{e}");
    }
}

/// pbrt's orthographic camera looks through the same screen window as the perspective
/// one, measured in camera space (Pharr et al. 4th ed. §5.2.1): [-1, 1] on the shorter
/// image side by default, so a window 2 units high at 2:1 and 1:1 and 4 at 1:2; a window
/// of its own is its size; a `Scale` before `Camera` shrinks camera space units in the
/// scene, so the window it sees grows by the inverse. `fov` means nothing to it.
#[test]
fn an_orthographic_camera_sees_its_screen_window_in_camera_space_units() {
    let camera = |transform: &str, params: &str| {
        let text = format!(
            "{transform}Camera \"orthographic\" {params}\nFilm \"rgb\" \"integer xresolution\" 200 \"integer yresolution\" 100\nWorldBegin\n"
        );
        read(&text).unwrap()
    };
    let height = |c: &crate::scene::CameraDesc, w, h| c.ortho_height_for(w, h).unwrap();
    let s = camera("", "");
    let c = s.camera.unwrap();
    for ([w, h], want) in [([200, 100], 2.0), ([100, 100], 2.0), ([100, 200], 4.0)] {
        assert!((height(&c, w, h) - want).abs() < 1e-5, "{w}x{h}: {}", height(&c, w, h));
    }
    assert!(s.warnings.is_empty(), "{:?}", s.warnings);
    let c = camera("", "\"float screenwindow\" [-3 3 -1.5 1.5]").camera.unwrap();
    assert!((height(&c, 200, 100) - 3.0).abs() < 1e-5, "{}", height(&c, 200, 100));
    let c = camera("Scale 0.5 0.5 1\n", "").camera.unwrap();
    assert!((height(&c, 200, 100) - 4.0).abs() < 1e-5, "{}", height(&c, 200, 100));
    let w = camera("", "\"float fov\" 30").warnings;
    assert!(w.iter().any(|w| w.contains("fov")), "{w:?}");
    // A projection tress does not have is drawn in perspective, and said.
    let text = "Camera \"spherical\"\nWorldBegin\n";
    let s = read(text).unwrap();
    assert_eq!(s.camera.unwrap().projection, crate::scene::CameraProjection::Perspective);
    assert!(s.warnings.iter().any(|w| w.contains("spherical")), "{:?}", s.warnings);
}

#[test]
fn trianglemesh_normals_and_uvs_beyond_single_precision_are_errors_naming_them() {
    let mesh = |extra: &str| {
        read(&format!("WorldBegin\nShape \"trianglemesh\" \"point3 P\" [ 0 0 0  1 0 0  0 1 0 ]\n  {extra}\n"))
    };
    assert!(mesh("\"normal N\" [ 0 0 1  0 0 1  0 0 1 ] \"point2 uv\" [ 0 0  1 0  0 1 ]").is_ok());
    // Finite as doubles, infinite in single precision.
    for (extra, name) in [
        ("\"normal N\" [ 0 0 1  0 0 1e39  0 0 1 ]", "\"N\""),
        ("\"point2 uv\" [ 0 0  1e39 0  0 1 ]", "\"uv\""),
        ("\"point2 st\" [ 0 0  1 0  0 -1e39 ]", "\"st\""),
    ] {
        let e = mesh(extra).unwrap_err().to_string();
        assert!(e.starts_with("dir/scene.pbrt: line 3:") && e.contains(name) && e.contains("single precision"), "{e}");
    }
}

#[test]
fn a_trianglemesh_with_empty_indices_is_an_error() {
    // Found by the hostile proptest: small.pbrt's indices with their 13 bytes deleted.
    let e = read(
        "WorldBegin\nShape \"trianglemesh\" \"integer indices\" [ ]\n  \"point3 P\" [ 0 0 0  1 0 0  0 1 0  1 1 0 ]\n",
    )
    .unwrap_err()
    .to_string();
    assert!(e.starts_with("dir/scene.pbrt: line 2:") && e.contains("no triangles"), "{e}");
}

/// Area lights: the shapes under a `diffuse` (v3: `area`) light emit `L` × `scale` from
/// the side pbrt's surface normal faces (a mesh's winding, turned by a mirroring transform
/// and by `ReverseOrientation`; a sphere's outside), from both with `twosided`, scaled to
/// v4's `power`; the light replaces the shape, for the shapes of its attribute block only.
#[test]
fn area_lights_emit_from_the_side_pbrt_faces() {
    const QUAD: &str =
        "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3] \"point3 P\" [-1 -1 0  1 -1 0  1 1 0  -1 1 0]";
    let lit = |before: &str, light: &str, shape: &str| {
        let s = read(&format!(
            "WorldBegin\nAttributeBegin\n{before}\nAreaLightSource {light}\n{shape}\nAttributeEnd\n{QUAD}\n"
        ))
        .unwrap();
        assert!(s.warnings.iter().all(|w| !w.contains("not supported") && !w.contains("not used")), "{:?}", s.warnings);
        // The quad after the block is drawn, not lit.
        assert_eq!((s.contents.lights.len(), s.contents.meshes.len()), (1, 1));
        let LightSource::Inline(light) = &s.contents.lights[0] else { panic!() };
        let from = |z: f32| light.emitted(Vec3::new(0.1, 0.2, z), Vec3::new(0.0, 0.0, -z.signum()), 100.0).map(|e| e.1);
        (from(5.0), from(-5.0))
    };
    let rgb = Vec3::new(2.0, 4.0, 6.0);
    let diffuse = "\"diffuse\" \"rgb L\" [1 2 3] \"float scale\" 2";
    assert_eq!(lit("", diffuse, QUAD), (Some(rgb), None));
    assert_eq!(lit("ReverseOrientation", diffuse, QUAD), (None, Some(rgb)));
    assert_eq!(lit("Scale -1 1 1", diffuse, QUAD), (Some(rgb), None));
    assert_eq!(lit("", "\"area\" \"color L\" [1 2 3] \"color scale\" [2 2 2]", QUAD), (Some(rgb), None));
    let two = "\"diffuse\" \"rgb L\" [1 2 3] \"float scale\" 2 \"bool twosided\" true";
    assert_eq!(lit("", two, QUAD), (Some(rgb), Some(rgb)));
    // 8π W from a 4 m² one-sided quad: L = Φ / (π A) = 2.
    let power = lit("", "\"diffuse\" \"float power\" 25.132741", QUAD).0.unwrap();
    assert!((power - Vec3::splat(2.0)).abs().max_element() < 1e-5, "{power}");
    // A sphere emits from its outside (rays from z = ±5 meet it from outside both times).
    assert_eq!(lit("", diffuse, "Shape \"sphere\" \"float radius\" 1"), (Some(rgb), Some(rgb)));
    let inside = read(&format!("WorldBegin\nAreaLightSource {diffuse}\nShape \"sphere\"\n")).unwrap();
    let LightSource::Inline(sphere) = &inside.contents.lights[0] else { panic!() };
    assert_eq!(sphere.emitted(Vec3::ZERO, Vec3::X, 100.0), None);
    // The import's mirror about the camera's vertical plane keeps the emitting side.
    let s = read(&format!(
        "LookAt 3 0 5  0 0 0  0 1 0\nCamera \"perspective\"\nWorldBegin\nAreaLightSource {diffuse}\n{QUAD}\n"
    ));
    let LightSource::Inline(light) = &s.unwrap().contents.lights[0] else { panic!() };
    assert!(light.emitted(Vec3::new(0.1, 0.2, 5.0), Vec3::NEG_Z, 100.0).is_some());
    assert!(light.emitted(Vec3::new(0.1, 0.2, -5.0), Vec3::Z, 100.0).is_none());
    // Other kinds are reported; their shapes are drawn.
    let s = read(&format!("WorldBegin\nAreaLightSource \"goniometric\"\n{QUAD}\n")).unwrap();
    assert_eq!((s.contents.lights.len(), s.contents.meshes.len()), (0, 1));
    assert!(s.warnings.iter().any(|w| w.contains("area light \"goniometric\" is not supported")), "{:?}", s.warnings);
    // Negative emission is an error naming the line.
    let e = read("WorldBegin\nAreaLightSource \"diffuse\" \"rgb L\" [1 -1 1]\n").unwrap_err().to_string();
    assert!(e.contains("line 2") && e.contains("not negative"), "{e}");
}

/// `loopsubdiv` (v4 `levels`, v3 `nlevels`, default 3) is Loop-subdivided to its limit
/// surface: an octahedron's vertex (1, 0, 0) lands at (1/2, 0, 0) at any level.
#[test]
fn loop_subdivision_surfaces_are_subdivided_to_their_limit() {
    let octahedron = "\"point3 P\" [1 0 0  -1 0 0  0 1 0  0 -1 0  0 0 1  0 0 -1] \
        \"integer indices\" [0 2 4  2 1 4  1 3 4  3 0 4  2 0 5  1 2 5  3 1 5  0 3 5]";
    for (levels, triangles) in [("", 8 * 64), ("\"integer levels\" 1", 8 * 4), ("\"integer nlevels\" 2", 8 * 16)] {
        let s = read(&format!("WorldBegin\nShape \"loopsubdiv\" {levels} {octahedron}\n")).unwrap();
        assert!(s.warnings.is_empty(), "{:?}", s.warnings);
        let MeshSource::Inline(mesh) = &s.contents.meshes[0].source else { panic!() };
        assert_eq!(mesh.indices.len(), triangles, "{levels}");
        assert!((mesh.positions[0] - Vec3::new(0.5, 0.0, 0.0)).length() < 1e-6, "{}", mesh.positions[0]);
        assert!(mesh.normals.as_ref().is_some_and(|n| n[0].x > 0.99), "{levels}");
    }
}
