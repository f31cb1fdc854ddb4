//! A rendered image: colour and the AOVs by their EXR channel names, as NumPy arrays.

use numpy::ndarray::Array3;
use numpy::{IntoPyArray, PyArray2, PyArray3};
use pyo3::exceptions::PyKeyError;
use pyo3::prelude::*;
use std::path::PathBuf;
use tress::film::{Film, CHANNELS};

/// AOVs of several channels, by the prefix their EXR channels share.
const GROUPS: [(&str, &[&str]); 4] = [
    ("RGBA", &["R", "G", "B", "A"]),
    ("RGB", &["R", "G", "B"]),
    ("N", &["N.X", "N.Y", "N.Z"]),
    ("rootUV", &["rootUV.U", "rootUV.V"]),
];

/// A rendered image with its AOVs. `numpy.asarray(image)` (or `image.rgba`) is the colour
/// and alpha as float32 of shape (height, width, 4), linear RGB, top row first.
#[pyclass(module = "tress._tress", frozen)]
pub struct Image {
    film: Film,
    /// False when the render was stopped before every tile was done (unfinished tiles are
    /// black with alpha 0), or for a farm tile read from a file.
    #[pyo3(get)]
    complete: bool,
    /// What was skipped while preparing the scene.
    #[pyo3(get)]
    warnings: Vec<String>,
    /// Rays traced.
    #[pyo3(get)]
    rays: u64,
    /// Wall-clock seconds of the render (not of preparing the scene).
    #[pyo3(get)]
    seconds: f64,
}

impl Image {
    pub fn new(film: Film, complete: bool, warnings: Vec<String>, rays: u64, seconds: f64) -> Image {
        Image { film, complete, warnings, rays, seconds }
    }

    /// The named channels as an (h, w, len) array.
    fn stack<'py>(&self, py: Python<'py>, names: &[&str]) -> PyResult<Bound<'py, PyArray3<f32>>> {
        let getters = names
            .iter()
            .map(|n| CHANNELS.iter().find(|c| c.0 == *n).map(|c| c.1).ok_or_else(|| PyKeyError::new_err(n.to_string())))
            .collect::<PyResult<Vec<_>>>()?;
        let data: Vec<f32> = self.film.pixels.iter().flat_map(|p| getters.iter().map(move |g| g(p))).collect();
        let shape = (self.film.height as usize, self.film.width as usize, names.len());
        Ok(Array3::from_shape_vec(shape, data).expect("one value per channel and pixel").into_pyarray(py))
    }
}

#[pymethods]
impl Image {
    /// Width in pixels.
    #[getter]
    fn width(&self) -> u32 {
        self.film.width
    }

    /// Height in pixels.
    #[getter]
    fn height(&self) -> u32 {
        self.film.height
    }

    /// Colour and alpha, float32 of shape (height, width, 4).
    #[getter]
    fn rgba<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray3<f32>>> {
        self.stack(py, GROUPS[0].1)
    }

    /// The names `aov` takes: every EXR channel, and the groups `RGBA`, `RGB`, `N`, `rootUV`.
    #[getter]
    fn aov_names(&self) -> Vec<&'static str> {
        CHANNELS.iter().map(|c| c.0).chain(GROUPS.iter().map(|g| g.0)).collect()
    }

    /// One AOV by its EXR channel name (`Z`, `objectId`, `strandId`, `N.X`, ...) as float32 of
    /// shape (height, width), or a group (`N`, `rootUV`, `RGB`, `RGBA`) as (height, width, k).
    /// Raises KeyError for an unknown name.
    fn aov<'py>(&self, py: Python<'py>, name: &str) -> PyResult<Bound<'py, PyAny>> {
        if let Some((_, names)) = GROUPS.iter().find(|g| g.0 == name) {
            return Ok(self.stack(py, names)?.into_any());
        }
        let Some(channel) = CHANNELS.iter().find(|c| c.0 == name) else {
            return Err(PyKeyError::new_err(format!("no AOV `{name}`; the AOVs are {}", self.aov_names().join(", "))));
        };
        let data: Vec<f32> = self.film.pixels.iter().map(channel.1).collect();
        let shape = (self.film.height as usize, self.film.width as usize);
        let a = numpy::ndarray::Array2::from_shape_vec(shape, data).expect("one value per pixel");
        let array: Bound<'py, PyArray2<f32>> = a.into_pyarray(py);
        Ok(array.into_any())
    }

    /// Every AOV by channel name, as a dict of (height, width) arrays.
    fn aovs<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, pyo3::types::PyDict>> {
        let d = pyo3::types::PyDict::new(py);
        for (name, _, _) in CHANNELS {
            d.set_item(name, self.aov(py, name)?)?;
        }
        Ok(d)
    }

    /// Writes the image as the command line does: `.png` (8-bit sRGB) or `.exr` (linear
    /// float with every AOV), atomically.
    fn save(&self, py: Python<'_>, path: PathBuf) -> PyResult<()> {
        py.detach(|| tress::film::write_image(&path, &self.film)).map_err(crate::error)
    }

    #[pyo3(signature = (dtype = None, copy = None))]
    fn __array__<'py>(
        &self,
        py: Python<'py>,
        dtype: Option<Bound<'py, PyAny>>,
        copy: Option<bool>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let _ = copy;
        let a = self.rgba(py)?.into_any();
        match dtype {
            Some(d) => a.call_method1("astype", (d,)),
            None => Ok(a),
        }
    }

    fn __repr__(&self) -> String {
        format!(
            "<tress.Image {}x{}{}>",
            self.film.width,
            self.film.height,
            if self.complete { "" } else { ", incomplete" }
        )
    }
}
