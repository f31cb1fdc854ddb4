//! Other tools' scenes end to end: a pbrt-v4 curve scene renders with its curves where
//! their control points project; the example scenes of every format render; export to
//! `.hair` and `.usda` and import back keep points and widths; `[[import]]` entries and
//! the command line on bad foreign files.

use glam::Vec3;
use std::path::Path;
use std::process::Command;
use tress::geometry::StrandSet;
use tress::io::read_imported;
use tress::prepare::prepare;
use tress::scene::{Description, HairSource};

fn render(desc: &Description) -> tress::film::Film {
    let (world, _) = prepare(desc).unwrap();
    tress::render::render(&world, None).0
}

/// Where a world point lands on the image, in pixels (a pinhole camera as tress's).
fn project(desc: &Description, p: Vec3) -> (f32, f32) {
    let c = &desc.camera;
    let forward = (c.target - c.eye).normalize();
    let right = forward.cross(c.up).normalize();
    let up = right.cross(forward);
    let d = p - c.eye;
    let half = (0.5 * c.vfov.to_radians()).tan();
    let (w, h) = (desc.settings.width as f32, desc.settings.height as f32);
    let x = d.dot(right) / d.dot(forward) / (half * w / h);
    let y = d.dot(up) / d.dot(forward) / half;
    ((x + 1.0) * 0.5 * w, (1.0 - y) * 0.5 * h)
}

#[test]
fn a_pbrt_curve_scene_renders_its_curves_over_their_control_points() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("curves.pbrt");
    // Two thick curves: a straight Bézier at x = 0.5 and a bent B-spline at x = −0.6.
    std::fs::write(
        &path,
        "LookAt 0 0 4  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 40\n\
         Film \"rgb\" \"integer xresolution\" 96 \"integer yresolution\" 72\nSampler \"zsobol\" \"integer pixelsamples\" 2\n\
         WorldBegin\nLightSource \"infinite\" \"rgb L\" [0.5 0.5 0.5]\n\
         Material \"hair\" \"rgb reflectance\" [0.8 0.5 0.2]\n\
         Shape \"curve\" \"point3 P\" [0.5 -1 0  0.5 -0.3 0  0.5 0.3 0  0.5 1 0] \"float width\" 0.12\n\
         Shape \"curve\" \"string basis\" \"bspline\" \"point3 P\" [-0.6 -1.2 0  -0.6 -0.6 0  -0.2 0 0  -0.6 0.6 0  -0.6 1.2 0] \"float width\" 0.12\n",
    )
    .unwrap();
    let (desc, _) = read_imported(&path).unwrap().into_description();
    let film = render(&desc);
    let HairSource::Inline(set) = &desc.contents.hair[0].source else { panic!() };
    let m = desc.contents.hair[0].transform;
    // Every sampled point of both curves (a control-point curve, mirrored like pbrt's
    // image) is covered by hair in the image.
    let hair_at = |x: f32, y: f32| {
        let (x, y) = (x.round() as i64, y.round() as i64);
        (-1..=1).any(|dx| {
            (-1..=1).any(|dy| {
                let (px, py) = (x + dx, y + dy);
                px >= 0 && py >= 0 && px < 96 && py < 72 && film.pixels[(py * 96 + px) as usize].strand_id >= 0.0
            })
        })
    };
    for p in &set.points {
        let (x, y) = project(&desc, m.transform_point3(Vec3::new(p[0], p[1], p[2])));
        if (0.0..96.0).contains(&x) && (0.0..72.0).contains(&y) {
            assert!(hair_at(x, y), "no hair at ({x}, {y})");
        }
    }
    // The straight curve's x = 0.5 shows on the image's left (pbrt's handedness), the bent
    // one's bulge at x = −0.2 right of its ends.
    let (x_straight, _) = project(&desc, m.transform_point3(Vec3::new(0.5, 0.0, 0.0)));
    assert!(x_straight < 48.0, "{x_straight}");
    // Background far from both curves.
    assert!(film.pixels[36 * 96 + 48].strand_id < 0.0);
    assert!(film.pixels.iter().filter(|p| p.strand_id >= 0.0).count() > 100);
}

