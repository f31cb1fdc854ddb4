use super::parse::{parse, Atom};
use super::*;
use crate::scene::{HairSource, MaterialSource, MeshSource};
use crate::shading::Material;

fn scene(text: &str) -> AssScene {
    parse_ass(text, Path::new("t.ass"), None).unwrap_or_else(|e| panic!("{e}"))
}

fn error(text: &str) -> String {
    parse_ass(text, Path::new("t.ass"), None).unwrap_err().to_string()
}

#[test]
fn values_are_plain_lists_inline_arrays_matrix_rows_and_encoded_arrays() {
    let nodes = parse(
        "# a comment\noptions\n{\n xres 64 # trailing\n camera \"my cam\"\n flag on\n}\n\
         polymesh\n{\n name /a|b\n nsides 2 1 UINT\n 4 3\n vlist 2 2 VECTOR 1 2 3 4 5 6 7 8 9 10 11 12\n matrix\n 1 0 0 0\n 0 1 0 0\n 0 0 1 0\n 5 6 7 1\n\
          declare tag constant STRING\n tag \"x\"\n uvlist 2 1 b85VECTOR2 zy!8+HY8$$$$&\n}\n",
    )
    .unwrap();
    assert_eq!(nodes.len(), 2);
    let o = &nodes[0];
    assert_eq!(o.param("xres").unwrap().values, vec![Atom::Num(64.0)]);
    assert_eq!(o.param("camera").unwrap().values, vec![Atom::Str("my cam".into())]);
    assert_eq!(o.param("flag").unwrap().values, vec![Atom::Word("on".into())]);
    let m = &nodes[1];
    assert_eq!(m.name, "/a|b");
    assert_eq!(m.param("nsides").unwrap().values, vec![Atom::Num(4.0), Atom::Num(3.0)]);
    // Of two motion keys, the first.
    assert_eq!(m.param("vlist").unwrap().values.len(), 6);
    let rows = &m.param("matrix").unwrap().values;
    assert_eq!((rows.len(), &rows[12]), (16, &Atom::Num(5.0)));
    // User data is no parameter.
    assert!(m.param("tag").is_none() && m.param("declare").is_none());
    // Encoded: 0, 1.0 (`y`), then 0.25 twice (`!` word count).
    let uv: Vec<Atom> = [0.0, 1.0, 0.25, 0.25].map(Atom::Num).to_vec();
    assert_eq!(m.param("uvlist").unwrap().values, uv);
}

/// Standard base64 of `bytes`, without padding (as Arnold writes an array whose bytes do
/// not fill the last group).
fn base64(bytes: &[u8]) -> String {
    use base64::Engine;
    base64::engine::general_purpose::STANDARD_NO_PAD.encode(bytes)
}

#[test]
fn b64_arrays_are_the_elements_bytes_over_as_many_lines_as_they_take() {
    let floats: Vec<f32> = vec![-0.5, 0.5, 0.5, 0.25, -1.0, 1e-3];
    let data = base64(&floats.iter().flat_map(|x| x.to_le_bytes()).collect::<Vec<u8>>());
    let (first, rest) = data.split_at(10);
    let ints = base64(&[7u32, 0, 123_456].iter().flat_map(|x| x.to_le_bytes()).collect::<Vec<u8>>());
    let signed = base64(&(-3i32).to_le_bytes());
    let text = format!(
        "polymesh\n{{\n name m\n vlist 2 1 b64POINT\n {first}\n {rest}\n\n vidxs 3 1 b64UINT\n {ints}\n\
          shidxs 1 1 b64INT {signed}\n flags 3 1 b64BYTE {}\n smoothing on\n}}\n",
        base64(&[1, 0, 255]),
    );
    let nodes = parse(&text).unwrap();
    let m = &nodes[0];
    let nums = |name: &str| m.param(name).unwrap().values.clone();
    assert_eq!(nums("vlist"), floats.iter().map(|&x| Atom::Num(f64::from(x))).collect::<Vec<_>>());
    assert_eq!(nums("vidxs"), [7.0, 0.0, 123456.0].map(Atom::Num).to_vec());
    assert_eq!(nums("shidxs"), vec![Atom::Num(-3.0)]);
    assert_eq!(nums("flags"), [1.0, 0.0, 255.0].map(Atom::Num).to_vec());
    // The parameter after the data is read as one.
    assert_eq!(nums("smoothing"), vec![Atom::Word("on".into())]);
    // Padded data reads the same.
    let padded = parse(&format!("polymesh\n{{\n shidxs 1 1 b64INT {signed}==\n}}\n")).unwrap();
    assert_eq!(padded[0].param("shidxs").unwrap().values, vec![Atom::Num(-3.0)]);
}

