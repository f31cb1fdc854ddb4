//! Maya's fur presets by name (specification section 2.6), as TOML data files shipped in
//! the crate (`presets/*.toml`, the same attribute keys as a scene's `[[fur]]` entry).
//!
//! Maya's preset files are not public; only Duckling's Inclination, Polar and Roll are
//! documented. The other values are ours, chosen from photographs of each animal and
//! checked against renders (`docs/presets/`). They are authored for objects about two
//! units across (the unit torus); scale them with `global_scale`. A preset starts from
//! Maya's node defaults, like a Maya preset applied to a new description.

use super::description::FurDescription;
use std::path::Path;

/// Every preset: Maya's name and the file's text.
pub const PRESETS: &[(&str, &str)] = &[
    ("Bear", include_str!("../../presets/Bear.toml")),
    ("Bison", include_str!("../../presets/Bison.toml")),
    ("Dreadlocks", include_str!("../../presets/Dreadlocks.toml")),
    ("Duckling", include_str!("../../presets/Duckling.toml")),
    ("Gorilla", include_str!("../../presets/Gorilla.toml")),
    ("Grass", include_str!("../../presets/Grass.toml")),
    ("LionMane", include_str!("../../presets/LionMane.toml")),
    ("Llama", include_str!("../../presets/Llama.toml")),
    ("Mouse", include_str!("../../presets/Mouse.toml")),
    ("PolarBear", include_str!("../../presets/PolarBear.toml")),
    ("Porcupine", include_str!("../../presets/Porcupine.toml")),
    ("Punk", include_str!("../../presets/Punk.toml")),
    ("Raccoon", include_str!("../../presets/Raccoon.toml")),
    ("Sheep", include_str!("../../presets/Sheep.toml")),
    ("Squirrel", include_str!("../../presets/Squirrel.toml")),
    ("WetLabrador", include_str!("../../presets/WetLabrador.toml")),
    ("WetOtter", include_str!("../../presets/WetOtter.toml")),
];

/// The preset called `name` (case and spaces ignored: "polar bear" is PolarBear).
pub fn preset(name: &str) -> Result<FurDescription, String> {
    let wanted: String = name.chars().filter(|c| !c.is_whitespace()).collect();
    let (_, text) = PRESETS.iter().find(|(n, _)| n.eq_ignore_ascii_case(&wanted)).ok_or_else(|| {
        let names: Vec<&str> = PRESETS.iter().map(|p| p.0).collect();
        format!("unknown fur preset `{name}` (presets: {})", names.join(", "))
    })?;
    let table: toml::Table = toml::from_str(text).map_err(|e| format!("preset {name}: {e}"))?;
    let mut desc = FurDescription::default();
    desc.apply_table(&table, Path::new("")).map_err(|e| format!("preset {name}: {e}"))?;
    Ok(desc)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fur::description::{MapSource, Scalar};

    #[test]
    fn every_preset_parses_validates_and_needs_no_map() {
        for (name, _) in PRESETS {
            let d = preset(name).unwrap_or_else(|e| panic!("{e}"));
            d.validate().unwrap();
            assert!(d.scalars.iter().all(|a| a.map.is_none()), "{name}: presets store no maps (as in Maya)");
            assert!(d[Scalar::BaseWidth].value > 0.0 && d.segments > 1, "{name} would be invisible or stiff");
            assert!(!d.colors.iter().any(|c| matches!(c.map, Some(MapSource::Image(_)))));
        }
    }

    #[test]
    fn duckling_has_its_documented_values_and_names_are_forgiving() {
        let d = preset("duckling").unwrap();
        assert_eq!((d[Scalar::Inclination].value, d[Scalar::Polar].value, d[Scalar::Roll].value), (0.6, 0.5, 0.5));
        assert_eq!(preset("polar bear").unwrap(), preset("PolarBear").unwrap());
        let e = preset("Chinchilla").unwrap_err();
        assert!(e.contains("Chinchilla") && e.contains("Squirrel"), "{e}");
    }
}
