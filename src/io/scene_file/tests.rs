//! The scene file's reading: defaults, every table, errors naming the key, animation.

use super::schema::{ScaleToml, TransformToml};
use super::*;
use crate::accel::lod::LodParams;
use crate::film::PixelFilter;
use crate::fur::{AttractorModel, FurDescription, Placement as FurPlacement};
use crate::hair_system::{HairColors, HairSystem, Interp, NoiseMethod, Placement};
use crate::light::Light;
use crate::scene::{GuideSource, LightSource, MaterialSource};
use crate::shading::hair_bsdf::{Absorption, HairParams};
use crate::shading::Material;
use glam::Vec3;

const MINIMAL: &str = r#"
[camera]
eye = [0.0, 1.6, 3.2]
target = [0.0, 0.0, 0.0]
"#;

fn parse(extra: &str) -> Result<Description, SceneFileError> {
    scene(&format!("{MINIMAL}{extra}"), Path::new("dir/test.toml"))
}

/// The description of a scene that is not animated.
fn scene(text: &str, path: &Path) -> Result<Description, SceneFileError> {
    super::parse(text, path, None).map(|(d, _)| d)
}

#[test]
fn reads_the_issue_example_with_defaults() {
    let d = parse(
        r#"
[render]
resolution = [320, 240]
spp = 4
[[light]]
type = "distant"
direction = [0.45, 0.8, 0.4]
irradiance = [3.0, 3.0, 3.0]
[[mesh]]
file = "torus.obj"
material = { type = "diffuse", color = [0.5, 0.5, 0.5] }
[[hair]]
file = "hairy_torus.hair"
material = { type = "tube", diffuse = [0.35, 0.2, 0.1], specular = [0.3, 0.3, 0.3], specular_power = 40.0 }
"#,
    )
    .unwrap();
    assert_eq!((d.settings.width, d.settings.height, d.settings.spp), (320, 240, 4));
    assert_eq!(d.camera.vfov, 35.0);
    assert_eq!(d.contents.meshes[0].source, MeshSource::File(PathBuf::from("dir/torus.obj")));
    assert_eq!(d.contents.hair[0].source, HairSource::File(PathBuf::from("dir/hairy_torus.hair")));
    match &d.contents.hair[0].material {
        MaterialSource::Inline(Material::Tube(t)) => assert_eq!(t.ambient, t.diffuse),
        m => panic!("{m:?}"),
    }
    match d.contents.lights[0] {
        LightSource::Inline(Light::Distant { direction, .. }) => assert!((direction.length() - 1.0).abs() < 1e-6),
        ref l => panic!("{l:?}"),
    }
}

#[test]
fn unknown_key_is_an_error_naming_file_and_key() {
    let e = parse("[render]\nsppp = 4\n").unwrap_err().to_string();
    assert!(e.contains("dir/test.toml") && e.contains("sppp"), "{e}");
    let e = parse("[[light]]\ntype = \"distant\"\ndirection = [0,1,0]\nirradiance = [1,1,1]\ncolour = 1\n")
        .unwrap_err()
        .to_string();
    assert!(e.contains("colour"), "{e}");
}

#[test]
fn wrong_type_and_missing_field_are_errors() {
    let e = parse("[render]\nspp = \"many\"\n").unwrap_err().to_string();
    assert!(e.contains("dir/test.toml") && e.contains("spp"), "{e}");
    let e = scene("[camera]\neye = [0, 0, 1]\n", Path::new("s.toml")).unwrap_err().to_string();
    assert!(e.contains("camera") && e.contains("target"), "{e}");
    let e = parse("[[light]]\ntype = \"laser\"\n").unwrap_err().to_string();
    assert!(e.contains("laser"), "{e}");
}

