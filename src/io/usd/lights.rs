//! UsdLux lights: `DistantLight`, `SphereLight`, `RectLight`, `DiskLight`, `CylinderLight`,
//! `DomeLight` and `DomeLight_1`.
//!
//! UsdLux gives every light the same emission: `inputs:color × inputs:intensity ×
//! 2^inputs:exposure` is the radiance of its surface (UsdLux's `LightAPI`), divided by the
//! emitting area when `inputs:normalize` is on. A distant light's irradiance is the
//! emission, as USD's Storm renderer and RenderMan light it (UsdLux would have an
//! unnormalized one's disk radiate it instead, far darker): a delta light without an
//! authored `inputs:angle`, a disk of that angular diameter with one. Lights
//! shine along their local −Z; a rect light is `width × height` in its local XY plane, a
//! disk light of radius `radius` is drawn as the square of the same area and emission. A
//! cylinder light (`length` along its local X, `radius`, emitting from its side only) is
//! drawn as a row of spheres of its radius along its axis: `length / 2·radius` such spheres
//! have exactly its side's area (n · 4πr² = 2πr · length); when the count is rounded to a
//! whole number, their radius is set so their area (and so, at the cylinder's radiance,
//! their power) is still the side's.
//!
//! A stage Blender wrote (its layer's `doc` says so) has its normalized lights read by
//! Blender's conventions ([`super::blender`]): suns written with a quarter of their
//! strength and half their diameter, and areas measured in square metres.
//!
//! A dome's `inputs:texture:file` (latitude-longitude, `texture:format` `automatic` or
//! `latlong`) is an environment map times the emission (read when the scene is prepared), oriented as UsdLux specifies after
//! OpenEXR's latitude-longitude maps: the top row is +Y, the image's left edge longitude
//! +π and its right edge −π, longitude 0 along +Z and π/2 along +X. That is tress's map
//! layout turned 180° about +Y. `DomeLight_1` first turns its pole from +Y to its
//! `poleAxis` (`"Z"`, or `"scene"` on a Z-up stage); the dome's own transform turns it
//! after that. Arnold-USD's `primvars:arnold:camera` is the weight camera rays see a
//! light with (0 hides it from the camera; it still lights); Arnold's default is 1 on a
//! dome and 0 on its area lights (sphere, rect, disk, cylinder), which the camera then
//! sees through.
//!
//! Arnold-USD hands a light's other `primvars:arnold:` primvars to its Arnold light node
//! (`ReadArnoldParameters` in its `read_light.cpp`): the per-ray weights `diffuse`,
//! `specular`, `transmission`, `sss`, `indirect`, `volume`, and `cast_shadows`. tress's
//! lights reach every other ray in full and
//! always cast shadows, so a weight other than 1 or shadows turned off is reported, once per
//! attribute with a count and the first prim. Ray visibility primvars
//! (`primvars:arnold:visibility`, `...:visibility:camera`, ...) are Arnold's shape
//! parameters: Arnold-USD reads them on shapes only, so on a light they change nothing,
//! here as in Arnold (reported, since they say the author meant to hide something).
//!
//! A `Mesh` with `primvars:arnold:light = 1` is Arnold-USD's mesh light: its triangles (as
//! the mesh is drawn, subdivided and placed) emit `primvars:arnold:light:color ×
//! :intensity × 2^:exposure` (white, 1, 0 by default) from their front faces (by the
//! mesh's `orientation`), divided by
//! the mesh's area when `primvars:arnold:light:normalize` (on by default, as in Arnold).
//! The light replaces the mesh: camera rays see its emission unless the prim's Arnold
//! visibility hides it from them, and it casts no shadow of its own. A texture on its
//! emission (`primvars:arnold:light:shaders`) is reported, not applied.

use super::values::{boolean, number, token, value, vec3, Res};
use super::Notes;
use crate::geometry::TriangleMesh;
use crate::io::arnold_light;
use crate::light::{Light, MeshLight};
use crate::scene::{EnvironmentFile, LightSource};
use glam::{Affine3A, Mat3, Vec3};
use openusd::sdf;
use openusd::usd::{Prim, TimeCode};

