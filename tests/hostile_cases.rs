//! One test per way a hostile user broke tress: inputs that are not files, endless or huge
//! inputs, paths that alias each other, runaway importer work. Each runs the `tress`
//! command (or the library) on files it writes and checks for one clear error naming the
//! file, in bounded time, and that no existing file is lost.

use std::path::Path;
use std::process::{Command, Output};
use std::time::{Duration, Instant};

/// Runs `tress` in `dir`, killing it if it takes longer than `limit`.
fn tress_within(args: &[&str], dir: &Path, limit: Duration) -> Output {
    let child = Command::new(env!("CARGO_BIN_EXE_tress"))
        .args(args)
        .current_dir(dir)
        .stdin(std::process::Stdio::null())
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    let pid = child.id();
    let start = Instant::now();
    let (done_tx, done_rx) = std::sync::mpsc::channel();
    std::thread::spawn(move || done_tx.send(child.wait_with_output().unwrap()).unwrap());
    match done_rx.recv_timeout(limit) {
        Ok(out) => out,
        Err(_) => {
            // SAFETY: kill(2) on the child this test started.
            unsafe { libc::kill(pid as i32, libc::SIGKILL) };
            panic!("tress {args:?} still running after {:?}", start.elapsed());
        }
    }
}

fn tress(args: &[&str], dir: &Path) -> Output {
    tress_within(args, dir, Duration::from_secs(60))
}

/// Asserts `tress args` failed without panicking and its message holds every needle.
fn assert_refused(out: &Output, needles: &[&str]) -> String {
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    assert!(!out.status.success(), "expected a failure: {stderr}");
    assert_eq!(out.status.code(), Some(1), "expected exit status 1: {stderr}");
    assert!(!stderr.contains("panicked"), "panic: {stderr}");
    for n in needles {
        assert!(stderr.contains(n), "stderr lacks `{n}`: {stderr}");
    }
    stderr
}

const HEAD: &str = "[camera]\neye = [0, 1, 3]\ntarget = [0, 0, 0]\n[render]\nresolution = [8, 6]\nspp = 1\n";

fn mkfifo(path: &Path) {
    let c = std::ffi::CString::new(path.as_os_str().as_encoded_bytes()).unwrap();
    // SAFETY: a NUL-terminated path and a mode.
    assert_eq!(unsafe { libc::mkfifo(c.as_ptr(), 0o600) }, 0);
}

/// A FIFO, a device or a directory named where a file is read is refused at once, by name,
/// wherever it is named: as the scene, a `.hair` file, a mesh, a pbrt `Include`, a merge
/// tile, a checkpoint.
#[test]
fn what_is_not_a_regular_file_is_refused_before_reading() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    mkfifo(&d.join("fifo"));
    std::fs::create_dir(d.join("folder.hair")).unwrap();
    std::os::unix::fs::symlink("/dev/zero", d.join("zero.obj")).unwrap();
    let limit = Duration::from_secs(10);
    let out = tress_within(&["render", "fifo", "-o", "x.png"], d, limit);
    assert_refused(&out, &["fifo: is a FIFO", "not a regular file"]);
    for (name, entry) in [
        ("hair_fifo.toml", "[[hair]]\nfile = \"fifo\"\nmaterial = { type = \"tube\", diffuse = [1, 1, 1] }\n"),
        ("hair_dir.toml", "[[hair]]\nfile = \"folder.hair\"\nmaterial = { type = \"tube\", diffuse = [1, 1, 1] }\n"),
        ("zero.toml", "[[mesh]]\nfile = \"zero.obj\"\nmaterial = { type = \"diffuse\", color = [1, 1, 1] }\n"),
    ] {
        std::fs::write(d.join(name), format!("{HEAD}{entry}")).unwrap();
        let out = tress_within(&["render", name, "-o", "x.png"], d, limit);
        assert_refused(&out, &["not a regular file"]);
    }
    std::fs::write(d.join("inc.pbrt"), "Include \"fifo\"\n").unwrap();
    assert_refused(&tress_within(&["render", "inc.pbrt", "-o", "x.png"], d, limit), &["fifo: is a FIFO"]);
    let out = tress_within(&["merge", "fifo", "-o", "m.exr"], d, limit);
    assert_refused(&out, &["fifo: is a FIFO"]);
    let out = tress_within(&["merge", "/dev/zero", "-o", "m.exr"], d, limit);
    assert_refused(&out, &["/dev/zero: is a device"]);
    std::fs::write(d.join("ok.toml"), HEAD).unwrap();
    let out = tress_within(&["render", "ok.toml", "-o", "x.exr", "--checkpoint", "fifo.exr"], d, limit);
    // A checkpoint path that is not a regular file cannot be resumed from nor replaced.
    mkfifo(&d.join("fifo.exr"));
    let out2 = tress_within(&["render", "ok.toml", "-o", "x.exr", "--checkpoint", "fifo.exr"], d, limit);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert_refused(&out2, &["fifo.exr: is a FIFO"]);
}