/// The mean radiance of the hair pixels of a Maya file's render.
fn maya_hair_mean(text: &str) -> f32 {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("hair.ma");
    std::fs::write(&path, text).unwrap();
    let (mut desc, _) = read_imported(&path).unwrap().into_description();
    (desc.settings.width, desc.settings.height, desc.settings.spp) = (48, 36, 4);
    let film = render(&desc);
    let hair: Vec<Vec3> = film.pixels.iter().filter(|p| p.strand_id >= 0.0).map(|p| p.color).collect();
    assert!(hair.len() > 100, "{} hair pixels", hair.len());
    hair.iter().sum::<Vec3>().element_sum() / (3.0 * hair.len() as f32)
}

#[test]
fn maya_curves_with_arnolds_standard_hair_darken_with_melanin() {
    // Twenty thick curves side by side under a curve collector with an aiStandardHair.
    let mut text = String::from(
        "createNode transform -n col;\ncreateNode aiCurveCollector -n cols -p col;\n\tsetAttr \".aiCurveWidth\" 0.1;\n",
    );
    for i in 0..20 {
        let x = i as f32 * 0.1;
        text += &format!(
            "createNode transform -n c{i} -p col;\ncreateNode nurbsCurve -n c{i}s -p c{i};\n\
             \tsetAttr \".cc\" -type \"nurbsCurve\" 1 1 0 no 3 2 0 1 2 {x} 0 0 {x} 2 0;\n"
        );
    }
    let shaded = |melanin: f32| {
        maya_hair_mean(&format!(
            "{text}createNode aiStandardHair -n sh;\n\tsetAttr \".melanin\" {melanin};\nconnectAttr \"sh.out\" \"cols.aiCurveShader\";\n"
        ))
    };
    let (white, black) = (shaded(0.0), shaded(1.0));
    assert!(black < 0.25 * white, "melanin 1: {black}, melanin 0: {white}");
}

#[test]
fn the_example_scenes_of_every_format_render() {
    let scenes = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes");
    for name in ["maya_hair.ma", "pbrt_hair.pbrt", "usd_hair.usda"] {
        let (mut desc, _) = read_imported(&scenes.join(name)).unwrap().into_description();
        desc.settings.width = 48;
        desc.settings.height = 36;
        desc.settings.spp = 1;
        let film = render(&desc);
        let hair = film.pixels.iter().filter(|p| p.strand_id >= 0.0).count();
        let lit = film.pixels.iter().filter(|p| p.color.max_element() > 0.02).count();
        assert!(hair > 20 && lit > 200, "{name}: {hair} hair pixels, {lit} lit pixels");
    }
}

fn tress(args: &[&str], dir: &Path) -> (bool, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_tress")).args(args).current_dir(dir).output().unwrap();
    (out.status.success(), String::from_utf8_lossy(&out.stderr).into_owned())
}

fn strands_of(desc: &Description) -> StrandSet {
    let mut all = StrandSet::new();
    for (shape, _) in tress::prepare::load_geometry(desc).unwrap().shapes {
        if let tress::accel::Shape::Strands(s) = shape {
            all.append(&s);
        }
    }
    all
}

#[test]
fn export_to_hair_and_usda_round_trips_points_and_widths() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let scenes = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes");
    let src = scenes.join("maya_hair.ma");
    let (ok, err) = tress(&["export", src.to_str().unwrap(), "-o", "out.hair"], d);
    assert!(ok, "{err}");
    let (ok, err) = tress(&["export", src.to_str().unwrap(), "-o", "out.usda"], d);
    assert!(ok, "{err}");
    // The render strands after hair-system expansion.
    let (desc, _) = read_imported(&src).unwrap().into_description();
    let want = strands_of(&desc);
    assert!(want.strand_count() > 1000);
    let hair = tress::io::cem_hair::read_hair(&d.join("out.hair")).unwrap();
    assert_eq!((hair.offsets.clone(), hair.points.clone()), (want.offsets.clone(), want.points.clone()));
    let (back, _) = read_imported(&d.join("out.usda")).unwrap().into_description();
    let usd = strands_of(&back);
    assert_eq!(usd.offsets, want.offsets);
    assert_eq!(usd.points, want.points);
    assert_eq!(usd.colors, want.colors);
    // Meshes come along in the USD file.
    assert_eq!(back.contents.meshes.len(), desc.contents.meshes.len());
}

