//! Renders as farm jobs: tiles merged into the single render byte for byte, renders killed
//! and resumed from their checkpoints, interrupted renders writing valid partial images,
//! animation frames, and the memory limit. Mostly through the real `tress` binary.

use std::path::{Path, PathBuf};
use std::process::{Child, Command, Output};
use std::sync::OnceLock;
use std::time::{Duration, Instant};
use tress::film::{Film, Region};
use tress::partial::Partial;
use tress::render::{render_tiles, Control, TiledFilm};

fn tress(args: &[&str], dir: &Path) -> Output {
    Command::new(env!("CARGO_BIN_EXE_tress")).args(args).current_dir(dir).output().unwrap()
}

fn ok(args: &[&str], dir: &Path) {
    let out = tress(args, dir);
    assert!(out.status.success(), "tress {args:?} failed: {}", String::from_utf8_lossy(&out.stderr));
}

/// A quick demo render.
const QUICK: &[&str] = &["--demo-strands", "2000", "--resolution", "96x70", "--spp", "2", "--quiet"];
/// A demo render slow enough (a few seconds) to be interrupted midway.
const SLOW: &[&str] = &["--demo-strands", "2000", "--resolution", "128x96", "--spp", "48", "--quiet", "--threads", "2"];

fn args<'a>(base: &[&'a str], more: &[&'a str]) -> Vec<&'a str> {
    ["render"].iter().chain(base).chain(more).copied().collect()
}

/// The uninterrupted SLOW render, made once for the tests that need it.
fn slow_reference() -> &'static Path {
    static DIR: OnceLock<PathBuf> = OnceLock::new();
    DIR.get_or_init(|| {
        let dir = tempfile::tempdir().unwrap().keep();
        ok(&args(SLOW, &["-o", "reference.exr"]), &dir);
        dir.join("reference.exr")
    })
}

#[test]
fn tiles_merged_equal_the_single_render_byte_for_byte() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    for out in ["single.exr", "single.png"] {
        ok(&args(QUICK, &["-o", out]), d);
    }
    let n = 4;
    let tiles: Vec<String> = (0..n).map(|i| format!("tile{i}.exr")).collect();
    for (i, t) in tiles.iter().enumerate() {
        let tile = format!("{i}/{n}");
        // Different thread counts per tile: the pixels do not depend on them.
        ok(&args(QUICK, &["--tile", &tile, "--threads", &(1 + i % 2).to_string(), "-o", t]), d);
    }
    // Tiles in any order.
    let mut merge: Vec<&str> = vec!["merge"];
    merge.extend(tiles.iter().rev().map(String::as_str));
    for out in ["merged.exr", "merged.png"] {
        ok(&[&merge[..], &["-o", out]].concat(), d);
    }
    for (a, b) in [("single.exr", "merged.exr"), ("single.png", "merged.png")] {
        let (a, b) = (std::fs::read(d.join(a)).unwrap(), std::fs::read(d.join(b)).unwrap());
        assert!(a == b, "merged image differs from the single render");
    }
    // A tile is a standard EXR crop: its data window is its band of rows.
    let t = Partial::load(&d.join("tile2.exr")).unwrap();
    assert_eq!(t.state.region, Region::band(96, 70, 2, 4).unwrap());
    assert_eq!((t.full, t.farm_tile), ((96, 70), Some((2, 4))));
    assert!(t.is_complete());

    // Missing, repeated and foreign tiles are refused.
    let fail = |more: &[&str], needle: &str| {
        let out = tress(&[&["merge"], more, &["-o", "bad.exr"]].concat(), d);
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(!out.status.success() && err.contains(needle), "{more:?}: {err}");
    };
    fail(&["tile0.exr", "tile1.exr", "tile2.exr"], "tiles 3 of 4 are missing");
    fail(&["tile0.exr", "tile1.exr", "tile2.exr", "tile2.exr"], "given twice");
    ok(&args(QUICK, &["--seed", "9", "--tile", "3/4", "-o", "other.exr"]), d);
    fail(&["tile0.exr", "tile1.exr", "tile2.exr", "other.exr"], "another render");
    fail(&["single.exr"], "not a tile or checkpoint written by tress");
    assert!(!d.join("bad.exr").exists());
    let out = tress(&args(QUICK, &["--tile", "1/4", "-o", "t.png"]), d);
    assert!(String::from_utf8_lossy(&out.stderr).contains("must be written to an .exr file"));
}

