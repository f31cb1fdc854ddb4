//! Raw strand and mesh files as scenes of their own (`tress render|info|export FILE` for
//! `.hair`, `.ply`, `.obj`): framed, lit, with widths relative to their size when they
//! have none; TOML scenes without a camera; width overrides on `[[import]]` and the
//! command line; `.hair` export round trips.

use glam::Vec3;
use std::path::Path;
use std::process::Command;
use tress::geometry::StrandSet;
use tress::io::read_imported;
use tress::prepare::prepare;
use tress::scene::{Description, HairSource};

fn tress(args: &[&str], dir: &Path) -> (bool, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_tress")).args(args).current_dir(dir).output().unwrap();
    (
        out.status.success(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// 40 strands of 6 points in a 2 × 2 patch at height 0..3, each a different colour, with
/// transparency and tapering widths, and one single-point strand.
fn groom() -> StrandSet {
    let mut s = StrandSet::new();
    for i in 0..40 {
        let (x, z) = ((i % 8) as f32 * 0.25 - 1.0, (i / 8) as f32 * 0.4 - 1.0);
        s.push_strand((0..6).map(|k| (Vec3::new(x + 0.05 * k as f32, 0.6 * k as f32, z), 0.04 - 0.005 * k as f32)));
    }
    s.push_strand([(Vec3::new(3.0, 0.0, 0.0), 0.01)]);
    let n = s.points.len();
    s.colors = Some((0..n).map(|i| [i as f32 / n as f32, 0.5, 1.0 - i as f32 / n as f32]).collect());
    s.opacity = Some((0..n).map(|i| 1.0 - (i % 5) as f32 * 0.1).collect());
    s
}

/// The same strands as a PLY file: vertex counts, no widths, byte colours.
fn groom_ply() -> String {
    let g = groom();
    let n = g.strand_count() - 1;
    let points = g.offsets[n] as usize;
    let mut text = format!(
        "ply\nformat ascii 1.0\nelement vertex {points}\nproperty float x\nproperty float y\nproperty float z\n\
         property uchar red\nproperty uchar green\nproperty uchar blue\nelement strand {n}\nproperty int vertex_count\nend_header\n"
    );
    for p in &g.points[..points] {
        text += &format!("{} {} {} 200 120 40\n", p[0], p[1], p[2]);
    }
    for i in 0..n {
        text += &format!("{}\n", g.offsets[i + 1] - g.offsets[i]);
    }
    text
}

/// The strands as OBJ `l` lines, one line element per segment.
fn groom_obj() -> String {
    let g = groom();
    let mut text = String::new();
    for p in &g.points {
        text += &format!("v {} {} {}\n", p[0], p[1], p[2]);
    }
    for i in 0..g.strand_count() - 1 {
        for k in g.offsets[i]..g.offsets[i + 1] - 1 {
            text += &format!("l {} {}\n", k + 1, k + 2);
        }
    }
    text
}

fn small(mut desc: Description) -> Description {
    (desc.settings.width, desc.settings.height, desc.settings.spp) = (48, 36, 1);
    desc
}

/// Hair pixels and lit pixels of a render.
fn coverage(desc: &Description) -> (usize, usize) {
    let (world, _) = prepare(desc).unwrap();
    let film = tress::render::render(&world, None).0;
    let hair = film.pixels.iter().filter(|p| p.strand_id >= 0.0).count();
    let lit = film.pixels.iter().filter(|p| p.strand_id >= 0.0 && p.color.max_element() > 0.02).count();
    (hair, lit)
}

fn inline(desc: &Description, i: usize) -> &StrandSet {
    let HairSource::Inline(s) = &desc.contents.hair[i].source else { panic!("not inline") };
    s
}

#[test]
fn raw_hair_ply_and_obj_files_render_framed_and_lit() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    tress::io::cem_hair::write_hair(&d.join("g.hair"), &groom()).unwrap();
    std::fs::write(d.join("g.ply"), groom_ply()).unwrap();
    std::fs::write(d.join("g.obj"), groom_obj()).unwrap();
    for name in ["g.hair", "g.ply", "g.obj"] {
        let imported = read_imported(&d.join(name)).unwrap();
        let (desc, warnings) = imported.into_description();
        assert!(warnings.iter().any(|w| w.contains("no camera")), "{name}: {warnings:?}");
        assert!(warnings.iter().any(|w| w.contains("no lights")), "{name}: {warnings:?}");
        assert_eq!(inline(&desc, 0).strand_count(), if name == "g.hair" { 41 } else { 40 }, "{name}");
        // The camera sees the groom, lit. The `.hair` strands are 0.02 to 0.08 wide; PLY and
        // OBJ ones, without widths, a thousandth of the groom (thin at 48 × 36 pixels).
        let (hair, lit) = coverage(&small(desc));
        let least = if name == "g.hair" { 100 } else { 15 };
        assert!(hair > least && lit > hair / 2, "{name}: {hair} hair pixels, {lit} lit");
    }
    // Without widths, PLY and OBJ strands are a thousandth of the groom's size wide, said once.
    let (desc, warnings) = read_imported(&d.join("g.obj")).unwrap().into_description();
    let w: Vec<_> = warnings.iter().filter(|w| w.contains("no width")).collect();
    assert_eq!(w.len(), 1, "{warnings:?}");
    let diagonal = (Vec3::new(2.0, 3.0, 1.6) + Vec3::new(0.25, 0.0, 0.0)).length();
    let r = inline(&desc, 0).points[0][3];
    assert!((r - 0.5e-3 * diagonal).abs() < 0.05 * r, "{r} vs {}", 0.5e-3 * diagonal);
    // The command line renders and describes them.
    for name in ["g.hair", "g.ply", "g.obj"] {
        let out = format!("{name}.png");
        let (ok, _, err) = tress(&["render", name, "-o", &out, "--resolution", "24x18", "--spp", "1", "--quiet"], d);
        assert!(ok && d.join(&out).exists(), "{name}: {err}");
        let (ok, out, err) = tress(&["info", name], d);
        assert!(ok && out.contains("strands"), "{name}: {out} {err}");
    }
}

#[test]
fn export_to_hair_keeps_points_widths_colours_and_transparency() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let g = groom();
    tress::io::cem_hair::write_hair(&d.join("in.hair"), &g).unwrap();
    let (ok, _, err) = tress(&["export", "in.hair", "-o", "out.hair"], d);
    assert!(ok, "{err}");
    let back = tress::io::cem_hair::read_hair(&d.join("out.hair")).unwrap();
    assert_eq!(back.offsets, g.offsets);
    assert_eq!(back.points, g.points);
    assert_eq!(back.colors, g.colors);
    assert_eq!(back.opacity, g.opacity);
    // A PLY groom's points and colours come through too, with the width given.
    std::fs::write(d.join("g.ply"), groom_ply()).unwrap();
    let (ok, _, err) = tress(&["export", "g.ply", "-o", "ply.hair", "--hair-width", "0.02"], d);
    assert!(ok, "{err}");
    let back = tress::io::cem_hair::read_hair(&d.join("ply.hair")).unwrap();
    assert_eq!(back.strand_count(), 40);
    for (a, b) in back.points.iter().zip(&g.points) {
        assert!((Vec3::from_slice(&a[..3]) - Vec3::from_slice(&b[..3])).length() < 1e-5);
        assert!((a[3] - 0.01).abs() < 1e-7, "{}", a[3]);
    }
    let c = back.colors.as_ref().unwrap()[0];
    assert!((c[0] - 200.0 / 255.0).abs() < 1e-6 && (c[2] - 40.0 / 255.0).abs() < 1e-6, "{c:?}");
}

#[test]
fn toml_scenes_without_a_camera_frame_their_geometry() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    tress::io::cem_hair::write_hair(&d.join("g.hair"), &groom()).unwrap();
    let scene = "[render]\nresolution = [48, 36]\nspp = 1\n[[light]]\ntype = \"distant\"\ndirection = [0, 1, 1]\n\
                 irradiance = [3, 3, 3]\n[[hair]]\nfile = \"g.hair\"\nmaterial = { type = \"tube\", diffuse = [0.8, 0.6, 0.4] }\n";
    std::fs::write(d.join("s.toml"), scene).unwrap();
    let (desc, warnings) = tress::io::scene_file::read(&d.join("s.toml"), None).unwrap();
    assert!(warnings.iter().any(|w| w.contains("no [camera]")), "{warnings:?}");
    // Framed: the groom's centre is looked at, and its hairs fill the image's middle.
    let centre = Vec3::new(0.0, 1.5, 0.0);
    let to = (desc.camera.target - desc.camera.eye).normalize();
    assert!(((centre - desc.camera.eye).normalize() - to).length() < 0.35, "{:?}", desc.camera);
    let (hair, lit) = coverage(&desc);
    assert!(hair > 100 && lit > hair / 2, "{hair} hair pixels, {lit} lit");
}