#[test]
fn toml_scenes_import_other_formats() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let scenes = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes");
    std::fs::copy(scenes.join("usd_hair.usda"), d.join("grass.usda")).unwrap();
    let toml = "[camera]\neye = [0, 2, 5]\ntarget = [0, 0, 0]\n[render]\nresolution = [32, 24]\nspp = 1\n\
                [[light]]\ntype = \"distant\"\ndirection = [0, 1, 0]\nirradiance = [1, 1, 1]\n\
                [[mesh]]\nshape = { type = \"sphere\" }\nmaterial = { type = \"diffuse\", color = [0.5, 0.5, 0.5] }\n\
                [[import]]\nfile = \"grass.usda\"\ntransform = { translate = [0, 10, 0] }\n";
    std::fs::write(d.join("scene.toml"), toml).unwrap();
    let (desc, _) = tress::io::scene_file::read(&d.join("scene.toml"), None).unwrap();
    // The scene's own mesh stays first; the import adds a mesh and two strand sets, moved.
    assert_eq!((desc.contents.meshes.len(), desc.contents.hair.len(), desc.contents.lights.len()), (2, 2, 1));
    assert_eq!(desc.contents.meshes[1].transform.transform_point3(Vec3::ZERO), Vec3::new(0.0, 10.0, 0.0));
    let with_lights = toml.replace("translate = [0, 10, 0] }", "translate = [0, 10, 0] }\nlights = true");
    std::fs::write(d.join("lit.toml"), with_lights).unwrap();
    let (desc, _) = tress::io::scene_file::read(&d.join("lit.toml"), None).unwrap();
    assert_eq!(desc.contents.lights.len(), 3);
    // A broken import names the scene entry and the imported file's line.
    std::fs::write(d.join("bad.ma"), "createNode mesh;\nsetAttr \".vt[0:1]\" 1 2;\n").unwrap();
    std::fs::write(d.join("bad.toml"), toml.replace("grass.usda", "bad.ma")).unwrap();
    let e = tress::io::scene_file::read(&d.join("bad.toml"), None).unwrap_err().to_string();
    assert!(e.contains("import 1") && e.contains("bad.ma") && e.contains("line 2"), "{e}");
}

#[test]
fn the_command_line_reports_bad_foreign_files_without_panicking() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    for (name, text, needles) in [
        ("a.ma", "createNode transform -n t;\nsetAttr \".t\" -type \"double3\" 1 x 3;\n", &["a.ma", "line 2"][..]),
        ("b.pbrt", "WorldBegin\nShape \"curve\" \"point3 P\" [0 0 0]\n", &["b.pbrt", "line 2"]),
        ("c.usda", "#usda 1.0\ndef Xform \"A\" {\n  float3 x = (1, 2\n}\n", &["c.usda"]),
        ("d.usda", "not usd", &["d.usda", "#usda"]),
    ] {
        std::fs::write(d.join(name), text).unwrap();
        let (ok, err) = tress(&["render", name, "-o", "x.png", "--quiet"], d);
        assert!(!ok && !err.contains("panicked"), "{name}: {err}");
        for n in needles {
            assert!(err.contains(n), "{name}: stderr lacks `{n}`: {err}");
        }
    }
    let (ok, err) = tress(&["export", "-o", "x.obj", "--demo-strands", "10"], d);
    assert!(!ok && err.contains(".usda"), "{err}");
}