/// Starts a SLOW render writing checkpoints to `checkpoint` and waits until the first one
/// is on disk, so the render is known to be midway.
fn start_until_checkpoint(dir: &Path, output: &str, checkpoint: &str) -> Child {
    let mut child = Command::new(env!("CARGO_BIN_EXE_tress"))
        .args(args(SLOW, &["-o", output, "--checkpoint", checkpoint, "--checkpoint-every", "0.005"]))
        .current_dir(dir)
        .spawn()
        .unwrap();
    let start = Instant::now();
    while !dir.join(checkpoint).exists() {
        assert!(child.try_wait().unwrap().is_none(), "the render ended before its first checkpoint");
        assert!(start.elapsed() < Duration::from_secs(60), "no checkpoint after a minute");
        std::thread::sleep(Duration::from_millis(20));
    }
    child
}

#[test]
fn a_killed_render_resumes_from_its_checkpoint_to_the_same_image() {
    let reference = std::fs::read(slow_reference()).unwrap();
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let mut child = start_until_checkpoint(d, "out.exr", "ck.exr");
    child.kill().unwrap(); // SIGKILL: no chance to save anything more
    child.wait().unwrap();
    let saved = Partial::load(&d.join("ck.exr")).unwrap();
    assert!(!saved.is_complete(), "the render finished before it was killed: make SLOW slower");
    assert!(!d.join("out.exr").exists());

    // Not quiet, to see the resume reported.
    let loud: Vec<&str> = SLOW.iter().copied().filter(|a| *a != "--quiet").collect();
    let out = tress(&args(&loud, &["-o", "out.exr", "--checkpoint", "ck.exr"]), d);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{stderr}");
    assert!(stderr.contains("resuming from ck.exr"), "{stderr}");
    assert!(
        std::fs::read(d.join("out.exr")).unwrap() == reference,
        "resumed render differs from the uninterrupted one"
    );
    assert!(!d.join("ck.exr").exists(), "the checkpoint is removed once the image is written");

    // A checkpoint of another render is refused, not silently mixed in.
    saved.save(&d.join("ck.exr")).unwrap();
    let out = tress(&args(SLOW, &["--seed", "3", "-o", "other.exr", "--checkpoint", "ck.exr"]), d);
    assert!(String::from_utf8_lossy(&out.stderr).contains("the checkpoint is of another render"));
}

#[cfg(unix)]
#[test]
fn sigint_stops_the_render_and_writes_a_valid_partial_image() {
    let path = slow_reference();
    let reference = tress::film::decode_exr(&std::fs::read(path).unwrap(), path).unwrap().film;
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let child = start_until_checkpoint(d, "out.exr", "ck.exr");
    let sent = Instant::now();
    // SAFETY: kill(2) on our own child's pid.
    assert_eq!(unsafe { libc::kill(child.id() as i32, libc::SIGINT) }, 0);
    let out = child.wait_with_output().unwrap();
    let took = sent.elapsed();
    // The workers stop at the next pixel; most of this is writing two images.
    assert!(took < Duration::from_secs(2), "took {took:?} to stop");
    assert_eq!(out.status.code(), Some(128 + libc::SIGINT), "exit status tells the job did not finish");

    let part = Partial::load(&d.join("out.exr")).unwrap();
    let done = part.state.done.count();
    assert!(done > 0 && !part.is_complete(), "{done} tiles done");
    assert!(part.is_consistent());
    // Finished tiles hold exactly the uninterrupted render's pixels; the others are empty.
    let empty = Film::new(1, 1).pixels[0];
    for t in 0..part.state.done.len() {
        let tile = part.state.tile(t);
        let got = part.state.film.crop(tile);
        if part.state.done.get(t) {
            assert!(got == reference.crop(tile), "tile {t} differs from the uninterrupted render");
        } else {
            assert!(got.pixels.iter().all(|p| *p == empty), "unfinished tile {t} is not empty");
        }
    }
    // The checkpoint saved at the interruption has the same tiles, and resuming finishes it,
    // writing over the render's own partial image without --force.
    assert_eq!(Partial::load(&d.join("ck.exr")).unwrap().state.done, part.state.done);
    ok(&args(SLOW, &["-o", "out.exr", "--checkpoint", "ck.exr"]), d);
    assert!(std::fs::read(d.join("out.exr")).unwrap() == std::fs::read(path).unwrap());
}