/// Quad and sphere lights take a `camera_visibility` too (1 when not given).
#[test]
fn area_lights_take_a_camera_visibility() {
    let light = |body: &str| {
        let d = parse(&format!("[[light]]\n{body}\n"));
        d.map(|d| match &d.contents.lights[..] {
            [LightSource::Inline(l)] => l.camera_visibility(),
            other => panic!("{other:?}"),
        })
    };
    let quad = "type = \"quad\"\ncorner = [0, 1, 0]\nedge_u = [1, 0, 0]\nedge_v = [0, 0, 1]\nradiance = [1, 1, 1]";
    let sphere = "type = \"sphere\"\ncenter = [0, 1, 0]\nradius = 0.5\nradiance = [1, 1, 1]";
    assert_eq!(light(quad).unwrap(), 1.0);
    assert_eq!(light(&format!("{quad}\ncamera_visibility = 0")).unwrap(), 0.0);
    assert_eq!(light(&format!("{sphere}\ncamera_visibility = 0.5")).unwrap(), 0.5);
    let e = light(&format!("{sphere}\ncamera_visibility = -1")).unwrap_err().to_string();
    assert!(e.contains("light 1") && e.contains("camera_visibility"), "{e}");
}

/// `camera_visibility` weighs what camera rays see of an environment light, constant or
/// mapped (1 when not given); a negative weight is an error naming the key.
#[test]
fn environment_lights_take_a_camera_visibility() {
    let env = |extra: &str| parse(&format!("[[light]]\ntype = \"environment\"\n{extra}\n"));
    let lights = |d: Description| d.contents.lights;
    let constant = |w| vec![Light::Environment { radiance: Vec3::splat(0.5), camera_visibility: w }.into()];
    assert_eq!(lights(env("radiance = [0.5, 0.5, 0.5]").unwrap()), constant(1.0));
    assert_eq!(lights(env("radiance = [0.5, 0.5, 0.5]\ncamera_visibility = 0").unwrap()), constant(0.0));
    let map = lights(env("file = \"sky.exr\"\ncamera_visibility = 0.25").unwrap());
    let [LightSource::File(f)] = &map[..] else { panic!("{map:?}") };
    assert_eq!(f.placement.camera_visibility(), 0.25);
    let [LightSource::File(f)] = &lights(env("file = \"sky.exr\"").unwrap())[..] else { panic!() };
    assert_eq!(f.placement.camera_visibility(), 1.0);
    let e = env("radiance = [1, 1, 1]\ncamera_visibility = -1").unwrap_err().to_string();
    assert!(e.contains("light 1") && e.contains("camera_visibility"), "{e}");
}

#[test]
fn out_of_range_values_are_errors() {
    let e = parse("[render]\nresolution = [0, 10]\n").unwrap_err().to_string();
    assert!(e.contains("resolution"), "{e}");
    let e = parse("[[light]]\ntype = \"point\"\nposition = [0,1,0]\nintensity = [-1,1,1]\n").unwrap_err().to_string();
    assert!(e.contains("light 1") && e.contains("intensity"), "{e}");
    let e = parse("[[mesh]]\nshape = { type = \"sphere\" }\nfile = \"a.obj\"\nmaterial = { type = \"mirror\" }\n")
        .unwrap_err()
        .to_string();
    assert!(e.contains("mesh 1") && e.contains("exactly one"), "{e}");
    // TOML has inf and nan literals; they must not reach the geometry.
    let e = parse("[[mesh]]\nshape = { type = \"sphere\", radius = nan }\nmaterial = { type = \"mirror\" }\n")
        .unwrap_err()
        .to_string();
    assert!(e.contains("radius"), "{e}");
    let e = scene("[camera]\neye = [inf, 0, 0]\ntarget = [0, 0, 0]\n", Path::new("s.toml")).unwrap_err();
    assert!(e.to_string().contains("camera"), "{e}");
}

const HAIR_SYSTEM: &str = r#"
[[mesh]]
shape = { type = "sphere" }
material = { type = "diffuse", color = [0.5, 0.5, 0.5] }
[[hair_system]]
follicles = { mesh = 1, placement = "grid", u = 12, v = 6, points_per_hair = 8, length = 1.5 }
hairs_per_clump = 20
clump_width_scale = [[0.0, 1.0, "linear"], [1.0, 0.2]]
hair_width_scale = [{ position = 0.8, value = 1.0, interp = "smooth" }, { position = 1.0, value = 0.2 }]
clump_curl = 0.6
hair_color = [0.5, 0.3, 0.1]
hair_color_scale = [[0.0, [0.5, 0.5, 0.5], "spline"], [1.0, [1.0, 1.0, 1.0], "spline"]]
noise_method = "clump_uv"
seed = 7
"#;

