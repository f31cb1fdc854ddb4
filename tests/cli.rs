//! The command line as a new user meets it: `tress SCENE` renders to an image named after
//! the scene and never overwrites one silently, frame ranges, progress in logs, `--quiet`;
//! and on bad input one clear error naming the file, a non-zero exit, no panic.

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
        let (ok, stderr) = tress(&["render", "s.toml", "-o", out], d);
        assert!(ok, "{stderr}");
        assert!(d.join(out).exists());
        assert_eq!(stderr.matches("rays/s").count(), 1, "one summary: {stderr}");
        assert!(stderr.contains(&format!("wrote {out} (8x6, 1 spp")), "{stderr}");
    }
    // --quiet prints nothing but errors.
    let (ok, stderr) = tress(&["render", "s.toml", "-o", "q.png", "--quiet"], d);
    assert!(ok && stderr.is_empty() && d.join("q.png").exists(), "{stderr}");
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

/// A lit sphere, 8x6 pixels.
fn sphere_scene(d: &Path, name: &str) {
    let scene = format!(
        "{HEAD}[[light]]\ntype = \"distant\"\ndirection = [0, 1, 0]\nirradiance = [1, 1, 1]\n\
         [[mesh]]\nshape = {{ type = \"sphere\", radius = 0.5 }}\nmaterial = {{ type = \"diffuse\", color = [1, 1, 1] }}\n"
    );
    std::fs::write(d.join(name), scene).unwrap();
}

#[test]
fn a_scene_alone_renders_to_its_own_name_and_is_not_overwritten_without_force() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    std::fs::create_dir(d.join("shots")).unwrap();
    sphere_scene(&d.join("shots"), "fox.toml");
    // `tress SCENE` is `tress render SCENE`; the image goes to the working directory.
    let (ok, stderr) = tress(&["shots/fox.toml", "-q"], d);
    assert!(ok, "{stderr}");
    assert!(d.join("fox.png").exists() && !d.join("shots/fox.png").exists());
    let first = std::fs::read(d.join("fox.png")).unwrap();
    // A second render with another seed is refused and leaves the image alone.
    std::fs::write(d.join("fox.png"), b"keep").unwrap();
    assert_clear_error(&["shots/fox.toml", "--seed", "3"], d, &["fox.png exists", "--force"]);
    assert_eq!(std::fs::read(d.join("fox.png")).unwrap(), b"keep");
    assert_clear_error(&["render", "shots/fox.toml", "-o", "fox.png"], d, &["fox.png exists"]);
    // --force (-f) overwrites; `render` spelled out works the same.
    let (ok, stderr) = tress(&["render", "shots/fox.toml", "-f", "-q"], d);
    assert!(ok, "{stderr}");
    assert_eq!(std::fs::read(d.join("fox.png")).unwrap(), first);
    // Short flags: -o, -s, -r, -t.
    let (ok, stderr) = tress(&["shots/fox.toml", "-o", "small.png", "-s", "2", "-r", "4x3", "-t", "1"], d);
    assert!(ok && stderr.contains("wrote small.png (4x3, 2 spp, 1 threads)"), "{stderr}");
    assert_eq!(image::open(d.join("small.png")).unwrap().to_rgb8().dimensions(), (4, 3));
    // No arguments at all: the help, not a render.
    let out = Command::new(env!("CARGO_BIN_EXE_tress")).current_dir(d).output().unwrap();
    assert!(String::from_utf8_lossy(&out.stderr).contains("Usage: tress [OPTIONS] [SCENE]"));
    assert!(!d.join("demo.png").exists());
}

