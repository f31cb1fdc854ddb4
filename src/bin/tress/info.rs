//! `tress info`: the counts and memory of a scene, by part, and its levels of detail.

use crate::options::{in_scene, load, pool, Overrides};
use anyhow::Result;
use std::path::PathBuf;
use tress::accel::Shape;
use tress::prepare::prepare_owned;
use tress::stats::{human_bytes, Memory};
use tress::world::World;

/// The arguments of `tress info`.
#[derive(clap::Args)]
pub struct InfoArgs {
    #[arg(help = crate::options::SCENE_HELP)]
    scene: Option<PathBuf>,
    /// Animation frame (scenes with camera keys or frame patterns, USD time samples, Maya animation curves).
    #[arg(long)]
    frame: Option<u32>,
    #[command(flatten)]
    overrides: Overrides,
}

/// Prepares the scene and prints what it holds.
pub fn run(args: &InfoArgs) -> Result<()> {
    let desc = load(args.scene.as_deref(), &args.overrides, args.frame, false)?;
    let scene = args.scene.as_deref();
    tress::prepare::check_memory(&desc, None).map_err(|e| in_scene(scene, e))?;
    let (world, times) =
        pool(desc.settings.threads)?.install(|| prepare_owned(desc)).map_err(|e| in_scene(scene, e))?;
    let m = Memory::of(&world.accel);
    println!("meshes        {} ({} triangles)", m.meshes, m.triangles);
    println!("strand sets   {} ({} strands, {} segments)", m.strand_sets, m.strands, m.segments);
    println!("lights        {}", world.lights.len());
    println!("memory");
    println!("  mesh data   {}", human_bytes(m.mesh));
    println!("  mesh bvh    {}", human_bytes(m.mesh_bvh));
    println!("  strand data {}", human_bytes(m.strand_points));
    println!("  strand bvh  {}", human_bytes(m.strand_bvh));
    println!("  top bvh     {}", human_bytes(m.top_bvh));
    if m.segments > 0 {
        println!("  per segment {:.1} bytes (strand data + strand bvh)", m.bytes_per_segment());
    }
    lod_info(&world);
    println!("build: load {:.3} s, bvh {:.3} s", times.load.as_secs_f64(), times.build.as_secs_f64());
    Ok(())
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
