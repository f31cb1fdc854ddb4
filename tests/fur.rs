//! The fur generator's semantics (issue 3): root counts, baldness, orientation, curl,
//! maps, clumping, attraction, determinism and stability, each against the value the
//! specification (`docs/maya-fur-hair.md`) or geometry says it must have.

use glam::Vec3;
use std::collections::HashMap;
use std::f32::consts::{FRAC_PI_2, PI, TAU};
use tress::fur::{
    grow, AttractorModel, Attractors, ColorAttr, FurDescription, GrowOptions, GrownFur, MapSource, Placement, Scalar,
};
use tress::geometry::{StrandSet, TriangleMesh};

fn desc(density: u32, segments: u32, set: &[(Scalar, f32)]) -> FurDescription {
    let mut d = FurDescription { density, segments, ..Default::default() };
    // Straight hairs of length 1 unless a test says otherwise.
    for s in [Scalar::BaseCurl, Scalar::TipCurl, Scalar::Polar, Scalar::Roll] {
        d[s].value = 0.5;
    }
    d[Scalar::BaseWidth].value = 0.01;
    for &(s, v) in set {
        d[s].value = v;
    }
    d
}

/// Grows `d` with seed 7, its image maps decoded as a scene's are.
fn grow_on(mesh: &TriangleMesh, d: &FurDescription) -> GrownFur {
    let images = tress::prepare::read_map_images(d).unwrap();
    grow(mesh, d, GrowOptions { seed: 7, images: &images, ..Default::default() }).unwrap()
}

fn strand(s: &StrandSet, i: usize) -> Vec<Vec3> {
    (s.offsets[i]..s.offsets[i + 1]).map(|p| s.position(p)).collect()
}

fn strands(s: &StrandSet) -> impl Iterator<Item = Vec<Vec3>> + '_ {
    (0..s.strand_count()).map(move |i| strand(s, i))
}

fn polyline_length(p: &[Vec3]) -> f32 {
    p.windows(2).map(|w| (w[1] - w[0]).length()).sum()
}

fn uv(s: &StrandSet, i: usize) -> [f32; 2] {
    s.strand_info.as_ref().unwrap().root_uv[i]
}

fn torus() -> TriangleMesh {
    TriangleMesh::torus(1.0, 0.35, 96, 48)
}

#[test]
fn root_count_is_density_spread_by_area() {
    // Density is the expected count over the whole surface; each triangle's count is
    // floor(expected + U), so the total differs from it by a sum of independent terms in
    // (-1, 1) with variance at most 1/4 per triangle.
    let mesh = TriangleMesh::sphere(1.0, 48);
    let tris = mesh.indices.len() as f64;
    let bound = 5.0 * (tris / 4.0).sqrt();
    for density in [5_000u32, 40_000] {
        let fur = grow_on(&mesh, &desc(density, 1, &[]));
        let n = fur.strands.strand_count() as f64;
        assert!((n - density as f64).abs() < bound, "{n} roots for density {density} (bound {bound:.0})");
    }
    // By area: the cap v < 0.1 of the UV sphere (a polar angle below 18 degrees) holds
    // (1 - cos 18deg) / 2 = 2.4 % of the area but 10 % of the UV area.
    let n = 40_000;
    let share = |placement| {
        let fur = grow(&mesh, &desc(n, 1, &[]), GrowOptions { placement, seed: 3, ..Default::default() }).unwrap();
        let s = &fur.strands;
        (0..s.strand_count()).filter(|&i| uv(s, i)[1] < 0.1).count() as f64 / s.strand_count() as f64
    };
    let cap = (1.0 - (0.1 * std::f64::consts::PI).cos()) / 2.0;
    let tol = |p: f64| 5.0 * (p * (1.0 - p) / n as f64).sqrt() + 0.002;
    let area = share(Placement::Area);
    assert!((area - cap).abs() < tol(cap), "area placement: {area:.4} of roots in a cap of {cap:.4} of the area");
    let uv_share = share(Placement::Uv);
    assert!((uv_share - 0.1).abs() < tol(0.1), "uv placement: {uv_share:.4} of roots in 0.1 of the UV area");
}

