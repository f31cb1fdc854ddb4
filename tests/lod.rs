//! Level of detail end to end, on a small version of `scenes/lod_field.toml`: images
//! independent of the thread count, unchanged with LOD switched off, and levels that grow
//! with distance and with thinner hair; smooth LOD: independent of the thread count too,
//! the same look, and less change between two nearby frames of a camera move.

use std::path::Path;
use tress::film::Film;
use tress::hair_system::Placement;
use tress::prepare::prepare;
use tress::scene::{Description, GuideSource};

/// The benchmark scene at 240x135, 2 samples, a tenth of the follicles, `start = 1`.
fn small_field() -> Description {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/lod_field.toml");
    let mut desc = tress::io::scene_file::read(&path, None).unwrap().0;
    (desc.settings.width, desc.settings.height, desc.settings.spp) = (240, 135, 2);
    for h in &mut desc.contents.hair_systems {
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
    none.contents.hair_systems.iter_mut().for_each(|h| h.lod = None);
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

/// [`small_field`] pruned from the benchmark's footprint of 4 widths, where its coarse
/// strands are drawn semi-transparent (`spread = 4`), and with `smooth` as given.
fn spread_field(smooth: bool) -> Description {
    let mut desc = small_field();
    let with = |p: tress::accel::lod::LodParams| tress::accel::lod::LodParams { start: 4.0, smooth, ..p };
    desc.contents.hair_systems.iter_mut().for_each(|h| h.lod = h.lod.map(with));
    desc
}

/// RMS difference of linear RGB between `a` and `b` over the pixels farther than 15 units
/// in both.
fn far_difference(a: &Film, b: &Film) -> f64 {
    let (mut sum, mut n) = (0.0, 0);
    for (p, q) in a.pixels.iter().zip(&b.pixels) {
        if p.depth > 15.0 && q.depth > 15.0 && p.depth.is_finite() && q.depth.is_finite() {
            sum += (p.color - q.color).length_squared() as f64 / 3.0;
            n += 1;
        }
    }
    assert!(n > 1000, "too few far pixels: {n}");
    (sum / n as f64).sqrt()
}

#[test]
fn smooth_lod_is_the_same_with_one_and_two_threads() {
    let desc = spread_field(true);
    assert_eq!(bits(&render(&desc, 1)), bits(&render(&desc, 2)));
}

#[test]
fn smooth_lod_keeps_the_look_and_changes_less_from_frame_to_frame() {
    // Two frames of a pull-back, the camera one twentieth of a unit apart.
    let frames = |desc: &Description| {
        let mut next = desc.clone();
        next.camera.eye += (desc.camera.eye - desc.camera.target).normalize() * 0.05;
        (render(desc, 2), render(&next, 2))
    };
    let (a, b) = frames(&spread_field(false));
    let (sa, sb) = frames(&spread_field(true));
    let (hard, soft) = (far_difference(&a, &b), far_difference(&sa, &sb));
    eprintln!("far difference between frames: LOD {hard:.5}, smooth LOD {soft:.5}");
    assert!(soft < 0.75 * hard, "smooth {soft} vs {hard}");
    // The same image on average: mean far colour within 2 %.
    let mean = |f: &Film| f.pixels.iter().filter(|p| p.depth > 15.0).map(|p| p.color.element_sum() as f64).sum::<f64>();
    let (m, sm) = (mean(&a), mean(&sa));
    assert!((sm / m - 1.0).abs() < 0.02, "mean far colour {sm} vs {m}");
}
