//! Light transport end to end: the path tracer in a white furnace, the final gather
//! against the path tracer's one-bounce result, the path tracer against the direct
//! integrator where only direct light exists, shadows through hair of known opacity,
//! layers sharing a shadow ray lit as if each had its own,
//! fast multi-hit transparency against re-tracing after every hit, adaptive sampling on
//! edges, the same image for any thread count with every integrator, and unlit surfaces
//! seen as their colour and lighting their neighbours.

use glam::{Affine3A, Vec3};
use tress::film::Film;
use tress::geometry::{StrandSet, TriangleMesh};
use tress::light::Light;
use tress::math::Color;
use tress::prepare::prepare;
use tress::scene::{CameraDesc, Contents, Description, HairEntry, HairSource, MeshEntry, MeshSource};
use tress::shading::hair_bsdf::{Absorption, HairParams, PhysicalHair};
use tress::shading::Material;
use tress::world::{Adaptive, Integrator, IrradianceCacheSettings, RenderSettings};

fn render(desc: &Description, threads: usize) -> Film {
    let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
    pool.install(|| {
        let (world, _) = prepare(desc).unwrap();
        tress::render::render(&world, None).0
    })
}

fn mean(film: &Film) -> Vec3 {
    film.pixels.iter().map(|p| p.color).sum::<Vec3>() / film.pixels.len() as f32
}

fn mesh(mesh: TriangleMesh, material: Material, transform: Affine3A) -> MeshEntry {
    MeshEntry { source: MeshSource::Inline(mesh), material: material.into(), transform, visibility: Default::default() }
}

fn hair(strands: StrandSet, material: Material) -> HairEntry {
    HairEntry {
        source: HairSource::Inline(strands),
        material: material.into(),
        transform: Affine3A::IDENTITY,
        radius_scale: 1.0,
        file_colors: true,
        lod: None,
        visibility: Default::default(),
    }
}

fn settings(width: u32, height: u32, spp: u32, max_depth: u32, integrator: Integrator) -> RenderSettings {
    RenderSettings { width, height, spp, max_depth, integrator, ..Default::default() }
}

/// A ball of random strands of radius `r0` at the root to `r1` at the tip: light scatters
/// many times inside it.
fn hair_ball(count: u32, (r0, r1): (f32, f32)) -> StrandSet {
    let mut s = StrandSet::new();
    for i in 0..count {
        let h = |k: u32| tress::math::rng::unit_float(tress::math::rng::hash_combine(&[i, k]));
        let a = tress::math::sampling::uniform_sphere(h(0), h(1)) * 0.6;
        let b = tress::math::sampling::uniform_sphere(h(2), h(3)) * 0.6;
        s.push_strand([(a, r0), (a.lerp(b, 0.5) + Vec3::splat(0.05), 0.5 * (r0 + r1)), (b, r1)]);
    }
    s
}

fn white_hair(beta: f32) -> Material {
    Material::Physical(PhysicalHair::new(HairParams {
        absorption: Absorption::Color(Color::ONE),
        beta_m: beta,
        beta_n: beta,
        ..Default::default()
    }))
}

/// A camera on +z looking at the origin, which the furnace and lone-strand scenes frame.
fn front_camera() -> CameraDesc {
    CameraDesc { eye: Vec3::new(0.0, 0.0, 4.0), target: Vec3::ZERO, up: Vec3::Y, vfov: 40.0, ..Default::default() }
}

/// A diffuse albedo-1 sphere and a ball of hair of `material` (strand radii `radii` at the
/// root and the tip) in a uniform environment of radiance 1.
fn furnace(radii: (f32, f32), material: Material, settings: RenderSettings) -> Description {
    Description {
        camera: front_camera(),
        settings,
        contents: Contents {
            lights: vec![Light::Environment { radiance: Color::ONE, camera_visibility: 1.0 }.into()],
            meshes: vec![mesh(
                TriangleMesh::sphere(0.5, 48),
                Material::Diffuse { color: Color::ONE },
                Affine3A::from_translation(Vec3::new(-0.7, 0.0, 0.0)),
            )],
            hair: vec![hair(
                {
                    let mut b = hair_ball(300, radii);
                    b.transform(&Affine3A::from_translation(Vec3::new(0.7, 0.0, 0.0)));
                    b
                },
                material,
            )],
            ..Default::default()
        },
    }
}

/// The mean of the image and of its hair pixels.
fn furnace_means(film: &Film) -> (Vec3, f32) {
    let hair_pixels: Vec<f32> = film.pixels.iter().filter(|p| p.strand_id >= 0.0).map(|p| p.color.x).collect();
    assert!(hair_pixels.len() > 20, "the hair ball is seen: {}", hair_pixels.len());
    (mean(film), hair_pixels.iter().sum::<f32>() / hair_pixels.len() as f32)
}

