//! Level of detail end to end, on a small version of `scenes/lod_field.toml`: images
//! independent of the thread count, unchanged with LOD switched off, and levels that grow
//! with distance and with thinner hair.

use std::path::Path;
use tress::film::Film;
use tress::hair::Placement;
use tress::scene::{prepare, Description, GuideSource};

/// The benchmark scene at 240x135, 2 samples, a tenth of the follicles, `start = 1`.
fn small_field() -> Description {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/lod_field.toml");
    let mut desc = tress::io::scene_file::read_scene(&path).unwrap();
    (desc.settings.width, desc.settings.height, desc.settings.spp) = (240, 135, 2);
    for h in &mut desc.hair_systems {
        if let GuideSource::Follicles { params, .. } = &mut h.guides {
            params.placement = Placement::Random { count: 2000 };
        }
        assert!(h.lod.is_some(), "the benchmark scene asks for level of detail");
        // Pruning from a footprint of one width (the thesis' rule), so that the near fur
        // already uses several levels.
        h.lod = h.lod.map(|p| tress::accel::lod::LodParams { start: 1.0, ..p });
    }
    desc
}

fn render(desc: &Description, threads: usize) -> Film {
    let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
    pool.install(|| {
        let (world, _) = prepare(desc).unwrap();
        tress::render::render(&world, None).0
    })
}

fn bits(f: &Film) -> Vec<u32> {
    f.pixels.iter().flat_map(|p| [p.color.x, p.color.y, p.color.z, p.lod_level].map(f32::to_bits)).collect()
}

#[test]
fn lod_image_is_the_same_with_one_and_two_threads() {
    let desc = small_field();
    assert_eq!(bits(&render(&desc, 1)), bits(&render(&desc, 2)));
}

#[test]
fn switching_lod_off_renders_as_without_lod() {
    let mut off = small_field();
    off.settings.lod = false;
    let mut none = small_field();
    none.hair_systems.iter_mut().for_each(|h| h.lod = None);
    let (a, b) = (render(&off, 2), render(&none, 2));
    assert_eq!(bits(&a), bits(&b));
    assert!(a.pixels.iter().all(|p| p.lod_level <= 0.0));
    assert_ne!(bits(&a), bits(&render(&small_field(), 2)), "LOD on changes the far fur");
}

#[test]
fn levels_grow_with_distance_and_thinner_hair() {
    let film = render(&small_field(), 2);
    // Mean level of the hair pixels of one image half (left: thin fur, right: thick) in the
    // rows whose depth lies in a range.
    let mean_level = |left: bool, near: f32, far: f32| {
        let (mut sum, mut n) = (0.0, 0);
        for (i, p) in film.pixels.iter().enumerate() {
            let x = i as u32 % film.width;
            if p.lod_level >= 0.0 && (x < film.width / 2) == left && (near..far).contains(&p.depth) {
                sum += p.lod_level as f64;
                n += 1;
            }
        }
        assert!(n > 10, "too few hair pixels at depth {near}..{far}");
        sum / n as f64
    };
    for left in [true, false] {
        assert!(mean_level(left, 0.0, 4.0) < mean_level(left, 12.0, 70.0), "left {left}");
    }
    // The thin fur, four times thinner, is coarser (log_1.5 4 = 3.4 levels) until both
    // reach the coarsest level far away.
    for (near, far) in [(0.0, 4.0), (4.0, 8.0)] {
        assert!(mean_level(true, near, far) > mean_level(false, near, far) + 1.0, "{near}..{far}");
    }
}
