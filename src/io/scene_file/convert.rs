//! Conversion of the schema's tables into the description's types: lights, materials,
//! transforms, procedural shapes, level of detail, filters, hair systems and fur. Each
//! function checks its values and names the wrong one.

use super::schema::*;
use crate::accel::lod::LodParams;
use crate::film::PixelFilter;
use crate::fur::{AttractorModel, Attractors, FurDescription, Placement as FurPlacement};
use crate::geometry::TriangleMesh;
use crate::hair_system::ramp::RampValue;
use crate::hair_system::{FollicleParams, HairColors, HairSystem, Interp, NoiseMethod, Placement, Ramp, RampKey};
use crate::light::{Light, MapPlacement, PhysicalSky};
use crate::math::Color;
use crate::scene::{
    EnvironmentFile, FurEntry, GuideSource, HairSource, HairSystemEntry, LightSource, MaterialSource, Projection,
    RoughnessSource, TexturedFiles, Visibility,
};
use crate::shading::hair_bsdf::{Absorption, HairParams, PhysicalHair};
use crate::shading::{tube::Tube, Material};
use glam::{Affine3A, Quat, Vec3};
use std::path::Path;

impl FilterToml {
    pub(super) fn filter(&self) -> Result<PixelFilter, String> {
        let (kind, radius, sigma) = match self {
            FilterToml::Name(name) => (name.as_str(), None, None),
            FilterToml::With(t) => (t.kind.as_str(), t.radius, t.sigma),
        };
        let f = match kind.parse()? {
            PixelFilter::Box if radius.is_none() && sigma.is_none() => PixelFilter::Box,
            PixelFilter::Box => return Err("the `box` filter takes no `radius` or `sigma`".into()),
            PixelFilter::Gaussian { .. } => {
                let radius = radius.unwrap_or(PixelFilter::GAUSSIAN_RADIUS);
                PixelFilter::Gaussian { radius, sigma: sigma.unwrap_or(radius / 3.0) }
            }
        };
        f.validate()?;
        Ok(f)
    }
}

impl LodToml {
    pub(super) fn params(&self) -> Result<LodParams, String> {
        let d = LodParams::default();
        let p = LodParams {
            decimation: self.decimation.unwrap_or(d.decimation),
            levels: self.levels.unwrap_or(d.levels),
            compensation: self.compensation.unwrap_or(d.compensation),
            contrast: self.contrast.unwrap_or(d.contrast),
            start: self.start.unwrap_or(d.start),
            spread: self.spread.unwrap_or(d.spread),
            simplify: self.simplify.unwrap_or(d.simplify),
            smooth: self.smooth.unwrap_or(d.smooth),
        };
        p.validate()?;
        Ok(p)
    }
}

/// Converts a ramp with `convert` for its values, naming the attribute in errors.
pub(super) fn ramp<U: Copy, T: RampValue>(
    name: &str,
    r: &RampToml<U>,
    convert: impl Fn(U) -> T,
) -> Result<Ramp<T>, String> {
    let keys = match r {
        RampToml::Constant(v) => return Ok(Ramp::constant(convert(*v))),
        RampToml::Keys(keys) => keys,
    };
    let mut out = Vec::with_capacity(keys.len());
    for (i, k) in keys.iter().enumerate() {
        let (position, value, interp) = match k {
            RampKeyToml::Pair(p, v) => (*p, *v, None),
            RampKeyToml::Triple(p, v, s) => (*p, *v, Some(s)),
            RampKeyToml::Table { position, value, interp } => (*position, *value, interp.as_ref()),
        };
        let interp = match interp {
            None => Interp::Linear,
            Some(how) => Interp::from_name(how).ok_or_else(|| {
                format!("`{name}` key {}: unknown interpolation `{how}` (none, linear, smooth or spline)", i + 1)
            })?,
        };
        out.push(RampKey { position, value: convert(value), interp });
    }
    Ramp::new(out).map_err(|e| format!("`{name}` {e}"))
}