/// The missing file's OS error is printed once, after the file's name.
#[test]
fn a_missing_file_is_reported_once() {
    let dir = tempfile::tempdir().unwrap();
    let out = tress(&["render", "absent.toml", "-o", "x.png"], dir.path());
    let stderr = assert_refused(&out, &["absent.toml"]);
    assert_eq!(stderr.matches("No such file").count(), 1, "{stderr}");
}

/// pbrt `Include`s: a chain of 31 files each including the next twice is 2^31 inclusions
/// (it hung); a file including itself, or two including each other, is a cycle named.
#[test]
fn pbrt_include_fan_out_and_cycles_are_refused() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    for i in 0..31 {
        std::fs::write(
            d.join(format!("f{i}.pbrt")),
            format!("Include \"f{}.pbrt\"\nInclude \"f{}.pbrt\"\n", i + 1, i + 1),
        )
        .unwrap();
    }
    std::fs::write(d.join("f31.pbrt"), "Translate 0 0 0\n").unwrap();
    let start = Instant::now();
    let e = tress::io::pbrt::read_pbrt(&d.join("f0.pbrt")).unwrap_err().to_string();
    assert!(e.contains("includes in all"), "{e}");
    assert!(start.elapsed() < Duration::from_secs(10), "{:?}", start.elapsed());

    std::fs::write(d.join("a.pbrt"), "Include \"b.pbrt\"\n").unwrap();
    std::fs::write(d.join("b.pbrt"), "Include \"a.pbrt\"\n").unwrap();
    let e = tress::io::pbrt::read_pbrt(&d.join("a.pbrt")).unwrap_err().to_string();
    assert!(e.contains("include cycle") && e.contains("a.pbrt includes") && e.contains("b.pbrt includes"), "{e}");
    std::fs::write(d.join("self.pbrt"), "Include \"./self.pbrt\"\n").unwrap();
    let e = tress::io::pbrt::read_pbrt(&d.join("self.pbrt")).unwrap_err().to_string();
    assert!(e.contains("include cycle"), "{e}");
}

/// `-o X.exr --checkpoint X.exr` wrote the image, then deleted it as the checkpoint. Every
/// spelling of one file as two (the same name, `./`, a symbolic link, a hard link) is
/// refused before rendering, and an existing image is kept.
#[test]
fn output_and_checkpoint_must_be_different_files() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    std::fs::write(d.join("s.toml"), HEAD).unwrap();
    std::fs::write(d.join("X.exr"), b"an earlier image").unwrap();
    std::os::unix::fs::symlink("X.exr", d.join("link.exr")).unwrap();
    std::fs::hard_link(d.join("X.exr"), d.join("hard.exr")).unwrap();
    let sub = d.join("sub");
    std::fs::create_dir(&sub).unwrap();
    for checkpoint in ["X.exr", "./X.exr", "link.exr", "hard.exr", "sub/../X.exr"] {
        let out = tress(&["render", "s.toml", "-o", "X.exr", "--checkpoint", checkpoint], d);
        assert_refused(&out, &["are the same file"]);
        assert_eq!(std::fs::read(d.join("X.exr")).unwrap(), b"an earlier image", "{checkpoint}");
    }
    // Not existing yet, through different spellings of one directory.
    let out = tress(&["render", "s.toml", "-o", "new.exr", "--checkpoint", "sub/../new.exr"], d);
    assert_refused(&out, &["are the same file"]);
    // Merging tiles over one of them.
    let out = tress(&["render", "s.toml", "-o", "t0.exr", "--tile", "0/1"], d);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let out = tress(&["merge", "t0.exr", "-o", "./t0.exr"], d);
    assert_refused(&out, &["are the same file"]);
    // Distinct files still work: the image is written and the checkpoint removed.
    let out = tress(&["render", "s.toml", "-o", "X.exr", "--checkpoint", "c.exr", "--force"], d);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert!(std::fs::metadata(d.join("X.exr")).unwrap().len() > 100 && !d.join("c.exr").exists());
}