#[test]
fn malformed_text_is_an_error_naming_the_line() {
    for (text, line, what) in [
        ("options\n{\n xres 10\n", 4, "not closed"),
        ("polymesh\n{\n vlist 2 1 VECTOR 1 2 3 4 5\n nsides 1\n}\n", 4, "nsides in an array of VECTOR"),
        ("polymesh\n{\n vlist 1000000000 1 VECTOR 1 2\n}\n", 3, "more values than the file can"),
        ("polymesh\n{\n vlist 1 1 VECTOR 1 nan 2\n}\n", 3, "not a finite number"),
        ("options\n{\n xres 1e400\n}\n", 3, "not a finite number"),
        ("options\n{\n camera \"cam\n}\n", 3, "not closed"),
        ("{ }\n", 1, "expected a node type"),
        ("polymesh\n{\n uvlist 2 1 b85VECTOR2 z\n}\n", 3, "declares 4"),
        ("polymesh\n{\n nsides 2 1 b85UINT Q$$$$$\n}\n", 3, "packing"),
        // Data short of the twelve bytes declared; then a byte too many.
        ("polymesh\n{\n vidxs 3 1 b64UINT AAAAAAAAAAA\n}\n", 4, "expected encoded UINT data, found `}`"),
        ("polymesh\n{\n flags 2 1 b64BYTE AAAA\n}\n", 3, "holds 3 bytes where the array declares 2"),
        ("polymesh\n{\n vlist 1 1 b64FLOAT AA*AAAAA\n}\n", 3, "not base64"),
        ("polymesh\n{\n vlist 1 1 b64FLOAT AAAA\n", 4, "ends before its encoded data"),
    ] {
        let e = error(text);
        assert!(e.starts_with("t.ass") && e.contains(&format!("line {line}")) && e.contains(what), "{text:?}: {e}");
    }
    // Read, not parsed: a number that is a name.
    let e = error("options\n{\n xres big\n}\n");
    assert!(e.contains("line 3") && e.contains("not a number"), "{e}");
}

#[test]
fn options_set_the_image_samples_depth_and_camera() {
    let s = scene(
        "options\n{\n xres 200\n yres 100\n AA_samples 4\n GI_diffuse_depth 2\n GI_specular_depth 3\n camera \"b\"\n}\n\
         persp_camera\n{\n name a\n}\npersp_camera\n{\n name b\n fov 90\n matrix 1 0 0 0 0 1 0 0 0 0 1 0 1 2 3 1\n}\n",
    );
    let i = &s.imported;
    assert_eq!((i.resolution, i.spp, i.max_depth), (Some([200, 100]), Some(16), Some(3)));
    let c = i.camera.as_ref().unwrap();
    assert_eq!((c.eye, c.target), (Vec3::new(1.0, 2.0, 3.0), Vec3::new(1.0, 2.0, 2.0)));
    // 90° across the width of a 2:1 image: 2 atan(1/2) down its height.
    assert!((c.vfov_for(200, 100) - 2.0 * 0.5f32.atan().to_degrees()).abs() < 1e-3, "{}", c.vfov_for(200, 100));
    // Asked for by name, an unknown camera lists the file's.
    let e = parse_ass("persp_camera\n{\n name a\n}\n", Path::new("t.ass"), Some("zz")).unwrap_err().to_string();
    assert!(e.contains("no camera `zz`") && e.contains("its cameras: a"), "{e}");
}

