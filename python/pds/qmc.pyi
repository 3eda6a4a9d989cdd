from typing import Any, Literal

import numpy as np
import numpy.typing as npt

_Seed = int | np.integer | np.random.Generator | np.random.RandomState | np.random.SeedSequence | None

class PoissonDisk:
    d: int
    radius: float
    hypersphere: str
    ncandidates: int
    method: str
    threads: int
    num_generated: int
    l_bounds: npt.NDArray[np.float64]
    u_bounds: npt.NDArray[np.float64]
    def __init__(
        self,
        d: int,
        *,
        radius: float = ...,
        hypersphere: Literal["volume", "surface"] = ...,
        ncandidates: int = ...,
        optimization: None = ...,
        seed: _Seed = ...,
        l_bounds: npt.ArrayLike | None = ...,
        u_bounds: npt.ArrayLike | None = ...,
        rng: _Seed = ...,
        method: str = ...,
        threads: int = ...,
    ) -> None: ...
    def random(self, n: int | float = ..., *, workers: int = ...) -> npt.NDArray[np.float64]: ...
    def fill_space(self) -> npt.NDArray[np.float64]: ...
    def reset(self) -> PoissonDisk: ...
    def fast_forward(self, n: int) -> PoissonDisk: ...
    def integers(
        self,
        l_bounds: npt.ArrayLike,
        *,
        u_bounds: npt.ArrayLike | None = ...,
        n: int = ...,
        endpoint: bool = ...,
        workers: int = ...,
    ) -> npt.NDArray[np.int64]: ...

def __getattr__(name: str) -> Any: ...