#[test]
fn baldness_keeps_that_fraction_of_the_same_roots() {
    let mesh = torus();
    let full = grow_on(&mesh, &desc(30_000, 1, &[]));
    let roots: std::collections::HashSet<[u32; 3]> =
        strands(&full.strands).map(|p| p[0].to_array().map(f32::to_bits)).collect();
    for b in [0.25f32, 0.7] {
        let fur = grow_on(&mesh, &desc(30_000, 1, &[(Scalar::Baldness, b)]));
        let kept = fur.strands.strand_count() as f64 / full.strands.strand_count() as f64;
        let sd = (b as f64 * (1.0 - b as f64) / full.strands.strand_count() as f64).sqrt();
        assert!((kept - b as f64).abs() < 5.0 * sd, "baldness {b}: kept {kept:.4}");
        // The survivors are a subset of the full fur's roots: baldness removes, never moves.
        assert!(strands(&fur.strands).all(|p| roots.contains(&p[0].to_array().map(f32::to_bits))));
    }
    assert_eq!(grow_on(&mesh, &desc(30_000, 1, &[(Scalar::Baldness, 0.0)])).strands.strand_count(), 0);
}

#[test]
fn inclination_leans_from_the_normal_to_the_tangent_plane() {
    // On a plane facing +y every hair starts along the normal at inclination 0.
    let plane = TriangleMesh::plane(2.0);
    let fur = grow_on(&plane, &desc(500, 1, &[(Scalar::Inclination, 0.0)]));
    for p in strands(&fur.strands) {
        assert!(((p[1] - p[0]) - Vec3::Y).length() < 1e-5, "{}", p[1] - p[0]);
    }
    // On a sphere the angle to the normal is inclination * 90 degrees.
    let sphere = TriangleMesh::sphere(1.0, 64);
    for i in [0.0f32, 0.5, 1.0] {
        let fur = grow_on(&sphere, &desc(2000, 1, &[(Scalar::Inclination, i)]));
        for p in strands(&fur.strands) {
            let angle = (p[1] - p[0]).normalize().dot(p[0].normalize()).clamp(-1.0, 1.0).acos();
            // Interpolated normals of the tessellated sphere stray from the radius by < 1 deg.
            assert!((angle - i * FRAC_PI_2).abs() < 0.02, "inclination {i}: {angle} rad from the normal");
        }
    }
}

#[test]
fn polar_turns_the_hair_about_the_normal() {
    // Plane: U = +x (UVs run along x), V = N x U = -z. Inclination 1 lies along V at polar
    // 0.5; polar p turns it about +y by (p - 0.5) * 360 degrees.
    let plane = TriangleMesh::plane(2.0);
    for p in [0.0f32, 0.25, 0.5, 0.6, 0.75, 1.0] {
        let fur = grow_on(&plane, &desc(200, 1, &[(Scalar::Inclination, 1.0), (Scalar::Polar, p)]));
        let angle = (p - 0.5) * TAU;
        let expected = glam::Quat::from_axis_angle(Vec3::Y, angle) * Vec3::NEG_Z;
        for s in strands(&fur.strands) {
            assert!(((s[1] - s[0]) - expected).length() < 1e-4, "polar {p}: {} vs {expected}", s[1] - s[0]);
        }
    }
}

