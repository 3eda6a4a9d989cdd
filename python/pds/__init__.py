"""pds: Poisson disk and blue-noise sampling, NumPy arrays in and out.

The Python face of the pds C++ library (docs/python.md). Every sampling
method of the library is reachable by name through :func:`generate`; the
measures of ``pds analyze`` are :func:`periodogram`, :func:`radial_power`,
:func:`pair_correlation` and :func:`discrepancy`; :mod:`pds.qmc` holds
``PoissonDisk``, a drop-in for ``scipy.stats.qmc.PoissonDisk``.

Conventions, the same as the command line's:

- ``radius`` is the minimum distance between any two samples (Bridson's and
  SciPy's convention), not the radius of disks drawn around them.
- The domain is the unit square (cube for ``dim=3``) unless ``bounds`` gives
  the lower corner then the upper one (``[x0, y0, x1, y1]`` or
  ``[[x0, y0], [x1, y1]]``); ``torus=True`` makes it periodic. Every point
  satisfies lo <= x < hi.
- The seed defaults to 0, never to the clock: the same call gives the same
  bytes, and the same bytes as ``pds generate`` with the same options.
- Bad input raises ``ValueError`` with the message the command line prints
  after ``pds: error:``; a failure while doing valid work raises
  ``RuntimeError``.
- The GIL is released while the library works, so threads run in parallel.
"""

from __future__ import annotations

import json as _json
import os as _os

import numpy as _np

from . import _pds

__all__ = [
    "generate",
    "generate_classes",
    "tile",
    "methods",
    "analyze",
    "periodogram",
    "radial_power",
    "pair_correlation",
    "discrepancy",
    "min_distance",
    "read_chunks",
    "render",
    "MAX_POINTS",
    "qmc",
]

#: Requests that could produce more points than this are refused before any
#: memory is committed (``max_points=`` raises or lowers it per call).
MAX_POINTS: int = _pds.max_points_default

# The registry, read once: it does not change while the process runs.
_METHODS = tuple(_pds.methods())
_PARAM_NAMES = {m["name"]: frozenset(p["name"] for p in m["params"]) for m in _METHODS}
_U64 = 1 << 64


def _bounds(bounds, dim):
    """(lo, hi) lists for the library; empty lists mean the unit square/cube."""
    if bounds is None:
        return [], []
    flat = _np.asarray(bounds, dtype=float).reshape(-1)
    if flat.size != 2 * dim:
        raise ValueError(
            f"bounds needs {2 * dim} values for dimension {dim} (lo corner then hi corner), got {flat.size}"
        )
    return flat[:dim].tolist(), flat[dim:].tolist()


def _params(method, params):
    """Method parameters by their registry names: Python keywords spell
    a hyphen as an underscore (``all_pairs=1`` for ``all-pairs``)."""
    if not params:
        return {}
    known = _PARAM_NAMES.get(method, frozenset())
    out = {}
    for name, value in params.items():
        key = name if name in known else name.replace("_", "-")
        try:
            out[key] = float(value)
        except (TypeError, ValueError):
            raise ValueError(f"parameter {name} must be a number, got {value!r}") from None
    return out


def _uint(value, name, top=_U64):
    if value is None:
        return None
    if isinstance(value, bool) or not isinstance(value, (int, _np.integer)):
        raise TypeError(f"{name} must be an integer, got {type(value).__name__}")
    value = int(value)
    if value < 0 or value >= top:
        raise ValueError(f"{name} must be in [0, {top}), got {value}")
    return value


