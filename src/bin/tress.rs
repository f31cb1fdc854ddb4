//! The `tress` command: render a scene, print what a scene holds, benchmark tracing.

use anyhow::{Context, Result};
use clap::{Parser, Subcommand};
use indicatif::{ProgressBar, ProgressStyle};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::Arc;
use std::time::Duration;
use tress::accel::Shape;
use tress::bench::{light_direction, trace_primary, trace_shadow, Memory, Tracing};
use tress::film::Region;
use tress::partial::{fingerprint, Checkpointer, Partial};
use tress::prepare::{prepare, prepare_owned};
use tress::render::{render_tiles, Control, TiledFilm};
use tress::scene::Description;
use tress::shading::Material;
use tress::stats::{human_bytes, peak_memory_bytes};
use tress::world::World;

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
        #[command(flatten)]
        job: Job,
    },
    /// Assemble farm tiles (from `render --tile I/N`) into the whole image.
    Merge {
        /// The tile files, all N of them, in any order.
        #[arg(required = true)]
        tiles: Vec<PathBuf>,
        /// Output image: .png or .exr, bit for bit what a single render would write.
        #[arg(short, long)]
        output: PathBuf,
    },
    /// Print the counts and memory of a scene (the demo scene when omitted).
    Info {
        /// Scene file (TOML).
        scene: Option<PathBuf>,
        /// Animation frame (for scenes with camera keys or frame patterns).
        #[arg(long)]
        frame: Option<u32>,
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
        /// Animation frame (for scenes with camera keys or frame patterns).
        #[arg(long)]
        frame: Option<u32>,
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
        /// How rays are traced, comma separated: one at a time (`single`, reported as
        /// `primary` / `shadow`), and a pixel's samples as one packet (`packet`, reported as
        /// `primary-packet` / `shadow-packet`).
        #[arg(long, value_enum, value_delimiter = ',', default_value = "single,packet")]
        tracing: Vec<Tracing>,
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
    integrator: Option<tress::world::Integrator>,
    /// Partial hits collected per traversal through semi-transparent hair (1 re-traces
    /// after every hit, the slow way).
    #[arg(long)]
    transparency_layers: Option<u32>,
    /// Final gather: the irradiance cache on diffuse surfaces, on or off (the scene's
    /// `irradiance_cache` otherwise).
    #[arg(long, value_name = "on|off", value_parser = parse_on_off)]
    irradiance_cache: Option<bool>,
    /// Final gather: the irradiance cache's accuracy (Ward's a; turns the cache on).
    #[arg(long, value_name = "A")]
    cache_accuracy: Option<f32>,
    /// Pixel filter: box, or gaussian with an optional radius in pixels (gaussian:2;
    /// default 1.5, sigma a third of it).
    #[arg(long, value_name = "box|gaussian[:R]", value_parser = parse_filter)]
    filter: Option<tress::film::PixelFilter>,
    /// Strands in the demo scene (ignored for scene files).
    #[arg(long, default_value_t = tress::demo::DEMO_STRANDS)]
    demo_strands: u32,
    /// Render every strand: turn level of detail off (`[render] lod = false`).
    #[arg(long)]
    no_lod: bool,
    /// Animation frame: camera keys are interpolated at it and `#` runs in file names
    /// become its number (see docs/scene-format.md).
    #[arg(long)]
    frame: Option<u32>,
}

/// How a render runs as a job: a farm tile, checkpoints, limits (see docs/render-farm.md).
#[derive(clap::Args)]
struct Job {
    /// Render only tile I of N (bands of rows, I from 0) into an .exr tile file for
    /// `tress merge`.
    #[arg(long, value_name = "I/N", value_parser = tress::partial::parse_farm_tile)]
    tile: Option<(u32, u32)>,
    /// Checkpoint file (.exr): progress is saved there, and a render started again with the
    /// same command resumes from it. Removed once the image is written.
    #[arg(long, value_name = "PATH")]
    checkpoint: Option<PathBuf>,
    /// Minutes between checkpoints.
    #[arg(long, value_name = "MINUTES", default_value_t = 10.0, requires = "checkpoint")]
    checkpoint_every: f64,
    /// Refuse, before loading anything, a scene whose estimated memory exceeds this
    /// (bytes, or with a K, M, G or T suffix: powers of 1024).
    #[arg(long, value_name = "SIZE", value_parser = tress::prepare::parse_memory_size)]
    memory_limit: Option<u64>,
}

