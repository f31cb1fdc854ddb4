"""Maya scene values as tress scene entries: the pure part of the Maya exporter
(``tress_export.py``), with no Maya import, so it is tested without Maya.

Conventions follow tress's Maya ASCII reader (``docs/scene-format.md``, "Other tools'
scene files"): Maya matrices act on row vectors (translation in the last row); light
colour times intensity, times π for directional, point and spot lights (Maya's shading
has no 1/π); the vertical field of view from focal length, film aperture and film fit.
"""

from __future__ import annotations

import math
import re
from typing import Any, Iterable, Mapping, Sequence

from scene_folder import MeshData, SceneDoc, StrandData, visibility

# [[hair_system]] keys by Maya hairSystem long attribute name, and how each is read.
HAIR_SYSTEM_ATTRIBUTES = {
    "hairsPerClump": ("hairs_per_clump", "int"),
    "subSegments": ("sub_segments", "int"),
    "thinning": ("thinning", "float"),
    "clumpWidth": ("clump_width", "float"),
    "clumpWidthScale": ("clump_width_scale", "ramp"),
    "clumpTwist": ("clump_twist", "float"),
    "clumpCurl": ("clump_curl", "ramp"),
    "clumpFlatness": ("clump_flatness", "ramp"),
    "bendFollow": ("bend_follow", "float"),
    "hairWidth": ("hair_width", "float"),
    "hairWidthScale": ("hair_width_scale", "ramp"),
    "displacementScale": ("displacement_scale", "ramp"),
    "curl": ("curl", "float"),
    "curlFrequency": ("curl_frequency", "float"),
    "noiseMethod": ("noise_method", "noise_method"),
    "noise": ("noise", "float"),
    "noiseFrequency": ("noise_frequency", "float"),
    "noiseFrequencyU": ("noise_frequency_u", "float"),
    "noiseFrequencyV": ("noise_frequency_v", "float"),
    "noiseFrequencyW": ("noise_frequency_w", "float"),
    "hairColor": ("hair_color", "color"),
    "hairColorScale": ("hair_color_scale", "color_ramp"),
    "diffuseRand": ("diffuse_rand", "float"),
    "hueRand": ("hue_rand", "float"),
    "satRand": ("sat_rand", "float"),
    "valRand": ("val_rand", "float"),
    "specularColor": ("specular_color", "color"),
    "specularPower": ("specular_power", "float"),
    "opacity": ("opacity", "float"),
    "translucence": ("translucence", "float"),
    "specularRand": ("specular_rand", "float"),
}

# FurDescription attributes tress reads ([[fur]] keys, Maya's long names in snake case).
FUR_ATTRIBUTES = (
    "density", "global_scale", "segments", "light_model", "length", "baldness", "inclination", "polar", "roll",
    "base_curl", "tip_curl", "scraggle", "scraggle_frequency", "scraggle_correlation", "clumping",
    "clumping_frequency", "clump_shape", "offset", "attraction", "base_width", "tip_width", "base_opacity",
    "tip_opacity", "base_color", "tip_color", "base_ambient_color", "tip_ambient_color", "specular_color",
    "specular_sharpness",
)
FUR_COLORS = {"base_color", "tip_color", "base_ambient_color", "tip_ambient_color", "specular_color"}
FUR_INTEGERS = {"density", "segments", "light_model"}

# A shape's render stats and MtoA's holdout, by long name, with Maya's defaults.
VISIBILITY_ATTRIBUTES = {"primaryVisibility": True, "castsShadows": True, "aiMatte": False}

INTERPOLATIONS = ("none", "linear", "smooth", "spline")
NOISE_METHODS = ("random", "surface_uv", "clump_uv")


def snake_case(name: str) -> str:
    """``BaseColor`` or ``baseColor`` as ``base_color``."""
    return re.sub(r"(?<=[a-z0-9])([A-Z])", r"_\1", name).lower()


def ramp(keys: Iterable[tuple[float, Any, int]]) -> list[list[Any]]:
    """Maya ramp entries (position, value, interpolation enum) as tress ramp keys, sorted
    by position."""
    out = []
    for position, value, interp in sorted(keys, key=lambda k: k[0]):
        v = [float(c) for c in value] if isinstance(value, (list, tuple)) else float(value)
        name = INTERPOLATIONS[int(interp)] if 0 <= int(interp) < len(INTERPOLATIONS) else "linear"
        out.append([float(position), v, name])
    return out