def generate(
    method: str,
    *,
    count: int | None = None,
    radius: float | None = None,
    dim: int = 2,
    bounds=None,
    torus: bool = False,
    seed: int = 0,
    threads: int = 0,
    max_points: int = MAX_POINTS,
    dtype="float64",
    density=None,
    radius_range=None,
    invert: bool = False,
    mask=None,
    fixed=None,
    **params: float,
) -> _np.ndarray:
    """Sample points with a registered method (the list is below).

    Returns a float64 array of shape (N, dim) that owns the library's own
    buffer (no copy). ``count`` or ``radius`` sizes the set, as the method
    allows; ``radius`` is the minimum distance between any two samples.
    ``params`` are the method's parameters (``k=10`` for Bridson; a hyphen in
    a name is written as an underscore). ``threads=0`` uses every core;
    results never depend on the thread count. Raises ValueError for bad
    input, with the command line's message. ``dtype="float32"`` returns
    float32 coordinates that keep the promises after rounding: every point
    inside the bounds and, with ``radius``, every pair at least that far apart
    (docs/point-files.md).

    ``bridson`` and ``dart-throwing`` also take (docs/density.md): ``density``,
    a (rows, columns) array of grey levels in [0, 1] laid over ``bounds``
    (row 0 at the top; black at ``radius_range[0]``, dense, white at
    ``radius_range[1]``; ``invert=True`` swaps them), which replaces
    ``radius``; ``mask``, such an array whose dark pixels (< 0.5) are where
    samples may go; ``fixed``, an (N, dim) array of points kept as the first
    N rows of the result. No sample's centre lies within another's radius
    (the larger of the two at their positions). The radius sizes the set:
    ``count`` is not taken with them, nor float32. ``elimination`` takes
    ``density`` and ``mask`` too (not ``fixed``), with ``count`` or, with a
    density and no count, the count the field asks for; it promises no
    minimum distance.
    """
    dt = _np.dtype(dtype)
    if dt not in (_np.float64, _np.float32):
        raise ValueError(f"dtype must be float64 or float32, got {dt}")
    if density is not None or mask is not None or fixed is not None or radius_range is not None or invert:
        if dt == _np.float32:
            raise ValueError(f"{method}: float32 is not taken with a density, a mask or fixed points (use float64)")
        if radius_range is not None and len(radius_range) != 2:
            raise ValueError(f"radius_range must be (rmin, rmax), got {radius_range!r}")
        return _pds.generate_constrained(
            method,
            None if count is None else _uint(count, "count"),
            None if radius is None else float(radius),
            *_request_args(method, dim, bounds, torus, seed, threads, max_points, params),
            None if density is None else _np.asarray(density, dtype=float),
            None if radius_range is None else tuple(float(r) for r in radius_range),
            bool(invert),
            None if mask is None else _np.asarray(mask, dtype=float),
            None if fixed is None else _np.asarray(fixed, dtype=float),
        )
    points = _generate(method, count, radius, dim, bounds, torus, seed, threads, max_points, params, False,
                       dt == _np.float32)
    # float32 output holds float32 values already: the cast is exact.
    return points.astype(_np.float32) if dt == _np.float32 else points


def generate_classes(
    radii,
    *,
    matrix=None,
    dim: int = 2,
    bounds=None,
    torus: bool = False,
    seed: int = 0,
    max_points: int = MAX_POINTS,
    failures: int = 0,
) -> tuple[_np.ndarray, _np.ndarray]:
    """Several classes of Poisson disk samples (Wei, "Multi-class blue noise
    sampling", SIGGRAPH 2010; docs/density.md), as ``pds generate
    dart-throwing --classes`` makes them.

    ``radii`` are the minimum distances within each class. ``matrix`` is the
    k x k symmetric matrix of least distances between classes (its diagonal
    the radii); by default Wei's, under which every class alone and the union
    of the sparser ones are Poisson disk sets. Darts go to the class furthest
    below its share; a class closes after ``failures`` rejected darts in a row
    (0: the default bound at the matrix's smallest entry). Returns
    ``(points, classes)``: a float64 array of shape (N, dim) and a uint32
    array of shape (N,) with the class of each point (0 to k - 1). Every pair
    of points of classes a and b lies at least ``matrix[a][b]`` apart.
    """
    radii_array = _np.asarray(radii, dtype=float)
    if radii_array.ndim > 1:
        raise ValueError(f"radii must be a sequence of numbers, got an array of shape {radii_array.shape}")
    radii_list = [float(r) for r in _np.atleast_1d(radii_array)]
    flat = []
    if matrix is not None:
        m = _np.asarray(matrix, dtype=float)
        k = len(radii_list)
        if m.shape != (k, k):
            raise ValueError(f"matrix must have shape ({k}, {k}) for {k} radii, got {m.shape}")
        flat = [float(v) for v in m.ravel()]
    lo, hi = _bounds(bounds, dim)
    return _pds.generate_classes(radii_list, flat, int(dim), lo, hi, bool(torus), _uint(seed, "seed"),
                                 _uint(max_points, "max_points"), _uint(failures, "failures"))