#[test]
fn curl_bends_by_the_documented_angle_and_keeps_length() {
    let plane = TriangleMesh::plane(2.0);
    let segments = 64;
    let grow_curl = |base: f32, tip: f32| {
        grow_on(&plane, &desc(50, segments, &[(Scalar::BaseCurl, base), (Scalar::TipCurl, tip), (Scalar::Length, 2.0)]))
    };
    // 0.5 is straight.
    for p in strands(&grow_curl(0.5, 0.5).strands) {
        assert!((p[segments as usize] - p[0] - Vec3::Y * 2.0).length() < 1e-4);
    }
    // The turn from the first to the last segment is the integral of 2 pi (c(s) - 0.5)
    // between their midpoints, c linear from base to tip.
    let turn = |b: f32, t: f32, s: f32| TAU * ((b - 0.5) * s + 0.5 * (t - b) * s * s);
    let (first, last) = (0.5 / segments as f32, 1.0 - 0.5 / segments as f32);
    for (b, t) in [(0.0, 0.0), (1.0, 1.0), (0.0, 0.5), (0.5, 1.0), (0.3, 0.8), (0.25, 0.25)] {
        let fur = grow_curl(b, t);
        let expected = (turn(b, t, last) - turn(b, t, first)).abs();
        for p in strands(&fur.strands) {
            assert!((polyline_length(&p) - 2.0).abs() < 1e-4, "curl ({b}, {t}) changed the length");
            let n = p.len();
            let angle = (p[1] - p[0]).normalize().dot((p[n - 1] - p[n - 2]).normalize()).clamp(-1.0, 1.0).acos();
            assert!((angle - expected).abs() < 1e-3, "curl ({b}, {t}): turned {angle}, expected {expected}");
        }
    }
    // Curl 0 or 1 all along is a half circle: the tip lies a diameter, 2 L / pi, from the
    // root, on opposite sides for 0 and 1.
    let tip = |b: f32| {
        let p = strand(&grow_curl(b, b).strands, 0);
        p[segments as usize] - p[0]
    };
    let (t0, t1) = (tip(0.0), tip(1.0));
    let diameter = 2.0 * 2.0 / PI;
    assert!((t0.length() - diameter).abs() < 1e-3 && (t1.length() - diameter).abs() < 1e-3, "{t0} {t1}");
    assert!(t0.y.abs() < 1e-3 && (t0 + t1).length() < 1e-3, "mirror images: {t0} {t1}");
}

#[test]
fn roll_turns_the_curl_plane_about_the_root_direction() {
    // Upright hairs curled toward the lean direction B = -z (polar 0.5) at roll 0.5; roll r
    // turns that bend about the hair's root direction (+y) by (r - 0.5) * 180 degrees.
    let plane = TriangleMesh::plane(2.0);
    for r in [0.0f32, 0.25, 0.5, 1.0] {
        let set = [(Scalar::BaseCurl, 0.8), (Scalar::TipCurl, 0.8), (Scalar::Roll, r)];
        let fur = grow_on(&plane, &desc(20, 16, &set));
        let expected = glam::Quat::from_axis_angle(Vec3::Y, (r - 0.5) * PI) * Vec3::NEG_Z;
        for p in strands(&fur.strands) {
            let d = p[16] - p[0];
            let sideways = Vec3::new(d.x, 0.0, d.z).normalize();
            assert!((sideways - expected).length() < 1e-4, "roll {r}: bends toward {sideways}, not {expected}");
        }
    }
}

#[test]
fn length_map_halves_length_where_it_is_half() {
    // A 16-bit map: the left half at 0.5, the right half at 1. Hairs whose roots lie
    // between texel centres of one half read that half's value exactly.
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("length.png");
    let row: Vec<u16> = (0..8).map(|i| if i < 4 { 32768 } else { 65535 }).collect();
    let img = image::ImageBuffer::<image::Luma<u16>, _>::from_raw(8, 1, row).unwrap();
    img.save(&path).unwrap();
    let plane = TriangleMesh::plane(2.0);
    let mut d = desc(4000, 4, &[(Scalar::Length, 3.0)]);
    let plain = grow_on(&plane, &d);
    d[Scalar::Length].map = Some(MapSource::Image(path));
    d[Scalar::Length].map_mult = 3.0;
    let mapped = grow_on(&plane, &d);
    assert_eq!(plain.strands.strand_count(), mapped.strands.strand_count(), "a map moves no root");
    let (mut left, mut right) = (0, 0);
    for i in 0..mapped.strands.strand_count() {
        let u = uv(&mapped.strands, i)[0];
        let (a, b) = (polyline_length(&strand(&plain.strands, i)), polyline_length(&strand(&mapped.strands, i)));
        assert!((a - 3.0).abs() < 1e-4);
        if (0.0625..0.4375).contains(&u) {
            assert!((b - 1.5 * 32768.0 / 32767.5).abs() < 1e-3, "u {u}: length {b}");
            left += 1;
        } else if (0.5625..0.9375).contains(&u) {
            assert!((b - 3.0).abs() < 1e-4, "u {u}: length {b}");
            right += 1;
        }
    }
    assert!(left > 1000 && right > 1000);
}

