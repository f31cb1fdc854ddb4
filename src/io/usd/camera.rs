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
//!
//! `horizontalApertureOffset` and `verticalApertureOffset` shift the image window by that
//! much of the aperture, as Arnold-USD shifts `persp_camera`'s screen window by twice the
//! offset over the aperture on each axis.
//!
//! An orthographic camera (`projection = "orthographic"`) casts parallel rays from a window
//! on the camera's plane: Arnold's `ortho_camera` window `primvars:arnold:screen_window_min`
//! and `max` (in scene units on the camera's x axis, as Arnold spans it; on its y axis in
//! units of the image's height over its width) when authored, else the apertures, which the
//! schema gives for orthographic cameras in tenths of a scene unit (UsdGeomCamera, "Cameras,
//! Lenses, and Projections"), fitted as above.
//!
//! Arnold's USD writer also stores the `persp_camera` parameters as `primvars:arnold:`
//! primvars, and Arnold's reader applies them over the schema's attributes: `fov` (Arnold's
//! horizontal field of view, in degrees) replaces the horizontal aperture's, and a camera
//! with no transform operations of its own is placed by `position`, `look_at` and `up` (in
//! its parent's space), as Arnold places it.

use super::values::{floats, number, short, token, value, vec2, vec3, Res};
use crate::scene::{CameraDesc, CameraProjection, Film, FilmFit, FULL_SCREEN};
use crate::world::RenderSettings;
use glam::{Affine3A, Vec2, Vec3};
use openusd::sdf;
use openusd::usd::{Prim, TimeCode};

/// The camera `prim` placed by `transform` (local to world), for an image of `image`
/// pixels if known; returns it with the image size to render.
pub fn read_camera(
    prim: &Prim,
    transform: &Affine3A,
    time: TimeCode,
    image: Option<[u32; 2]>,
) -> Res<(CameraDesc, [u32; 2])> {
    let num = |name: &str, d: f64| -> Res<f32> {
        let x = number(value(prim, name, time)?, name)?.unwrap_or(d) as f32;
        anyhow::ensure!(x.is_finite() && x > 0.0, "`{name}` must be finite and positive");
        Ok(x)
    };
    // The schema's fallbacks: a 35 mm academy aperture and a 50 mm lens.
    let focal = num("focalLength", 50.0)?;
    let (h_ap, v_ap) = (num("horizontalAperture", 20.955)?, num("verticalAperture", 15.2908)?);
    let orthographic = match token(value(prim, "projection", time)?, "perspective").as_str() {
        "perspective" => false,
        "orthographic" => true,
        other => anyhow::bail!("`projection` is `{other}`: neither `perspective` nor `orthographic`"),
    };
    let offset = |name: &str| -> Res<f32> {
        let x = number(value(prim, name, time)?, name)?.unwrap_or(0.0) as f32;
        anyhow::ensure!(x.is_finite(), "`{name}` must be finite");
        Ok(x)
    };
    // Twice the offset over the aperture: the screen's −1..1 spans the aperture.
    let shift =
        Vec2::new(2.0 * offset("horizontalApertureOffset")? / h_ap, 2.0 * offset("verticalApertureOffset")? / v_ap);
    let [w, h] = image.unwrap_or_else(|| {
        let width = RenderSettings::default().width;
        [width, ((width as f32 * v_ap / h_ap).round() as u32).clamp(1, 16 * width)]
    });
    let (film, window) = if orthographic {
        ortho_window(prim, time, [h_ap, v_ap])?
    } else {
        (angle_of_view(prim, time, [h_ap, v_ap], focal)?, FULL_SCREEN)
    };
    let window = window.map(|corner| corner + shift);
    let vfov = if orthographic { CameraDesc::default().vfov } else { film.vfov(w, h) };
    let projection = match orthographic {
        true => CameraProjection::Orthographic { height: film.fitted_height(w, h) },
        false => CameraProjection::Perspective,
    };
    let arnold_position = vec3(value(prim, "primvars:arnold:position", time)?, "primvars:arnold:position")?;
    // `forward` is along the view, as long as the transform makes one unit of the camera's.
    let (eye, forward, up) = match arnold_position
        .filter(|_| value(prim, "xformOpOrder", time).ok().flatten().is_none())
    {
        Some(position) => {
            let look_at = vec3(value(prim, "primvars:arnold:look_at", time)?, "primvars:arnold:look_at")?;
            let up = vec3(value(prim, "primvars:arnold:up", time)?, "primvars:arnold:up")?;
            // Arnold's defaults: looking down −Z with +Y up.
            let (look_at, up) = (look_at.unwrap_or(position - Vec3::Z), up.unwrap_or(Vec3::Y));
            let view = (look_at - position).normalize_or(-Vec3::Z);
            (transform.transform_point3(position), transform.transform_vector3(view), transform.transform_vector3(up))
        }
        None => (
            transform.transform_point3(Vec3::ZERO),
            transform.transform_vector3(-Vec3::Z),
            transform.transform_vector3(Vec3::Y),
        ),
    };
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
    Ok((CameraDesc { eye, target, up: up.normalize(), vfov, projection, film: Some(film), clip, window }, [w, h]))
}