/// A quad with UVs under Arnold's `flat` shader whose colour is a checkerboard (Arnold's
/// default frequency: 2 × 2 cells): each quarter of the quad is its cell's colour, exactly
/// (unlit), `color2` at the UV origin, and with a `u_offset` of half a period (one cell)
/// the colours swap.
#[test]
fn usd_checkerboards_colour_their_cells_by_uv() {
    let usda = |u_offset: f32| {
        format!(
            r#"#usda 1.0
def Mesh "Quad" (apiSchemas = ["MaterialBindingAPI"]) {{
    int[] faceVertexCounts = [4]
    int[] faceVertexIndices = [0, 1, 2, 3]
    point3f[] points = [(-1, -1, 0), (1, -1, 0), (1, 1, 0), (-1, 1, 0)]
    texCoord2f[] primvars:st = [(0, 0), (1, 0), (1, 1), (0, 1)] (interpolation = "vertex")
    rel material:binding = </Looks/Checked>
}}
def Scope "Looks" {{
    def Material "Checked" {{
        token outputs:arnold:surface.connect = </Looks/Checked/flat.outputs:surface>
        def Shader "flat" {{
            uniform token info:id = "arnold:flat"
            color3f inputs:color.connect = </Looks/Checked/checker.outputs:out>
            token outputs:surface
        }}
        def Shader "checker" {{
            uniform token info:id = "arnold:checkerboard"
            color3f inputs:color1 = (1, 0, 0)
            color3f inputs:color2 = (0, 0, 1)
            float inputs:u_offset = {u_offset}
            color3f outputs:out
        }}
    }}
}}
"#
        )
    };
    let dir = tempfile::tempdir().unwrap();
    let (red, blue) = (Vec3::new(1.0, 0.0, 0.0), Vec3::new(0.0, 0.0, 1.0));
    for (offset, left, right) in [(0.0, blue, red), (0.5, red, blue)] {
        let path = dir.path().join("checker.usda");
        std::fs::write(&path, usda(offset)).unwrap();
        let (mut desc, _) = read_imported(&path).unwrap().into_description();
        (desc.settings.width, desc.settings.height, desc.settings.spp) = (64, 48, 4);
        let film = render(&desc);
        for (p, want) in [(Vec3::new(-0.5, -0.5, 0.0), left), (Vec3::new(0.5, -0.5, 0.0), right)] {
            let (x, y) = project(&desc, p);
            let got = film.pixels[y as usize * 64 + x as usize].color;
            assert!((got - want).abs().max_element() < 1e-3, "offset {offset}, at {p}: {got}, want {want}");
        }
    }
}

/// Curves under an Arnold shader bound through `outputs:arnold:surface`: a `flat`
/// checkerboard textures each curve by its `primvars:st` (one UV per curve, as Arnold's
/// curve `uvs`), so the curve in the origin's cell is `color2` and the next `color1`,
/// exactly (unlit); a `standard_surface` gives the curves its base colour.
#[test]
fn usd_curves_take_their_arnold_surface_shader_textured_by_their_uvs() {
    let usda = |surface: &str| {
        format!(
            r#"#usda 1.0
def BasisCurves "Hair" (apiSchemas = ["MaterialBindingAPI"]) {{
    uniform token type = "linear"
    int[] curveVertexCounts = [2, 2]
    point3f[] points = [(-0.5, -1, 0), (-0.5, 1, 0), (0.5, -1, 0), (0.5, 1, 0)]
    float[] widths = [0.4] (interpolation = "constant")
    texCoord2f[] primvars:st = [(0.25, 0.25), (0.75, 0.25)] (interpolation = "uniform")
    rel material:binding = </Looks/Hair>
}}
def Scope "Looks" {{
    def Material "Hair" {{
        token outputs:arnold:surface.connect = </Looks/Hair/surface.outputs:surface>
        def Shader "surface" {{
            {surface}
            token outputs:surface
        }}
        def Shader "checker" {{
            uniform token info:id = "arnold:checkerboard"
            color3f inputs:color1 = (1, 0, 0)
            color3f inputs:color2 = (0, 0, 1)
            color3f outputs:out
        }}
    }}
}}
"#
        )
    };
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("curves.usda");
    std::fs::write(
        &path,
        usda("uniform token info:id = \"arnold:flat\"\n            color3f inputs:color.connect = </Looks/Hair/checker.outputs:out>"),
    )
    .unwrap();
    let (mut desc, _) = read_imported(&path).unwrap().into_description();
    (desc.settings.width, desc.settings.height, desc.settings.spp) = (64, 48, 4);
    let film = render(&desc);
    for (p, want) in [(Vec3::new(-0.5, 0.0, 0.0), Vec3::new(0.0, 0.0, 1.0)), (Vec3::new(0.5, 0.0, 0.0), Vec3::X)] {
        let (x, y) = project(&desc, p);
        let got = film.pixels[y as usize * 64 + x as usize].color;
        assert!((got - want).abs().max_element() < 1e-3, "at {p}: {got}, want {want}");
    }

    std::fs::write(
        &path,
        usda("uniform token info:id = \"arnold:standard_surface\"\n            color3f inputs:base_color = (0.2, 0.6, 0.3)\n            float inputs:specular = 0"),
    )
    .unwrap();
    let (desc, _) = read_imported(&path).unwrap().into_description();
    let material = match &desc.contents.hair[0].material {
        tress::scene::MaterialSource::Inline(m) => m.clone(),
        other => panic!("{other:?}"),
    };
    // Arnold's default `base` weight is 0.8.
    let want = Vec3::new(0.2, 0.6, 0.3) * 0.8;
    assert!(
        matches!(material, tress::shading::Material::Diffuse { color } if (color - want).abs().max_element() < 1e-6),
        "{material:?}"
    );
}