#[test]
fn path_tracer_white_furnace() {
    // Diffuse albedo 1 sphere and a ball of non-absorbing hair in a uniform environment of
    // radiance 1: every pixel's expected value is 1, for strands of constant radius and
    // tapered ones (which rays leaving a strand must not hit again where they start).
    for radii in [(0.01, 0.01), (0.02, 0.004)] {
        let desc = furnace(radii, white_hair(0.3), settings(24, 24, 64, 64, Integrator::Path));
        let film = render(&desc, 2);
        let (m, hm) = furnace_means(&film);
        println!("furnace, radii {radii:?}: image mean {m}, hair pixels' mean {hm}");
        assert!((m - Vec3::ONE).abs().max_element() < 0.01, "image mean {m}");
        assert!((hm - 1.0).abs() < 0.01, "hair mean {hm}");
        // The sphere alone is exact for every sample (cosine sampling of an albedo-1 Lambertian).
        for p in film.pixels.iter().filter(|p| p.object_id == 0.0 && p.coverage == 1.0) {
            assert!((p.color - Vec3::ONE).abs().max_element() < 1e-4, "{}", p.color);
        }
    }
}

#[test]
fn regularized_path_tracer_white_furnace() {
    // Narrow non-absorbing hair whose lobes path regularization widens past the camera hit
    // still reflects all the light: the widened lobes conserve energy.
    let s = RenderSettings { indirect_hair_roughness: 0.6, ..settings(24, 24, 64, 64, Integrator::Path) };
    let film = render(&furnace((0.01, 0.01), white_hair(0.1), s), 2);
    let (m, hm) = furnace_means(&film);
    println!("regularized furnace: image mean {m}, hair pixels' mean {hm}");
    assert!((m - Vec3::ONE).abs().max_element() < 0.01, "image mean {m}");
    assert!((hm - 1.0).abs() < 0.01, "hair mean {hm}");
}

#[test]
fn hair_regularization_leaves_the_camera_hit_and_rough_hair_alone() {
    // Sunlit hair against a dim sky: the camera hit is never widened (with max_depth 0 the
    // image is the one without regularization, bit for bit), nor hair already as rough;
    // narrower hair past the camera hit is.
    let lit = |beta: f32, max_depth: u32, r: f32| {
        let s = RenderSettings { indirect_hair_roughness: r, ..settings(24, 24, 4, max_depth, Integrator::Path) };
        let mut desc = furnace((0.01, 0.01), white_hair(beta), s);
        desc.contents.lights = vec![
            Light::Environment { radiance: Color::splat(0.1), camera_visibility: 1.0 }.into(),
            Light::Sun {
                direction: Vec3::new(0.3, 1.0, 0.5).normalize(),
                radiance: Color::splat(1000.0),
                cos_max: 0.9995,
            }
            .into(),
        ];
        render(&desc, 2).pixels.iter().map(|p| p.color).collect::<Vec<_>>()
    };
    assert_eq!(lit(0.1, 0, 0.9), lit(0.1, 0, 0.0), "camera hit widened");
    assert_eq!(lit(0.4, 4, 0.3), lit(0.4, 4, 0.0), "rough hair widened");
    assert_ne!(lit(0.1, 4, 0.6), lit(0.1, 4, 0.0), "narrow hair past the camera hit not widened");
}

/// A diffuse ground and sphere under a quad light, a sphere light and the sun.
fn lit_scene(integrator: Integrator, spp: u32, max_depth: u32, environment: bool) -> Description {
    let mut lights = vec![
        Light::Quad {
            corner: Vec3::new(-0.5, 2.0, -0.5),
            edge_u: Vec3::new(1.0, 0.0, 0.0),
            edge_v: Vec3::new(0.0, 0.0, 1.0),
            radiance: Color::splat(4.0),
            camera_visibility: 1.0,
        },
        Light::Sphere {
            center: Vec3::new(1.5, 1.0, 1.0),
            radius: 0.3,
            radiance: Color::new(3.0, 2.0, 1.0),
            camera_visibility: 1.0,
        },
        Light::distant(Vec3::new(-0.5, 1.0, 0.3).normalize(), Color::splat(1.0), 0.1),
    ];
    if environment {
        lights.push(Light::Environment { radiance: Color::splat(0.3), camera_visibility: 1.0 });
    }
    Description {
        camera: CameraDesc {
            eye: Vec3::new(0.0, 1.5, 4.0),
            target: Vec3::ZERO,
            up: Vec3::Y,
            vfov: 40.0,
            ..Default::default()
        },
        settings: RenderSettings { gather_rays: 4, ..settings(32, 24, spp, max_depth, integrator) },
        contents: Contents {
            lights: lights.into_iter().map(Into::into).collect(),
            meshes: vec![
                mesh(TriangleMesh::plane(8.0), Material::Diffuse { color: Color::splat(0.9) }, Affine3A::IDENTITY),
                mesh(
                    TriangleMesh::sphere(0.6, 32),
                    Material::Diffuse { color: Color::new(0.8, 0.5, 0.3) },
                    Affine3A::from_translation(Vec3::new(0.0, 0.6, 0.0)),
                ),
            ],
            hair: vec![],
            ..Default::default()
        },
    }
}

