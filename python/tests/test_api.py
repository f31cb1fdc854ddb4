"""The Python API against the command line: same images bit for bit, AOVs by name, the
command line's error messages, progress, cancelling."""

import os
import signal
import threading
import time
import tomllib

import numpy as np
import pytest

import tress
from tress import scene_folder

from tress_testing import run_cli, strands_on_sphere, uv_sphere


def groom_scene(width=48, height=36, spp=2):
    """A sphere with strands from arrays (per-point colours), a hair system grown from
    guide arrays, fur on the sphere, two lights."""
    scene = tress.Scene(
        camera={"eye": [0.0, 0.6, 4.2], "target": [0.0, 0.0, 0.0], "vfov": 40.0},
        render={"resolution": [width, height], "spp": spp, "seed": 3},
    )
    scene.add_light(type="distant", direction=[0.4, 0.8, 0.5], irradiance=[3.0, 3.0, 3.0])
    scene.add_light(type="environment", radiance=[0.2, 0.2, 0.25])
    pts, tris, normals, uvs = uv_sphere()
    sphere = scene.add_mesh(pts, tris, normals=normals, uvs=uvs,
                            material={"type": "diffuse", "color": [0.6, 0.5, 0.4]})
    points, radius, offsets, colors = strands_on_sphere()
    scene.add_hair(points, radius, offsets, colors=colors,
                   material={"type": "tube", "diffuse": [0.3, 0.2, 0.1]})
    guide_points, _, guide_offsets, _ = strands_on_sphere(count=6, points_per_strand=4, length=0.6, seed=7)
    scene.add_hair_system(guides=(guide_points, guide_offsets), hairs_per_clump=4, clump_width=0.15,
                          hair_width=0.01, hair_color=[0.5, 0.3, 0.15], seed=2)
    scene.add_fur(sphere, preset="Squirrel", density=300, seed=5)
    return scene


def test_arrays_render_as_the_command_line_renders_the_exported_folder(tmp_path, tress_cli):
    scene = groom_scene()
    image = tress.render(scene, threads=2)
    assert image.complete and (image.width, image.height) == (48, 36)
    folder = tmp_path / "groom"
    written = tress.export(scene, folder)
    assert sorted(os.listdir(folder)) == ["hair_1.hair", "hair_system_1.hair", "mesh_1.obj", "scene.toml"]
    out = tmp_path / "cli.exr"
    run_cli(tress_cli, "render", written, "-o", out, "--quiet", "--threads", "1")
    cli = tress.read_exr(out)
    assert cli.complete
    for name in ["R", "G", "B", "A", "Z", "N.X", "objectId", "strandId", "strandAlong", "clumpId", "strandRandom"]:
        a, b = image.aov(name), cli.aov(name)
        assert np.array_equal(a.view(np.uint32), b.view(np.uint32)), f"AOV {name} differs"
    rgba = np.asarray(image)
    assert rgba.shape == (36, 48, 4) and rgba.dtype == np.float32
    # Not an empty picture: hair, sphere and fur in it, each object seen.
    assert rgba[..., 3].mean() > 0.2
    assert set(np.unique(image.aov("objectId"))) >= {0.0, 1.0, 2.0, 3.0}


def test_same_image_for_any_thread_count():
    scene = groom_scene(width=32, height=24)
    a = tress.render(scene, threads=1)
    b = tress.render(scene, threads=2)
    assert np.array_equal(np.asarray(a), np.asarray(b))
    c = tress.render(scene, threads=2, seed=4)
    assert not np.array_equal(np.asarray(a), np.asarray(c)), "the seed changes the samples"


def test_loaded_file_renders_as_the_command_line(tmp_path, tress_cli):
    folder = tmp_path / "scene"
    groom_scene(width=24, height=16).write(folder)
    out = tmp_path / "cli.exr"
    run_cli(tress_cli, "render", folder / "scene.toml", "-o", out, "--quiet", "--spp", "3", "--seed", "9")
    image = tress.render(tress.load(folder / "scene.toml"), spp=3, seed=9)
    assert np.array_equal(np.asarray(image), np.asarray(tress.read_exr(out)))


