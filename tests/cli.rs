//! The command line on bad input: one clear error naming the file, a non-zero exit, no panic.

use std::path::Path;
use std::process::Command;

fn tress(args: &[&str], dir: &Path) -> (bool, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_tress")).args(args).current_dir(dir).output().unwrap();
    (out.status.success(), String::from_utf8_lossy(&out.stderr).into_owned())
}

fn assert_clear_error(args: &[&str], dir: &Path, needles: &[&str]) {
    let (ok, stderr) = tress(args, dir);
    assert!(!ok, "expected failure for {args:?}");
    assert!(!stderr.contains("panicked"), "panic for {args:?}: {stderr}");
    for n in needles {
        assert!(stderr.contains(n), "stderr for {args:?} lacks `{n}`: {stderr}");
    }
}

const HEAD: &str = "[camera]\neye = [0, 1, 3]\ntarget = [0, 0, 0]\n[render]\nresolution = [8, 6]\nspp = 1\n";

#[test]
fn bad_scene_files_and_geometry_give_clear_errors() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let write = |name: &str, text: &[u8]| std::fs::write(d.join(name), text).unwrap();
    write("unknown.toml", format!("{HEAD}bogus = 1\n").as_bytes());
    assert_clear_error(&["render", "unknown.toml", "-o", "x.png"], d, &["unknown.toml", "bogus"]);
    write("type.toml", b"[camera]\neye = \"up\"\ntarget = [0, 0, 0]\n");
    assert_clear_error(&["render", "type.toml", "-o", "x.png"], d, &["type.toml", "eye"]);
    assert_clear_error(&["render", "absent.toml", "-o", "x.png"], d, &["absent.toml"]);
    let mesh = |file: &str| {
        format!("{HEAD}[[mesh]]\nfile = \"{file}\"\nmaterial = {{ type = \"diffuse\", color = [1, 1, 1] }}\n")
    };
    write("missing_obj.toml", mesh("nothere.obj").as_bytes());
    assert_clear_error(&["render", "missing_obj.toml", "-o", "x.png"], d, &["nothere.obj"]);
    write("broken.obj", b"v 0 0 0\nv 1 0 0\nf 1 2 9\n");
    write("broken_obj.toml", mesh("broken.obj").as_bytes());
    assert_clear_error(&["render", "broken_obj.toml", "-o", "x.png"], d, &["broken.obj"]);
    write("bad.hair", &[&b"HAIX"[..], &[0u8; 200]].concat());
    let hair = format!("{HEAD}[[hair]]\nfile = \"bad.hair\"\nmaterial = {{ type = \"tube\", diffuse = [1, 1, 1] }}\n");
    write("bad_hair.toml", hair.as_bytes());
    assert_clear_error(&["render", "bad_hair.toml", "-o", "x.png"], d, &["bad.hair", "signature"]);
    assert!(!d.join("x.png").exists(), "no image may be written for a failed render");
    write("ok.toml", HEAD.as_bytes());
    assert_clear_error(&["render", "ok.toml", "-o", "x.jpg"], d, &["x.jpg"]);
    assert_clear_error(&["render", "ok.toml", "-o", "no/such/dir/x.png"], d, &["no/such/dir"]);
    assert_clear_error(&["render", "ok.toml", "--resolution", "8by6"], d, &["8by6"]);
}

#[test]
fn renders_a_scene_file_to_png_and_exr() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let scene = format!(
        "{HEAD}[[light]]\ntype = \"distant\"\ndirection = [0, 1, 0]\nirradiance = [1, 1, 1]\n\
         [[mesh]]\nshape = {{ type = \"sphere\", radius = 0.5 }}\nmaterial = {{ type = \"diffuse\", color = [1, 1, 1] }}\n"
    );
    std::fs::write(d.join("s.toml"), scene).unwrap();
    for out in ["s.png", "s.exr"] {
        let (ok, stderr) = tress(&["render", "s.toml", "-o", out, "--quiet"], d);
        assert!(ok, "{stderr}");
        assert!(d.join(out).exists());
        assert!(stderr.contains("rays"), "summary missing: {stderr}");
    }
    let img = image::open(d.join("s.png")).unwrap().to_rgb8();
    assert_eq!(img.dimensions(), (8, 6));
    // The sphere is in the middle of the frame, lit from above.
    assert!(img.get_pixel(4, 2)[0] > 30);
}

