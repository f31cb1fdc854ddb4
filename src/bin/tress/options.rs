//! What the commands that read a scene share: the settings that override the scene file's,
//! their parsers, and loading the description.

use anyhow::{Context, Result};
use std::path::Path;
use tress::scene::Description;

/// Settings that override the scene file's.
#[derive(clap::Args, Default)]
pub struct Overrides {
    /// Samples per pixel.
    #[arg(short, long)]
    pub spp: Option<u32>,
    /// Worker threads (0 = every core).
    #[arg(short, long)]
    pub threads: Option<usize>,
    /// Image size as WIDTHxHEIGHT, e.g. 640x480.
    #[arg(short, long, value_parser = parse_resolution)]
    pub resolution: Option<(u32, u32)>,
    /// Seed of every random decision.
    #[arg(long)]
    pub seed: Option<u32>,
    /// Light transport: direct, final-gather or path.
    #[arg(short, long, value_parser = parse_integrator)]
    pub integrator: Option<tress::world::Integrator>,
    /// Path tracing: the smallest roughness of physical hair after the camera hit (path
    /// regularization; 0 turns it off).
    #[arg(long, value_name = "R")]
    pub indirect_hair_roughness: Option<f32>,
    /// The largest colour channel a camera sample may have: brighter samples are scaled
    /// down to it, hue kept (fewer fireflies, a darker image).
    #[arg(long, value_name = "V")]
    pub max_sample_value: Option<f32>,
    /// Partial hits collected per traversal through semi-transparent hair (1 re-traces
    /// after every hit, the slow way).
    #[arg(long)]
    pub transparency_layers: Option<u32>,
    /// Final gather: the irradiance cache on diffuse surfaces, on or off (the scene's
    /// `irradiance_cache` otherwise).
    #[arg(long, value_name = "on|off", value_parser = parse_on_off)]
    pub irradiance_cache: Option<bool>,
    /// Final gather: the irradiance cache's accuracy (Ward's a; turns the cache on).
    #[arg(long, value_name = "A")]
    pub cache_accuracy: Option<f32>,
    /// Pixel filter: box, or gaussian with an optional radius in pixels (gaussian:2;
    /// default 1.5, sigma a third of it).
    #[arg(long, value_name = "box|gaussian[:R]", value_parser = parse_filter)]
    pub filter: Option<tress::film::PixelFilter>,
    /// Strands in the demo scene (ignored for scene files).
    #[arg(long, default_value_t = tress::demo::DEMO_STRANDS)]
    pub demo_strands: u32,
    /// Render every strand: turn level of detail off (`[render] lod = false`).
    #[arg(long)]
    pub no_lod: bool,
    /// Draw every strand this wide, in scene units (for files whose strands have no
    /// width, or the wrong one).
    #[arg(long, value_name = "WIDTH", value_parser = parse_width)]
    pub hair_width: Option<f32>,
    /// Render through this camera of the file: a USD camera's prim path (`/World/Cam`), a
    /// Maya camera's transform or shape name, or an Arnold camera node's name. Without it, the file's first camera.
    #[arg(long, value_name = "PATH")]
    pub camera: Option<String>,
}

fn parse_width(s: &str) -> Result<f32, String> {
    match s.parse::<f32>() {
        Ok(w) if w.is_finite() && w > 0.0 => Ok(w),
        _ => Err(format!("`{s}` is not a positive width")),
    }
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

/// What a SCENE argument may name, shown in `--help` of every command that reads one.
pub const SCENE_HELP: &str = "Scene file: TOML, Maya ASCII (.ma), Arnold (.ass, .ass.gz), pbrt (.pbrt), USD \
(.usda, .usdc, .usdz, .usd), or raw strands or meshes (.hair, .ply, .obj); or a reference scene directory \
of scripts/gen_scenes.py; the built-in demo scene when omitted";

/// Reads the scene at `frame` (the demo scene when there is no file), prints the
/// reader's warnings unless `quiet`, and applies the overrides.
pub fn load(scene: Option<&Path>, o: &Overrides, frame: Option<u32>, quiet: bool) -> Result<Description> {
    let (desc, warnings) = load_with_warnings(scene, o, frame)?;
    if !quiet {
        for w in warnings {
            eprintln!("warning: {w}");
        }
    }
    Ok(desc)
}

/// [`load`], returning the reader's warnings (each naming the file) instead of printing
/// them.
pub fn load_with_warnings(
    scene: Option<&Path>,
    o: &Overrides,
    frame: Option<u32>,
) -> Result<(Description, Vec<String>)> {
    if o.camera.is_some() && scene.is_none() {
        anyhow::bail!("--camera chooses among a scene file's cameras: give a USD, Maya or Arnold file");
    }
    let (mut desc, notes) = match scene {
        // A file or a reference scene directory of scripts/gen_scenes.py (scene.json);
        // the warnings name the file.
        Some(path) => tress::io::read_scene_with(
            path,
            &tress::io::ImportOptions { frame, camera: o.camera.clone(), ..Default::default() },
        )?,
        None => (tress::demo::description(o.demo_strands, 1), Vec::new()),
    };
    if let Some(w) = o.hair_width {
        tress::io::override_hair_width(&mut desc.contents, w)?;
    }
    apply(&mut desc, o);
    desc.validate().map_err(|e| in_scene(scene, e))?;
    Ok((desc, notes))
}

/// An error preparing the scene read from `scene`, naming that file when the error is
/// about what the scene says (settings, camera, fur, hair systems); an error reading
/// another file already names it.
pub fn in_scene(scene: Option<&Path>, e: tress::error::PrepareError) -> anyhow::Error {
    match (scene, e) {
        (_, tress::error::PrepareError::Load(e)) => e.into(),
        (Some(path), e) => anyhow::anyhow!("{}: {e}", path.display()),
        (None, e) => anyhow::anyhow!("the demo scene: {e}"),
    }
}

fn apply(desc: &mut Description, o: &Overrides) {
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
    if let Some(r) = o.indirect_hair_roughness {
        s.indirect_hair_roughness = r;
    }
    if let Some(v) = o.max_sample_value {
        s.max_sample_value = v;
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
}

/// A pool of `threads` workers (0 = every core).
pub fn pool(threads: usize) -> Result<rayon::ThreadPool> {
    rayon::ThreadPoolBuilder::new().num_threads(threads).build().context("cannot start worker threads")
}
