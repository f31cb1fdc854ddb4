//! `tress render` (and `tress SCENE`): renders a scene, or a range of its frames, to images;
//! as a farm job, one tile of it, with checkpoints and a memory limit
//! (docs/render-farm.md).

use crate::frames::{parse_frames, Frames};
use crate::interrupt::Interrupt;
use crate::options::{in_scene, load_with_warnings, pool, Overrides};
use crate::progress::Progress;
use anyhow::{bail, Result};
use std::collections::HashSet;
use std::path::{Path, PathBuf};
use std::time::Duration;
use tress::film::Region;
use tress::io::scene_file::{at_frame, has_pattern};
use tress::partial::{fingerprint, Checkpointer, Partial};
use tress::prepare::prepare_owned;
use tress::render::{render_tiles, Control, RenderStats, TiledFilm};
use tress::stats::{human_bytes, peak_memory_bytes, Memory};
use tress::world::World;

/// The arguments of `tress render`.
#[derive(clap::Args)]
pub struct RenderArgs {
    #[arg(help = crate::options::SCENE_HELP)]
    scene: Option<PathBuf>,
    #[command(flatten)]
    overrides: Overrides,
    /// Output image: .png (8-bit sRGB) or .exr (linear float with AOVs); a run of # becomes
    /// the frame number, zero-padded (out.####.exr). [default: the scene's name with .png
    /// (.####.png with --frames), in the working directory]
    #[arg(short, long)]
    output: Option<PathBuf>,
    /// Overwrite an output image that exists already.
    #[arg(short, long)]
    force: bool,
    /// Animation frames: one frame (12), a range (1-24) or every STEP-th frame of one
    /// (1-24x2). Camera keys are interpolated at each frame and # runs in the scene's file
    /// names become its number (docs/scene-format.md); USD files are read at that time code,
    /// Maya files with their animation curves at that frame (docs/interop.md).
    #[arg(long, visible_alias = "frame", value_name = "N|FIRST-LAST[xSTEP]", value_parser = parse_frames)]
    frames: Option<Frames>,
    /// Print nothing but errors: no progress, warnings or summary.
    #[arg(short, long)]
    quiet: bool,
    /// Seconds between progress lines when stderr is not a terminal (a log file).
    #[arg(long, value_name = "SECONDS", default_value_t = 5.0)]
    progress_every: f64,
    #[command(flatten)]
    job: Job,
}

/// How a render runs as a job: a farm tile, checkpoints, limits (see docs/render-farm.md).
#[derive(clap::Args)]
struct Job {
    /// Render only tile I of N (bands of rows, I from 0) into an .exr tile file for
    /// `tress merge`.
    #[arg(long, value_name = "I/N", value_parser = tress::partial::parse_farm_tile)]
    tile: Option<(u32, u32)>,
    /// Checkpoint file (.exr; a run of # becomes the frame number): progress is saved
    /// there, and a render started again with the same command resumes from it, writing
    /// over its own output. Removed once the image is written.
    #[arg(long, value_name = "PATH")]
    checkpoint: Option<PathBuf>,
    /// Minutes between checkpoints (at most a year).
    #[arg(long, value_name = "MINUTES", default_value_t = 10.0, requires = "checkpoint",
          value_parser = tress::partial::parse_checkpoint_minutes)]
    checkpoint_every: f64,
    /// Refuse, before loading anything, a scene whose estimated memory (grown fur and
    /// hair systems included) exceeds this (bytes, or with a K, M, G or T suffix: powers of
    /// 1024). [default: the memory the machine has available]
    #[arg(long, value_name = "SIZE", value_parser = tress::prepare::parse_memory_size)]
    memory_limit: Option<u64>,
}

/// One image to render: a frame (or the scene as it is), where it goes, its checkpoint.
struct Target {
    frame: Option<u32>,
    output: PathBuf,
    checkpoint: Option<PathBuf>,
}

/// What a finished image took, for the summary.
struct Rendered {
    world: World,
    stats: RenderStats,
    build: (Duration, Duration),
    threads: usize,
    region: Region,
}

