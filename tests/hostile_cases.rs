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
