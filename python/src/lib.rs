//! The native part of the `tress` Python package: a thin layer over the tress library.
//!
//! Scenes are read by the library's readers (`load`), or parsed from the scene TOML the
//! Python side writes with geometry held in memory (`parse`); rendering runs the library's
//! tiled renderer on its own thread with the GIL released, while the calling thread reports
//! progress and checks for Ctrl-C.

mod geometry;
mod image;

use geometry::{Mesh, Strands};
use image::Image;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::path::PathBuf;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::Mutex;
use std::time::{Duration, Instant};
use tress::accel::Shape;
use tress::film::{Film, Region};
use tress::render::{render_tiles, Control, TiledFilm};
use tress::scene::{Description, GuideSource, HairSource, MeshSource};
use tress::world::Integrator;

pyo3::create_exception!(
    _tress,
    TressError,
    pyo3::exceptions::PyException,
    "A scene or file tress cannot use; the message is the command line's."
);

/// A library error as a Python exception, worded as the command line words it
/// (`anyhow`'s `{:#}`: the error and its causes), without the line end some parser
/// messages carry.
fn error(e: impl Into<anyhow::Error>) -> PyErr {
    TressError::new_err(tress::error::message(e.into().as_ref()).trim_end().to_string())
}

/// A scene description: what a scene file (or a scene built in Python) says, before any
/// geometry is read.
#[pyclass(module = "tress._tress", name = "Description")]
pub struct PyDescription {
    desc: Description,
    /// What the reader skipped or did not understand.
    #[pyo3(get)]
    warnings: Vec<String>,
}

#[pymethods]
impl PyDescription {
    /// The render settings as a dict with the keys of the scene file's `[render]` table.
    #[getter]
    fn settings<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let s = &self.desc.settings;
        let d = PyDict::new(py);
        d.set_item("resolution", (s.width, s.height))?;
        d.set_item("spp", s.spp)?;
        d.set_item("seed", s.seed)?;
        d.set_item("max_depth", s.max_depth)?;
        d.set_item("indirect_hair_roughness", s.indirect_hair_roughness)?;
        d.set_item("max_sample_value", s.max_sample_value)?;
        d.set_item("threads", s.threads)?;
        d.set_item("lod", s.lod)?;
        d.set_item("integrator", integrator_name(s.integrator))?;
        d.set_item("transparency_layers", s.transparency_layers)?;
        d.set_item("gather_rays", s.gather_rays)?;
        Ok(d)
    }

    fn __repr__(&self) -> String {
        let (d, c) = (&self.desc, &self.desc.contents);
        format!(
            "<tress.Description: {} meshes, {} strand sets, {} hair systems, {} fur, {} lights, {}x{}>",
            c.meshes.len(),
            c.hair.len(),
            c.hair_systems.len(),
            c.fur.len(),
            c.lights.len(),
            d.settings.width,
            d.settings.height
        )
    }
}

fn integrator_name(i: Integrator) -> &'static str {
    match i {
        Integrator::Direct => "direct",
        Integrator::FinalGather => "final-gather",
        Integrator::Path => "path",
    }
}

/// Reads any scene the command line renders: a scene TOML, a Maya ASCII, pbrt-v4 or USD
/// text file, or a reference scene directory; `frame` picks the frame of an animated scene.
#[pyfunction]
#[pyo3(signature = (path, frame = None))]
fn load(py: Python<'_>, path: PathBuf, frame: Option<u32>) -> PyResult<PyDescription> {
    let (desc, warnings) = py.detach(|| tress::io::read_scene(&path, frame)).map_err(error)?;
    Ok(PyDescription { desc, warnings })
}