#[test]
fn reads_a_hair_system_with_follicles_and_ramps() {
    let d = parse(HAIR_SYSTEM).unwrap();
    let h = &d.contents.hair_systems[0];
    let GuideSource::Follicles { mesh, params } = &h.guides else { panic!("{:?}", h.guides) };
    assert_eq!((*mesh, params.placement, params.points_per_hair), (0, Placement::Grid { u: 12, v: 6 }, 8));
    assert_eq!((params.length, h.seed, h.system.hairs_per_clump), (1.5, 7, 20));
    assert_eq!(h.system.clump_width, HairSystem::default().clump_width);
    assert!((h.system.clump_width_scale.eval(0.5) - 0.6).abs() < 1e-6);
    assert_eq!(h.system.hair_width_scale.keys()[0].interp, Interp::Smooth);
    assert_eq!(h.system.hair_width_scale.keys()[1].interp, Interp::Linear);
    assert_eq!(h.system.clump_curl.eval(0.3), 0.6);
    assert_eq!(h.system.hair_color_scale.eval(1.0), Vec3::ONE);
    assert_eq!(h.system.noise_method, NoiseMethod::ClumpUv);
    // No material given: tube shading from the hair-system attributes.
    assert_eq!(h.material, Material::Tube(h.system.tube()).into());
    let d = parse(&format!("{HAIR_SYSTEM}[[hair_system]]\nfile = \"g.hair\"\nfollicles = {{ mesh = 1 }}\n"));
    assert!(d.unwrap_err().to_string().contains("hair_system 2: give exactly one"));
    let d = parse("[[hair_system]]\nfile = \"g.hair\"\ncolors = \"guides\"\ntransform = { scale = 2.0 }\n").unwrap();
    assert_eq!(d.contents.hair_systems[0].guides, GuideSource::File(PathBuf::from("dir/g.hair")));
    assert_eq!(d.contents.hair_systems[0].colors, HairColors::Guides);
}

#[test]
fn bad_hair_system_values_name_the_entry_and_attribute() {
    for (bad, words) in [
        ("thinning = nan", &["hair_system 1", "thinning"][..]),
        ("clump_width = -1.0", &["hair_system 1", "clump_width"]),
        ("hairs_per_clump = 0", &["hair_system 1", "hairs_per_clump"]),
        ("clump_flatness = [[0.0, 0.0], [1.5, 1.0]]", &["clump_flatness", "key 2", "position"]),
        ("clump_curl = [[0.0, 2.0]]", &["clump_curl", "key 1"]),
        ("hair_width_scale = [[0.0, 1.0, \"cubic\"]]", &["hair_width_scale", "cubic"]),
        ("hair_color = [0.1, inf, 0.1]", &["hair_color"]),
        ("noise_method = \"perlin\"", &["noise_method", "perlin"]),
        ("colors = \"rainbow\"", &["colors", "rainbow"]),
        ("transform = { scale = 2.0 }", &["transform"]),
        ("hairz = 1", &["hairz"]),
    ] {
        let minimal = &HAIR_SYSTEM[..HAIR_SYSTEM.find("hairs_per_clump").unwrap()];
        let e = parse(&format!("{minimal}{bad}\n")).unwrap_err().to_string();
        assert!(e.contains("dir/test.toml"), "{e}");
        for w in words {
            assert!(e.contains(w), "`{bad}`: {e}");
        }
    }
    for (follicles, words) in [
        ("{ mesh = 2 }", &["mesh = 2", "names no"][..]),
        ("{ mesh = 1, placement = \"random\" }", &["count"]),
        ("{ mesh = 1, placement = \"grid\", count = 4 }", &["count"]),
        ("{ mesh = 1, placement = \"spiral\" }", &["spiral"]),
        ("{ mesh = 1, length = nan }", &["follicles", "length"]),
        ("{ mesh = 1, u = 0 }", &["follicles", "count"]),
        ("{ mesh = 1, uv_range = [[0.5, 0.0], [0.2, 1.0]] }", &["uv_range"]),
        ("{ mesh = 1, gravity = [0.0, 0.0, 0.0] }", &["follicles", "gravity"]),
    ] {
        let text = HAIR_SYSTEM
            .replace("{ mesh = 1, placement = \"grid\", u = 12, v = 6, points_per_hair = 8, length = 1.5 }", follicles);
        let e = parse(&text).unwrap_err().to_string();
        assert!(e.contains("hair_system 1"), "{e}");
        for w in words {
            assert!(e.contains(w), "`{follicles}`: {e}");
        }
    }
}

