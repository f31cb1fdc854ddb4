"""The Principled Hair BSDF mapping (plain Python: runs without Blender)."""

import math

import pytest

from tress_addon import materials


def test_principled_hair_maps_as_documented():
    values = {"Melanin": 0.6, "Melanin Redness": 0.3, "Roughness": 0.25, "Radial Roughness": 0.4,
              "Offset": math.radians(3.0), "IOR": 1.6, "Coat": 0.0, "Tint": (1.0, 1.0, 1.0)}
    m, warnings = materials.principled_hair(values, "MELANIN")
    q = -math.log(1 - 0.6)
    assert m["type"] == "physical" and warnings == []
    assert m["eumelanin"] == pytest.approx(q * 0.7) and m["pheomelanin"] == pytest.approx(q * 0.3)
    assert (m["beta_m"], m["beta_n"]) == (0.25, 0.4)
    assert m["alpha"] == pytest.approx(3.0) and m["eta"] == pytest.approx(1.6)
    # Absorption: the colour whose inversion (Chiang §4.2) gives the coefficient back.
    sigma = (0.2, 0.5, 1.3)
    m, _ = materials.principled_hair({"Absorption Coefficient": sigma, "Radial Roughness": 0.3}, "ABSORPTION")
    p = materials.color_polynomial(0.3)
    back = [(math.log(c) / p) ** 2 for c in m["color"]]
    assert back == pytest.approx(list(sigma), rel=1e-9)
    m, _ = materials.principled_hair({"Color": (0.3, 0.2, 0.1)}, "COLOR")
    assert m["color"] == [0.3, 0.2, 0.1]
    _, warnings = materials.principled_hair({"Coat": 0.5, "Random Color": 0.2, "Tint": (1, 0.5, 0.5)}, "MELANIN")
    assert len(warnings) == 3 and any("Coat 0.5" in w for w in warnings)


def test_other_shaders_map_to_the_nearest_material():
    assert materials.surface("ShaderNodeBsdfPrincipled", {"Base Color": (0.2, 0.3, 0.4, 1.0)}) == (
        {"type": "diffuse", "color": [0.2, 0.3, 0.4]}, [])
    m, w = materials.surface("ShaderNodeBsdfPrincipled", {"Base Color": (1, 1, 1, 1), "Metallic": 1.0})
    assert m["type"] == "mirror" and w
    m, _ = materials.surface("ShaderNodeBsdfGlass", {"Color": (1, 1, 1, 1), "IOR": 1.33})
    assert m == {"type": "glass", "ior": 1.33, "color": [1.0, 1.0, 1.0]}
    m, _ = materials.surface("ShaderNodeBsdfHair", {"Color": (0.3, 0.2, 0.1, 1.0)})
    assert m == {"type": "tube", "diffuse": [0.3, 0.2, 0.1]}
    m, w = materials.surface("ShaderNodeEmission", {"Color": (1, 0, 0, 1)})
    assert m["type"] == "diffuse" and "ShaderNodeEmission is not mapped" in w[0]


def test_the_zip_holds_the_add_on_with_its_links_resolved(tmp_path):
    import ast
    import importlib.util
    import zipfile
    from pathlib import Path

    here = Path(__file__).resolve().parents[1]
    spec = importlib.util.spec_from_file_location("make_zip", here / "make_zip.py")
    make_zip = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(make_zip)
    path = make_zip.make_zip(str(tmp_path / "tress_addon.zip"))
    with zipfile.ZipFile(path) as z:
        names = set(z.namelist())
        assert {"tress_addon/__init__.py", "tress_addon/engine.py", "tress_addon/export.py",
                "tress_addon/scene_folder.py", "tress_addon/blender_manifest.toml"} <= names
        init = ast.parse(z.read("tress_addon/__init__.py"))
        bl_info = next(n for n in init.body if isinstance(n, ast.Assign) and n.targets[0].id == "bl_info")
        assert ast.literal_eval(bl_info.value)["name"] == "tress"
        shared = (here.parent / "python" / "tress" / "scene_folder.py").read_bytes()
        assert z.read("tress_addon/scene_folder.py") == shared
