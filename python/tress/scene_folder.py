"""Writing tress scene folders: ``scene.toml`` with the meshes as OBJ and the strands as
Cem Yuksel ``.hair`` files beside it, in the format of ``docs/scene-format.md``.

Pure Python with no dependency (NumPy arrays are used as they are when given, plain
sequences otherwise), so the Blender add-on and the Maya exporter use it too.

A scene is a :class:`SceneDoc`: the TOML tables as dicts with the scene file's keys, and
the geometry the entries' ``file`` keys name, held in memory until written.
"""

from __future__ import annotations

import json
import math
import os
import re
import struct
import sys
import tempfile
from array import array
from typing import Any, Iterable, Mapping, Sequence

__all__ = ["MeshData", "StrandData", "ImageData", "SceneDoc", "visibility", "dumps", "write_hair", "write_obj", "write_pfm", "write_atomically"]

_BARE_KEY = re.compile(r"^[A-Za-z0-9_-]+$")

# Entries of the scene file that are arrays of tables, in the order they are written, and
# the attribute of SceneDoc holding each.
_ARRAYS = (("light", "lights"), ("mesh", "meshes"), ("hair", "hair"), ("hair_system", "hair_systems"), ("fur", "fur"))


class MeshData:
    """A triangle mesh: ``points`` (n x 3), ``triangles`` (t x 3 vertex indices from 0),
    optional ``normals`` (n x 3) and ``uvs`` (n x 2)."""

    def __init__(self, points, triangles, normals=None, uvs=None):
        self.points = points
        self.triangles = triangles
        self.normals = normals
        self.uvs = uvs


class StrandData:
    """Strands: ``points`` (n x 3), ``radius`` (n: half the thickness), ``offsets``
    (strands + 1: strand i owns points ``offsets[i]:offsets[i + 1]``), optional ``colors``
    (n x 3, linear RGB) and ``opacity`` (n, 1 = opaque)."""

    def __init__(self, points, radius, offsets, colors=None, opacity=None):
        self.points = points
        self.radius = radius
        self.offsets = offsets
        self.colors = colors
        self.opacity = opacity

    @property
    def strand_count(self) -> int:
        return len(self.offsets) - 1


class ImageData:
    """A linear RGB float image, such as an environment map: ``pixels`` (height x width x
    3), top row first. Written as a PFM file (``.pfm``), which tress reads as it reads EXR."""

    def __init__(self, pixels):
        self.pixels = pixels


class SceneDoc:
    """A scene as the tables of its TOML file plus the geometry its entries name.

    ``camera`` and ``render`` are dicts; ``lights``, ``meshes``, ``hair``, ``hair_systems``
    and ``fur`` are lists of dicts, each with the keys of the scene file's entry; ``files``
    maps a file name (relative to the folder) to the :class:`MeshData` or
    :class:`StrandData` written there.
    """

    def __init__(self, camera: Mapping[str, Any] | None = None, render: Mapping[str, Any] | None = None):
        self.camera: dict[str, Any] = dict(camera or {})
        self.render: dict[str, Any] = dict(render or {})
        self.lights: list[dict[str, Any]] = []
        self.meshes: list[dict[str, Any]] = []
        self.hair: list[dict[str, Any]] = []
        self.hair_systems: list[dict[str, Any]] = []
        self.fur: list[dict[str, Any]] = []
        self.files: dict[str, Any] = {}

    def tables(self) -> dict[str, Any]:
        """The whole scene as one dict shaped like the TOML file."""
        out: dict[str, Any] = {"camera": self.camera}
        if self.render:
            out["render"] = self.render
        for key, attr in _ARRAYS:
            entries = getattr(self, attr)
            if entries:
                out[key] = entries
        return out

    def to_toml(self) -> str:
        """The scene file's text."""
        return dumps(self.tables())

    def write(self, folder: str | os.PathLike, name: str = "scene.toml") -> str:
        """Writes the scene file and every geometry file into ``folder`` (created if
        needed), each atomically; returns the scene file's path."""
        folder = os.fspath(folder)
        os.makedirs(folder, exist_ok=True)
        for file, data in self.files.items():
            path = os.path.join(folder, file)
            os.makedirs(os.path.dirname(path) or folder, exist_ok=True)
            if isinstance(data, MeshData) or _has(data, "triangles"):
                write_obj(path, data)
            elif isinstance(data, ImageData):
                write_pfm(path, data)
            else:
                write_hair(path, data)
        scene = os.path.join(folder, name)
        write_atomically(scene, self.to_toml().encode("utf-8"))
        return scene


