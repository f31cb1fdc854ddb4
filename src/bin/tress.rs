//! The `tress` command: render a scene, print what a scene holds, benchmark tracing.

use anyhow::{Context, Result};
use clap::{Parser, Subcommand};
use indicatif::{ProgressBar, ProgressStyle};
use std::path::{Path, PathBuf};
use tress::accel::Shape;
use tress::bench::{light_direction, read_reference_scene, trace_primary, trace_shadow, Memory};
use tress::scene::{prepare, Description, World};
use tress::shading::Material;
use tress::stats::{human_bytes, peak_memory_bytes};

#[derive(Parser)]
#[command(name = "tress", version, about = "A ray tracer for hair and fur")]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Render a scene file (or the built-in demo scene) to an image.
    Render {
        /// Scene file: TOML, Maya ASCII (.ma), pbrt-v4 (.pbrt) or USD text (.usda), or a
        /// reference scene directory of shared/scenes/gen_scenes.py; the built-in demo scene
        /// when omitted.
        scene: Option<PathBuf>,
        #[command(flatten)]
        overrides: Overrides,
        /// Output image: .png (8-bit sRGB) or .exr (linear float with AOVs).
        #[arg(short, long, default_value = "tress.png")]
        output: PathBuf,
        /// Do not show the progress bar.
        #[arg(long)]
        quiet: bool,
    },
    /// Print the counts and memory of a scene (the demo scene when omitted).
    Info {
        /// Scene file (TOML).
        scene: Option<PathBuf>,
        /// Strands in the demo scene.
        #[arg(long, default_value_t = tress::demo::DEMO_STRANDS)]
        demo_strands: u32,
    },
    /// Write the scene's render strands (all strand sets, in world space) to a file.
    Export {
        /// Scene file (TOML, .ma, .pbrt or .usda); the built-in demo scene when omitted.
        scene: Option<PathBuf>,
        /// Output file: a Cem Yuksel .hair file (strands) or a USD text .usda file (strands
        /// as linear BasisCurves and meshes).
        #[arg(short, long)]
        output: PathBuf,
        /// Strands in the demo scene.
        #[arg(long, default_value_t = tress::demo::DEMO_STRANDS)]
        demo_strands: u32,
    },
    /// Grow fur: export it, list the presets.
    Fur {
        #[command(subcommand)]
        command: FurCommand,
    },
    /// Measure BVH build time, ray throughput and memory per hair segment.
    Bench {
        /// Scene file (TOML), or a reference scene directory written by
        /// shared/scenes/gen_scenes.py (scene.json, torus.obj, hairy_torus.hair);
        /// the built-in demo scene when omitted.
        scene: Option<PathBuf>,
        #[command(flatten)]
        overrides: Overrides,
        /// Thread counts to measure, comma separated (0 = every core).
        #[arg(long, value_delimiter = ',', default_value = "1,0")]
        thread_counts: Vec<usize>,
        /// Repetitions of each measurement (the median is reported).
        #[arg(long, default_value_t = 3)]
        reps: usize,
    },
}

#[derive(Subcommand)]
enum FurCommand {
    /// Write the fur a scene grows (every [[fur]] entry, in world space) to a file.
    Export {
        /// Scene file (TOML).
        scene: PathBuf,
        /// Output file: a Cem Yuksel .hair file.
        #[arg(short, long)]
        output: PathBuf,
    },
    /// List the fur presets by Maya's names.
    Presets,
}

/// Settings that override the scene file's.
#[derive(clap::Args, Default)]
struct Overrides {
    /// Samples per pixel.
    #[arg(long)]
    spp: Option<u32>,
    /// Worker threads (0 = every core).
    #[arg(long)]
    threads: Option<usize>,
    /// Image size as WIDTHxHEIGHT, e.g. 640x480.
    #[arg(long, value_parser = parse_resolution)]
    resolution: Option<(u32, u32)>,
    /// Seed of every random decision.
    #[arg(long)]
    seed: Option<u32>,
    /// Light transport: direct, final-gather or path.
    #[arg(long, value_parser = parse_integrator)]
    integrator: Option<tress::scene::Integrator>,
    /// Partial hits collected per traversal through semi-transparent hair (1 re-traces
    /// after every hit, the slow way).
    #[arg(long)]
    transparency_layers: Option<u32>,
    /// Strands in the demo scene (ignored for scene files).
    #[arg(long, default_value_t = tress::demo::DEMO_STRANDS)]
    demo_strands: u32,
}

fn parse_resolution(s: &str) -> Result<(u32, u32), String> {
    let (w, h) = s.split_once(['x', 'X']).ok_or_else(|| format!("`{s}` is not WIDTHxHEIGHT"))?;
    let parse = |v: &str| v.trim().parse::<u32>().map_err(|_| format!("`{s}` is not WIDTHxHEIGHT"));
    Ok((parse(w)?, parse(h)?))
}

fn parse_integrator(s: &str) -> Result<tress::scene::Integrator, String> {
    tress::scene::Integrator::from_name(s).ok_or_else(|| format!("`{s}` is not direct, final-gather or path"))
}

