//! `tress merge`: farm tiles (from `render --tile I/N`) assembled into the whole image.

use anyhow::{bail, Result};
use std::path::PathBuf;
use tress::partial::Partial;

/// The arguments of `tress merge`.
#[derive(clap::Args)]
pub struct MergeArgs {
    /// The tile files, all N of them, in any order.
    #[arg(required = true)]
    tiles: Vec<PathBuf>,
    /// Output image: .png or .exr, bit for bit what a single render would write.
    #[arg(short, long)]
    output: PathBuf,
    /// Overwrite the output image if it exists already.
    #[arg(short, long)]
    force: bool,
}

/// Merges the tiles and writes the image.
pub fn run(args: &MergeArgs) -> Result<()> {
    let output = &args.output;
    tress::film::check_output(output)?;
    for tile in &args.tiles {
        tress::partial::check_distinct(&[("-o", output), ("the tile", tile)]).map_err(anyhow::Error::msg)?;
    }
    if output.exists() && !args.force {
        bail!("{} exists already: pass --force (-f) to overwrite it, or name another with -o", output.display());
    }
    let parts = args.tiles.iter().map(|p| Ok((p.clone(), Partial::load(p)?))).collect::<Result<Vec<_>>>()?;
    let film = tress::partial::merge(&parts)?;
    tress::film::write_image(output, &film)?;
    eprintln!("wrote {} ({}x{}, from {} tiles)", output.display(), film.width, film.height, parts.len());
    Ok(())
}
