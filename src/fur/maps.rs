//! Attribute evaluation over the surface: global value, map, multiplier, offset and noise
//! (specification `docs/maya-fur-hair.md`, section 2.1):
//!
//! ```text
//! base(u, v)  = map present ? map(u, v) * MapMult + MapOffset : X
//! value(u, v) = clamp(base(u, v) + Noise * n(u * NoiseFreq, v * NoiseFreq), min, max)
//! ```
//!
//! `n` is signed 2-D Perlin noise over the surface UV (FastNoise Lite), one independent
//! field per attribute derived from the fur seed. A map replaces the global value where present. The
//! evaluated value is clamped to the attribute's legal range (noise and maps can overshoot
//! it; the global value itself is checked when read). Scalar image maps use the mean of R,
//! G and B; colour maps are decoded from sRGB to linear. Image maps wrap (repeat) in UV,
//! with v = 0 at the bottom row of the image, and are sampled bilinearly.
//!
//! Image files are decoded by [`crate::prepare`], which hands their texels over as
//! [`MapImage`]s; nothing here reads a file.

use super::description::{ColorAttr, FurDescription, MapSource, Scalar};
use super::FurError;
use crate::geometry::TriangleMesh;
use crate::math::noise::{perlin, Perlin};
use crate::math::rng::hash_combine;
use crate::math::Color;
use glam::Vec3;
use std::borrow::Cow;
use std::path::{Path, PathBuf};

/// An image map, decoded: its texels as the file stores them (colour maps still
/// sRGB-encoded), row 0 at the top (v = 1).
#[derive(Clone, Debug, PartialEq)]
pub struct MapImage {
    /// The file it was decoded from, as the description names it.
    pub path: PathBuf,
    /// Width in texels.
    pub width: u32,
    /// Height in texels.
    pub height: u32,
    /// RGB texels, row by row from the top; `width * height` of them.
    pub texels: Vec<[f32; 3]>,
}

/// The image files a description's maps name, each once, in attribute order.
pub fn image_map_paths(desc: &FurDescription) -> Vec<&Path> {
    let scalars = Scalar::ALL.into_iter().map(|s| desc[s].map.as_ref());
    let colors = ColorAttr::ALL.into_iter().map(|c| desc[c].map.as_ref());
    let mut paths: Vec<&Path> = Vec::new();
    for map in scalars.chain(colors).flatten() {
        if let MapSource::Image(path) = map {
            if !paths.contains(&path.as_path()) {
                paths.push(path);
            }
        }
    }
    paths
}

/// A point on the mesh where attributes are evaluated.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SurfacePoint {
    /// Triangle index.
    pub tri: u32,
    /// Barycentric weight of the triangle's second corner.
    pub b1: f32,
    /// Barycentric weight of the third corner.
    pub b2: f32,
    /// Surface UV (zero on meshes without UVs).
    pub uv: [f32; 2],
}

/// A map's values, ready to sample.
#[derive(Clone, Debug)]
enum Map<'a> {
    /// Linear RGB texels, row 0 at the top (v = 1).
    Image { width: u32, height: u32, texels: Cow<'a, [[f32; 3]]> },
    /// One value per vertex.
    Vertex(Vec<[f32; 3]>),
}

impl Map<'_> {
    fn sample(&self, mesh: &TriangleMesh, at: &SurfacePoint) -> Vec3 {
        match self {
            Map::Vertex(values) => {
                let [a, b, c] = mesh.indices[at.tri as usize];
                let v = |i: u32| Vec3::from(values[i as usize]);
                v(a) * (1.0 - at.b1 - at.b2) + v(b) * at.b1 + v(c) * at.b2
            }
            Map::Image { width, height, texels } => {
                let (w, h) = (*width as i64, *height as i64);
                // Texel centres at (i + 0.5) / w; v runs up the image.
                let x = at.uv[0] * *width as f32 - 0.5;
                let y = (1.0 - at.uv[1]) * *height as f32 - 0.5;
                let (x, y) = if x.is_finite() && y.is_finite() { (x, y) } else { (0.0, 0.0) };
                let (x0, y0) = (x.floor(), y.floor());
                let (fx, fy) = (x - x0, y - y0);
                let texel = |i: i64, j: i64| Vec3::from(texels[(j.rem_euclid(h) * w + i.rem_euclid(w)) as usize]);
                let (i, j) = (x0 as i64, y0 as i64);
                let top = texel(i, j).lerp(texel(i + 1, j), fx);
                let bottom = texel(i, j + 1).lerp(texel(i + 1, j + 1), fx);
                top.lerp(bottom, fy)
            }
        }
    }
}

/// An attribute's noise: field, amplitude, frequency and a domain offset.
struct Noise {
    field: Perlin,
    amplitude: f32,
    freq: f32,
    offset: [f32; 2],
}

