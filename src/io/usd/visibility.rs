//! Arnold's per-object ray visibility and holdout on USD prims, read as Arnold-USD's
//! reader reads them on a shape (`ReadArnoldParameters` with the `primvars:arnold`
//! scope, in its `libs/common/parameters_utils.cpp`):
//!
//! - `primvars:arnold:visibility`: the packed byte of Arnold's shape parameter
//!   `visibility`, one bit per ray type (Arnold's `ai_ray.h`: camera 1, shadow 2,
//!   diffuse_transmit 4, specular_transmit 8, volume 16, diffuse_reflect 32,
//!   specular_reflect 64, subsurface 128; all 255);
//! - `primvars:arnold:visibility:RAY` for each of those ray names: sets (true) or clears
//!   (false) that one bit. It wins over the packed byte's bit, whichever is authored
//!   where: Arnold's reader applies the packed byte first (it sorts first by name), and
//!   Arnold-USD issues #2345 and #2385 settle that the single flag overrides it;
//! - `primvars:arnold:matte`: the shape's holdout switch.
//!
//! Each of them is a primvar, so a prim takes the nearest one authored on itself or its
//! ancestors (constant primvars inherit down the namespace, as `UsdGeomPrimvarsAPI`'s
//! `FindPrimvarsWithInheritance` resolves them for Arnold's reader): a PointInstancer's
//! apply to the prototypes beneath it. USD's own `visibility = "invisible"` wins over all
//! of them (Arnold-USD issue #1613): such prims are not drawn at all.
//!
//! tress hides objects from camera rays and shadow rays ([`Visibility`]); a prim whose
//! byte clears every bit is not drawn, as Arnold draws it for no ray. Clearing the
//! reflection or transmission bits alone cannot be honoured: those rays still see the
//! object, said once per ray type. Volume and subsurface rays do not exist in tress, so
//! hiding from them changes nothing and is not reported. The same names without the
//! `primvars:` prefix (`arnold:visibility:camera`, ...) are read by Arnold only on its own
//! `Arnold*` prim types, not on UsdGeom prims: on those they are named in a warning.

use super::values::{held_value, short, token, Res};
use super::Notes;
use crate::scene::Visibility;
use openusd::sdf;
use openusd::usd::{Prim, TimeCode};

/// Arnold's ray types: the name of each in `visibility:` primvars and its bit in the
/// packed byte (`AI_RAY_CAMERA`, ... in Arnold's `ai_ray.h`).
pub const RAYS: [(&str, u8); 8] = [
    ("camera", 1),
    ("shadow", 2),
    ("diffuse_transmit", 4),
    ("specular_transmit", 8),
    ("volume", 16),
    ("diffuse_reflect", 32),
    ("specular_reflect", 64),
    ("subsurface", 128),
];

/// The bits tress honours (camera, shadow) or has no rays for (volume, subsurface):
/// clearing any other is reported.
const HONOURED: u8 = 1 | 2 | 16 | 128;

/// A prim's visibility as Arnold's primvars set it, `None` when they hide it from every
/// ray (not drawn). Malformed values (a packed byte past 255, a flag that is not a bool or
/// an integer) are left out with a warning naming the prim and attribute, as Arnold's
/// reader ignores a value it cannot convert.
pub fn read(prim: &Prim, time: TimeCode, notes: &mut Notes) -> Res<Option<Visibility>> {
    let mut bits = 255u8;
    // Where each bit was cleared, for the warning on those tress cannot honour.
    let mut cleared_by: [Option<String>; 8] = Default::default();
    let packed = "primvars:arnold:visibility";
    if let Some(v) = inherited(prim, packed, time)? {
        match v {
            sdf::Value::Uchar(b) => bits = b,
            sdf::Value::Int(_) | sdf::Value::Uint(_) | sdf::Value::Int64(_) | sdf::Value::Uint64(_) => {
                match integer(&v).and_then(|i| u8::try_from(i).ok()) {
                    Some(b) => bits = b,
                    None => bad(notes, prim, packed, "not a byte (0 to 255)", &v),
                }
            }
            other => bad(notes, prim, packed, "not a byte (0 to 255)", &other),
        }
        for (slot, (_, bit)) in cleared_by.iter_mut().zip(RAYS) {
            if bits & bit == 0 {
                *slot = Some(packed.to_string());
            }
        }
    }
    for (slot, (ray, bit)) in cleared_by.iter_mut().zip(RAYS) {
        let name = format!("primvars:arnold:visibility:{ray}");
        match inherited(prim, &name, time)?.map(|v| (flag(&v), v)) {
            None => {}
            Some((Some(true), _)) => {
                bits |= bit;
                *slot = None;
            }
            Some((Some(false), _)) => {
                bits &= !bit;
                *slot = Some(name);
            }
            Some((None, v)) => bad(notes, prim, &name, "not a bool or an integer", &v),
        }
    }
    let matte = match inherited(prim, "primvars:arnold:matte", time)? {
        None => false,
        Some(v) => flag(&v).unwrap_or_else(|| {
            bad(notes, prim, "primvars:arnold:matte", "not a bool or an integer", &v);
            false
        }),
    };
    note_non_primvars(prim, time, notes)?;
    let Some(visibility) = from_bits(bits, matte) else {
        return Ok(None);
    };
    for ((ray, bit), by) in RAYS.iter().zip(&cleared_by) {
        if let (false, Some(by)) = (HONOURED & bit != 0, by) {
            notes.note_why(
                format!("Arnold visibility off for {ray} rays: not applied (tress hides objects only from camera and shadow rays), seen by them"),
                prim,
                by,
            );
        }
    }
    Ok(Some(visibility))
}

