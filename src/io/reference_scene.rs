//! Reference scenes: the directories the benchmark shares with the Embree, Mitsuba and
//! Cycles baselines (`scene.json` naming an OBJ mesh and a `.hair` file, lights and
//! camera), read as a scene description. Every renderer shades the curves as diffuse
//! surfaces there, for a pixel-for-pixel comparison.

use crate::error::LoadError;
use crate::light::Light;
use crate::scene::{CameraDesc, Contents, Description, HairEntry, HairSource, MeshEntry, MeshSource};
use crate::shading::Material;
use crate::world::RenderSettings;
use glam::{Affine3A, Vec3};
use serde::Deserialize;
use std::path::Path;

#[derive(Deserialize)]
struct RefScene {
    film: RefFilm,
    camera: RefCamera,
    lights: Vec<RefLight>,
    meshes: Vec<RefMesh>,
    hair: Vec<RefHair>,
}
#[derive(Deserialize)]
struct RefFilm {
    width: u32,
    height: u32,
    spp: u32,
}
#[derive(Deserialize)]
struct RefCamera {
    eye: [f32; 3],
    target: [f32; 3],
    up: [f32; 3],
    vfov_deg: f32,
}
#[derive(Deserialize)]
#[serde(tag = "type", rename_all = "snake_case")]
enum RefLight {
    Distant { direction_to_light: [f32; 3], radiance: [f32; 3] },
    ConstantEnvironment { radiance: [f32; 3] },
}
#[derive(Deserialize)]
struct RefMesh {
    obj: String,
    diffuse: [f32; 3],
}
#[derive(Deserialize)]
struct RefHair {
    file: String,
    diffuse: [f32; 3],
}

/// Reads a reference scene directory written by `scripts/gen_scenes.py` (`scene.json`,
/// the OBJ and the `.hair` it names) as a scene description.
pub fn read_reference_scene(dir: &Path) -> Result<Description, LoadError> {
    let path = dir.join("scene.json");
    let text = crate::input_file::read_text(&path, crate::input_file::Kind::Scene)?;
    let s: RefScene =
        serde_json::from_str(&text).map_err(|e| LoadError::format(&path, format!("not a reference scene: {e}")))?;
    let lights = s
        .lights
        .iter()
        .map(|l| match *l {
            RefLight::Distant { direction_to_light, radiance } => Light::Distant {
                direction: Vec3::from(direction_to_light).normalize_or(Vec3::Y),
                irradiance: radiance.into(),
            }
            .into(),
            RefLight::ConstantEnvironment { radiance } => {
                Light::Environment { radiance: radiance.into(), camera_visibility: 1.0 }.into()
            }
        })
        .collect();
    let meshes = s
        .meshes
        .iter()
        .map(|m| MeshEntry {
            source: MeshSource::File(dir.join(&m.obj)),
            material: Material::Diffuse { color: m.diffuse.into() }.into(),
            transform: Affine3A::IDENTITY,
            visibility: Default::default(),
        })
        .collect();
    let hair = s
        .hair
        .iter()
        .map(|h| HairEntry {
            source: HairSource::File(dir.join(&h.file)),
            // Peers shade the curves as diffuse surfaces; so does tress here, for a
            // pixel-for-pixel comparison.
            material: Material::Diffuse { color: h.diffuse.into() }.into(),
            transform: Affine3A::IDENTITY,
            radius_scale: 1.0,
            file_colors: false,
            lod: None,
            visibility: Default::default(),
        })
        .collect();
    Ok(Description {
        camera: CameraDesc {
            eye: s.camera.eye.into(),
            target: s.camera.target.into(),
            up: s.camera.up.into(),
            vfov: s.camera.vfov_deg,
            ..Default::default()
        },
        settings: RenderSettings { width: s.film.width, height: s.film.height, spp: s.film.spp, ..Default::default() },
        contents: Contents { lights, meshes, hair, ..Default::default() },
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_a_reference_scene_and_names_the_file_in_errors() {
        let dir = tempfile::tempdir().unwrap();
        let json = r#"{"film": {"width": 64, "height": 48, "spp": 2},
            "camera": {"eye": [0, 0, 5], "target": [0, 0, 0], "up": [0, 1, 0], "vfov_deg": 30},
            "lights": [{"type": "distant", "direction_to_light": [0, 2, 0], "radiance": [3, 3, 3]},
                       {"type": "constant_environment", "radiance": [0.1, 0.1, 0.1]}],
            "meshes": [{"obj": "m.obj", "diffuse": [0.5, 0.5, 0.5]}],
            "hair": [{"file": "h.hair", "diffuse": [0.4, 0.3, 0.2]}]}"#;
        std::fs::write(dir.path().join("scene.json"), json).unwrap();
        let d = read_reference_scene(dir.path()).unwrap();
        assert_eq!((d.settings.width, d.settings.height, d.settings.spp), (64, 48, 2));
        assert_eq!(d.camera.vfov, 30.0);
        assert_eq!(d.contents.lights[0], Light::Distant { direction: Vec3::Y, irradiance: Vec3::splat(3.0) }.into());
        assert_eq!(d.contents.meshes[0].source, MeshSource::File(dir.path().join("m.obj")));
        assert_eq!(d.contents.hair[0].source, HairSource::File(dir.path().join("h.hair")));
        assert_eq!(d.contents.hair[0].material, Material::Diffuse { color: Vec3::new(0.4, 0.3, 0.2) }.into());
        std::fs::write(dir.path().join("scene.json"), "{").unwrap();
        let e = read_reference_scene(dir.path()).unwrap_err().to_string();
        assert!(e.contains("scene.json") && e.contains("not a reference scene"), "{e}");
    }
}