#[test]
fn lod_tables_take_defaults_and_reject_bad_values() {
    let minimal = &HAIR_SYSTEM[..HAIR_SYSTEM.find("hairs_per_clump").unwrap()];
    let d = parse(&format!("{minimal}lod = {{ levels = 4, start = 8 }}\n[render]\nlod = false\n")).unwrap();
    assert_eq!(d.contents.hair_systems[0].lod, Some(LodParams { levels: 4, start: 8.0, ..Default::default() }));
    assert!(!d.settings.lod);
    let d = parse(&format!("{minimal}lod = {{ spread = 4, smooth = true }}\n")).unwrap();
    assert_eq!(d.contents.hair_systems[0].lod, Some(LodParams { spread: 4.0, smooth: true, ..Default::default() }));
    assert!(parse(minimal).unwrap().settings.lod && parse(minimal).unwrap().contents.hair_systems[0].lod.is_none());
    for (bad, key) in [
        ("decimation = 1.0", "decimation"),
        ("levels = 0", "levels"),
        ("levels = 17", "levels"),
        ("compensation = nan", "compensation"),
        ("start = 0.5", "start"),
        ("decimate = 2.0", "decimate"),
    ] {
        let e = parse(&format!("{minimal}lod = {{ {bad} }}\n")).unwrap_err().to_string();
        assert!(e.contains("dir/test.toml") && e.contains(key), "{bad}: {e}");
    }
    let e = parse("[[hair]]\nfile = \"h.hair\"\nmaterial = { type = \"mirror\" }\nlod = { levels = 99 }\n");
    assert!(e.unwrap_err().to_string().contains("hair 1: lod `levels`"));
}

#[test]
fn every_material_has_defaults() {
    let material = |kind: &str| {
        let d = parse(&format!("[[hair]]\nfile = \"h.hair\"\nmaterial = {{ type = \"{kind}\" }}\n"));
        match d.unwrap_or_else(|e| panic!("{kind}: {e}")).contents.hair[0].material.clone() {
            MaterialSource::Inline(m) => m,
            m => panic!("{kind}: {m:?}"),
        }
    };
    let grey = Material::DEFAULT_COLOR;
    assert_eq!(material("tube"), Material::Tube(crate::shading::tube::Tube::default()));
    assert_eq!(material("diffuse"), Material::Diffuse { color: grey });
    assert_eq!(
        material("phong"),
        Material::Phong {
            diffuse: grey,
            specular: Material::DEFAULT_PHONG_SPECULAR,
            exponent: Material::DEFAULT_PHONG_EXPONENT
        }
    );
    assert_eq!(material("mirror"), Material::Mirror { color: Vec3::ONE });
    assert_eq!(material("glass"), Material::Glass { ior: Material::DEFAULT_IOR, color: Vec3::ONE });
    assert_eq!(material("unlit"), Material::Unlit { color: Vec3::ONE });
    // An unlit colour is a radiance: above 1 is kept, negative refused.
    let unlit =
        |c: &str| parse(&format!("[[hair]]\nfile = \"h.hair\"\nmaterial = {{ type = \"unlit\", color = {c} }}\n"));
    let MaterialSource::Inline(m) = &unlit("[4.0, 0.5, 0.0]").unwrap().contents.hair[0].material else { panic!() };
    assert_eq!(*m, Material::Unlit { color: Vec3::new(4.0, 0.5, 0.0) });
    let Err(e) = unlit("[-1.0, 0.5, 0.0]") else { panic!("a negative unlit colour is accepted") };
    assert!(e.to_string().contains("`color` must be finite and not negative"), "{e}");
    let Material::Physical(p) = material("physical") else { panic!("physical") };
    assert_eq!(*p.params(), HairParams::default());
    // A tube's ambient colour follows its diffuse colour unless given.
    let d = parse("[[hair]]\nfile = \"h.hair\"\nmaterial = { type = \"tube\", diffuse = [0.2, 0.1, 0.05] }\n");
    let MaterialSource::Inline(Material::Tube(t)) = &d.unwrap().contents.hair[0].material else { panic!("tube") };
    assert_eq!((t.ambient, t.diffuse), (Vec3::new(0.2, 0.1, 0.05), Vec3::new(0.2, 0.1, 0.05)));
    assert_eq!((t.specular, t.specular_power), (Vec3::splat(0.3), 40.0));
}

