//! Environment maps that other tools' scene files name (pbrt-v3 `mapname` in
//! latitude-longitude, pbrt-v4 `filename` in the equal-area square, USD `DomeLight`
//! textures): a map dark but for a bright spot in one direction lights the side of a
//! diffuse sphere that faces that direction, wherever the file's conventions and the
//! light's transform put it.

use std::path::Path;
use tress::prepare::prepare;
use tress::scene::Description;

/// The image of `desc`, whose map must be usable (no constant sky stands in for it).
fn render(desc: &Description) -> tress::film::Film {
    let (world, _) = prepare(desc).unwrap();
    assert!(!world.warnings.iter().any(|w| w.contains("constant sky")), "{:?}", world.warnings);
    tress::render::render(&world, None).0
}

/// A little-endian RGB PFM image, `f(x, y)` its pixel at column x of row y from the top.
fn pfm(w: usize, h: usize, f: impl Fn(usize, usize) -> f32) -> Vec<u8> {
    let mut out = format!("PF\n{w} {h}\n-1.0\n").into_bytes();
    // PFM stores its rows from the bottom up.
    for y in (0..h).rev() {
        for x in 0..w {
            for _ in 0..3 {
                out.extend(f(x, y).to_le_bytes());
            }
        }
    }
    out
}

/// The mean brightness of the sphere's image in its right, left, top and bottom quarters
/// (pixels that hit it, in image terms).
fn sides(film: &tress::film::Film) -> [f32; 4] {
    let (w, h) = (film.width as usize, film.height as usize);
    let mut sum = [0.0f32; 4];
    let mut n = [0u32; 4];
    for y in 0..h {
        for x in 0..w {
            let p = &film.pixels[y * w + x];
            if p.object_id < 0.0 {
                continue;
            }
            let (dx, dy) = (x as f32 + 0.5 - w as f32 / 2.0, y as f32 + 0.5 - h as f32 / 2.0);
            let side = match (dx.abs() > dy.abs(), dx > 0.0, dy > 0.0) {
                (true, true, _) => 0,
                (true, false, _) => 1,
                (false, _, false) => 2,
                (false, _, true) => 3,
            };
            sum[side] += p.color.x + p.color.y + p.color.z;
            n[side] += 1;
        }
    }
    assert!(n.iter().all(|&n| n > 20), "{n:?}");
    [0, 1, 2, 3].map(|i| sum[i] / n[i] as f32)
}

/// Which quarter is brightest, and by how much over the next.
fn brightest(s: [f32; 4]) -> (&'static str, f32) {
    let names = ["right", "left", "top", "bottom"];
    let mut order = [0, 1, 2, 3];
    order.sort_by(|a, b| s[*b].total_cmp(&s[*a]));
    (names[order[0]], s[order[0]] / s[order[1]].max(1e-6))
}

/// A pbrt scene: a unit diffuse sphere seen from −z (so the image's right is world +x, as
/// pbrt's LookAt makes it), lit only by `light`.
fn pbrt_scene(dir: &Path, light: &str) -> Description {
    let path = dir.join("sphere.pbrt");
    std::fs::write(
        &path,
        format!(
            "LookAt 0 0 -5  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 30\n\
             Film \"rgb\" \"integer xresolution\" 48 \"integer yresolution\" 48\n\
             Sampler \"zsobol\" \"integer pixelsamples\" 16\nIntegrator \"path\" \"integer maxdepth\" 1\n\
             WorldBegin\nAttributeBegin\n{light}\nAttributeEnd\n\
             Material \"diffuse\" \"rgb reflectance\" [0.8 0.8 0.8]\nShape \"sphere\" \"float radius\" 1\n"
        ),
    )
    .unwrap();
    let (desc, warnings) = tress::io::read_scene(&path, None).unwrap();
    assert!(!warnings.iter().any(|w| w.contains("constant")), "{warnings:?}");
    desc
}

