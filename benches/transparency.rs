//! Cost of fast transparency (thesis section 2.2.8): renders the furry pillow of
//! `scenes/furry_pillow.toml` (fewer hairs, a smaller image) with the direct integrator,
//! once with opaque fur and once with the scene's 50 % tip opacity, and prints the ratio
//! of their render times. Each render runs on one thread and is timed by the process's
//! CPU time (steady on a shared machine), best of three. Run with
//! `cargo bench --bench transparency`.

use std::path::Path;
use std::time::Duration;
use tress::fur::Scalar;
use tress::io::scene_file::read;
use tress::prepare::prepare;
use tress::stats::process_cpu_time;
use tress::world::Integrator;

fn main() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/furry_pillow.toml");
    let mut desc = read(&path, None).expect("the shipped scene reads").0;
    desc.settings.width = 320;
    desc.settings.height = 240;
    desc.settings.spp = 4;
    desc.settings.integrator = Integrator::Direct;
    desc.contents.fur[0].description.density = 40_000;
    let tip = desc.contents.fur[0].description[Scalar::TipOpacity].value;
    assert!(tip < 1.0, "the scene's fur is semi-transparent");
    let pool = rayon::ThreadPoolBuilder::new().num_threads(1).build().expect("thread pool");
    let mut times = Vec::new();
    for opacity in [1.0, tip] {
        desc.contents.fur[0].description[Scalar::TipOpacity].value = opacity;
        let (world, _) = prepare(&desc).expect("the scene prepares");
        let mut best = Duration::MAX;
        let mut rays = 0;
        for _ in 0..3 {
            let cpu = process_cpu_time();
            let (_, stats) = pool.install(|| tress::render::render(&world, None));
            best = best.min(process_cpu_time().saturating_sub(cpu));
            rays = stats.rays;
        }
        println!("tip opacity {opacity:.2}: {:.3} s CPU (best of 3), {rays} rays", best.as_secs_f64());
        times.push(best.as_secs_f64());
    }
    println!("transparent / opaque render time: {:.2}x (the target is at most 1.5x)", times[1] / times[0]);
}
