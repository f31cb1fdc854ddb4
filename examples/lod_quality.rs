//! Measures what level of detail buys on a scene (default `scenes/lod_field.toml`):
//! - error: RMSE of linear RGB against a high-sample reference rendered without LOD, over
//!   the whole image and over the far region (pixels whose reference depth exceeds `FAR`),
//!   at 1, 4 and 16 spp, LOD off, on (as the scene sets it) and smooth;
//! - look: coverage and mean colour of the far region relative to the reference;
//! - cost: process CPU time (user + system) of the render alone, for each;
//! - flicker: a camera pull-back of `FRAMES` frames at a smaller resolution; the flicker is
//!   the RMS difference between consecutive frames over the far region, averaged over the
//!   sequence, at 4 spp without LOD, with it and with it smooth (`smooth = true` on every
//!   strand set), at 16 spp without, and at the reference spp without LOD.
//!
//! `cargo run --release --example lod_quality -- [SCENE.toml] [REFERENCE_SPP] [WIDTH HEIGHT] [FRAMES]`
//! (defaults: the scene's size, 256 spp, 24 frames; 0 frames skips the pull-back). The
//! figures go to stdout; what is being rendered goes to stderr as it starts, since the
//! whole run takes minutes.

use tress::film::Film;
use tress::prepare::prepare;
use tress::scene::Description;
use tress::stats::process_cpu_time;

/// Depth beyond which a pixel counts as far.
const FAR: f32 = 15.0;
/// How far the camera moves back per frame, along its viewing direction.
const STEP: f32 = 0.05;

/// How a render sees the scene's level of detail.
#[derive(Clone, Copy, PartialEq)]
enum Lod {
    /// Off: full detail.
    Off,
    /// As the scene file sets it.
    On,
    /// As the scene file sets it, with `smooth = true` on every strand set.
    Smooth,
}

impl Lod {
    fn name(self) -> &'static str {
        match self {
            Lod::Off => "off",
            Lod::On => "on",
            Lod::Smooth => "smooth",
        }
    }
}