/// A plane facing a camera, a distant light of intensity 0 (so that no default light is
/// added) and `light` (USDA lines) on a small square a unit over the plane wound to face
/// it: the scene's mean pixel value and its warnings.
fn usd_mesh_light_scene(light: &str) -> (f32, Vec<String>) {
    let text = format!(
        "#usda 1.0\n\
         def Camera \"cam\" {{\n double3 xformOp:translate = (0, 0, 6)\n uniform token[] xformOpOrder = [\"xformOp:translate\"]\n\
          float focalLength = 35\n float horizontalAperture = 36\n float verticalAperture = 24\n}}\n\
         def DistantLight \"off\" {{\n float inputs:intensity = 0\n}}\n\
         def Mesh \"plane\" {{\n int[] faceVertexCounts = [4]\n int[] faceVertexIndices = [0, 1, 2, 3]\n\
          point3f[] points = [(-2, -2, 0), (2, -2, 0), (2, 2, 0), (-2, 2, 0)]\n}}\n\
         def Mesh \"lamp\" {{\n int[] faceVertexCounts = [4]\n int[] faceVertexIndices = [0, 1, 2, 3]\n\
          point3f[] points = [(-0.5, -0.5, 1), (-0.5, 0.5, 1), (0.5, 0.5, 1), (0.5, -0.5, 1)]\n {light}\n}}\n"
    );
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("lamp.usda");
    std::fs::write(&path, text).unwrap();
    let (mut desc, warnings) = read_imported(&path).unwrap().into_description();
    (desc.settings.width, desc.settings.height, desc.settings.spp) = (32, 24, 4);
    let film = render(&desc);
    let mean = film.pixels.iter().map(|p| p.color.element_sum()).sum::<f32>() / (3.0 * film.pixels.len() as f32);
    (mean, warnings)
}

#[test]
fn usd_arnold_mesh_lights_light_the_plane_under_them() {
    // Without the light the scene is unlit.
    let (dark, _) = usd_mesh_light_scene("");
    assert!(dark < 1e-4, "{dark}");
    // As a light (normalized: 2^2 × 1 over its 1 unit² area) it lights the plane; from
    // above, the camera sees only its unlit back, so the light is all on the plane.
    let (lit, warnings) = usd_mesh_light_scene(
        "bool primvars:arnold:light = 1\n float primvars:arnold:light:exposure = 2\n \
         string primvars:arnold:light:shaders = \"/tex\"",
    );
    assert!(lit > 0.01, "{lit}");
    assert!(
        warnings.iter().any(|w| w.contains("primvars:arnold:light:shaders") && w.contains("/lamp")),
        "{warnings:?}"
    );
    // Turned over (the other winding) and hidden from the camera by its Arnold visibility
    // (every ray but camera rays), it lights only the empty space above.
    let (away, _) = usd_mesh_light_scene(
        "bool primvars:arnold:light = 1\n uniform token orientation = \"leftHanded\"\n \
         uchar primvars:arnold:visibility = 254",
    );
    assert!(away < 1e-4, "{away}");
    // A NaN intensity is reported naming the prim, and nothing is lit.
    let (nan, warnings) =
        usd_mesh_light_scene("bool primvars:arnold:light = 1\n float primvars:arnold:light:intensity = nan");
    assert!(nan < 1e-4 && warnings.iter().any(|w| w.contains("/lamp") && w.contains("finite")), "{warnings:?}");
}

