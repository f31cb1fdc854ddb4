//! The `tress` command: render a scene (the default command), assemble farm tiles, print
//! what a scene holds, export its strands, grow fur, benchmark tracing. One module per
//! command; `options` holds what the commands that read a scene share.

mod bench;
mod export;
mod frames;
mod info;
mod interrupt;
mod merge;
mod options;
mod progress;
mod render;

use clap::{Parser, Subcommand};

const EXAMPLES: &str = "\
Examples:
  tress scene.toml                           render scene.toml to scene.png
  tress scene.toml -o out.exr -s 64 -t 8     64 samples per pixel, 8 threads, linear EXR
  tress anim.toml --frames 1-24 -o anim.####.exr
                                             frames 1 to 24, anim.0001.exr to anim.0024.exr
  tress render                               the built-in demo scene, to demo.png
  tress info scene.toml                      counts and memory of a scene
  tress <COMMAND> --help                     the options of a command";

#[derive(Parser)]
#[command(
    name = "tress",
    version,
    about = "A ray tracer for hair and fur",
    after_help = EXAMPLES,
    args_conflicts_with_subcommands = true,
    arg_required_else_help = true
)]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
    /// `tress SCENE ...` is `tress render SCENE ...`.
    #[command(flatten)]
    render: render::RenderArgs,
}

#[derive(Subcommand)]
enum Command {
    /// Render a scene file (or the built-in demo scene) to an image (the default command).
    Render(render::RenderArgs),
    /// Assemble farm tiles (from `render --tile I/N`) into the whole image.
    Merge(merge::MergeArgs),
    /// Print the counts and memory of a scene (the demo scene when omitted).
    Info(info::InfoArgs),
    /// Write the scene's render strands (all strand sets, in world space) to a file.
    Export(export::ExportArgs),
    /// Grow fur: export it, list the presets.
    Fur {
        #[command(subcommand)]
        command: export::FurCommand,
    },
    /// Measure BVH build time, ray throughput and memory per hair segment.
    Bench(bench::BenchArgs),
}

fn main() {
    let cli = Cli::parse();
    let result = match cli.command {
        None => render::run(&cli.render),
        Some(Command::Render(args)) => render::run(&args),
        Some(Command::Merge(args)) => merge::run(&args),
        Some(Command::Info(args)) => info::run(&args),
        Some(Command::Export(args)) => export::run(&args),
        Some(Command::Fur { command }) => export::run_fur(&command),
        Some(Command::Bench(args)) => bench::run(&args),
    };
    if let Err(e) = result {
        eprintln!("error: {}", tress::error::message(e.as_ref()));
        std::process::exit(1);
    }
}