def visibility(camera_visible: bool = True, casts_shadows: bool = True, matte: bool = False) -> dict[str, bool]:
    """The visibility switches of a ``[[mesh]]``, ``[[hair]]``, ``[[hair_system]]`` or
    ``[[fur]]`` entry (``docs/scene-format.md``, Visibility) that differ from the scene
    file's defaults, to merge into the entry: an exporter hands over what its tool says
    (Blender's ray visibility and holdout, Maya's render stats and ``aiMatte``) and the
    scene file says it only where it is not the default."""
    keys = {"camera_visible": bool(camera_visible), "casts_shadows": bool(casts_shadows), "matte": bool(matte)}
    defaults = {"camera_visible": True, "casts_shadows": True, "matte": False}
    return {k: v for k, v in keys.items() if v != defaults[k]}


def _has(obj: Any, attr: str) -> bool:
    return getattr(obj, attr, None) is not None


# --- TOML --------------------------------------------------------------------------------


def _key(k: str) -> str:
    if not isinstance(k, str):
        raise TypeError(f"TOML keys are strings, not {type(k).__name__} ({k!r})")
    return k if _BARE_KEY.match(k) else json.dumps(k, ensure_ascii=False)


def _value(v: Any) -> str:
    """A TOML value: numbers, booleans, strings, arrays and inline tables."""
    if isinstance(v, bool) or type(v).__name__ == "bool_":
        return "true" if v else "false"
    if hasattr(v, "tolist") and not isinstance(v, (str, bytes)):
        # NumPy scalars and arrays.
        return _value(v.tolist())
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        if math.isnan(v):
            return "nan"
        if math.isinf(v):
            return "inf" if v > 0 else "-inf"
        # repr is the shortest text that reads back as the same double, so a float32
        # value survives the round trip exactly.
        text = repr(v)
        return text if any(c in text for c in ".en") else text + ".0"
    if isinstance(v, str):
        return json.dumps(v, ensure_ascii=False)
    if isinstance(v, os.PathLike):
        return json.dumps(os.fspath(v), ensure_ascii=False)
    if isinstance(v, Mapping):
        return "{ " + ", ".join(f"{_key(k)} = {_value(x)}" for k, x in v.items() if x is not None) + " }" if v else "{}"
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(_value(x) for x in v) + "]"
    raise TypeError(f"{type(v).__name__} ({v!r}) has no TOML form")


def _is_table_array(v: Any) -> bool:
    return isinstance(v, (list, tuple)) and len(v) > 0 and all(isinstance(x, Mapping) for x in v)


def _table_body(table: Mapping[str, Any], path: str, lines: list[str]) -> None:
    """Plain keys first, then sub-arrays of tables (``[[camera.key]]``)."""
    subs = []
    for k, v in table.items():
        if v is None:
            continue
        if path == "camera" and k == "key" and _is_table_array(v):
            subs.append((k, v))
        else:
            lines.append(f"{_key(k)} = {_value(v)}")
    for k, entries in subs:
        for e in entries:
            lines.append("")
            lines.append(f"[[{path}.{_key(k)}]]")
            _table_body(e, f"{path}.{k}", lines)


