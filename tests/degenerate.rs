//! Valid but degenerate geometry renders, or is skipped with a warning: zero-length
//! segments, zero radii, coincident points, a million points on one strand, enormous
//! coordinates, and numbers a transform pushes past the float range (NaN or infinity
//! must never reach the BVH).

use glam::{Affine3A, Vec3};
use tress::film::Film;
use tress::geometry::{StrandSet, TriangleMesh};
use tress::light::Light;
use tress::math::Color;
use tress::prepare::prepare;
use tress::scene::{CameraDesc, Contents, Description, HairEntry, HairSource, MeshEntry, MeshSource};
use tress::shading::{tube::Tube, Material};
use tress::world::RenderSettings;

fn describe(hair: Vec<(StrandSet, Affine3A)>, meshes: Vec<(TriangleMesh, Affine3A)>, eye: Vec3) -> Description {
    let tube = Material::Tube(Tube {
        ambient: Color::splat(0.1),
        diffuse: Color::splat(0.6),
        specular: Color::splat(0.3),
        specular_power: 20.0,
    });
    Description {
        camera: CameraDesc { eye, target: Vec3::ZERO, up: Vec3::Y, vfov: 40.0, ..Default::default() },
        settings: RenderSettings { width: 48, height: 36, spp: 2, ..Default::default() },
        contents: Contents {
            lights: vec![
                Light::Distant { direction: Vec3::new(0.3, 1.0, 0.5).normalize(), irradiance: Color::ONE }.into(),
                Light::Environment { radiance: Color::splat(0.2), camera_visibility: 1.0 }.into(),
            ],
            meshes: meshes
                .into_iter()
                .map(|(m, transform)| MeshEntry {
                    source: MeshSource::Inline(m),
                    material: Material::Diffuse { color: Color::splat(0.5) }.into(),
                    transform,
                    visibility: Default::default(),
                })
                .collect(),
            hair: hair
                .into_iter()
                .map(|(s, transform)| HairEntry {
                    source: HairSource::Inline(s),
                    material: tube.clone().into(),
                    transform,
                    radius_scale: 1.0,
                    file_colors: true,
                    lod: None,
                    visibility: Default::default(),
                })
                .collect(),
            ..Default::default()
        },
    }
}

/// Renders and checks every pixel is finite; returns the film and the warnings.
fn render(desc: &Description) -> (Film, Vec<String>) {
    let (world, _) = prepare(desc).unwrap();
    let (film, _) = tress::render::render(&world, None);
    for (i, p) in film.pixels.iter().enumerate() {
        assert!(p.color.is_finite() && p.coverage.is_finite(), "pixel {i} is not finite: {p:?}");
        assert!(p.normal.is_finite() && !p.depth.is_nan(), "pixel {i} AOVs: {p:?}");
    }
    (film, world.warnings.clone())
}

/// A plain visible strand across the middle of the view, to show the rest still renders.
fn witness() -> StrandSet {
    let mut s = StrandSet::new();
    s.push_strand((0..10).map(|i| (Vec3::new(i as f32 * 0.2 - 0.9, 0.0, 0.0), 0.03)));
    s
}

fn hits(film: &Film) -> usize {
    film.pixels.iter().filter(|p| p.strand_id >= 0.0).count()
}

#[test]
fn zero_length_segments_zero_radii_and_coincident_points_render() {
    let mut s = witness();
    s.push_strand([(Vec3::Y * 0.3, 0.05); 4]); // every point coincident
    s.push_strand([(Vec3::new(0.0, -0.3, 0.0), 0.0), (Vec3::new(0.5, -0.3, 0.0), 0.0)]); // zero radius
    s.push_strand([
        (Vec3::new(-0.5, 0.4, 0.0), 0.04),
        (Vec3::new(-0.5, 0.4, 0.0), 0.04),
        (Vec3::new(0.5, 0.6, 0.0), 0.04),
    ]);
    s.push_strand([(Vec3::new(0.2, 0.2, 0.0), 0.02)]); // a single point: no segment
    let (film, warnings) = render(&describe(vec![(s, Affine3A::IDENTITY)], vec![], Vec3::new(0.0, 0.0, 3.0)));
    assert!(warnings.is_empty(), "{warnings:?}");
    assert!(hits(&film) > 20, "the strands are visible: {} hair pixels", hits(&film));
    // A zero-radius strand alone is invisible, not an error.
    let mut thin = StrandSet::new();
    thin.push_strand([(Vec3::new(-1.0, 0.0, 0.0), 0.0), (Vec3::new(1.0, 0.0, 0.0), 0.0)]);
    let (film, _) = render(&describe(vec![(thin, Affine3A::IDENTITY)], vec![], Vec3::new(0.0, 0.0, 3.0)));
    assert_eq!(hits(&film), 0);
}