def shape_visibility(values: Mapping[str, Any]) -> dict[str, bool]:
    """The visibility switches of a mesh or hairSystem shape's entry from its
    ``VISIBILITY_ATTRIBUTES`` values by long name (a missing one is Maya's default), as
    tress's Maya ASCII reader reads them: ``primaryVisibility`` off is ``camera_visible =
    false``, ``castsShadows`` off ``casts_shadows = false``, ``aiMatte`` on ``matte``."""
    v = {**VISIBILITY_ATTRIBUTES, **values}
    return visibility(v["primaryVisibility"], v["castsShadows"], v["aiMatte"])


def hair_system_entry(values: Mapping[str, Any], guides_file: str, seed: int = 0):
    """A ``[[hair_system]]`` entry from hairSystem attribute values by long name (ramps
    as lists of (position, value, interp)); returns the entry and warnings."""
    entry: dict[str, Any] = {"file": guides_file, "seed": int(seed)}
    warnings = []
    for name, value in values.items():
        if name not in HAIR_SYSTEM_ATTRIBUTES:
            warnings.append(f"hairSystem attribute {name} is not read by tress")
            continue
        key, kind = HAIR_SYSTEM_ATTRIBUTES[name]
        if kind == "int":
            entry[key] = int(value)
        elif kind == "float":
            entry[key] = float(value)
        elif kind == "color":
            entry[key] = [float(c) for c in _flat3(value)]
        elif kind == "noise_method":
            entry[key] = NOISE_METHODS[int(value)] if 0 <= int(value) < len(NOISE_METHODS) else "random"
        elif kind in ("ramp", "color_ramp"):
            entry[key] = ramp(value)
    return entry, warnings


def fur_entry(mesh_number: int, values: Mapping[str, Any], seed: int = 0):
    """A ``[[fur]]`` entry on mesh ``mesh_number`` (1-based) from FurDescription
    attribute values by Maya long name; returns the entry and warnings."""
    entry: dict[str, Any] = {"mesh": int(mesh_number), "seed": int(seed)}
    warnings = []
    for name, value in values.items():
        key = snake_case(name)
        if key not in FUR_ATTRIBUTES:
            warnings.append(f"FurDescription attribute {name} is not read by tress")
        elif key in FUR_COLORS:
            entry[key] = [float(c) for c in _flat3(value)]
        elif key in FUR_INTEGERS:
            entry[key] = int(round(float(value)))
        else:
            entry[key] = float(value)
    return entry, warnings


def _flat3(value) -> list[float]:
    """A colour as getAttr returns it (``[(r, g, b)]`` or ``(r, g, b)``)."""
    if isinstance(value, (list, tuple)) and len(value) == 1 and isinstance(value[0], (list, tuple)):
        value = value[0]
    values = [float(c) for c in value]
    if len(values) != 3:
        raise ValueError(f"a colour has three values, not {values}")
    return values


def transform_points(points: Sequence[Sequence[float]], matrix: Sequence[float]) -> list[list[float]]:
    """Points times a Maya world matrix (16 values, row-major, row vectors)."""
    m = [list(matrix[i * 4:i * 4 + 4]) for i in range(4)]
    return [[p[0] * m[0][j] + p[1] * m[1][j] + p[2] * m[2][j] + m[3][j] for j in range(3)] for p in points]


def transform_direction(d: Sequence[float], matrix: Sequence[float]) -> list[float]:
    m = [list(matrix[i * 4:i * 4 + 4]) for i in range(4)]
    v = [d[0] * m[0][j] + d[1] * m[1][j] + d[2] * m[2][j] for j in range(3)]
    n = math.sqrt(sum(c * c for c in v)) or 1.0
    return [c / n for c in v]


