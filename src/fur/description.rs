//! `FurDescription`: every attribute of Maya Fur's FurDescription node (specification
//! `docs/maya-fur-hair.md`, table 2.2) under Maya's names, with Maya's *node*
//! defaults, so a description that only states changed values (as Maya files do) means
//! what it meant in Maya.
//!
//! Attributes are kept in arrays indexed by [`Scalar`] and [`ColorAttr`], and described by
//! one table each ([`Scalar::spec`], [`ColorAttr::spec`]): parsing, range checks and
//! evaluation walk the table instead of repeating code per attribute.
//!
//! In a scene or preset file an attribute is named in snake case (`base_curl`) or by
//! Maya's short name (`dbcl`). Each mappable attribute `x` also takes `x_map` (an image
//! file sampled at the surface UV, or one value per mesh vertex), `x_noise` and
//! `x_noise_freq`; scalar ones also take `x_map_offset` and `x_map_mult` (section 2.1).

use crate::math::Color;
use crate::shading::fur_tube::LightModel;
use std::path::{Path, PathBuf};

/// A scalar, mappable fur attribute.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Scalar {
    /// Length (`.dl`): hair length in world units, times Global Scale.
    Length,
    /// Baldness (`.db`): amount of fur, 1 full, 0 bald; a hair is kept with this probability.
    Baldness,
    /// Inclination (`.di`): 0 along the normal, 1 flat on the surface.
    Inclination,
    /// Roll (`.dr`): turns the curl plane about the hair's root direction, 0 = -90 degrees,
    /// 0.5 none, 1 = +90 degrees.
    Roll,
    /// Polar (`.dp`): turns the hair about the normal, 0 = -180 degrees, 0.5 none,
    /// 1 = +180 degrees.
    Polar,
    /// Base Width (`.dbw`): hair thickness (a diameter) at the root, world units.
    BaseWidth,
    /// Tip Width (`.dtw`): thickness at the tip.
    TipWidth,
    /// Base Curl (`.dbcl`): curl near the root, 0 and 1 half a circle either way, 0.5 none.
    BaseCurl,
    /// Tip Curl (`.dtcl`): curl near the tip, same encoding.
    TipCurl,
    /// Scraggle (`.ds`): crookedness, 0 none, 1 full.
    Scraggle,
    /// Scraggle Frequency (`.dsf`): kinks along a hair.
    ScraggleFrequency,
    /// Scraggle Correlation (`.dsco`): 0 every hair its own kinks, 1 all hairs alike.
    ScraggleCorrelation,
    /// Clumping (`.dc`): pull of hairs toward their clump's centre hair.
    Clumping,
    /// Clumping Frequency (`.dcf`): clumps across the surface (about its square in all).
    ClumpingFrequency,
    /// Clump Shape (`.dcs`): profile of the pull along the hair, -10 concave to +10 convex.
    ClumpShape,
    /// Offset (`.dofs`): root offset along the normal, world units.
    Offset,
    /// Attraction (`.dat`): how strongly hairs follow attractor curves.
    Attraction,
    /// Base Opacity (`.dbo`): opacity at the root.
    BaseOpacity,
    /// Tip Opacity (`.dto`): opacity at the tip.
    TipOpacity,
    /// Specular Sharpness (`.dss`): the specular exponent.
    SpecularSharpness,
}

/// A colour, mappable fur attribute.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ColorAttr {
    /// Base Color (`.dbc`): diffuse colour at the root.
    BaseColor,
    /// Tip Color (`.dtc`): diffuse colour at the tip.
    TipColor,
    /// Base Ambient Color (`.dbac`): ambient colour at the root.
    BaseAmbientColor,
    /// Tip Ambient Color (`.dtac`): ambient colour at the tip.
    TipAmbientColor,
    /// Specular Color (`.dsc`): highlight colour.
    SpecularColor,
}

/// Name, Maya names, node default and legal range of a scalar attribute.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ScalarSpec {
    /// Name in scene and preset files (snake case of Maya's long name).
    pub name: &'static str,
    /// Maya's long name.
    pub maya: &'static str,
    /// Maya's short name (accepted in files too).
    pub short: &'static str,
    /// Maya's node default.
    pub default: f32,
    /// Smallest legal value.
    pub min: f32,
    /// Largest legal value.
    pub max: f32,
}