#[test]
fn clumping_one_brings_tips_onto_the_clump_centre() {
    let mesh = torus();
    let set = [(Scalar::Inclination, 0.4), (Scalar::Length, 0.3), (Scalar::ClumpingFrequency, 8.0)];
    let mut d = desc(8000, 6, &set);
    let loose = grow_on(&mesh, &d);
    d[Scalar::Clumping].value = 1.0;
    let clumped = grow_on(&mesh, &d);
    let info = clumped.strands.strand_info.as_ref().unwrap();
    let mut tips: HashMap<u32, Vec3> = HashMap::new();
    for (i, p) in strands(&clumped.strands).enumerate() {
        let tip = *p.last().unwrap();
        let first = *tips.entry(info.clump[i]).or_insert(tip);
        assert!((tip - first).length() < 1e-5, "hair {i} of clump {}: tip {tip} vs {first}", info.clump[i]);
        assert_eq!(p[0], strand(&loose.strands, i)[0], "clumping moves no root");
    }
    // About frequency^2 clumps over the surface, most of them holding hairs.
    assert!(tips.len() > 40 && tips.len() <= 64 + 30, "{} clumps", tips.len());
    // Without clumping, tips of one clump's hairs are spread out.
    let spread = strands(&loose.strands)
        .zip(&info.clump)
        .filter(|(_, &c)| c == info.clump[0])
        .map(|(p, _)| (*p.last().unwrap() - tips[&info.clump[0]]).length())
        .fold(0.0f32, f32::max);
    assert!(spread > 0.05, "{spread}");
    // Clump Shape: at +10 (p = 0.1) the pull is strong all along the hair, at -10
    // (p = 10) only near the tip, so mid-hair points move much further at +10.
    let mid_shift = |shape: f32| {
        let mut d = d.clone();
        d[Scalar::Clumping].value = 0.5;
        d[Scalar::ClumpShape].value = shape;
        let f = grow_on(&mesh, &d);
        let n = f.strands.strand_count();
        (0..n).map(|i| (strand(&f.strands, i)[3] - strand(&loose.strands, i)[3]).length()).sum::<f32>() / n as f32
    };
    let (convex, concave) = (mid_shift(10.0), mid_shift(-10.0));
    assert!(convex > 10.0 * concave && concave > 0.0, "{convex} vs {concave}");
}

#[test]
fn attraction_pulls_hairs_toward_a_guide() {
    // Upright fur on a plane; one guide from the centre lying along +x.
    let plane = TriangleMesh::plane(4.0);
    let mut guide = StrandSet::new();
    guide.push_strand((0..=10).map(|i| (Vec3::new(0.1 * i as f32, 0.0, 0.0), 0.01)));
    let d = desc(3000, 8, &[]);
    // (The guide and the hairs are 1 long, so Interpolate pulls as Local does.)
    for model in [AttractorModel::Local, AttractorModel::Global, AttractorModel::Interpolate] {
        let attractors = Attractors { model, radius: 0.8, threshold_length: 0.0, ..Default::default() };
        let options = GrowOptions { seed: 7, guides: Some((&guide, &attractors)), ..Default::default() };
        let fur = grow(&plane, &d, options).unwrap();
        let clump = &fur.strands.strand_info.as_ref().unwrap().clump;
        let (mut near, mut far) = (0, 0);
        for (i, p) in strands(&fur.strands).enumerate() {
            let (root, tip) = (p[0], *p.last().unwrap());
            let d_root = root.length();
            if d_root < 0.7 {
                // Pulled from straight up toward the guide: toward +x, and lower.
                near += 1;
                assert_eq!(clump[i], 0);
                let pull = 1.0 - d_root / 0.8;
                let free_tip = root + Vec3::Y;
                let target = match model {
                    AttractorModel::Local | AttractorModel::Interpolate => root + Vec3::X,
                    AttractorModel::Global => Vec3::X,
                };
                assert!(((tip - free_tip) - (target - free_tip) * pull).length() < 1e-3, "{model:?} hair at {root}");
            } else if d_root > 0.8 {
                far += 1;
                assert_eq!(clump[i], u32::MAX);
                assert!((tip - root - Vec3::Y).length() < 1e-5, "beyond the radius nothing moves");
            }
        }
        assert!(near > 50 && far > 1000, "{near} {far}");
    }
    // Attraction 0 turns it off.
    let attractors = Attractors { threshold_length: 0.0, ..Default::default() };
    let off = desc(3000, 8, &[(Scalar::Attraction, 0.0)]);
    let fur = grow(&plane, &off, GrowOptions { seed: 7, guides: Some((&guide, &attractors)), ..Default::default() });
    assert!(strands(&fur.unwrap().strands).all(|p| (*p.last().unwrap() - p[0] - Vec3::Y).length() < 1e-5));
}

