import os
from typing import Any, Literal, Sequence, Union, overload

import numpy as np
import numpy.typing as npt

from . import qmc as qmc

MAX_POINTS: int

_Bounds = Union[Sequence[float], Sequence[Sequence[float]], npt.ArrayLike, None]
_Points = Union[npt.ArrayLike, Sequence[npt.ArrayLike]]

def generate(
    method: str,
    *,
    count: int | None = ...,
    radius: float | None = ...,
    dim: int = ...,
    bounds: _Bounds = ...,
    torus: bool = ...,
    seed: int = ...,
    threads: int = ...,
    max_points: int = ...,
    dtype: npt.DTypeLike = ...,
    density: npt.ArrayLike | None = ...,
    radius_range: tuple[float, float] | None = ...,
    invert: bool = ...,
    mask: npt.ArrayLike | None = ...,
    fixed: npt.ArrayLike | None = ...,
    **params: float,
) -> npt.NDArray[np.float64] | npt.NDArray[np.float32]: ...
def generate_classes(
    radii: Sequence[float] | npt.ArrayLike,
    *,
    matrix: npt.ArrayLike | None = ...,
    dim: int = ...,
    bounds: _Bounds = ...,
    torus: bool = ...,
    seed: int = ...,
    max_points: int = ...,
    failures: int = ...,
) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.uint32]]: ...
def tile(
    method: str,
    *,
    count: int | None = ...,
    radius: float | None = ...,
    dim: int = ...,
    seed: int = ...,
    threads: int = ...,
    **params: float,
) -> npt.NDArray[np.float64]: ...
def methods() -> list[dict[str, Any]]: ...
def analyze(
    points: _Points,
    *,
    bounds: _Bounds = ...,
    torus: bool = ...,
    radius: float | None = ...,
    max_frequency: int = ...,
    spectrum: bool = ...,
    pcf_r_max: float = ...,
    pcf_bandwidth: float = ...,
) -> dict[str, Any]: ...
def periodogram(
    points: _Points, *, bounds: _Bounds = ..., torus: bool = ..., max_frequency: int = ...
) -> npt.NDArray[np.float64]: ...
def radial_power(
    points: _Points, *, bounds: _Bounds = ..., torus: bool = ..., max_frequency: int = ...
) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64], npt.NDArray[np.float64]]: ...
def pair_correlation(
    points: _Points,
    *,
    bounds: _Bounds = ...,
    torus: bool = ...,
    r_max: float = ...,
    bandwidth: float = ...,
    steps: int = ...,
) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]: ...
def discrepancy(
    points: npt.ArrayLike, method: str | None = ..., *, bounds: _Bounds = ..., kind: str | None = ...
) -> float: ...
def min_distance(
    points: npt.ArrayLike, *, bounds: _Bounds = ..., torus: bool = ...
) -> tuple[float, int | None, int | None]: ...
@overload
def read_chunks(path: str | os.PathLike[str]) -> npt.NDArray[np.float64]: ...
@overload
def read_chunks(
    path: str | os.PathLike[str], *, with_region: Literal[True]
) -> tuple[npt.NDArray[np.float64], list[float], bool]: ...
@overload
def read_chunks(
    path: str | os.PathLike[str], *, with_region: bool
) -> npt.NDArray[np.float64] | tuple[npt.NDArray[np.float64], list[float], bool]: ...
def render(
    scene: str = ...,
    sampler: str = ...,
    *,
    spp: int = ...,
    size: tuple[int, int] = ...,
    filter: str = ...,
    seed: int = ...,
    tile_count: int = ...,
    threads: int = ...,
    **params: float,
) -> npt.NDArray[np.float64]: ...