#[test]
fn frame_ranges_write_one_numbered_image_per_frame() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let scene = "[camera]\n[[camera.key]]\nframe = 1\neye = [0, 0, 3]\ntarget = [0, 0, 0]\n\
        [[camera.key]]\nframe = 5\neye = [3, 0, 0]\ntarget = [0, 0, 0]\n\
        [render]\nresolution = [8, 6]\nspp = 1\n\
        [[light]]\ntype = \"distant\"\ndirection = [1, 0, 0]\nirradiance = [1, 1, 1]\n\
        [[mesh]]\nshape = { type = \"sphere\", radius = 0.6 }\nmaterial = { type = \"diffuse\", color = [1, 1, 1] }\n";
    std::fs::write(d.join("anim.toml"), scene).unwrap();
    let (ok, stderr) = tress(&["anim.toml", "--frames", "1-3", "-o", "out/a.####.png"], d);
    assert!(!ok && stderr.contains("out/a.0001.png") && stderr.contains("`out` does not exist"), "{stderr}");
    std::fs::create_dir(d.join("out")).unwrap();
    let (ok, stderr) = tress(&["anim.toml", "--frames", "1-3", "-o", "out/a.####.png"], d);
    assert!(ok, "{stderr}");
    for f in 1..=3 {
        assert!(stderr.contains(&format!("wrote out/a.{f:04}.png (frame {f}, 8x6")), "{stderr}");
    }
    assert_eq!(stderr.matches("rays/s").count(), 1, "one summary for all frames: {stderr}");
    // The camera moves between keys, from the dark side of the sphere to its lit side.
    assert!(std::fs::read(d.join("out/a.0001.png")).unwrap() != std::fs::read(d.join("out/a.0003.png")).unwrap());
    // Every second frame, the default name (scene stem and the frame, zero-padded).
    let (ok, stderr) = tress(&["anim.toml", "--frames", "1-5x2", "-q"], d);
    assert!(ok, "{stderr}");
    let names: Vec<bool> = (1..=5).map(|f| d.join(format!("anim.{f:04}.png")).exists()).collect();
    assert_eq!(names, [true, false, true, false, true]);
    // The same frame through --frames and through a range of one renders the same image.
    let (ok, stderr) = tress(&["anim.toml", "--frame", "3", "-o", "one.png", "-q"], d);
    assert!(ok, "{stderr}");
    assert_eq!(std::fs::read(d.join("one.png")).unwrap(), std::fs::read(d.join("anim.0003.png")).unwrap());
    // Several frames need a # in the name; existing frames are not overwritten.
    assert_clear_error(&["anim.toml", "--frames", "1-2", "-o", "a.png"], d, &["a.png", "2 frames", "a.####.png"]);
    assert_clear_error(&["anim.toml", "--frames", "2-5"], d, &["anim.0003.png exists"]);
    assert!(!d.join("anim.0002.png").exists(), "nothing rendered when a later frame would be overwritten");
    assert_clear_error(&["anim.toml", "--frames", "5-1"], d, &["5-1", "before the first"]);
    // Frames outside the camera keys warn; --quiet silences it.
    let (ok, stderr) = tress(&["anim.toml", "--frames", "6-7", "-o", "late.#.png"], d);
    assert!(ok, "{stderr}");
    assert_eq!(stderr.matches("outside the camera keys (frames 1 to 5)").count(), 2, "{stderr}");
    let (ok, stderr) = tress(&["anim.toml", "--frame", "8", "-o", "late.png", "-q"], d);
    assert!(ok && stderr.is_empty(), "{stderr}");
    // A still scene warns that its frames are all alike, once for the whole range.
    sphere_scene(d, "still.toml");
    let (ok, stderr) = tress(&["still.toml", "--frames", "1-3"], d);
    assert!(ok, "{stderr}");
    assert_eq!(stderr.matches("every frame renders the same image").count(), 1, "{stderr}");
}