def test_aovs_by_name_are_the_geometry_seen():
    # A square facing the camera 3 units away, filling the view, and one strand across it.
    scene = tress.Scene(camera={"eye": [0.0, 0.0, 3.0], "target": [0.0, 0.0, 0.0], "vfov": 20.0},
                        render={"resolution": [33, 33], "spp": 1})
    scene.add_light(type="distant", direction=[0.0, 0.0, 1.0], irradiance=[1.0, 1.0, 1.0])
    quad = np.array([[-2, -2, 0], [2, -2, 0], [2, 2, 0], [-2, 2, 0]], np.float32)
    scene.add_mesh(quad, [[0, 1, 2], [0, 2, 3]], material={"type": "diffuse", "color": [0.5, 0.5, 0.5]})
    strand = np.array([[-1.0, 0.3, 0.5], [0.0, 0.3, 0.5], [1.0, 0.3, 0.5]], np.float32)
    scene.add_hair(strand, 0.02, [0, 3], material={"type": "diffuse", "color": [0.2, 0.2, 0.2]})
    image = tress.render(scene)
    z, oid, sid = image.aov("Z"), image.aov("objectId"), image.aov("strandId")
    # The centre pixel's ray goes straight down the axis to the square.
    assert z[16, 16] == pytest.approx(3.0, abs=1e-4)
    assert oid[16, 16] == 0.0 and sid[16, 16] == -1.0
    assert np.allclose(image.aov("N")[16, 16], [0.0, 0.0, 1.0], atol=1e-5)
    # Lambert: irradiance 1 along the normal, albedo 0.5, so radiance 0.5 / pi.
    assert image.aov("RGB")[16, 16] == pytest.approx([0.5 / np.pi] * 3, rel=1e-4)
    # The strand: object 1, strand 0, 2.5 units away, along its length left to right.
    rows = np.nonzero((sid == 0.0).any(axis=1))[0]
    assert len(rows) > 0
    row = rows[len(rows) // 2]
    hit = np.nonzero(sid[row] == 0.0)[0]
    assert np.all(oid[row, hit] == 1.0)
    assert np.all(np.abs(z[row, hit] - 2.5) < 0.05)
    along = image.aov("strandAlong")[row, hit]
    assert np.all(np.diff(along) > 0) and 0.0 <= along[0] < along[-1] <= 1.0
    assert image.aov("A").min() == 1.0
    assert image.aov("rootUV").shape == (33, 33, 2)
    assert set(image.aovs()) == {n for n in image.aov_names if n not in ("RGBA", "RGB", "N", "rootUV")}
    with pytest.raises(KeyError, match="strandId"):
        image.aov("strandID")


def test_visibility_switches_survive_the_folder_export(tmp_path):
    # A square the camera does not see behind a strand that casts no shadow, and a matte
    # strand: the folder's scene file holds the switches, its reading keeps them (its USD
    # export writes them as Arnold's primvars) and renders as the scene in memory does.
    scene = tress.Scene(camera={"eye": [0.0, 0.0, 3.0], "target": [0.0, 0.0, 0.0], "vfov": 20.0},
                        render={"resolution": [17, 17], "spp": 1})
    scene.add_light(type="distant", direction=[0.0, 0.0, 1.0], irradiance=[1.0, 1.0, 1.0])
    quad = np.array([[-2, -2, 0], [2, -2, 0], [2, 2, 0], [-2, 2, 0]], np.float32)
    scene.add_mesh(quad, [[0, 1, 2], [0, 2, 3]], material={"type": "diffuse", "color": [0.5, 0.5, 0.5]},
                   **scene_folder.visibility(camera_visible=False))
    strand = np.array([[-1.0, 0.3, 0.5], [1.0, 0.3, 0.5]], np.float32)
    scene.add_hair(strand, 0.02, [0, 2], material={"type": "diffuse", "color": [0.2, 0.2, 0.2]},
                   casts_shadows=False)
    scene.add_hair(strand - [0.0, 0.6, 0.0], 0.02, [0, 2], material={"type": "diffuse", "color": [0.2, 0.2, 0.2]},
                   matte=True)
    written = tress.export(scene, tmp_path / "folder")
    tables = tomllib.loads(open(written).read())
    assert [{k: m[k] for k in ("camera_visible", "casts_shadows", "matte") if k in m}
            for m in tables["mesh"] + tables["hair"]] == [{"camera_visible": False}, {"casts_shadows": False},
                                                         {"matte": True}]
    loaded = tress.load(written)
    usda = tmp_path / "back.usda"
    tress.export(loaded, usda)
    text = usda.read_text()
    assert text.count("primvars:arnold:visibility:camera = false") == 1
    assert text.count("primvars:arnold:visibility:shadow = false") == 1
    assert text.count("primvars:arnold:matte = true") == 1
    image = tress.render(loaded)
    assert np.array_equal(np.asarray(image), np.asarray(tress.render(scene)))
    # The camera sees through the square: nothing behind it, so the centre is empty.
    assert np.asarray(image)[8, 8, 3] == 0.0
    assert scene_folder.visibility() == {}
    assert scene_folder.visibility(False, False, True) == {"camera_visible": False, "casts_shadows": False,
                                                           "matte": True}


def test_errors_carry_the_command_lines_messages(tmp_path, tress_cli):
    bad = tmp_path / "bad.toml"
    bad.write_text('[camera]\neye = [0, 0, 5]\ntarget = [0, 0, 0]\n[render]\nspp = 4\nsppp = 3\n')
    cli = run_cli(tress_cli, "render", bad, "-o", tmp_path / "x.png", check=False)
    assert cli.returncode == 1
    with pytest.raises(tress.TressError) as e:
        tress.load(bad)
    assert cli.stderr.strip() == f"error: {e.value}"
    assert "sppp" in str(e.value) and str(bad) in str(e.value)

    missing = tmp_path / "nowhere.toml"
    cli = run_cli(tress_cli, "render", missing, "-o", tmp_path / "x.png", check=False)
    with pytest.raises(tress.TressError) as e:
        tress.load(missing)
    assert cli.stderr.strip() == f"error: {e.value}"

    # A scene built in code is read by the same reader: the same message as the command
    # line gives for its TOML, but for the file name.
    scene = tress.Scene(camera={"eye": [0, 0, 5], "target": [0, 0, 0]})
    scene.add_mesh(shape={"type": "sphere", "radius": 1.0}, material={"type": "diffuse", "colour": [1, 1, 1]})
    path = tmp_path / "scene.toml"
    path.write_text(scene.to_toml())
    cli = run_cli(tress_cli, "render", path, "-o", tmp_path / "x.png", check=False)
    with pytest.raises(tress.TressError) as e:
        tress.render(scene)
    message = str(e.value).replace(os.path.join(os.getcwd(), "scene.toml"), str(path))
    assert cli.stderr.strip() == f"error: {message}"
    assert "colour" in message

    # Out-of-range settings: the description's own check.
    scene = groom_scene()
    with pytest.raises(tress.TressError, match="spp 0 is out of range"):
        tress.render(scene, spp=0)
    with pytest.raises(ValueError, match="unknown integrator `whitted`"):
        tress.render(scene, integrator="whitted")
    with pytest.raises(tress.TressError, match="unsupported export format"):
        tress.export(scene.description(), tmp_path / "x.obj")


def test_bad_arrays_raise_value_errors():
    scene = tress.Scene(camera={"eye": [0, 0, 5], "target": [0, 0, 0]})
    pts = np.zeros((4, 3), np.float32)
    with pytest.raises(ValueError, match="offsets must start at 0 and end at the number of points"):
        scene.add_hair(pts, 0.01, [0, 2, 3])
    with pytest.raises(ValueError, match="offsets decrease"):
        scene.add_hair(pts, 0.01, [0, 3, 2, 4])
    with pytest.raises(ValueError, match="3 radii for 4 points"):
        scene.add_hair(pts, [0.1, 0.1, 0.1], [0, 4])
    with pytest.raises(ValueError, match="negative radius"):
        scene.add_hair(pts, -0.1, [0, 4])
    with pytest.raises(ValueError, match=r"shape \(n, 3\)"):
        scene.add_hair(np.zeros((4, 2), np.float32), 0.1, [0, 4])
    with pytest.raises(ValueError, match="names a vertex past the 4 points"):
        scene.add_mesh(pts, [[0, 1, 4]])
    with pytest.raises(ValueError, match="opacity 1 is 2, outside"):
        scene.add_hair(pts, 0.1, [0, 4], opacity=[1, 2, 1, 1])
    assert scene.hair == [] and scene.meshes == []


def test_progress_reaches_every_tile_and_can_stop_the_render():
    scene = groom_scene(width=64, height=48)
    calls = []
    image = tress.render(scene, progress=lambda done, total: calls.append((done, total)))
    total = 4 * 3  # 16-pixel tiles
    assert calls[-1] == (total, total)
    assert all(b == total for _, b in calls) and [a for a, _ in calls] == sorted(a for a, _ in calls)
    assert image.complete

    # Slow enough (one thread, many samples) that the render is stopped before its end.
    slow = {"spp": 256, "integrator": "path", "threads": 1}
    stopped = tress.render(scene, **slow, progress=lambda done, total: done < 2)
    assert not stopped.complete
    # Finished tiles hold the image's pixels; the rest are empty.
    alpha = stopped.aov("A")
    full = tress.render(groom_scene(width=64, height=48), **slow)
    assert 0 < np.count_nonzero(alpha) < np.count_nonzero(full.aov("A"))
    done = alpha > 0
    assert np.array_equal(np.asarray(stopped)[done], np.asarray(full)[done])

    def fail(done, total):
        raise RuntimeError("from the callback")

    with pytest.raises(RuntimeError, match="from the callback"):
        tress.render(scene, progress=fail)

    previews = []
    tress.render(scene, spp=64, threads=1, preview=previews.append, preview_interval=0.0)
    assert previews and all(isinstance(p, tress.Image) and not p.complete for p in previews)


def test_ctrl_c_stops_a_render_quickly():
    scene = groom_scene(width=320, height=240, spp=256)
    timer = threading.Timer(0.5, lambda: os.kill(os.getpid(), signal.SIGINT))
    start = time.monotonic()
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        tress.render(scene, integrator="path", threads=1)
    assert time.monotonic() - start < 10.0


def test_info_counts_what_the_arrays_hold():
    scene = groom_scene()
    info = scene.info()
    pts, tris, _, _ = uv_sphere()
    assert info["meshes"] == 1 and info["triangles"] == len(tris)
    assert info["strand_sets"] == 3 and info["lights"] == 2
    # The strand set from arrays (60 strands of 4 segments), 6 guides x 4 hairs per clump,
    # and the fur.
    assert info["strands"] > 60 + 24
    assert info["memory"]["total"] > info["memory"]["strand_data"] > 0
    assert info["estimate"]["image"] > 0
    assert tress.info(scene.description()) == info


def test_export_hair_holds_every_render_strand(tmp_path):
    scene = tress.Scene(camera={"eye": [0, 0, 5], "target": [0, 0, 0]})
    points, radius, offsets, colors = strands_on_sphere(count=10)
    scene.add_hair(points, radius, offsets, colors=colors, material={"type": "diffuse", "color": [1, 1, 1]},
                   transform={"translate": [1.0, 0.0, 0.0]})
    out = tmp_path / "all.hair"
    tress.export(scene, out)
    data = out.read_bytes()
    assert data[:4] == b"HAIR" and int.from_bytes(data[4:8], "little") == 10
    assert int.from_bytes(data[8:12], "little") == len(points)
    first = np.frombuffer(data[128 + 20:128 + 32], np.float32)
    assert np.allclose(first, points[0] + [1, 0, 0])


def test_toml_writer_round_trips_through_tomllib():
    tables = {
        "camera": {"vfov": 30.0, "key": [{"frame": 1, "eye": [0.0, 1.0, 2.0], "target": [0, 0, 0]},
                                         {"frame": 9, "eye": [1e-7, 3.5e20, -0.0], "target": [0, 0, 0]}]},
        "render": {"resolution": [4, 3], "lod": False, "filter": {"type": "gaussian", "radius": 1.5}},
        "hair_system": [{"file": 'odd "name"\\.hair', "clump_width_scale": [[0.0, 1.0, "smooth"], [1.0, 0.2]],
                         "hair_color": np.array([0.1, 0.2, 0.3], np.float32), "hairs_per_clump": np.int64(7)}],
        "fur": [{"mesh": 1, "réglage": "é"}],
    }
    back = tomllib.loads(scene_folder.dumps(tables))
    assert back["camera"]["key"][1]["eye"] == [1e-7, 3.5e20, -0.0]
    assert back["render"] == {"resolution": [4, 3], "lod": False, "filter": {"type": "gaussian", "radius": 1.5}}
    hs = back["hair_system"][0]
    assert hs["file"] == 'odd "name"\\.hair' and hs["hairs_per_clump"] == 7
    assert hs["clump_width_scale"] == [[0.0, 1.0, "smooth"], [1.0, 0.2]]
    # float32 values survive exactly.
    assert np.array_equal(np.array(hs["hair_color"], np.float32), np.array([0.1, 0.2, 0.3], np.float32))
    assert back["fur"] == [{"mesh": 1, "réglage": "é"}]
    assert "nan" in scene_folder.dumps({"camera": {"vfov": float("nan")}})