def dumps(tables: Mapping[str, Any]) -> str:
    """TOML text of a scene shaped like the file: top-level dicts become tables, top-level
    lists of dicts arrays of tables, dicts inside them inline tables; None values are left
    out. Non-finite floats are written as TOML's ``nan``/``inf``, which tress rejects with
    a message naming the key."""
    lines: list[str] = []
    for name, v in tables.items():
        if v is None:
            continue
        if isinstance(v, Mapping):
            if lines:
                lines.append("")
            lines.append(f"[{_key(name)}]")
            _table_body(v, name, lines)
        elif _is_table_array(v):
            for entry in v:
                lines.append("")
                lines.append(f"[[{_key(name)}]]")
                _table_body(entry, name, lines)
        elif isinstance(v, (list, tuple)) and not v:
            continue
        else:
            lines.insert(0, f"{_key(name)} = {_value(v)}")
    return "\n".join(lines) + "\n"


# --- geometry files ----------------------------------------------------------------------


def write_atomically(path: str, data: bytes) -> None:
    """Writes ``data`` to a temporary file beside ``path``, then renames it over ``path``,
    so no half-written file is ever left under the final name."""
    folder = os.path.dirname(os.path.abspath(path))
    fd, tmp = tempfile.mkstemp(prefix=".tress-", suffix=".tmp", dir=folder)
    try:
        with os.fdopen(fd, "wb") as f:
            f.write(data)
            f.flush()
            os.fsync(f.fileno())
        os.chmod(tmp, 0o644)
        os.replace(tmp, path)
    except BaseException:
        try:
            os.unlink(tmp)
        except OSError:
            pass
        raise


def _f32(values: Any, per: int, what: str, count: int | None = None) -> bytes:
    """Little-endian float32 bytes of ``values`` (an array or nested sequences of ``per``
    numbers each)."""
    if hasattr(values, "astype") and hasattr(values, "tobytes"):
        a = values.astype("<f4", copy=False)
        n = a.size // per if per else a.size
        if a.size != n * per or (per > 1 and a.ndim == 2 and a.shape[1] != per):
            raise ValueError(f"{what} must have {per} values per row")
        data = a.tobytes(order="C")
    else:
        flat = array("f")
        for row in values:
            if per == 1:
                flat.append(float(row))
            else:
                r = list(row)
                if len(r) != per:
                    raise ValueError(f"{what} must have {per} values per row, not {len(r)}")
                flat.extend(float(x) for x in r)
        n = len(flat) // per
        if sys.byteorder == "big":
            flat.byteswap()
        data = flat.tobytes()
    if count is not None and n != count:
        raise ValueError(f"{n} {what} for {count} points")
    return data


def _ints(values: Any) -> list[int]:
    return [int(v) for v in (values.tolist() if hasattr(values, "tolist") else values)]


def hair_bytes(strands: Any) -> bytes:
    """The bytes of a ``.hair`` file holding ``strands`` (a :class:`StrandData` or anything
    with the same attributes): segments, points, thickness (twice the radius), and
    transparency (1 - opacity) and colours when present."""
    offsets = _ints(strands.offsets)
    if not offsets or offsets[0] != 0 or any(b < a for a, b in zip(offsets, offsets[1:])):
        raise ValueError("offsets must start at 0 and never decrease")
    n = offsets[-1]
    segments = []
    for a, b in zip(offsets, offsets[1:]):
        if b == a:
            continue  # an empty strand: the format cannot hold one
        if b - a > 65536:
            raise ValueError(f"a strand of {b - a} points is more than a .hair file holds (65536)")
        segments.append(b - a - 1)
    points = _f32(strands.points, 3, "points")
    if len(points) != 12 * n:
        raise ValueError(f"{len(points) // 12} points, but the offsets end at {n}")
    radius = strands.radius
    if hasattr(radius, "astype"):
        thickness = _f32(radius.astype("<f4") * 2, 1, "radii", n)
    else:
        thickness = _f32([2.0 * float(r) for r in radius], 1, "radii", n)
    flags = 1 | 2 | 4
    body = [struct.pack(f"<{len(segments)}H", *segments), points, thickness]
    opacity = getattr(strands, "opacity", None)
    if opacity is not None:
        flags |= 8
        if hasattr(opacity, "astype"):
            body.append(_f32(1 - opacity.astype("<f4"), 1, "opacities", n))
        else:
            body.append(_f32([1.0 - float(o) for o in opacity], 1, "opacities", n))
    colors = getattr(strands, "colors", None)
    if colors is not None:
        flags |= 16
        body.append(_f32(colors, 3, "colours", n))
    first_segments = segments[0] if segments else 0
    first_thickness = struct.unpack("<f", thickness[:4])[0] if n else 0.0
    header = struct.pack(
        "<4sIIIIff3f88s", b"HAIR", len(segments), n, flags, first_segments, first_thickness, 0.0, 1.0, 1.0, 1.0,
        b"written by tress",
    )
    return header + b"".join(body)


