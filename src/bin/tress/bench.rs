//! `tress bench`: BVH build time, memory per hair segment and ray throughput, laid out to
//! sit beside the Embree baseline (`scripts/bench-vs-embree.sh`).

use crate::options::{load, pool, Overrides};
use anyhow::Result;
use std::path::PathBuf;
use tress::bench::{light_direction, trace_primary, trace_shadow, Tracing};
use tress::prepare::prepare;
use tress::stats::Memory;

/// The arguments of `tress bench`.
#[derive(clap::Args)]
pub struct BenchArgs {
    /// Scene file (TOML), or a reference scene directory written by scripts/gen_scenes.py
    /// (scene.json, torus.obj, hairy_torus.hair); the built-in demo scene when omitted.
    scene: Option<PathBuf>,
    #[command(flatten)]
    overrides: Overrides,
    /// Thread counts to measure, comma separated (0 = every core).
    #[arg(long, value_delimiter = ',', default_value = "1,0")]
    thread_counts: Vec<usize>,
    /// Repetitions of each measurement (the median is reported).
    #[arg(long, default_value_t = 3)]
    reps: usize,
    /// How rays are traced, comma separated: one at a time (`single`, reported as
    /// `primary` / `shadow`), and a pixel's samples as one packet (`packet`, reported as
    /// `primary-packet` / `shadow-packet`).
    #[arg(long, value_name = "single|packet", value_delimiter = ',', default_value = "single,packet")]
    tracing: Vec<Tracing>,
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn list(v: &[f64]) -> String {
    v.iter().map(|x| format!("{x:.3}")).collect::<Vec<_>>().join(", ")
}

/// Builds the scene `reps` times, then traces its camera and shadow rays for each thread
/// count and way of tracing; prints `RESULT` lines.
pub fn run(args: &BenchArgs) -> Result<()> {
    let desc = load(args.scene.as_deref(), &args.overrides, None, false)?;
    let reps = args.reps.max(1);
    let all = pool(0)?.current_num_threads();
    let (mut builds, mut build_cpus) = (Vec::new(), Vec::new());
    let mut world = None;
    for _ in 0..reps {
        let (w, times) = pool(0)?.install(|| prepare(&desc))?;
        builds.push(times.build.as_secs_f64() * 1e3);
        build_cpus.push(times.build_cpu.as_secs_f64() * 1e3);
        world = Some(w);
    }
    let world = world.expect("at least one repetition");
    let m = Memory::of(&world.accel);
    let s = &world.settings;
    println!("scene: {} hair segments, {}x{} x {} spp camera rays", m.segments, s.width, s.height, s.spp);
    println!(
        "RESULT build_ms median {:.1} [{}] | build cpu ms (all threads) median {:.1} [{}] ({all} threads)",
        median(builds.clone()),
        list(&builds),
        median(build_cpus.clone()),
        list(&build_cpus)
    );
    let seg = m.segments.max(1) as f64;
    println!(
        "RESULT mem points {} B, bvh {} B, total {} B, bvh/segment {:.1} B, total/segment {:.1} B (meshes {} B, their bvh {} B)",
        m.strand_points,
        m.strand_bvh,
        m.strand_points + m.strand_bvh,
        m.strand_bvh as f64 / seg,
        m.bytes_per_segment(),
        m.mesh,
        m.mesh_bvh + m.top_bvh
    );
    let light = light_direction(&world);
    for &t in &args.thread_counts {
        let threads = if t == 0 { all } else { t };
        let pool = pool(threads)?;
        for &tracing in &args.tracing {
            let mut primary = Vec::new();
            let mut origins = Vec::new();
            for _ in 0..reps {
                let (o, r) = pool.install(|| trace_primary(&world, threads, tracing));
                primary.push(r);
                origins = o;
            }
            let shadow: Vec<_> =
                (0..reps).map(|_| pool.install(|| trace_shadow(&world, &origins, light, threads, tracing)).1).collect();
            let suffix = match tracing {
                Tracing::Single => "",
                Tracing::Packet => "-packet",
            };
            for (name, rates) in [("primary", &primary), ("shadow", &shadow)] {
                let wall: Vec<f64> = rates.iter().map(|r| r.mrays()).collect();
                let cpu: Vec<f64> = rates.iter().map(|r| r.mrays_cpu()).collect();
                println!(
                    "RESULT threads {threads} {:<15} Mrays/s median {:7.3} [{}] | cpu-time based {:7.3} [{}] | rays {}",
                    format!("{name}{suffix}"),
                    median(wall.clone()),
                    list(&wall),
                    median(cpu.clone()),
                    list(&cpu),
                    rates[0].rays
                );
            }
        }
    }
    Ok(())
}
