//! Maya Hair: hair systems that expand a few guide ("master") hairs into clumps of render
//! hairs (thesis section 2.1.3; docs/maya-fur-hair.md section 5).
//!
//! Guides come from a `.hair` file or are grown as follicles on a mesh
//! ([`follicles`], what Maya's Create Hair dialog does); [`mod@expand`] turns them into a
//! [`StrandSet`] of render hairs with the attributes of a [`HairSystem`]. Everything is a
//! pure function of its inputs and a seed, so a scene gives the same hair on any number
//! of threads.

mod color;
pub mod expand;
pub mod follicles;
pub mod ramp;
pub mod system;

pub use expand::{expand, HairColors, MAX_RENDER_POINTS};
pub use follicles::{grow_guides, FollicleParams, Placement};
pub use ramp::{Interp, Ramp, RampKey};
pub use system::{HairSystem, NoiseMethod};

use crate::geometry::StrandSet;

/// Guide curves: one strand per guide (a clump of render hairs), roots first.
#[derive(Clone, Debug, PartialEq)]
pub struct Guides {
    /// The curves; point radii are not used. Per-point colours, when present, can colour
    /// the render hairs ([`HairColors::Guides`]).
    pub curves: StrandSet,
    /// UV of each guide's root on the surface it grows from; `None` for guides read from a
    /// file, which have no surface.
    pub root_uv: Option<Vec<[f32; 2]>>,
}

impl Guides {
    /// Guides from curves without a surface (a `.hair` file).
    pub fn from_curves(curves: StrandSet) -> Guides {
        Guides { curves, root_uv: None }
    }
}