#[test]
fn fur_export_writes_the_grown_fur_and_bad_fur_gives_clear_errors() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let fur = |extra: &str| {
        format!(
            "{HEAD}[[mesh]]\nshape = {{ type = \"sphere\", radius = 0.5 }}\nmaterial = {{ type = \"diffuse\", color = [1, 1, 1] }}\n\
             [[hair]]\nfile = \"two.hair\"\nmaterial = {{ type = \"tube\", diffuse = [1, 1, 1] }}\n\
             [[fur]]\nmesh = 1\npreset = \"Mouse\"\ndensity = 3000\n{extra}"
        )
    };
    let data = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/two_strands.hair");
    std::fs::copy(data, d.join("two.hair")).unwrap();
    std::fs::write(d.join("fur.toml"), fur("")).unwrap();
    let (ok, stderr) = tress(&["fur", "export", "fur.toml", "-o", "fur.hair"], d);
    assert!(ok, "{stderr}");
    // Only the fur is written, not the scene's other strands; it reads back whole.
    let strands = tress::io::cem_hair::read_hair(&d.join("fur.hair")).unwrap();
    let desc = tress::io::scene_file::read(&d.join("fur.toml"), None).unwrap().0;
    let geometry = tress::prepare::load_geometry(&desc).unwrap();
    let grown = geometry.shapes.iter().find_map(|(s, m)| match (s, &geometry.materials[*m as usize]) {
        (tress::accel::Shape::Strands(s), tress::shading::Material::Fur(_)) => Some(s),
        _ => None,
    });
    let grown = grown.expect("the scene grows fur");
    assert_eq!(strands.strand_count(), grown.strand_count());
    assert!((2900..3100).contains(&strands.strand_count()), "{}", strands.strand_count());
    assert_eq!(strands.points, grown.points);
    assert_eq!(strands.colors, grown.colors);
    // `tress export` writes every strand set: two more strands.
    let (ok, stderr) = tress(&["export", "fur.toml", "-o", "all.hair"], d);
    assert!(ok, "{stderr}");
    assert_eq!(tress::io::cem_hair::read_hair(&d.join("all.hair")).unwrap().strand_count(), grown.strand_count() + 2);

    std::fs::write(d.join("nomap.toml"), fur("length_map = \"missing.png\"\n")).unwrap();
    assert_clear_error(&["fur", "export", "nomap.toml", "-o", "x.hair"], d, &["missing.png"]);
    std::fs::write(d.join("neg.toml"), fur("tip_width = -1\n")).unwrap();
    assert_clear_error(&["render", "neg.toml", "-o", "x.png"], d, &["neg.toml", "fur 1", "tip_width"]);
    std::fs::write(d.join("size.toml"), fur("polar_map = [0.5, 0.5]\n")).unwrap();
    assert_clear_error(&["fur", "export", "size.toml", "-o", "x.hair"], d, &["fur 1", "polar_map", "2 values"]);
    assert_clear_error(&["fur", "export", "fur.toml", "-o", "x.obj"], d, &["x.obj", ".hair"]);
    assert!(!d.join("x.hair").exists());

    let out = Command::new(env!("CARGO_BIN_EXE_tress")).args(["fur", "presets"]).output().unwrap();
    let listing = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success());
    for name in ["Duckling:", "Squirrel:", "Llama:", "PolarBear:"] {
        assert!(listing.lines().any(|l| l.starts_with(name)), "`fur presets` lacks {name}: {listing}");
    }
}