/// Parses scene TOML `text` as if it were the file `path` (relative paths resolve from its
/// directory, messages name it), then puts in-memory geometry in place of the files some
/// entries name: `inline` holds `(kind, index, geometry)` with kind `"mesh"`, `"hair"`,
/// `"hair_system"` or `"fur_guides"` and the 0-based index of the entry among its kind.
#[pyfunction]
fn parse(text: &str, path: PathBuf, inline: Vec<(String, usize, Bound<'_, PyAny>)>) -> PyResult<PyDescription> {
    let (mut desc, warnings) = tress::io::scene_file::parse(text, &path, None).map_err(error)?;
    for (kind, index, geometry) in inline {
        let missing = || PyValueError::new_err(format!("the scene has no {kind} entry {}", index + 1));
        match kind.as_str() {
            "mesh" => {
                let entry = desc.contents.meshes.get_mut(index).ok_or_else(missing)?;
                entry.source = MeshSource::Inline(geometry.cast::<Mesh>()?.borrow().mesh.clone());
            }
            "hair" => {
                let entry = desc.contents.hair.get_mut(index).ok_or_else(missing)?;
                entry.source = HairSource::Inline(geometry.cast::<Strands>()?.borrow().strands.clone());
            }
            "hair_system" => {
                let entry = desc.contents.hair_systems.get_mut(index).ok_or_else(missing)?;
                let curves = geometry.cast::<Strands>()?.borrow().strands.clone();
                entry.guides = GuideSource::Inline(tress::hair_system::Guides::from_curves(curves));
            }
            "fur_guides" => {
                let entry = desc.contents.fur.get_mut(index).ok_or_else(missing)?;
                let (source, _) = entry.guides.as_mut().ok_or_else(missing)?;
                *source = HairSource::Inline(geometry.cast::<Strands>()?.borrow().strands.clone());
            }
            other => return Err(PyValueError::new_err(format!("unknown kind of entry `{other}`"))),
        }
    }
    Ok(PyDescription { desc, warnings })
}

/// Applies the keyword overrides of `render` and `info` (the command line's `--spp`,
/// `--threads`, ...) and checks the settings.
#[allow(clippy::too_many_arguments)]
fn with_overrides(
    scene: &PyDescription,
    spp: Option<u32>,
    threads: Option<usize>,
    seed: Option<u32>,
    integrator: Option<&str>,
    resolution: Option<(u32, u32)>,
    transparency_layers: Option<u32>,
    lod: Option<bool>,
) -> PyResult<Description> {
    let mut desc = scene.desc.clone();
    let s = &mut desc.settings;
    if let Some(spp) = spp {
        s.spp = spp;
    }
    if let Some(t) = threads {
        s.threads = t;
    }
    if let Some(seed) = seed {
        s.seed = seed;
    }
    if let Some(name) = integrator {
        s.integrator = name.parse::<Integrator>().map_err(PyValueError::new_err)?;
    }
    if let Some((w, h)) = resolution {
        (s.width, s.height) = (w, h);
    }
    if let Some(k) = transparency_layers {
        s.transparency_layers = k;
    }
    if let Some(l) = lod {
        s.lod = l;
    }
    desc.validate().map_err(error)?;
    Ok(desc)
}

fn pool(threads: usize) -> PyResult<rayon::ThreadPool> {
    rayon::ThreadPoolBuilder::new().num_threads(threads).build().map_err(|e| error(anyhow::anyhow!(e)))
}

/// Counts finished tiles for the polling thread.
struct TileCounter(AtomicU64);

impl tress::render::Progress for TileCounter {
    fn advance(&self, tiles: u64, _rays: u64) {
        self.0.fetch_add(tiles, Ordering::Relaxed);
    }
}

/// Renders a scene; see `tress.render` for the arguments.
#[pyfunction]
#[pyo3(signature = (scene, *, spp = None, threads = None, seed = None, integrator = None, resolution = None,
    transparency_layers = None, lod = None, progress = None, preview = None, preview_interval = 1.0))]