/// `--checkpoint-every 1e300` panicked converting to a duration.
#[test]
fn checkpoint_intervals_are_bounded() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    std::fs::write(d.join("s.toml"), HEAD).unwrap();
    for every in ["1e300", "inf", "nan", "0", "-1", "525601"] {
        let every_arg = format!("--checkpoint-every={every}");
        let out = tress(&["render", "s.toml", "-o", "x.exr", "--checkpoint", "c.exr", &every_arg], d);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(!out.status.success() && !stderr.contains("panicked"), "{every}: {stderr}");
        assert!(stderr.contains("--checkpoint-every") && stderr.contains("525600"), "{every}: {stderr}");
    }
}

/// Hidden temporary files left by a run killed while writing are removed when the image is
/// next written; one a live writer holds is kept.
#[test]
fn stale_temporary_images_are_removed_on_the_next_write() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    std::fs::write(d.join("s.toml"), HEAD).unwrap();
    std::fs::write(d.join(".x.png.aB3dE9.tmp"), b"left by kill -9").unwrap();
    let live = std::fs::File::create(d.join(".x.png.Zz9Yy8.tmp")).unwrap();
    live.lock().unwrap();
    std::fs::write(d.join(".other.png.aB3dE9.tmp"), b"another image's").unwrap();
    let out = tress(&["render", "s.toml", "-o", "x.png"], d);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert!(!d.join(".x.png.aB3dE9.tmp").exists(), "the stale temporary file is still there");
    assert!(d.join(".x.png.Zz9Yy8.tmp").exists(), "a live writer's temporary file was removed");
    assert!(d.join(".other.png.aB3dE9.tmp").exists(), "another image's temporary file was removed");
}

/// A checkpoint whose tile list was edited to claim unrendered tiles resumed to black
/// tiles with exit 0: the checksum refuses it.
#[test]
fn a_tampered_checkpoint_is_refused() {
    use tress::partial::Partial;
    let dir = tempfile::tempdir().unwrap();
    // 40x20 pixels: 3x2 tiles of 16, of which 0 and 1 are done.
    let mut state = tress::render::TiledFilm::new(tress::film::Region::full(40, 20));
    state.done.set(0);
    state.done.set(1);
    for p in &mut state.film.pixels[..16] {
        p.color = glam::Vec3::splat(0.5);
    }
    let part = Partial { state, full: (40, 20), fingerprint: 7, farm_tile: None };
    let path = dir.path().join("c.exr");
    part.save(&path).unwrap();
    assert_eq!(Partial::load(&path).unwrap(), part);
    // Claim tiles 3 and 4 instead, keeping the count and the status: what a hand edit of
    // the header would do.
    let bytes = std::fs::read(&path).unwrap();
    let attribute = bytes.windows(10).position(|w| w == b"tressTiles").expect("the tile list");
    let at = attribute + bytes[attribute..].windows(3).position(|w| w == b"0-1").expect("the tiles");
    let mut edited = bytes.clone();
    edited[at..at + 3].copy_from_slice(b"3-4");
    let e = Partial::decode(&edited, &path).unwrap_err().to_string();
    assert!(e.contains("c.exr") && e.contains("changed after tress wrote it"), "{e}");
}

