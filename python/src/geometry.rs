//! Meshes and strand sets built from NumPy arrays, checked once when they are made.

use glam::Vec3;
use numpy::ndarray::{Array1, Array2};
use numpy::{IntoPyArray, PyArray1, PyArray2, PyReadonlyArray1, PyReadonlyArray2};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use tress::geometry::{StrandSet, TriangleMesh};

fn bad(message: String) -> PyErr {
    PyValueError::new_err(message)
}

/// Rows of an `(n, K)` array as fixed-size arrays, checking the column count.
fn rows<T: Copy + numpy::Element, const K: usize>(a: &PyReadonlyArray2<'_, T>, what: &str) -> PyResult<Vec<[T; K]>> {
    let view = a.as_array();
    if view.ncols() != K {
        return Err(bad(format!("{what} must have shape (n, {K}), not {:?}", view.shape())));
    }
    Ok(view.rows().into_iter().map(|r| std::array::from_fn(|k| r[k])).collect())
}

fn to_py2<'py, T: numpy::Element + Copy, const K: usize>(py: Python<'py>, rows: &[[T; K]]) -> Bound<'py, PyArray2<T>> {
    let flat: Vec<T> = rows.iter().flatten().copied().collect();
    Array2::from_shape_vec((rows.len(), K), flat).expect("rows of K values").into_pyarray(py)
}

/// A triangle mesh: vertex positions, three vertex indices per triangle, and optional
/// per-vertex normals and UVs.
#[pyclass(module = "tress._tress", frozen)]
pub struct Mesh {
    pub(crate) mesh: TriangleMesh,
}

#[pymethods]
impl Mesh {
    #[new]
    #[pyo3(signature = (points, triangles, normals = None, uvs = None))]
    fn new(
        points: PyReadonlyArray2<'_, f32>,
        triangles: PyReadonlyArray2<'_, u32>,
        normals: Option<PyReadonlyArray2<'_, f32>>,
        uvs: Option<PyReadonlyArray2<'_, f32>>,
    ) -> PyResult<Mesh> {
        let positions: Vec<Vec3> = rows::<f32, 3>(&points, "points")?.into_iter().map(Vec3::from).collect();
        if let Some(i) = positions.iter().position(|p| !p.is_finite()) {
            return Err(bad(format!("point {i} is not finite: {:?}", positions[i])));
        }
        let indices = rows::<u32, 3>(&triangles, "triangles")?;
        if let Some((t, _)) =
            indices.iter().enumerate().find(|(_, tri)| tri.iter().any(|&v| v as usize >= positions.len()))
        {
            return Err(bad(format!(
                "triangle {t} ({:?}) names a vertex past the {} points",
                indices[t],
                positions.len()
            )));
        }
        let normals = match normals {
            Some(n) => {
                let n: Vec<Vec3> = rows::<f32, 3>(&n, "normals")?.into_iter().map(Vec3::from).collect();
                if n.len() != positions.len() {
                    return Err(bad(format!("{} normals for {} points", n.len(), positions.len())));
                }
                Some(n)
            }
            None => None,
        };
        let uvs = match uvs {
            Some(u) => {
                let u = rows::<f32, 2>(&u, "uvs")?;
                if u.len() != positions.len() {
                    return Err(bad(format!("{} uvs for {} points", u.len(), positions.len())));
                }
                Some(u)
            }
            None => None,
        };
        Ok(Mesh { mesh: TriangleMesh { positions, normals, uvs, indices } })
    }

    /// Vertex positions, shape (n, 3).
    #[getter]
    fn points<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<f32>> {
        let p: Vec<[f32; 3]> = self.mesh.positions.iter().map(|v| v.to_array()).collect();
        to_py2(py, &p)
    }

    /// Vertex indices, shape (t, 3).
    #[getter]
    fn triangles<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<u32>> {
        to_py2(py, &self.mesh.indices)
    }

    /// Per-vertex normals, shape (n, 3), or None.
    #[getter]
    fn normals<'py>(&self, py: Python<'py>) -> Option<Bound<'py, PyArray2<f32>>> {
        let n: Option<Vec<[f32; 3]>> = self.mesh.normals.as_ref().map(|n| n.iter().map(|v| v.to_array()).collect());
        n.map(|n| to_py2(py, &n))
    }

    /// Per-vertex UVs, shape (n, 2), or None.
    #[getter]
    fn uvs<'py>(&self, py: Python<'py>) -> Option<Bound<'py, PyArray2<f32>>> {
        self.mesh.uvs.as_ref().map(|u| to_py2(py, u))
    }

    fn __repr__(&self) -> String {
        format!("<tress.Mesh: {} points, {} triangles>", self.mesh.positions.len(), self.mesh.indices.len())
    }
}

