//! Maya Fur's `FurDescription` nodes as read from a `.ma` file: a plain record of the
//! description's attributes under Maya's long names, starting from the node defaults
//! (docs/maya-fur-hair.md section 2.2: a `.ma` file stores only the attributes that
//! differ from them), plus the meshes it is attached to.
//!
//! Growing the fur is the job of [`crate::fur`]; [`fur_description`] carries the
//! attributes over and [`fur_entries`] attaches the result to the meshes.

use super::parse::{Graph, Value};
use crate::fur::description::{MAX_DENSITY, MAX_SEGMENTS};
use crate::fur::{ColorAttr, FurDescription, Placement, Scalar};
use crate::math::Color;
use crate::scene::FurEntry;
use crate::shading::fur_tube::LightModel;
use std::collections::BTreeMap;

/// The value of a FurDescription attribute.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum FurValue {
    /// A number (enums and integers included).
    Number(f64),
    /// An RGB colour.
    Color([f64; 3]),
}

/// A FurDescription attribute: long name, short name, node default.
struct FurAttr {
    long: &'static str,
    short: &'static str,
    default: FurValue,
}

const fn num(long: &'static str, short: &'static str, v: f64) -> FurAttr {
    FurAttr { long, short, default: FurValue::Number(v) }
}
const fn rgb(long: &'static str, short: &'static str, v: f64) -> FurAttr {
    FurAttr { long, short, default: FurValue::Color([v, v, v]) }
}

/// The attributes of docs/maya-fur-hair.md table 2.2 with their **node** defaults
/// (not the values Maya's UI gives a new description).
const ATTRIBUTES: [FurAttr; 29] = [
    num("LightModel", "lmd", 2.0),
    num("Density", "d", 1000.0),
    num("GlobalScale", "gs", 1.0),
    rgb("BaseColor", "dbc", 1.0),
    rgb("TipColor", "dtc", 1.0),
    rgb("BaseAmbientColor", "dbac", 0.0),
    rgb("TipAmbientColor", "dtac", 0.0),
    rgb("SpecularColor", "dsc", 0.5),
    num("SpecularSharpness", "dss", 5.0),
    num("Length", "dl", 1.0),
    num("Baldness", "db", 1.0),
    num("BaseOpacity", "dbo", 1.0),
    num("TipOpacity", "dto", 1.0),
    num("BaseWidth", "dbw", 0.0),
    num("TipWidth", "dtw", 0.0),
    num("Segments", "dsg", 1.0),
    num("BaseCurl", "dbcl", 0.0),
    num("TipCurl", "dtcl", 0.0),
    num("Scraggle", "ds", 0.0),
    num("ScraggleFrequency", "dsf", 5.0),
    num("ScraggleCorrelation", "dsco", 0.0),
    num("Inclination", "di", 0.0),
    num("Roll", "dr", 0.0),
    num("Polar", "dp", 0.0),
    num("Attraction", "dat", 1.0),
    num("Offset", "dofs", 0.0),
    num("Clumping", "dc", 0.0),
    num("ClumpingFrequency", "dcf", 50.0),
    num("ClumpShape", "dcs", 0.0),
];

/// The per-attribute modifiers of section 2.1 (`X` + suffix; short name `x` + suffix) and
/// their defaults. Colours have only the noise pair.
const MODIFIERS: [(&str, &str, f64, bool); 4] = [
    ("Noise", "n", 0.0, true),
    ("NoiseFreq", "nf", 10.0, true),
    ("MapOffset", "mo", 0.0, false),
    ("MapMult", "mm", 1.0, false),
];

/// One FurDescription node.
#[derive(Clone, Debug, PartialEq)]
pub struct MayaFur {
    /// The node's name.
    pub name: String,
    /// Every attribute of table 2.2 and its modifiers (`LengthNoise`, `LengthNoiseFreq`,
    /// `LengthMapOffset`, `LengthMapMult`, ...), by Maya's long name: the file's value or
    /// the node default.
    pub attributes: BTreeMap<String, FurValue>,
    /// Texture maps: (attribute as written, e.g. `LengthMap[0]`, file path).
    pub maps: Vec<(String, String)>,
    /// Indices into the import's meshes of the surfaces the description is attached to.
    pub meshes: Vec<usize>,
    /// Line of the node's `createNode`.
    pub line: u32,
}