#[test]
fn progress_goes_to_logs_as_lines_with_percent_rate_and_time_left() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    // A demo render of a second or two; stderr is a pipe here, as in a farm log.
    let slow = ["render", "--demo-strands", "2000", "-r", "128x96", "-s", "32", "-t", "2"];
    let (ok, stderr) = tress(&[&slow[..], &["-o", "p.png", "--progress-every", "0.05"]].concat(), d);
    assert!(ok, "{stderr}");
    let lines: Vec<&str> = stderr.lines().filter(|l| l.contains(" % (")).collect();
    assert!(!lines.is_empty(), "no progress lines: {stderr}");
    for l in &lines {
        assert!(l.contains(" tiles), ") && l.contains(" M rays/s, ETA "), "{l}");
    }
    assert!(!stderr.contains('\r') && !stderr.contains("\u{1b}["), "no terminal bar in a log: {stderr}");
    assert_eq!(stderr.matches("rays          ").count(), 1, "{stderr}");
    let (ok, stderr) = tress(&[&slow[..], &["-o", "q.png", "--progress-every", "0.05", "-q"]].concat(), d);
    assert!(ok && stderr.is_empty(), "--quiet: {stderr}");
}

#[test]
fn export_to_usda_keeps_visibility_and_to_hair_says_it_cannot() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let data = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/two_strands.hair");
    std::fs::copy(data, d.join("two.hair")).unwrap();
    let diffuse = "material = { type = \"diffuse\", color = [1, 1, 1] }";
    let scene = format!(
        "{HEAD}[[mesh]]\nshape = {{ type = \"sphere\", radius = 0.5 }}\n{diffuse}\ncamera_visible = false\nmatte = true\n\
         [[mesh]]\nshape = {{ type = \"plane\", size = 2.0 }}\n{diffuse}\n\
         [[hair]]\nfile = \"two.hair\"\nmaterial = {{ type = \"tube\", diffuse = [1, 1, 1] }}\ncasts_shadows = false\n"
    );
    std::fs::write(d.join("vis.toml"), scene).unwrap();
    let (ok, stderr) = tress(&["export", "vis.toml", "-o", "vis.usda"], d);
    assert!(ok, "{stderr}");
    let back = tress::io::usd::read_usd(&d.join("vis.usda"), &Default::default()).unwrap();
    let seen = |camera, shadows, matte| tress::scene::Visibility { camera, shadows, matte };
    let meshes: Vec<_> = back.contents.meshes.iter().map(|m| m.visibility).collect();
    assert_eq!(meshes, [seen(false, true, true), seen(true, true, false)]);
    assert_eq!(back.contents.hair.iter().map(|h| h.visibility).collect::<Vec<_>>(), [seen(true, false, false)]);
    // Exporting the exported file again writes the same prims with the same switches.
    let (ok, stderr) = tress(&["export", "vis.usda", "-o", "again.usda"], d);
    assert!(ok, "{stderr}");
    let switches = |name: &str| {
        let text = std::fs::read_to_string(d.join(name)).unwrap();
        let kept = text.lines().filter(|l| l.trim_start().starts_with("def ") || l.contains("primvars:arnold:"));
        kept.map(str::trim).collect::<Vec<_>>().join("\n")
    };
    assert_eq!(switches("again.usda"), switches("vis.usda"));
    assert_eq!(switches("vis.usda").matches("primvars:arnold:").count(), 3);
    // A .hair file has no place for it: said, and the strands written all the same.
    let (ok, stderr) = tress(&["export", "vis.toml", "-o", "vis.hair"], d);
    assert!(ok && stderr.contains("warning: 1 strand sets are hidden from the camera"), "{stderr}");
    assert_eq!(tress::io::cem_hair::read_hair(&d.join("vis.hair")).unwrap().strand_count(), 2);
}