/// A busy description: every feature on, maps and noise included.
fn busy() -> FurDescription {
    let mut d = tress::fur::presets::preset("Llama").unwrap();
    d.density = 20_000;
    d[Scalar::Polar].noise = 0.2;
    d[ColorAttr::BaseColor].noise = 0.3;
    d[ColorAttr::BaseAmbientColor].noise = 0.1;
    d
}

#[test]
fn same_fur_whatever_the_thread_count() {
    let mesh = torus();
    let mut guide = StrandSet::new();
    guide.push_strand((0..5).map(|i| (Vec3::new(1.35, 0.1 * i as f32, 0.0), 0.01)));
    let attractors = Attractors { threshold_length: 0.0, ..Default::default() };
    let run = |threads| {
        let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
        let options = GrowOptions { seed: 11, guides: Some((&guide, &attractors)), ..Default::default() };
        pool.install(|| grow(&mesh, &busy(), options).unwrap())
    };
    let (a, b, c) = (run(1), run(2), run(3));
    let bits = |f: &GrownFur| f.strands.points.iter().flat_map(|p| p.map(f32::to_bits)).collect::<Vec<_>>();
    assert_eq!(bits(&a), bits(&b));
    assert_eq!(a, b);
    assert_eq!(a, c);
    assert!(a.shading.ambient.len() > 1, "mapped ambient colour is kept per strand");
    // Another seed is other fur.
    let other = grow(&mesh, &busy(), GrowOptions { seed: 12, ..Default::default() }).unwrap();
    assert_ne!(other.strands.points, a.strands.points);
}

#[test]
fn a_root_keeps_its_hair_when_density_or_another_triangle_changes() {
    let mesh = torus();
    let key = |p: &[Vec3]| p[0].to_array().map(f32::to_bits);
    let index = |s: &StrandSet| strands(s).map(|p| (key(&p), p)).collect::<HashMap<_, _>>();
    let mut d = busy();
    d[Scalar::Clumping].value = 0.0;
    let sparse = grow_on(&mesh, &d);
    d.density *= 2;
    let dense = index(&grow_on(&mesh, &d).strands);
    for p in strands(&sparse.strands) {
        assert_eq!(dense.get(&key(&p)), Some(&p), "a root of the sparse fur lost or changed its hair");
    }
    // Move one vertex: only hairs on its six triangles may change; elsewhere every root
    // that exists in both keeps its hair (counts shift a little: the total area changed).
    d.density /= 2;
    let mut moved = mesh.clone();
    moved.positions[500] *= 1.3;
    let after = index(&grow_on(&moved, &d).strands);
    let (mut same, mut total) = (0, 0);
    for p in strands(&sparse.strands) {
        if (p[0] - mesh.positions[500]).length() > 0.2 {
            total += 1;
            if let Some(q) = after.get(&key(&p)) {
                assert_eq!(q, &p);
                same += 1;
            }
        }
    }
    assert!(same as f64 > 0.99 * total as f64, "{same} of {total} roots kept");
}

