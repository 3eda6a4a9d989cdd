"""A drop-in for ``scipy.stats.qmc.PoissonDisk``, backed by pds.

Change ``from scipy.stats import qmc`` to ``from pds import qmc`` and
``qmc.PoissonDisk`` runs in the pds library (docs/python.md); every other
name of ``scipy.stats.qmc`` (``qmc.scale``, ``qmc.Sobol``, ``qmc.discrepancy``,
...) is looked up in SciPy when it is installed, so the rest of the code keeps
working.

What is the same as SciPy's PoissonDisk: the constructor (``d, *, radius,
hypersphere, ncandidates, optimization, seed, l_bounds, u_bounds``), the
methods (``random``, ``fill_space``, ``reset``, ``integers``,
``fast_forward``), ``radius`` as the minimum distance between any two
samples, output inside the bounds (``l_bounds <= x < u_bounds``, the unit
cube by default), ``random(n)`` returning up to n samples and continuing
where the previous call ended, ``fill_space()`` returning every sample still
to come, ``reset()`` starting the same sequence again.

What differs:

- The whole set is drawn at the first ``random``/``fill_space`` call (the
  library's samplers are not resumable), then handed out in order, so the
  first call costs what ``fill_space`` costs (milliseconds for 10^5 points)
  and the memory of the whole set.
- The method is SciPy's own loop, run by pds's Bridson sampler
  (``bridson`` with ``scipy=1``): a sample picked at random from the pool
  leaves it after exactly ``ncandidates`` candidates uniform in the ball of
  radius 2 radius (``hypersphere="volume"``) or on the sphere of radius
  1.001 radius (``"surface"``), and every free candidate joins the set and
  the pool. Candidates closer than the radius to the centre are counted, not
  drawn (they can never be kept). The offsets are drawn on a grid of
  2 radius 2^-31 along each axis, two numbers a 64-bit draw. So the sets
  follow SciPy's law to d = 4 (the same number of points on average; from
  d = 5 SciPy's own neighbour search misses some conflicts and breaks the
  radius, pds's does not), not Bridson's (which keeps a sample until
  ``ncandidates`` candidates fail in a row: 3% more points in 2D, 1.6 times
  the time).
  ``method=`` picks any other pds method that takes a radius, e.g.
  ``"dunbar-humphreys"`` (maximal, 2D) or ``"ebeida"`` (maximal); those take
  ``hypersphere="volume"`` only.
- ``d`` is any dimension the method takes (1 to 8 for bridson);
  ``optimization`` must be None.
- Seeds: an int ``s`` is the pds seed ``s`` (so ``pds generate bridson
  --radius R --param scipy=1 --seed s`` prints the same points); a
  ``numpy.random.Generator`` or ``RandomState`` gives one 64-bit draw at
  construction (advancing it once), a ``SeedSequence`` its first 64-bit
  state word, and None fresh OS entropy. ``reset()`` returns to that pds
  seed, as SciPy's returns to its seed. The points are pds's, not SciPy's: the same seed gives a different
  (equally valid) set.
"""

from __future__ import annotations

import numbers

import numpy as np

from . import generate as _generate
from . import methods as _pds_methods

__all__ = ["PoissonDisk"]


_dims_by_method = None


def _method_dims():
    """Each registered method's dimensions (a range), read once."""
    global _dims_by_method
    if _dims_by_method is None:
        _dims_by_method = {m["name"]: m["dims"] for m in _pds_methods()}
    return _dims_by_method


def _pds_seed(seed) -> int:
    """The 64-bit pds seed for a SciPy-style seed (see the module docstring)."""
    if seed is None:
        return int(np.random.SeedSequence().generate_state(1, np.uint64)[0])
    if isinstance(seed, (numbers.Integral, np.integer)) and not isinstance(seed, bool):
        seed = int(seed)
        if not 0 <= seed < 1 << 64:
            raise ValueError(f"seed must be in [0, 2**64), got {seed}")
        return seed
    if isinstance(seed, np.random.Generator):
        return int(seed.integers(0, 1 << 64, dtype=np.uint64))
    if isinstance(seed, np.random.RandomState):
        return int(seed.randint(0, 1 << 64, dtype=np.uint64))
    if isinstance(seed, np.random.SeedSequence):
        return int(seed.generate_state(1, np.uint64)[0])
    raise ValueError(f"{seed!r} cannot be used to seed a pds.qmc.PoissonDisk instance")