#[test]
fn screen_windows_and_lens_shifts_move_the_image_window() {
    let cam = |kind: &str, params: &str| {
        let s = scene(&format!("options\n{{\n xres 200\n yres 100\n}}\n{kind}\n{{\n name c\n{params}}}\n"));
        s.imported.camera.unwrap()
    };
    let c = cam("persp_camera", " screen_window_min -0.2 -0.2\n screen_window_max 1 1\n");
    assert_eq!(c.window, [Vec2::splat(-0.2), Vec2::ONE]);
    // +1 across moves the frame's centre to the right edge, +1 up to the bottom edge.
    let c = cam("persp_camera", " lens_shift 0.5 0.25\n");
    assert_eq!(c.window, [Vec2::new(-0.5, -1.25), Vec2::new(1.5, 0.75)]);
    // Orthographic: a screen 2 units wide, its height following the image, seen through
    // its window (in scene units across).
    let c = cam("ortho_camera", " screen_window_min -15 -5\n screen_window_max 15 25\n");
    assert_eq!((c.window, c.ortho_height_for(200, 100)), ([Vec2::new(-15.0, -5.0), Vec2::new(15.0, 25.0)], Some(1.0)));
    let e = error("persp_camera\n{\n name c\n screen_window_min 1 0\n screen_window_max 1 1\n}\n");
    assert!(e.contains("no width or no height"), "{e}");
}

#[test]
fn lights_emit_intensity_times_two_to_the_exposure() {
    let s = scene(
        "distant_light\n{\n name d\n intensity 3\n exposure 2\n color 1 0.5 0\n matrix 1 0 0 0 0 0 -1 0 0 1 0 0 0 0 0 1\n}\n\
         skydome_light\n{\n name s\n intensity 0.5\n color 0.2 0.2 0.2\n camera 0\n}\n",
    );
    let lights: Vec<&Light> = s
        .imported
        .contents
        .lights
        .iter()
        .map(|l| match l {
            LightSource::Inline(l) => l,
            other => panic!("{other:?}"),
        })
        .collect();
    let Light::Distant { direction, irradiance } = lights[0] else { panic!("{:?}", lights[0]) };
    assert_eq!(*irradiance, Vec3::new(12.0, 6.0, 0.0));
    // Local −Z turned to −Y: the light shines down, from +Y.
    assert!((*direction - Vec3::Y).length() < 1e-6, "{direction}");
    assert_eq!(*lights[1], Light::Environment { radiance: Vec3::splat(0.1), camera_visibility: 0.0 });
}

#[test]
fn portals_let_their_interior_only_sky_in_and_emit_nothing_themselves() {
    let portal = "quad_light\n{\n name p\n vertices 4 1 VECTOR 0 0 0 0 1 0 1 1 0 1 0 0\n portal on\n intensity 9\n}\n";
    let s = scene(&format!("skydome_light\n{{\n name s\n intensity 0.5\n camera 0\n}}\n{portal}"));
    // The dome comes in through the portal only, at its radiance, seen as the dome is.
    let want = Light::Quad {
        corner: Vec3::ZERO,
        edge_u: Vec3::X,
        edge_v: Vec3::Y,
        radiance: Vec3::splat(0.5),
        camera_visibility: 0.0,
    };
    assert_eq!(scene_lights(&s), vec![want]);
    // Letting light outside the portals through, the dome is whole and the portal nothing.
    let s = scene(&format!("skydome_light\n{{\n name s\n portal_mode \"interior_exterior\"\n}}\n{portal}"));
    assert!(matches!(scene_lights(&s)[..], [Light::Environment { .. }]), "{:?}", scene_lights(&s));
}