#[allow(clippy::too_many_arguments)]
fn render(
    py: Python<'_>,
    scene: &PyDescription,
    spp: Option<u32>,
    threads: Option<usize>,
    seed: Option<u32>,
    integrator: Option<&str>,
    resolution: Option<(u32, u32)>,
    transparency_layers: Option<u32>,
    lod: Option<bool>,
    progress: Option<Bound<'_, PyAny>>,
    preview: Option<Bound<'_, PyAny>>,
    preview_interval: f64,
) -> PyResult<Image> {
    let desc = with_overrides(scene, spp, threads, seed, integrator, resolution, transparency_layers, lod)?;
    if !(preview_interval.is_finite() && preview_interval >= 0.0) {
        return Err(PyValueError::new_err("preview_interval must be a number of seconds >= 0"));
    }
    tress::prepare::check_memory(&desc, None).map_err(error)?;
    let pool = pool(desc.settings.threads)?;
    let (world, _) = py.detach(|| pool.install(|| tress::prepare::prepare_owned(desc))).map_err(error)?;
    let full = Region::full(world.settings.width, world.settings.height);
    let state = TiledFilm::new(full);
    let total = u64::from(state.done.len());

    let cancel = AtomicBool::new(false);
    let finished = AtomicBool::new(false);
    let tiles = TileCounter(AtomicU64::new(0));
    let want_snapshot = AtomicBool::new(false);
    let snapshot: Mutex<Option<Film>> = Mutex::new(None);
    let after_tile = |shared: &Mutex<TiledFilm>| {
        if want_snapshot.swap(false, Ordering::AcqRel) {
            let film = shared.lock().unwrap_or_else(|e| e.into_inner()).film.clone();
            *snapshot.lock().unwrap_or_else(|e| e.into_inner()) = Some(film);
        }
    };
    let control = Control { progress: Some(&tiles), cancel: Some(&cancel), after_tile: Some(&after_tile) };
    let interval = Duration::from_secs_f64(preview_interval);
    let mut failure: Option<PyErr> = None;
    let mut stopped_by_callback = false;

    let (state, stats) = std::thread::scope(|s| {
        let worker = s.spawn(|| {
            let out = pool.install(|| render_tiles(&world, state, &control));
            finished.store(true, Ordering::Release);
            out
        });
        let mut last_preview = Instant::now();
        let mut reported = u64::MAX;
        loop {
            let done_now = finished.load(Ordering::Acquire);
            if failure.is_none() && !stopped_by_callback {
                if let Err(e) = py.check_signals() {
                    cancel.store(true, Ordering::Relaxed);
                    failure = Some(e);
                }
            }
            let done = tiles.0.load(Ordering::Relaxed);
            if let (Some(cb), None, false) = (&progress, &failure, stopped_by_callback) {
                if done != reported || done_now {
                    reported = done;
                    match cb.call1((done, total)) {
                        Ok(r) if r.extract::<bool>().ok() == Some(false) => {
                            cancel.store(true, Ordering::Relaxed);
                            stopped_by_callback = true;
                        }
                        Ok(_) => {}
                        Err(e) => {
                            cancel.store(true, Ordering::Relaxed);
                            failure = Some(e);
                        }
                    }
                }
            }
            if let (Some(cb), None) = (&preview, &failure) {
                if !done_now && last_preview.elapsed() >= interval {
                    want_snapshot.store(true, Ordering::Release);
                    last_preview = Instant::now();
                }
                let film = snapshot.lock().unwrap_or_else(|e| e.into_inner()).take();
                if let Some(film) = film {
                    let image = Image::new(film, false, Vec::new(), 0, 0.0);
                    if let Err(e) = cb.call1((image,)) {
                        cancel.store(true, Ordering::Relaxed);
                        failure = Some(e);
                    }
                }
            }
            if done_now {
                break;
            }
            py.detach(|| {
                let until = Instant::now() + Duration::from_millis(50);
                while Instant::now() < until && !finished.load(Ordering::Acquire) {
                    std::thread::sleep(Duration::from_millis(5));
                }
            });
        }
        worker.join().map_err(|_| error(anyhow::anyhow!("the render thread panicked")))
    })?;
    if let Some(e) = failure {
        return Err(e);
    }
    let complete = state.done.is_full();
    Ok(Image::new(state.film, complete, world.warnings.clone(), stats.rays, stats.elapsed.as_secs_f64()))
}

