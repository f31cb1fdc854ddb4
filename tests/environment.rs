//! Environment maps end to end: a map of constant value lights a scene as the constant
//! environment does with every integrator; a convex diffuse body in a white map reflects
//! its albedo; rotation turns the map where the documented frame says; scene files load
//! maps from disk and name the file when it is unusable.

use glam::{Affine3A, Vec3};
use tress::film::Film;
use tress::geometry::{StrandSet, TriangleMesh};
use tress::light::{EnvironmentMap, Light};
use tress::math::Color;
use tress::prepare::prepare;
use tress::scene::{CameraDesc, Contents, Description, HairEntry, HairSource, MeshEntry, MeshSource};
use tress::shading::hair_bsdf::{Absorption, HairParams, PhysicalHair};
use tress::shading::Material;
use tress::world::{Integrator, RenderSettings};

fn render(desc: &Description) -> Film {
    let (world, _) = prepare(desc).unwrap();
    tress::render::render(&world, None).0
}

/// A constant map: every pixel `value`.
fn constant_map(value: f32) -> Light {
    let (w, h) = (32u32, 16u32);
    Light::EnvironmentMap(EnvironmentMap::from_pixels(w, h, &vec![value; (w * h * 3) as usize], 0.0, 1.0).unwrap())
}

/// A diffuse torus with physical brown hair on a diffuse ground, seen from above.
fn scene(light: Light, integrator: Integrator, spp: u32) -> Description {
    let mut hair = StrandSet::new();
    for i in 0..400u32 {
        let h = |k: u32| tress::math::rng::unit_float(tress::math::rng::hash_combine(&[i, k]));
        let root = Vec3::new(h(0) * 1.6 - 0.8, 0.0, h(1) * 1.2 - 0.6);
        let tip = root + Vec3::new(h(2) - 0.5, 0.8, h(3) - 0.5) * 0.5;
        hair.push_strand([(root, 0.008), (root.lerp(tip, 0.5) + Vec3::X * 0.03, 0.006), (tip, 0.002)]);
    }
    let physical = Material::Physical(PhysicalHair::new(HairParams {
        absorption: Absorption::Melanin { eumelanin: 0.8, pheomelanin: 0.1 },
        ..Default::default()
    }));
    Description {
        camera: CameraDesc {
            eye: Vec3::new(0.0, 2.5, 2.5),
            target: Vec3::new(0.0, 0.2, 0.0),
            up: Vec3::Y,
            vfov: 40.0,
            ..Default::default()
        },
        settings: RenderSettings { width: 48, height: 36, spp, integrator, max_depth: 2, ..Default::default() },
        contents: Contents {
            lights: vec![light.into()],
            meshes: vec![
                MeshEntry {
                    source: MeshSource::Inline(TriangleMesh::torus(0.6, 0.2, 32, 16)),
                    material: Material::Diffuse { color: Color::new(0.6, 0.4, 0.3) }.into(),
                    transform: Affine3A::from_translation(Vec3::Y * 0.2),
                    visibility: Default::default(),
                },
                MeshEntry {
                    source: MeshSource::Inline(TriangleMesh::plane(6.0)),
                    material: Material::Diffuse { color: Color::splat(0.5) }.into(),
                    transform: Affine3A::IDENTITY,
                    visibility: Default::default(),
                },
            ],
            hair: vec![HairEntry {
                source: HairSource::Inline(hair),
                material: physical.into(),
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

/// Means of 6x6-pixel blocks: what two noisy renders of one image agree on.
fn blocks(film: &Film) -> Vec<Vec3> {
    let (w, h) = (film.width as usize, film.height as usize);
    let mut out = Vec::new();
    for by in (0..h).step_by(6) {
        for bx in (0..w).step_by(6) {
            let mut sum = Vec3::ZERO;
            for y in by..by + 6 {
                for x in bx..bx + 6 {
                    sum += film.pixels[y * w + x].color;
                }
            }
            out.push(sum / 36.0);
        }
    }
    out
}

/// The constant environment and a map of the same constant value light the scene alike
/// (hair, surfaces, shadowing, the background) with every integrator, within noise.
#[test]
fn a_constant_map_renders_as_the_constant_environment() {
    for integrator in [Integrator::Direct, Integrator::FinalGather, Integrator::Path] {
        let spp = if integrator == Integrator::Direct { 64 } else { 32 };
        let constant =
            render(&scene(Light::Environment { radiance: Color::splat(0.8), camera_visibility: 1.0 }, integrator, spp));
        let map = render(&scene(constant_map(0.8), integrator, spp));
        let (a, b) = (blocks(&constant), blocks(&map));
        let mean = |v: &[Vec3]| v.iter().sum::<Vec3>() / v.len() as f32;
        let (ma, mb) = (mean(&a), mean(&b));
        assert!((ma - mb).abs().max_element() < 0.015 * ma.max_element(), "{integrator:?}: mean {ma} vs {mb}");
        let worst = a
            .iter()
            .zip(&b)
            .map(|(x, y)| (*x - *y).abs().max_element() / x.max_element().max(0.05))
            .fold(0.0, f32::max);
        assert!(worst < 0.08, "{integrator:?}: a block differs by {:.1} %", worst * 100.0);
    }
}

/// A map brighter towards +y, seen by camera rays with weight `camera`.
fn sky_map(camera: f32) -> Light {
    let (w, h) = (32u32, 16u32);
    let rgb: Vec<f32> = (0..w * h * 3).map(|i| 0.2 + 2.0 * (h - i / 3 / w) as f32 / h as f32).collect();
    let placement = tress::light::MapPlacement::new(30.0, 1.0).seen_by_camera(camera);
    Light::EnvironmentMap(EnvironmentMap::placed(w, h, &rgb, placement).unwrap())
}

/// Environments hidden from the camera (`camera_visibility` 0, Arnold's `camera` 0) are a
/// black background and light the scene exactly as visible ones, with every integrator:
/// every pixel all of whose samples hit geometry is bit for bit the same, the coverage
/// (alpha) is the same, and a pixel of background only is black, or exactly half as
/// bright at visibility one half.
#[test]
fn environments_hidden_from_the_camera_are_black_behind_and_light_alike() {
    for integrator in [Integrator::Direct, Integrator::FinalGather, Integrator::Path] {
        let film = |camera_visibility| {
            let mut desc = scene(Light::Environment { radiance: Color::splat(0.3), camera_visibility }, integrator, 4);
            desc.contents.lights.push(sky_map(camera_visibility).into());
            render(&desc)
        };
        let (seen, hidden, half) = (film(1.0), film(0.0), film(0.5));
        let (mut hit, mut sky) = (0, 0);
        for ((s, h), q) in seen.pixels.iter().zip(&hidden.pixels).zip(&half.pixels) {
            assert_eq!(s.coverage, h.coverage);
            if s.coverage == 1.0 {
                hit += 1;
                assert_eq!(
                    s.color.to_array().map(f32::to_bits),
                    h.color.to_array().map(f32::to_bits),
                    "{integrator:?}"
                );
            } else if s.coverage == 0.0 {
                sky += 1;
                assert!(s.color.min_element() > 0.2, "{integrator:?}: {}", s.color);
                assert_eq!(h.color, Vec3::ZERO, "{integrator:?}");
                assert_eq!(q.color, 0.5 * s.color, "{integrator:?}");
            } else {
                assert!(h.color.cmple(s.color).all(), "{integrator:?}: {} over {}", h.color, s.color);
            }
        }
        assert!(hit > 1000 && sky > 30, "{integrator:?}: {hit} lit, {sky} background pixels");
    }
}

/// A convex diffuse sphere of albedo 0.5 in a white map reflects exactly half the light:
/// every pixel on it is 0.5, with light sampling and material sampling weighed by MIS.
#[test]
fn a_white_map_lights_a_convex_diffuse_body_to_its_albedo() {
    for integrator in [Integrator::Direct, Integrator::Path] {
        let desc = Description {
            camera: CameraDesc {
                eye: Vec3::new(0.0, 0.0, 3.0),
                target: Vec3::ZERO,
                up: Vec3::Y,
                vfov: 20.0,
                ..Default::default()
            },
            settings: RenderSettings { width: 16, height: 16, spp: 64, integrator, max_depth: 4, ..Default::default() },
            contents: Contents {
                lights: vec![constant_map(1.0).into()],
                meshes: vec![MeshEntry {
                    source: MeshSource::Inline(TriangleMesh::sphere(0.6, 48)),
                    material: Material::Diffuse { color: Color::splat(0.5) }.into(),
                    transform: Affine3A::IDENTITY,
                    visibility: Default::default(),
                }],
                ..Default::default()
            },
        };
        let film = render(&desc);
        let centre: Vec<f32> =
            (5..11).flat_map(|y| (5..11).map(move |x| (x, y))).map(|(x, y)| film.pixels[y * 16 + x].color.x).collect();
        let mean = centre.iter().sum::<f32>() / centre.len() as f32;
        assert!((mean - 0.5).abs() < 0.01, "{integrator:?}: {mean}");
    }
}

/// Writes a PFM map, black but for a bright spot at the centre column, halfway up.
fn write_spot_map(path: &std::path::Path) {
    let (w, h) = (64usize, 32usize);
    let mut bytes = format!("PF\n{w} {h}\n-1.0\n").into_bytes();
    for _row in 0..h {
        for x in 0..w {
            let v = if x == w / 2 || x == w / 2 - 1 { 50.0f32 } else { 0.0 };
            for _ in 0..3 {
                bytes.extend_from_slice(&v.to_le_bytes());
            }
        }
    }
    // Keep only the rows at the horizon bright: the rows were written bottom-up.
    let header = format!("PF\n{w} {h}\n-1.0\n").len();
    for row in 0..h {
        if row != h / 2 && row != h / 2 - 1 {
            for x in 0..w * 3 {
                let at = header + 4 * (row * w * 3 + x);
                bytes[at..at + 4].copy_from_slice(&0f32.to_le_bytes());
            }
        }
    }
    std::fs::write(path, bytes).unwrap();
}

fn spot_scene(rotation: f32) -> String {
    format!(
        r#"
[camera]
eye = [0.0, 0.0, 0.0]
target = [0.0, 0.0, -1.0]
vfov = 90.0
[render]
resolution = [64, 64]
spp = 4
[[light]]
type = "environment"
file = "spot.pfm"
rotation = {rotation}
exposure = 1.0
"#
    )
}

/// The direction, in degrees to the right of the view's centre, of the light seen along
/// the image's middle row (the horizon): the radiance-weighted mean of the pixels' angles.
fn spot_angle(film: &Film) -> f32 {
    let w = film.width as usize;
    let half = w as f32 / 2.0;
    let (mut sum, mut weight) = (0.0, 0.0);
    for y in [w / 2 - 1, w / 2] {
        for x in 0..w {
            let v = film.pixels[y * w + x].color.x;
            sum += v * ((x as f32 + 0.5 - half) / half).atan().to_degrees();
            weight += v;
        }
    }
    sum / weight
}

/// The map's centre column is seen straight ahead along -z; turned by 30 degrees
/// counter-clockwise seen from above, it is seen 30 degrees to the camera's left; and
/// `exposure` doubles it per stop.
#[test]
fn rotation_moves_the_bright_spot_where_the_frame_says() {
    let dir = tempfile::tempdir().unwrap();
    write_spot_map(&dir.path().join("spot.pfm"));
    let scene_path = dir.path().join("spot.toml");
    let film = |rotation: f32| {
        let desc = tress::io::scene_file::parse(&spot_scene(rotation), &scene_path, None).map(|d| d.0).unwrap();
        render(&desc)
    };
    let ahead = film(0.0);
    assert!(spot_angle(&ahead).abs() < 0.5, "{}", spot_angle(&ahead));
    let turned = film(30.0);
    assert!((spot_angle(&turned) + 30.0).abs() < 1.0, "{}", spot_angle(&turned));
    let back = film(-20.0);
    assert!((spot_angle(&back) - 20.0).abs() < 1.0, "{}", spot_angle(&back));
    // The spot's peak: 50 times 2^1, blurred over the map's pixels by its bilinear lookup.
    let peak = ahead.pixels.iter().map(|p| p.color.x).fold(0.0, f32::max);
    assert!(peak > 50.0 && peak <= 100.0 + 1e-3, "{peak}");
}

/// The map is read when the scene is prepared: a file that cannot be used is an error
/// then, naming the light and the file.
#[test]
fn scene_files_name_the_unusable_map() {
    let dir = tempfile::tempdir().unwrap();
    let scene_path = dir.path().join("spot.toml");
    let prepare_error = || {
        let desc = tress::io::scene_file::parse(&spot_scene(0.0), &scene_path, None).unwrap().0;
        tress::prepare::prepare(&desc).map(|_| ()).unwrap_err().to_string()
    };
    let e = prepare_error();
    assert!(e.contains("light 1") && e.contains("spot.pfm: could not open the file"), "{e}");
    std::fs::write(dir.path().join("spot.pfm"), b"PF\n2 2\n-1\n\0\0").unwrap();
    let e = prepare_error();
    assert!(e.contains("light 1") && e.contains("spot.pfm: the header announces 2x2 pixels"), "{e}");
    let both = spot_scene(0.0).replace("file = \"spot.pfm\"", "file = \"spot.pfm\"\nradiance = [1.0, 1.0, 1.0]");
    let e = tress::io::scene_file::parse(&both, &scene_path, None).map(|d| d.0).unwrap_err().to_string();
    assert!(e.contains("exactly one of `radiance` and `file`"), "{e}");
}

/// The tube model's ambient term stands for the environment map too: a tube strand with
/// only an ambient colour, under a map bright above the horizon and black below (mean
/// radiance over the sphere 1), shows the ambient colour times 1, with every integrator
/// that shades tubes by their ambient term.
#[test]
fn the_tube_ambient_term_takes_an_environment_maps_mean_radiance() {
    let (w, h) = (32u32, 16u32);
    let rgb: Vec<f32> = (0..w * h * 3).map(|i| if i / 3 / w < h / 2 { 2.0 } else { 0.0 }).collect();
    let map = EnvironmentMap::from_pixels(w, h, &rgb, 0.0, 1.0).unwrap();
    assert!((map.mean_radiance() - Color::ONE).abs().max_element() < 1e-5, "{}", map.mean_radiance());
    let mut strands = StrandSet::new();
    strands.push_strand([(Vec3::new(0.0, -1.0, 0.0), 0.4), (Vec3::new(0.0, 1.0, 0.0), 0.4)]);
    let ambient = Color::new(0.3, 0.2, 0.1);
    let tube = tress::shading::tube::Tube { ambient, diffuse: Color::ZERO, specular: Color::ZERO, specular_power: 1.0 };
    for integrator in [Integrator::Direct, Integrator::FinalGather] {
        let desc = Description {
            camera: CameraDesc {
                eye: Vec3::new(0.0, 0.0, 4.0),
                target: Vec3::ZERO,
                up: Vec3::Y,
                vfov: 40.0,
                ..Default::default()
            },
            settings: RenderSettings { width: 16, height: 16, spp: 4, integrator, ..Default::default() },
            contents: Contents {
                lights: vec![Light::EnvironmentMap(map.clone()).into()],
                hair: vec![HairEntry {
                    source: HairSource::Inline(strands.clone()),
                    material: Material::Tube(tube.clone()).into(),
                    transform: Affine3A::IDENTITY,
                    radius_scale: 1.0,
                    file_colors: false,
                    lod: None,
                    visibility: Default::default(),
                }],
                ..Default::default()
            },
        };
        let film = render(&desc);
        let on_strand: Vec<Vec3> =
            film.pixels.iter().filter(|p| p.strand_id >= 0.0 && p.coverage == 1.0).map(|p| p.color).collect();
        assert!(!on_strand.is_empty(), "{integrator:?}: the strand is seen");
        for c in on_strand {
            assert!((c - ambient).abs().max_element() < 1e-4, "{integrator:?}: {c} where {ambient} is right");
        }
    }
}