/// The light types this module reads.
pub const LIGHT_TYPES: [&str; 7] =
    ["DistantLight", "SphereLight", "RectLight", "DiskLight", "CylinderLight", "DomeLight", "DomeLight_1"];

/// Arnold's per-ray weights of its light nodes (1 by default) that tress has no switch for.
const ARNOLD_RAY_WEIGHTS: [&str; 6] = ["diffuse", "specular", "transmission", "sss", "indirect", "volume"];

/// An `inputs:` attribute, or the same name without the prefix as lights authored before
/// UsdLux took it (USD 21.02) spell it.
fn input(prim: &Prim, name: &str, time: TimeCode) -> Res<Option<openusd::sdf::Value>> {
    match value(prim, &format!("inputs:{name}"), time)? {
        Some(v) => Ok(Some(v)),
        None => value(prim, name, time),
    }
}

/// Reports the Arnold primvars of light `prim` (of type `kind`) that tress does not apply
/// (see the module's documentation). A value that is not a number or a flag is not one
/// Arnold-USD converts either, and is passed over.
fn note_arnold_light_parameters(prim: &Prim, time: TimeCode, notes: &mut Notes) {
    let get = |name: &str| value(prim, &format!("primvars:arnold:{name}"), time).ok().flatten();
    for name in ARNOLD_RAY_WEIGHTS {
        if let Some(w) = get(name).and_then(|v| number(Some(v), name).ok().flatten()) {
            if w != 1.0 {
                notes.note(
                    format!(
                        "Arnold light weight `primvars:arnold:{name}` other than 1: not applied (tress's lights \
                         reach every ray but camera rays in full)"
                    ),
                    prim,
                );
            }
        }
    }
    if get("cast_shadows").is_some_and(|v| !boolean(Some(v), true)) {
        notes.note("Arnold lights with `primvars:arnold:cast_shadows` off: their shadows are cast".into(), prim);
    }
    let visibility = std::iter::once("visibility".to_string())
        .chain(super::visibility::RAYS.iter().map(|(ray, _)| format!("visibility:{ray}")));
    if let Some(name) = visibility.into_iter().find(|n| get(n).is_some()) {
        notes.note_why(
            "Arnold ray visibility primvars on lights: not applied (Arnold-USD reads them on shapes only; a light's \
             rays are weighted by `primvars:arnold:camera`, `diffuse`, `specular`, ...)"
                .into(),
            prim,
            &format!("primvars:arnold:{name}"),
        );
    }
}

/// Arnold-USD's `primvars:arnold:camera` on `prim`, the weight camera rays see a light with
/// (`default` when not authored).
fn camera_weight(prim: &Prim, time: TimeCode, default: f32) -> Res<f32> {
    let w =
        number(value(prim, "primvars:arnold:camera", time)?, "primvars:arnold:camera")?.map_or(default, |x| x as f32);
    anyhow::ensure!(w.is_finite() && w >= 0.0, "`primvars:arnold:camera` must be finite and not negative");
    Ok(w)
}

