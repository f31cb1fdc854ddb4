//! Environment maps in the integrators: the sky an escaping ray sees, and the two samples a
//! hit takes of a map, one by the map's distribution and one by the material's own
//! sampling, weighted by multiple importance sampling (power heuristic; Veach and Guibas
//! 1995, PBR 4th ed. section 2.2.3). A bright sun in a map is found by the first, a
//! glossy highlight of the map by the second.

use crate::light::{EnvironmentMap, Light, LightSample};
use crate::math::rng::PixelSampler;
use crate::math::sampling::power_heuristic;
use crate::math::Color;
use crate::shading::{Material, ShadingPoint};
use crate::world::World;
use glam::Vec3;

/// Radiance a ray along `dir` that meets nothing brings back: the constant environment,
/// plus every environment map times `map_weight(its density along dir)`, the MIS weight
/// of a ray drawn by a material (1 for camera and specular rays, which light sampling
/// cannot stand in for). A camera ray (`from_camera`) sees each environment times its
/// camera visibility ([`Light::camera_visibility`]); reflected, refracted and scattered
/// rays see it whole, so a sky hidden from the camera lights the scene unchanged.
pub(super) fn sky(world: &World, dir: Vec3, from_camera: bool, map_weight: impl Fn(f32) -> f32) -> Color {
    let mut sky = if from_camera { world.camera_background } else { world.background };
    for light in &world.lights {
        if let Light::EnvironmentMap(map) = light {
            let seen = if from_camera { map.camera_visibility() } else { 1.0 };
            sky += map.radiance(dir) * (map_weight(map.pdf(dir)) * seen);
        }
    }
    sky
}

/// The light an environment map sends to a hit, as up to two samples whose values (radiance
/// over density) carry their MIS weights: one drawn from the map, one from the material
/// ([`Material::sample_scatter`]). Multiplied by the material's response and the
/// visibility along each, their sum is an unbiased estimate of the reflected light.
pub(super) fn map_samples(
    map: &EnvironmentMap,
    material: &Material,
    sp: &ShadingPoint,
    wo: Vec3,
    sampler: &mut PixelSampler,
) -> [Option<LightSample>; 2] {
    let from_map = map.sample(sampler.next_2d()).map(|(dir, pdf, radiance)| {
        let w = power_heuristic(pdf, material.scatter_pdf(sp, wo, dir));
        LightSample { dir, dist: f32::INFINITY, value: radiance * (w / pdf) }
    });
    let from_material = material.sample_scatter(sp, wo, sampler).filter(|s| !s.is_specular()).map(|s| {
        let w = power_heuristic(s.pdf, map.pdf(s.dir));
        LightSample { dir: s.dir, dist: f32::INFINITY, value: map.radiance(s.dir) * (w / s.pdf) }
    });
    [from_map, from_material]
}