impl MayaFur {
    /// A description with every attribute at its node default.
    pub fn with_defaults(name: &str, line: u32) -> MayaFur {
        let mut attributes = BTreeMap::new();
        for a in &ATTRIBUTES {
            attributes.insert(a.long.to_string(), a.default);
            for (suffix, _, default, colour_too) in MODIFIERS {
                if colour_too || matches!(a.default, FurValue::Number(_)) {
                    attributes.insert(format!("{}{suffix}", a.long), FurValue::Number(default));
                }
            }
        }
        MayaFur { name: name.into(), attributes, maps: Vec::new(), meshes: Vec::new(), line }
    }

    /// A number attribute by long name (`None` for unknown names and colours).
    pub fn number(&self, long: &str) -> Option<f64> {
        match self.attributes.get(long)? {
            FurValue::Number(v) => Some(*v),
            FurValue::Color(_) => None,
        }
    }

    /// A colour attribute by long name.
    pub fn color(&self, long: &str) -> Option<[f64; 3]> {
        match self.attributes.get(long)? {
            FurValue::Color(c) => Some(*c),
            FurValue::Number(_) => None,
        }
    }
}

/// The long name an attribute path as written (short or long, a colour's component
/// `dbcr`/`BaseColorR` included) stands for, with the component index for components.
fn long_name(written: &str) -> Option<(String, Option<usize>)> {
    for a in &ATTRIBUTES {
        let colour = matches!(a.default, FurValue::Color(_));
        let mut names = vec![(a.long.to_string(), a.short.to_string())];
        for (suffix, short_suffix, _, colour_too) in MODIFIERS {
            if colour_too || !colour {
                names.push((format!("{}{suffix}", a.long), format!("{}{short_suffix}", a.short)));
            }
        }
        for (i, (long, short)) in names.iter().enumerate() {
            if written == long || written == short {
                return Some((long.clone(), None));
            }
            if colour && i == 0 {
                for (k, c) in ["R", "G", "B"].iter().enumerate() {
                    if written == format!("{long}{c}") || written == format!("{short}{}", c.to_ascii_lowercase()) {
                        return Some((long.clone(), Some(k)));
                    }
                }
            }
        }
    }
    None
}

/// Reads the FurDescription node `node`: defaults, then its `setAttr`s in file order.
/// Attributes outside table 2.2 (mental ray settings, equalizer maps, renderer add-ons)
/// are ignored; a malformed value on one of the table's is an error with its line.
pub fn read_fur(g: &Graph, node: usize) -> Result<MayaFur, (u32, String)> {
    let n = &g.nodes[node];
    let mut fur = MayaFur::with_defaults(&n.name, n.line);
    for a in &n.attrs {
        if let Value::Strings(s) = &a.value {
            if a.name.contains("Map[") || a.name.contains("map[") {
                fur.maps.push((a.name.clone(), s.first().cloned().unwrap_or_default()));
            }
            continue;
        }
        let Some((long, component)) = long_name(&a.name) else { continue };
        let values = match &a.value {
            Value::Numbers(v) => v,
            _ => return Err((a.line, format!("{}: `{}` must be numbers", n.name, a.name))),
        };
        let entry = fur.attributes.get_mut(&long).expect("every long name has a default");
        match (entry, component, values.as_slice()) {
            (FurValue::Number(x), None, [v]) => *x = *v,
            (FurValue::Color(c), None, [r, g, b]) => *c = [*r, *g, *b],
            (FurValue::Color(c), Some(k), [v]) => c[k] = *v,
            (_, _, v) => {
                return Err((
                    a.line,
                    format!("{}: `{}` has {} values, which does not fit the attribute", n.name, a.name, v.len()),
                ))
            }
        }
    }
    Ok(fur)
}