#[test]
fn physical_hair_material_takes_one_colour_source() {
    let hair = |m: &str| parse(&format!("[[hair]]\nfile = \"h.hair\"\nmaterial = {{ type = \"physical\", {m} }}\n"));
    let params = |m: &str| match &hair(m).unwrap().contents.hair[0].material {
        MaterialSource::Inline(Material::Physical(p)) => *p.params(),
        m => panic!("{m:?}"),
    };
    let p = params("eumelanin = 1.3");
    assert_eq!(p, HairParams::default());
    assert_eq!(p.beta_m, 0.3);
    assert_eq!(p.alpha_degrees, 2.0);
    assert_eq!(p.eta, 1.55);
    let p = params("pheomelanin = 0.5, beta_m = 0.1, beta_n = 0.7, alpha = -3.0, eta = 1.6");
    assert_eq!(p.absorption, Absorption::Melanin { eumelanin: 0.0, pheomelanin: 0.5 });
    assert_eq!((p.beta_m, p.beta_n, p.alpha_degrees, p.eta), (0.1, 0.7, -3.0, 1.6));
    assert_eq!(params("color = [0.8, 0.6, 0.3]").absorption, Absorption::Color(Vec3::new(0.8, 0.6, 0.3)));
    assert_eq!(params("from_file = true").absorption, Absorption::FromStrands);
    assert_eq!(params("from_file = false"), HairParams::default(), "no colour source: the default melanin");
    for bad in ["eumelanin = 1.0, color = [0.5, 0.5, 0.5]", "color = [0.5, 0.5, 0.5], from_file = true"] {
        let e = hair(bad).unwrap_err().to_string();
        assert!(e.contains("hair 1") && e.contains("at most one"), "{bad}: {e}");
    }
    for (bad, key) in [
        ("eumelanin = -1.0", "eumelanin"),
        ("color = [2.0, 0.5, 0.5]", "color"),
        ("eumelanin = 1.0, beta_m = 0.0", "beta_m"),
        ("eumelanin = 1.0, eta = 0.5", "eta"),
        ("eumelanin = 1.0, alpha = 60.0", "alpha"),
    ] {
        let e = hair(bad).unwrap_err().to_string();
        assert!(e.contains("hair 1") && e.contains(key), "{bad}: {e}");
    }
    let e = hair("eumelanin = 1.0, roughness = 0.3").unwrap_err().to_string();
    assert!(e.contains("roughness"), "{e}");
}

const MESH: &str = "[[mesh]]\nshape = { type = \"torus\" }\nmaterial = { type = \"diffuse\", color = [1, 1, 1] }\n";