/// Arnold's packed visibility byte (camera 1, shadow 2, ...; [`RAYS`]) as what tress
/// honours, `None` when it hides the shape from every ray (not drawn).
pub fn from_bits(bits: u8, matte: bool) -> Option<Visibility> {
    (bits != 0).then_some(Visibility { camera: bits & 1 != 0, shadows: bits & 2 != 0, matte })
}

/// The value of the primvar `name` on `prim`, else on its nearest ancestor that authors
/// it with constant interpolation (the only kind that inherits).
pub(super) fn inherited(prim: &Prim, name: &str, time: TimeCode) -> Res<Option<sdf::Value>> {
    // Integer samples are held, not blended (a byte between 0 and 255 is no mask).
    if let Some(v) = held_value(&prim.attribute(name), time)? {
        return Ok(Some(v));
    }
    let mut path = prim.path().parent();
    while let Some(p) = path.filter(|p| !p.as_str().is_empty() && p.as_str() != "/") {
        let attr = prim.stage().prim(p.clone()).attribute(name);
        if let Some(v) = held_value(&attr, time)? {
            let interpolation = token(attr.get_metadata::<sdf::Value>("interpolation")?, "constant");
            if interpolation == "constant" {
                return Ok(Some(v));
            }
        }
        path = p.parent();
    }
    Ok(None)
}

/// A flag's value: a bool, or an integer read as true when not 0 (Arnold's reader takes
/// `bool`, `int` and `long`).
fn flag(v: &sdf::Value) -> Option<bool> {
    match v {
        sdf::Value::Bool(b) => Some(*b),
        other => integer(other).map(|i| i != 0),
    }
}

/// An integer value of any width.
pub(super) fn integer(v: &sdf::Value) -> Option<i128> {
    match *v {
        sdf::Value::Uchar(x) => Some(x.into()),
        sdf::Value::Int(x) => Some(x.into()),
        sdf::Value::Uint(x) => Some(x.into()),
        sdf::Value::Int64(x) => Some(x.into()),
        sdf::Value::Uint64(x) => Some(x.into()),
        _ => None,
    }
}

/// Counts a visibility attribute whose value cannot be read.
fn bad(notes: &mut Notes, prim: &Prim, name: &str, why: &str, v: &sdf::Value) {
    let value = match integer(v) {
        Some(i) => i.to_string(),
        None => short(v),
    };
    notes.note_why(
        format!("Arnold visibility attributes whose value is {why}: left out"),
        prim,
        &format!("{name} = {value}"),
    );
}