/// Renders every frame asked for, then prints one summary.
pub fn run(args: &RenderArgs) -> Result<()> {
    let targets = plan(args)?;
    let interrupt = Interrupt::install()?;
    // Warnings each frame repeats are printed once.
    let mut warned = HashSet::new();
    let mut last = None;
    let mut total = RenderStats::default();
    let mut build = (Duration::ZERO, Duration::ZERO);
    for target in &targets {
        let r = render_target(args, target, &interrupt, &mut warned)?;
        (total.rays, total.elapsed) = (total.rays + r.stats.rays, total.elapsed + r.stats.elapsed);
        total.irradiance_records += r.stats.irradiance_records;
        (build.0, build.1) = (build.0 + r.build.0, build.1 + r.build.1);
        if !args.quiet {
            eprintln!("{}", wrote_line(target, &r, args.job.tile));
        }
        last = Some(r);
    }
    if let (false, Some(last)) = (args.quiet, last) {
        summary(&last, &total, build, targets.len());
    }
    Ok(())
}

/// The images to write, checked before anything is loaded: formats, directories, and
/// outputs that exist already.
fn plan(args: &RenderArgs) -> Result<Vec<Target>> {
    let job = &args.job;
    if !(args.progress_every.is_finite() && args.progress_every > 0.0) {
        bail!("--progress-every must be a positive number of seconds");
    }
    let frames: Vec<Option<u32>> = match args.frames {
        Some(f) => f.list().into_iter().map(Some).collect(),
        None => vec![None],
    };
    let output = match &args.output {
        Some(o) => o.clone(),
        None => default_output(args.scene.as_deref(), args.frames.is_some(), job.tile),
    };
    let is_exr = |p: &Path| p.extension().is_some_and(|e| e.eq_ignore_ascii_case("exr"));
    if job.tile.is_some() && !is_exr(&output) {
        bail!("{}: a tile (--tile) must be written to an .exr file", output.display());
    }
    if let Some(c) = &job.checkpoint {
        if !is_exr(c) {
            bail!("{}: a checkpoint must be an .exr file", c.display());
        }
    }
    if frames.len() > 1 {
        for path in std::iter::once(&output).chain(&job.checkpoint) {
            if !has_pattern(path) {
                bail!(
                    "{}: {} frames cannot go to one file: put a run of # in the name for the frame number (e.g. {})",
                    path.display(),
                    frames.len(),
                    with_pattern(path).display()
                );
            }
        }
    }
    let mut targets = Vec::with_capacity(frames.len());
    for frame in frames {
        let at = |p: &Path| frame.map_or(p.to_owned(), |f| at_frame(p, f));
        let target = Target { frame, output: at(&output), checkpoint: job.checkpoint.as_deref().map(at) };
        tress::film::check_output(&target.output)?;
        if let Some(c) = &target.checkpoint {
            tress::film::check_output(c)?;
            tress::partial::check_distinct(&[("-o", &target.output), ("--checkpoint", c)])
                .map_err(anyhow::Error::msg)?;
        }
        // Resuming writes over the partial image the interrupted render left.
        let resuming = target.checkpoint.as_ref().is_some_and(|c| c.exists());
        if target.output.exists() && !args.force && !resuming {
            bail!(
                "{} exists already: pass --force (-f) to overwrite it, or name another with -o",
                target.output.display()
            );
        }
        targets.push(target);
    }
    Ok(targets)
}

/// The output named after the scene, in the working directory: `scene.png`,
/// `scene.####.png` for frames, `scene.tileI.exr` for a farm tile; `demo` for the built-in
/// scene.
fn default_output(scene: Option<&Path>, frames: bool, tile: Option<(u32, u32)>) -> PathBuf {
    let stem = scene.and_then(|s| s.file_stem()).map_or("demo".into(), |s| s.to_string_lossy().into_owned());
    let frame = if frames { ".####" } else { "" };
    let tail = match tile {
        Some((i, _)) => format!(".tile{i}.exr"),
        None => ".png".into(),
    };
    PathBuf::from(format!("{stem}{frame}{tail}"))
}

/// `path` with `.####` before its extension, as a hint.
fn with_pattern(path: &Path) -> PathBuf {
    let stem = path.file_stem().map_or("out".into(), |s| s.to_string_lossy().into_owned());
    let ext = path.extension().map_or(String::new(), |e| format!(".{}", e.to_string_lossy()));
    path.with_file_name(format!("{stem}.####{ext}"))
}

