//! The physical hair material through the whole renderer: a white fibre in a white
//! furnace disappears (the integrator lights it from the whole sphere, by sampling the
//! BSDF, and the BSDF conserves energy), and colours from the strands need strands with
//! colours.

use glam::{Affine3A, Vec3};
use tress::geometry::StrandSet;
use tress::light::Light;
use tress::math::Color;
use tress::prepare::prepare;
use tress::scene::{CameraDesc, Contents, Description, HairEntry, HairSource};
use tress::shading::hair_bsdf::{Absorption, HairParams, PhysicalHair};
use tress::shading::Material;
use tress::world::RenderSettings;

/// A short straight strand across the view, seen from +z, under a constant environment.
fn furnace(strands: StrandSet, params: HairParams, file_colors: bool) -> Description {
    Description {
        camera: CameraDesc {
            eye: Vec3::new(0.0, 0.0, 2.0),
            target: Vec3::ZERO,
            up: Vec3::Y,
            vfov: 6.0,
            ..Default::default()
        },
        settings: RenderSettings { width: 24, height: 24, spp: 1024, max_depth: 0, ..Default::default() },
        contents: Contents {
            lights: vec![Light::Environment { radiance: Color::ONE, camera_visibility: 1.0 }.into()],
            meshes: vec![],
            hair: vec![HairEntry {
                source: HairSource::Inline(strands),
                material: Material::Physical(PhysicalHair::new(params)).into(),
                transform: Affine3A::IDENTITY,
                radius_scale: 1.0,
                file_colors,
                lod: None,
                visibility: Default::default(),
            }],
            ..Default::default()
        },
    }
}

fn strand() -> StrandSet {
    let mut s = StrandSet::new();
    // Three points: the shadow rays skip the hit segment and its neighbours, so nothing of
    // the strand can shadow itself and every hit sees the whole environment.
    s.push_strand([
        (Vec3::new(-1.0, 0.0, 0.0), 0.04),
        (Vec3::new(0.0, 0.02, 0.0), 0.04),
        (Vec3::new(1.0, 0.0, 0.0), 0.04),
    ]);
    s
}

/// Mean colour of the pixels mostly covered by hair, and how many there are.
fn hair_mean(desc: &Description) -> (Color, usize) {
    let (world, _) = prepare(desc).unwrap();
    let film = tress::render::render(&world, None).0;
    let hair: Vec<_> = film.pixels.iter().filter(|p| p.strand_id >= 0.0 && p.coverage > 0.9).collect();
    assert!(film.pixels.iter().all(|p| p.color.is_finite()));
    (hair.iter().map(|p| p.color).sum::<Color>() / hair.len().max(1) as f32, hair.len())
}

#[test]
fn white_fibre_vanishes_in_a_white_furnace() {
    // No absorption: each hit reflects and transmits exactly what arrives, 1 from every
    // direction. Lighting only the hemisphere of the hit normal would lose the light
    // transmitted from behind (TT) and give about half; a cosine too many, less.
    let white =
        HairParams { absorption: Absorption::Melanin { eumelanin: 0.0, pheomelanin: 0.0 }, ..Default::default() };
    let (mean, n) = hair_mean(&furnace(strand(), white, false));
    println!("white fibre in a white furnace: mean {mean} over {n} pixels");
    assert!(n > 30, "only {n} hair pixels");
    assert!((mean - Color::ONE).abs().max_element() < 0.02, "{mean} over {n} pixels");
    // Blonde hair absorbs some, blue most.
    let blonde = HairParams { absorption: Absorption::Melanin { eumelanin: 0.3, pheomelanin: 0.0 }, ..white };
    let (mean, _) = hair_mean(&furnace(strand(), blonde, false));
    assert!(mean.x < 0.98 && mean.z < mean.x && mean.z > 0.2, "{mean}");
}

#[test]
fn colours_from_strands_need_strands_with_colours() {
    let from = HairParams { absorption: Absorption::FromStrands, ..Default::default() };
    let e = prepare(&furnace(strand(), from, true)).unwrap_err().to_string();
    assert!(e.contains("hair 1") && e.contains("from_file") && e.contains("no colours"), "{e}");
    let mut coloured = strand();
    coloured.colors = Some(vec![[0.9, 0.5, 0.2]; 3]);
    let e = prepare(&furnace(coloured.clone(), from, false)).unwrap_err().to_string();
    assert!(e.contains("file_colors"), "{e}");
    // With colours, the strand's colour sets the absorption: red stays brightest.
    let (mean, _) = hair_mean(&furnace(coloured, from, true));
    assert!(mean.x > mean.y && mean.y > mean.z && mean.x < 1.03, "{mean}");
}

#[test]
fn example_scene_uses_the_physical_material_and_renders_the_same_on_any_thread_count() {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/hairy_torus_closeup.toml");
    let mut desc = tress::io::scene_file::read(&path, None).unwrap().0;
    assert!(matches!(desc.contents.hair[0].material, tress::scene::MaterialSource::Inline(Material::Physical(_))));
    desc.settings.width = 48;
    desc.settings.height = 36;
    desc.settings.spp = 2;
    let render = |threads: usize| {
        let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
        pool.install(|| tress::render::render(&prepare(&desc).unwrap().0, None).0)
    };
    let bits =
        |f: &tress::film::Film| f.pixels.iter().flat_map(|p| p.color.to_array().map(f32::to_bits)).collect::<Vec<_>>();
    let (a, b) = (render(1), render(2));
    assert!(a.pixels.iter().any(|p| p.strand_id >= 0.0), "no hair in view");
    assert_eq!(bits(&a), bits(&b));
}