class PoissonDisk:
    """Poisson disk sampling, a drop-in for ``scipy.stats.qmc.PoissonDisk``.

    Parameters
    ----------
    d : int
        Dimension of the parameter space: any the method takes (1 to 8
        for "bridson", "dart-throwing", "ebeida" and "wei"; past 5 the last
        two serve small sets only, docs/dimensions.md).
    radius : float
        Minimal distance to keep between points (default 0.05), in the units
        of the bounds.
    hypersphere : {"volume", "surface"}
        Where the candidates are drawn: "volume" (default) uniformly in the
        ball of radius 2 radius, "surface" on the sphere of radius 1.001
        radius (denser sets), as SciPy's. Other methods take "volume" only.
    ncandidates : int
        Candidates tried around each sample once, as SciPy's (default 30).
    optimization : None
        SciPy's post-processing of the sample; only None is supported (an
        optimised sample would no longer keep the minimum distance).
    seed : {None, int, numpy.random.Generator, numpy.random.RandomState, numpy.random.SeedSequence}
        How the pds seed is chosen (see the module docstring).
    l_bounds, u_bounds : array_like of d floats, optional
        Lower and upper corners of the domain (default the unit cube).
    method : str
        (pds only) The pds method that draws the set, any that takes a
        radius: "bridson" (default), "dart-throwing", "dunbar-humphreys",
        "wei", "jones", "ebeida".
    threads : int
        (pds only) Threads for parallel methods; 0 (default) uses every core.
    """

    def __init__(
        self,
        d,
        *,
        radius=0.05,
        hypersphere="volume",
        ncandidates=30,
        optimization=None,
        seed=None,
        l_bounds=None,
        u_bounds=None,
        rng=None,
        method="bridson",
        threads=0,
    ):
        if isinstance(d, bool) or not isinstance(d, (numbers.Integral, np.integer)) or d < 0:
            raise ValueError("d must be a non-negative integer value")
        dims = _method_dims().get(method)
        if dims is not None and d not in dims:
            raise ValueError(
                f"pds.qmc.PoissonDisk: method {method!r} samples in {dims.start} to {dims[-1]} dimensions, got d={d}"
            )
        if hypersphere not in ("volume", "surface"):
            raise ValueError(
                f"{hypersphere!r} is not a valid hypersphere sampling method. "
                "It must be one of {'volume', 'surface'}"
            )
        if optimization is not None:
            raise NotImplementedError(
                f"optimization={optimization!r}: pds.qmc.PoissonDisk supports only optimization=None "
                "(an optimised sample no longer keeps the minimum distance)"
            )
        if rng is not None:  # SciPy 1.15 renamed seed to rng
            if seed is not None:
                raise ValueError("give seed or rng, not both")
            seed = rng
        self.d = int(d)
        self.radius = float(radius)
        self.hypersphere = hypersphere
        self.ncandidates = int(ncandidates)
        self.method = str(method)
        self.threads = int(threads)
        lo = np.zeros(self.d) if l_bounds is None else np.broadcast_to(np.asarray(l_bounds, float), (self.d,))
        hi = np.ones(self.d) if u_bounds is None else np.broadcast_to(np.asarray(u_bounds, float), (self.d,))
        if not np.all(lo < hi):
            raise ValueError("Bounds are not consistent 'l_bounds' < 'u_bounds'")
        self.l_bounds = lo.copy()
        self.u_bounds = hi.copy()
        self._bounds = None if l_bounds is None and u_bounds is None else np.concatenate([lo, hi]).tolist()
        if hypersphere == "surface" and self.method != "bridson":
            raise ValueError(f"hypersphere='surface' is a bridson option; method {self.method!r} takes 'volume' only")
        self._params = {}
        if self.method == "bridson":
            self._params = {"k": self.ncandidates, "surface": int(hypersphere == "surface"), "scipy": 1}
        self._seed = _pds_seed(seed)
        self.reset()

    def _draw(self):
        return _generate(
            self.method,
            radius=self.radius,
            dim=self.d,
            bounds=self._bounds,
            seed=self._seed,
            threads=self.threads,
            **self._params,
        )

    def random(self, n=1, *, workers=1):
        """Up to ``n`` samples, continuing where the last call ended.

        Fewer than ``n`` (possibly none) once the domain is full. Returns an
        (m, d) float64 array.
        """
        if n != np.inf:
            n = int(n)
            if n < 0:
                raise ValueError(f"n must be non-negative, got {n}")
        if self._points is None and self._pos == 0 and n > 0:
            self._points = self._draw()
        points = self._points
        if points is None or n == 0:
            return np.empty((0, self.d))
        start = self._pos
        stop = len(points) if n == np.inf else min(len(points), start + n)
        self._pos = stop
        self.num_generated += stop - start
        if stop == len(points):
            self._points = None  # exhausted: the caller may keep the buffer
            if start == 0:
                return points
        return points[start:stop].copy()

    def fill_space(self):
        """Every sample still to come: the rest of a set to which nothing more can be added."""
        return self.random(np.inf)

    def reset(self):
        """Start again from the first sample (same seed, same samples); returns self."""
        self._points = None
        self._pos = 0
        self.num_generated = 0
        return self

    def fast_forward(self, n):
        """Skip ``n`` samples; returns self."""
        self.random(n)
        return self

    def integers(self, l_bounds, *, u_bounds=None, n=1, endpoint=False, workers=1):
        """``n`` samples mapped to integers in [l_bounds, u_bounds) (``endpoint``: inclusive).

        As SciPy's: floor((u - l) * sample + l), the sample taken in the unit
        cube (relative to this engine's own bounds).
        """
        if u_bounds is None:
            u_bounds, l_bounds = l_bounds, 0
        u = np.atleast_1d(u_bounds)
        lo = np.atleast_1d(l_bounds)
        if endpoint:
            u = u + 1
        if not (np.issubdtype(lo.dtype, np.integer) and np.issubdtype(u.dtype, np.integer)):
            raise ValueError("'u_bounds' and 'l_bounds' must be integers or array-like of integers")
        unit = (self.random(n) - self.l_bounds) / (self.u_bounds - self.l_bounds)
        return np.floor(unit * (u - lo) + lo).astype(np.int64)

    def __repr__(self):
        return f"pds.qmc.PoissonDisk(d={self.d}, radius={self.radius}, method={self.method!r}, seed={self._seed})"


def __getattr__(name):
    """Every other name of scipy.stats.qmc, so that only the import line changes."""
    try:
        from scipy.stats import qmc as _scipy_qmc
    except ImportError:  # pragma: no cover - SciPy is optional
        raise AttributeError(f"module 'pds.qmc' has no attribute {name!r} (SciPy is not installed)") from None
    try:
        return getattr(_scipy_qmc, name)
    except AttributeError:
        raise AttributeError(f"module 'pds.qmc' has no attribute {name!r}") from None
