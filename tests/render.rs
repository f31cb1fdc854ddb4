//! End-to-end renders of the demo scene and a fur scene: golden images with a tolerance,
//! bit-identical images whatever the thread count, and strand transparency.

use std::path::Path;
use tress::film::{srgb_encode, Film};
use tress::prepare::prepare;

/// A small demo render: 160x120, 4 samples, 6000 strands (the full scene's look, quickly).
fn small_demo(threads: usize) -> Film {
    let mut desc = tress::demo::description(6000, 1);
    desc.settings.width = 160;
    desc.settings.height = 120;
    desc.settings.spp = 4;
    let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
    pool.install(|| {
        let (world, _) = prepare(&desc).unwrap();
        tress::render::render(&world, None).0
    })
}

fn to_rgb8(film: &Film) -> Vec<u8> {
    film.pixels.iter().flat_map(|p| p.color.to_array().map(srgb_encode)).collect()
}

#[test]
fn same_image_with_one_and_two_threads() {
    let a = small_demo(1);
    let b = small_demo(2);
    // Compare bit patterns so NaN would also be caught.
    let bits = |f: &Film| f.pixels.iter().flat_map(|p| p.color.to_array().map(f32::to_bits)).collect::<Vec<_>>();
    assert_eq!(bits(&a), bits(&b));
    assert_eq!(a, b);
}

/// Compares a render with the reference `tests/data/NAME` (rewritten when `TRESS_BLESS`
/// is set). Tolerance: small per-pixel differences from floating-point changes are fine;
/// a shading, sampling or geometry change moves the mean or many pixels.
fn assert_matches_golden(film: &Film, name: &str) -> Vec<u8> {
    let got = to_rgb8(film);
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data").join(name);
    if std::env::var_os("TRESS_BLESS").is_some() {
        image::save_buffer(&path, &got, film.width, film.height, image::ColorType::Rgb8).unwrap();
    }
    let want = image::open(&path).expect("reference image (regenerate with TRESS_BLESS=1)").to_rgb8();
    assert_eq!((want.width(), want.height()), (film.width, film.height));
    let diffs: Vec<i32> = got.iter().zip(want.as_raw()).map(|(&a, &b)| (a as i32 - b as i32).abs()).collect();
    let mean = diffs.iter().sum::<i32>() as f64 / diffs.len() as f64;
    let large = diffs.iter().filter(|&&d| d > 16).count() as f64 / diffs.len() as f64;
    assert!(mean < 1.0 && large < 0.01, "mean difference {mean:.3}, {:.2} % of values differ by > 16", large * 100.0);
    got
}

#[test]
fn demo_matches_the_golden_image() {
    let film = small_demo(2);
    let got = assert_matches_golden(&film, "golden_demo.png");
    // The image is not trivially black or saturated: hair, torus and ground are all lit.
    let avg = got.iter().map(|&v| v as f64).sum::<f64>() / got.len() as f64;
    assert!(avg > 20.0 && avg < 200.0, "mean value {avg}");
    assert!(film.pixels.iter().any(|p| p.strand_id >= 0.0), "no hair visible");
}

/// A small fur scene: the Squirrel preset (clumping, scraggle, noise) with see-through
/// tips on a sphere, through the scene file, the generator and fur shading.
const FUR_SCENE: &str = r#"
[camera]
eye = [0.0, 1.2, 3.0]
target = [0.0, 0.0, 0.0]
[render]
resolution = [160, 120]
spp = 4
[[light]]
type = "distant"
direction = [0.4, 0.9, 0.6]
irradiance = [3.0, 3.0, 3.0]
[[light]]
type = "environment"
radiance = [0.4, 0.4, 0.45]
[[mesh]]
shape = { type = "sphere", radius = 0.8 }
material = { type = "diffuse", color = [0.07, 0.05, 0.04] }
[[fur]]
mesh = 1
preset = "Squirrel"
density = 20000
tip_opacity = 0.5
seed = 3
"#;

#[test]
fn fur_matches_the_golden_image_whatever_the_thread_count() {
    let desc = tress::io::scene_file::parse(FUR_SCENE, Path::new("fur.toml"), None).unwrap().0;
    let render = |threads| {
        let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
        pool.install(|| tress::render::render(&prepare(&desc).unwrap().0, None).0)
    };
    let film = render(2);
    assert_eq!(film, render(1));
    let got = assert_matches_golden(&film, "golden_fur.png");
    // Fur covers much of the frame and is lit: brownish grey, neither black nor white.
    let hair = film.pixels.iter().filter(|p| p.strand_id >= 0.0).count() as f64 / film.pixels.len() as f64;
    assert!(hair > 0.3, "fur covers {hair:.2} of the frame");
    let avg = got.iter().map(|&v| v as f64).sum::<f64>() / got.len() as f64;
    assert!(avg > 40.0 && avg < 200.0, "mean value {avg}");
}