/// The light `prim` of type `kind`, placed by `transform` (local to world), as the lights
/// tress draws it with (one, but a cylinder's row of spheres); `z_up` when the stage's up
/// axis is Z (for `DomeLight_1`'s `poleAxis = "scene"`).
pub fn read_light(
    prim: &Prim,
    kind: &str,
    transform: &Affine3A,
    time: TimeCode,
    z_up: bool,
    notes: &mut Notes,
) -> Res<Vec<LightSource>> {
    let num = |name: &str, d: f32| -> Res<f32> {
        let x = number(input(prim, name, time)?, name)?.map_or(d, |x| x as f32);
        anyhow::ensure!(x.is_finite(), "`inputs:{name}` must be finite");
        Ok(x)
    };
    let color = vec3(input(prim, "color", time)?, "inputs:color")?.unwrap_or(Vec3::ONE);
    let emission =
        arnold_light::emission(color, num("intensity", 1.0)?, num("exposure", 0.0)?).map_err(anyhow::Error::msg)?;
    let normalize = boolean(input(prim, "normalize", time)?, false);
    // Blender's conventions (the module docs) hold for the lights its exporter normalized.
    let blender = normalize && super::blender::wrote(prim.stage());
    // What a normalized light's emission is spread over, per unit of its area in the stage.
    let unit_area = if blender { super::blender::square_metres_per_unit(prim.stage()) } else { 1.0 };
    // The schema's default temperature, 6500 K, is D65: the white point of the sRGB primaries
    // tress renders in, so no tint (Blender writes `enableColorTemperature` on every light,
    // the temperature only when its light has one).
    if boolean(input(prim, "enableColorTemperature", time)?, false) && num("colorTemperature", 6500.0)? != 6500.0 {
        notes.note("light `colorTemperature` other than 6500 K: not applied".into(), prim);
    }
    // A sphere light shaped by a cone is Arnold's spot light (as Arnold-USD reads it).
    let cone = number(input(prim, "shaping:cone:angle", time)?, "inputs:shaping:cone:angle")?
        .map(|a| a as f32)
        .filter(|a| *a > 0.0 && kind == "SphereLight");
    let authored = |n: &str| value(prim, &format!("inputs:{n}"), time).ok().flatten().is_some();
    if cone.is_none() && authored("shaping:cone:angle") && kind != "SphereLight" {
        notes.note("light cones on lights other than sphere lights: not applied".into(), prim);
    }
    if authored("shaping:focus") {
        notes.note("light shaping `focus`: not applied".into(), prim);
    }
    if authored("shaping:ies:file") {
        notes.note("light IES profiles: not applied".into(), prim);
    }
    note_arnold_light_parameters(prim, time, notes);
    // Arnold's default `camera` weight: 1 on a sky dome, 0 on its area lights.
    let camera_visibility = camera_weight(prim, time, if kind.starts_with("DomeLight") { 1.0 } else { 0.0 })?;
    let scale = transform.matrix3.determinant().abs().cbrt();
    let size = |name: &str, d: f32| -> Res<f32> {
        let x = num(name, d)?;
        anyhow::ensure!(x >= 0.0, "`inputs:{name}` must not be negative");
        Ok(x)
    };
    if kind == "CylinderLight" {
        let (length, radius) = (size("length", 1.0)?, size("radius", 0.5)?);
        return Ok(cylinder_spheres(transform, length, radius, emission / unit_area, normalize, camera_visibility));
    }
    Ok(vec![LightSource::Inline(match kind {
        "DistantLight" => {
            let direction = transform.transform_vector3(Vec3::Z).normalize_or(Vec3::Y);
            // Blender writes a quarter of its sun's strength and half its diameter.
            let (emission, diameter) = match blender {
                true => (emission * super::blender::SUN_STRENGTH_PER_INTENSITY, super::blender::SUN_DIAMETER_PER_ANGLE),
                false => (emission, 1.0),
            };
            let angle = number(input(prim, "angle", time)?, "inputs:angle")?.map_or(0.0, |a| a as f32 * diameter);
            anyhow::ensure!(angle.is_finite(), "`inputs:angle` must be finite");
            arnold_light::distant(direction, emission, angle)
        }
        "DomeLight" | "DomeLight_1" => {
            let pole_z = kind == "DomeLight_1"
                && match token(input(prim, "poleAxis", time)?, "scene").as_str() {
                    "Z" => true,
                    "scene" => z_up,
                    _ => false,
                };
            // +Y to +Z: 90° about +X.
            let pole = if pole_z { Mat3::from_rotation_x(0.5 * std::f32::consts::PI) } else { Mat3::IDENTITY };
            let turn = crate::math::orthogonal_part(transform) * pole;
            if let Some(sky) = arnold_sky(prim, time)? {
                // The sky is the dome's colour: its intensity and exposure scale it.
                let placement =
                    crate::light::MapPlacement::new(0.0, num("intensity", 1.0)? * num("exposure", 0.0)?.exp2())
                        .rotated(turn)
                        .seen_by_camera(camera_visibility);
                let lights = sky.lights(placement).map_err(anyhow::Error::msg)?;
                return Ok(lights.into_iter().map(LightSource::Inline).collect());
            }
            match dome_texture(prim, time, emission, notes)? {
                Some(mut map) => {
                    map.placement = map.placement.rotated(turn).seen_by_camera(camera_visibility);
                    return Ok(vec![LightSource::File(map)]);
                }
                None => Light::Environment { radiance: emission, camera_visibility },
            }
        }
        "SphereLight" if cone.is_some() => {
            // Arnold-USD: the spot's full cone is twice the USD half-angle, its penumbra
            // that cone times the softness.
            let cone_angle = 2.0 * cone.unwrap_or_default();
            let softness = number(input(prim, "shaping:cone:softness", time)?, "inputs:shaping:cone:softness")?
                .map_or(0.0, |s| s as f32);
            anyhow::ensure!(cone_angle.is_finite() && softness.is_finite(), "light cone angles must be finite");
            let direction = transform.transform_vector3(Vec3::NEG_Z).normalize_or(Vec3::NEG_Z);
            let radius = size("radius", 0.5)? * scale;
            let position = transform.transform_point3(Vec3::ZERO);
            arnold_light::spot(position, direction, emission, [radius, cone_angle, cone_angle * softness], normalize)
        }
        "SphereLight" => {
            let radius = size("radius", 0.5)? * scale;
            // Normalized, the emission is per unit area in the stage's unit.
            let emission = if normalize { emission / unit_area } else { emission };
            arnold_light::sphere(transform.transform_point3(Vec3::ZERO), radius, emission, normalize, camera_visibility)
        }
        _ => {
            // Normalized, the emission is per unit area in the stage's unit.
            let emission = if normalize { emission / unit_area } else { emission };
            if kind == "RectLight" {
                if input(prim, "texture:file", time)?.is_some() {
                    notes.note("RectLight textures: not applied".into(), prim);
                }
                let sides = [size("width", 1.0)?, size("height", 1.0)?];
                arnold_light::rectangle(transform, sides, emission, normalize, camera_visibility)
            } else {
                arnold_light::disk(transform, size("radius", 0.5)?, emission, normalize, camera_visibility)
            }
        }
    })])
}