#[test]
fn a_million_points_on_one_strand_render() {
    let mut s = StrandSet::new();
    let n = 1_000_000;
    // A tight helix: a million tiny segments.
    s.push_strand((0..n).map(|i| {
        let t = i as f32 / n as f32;
        let a = t * 400.0;
        (Vec3::new(t * 2.0 - 1.0, 0.1 * a.sin(), 0.1 * a.cos()), 0.01)
    }));
    let (film, warnings) = render(&describe(vec![(s, Affine3A::IDENTITY)], vec![], Vec3::new(0.0, 0.0, 3.0)));
    assert!(warnings.is_empty());
    assert!(hits(&film) > 30, "{} hair pixels", hits(&film));
}

/// The hair and ground of the witness scene scaled by `scale`, seen from as far.
fn scaled(scale: f32) -> Description {
    let mut s = StrandSet::new();
    s.push_strand((0..10).map(|i| (Vec3::new(i as f32 * 0.2 - 0.9, 0.0, 0.0) * scale, 0.05 * scale)));
    let mut mesh = TriangleMesh::plane(2.0 * scale);
    mesh.transform(&Affine3A::from_translation(Vec3::new(0.0, -0.5 * scale, 0.0)));
    describe(vec![(s, Affine3A::IDENTITY)], vec![(mesh, Affine3A::IDENTITY)], Vec3::new(0.0, 0.3, 3.0) * scale)
}

#[test]
fn enormous_coordinates_render_up_to_the_limit_and_are_skipped_past_it() {
    let reference = render(&scaled(1.0)).0;
    // Up to MAX_COORDINATE the image is the same scene at another scale: the same pixels
    // are hair and ground.
    for scale in [1e6, tress::geometry::MAX_COORDINATE / 3.0] {
        let (film, warnings) = render(&scaled(scale));
        assert!(warnings.is_empty(), "{warnings:?}");
        let differ = film.pixels.iter().zip(&reference.pixels).filter(|(a, b)| a.object_id != b.object_id).count();
        assert!(differ <= 3, "at scale {scale:e}, {differ} pixels see another object");
        assert!(hits(&film) > 10, "at scale {scale:e}: {} hair pixels", hits(&film));
    }
    // Past it, where products of lengths would overflow, the geometry is skipped and said so.
    let (film, warnings) = render(&scaled(1e30));
    assert_eq!(warnings.len(), 2, "{warnings:?}");
    assert!(warnings.iter().all(|w| w.contains("beyond ±1e10")), "{warnings:?}");
    assert_eq!(hits(&film), 0);
}

#[test]
fn numbers_pushed_past_the_float_range_are_skipped_with_a_warning() {
    // A transform scales one strand set to infinity; a generator left a NaN in another.
    let mut huge = StrandSet::new();
    huge.push_strand([(Vec3::new(1e30, 0.0, 0.0), 0.1), (Vec3::new(2e30, 0.0, 0.0), 0.1)]);
    huge.push_strand([(Vec3::ZERO, 0.1), (Vec3::X * 0.1, 0.1)]);
    let mut nan = witness();
    nan.push_strand([(Vec3::ZERO, f32::NAN), (Vec3::Y, 0.1)]);
    let mut mesh = TriangleMesh::plane(1.0);
    mesh.positions[0].x = f32::INFINITY;
    let desc = describe(
        vec![(huge, Affine3A::from_scale(Vec3::splat(1e10))), (nan, Affine3A::IDENTITY)],
        vec![(mesh, Affine3A::IDENTITY)],
        Vec3::new(0.0, 0.0, 3.0),
    );
    let (film, warnings) = render(&desc);
    assert_eq!(warnings.len(), 3, "{warnings:?}");
    assert!(warnings.iter().all(|w| w.contains("not finite")), "{warnings:?}");
    assert!(warnings[0].starts_with("mesh 1: skipped") && warnings[0].contains("triangles"), "{warnings:?}");
    assert!(warnings[1].starts_with("hair 1: skipped 1 strands"), "{warnings:?}");
    assert!(warnings[2].starts_with("hair 2: skipped 1 strands"), "{warnings:?}");
    assert!(hits(&film) > 20, "the usable strands still render");
    let (world, _) = prepare(&desc).unwrap();
    let b = world.accel.bounds();
    assert!(b.min.is_finite() && b.max.is_finite(), "the BVH bounds are finite: {b:?}");
}
