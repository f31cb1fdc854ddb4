//! tress: a ray tracer for hair and fur.
//!
//! Data flows one way (see `docs/architecture.md`):
//!
//! ```text
//! scene description -> prepare (load, grow, expand) -> world -> integrator -> film -> file
//! ```
//!
//! | module | job |
//! |---|---|
//! | [`scene`] | the scene description: what a file says, with paths |
//! | [`io`] | file formats: scene TOML, meshes, strands, other tools' scenes |
//! | [`input_file`] | opening input files: regular files only, a size cap per kind |
//! | [`prepare`] | the only code that reads geometry and map files; builds the world |
//! | [`world`] | the prepared world and render settings: plain data, no paths |
//! | [`render`] | the integrators, reading only the world |
//! | [`film`] | pixels, reconstruction filters, image files |
//! | [`error`] | why a file cannot be read or a description prepared |
//! | [`memory`] | the memory a render may take; large buffers allocated without aborting |
//! | [`fur`] | Maya Fur grown on meshes |
//! | [`hair_system`] | Maya hair systems: guides expanded into clumps |
//! | [`accel`], [`geometry`], [`shading`], [`light`], [`camera`], [`math`] | the renderer's parts |
//! | [`partial`], [`mod@bench`], [`stats`], [`demo`] | tile merging, benchmarks, timings, the demo scene |
//!
//! [`render`] imports neither [`scene`] nor [`io`], so the renderer never depends on where
//! a scene came from.

pub mod accel;
pub mod bench;
pub mod camera;
pub mod demo;
pub mod error;
pub mod film;
pub mod fur;
pub mod geometry;
pub mod hair_system;
pub mod input_file;
pub mod io;
pub mod light;
pub mod math;
pub mod memory;
pub mod partial;
pub mod prepare;
pub mod render;
pub mod scene;
pub mod shading;
pub mod stats;
#[cfg(test)]
mod test_worlds;
pub mod world;