/// Name, Maya names and node default of a colour attribute (legal range: each channel
/// finite and at least 0).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ColorSpec {
    /// Name in scene and preset files.
    pub name: &'static str,
    /// Maya's long name.
    pub maya: &'static str,
    /// Maya's short name.
    pub short: &'static str,
    /// Maya's node default.
    pub default: [f32; 3],
}

const fn scalar(
    name: &'static str,
    maya: &'static str,
    short: &'static str,
    default: f32,
    min: f32,
    max: f32,
) -> ScalarSpec {
    ScalarSpec { name, maya, short, default, min, max }
}

/// Upper bound of the frequencies, so a typo cannot ask for billions of clumps or kinks.
const MAX_FREQUENCY: f32 = 1000.0;

/// The scalar attributes' table, in [`Scalar`] order (spec table 2.2, node defaults).
const SCALARS: [ScalarSpec; Scalar::COUNT] = [
    scalar("length", "Length", "dl", 1.0, 0.0, f32::MAX),
    scalar("baldness", "Baldness", "db", 1.0, 0.0, 1.0),
    scalar("inclination", "Inclination", "di", 0.0, 0.0, 1.0),
    scalar("roll", "Roll", "dr", 0.0, 0.0, 1.0),
    scalar("polar", "Polar", "dp", 0.0, 0.0, 1.0),
    scalar("base_width", "BaseWidth", "dbw", 0.0, 0.0, f32::MAX),
    scalar("tip_width", "TipWidth", "dtw", 0.0, 0.0, f32::MAX),
    scalar("base_curl", "BaseCurl", "dbcl", 0.0, 0.0, 1.0),
    scalar("tip_curl", "TipCurl", "dtcl", 0.0, 0.0, 1.0),
    scalar("scraggle", "Scraggle", "ds", 0.0, 0.0, 1.0),
    scalar("scraggle_frequency", "ScraggleFrequency", "dsf", 5.0, 0.0, MAX_FREQUENCY),
    scalar("scraggle_correlation", "ScraggleCorrelation", "dsco", 0.0, 0.0, 1.0),
    scalar("clumping", "Clumping", "dc", 0.0, 0.0, 1.0),
    scalar("clumping_frequency", "ClumpingFrequency", "dcf", 50.0, 0.0, MAX_FREQUENCY),
    scalar("clump_shape", "ClumpShape", "dcs", 0.0, -10.0, 10.0),
    scalar("offset", "Offset", "dofs", 0.0, f32::MIN, f32::MAX),
    scalar("attraction", "Attraction", "dat", 1.0, 0.0, 1.0),
    scalar("base_opacity", "BaseOpacity", "dbo", 1.0, 0.0, 1.0),
    scalar("tip_opacity", "TipOpacity", "dto", 1.0, 0.0, 1.0),
    scalar("specular_sharpness", "SpecularSharpness", "dss", 5.0, 0.0, f32::MAX),
];

/// The colour attributes' table, in [`ColorAttr`] order.
const COLORS: [ColorSpec; ColorAttr::COUNT] = [
    ColorSpec { name: "base_color", maya: "BaseColor", short: "dbc", default: [1.0; 3] },
    ColorSpec { name: "tip_color", maya: "TipColor", short: "dtc", default: [1.0; 3] },
    ColorSpec { name: "base_ambient_color", maya: "BaseAmbientColor", short: "dbac", default: [0.0; 3] },
    ColorSpec { name: "tip_ambient_color", maya: "TipAmbientColor", short: "dtac", default: [0.0; 3] },
    ColorSpec { name: "specular_color", maya: "SpecularColor", short: "dsc", default: [0.5; 3] },
];

impl Scalar {
    /// Number of scalar attributes.
    pub const COUNT: usize = 20;
    /// Every scalar attribute, in table order.
    pub const ALL: [Scalar; Scalar::COUNT] = [
        Scalar::Length,
        Scalar::Baldness,
        Scalar::Inclination,
        Scalar::Roll,
        Scalar::Polar,
        Scalar::BaseWidth,
        Scalar::TipWidth,
        Scalar::BaseCurl,
        Scalar::TipCurl,
        Scalar::Scraggle,
        Scalar::ScraggleFrequency,
        Scalar::ScraggleCorrelation,
        Scalar::Clumping,
        Scalar::ClumpingFrequency,
        Scalar::ClumpShape,
        Scalar::Offset,
        Scalar::Attraction,
        Scalar::BaseOpacity,
        Scalar::TipOpacity,
        Scalar::SpecularSharpness,
    ];

    /// The attribute's names, default and range.
    pub fn spec(self) -> &'static ScalarSpec {
        &SCALARS[self as usize]
    }
}

