//! Fur generation speed: grows a million hairs on a torus with one, then every, worker
//! thread and reports hairs per second of wall time, and per second of the process's CPU
//! time (the figure that stays meaningful on a machine shared with other jobs). Run with
//! `cargo bench --bench fur`.

use std::time::Instant;
use tress::fur::{grow, presets::preset, GrowOptions};
use tress::geometry::TriangleMesh;

fn main() {
    let mesh = TriangleMesh::torus(1.0, 0.35, 192, 96);
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    let mut thread_counts = vec![1, cores];
    thread_counts.dedup();
    // Squirrel clumps; Sheep curls and scraggles; both with their segment counts.
    for name in ["Squirrel", "Sheep"] {
        let mut desc = preset(name).expect("shipped preset");
        desc.density = 1_000_000;
        for &threads in &thread_counts {
            let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().expect("thread pool");
            let (start, cpu) = (Instant::now(), cpu_time::ProcessTime::now());
            let fur = pool.install(|| grow(&mesh, &desc, GrowOptions { seed: 1, ..Default::default() })).unwrap();
            let (secs, cpu_secs) = (start.elapsed().as_secs_f64(), cpu.elapsed().as_secs_f64());
            let hairs = fur.strands.strand_count() as f64;
            println!(
                "{name:<9} {threads} thread(s): {hairs} hairs, {} segments in {secs:.3} s = {:.0} hairs/s \
                 ({cpu_secs:.3} s CPU, {:.2} cores busy, {:.0} hairs per CPU second)",
                fur.strands.segment_count(),
                hairs / secs,
                cpu_secs / secs,
                hairs / cpu_secs
            );
        }
    }
}
