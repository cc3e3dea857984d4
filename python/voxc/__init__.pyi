# Type stubs for voxc (the module is voxc._native, built with pybind11 over libvoxc).
import os
from typing import Callable, Mapping, Optional, Sequence, Tuple, Union, overload

import numpy as np
import numpy.typing as npt

__version__: str

Vec3 = Tuple[int, int, int]
Region = Tuple[Vec3, Vec3]
# Called between steps with the phase ("check", "compile", "generate", "mesh") and the fraction
# of it done; returning False stops the call (Cancelled), raising stops it with that exception.
Progress = Callable[[str, float], Optional[bool]]
Source = Union[str, os.PathLike[str]]

class Error(Exception): ...
class UserError(Error): ...
class InternalError(Error): ...
class Cancelled(Error): ...

class Diagnostic:
    """One diagnostic of a check, as `voxc check` reports it."""
    @property
    def code(self) -> str: ...
    @property
    def severity(self) -> str: ...  # "error", "warning" or "note"
    @property
    def file(self) -> str: ...
    @property
    def line(self) -> int: ...  # 1-based; 0: about the whole file
    @property
    def column(self) -> int: ...
    @property
    def length(self) -> int: ...
    @property
    def message(self) -> str: ...
    @property
    def rendered(self) -> str: ...  # file:line:col: error CODE: message, the line and a caret

class Mesh:
    """A marching-cubes mesh, closed and manifold, in world coordinates; the arrays view its memory."""
    @property
    def vertices(self) -> npt.NDArray[np.float32]: ...  # (n, 3)
    @property
    def normals(self) -> npt.NDArray[np.float32]: ...  # (n, 3), unit, from solid to air
    @property
    def triangles(self) -> npt.NDArray[np.uint32]: ...  # (m, 3), counter-clockwise seen from air
    @property
    def materials(self) -> npt.NDArray[np.uint8]: ...  # (m,), material id per triangle
    @property
    def lod(self) -> int: ...

class Grid:
    """Generated densities and material ids; the arrays are views of the grid (no copy)."""
    @property
    def density(self) -> npt.NDArray[np.float32]: ...  # (size_x, size_y, size_z), [x, y, z]
    @property
    def material(self) -> npt.NDArray[np.uint8]: ...  # same shape; 0 is none
    @property
    def size(self) -> Vec3: ...
    @property
    def origin(self) -> Vec3: ...
    @overload
    def mesh(self, iso: float = 0.5, lod: int = 0, progress: Optional[Progress] = None) -> Mesh: ...
    @overload
    def mesh(self, iso: float = 0.5, lod: Sequence[int] = ..., progress: Optional[Progress] = None) -> list[Mesh]: ...

class Program:
    """A checked and compiled .vox file (a path, or text=), or a compiled package (package=)."""
    def __init__(
        self,
        source: Optional[Source] = None,
        *,
        text: Optional[str] = None,
        package: Optional[str] = None,
        name: str = "<text>.vox",
        seed: Optional[int] = None,
        chunk: Optional[int] = None,
        overrides: Optional[Mapping[str, float]] = None,
        progress: Optional[Progress] = None,
    ) -> None: ...
    @property
    def size(self) -> Vec3: ...
    @property
    def origin(self) -> Vec3: ...
    @property
    def materials(self) -> dict[int, str]: ...
    @property
    def material_colors(self) -> dict[int, Tuple[float, float, float]]: ...
    @property
    def pipeline_counts(self) -> Tuple[int, int]: ...
    def run(
        self, region: Optional[Region] = None, device: str = "auto", progress: Optional[Progress] = None
    ) -> Grid: ...
    @overload
    def mesh(
        self,
        region: Optional[Region] = None,
        device: str = "auto",
        iso: float = 0.5,
        lod: int = 0,
        progress: Optional[Progress] = None,
    ) -> Mesh: ...
    @overload
    def mesh(
        self,
        region: Optional[Region] = None,
        device: str = "auto",
        iso: float = 0.5,
        lod: Sequence[int] = ...,
        progress: Optional[Progress] = None,
    ) -> list[Mesh]: ...

def check(
    source: Optional[Source] = None,
    *,
    text: Optional[str] = None,
    name: str = "<text>.vox",
    seed: Optional[int] = None,
    overrides: Optional[Mapping[str, float]] = None,
) -> list[Diagnostic]: ...
