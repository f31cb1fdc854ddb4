//! Per-object visibility end to end: an object hidden from the camera still shadows, one
//! that casts no shadows is still seen, and a matte object (a holdout) leaves its pixels
//! black with alpha 0 while hiding what lies behind it, with every integrator.

use glam::{Affine3A, Vec3};
use tress::film::Film;
use tress::geometry::{StrandSet, TriangleMesh};
use tress::light::Light;
use tress::math::Color;
use tress::prepare::prepare;
use tress::scene::{CameraDesc, Contents, Description, HairEntry, HairSource, MeshEntry, MeshSource, Visibility};
use tress::shading::Material;
use tress::world::{Integrator, RenderSettings};

fn render(desc: &Description, threads: usize) -> Film {
    let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
    pool.install(|| {
        let (world, _) = prepare(desc).unwrap();
        tress::render::render(&world, None).0
    })
}

fn mesh(mesh: TriangleMesh, transform: Affine3A, visibility: Visibility) -> MeshEntry {
    let material = Material::Diffuse { color: Color::splat(0.8) }.into();
    MeshEntry { source: MeshSource::Inline(mesh), material, transform, visibility }
}

/// A plane lit from straight above, seen from above and in front, and (with `ball`) a
/// sphere of radius 0.5 floating over it, seen as `ball` says.
fn ball_over_plane(ball: Option<Visibility>, integrator: Integrator) -> Description {
    let mut meshes = vec![mesh(TriangleMesh::plane(8.0), Affine3A::IDENTITY, Visibility::default())];
    if let Some(v) = ball {
        meshes.push(mesh(TriangleMesh::sphere(0.5, 24), Affine3A::from_translation(Vec3::new(0.0, 1.0, 0.0)), v));
    }
    Description {
        camera: CameraDesc {
            eye: Vec3::new(0.0, 4.0, 4.0),
            target: Vec3::new(0.0, 0.3, 0.0),
            vfov: 40.0,
            ..Default::default()
        },
        settings: RenderSettings { width: 64, height: 48, spp: 4, max_depth: 1, integrator, ..Default::default() },
        contents: Contents {
            lights: vec![Light::Distant { direction: Vec3::Y, irradiance: Color::splat(3.0) }.into()],
            meshes,
            ..Default::default()
        },
    }
}

/// The pixels of the plane that the ball shadows in `shadowed`: lit without the ball
/// (`plane`), dark in `shadowed`, and away from the ball's outline in `seen` (the ball
/// seen as usual), so every sample of them is on the plane.
fn shadow_pixels(plane: &Film, shadowed: &Film, seen: &Film) -> Vec<usize> {
    let (w, h) = (plane.width as usize, plane.height as usize);
    let lit = plane.pixels.iter().map(|p| p.color.x).fold(0.0, f32::max);
    let near_ball = |x: usize, y: usize| {
        (y.saturating_sub(1)..(y + 2).min(h))
            .any(|y| (x.saturating_sub(1)..(x + 2).min(w)).any(|x| seen.pixels[y * w + x].object_id == 1.0))
    };
    (0..plane.pixels.len())
        .filter(|&i| {
            let (a, b) = (&plane.pixels[i], &shadowed.pixels[i]);
            a.color.x > 0.3 * lit && b.color.x < 0.1 * a.color.x && !near_ball(i % w, i / w)
        })
        .collect()
}

/// The pixels inside the ball's outline: the ball in the first sample of the pixel and of
/// its eight neighbours (so every sample of it is on the ball).
fn ball_pixels(film: &Film) -> Vec<usize> {
    let (w, h) = (film.width as usize, film.height as usize);
    let ball = |x: usize, y: usize| film.pixels[y * w + x].object_id == 1.0;
    let inside = |x: usize, y: usize| (y - 1..=y + 1).all(|y| (x - 1..=x + 1).all(|x| ball(x, y)));
    (1..h - 1)
        .flat_map(|y| (1..w - 1).map(move |x| (x, y)))
        .filter(|&(x, y)| inside(x, y))
        .map(|(x, y)| y * w + x)
        .collect()
}

#[test]
fn hidden_objects_shadow_and_shadowless_objects_show() {
    for integrator in [Integrator::Direct, Integrator::Path] {
        let plane = render(&ball_over_plane(None, integrator), 2);
        let seen = render(&ball_over_plane(Some(Visibility::default()), integrator), 2);
        let shadows = shadow_pixels(&plane, &seen, &seen);
        let ball = ball_pixels(&seen);
        assert!(shadows.len() > 20 && ball.len() > 20, "{integrator:?}: {} shadow, {} ball", shadows.len(), ball.len());

        // Hidden from the camera: the plane shows where the ball was, still in its shadow.
        let hidden = Visibility { camera: false, ..Default::default() };
        let film = render(&ball_over_plane(Some(hidden), integrator), 2);
        assert!(film.pixels.iter().all(|p| p.object_id != 1.0), "{integrator:?}: the hidden ball is seen");
        for &i in &ball {
            assert_eq!(film.pixels[i].object_id, 0.0, "{integrator:?}: pixel {i} shows no plane");
        }
        for &i in &shadows {
            assert!(film.pixels[i].color.x < 0.1 * plane.pixels[i].color.x, "{integrator:?}: pixel {i} unshadowed");
        }

        // Casting no shadows: the ball shows, the plane under it is as lit as without it.
        let shadowless = Visibility { shadows: false, ..Default::default() };
        let film = render(&ball_over_plane(Some(shadowless), integrator), 2);
        for &i in &ball {
            assert_eq!(film.pixels[i].object_id, 1.0, "{integrator:?}: pixel {i} does not show the ball");
        }
        for &i in &shadows {
            let (got, lit) = (film.pixels[i].color.x, plane.pixels[i].color.x);
            assert!((got - lit).abs() < 0.05 * lit, "{integrator:?}: pixel {i} shadowed: {got} against {lit}");
        }
    }
}