/// Loads, prepares and renders one image and writes it; an interrupted render writes what
/// it has and ends the process with the signal's status.
fn render_target(
    args: &RenderArgs,
    target: &Target,
    interrupt: &Interrupt,
    warned: &mut HashSet<String>,
) -> Result<Rendered> {
    interrupt.set_loading(true);
    let (desc, warnings) = load_with_warnings(args.scene.as_deref(), &args.overrides, target.frame)?;
    let mut warn = |w: String| {
        if !args.quiet && warned.insert(w.clone()) {
            eprintln!("warning: {w}");
        }
    };
    warnings.into_iter().for_each(&mut warn);
    let scene = args.scene.as_deref();
    tress::prepare::check_memory(&desc, args.job.memory_limit).map_err(|e| in_scene(scene, e))?;
    let pool = pool(desc.settings.threads)?;
    // The description is not needed again: its inline strands move into the world.
    let (world, times) = pool.install(|| prepare_owned(desc)).map_err(|e| in_scene(scene, e))?;
    world.warnings.iter().cloned().for_each(warn);
    let s = &world.settings;
    let region = match args.job.tile {
        Some((i, n)) => Region::band(s.width, s.height, i, n).map_err(anyhow::Error::msg)?,
        None => Region::full(s.width, s.height),
    };
    let template = Partial {
        state: TiledFilm::new(region),
        full: (s.width, s.height),
        fingerprint: fingerprint(&world),
        farm_tile: args.job.tile,
    };
    let state = match &target.checkpoint {
        Some(path) if path.exists() => resume(path, &template, args.quiet)?,
        _ => template.state.clone(),
    };
    let checkpointer = target.checkpoint.as_ref().map(|path| {
        Checkpointer::new(path.clone(), Duration::from_secs_f64(args.job.checkpoint_every * 60.0), template.clone())
    });
    interrupt.set_loading(false);
    if let Some(sig) = interrupt.signal() {
        eprintln!("interrupted by signal {sig} before rendering started; nothing written");
        std::process::exit(128 + sig);
    }

    let label = target.frame.filter(|_| args.frames.is_some_and(|f| f.list().len() > 1));
    let progress = Progress::new(
        args.quiet,
        Duration::from_secs_f64(args.progress_every),
        label.map_or(String::new(), |f| format!("frame {f}: ")),
        u64::from(state.done.len()),
        u64::from(state.done.count()),
    );
    let after_tile = |shared: &std::sync::Mutex<TiledFilm>| {
        if let Some(Err(e)) = checkpointer.as_ref().and_then(|c| c.maybe_save(shared)) {
            progress.println(&format!("error: checkpoint not saved (rendering goes on): {e}"));
        }
    };
    let control = Control { progress: Some(&progress), cancel: Some(interrupt.flag()), after_tile: Some(&after_tile) };
    let (state, stats) = pool.install(|| render_tiles(&world, state, &control));
    progress.finish();

    let part = Partial { state, ..template };
    if !part.is_complete() {
        stop_interrupted(&part, target, checkpointer.as_ref(), interrupt);
    }
    if args.job.tile.is_some() {
        part.save(&target.output)?;
    } else {
        tress::film::write_image(&target.output, &part.state.film)?;
    }
    if let Some(c) = &checkpointer {
        std::fs::remove_file(c.path()).or_else(|e| match e.kind() {
            std::io::ErrorKind::NotFound => Ok(()),
            _ => Err(e),
        })?;
    }
    let threads = pool.current_num_threads();
    Ok(Rendered { world, stats, build: (times.load, times.build), threads, region })
}

/// The state saved in a checkpoint, if it belongs to this render.
fn resume(path: &Path, template: &Partial, quiet: bool) -> Result<TiledFilm> {
    let saved = Partial::load(path)?;
    if saved.fingerprint != template.fingerprint
        || saved.full != template.full
        || saved.state.region != template.state.region
        || saved.farm_tile != template.farm_tile
    {
        bail!(
            "{}: the checkpoint is of another render (scene, settings, frame or tile differ); delete it to start afresh",
            path.display()
        );
    }
    if !quiet {
        eprintln!(
            "resuming from {}: {} of {} tiles done",
            path.display(),
            saved.state.done.count(),
            saved.state.done.len()
        );
    }
    Ok(saved.state)
}