pub(super) fn hair_system(h: &HairSystemToml, base: &Path, meshes: usize) -> Result<HairSystemEntry, String> {
    let mut s = HairSystem::default();
    macro_rules! set {
        ($($field:ident),*) => { $( if let Some(v) = h.$field { s.$field = v; } )* };
    }
    set!(
        hairs_per_clump,
        sub_segments,
        thinning,
        clump_width,
        clump_twist,
        bend_follow,
        hair_width,
        curl,
        curl_frequency,
        noise,
        noise_frequency,
        noise_frequency_u,
        noise_frequency_v,
        noise_frequency_w,
        opacity,
        translucence,
        specular_power,
        diffuse_rand,
        specular_rand,
        hue_rand,
        sat_rand,
        val_rand
    );
    macro_rules! set_ramp {
        ($($field:ident),*) => { $( if let Some(r) = &h.$field { s.$field = ramp(stringify!($field), r, |x| x)?; } )* };
    }
    set_ramp!(clump_width_scale, clump_curl, clump_flatness, hair_width_scale, displacement_scale);
    if let Some(r) = &h.hair_color_scale {
        s.hair_color_scale = ramp("hair_color_scale", r, Vec3::from)?;
    }
    if let Some(c) = h.hair_color {
        s.hair_color = c.into();
    }
    if let Some(c) = h.specular_color {
        s.specular_color = c.into();
    }
    if let Some(m) = &h.noise_method {
        s.noise_method = match m.as_str() {
            "random" => NoiseMethod::Random,
            "surface_uv" => NoiseMethod::SurfaceUv,
            "clump_uv" => NoiseMethod::ClumpUv,
            _ => return Err(format!("unknown `noise_method` `{m}` (random, surface_uv or clump_uv)")),
        };
    }
    s.validate()?;
    let colors = match h.colors.as_deref() {
        None | Some("system") => HairColors::System,
        Some("guides") => HairColors::Guides,
        Some("material") => HairColors::Material,
        Some(c) => return Err(format!("unknown `colors` `{c}` (system, guides or material)")),
    };
    let guides = match (&h.file, &h.follicles) {
        (Some(file), None) => GuideSource::File(base.join(file)),
        (None, Some(f)) => {
            if h.transform.is_some() {
                return Err("`transform` applies to guides from a `file`; follicles follow their mesh".into());
            }
            GuideSource::Follicles { mesh: follicle_mesh(f, meshes)?, params: follicles(f)? }
        }
        _ => return Err("give exactly one of `file` and `follicles`".into()),
    };
    let material = match &h.material {
        Some(m) => material(m, base)?,
        None => Material::Tube(s.tube()).into(),
    };
    let transform = match &h.transform {
        Some(t) => transform(t)?,
        None => Affine3A::IDENTITY,
    };
    let lod = h.lod.as_ref().map(LodToml::params).transpose()?;
    let visibility = visibility_keys(Visibility::default(), (h.camera_visible, h.casts_shadows, h.matte));
    Ok(HairSystemEntry { guides, system: s, material, colors, transform, seed: h.seed, lod, visibility })
}

pub(super) fn follicle_mesh(f: &FolliclesToml, meshes: usize) -> Result<usize, String> {
    match f.mesh {
        m if m >= 1 && m <= meshes => Ok(m - 1),
        m => Err(format!("follicles `mesh = {m}` names no [[mesh]] entry (the scene has {meshes}, numbered from 1)")),
    }
}

pub(super) fn follicles(f: &FolliclesToml) -> Result<FollicleParams, String> {
    let d = FollicleParams::default();
    let placement = match (f.placement.as_str(), f.count) {
        ("grid", None) => Placement::Grid { u: f.u.unwrap_or(10), v: f.v.unwrap_or(10) },
        ("random", Some(count)) if f.u.is_none() && f.v.is_none() => Placement::Random { count },
        ("grid", Some(_)) => return Err("follicles: `count` goes with `placement = \"random\"`".into()),
        ("random", _) => return Err("follicles: `placement = \"random\"` takes `count` (not `u`, `v`)".into()),
        (p, _) => return Err(format!("follicles: unknown `placement` `{p}` (grid or random)")),
    };
    let [uv_min, uv_max] = f.uv_range.unwrap_or([d.uv_min, d.uv_max]);
    let params = FollicleParams {
        placement,
        randomization: f.randomization.unwrap_or(d.randomization),
        uv_min,
        uv_max,
        points_per_hair: f.points_per_hair.unwrap_or(d.points_per_hair),
        length: f.length.unwrap_or(d.length),
        droop: f.droop.unwrap_or(d.droop),
        gravity: match f.gravity {
            // Normalised here; a zero or non-finite direction fails validation below.
            Some(g) => Vec3::from(g).try_normalize().unwrap_or(Vec3::NAN),
            None => d.gravity,
        },
    };
    params.validate().map_err(|e| format!("follicles: {e}"))?;
    Ok(params)
}