/// A stage as Blender's USD exporter writes one: a camera 5 units over a 4 × 4 plane
/// (Principled BSDF of base colour 0.5 as Blender's UsdPreviewSurface) looking straight
/// down, its apertures and focal length in tenths of a unit as Blender writes them (36 mm
/// sensor, 35 mm lens), and a sun of strength 3 shining straight down (written as
/// Blender writes it: a quarter of its strength, half its diameter). `doc` is the layer's
/// `doc` line. Rendered at 64 × 48: the film's linear values.
fn blender_sun_scene(doc: &str) -> tress::film::Film {
    let text = format!(
        r#"#usda 1.0
(
    defaultPrim = "root"
    {doc}
    metersPerUnit = 1
    upAxis = "Z"
)
def Xform "root"
{{
    def Xform "Camera"
    {{
        double3 xformOp:translate = (0, 0, 5)
        float3 xformOp:rotateXYZ = (0, -0, 0)
        uniform token[] xformOpOrder = ["xformOp:translate", "xformOp:rotateXYZ"]
        def Camera "Camera"
        {{
            float2 clippingRange = (0.1, 100)
            float focalLength = 0.35
            float horizontalAperture = 0.36
            token projection = "perspective"
            float verticalAperture = 0.27
        }}
    }}
    def Scope "_materials"
    {{
        def Material "Ground"
        {{
            token outputs:surface.connect = </root/_materials/Ground/Principled_BSDF.outputs:surface>
            def Shader "Principled_BSDF"
            {{
                uniform token info:id = "UsdPreviewSurface"
                color3f inputs:diffuseColor = (0.5, 0.5, 0.5)
                float inputs:roughness = 0.5
                float inputs:specular = 0.5
                token outputs:surface
            }}
        }}
    }}
    def Xform "Plane"
    {{
        def Mesh "Plane" (prepend apiSchemas = ["MaterialBindingAPI"])
        {{
            int[] faceVertexCounts = [4]
            int[] faceVertexIndices = [0, 1, 3, 2]
            rel material:binding = </root/_materials/Ground>
            point3f[] points = [(-2, -2, 0), (2, -2, 0), (-2, 2, 0), (2, 2, 0)]
        }}
    }}
    def Xform "Sun"
    {{
        float3 xformOp:rotateXYZ = (0, -0, 0)
        uniform token[] xformOpOrder = ["xformOp:rotateXYZ"]
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
    );
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("blender.usda");
    std::fs::write(&path, text).unwrap();
    let (mut desc, _) = read_imported(&path).unwrap().into_description();
    (desc.settings.width, desc.settings.height, desc.settings.spp) = (64, 48, 4);
    render(&desc)
}

#[test]
fn a_blender_sun_lights_a_lambert_plane_with_its_strength_framed_by_its_sensor() {
    let film = blender_sun_scene("doc = \"Blender v5.0.1\"");
    let at = |x: usize, y: usize| film.pixels[y * 64 + x].color;
    // Straight down on a Lambertian plane of albedo 0.5: radiance 0.5 × 3 / π.
    let expected = 0.5 * 3.0 / std::f32::consts::PI;
    let centre = at(32, 24);
    assert!((centre - Vec3::splat(expected)).abs().max_element() < 0.02 * expected, "{centre} vs {expected}");
    // The 36 mm sensor over the 35 mm lens sees 5 × 18 / 35 = 2.57 units either side at the
    // plane: its edges (±2) fall at 32 ± 32 × 2 / 2.57 = 32 ± 24.9 pixels.
    let lit = |x: usize| at(x, 24).x > 0.5 * expected;
    assert!(!lit(5) && lit(9) && lit(54) && !lit(58), "{:?}", (0..64).map(|x| at(x, 24).x).collect::<Vec<_>>());
    // Written by any other tool, the same sun is UsdLux's: its intensity is its irradiance.
    let other = blender_sun_scene("doc = \"another tool\"").pixels[24 * 64 + 32].color;
    assert!((other - Vec3::splat(expected / 4.0)).abs().max_element() < 0.02 * expected, "{other}");
}

/// An Arnold scene: a 2 × 2 Lambert quad (Kd 1) facing a camera 5 units away (horizontal
/// fov 60°, 40 × 30 pixels), under a distant light of intensity 2 and exposure 1 tilted
/// 60° from the quad's normal, and the lines `more`.
fn ass_quad_scene(more: &str) -> String {
    format!(
        "options\n{{\n xres 40\n yres 30\n AA_samples 2\n camera \"cam\"\n}}\n\
         persp_camera\n{{\n name cam\n fov 60\n matrix\n 1 0 0 0\n 0 1 0 0\n 0 0 1 0\n 0 0 5 1\n}}\n\
         distant_light\n{{\n name sun\n intensity 2\n exposure 1\n matrix\n 1 0 0 0\n 0 0.5 -0.8660254 0\n 0 0.8660254 0.5 0\n 0 0 0 1\n}}\n\
         lambert\n{{\n name white\n Kd 1\n}}\n\
         polymesh\n{{\n name quad\n nsides 1 1 UINT 4\n vidxs 4 1 UINT 0 1 2 3\n\
          vlist 4 1 VECTOR -1 -1 0 1 -1 0 1 1 0 -1 1 0\n shader \"white\"\n}}\n{more}"
    )
}

#[test]
fn an_arnold_scene_frames_its_quad_and_lights_it_as_arnold_does() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("quad.ass");
    std::fs::write(&path, ass_quad_scene("")).unwrap();
    let (desc, warnings) = read_imported(&path).unwrap().into_description();
    assert!(!warnings.iter().any(|w| w.contains("no lights") || w.contains("no camera")), "{warnings:?}");
    assert_eq!((desc.settings.width, desc.settings.height, desc.settings.spp), (40, 30, 4));
    let film = render(&desc);
    let at = |x: u32, y: u32| film.pixels[(y * film.width + x) as usize].color;
    // The quad's edges at x = ±1 land at 20 ± 20 / (5 tan 30°) = 13.07 and 26.93 pixels,
    // y = ±1 at 15 ∓ 15 / (5 tan 30° × 0.75) = 8.07 and 21.93.
    for (x, y) in [(12, 15), (27, 15), (20, 7), (20, 22)] {
        assert!(at(x, y).max_element() < 1e-6, "({x}, {y}) {}", at(x, y));
    }
    // Irradiance 2 × 2¹ × cos 60° = 2 on a white Lambert surface: radiance 2 / π.
    let expected = 2.0 / std::f32::consts::PI;
    for (x, y) in [(14, 15), (25, 15), (20, 9), (20, 20), (20, 15)] {
        let c = at(x, y);
        assert!((c - Vec3::splat(expected)).abs().max_element() < 1e-3, "({x}, {y}) {c} vs {expected}");
    }
    // The same file gzipped reads the same.
    let gz = dir.path().join("quad.ass.gz");
    let mut e = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::default());
    std::io::Write::write_all(&mut e, ass_quad_scene("").as_bytes()).unwrap();
    std::fs::write(&gz, e.finish().unwrap()).unwrap();
    let (packed, _) = read_imported(&gz).unwrap().into_description();
    assert_eq!(format!("{:?}", packed.contents.meshes), format!("{:?}", desc.contents.meshes));
    assert_eq!(packed.camera, desc.camera);
}

#[test]
fn arnold_usd_procedurals_pull_in_their_file_placed_by_their_matrix_and_cycles_are_errors() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("ball.usda"), "#usda 1.0\ndef Sphere \"ball\" {\n double radius = 0.5\n}\n")
        .unwrap();
    let path = dir.path().join("scene.ass");
    std::fs::write(
        &path,
        ass_quad_scene("usd\n{\n name proc\n filename \"ball.usda\"\n matrix 1 0 0 0 0 1 0 0 0 0 1 0 3 0 0 1\n}\n"),
    )
    .unwrap();
    let imported = read_imported(&path).unwrap();
    assert_eq!(imported.contents.meshes.len(), 2);
    let entry = &imported.contents.meshes[1];
    let tress::scene::MeshSource::Inline(ball) = &entry.source else { panic!("not inline") };
    let b = ball.bounds_under(&entry.transform);
    let centre = Vec3::from(b.center());
    assert!((centre - Vec3::new(3.0, 0.0, 0.0)).length() < 1e-3, "{centre}");
    // An .ass procedural pulling in a file that pulls it back in.
    std::fs::write(dir.path().join("a.ass"), "procedural\n{\n name pa\n filename \"b.ass\"\n}\n").unwrap();
    std::fs::write(dir.path().join("b.ass"), "procedural\n{\n name pb\n filename \"a.ass\"\n}\n").unwrap();
    let e = read_imported(&dir.path().join("a.ass")).unwrap_err().to_string();
    assert!(e.contains("b.ass") && e.contains("already being read") && e.contains("a.ass"), "{e}");
}