#[test]
fn path_tracer_with_mis_agrees_with_direct_lighting() {
    // max_depth 0: the path tracer computes direct light only, combining light and
    // material samples; the direct integrator samples the lights alone.
    let direct = mean(&render(&lit_scene(Integrator::Direct, 256, 0, false), 2));
    let path = mean(&render(&lit_scene(Integrator::Path, 256, 0, false), 2));
    println!("direct {direct}, path {path}");
    assert!(((path - direct) / direct).abs().max_element() < 0.02, "direct {direct}, path {path}");
}

#[test]
fn final_gather_converges_to_one_bounce_path_tracing() {
    // No environment: the direct integrator (and so the final gather) lets the
    // environment shine through area lights, which the path tracer does not.
    let fg = mean(&render(&lit_scene(Integrator::FinalGather, 64, 5, false), 2));
    let path = mean(&render(&lit_scene(Integrator::Path, 512, 1, false), 2));
    let direct = mean(&render(&lit_scene(Integrator::Direct, 64, 5, false), 2));
    println!("final gather {fg}, path one bounce {path}, direct {direct}");
    assert!(((fg - path) / path).abs().max_element() < 0.004, "final gather {fg}, path {path}");
    // The gathered bounce is a real contribution, several times the tolerance.
    let gathered = (fg - direct).element_sum() / direct.element_sum();
    assert!(gathered > 0.02, "final gather {fg}, direct {direct}");
}

/// Horizontal strands side by side at height 1 over -2 < z < 0, `layers` crossed layers of
/// them, each of opacity `a`; a diffuse ground; the sun straight above.
fn shadow_scene(layers: u32, a: f32, integrator: Integrator) -> Description {
    let mut strands = StrandSet::new();
    let r = 0.01;
    for layer in 0..layers {
        let y = 1.0 + 3.0 * r * layer as f32;
        // Strands touching side by side: seen from above, they cover their area exactly.
        let count = if layer % 2 == 0 { 100 } else { 200 };
        for i in 0..count {
            let c = -2.0 + (2.0 * i as f32 + 1.0) * r;
            let (p, q) = if layer % 2 == 0 {
                (Vec3::new(-3.0, y, c), Vec3::new(3.0, y, c))
            } else {
                (Vec3::new(c, y, -2.0), Vec3::new(c, y, 0.0))
            };
            strands.push_strand([(p, r), (q, r)]);
        }
    }
    strands.opacity = Some(vec![a; strands.points.len()]);
    Description {
        // Looking along the ground from below the strands: only the ground is seen.
        camera: CameraDesc {
            eye: Vec3::new(0.0, 0.5, 3.0),
            target: Vec3::new(0.0, 0.0, 0.0),
            up: Vec3::Y,
            vfov: 60.0,
            ..Default::default()
        },
        settings: settings(32, 32, 4, 0, integrator),
        contents: Contents {
            lights: vec![Light::Distant { direction: Vec3::Y, irradiance: Color::ONE }.into()],
            meshes: vec![mesh(TriangleMesh::plane(20.0), Material::Diffuse { color: Color::ONE }, Affine3A::IDENTITY)],
            hair: vec![hair(strands, Material::Diffuse { color: Color::ONE })],
            ..Default::default()
        },
    }
}