def vertical_fov(focal_length_mm: float, h_aperture_in: float, v_aperture_in: float, film_fit: int,
                 width: int, height: int) -> float:
    """Vertical field of view in degrees of a Maya camera: film aperture in inches, film
    fit 0 fill, 1 horizontal, 2 vertical, 3 overscan."""
    image_aspect = width / height
    film_aspect = h_aperture_in / v_aperture_in
    if film_fit == 0:
        fit_horizontal = image_aspect > film_aspect
    elif film_fit == 3:
        fit_horizontal = image_aspect < film_aspect
    else:
        fit_horizontal = film_fit == 1
    if fit_horizontal:
        half = math.atan(h_aperture_in * 25.4 / (2.0 * focal_length_mm))
        return math.degrees(2.0 * math.atan(math.tan(half) / image_aspect))
    return math.degrees(2.0 * math.atan(v_aperture_in * 25.4 / (2.0 * focal_length_mm)))


def camera_table(matrix: Sequence[float], vfov: float) -> dict[str, Any]:
    """``[camera]`` of a camera whose world matrix is ``matrix`` (looking down its -Z)."""
    eye = [float(matrix[12]), float(matrix[13]), float(matrix[14])]
    forward = transform_direction([0.0, 0.0, -1.0], matrix)
    up = transform_direction([0.0, 1.0, 0.0], matrix)
    return {"eye": eye, "target": [e + f for e, f in zip(eye, forward)], "up": up, "vfov": float(vfov)}


def light_entry(kind: str, matrix: Sequence[float], color: Sequence[float], intensity: float,
                cone_angle: float = 40.0, penumbra: float = 0.0):
    """A ``[[light]]`` entry of a Maya light node type (``directionalLight``,
    ``pointLight``, ``spotLight``, ``ambientLight``, ``areaLight``), or None."""
    c = [float(x) * float(intensity) for x in _flat3(color)]
    position = [float(matrix[12]), float(matrix[13]), float(matrix[14])]
    if kind == "directionalLight":
        return {"type": "distant", "direction": transform_direction([0.0, 0.0, 1.0], matrix),
                "irradiance": [x * math.pi for x in c]}
    if kind == "pointLight":
        return {"type": "point", "position": position, "intensity": [x * math.pi for x in c]}
    if kind == "spotLight":
        outer = cone_angle / 2.0 + max(0.0, penumbra)
        inner = cone_angle / 2.0 + min(0.0, penumbra)
        forward = transform_direction([0.0, 0.0, -1.0], matrix)
        return {"type": "spot", "position": position, "target": [p + f for p, f in zip(position, forward)],
                "intensity": [x * math.pi for x in c], "inner_angle": max(0.0, inner), "outer_angle": outer}
    if kind == "ambientLight":
        return {"type": "environment", "radiance": c}
    if kind == "areaLight":
        # Maya's area light is the square from -1 to 1 in its XY plane, emitting along -Z;
        # tress's quad emits towards edge_u x edge_v.
        corner, eu, ev = transform_points([[-1.0, -1.0, 0.0], [-1.0, 1.0, 0.0], [1.0, -1.0, 0.0]], matrix)
        return {"type": "quad", "corner": corner, "edge_u": [a - b for a, b in zip(eu, corner)],
                "edge_v": [a - b for a, b in zip(ev, corner)], "radiance": c}
    return None


def strands(curves: Sequence[Sequence[Sequence[float]]], width: float | Sequence[float] = 0.0) -> StrandData:
    """Sampled curves (lists of points) as strands of diameter ``width`` (one per curve,
    or one for all)."""
    points, radius, offsets = [], [], [0]
    widths = [width] * len(curves) if isinstance(width, (int, float)) else list(width)
    for curve, w in zip(curves, widths):
        points.extend([float(c) for c in p[:3]] for p in curve)
        radius.extend([0.5 * float(w)] * len(curve))
        offsets.append(len(points))
    return StrandData(points, radius, offsets)


def mesh(points: Sequence[Sequence[float]], triangles: Sequence[Sequence[int]], normals=None, uvs=None) -> MeshData:
    return MeshData([list(map(float, p[:3])) for p in points], [list(map(int, t)) for t in triangles], normals, uvs)


def scene_doc(camera: Mapping[str, Any], resolution: tuple[int, int]) -> SceneDoc:
    return SceneDoc(camera=camera, render={"resolution": [int(resolution[0]), int(resolution[1])]})