/// The fur module's description of a FurDescription read from a file: every attribute of
/// table 2.2 and its noise, map offset and map multiplier, by Maya's long name (both
/// start from the same node defaults). Texture maps are not carried over: Maya's are
/// `.iff` files, which tress does not read; the caller says so.
pub fn fur_description(f: &MayaFur) -> Result<FurDescription, String> {
    let mut d = FurDescription::default();
    let whole = |name: &str, max: f64| -> Result<i64, String> {
        let v = f.number(name).unwrap_or(0.0).round();
        match (0.0..=max).contains(&v) {
            true => Ok(v as i64),
            false => Err(format!("`{name}` = {v} is out of range (0 to {max})")),
        }
    };
    d.light_model = LightModel::from_index(whole("LightModel", 3.0)?).expect("range checked");
    d.density = whole("Density", MAX_DENSITY as f64)? as u32;
    d.segments = whole("Segments", MAX_SEGMENTS as f64)?.max(1) as u32;
    d.global_scale = f.number("GlobalScale").unwrap_or(1.0) as f32;
    let num = |name: String| f.number(&name).map(|v| v as f32);
    for s in Scalar::ALL {
        let long = s.spec().maya;
        let a = &mut d[s];
        a.value = num(long.to_string()).unwrap_or(a.value);
        a.noise = num(format!("{long}Noise")).unwrap_or(a.noise);
        a.noise_freq = num(format!("{long}NoiseFreq")).unwrap_or(a.noise_freq);
        a.map_offset = num(format!("{long}MapOffset")).unwrap_or(a.map_offset);
        a.map_mult = num(format!("{long}MapMult")).unwrap_or(a.map_mult);
    }
    for c in ColorAttr::ALL {
        let long = c.spec().maya;
        let a = &mut d[c];
        if let Some(v) = f.color(long) {
            a.value = Color::from(v.map(|x| x as f32));
        }
        a.noise = num(format!("{long}Noise")).unwrap_or(a.noise);
        a.noise_freq = num(format!("{long}NoiseFreq")).unwrap_or(a.noise_freq);
    }
    d.validate()?;
    Ok(d)
}

/// Scene entries for the FurDescriptions of an import: one per (description, attached
/// mesh), `mesh` indexing the import's meshes, roots spread by area (what Maya's default
/// equalizer maps aim at), seed 0; and warnings for what is left out (descriptions on no
/// mesh, texture maps).
pub fn fur_entries(fur: &[MayaFur]) -> Result<(Vec<FurEntry>, Vec<String>), (u32, String)> {
    let (mut entries, mut warnings) = (Vec::new(), Vec::new());
    for f in fur {
        let description = fur_description(f).map_err(|e| (f.line, format!("FurDescription {}: {e}", f.name)))?;
        if f.meshes.is_empty() {
            warnings.push(format!("FurDescription {} is attached to no mesh: no fur grows", f.name));
        }
        if !f.maps.is_empty() {
            warnings.push(format!(
                "FurDescription {}: {} attribute map(s) left out (Maya's .iff maps are not read)",
                f.name,
                f.maps.len()
            ));
        }
        for &mesh in &f.meshes {
            entries.push(FurEntry {
                mesh,
                description: description.clone(),
                placement: Placement::Area,
                seed: 0,
                guides: None,
                lod: None,
                grows_on: None,
                width_profile: None,
                visibility: Default::default(),
            });
        }
    }
    Ok((entries, warnings))
}

#[cfg(test)]
mod tests {
    use super::super::parse::parse;
    use super::*;