#[test]
fn spot_disk_and_cylinder_lights_are_read_by_arnolds_parameters() {
    let s = scene(
        "spot_light\n{\n name s\n matrix 1 0 0 0 0 0 -1 0 0 1 0 0 0 5 0 1\n cone_angle 60\n penumbra_angle 10\n\
          radius 0.5\n exposure 1\n}\n\
         disk_light\n{\n name d\n position 0 3 0\n direction 0 -1 0\n radius 1\n intensity 2\n}\n\
         cylinder_light\n{\n name c\n radius 0.5\n normalize off\n}\n\
         photometric_light\n{\n name p\n filename \"a.ies\"\n}\n",
    );
    let lights = scene_lights(&s);
    // Local −Z turned to −Y; the penumbra inside the cone's 30° edge; the radius a point of
    // the same power.
    let Light::Spot { position, direction, intensity, cos_inner, cos_outer, decay: 2 } = lights[0] else {
        panic!("{:?}", lights[0])
    };
    assert_eq!((position, intensity), (Vec3::new(0.0, 5.0, 0.0), Vec3::splat(2.0)));
    assert!((direction - Vec3::NEG_Y).length() < 1e-6, "{direction}");
    assert!((cos_outer - 30f32.to_radians().cos()).abs() < 1e-6 && (cos_inner - 20f32.to_radians().cos()).abs() < 1e-6);
    // The disk: a square of its area π, shining down, its emission spread over it.
    let Light::Quad { corner, edge_u, edge_v, radiance, .. } = lights[1] else { panic!("{:?}", lights[1]) };
    let n = edge_u.cross(edge_v);
    assert!((n.length() - std::f32::consts::PI).abs() < 1e-5 && (n.normalize() - Vec3::NEG_Y).length() < 1e-5);
    assert!(((corner + 0.5 * (edge_u + edge_v)) - Vec3::new(0.0, 3.0, 0.0)).length() < 1e-5);
    assert!((radiance - Vec3::splat(2.0 / std::f32::consts::PI)).length() < 1e-5, "{radiance}");
    // The cylinder from (0, −1, 0) to (0, 1, 0), 2 long and 1 wide: two spheres of its
    // side's area, at its radiance (not normalized).
    let spheres: Vec<&Light> = lights[2..].iter().collect();
    assert_eq!(spheres.len(), 2, "{lights:?}");
    for (l, y) in spheres.iter().zip([-0.5, 0.5]) {
        let Light::Sphere { center, radius, radiance, .. } = l else { panic!("{l:?}") };
        assert_eq!((*center, *radiance), (Vec3::new(0.0, y, 0.0), Vec3::ONE));
        assert!((2.0 * 4.0 * std::f32::consts::PI * radius * radius - std::f32::consts::TAU).abs() < 1e-5);
    }
    let w = &s.imported.warnings;
    for what in ["spot light radii", "`photometric_light` nodes: not read (tress reads no IES profiles"] {
        assert!(w.iter().any(|w| w.contains(what)), "{what}: {w:?}");
    }
}

#[test]
fn a_file_without_lights_renders_black_as_in_arnold() {
    let (d, w) = scene("sphere\n{\n name b\n}\n").imported.into_description();
    assert!(d.contents.lights.is_empty(), "{:?}", d.contents.lights);
    assert!(w.iter().any(|w| w.contains("no lights: black")), "{w:?}");
}

#[test]
fn polymeshes_and_curves_are_read_with_their_instances() {
    let s = scene(
        "polymesh\n{\n name m\n nsides 2 1 UINT 4 3\n vidxs 7 1 UINT 0 1 2 3 0 2 4\n\
          vlist 5 1 VECTOR 0 0 0 1 0 0 1 1 0 0 1 0 2 2 0\n visibility 0\n}\n\
         ginstance\n{\n name g\n node m\n matrix 1 0 0 0 0 1 0 0 0 0 1 0 5 0 0 1\n}\n\
         curves\n{\n name c\n num_points 2 1 UINT 4 7\n points 11 1 VECTOR\n 0 0 0 0 1 0 0 2 0 0 3 0\n\
          1 0 0 1 1 0 1 2 0 1 3 0 1 4 0 1 5 0 1 6 0\n radius 5 1 FLOAT 0.1 0.2 0.1 0.2 0.3\n basis \"bezier\"\n}\n",
    );
    let c = &s.imported.contents;
    // The mesh itself is hidden; its instance draws it, 2 + 1 triangles, 5 units over.
    assert_eq!(c.meshes.len(), 1);
    let MeshSource::Inline(mesh) = &c.meshes[0].source else { panic!() };
    assert_eq!(mesh.indices.len(), 3);
    assert_eq!(c.meshes[0].transform.translation, Vec3::new(5.0, 0.0, 0.0).into());
    let HairSource::Inline(set) = &c.hair[0].source else { panic!() };
    assert_eq!(set.strand_count(), 2);
    // Bézier curves reach their end points; radii per segment end (1 segment, then 2).
    let first = set.points[0];
    let last = set.points[set.points.len() - 1];
    assert_eq!((first[..3].to_vec(), last[..3].to_vec()), (vec![0.0, 0.0, 0.0], vec![1.0, 6.0, 0.0]));
    assert!((first[3] - 0.1).abs() < 1e-6 && (last[3] - 0.3).abs() < 1e-6, "{first:?} {last:?}");
    // Counts that do not add up are an error naming the node.
    let e = error("curves\n{\n name c\n num_points 1 1 UINT 5\n points 1 1 VECTOR 0 0 0\n}\n");
    assert!(e.contains("curves `c`") && e.contains("adds up to 5"), "{e}");
}