/// Resolutions that validation allows aborted above about 4100x4100 under 4 GB, and fur
/// under its point limit aborted: the memory estimate now runs on every render, against
/// the memory the machine has (no `--memory-limit` given), counts hair systems, and
/// refuses before allocating.
#[test]
fn renders_larger_than_the_machine_are_refused_before_allocating() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    // 65536 x 65536 pixels: the largest resolution validation allows, about 870 GB of film.
    let big = HEAD.replace("resolution = [8, 6]", "resolution = [65536, 65536]");
    std::fs::write(d.join("big.toml"), &big).unwrap();
    let stderr = assert_refused(&tress(&["render", "big.toml", "-o", "x.exr"], d), &["more than the memory available"]);
    assert!(stderr.contains("image ") && stderr.contains("GiB"), "{stderr}");
    // A hair system's expansion counts too (it did not): 9 million follicles of 10 points
    // make 99 million render points, under the expansion limit, about 17 GB.
    let hair = format!(
        "{HEAD}[[mesh]]\nshape = {{ type = \"sphere\", radius = 1.0 }}\nmaterial = {{ type = \"diffuse\", color = [1, 1, 1] }}\n\
         [[hair_system]]\nfollicles = {{ mesh = 1, placement = \"grid\", u = 3000, v = 3000, points_per_hair = 10, length = 0.3 }}\n\
         hairs_per_clump = 1\n"
    );
    std::fs::write(d.join("hair.toml"), hair).unwrap();
    let out = tress_within(&["render", "hair.toml", "-o", "x.png", "--memory-limit", "4G"], d, Duration::from_secs(10));
    assert_refused(&out, &["more than the memory limit of 4.0 GiB", "geometry"]);
    // An explicit limit replaces the machine's.
    let out = tress(&["render", "big.toml", "-o", "x.exr", "--memory-limit", "1M"], d);
    assert_refused(&out, &["more than the memory limit of 1.0 MiB"]);
    assert!(!d.join("x.exr").exists() && !d.join("x.png").exists());
}

/// `resolution = [64, 48, 3]` and a four-number `eye` were accepted (serde read the first
/// numbers and dropped the rest); NaN and infinities, camera and fur errors: each is one
/// error naming the scene file and the key.
#[test]
fn scene_values_are_checked_by_key_and_file() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let cases: &[(&str, &str, &[&str])] = &[
        ("res.toml", "resolution = [8, 6]", &["res.toml", "resolution", "invalid length 3", "exactly 2"]),
        ("eye.toml", "eye = [0, 1, 3]", &["eye.toml", "eye", "invalid length 4", "exactly 3"]),
        ("nan.toml", "eye = [0, 1, 3]", &["nan.toml", "camera `eye`", "not a finite number"]),
        ("inf.toml", "target = [0, 0, 0]", &["inf.toml", "camera `target`", "not a finite number"]),
        ("same.toml", "target = [0, 0, 0]", &["same.toml: camera: eye and target are the same point"]),
    ];
    let replacement = |name: &str| match name {
        "res.toml" => "resolution = [64, 48, 3]",
        "eye.toml" => "eye = [0, 1, 3, 7]",
        "nan.toml" => "eye = [0, nan, 3]",
        "inf.toml" => "target = [0, 0, -inf]",
        _ => "target = [0, 1, 3]",
    };
    for (name, key, needles) in cases {
        std::fs::write(d.join(name), HEAD.replace(key, replacement(name))).unwrap();
        let stderr = assert_refused(&tress(&["render", name, "-o", "x.png"], d), needles);
        assert_eq!(stderr.matches("error:").count(), 1, "printed once: {stderr}");
    }
    // Fur errors name the scene file, once: fur placed by UV on a mesh without UVs.
    let mesh = format!(
        "{HEAD}[[mesh]]\nfile = \"tri.obj\"\nmaterial = {{ type = \"diffuse\", color = [1, 1, 1] }}\n\
         [[fur]]\nmesh = 1\ndensity = 100\nplacement = \"uv\"\n"
    );
    std::fs::write(d.join("tri.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").unwrap();
    std::fs::write(d.join("fur.toml"), mesh).unwrap();
    let stderr = assert_refused(&tress(&["render", "fur.toml", "-o", "x.png"], d), &["fur.toml: fur 1:", "UVs"]);
    assert_eq!(stderr.matches("error:").count(), 1, "printed once: {stderr}");
}

/// An infinite pbrt camera was reported as "eye and target are the same point".
#[test]
fn an_infinite_pbrt_camera_is_named_as_such() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    std::fs::write(d.join("far.pbrt"), "LookAt 0 0 1e39  0 0 0  0 1 0\nCamera \"perspective\"\nWorldBegin\n").unwrap();
    let out = tress(&["render", "far.pbrt", "-o", "x.png"], d);
    assert_refused(&out, &["far.pbrt: line 2: the camera's position is beyond single precision"]);
}

