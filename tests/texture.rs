//! Mesh textures end to end: a textured quad shows the texture's colours where its UVs put
//! them, a far-away checkerboard is filtered to its mean by the ray footprint (not by
//! supersampling), and a scene naming an unusable texture is an error naming the file.

use tress::film::Film;

fn render_scene(text: &str, path: &std::path::Path) -> Film {
    let desc = tress::io::scene_file::parse(text, path, None).map(|d| d.0).unwrap();
    let (world, _) = tress::prepare::prepare(&desc).unwrap();
    tress::render::render(&world, None).0
}

/// A plane of side 2 seen from `height` above, straight down, with image right along +x
/// and image up along -z; lit by a white constant environment, which makes a matte
/// surface's radiance its albedo exactly under the direct integrator.
fn quad_scene(texture: &str, height: f32, resolution: u32, spp: u32) -> String {
    format!(
        r#"
[camera]
eye = [0.0, {height}, 0.0]
target = [0.0, 0.0, 0.0]
up = [0.0, 0.0, -1.0]
vfov = 40.0
[render]
resolution = [{resolution}, {resolution}]
spp = {spp}
[[light]]
type = "environment"
radiance = [1.0, 1.0, 1.0]
[[mesh]]
shape = {{ type = "plane", size = 2.0 }}
material = {{ type = "textured", color = "{texture}" }}
"#
    )
}

fn srgb(v: u8) -> f32 {
    let v = v as f32 / 255.0;
    if v <= 0.04045 {
        v / 12.92
    } else {
        ((v + 0.055) / 1.055).powf(2.4)
    }
}

/// The plane's UV (0, 0) lies at its -x, -z corner, the image's top left; v = 0 is the
/// texture's bottom row (the OBJ convention), so the view shows the texture upside down:
/// the top-left quadrant of the image shows the texture's bottom-left texel.
#[test]
fn a_textured_quad_shows_the_texture_where_its_uvs_put_it() {
    let dir = tempfile::tempdir().unwrap();
    // Texture quadrants from the top: red, green / blue, yellow.
    let colors = [[200u8, 30, 30], [30, 200, 30], [30, 30, 200], [220, 220, 40]];
    // Each colour a block of 4x4 texels: bilinear lookups inside a block read it exactly.
    let img = image::RgbImage::from_fn(8, 8, |x, y| image::Rgb(colors[(y / 4 * 2 + x / 4) as usize]));
    img.save(dir.path().join("quad.png")).unwrap();
    // From 1 / tan(20 degrees) above, the plane's side of 2 just fills the 40-degree view.
    let film = render_scene(&quad_scene("quad.png", 2.747, 40, 4), &dir.path().join("quad.toml"));
    let at = |x: usize, y: usize| film.pixels[y * 40 + x].color;
    // Quadrant centres: image top-left shows texel (0, 1) (bottom-left: blue), top-right
    // texel (1, 1) (yellow), bottom-left texel (0, 0) (red), bottom-right (1, 0) (green).
    for ((x, y), c) in [((10, 10), colors[2]), ((30, 10), colors[3]), ((10, 30), colors[0]), ((30, 30), colors[1])] {
        let expected = glam::Vec3::new(srgb(c[0]), srgb(c[1]), srgb(c[2]));
        let got = at(x, y);
        assert!((got - expected).abs().max_element() < 1e-3, "pixel ({x}, {y}): {got} vs {expected}");
    }
}

/// A checkerboard of single-texel squares far away: every pixel spans many texels, and
/// with one sample a pixel the footprint-filtered lookup gives the mean (0.5) in every
/// pixel, where a point lookup would give 0 or 1.
#[test]
fn a_distant_checkerboard_is_filtered_to_its_mean() {
    let dir = tempfile::tempdir().unwrap();
    let n = 512u32;
    let img = image::RgbImage::from_fn(n, n, |x, y| image::Rgb([if (x + y) % 2 == 0 { 255 } else { 0 }; 3]));
    img.save(dir.path().join("checker.png")).unwrap();
    // The plane fills the 32-pixel view: 16 texels a pixel.
    let film = render_scene(&quad_scene("checker.png", 2.7, 32, 1), &dir.path().join("far.toml"));
    let mut on_plane = 0;
    for y in 8..24 {
        for x in 8..24 {
            let v = film.pixels[y * 32 + x].color;
            assert!((v.x - 0.5).abs() < 0.06, "pixel ({x}, {y}) is {v}");
            on_plane += 1;
        }
    }
    assert_eq!(on_plane, 256);
    // Close up (4 pixels a texel) the same texture is sharp: the squares show, with the
    // spread of a bilinear checkerboard (a standard deviation of 1/6).
    let close = render_scene(&quad_scene("checker.png", 0.043, 32, 1), &dir.path().join("near.toml"));
    let mean = close.pixels.iter().map(|p| p.color.x).sum::<f32>() / 1024.0;
    let std = (close.pixels.iter().map(|p| (p.color.x - mean).powi(2)).sum::<f32>() / 1024.0).sqrt();
    assert!(std > 0.1, "standard deviation {std} close up");
}

/// Textures are read when the scene is prepared: one that cannot be used is an error then,
/// naming the mesh and the file.
#[test]
fn an_unusable_texture_is_an_error_naming_it() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("bad.toml");
    let prepare_error = || {
        let desc = tress::io::scene_file::parse(&quad_scene("skin.png", 2.0, 8, 1), &path, None).unwrap().0;
        tress::prepare::prepare(&desc).map(|_| ()).unwrap_err().to_string()
    };
    let e = prepare_error();
    assert!(e.contains("mesh 1") && e.contains("skin.png: could not open the file"), "{e}");
    std::fs::write(dir.path().join("skin.png"), b"\x89PNG\r\n\x1a\n broken").unwrap();
    let e = prepare_error();
    assert!(e.contains("mesh 1") && e.contains("skin.png: not a readable png file"), "{e}");
}