/// Renders `desc` with `spp`, `seed` and level of detail `lod`; the film and the CPU
/// seconds the render took (scene preparation excluded).
fn render(desc: &Description, spp: u32, seed: u32, lod: Lod) -> (Film, f64) {
    let mut d = desc.clone();
    (d.settings.spp, d.settings.seed, d.settings.lod) = (spp, seed, lod != Lod::Off);
    if lod == Lod::Smooth {
        let sets = d.contents.hair.iter_mut().map(|h| &mut h.lod);
        let sets = sets
            .chain(d.contents.hair_systems.iter_mut().map(|h| &mut h.lod))
            .chain(d.contents.fur.iter_mut().map(|f| &mut f.lod));
        sets.flatten().for_each(|p| p.smooth = true);
    }
    let (world, _) = prepare(&d).expect("scene");
    let start = process_cpu_time();
    let film = tress::render::render(&world, None).0;
    (film, process_cpu_time().saturating_sub(start).as_secs_f64())
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

/// Mean coverage and mean colour (RGB mean) over the masked pixels.
fn look(f: &Film, mask: &[bool]) -> (f64, f64) {
    let (mut cov, mut col, mut n) = (0.0, 0.0, 0);
    for (p, &m) in f.pixels.iter().zip(mask) {
        if m {
            cov += p.coverage as f64;
            col += p.color.element_sum() as f64 / 3.0;
            n += 1;
        }
    }
    (cov / n.max(1) as f64, col / n.max(1) as f64)
}

/// Pixels of the far region: depth beyond [`FAR`] in `reference`.
fn far_mask(reference: &Film) -> Vec<bool> {
    reference.pixels.iter().map(|p| p.depth > FAR && p.depth.is_finite()).collect()
}

/// Mean frame-to-frame RMS difference over the far region of a pull-back rendered with
/// `spp` and level of detail `lod`; `masks` are the far regions of the reference frames.
fn flicker(desc: &Description, frames: u32, spp: u32, lod: Lod, masks: &mut Vec<Vec<bool>>) -> f64 {
    let back = (desc.camera.eye - desc.camera.target).normalize();
    let mut previous: Option<Film> = None;
    let mut sum = 0.0;
    for frame in 0..frames {
        eprintln!("  pull-back at {spp} spp, LOD {}: frame {} of {frames}", lod.name(), frame + 1);
        let mut d = desc.clone();
        d.camera.eye += back * (STEP * frame as f32);
        let film = render(&d, spp, 0, lod).0;
        if masks.len() <= frame as usize {
            masks.push(far_mask(&film));
        }
        if let Some(p) = &previous {
            // The far region of both frames.
            let both: Vec<bool> =
                masks[frame as usize].iter().zip(&masks[frame as usize - 1]).map(|(a, b)| *a && *b).collect();
            sum += rms(&film, p, &both);
        }
        previous = Some(film);
    }
    sum / (frames - 1) as f64
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let path = args.get(1).map_or("scenes/lod_field.toml", String::as_str);
    let ref_spp: u32 = args.get(2).map_or(256, |s| s.parse().expect("reference spp"));
    let mut desc = tress::io::scene_file::read(std::path::Path::new(path), None).expect("scene file").0;
    if let (Some(w), Some(h)) = (args.get(3), args.get(4)) {
        (desc.settings.width, desc.settings.height) = (w.parse().expect("width"), h.parse().expect("height"));
    }
    eprintln!("rendering the {ref_spp}-spp reference without LOD");
    let (reference, t_ref) = render(&desc, ref_spp, 0, Lod::Off);
    let all = vec![true; reference.pixels.len()];
    let far = far_mask(&reference);
    let (ref_cov, ref_col) = look(&reference, &far);
    println!(
        "{}x{}, reference {ref_spp} spp without LOD ({t_ref:.1} CPU s); far pixels (depth > {FAR}): {}",
        desc.settings.width,
        desc.settings.height,
        far.iter().filter(|&&m| m).count()
    );
    println!("far region reference: coverage {ref_cov:.4}, mean colour {ref_col:.4}");
    println!("spp lod     cpu_s  rmse_all  rmse_far  far_coverage(rel)    far_colour(rel)");
    // 16 spp also gives the cost where rendering dominates, and the error LOD at 4 spp
    // should be set against.
    for spp in [1, 4, 16] {
        for lod in [Lod::Off, Lod::On, Lod::Smooth] {
            eprintln!("rendering {spp} spp, LOD {}", lod.name());
            let (a, t) = render(&desc, spp, 1, lod);
            let (cov, col) = look(&a, &far);
            println!(
                "{spp:>3} {:>6} {t:6.2} {:9.5} {:9.5} {:9.4} ({:+5.1} %) {:9.4} ({:+5.1} %)",
                lod.name(),
                rms(&a, &reference, &all),
                rms(&a, &reference, &far),
                cov,
                100.0 * (cov / ref_cov - 1.0),
                col,
                100.0 * (col / ref_col - 1.0),
            );
        }
    }
    let frames: u32 = args.get(5).map_or(24, |s| s.parse().expect("frames"));
    if frames < 2 {
        return;
    }
    // The pull-back at a quarter of the size (each side halved).
    let mut small = desc.clone();
    (small.settings.width, small.settings.height) = (desc.settings.width / 2, desc.settings.height / 2);
    let mut masks = Vec::new();
    let reference = flicker(&small, frames, ref_spp, Lod::Off, &mut masks);
    println!(
        "flicker over {frames} frames ({}x{}, far region), and its ratio to {ref_spp} spp without LOD ({reference:.5}):",
        small.settings.width, small.settings.height
    );
    for (spp, lod) in [(4, Lod::Off), (4, Lod::On), (4, Lod::Smooth), (16, Lod::Off)] {
        let f = flicker(&small, frames, spp, lod, &mut masks);
        println!("{spp:>3} spp {:>6}: {f:.5} ({:.2}x)", lod.name(), f / reference);
    }
}