/// The Arnold `physical_sky` shader a dome's `primvars:arnold:shaders` node graph connects
/// to its `outputs:color` (how Arnold-USD and Houdini write a physical sky dome), if any.
fn arnold_sky(dome: &Prim, time: TimeCode) -> Res<Option<crate::light::PhysicalSky>> {
    let graph = token(value(dome, "primvars:arnold:shaders", time)?, "");
    let Ok(path) = sdf::Path::new(&graph) else { return Ok(None) };
    let graph = dome.stage().prim(path);
    let Some(shader) = super::shapes::connected_shader(&graph, "outputs:color")? else { return Ok(None) };
    if token(value(&shader, "info:id", time)?, "") != "arnold:physical_sky" {
        return Ok(None);
    }
    let sky = arnold_light::physical_sky(&ShaderInputs { shader: &shader, time })
        .map_err(|e| anyhow::anyhow!("{}: {e}", shader.path()))?;
    Ok(Some(sky))
}

/// A shader prim's `inputs:` at a time, for the Arnold code shared with other readers.
struct ShaderInputs<'a> {
    shader: &'a Prim,
    time: TimeCode,
}

impl arnold_light::Params for ShaderInputs<'_> {
    fn number(&self, name: &str, default: f32) -> Result<f32, String> {
        let x =
            number(input(self.shader, name, self.time).map_err(|e| e.to_string())?, name).map_err(|e| e.to_string())?;
        let x = x.map_or(default, |x| x as f32);
        match x.is_finite() {
            true => Ok(x),
            false => Err(format!("`inputs:{name}` must be finite")),
        }
    }

    fn triple(&self, name: &str, default: Vec3) -> Result<Vec3, String> {
        let v =
            vec3(input(self.shader, name, self.time).map_err(|e| e.to_string())?, name).map_err(|e| e.to_string())?;
        Ok(v.unwrap_or(default))
    }

    fn boolean(&self, name: &str, default: bool) -> Result<bool, String> {
        Ok(boolean(input(self.shader, name, self.time).map_err(|e| e.to_string())?, default))
    }
}