/// A `usd` procedural reads its stage as Arnold does: in the stage's own axes (a Z-up
/// stage is not turned to Y up, so the `.ass` camera sees it where Arnold's does), without
/// the prims its `disable` operators select, directly or through a `merge`.
#[test]
fn arnold_usd_procedurals_keep_the_stage_axes_and_apply_disable_operators() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("z_up.usda"),
        "#usda 1.0\n(\n upAxis = \"Z\"\n)\n\
         def Xform \"W\" {\n def Sphere \"Kept\" { double3 xformOp:translate = (0, 0, 5)\n uniform token[] xformOpOrder = [\"xformOp:translate\"] }\n\
         def Sphere \"Door1\" {}\n def Sphere \"Door2\" {}\n def Sphere \"Shelf\" {}\n}\n",
    )
    .unwrap();
    let path = dir.path().join("scene.ass");
    let scene = |operator: &str, nodes: &str| {
        let text = format!("usd\n{{\n name proc\n filename \"z_up.usda\"\n {operator}\n}}\n{nodes}");
        std::fs::write(&path, text).unwrap();
        read_imported(&path).unwrap()
    };
    let all = scene("", "");
    assert_eq!(all.contents.meshes.len(), 4);
    let entry = &all.contents.meshes[0];
    let tress::scene::MeshSource::Inline(ball) = &entry.source else { panic!("not inline") };
    let centre = Vec3::from(ball.bounds_under(&entry.transform).center());
    assert!((centre - Vec3::new(0.0, 0.0, 5.0)).length() < 1e-3, "{centre}");
    let some = scene(
        "operator \"both\"",
        "merge\n{\n name both\n inputs 2 1 NODE doors off\n}\n\
         disable\n{\n name doors\n selection \"/W/Door*\"\n}\n\
         disable\n{\n name off\n selection \"/W/Shelf\"\n enable off\n}\n",
    );
    assert_eq!(some.contents.meshes.len(), 2, "{:?}", some.warnings);
    assert!(some.warnings.iter().all(|w| !w.contains("disable") && !w.contains("merge")), "{:?}", some.warnings);
}

