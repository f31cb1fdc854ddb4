//! Image files a description names, with how to read them: environment maps
//! ([`EnvironmentFile`], a light) and textures ([`TexturedFiles`], a material). The
//! description holds only their paths; [`crate::prepare`] decodes them.

use crate::light::{Light, MapPlacement};
use crate::math::Color;
use crate::shading::Material;
use std::path::PathBuf;

/// A light in the scene.
#[derive(Clone, Debug, PartialEq)]
pub enum LightSource {
    /// A light given by its values (or an environment map already in memory).
    Inline(Light),
    /// An environment map read from an image file.
    File(EnvironmentFile),
}

impl From<Light> for LightSource {
    fn from(light: Light) -> LightSource {
        LightSource::Inline(light)
    }
}

/// How an environment image covers the sphere of directions.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Projection {
    /// Latitude-longitude, in the layout of [`crate::light::EnvironmentMap`].
    LatLong,
    /// pbrt-v4's equal-area octahedral square (Clarberg 2008), its centre the pole: read
    /// as the latitude-longitude image whose pixel at (s, t) looks along
    /// (sin θ cos φ, sin θ sin φ, cos θ) of the square's frame, φ = 2π s, θ = π t (pbrt-v3's
    /// layout). A map that is not square is read as latitude-longitude, with a warning.
    EqualArea,
}

/// An environment map to be read from an image file (OpenEXR, Radiance `.hdr`, PFM, or an
/// 8-bit PNG or JPEG taken as sRGB).
#[derive(Clone, Debug, PartialEq)]
pub struct EnvironmentFile {
    /// The image.
    pub path: PathBuf,
    /// How its pixels cover the sphere.
    pub projection: Projection,
    /// Factor on every pixel, by channel (the light's colour).
    pub tint: Color,
    /// When given, the pixels are scaled further so that the upper half of the
    /// latitude-longitude image (the hemisphere about its top row) gives this illuminance to
    /// a surface facing its pole (pbrt-v4's `illuminance`).
    pub illuminance: Option<f32>,
    /// Turn and intensity.
    pub placement: MapPlacement,
    /// Radiance of the constant sky that lights the scene, with a warning, when the file
    /// cannot be used; `None` makes that an error.
    pub fallback: Option<Color>,
}

/// A material of the scene.
#[derive(Clone, Debug, PartialEq)]
pub enum MaterialSource {
    /// A material given by its values.
    Inline(Material),
    /// A textured surface ([`crate::shading::Textured`]) whose images are read from files.
    Textured(TexturedFiles),
}

impl From<Material> for MaterialSource {
    fn from(material: Material) -> MaterialSource {
        MaterialSource::Inline(material)
    }
}

/// A textured surface to be read: Lambert with `tint` times the colour texture, plus a
/// specular layer when it has a roughness.
#[derive(Clone, Debug, PartialEq)]
pub struct TexturedFiles {
    /// The colour texture (8-bit images are sRGB-encoded, high-dynamic-range ones linear).
    pub color: PathBuf,
    /// Factor on the texture's colour.
    pub tint: Color,
    /// The specular layer's roughness, `None` for a matte surface.
    pub roughness: Option<RoughnessSource>,
    /// Reflectance of the specular layer at normal incidence.
    pub specular: Color,
}

/// A roughness in (0, 1]: one value, or the red channel of an image read as it is.
#[derive(Clone, Debug, PartialEq)]
pub enum RoughnessSource {
    /// The same everywhere.
    Constant(f32),
    /// An image's red channel, its values taken as linear.
    Map(PathBuf),
}