#[test]
fn pbrt_v3_lat_long_maps_light_the_side_facing_their_bright_spot() {
    let dir = tempfile::tempdir().unwrap();
    // φ = 0 (column 0) at the equator: light-space +x.
    std::fs::write(
        dir.path().join("spot.pfm"),
        pfm(32, 16, |x, y| if x < 2 && (7..9).contains(&y) { 400.0 } else { 0.0 }),
    )
    .unwrap();
    let light = "LightSource \"infinite\" \"string mapname\" \"spot.pfm\"";
    let (side, ratio) = brightest(sides(&render(&pbrt_scene(dir.path(), light))));
    assert_eq!(side, "right", "{ratio}");
    assert!(ratio > 2.0, "{ratio}");
    // Turned 90° about z, +x goes to +y: the top.
    let light = format!("Rotate 90 0 0 1\n{light}");
    let (side, ratio) = brightest(sides(&render(&pbrt_scene(dir.path(), &light))));
    assert_eq!(side, "top", "{ratio}");
    assert!(ratio > 2.0, "{ratio}");
}

#[test]
fn pbrt_v4_equal_area_maps_light_the_side_facing_their_bright_spot() {
    let dir = tempfile::tempdir().unwrap();
    // The square's (0, 1/2) edge is light-space −x: the image's left.
    let edge = |x: usize, y: usize| if x == 0 && (7..9).contains(&y) { 400.0 } else { 0.0 };
    std::fs::write(dir.path().join("edge.pfm"), pfm(16, 16, edge)).unwrap();
    let light = "LightSource \"infinite\" \"string filename\" \"edge.pfm\"";
    let (side, ratio) = brightest(sides(&render(&pbrt_scene(dir.path(), light))));
    assert_eq!(side, "left", "{ratio}");
    assert!(ratio > 2.0, "{ratio}");
    // The centre is light-space +z; `Rotate -90 1 0 0` (a z-up map in a y-up world) puts
    // it overhead. Its scale scales the image.
    let centre = |x: usize, y: usize| if (7..9).contains(&x) && (7..9).contains(&y) { 400.0 } else { 0.0 };
    std::fs::write(dir.path().join("zenith.pfm"), pfm(16, 16, centre)).unwrap();
    let light = "Rotate -90 1 0 0\nLightSource \"infinite\" \"string filename\" \"zenith.pfm\"";
    let lit = sides(&render(&pbrt_scene(dir.path(), light)));
    let (side, ratio) = brightest(lit);
    assert_eq!(side, "top", "{ratio}");
    assert!(ratio > 2.0, "{ratio}");
    let half = sides(&render(&pbrt_scene(dir.path(), &format!("{light} \"float scale\" 0.5"))));
    assert!((half[2] / lit[2] - 0.5).abs() < 0.02, "{half:?} {lit:?}");
}

/// A USD stage: a unit sphere seen from +z by a camera (image right is world +x), lit only
/// by `dome` (a DomeLight prim's body of attributes), rendered small.
fn usd_scene(dir: &Path, dome: &str) -> Description {
    let path = dir.join("dome.usda");
    std::fs::write(
        &path,
        format!(
            "#usda 1.0\n(\n    upAxis = \"Y\"\n)\n\
             def Sphere \"Ball\" {{ double radius = 1 }}\n\
             def Camera \"Cam\" {{\n    float focalLength = 35\n    float horizontalAperture = 20.955\n    \
             float verticalAperture = 20.955\n    double3 xformOp:translate = (0, 0, 5)\n    \
             uniform token[] xformOpOrder = [\"xformOp:translate\"]\n}}\n\
             def DomeLight \"Sky\" {{\n{dome}\n}}\n"
        ),
    )
    .unwrap();
    let (mut desc, warnings) = tress::io::read_scene(&path, None).unwrap();
    assert!(!warnings.iter().any(|w| w.contains("dome")), "{warnings:?}");
    let s = &mut desc.settings;
    (s.width, s.height, s.spp, s.integrator) = (48, 48, 16, tress::world::Integrator::Direct);
    desc
}

