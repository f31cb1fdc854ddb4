"""Type stubs of the native module ``tress._tress`` (see ``tress`` for the documentation)."""

from os import PathLike
from typing import Any, Callable, Sequence

import numpy as np
import numpy.typing as npt

__version__: str

class TressError(Exception):
    """A scene or file tress cannot use; the message is the command line's."""

class Description:
    """A scene description as tress reads it, before any geometry is loaded."""

    @property
    def warnings(self) -> list[str]: ...
    @property
    def settings(self) -> dict[str, Any]:
        """The ``[render]`` settings: resolution, spp, seed, max_depth,
        indirect_hair_roughness, threads, lod, integrator, transparency_layers, gather_rays."""

class Mesh:
    """A triangle mesh from arrays: points (n, 3), triangles (t, 3), optional normals
    (n, 3) and uvs (n, 2)."""

    def __init__(
        self,
        points: npt.NDArray[np.float32],
        triangles: npt.NDArray[np.uint32],
        normals: npt.NDArray[np.float32] | None = None,
        uvs: npt.NDArray[np.float32] | None = None,
    ) -> None: ...
    @property
    def points(self) -> npt.NDArray[np.float32]: ...
    @property
    def triangles(self) -> npt.NDArray[np.uint32]: ...
    @property
    def normals(self) -> npt.NDArray[np.float32] | None: ...
    @property
    def uvs(self) -> npt.NDArray[np.float32] | None: ...

class Strands:
    """Strands from arrays: points (n, 3), radius (n,), offsets (strands + 1,), optional
    colors (n, 3) and opacity (n,)."""

    def __init__(
        self,
        points: npt.NDArray[np.float32],
        radius: npt.NDArray[np.float32],
        offsets: npt.NDArray[np.uint32],
        colors: npt.NDArray[np.float32] | None = None,
        opacity: npt.NDArray[np.float32] | None = None,
    ) -> None: ...
    @property
    def points(self) -> npt.NDArray[np.float32]: ...
    @property
    def radius(self) -> npt.NDArray[np.float32]: ...
    @property
    def offsets(self) -> npt.NDArray[np.uint32]: ...
    @property
    def colors(self) -> npt.NDArray[np.float32] | None: ...
    @property
    def opacity(self) -> npt.NDArray[np.float32] | None: ...
    @property
    def strand_count(self) -> int: ...
    @property
    def point_count(self) -> int: ...
    def __len__(self) -> int: ...

class Image:
    """A rendered image; ``numpy.asarray(image)`` is RGBA float32 (height, width, 4)."""

    @property
    def width(self) -> int: ...
    @property
    def height(self) -> int: ...
    @property
    def complete(self) -> bool: ...
    @property
    def warnings(self) -> list[str]: ...
    @property
    def rays(self) -> int: ...
    @property
    def seconds(self) -> float: ...
    @property
    def rgba(self) -> npt.NDArray[np.float32]: ...
    @property
    def aov_names(self) -> list[str]: ...
    def aov(self, name: str) -> npt.NDArray[np.float32]:
        """An AOV by EXR channel name (``Z``, ``objectId``, ``strandId``, ``N.X``, ...) as
        (height, width), or a group (``N``, ``rootUV``, ``RGB``, ``RGBA``) as (height, width, k)."""
    def aovs(self) -> dict[str, npt.NDArray[np.float32]]: ...
    def save(self, path: str | PathLike[str]) -> None: ...
    def __array__(self, dtype: Any = None, copy: bool | None = None) -> npt.NDArray[Any]: ...

def load(path: str | PathLike[str], frame: int | None = None) -> Description: ...
def parse(text: str, path: str | PathLike[str], inline: Sequence[tuple[str, int, Mesh | Strands]]) -> Description: ...
def render(
    scene: Description,
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
) -> Image: ...
def info(scene: Description) -> dict[str, Any]: ...
def export_shapes(scene: Description, path: str | PathLike[str]) -> None: ...
def read_exr(path: str | PathLike[str]) -> Image: ...