fn load(scene: Option<&Path>, o: &Overrides) -> Result<Description> {
    let mut desc = match scene {
        // A directory is a reference scene of shared/scenes/gen_scenes.py (scene.json).
        Some(dir) if dir.is_dir() => read_reference_scene(dir)?,
        Some(path) => {
            let (desc, warnings) = if tress::io::imported::is_imported(path) {
                tress::io::imported::read_imported(path)?.into_description()
            } else {
                tress::io::scene_file::read_scene_with_warnings(path)?
            };
            for w in warnings {
                eprintln!("warning: {}: {w}", path.display());
            }
            desc
        }
        None => tress::demo::description(o.demo_strands, 1),
    };
    let s = &mut desc.settings;
    if let Some(spp) = o.spp {
        s.spp = spp;
    }
    if let Some(t) = o.threads {
        s.threads = t;
    }
    if let Some((w, h)) = o.resolution {
        (s.width, s.height) = (w, h);
    }
    if let Some(seed) = o.seed {
        s.seed = seed;
    }
    if let Some(i) = o.integrator {
        s.integrator = i;
    }
    if let Some(k) = o.transparency_layers {
        s.transparency_layers = k;
    }
    desc.validate()?;
    Ok(desc)
}

fn pool(threads: usize) -> Result<rayon::ThreadPool> {
    rayon::ThreadPoolBuilder::new().num_threads(threads).build().context("cannot start worker threads")
}

fn main() {
    if let Err(e) = run(Cli::parse()) {
        eprintln!("error: {e:#}");
        std::process::exit(1);
    }
}

fn run(cli: Cli) -> Result<()> {
    match cli.command {
        Command::Render { scene, overrides, output, quiet } => render(scene.as_deref(), &overrides, &output, quiet),
        Command::Info { scene, demo_strands } => {
            let o = Overrides { demo_strands, ..Default::default() };
            let desc = load(scene.as_deref(), &o)?;
            let (world, times) = pool(desc.settings.threads)?.install(|| prepare(&desc))?;
            info(&world);
            println!("build: load {:.3} s, bvh {:.3} s", times.load.as_secs_f64(), times.build.as_secs_f64());
            Ok(())
        }
        Command::Export { scene, output, demo_strands } => {
            let o = Overrides { demo_strands, ..Default::default() };
            export(scene.as_deref(), &o, &output, |_| true)
        }
        Command::Fur { command: FurCommand::Export { scene, output } } => {
            let o = Overrides::default();
            export(Some(&scene), &o, &output, |m| matches!(m, Material::Fur(_)))
        }
        Command::Fur { command: FurCommand::Presets } => {
            // Each preset file opens with "# Name: what it looks like".
            for (_, text) in tress::fur::presets::PRESETS {
                println!("{}", text.lines().next().unwrap_or("").trim_start_matches('#').trim());
            }
            Ok(())
        }
        Command::Bench { scene, overrides, thread_counts, reps } => {
            bench(scene.as_deref(), &overrides, &thread_counts, reps)
        }
    }
}

/// Writes the shapes of a scene whose material passes `keep`, in world space: strand sets
/// to a `.hair` file, or strand sets and meshes to a `.usda` file.
fn export(scene: Option<&Path>, o: &Overrides, output: &Path, keep: impl Fn(&Material) -> bool) -> Result<()> {
    let is = |ext: &str| output.extension().is_some_and(|e| e.eq_ignore_ascii_case(ext));
    if !is("hair") && !is("usda") {
        anyhow::bail!("{}: unsupported export format: use a .hair or .usda file name", output.display());
    }
    let desc = load(scene, o)?;
    let geometry = tress::scene::load_geometry(&desc)?;
    if is("usda") {
        let materials = &geometry.materials;
        let shapes: Vec<_> = geometry.shapes.into_iter().filter(|(_, m)| keep(&materials[*m as usize])).collect();
        tress::io::usd::write_usd(output, &shapes, materials)?;
        eprintln!("wrote {} ({} shapes)", output.display(), shapes.len());
        return Ok(());
    }
    let mut all = tress::geometry::StrandSet::new();
    for (shape, material) in &geometry.shapes {
        if let Shape::Strands(s) = shape {
            if keep(&geometry.materials[*material as usize]) {
                all.append(s);
            }
        }
    }
    tress::io::hair::write_hair(output, &all)?;
    eprintln!("wrote {} ({} strands, {} segments)", output.display(), all.strand_count(), all.segment_count());
    Ok(())
}