/// A scene of black tube `strands` in front of a white environment, seen along -z from
/// z = 5 with a 10-degree field of view, rendered with `settings`.
fn black_strands_on_white(
    strands: tress::geometry::StrandSet,
    settings: tress::world::RenderSettings,
) -> tress::scene::Description {
    use glam::{Affine3A, Vec3};
    use tress::light::Light;
    use tress::math::Color;
    use tress::scene::{CameraDesc, Contents, Description, HairEntry, HairSource};
    use tress::shading::{tube::Tube, Material};
    let black = Tube { ambient: Color::ZERO, diffuse: Color::ZERO, specular: Color::ZERO, specular_power: 1.0 };
    Description {
        camera: CameraDesc {
            eye: Vec3::new(0.0, 0.0, 5.0),
            target: Vec3::ZERO,
            up: Vec3::Y,
            vfov: 10.0,
            ..Default::default()
        },
        settings,
        contents: Contents {
            lights: vec![Light::Environment { radiance: Color::ONE, camera_visibility: 1.0 }.into()],
            hair: vec![HairEntry {
                source: HairSource::Inline(strands),
                material: Material::Tube(black).into(),
                transform: Affine3A::IDENTITY,
                radius_scale: 1.0,
                file_colors: false,
                lod: None,
                visibility: Default::default(),
            }],
            ..Default::default()
        },
    }
}

/// Strands of opacity `a` in front of a uniform background let through `1 - a` of it on
/// average (stochastic transparency), and stacked strands multiply their transmittance.
#[test]
fn semi_transparent_strands_let_the_background_through() {
    use glam::Vec3;
    use tress::geometry::StrandSet;
    use tress::math::{rng::PixelSampler, Ray};
    use tress::render::Tracer;
    use tress::world::RenderSettings;
    let seen = |opacities: &[f32]| {
        let mut strands = StrandSet::new();
        for (i, _) in opacities.iter().enumerate() {
            // Thick black strands across the view axis, one behind the other.
            let z = -(i as f32);
            strands.push_strand([(Vec3::new(-1.0, 0.0, z), 0.2), (Vec3::new(1.0, 0.0, z), 0.2)]);
        }
        strands.opacity = Some(opacities.iter().flat_map(|&a| [a, a]).collect());
        let desc =
            black_strands_on_white(strands, RenderSettings { width: 8, height: 8, spp: 1, ..Default::default() });
        let world = prepare(&desc).unwrap().0;
        let n = 4096;
        let mut sum = 0.0;
        for i in 0..n {
            let mut sampler = PixelSampler::new(0, 3, 4, i);
            let ray = Ray::new(Vec3::new(0.0, 0.0, 5.0), -Vec3::Z);
            sum += Tracer::new(&world).trace_camera(&ray, &mut sampler).0.x;
        }
        sum / n as f32
    };
    assert_eq!(seen(&[1.0]), 0.0);
    for (opacities, expected) in [(&[0.25][..], 0.75), (&[0.5, 0.5], 0.25), (&[0.0, 0.9], 0.1)] {
        let got = seen(opacities);
        assert!((got - expected).abs() < 0.03, "{opacities:?}: {got} vs {expected}");
    }
}

#[test]
fn a_gaussian_filter_widens_edges_and_keeps_coverage() {
    use glam::Vec3;
    use tress::film::PixelFilter;
    use tress::geometry::StrandSet;
    use tress::world::RenderSettings;
    // A thick horizontal strand, about 5.5 pixels tall, across a 16x16 image.
    let render = |filter: PixelFilter| {
        let mut strands = StrandSet::new();
        strands.push_strand([(Vec3::new(-2.0, 0.01, 0.0), 0.15), (Vec3::new(2.0, 0.01, 0.0), 0.15)]);
        let desc = black_strands_on_white(
            strands,
            RenderSettings { width: 16, height: 16, spp: 256, filter, ..Default::default() },
        );
        tress::render::render(&prepare(&desc).unwrap().0, None).0
    };
    // Pixels of column 8 between all and nothing, and the column's summed coverage.
    let column = |f: &Film| {
        let c: Vec<f32> = (0..16).map(|y| f.pixels[y * 16 + 8].coverage).collect();
        (c.iter().filter(|&&c| c > 0.02 && c < 0.98).count(), c.iter().sum::<f32>())
    };
    let (box_edge, box_sum) = column(&render(PixelFilter::Box));
    let (gauss_edge, gauss_sum) = column(&render(PixelFilter::gaussian(1.5)));
    // A box pixel straddles each edge at most once; the Gaussian's samples reach 1.5
    // pixels out, so its transition spans at least two pixels per edge.
    assert!(box_edge <= 2, "box: {box_edge} partial pixels");
    assert!(gauss_edge >= 4, "gaussian: {gauss_edge} partial pixels");
    // Both reconstruct the same strand: the summed coverage is its height in pixels.
    assert!((box_sum - gauss_sum).abs() < 0.05 * box_sum, "{box_sum} vs {gauss_sum}");
}

