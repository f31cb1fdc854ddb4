//! Attribute values of a composed stage read as tress's types, at the frame's time code:
//! arrays of vectors, numbers and integers, tokens, and primvar interpolations.

use glam::{DQuat, Vec3};
use openusd::usd::{Attribute, Prim, TimeCode};
use openusd::{gf, sdf};

pub type Res<T> = anyhow::Result<T>;

/// The attribute `name` of `prim` at `time`: its time samples there (interpolated
/// between the two around it where their types and lengths allow, as the crate's stage
/// resolves them) or its default value.
pub fn value(prim: &Prim, name: &str, time: TimeCode) -> Res<Option<sdf::Value>> {
    prim.attribute(name).get_at::<sdf::Value>(time)
}

/// An attribute's value at `time`, held at the sample at or before it (no interpolation):
/// for values whose samples may change the topology they go with.
pub fn held_value(attr: &Attribute, time: TimeCode) -> Res<Option<sdf::Value>> {
    match attr.bracketing_time_samples(time)? {
        Some((lo, _)) => attr.get_at::<sdf::Value>(TimeCode::new(lo)),
        None => attr.get_at::<sdf::Value>(time),
    }
}

/// An array of 3-vectors (float, double or half).
pub fn vec3s(v: Option<sdf::Value>, what: &str) -> Res<Option<Vec<Vec3>>> {
    let g = |v: &gf::Vec3f| Vec3::new(v.x, v.y, v.z);
    Ok(match v {
        None => None,
        Some(sdf::Value::Vec3fVec(v)) => Some(v.iter().map(g).collect()),
        Some(sdf::Value::Vec3dVec(v)) => {
            Some(v.iter().map(|p| Vec3::new(p.x as f32, p.y as f32, p.z as f32)).collect())
        }
        Some(sdf::Value::Vec3hVec(v)) => {
            Some(v.iter().map(|p| Vec3::new(p.x.to_f32(), p.y.to_f32(), p.z.to_f32())).collect())
        }
        Some(other) => anyhow::bail!("`{what}` is not an array of 3-vectors: {}", short(&other)),
    })
}

/// One 2-vector, or an array of one (as Arnold's writer stores its `VECTOR2` parameters),
/// or `None` when not authored.
pub fn vec2(v: Option<sdf::Value>, what: &str) -> Res<Option<[f32; 2]>> {
    let first = |v: Option<[f32; 2]>| v.ok_or_else(|| anyhow::anyhow!("`{what}` is an empty array"));
    let v = match v {
        None => return Ok(None),
        Some(sdf::Value::Vec2f(v)) => [v.x, v.y],
        Some(sdf::Value::Vec2d(v)) => [v.x as f32, v.y as f32],
        Some(sdf::Value::Vec2fVec(v)) => first(v.first().map(|p| [p.x, p.y]))?,
        Some(sdf::Value::Vec2dVec(v)) => first(v.first().map(|p| [p.x as f32, p.y as f32]))?,
        Some(other) => anyhow::bail!("`{what}` is not a 2-vector: {}", short(&other)),
    };
    anyhow::ensure!(v.iter().all(|x| x.is_finite()), "`{what}` must be finite");
    Ok(Some(v))
}

/// One 3-vector (a colour), or `None` when not authored.
pub fn vec3(v: Option<sdf::Value>, what: &str) -> Res<Option<Vec3>> {
    Ok(match v {
        None => None,
        Some(sdf::Value::Vec3f(c)) => Some(Vec3::new(c.x, c.y, c.z)),
        Some(sdf::Value::Vec3d(c)) => Some(Vec3::new(c.x as f32, c.y as f32, c.z as f32)),
        Some(sdf::Value::Vec3h(c)) => Some(Vec3::new(c.x.to_f32(), c.y.to_f32(), c.z.to_f32())),
        Some(v @ (sdf::Value::Vec3fVec(_) | sdf::Value::Vec3dVec(_) | sdf::Value::Vec3hVec(_))) => {
            vec3s(Some(v), what)?.and_then(|v| v.first().copied())
        }
        Some(other) => anyhow::bail!("`{what}` is not a 3-vector: {}", short(&other)),
    })
}

/// An array of numbers (float, double or half).
pub fn floats(v: Option<sdf::Value>, what: &str) -> Res<Option<Vec<f32>>> {
    Ok(match v {
        None => None,
        Some(sdf::Value::FloatVec(v)) => Some(v),
        Some(sdf::Value::DoubleVec(v)) => Some(v.iter().map(|&x| x as f32).collect()),
        Some(sdf::Value::HalfVec(v)) => Some(v.iter().map(|x| x.to_f32()).collect()),
        Some(other) => anyhow::bail!("`{what}` is not an array of numbers: {}", short(&other)),
    })
}