/// A `.hair` file with no strands was accepted silently. It renders (a frame of a hair
/// cache can be empty while the rest of the scene is not) with a warning naming the file.
#[test]
fn a_hair_file_without_strands_is_named_in_a_warning() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    tress::io::cem_hair::write_hair(&d.join("empty.hair"), &tress::geometry::StrandSet::new()).unwrap();
    let scene =
        format!("{HEAD}[[hair]]\nfile = \"empty.hair\"\nmaterial = {{ type = \"tube\", diffuse = [1, 1, 1] }}\n");
    std::fs::write(d.join("s.toml"), scene).unwrap();
    let out = tress(&["render", "s.toml", "-o", "x.png"], d);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{stderr}");
    assert!(stderr.contains("warning: ") && stderr.contains("empty.hair: the file holds no strands"), "{stderr}");
}

/// An image named as the scene was read as a scene TOML (an empty `.exr` rendered an empty
/// scene, exit 0), and a scene with nothing in it rendered its background without a word.
#[test]
fn images_are_not_scenes_and_empty_scenes_are_said() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    std::fs::write(d.join("beauty.exr"), b"").unwrap();
    assert_refused(
        &tress(&["render", "beauty.exr", "-o", "x.png"], d),
        &["beauty.exr: is an OpenEXR image, not a scene"],
    );
    assert!(!d.join("x.png").exists());
    std::fs::write(d.join("empty.toml"), HEAD).unwrap();
    let out = tress(&["render", "empty.toml", "-o", "x.png"], d);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{stderr}");
    assert!(stderr.contains("empty.toml: the scene has nothing to render"), "{stderr}");
}

/// Parses Maya ASCII text in memory, returning the result and the time it took.
fn parse_maya_timed(text: &str) -> (Result<tress::io::imported::Imported, String>, Duration) {
    let start = Instant::now();
    let r = tress::io::maya_ascii::parse_maya(text, Path::new("big.ma")).map_err(|e| e.to_string());
    (r, start.elapsed())
}

/// Maya files of a few MB took quadratic time: 100k empty meshes with 100k connections
/// took 20 s. Connections are looked up by node now; this takes a small fraction of a
/// second (the bound leaves room for a loaded machine).
#[test]
fn maya_connections_cost_linear_time() {
    let mut text = String::from("requires maya \"2024\";\n");
    for i in 0..100_000 {
        text += &format!(
            "createNode transform -n \"t{i}\";\ncreateNode mesh -n \"m{i}\" -p \"t{i}\";\n\
             connectAttr \"m{i}.iog\" \"initialShadingGroup.dsm\" -na;\n"
        );
    }
    let (r, took) = parse_maya_timed(&text);
    assert!(r.is_ok(), "{r:?}");
    assert!(took < Duration::from_secs(3), "100k meshes and connections took {took:?}");
}

/// A 50k-deep chain of transforms, each with a shape, and a mesh at the bottom: world
/// matrices and visibility are memoised, so the chain costs its length (it took over 60 s),
/// and walking it is a loop, not a recursion that could overflow the stack.
#[test]
fn a_deep_maya_hierarchy_costs_its_size() {
    let mut text = String::from("createNode transform -n \"t0\";\n");
    for i in 1..50_000 {
        text += &format!(
            "createNode transform -n \"t{i}\" -p \"t{}\";\nsetAttr \".t\" -type \"double3\" 0 0.00001 0;\n\
             createNode mesh -n \"s{i}\" -p \"t{i}\";\n",
            i - 1
        );
    }
    text += "createNode mesh -n \"ball\" -p \"t49999\";\ncreateNode polySphere -n \"p\";\nconnectAttr \"p.out\" \"ball.i\";\n";
    let (r, took) = parse_maya_timed(&text);
    let imported = r.unwrap();
    assert_eq!(imported.contents.meshes.len(), 1);
    // The sphere sits at the end of the chain: 49,999 steps of 1e-5 up.
    let t = imported.contents.meshes[0].transform.translation;
    assert!((t.y - 0.49999).abs() < 1e-3, "{t}");
    assert!(took < Duration::from_secs(3), "the 50k-deep chain took {took:?}");
}

/// Parents that form a cycle are an error naming the chain.
#[test]
fn maya_parent_cycles_are_named() {
    let text = "createNode transform -n \"a\" -p \"b\";\ncreateNode transform -n \"b\" -p \"c\";\n\
                createNode transform -n \"c\" -p \"a\";\ncreateNode mesh -n \"ball\" -p \"a\";\n\
                createNode polySphere -n \"p\";\nconnectAttr \"p.out\" \"ball.i\";\n";
    let e = parse_maya_timed(text).0.unwrap_err();
    assert!(
        e.starts_with("big.ma") && e.contains("parent cycle: a is a child of b is a child of c is a child of a"),
        "{e}"
    );
}