/// A set of strands: points with a radius each, strand `i` owning points
/// `offsets[i]:offsets[i + 1]`, and optional per-point colours and opacities.
#[pyclass(module = "tress._tress", frozen)]
pub struct Strands {
    pub(crate) strands: StrandSet,
}

#[pymethods]
impl Strands {
    #[new]
    #[pyo3(signature = (points, radius, offsets, colors = None, opacity = None))]
    fn new(
        points: PyReadonlyArray2<'_, f32>,
        radius: PyReadonlyArray1<'_, f32>,
        offsets: PyReadonlyArray1<'_, u32>,
        colors: Option<PyReadonlyArray2<'_, f32>>,
        opacity: Option<PyReadonlyArray1<'_, f32>>,
    ) -> PyResult<Strands> {
        let xyz = rows::<f32, 3>(&points, "points")?;
        let radius = radius.as_array();
        if radius.len() != xyz.len() {
            return Err(bad(format!("{} radii for {} points", radius.len(), xyz.len())));
        }
        let points: Vec<[f32; 4]> = xyz.iter().zip(radius.iter()).map(|(p, &r)| [p[0], p[1], p[2], r]).collect();
        if let Some(i) = points.iter().position(|p| !p.iter().all(|c| c.is_finite()) || p[3] < 0.0) {
            return Err(bad(format!("point {i} is not finite or has a negative radius: {:?}", points[i])));
        }
        let offsets: Vec<u32> = offsets.as_array().to_vec();
        if offsets.first() != Some(&0) || offsets.last().map(|&o| o as usize) != Some(points.len()) {
            return Err(bad(format!(
                "offsets must start at 0 and end at the number of points ({}); they are {} long, from {:?} to {:?}",
                points.len(),
                offsets.len(),
                offsets.first(),
                offsets.last()
            )));
        }
        if let Some(i) = offsets.windows(2).position(|w| w[1] < w[0]) {
            return Err(bad(format!("offsets decrease at strand {i} ({} then {})", offsets[i], offsets[i + 1])));
        }
        let colors = match colors {
            Some(c) => {
                let c = rows::<f32, 3>(&c, "colors")?;
                if c.len() != points.len() {
                    return Err(bad(format!("{} colours for {} points", c.len(), points.len())));
                }
                if let Some(i) = c.iter().position(|c| !c.iter().all(|v| v.is_finite() && *v >= 0.0)) {
                    return Err(bad(format!("colour {i} is not finite and >= 0: {:?}", c[i])));
                }
                Some(c)
            }
            None => None,
        };
        let opacity = match opacity {
            Some(o) => {
                let o = o.as_array().to_vec();
                if o.len() != points.len() {
                    return Err(bad(format!("{} opacities for {} points", o.len(), points.len())));
                }
                if let Some(i) = o.iter().position(|v| !(0.0..=1.0).contains(v)) {
                    return Err(bad(format!("opacity {i} is {}, outside [0, 1]", o[i])));
                }
                Some(o)
            }
            None => None,
        };
        Ok(Strands { strands: StrandSet { points, offsets, colors, opacity, strand_info: None, file_order: None } })
    }

    /// Point positions, shape (n, 3).
    #[getter]
    fn points<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<f32>> {
        let p: Vec<[f32; 3]> = self.strands.points.iter().map(|p| [p[0], p[1], p[2]]).collect();
        to_py2(py, &p)
    }

    /// Point radii (half the thickness), shape (n,).
    #[getter]
    fn radius<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f32>> {
        Array1::from_iter(self.strands.points.iter().map(|p| p[3])).into_pyarray(py)
    }

    /// Strand offsets into the points, shape (strands + 1,).
    #[getter]
    fn offsets<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<u32>> {
        Array1::from_vec(self.strands.offsets.clone()).into_pyarray(py)
    }

    /// Per-point linear RGB colours, shape (n, 3), or None.
    #[getter]
    fn colors<'py>(&self, py: Python<'py>) -> Option<Bound<'py, PyArray2<f32>>> {
        self.strands.colors.as_ref().map(|c| to_py2(py, c))
    }

    /// Per-point opacities, shape (n,), or None (opaque).
    #[getter]
    fn opacity<'py>(&self, py: Python<'py>) -> Option<Bound<'py, PyArray1<f32>>> {
        self.strands.opacity.as_ref().map(|o| Array1::from_vec(o.clone()).into_pyarray(py))
    }

    /// Number of strands.
    #[getter]
    fn strand_count(&self) -> usize {
        self.strands.strand_count()
    }

    /// Number of points.
    #[getter]
    fn point_count(&self) -> usize {
        self.strands.points.len()
    }

    fn __len__(&self) -> usize {
        self.strands.strand_count()
    }

    fn __repr__(&self) -> String {
        format!("<tress.Strands: {} strands, {} points>", self.strands.strand_count(), self.strands.points.len())
    }
}