#[test]
fn shadow_through_layers_of_hair_has_the_expected_transmittance() {
    for (layers, a) in [(1, 0.5), (2, 0.5), (2, 0.3), (3, 0.8)] {
        for integrator in [Integrator::Direct, Integrator::Path] {
            let (world, _) = prepare(&shadow_scene(layers, a, integrator)).unwrap();
            let mut tracer = tress::render::Tracer::new(&world);
            // The direct integrator estimates shadow transmittance stochastically (each
            // shadow ray passes or not): average many samples of one ray.
            const SAMPLES: u32 = 4096;
            let mut radiance = |target: Vec3| {
                let eye = Vec3::new(0.0, 0.5, 3.0);
                let ray = tress::math::Ray::new(eye, (target - eye).normalize());
                let sum: f32 = (0..SAMPLES)
                    .map(|i| {
                        let mut sampler = tress::math::rng::PixelSampler::new(0, 0, 0, i);
                        tracer.trace_camera(&ray, &mut sampler).0.x
                    })
                    .sum();
                sum / SAMPLES as f32
            };
            // Under the layers (between strand axes and on them) and in the open.
            let open = radiance(Vec3::new(0.0, 0.0, 1.0));
            for target in [Vec3::new(0.013, 0.0, -1.004), Vec3::new(0.204, 0.0, -0.507), Vec3::new(-0.31, 0.0, -1.4963)]
            {
                let shaded = radiance(target);
                let want = (1.0 - a).powi(layers as i32);
                // Four standard deviations of the mean of SAMPLES pass-or-block trials.
                let tolerance = 1e-3 + 4.0 * (want * (1.0 - want) / SAMPLES as f32).sqrt();
                assert!(
                    (shaded / open - want).abs() < tolerance,
                    "{layers} layers of opacity {a}, {integrator:?}: {} vs {want}",
                    shaded / open
                );
            }
        }
    }
}

/// The layers a camera ray shades share one shadow ray per light, picked in proportion to
/// their unshadowed light; on average each layer is still lit through its own shadow ray.
/// A ray through one layer of strands of opacity `a` onto the ground, lit from straight
/// above: the strands are in full light, the ground gets `1 - a` of it through them, so
/// the pixel averages `a C_strand + (1 - a)^2 C_ground` (blend weights `a` and `1 - a`).
#[test]
fn layers_sharing_a_shadow_ray_are_each_lit_through_their_own_on_average() {
    let eye = Vec3::new(0.3, 3.0, 1.0);
    // The ground point lies inside the shadow of one strand (axes 0.02 apart, radius 0.01).
    let ray = tress::math::Ray::new(eye, (Vec3::new(0.013, 0.0, -1.004) - eye).normalize());
    let radiance = |desc: &Description, samples: u32| -> Vec<f32> {
        let (world, _) = prepare(desc).unwrap();
        let mut tracer = tress::render::Tracer::new(&world);
        (0..samples)
            .map(|i| {
                let mut sampler = tress::math::rng::PixelSampler::new(0, 0, 0, i);
                tracer.trace_camera(&ray, &mut sampler).0.x
            })
            .collect()
    };
    let mut bare = shadow_scene(1, 0.5, Integrator::Direct);
    bare.contents.hair.clear();
    let ground = radiance(&bare, 1)[0];
    let strand = radiance(&shadow_scene(1, 1.0, Integrator::Direct), 1)[0];
    assert!(ground > 0.1 && strand > 0.1, "ground {ground}, strand {strand}");
    for a in [0.3, 0.5, 0.8] {
        const SAMPLES: u32 = 4096;
        let values = radiance(&shadow_scene(1, a, Integrator::Direct), SAMPLES);
        let mean = values.iter().sum::<f32>() / SAMPLES as f32;
        let variance = values.iter().map(|v| (v - mean) * (v - mean)).sum::<f32>() / (SAMPLES - 1) as f32;
        let want = a * strand + (1.0 - a) * (1.0 - a) * ground;
        // Four standard deviations of the mean.
        let tolerance = 1e-4 + 4.0 * (variance / SAMPLES as f32).sqrt();
        assert!((mean - want).abs() < tolerance, "opacity {a}: {mean} vs {want} (tolerance {tolerance})");
        // Lighting both layers through the front layer's shadow ray would be told apart.
        let front_only = a * strand + (1.0 - a) * ground;
        assert!((front_only - want).abs() > 3.0 * tolerance, "opacity {a}: the test cannot tell");
    }
}

/// The demo's hair made semi-transparent: opacity 0.6 at the root to 0.2 at the tip.
fn transparent_demo(strands: u32, k: u32, integrator: Integrator) -> Description {
    let mut desc = tress::demo::description(strands, 1);
    desc.settings.width = 96;
    desc.settings.height = 72;
    desc.settings.spp = 2;
    desc.settings.transparency_layers = k;
    desc.settings.integrator = integrator;
    desc.settings.gather_rays = 2;
    for h in &mut desc.contents.hair {
        let HairSource::Inline(s) = &mut h.source else { panic!("the demo's hair is inline") };
        let mut opacity = vec![0.0; s.points.len()];
        for w in s.offsets.windows(2) {
            let n = (w[1] - w[0]) as usize;
            for j in 0..n {
                opacity[w[0] as usize + j] = 0.6 - 0.4 * j as f32 / (n - 1).max(1) as f32;
            }
        }
        s.opacity = Some(opacity);
    }
    desc
}