impl ColorAttr {
    /// Number of colour attributes.
    pub const COUNT: usize = 5;
    /// Every colour attribute, in table order.
    pub const ALL: [ColorAttr; ColorAttr::COUNT] = [
        ColorAttr::BaseColor,
        ColorAttr::TipColor,
        ColorAttr::BaseAmbientColor,
        ColorAttr::TipAmbientColor,
        ColorAttr::SpecularColor,
    ];

    /// The attribute's names and default.
    pub fn spec(self) -> &'static ColorSpec {
        &COLORS[self as usize]
    }
}

/// Where an attribute map's values come from.
#[derive(Clone, Debug, PartialEq)]
pub enum MapSource {
    /// An image file (PNG or JPEG) sampled at the surface UV. Scalars use the mean of R, G
    /// and B in [0, 1]; colours are decoded from sRGB to linear.
    Image(PathBuf),
    /// One value per mesh vertex, interpolated across triangles (scalars repeat the value
    /// in all three channels).
    Vertex(Vec<[f32; 3]>),
}

/// A scalar attribute: its global value, optional map, and noise (spec section 2.1).
#[derive(Clone, Debug, PartialEq)]
pub struct ScalarAttribute {
    /// The global value (Maya's `X`).
    pub value: f32,
    /// A map that replaces the global value where present (`XMap`).
    pub map: Option<MapSource>,
    /// Added to the map value (`XMapOffset`).
    pub map_offset: f32,
    /// Multiplies the map value (`XMapMult`).
    pub map_mult: f32,
    /// Noise amplitude (`XNoise`); 0 = none.
    pub noise: f32,
    /// Noise frequency over the UV square (`XNoiseFreq`).
    pub noise_freq: f32,
}

/// A colour attribute: global value, optional map and noise (Maya stores no map offset or
/// multiplier for colours).
#[derive(Clone, Debug, PartialEq)]
pub struct ColorAttribute {
    /// The global value.
    pub value: Color,
    /// A map that replaces the global value where present.
    pub map: Option<MapSource>,
    /// Noise amplitude, added to all three channels alike (a brightness variation).
    pub noise: f32,
    /// Noise frequency over the UV square.
    pub noise_freq: f32,
}

/// Maya's node default of an attribute's noise frequency.
const DEFAULT_NOISE_FREQ: f32 = 10.0;

/// Most hairs one description may ask for, so a typo cannot exhaust memory.
pub const MAX_DENSITY: u32 = 50_000_000;
/// Most segments per hair.
pub const MAX_SEGMENTS: u32 = 256;

/// A Maya FurDescription: everything needed to grow and shade fur on a surface.
#[derive(Clone, Debug, PartialEq)]
pub struct FurDescription {
    /// Light Model (`.lmd`), default ambient + diffuse + specular.
    pub light_model: LightModel,
    /// Density (`.d`): expected number of hairs on the whole surface (Maya's "per fur
    /// description" area values for one surface), before baldness; default 1000.
    pub density: u32,
    /// Global Scale (`.gs`): factor on Length, Base and Tip Width and Offset; default 1.
    pub global_scale: f32,
    /// Segments (`.dsg`): segments per hair; node default 1.
    pub segments: u32,
    /// The scalar attributes, indexed by [`Scalar`].
    pub scalars: [ScalarAttribute; Scalar::COUNT],
    /// The colour attributes, indexed by [`ColorAttr`].
    pub colors: [ColorAttribute; ColorAttr::COUNT],
}

impl Default for FurDescription {
    /// Maya's node defaults: the values of a bare `createNode FurDescription`.
    fn default() -> Self {
        FurDescription {
            light_model: LightModel::default(),
            density: 1000,
            global_scale: 1.0,
            segments: 1,
            scalars: Scalar::ALL.map(|s| ScalarAttribute {
                value: s.spec().default,
                map: None,
                map_offset: 0.0,
                map_mult: 1.0,
                noise: 0.0,
                noise_freq: DEFAULT_NOISE_FREQ,
            }),
            colors: ColorAttr::ALL.map(|c| ColorAttribute {
                value: Color::from(c.spec().default),
                map: None,
                noise: 0.0,
                noise_freq: DEFAULT_NOISE_FREQ,
            }),
        }
    }
}

impl std::ops::Index<Scalar> for FurDescription {
    type Output = ScalarAttribute;
    fn index(&self, s: Scalar) -> &ScalarAttribute {
        &self.scalars[s as usize]
    }
}

