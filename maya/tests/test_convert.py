"""The Maya exporter's conversions, without Maya: camera, lights, matrices, hair system and
fur attributes, and a folder the command line reads."""

import math
import tomllib

import pytest

import tress_maya_convert as convert
from tress_testing import run_cli

# Maya's default 35 mm camera: 36 x 24 mm film back (1.417 x 0.945 inches).
H_AP, V_AP = 1.41732, 0.94488


def test_vertical_fov_follows_the_film_fit():
    # Vertical fit: the vertical aperture alone.
    assert convert.vertical_fov(35.0, H_AP, V_AP, 2, 640, 480) == pytest.approx(
        math.degrees(2 * math.atan(V_AP * 25.4 / 70.0)))
    # Horizontal fit at 4:3: the horizontal field of view over the image's aspect.
    h = 2 * math.atan(H_AP * 25.4 / 70.0)
    assert convert.vertical_fov(35.0, H_AP, V_AP, 1, 640, 480) == pytest.approx(
        math.degrees(2 * math.atan(math.tan(h / 2) * 480 / 640)))
    # Fill: a wider image than the film fits horizontally, a narrower one vertically.
    assert convert.vertical_fov(35.0, H_AP, V_AP, 0, 1920, 1080) == convert.vertical_fov(35.0, H_AP, V_AP, 1, 1920, 1080)
    assert convert.vertical_fov(35.0, H_AP, V_AP, 0, 480, 640) == convert.vertical_fov(35.0, H_AP, V_AP, 2, 480, 640)
    # Overscan is the opposite of fill.
    assert convert.vertical_fov(35.0, H_AP, V_AP, 3, 1920, 1080) == convert.vertical_fov(35.0, H_AP, V_AP, 2, 1920, 1080)


def rotation_x(degrees, translate=(0.0, 0.0, 0.0)):
    """A Maya world matrix (row vectors) rotating about X, then translating."""
    c, s = math.cos(math.radians(degrees)), math.sin(math.radians(degrees))
    return [1, 0, 0, 0, 0, c, s, 0, 0, -s, c, 0, *translate, 1]


def test_matrices_act_on_row_vectors():
    m = rotation_x(90.0, (1.0, 2.0, 3.0))
    assert convert.transform_points([[0.0, 1.0, 0.0]], m)[0] == pytest.approx([1.0, 2.0, 4.0])
    cam = convert.camera_table(m, 30.0)
    assert cam["eye"] == [1.0, 2.0, 3.0]
    # The row vector (0, 0, -1) times the rotation is minus its third row, (0, 1, 0): the
    # camera looks along +Y, and its up (0, 1, 0) turns to +Z.
    assert cam["target"] == pytest.approx([1.0, 3.0, 3.0])
    assert cam["up"] == pytest.approx([0.0, 0.0, 1.0])


def test_lights_follow_the_maya_ascii_reader():
    m = rotation_x(-90.0)  # local +Z turned to +Y: a directional light shining down
    sun = convert.light_entry("directionalLight", m, [(1.0, 0.5, 0.25)], 2.0)
    assert sun["type"] == "distant" and sun["direction"] == pytest.approx([0.0, 1.0, 0.0])
    assert sun["irradiance"] == pytest.approx([2 * math.pi, math.pi, math.pi / 2])
    point = convert.light_entry("pointLight", rotation_x(0, (0, 5, 0)), (1, 1, 1), 1.0)
    assert point == {"type": "point", "position": [0.0, 5.0, 0.0], "intensity": pytest.approx([math.pi] * 3)}
    spot = convert.light_entry("spotLight", rotation_x(0), (1, 1, 1), 1.0, cone_angle=40.0, penumbra=10.0)
    assert (spot["inner_angle"], spot["outer_angle"]) == (20.0, 30.0)
    assert spot["target"] == pytest.approx([0.0, 0.0, -1.0])
    spot = convert.light_entry("spotLight", rotation_x(0), (1, 1, 1), 1.0, cone_angle=40.0, penumbra=-5.0)
    assert (spot["inner_angle"], spot["outer_angle"]) == (15.0, 20.0)
    assert convert.light_entry("ambientLight", m, (0.1, 0.2, 0.3), 2.0) == {
        "type": "environment", "radiance": pytest.approx([0.2, 0.4, 0.6])}
    quad = convert.light_entry("areaLight", rotation_x(0), (1, 1, 1), 1.0)
    u, v = quad["edge_u"], quad["edge_v"]
    normal = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
    assert normal == pytest.approx([0.0, 0.0, -4.0]), "emits along Maya's -Z"
    assert convert.light_entry("volumeLight", m, (1, 1, 1), 1.0) is None