/// A perspective camera's film: the apertures over the focal length, or Arnold's `fov`.
fn angle_of_view(prim: &Prim, time: TimeCode, [h_ap, v_ap]: [f32; 2], focal: f32) -> Res<Film> {
    let film = match arnold_number(prim, "fov", time)? {
        Some(fov) => arnold_fov_film(fov, v_ap / h_ap).map_err(|e| anyhow::anyhow!("`primvars:arnold:fov` {e}"))?,
        None => Film { aperture: [h_ap / focal, v_ap / focal], fit: FilmFit::Horizontal },
    };
    anyhow::ensure!(
        film.aperture.iter().all(|a| a.is_finite() && *a > 0.0),
        "apertures {h_ap} × {v_ap} over focal length {focal} do not give a field of view"
    );
    Ok(film)
}

/// The film of Arnold's `persp_camera` of horizontal field of view `fov` degrees, which
/// Arnold fits to the image's width (the vertical aperture, `aspect` times the horizontal
/// one, only sets the image's aspect when nothing else does); an error when `fov` is not
/// an angle between 0 and 180°.
pub fn arnold_fov_film(fov: f32, aspect: f32) -> Result<Film, String> {
    if !(fov > 0.0 && fov < 180.0) {
        return Err(format!("{fov} is not an angle between 0 and 180°"));
    }
    let h = 2.0 * (0.5 * fov).to_radians().tan();
    Ok(Film { aperture: [h, h * aspect], fit: FilmFit::Horizontal })
}

/// The film of Arnold's `ortho_camera`, whose screen window is in scene units: a screen
/// two units wide (−1..1) across the image, its height following the image aspect, so that
/// the window's y is in units of the image's height over its width.
pub const ARNOLD_ORTHO_FILM: Film = Film { aperture: [2.0, 2.0], fit: FilmFit::Horizontal };

/// An orthographic camera's film and the window of it seen: Arnold's screen window on
/// [`ARNOLD_ORTHO_FILM`] when authored, else the apertures in tenths of a unit, whole.
fn ortho_window(prim: &Prim, time: TimeCode, [h_ap, v_ap]: [f32; 2]) -> Res<(Film, [Vec2; 2])> {
    let corner = |name: &str| -> Res<Option<[f32; 2]>> {
        let what = format!("primvars:arnold:{name}");
        vec2(value(prim, &what, time)?, &what)
    };
    let (film, window) = match (corner("screen_window_min")?, corner("screen_window_max")?) {
        (None, None) => (Film { aperture: [h_ap / 10.0, v_ap / 10.0], fit: FilmFit::Horizontal }, FULL_SCREEN),
        (min, max) => {
            // Arnold's defaults: (-1, -1) to (1, 1).
            let (min, max) = (min.map_or(Vec2::NEG_ONE, Vec2::from), max.map_or(Vec2::ONE, Vec2::from));
            anyhow::ensure!(
                min.is_finite() && max.is_finite() && (max - min).min_element() > 0.0,
                "the orthographic screen window {min} to {max} is not a finite window"
            );
            (ARNOLD_ORTHO_FILM, [min, max])
        }
    };
    anyhow::ensure!(
        film.aperture.iter().all(|a| a.is_finite() && *a > 0.0),
        "the orthographic window {} × {} is not a finite positive size",
        film.aperture[0],
        film.aperture[1]
    );
    Ok((film, window))
}

/// An Arnold parameter Arnold-USD writes as a `primvars:arnold:NAME` primvar: a number, or
/// an array of one.
fn arnold_number(prim: &Prim, name: &str, time: TimeCode) -> Res<Option<f32>> {
    let what = format!("primvars:arnold:{name}");
    let v = value(prim, &what, time)?;
    let x = match v {
        Some(sdf::Value::FloatVec(_) | sdf::Value::DoubleVec(_) | sdf::Value::HalfVec(_)) => {
            floats(v, &what)?.and_then(|v| v.first().copied())
        }
        other => number(other, &what)?.map(|x| x as f32),
    };
    anyhow::ensure!(x.is_none_or(f32::is_finite), "`{what}` must be finite");
    Ok(x)
}
