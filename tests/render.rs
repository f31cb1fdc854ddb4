//! End-to-end renders of the demo scene: a golden image with a tolerance, and
//! bit-identical images whatever the thread count.

use std::path::Path;
use tress::film::{srgb_encode, Film};
use tress::scene::prepare;

/// A small demo render: 160x120, 4 samples, 6000 strands (the full scene's look, quickly).
fn small_demo(threads: usize) -> Film {
    let mut desc = tress::demo::description(6000, 1);
    desc.settings.width = 160;
    desc.settings.height = 120;
    desc.settings.spp = 4;
    let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
    pool.install(|| {
        let (world, _) = prepare(&desc).unwrap();
        tress::render::render(&world, None).0
    })
}

fn to_rgb8(film: &Film) -> Vec<u8> {
    film.pixels.iter().flat_map(|p| p.color.to_array().map(srgb_encode)).collect()
}

#[test]
fn same_image_with_one_and_two_threads() {
    let a = small_demo(1);
    let b = small_demo(2);
    // Compare bit patterns so NaN would also be caught.
    let bits = |f: &Film| f.pixels.iter().flat_map(|p| p.color.to_array().map(f32::to_bits)).collect::<Vec<_>>();
    assert_eq!(bits(&a), bits(&b));
    assert_eq!(a, b);
}

#[test]
fn demo_matches_the_golden_image() {
    let film = small_demo(2);
    let got = to_rgb8(&film);
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/golden_demo.png");
    if std::env::var_os("TRESS_BLESS").is_some() {
        image::save_buffer(&path, &got, film.width, film.height, image::ColorType::Rgb8).unwrap();
    }
    let want = image::open(&path).expect("reference image (regenerate with TRESS_BLESS=1)").to_rgb8();
    assert_eq!((want.width(), want.height()), (film.width, film.height));
    // Tolerance: small per-pixel differences from floating-point changes are fine; a
    // shading, sampling or geometry change moves the mean or many pixels.
    let diffs: Vec<i32> = got.iter().zip(want.as_raw()).map(|(&a, &b)| (a as i32 - b as i32).abs()).collect();
    let mean = diffs.iter().sum::<i32>() as f64 / diffs.len() as f64;
    let large = diffs.iter().filter(|&&d| d > 16).count() as f64 / diffs.len() as f64;
    assert!(mean < 1.0 && large < 0.01, "mean difference {mean:.3}, {:.2} % of values differ by > 16", large * 100.0);
    // The image is not trivially black or saturated: hair, torus and ground are all lit.
    let avg = got.iter().map(|&v| v as f64).sum::<f64>() / got.len() as f64;
    assert!(avg > 20.0 && avg < 200.0, "mean value {avg}");
    assert!(film.pixels.iter().any(|p| p.strand_id >= 0.0), "no hair visible");
}
