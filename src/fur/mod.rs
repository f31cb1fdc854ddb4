//! Maya Fur, rebuilt: grow fur on any triangle mesh from a fur description, as the thesis
//! did in section 2.1.5, and the parts it left out (clumping, attraction to guide curves,
//! mapped ambient colour).
//!
//! - [`description`]: `FurDescription`, every attribute of Maya's FurDescription node under
//!   Maya's names and node defaults (specification `docs/maya-fur-hair.md`).
//! - [`maps`]: attribute maps (images at the surface UV, per-vertex values), multiplier,
//!   offset and noise.
//! - [`presets`]: Maya's fur presets by name, as data files shipped in the crate.
//! - [`generate`]: root placement and hair shape into a [`crate::geometry::StrandSet`].
//! - [`guides`]: attraction toward guide curves.
//!
//! Shading is [`crate::shading::fur_tube`] (thesis eq. 2.4 to 2.7).

pub mod description;
pub mod generate;
pub mod guides;
pub mod maps;
pub mod presets;

pub use description::{ColorAttr, FurDescription, MapSource, Scalar};
pub use generate::{grow, GrowOptions, GrownFur, Placement};
pub use guides::{AttractorModel, Attractors};
pub use maps::{image_map_paths, MapImage};

/// Why fur cannot be grown.
#[derive(Debug, thiserror::Error)]
pub enum FurError {
    /// The description, the mesh or the guides cannot be used as given.
    #[error("{0}")]
    Invalid(String),
}