/// Camera clipping: a near plane inside a sphere shows its far inside wall, a far plane
/// before it shows the background, and the depth channel stays the distance from the eye.
#[test]
fn camera_clip_planes_cut_what_the_camera_sees() {
    use std::path::Path;
    let scene = |clip: &str| {
        format!(
            "[camera]\neye = [0.0, 0.0, 5.0]\ntarget = [0.0, 0.0, 0.0]\nvfov = 5.0\n{clip}\n[render]\nresolution = [8, 8]\nspp = 1\n\
             [[light]]\ntype = \"environment\"\nradiance = [0.5, 0.5, 0.5]\n\
             [[mesh]]\nshape = {{ type = \"sphere\", radius = 1.0 }}\nmaterial = {{ type = \"diffuse\", color = [0.5, 0.5, 0.5] }}\n"
        )
    };
    let centre_depth = |clip: &str| {
        let desc = tress::io::scene_file::parse(&scene(clip), Path::new("clip.toml"), None).unwrap().0;
        let (world, _) = tress::prepare::prepare(&desc).unwrap();
        let film = tress::render::render(&world, None).0;
        let p = &film.pixels[4 * 8 + 4];
        (p.coverage > 0.5).then_some(p.depth)
    };
    let front = centre_depth("").expect("the sphere is seen");
    assert!((front - 4.0).abs() < 0.01, "{front}");
    let back = centre_depth("clip = [4.5, 100.0]").expect("the far wall is seen");
    assert!((back - 6.0).abs() < 0.01, "{back}");
    assert_eq!(centre_depth("clip = [0.1, 3.0]"), None);
    let err = tress::io::scene_file::parse(&scene("clip = [2.0, 1.0]"), Path::new("clip.toml"), None).unwrap_err();
    assert!(err.to_string().contains("clip.toml") && err.to_string().contains("`clip`"), "{err}");
}

/// `max_sample_value` scales every camera sample down to it (pbrt-v4's
/// `maxcomponentvalue`): with a small, very bright sphere light over the demo's hair, the
/// unclamped image has pixels far above the bound, the clamped one none (a pixel is the
/// mean of its samples), every pixel is at most as bright as unclamped, the image is the
/// same bit for bit with one and two threads, and a bound no sample reaches changes no bit.
#[test]
fn a_sample_clamp_bounds_every_sample_whatever_the_thread_count() {
    use tress::light::Light;
    use tress::math::Color;
    let render = |max_sample_value: f32, threads: usize| {
        let mut desc = tress::demo::description(2000, 1);
        let s = &mut desc.settings;
        (s.width, s.height, s.spp, s.max_sample_value) = (64, 48, 4, max_sample_value);
        let bulb = Light::Sphere {
            center: glam::Vec3::new(0.3, 0.6, 0.5),
            radius: 0.05,
            radiance: Color::splat(2e4),
            camera_visibility: 1.0,
        };
        desc.contents.lights.push(bulb.into());
        let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
        pool.install(|| tress::render::render(&prepare(&desc).unwrap().0, None).0)
    };
    let bits = |f: &Film| f.pixels.iter().flat_map(|p| p.color.to_array().map(f32::to_bits)).collect::<Vec<_>>();
    let max = 2.0;
    let (free, clamped) = (render(f32::INFINITY, 2), render(max, 1));
    let brightest = |f: &Film| f.pixels.iter().map(|p| p.color.max_element()).fold(0.0, f32::max);
    assert!(brightest(&free) > 100.0 * max, "the test needs a firefly-bright light: {}", brightest(&free));
    assert!(brightest(&clamped) <= max * (1.0 + 1e-6), "{}", brightest(&clamped));
    for (c, f) in clamped.pixels.iter().zip(&free.pixels) {
        assert!(c.color.cmple(f.color).all(), "{} over {}", c.color, f.color);
    }
    assert_eq!(bits(&clamped), bits(&render(max, 2)));
    assert_eq!(bits(&free), bits(&render(1e30, 1)));
}