#[test]
fn fur_export_needs_fur_and_the_memory_limit_counts_grown_fur() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    sphere_scene(d, "bare.toml");
    assert_clear_error(&["fur", "export", "bare.toml", "-o", "fur.hair"], d, &["bare.toml", "no fur"]);
    assert_clear_error(&["fur", "export", "bare.toml", "-o", "fur.usda"], d, &["bare.toml", "no fur"]);
    assert_clear_error(&["export", "bare.toml", "-o", "all.hair"], d, &["bare.toml", "no strands"]);
    assert!(!d.join("fur.hair").exists() && !d.join("fur.usda").exists() && !d.join("all.hair").exists());
    // Two million hairs of 8 segments are some 600 MB before their BVH: over a 256 MiB
    // limit, refused before any fur is grown. The bare sphere is far below it.
    let furry = format!(
        "{}[[fur]]\nmesh = 1\npreset = \"Mouse\"\ndensity = 2000000\nsegments = 8\n",
        std::fs::read_to_string(d.join("bare.toml")).unwrap()
    );
    std::fs::write(d.join("furry.toml"), furry).unwrap();
    assert_clear_error(&["furry.toml", "--memory-limit", "256M"], d, &["needs an estimated", "256.0 MiB"]);
    let (ok, stderr) = tress(&["bare.toml", "--memory-limit", "256M", "-q"], d);
    assert!(ok, "{stderr}");
}

#[test]
fn help_shows_no_rustdoc_link_syntax() {
    for command in [
        &["--help"][..],
        &["render", "--help"],
        &["bench", "--help"],
        &["info", "--help"],
        &["fur", "export", "--help"],
    ] {
        let out = Command::new(env!("CARGO_BIN_EXE_tress")).args(command).output().unwrap();
        let help = String::from_utf8_lossy(&out.stdout);
        assert!(out.status.success() && help.contains("Usage: tress"), "{command:?}: {help}");
        assert!(!help.contains("[`") && !help.contains("`]"), "{command:?} shows rustdoc links: {help}");
    }
}

#[test]
fn camera_picks_one_of_a_files_cameras_and_an_unknown_one_lists_them() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let camera = |name: &str, z: f32| {
        format!(
            "def Camera \"{name}\" {{\n    double3 xformOp:translate = (0, 0, {z})\n    \
             uniform token[] xformOpOrder = [\"xformOp:translate\"]\n}}\n"
        )
    };
    std::fs::write(
        d.join("two.usda"),
        format!(
            "#usda 1.0\ndef Sphere \"Ball\" {{ double radius = 1 }}\ndef Scope \"Cams\" {{\n{}{}}}\n",
            camera("Near", 4.0),
            camera("Far", 40.0)
        ),
    )
    .unwrap();
    let render = |extra: &[&str], out: &str| {
        let mut args = vec!["render", "two.usda", "-r", "16x16", "-s", "1", "-o", out];
        args.extend(extra);
        tress(&args, d)
    };
    // Without --camera: the first, with a warning naming the choice.
    let (ok, stderr) = render(&[], "first.png");
    assert!(ok, "{stderr}");
    assert!(stderr.contains("2 cameras: rendering through /Cams/Near"), "{stderr}");
    let (ok, stderr) = render(&["--camera", "/Cams/Far"], "far.png");
    assert!(ok && !stderr.contains("2 cameras"), "{stderr}");
    // The far camera sees the sphere smaller: fewer lit pixels.
    let covered = |f: &str| {
        let img = image::open(d.join(f)).unwrap().to_rgb8();
        let sky = img.get_pixel(0, 0).0;
        img.pixels().filter(|p| p.0.iter().zip(sky).any(|(&c, s)| c.abs_diff(s) > 8)).count()
    };
    assert!(covered("far.png") < covered("first.png"), "{} {}", covered("far.png"), covered("first.png"));
    assert_clear_error(
        &["render", "two.usda", "--camera", "/Cams/Side", "-o", "x.png"],
        d,
        &["two.usda", "no camera `/Cams/Side`", "/Cams/Near, /Cams/Far"],
    );
    // Files without named cameras say so.
    std::fs::write(d.join("s.toml"), HEAD).unwrap();
    assert_clear_error(&["render", "s.toml", "--camera", "/Cam", "-o", "y.png"], d, &["s.toml", "--camera"]);
}