#[test]
fn multi_hit_transparency_matches_retracing_after_every_hit() {
    let fast = render(&transparent_demo(3000, 8, Integrator::Direct), 2);
    let slow = render(&transparent_demo(3000, 1, Integrator::Direct), 2);
    let diffs: Vec<f32> =
        fast.pixels.iter().zip(&slow.pixels).map(|(a, b)| (a.color - b.color).abs().max_element()).collect();
    let mean_diff = diffs.iter().sum::<f32>() / diffs.len() as f32;
    let worst = diffs.iter().copied().fold(0.0, f32::max);
    println!("K = 8 vs K = 1: mean difference {mean_diff:.2e}, worst {worst:.2e}");
    assert!(mean_diff < 1e-3 && worst < 0.05, "mean {mean_diff}, worst {worst}");
    // The hair is seen through: some pixels blend hair over what is behind it.
    let opaque = render(&tress::demo::description(3000, 1), 2);
    assert_ne!(mean(&opaque), mean(&fast));
}

#[test]
fn every_integrator_gives_the_same_image_on_one_and_two_threads() {
    for integrator in [Integrator::Direct, Integrator::FinalGather, Integrator::Path] {
        let mut desc = transparent_demo(2000, 4, integrator);
        desc.settings.adaptive = Some(Adaptive { min_spp: 1, max_spp: 4, threshold: 0.05 });
        let (a, b) = (render(&desc, 1), render(&desc, 2));
        let bits = |f: &Film| f.pixels.iter().flat_map(|p| p.color.to_array().map(f32::to_bits)).collect::<Vec<_>>();
        assert_eq!(bits(&a), bits(&b), "{integrator:?}");
        assert_eq!(a, b, "{integrator:?}");
    }
}

#[test]
fn adaptive_sampling_refines_edges_and_strands() {
    let mut desc = tress::demo::description(3000, 1);
    desc.settings.width = 96;
    desc.settings.height = 72;
    desc.settings.adaptive = Some(Adaptive { min_spp: 2, max_spp: 32, threshold: 0.05 });
    let film = render(&desc, 2);
    let (w, h) = (film.width as usize, film.height as usize);
    let (mut edge, mut flat) = (Vec::new(), Vec::new());
    for y in 1..h - 1 {
        for x in 1..w - 1 {
            let p = &film.pixels[y * w + x];
            let id = |q: &tress::film::Pixel| (q.object_id, q.strand_id);
            let neighbours = [(x - 1, y), (x + 1, y), (x, y - 1), (x, y + 1)];
            let differs = neighbours.iter().any(|&(i, j)| id(&film.pixels[j * w + i]) != id(p));
            if differs || p.coverage > 0.0 && p.coverage < 1.0 {
                edge.push(p.samples);
            } else if p.coverage == 0.0 {
                flat.push(p.samples);
            }
        }
    }
    let avg = |v: &[f32]| v.iter().sum::<f32>() / v.len() as f32;
    println!(
        "samples: edges {:.1} ({} px), empty background {:.1} ({} px)",
        avg(&edge),
        edge.len(),
        avg(&flat),
        flat.len()
    );
    assert!(!edge.is_empty() && !flat.is_empty());
    assert!(flat.iter().all(|&s| s == 2.0), "the uniform background takes the minimum");
    assert!(avg(&edge) > 8.0, "edges take more samples: {}", avg(&edge));
    assert!(film.pixels.iter().all(|p| (2.0..=32.0).contains(&p.samples)));
}

fn render_with_stats(desc: &Description, threads: usize) -> (Film, tress::render::RenderStats) {
    let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
    pool.install(|| {
        let (world, _) = prepare(desc).unwrap();
        tress::render::render(&world, None)
    })
}

/// The lit scene for the final gather with and without the irradiance cache.
fn cached_scene(cache: bool, spp: u32) -> Description {
    let mut desc = lit_scene(Integrator::FinalGather, spp, 5, false);
    desc.settings.width = 64;
    desc.settings.height = 48;
    // Records 2 pixels apart at least: on an image this small, the default 4 would leave
    // a few dozen records for the whole floor.
    desc.settings.irradiance_cache = cache.then_some(IrradianceCacheSettings { accuracy: 0.3, spacing: 2, rays: 1024 });
    desc
}

