//! Stages written by Blender's USD exporter, and where its conventions differ from what
//! UsdGeom and UsdLux (and Arnold, Storm) mean by the same attributes.
//!
//! The exporter names itself in the root layer's `doc` (`"Blender v5.0.1"`); only stages
//! so marked are read by the conventions below, every other stage as the schemas say.
//! Each is the inverse of what Blender's own USD importer does with the attribute, so a
//! marked stage renders as Blender rendered the scene it came from:
//!
//! - A sun's `inputs:intensity` is a quarter of its strength (irradiance, W/m²), and its
//!   `inputs:angle` half its angular diameter. Only lights the exporter also marked
//!   `inputs:normalize` are read so: that is how Blender writes lights since its
//!   exporter took the quarter (before, it wrote the strength itself, unnormalized).
//!   Point and area lights need nothing: their `intensity` is the power over π with
//!   `normalize` on, which is UsdLux's radiance of a Lambertian emitter of that power.
//! - A normalized light spreads its power over its area in square metres: Blender's
//!   importer scales a stage of another `metersPerUnit` into metres, so its lights' power
//!   stays what was written while their sizes and distances shrink or grow with the
//!   stage ([`square_metres_per_unit`]). (A stage left at `metersPerUnit = 1`, as the
//!   exporter writes one by default whatever the scene's unit scale, is read as it is,
//!   as Cycles renders the scene.)
//! - Curves without `widths` (Blender's particle hair is always written so) are
//!   [`CURVE_WIDTH`] wide: Blender's importer leaves such curves without a radius, and
//!   Blender draws them with its default radius.

use openusd::sdf;
use openusd::usd::Stage;

/// A sun's strength (irradiance) per unit of the `inputs:intensity` Blender writes.
pub const SUN_STRENGTH_PER_INTENSITY: f32 = 4.0;

/// A sun's angular diameter per unit of the `inputs:angle` Blender writes.
pub const SUN_DIAMETER_PER_ANGLE: f32 = 2.0;

/// The width of curves without `widths` in a Blender stage: twice Blender's default curve
/// radius, 0.01 (in the stage's units).
pub const CURVE_WIDTH: f32 = 0.02;

/// Whether Blender's exporter wrote `stage` (its root layer's `doc`, Sdf's `documentation`
/// field, says so).
pub fn wrote(stage: &Stage) -> bool {
    matches!(stage.stage_metadata("documentation"), Ok(Some(sdf::Value::String(doc))) if doc.starts_with("Blender v"))
}

/// The square metres of one square unit of `stage` (`metersPerUnit`², UsdGeom's fallback
/// of centimetres when not authored): what Blender measures a normalized light's area in.
pub fn square_metres_per_unit(stage: &Stage) -> f32 {
    let metres = match stage.stage_metadata("metersPerUnit") {
        Ok(Some(sdf::Value::Double(m))) => m,
        Ok(Some(sdf::Value::Float(m))) => f64::from(m),
        Ok(Some(sdf::Value::Int(m))) => f64::from(m),
        _ => 0.01,
    };
    match (metres * metres) as f32 {
        a if a.is_finite() && a > 0.0 => a,
        _ => 1.0,
    }
}