#[test]
fn an_arnold_procedurals_shader_draws_every_surface_of_its_file() {
    let dir = tempfile::tempdir().unwrap();
    let quad = "polymesh\n{\n name q\n nsides 1 1 UINT 4\n vidxs 4 1 UINT 0 1 2 3\n \
                vlist 4 1 VECTOR 0 0 0 1 0 0 1 1 0 0 1 0\n shader \"own\"\n}\n\
                lambert\n{\n name own\n Kd_color 0 0 1\n}\n";
    std::fs::write(dir.path().join("inner.ass"), quad).unwrap();
    let path = dir.path().join("scene.ass");
    std::fs::write(
        &path,
        "procedural\n{\n name plain\n filename \"inner.ass\"\n}\n\
         procedural\n{\n name over\n filename \"inner.ass\"\n shader \"yellow\"\n}\n\
         lambert\n{\n name yellow\n Kd_color 1 1 0\n}\n",
    )
    .unwrap();
    let imported = read_imported(&path).unwrap();
    let colours: Vec<String> = imported.contents.meshes.iter().map(|m| format!("{:?}", m.material)).collect();
    assert_eq!(colours.len(), 2);
    assert_ne!(colours[0], colours[1], "the procedural's shader replaces the file's own");
    let own = format!(
        "{:?}",
        tress::scene::MaterialSource::from(tress::shading::Material::Diffuse { color: Vec3::new(0.0, 0.0, 0.7) })
    );
    let yellow = format!(
        "{:?}",
        tress::scene::MaterialSource::from(tress::shading::Material::Diffuse { color: Vec3::new(0.7, 0.7, 0.0) })
    );
    assert_eq!((&colours[0], &colours[1]), (&own, &yellow));
    assert!(imported.warnings.iter().all(|w| !w.contains("shader")), "{:?}", imported.warnings);
}
