//! Geometry as plain data: triangle meshes and strand sets, and the ray/primitive tests.

pub mod curve;
pub mod mesh;
pub mod segment;
pub mod strands;
pub mod triangle;

pub use mesh::TriangleMesh;
pub use strands::{StrandInfo, StrandPoint, StrandSet};