def _request_args(method, dim, bounds, torus, seed, threads, max_points, params):
    """The arguments every _pds generation call takes from dim to params."""
    if not isinstance(method, str):
        raise TypeError(f"method must be a str, got {type(method).__name__}")
    lo, hi = _bounds(bounds, dim)
    return (int(dim), lo, hi, bool(torus), _uint(seed, "seed"), int(threads), _uint(max_points, "max_points"),
            _params(method, params))


def _generate(method, count, radius, dim, bounds, torus, seed, threads, max_points, params, sized, float32=False):
    return _pds.generate(
        method,
        _uint(count, "count"),
        None if radius is None else float(radius),
        *_request_args(method, dim, bounds, torus, seed, threads, max_points, params),
        sized,
        float32,
    )


def tile(
    method: str,
    *,
    count: int | None = None,
    radius: float | None = None,
    dim: int = 2,
    seed: int = 0,
    threads: int = 0,
    **params: float,
) -> _np.ndarray:
    """A tileable pattern: ``method`` on the unit torus (``pds tile``).

    Its minimum distance holds across the seams, so copies of it cover the
    plane (or space) without closer pairs. Same arguments as :func:`generate`;
    as ``pds tile`` (and the tiled render samplers), a ``count`` asked of a
    method that takes only a radius becomes the radius at which that many
    points have relative radius 0.75 (the registry's sizing policy).
    """
    return _generate(method, count, radius, dim, None, True, seed, threads, MAX_POINTS, params, True)


def methods() -> list[dict]:
    """Every registered method, in the order ``pds --help`` lists them.

    Each is a dict: ``name``, ``family``, ``summary``, ``citation``, ``docs``
    (its page in the repository), ``takes_count``, ``takes_radius``, the
    guarantees ``min_distance``, ``maximal``, ``exact_count``,
    ``progressive``, ``deterministic``, ``equal_periods`` (on a torus, equal
    periods only), ``dims``, and ``params`` (each with
    ``name``, ``default``, ``min``, ``max``, ``integer``, ``help``).
    """
    return _pds.methods()


def _sets(points):
    """One (N, D) array, or a sequence of them (realisations of one process)."""
    if isinstance(points, _np.ndarray):
        return [points]
    points = list(points)
    if points and _np.ndim(points[0]) == 1:  # a list of coordinate rows
        return [_np.asarray(points, dtype=float)]
    return points


def _dim(sets):
    a = sets[0] if sets else None
    return _np.shape(a)[1] if a is not None and _np.ndim(a) == 2 else 2


def analyze(
    points,
    *,
    bounds=None,
    torus: bool = False,
    radius: float | None = None,
    max_frequency: int = 0,
    spectrum: bool = False,
    pcf_r_max: float = 0.0,
    pcf_bandwidth: float = 0.0,
) -> dict:
    """The measures of ``pds analyze``, as the dict of its JSON output.

    ``points``: an (N, D) array, or a list of them (realisations: the
    first-set fields describe the first, spacing and discrepancy are means,
    the spectrum and pair correlation averages). Keys, in the command line's
    order: ``count``, ``dim``, ``domain``, ``min_distance`` (and
    ``min_distance_pair``), ``mean_nn_distance``, ``relative_radius``,
    ``max_packing_radius``; with ``radius``, also ``radius``,
    ``min_distance_holds``, ``maximal`` and ``maximality``; then ``sets``,
    ``rho_min``, ``rho_mean``, the discrepancies, ``spectrum`` and ``pcf``
    summaries (docs/verification.md, docs/analysis.md). Measures that do not
    exist are None. ``max_frequency`` (0: 128 in 2D, 32 in 3D) and
    ``spectrum=True`` (compute it whatever it costs) are ``--frequencies``
    and ``--spectrum``; ``pcf_r_max`` and ``pcf_bandwidth`` are ``--pcf-max``
    and ``--pcf-bandwidth``.
    """
    if not _pds.has_analyze:
        raise RuntimeError("pds was built without its json component (PDS_WITH_JSON=OFF)")
    sets = _sets(points)
    lo, hi = _bounds(bounds, _dim(sets))
    text = _pds.analyze_json(
        sets,
        lo,
        hi,
        bool(torus),
        None if radius is None else float(radius),
        int(max_frequency),
        bool(spectrum),
        float(pcf_r_max),
        float(pcf_bandwidth),
    )
    return _json.loads(text)