#[test]
fn matte_objects_are_black_and_transparent_yet_shadow() {
    for integrator in [Integrator::Direct, Integrator::FinalGather, Integrator::Path] {
        let plane = render(&ball_over_plane(None, integrator), 2);
        let seen = render(&ball_over_plane(Some(Visibility::default()), integrator), 2);
        let matte = Visibility { matte: true, ..Default::default() };
        let film = render(&ball_over_plane(Some(matte), integrator), 1);
        let ball = ball_pixels(&seen);
        assert!(ball.len() > 20, "{integrator:?}");
        for &i in &ball {
            let p = &film.pixels[i];
            assert_eq!((p.color, p.coverage), (Vec3::ZERO, 0.0), "{integrator:?}: pixel {i}");
        }
        // Seen, its lit upper half is not black.
        let lit = ball.iter().filter(|&&i| seen.pixels[i].color.max_element() > 0.1).count();
        assert!(lit > ball.len() / 3, "{integrator:?}: {lit} of {} ball pixels lit", ball.len());
        // It still casts its shadow: the same shadowed pixels as the ball seen.
        let shadows = shadow_pixels(&plane, &seen, &seen);
        assert!(shadows.len() > 20, "{integrator:?}: {} shadow pixels", shadows.len());
        assert_eq!(shadow_pixels(&plane, &film, &seen), shadows, "{integrator:?}");
        // The same image on any number of threads.
        let again = render(&ball_over_plane(Some(matte), integrator), 3);
        let bits = |f: &Film| f.pixels.iter().flat_map(|p| p.color.to_array()).map(f32::to_bits).collect::<Vec<_>>();
        assert_eq!(bits(&film), bits(&again), "{integrator:?}");
    }
}

/// A wall of vertical strands one unit behind a ball, seen from the front, the strands of
/// opacity `opacity` (semi-transparent ones take the renderer's multi-hit path).
fn ball_before_strands(ball: Option<Visibility>, opacity: Option<f32>) -> Description {
    let mut strands = StrandSet::new();
    for i in 0..160 {
        let x = -2.0 + i as f32 * 0.025;
        strands.push_strand([(Vec3::new(x, -1.0, -1.0), 0.02), (Vec3::new(x, 3.0, -1.0), 0.02)]);
    }
    if let Some(a) = opacity {
        strands.opacity = Some(vec![a; strands.points.len()]);
    }
    let meshes = ball
        .map(|v| mesh(TriangleMesh::sphere(0.5, 24), Affine3A::from_translation(Vec3::new(0.0, 1.0, 0.0)), v))
        .into_iter()
        .collect();
    let hair = HairEntry {
        source: HairSource::Inline(strands),
        material: Material::Diffuse { color: Color::splat(0.6) }.into(),
        transform: Affine3A::IDENTITY,
        radius_scale: 1.0,
        file_colors: false,
        lod: None,
        visibility: Visibility::default(),
    };
    Description {
        camera: CameraDesc {
            eye: Vec3::new(0.0, 1.0, 5.0),
            target: Vec3::new(0.0, 1.0, 0.0),
            vfov: 30.0,
            ..Default::default()
        },
        settings: RenderSettings { width: 48, height: 48, spp: 4, ..Default::default() },
        contents: Contents {
            lights: vec![Light::Distant { direction: Vec3::Z, irradiance: Color::splat(2.0) }.into()],
            meshes,
            hair: vec![hair],
            ..Default::default()
        },
    }
}

#[test]
fn a_matte_object_hides_the_strands_behind_it() {
    for opacity in [None, Some(0.5)] {
        let strands = render(&ball_before_strands(None, opacity), 2);
        let matte = Visibility { matte: true, ..Default::default() };
        let film = render(&ball_before_strands(Some(matte), opacity), 2);
        // The middle of the image: the ball, before strands that show without it.
        let centre: Vec<usize> = (20..28).flat_map(|y| (20..28).map(move |x| y * 48 + x)).collect();
        for &i in &centre {
            assert!(strands.pixels[i].coverage > 0.0 && strands.pixels[i].color.max_element() > 0.0, "{opacity:?}");
            let p = &film.pixels[i];
            assert_eq!((p.color, p.coverage), (Vec3::ZERO, 0.0), "{opacity:?}: pixel {i}");
        }
        // Away from the ball the strands show as without it.
        let corner = 4 * 48 + 4;
        assert!(film.pixels[corner].coverage > 0.0, "{opacity:?}");
    }
}
