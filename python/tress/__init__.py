"""tress from Python: render hair and fur scenes to NumPy arrays.

Load any scene the ``tress`` command renders, or build one in code with the scene file's
own keys (``docs/scene-format.md``) and geometry from NumPy arrays::

    import numpy as np, tress

    scene = tress.Scene(camera={"eye": [0, 0, 4], "target": [0, 0, 0]},
                        render={"resolution": [64, 48], "spp": 4})
    scene.add_light(type="distant", direction=[0, 1, 1], irradiance=[3, 3, 3])
    scene.add_hair(points=pts, radius=r, offsets=offs,
                   material={"type": "physical", "eumelanin": 1.3})
    image = tress.render(scene, spp=8, progress=lambda done, total: print(done, total))
    rgba = np.asarray(image)           # (H, W, 4) float32, linear
    depth = image.aov("Z")             # (H, W)
    tress.export(scene, "farm/groom")  # scene.toml + .hair + .obj, for the command line

Errors in a scene raise :class:`TressError` with the command line's message.
"""

from __future__ import annotations

import os
from typing import Any, Callable, Mapping

import numpy as np

from . import scene_folder
from ._tress import Description, Image, Mesh, Strands, TressError
from ._tress import export_shapes as _export_shapes
from ._tress import info as _info
from ._tress import load as _load
from ._tress import parse as _parse
from ._tress import read_exr
from ._tress import render as _render

__all__ = [
    "Scene",
    "Mesh",
    "Strands",
    "Image",
    "Description",
    "TressError",
    "load",
    "render",
    "export",
    "read_exr",
]

__version__ = "0.1.0"

# The file name a scene built in Python reports in messages and resolves relative paths
# from (the current directory).
_SCENE_NAME = "scene.toml"


def _mesh(points, triangles, normals=None, uvs=None) -> Mesh:
    f32 = lambda a: None if a is None else np.ascontiguousarray(a, dtype=np.float32)
    return Mesh(f32(points), np.ascontiguousarray(triangles, dtype=np.uint32), f32(normals), f32(uvs))


def _strands(points, radius, offsets, colors=None, opacity=None) -> Strands:
    points = np.ascontiguousarray(points, dtype=np.float32)
    radius = np.asarray(radius, dtype=np.float32)
    if radius.ndim == 0:
        radius = np.full(len(points), radius, dtype=np.float32)
    opacity_array = None if opacity is None else np.asarray(opacity, dtype=np.float32)
    if opacity_array is not None and opacity_array.ndim == 0:
        opacity_array = np.full(len(points), opacity_array, dtype=np.float32)
    return Strands(
        points,
        np.ascontiguousarray(radius),
        np.ascontiguousarray(offsets, dtype=np.uint32),
        None if colors is None else np.ascontiguousarray(colors, dtype=np.float32),
        None if opacity_array is None else np.ascontiguousarray(opacity_array),
    )


class Scene(scene_folder.SceneDoc):
    """A scene built in code. Every ``add_*`` takes the keys of the scene file's entry
    (``[[light]]``, ``[[mesh]]``, ``[[hair]]``, ``[[hair_system]]``, ``[[fur]]``) as keyword
    arguments, with geometry from arrays in place of ``file``; they return the entry's
    1-based number (what ``[[fur]] mesh`` and error messages count).

    ``camera`` and ``render`` are the ``[camera]`` and ``[render]`` tables. The scene is
    checked by tress's own scene reader when it is rendered, exported or asked for its
    ``info()``, so keys, defaults and messages are the scene file's.
    """

    def __init__(self, camera: Mapping[str, Any] | None = None, render: Mapping[str, Any] | None = None):
        super().__init__(camera, render)
        # (kind, 0-based index, native geometry) of entries whose geometry is in memory.
        self._inline: list[tuple[str, int, Any]] = []

    def _geometry_file(self, kind: str, index: int, data: Any, ext: str) -> str:
        name = f"{kind}_{index + 1}.{ext}"
        self.files[name] = data
        self._inline.append((kind, index, data))
        return name

    def add_light(self, **keys: Any) -> int:
        """A ``[[light]]`` entry, e.g. ``add_light(type="distant", direction=[0, 1, 0],
        irradiance=[3, 3, 3])``."""
        self.lights.append(dict(keys))
        return len(self.lights)

    def add_mesh(self, points=None, triangles=None, *, normals=None, uvs=None, **keys: Any) -> int:
        """A ``[[mesh]]`` entry: from arrays (``points`` (n, 3), ``triangles`` (t, 3)
        vertex indices from 0, optional ``normals``, ``uvs``), or with the file's ``file``
        or ``shape`` key. ``material`` and ``transform`` as in the file."""
        entry = dict(keys)
        if points is not None or triangles is not None:
            if "file" in entry or "shape" in entry:
                raise ValueError("give the mesh as arrays or as `file`/`shape`, not both")
            if points is None or triangles is None:
                raise ValueError("a mesh from arrays needs both points and triangles")
            mesh = _mesh(points, triangles, normals, uvs)
            entry = {"file": self._geometry_file("mesh", len(self.meshes), mesh, "obj"), **entry}
        self.meshes.append(entry)
        return len(self.meshes)

    def add_hair(self, points=None, radius=None, offsets=None, *, colors=None, opacity=None, **keys: Any) -> int:
        """A ``[[hair]]`` entry: strands from arrays (``points`` (n, 3), ``radius`` (n,)
        or one number, ``offsets`` (strands + 1,) from 0 to n, optional per-point
        ``colors`` (n, 3) and ``opacity``), or from a ``.hair`` ``file``. ``material``,
        ``transform``, ``radius_scale``, ``file_colors`` and ``lod`` as in the file."""
        entry = dict(keys)
        if points is not None:
            if "file" in entry:
                raise ValueError("give the strands as arrays or as `file`, not both")
            if radius is None or offsets is None:
                raise ValueError("strands from arrays need points, radius and offsets")
            strands = _strands(points, radius, offsets, colors, opacity)
            entry = {"file": self._geometry_file("hair", len(self.hair), strands, "hair"), **entry}
        self.hair.append(entry)
        return len(self.hair)

    def add_hair_system(self, guides=None, **keys: Any) -> int:
        """A ``[[hair_system]]`` entry (Maya's hair system): guide curves as
        :class:`Strands` or a ``(points, offsets)`` pair, or the file's ``file`` or
        ``follicles`` key; every attribute by its scene-file name (``hairs_per_clump``,
        ``clump_width``, ramps, ...)."""
        entry = dict(keys)
        if guides is not None:
            if "file" in entry or "follicles" in entry:
                raise ValueError("give the guides as arrays or as `file`/`follicles`, not both")
            if not isinstance(guides, Strands):
                points, offsets = guides
                guides = _strands(points, 0.0, offsets)
            entry = {"file": self._geometry_file("hair_system", len(self.hair_systems), guides, "hair"), **entry}
        self.hair_systems.append(entry)
        return len(self.hair_systems)

    def add_fur(self, mesh: int, guides=None, **keys: Any) -> int:
        """A ``[[fur]]`` entry on mesh number ``mesh`` (1-based): ``preset``, ``seed``,
        ``placement`` and every fur attribute by its long or Maya short name; optional
        attractor ``guides`` as :class:`Strands` or ``(points, offsets)``."""
        entry = {"mesh": mesh, **keys}
        if guides is not None:
            if not isinstance(guides, Strands):
                points, offsets = guides
                guides = _strands(points, 0.0, offsets)
            name = f"fur_{len(self.fur) + 1}_guides.hair"
            self.files[name] = guides
            self._inline.append(("fur_guides", len(self.fur), guides))
            entry["guides"] = name
        self.fur.append(entry)
        return len(self.fur)

    def description(self) -> Description:
        """The scene as tress reads it (raises :class:`TressError` with the scene file's
        messages when a key or value is wrong)."""
        return _parse(self.to_toml(), os.path.join(os.getcwd(), _SCENE_NAME), self._inline)

    def info(self) -> dict[str, Any]:
        """Counts (meshes, triangles, strand sets, strands, segments, lights) and memory
        in bytes (``memory``: measured after building; ``estimate``: tress's estimate
        before it), as ``tress info`` prints them."""
        return _info(self.description())