/// Warns about Arnold's visibility and matte authored as plain attributes on a UsdGeom
/// prim, where Arnold does not read them.
fn note_non_primvars(prim: &Prim, time: TimeCode, notes: &mut Notes) -> Res<()> {
    let names = ["arnold:visibility".to_string(), "arnold:matte".to_string()]
        .into_iter()
        .chain(RAYS.iter().map(|(ray, _)| format!("arnold:visibility:{ray}")));
    for name in names {
        if held_value(&prim.attribute(name.as_str()), time)?.is_some() {
            notes.note_why(
                "Arnold visibility and matte as attributes, not primvars: not read (Arnold reads them on UsdGeom \
                 prims only as `primvars:arnold:` primvars)"
                    .into(),
                prim,
                &name,
            );
            break;
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::super::tests::read_text;
    use super::*;
    use crate::io::usd::read_usd;
    use crate::io::ImportOptions;

    /// A stage of `body` under a Y-up header.
    fn stage(body: &str) -> String {
        format!("#usda 1.0\n(\n    upAxis = \"Y\"\n)\n{body}")
    }

    /// A unit-triangle mesh prim named `name` with the extra lines `attrs`.
    fn mesh(name: &str, attrs: &str) -> String {
        format!(
            "def Mesh \"{name}\"\n{{\n    int[] faceVertexCounts = [3]\n    int[] faceVertexIndices = [0, 1, 2]\n    \
             point3f[] points = [(0, 0, 0), (1, 0, 0), (0, 1, 0)]\n    {attrs}\n}}\n"
        )
    }

    fn seen(camera: bool, shadows: bool, matte: bool) -> Visibility {
        Visibility { camera, shadows, matte }
    }

    /// Every mesh's visibility, in stage order.
    fn meshes(text: &str) -> (Vec<Visibility>, Vec<String>) {
        let s = read_text(&stage(text)).unwrap();
        (s.contents.meshes.iter().map(|m| m.visibility).collect(), s.warnings)
    }

    #[test]
    fn each_form_sets_its_switch_on_meshes_curves_points_and_gprims() {
        let curves = "def BasisCurves \"Hair\"\n{\n    uniform token type = \"linear\"\n    int[] curveVertexCounts = [2]\n    \
                      point3f[] points = [(0, 0, 0), (0, 1, 0)]\n    float[] widths = [0.1] (interpolation = \"constant\")\n    \
                      bool primvars:arnold:visibility:shadow = 0\n}\n";
        let points = "def Points \"Dots\"\n{\n    point3f[] points = [(0, 0, 0)]\n    float[] widths = [0.1]\n    \
                      bool primvars:arnold:matte = 1 (interpolation = \"constant\")\n}\n";
        let text = [
            mesh("Hidden", "bool primvars:arnold:visibility:camera = 0 (interpolation = \"constant\")"),
            mesh("Shadowless", "uchar primvars:arnold:visibility = 253"),
            mesh("IntMask", "int primvars:arnold:visibility = 254"),
            mesh("IntFlag", "int primvars:arnold:visibility:shadow = 0"),
            mesh("Plain", ""),
            curves.to_string(),
            points.to_string(),
            "def Sphere \"Ball\"\n{\n    bool primvars:arnold:visibility:camera = false\n}\n".to_string(),
        ]
        .concat();
        let s = read_text(&stage(&text)).unwrap();
        let got: Vec<Visibility> = s.contents.meshes.iter().map(|m| m.visibility).collect();
        assert_eq!(
            got,
            [
                seen(false, true, false),
                seen(true, false, false),
                seen(false, true, false),
                seen(true, false, false),
                seen(true, true, false),
                seen(true, true, true),
                seen(false, true, false),
            ]
        );
        assert_eq!(s.contents.hair.len(), 1);
        assert_eq!(s.contents.hair[0].visibility, seen(true, false, false));
        assert!(!s.warnings.iter().any(|w| w.contains("visibility")), "{:?}", s.warnings);
    }

    #[test]
    fn single_ray_flags_win_over_the_packed_byte_and_usd_invisible_wins_over_all() {
        let (got, _) = meshes(
            &[
                // Arnold-USD #2385: casts no shadows (253), then hidden from the camera.
                mesh("Both", "bool primvars:arnold:visibility:camera = 0\n    uchar primvars:arnold:visibility = 253"),
                // #2345: the flag turns the camera bit the byte clears back on.
                mesh("Back", "uchar primvars:arnold:visibility = 254\n    bool primvars:arnold:visibility:camera = 1"),
                // #1613: USD's own visibility hides it whatever Arnold's say.
                mesh("Gone", "token visibility = \"invisible\"\n    bool primvars:arnold:visibility:camera = 1"),
                // Hidden from every ray: not drawn.
                mesh("None", "int primvars:arnold:visibility = 0"),
                // Cleared bits, then set back one by one.
                mesh("Zero", "uchar primvars:arnold:visibility = 0\n    bool primvars:arnold:visibility:shadow = 1"),
            ]
            .concat(),
        );
        assert_eq!(got, [seen(false, false, false), seen(true, true, false), seen(false, true, false)]);
    }

    #[test]
    fn constant_primvars_inherit_from_ancestors_the_nearest_winning() {
        let child = mesh("Own", "bool primvars:arnold:visibility:camera = 1");
        let packed = mesh("Packed", "uchar primvars:arnold:visibility = 255");
        let text = format!(
            "def Xform \"Group\"\n{{\n    bool primvars:arnold:visibility:camera = 0 (interpolation = \"constant\")\n    \
             bool primvars:arnold:matte = 1\n    bool primvars:arnold:visibility:shadow = 0 (interpolation = \"uniform\")\n\
             {}{child}{packed}}}\n",
            mesh("Inherits", "")
        );
        let (got, _) = meshes(&text);
        // The group's camera flag and matte reach every child; its uniform shadow flag does
        // not inherit; a child's own flag wins; a child's packed byte is overridden by the
        // inherited single flag, as Arnold applies flags after the byte.
        assert_eq!(got, [seen(false, true, true), seen(true, true, true), seen(false, true, true)]);
    }

    #[test]
    fn a_point_instancers_primvars_reach_its_prototypes_instances() {
        let text = format!(
            "def PointInstancer \"Matte\"\n{{\n    bool primvars:arnold:matte = 1 (interpolation = \"constant\")\n    \
             int[] protoIndices = [0, 0]\n    point3f[] positions = [(0, 0, 0), (2, 0, 0)]\n    \
             rel prototypes = </Matte/Protos/Tri>\n    def Scope \"Protos\"\n    {{\n{}    }}\n}}\n{}",
            mesh("Tri", "bool primvars:arnold:visibility:camera = 0"),
            mesh("Free", "")
        );
        let (got, _) = meshes(&text);
        assert_eq!(got, [seen(false, true, true), seen(false, true, true), seen(true, true, false)]);
    }

    #[test]
    fn rays_tress_cannot_hide_from_are_said_once_per_kind_naming_the_attribute() {
        let (got, warnings) = meshes(
            &[
                mesh("A", "bool primvars:arnold:visibility:diffuse_reflect = 0"),
                mesh("B", "bool primvars:arnold:visibility:diffuse_reflect = 0\n    bool primvars:arnold:visibility:volume = 0"),
                // Specular reflection only (Arnold's mesh lights in its test suite).
                mesh("C", "uchar primvars:arnold:visibility = 64"),
                // Cleared by the byte, set back by the flag: seen by diffuse rays after all.
                mesh("D", "uchar primvars:arnold:visibility = 223\n    bool primvars:arnold:visibility:diffuse_reflect = 1"),
            ]
            .concat(),
        );
        assert_eq!(
            got,
            [seen(true, true, false), seen(true, true, false), seen(false, false, false), seen(true, true, false)]
        );
        let about = |ray: &str| warnings.iter().filter(|w| w.contains(&format!("for {ray} rays"))).collect::<Vec<_>>();
        let diffuse = about("diffuse_reflect");
        assert_eq!(diffuse.len(), 1, "{warnings:?}");
        assert!(diffuse[0].contains("(3; first: /A: primvars:arnold:visibility:diffuse_reflect)"), "{}", diffuse[0]);
        for ray in ["diffuse_transmit", "specular_transmit"] {
            assert!(about(ray)[0].contains("(1; first: /C: primvars:arnold:visibility)"), "{warnings:?}");
        }
        // tress traces no volume, subsurface or (here) specular-reflection-only rays to hide from.
        assert!(about("volume").is_empty() && about("subsurface").is_empty() && about("specular_reflect").is_empty());
    }

    #[test]
    fn malformed_values_and_plain_attributes_are_named_and_left_out() {
        let (got, warnings) = meshes(
            &[
                mesh("Big", "int primvars:arnold:visibility = 300"),
                mesh("Text", "string primvars:arnold:visibility:camera = \"off\""),
                mesh("Real", "double primvars:arnold:matte = 1"),
                mesh("Plain", "bool arnold:visibility:camera = 0"),
            ]
            .concat(),
        );
        assert_eq!(got, [Visibility::default(); 4]);
        let joined = warnings.join("\n");
        assert!(
            joined.contains("not a byte (0 to 255): left out (1; first: /Big: primvars:arnold:visibility = 300)"),
            "{joined}"
        );
        assert!(
            joined.contains(
                "not a bool or an integer: left out (2; first: /Text: primvars:arnold:visibility:camera = String)"
            ),
            "{joined}"
        );
        assert!(
            joined.contains("not primvars: not read") && joined.contains("/Plain: arnold:visibility:camera"),
            "{joined}"
        );
    }

    #[test]
    fn time_sampled_bytes_are_held_at_the_frame() {
        let text = stage(&mesh("Late", "uchar primvars:arnold:visibility.timeSamples = { 1: 0, 3: 255 }"));
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("late.usda");
        std::fs::write(&path, text).unwrap();
        let at = |frame| read_usd(&path, &ImportOptions { frame: Some(frame), ..ImportOptions::default() }).unwrap();
        // Held at 0 until frame 3 (a blended 127 would hide it from the camera only).
        assert!(at(1).contents.meshes.is_empty() && at(2).contents.meshes.is_empty());
        assert_eq!(at(3).contents.meshes[0].visibility, Visibility::default());
    }
}
