//! tress: a ray tracer for hair and fur.
//!
//! Data flows one way (see `docs/architecture.md`):
//! scene description ([`scene`], [`io`]) -> geometry ([`geometry`]) -> acceleration ([`accel`])
//! -> integrator ([`render`]) -> film ([`film`]) -> file.
//!
//! The prepared [`scene::World`] is plain data with no file paths, so the renderer never
//! depends on where a scene came from.

pub mod accel;
pub mod bench;
pub mod camera;
pub mod demo;
pub mod film;
pub mod fur;
pub mod geometry;
pub mod hair_system;
pub mod io;
pub mod light;
pub mod math;
pub mod partial;
pub mod render;
pub mod scene;
pub mod shading;
pub mod stats;