def test_attributes_become_scene_keys():
    entry, warnings = convert.hair_system_entry(
        {"hairsPerClump": 12.0, "clumpWidth": 0.2, "hairColor": [(0.3, 0.2, 0.1)], "noiseMethod": 2,
         "clumpWidthScale": [(1.0, 0.2, 1), (0.0, 1.0, 2)], "startCurveAttract": 0.5}, "g.hair", seed=4)
    assert entry == {"file": "g.hair", "seed": 4, "hairs_per_clump": 12, "clump_width": 0.2,
                     "hair_color": [0.3, 0.2, 0.1], "noise_method": "clump_uv",
                     "clump_width_scale": [[0.0, 1.0, "smooth"], [1.0, 0.2, "linear"]]}
    assert warnings == ["hairSystem attribute startCurveAttract is not read by tress"]
    fur, warnings = convert.fur_entry(1, {"Density": 2000.4, "BaseColor": [(0.5, 0.4, 0.3)], "Length": 0.3,
                                          "BaseWidth": 0.01, "FurAccuracy": 1.0})
    assert fur == {"mesh": 1, "seed": 0, "density": 2000, "base_color": [0.5, 0.4, 0.3], "length": 0.3,
                   "base_width": 0.01}
    assert warnings == ["FurDescription attribute FurAccuracy is not read by tress"]
    assert convert.snake_case("ScraggleFrequency") == "scraggle_frequency"


def test_render_stats_become_visibility_switches():
    # As tress's .ma reader takes them: Maya's defaults write nothing.
    assert convert.shape_visibility({}) == {}
    assert convert.shape_visibility({"primaryVisibility": True, "castsShadows": True, "aiMatte": False}) == {}
    assert convert.shape_visibility({"primaryVisibility": False}) == {"camera_visible": False}
    assert convert.shape_visibility({"castsShadows": 0, "aiMatte": 1}) == {"casts_shadows": False, "matte": True}


def test_a_converted_scene_is_read_and_rendered_by_the_command_line(tmp_path, tress_cli):
    doc = convert.scene_doc(convert.camera_table(rotation_x(0, (0.0, 0.0, 4.0)), 40.0), (32, 24))
    doc.render["spp"] = 1
    doc.lights.append(convert.light_entry("directionalLight", rotation_x(-45.0), (1, 1, 1), 1.0))
    # A square (two triangles) and four guides rising from it.
    doc.files["plane.obj"] = convert.mesh([[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]], [[0, 1, 2], [0, 2, 3]])
    doc.meshes.append({"file": "plane.obj", "material": {"type": "diffuse", "color": [0.4, 0.4, 0.4]}})
    guides = [[[x, y, 0.0], [x, y, 0.3], [x, y + 0.2, 0.6]] for x in (-0.5, 0.5) for y in (-0.5, 0.5)]
    doc.files["g.hair"] = convert.strands(guides)
    entry, _ = convert.hair_system_entry({"hairsPerClump": 5, "clumpWidth": 0.2, "hairWidth": 0.01,
                                          "clumpWidthScale": [(0.0, 1.0, 1), (1.0, 0.3, 2)]}, "g.hair")
    doc.hair_systems.append({**entry, **convert.shape_visibility({"castsShadows": False})})
    fur, _ = convert.fur_entry(1, {"Density": 200, "Length": 0.2, "BaseWidth": 0.01, "TipWidth": 0.005,
                                   "BaseCurl": 0.5, "TipCurl": 0.5, "Segments": 3})
    doc.fur.append(fur)
    scene = doc.write(tmp_path / "maya")
    (system,) = tomllib.loads(open(scene).read())["hair_system"]
    assert system["hairs_per_clump"] == 5 and system["casts_shadows"] is False
    info = run_cli(tress_cli, "info", scene).stdout
    assert "meshes        1 (2 triangles)" in info
    assert "strand sets   2" in info
    out = tmp_path / "maya.exr"
    run_cli(tress_cli, "render", scene, "-o", out, "--quiet")
    assert out.stat().st_size > 0