/// One attribute, ready to evaluate.
struct Field<'a> {
    value: Vec3,
    map: Option<(Map<'a>, f32, f32)>,
    noise: Option<Noise>,
    min: f32,
    max: f32,
}

impl Field<'_> {
    fn eval(&self, mesh: &TriangleMesh, at: &SurfacePoint, scalar: bool) -> Vec3 {
        if self.is_uniform() {
            return self.value.clamp(Vec3::splat(self.min), Vec3::splat(self.max));
        }
        let mut v = match &self.map {
            Some((map, mult, offset)) => {
                let m = map.sample(mesh, at);
                let m = if scalar { Vec3::splat((m.x + m.y + m.z) / 3.0) } else { m };
                m * *mult + Vec3::splat(*offset)
            }
            None => self.value,
        };
        if let Some(n) = &self.noise {
            let x = n.field.get_noise_2d(at.uv[0] * n.freq + n.offset[0], at.uv[1] * n.freq + n.offset[1]);
            v += Vec3::splat(n.amplitude * x);
        }
        v.clamp(Vec3::splat(self.min), Vec3::splat(self.max))
    }

    fn is_uniform(&self) -> bool {
        self.map.is_none() && self.noise.is_none()
    }
}

/// A description's attributes resolved on one mesh: maps loaded and checked, noise
/// fields seeded. Evaluation is read-only and can run on many threads.
pub struct Attributes<'a> {
    mesh: &'a TriangleMesh,
    scalars: Vec<Field<'a>>,
    colors: Vec<Field<'a>>,
}

/// sRGB transfer function to linear (IEC 61966-2-1).
fn srgb_to_linear(c: f32) -> f32 {
    if c <= 0.04045 {
        c / 12.92
    } else {
        ((c + 0.055) / 1.055).powf(2.4)
    }
}

fn load_map<'a>(
    source: &MapSource,
    key: &str,
    mesh: &TriangleMesh,
    images: &'a [MapImage],
    color: bool,
) -> Result<Map<'a>, FurError> {
    match source {
        MapSource::Image(path) => {
            if mesh.uvs.is_none() {
                return Err(FurError::Invalid(format!("the mesh has no UVs, which the image map `{key}` needs")));
            }
            let Some(image) = images.iter().find(|i| i.path == *path) else {
                return Err(FurError::Invalid(format!("the image map `{key}` ({}) was not decoded", path.display())));
            };
            let texels = match color {
                true => Cow::Owned(image.texels.iter().map(|t| t.map(srgb_to_linear)).collect()),
                false => Cow::Borrowed(image.texels.as_slice()),
            };
            Ok(Map::Image { width: image.width, height: image.height, texels })
        }
        MapSource::Vertex(values) => {
            if values.len() != mesh.positions.len() {
                return Err(FurError::Invalid(format!(
                    "`{key}` has {} values but the mesh has {} vertices",
                    values.len(),
                    mesh.positions.len()
                )));
            }
            Ok(Map::Vertex(values.clone()))
        }
    }
}

/// Salt of the noise fields' seeds.
const NOISE_SALT: u32 = 0x4e4f_4953;

fn noise_field(
    seed: u32,
    index: u32,
    amplitude: f32,
    freq: f32,
    key: &str,
    mesh: &TriangleMesh,
) -> Result<Option<Noise>, FurError> {
    if amplitude == 0.0 {
        return Ok(None);
    }
    if mesh.uvs.is_none() {
        return Err(FurError::Invalid(format!("the mesh has no UVs, which `{key}_noise` needs")));
    }
    let h = hash_combine(&[seed, NOISE_SALT, index]);
    // Shift each field's lattice (where Perlin noise is zero) away from the others'.
    let offset = [(h & 0xffff) as f32 / 256.0, (h >> 16) as f32 / 256.0];
    Ok(Some(Noise { field: perlin(h), amplitude, freq, offset }))
}