#[test]
fn what_is_not_read_is_reported_once_per_kind() {
    let s = scene("noise\n{\n name n1\n}\nnoise\n{\n name n2\n}\npolymesh\n{\n name m\n step_size 1\n}\n");
    let w = &s.imported.warnings;
    assert!(w.iter().any(|w| w.contains("`noise` nodes: not read (2; first: n1)")), "{w:?}");
    assert!(w.iter().any(|w| w.contains("`polymesh` parameters not read: step_size")), "{w:?}");
}

/// Curves of one linear strand of three points, root (0, 0, 0) to tip (0, 2, 0), shaded by
/// `shader`, with `nodes` after them.
fn shaded_strand(shader: &str, nodes: &str) -> AssScene {
    scene(&format!(
        "curves\n{{\n name c\n num_points 1 1 UINT 3\n points 3 1 VECTOR 0 0 0 0 1 0 0 2 0\n basis \"linear\"\n\
          shader \"{shader}\"\n}}\n{nodes}"
    ))
}

fn strand_colors(s: &AssScene) -> (Vec<[f32; 3]>, &Material) {
    let h = &s.imported.contents.hair[0];
    let HairSource::Inline(set) = &h.source else { panic!() };
    let MaterialSource::Inline(m) = &h.material else { panic!() };
    (set.colors.clone().expect("strand colours"), m)
}

#[test]
fn a_v_ramp_on_a_hair_shaders_colour_colours_the_strands_root_to_tip() {
    let s = shaded_strand(
        "h",
        "standard_hair\n{\n name h\n diffuse 1\n diffuse_color m\n}\n\
         multiply\n{\n name m\n input1 0.5 0.5 0.5\n input2 r\n}\n\
         ramp_rgb\n{\n name r\n type \"v\"\n position 2 1 FLOAT 0 1\n color 2 1 RGB 1 0 0 0 0 1\n\
          interpolation 2 1 INT 1 1\n}\n",
    );
    let (colors, material) = strand_colors(&s);
    // Halfway along, half of each; the multiply's 0.5 on all.
    assert_eq!(colors, vec![[0.5, 0.0, 0.0], [0.25, 0.0, 0.25], [0.0, 0.0, 0.5]]);
    assert_eq!(*material, Material::Diffuse { color: Vec3::ONE });
    let w = &s.imported.warnings;
    assert!(!w.iter().any(|w| w.contains("multiply") || w.contains("ramp_rgb")), "{w:?}");
}

#[test]
fn legacy_hair_and_standard_shaders_draw_their_colours_along_strands() {
    let s = shaded_strand("h", "hair\n{\n name h\n rootcolor 1 0 0\n tipcolor 0 1 0\n spec 0.5\n spec_gloss 20\n}\n");
    let (colors, material) = strand_colors(&s);
    assert_eq!(colors, vec![[1.0, 0.0, 0.0], [0.5, 0.5, 0.0], [0.0, 1.0, 0.0]]);
    let Material::Tube(t) = material else { panic!("{material:?}") };
    assert_eq!((t.specular, t.specular_power), (Vec3::splat(0.5), 20.0));
    // Arnold's ambdiff 0.6 is not tube shading's: said.
    assert!(s.imported.warnings.iter().any(|w| w.contains("ambdiff 0.6")), "{:?}", s.imported.warnings);
    let s = shaded_strand(
        "s",
        "standard\n{\n name s\n Kd 0.5\n Kd_color r\n}\n\
         ramp_float\n{\n name r\n type \"v\"\n position 2 1 FLOAT 0 0.5\n value 2 1 FLOAT 0 1\n\
          interpolation 2 1 INT 0 0\n}\n",
    );
    // A step at v 0.5 (interpolation 0), times Kd.
    assert_eq!(strand_colors(&s).0, vec![[0.0; 3], [0.5; 3], [0.5; 3]]);
}