impl std::ops::IndexMut<Scalar> for FurDescription {
    fn index_mut(&mut self, s: Scalar) -> &mut ScalarAttribute {
        &mut self.scalars[s as usize]
    }
}

impl std::ops::Index<ColorAttr> for FurDescription {
    type Output = ColorAttribute;
    fn index(&self, c: ColorAttr) -> &ColorAttribute {
        &self.colors[c as usize]
    }
}

impl std::ops::IndexMut<ColorAttr> for FurDescription {
    fn index_mut(&mut self, c: ColorAttr) -> &mut ColorAttribute {
        &mut self.colors[c as usize]
    }
}

/// The parts of a mappable attribute a file key can set.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Part {
    Value,
    Map,
    MapOffset,
    MapMult,
    Noise,
    NoiseFreq,
}

/// Key suffixes, longest first so `_map_offset` is not read as `_map`.
const SUFFIXES: [(&str, Part); 5] = [
    ("_map_offset", Part::MapOffset),
    ("_map_mult", Part::MapMult),
    ("_noise_freq", Part::NoiseFreq),
    ("_map", Part::Map),
    ("_noise", Part::Noise),
];

/// A mappable attribute named by a key.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Target {
    Scalar(Scalar),
    Color(ColorAttr),
}

fn target(name: &str) -> Option<Target> {
    Scalar::ALL.into_iter().find(|s| s.spec().name == name || s.spec().short == name).map(Target::Scalar).or_else(
        || ColorAttr::ALL.into_iter().find(|c| c.spec().name == name || c.spec().short == name).map(Target::Color),
    )
}

fn number(key: &str, v: &toml::Value) -> Result<f32, String> {
    let x = match v {
        toml::Value::Float(f) => *f as f32,
        toml::Value::Integer(i) => *i as f32,
        _ => return Err(format!("`{key}` must be a number")),
    };
    if x.is_finite() {
        Ok(x)
    } else {
        Err(format!("`{key}` = {x} is not a finite number"))
    }
}

fn integer(key: &str, v: &toml::Value, min: i64, max: i64) -> Result<i64, String> {
    match v {
        toml::Value::Integer(i) if (min..=max).contains(i) => Ok(*i),
        toml::Value::Integer(i) => Err(format!("`{key}` = {i} is out of range ({min} to {max})")),
        _ => Err(format!("`{key}` must be an integer")),
    }
}

fn color(key: &str, v: &toml::Value) -> Result<[f32; 3], String> {
    let not = || format!("`{key}` must be a colour [r, g, b] of finite numbers >= 0");
    let a = v.as_array().filter(|a| a.len() == 3).ok_or_else(not)?;
    let mut c = [0.0; 3];
    for (ci, vi) in c.iter_mut().zip(a) {
        *ci = number(key, vi).map_err(|_| not())?;
        if *ci < 0.0 {
            return Err(not());
        }
    }
    Ok(c)
}

/// Reads a map: a file name (relative to `base`), or an array of per-vertex values
/// (numbers for scalars, `[r, g, b]` for colours).
fn map_source(key: &str, v: &toml::Value, base: &Path, is_color: bool) -> Result<MapSource, String> {
    match v {
        toml::Value::String(s) if !s.is_empty() => Ok(MapSource::Image(base.join(s))),
        toml::Value::Array(a) => {
            let values = a
                .iter()
                .map(|x| match is_color {
                    true => color(key, x),
                    false => number(key, x).map(|n| [n; 3]),
                })
                .collect::<Result<Vec<_>, _>>()?;
            Ok(MapSource::Vertex(values))
        }
        _ => Err(format!(
            "`{key}` must be an image file name or an array of per-vertex {}",
            if is_color { "colours" } else { "numbers" }
        )),
    }
}

fn in_range(key: &str, x: f32, min: f32, max: f32) -> Result<f32, String> {
    if (min..=max).contains(&x) {
        return Ok(x);
    }
    let bound = |b: f32| match b {
        f32::MAX => "no limit".to_string(),
        f32::MIN => "no limit".to_string(),
        b => b.to_string(),
    };
    Err(format!("`{key}` = {x} is out of range ({} to {})", bound(min), bound(max)))
}

impl FurDescription {
    /// Sets the attributes a TOML table names (a preset file, or the attribute keys of a
    /// scene's `[[fur]]` entry). Map file names are relative to `base`. An unknown key, a
    /// wrong type, a non-finite number or a value outside the attribute's range is an
    /// error naming the key; nothing is clamped here (evaluated values are, see
    /// [`crate::fur::maps`]).
    pub fn apply_table(&mut self, table: &toml::Table, base: &Path) -> Result<(), String> {
        for (key, v) in table {
            self.apply(key, v, base)?;
        }
        Ok(())
    }