#[test]
fn fur_entries_take_a_preset_overrides_maps_and_guides() {
    use crate::fur::{presets::preset, MapSource, Scalar};
    let d = parse(&format!(
            "{MESH}{MESH}[[fur]]\nmesh = 2\npreset = \"Squirrel\"\nseed = 9\nplacement = \"uv\"\nlength = 0.5\n\
             dbw = 0.02\nlength_map = \"len.png\"\nguides = \"g.hair\"\nattractors = {{ model = \"global\", radius = 2.0 }}\n"
        ))
        .unwrap();
    let f = &d.contents.fur[0];
    assert_eq!((f.mesh, f.seed, f.placement), (1, 9, FurPlacement::Uv));
    let mut expected = preset("Squirrel").unwrap();
    expected[Scalar::Length].value = 0.5;
    expected[Scalar::BaseWidth].value = 0.02;
    expected[Scalar::Length].map = Some(MapSource::Image(PathBuf::from("dir/len.png")));
    assert_eq!(f.description, expected);
    let (source, a) = f.guides.as_ref().unwrap();
    assert_eq!(source, &HairSource::File(PathBuf::from("dir/g.hair")));
    assert_eq!((a.model, a.radius, a.power), (AttractorModel::Global, 2.0, 1.0));
    // Without a preset: Maya's node defaults.
    let d = parse(&format!("{MESH}[[fur]]\nmesh = 1\n")).unwrap();
    assert_eq!(d.contents.fur[0].description, FurDescription::default());
}

#[test]
fn bad_fur_entries_are_errors_naming_the_entry_and_key() {
    for (entry, needles) in [
        ("mesh = 2", &["fur 1", "mesh"][..]),
        ("mesh = 0", &["fur 1", "mesh"]),
        ("mesh = 1\ndensity = -5", &["fur 1", "density", "-5"]),
        ("mesh = 1\nlength = nan", &["fur 1", "length", "finite"]),
        ("mesh = 1\nbaldness = 2", &["fur 1", "baldness", "0 to 1"]),
        ("mesh = 1\nfluffiness = 2", &["fur 1", "fluffiness"]),
        ("mesh = 1\npreset = \"Chinchilla\"", &["fur 1", "Chinchilla", "Duckling"]),
        ("mesh = 1\nattractors = { radius = 1.0 }", &["fur 1", "guides"]),
        ("mesh = 1\nguides = \"g.hair\"\nattractors = { radius = -1.0 }", &["fur 1", "radius"]),
        ("mesh = 1\nguides = \"g.hair\"\nattractors = { pull = 1.0 }", &["pull"]),
        ("mesh = 1\nplacement = \"random\"", &["random"]),
    ] {
        let e = parse(&format!("{MESH}[[fur]]\n{entry}\n")).unwrap_err().to_string();
        assert!(e.contains("dir/test.toml"), "{e}");
        for n in needles {
            assert!(e.contains(n), "{entry}: `{e}` lacks `{n}`");
        }
    }
}

const KEYS: &str = r#"
[camera]
vfov = 40.0
[[camera.key]]
frame = 10
eye = [0.0, 0.0, 10.0]
target = [0.0, 0.0, 0.0]
[[camera.key]]
frame = 20
eye = [10.0, 0.0, 0.0]
target = [0.0, 2.0, 0.0]
vfov = 20.0
[[hair]]
file = "sim/hair.####.hair"
material = { type = "diffuse", color = [1, 1, 1] }
[[mesh]]
file = "ground_#.obj"
material = { type = "diffuse", color = [1, 1, 1] }
"#;