#[test]
fn irradiance_cache_agrees_with_gathering_at_every_hit() {
    let (cached, stats) = render_with_stats(&cached_scene(true, 16), 2);
    let (gathered, gathered_stats) = render_with_stats(&cached_scene(false, 16), 2);
    let (reference, _) = render_with_stats(&cached_scene(false, 128), 2);
    let mut direct_desc = cached_scene(false, 128);
    direct_desc.settings.integrator = Integrator::Direct;
    let direct = mean(&render(&direct_desc, 2));
    // The indirect light (final gather less direct light) on average, and pixel by pixel.
    let (c, r) = (mean(&cached) - direct, mean(&reference) - direct);
    let rmse = |a: &Film| {
        let sum: f32 = a.pixels.iter().zip(&reference.pixels).map(|(p, q)| (p.color - q.color).length_squared()).sum();
        (sum / a.pixels.len() as f32).sqrt()
    };
    println!(
        "indirect: cached {c}, reference {r}; RMSE against the reference: cached {}, gathered at 16 spp {}; \
         {} records, rays {} vs {}",
        rmse(&cached),
        rmse(&gathered),
        stats.irradiance_records,
        stats.rays,
        gathered_stats.rays
    );
    // Interpolation blurs the indirect light a little; on average it stays within 5 %.
    assert!(((c - r) / r).abs().max_element() < 0.05, "cached indirect {c} vs {r}");
    // The cache is used: it holds records and saves gather rays.
    assert!(stats.irradiance_records > 10, "{} records", stats.irradiance_records);
    assert!(stats.rays < gathered_stats.rays, "{} rays vs {}", stats.rays, gathered_stats.rays);
}

#[test]
fn irradiance_cache_gives_the_same_image_on_one_and_two_threads() {
    let mut desc = cached_scene(true, 2);
    desc.settings.adaptive = Some(Adaptive { min_spp: 1, max_spp: 4, threshold: 0.05 });
    let (a, sa) = render_with_stats(&desc, 1);
    let (b, sb) = render_with_stats(&desc, 2);
    assert_eq!(sa.irradiance_records, sb.irradiance_records);
    assert!(sa.irradiance_records > 0);
    assert_eq!(a, b);
}

/// One straight strand of four segments along y, seen from the side: radius `r0` at the
/// root to `r1` at the tip.
fn lone_strand(r0: f32, r1: f32, material: Material, integrator: Integrator, max_depth: u32) -> Description {
    let mut strands = StrandSet::new();
    strands.push_strand((0..5).map(|i| {
        let f = i as f32 / 4.0;
        (Vec3::new(0.0, -1.0 + 2.0 * f, 0.0), r0 + (r1 - r0) * f)
    }));
    Description {
        camera: front_camera(),
        settings: RenderSettings { gather_rays: 4, ..settings(8, 8, 1, max_depth, integrator) },
        contents: Contents {
            lights: vec![Light::Environment { radiance: Color::ONE, camera_visibility: 1.0 }.into()],
            hair: vec![hair(strands, material)],
            ..Default::default()
        },
    }
}

/// The mean radiance of camera rays aimed across the strand of [`lone_strand`] at many
/// heights and offsets from its axis (each ray hits it, 16 samples each), and the standard
/// error of that mean.
fn lone_strand_radiance(desc: &Description, r0: f32, r1: f32) -> (Vec3, f32) {
    let (world, _) = prepare(desc).unwrap();
    let mut tracer = tress::render::Tracer::new(&world);
    let eye = desc.camera.eye;
    let mut values = Vec::new();
    for i in 0..64 {
        let y = -0.95 + 1.9 * (i as f32 + 0.5) / 64.0;
        let r = r0 + (r1 - r0) * (y + 1.0) / 2.0;
        for j in 0..32 {
            let x = r * 0.95 * (-1.0 + 2.0 * (j as f32 + 0.5) / 32.0);
            let ray = tress::math::Ray::new(eye, (Vec3::new(x, y, 0.0) - eye).normalize());
            for sample in 0..16 {
                let mut sampler = tress::math::rng::PixelSampler::new(0, i, j, sample);
                let (color, first) = tracer.trace_camera(&ray, &mut sampler);
                assert!(first.is_some_and(|f| f.strand == Some(0)), "the ray at {x} {y} hits the strand");
                values.push(color);
            }
        }
    }
    let n = values.len() as f32;
    let mean = values.iter().sum::<Vec3>() / n;
    let variance = values.iter().map(|v| (v.x - mean.x).powi(2)).sum::<f32>() / (n - 1.0);
    (mean, (variance / n).sqrt())
}