/// Prepares the scene (reads and grows its geometry, builds the BVHs) and tells what it
/// holds: counts and memory by part, in bytes.
#[pyfunction]
fn info<'py>(py: Python<'py>, scene: &PyDescription) -> PyResult<Bound<'py, PyDict>> {
    let desc = scene.desc.clone();
    let estimate = tress::prepare::check_memory(&desc, None).map_err(error)?;
    let pool = pool(desc.settings.threads)?;
    let (world, _) = py.detach(|| pool.install(|| tress::prepare::prepare_owned(desc))).map_err(error)?;
    let memory = tress::stats::Memory::of(&world.accel);
    let d = PyDict::new(py);
    d.set_item("meshes", memory.meshes)?;
    d.set_item("triangles", memory.triangles)?;
    d.set_item("strand_sets", memory.strand_sets)?;
    d.set_item("strands", memory.strands)?;
    d.set_item("segments", memory.segments)?;
    d.set_item("lights", world.lights.len())?;
    let m = PyDict::new(py);
    m.set_item("mesh_data", memory.mesh)?;
    m.set_item("mesh_bvh", memory.mesh_bvh)?;
    m.set_item("strand_data", memory.strand_points)?;
    m.set_item("strand_bvh", memory.strand_bvh)?;
    m.set_item("top_bvh", memory.top_bvh)?;
    m.set_item("total", memory.mesh + memory.mesh_bvh + memory.strand_points + memory.strand_bvh + memory.top_bvh)?;
    d.set_item("memory", m)?;
    let e = PyDict::new(py);
    e.set_item("geometry", estimate.geometry)?;
    e.set_item("bvh", estimate.bvh)?;
    e.set_item("image", estimate.image)?;
    e.set_item("maps", estimate.maps)?;
    e.set_item("total", estimate.total())?;
    d.set_item("estimate", e)?;
    d.set_item("warnings", world.warnings.clone())?;
    Ok(d)
}

/// Writes the scene's render strands (every strand set, in world space, after hair-system
/// expansion and fur growth) to a `.hair` file, or strands and meshes to a `.usda` file, as
/// `tress export` does.
#[pyfunction]
fn export_shapes(py: Python<'_>, scene: &PyDescription, path: PathBuf) -> PyResult<()> {
    let is = |ext: &str| path.extension().is_some_and(|e| e.eq_ignore_ascii_case(ext));
    if !is("hair") && !is("usda") {
        return Err(error(anyhow::anyhow!(
            "{}: unsupported export format: use a .hair or .usda file name",
            path.display()
        )));
    }
    py.detach(|| -> anyhow::Result<()> {
        let geometry = tress::prepare::load_geometry(&scene.desc)?;
        if is("usda") {
            tress::io::usd::write_usd(&path, &geometry.shapes, &geometry.materials, &geometry.visibility)?;
        } else {
            let mut all = tress::geometry::StrandSet::new();
            for (shape, _) in &geometry.shapes {
                if let Shape::Strands(s) = shape {
                    all.append(s);
                }
            }
            tress::io::cem_hair::write_hair(&path, &all)?;
        }
        Ok(())
    })
    .map_err(error)
}

/// Reads an EXR image tress wrote (a render, a farm tile or a checkpoint) with its AOVs.
#[pyfunction]
fn read_exr(py: Python<'_>, path: PathBuf) -> PyResult<Image> {
    let exr = py
        .detach(|| -> Result<_, tress::error::LoadError> {
            let bytes = std::fs::read(&path).map_err(|e| tress::error::LoadError::io(&path, "read the file", e))?;
            tress::film::decode_exr(&bytes, &path)
        })
        .map_err(error)?;
    let complete = exr.at == (0, 0) && exr.full == (exr.film.width, exr.film.height);
    Ok(Image::new(exr.film, complete, Vec::new(), 0, 0.0))
}

/// The native module `tress._tress`.
#[pymodule]
fn _tress(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("TressError", m.py().get_type::<TressError>())?;
    m.add_class::<PyDescription>()?;
    m.add_class::<Mesh>()?;
    m.add_class::<Strands>()?;
    m.add_class::<Image>()?;
    m.add_function(wrap_pyfunction!(load, m)?)?;
    m.add_function(wrap_pyfunction!(parse, m)?)?;
    m.add_function(wrap_pyfunction!(render, m)?)?;
    m.add_function(wrap_pyfunction!(info, m)?)?;
    m.add_function(wrap_pyfunction!(export_shapes, m)?)?;
    m.add_function(wrap_pyfunction!(read_exr, m)?)?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