/// A pbrt object that instances itself, directly or through an object it is inside, is a
/// cycle named in the error.
#[test]
fn pbrt_objects_instancing_themselves_are_refused() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    std::fs::write(d.join("self.pbrt"), "WorldBegin\nObjectBegin \"a\"\nObjectInstance \"a\"\nObjectEnd\n").unwrap();
    let e = tress::io::pbrt::read_pbrt(&d.join("self.pbrt")).unwrap_err().to_string();
    assert!(e.contains("self.pbrt") && e.contains("object cycle: \"a\" instances \"a\""), "{e}");
    let nested = "WorldBegin\nObjectBegin \"a\"\nObjectBegin \"b\"\nObjectInstance \"a\"\nObjectEnd\nObjectEnd\n";
    std::fs::write(d.join("nested.pbrt"), nested).unwrap();
    let e = tress::io::pbrt::read_pbrt(&d.join("nested.pbrt")).unwrap_err().to_string();
    assert!(e.contains("object cycle: \"a\" contains \"b\" instances \"a\""), "{e}");
    // Instancing another, ended object is only skipped.
    let fine = "WorldBegin\nObjectBegin \"a\"\nObjectEnd\nObjectInstance \"a\"\n";
    std::fs::write(d.join("fine.pbrt"), fine).unwrap();
    assert!(tress::io::pbrt::read_pbrt(&d.join("fine.pbrt")).is_ok());
}

/// Ctrl-C and SIGTERM waited for the scene build (8 to 9 s on a 2M-hair fur scene): while
/// the scene loads, grows and builds its BVH, a signal ends the process at once, with the
/// signal's exit status and no file written.
#[test]
fn a_signal_during_the_scene_build_ends_it_at_once() {
    use std::os::unix::process::ExitStatusExt;
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    // A million hairs take seconds to grow and build on any machine.
    let fur = format!(
        "{HEAD}[[mesh]]\nshape = {{ type = \"sphere\", radius = 1.0 }}\nmaterial = {{ type = \"diffuse\", color = [1, 1, 1] }}\n\
         [[fur]]\nmesh = 1\ndensity = 1000000\nsegments = 8\n"
    );
    std::fs::write(d.join("fur.toml"), fur).unwrap();
    let mut child = Command::new(env!("CARGO_BIN_EXE_tress"))
        .args(["render", "fur.toml", "-o", "x.exr"])
        .current_dir(d)
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    std::thread::sleep(Duration::from_millis(700));
    assert!(child.try_wait().unwrap().is_none(), "the build finished before the signal: the test needs a slower scene");
    // SAFETY: kill(2) on the child this test started.
    unsafe { libc::kill(child.id() as i32, libc::SIGTERM) };
    let sent = Instant::now();
    let status = loop {
        if let Some(s) = child.try_wait().unwrap() {
            break s;
        }
        if sent.elapsed() > Duration::from_secs(10) {
            child.kill().unwrap();
            panic!("still running 10 s after SIGTERM");
        }
        std::thread::sleep(Duration::from_millis(10));
    };
    let took = sent.elapsed();
    let mut stderr = String::new();
    std::io::Read::read_to_string(&mut child.stderr.take().unwrap(), &mut stderr).unwrap();
    assert!(took < Duration::from_secs(1), "took {took:?} to stop");
    assert_eq!(status.code().or(status.signal().map(|s| 128 + s)), Some(128 + libc::SIGTERM), "{stderr}");
    assert!(stderr.contains("interrupted while loading the scene; nothing written"), "{stderr}");
    assert!(std::fs::read_dir(d).unwrap().all(|e| !e.unwrap().file_name().to_string_lossy().contains("x.exr")));
}