pub(super) fn fur(f: &FurToml, meshes: usize, base: &Path) -> Result<FurEntry, String> {
    if f.mesh < 1 || f.mesh as usize > meshes {
        return Err(format!("`mesh` = {} names no mesh (give 1 to {meshes}, the [[mesh]] entries in order)", f.mesh));
    }
    let mut description = match &f.preset {
        Some(name) => crate::fur::presets::preset(name)?,
        None => FurDescription::default(),
    };
    description.apply_table(&f.attributes, base)?;
    let guides = match (&f.guides, &f.attractors) {
        (Some(file), a) => {
            let d = Attractors::default();
            let a = a.as_ref();
            let attractors = Attractors {
                model: match a.and_then(|a| a.model.as_ref()) {
                    Some(AttractorModelToml::Global) => AttractorModel::Global,
                    Some(AttractorModelToml::Local) => AttractorModel::Local,
                    None => d.model,
                },
                curves_per_fur: a.and_then(|a| a.curves_per_fur).unwrap_or(d.curves_per_fur),
                global_scale: a.and_then(|a| a.global_scale).unwrap_or(d.global_scale),
                radius: a.and_then(|a| a.radius).unwrap_or(d.radius),
                power: a.and_then(|a| a.power).unwrap_or(d.power),
                influence: a.and_then(|a| a.influence).unwrap_or(d.influence),
                threshold_length: a.and_then(|a| a.threshold_length).unwrap_or(d.threshold_length),
            };
            attractors.validate()?;
            Some((HairSource::File(base.join(file)), attractors))
        }
        (None, Some(_)) => return Err("`attractors` needs `guides`".into()),
        (None, None) => None,
    };
    Ok(FurEntry {
        mesh: f.mesh as usize - 1,
        description,
        placement: match f.placement {
            PlacementToml::Area => FurPlacement::Area,
            PlacementToml::Uv => FurPlacement::Uv,
        },
        seed: f.seed,
        guides,
        lod: f.lod.as_ref().map(LodToml::params).transpose()?,
        grows_on: None,
        width_profile: None,
        visibility: visibility_keys(Visibility::default(), (f.camera_visible, f.casts_shadows, f.matte)),
    })
}

/// `base` with the switches an entry's `camera_visible`, `casts_shadows` and `matte` keys
/// give (each key not given keeps `base`'s).
pub(super) fn visibility_keys(
    base: Visibility,
    (camera, shadows, matte): (Option<bool>, Option<bool>, Option<bool>),
) -> Visibility {
    Visibility {
        camera: camera.unwrap_or(base.camera),
        shadows: shadows.unwrap_or(base.shadows),
        matte: matte.unwrap_or(base.matte),
    }
}

pub(super) fn check(name: &str, v: &[f32], min: f32) -> Result<(), String> {
    match v.iter().all(|x| x.is_finite() && *x >= min) {
        true => Ok(()),
        false if min == 0.0 => Err(format!("`{name}` must be finite and not negative")),
        false => Err(format!("`{name}` must be finite")),
    }
}

