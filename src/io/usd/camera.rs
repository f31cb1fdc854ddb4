//! `Camera` prims (UsdGeomCamera) to tress's camera, at the frame's time code.
//!
//! The camera looks down its local −Z with +Y up. Its film is its apertures over
//! `focalLength` (both in the same unit, so the ratio is all that counts), fitted to the
//! image finally rendered by the horizontal aperture, as Arnold's USD reader does (it sets
//! `persp_camera`'s horizontal `fov` from the horizontal aperture): the horizontal field of
//! view is `2 atan(horizontalAperture / (2 focalLength))` and the vertical one follows the
//! image aspect, also for an image size given later (`-r`). Without an image size of its
//! own (a `RenderSettings` prim's `resolution`), the image takes the apertures' aspect at
//! tress's default width. `clippingRange` (near, far), the schema's (1, 10⁶) when
//! not authored, clips along the view direction, in the camera's units: a scale in the
//! camera's transform scales the distances with it.

use super::values::{number, short, token, value, Res};
use super::Notes;
use crate::scene::{CameraDesc, Film, FilmFit};
use crate::world::RenderSettings;
use glam::{Affine3A, Vec3};
use openusd::sdf;
use openusd::usd::{Prim, TimeCode};

/// The camera `prim` placed by `transform` (local to world), for an image of `image`
/// pixels if known; returns it with the image size to render.
pub fn read_camera(
    prim: &Prim,
    transform: &Affine3A,
    time: TimeCode,
    image: Option<[u32; 2]>,
    notes: &mut Notes,
) -> Res<(CameraDesc, [u32; 2])> {
    let num = |name: &str, d: f64| -> Res<f32> {
        let x = number(value(prim, name, time)?, name)?.unwrap_or(d) as f32;
        anyhow::ensure!(x.is_finite() && x > 0.0, "`{name}` must be finite and positive");
        Ok(x)
    };
    // The schema's fallbacks: a 35 mm academy aperture and a 50 mm lens.
    let focal = num("focalLength", 50.0)?;
    let (h_ap, v_ap) = (num("horizontalAperture", 20.955)?, num("verticalAperture", 15.2908)?);
    if token(value(prim, "projection", time)?, "perspective") != "perspective" {
        notes.note("orthographic cameras: rendered in perspective with the same apertures".into(), prim);
    }
    for name in ["horizontalApertureOffset", "verticalApertureOffset"] {
        if number(value(prim, name, time)?, name)?.is_some_and(|x| x != 0.0) {
            notes.note("camera aperture offsets: not applied".into(), prim);
        }
    }
    let [w, h] = image.unwrap_or_else(|| {
        let width = RenderSettings::default().width;
        [width, ((width as f32 * v_ap / h_ap).round() as u32).clamp(1, 16 * width)]
    });
    let film = Film { aperture: [h_ap / focal, v_ap / focal], fit: FilmFit::Horizontal };
    anyhow::ensure!(
        film.aperture.iter().all(|a| a.is_finite() && *a > 0.0),
        "apertures {h_ap} × {v_ap} over focal length {focal} do not give a field of view"
    );
    let vfov = film.vfov(w, h);
    let eye = transform.transform_point3(Vec3::ZERO);
    let forward = transform.transform_vector3(-Vec3::Z);
    let up = transform.transform_vector3(Vec3::Y);
    anyhow::ensure!(
        eye.is_finite() && forward.length() > 0.0 && up.cross(forward).length() > 0.0,
        "its transform does not give a view direction and an up direction"
    );
    let target = eye + forward.normalize();
    let [near, far] = match value(prim, "clippingRange", time)? {
        None => [1.0, 1.0e6],
        Some(sdf::Value::Vec2f(v)) => [v.x, v.y],
        Some(sdf::Value::Vec2d(v)) => [v.x as f32, v.y as f32],
        Some(sdf::Value::Vec2h(v)) => [v.x.to_f32(), v.y.to_f32()],
        Some(other) => anyhow::bail!("`clippingRange` is not a pair of numbers: {}", short(&other)),
    };
    anyhow::ensure!(
        near.is_finite() && near >= 0.0 && far > near,
        "`clippingRange` ({near}, {far}) is not a range from a finite near distance >= 0 to a larger far one"
    );
    let clip = [near, far].map(|d| d * forward.length());
    Ok((CameraDesc { eye, target, up: up.normalize(), vfov, film: Some(film), clip }, [w, h]))
}