/// Image maps are input files too: a FIFO named as a fur map or a texture is refused at
/// once, a map larger than the decoder's limits is an error naming the file (from its
/// header, before decoding), and the memory estimate counts each distinct map once.
#[test]
fn image_maps_are_opened_and_decoded_within_limits() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    mkfifo(&d.join("fifo.png"));
    // 8193 x 1 pixels: one more than a map's side may have, a few bytes of PNG.
    image::save_buffer(d.join("wide.png"), &vec![128u8; 8193 * 3], 8193, 1, image::ColorType::Rgb8).unwrap();
    let sphere =
        "[[mesh]]\nshape = { type = \"sphere\", radius = 1.0 }\nmaterial = { type = \"diffuse\", color = [1, 1, 1] }\n";
    let limit = Duration::from_secs(10);
    for (name, map, needles) in [
        ("fifo.toml", "fifo.png", &["fifo.png: is a FIFO"][..]),
        ("wide.toml", "wide.png", &["wide.png", "larger than 8192 pixels a side"][..]),
    ] {
        let scene = format!("{HEAD}{sphere}[[fur]]\nmesh = 1\ndensity = 100\nlength_map = \"{map}\"\n");
        std::fs::write(d.join(name), scene).unwrap();
        assert_refused(&tress_within(&["render", name, "-o", "x.png"], d, limit), needles);
    }
    let textured = format!(
        "{HEAD}[[mesh]]\nshape = {{ type = \"sphere\", radius = 1.0 }}\nmaterial = {{ type = \"textured\", color = \"fifo.png\" }}\n"
    );
    std::fs::write(d.join("tex.toml"), textured).unwrap();
    assert_refused(&tress_within(&["render", "tex.toml", "-o", "x.png"], d, limit), &["fifo.png: is a FIFO"]);
    // Six maps naming one 64x32 file: one decode in the estimate, 64 * 32 pixels.
    image::save_buffer(d.join("grey.png"), &vec![128u8; 64 * 32 * 3], 64, 32, image::ColorType::Rgb8).unwrap();
    let maps: String = ["length", "baldness", "inclination", "roll", "polar", "base_width"]
        .iter()
        .map(|a| format!("{a}_map = \"grey.png\"\n"))
        .collect();
    let scene = format!("{HEAD}{sphere}[[fur]]\nmesh = 1\ndensity = 100\n{maps}");
    let desc = tress::io::scene_file::parse(&scene, &d.join("six.toml"), None).unwrap().0;
    let once = tress::prepare::estimate_memory(&desc).unwrap().maps;
    assert!(once > 0 && once < 64 * 32 * 64, "{once} bytes for one 64x32 map");
    let scene = format!("{HEAD}{sphere}[[fur]]\nmesh = 1\ndensity = 100\nlength_map = \"grey.png\"\n");
    let desc = tress::io::scene_file::parse(&scene, &d.join("one.toml"), None).unwrap().0;
    assert_eq!(tress::prepare::estimate_memory(&desc).unwrap().maps, once);
    tress::prepare::prepare(&desc).unwrap();
}

/// Maya `file -r` references were dropped silently: each is a warning naming the file.
#[test]
fn maya_references_are_named_in_a_warning() {
    let text = "file -rdi 1 -ns \"prop\" -rfn \"propRN\" -typ \"mayaAscii\" \"/assets/prop.ma\";\n\
                file -r -ns \"prop\" -dr 1 -rfn \"propRN\" -typ \"mayaAscii\" \"/assets/prop.ma\";\n\
                createNode transform -n \"t\";\n";
    let imported = parse_maya_timed(text).0.unwrap();
    let named: Vec<&String> = imported.warnings.iter().filter(|w| w.contains("/assets/prop.ma")).collect();
    assert_eq!(named.len(), 1, "{:?}", imported.warnings);
    assert!(named[0].contains("does not load"), "{named:?}");
}

/// USD layers, the scene's own and those it composes, are input files: a FIFO is refused
/// at once instead of blocking (as the scene, an error; as a sublayer, the composition
/// problem every unreadable sublayer is, a warning naming it).
#[test]
fn usd_layers_are_opened_as_input_files() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    mkfifo(&d.join("fifo.usda"));
    let limit = Duration::from_secs(10);
    assert_refused(&tress_within(&["render", "fifo.usda", "-o", "x.png"], d, limit), &["fifo.usda: is a FIFO"]);
    std::fs::write(d.join("top.usda"), "#usda 1.0\n(\n    subLayers = [@./fifo.usda@]\n)\n").unwrap();
    let out = tress_within(&["render", "top.usda", "-o", "x.png", "-r", "8x6", "-s", "1"], d, limit);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains("warning: top.usda: composition problem") && stderr.contains("fifo.usda: is a FIFO"),
        "{stderr}"
    );
}
