//! `tress export` and `tress fur`: a scene's render strands (or only its grown fur) written
//! to a file in world space, and the list of fur presets.

use crate::options::{load, Overrides};
use anyhow::{bail, Result};
use std::path::{Path, PathBuf};
use tress::accel::Shape;
use tress::shading::Material;

/// The arguments of `tress export`.
#[derive(clap::Args)]
pub struct ExportArgs {
    #[arg(help = crate::options::SCENE_HELP)]
    scene: Option<PathBuf>,
    /// Output file: a Cem Yuksel .hair file (strands) or a USD text .usda file (strands
    /// as linear BasisCurves and meshes).
    #[arg(short, long)]
    output: PathBuf,
    /// Animation frame (scenes with camera keys or frame patterns, USD time samples, Maya animation curves).
    #[arg(long)]
    frame: Option<u32>,
    #[command(flatten)]
    overrides: Overrides,
}

/// The commands of `tress fur`.
#[derive(clap::Subcommand)]
pub enum FurCommand {
    /// Write the fur a scene grows (every [[fur]] entry, in world space) to a file.
    Export {
        /// Scene file (TOML) with at least one [[fur]] entry.
        scene: PathBuf,
        /// Output file: a Cem Yuksel .hair file, or a USD text .usda file.
        #[arg(short, long)]
        output: PathBuf,
        /// Animation frame (scenes with camera keys or frame patterns, USD time samples, Maya animation curves).
        #[arg(long)]
        frame: Option<u32>,
    },
    /// List the fur presets by Maya's names.
    Presets,
}

/// Writes every strand set (and, to .usda, every mesh) of the scene.
pub fn run(args: &ExportArgs) -> Result<()> {
    export(args.scene.as_deref(), &args.overrides, args.frame, &args.output, "strands", |_| true)
}

/// Runs a `tress fur` command.
pub fn run_fur(command: &FurCommand) -> Result<()> {
    match command {
        FurCommand::Export { scene, output, frame } => {
            export(Some(scene), &Overrides::default(), *frame, output, "fur", |m| matches!(m, Material::Fur(_)))
        }
        FurCommand::Presets => {
            // Each preset file opens with "# Name: what it looks like".
            for (_, text) in tress::fur::presets::PRESETS {
                println!("{}", text.lines().next().unwrap_or("").trim_start_matches('#').trim());
            }
            Ok(())
        }
    }
}

/// Writes the shapes of a scene whose material passes `keep`, in world space: strand sets
/// to a `.hair` file, or strand sets and meshes to a `.usda` file. A scene with nothing to
/// write (`what`: "strands" or "fur") is an error, not an empty file.
fn export(
    scene: Option<&Path>,
    o: &Overrides,
    frame: Option<u32>,
    output: &Path,
    what: &str,
    keep: impl Fn(&Material) -> bool,
) -> Result<()> {
    let is = |ext: &str| output.extension().is_some_and(|e| e.eq_ignore_ascii_case(ext));
    if !is("hair") && !is("usda") {
        bail!("{}: unsupported export format: use a .hair or .usda file name", output.display());
    }
    let desc = load(scene, o, frame, false)?;
    let geometry = tress::prepare::load_geometry(&desc)?;
    let materials = &geometry.materials;
    let (shapes, visibility): (Vec<_>, Vec<_>) = geometry
        .shapes
        .into_iter()
        .zip(geometry.visibility)
        .filter(|((_, m), _)| keep(&materials[*m as usize]))
        .unzip();
    let name = scene.map_or("the demo scene".into(), |s| s.display().to_string());
    let strands = shapes.iter().any(|(s, _)| matches!(s, Shape::Strands(s) if s.strand_count() > 0));
    if !strands && (what == "fur" || is("hair")) {
        bail!("{name} has no {what} to export: {} not written", output.display());
    }
    if is("usda") {
        if shapes.is_empty() {
            bail!("{name} has nothing to export: {} not written", output.display());
        }
        tress::io::usd::write_usd(output, &shapes, materials, &visibility)?;
        eprintln!("wrote {} ({} shapes)", output.display(), shapes.len());
        return Ok(());
    }
    let mut all = tress::geometry::StrandSet::new();
    let mut flagged = 0;
    for ((shape, _), seen) in shapes.iter().zip(&visibility) {
        if let Shape::Strands(s) = shape {
            all.append(s);
            flagged += usize::from(*seen != tress::scene::Visibility::default());
        }
    }
    if flagged > 0 {
        eprintln!(
            "warning: {flagged} strand sets are hidden from the camera, cast no shadows or are matte: a .hair file \
             cannot hold that, they are written as plain strands (a .usda file keeps it)"
        );
    }
    tress::io::cem_hair::write_hair(output, &all)?;
    eprintln!("wrote {} ({} strands, {} segments)", output.display(), all.strand_count(), all.segment_count());
    Ok(())
}