/// Keeps what an interrupted render finished (checkpoint and partial image) and ends the
/// process with the signal's status, so a scheduler sees the job did not finish.
fn stop_interrupted(part: &Partial, target: &Target, checkpointer: Option<&Checkpointer>, interrupt: &Interrupt) -> ! {
    let sig = interrupt.signal().unwrap_or(signal_hook::consts::SIGINT);
    let written = (|| -> Result<()> {
        if let Some(c) = checkpointer {
            c.save(part.state.clone())?;
            eprintln!("saved checkpoint {}", c.path().display());
        }
        if target.output.extension().is_some_and(|e| e.eq_ignore_ascii_case("exr")) {
            part.save(&target.output)?;
        } else {
            tress::film::write_image(&target.output, &part.state.film)?;
        }
        Ok(())
    })();
    match written {
        Ok(()) => eprintln!(
            "interrupted by signal {sig}: wrote the partial image {} ({} of {} tiles done)",
            target.output.display(),
            part.state.done.count(),
            part.state.done.len()
        ),
        Err(e) => eprintln!("error: interrupted by signal {sig}, and the partial image was not written: {e:#}"),
    }
    std::process::exit(128 + sig);
}

/// `wrote out.png (640x480, 16 spp, 2 threads)`, with the frame and the tile's rows.
fn wrote_line(target: &Target, r: &Rendered, tile: Option<(u32, u32)>) -> String {
    let s = &r.world.settings;
    let frame = target.frame.map_or(String::new(), |f| format!("frame {f}, "));
    let part_of = match tile {
        Some((i, n)) => format!("tile {i}/{n}: rows {} to {} of ", r.region.y, r.region.y + r.region.height - 1),
        None => String::new(),
    };
    format!(
        "wrote {} ({frame}{part_of}{}x{}, {} spp, {} threads) in {:.3} s",
        target.output.display(),
        s.width,
        s.height,
        s.spp,
        r.threads,
        r.stats.elapsed.as_secs_f64()
    )
}

/// The figures of the whole run, printed once: build and render times (summed over the
/// frames), rays, peak memory, and the last frame's hair.
fn summary(last: &Rendered, total: &RenderStats, (load, build): (Duration, Duration), frames: usize) {
    let over = if frames > 1 { format!(", {frames} frames") } else { String::new() };
    eprintln!(
        "scene build   {:.3} s (load {:.3} s, bvh {:.3} s{over})",
        (load + build).as_secs_f64(),
        load.as_secs_f64(),
        build.as_secs_f64()
    );
    let secs = total.elapsed.as_secs_f64();
    eprintln!("render        {secs:.3} s ({:?} integrator{over})", last.world.settings.integrator);
    eprintln!("rays          {} ({:.2} M rays/s)", total.rays, total.rays as f64 / secs / 1e6);
    if total.irradiance_records > 0 {
        eprintln!("irradiance    {} cache records", total.irradiance_records);
    }
    if let Some(peak) = peak_memory_bytes() {
        eprintln!("peak memory   {}", human_bytes(peak));
    }
    let hair = Memory::of(&last.world.accel);
    if hair.segments > 0 {
        eprintln!(
            "hair          {} segments, {:.1} bytes/segment (points + BVH)",
            hair.segments,
            hair.bytes_per_segment()
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn outputs_are_named_after_the_scene() {
        let name = |scene: Option<&str>, frames, tile| default_output(scene.map(Path::new), frames, tile);
        assert_eq!(name(Some("shots/fox.toml"), false, None), Path::new("fox.png"));
        assert_eq!(name(Some("fox.ma"), true, None), Path::new("fox.####.png"));
        assert_eq!(name(Some("fox.toml"), true, Some((3, 8))), Path::new("fox.####.tile3.exr"));
        assert_eq!(name(None, false, None), Path::new("demo.png"));
        assert_eq!(with_pattern(Path::new("out/a.exr")), Path::new("out/a.####.exr"));
    }
}