fn parse_resolution(s: &str) -> Result<(u32, u32), String> {
    let (w, h) = s.split_once(['x', 'X']).ok_or_else(|| format!("`{s}` is not WIDTHxHEIGHT"))?;
    let parse = |v: &str| v.trim().parse::<u32>().map_err(|_| format!("`{s}` is not WIDTHxHEIGHT"));
    Ok((parse(w)?, parse(h)?))
}

fn parse_on_off(s: &str) -> Result<bool, String> {
    match s {
        "on" => Ok(true),
        "off" => Ok(false),
        _ => Err(format!("`{s}` is not on or off")),
    }
}

fn parse_integrator(s: &str) -> Result<tress::world::Integrator, String> {
    s.parse()
}

fn parse_filter(s: &str) -> Result<tress::film::PixelFilter, String> {
    s.parse()
}

fn load(scene: Option<&Path>, o: &Overrides) -> Result<Description> {
    let mut desc = match scene {
        Some(path) => {
            let (desc, warnings) = tress::io::read_scene(path, o.frame)?;
            for w in warnings {
                eprintln!("warning: {w}");
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
    if o.no_lod {
        s.lod = false;
    }
    if let Some(i) = o.integrator {
        s.integrator = i;
    }
    if let Some(k) = o.transparency_layers {
        s.transparency_layers = k;
    }
    if let Some(f) = o.filter {
        s.filter = f;
    }
    match o.irradiance_cache {
        Some(false) => s.irradiance_cache = None,
        Some(true) => s.irradiance_cache = Some(s.irradiance_cache.unwrap_or_default()),
        None => {}
    }
    if let Some(a) = o.cache_accuracy {
        s.irradiance_cache =
            Some(tress::world::IrradianceCacheSettings { accuracy: a, ..s.irradiance_cache.unwrap_or_default() });
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
        Command::Render { scene, overrides, output, quiet, job } => {
            render(scene.as_deref(), &overrides, &output, quiet, &job)
        }
        Command::Merge { tiles, output } => merge(&tiles, &output),
        Command::Info { scene, demo_strands, frame } => {
            let o = Overrides { demo_strands, frame, ..Default::default() };
            let desc = load(scene.as_deref(), &o)?;
            let (world, times) = pool(desc.settings.threads)?.install(|| prepare_owned(desc))?;
            info(&world);
            println!("build: load {:.3} s, bvh {:.3} s", times.load.as_secs_f64(), times.build.as_secs_f64());
            Ok(())
        }
        Command::Export { scene, output, demo_strands, frame } => {
            let o = Overrides { demo_strands, frame, ..Default::default() };
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
        Command::Bench { scene, overrides, thread_counts, reps, tracing } => {
            bench(scene.as_deref(), &overrides, &thread_counts, reps, &tracing)
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
    let geometry = tress::prepare::load_geometry(&desc)?;
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
    tress::io::cem_hair::write_hair(output, &all)?;
    eprintln!("wrote {} ({} strands, {} segments)", output.display(), all.strand_count(), all.segment_count());
    Ok(())
}

fn render(scene: Option<&Path>, o: &Overrides, output: &Path, quiet: bool, job: &Job) -> Result<()> {
    // Check the outputs before spending time on the render.
    tress::film::check_output(output)?;
    let is_exr = |p: &Path| p.extension().is_some_and(|e| e.eq_ignore_ascii_case("exr"));
    if job.tile.is_some() && !is_exr(output) {
        anyhow::bail!("{}: a tile (--tile) must be written to an .exr file", output.display());
    }
    if let Some(c) = &job.checkpoint {
        tress::film::check_output(c)?;
        if !is_exr(c) {
            anyhow::bail!("{}: a checkpoint must be an .exr file", c.display());
        }
    }
    if !(job.checkpoint_every.is_finite() && job.checkpoint_every > 0.0) {
        anyhow::bail!("--checkpoint-every must be a positive number of minutes");
    }
    let desc = load(scene, o)?;
    if let Some(limit) = job.memory_limit {
        let e = tress::prepare::estimate_memory(&desc)?;
        if e.total() > limit {
            anyhow::bail!(
                "the scene needs an estimated {} (geometry {}, BVH {}, image {}), more than the memory limit of {}",
                human_bytes(e.total()),
                human_bytes(e.geometry),
                human_bytes(e.bvh),
                human_bytes(e.image),
                human_bytes(limit)
            );
        }
    }
    let interrupt = Interrupt::install()?;
    let pool = pool(desc.settings.threads)?;
    // The description is not needed again: its inline strands move into the world.
    let (world, times) = pool.install(|| prepare_owned(desc))?;
    for w in &world.warnings {
        eprintln!("warning: {w}");
    }
    let s = &world.settings;
    let full = (s.width, s.height);
    let region = match job.tile {
        Some((i, n)) => Region::band(s.width, s.height, i, n).map_err(anyhow::Error::msg)?,
        None => Region::full(s.width, s.height),
    };
    let template =
        Partial { state: TiledFilm::new(region), full, fingerprint: fingerprint(&world), farm_tile: job.tile };
    let state = match &job.checkpoint {
        Some(path) if path.exists() => resume(path, &template)?,
        _ => template.state.clone(),
    };
    let checkpointer = job.checkpoint.as_ref().map(|path| {
        Checkpointer::new(path.clone(), Duration::from_secs_f64(job.checkpoint_every * 60.0), template.clone())
    });
    if let Some(sig) = interrupt.signal() {
        eprintln!("interrupted by signal {sig} before rendering started; nothing written");
        std::process::exit(128 + sig);
    }

    let bar = if quiet { ProgressBar::hidden() } else { ProgressBar::new(u64::from(state.done.len())) };
    bar.set_style(
        ProgressStyle::with_template("{spinner} [{elapsed_precise}] {wide_bar} {percent}% ETA {eta}")
            .expect("static template"),
    );
    bar.set_position(u64::from(state.done.count()));
    bar.reset_eta();
    let after_tile = |shared: &std::sync::Mutex<TiledFilm>| {
        if let Some(Err(e)) = checkpointer.as_ref().and_then(|c| c.maybe_save(shared)) {
            bar.println(format!("warning: checkpoint not saved: {e}"));
        }
    };
    let control = Control { progress: Some(&bar), cancel: Some(interrupt.flag()), after_tile: Some(&after_tile) };
    let (state, stats) = pool.install(|| render_tiles(&world, state, &control));
    bar.finish_and_clear();

    let part = Partial { state, ..template };
    if !part.is_complete() {
        // Interrupted: keep what is done and stop with the signal's status, so a scheduler
        // sees the job did not finish.
        let sig = interrupt.signal().unwrap_or(libc::SIGINT);
        if let Some(c) = &checkpointer {
            c.save(part.state.clone())?;
            eprintln!("saved checkpoint {}", c.path().display());
        }
        if is_exr(output) {
            part.save(output)?;
        } else {
            tress::film::write_image(output, &part.state.film)?;
        }
        eprintln!(
            "interrupted by signal {sig}: wrote the partial image {} ({} of {} tiles done)",
            output.display(),
            part.state.done.count(),
            part.state.done.len()
        );
        std::process::exit(128 + sig);
    }
    if job.tile.is_some() {
        part.save(output)?;
    } else {
        tress::film::write_image(output, &part.state.film)?;
    }
    if let Some(c) = &checkpointer {
        std::fs::remove_file(c.path()).or_else(|e| match e.kind() {
            std::io::ErrorKind::NotFound => Ok(()),
            _ => Err(e),
        })?;
    }
    let hair = Memory::of(&world.accel);
    let secs = stats.elapsed.as_secs_f64();
    let part_of = match job.tile {
        Some((i, n)) => format!("tile {i}/{n}: rows {} to {} of ", region.y, region.y + region.height - 1),
        None => String::new(),
    };
    eprintln!(
        "wrote {} ({part_of}{}x{}, {} spp, {} threads)",
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
    if stats.irradiance_records > 0 {
        eprintln!("irradiance    {} cache records", stats.irradiance_records);
    }
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

/// The state saved in a checkpoint, if it belongs to this render.
fn resume(path: &Path, template: &Partial) -> Result<TiledFilm> {
    let saved = Partial::load(path)?;
    if saved.fingerprint != template.fingerprint
        || saved.full != template.full
        || saved.state.region != template.state.region
        || saved.farm_tile != template.farm_tile
    {
        anyhow::bail!(
            "{}: the checkpoint is of another render (scene, settings, frame or tile differ); delete it to start afresh",
            path.display()
        );
    }
    eprintln!(
        "resuming from {}: {} of {} tiles done",
        path.display(),
        saved.state.done.count(),
        saved.state.done.len()
    );
    Ok(saved.state)
}

/// SIGINT and SIGTERM (and SIGHUP) handling for renders: the first signal asks the render
/// to stop and write what it has; a second one ends the process at once.
struct Interrupt {
    flag: Arc<AtomicBool>,
    signal: Arc<AtomicUsize>,
}

impl Interrupt {
    fn install() -> Result<Interrupt> {
        use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM};
        let interrupt = Interrupt { flag: Arc::new(AtomicBool::new(false)), signal: Arc::new(AtomicUsize::new(0)) };
        for sig in [SIGINT, SIGTERM, SIGHUP] {
            // Registered first, so it sees the flag as the previous signal left it.
            signal_hook::flag::register_conditional_shutdown(sig, 128 + sig, interrupt.flag.clone())?;
            signal_hook::flag::register_usize(sig, interrupt.signal.clone(), sig as usize)?;
            signal_hook::flag::register(sig, interrupt.flag.clone())?;
        }
        Ok(interrupt)
    }

    fn flag(&self) -> &AtomicBool {
        &self.flag
    }

    /// The signal received, if any.
    fn signal(&self) -> Option<i32> {
        match self.signal.load(Ordering::SeqCst) {
            0 => None,
            s => Some(s as i32),
        }
    }
}

fn merge(tiles: &[PathBuf], output: &Path) -> Result<()> {
    tress::film::check_output(output)?;
    let parts = tiles.iter().map(|p| Ok((p.clone(), Partial::load(p)?))).collect::<Result<Vec<_>>>()?;
    let film = tress::partial::merge(&parts)?;
    tress::film::write_image(output, &film)?;
    eprintln!("wrote {} ({}x{}, from {} tiles)", output.display(), film.width, film.height, parts.len());
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
                strand_bvh += o.bvh_bytes();
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
    lod_info(world);
}

/// The level of detail of each strand set that has it, and the memory it adds: its BVH with
/// widened bounds against the BVH the set would have without it, plus the LOD's bookkeeping.
fn lod_info(world: &World) {
    for (i, o) in world.accel.objects.iter().enumerate() {
        let (Some(lod), Shape::Strands(s)) = (o.lod(), &o.shape) else { continue };
        let p = lod.params();
        let plain = o.plain_bvh_bytes();
        let added = o.bvh_bytes() as i64 - plain as i64 + lod.bookkeeping_bytes() as i64;
        let data = s.memory_bytes() as f64;
        println!(
            "lod object {i}: {} levels, decimation {}, compensation {}, width {:.3e}, strands per group {:?}",
            p.levels,
            p.decimation,
            p.compensation,
            lod.width(),
            lod.group_strands()
        );
        println!(
            "  lod bvh {} (without lod: {}), bookkeeping {} B: added {}{} ({:+.2} % of the strand data)",
            human_bytes(o.bvh_bytes() as u64),
            human_bytes(plain as u64),
            lod.bookkeeping_bytes(),
            if added < 0 { "-" } else { "" },
            human_bytes(added.unsigned_abs()),
            100.0 * added as f64 / data
        );
    }
}

fn bench(
    scene: Option<&Path>,
    o: &Overrides,
    thread_counts: &[usize],
    reps: usize,
    tracings: &[Tracing],
) -> Result<()> {
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
        for &tracing in tracings {
            let mut primary = Vec::new();
            let mut shadow = Vec::new();
            let mut origins = Vec::new();
            for _ in 0..reps.max(1) {
                let (o, r) = pool.install(|| trace_primary(&world, threads, tracing));
                primary.push(r);
                origins = o;
            }
            for _ in 0..reps.max(1) {
                shadow.push(pool.install(|| trace_shadow(&world, &origins, light, threads, tracing)).1);
            }
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