    fn apply(&mut self, key: &str, v: &toml::Value, base: &Path) -> Result<(), String> {
        match key {
            "light_model" | "lmd" => {
                let i = integer(key, v, 0, 3)?;
                self.light_model = LightModel::from_index(i).expect("checked range");
                return Ok(());
            }
            "density" | "d" => {
                self.density = integer(key, v, 0, MAX_DENSITY as i64)? as u32;
                return Ok(());
            }
            "global_scale" | "gs" => {
                self.global_scale = in_range(key, number(key, v)?, 0.0, f32::MAX)?;
                return Ok(());
            }
            "segments" | "dsg" => {
                self.segments = integer(key, v, 1, MAX_SEGMENTS as i64)? as u32;
                return Ok(());
            }
            _ => {}
        }
        let (name, part) = match target(key) {
            Some(_) => (key, Part::Value),
            None => SUFFIXES
                .iter()
                .find_map(|&(suffix, part)| key.strip_suffix(suffix).map(|name| (name, part)))
                .ok_or_else(|| format!("unknown fur attribute `{key}`"))?,
        };
        let unknown = || format!("unknown fur attribute `{key}`");
        match (target(name).ok_or_else(unknown)?, part) {
            (Target::Scalar(s), part) => {
                let spec = s.spec();
                let a = &mut self[s];
                match part {
                    Part::Value => a.value = in_range(key, number(key, v)?, spec.min, spec.max)?,
                    Part::Map => a.map = Some(map_source(key, v, base, false)?),
                    Part::MapOffset => a.map_offset = number(key, v)?,
                    Part::MapMult => a.map_mult = number(key, v)?,
                    Part::Noise => a.noise = in_range(key, number(key, v)?, 0.0, f32::MAX)?,
                    Part::NoiseFreq => a.noise_freq = in_range(key, number(key, v)?, 0.0, 1.0e6)?,
                }
            }
            (Target::Color(c), part) => {
                let a = &mut self[c];
                match part {
                    Part::Value => a.value = Color::from(color(key, v)?),
                    Part::Map => a.map = Some(map_source(key, v, base, true)?),
                    Part::Noise => a.noise = in_range(key, number(key, v)?, 0.0, f32::MAX)?,
                    Part::NoiseFreq => a.noise_freq = in_range(key, number(key, v)?, 0.0, 1.0e6)?,
                    Part::MapOffset | Part::MapMult => {
                        return Err(format!("`{key}`: colour maps have no offset or multiplier (as in Maya)"))
                    }
                }
            }
        }
        Ok(())
    }