/// A lone diffuse strand of albedo `a` in a uniform environment of radiance 1 reflects
/// exactly `a` (it sees nothing but the sky): every integrator, tapered either way or not.
/// The direct integrator and the final gather are exact per sample (cosine sampling of a
/// Lambertian under constant light; gathered rays that reach the sky bring nothing) unless
/// a ray leaving the strand hits the strand again; the path tracer samples the sphere
/// around a strand of a non-hair material, so its tolerance is statistical.
#[test]
fn a_lone_diffuse_strand_in_a_uniform_sky_reflects_its_albedo() {
    let a = 0.5;
    for (r0, r1) in [(0.08, 0.02), (0.02, 0.08), (0.05, 0.05)] {
        for integrator in [Integrator::Path, Integrator::FinalGather, Integrator::Direct] {
            let desc = lone_strand(r0, r1, Material::Diffuse { color: Color::splat(a) }, integrator, 8);
            let (m, error) = lone_strand_radiance(&desc, r0, r1);
            println!("radius {r0} to {r1}, {integrator:?}: {m} (standard error {error})");
            let tolerance = 1e-3 + 4.0 * error;
            assert!(
                (m - Vec3::splat(a)).abs().max_element() < tolerance,
                "radius {r0} to {r1}, {integrator:?}: {m}, tolerance {tolerance}"
            );
        }
    }
}

/// Every integrator, the final gather with and without the irradiance cache.
fn every_integrator(spp: u32, max_depth: u32) -> Vec<RenderSettings> {
    let cache = IrradianceCacheSettings { accuracy: 0.3, spacing: 2, rays: 256 };
    [Integrator::Direct, Integrator::FinalGather, Integrator::Path]
        .into_iter()
        .map(|i| settings(32, 24, spp, max_depth, i))
        .chain([RenderSettings {
            irradiance_cache: Some(cache),
            ..settings(32, 24, spp, max_depth, Integrator::FinalGather)
        }])
        .collect()
}

#[test]
fn an_unlit_plane_is_its_colour_with_and_without_lights() {
    // A plane filling the view from above, its colour a radiance above 1 in red: every
    // pixel is that colour, in the dark and under a quad light, the sun and a sky alike.
    let color = Color::new(2.0, 0.3, 0.05);
    let lights = [
        Light::Quad {
            corner: Vec3::new(-0.5, 1.0, -0.5),
            edge_u: Vec3::new(1.0, 0.0, 0.0),
            edge_v: Vec3::new(0.0, 0.0, 1.0),
            radiance: Color::splat(4.0),
            camera_visibility: 1.0,
        },
        Light::distant(Vec3::new(-0.5, 1.0, 0.3).normalize(), Color::splat(3.0), 0.1),
        Light::Environment { radiance: Color::splat(0.5), camera_visibility: 1.0 },
    ];
    for lit in [false, true] {
        for settings in every_integrator(4, 5) {
            let desc = Description {
                camera: CameraDesc { eye: Vec3::new(0.0, 2.0, 0.0), up: Vec3::Z, vfov: 40.0, ..Default::default() },
                settings,
                contents: Contents {
                    lights: if lit { lights.iter().cloned().map(Into::into).collect() } else { vec![] },
                    meshes: vec![mesh(TriangleMesh::plane(8.0), Material::Unlit { color }, Affine3A::IDENTITY)],
                    ..Default::default()
                },
            };
            let film = render(&desc, 2);
            for p in &film.pixels {
                let what = format!("{:?}, lit {lit}", desc.settings.integrator);
                assert!((p.color - color).abs().max_element() < 1e-6, "{what}: {}", p.color);
            }
        }
    }
}