pub(super) fn light(l: &LightToml, base: &Path) -> Result<Vec<LightSource>, String> {
    const ANY: f32 = f32::NEG_INFINITY;
    Ok(vec![LightSource::Inline(match *l {
        LightToml::Distant { direction, irradiance, angular_diameter } => {
            check("direction", &direction, ANY)?;
            check("irradiance", &irradiance, 0.0)?;
            if !(0.0..=180.0).contains(&angular_diameter) {
                return Err("`angular_diameter` must be between 0 and 180 degrees".into());
            }
            let direction = Vec3::from(direction).try_normalize().ok_or("`direction` is zero")?;
            Light::distant(direction, irradiance.into(), angular_diameter.to_radians())
        }
        LightToml::Point { position, intensity } => {
            check("position", &position, ANY)?;
            check("intensity", &intensity, 0.0)?;
            Light::Point { position: position.into(), intensity: intensity.into(), decay: 2 }
        }
        LightToml::Spot { position, target, intensity, inner_angle, outer_angle } => {
            check("position", &position, ANY)?;
            check("target", &target, ANY)?;
            check("intensity", &intensity, 0.0)?;
            check("angles", &[inner_angle, outer_angle], 0.0)?;
            if inner_angle > outer_angle || outer_angle > 180.0 {
                return Err("need 0 <= inner_angle <= outer_angle <= 180".into());
            }
            let direction = (Vec3::from(target) - Vec3::from(position)).try_normalize().ok_or("target = position")?;
            Light::Spot {
                position: position.into(),
                direction,
                intensity: intensity.into(),
                cos_inner: inner_angle.to_radians().cos(),
                cos_outer: outer_angle.to_radians().cos(),
                decay: 2,
            }
        }
        LightToml::Quad { corner, edge_u, edge_v, radiance, camera_visibility } => {
            check("corner and edges", &[corner, edge_u, edge_v].concat(), ANY)?;
            check("radiance", &radiance, 0.0)?;
            check("camera_visibility", &[camera_visibility], 0.0)?;
            if Vec3::from(edge_u).cross(edge_v.into()).length_squared() == 0.0 {
                return Err("quad edges are parallel or zero".into());
            }
            Light::Quad {
                corner: corner.into(),
                edge_u: edge_u.into(),
                edge_v: edge_v.into(),
                radiance: radiance.into(),
                camera_visibility,
            }
        }
        LightToml::Sphere { center, radius, radiance, camera_visibility } => {
            check("center", &center, ANY)?;
            check("radius", &[radius], 0.0)?;
            check("radiance", &radiance, 0.0)?;
            check("camera_visibility", &[camera_visibility], 0.0)?;
            Light::Sphere { center: center.into(), radius, radiance: radiance.into(), camera_visibility }
        }
        LightToml::Environment { radiance, ref file, rotation, intensity, exposure, camera_visibility } => {
            check("rotation", &[rotation], ANY)?;
            check("camera_visibility", &[camera_visibility], 0.0)?;
            check("intensity", &[intensity], 0.0)?;
            check("exposure", &[exposure], ANY)?;
            let scale = intensity * exposure.exp2();
            if !scale.is_finite() {
                return Err("`intensity` times 2^`exposure` is too large".into());
            }
            match (radiance, file) {
                (Some(radiance), None) => {
                    check("radiance", &radiance, 0.0)?;
                    if rotation != 0.0 {
                        return Err("`rotation` turns an environment map: give it a `file`".into());
                    }
                    Light::Environment { radiance: Vec3::from(radiance) * scale, camera_visibility }
                }
                // Read by `prepare`, which reports a file it cannot use.
                (None, Some(file)) => {
                    return Ok(vec![LightSource::File(EnvironmentFile {
                        path: base.join(file),
                        projection: Projection::LatLong,
                        tint: Color::ONE,
                        illuminance: None,
                        placement: MapPlacement::new(rotation, scale).seen_by_camera(camera_visibility),
                        fallback: None,
                    })])
                }
                _ => return Err("give exactly one of `radiance` and `file`".into()),
            }
        }
        LightToml::Sky {
            elevation,
            azimuth,
            turbidity,
            ground_albedo,
            sun_size,
            intensity,
            exposure,
            camera_visibility,
        } => {
            check("elevation, azimuth, exposure", &[elevation, azimuth, exposure], ANY)?;
            check("turbidity, sun_size, intensity", &[turbidity, sun_size, intensity], 0.0)?;
            check("camera_visibility", &[camera_visibility], 0.0)?;
            check("ground_albedo", &ground_albedo, 0.0)?;
            if !(1.0..=10.0).contains(&turbidity) {
                return Err("`turbidity` must be between 1 and 10".into());
            }
            let sky = PhysicalSky {
                sun: crate::light::sun_direction(elevation, azimuth),
                turbidity,
                ground_albedo: ground_albedo.into(),
                sun_size,
                ..PhysicalSky::arnold_default()
            };
            let placement = MapPlacement::new(0.0, intensity * exposure.exp2()).seen_by_camera(camera_visibility);
            return Ok(sky.lights(placement)?.into_iter().map(LightSource::Inline).collect());
        }
    })])
}