    /// Checks every value against its range (for descriptions built in code rather than
    /// read from a file); returns the first problem found.
    pub fn validate(&self) -> Result<(), String> {
        if self.density > MAX_DENSITY {
            return Err(format!("`density` = {} is out of range (0 to {MAX_DENSITY})", self.density));
        }
        if !(1..=MAX_SEGMENTS).contains(&self.segments) {
            return Err(format!("`segments` = {} is out of range (1 to {MAX_SEGMENTS})", self.segments));
        }
        if !(self.global_scale.is_finite() && self.global_scale >= 0.0) {
            return Err(format!("`global_scale` = {} must be finite and >= 0", self.global_scale));
        }
        for s in Scalar::ALL {
            let (spec, a) = (s.spec(), &self[s]);
            let name = spec.name;
            in_range(name, a.value, spec.min, spec.max)?;
            for (part, x) in [("map_offset", a.map_offset), ("map_mult", a.map_mult)] {
                if !x.is_finite() {
                    return Err(format!("`{name}_{part}` = {x} is not a finite number"));
                }
            }
            in_range(&format!("{name}_noise"), a.noise, 0.0, f32::MAX)?;
            in_range(&format!("{name}_noise_freq"), a.noise_freq, 0.0, 1.0e6)?;
        }
        for c in ColorAttr::ALL {
            let (name, a) = (c.spec().name, &self[c]);
            if !(a.value.is_finite() && a.value.min_element() >= 0.0) {
                return Err(format!("`{name}` = {} must be finite and >= 0", a.value));
            }
            in_range(&format!("{name}_noise"), a.noise, 0.0, f32::MAX)?;
            in_range(&format!("{name}_noise_freq"), a.noise_freq, 0.0, 1.0e6)?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn table(text: &str) -> toml::Table {
        toml::from_str(text).unwrap()
    }

    #[test]
    fn defaults_are_maya_node_defaults() {
        let d = FurDescription::default();
        assert_eq!((d.density, d.segments, d.global_scale), (1000, 1, 1.0));
        assert_eq!(d.light_model, LightModel::AmbientDiffuseSpecular);
        assert_eq!(d[Scalar::Length].value, 1.0);
        assert_eq!(d[Scalar::Baldness].value, 1.0);
        assert_eq!(d[Scalar::ClumpingFrequency].value, 50.0);
        assert_eq!(d[Scalar::SpecularSharpness].value, 5.0);
        assert_eq!(d[Scalar::Polar].value, 0.0);
        assert_eq!(d[ColorAttr::SpecularColor].value, Color::splat(0.5));
        assert_eq!((d[Scalar::Length].map_mult, d[Scalar::Length].noise_freq), (1.0, 10.0));
        d.validate().unwrap();
        // Names are unique across both tables, long and short.
        let mut names: Vec<&str> = Scalar::ALL.iter().flat_map(|s| [s.spec().name, s.spec().short]).collect();
        names.extend(ColorAttr::ALL.iter().flat_map(|c| [c.spec().name, c.spec().short]));
        let n = names.len();
        names.sort();
        names.dedup();
        assert_eq!(names.len(), n);
    }

    #[test]
    fn reads_long_and_short_names_maps_and_noise() {
        let mut d = FurDescription::default();
        let t = table(
            r#"
density = 5000
dl = 0.5
base_curl = 0.25
length_map = "maps/len.png"
length_map_mult = 2.0
length_map_offset = 0.1
inclination_noise = 0.2
inclination_noise_freq = 4
tip_color = [0.5, 0.25, 0.0]
base_color_map = [[1, 0, 0], [0, 1, 0]]
baldness_map = [0.5, 1.0]
light_model = 1
"#,
        );
        d.apply_table(&t, Path::new("scene")).unwrap();
        assert_eq!(d.density, 5000);
        let l = &d[Scalar::Length];
        assert_eq!((l.value, l.map_mult, l.map_offset), (0.5, 2.0, 0.1));
        assert_eq!(l.map, Some(MapSource::Image(PathBuf::from("scene/maps/len.png"))));
        assert_eq!((d[Scalar::Inclination].noise, d[Scalar::Inclination].noise_freq), (0.2, 4.0));
        assert_eq!(d[Scalar::BaseCurl].value, 0.25);
        assert_eq!(d[ColorAttr::TipColor].value, Color::new(0.5, 0.25, 0.0));
        assert_eq!(d[ColorAttr::BaseColor].map, Some(MapSource::Vertex(vec![[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]])));
        assert_eq!(d[Scalar::Baldness].map, Some(MapSource::Vertex(vec![[0.5; 3], [1.0; 3]])));
        assert_eq!(d.light_model, LightModel::AmbientDiffuse);
        d.validate().unwrap();
    }

    #[test]
    fn bad_values_are_errors_naming_the_key() {
        let err = |text: &str| FurDescription::default().apply_table(&table(text), Path::new("")).unwrap_err();
        for (text, needles) in [
            ("density = -5", &["density", "-5", "out of range"][..]),
            ("baldness = 1.5", &["baldness", "0 to 1"]),
            ("length = nan", &["length", "finite"]),
            ("inclination = inf", &["inclination", "finite"]),
            ("lenght = 1", &["unknown", "lenght"]),
            ("length_mapp = 1", &["unknown", "length_mapp"]),
            ("segments = 0", &["segments"]),
            ("base_color = [1, -1, 0]", &["base_color"]),
            ("base_color_map_mult = 2", &["base_color_map_mult", "colour maps"]),
            ("length_noise = -1", &["length_noise"]),
            ("clump_shape = 11", &["clump_shape", "-10 to 10"]),
            ("light_model = 7", &["light_model"]),
            ("length_map = 3", &["length_map", "image file"]),
            ("density = 1.5", &["density", "integer"]),
        ] {
            let e = err(text);
            for n in needles {
                assert!(e.contains(n), "{text}: `{e}` lacks `{n}`");
            }
        }
        let mut d = FurDescription::default();
        d[Scalar::Roll].value = f32::NAN;
        assert!(d.validate().unwrap_err().contains("roll"));
    }
}