#[test]
fn widths_colours_and_opacity_run_from_base_to_tip() {
    let plane = TriangleMesh::plane(2.0);
    let mut d = desc(100, 4, &[(Scalar::BaseWidth, 0.2), (Scalar::TipWidth, 0.04), (Scalar::BaseOpacity, 0.9)]);
    d[Scalar::TipOpacity].value = 0.1;
    d.global_scale = 0.5;
    d[ColorAttr::BaseColor].value = Vec3::new(1.0, 0.0, 0.0);
    d[ColorAttr::TipColor].value = Vec3::new(0.0, 0.0, 1.0);
    let s = grow_on(&plane, &d).strands;
    let (colors, opacity) = (s.colors.as_ref().unwrap(), s.opacity.as_ref().unwrap());
    for i in 0..s.strand_count() {
        let first = s.offsets[i] as usize;
        // Global scale halves widths and length; radius is half the width.
        assert!((s.points[first][3] - 0.05).abs() < 1e-6 && (s.points[first + 4][3] - 0.01).abs() < 1e-6);
        assert!((s.points[first + 2][3] - 0.03).abs() < 1e-6);
        assert!((polyline_length(&strand(&s, i)) - 0.5).abs() < 1e-5);
        assert_eq!(colors[first + 2], [0.5, 0.0, 0.5]);
        assert!((opacity[first] - 0.9).abs() < 1e-6 && (opacity[first + 4] - 0.1).abs() < 1e-6);
    }
    // Fully opaque fur stores no opacity.
    assert!(grow_on(&plane, &desc(100, 4, &[])).strands.opacity.is_none());
}

#[test]
fn bad_input_is_an_error_not_a_panic() {
    let plane = TriangleMesh::plane(1.0);
    let err = |mesh: &TriangleMesh, d: &FurDescription, placement| {
        grow(mesh, d, GrowOptions { placement, ..Default::default() }).unwrap_err().to_string()
    };
    let mut d = desc(100, 2, &[]);
    d[Scalar::Inclination].value = f32::NAN;
    assert!(err(&plane, &d, Placement::Area).contains("inclination"));
    let mut bare = plane.clone();
    bare.uvs = None;
    let e = err(&bare, &desc(100, 2, &[]), Placement::Uv);
    assert!(e.contains("no UVs") && e.contains("uv"), "{e}");
    let mut d = desc(100, 2, &[]);
    d[Scalar::Length].map = Some(MapSource::Image("no/such/map.png".into()));
    let e = err(&bare, &d, Placement::Area);
    assert!(e.contains("no UVs") && e.contains("length_map"), "{e}");
    let e = err(&plane, &d, Placement::Area);
    assert!(e.contains("no/such/map.png") && e.contains("not decoded"), "{e}");
    let e = tress::prepare::read_map_images(&d).unwrap_err().to_string();
    assert!(e.contains("no/such/map.png"), "{e}");
    d[Scalar::Length].map = Some(MapSource::Vertex(vec![[0.5; 3]; 5]));
    let e = err(&plane, &d, Placement::Area);
    assert!(e.contains("5 values") && e.contains("4 vertices"), "{e}");
    // UVs that cover no area cannot place roots by UV.
    let mut flat = plane.clone();
    flat.uvs = Some(vec![[0.5, 0.5]; 4]);
    assert!(err(&flat, &desc(100, 2, &[]), Placement::Uv).contains("no area"));
    // Too many points for memory.
    let e = err(&plane, &desc(tress::fur::description::MAX_DENSITY, 256, &[]), Placement::Area);
    assert!(e.contains("limit"), "{e}");
    // A mesh without UVs still grows fur by area, directions from a fixed frame.
    let fur = grow(&bare, &desc(100, 2, &[(Scalar::Inclination, 1.0)]), GrowOptions::default()).unwrap();
    assert!(strands(&fur.strands).all(|p| (p[1] - p[0]).y.abs() < 1e-5));
    // Guides with nothing usable.
    let empty = StrandSet::new();
    let a = Attractors::default();
    let e = grow(&plane, &desc(10, 2, &[]), GrowOptions { guides: Some((&empty, &a)), ..Default::default() });
    assert!(e.unwrap_err().to_string().contains("guides"));
}
