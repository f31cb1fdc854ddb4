//! Measures what level of detail buys on a scene (default `scenes/lod_field.toml`): render
//! time at equal samples per pixel, RMSE against a high-sample reference rendered without
//! LOD, noise (RMS difference between two seeds), and coverage and mean colour of the far
//! region (pixels whose reference depth exceeds `FAR`).
//!
//! `cargo run --release --example lod_quality -- [SCENE.toml] [REFERENCE_SPP]`

use std::time::Instant;
use tress::film::Film;
use tress::scene::{prepare, Description};

/// Depth beyond which a pixel counts as far.
const FAR: f32 = 15.0;

fn render(desc: &Description, spp: u32, seed: u32, lod: bool) -> (Film, f64) {
    let mut d = desc.clone();
    (d.settings.spp, d.settings.seed, d.settings.lod) = (spp, seed, lod);
    let (world, _) = prepare(&d).expect("scene");
    let start = Instant::now();
    let film = tress::render::render(&world, None).0;
    (film, start.elapsed().as_secs_f64())
}

/// RMS difference of linear RGB over the pixels `mask` selects.
fn rms(a: &Film, b: &Film, mask: &[bool]) -> f64 {
    let (mut sum, mut n) = (0.0, 0);
    for ((p, q), &m) in a.pixels.iter().zip(&b.pixels).zip(mask) {
        if m {
            sum += (p.color - q.color).length_squared() as f64 / 3.0;
            n += 1;
        }
    }
    (sum / n.max(1) as f64).sqrt()
}

/// Mean coverage and mean luminance-like colour (RGB mean) over the masked pixels.
fn look(f: &Film, mask: &[bool]) -> (f64, f64) {
    let (mut cov, mut col, mut n) = (0.0, 0.0, 0);
    for (p, &m) in f.pixels.iter().zip(mask) {
        if m {
            cov += p.coverage as f64;
            col += p.color.element_sum() as f64 / 3.0;
            n += 1;
        }
    }
    (cov / n as f64, col / n as f64)
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let path = args.get(1).map_or("scenes/lod_field.toml", String::as_str);
    let ref_spp: u32 = args.get(2).map_or(64, |s| s.parse().expect("reference spp"));
    let desc = tress::io::scene_file::read_scene(std::path::Path::new(path)).expect("scene file");
    let (reference, t_ref) = render(&desc, ref_spp, 0, false);
    let all = vec![true; reference.pixels.len()];
    let far: Vec<bool> = reference.pixels.iter().map(|p| p.depth > FAR && p.depth.is_finite()).collect();
    let (ref_cov, ref_col) = look(&reference, &far);
    println!(
        "reference: {ref_spp} spp without LOD, {t_ref:.2} s; far pixels (depth > {FAR}): {}",
        far.iter().filter(|&&m| m).count()
    );
    println!("far region reference: coverage {ref_cov:.4}, mean colour {ref_col:.4}");
    println!("spp lod  time_s  rmse_all  rmse_far  seed_noise_far  far_coverage(rel)  far_colour(rel)");
    for spp in [1, 4] {
        for lod in [false, true] {
            let (a, t) = render(&desc, spp, 1, lod);
            let (b, _) = render(&desc, spp, 2, lod);
            let (cov, col) = look(&a, &far);
            println!(
                "{spp:>3} {:>4} {t:7.2} {:9.5} {:9.5} {:15.5} {:10.4} ({:+.1} %) {:9.4} ({:+.1} %)",
                if lod { "on" } else { "off" },
                rms(&a, &reference, &all),
                rms(&a, &reference, &far),
                rms(&a, &b, &far),
                cov,
                100.0 * (cov / ref_cov - 1.0),
                col,
                100.0 * (col / ref_col - 1.0),
            );
        }
    }
}