/// A cylinder light (`length` along its local X, `radius`, centred on its origin, emitting
/// `emission` from its side, per unit area when `normalize`) as Arnold's cylinder light
/// is drawn ([`arnold_light::cylinder`]), placed by `transform`.
fn cylinder_spheres(
    transform: &Affine3A,
    length: f32,
    radius: f32,
    emission: Vec3,
    normalize: bool,
    camera_visibility: f32,
) -> Vec<LightSource> {
    let half = transform.transform_vector3(Vec3::new(0.5 * length, 0.0, 0.0));
    let centre = transform.transform_point3(Vec3::ZERO);
    // The radius scales with the transform's two other axes.
    let radius =
        radius * (transform.transform_vector3(Vec3::Y).length() * transform.transform_vector3(Vec3::Z).length()).sqrt();
    arnold_light::cylinder(centre - half, centre + half, radius, emission, normalize, camera_visibility)
        .into_iter()
        .map(LightSource::Inline)
        .collect()
}

/// A dome's texture as a map in its own frame (before its transform), times `emission`;
/// `None` when it has none or names none that can be found (reported). `prepare` reads the
/// file; one it cannot use lights the scene with the dome's colour × intensity instead.
fn dome_texture(prim: &Prim, time: TimeCode, emission: Vec3, notes: &mut Notes) -> Res<Option<EnvironmentFile>> {
    let asset = match input(prim, "texture:file", time)? {
        Some(sdf::Value::AssetPath(a)) if !a.authored_path.is_empty() => a,
        _ => return Ok(None),
    };
    let format = token(input(prim, "texture:format", time)?, "automatic");
    if !matches!(format.as_str(), "automatic" | "latlong") {
        notes.note(format!("dome textures in the `{format}` format: lit by the dome's colour × intensity"), prim);
        return Ok(None);
    }
    let Some(file) = asset.resolved_path().filter(|p| !p.is_empty()).map(std::path::PathBuf::from) else {
        let what = format!("dome texture `{}` is missing: lit by the dome's colour × intensity", asset.authored_path);
        notes.note(what, prim);
        return Ok(None);
    };
    Ok(Some(arnold_light::latlong_map(file, emission)))
}

/// Whether the Mesh `prim` is an Arnold mesh light (`primvars:arnold:light` on).
pub fn is_mesh_light(prim: &Prim, time: TimeCode) -> bool {
    boolean(value(prim, "primvars:arnold:light", time).ok().flatten(), false)
}

/// The Arnold mesh light of the Mesh `prim` (the module docs), whose triangles `mesh`
/// are placed by `transform`; seen by camera rays when `camera`. `None` (reported) when
/// no triangle has an area.
pub fn read_mesh_light(
    prim: &Prim,
    mesh: &TriangleMesh,
    transform: &Affine3A,
    camera: bool,
    time: TimeCode,
    notes: &mut Notes,
) -> Res<Option<LightSource>> {
    let get = |name: &str| value(prim, &format!("primvars:arnold:light:{name}"), time);
    let num = |name: &str, d: f32| -> Res<f32> {
        let what = format!("primvars:arnold:light:{name}");
        let x = number(get(name)?, &what)?.map_or(d, |x| x as f32);
        anyhow::ensure!(x.is_finite(), "`{what}` must be finite");
        Ok(x)
    };
    let color = vec3(get("color")?, "primvars:arnold:light:color")?.unwrap_or(Vec3::ONE);
    let emission =
        arnold_light::emission(color, num("intensity", 1.0)?, num("exposure", 0.0)?).map_err(anyhow::Error::msg)?;
    if get("shaders")?.is_some() {
        notes.note("Arnold mesh light textures (`primvars:arnold:light:shaders`): not applied".into(), prim);
    }
    // USD's front face winds counter-clockwise seen from the front, clockwise for a
    // `leftHanded` mesh (UsdGeomGprim `orientation`).
    let left = token(value(prim, "orientation", time)?, "rightHanded") == "leftHanded";
    let triangles = (0..mesh.indices.len() as u32).map(|i| {
        let [a, b, c] = mesh.corners(i).map(|p| transform.transform_point3(p));
        if left {
            [a, c, b]
        } else {
            [a, b, c]
        }
    });
    let camera_visibility = if camera { 1.0 } else { 0.0 };
    let Some(light) = MeshLight::new(triangles, emission, camera_visibility) else {
        notes.note("Arnold mesh lights without a face of positive area: not lit".into(), prim);
        return Ok(None);
    };
    let light = match boolean(get("normalize")?, true) {
        true => light.with_radiance(emission / light.area()),
        false => light,
    };
    Ok(Some(LightSource::Inline(Light::Mesh(light))))
}