#[test]
fn import_width_and_radius_scale_and_the_hair_width_option() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    std::fs::write(d.join("g.ply"), groom_ply()).unwrap();
    tress::io::cem_hair::write_hair(&d.join("g.hair"), &groom()).unwrap();
    let head = "[camera]\neye = [0, 1, 8]\ntarget = [0, 1, 0]\n";
    let read = |import: &str| {
        let text = format!("{head}[[import]]\n{import}\n");
        tress::io::scene_file::parse(&text, &d.join("s.toml"), None).map(|(d, _)| d)
    };
    let ply = read("file = \"g.ply\"\nwidth = 0.1").unwrap();
    assert!(inline(&ply, 0).points.iter().all(|p| p[3] == 0.05));
    // radius_scale multiplies the file's own radii.
    let scaled = read("file = \"g.hair\"\nradius_scale = 2").unwrap();
    let radii = |desc: &Description| {
        tress::prepare::load_geometry(desc).unwrap().shapes.into_iter().find_map(|(s, _)| match s {
            tress::accel::Shape::Strands(s) => Some(s.points.iter().map(|p| p[3]).collect::<Vec<_>>()),
            _ => None,
        })
    };
    let want: Vec<f32> = groom().points.iter().map(|p| 2.0 * p[3]).collect();
    assert_eq!(radii(&scaled).unwrap(), want);
    for bad in ["file = \"g.ply\"\nwidth = -1", "file = \"g.ply\"\nradius_scale = 0"] {
        let e = read(bad).unwrap_err().to_string();
        assert!(e.contains("import 1") && (e.contains("width") || e.contains("radius_scale")), "{e}");
    }
    let e = tress(&["render", "g.ply", "--hair-width", "-2"], d).2;
    assert!(e.contains("-2"), "{e}");
}