/// The material a table describes; textures are named by path, for `prepare` to read.
pub(super) fn material(m: &MaterialToml, base: &Path) -> Result<MaterialSource, String> {
    Ok(MaterialSource::Inline(match *m {
        MaterialToml::Textured { ref color, tint, ref roughness, specular } => {
            check("tint", &tint, 0.0)?;
            let roughness = match roughness {
                None => None,
                Some(RoughnessToml::Constant(r)) if r.is_finite() && *r > 0.0 && *r <= 1.0 => {
                    Some(RoughnessSource::Constant(*r))
                }
                Some(RoughnessToml::Constant(_)) => return Err("`roughness` must be in (0, 1]".into()),
                Some(RoughnessToml::Map(file)) => Some(RoughnessSource::Map(base.join(file))),
            };
            let specular = specular.unwrap_or(if roughness.is_some() { 0.04 } else { 0.0 });
            check("specular", &[specular], 0.0)?;
            return Ok(MaterialSource::Textured(TexturedFiles {
                color: base.join(color),
                tint: tint.into(),
                roughness,
                specular: Color::splat(specular),
            }));
        }
        MaterialToml::Diffuse { color } => {
            check("color", &color, 0.0)?;
            Material::Diffuse { color: color.into() }
        }
        MaterialToml::Phong { diffuse, specular, exponent } => {
            check("diffuse, specular and exponent", &[&diffuse[..], &specular[..], &[exponent]].concat(), 0.0)?;
            Material::Phong { diffuse: diffuse.into(), specular: specular.into(), exponent }
        }
        MaterialToml::Mirror { color } => {
            check("color", &color, 0.0)?;
            Material::Mirror { color: color.into() }
        }
        MaterialToml::Unlit { color } => {
            check("color", &color, 0.0)?;
            Material::Unlit { color: color.into() }
        }
        MaterialToml::Glass { ior, color } => {
            check("color", &color, 0.0)?;
            if !(ior.is_finite() && ior >= 1.0) {
                return Err("`ior` must be finite and at least 1".into());
            }
            Material::Glass { ior, color: color.into() }
        }
        MaterialToml::Tube { ambient, diffuse, specular, specular_power } => {
            let ambient = ambient.unwrap_or(diffuse);
            check(
                "tube colours and specular_power",
                &[&ambient[..], &diffuse, &specular, &[specular_power]].concat(),
                0.0,
            )?;
            Material::Tube(Tube {
                ambient: ambient.into(),
                diffuse: diffuse.into(),
                specular: specular.into(),
                specular_power,
            })
        }
        MaterialToml::Physical { eumelanin, pheomelanin, color, from_file, beta_m, beta_n, alpha, eta } => {
            let melanin = eumelanin.is_some() || pheomelanin.is_some();
            let absorption = match (melanin, color, from_file) {
                (true, None, false) => {
                    Absorption::Melanin { eumelanin: eumelanin.unwrap_or(0.0), pheomelanin: pheomelanin.unwrap_or(0.0) }
                }
                (false, Some(c), false) => Absorption::Color(c.into()),
                (false, None, true) => Absorption::FromStrands,
                (false, None, false) => HairParams::default().absorption,
                _ => {
                    return Err(
                        "physical: give at most one of `eumelanin`/`pheomelanin`, `color` and `from_file = true`"
                            .into(),
                    )
                }
            };
            let params = HairParams { absorption, beta_m, beta_n, alpha_degrees: alpha, eta };
            params.validate().map_err(|m| format!("physical: {m}"))?;
            Material::Physical(PhysicalHair::new(params))
        }
    }))
}

pub(super) fn transform(t: &TransformToml) -> Result<Affine3A, String> {
    let scale = match t.scale {
        None => Vec3::ONE,
        Some(ScaleToml::Uniform(s)) => Vec3::splat(s),
        Some(ScaleToml::Axes(a)) => a.into(),
    };
    check("scale", &scale.to_array(), f32::NEG_INFINITY)?;
    if scale.x * scale.y * scale.z == 0.0 {
        return Err("`scale` must not be zero".into());
    }
    let rotation = match t.rotate {
        None => Quat::IDENTITY,
        Some([x, y, z, deg]) => {
            check("rotate", &[x, y, z, deg], f32::NEG_INFINITY)?;
            let axis = Vec3::new(x, y, z).try_normalize().ok_or("`rotate` axis is zero")?;
            Quat::from_axis_angle(axis, deg.to_radians())
        }
    };
    let translate = t.translate.unwrap_or([0.0; 3]);
    check("translate", &translate, f32::NEG_INFINITY)?;
    Ok(Affine3A::from_scale_rotation_translation(scale, rotation, translate.into()))
}

pub(super) fn procedural(s: &ShapeToml) -> Result<TriangleMesh, String> {
    Ok(match *s {
        ShapeToml::Torus { major, minor } => {
            check("major and minor", &[major, minor], 0.0)?;
            TriangleMesh::torus(major, minor, 96, 48)
        }
        ShapeToml::Sphere { radius } => {
            check("radius", &[radius], 0.0)?;
            TriangleMesh::sphere(radius, 48)
        }
        ShapeToml::Plane { size } => {
            check("size", &[size], 0.0)?;
            TriangleMesh::plane(size)
        }
        ShapeToml::Pillow { size, thickness } => {
            check("size and thickness", &[size, thickness], 0.0)?;
            TriangleMesh::pillow(size, thickness, 64)
        }
    })
}