    #[test]
    fn defaults_apply_to_omitted_attributes() {
        let g = parse(
            "createNode FurDescription -n \"FurDescription1\";\n\tsetAttr \".dl\" 1.5;\n\tsetAttr \".Density\" 20000;\n\
             \tsetAttr \".dbc\" -type \"float3\" 0.2 0.1 0.05;\n\tsetAttr \".dtcb\" 0.25;\n\tsetAttr \".dln\" 0.3;\n\
             \tsetAttr \".ai_foo\" 7;\n\tsetAttr \".LengthMap[0]\" -type \"string\" \"furAttrMap/len.iff\";\n",
        )
        .unwrap();
        let f = read_fur(&g, 0).unwrap();
        assert_eq!(f.name, "FurDescription1");
        assert_eq!(f.number("Length"), Some(1.5));
        assert_eq!(f.number("Density"), Some(20000.0));
        assert_eq!(f.color("BaseColor"), Some([0.2, 0.1, 0.05]));
        assert_eq!(f.color("TipColor"), Some([1.0, 1.0, 0.25]));
        assert_eq!(f.number("LengthNoise"), Some(0.3));
        assert_eq!(f.maps, vec![("LengthMap[0]".to_string(), "furAttrMap/len.iff".to_string())]);
        // Node defaults (not the UI's): Base Width 0, Segments 1, Specular Sharpness 5,
        // Polar 0, Clumping Frequency 50, Length Noise Freq 10, Length Map Mult 1.
        for (name, v) in [
            ("BaseWidth", 0.0),
            ("Segments", 1.0),
            ("SpecularSharpness", 5.0),
            ("Polar", 0.0),
            ("ClumpingFrequency", 50.0),
            ("LengthNoiseFreq", 10.0),
            ("LengthMapMult", 1.0),
            ("Baldness", 1.0),
            ("LightModel", 2.0),
        ] {
            assert_eq!(f.number(name), Some(v), "{name}");
        }
        assert_eq!(f.color("SpecularColor"), Some([0.5; 3]));
        assert_eq!(f.color("BaseAmbientColor"), Some([0.0; 3]));
        assert_eq!(f.number("BaseColorNoise"), Some(0.0));
        assert_eq!(f.number("BaseColorMapMult"), None);
    }

    #[test]
    fn malformed_values_name_the_line() {
        let g = parse("createNode FurDescription -n f;\nsetAttr \".dl\" 1 2;\n").unwrap();
        assert_eq!(read_fur(&g, 0).unwrap_err().0, 2);
        let g = parse("createNode FurDescription -n f;\n\nsetAttr \".dbc\" -type \"float3\" a b c;\n").unwrap();
        assert_eq!(read_fur(&g, 0).unwrap_err().0, 3);
    }

    #[test]
    fn descriptions_carry_every_attribute_to_the_fur_module() {
        // Node defaults on both sides agree.
        assert_eq!(fur_description(&MayaFur::with_defaults("f", 1)).unwrap(), FurDescription::default());
        let g = parse(
            "createNode FurDescription -n f;\nsetAttr \".d\" 20000;\nsetAttr \".dsg\" 8;\nsetAttr \".lmd\" 1;\n\
             setAttr \".dl\" 0.4;\nsetAttr \".dlnf\" 3;\nsetAttr \".dtcl\" 0.7;\nsetAttr \".dsc\" -type \"float3\" 0.1 0.2 0.3;\n",
        )
        .unwrap();
        let d = fur_description(&read_fur(&g, 0).unwrap()).unwrap();
        assert_eq!((d.density, d.segments, d.light_model), (20000, 8, LightModel::from_index(1).unwrap()));
        assert_eq!((d[Scalar::Length].value, d[Scalar::Length].noise_freq, d[Scalar::TipCurl].value), (0.4, 3.0, 0.7));
        assert_eq!(d[ColorAttr::SpecularColor].value, Color::new(0.1, 0.2, 0.3));
        // Out of the fur module's range: an error naming the node and its line.
        let g = parse("createNode FurDescription -n bad;\nsetAttr \".di\" 3;\n").unwrap();
        let e = fur_entries(&[read_fur(&g, 0).unwrap()]).unwrap_err();
        assert!(e.0 == 1 && e.1.contains("bad") && e.1.contains("inclination"), "{e:?}");
        // A description on no mesh grows nothing and says so.
        let (entries, warnings) = fur_entries(&[MayaFur::with_defaults("lonely", 1)]).unwrap();
        assert!(entries.is_empty() && warnings[0].contains("lonely"));
    }
}