#[test]
fn networks_not_evaluated_keep_the_parameters_value_and_are_reported() {
    let s = shaded_strand(
        "h",
        "hair\n{\n name h\n rootcolor n\n tipcolor n\n}\nnoise\n{\n name n\n}\n\
         polymesh\n{\n name m\n vidxs 3 1 UINT 0 1 2\n vlist 3 1 VECTOR 0 0 0 1 0 0 0 1 0\n shader \"l\"\n}\n\
         lambert\n{\n name l\n Kd_color r\n}\nramp_rgb\n{\n name r\n type \"v\"\n position 2 1 FLOAT 0 1\n\
          color 2 1 RGB 0 0 0 1 1 1\n}\n",
    );
    let w = &s.imported.warnings;
    assert!(
        w.iter().any(|w| w.contains(
            "`noise` nodes in shader networks: not evaluated (the parameter's own value used) (2; first: n)"
        )),
        "{w:?}"
    );
    // On a surface a ramp along v is drawn in its mean, said.
    let MaterialSource::Inline(m) = &s.imported.contents.meshes[0].material else { panic!() };
    assert_eq!(*m, Material::Diffuse { color: Vec3::splat(0.35) });
    assert!(w.iter().any(|w| w.contains("varying shading networks on Kd_color (drawn in their mean)")), "{w:?}");
}

#[test]
fn utility_shaders_colour_curve_segments_at_random_and_draw_flat() {
    let s = scene(
        "curves\n{\n name c\n num_points 1 1 UINT 4\n points 4 1 VECTOR 0 0 0 0 1 0 0 2 0 0 3 0\n basis \"linear\"\n\
          shader \"u\"\n}\nutility\n{\n name u\n color_mode \"prims\"\n shade_mode \"flat\"\n}\n",
    );
    let (colors, material) = strand_colors(&s);
    assert_eq!(*material, Material::Unlit { color: Vec3::ONE });
    // One colour per segment (the tip ends the last one); three segments, three colours.
    assert_eq!(colors.len(), 4);
    assert!(colors[0] != colors[1] && colors[1] != colors[2] && colors[2] == colors[3], "{colors:?}");
    assert!(s.imported.warnings.iter().all(|w| !w.contains("utility")), "{:?}", s.imported.warnings);
}

/// The lights of `text`, which must all be inline.
fn inline_lights(text: &str) -> Vec<Light> {
    scene_lights(&scene(text))
}

/// The lights of `s`, which must all be inline.
fn scene_lights(s: &AssScene) -> Vec<Light> {
    s.imported
        .contents
        .lights
        .iter()
        .map(|l| match l {
            LightSource::Inline(l) => l.clone(),
            other => panic!("{other:?}"),
        })
        .collect()
}

#[test]
fn a_dome_of_a_physical_sky_is_that_sky_and_its_sun_scaled_by_the_dome() {
    let dome = |intensity: f32, sky: &str| {
        inline_lights(&format!(
            "skydome_light\n{{\n name d\n color s\n intensity {intensity}\n camera 0\n}}\nphysical_sky\n{{\n name s\n{sky}}}\n"
        ))
    };
    let lights = dome(1.0, " elevation 90\n azimuth 0\n sun_size 2\n");
    let [Light::Sun { direction, radiance, cos_max }, Light::EnvironmentMap(map)] = lights.as_slice() else {
        panic!("{lights:?}")
    };
    assert!(direction.abs_diff_eq(Vec3::Y, 1e-5), "the sun straight up: {direction}");
    assert!((cos_max - 1f32.to_radians().cos()).abs() < 1e-6, "a 2° disk");
    assert_eq!(map.camera_visibility(), 0.0);
    // Twice the dome's intensity, twice the sky and sun.
    let twice = dome(2.0, " elevation 90\n azimuth 0\n sun_size 2\n");
    let [Light::Sun { radiance: r2, .. }, Light::EnvironmentMap(m2)] = twice.as_slice() else { panic!() };
    assert!((*r2 - 2.0 * *radiance).length() < 1e-3 * r2.length());
    let up = map.radiance(Vec3::new(0.0, 0.5, 1.0).normalize());
    assert!((m2.radiance(Vec3::new(0.0, 0.5, 1.0).normalize()) - 2.0 * up).length() < 1e-4 * up.length());
    // The sun along `sun_direction` when not in degrees, in the X, Y, Z frame; no sun when
    // it is off; no sky when that is off.
    let lights = dome(1.0, " use_degrees off\n sun_direction 1 1 0\n X 0 1 0\n Y 1 0 0\n Z 0 0 -1\n");
    let Light::Sun { direction, .. } = &lights[0] else { panic!("{lights:?}") };
    assert!(direction.abs_diff_eq(Vec3::new(1.0, 1.0, 0.0).normalize(), 1e-5), "{direction}");
    assert!(matches!(dome(1.0, " enable_sun off\n").as_slice(), [Light::EnvironmentMap(_)]));
    assert!(matches!(dome(1.0, " enable_sky off\n").as_slice(), [Light::Sun { .. }]));
    // A value that cannot make a sky names its node.
    let e = error("skydome_light\n{\n name d\n color s\n}\nphysical_sky\n{\n name s\n sky_tint 1 -1 0\n}\n");
    assert!(e.contains("sky tint") && e.contains("line"), "{e}");
}