/// An array of numbers in double precision (NURBS knots).
pub fn doubles(v: Option<sdf::Value>, what: &str) -> Res<Option<Vec<f64>>> {
    Ok(match v {
        Some(sdf::Value::DoubleVec(v)) => Some(v),
        other => floats(other, what)?.map(|v| v.into_iter().map(f64::from).collect()),
    })
}

/// One number (float, double, half or integer), or `None` when not authored.
pub fn number(v: Option<sdf::Value>, what: &str) -> Res<Option<f64>> {
    Ok(match v {
        None => None,
        Some(sdf::Value::Float(x)) => Some(x as f64),
        Some(sdf::Value::Double(x)) => Some(x),
        Some(sdf::Value::Half(x)) => Some(x.to_f32() as f64),
        Some(sdf::Value::Int(x)) => Some(x as f64),
        Some(sdf::Value::Int64(x)) => Some(x as f64),
        Some(other) => anyhow::bail!("`{what}` is not a number: {}", short(&other)),
    })
}

/// An array of integers.
pub fn ints(v: Option<sdf::Value>, what: &str) -> Res<Option<Vec<i64>>> {
    Ok(match v {
        None => None,
        Some(sdf::Value::IntVec(v)) => Some(v.iter().map(|&x| x as i64).collect()),
        Some(sdf::Value::Int64Vec(v)) => Some(v),
        Some(sdf::Value::UintVec(v)) => Some(v.iter().map(|&x| x as i64).collect()),
        Some(other) => anyhow::bail!("`{what}` is not an array of integers: {}", short(&other)),
    })
}

/// A `quatf[]`, `quatd[]` or `quath[]` attribute's value; USD writes `(w, x, y, z)`.
pub fn quats(v: Option<sdf::Value>, what: &str) -> Res<Option<Vec<DQuat>>> {
    let q = |w: f64, x: f64, y: f64, z: f64| DQuat::from_xyzw(x, y, z, w);
    Ok(match v {
        None => None,
        Some(sdf::Value::QuatfVec(a)) => {
            Some(a.iter().map(|r| q(r.w.into(), r.x.into(), r.y.into(), r.z.into())).collect())
        }
        Some(sdf::Value::QuatdVec(a)) => Some(a.iter().map(|r| q(r.w, r.x, r.y, r.z)).collect()),
        Some(sdf::Value::QuathVec(a)) => {
            Some(a.iter().map(|r| q(r.w.to_f64(), r.x.to_f64(), r.y.to_f64(), r.z.to_f64())).collect())
        }
        Some(other) => anyhow::bail!("`{what}` is not an array of quaternions: {}", short(&other)),
    })
}

/// A token or string value, `default` when not authored.
pub fn token(v: Option<sdf::Value>, default: &str) -> String {
    match v {
        Some(sdf::Value::Token(t)) => t.as_str().to_string(),
        Some(sdf::Value::String(s)) => s,
        _ => default.to_string(),
    }
}

/// A bool value, `default` when not authored.
pub fn boolean(v: Option<sdf::Value>, default: bool) -> bool {
    match v {
        Some(sdf::Value::Bool(b)) => b,
        Some(sdf::Value::Int(i)) => i != 0,
        _ => default,
    }
}

/// A value's variant for messages, without its (possibly huge) contents.
pub fn short(v: &sdf::Value) -> String {
    let s = format!("{v:?}");
    s.split('(').next().unwrap_or(&s).to_string()
}

/// How a primvar's values map onto a prim's elements.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Interpolation {
    /// One value for the whole prim.
    Constant,
    /// One value per curve (or face).
    Uniform,
    /// One value per segment end, blended linearly.
    Varying,
    /// One value per control point, following the basis.
    Vertex,
}

/// An attribute's `interpolation` metadata, `default` when not authored (`faceVarying`
/// reads as vertex: curves have no faces).
pub fn interpolation(attr: &Attribute, default: Interpolation) -> Res<Interpolation> {
    Ok(match attr.get_metadata::<sdf::Value>("interpolation")? {
        None => default,
        Some(v) => match token(Some(v), "").as_str() {
            "constant" => Interpolation::Constant,
            "uniform" => Interpolation::Uniform,
            "varying" => Interpolation::Varying,
            "vertex" | "faceVarying" => Interpolation::Vertex,
            other => anyhow::bail!("unknown interpolation `{other}`"),
        },
    })
}