impl<'a> Attributes<'a> {
    /// Resolves the maps of `desc` for `mesh` (image maps from `images`, decoded from the
    /// files [`image_map_paths`] lists) and seeds the noise fields from `seed`.
    ///
    /// Errors: an image map missing from `images`, a per-vertex map whose length is not
    /// the mesh's vertex count, an image map or noise on a mesh without UVs.
    pub fn resolve(
        desc: &FurDescription,
        mesh: &'a TriangleMesh,
        images: &'a [MapImage],
        seed: u32,
    ) -> Result<Attributes<'a>, FurError> {
        let mut scalars = Vec::with_capacity(Scalar::COUNT);
        for (i, s) in Scalar::ALL.into_iter().enumerate() {
            let (spec, a) = (s.spec(), &desc[s]);
            let key = format!("{}_map", spec.name);
            let map = a.map.as_ref().map(|m| load_map(m, &key, mesh, images, false)).transpose()?;
            scalars.push(Field {
                value: Vec3::splat(a.value),
                map: map.map(|m| (m, a.map_mult, a.map_offset)),
                noise: noise_field(seed, i as u32, a.noise, a.noise_freq, spec.name, mesh)?,
                min: spec.min,
                max: spec.max,
            });
        }
        let mut colors = Vec::with_capacity(ColorAttr::COUNT);
        for (i, c) in ColorAttr::ALL.into_iter().enumerate() {
            let (name, a) = (c.spec().name, &desc[c]);
            let key = format!("{name}_map");
            let map = a.map.as_ref().map(|m| load_map(m, &key, mesh, images, true)).transpose()?;
            colors.push(Field {
                value: a.value,
                map: map.map(|m| (m, 1.0, 0.0)),
                noise: noise_field(seed, (Scalar::COUNT + i) as u32, a.noise, a.noise_freq, name, mesh)?,
                min: 0.0,
                max: f32::MAX,
            });
        }
        Ok(Attributes { mesh, scalars, colors })
    }

    /// The scalar attribute `s` at a surface point.
    #[inline]
    pub fn scalar(&self, s: Scalar, at: &SurfacePoint) -> f32 {
        self.scalars[s as usize].eval(self.mesh, at, true).x
    }

    /// The colour attribute `c` at a surface point.
    #[inline]
    pub fn color(&self, c: ColorAttr, at: &SurfacePoint) -> Color {
        self.colors[c as usize].eval(self.mesh, at, false)
    }

    /// True when scalar `s` is the same everywhere (no map, no noise).
    pub fn scalar_is_uniform(&self, s: Scalar) -> bool {
        self.scalars[s as usize].is_uniform()
    }

    /// True when colour `c` is the same everywhere.
    pub fn color_is_uniform(&self, c: ColorAttr) -> bool {
        self.colors[c as usize].is_uniform()
    }

    /// True when scalar `s` is 0 everywhere on the surface.
    pub fn scalar_is_zero(&self, s: Scalar) -> bool {
        let f = &self.scalars[s as usize];
        f.is_uniform() && f.value.x.clamp(f.min, f.max) == 0.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn at(tri: u32, b1: f32, b2: f32, uv: [f32; 2]) -> SurfacePoint {
        SurfacePoint { tri, b1, b2, uv }
    }

    #[test]
    fn map_replaces_value_with_mult_and_offset_and_is_clamped() {
        let mesh = TriangleMesh::plane(1.0);
        let mut d = FurDescription::default();
        d[Scalar::Length].value = 7.0;
        d[Scalar::Length].map = Some(MapSource::Vertex(vec![[0.0; 3], [1.0; 3], [0.5; 3], [0.5; 3]]));
        d[Scalar::Length].map_mult = 4.0;
        d[Scalar::Length].map_offset = 1.0;
        d[Scalar::Baldness].map = Some(MapSource::Vertex(vec![[3.0; 3]; 4]));
        let a = Attributes::resolve(&d, &mesh, &[], 0).unwrap();
        // Triangle 0 is vertices (0, 2, 1): values 0, 0.5, 1.
        assert_eq!(a.scalar(Scalar::Length, &at(0, 0.0, 0.0, [0.0; 2])), 1.0);
        assert_eq!(a.scalar(Scalar::Length, &at(0, 1.0, 0.0, [0.0; 2])), 3.0);
        assert_eq!(a.scalar(Scalar::Length, &at(0, 0.0, 1.0, [0.0; 2])), 5.0);
        // A map value above the legal range is clamped (baldness <= 1).
        assert_eq!(a.scalar(Scalar::Baldness, &at(1, 0.3, 0.3, [0.0; 2])), 1.0);
        assert!(!a.scalar_is_uniform(Scalar::Length) && a.scalar_is_uniform(Scalar::Roll));
    }

    #[test]
    fn noise_is_smooth_signed_bounded_and_seeded() {
        let mesh = TriangleMesh::plane(1.0);
        let mut d = FurDescription::default();
        d[Scalar::Inclination].value = 0.5;
        d[Scalar::Inclination].noise = 0.3;
        d[Scalar::Inclination].noise_freq = 5.0;
        let a = Attributes::resolve(&d, &mesh, &[], 1).unwrap();
        let b = Attributes::resolve(&d, &mesh, &[], 2).unwrap();
        let (mut lo, mut hi, mut differs, mut max_step) = (1.0f32, 0.0f32, false, 0.0f32);
        let mut prev: Option<f32> = None;
        for i in 0..1000 {
            let p = at(0, 0.0, 0.0, [i as f32 / 1000.0, 0.37]);
            let v = a.scalar(Scalar::Inclination, &p);
            lo = lo.min(v);
            hi = hi.max(v);
            differs |= v != b.scalar(Scalar::Inclination, &p);
            if let Some(q) = prev {
                max_step = max_step.max((v - q).abs());
            }
            prev = Some(v);
        }
        assert!(lo < 0.45 && hi > 0.55, "noise should move the value both ways: {lo}..{hi}");
        assert!(lo >= 0.5 - 0.3 && hi <= 0.5 + 0.3, "amplitude bounds the noise: {lo}..{hi}");
        assert!(max_step < 0.05, "noise at frequency 5 is smooth over 1/1000 of UV: {max_step}");
        assert!(differs, "another seed gives another field");
    }

    #[test]
    fn images_are_sampled_at_uv_with_v_up_and_colour_maps_linearised() {
        // 2x1 image: left black, right white; a 1x2 image: top white, bottom black.
        let image = |path: &str, width, height, texels: Vec<[f32; 3]>| MapImage {
            path: PathBuf::from(path),
            width,
            height,
            texels,
        };
        let grey = 128.0 / 255.0;
        let images = [
            image("map.png", 2, 1, vec![[0.0; 3], [1.0; 3]]),
            image("tall.png", 1, 2, vec![[1.0; 3], [0.0; 3]]),
            image("grey.png", 1, 1, vec![[grey; 3]]),
        ];
        let mesh = TriangleMesh::plane(1.0);
        let mut d = FurDescription::default();
        d[Scalar::Length].map = Some(MapSource::Image("map.png".into()));
        d[Scalar::Inclination].map = Some(MapSource::Image("tall.png".into()));
        d[ColorAttr::BaseColor].map = Some(MapSource::Image("grey.png".into()));
        d[Scalar::Roll].map = Some(MapSource::Image("grey.png".into()));
        assert_eq!(image_map_paths(&d), [Path::new("map.png"), Path::new("tall.png"), Path::new("grey.png")]);
        let a = Attributes::resolve(&d, &mesh, &images, 0).unwrap();
        let l = |u: f32| a.scalar(Scalar::Length, &at(0, 0.0, 0.0, [u, 0.5]));
        assert_eq!((l(0.25), l(0.75)), (0.0, 1.0));
        assert!((l(0.5) - 0.5).abs() < 1e-6, "bilinear between texel centres");
        let i = |v: f32| a.scalar(Scalar::Inclination, &at(0, 0.0, 0.0, [0.5, v]));
        assert_eq!((i(0.25), i(0.75)), (0.0, 1.0), "v = 1 is the top row");
        let c = a.color(ColorAttr::BaseColor, &at(0, 0.0, 0.0, [0.5, 0.5]));
        assert!((c.x - 0.2158).abs() < 1e-3, "sRGB 128 decodes to 0.216, got {c}");
        let r = a.scalar(Scalar::Roll, &at(0, 0.0, 0.0, [0.5, 0.5]));
        assert!((r - grey).abs() < 1e-6, "scalar maps are read as data");
    }

    #[test]
    fn bad_maps_are_errors_naming_the_problem() {
        let mesh = TriangleMesh::plane(1.0);
        let err =
            |d: &FurDescription, mesh: &TriangleMesh| Attributes::resolve(d, mesh, &[], 0).err().unwrap().to_string();
        let mut d = FurDescription::default();
        d[Scalar::Length].map = Some(MapSource::Image("absent.png".into()));
        let e = err(&d, &mesh);
        assert!(e.contains("absent.png") && e.contains("length_map"), "{e}");
        d[Scalar::Length].map = Some(MapSource::Vertex(vec![[1.0; 3]; 3]));
        let e = err(&d, &mesh);
        assert!(e.contains("length_map") && e.contains("3 values") && e.contains("4 vertices"), "{e}");
        let mut bare = mesh.clone();
        bare.uvs = None;
        let mut d = FurDescription::default();
        d[Scalar::Polar].map = Some(MapSource::Image("junk.png".into()));
        let e = err(&d, &bare);
        assert!(e.contains("no UVs") && e.contains("polar_map"), "{e}");
        let mut d = FurDescription::default();
        d[ColorAttr::TipColor].noise = 0.1;
        let e = err(&d, &bare);
        assert!(e.contains("no UVs") && e.contains("tip_color_noise"), "{e}");
        // Per-vertex maps need no UVs.
        let mut d = FurDescription::default();
        d[Scalar::Length].map = Some(MapSource::Vertex(vec![[1.0; 3]; 4]));
        assert!(Attributes::resolve(&d, &bare, &[], 0).is_ok());
    }
}