def load(path: str | os.PathLike, frame: int | None = None) -> Description:
    """Reads any scene ``tress render`` reads: a scene TOML, Maya ASCII (``.ma``),
    pbrt-v4 (``.pbrt``) or USD text (``.usda``) file, or a reference scene directory.
    ``frame`` picks a frame of an animated scene. Raises :class:`TressError`."""
    return _load(os.fspath(path), frame)


def _description(scene: Scene | Description) -> Description:
    if isinstance(scene, Description):
        return scene
    if isinstance(scene, Scene):
        return scene.description()
    raise TypeError(f"expected a tress.Scene or tress.Description, not {type(scene).__name__}")


def render(
    scene: Scene | Description,
    *,
    spp: int | None = None,
    threads: int | None = None,
    seed: int | None = None,
    integrator: str | None = None,
    resolution: tuple[int, int] | None = None,
    transparency_layers: int | None = None,
    lod: bool | None = None,
    progress: Callable[[int, int], Any] | None = None,
    preview: Callable[[Image], Any] | None = None,
    preview_interval: float = 1.0,
) -> Image:
    """Renders ``scene``; keyword arguments override its ``[render]`` settings as the
    command line's options do (``integrator``: ``"direct"``, ``"final-gather"`` or
    ``"path"``; ``threads=0``: every core). The result is the same bit for bit as
    ``tress render`` of the same scene, for any thread count.

    The GIL is released while rendering. ``progress(done_tiles, total_tiles)`` is called
    as tiles finish; it may return ``False`` to stop the render, which then returns the
    tiles done so far (``image.complete`` is False). ``preview(image)`` gets the partial
    image about every ``preview_interval`` seconds. Ctrl-C stops the render and raises
    KeyboardInterrupt; an exception in a callback stops it and is raised.
    """
    return _render(
        _description(scene),
        spp=spp,
        threads=threads,
        seed=seed,
        integrator=integrator,
        resolution=None if resolution is None else (int(resolution[0]), int(resolution[1])),
        transparency_layers=transparency_layers,
        lod=lod,
        progress=progress,
        preview=preview,
        preview_interval=preview_interval,
    )


def info(scene: Scene | Description) -> dict[str, Any]:
    """See :meth:`Scene.info`."""
    return _info(_description(scene))


def export(scene: Scene | Description, path: str | os.PathLike) -> str:
    """Writes ``scene`` out. To a folder (a path without an extension):
    ``scene.toml`` with the meshes as OBJ and the strands as ``.hair`` files beside it, for
    ``tress render folder/scene.toml`` (a :class:`Scene` built in code only). To a
    ``.hair`` file: every render strand in world space; to ``.usda``: strands and meshes
    (as ``tress export``). Returns the path written."""
    path = os.fspath(path)
    ext = os.path.splitext(path)[1].lower()
    if ext:
        # A file: `tress export`'s formats (and its message for any other).
        _export_shapes(_description(scene), path)
        return path
    if not isinstance(scene, Scene):
        raise TressError(
            f"{path}: a scene read from a file is exported to a .hair or .usda file; its own file is the scene folder"
        )
    scene.description()  # the same checks as a render, before anything is written
    return scene.write(path)