fn render(scene: Option<&Path>, o: &Overrides, output: &Path, quiet: bool) -> Result<()> {
    // Check the output before spending time on the render.
    tress::film::check_output(output)?;
    let desc = load(scene, o)?;
    let pool = pool(desc.settings.threads)?;
    let (world, times) = pool.install(|| prepare(&desc))?;
    let s = &world.settings;
    let tiles = tress::render::tile_count(s.width, s.height);
    let bar = if quiet { ProgressBar::hidden() } else { ProgressBar::new(tiles) };
    bar.set_style(
        ProgressStyle::with_template("{spinner} [{elapsed_precise}] {wide_bar} {percent}% ETA {eta}")
            .expect("static template"),
    );
    let (film, stats) = pool.install(|| tress::render::render(&world, Some(&bar)));
    bar.finish_and_clear();
    tress::film::write_image(output, &film)?;
    let hair = Memory::of(&world.accel);
    let secs = stats.elapsed.as_secs_f64();
    eprintln!(
        "wrote {} ({}x{}, {} spp, {} threads)",
        output.display(),
        s.width,
        s.height,
        s.spp,
        pool.current_num_threads()
    );
    eprintln!(
        "scene build   {:.3} s (load {:.3} s, bvh {:.3} s)",
        (times.load + times.build).as_secs_f64(),
        times.load.as_secs_f64(),
        times.build.as_secs_f64()
    );
    eprintln!("render        {secs:.3} s ({:?} integrator)", s.integrator);
    eprintln!("rays          {} ({:.2} M rays/s)", stats.rays, stats.rays as f64 / secs / 1e6);
    if let Some(peak) = peak_memory_bytes() {
        eprintln!("peak memory   {}", human_bytes(peak));
    }
    if hair.segments > 0 {
        eprintln!(
            "hair          {} segments, {:.1} bytes/segment (points + BVH)",
            hair.segments,
            hair.bytes_per_segment()
        );
    }
    Ok(())
}

fn info(world: &World) {
    let (mut meshes, mut triangles, mut sets, mut strands, mut segments) = (0, 0, 0, 0, 0);
    let (mut mesh_bytes, mut strand_bytes, mut mesh_bvh, mut strand_bvh) = (0, 0, 0, 0);
    for o in &world.accel.objects {
        match &o.shape {
            Shape::Mesh(m) => {
                meshes += 1;
                triangles += m.indices.len();
                mesh_bytes += m.memory_bytes();
                mesh_bvh += o.bvh().memory_bytes();
            }
            Shape::Strands(s) => {
                sets += 1;
                strands += s.strand_count();
                segments += s.segment_count();
                strand_bytes += s.memory_bytes();
                strand_bvh += o.bvh().memory_bytes();
            }
        }
    }
    let top = world.accel.bvh_bytes() - mesh_bvh - strand_bvh;
    println!("meshes        {meshes} ({triangles} triangles)");
    println!("strand sets   {sets} ({strands} strands, {segments} segments)");
    println!("lights        {}", world.lights.len());
    println!("memory");
    println!("  mesh data   {}", human_bytes(mesh_bytes as u64));
    println!("  mesh bvh    {}", human_bytes(mesh_bvh as u64));
    println!("  strand data {}", human_bytes(strand_bytes as u64));
    println!("  strand bvh  {}", human_bytes(strand_bvh as u64));
    println!("  top bvh     {}", human_bytes(top as u64));
    if segments > 0 {
        println!(
            "  per segment {:.1} bytes (strand data + strand bvh)",
            (strand_bytes + strand_bvh) as f64 / segments as f64
        );
    }
}

fn bench(scene: Option<&Path>, o: &Overrides, thread_counts: &[usize], reps: usize) -> Result<()> {
    let desc = load(scene, o)?;
    let all = pool(0)?.current_num_threads();
    let median = |mut v: Vec<f64>| {
        v.sort_by(f64::total_cmp);
        v[v.len() / 2]
    };
    let list = |v: &[f64]| v.iter().map(|x| format!("{x:.3}")).collect::<Vec<_>>().join(", ");
    let (mut builds, mut build_cpus) = (Vec::new(), Vec::new());
    let mut world = None;
    for _ in 0..reps.max(1) {
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
        m.other_bvh
    );
    let light = light_direction(&world);
    for &t in thread_counts {
        let threads = if t == 0 { all } else { t };
        let pool = pool(threads)?;
        let mut primary = Vec::new();
        let mut shadow = Vec::new();
        let mut origins = Vec::new();
        for _ in 0..reps.max(1) {
            let (o, r) = pool.install(|| trace_primary(&world, threads));
            primary.push(r);
            origins = o;
        }
        for _ in 0..reps.max(1) {
            shadow.push(pool.install(|| trace_shadow(&world, &origins, light, threads)).1);
        }
        for (name, rates) in [("primary", &primary), ("shadow", &shadow)] {
            let wall: Vec<f64> = rates.iter().map(|r| r.mrays()).collect();
            let cpu: Vec<f64> = rates.iter().map(|r| r.mrays_cpu()).collect();
            println!(
                "RESULT threads {threads} {name:<8} Mrays/s median {:7.3} [{}] | cpu-time based {:7.3} [{}] | rays {}",
                median(wall.clone()),
                list(&wall),
                median(cpu.clone()),
                list(&cpu),
                rates[0].rays
            );
        }
    }
    Ok(())
}
