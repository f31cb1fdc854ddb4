//! The built-in demo scene: a torus covered in drooping, slightly curled hair over a grey
//! ground, lit by one distant light and a dim environment. It needs no file, so
//! `tress render` works on a fresh checkout.

use crate::geometry::{StrandSet, TriangleMesh};
use crate::light::Light;
use crate::math::rng::GenRng;
use crate::math::{sampling, Color};
use crate::scene::{
    CameraDesc, Contents, Description, HairEntry, HairSource, MeshEntry, MeshSource, DEFAULT_SKY_RADIANCE,
};
use crate::shading::{tube::Tube, Material};
use crate::world::RenderSettings;
use glam::{Affine3A, Vec3};
use rand::{Rng, SeedableRng};

/// Strands on the demo torus by default.
pub const DEMO_STRANDS: u32 = 60_000;

/// The demo scene with `strands` hairs, grown deterministically from `seed`.
pub fn description(strands: u32, seed: u64) -> Description {
    let torus = TriangleMesh::torus(1.0, 0.35, 96, 48);
    let hair = grow_hair(&torus, strands, seed);
    let diffuse = Color::new(0.35, 0.2, 0.1);
    Description {
        camera: CameraDesc {
            eye: Vec3::new(0.0, 1.6, 3.2),
            target: Vec3::new(0.0, -0.05, 0.0),
            up: Vec3::Y,
            vfov: 35.0,
            ..Default::default()
        },
        settings: RenderSettings::default(),
        contents: Contents {
            lights: vec![
                Light::Distant { direction: Vec3::new(0.45, 0.8, 0.4).normalize(), irradiance: Color::splat(3.0) }
                    .into(),
                Light::Environment { radiance: Color::splat(DEFAULT_SKY_RADIANCE), camera_visibility: 1.0 }.into(),
            ],
            meshes: vec![
                MeshEntry {
                    source: MeshSource::Inline(torus),
                    material: Material::Diffuse { color: Color::splat(0.5) }.into(),
                    transform: Affine3A::IDENTITY,
                    visibility: Default::default(),
                },
                MeshEntry {
                    source: MeshSource::Inline(TriangleMesh::plane(12.0)),
                    material: Material::Diffuse { color: Color::splat(0.5) }.into(),
                    transform: Affine3A::from_translation(Vec3::new(0.0, -0.62, 0.0)),
                    visibility: Default::default(),
                },
            ],
            hair: vec![HairEntry {
                source: HairSource::Inline(hair),
                material: Material::Tube(Tube { ambient: diffuse, diffuse, ..Tube::default() }).into(),
                transform: Affine3A::IDENTITY,
                radius_scale: 1.0,
                file_colors: true,
                lod: None,
                visibility: Default::default(),
            }],
            ..Default::default()
        },
    }
}

/// Grows `count` strands on `mesh`: roots uniform by area, 10 to 16 segments each,
/// leaving along the surface normal, drooping under gravity and curling slowly about a
/// per-strand axis, tapering from root to tip.
pub fn grow_hair(mesh: &TriangleMesh, count: u32, seed: u64) -> StrandSet {
    let mut rng = GenRng::seed_from_u64(seed);
    // Cumulative triangle areas: a root picks its triangle with probability by area.
    let mut cdf = Vec::with_capacity(mesh.indices.len());
    let mut total = 0.0f64;
    for i in 0..mesh.indices.len() as u32 {
        total += mesh.area(i) as f64;
        cdf.push(total);
    }
    let mut strands = StrandSet::new();
    const ROOT_RADIUS: f32 = 0.0015;
    const TIP_RADIUS: f32 = 0.0004;
    let gravity = Vec3::new(0.0, -1.0, 0.0);
    for _ in 0..count {
        let x = rng.random::<f64>() * total;
        let tri = cdf.partition_point(|&c| c < x).min(cdf.len() - 1) as u32;
        let (b1, b2) = sampling::triangle_fold(rng.random(), rng.random());
        let [a, b, c] = mesh.corners(tri);
        let root = a * (1.0 - b1 - b2) + b * b1 + c * b2;
        let normal = mesh.shading_normal(tri, b1, b2);
        let segments = rng.random_range(10..=16u32);
        let length = 0.22 * rng.random_range(0.8..1.2f32);
        let step = length / segments as f32;
        let jitter = Vec3::new(rng.random(), rng.random(), rng.random()) - 0.5;
        let mut dir = (normal + 0.5 * jitter).normalize();
        let curl_axis = sampling::uniform_sphere(rng.random(), rng.random());
        let mut p = root;
        let mut points = Vec::with_capacity(segments as usize + 1);
        for k in 0..=segments {
            let f = k as f32 / segments as f32;
            points.push((p, ROOT_RADIUS + (TIP_RADIUS - ROOT_RADIUS) * f));
            // Per segment, bend towards gravity and around the curl axis, in proportion to
            // the step so the shape does not depend on the segment count.
            let bend = 12.0 * step;
            dir = (dir + bend * (0.9 * gravity + 0.6 * curl_axis.cross(dir))).normalize();
            p += dir * step;
        }
        strands.push_strand(points);
    }
    strands
}
