//! Secondary rays leave thin hair without hitting it again: no shadow acne on strands of
//! radius 1e-4 seen from 1e3 units away, nor on long, thin, nearly parallel segments.

use glam::{Affine3A, Vec3};
use tress::geometry::StrandSet;
use tress::light::Light;
use tress::math::rng::PixelSampler;
use tress::math::{Color, Ray};
use tress::prepare::prepare;
use tress::render::Tracer;
use tress::scene::{CameraDesc, Contents, Description, HairEntry, HairSource};
use tress::shading::{tube::Tube, Material};
use tress::world::{RenderSettings, World};

fn world(strands: StrandSet, material: Material, light_dir: Vec3, eye: Vec3) -> World {
    let desc = Description {
        camera: CameraDesc { eye, target: Vec3::ZERO, up: Vec3::Y, vfov: 1.0, ..Default::default() },
        settings: RenderSettings { width: 8, height: 8, spp: 1, max_depth: 0, ..Default::default() },
        contents: Contents {
            lights: vec![Light::Distant { direction: light_dir.normalize(), irradiance: Color::ONE }.into()],
            meshes: vec![],
            hair: vec![HairEntry {
                source: HairSource::Inline(strands),
                material: material.into(),
                transform: Affine3A::IDENTITY,
                radius_scale: 1.0,
                file_colors: false,
                lod: None,
                visibility: Default::default(),
            }],
            ..Default::default()
        },
    };
    prepare(&desc).unwrap().0
}

fn tube() -> Material {
    Material::Tube(Tube { ambient: Color::ZERO, diffuse: Color::ONE, specular: Color::ZERO, specular_power: 1.0 })
}

/// Shoots a fan of rays from `eye` across the strand near `target` and checks every hit is
/// lit exactly as an unshadowed point (the scene holds nothing that could shadow it).
fn assert_no_acne(world: &World, eye: Vec3, target: Vec3, spread: Vec3, expected: impl Fn(Vec3, Vec3) -> f32) {
    let (mut hits, mut dark) = (0, 0);
    for i in 0..2000 {
        let offset = spread * ((i as f32 + 0.5) / 2000.0 - 0.5);
        let ray = Ray::new(eye, (target + offset - eye).normalize());
        let Some(hit) = world.accel.intersect(&ray) else { continue };
        let mut sampler = PixelSampler::new(0, i, 0, 0);
        let (color, _) = Tracer::new(world).trace_camera(&ray, &mut sampler);
        let tress::accel::HitKind::Segment { normal, .. } = hit.kind else { panic!() };
        let want = expected(normal, ray.dir);
        hits += 1;
        if (color.x - want).abs() > 1e-3 * want.max(1e-3) {
            dark += 1;
        }
    }
    assert!(hits > 100, "too few hits to judge: {hits}");
    assert_eq!(dark, 0, "{dark} of {hits} hits are shadowed by the strand itself");
}

#[test]
fn tiny_strand_seen_from_far_away_has_no_self_shadow() {
    let mut strands = StrandSet::new();
    strands.push_strand([(Vec3::new(-0.01, 0.0, 0.0), 1e-4), (Vec3::ZERO, 1e-4), (Vec3::new(0.01, 0.0, 0.0), 1e-4)]);
    let eye = Vec3::new(0.0, 300.0, 950.0);
    let light = Vec3::new(0.3, 1.0, 0.2);
    let l = light.normalize();
    let spread = Vec3::new(0.0, -2.2e-4 * 0.95, 2.2e-4 * 0.3);
    // Tube shading: sin(T, L) / pi everywhere on the strand.
    let w = world(strands.clone(), tube(), light, eye);
    let sin_tl = (1.0 - l.x * l.x).sqrt();
    assert_no_acne(&w, eye, Vec3::new(0.003, 0.0, 0.0), spread, |_, _| sin_tl / std::f32::consts::PI);
    // Lambert on the true cylinder normal: lit wherever the normal faces the light.
    let w = world(strands, Material::Diffuse { color: Color::ONE }, light, eye);
    assert_no_acne(&w, eye, Vec3::new(0.003, 0.0, 0.0), spread, |n, _| n.dot(l).max(0.0) / std::f32::consts::PI);
}

#[test]
fn long_nearly_parallel_segments_do_not_shadow_each_other() {
    // Fifty 10-unit segments with 1e-3 radius, bending by a few thousandths of a radian.
    let mut strands = StrandSet::new();
    let mut p = Vec3::new(-250.0, 0.0, 0.0);
    let mut pts = vec![(p, 1e-3)];
    for k in 0..50 {
        let bend = if k % 2 == 0 { 0.003 } else { -0.003 };
        p += Vec3::new(10.0, 10.0 * bend, 0.0);
        pts.push((p, 1e-3));
    }
    strands.push_strand(pts);
    // A grazing light, almost along the strand.
    let light = Vec3::new(1.0, 0.05, 0.02);
    let l = light.normalize();
    let eye = Vec3::new(0.0, 2.0, 40.0);
    let w = world(strands.clone(), Material::Diffuse { color: Color::ONE }, light, eye);
    for x in [-45.0f32, -5.0, 0.0, 5.0, 35.0] {
        // Aim at the joints and the middles of segments (the strand zigzags around y ~ 0).
        let k = strands.points.iter().rposition(|p| p[0] <= x).unwrap();
        let (a, b) = (strands.points[k], strands.points[k + 1]);
        let y = a[1] + (b[1] - a[1]) * (x - a[0]) / (b[0] - a[0]);
        let spread = Vec3::new(0.0, 4e-3, 0.0);
        assert_no_acne(&w, eye, Vec3::new(x, y, 0.0), spread, |n, _| n.dot(l).max(0.0) / std::f32::consts::PI);
    }
    let w = world(strands.clone(), tube(), light, eye);
    // With tube shading the response is sin(T, L) with the interpolated tangent: only check
    // that nothing is darkened to zero, since T varies slightly along the zigzag.
    let joint = strands.position(25);
    let ray = Ray::new(eye, (joint - eye).normalize());
    let (c, first) = Tracer::new(&w).trace_camera(&ray, &mut PixelSampler::new(0, 0, 0, 0));
    assert!(first.is_some() && c.x > 0.9 * (1.0 - l.x * l.x).sqrt() / std::f32::consts::PI, "{c}");
}