def write_hair(path: str, strands: Any) -> None:
    """Writes ``strands`` to a Cem Yuksel ``.hair`` file, atomically."""
    write_atomically(path, hair_bytes(strands))


def _rows(values: Any) -> Iterable[Sequence[Any]]:
    return values.tolist() if hasattr(values, "tolist") else values


def obj_text(mesh: Any) -> str:
    """OBJ text of a mesh (a :class:`MeshData` or anything with its attributes): ``v``,
    optional ``vt`` and ``vn`` lines, and one ``f`` line per triangle. Coordinates are
    written as the shortest text that reads back as the same number."""
    out = []
    points = list(_rows(mesh.points))
    for p in points:
        out.append("v " + " ".join(repr(float(c)) for c in p))
    uvs = getattr(mesh, "uvs", None)
    normals = getattr(mesh, "normals", None)
    if uvs is not None:
        for t in _rows(uvs):
            out.append("vt " + " ".join(repr(float(c)) for c in t))
    if normals is not None:
        for nrm in _rows(normals):
            out.append("vn " + " ".join(repr(float(c)) for c in nrm))
    for tri in _rows(mesh.triangles):
        idx = [int(i) + 1 for i in tri]
        if len(idx) != 3 or min(idx) < 1 or max(idx) > len(points):
            raise ValueError(f"triangle {tri} does not name three of the {len(points)} points")
        if uvs is not None and normals is not None:
            out.append("f " + " ".join(f"{i}/{i}/{i}" for i in idx))
        elif uvs is not None:
            out.append("f " + " ".join(f"{i}/{i}" for i in idx))
        elif normals is not None:
            out.append("f " + " ".join(f"{i}//{i}" for i in idx))
        else:
            out.append("f " + " ".join(str(i) for i in idx))
    return "\n".join(out) + "\n"


def write_obj(path: str, mesh: Any) -> None:
    """Writes a triangle mesh to an OBJ file, atomically."""
    write_atomically(path, obj_text(mesh).encode("ascii"))


def pfm_bytes(image: Any) -> bytes:
    """The bytes of a colour PFM file holding ``image`` (an :class:`ImageData`, or anything
    with its ``pixels``): the ``PF`` header, then little-endian float32 RGB rows from the
    bottom row up, as the format orders them."""
    pixels = image.pixels
    if hasattr(pixels, "shape"):
        if len(pixels.shape) != 3 or pixels.shape[2] != 3:
            raise ValueError(f"image pixels must be height x width x 3, not {tuple(pixels.shape)}")
        height, width = int(pixels.shape[0]), int(pixels.shape[1])
        body = _f32(pixels[::-1].reshape(-1, 3), 3, "pixels")
    else:
        rows = [list(r) for r in pixels]
        height, width = len(rows), len(rows[0]) if rows else 0
        if any(len(r) != width for r in rows):
            raise ValueError("image rows must all have the same width")
        body = _f32([px for r in reversed(rows) for px in r], 3, "pixels")
    if width == 0 or height == 0:
        raise ValueError("an image needs at least one pixel")
    return f"PF\n{width} {height}\n-1.0\n".encode("ascii") + body


def write_pfm(path: str, image: Any) -> None:
    """Writes an RGB image to a PFM file, atomically."""
    write_atomically(path, pfm_bytes(image))
