//! A hair-system scene end to end: follicles grown on a mesh, expanded into clumps,
//! rendered with per-strand AOVs, the same on any number of threads.

use std::path::Path;
use tress::film::Film;
use tress::io::scene_file::parse;
use tress::math::rng::{hash_u32, unit_float};
use tress::prepare::prepare;

const SCENE: &str = r#"
[camera]
eye = [0.0, 0.5, 4.0]
target = [0.0, 0.0, 0.0]
[render]
resolution = [96, 72]
spp = 2
[[light]]
type = "distant"
direction = [0.3, 1.0, 0.5]
irradiance = [2.0, 2.0, 2.0]
[[mesh]]
shape = { type = "sphere", radius = 0.8 }
material = { type = "diffuse", color = [0.5, 0.5, 0.5] }
[[hair_system]]
follicles = { mesh = 1, placement = "grid", u = 16, v = 8, points_per_hair = 6, length = 0.6, droop = 1.0 }
hairs_per_clump = 12
sub_segments = 1
thinning = 0.3
clump_width = 0.1
hair_width = 0.01
noise = 2.0
"#;

fn render(threads: usize) -> Film {
    let desc = parse(SCENE, Path::new("inline.toml"), None).unwrap().0;
    let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
    pool.install(|| {
        let (world, _) = prepare(&desc).unwrap();
        tress::render::render(&world, None).0
    })
}

#[test]
fn hair_system_renders_the_same_on_one_and_two_threads() {
    assert_eq!(render(1), render(2));
}

#[test]
fn hair_pixels_carry_per_strand_aovs() {
    let film = render(2);
    let hair: Vec<_> = film.pixels.iter().filter(|p| p.object_id == 1.0).collect();
    assert!(hair.len() > 200, "only {} hair pixels", hair.len());
    // 16 x 8 grid follicles on the sphere; the pole rows of a UV sphere cover half of
    // their cells, so at most 128 clumps of 12 hairs.
    for p in &hair {
        assert!(p.strand_id >= 0.0 && p.strand_id < 128.0 * 12.0);
        assert_eq!(p.clump_id, (p.strand_id / 12.0).floor(), "clump = guide index");
        assert!((0.0..=1.0).contains(&p.strand_along), "{}", p.strand_along);
        assert!(p.root_uv.iter().all(|x| (0.0..=1.0).contains(x)), "{:?}", p.root_uv);
        assert_eq!(p.strand_random, unit_float(hash_u32(p.strand_id as u32)));
    }
    // Both roots and tips are seen, and many clumps.
    assert!(hair.iter().any(|p| p.strand_along < 0.3) && hair.iter().any(|p| p.strand_along > 0.7));
    let mut clumps: Vec<u32> = hair.iter().map(|p| p.clump_id as u32).collect();
    clumps.sort_unstable();
    clumps.dedup();
    assert!(clumps.len() > 20);
    // Pixels that are not hair have none of them.
    for p in film.pixels.iter().filter(|p| p.object_id != 1.0) {
        assert_eq!((p.strand_along, p.clump_id, p.strand_random, p.root_uv), (-1.0, -1.0, -1.0, [-1.0, -1.0]));
    }
}

#[test]
fn guides_from_a_hair_file_with_their_colours_and_a_transform() {
    use glam::Vec3;
    use tress::accel::Shape;
    use tress::geometry::StrandSet;
    let dir = tempfile::tempdir().unwrap();
    let mut guides = StrandSet::new();
    guides.push_strand((0..5).map(|k| (Vec3::new(0.0, k as f32 * 0.25, 0.0), 0.01)));
    guides.push_strand((0..5).map(|k| (Vec3::new(1.0, k as f32 * 0.25, 0.0), 0.01)));
    guides.colors = Some((0..10).map(|k| if k < 5 { [1.0, 0.0, 0.0] } else { [0.0, 0.0, 1.0] }).collect());
    tress::io::cem_hair::write_hair(&dir.path().join("guides.hair"), &guides).unwrap();
    let text = r#"
[camera]
eye = [0.0, 0.0, 5.0]
target = [0.0, 0.0, 0.0]
[[hair_system]]
file = "guides.hair"
colors = "guides"
transform = { scale = 2.0, translate = [0.0, 1.0, 0.0] }
hairs_per_clump = 7
clump_width = 0.0
hair_width = 0.02
diffuse_rand = 0.0
"#;
    let desc = parse(text, &dir.path().join("scene.toml"), None).unwrap().0;
    let geometry = tress::prepare::load_geometry(&desc).unwrap();
    let Shape::Strands(hair) = &geometry.shapes[0].0 else { panic!("not strands") };
    assert_eq!(hair.strand_count(), 14);
    // Transformed guides (scale 2, then up by 1); widths stay the system's, in world units.
    let tip = hair.position(hair.offsets[8] - 1);
    assert!((tip - Vec3::new(2.0, 3.0, 0.0)).length() < 1e-5, "{tip}");
    assert!(hair.points.iter().all(|p| (p[3] - 0.01).abs() < 1e-7));
    let colors = hair.colors.as_ref().unwrap();
    assert_eq!(colors[0], [1.0, 0.0, 0.0]);
    assert_eq!(*colors.last().unwrap(), [0.0, 0.0, 1.0]);
    // The root UV of guides without a surface is unknown.
    assert!(hair.strand_info.as_ref().unwrap().root_uv.is_empty());

    // A missing guide file: an error naming it.
    let desc = parse(&text.replace("guides.hair", "missing.hair"), &dir.path().join("scene.toml"), None).unwrap().0;
    let e = tress::prepare::load_geometry(&desc).err().unwrap().to_string();
    assert!(e.contains("missing.hair"), "{e}");
}