#[test]
fn checkerboards_texture_curves_by_their_uvs_and_meshes_by_theirs() {
    let s = scene(
        "curves\n{\n name c\n num_points 2 1 UINT 2 2\n points 4 1 VECTOR 0 0 0 0 1 0 1 0 0 1 1 0\n basis \"linear\"\n\
          uvs 2 1 VECTOR2 0.25 0.25 0.75 0.25\n shader \"h\"\n}\n\
         hair\n{\n name h\n rootcolor k\n tipcolor k\n}\n\
         checkerboard\n{\n name k\n color1 1 0 0\n color2 0 1 0\n}\n\
         polymesh\n{\n name m\n vidxs 3 1 UINT 0 1 2\n vlist 3 1 VECTOR 0 0 0 1 0 0 0 1 0\n shader \"l\"\n}\n\
         lambert\n{\n name l\n Kd 0.5\n Kd_color k\n}\n",
    );
    // Each strand its own cell, root to tip: Arnold's default two cells a side.
    let (colors, _) = strand_colors(&s);
    assert_eq!(colors, vec![[0.0, 1.0, 0.0], [0.0, 1.0, 0.0], [1.0, 0.0, 0.0], [1.0, 0.0, 0.0]]);
    let MaterialSource::Inline(Material::Textured(t)) = &s.imported.contents.meshes[0].material else {
        panic!("{:?}", s.imported.contents.meshes[0].material)
    };
    assert_eq!(t.tint, Vec3::splat(0.5));
    assert!(s.imported.warnings.iter().all(|w| !w.contains("checkerboard")), "{:?}", s.imported.warnings);
}

#[test]
fn a_spot_light_without_a_radius_shines_normalized_or_not() {
    for normalize in ["on", "off"] {
        let lights = inline_lights(&format!(
            "spot_light\n{{\n name s\n intensity 3\n cone_angle 40\n normalize {normalize}\n}}\n"
        ));
        let [Light::Spot { intensity, cos_outer, .. }] = lights.as_slice() else { panic!("{lights:?}") };
        assert_eq!(*intensity, Vec3::splat(3.0), "normalize {normalize}");
        assert!((cos_outer - 20f32.to_radians().cos()).abs() < 1e-6);
    }
}

#[test]
fn a_camera_without_a_matrix_is_placed_by_position_look_at_and_up() {
    let cam = |params: &str| scene(&format!("persp_camera\n{{\n name c\n{params}}}\n")).imported.camera.unwrap();
    // Looking from +X at the origin, +Y up: the matrix whose local −Z points along −X.
    let placed = cam(" position 5 0 0\n look_at 0 0 0\n up 0 1 0\n");
    let matrix = cam(" matrix 0 0 -1 0 0 1 0 0 1 0 0 0 5 0 0 1\n");
    assert_eq!(format!("{placed:?}"), format!("{matrix:?}"));
    // The matrix wins over a position.
    let both = cam(" matrix 0 0 -1 0 0 1 0 0 1 0 0 0 5 0 0 1\n position 9 9 9\n");
    assert_eq!(format!("{both:?}"), format!("{matrix:?}"));
    let e = error("persp_camera\n{\n name c\n position 1 2 3\n look_at 1 2 3\n}\n");
    assert!(e.contains("no view and up directions"), "{e}");
}