def periodogram(points, *, bounds=None, torus: bool = False, max_frequency: int = 128) -> _np.ndarray:
    """The exact periodogram |sum_j exp(-2 pi i k.u_j)|^2 / N, averaged over sets.

    ``points``: an (N, D) array, or a list of them (realisations averaged
    frequency by frequency). Returns an array of shape (2K+1,) * D, K =
    ``max_frequency``, indexed ``[k_y + K, k_x + K]`` in 2D (``[k_z + K,
    k_y + K, k_x + K]`` in 3D): frequencies in cycles per domain extent,
    white noise flat at 1, the centre (k = 0) equal to N (docs/analysis.md).
    """
    sets = _sets(points)
    lo, hi = _bounds(bounds, _dim(sets))
    return _pds.periodogram(sets, lo, hi, bool(torus), int(max_frequency))


def radial_power(points, *, bounds=None, torus: bool = False, max_frequency: int = 128):
    """The periodogram's radial average and anisotropy: ``(frequency, power, anisotropy_db)``.

    One annulus per frequency step; ``frequency`` is in units of the mean
    inter-point distance (blue noise has its ring near 1), ``power`` is 1 for
    white noise, ``anisotropy_db`` about 10 log10(1/M) for M isotropic sets.
    """
    sets = _sets(points)
    lo, hi = _bounds(bounds, _dim(sets))
    return _pds.radial_power(sets, lo, hi, bool(torus), int(max_frequency))


def pair_correlation(
    points, *, bounds=None, torus: bool = False, r_max: float = 0.0, bandwidth: float = 0.0, steps: int = 200
):
    """The pair correlation function g(r): ``(r, g)``, averaged over sets.

    1 for white noise, 0 below a Poisson disk set's minimum distance with a
    peak just above. ``r_max`` (default 2.5 mean inter-point distances) and
    the kernel half-width ``bandwidth`` (default 0.1 of them) are in domain
    units; 0 picks the default. A box gets the translation edge correction.
    """
    sets = _sets(points)
    lo, hi = _bounds(bounds, _dim(sets))
    return _pds.pair_correlation(sets, lo, hi, bool(torus), float(r_max), float(bandwidth), int(steps))


def discrepancy(points, method: str | None = None, *, bounds=None, kind: str | None = None) -> float:
    """Discrepancy of an (N, D) point set, any D >= 1 (``star``: 1 to 8).

    ``method`` takes SciPy's names and returns what
    ``scipy.stats.qmc.discrepancy(points, method=...)`` returns, the same
    double on the same points: ``"L2-star"`` (Warnock's T, not squared),
    ``"CD"``, ``"WD"``, ``"MD"`` (the squares of the centered, wrap-around
    and mixture discrepancies); up to 131072 points (O(N^2 D), on all cores).
    ``"star"``: the exact star discrepancy D* (about 10,000 points in 2D, 460
    in 3D). Without ``method`` (nor the older ``kind="l2-star"|"star"``) it is
    ``"L2-star"``, where SciPy's default is ``"CD"``.

    Points must lie in the closed unit cube, or in the box ``bounds`` (lo
    corner then hi corner), which is first scaled onto it as
    ``qmc.scale(points, lo, hi, reverse=True)`` does.
    """
    if method is not None and kind is not None:
        raise ValueError("give method or kind, not both")
    if kind is not None and kind not in ("l2-star", "star"):
        raise ValueError(f"discrepancy: kind must be 'l2-star' or 'star' (or method= one of SciPy's names), got {kind!r}")
    name = method if method is not None else (kind if kind is not None else "L2-star")
    sets = _sets(points)
    a = _np.asarray(sets[0], dtype=float)
    if a.ndim == 1:
        a = a.reshape(-1, 1)
    lo, hi = _bounds(bounds, _dim([a]))
    return _pds.discrepancy(a, lo, hi, str(name))