#[test]
fn usd_dome_textures_light_the_side_facing_their_bright_spot() {
    let dir = tempfile::tempdir().unwrap();
    // OpenEXR's latitude-longitude layout: longitude π/2 (+x) a quarter of the way across,
    // the equator half way down.
    exr::prelude::write_rgb_file(dir.path().join("sky.exr"), 32, 16, |x, y| {
        let v = if (7..9).contains(&x) && (7..9).contains(&y) { 400.0f32 } else { 0.0 };
        (v, v, v)
    })
    .unwrap();
    let dome = "    asset inputs:texture:file = @./sky.exr@\n    float inputs:intensity = 1";
    let lit_film = render(&usd_scene(dir.path(), dome));
    let lit = sides(&lit_film);
    let (side, ratio) = brightest(lit);
    assert_eq!(side, "right", "{ratio}");
    assert!(ratio > 2.0, "{ratio}");
    // The dome's transform turns it: 90° about z takes +x to +y, the top. Its intensity
    // scales the light.
    let turned =
        format!("{dome}\n    float xformOp:rotateZ = 90\n    uniform token[] xformOpOrder = [\"xformOp:rotateZ\"]");
    let (side, ratio) = brightest(sides(&render(&usd_scene(dir.path(), &turned))));
    assert_eq!(side, "top", "{ratio}");
    assert!(ratio > 2.0, "{ratio}");
    let half = sides(&render(&usd_scene(dir.path(), &dome.replace("intensity = 1", "intensity = 0.5"))));
    assert!((half[0] / lit[0] - 0.5).abs() < 0.02, "{half:?} {lit:?}");
    // Arnold-USD's `primvars:arnold:camera = 0` hides the textured dome from the camera,
    // and the sphere is lit as before (pixels wholly on it bit for bit the same).
    let hidden = usd_scene(dir.path(), &format!("{dome}\n    float primvars:arnold:camera = 0"));
    let [tress::scene::LightSource::File(map)] = &hidden.contents.lights[..] else { panic!() };
    assert_eq!(map.placement.camera_visibility(), 0.0);
    let hidden = render(&hidden);
    for (h, l) in hidden.pixels.iter().zip(&lit_film.pixels).filter(|(_, l)| l.coverage == 1.0) {
        assert_eq!(h.color, l.color);
    }
}

/// Maps are read when the scene is prepared: one that pbrt or USD names but that cannot be
/// read lights the scene as a constant sky of the light's colour, with a warning naming the
/// file, as those tools' own lights do without a map.
#[test]
fn unreadable_maps_are_a_constant_sky_of_the_lights_colour_said_so() {
    use tress::light::Light;
    use tress::math::Color;
    let dir = tempfile::tempdir().unwrap();
    let light = "LightSource \"infinite\" \"string mapname\" \"gone.exr\" \"rgb L\" [0.5 0.5 0.5]";
    let (world, _) = prepare(&pbrt_scene(dir.path(), light)).unwrap();
    assert_eq!(world.lights, [Light::Environment { radiance: Color::splat(0.5), camera_visibility: 1.0 }]);
    let said = |w: &[String], what: &str| w.iter().any(|w| w.contains(what) && w.contains("constant sky"));
    assert!(said(&world.warnings, "gone.exr: could not open the file"), "{:?}", world.warnings);
    std::fs::write(dir.path().join("sky.exr"), b"not an exr").unwrap();
    let dome = "    asset inputs:texture:file = @./sky.exr@\n    float inputs:intensity = 2";
    let (world, _) = prepare(&usd_scene(dir.path(), dome)).unwrap();
    assert_eq!(world.lights, [Light::Environment { radiance: Color::splat(2.0), camera_visibility: 1.0 }]);
    assert!(said(&world.warnings, "sky.exr: not a readable exr file"), "{:?}", world.warnings);
}