/// Library level: a render stopped after some tiles, saved, loaded and resumed, equals one
/// uninterrupted render, whatever the thread counts.
#[test]
fn stopped_saved_and_resumed_equals_uninterrupted() {
    let mut desc = tress::demo::description(1500, 2);
    (desc.settings.width, desc.settings.height, desc.settings.spp) = (70, 50, 2);
    let (world, _) = tress::prepare::prepare(&desc).unwrap();
    let pool = |n| rayon::ThreadPoolBuilder::new().num_threads(n).build().unwrap();
    let (whole, _) = pool(2).install(|| tress::render::render(&world, None));

    let region = Region::full(70, 50);
    let cancel = std::sync::atomic::AtomicBool::new(false);
    let stop_after_five = |s: &std::sync::Mutex<TiledFilm>| {
        if s.lock().unwrap().done.count() >= 5 {
            cancel.store(true, std::sync::atomic::Ordering::Relaxed);
        }
    };
    let control = Control { cancel: Some(&cancel), after_tile: Some(&stop_after_five), ..Control::default() };
    let (stopped, _) = pool(2).install(|| render_tiles(&world, TiledFilm::new(region), &control));
    assert!(stopped.done.count() >= 5 && !stopped.done.is_full());

    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("ck.exr");
    let fp = tress::partial::fingerprint(&world);
    Partial { state: stopped, full: (70, 50), fingerprint: fp, farm_tile: None }.save(&path).unwrap();
    let loaded = Partial::load(&path).unwrap();
    assert_eq!(loaded.fingerprint, fp);
    let (resumed, _) = pool(1).install(|| render_tiles(&world, loaded.state, &Control::default()));
    assert!(resumed.done.is_full());
    assert!(resumed.film == whole);
}

#[test]
fn frames_move_the_camera_and_read_per_frame_files() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let mut s = tress::geometry::StrandSet::new();
    for frame in 1..=2u32 {
        s.push_strand((0..8).map(|i| (glam::Vec3::new(frame as f32 * 0.2 - 0.3, i as f32 * 0.1 - 0.4, 0.0), 0.05)));
        tress::io::cem_hair::write_hair(&d.join(format!("strands.{frame:04}.hair")), &s).unwrap();
    }
    let scene = "[camera]\n[[camera.key]]\nframe = 1\neye = [0, 0, 3]\ntarget = [0, 0, 0]\n\
        [[camera.key]]\nframe = 3\neye = [0, 0, 5]\ntarget = [0, 0, 0]\n\
        [render]\nresolution = [32, 24]\nspp = 1\n\
        [[light]]\ntype = \"environment\"\nradiance = [1, 1, 1]\n\
        [[hair]]\nfile = \"strands.####.hair\"\nmaterial = { type = \"diffuse\", color = [1, 1, 1] }\n";
    std::fs::write(d.join("anim.toml"), scene).unwrap();
    for frame in ["1", "2"] {
        ok(&["render", "anim.toml", "--frame", frame, "-o", &format!("f{frame}.png"), "--quiet"], d);
    }
    let (a, b) = (std::fs::read(d.join("f1.png")).unwrap(), std::fs::read(d.join("f2.png")).unwrap());
    assert!(a != b, "frames 1 and 2 should differ");
    let info = tress(&["info", "anim.toml", "--frame", "2"], d);
    assert!(String::from_utf8_lossy(&info.stdout).contains("(2 strands, 14 segments)"));
    let missing = tress(&["render", "anim.toml", "--frame", "3", "-o", "f3.png"], d);
    assert!(String::from_utf8_lossy(&missing.stderr).contains("strands.0003.hair"));
    let none = tress(&["render", "anim.toml", "-o", "f.png"], d);
    assert!(String::from_utf8_lossy(&none.stderr).contains("--frame"));
    // The example scene renders any frame.
    let example = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/animated.toml");
    let e = example.to_str().unwrap();
    ok(&["render", e, "--frame", "30", "--resolution", "24x16", "--spp", "1", "-o", "ex.png", "--quiet"], d);
}

#[test]
fn memory_limit_refuses_before_building_with_the_estimate() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let out = tress(&args(QUICK, &["--memory-limit", "1M", "-o", "x.png"]), d);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(!out.status.success(), "{err}");
    assert!(err.contains("needs an estimated") && err.contains("more than the memory limit of 1.0 MiB"), "{err}");
    assert!(!err.contains("scene build"), "refused before building: {err}");
    assert!(!d.join("x.png").exists());
    ok(&args(QUICK, &["--memory-limit", "1G", "-o", "x.png"]), d);
    let out = tress(&args(QUICK, &["--memory-limit", "lots", "-o", "x.png"]), d);
    assert!(String::from_utf8_lossy(&out.stderr).contains("not a memory size"));
}