def min_distance(points, *, bounds=None, torus: bool = False):
    """The smallest distance between two of the (N, D) points, any D >= 1, and
    a pair attaining it: ``(distance, i, j)`` with i < j (``(inf, None,
    None)`` for fewer than two points). Exact; in the box ``bounds`` (default
    the unit cube) or, with ``torus=True``, on the torus over it.
    """
    a = _np.asarray(_sets(points)[0], dtype=float)
    lo, hi = _bounds(bounds, _dim([a]))
    return _pds.min_distance(a, lo, hi, bool(torus))


def read_chunks(path, *, with_region: bool = False):
    """A chunked set written by ``pds chunks`` or ``pds-mpi chunks`` (the
    path of its ``manifest.json``) as one (N, D) float64 array, sorted
    lexicographically (the canonical order: the bytes of the region sampled
    whole). The manifest and every chunk are checked (format, counts, each
    point inside its chunk); anything wrong raises ValueError naming the file.
    With ``with_region=True`` returns ``(points, bounds, torus)``: the region
    the chunks cover as ``bounds`` (lo then hi) and whether it is the whole
    torus of a periodic field, ready for ``analyze(points, bounds=bounds,
    torus=torus)``.
    """
    points, lo, hi, torus = _pds.read_chunks(_os.fspath(path))
    if with_region:
        return points, list(lo) + list(hi), bool(torus)
    return points


def render(
    scene: str = "checkerboard",
    sampler: str = "jittered",
    *,
    spp: int = 4,
    size=(512, 512),
    filter: str = "gaussian",
    seed: int = 0,
    tile_count: int = 4096,
    threads: int = 0,
    **params: float,
) -> _np.ndarray:
    """Render a test scene (``pds render``): a (height, width) float64 image.

    ``scene``: checkerboard, zone-plate or constant; ``sampler``: random,
    jittered, sobol-pixel, or any registered method tiled over the image
    plane from a toroidal tile of ``tile_count`` points (``tiled:METHOD`` for
    names taken by the per-pixel samplers); ``size`` is (width, height) in
    pixels; ``filter``: box, tent, gaussian or mitchell. Grey levels in [0, 1].
    """
    if not _pds.has_render:
        raise RuntimeError("pds was built without its render component (PDS_WITH_RENDER=OFF)")
    width, height = (int(v) for v in size)
    return _pds.render(
        str(scene),
        str(sampler),
        width,
        height,
        int(spp),
        str(filter),
        _uint(seed, "seed"),
        _uint(tile_count, "tile_count"),
        int(threads),
        _params(sampler.removeprefix("tiled:"), params),
    )


def _dims_text(dims):
    return str(dims.start) if len(dims) == 1 else f"{dims.start}-{dims[-1]}"


def _methods_text():
    lines = ["", "    Methods:"]
    for m in _METHODS:
        sizing = " or ".join(s for s, on in (("count", m["takes_count"]), ("radius", m["takes_radius"])) if on)
        lines.append(f"      {m['name']:<18}{m['summary']}")
        lines.append(f"      {'':<18}takes {sizing}; dims {_dims_text(m['dims'])}")
        for p in m["params"]:
            lines.append(f"      {'':<18}{p['name'].replace('-', '_')}={p['default']:g}  {p['help']}")
    return "\n".join(lines)


if generate.__doc__:  # None under python -OO
    generate.__doc__ += _methods_text()

from . import qmc  # noqa: E402  (uses the functions above)