#[test]
fn camera_keys_interpolate_and_frame_patterns_substitute() {
    let path = Path::new("dir/anim.toml");
    let at = |f| super::parse(KEYS, path, Some(f)).unwrap().0;
    let d = at(15);
    assert_eq!(d.camera.eye, Vec3::new(5.0, 0.0, 5.0));
    assert_eq!(d.camera.target, Vec3::new(0.0, 1.0, 0.0));
    assert_eq!(d.camera.vfov, 30.0);
    assert_eq!(d.contents.hair[0].source, HairSource::File(PathBuf::from("dir/sim/hair.0015.hair")));
    assert_eq!(d.contents.meshes[0].source, MeshSource::File(PathBuf::from("dir/ground_15.obj")));
    // Held before the first key and after the last.
    assert_eq!((at(0).camera.eye, at(0).camera.vfov), (Vec3::new(0.0, 0.0, 10.0), 40.0));
    assert_eq!((at(99).camera.eye, at(99).camera.vfov), (Vec3::new(10.0, 0.0, 0.0), 20.0));
    assert_eq!(at(12345).contents.hair[0].source, HairSource::File(PathBuf::from("dir/sim/hair.12345.hair")));
    let e = scene(KEYS, path).unwrap_err().to_string();
    assert!(e.contains("dir/anim.toml") && e.contains("--frame"), "{e}");
    // A still scene ignores the frame.
    assert_eq!(super::parse(MINIMAL, path, Some(3)).unwrap().0, scene(MINIMAL, path).unwrap());
    // Frames outside the keys, and frames of a still scene, warn; frames between keys do not.
    let warnings = |text, f| super::parse(text, path, Some(f)).unwrap().1;
    assert!(warnings(KEYS, 15).is_empty());
    for f in [0, 99] {
        let w = warnings(KEYS, f);
        assert!(w.len() == 1 && w[0].contains(&format!("frame {f} is outside the camera keys")), "{w:?}");
    }
    assert!(warnings(MINIMAL, 3)[0].contains("no camera keys"));
    assert!(super::parse(MINIMAL, path, None).unwrap().1.is_empty());
}

#[test]
fn bad_camera_paths_are_errors() {
    let path = Path::new("a.toml");
    let both = KEYS.replace("vfov = 40.0", "vfov = 40.0\neye = [1, 1, 1]");
    assert!(super::parse(&both, path, Some(1)).unwrap_err().to_string().contains("not both"));
    let order = KEYS.replace("frame = 20", "frame = 10");
    assert!(super::parse(&order, path, Some(1)).unwrap_err().to_string().contains("must increase"));
    let e = super::parse("[camera]\nvfov = 3.0\n", path, None).unwrap_err().to_string();
    assert!(e.contains("give `eye` and `target`"), "{e}");
    let nan = KEYS.replace("target = [0.0, 2.0, 0.0]", "target = [0.0, nan, 0.0]");
    assert!(super::parse(&nan, path, Some(15)).unwrap_err().to_string().contains("camera"));
}

#[test]
fn transforms_compose_scale_rotate_translate() {
    let t = transform(&TransformToml {
        translate: Some([1.0, 0.0, 0.0]),
        rotate: Some([0.0, 1.0, 0.0, 90.0]),
        scale: Some(ScaleToml::Uniform(2.0)),
    })
    .unwrap();
    let p = t.transform_point3(Vec3::X);
    assert!((p - Vec3::new(1.0, 0.0, -2.0)).length() < 1e-5, "{p}");
}

#[test]
fn reads_the_pixel_filter() {
    assert_eq!(parse("").unwrap().settings.filter, PixelFilter::Box);
    assert_eq!(parse("[render]\nfilter = \"box\"\n").unwrap().settings.filter, PixelFilter::Box);
    assert_eq!(parse("[render]\nfilter = \"gaussian\"\n").unwrap().settings.filter, PixelFilter::gaussian(1.5));
    let d = parse("[render]\nfilter = { type = \"gaussian\", radius = 2.0, sigma = 0.8 }\n").unwrap();
    assert_eq!(d.settings.filter, PixelFilter::Gaussian { radius: 2.0, sigma: 0.8 });
    for (bad, names) in [
        ("filter = \"mitchell\"", "mitchell"),
        ("filter = { type = \"gaussian\", radius = -1.0 }", "radius"),
        ("filter = { type = \"box\", radius = 2.0 }", "box"),
    ] {
        let e = parse(&format!("[render]\n{bad}\n")).unwrap_err().to_string();
        assert!(e.contains("dir/test.toml") && e.contains(names), "{e}");
    }
}