#[test]
fn a_rect_light_hidden_from_the_camera_lights_the_floor_the_same() {
    // A quad light of radiance 4 facing the camera, filling the image's centre, over a
    // diffuse floor it lights; nothing behind it. Camera visibility 1 shows it, 0 lets the
    // camera see through it to the black behind; the floor is lit alike either way.
    let scene = |camera_visibility: f32, settings: RenderSettings| Description {
        camera: CameraDesc {
            eye: Vec3::new(0.0, 0.7, 3.0),
            target: Vec3::new(0.0, 0.7, -1.0),
            up: Vec3::Y,
            vfov: 40.0,
            ..Default::default()
        },
        settings,
        contents: Contents {
            lights: vec![Light::Quad {
                corner: Vec3::new(-0.5, 0.3, -1.0),
                edge_u: Vec3::X,
                edge_v: Vec3::Y,
                radiance: Color::splat(4.0),
                camera_visibility,
            }
            .into()],
            meshes: vec![mesh(TriangleMesh::plane(8.0), Material::Diffuse { color: Color::ONE }, Affine3A::IDENTITY)],
            ..Default::default()
        },
    };
    for settings in every_integrator(4, 2) {
        let what = format!("{:?} {:?}", settings.integrator, settings.irradiance_cache);
        let (shown, hidden) = (render(&scene(1.0, settings.clone()), 2), render(&scene(0.0, settings), 2));
        let (w, h) = (shown.width as usize, shown.height as usize);
        let centre = (h / 2) * w + w / 2;
        assert!((shown.pixels[centre].color - Color::splat(4.0)).abs().max_element() < 1e-5, "{what}");
        assert_eq!(hidden.pixels[centre].color, Color::ZERO, "{what}");
        for x in 0..w {
            let (a, b) = (shown.pixels[(h - 1) * w + x].color, hidden.pixels[(h - 1) * w + x].color);
            assert!(a.min_element() > 0.01 && (a - b).abs().max_element() <= 1e-4 * a.max_element(), "{what}: {a} {b}");
        }
    }
}

/// A diffuse square of albedo `a` facing the camera inside a closed unlit sphere of
/// radiance `l`, with the sun and a bright sky outside, which the enclosure shuts out. (A
/// flat square: every direction above it reaches the enclosure, where rays leaving a
/// tessellated sphere by its interpolated normals may meet the sphere again.)
fn unlit_enclosure(a: Color, l: Color, settings: RenderSettings) -> Description {
    Description {
        camera: CameraDesc { eye: Vec3::new(0.0, 0.0, 1.5), vfov: 40.0, ..Default::default() },
        settings,
        contents: Contents {
            lights: vec![
                Light::distant(Vec3::new(0.3, 1.0, 0.5).normalize(), Color::splat(100.0), 0.1).into(),
                Light::Environment { radiance: Color::splat(5.0), camera_visibility: 1.0 }.into(),
            ],
            meshes: vec![
                mesh(
                    TriangleMesh::plane(1.0),
                    Material::Diffuse { color: a },
                    Affine3A::from_rotation_x(std::f32::consts::FRAC_PI_2),
                ),
                mesh(TriangleMesh::sphere(3.0, 48), Material::Unlit { color: l }, Affine3A::IDENTITY),
            ],
            ..Default::default()
        },
    }
}

#[test]
fn an_unlit_enclosure_lights_a_diffuse_square_inside_by_its_albedo_times_its_radiance() {
    // The light leaving the square is `a × l` (every direction above it sees the enclosure
    // at radiance `l`; the sun and the sky are shadowed): exactly so for every sample of
    // the path tracer and the final gather (cosine-weighted rays of weight `a`, each seeing
    // `l`), near it with the irradiance cache (records of `l`, extrapolated by their
    // gradients). The direct integrator lights nothing by an unlit surface.
    let (a, l) = (Color::new(0.8, 0.5, 0.2), Color::new(0.5, 1.0, 2.0));
    for settings in every_integrator(4, 3) {
        let (integrator, cached) = (settings.integrator, settings.irradiance_cache.is_some());
        let film = render(&unlit_enclosure(a, l, settings), 2);
        let (w, h) = (film.width as usize, film.height as usize);
        let object = |x: usize, y: usize| film.pixels[y * w + x].object_id;
        let (mut square, mut enclosure) = (0, 0);
        for y in 1..h - 1 {
            for x in 1..w - 1 {
                // Pixels whose neighbours see the same object: none of their samples sees the other.
                let id = object(x, y);
                if (y - 1..=y + 1).any(|j| (x - 1..=x + 1).any(|i| object(i, j) != id)) {
                    continue;
                }
                let c = film.pixels[y * w + x].color;
                let (want, tolerance) = match (id, integrator) {
                    (1.0, _) => (l, 1e-6),
                    (_, Integrator::Direct) => (Color::ZERO, 1e-6),
                    (_, Integrator::FinalGather) if cached => (a * l, 0.02),
                    _ => (a * l, 1e-5),
                };
                assert!((c - want).abs().max_element() <= tolerance, "{integrator:?} cached {cached}: {c} vs {want}");
                if id == 0.0 {
                    square += 1;
                } else {
                    enclosure += 1;
                }
            }
        }
        assert!(square > 50 && enclosure > 50, "{square} square and {enclosure} enclosure pixels");
    }
    // The same image on one and two threads.
    let desc = unlit_enclosure(a, l, settings(32, 24, 2, 3, Integrator::Path));
    assert_eq!(render(&desc, 1), render(&desc, 2));
}
