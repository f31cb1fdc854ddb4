//! Geometry as plain data: triangle meshes and strand sets, and the ray/primitive tests.

pub mod curve;
pub mod loop_subdivision;
pub mod mesh;
pub mod segment;
pub mod strands;
pub mod subdivision;
pub mod triangle;

pub use mesh::TriangleMesh;
pub use strands::{StrandInfo, StrandPoint, StrandSet};

/// Largest coordinate or radius magnitude rendered. Intersection tests multiply up to three
/// lengths together, which overflows `f32` (3.4e38) for lengths around 1e12; geometry past
/// this bound is skipped with a warning ([`StrandSet::remove_unusable_strands`],
/// [`TriangleMesh::remove_unusable_triangles`]) rather than rendered wrong.
pub const MAX_COORDINATE: f32 = 1e10;