#[test]
fn entries_and_imports_take_visibility_keys() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("tri.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").unwrap();
    let text = format!(
        r#"{MINIMAL}
[[mesh]]
shape = {{ type = "sphere", radius = 1.0 }}
material = {{ type = "diffuse", color = [0.5, 0.5, 0.5] }}
camera_visible = false
[[mesh]]
shape = {{ type = "plane", size = 1.0 }}
material = {{ type = "diffuse", color = [0.5, 0.5, 0.5] }}
[[hair]]
file = "h.hair"
material = {{ type = "tube" }}
casts_shadows = false
matte = true
[[fur]]
mesh = 2
matte = true
[[hair_system]]
follicles = {{ mesh = 2 }}
camera_visible = false
[[import]]
file = "tri.obj"
casts_shadows = false
"#
    );
    let d = scene(&text, &dir.path().join("s.toml")).unwrap();
    let v = |camera, shadows, matte| Visibility { camera, shadows, matte };
    let c = &d.contents;
    assert_eq!(
        c.meshes.iter().map(|m| m.visibility).collect::<Vec<_>>(),
        [v(false, true, false), v(true, true, false), v(true, false, false)]
    );
    assert_eq!(c.hair[0].visibility, v(true, false, true));
    assert_eq!(c.fur[0].visibility, v(true, true, true));
    // A fur key is not a fur attribute.
    assert_eq!(c.fur[0].description, FurDescription::default());
    assert_eq!(c.hair_systems[0].visibility, v(false, true, false));
    let e = parse("[[mesh]]\nshape = { type = \"plane\" }\nmaterial = { type = \"diffuse\" }\nmatte = 1\n")
        .unwrap_err()
        .to_string();
    assert!(e.contains("matte") && e.contains("bool"), "{e}");
}

#[test]
fn an_orthographic_camera_takes_its_window_height() {
    let path = Path::new("a.toml");
    let scene =
        |keys: &str| super::parse(&format!("[camera]\neye = [0, 0, 5]\ntarget = [0, 0, 0]\n{keys}"), path, None);
    let (d, _) = scene("projection = \"orthographic\"\northo_height = 3.5\n").unwrap();
    assert_eq!(d.camera.ortho_height_for(640, 480), Some(3.5));
    let (d, _) = scene("projection = \"orthographic\"\n").unwrap();
    assert_eq!(d.camera.ortho_height_for(640, 480), Some(2.0));
    assert_eq!(scene("").unwrap().0.camera.ortho_height_for(640, 480), None);
    for bad in
        ["projection = \"orthographic\"\northo_height = -1.0\n", "ortho_height = 2.0\n", "projection = \"fisheye\"\n"]
    {
        let e = scene(bad).unwrap_err().to_string();
        assert!(e.contains("ortho_height") || e.contains("fisheye"), "{bad}: {e}");
    }
}

/// `type = "sky"` is a physical sky map and its sun, as Arnold's `physical_sky` draws them.
#[test]
fn a_sky_light_is_a_sky_map_and_a_sun() {
    let lights = |body: &str| parse(&format!("[[light]]\ntype = \"sky\"\n{body}\n")).map(|d| d.contents.lights);
    let l = lights("elevation = 30\nazimuth = 0\nexposure = 1\ncamera_visibility = 0").unwrap();
    let [LightSource::Inline(Light::Sun { direction, .. }), LightSource::Inline(Light::EnvironmentMap(map))] = &l[..]
    else {
        panic!("{l:?}")
    };
    assert!(direction.abs_diff_eq(Vec3::new(30f32.to_radians().cos(), 0.5, 0.0), 1e-5), "{direction}");
    assert_eq!(map.camera_visibility(), 0.0);
    // Exposure 1 doubles the sky of the default one (same sun).
    let dim = lights("elevation = 30\nazimuth = 0").unwrap();
    let LightSource::Inline(Light::EnvironmentMap(dim)) = &dim[1] else { panic!() };
    let d = Vec3::new(0.0, 1.0, 1.0).normalize();
    assert!((map.radiance(d) - 2.0 * dim.radiance(d)).length() < 1e-5, "{} {}", map.radiance(d), dim.radiance(d));
    // No sun with a sun_size of 0; errors name the light and the key.
    assert_eq!(lights("sun_size = 0").unwrap().len(), 1);
    let e = lights("turbidity = 20").unwrap_err().to_string();
    assert!(e.contains("light 1") && e.contains("turbidity"), "{e}");
    let e = lights("ground_albedo = [0.1, -1, 0]").unwrap_err().to_string();
    assert!(e.contains("ground_albedo"), "{e}");
}
