// _pds: the compiled half of the Python package `pds` (python/pds/), a thin
// layer of pybind11 glue over the library. Every function takes plain values
// (the Python wrappers in pds/__init__.py have already normalised keywords,
// bounds and parameters), converts them to the library's types while holding
// the GIL, releases the GIL for the work itself, and hands the library's
// result buffer to NumPy without copying it (the array owns the moved
// std::vector through a capsule).
//
// Errors: pds::InvalidArgument derives from std::invalid_argument, which
// pybind11 raises as ValueError with the same message the command line prints
// after "pds: error: "; pds::Failure (std::runtime_error) becomes
// RuntimeError and std::bad_alloc MemoryError.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "pds/analysis/discrepancy.h"
#include "pds/analysis/distance.h"
#include "pds/analysis/pair_correlation.h"
#include "pds/analysis/report.h"
#include "pds/analysis/spectrum.h"
#include "pds/error.h"
#ifdef PDS_WITH_JSON
#include "pds/io/chunks.h"
#include "pds/io/report_json.h"
#endif
#include "pds/point.h"
#include "pds/registry.h"
#ifdef PDS_WITH_RENDER
#include "pds/detail/format.h"
#include "pds/render/image_field.h"
#include "pds/render/render.h"
#endif

namespace py = pybind11;

namespace {

using InputArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

/// A NumPy array of `shape` that owns `values` (moved, not copied).
template <class T>
py::array_t<T> adopt(std::vector<T>&& values, std::vector<py::ssize_t> shape) {
  auto* owner = new std::vector<T>(std::move(values));
  py::capsule release(owner, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  return py::array_t<T>(std::move(shape), owner->data(), release);
}

/// The request's domain, validated by the registry's own rules (same messages).
template <int D>
pds::Domain<D> make_domain(const std::vector<double>& lo, const std::vector<double>& hi, bool torus) {
  pds::GenerateRequest spec;
  spec.dim = D;
  spec.lo = lo;
  spec.hi = hi;
  spec.torus = torus;
  return spec.domain<D>();
}

/// The dimension of an (N, D) array of points, D >= 1 (each function says
/// which D it takes); throws InvalidArgument otherwise.
int dim_of(const InputArray& a, const std::string& what) {
  if (a.ndim() != 2 || a.shape(1) < 1 || a.shape(1) > pds::kMaxCloudDim)
    throw pds::InvalidArgument(what + " must be an array of shape (N, D), got " + std::to_string(a.ndim()) +
                               " dimension(s)" +
                               (a.ndim() == 2 ? " with " + std::to_string(a.shape(1)) + " columns" : ""));
  return static_cast<int>(a.shape(1));
}

pds::PointCloud to_cloud(const InputArray& a) {
  pds::PointCloud cloud{dim_of(a, "points"), {}};
  cloud.coords.assign(a.data(), a.data() + a.size());
  return cloud;
}

/// Empty bounds: the unit cube of `dim` dimensions.
void unit_if_empty(int dim, std::vector<double>& lo, std::vector<double>& hi) {
  if (lo.empty() && hi.empty()) {
    lo.assign(static_cast<std::size_t>(dim), 0.0);
    hi.assign(static_cast<std::size_t>(dim), 1.0);
  }
}

template <int D>
pds::PointSet<D> to_points(const InputArray& a) {
  static_assert(sizeof(pds::Point<D>) == D * sizeof(double));
  pds::PointSet<D> points(static_cast<std::size_t>(a.shape(0)));
  if (!points.empty()) std::memcpy(points.data(), a.data(), points.size() * sizeof(pds::Point<D>));
  return points;
}

/// Several realisations of one process: arrays of one dimension.
int dim_of_sets(const std::vector<InputArray>& sets) {
  if (sets.empty()) throw pds::InvalidArgument("points: need at least one set");
  const int dim = dim_of(sets[0], "points");
  for (const InputArray& s : sets)
    if (dim_of(s, "points") != dim)
      throw pds::InvalidArgument("points: every set needs the same dimension (" + std::to_string(dim) + ")");
  return dim;
}

/// The same for the spectra and the pair correlation, measured in 2D and 3D only.
int plane_or_space_dim_of_sets(const std::vector<InputArray>& sets) {
  const int dim = dim_of_sets(sets);
  if (dim != pds::kPlaneDim && dim != pds::kSpaceDim)
    throw pds::InvalidArgument(
        "points must be arrays of shape (N, 2) or (N, 3) (spectra and the pair correlation "
        "are measured in 2D and 3D only), got " +
        std::to_string(dim) + " columns");
  return dim;
}

template <int D>
std::vector<pds::PointSet<D>> to_sets(const std::vector<InputArray>& sets) {
  std::vector<pds::PointSet<D>> out;
  out.reserve(sets.size());
  for (const InputArray& s : sets) out.push_back(to_points<D>(s));
  return out;
}

pds::GenerateRequest make_request(std::optional<std::uint64_t> count, std::optional<double> radius, int dim,
                                  std::vector<double> lo, std::vector<double> hi, bool torus, std::uint64_t seed,
                                  int threads, std::uint64_t max_points, std::map<std::string, double> params) {
  pds::GenerateRequest request;
  request.dim = dim;
  request.lo = std::move(lo);
  request.hi = std::move(hi);
  request.torus = torus;
  request.count = count;
  request.radius = radius;
  request.seed = seed;
  request.threads = threads;
  request.max_points = max_points;
  request.params = std::move(params);
  return request;
}

py::array_t<double> run_request(const std::string& method, const pds::GenerateRequest& request, bool sized) {
  pds::PointCloud cloud;
  {
    py::gil_scoped_release unlocked;
    // sized: a count asked of a radius-only method becomes a radius by the
    // registry's one policy (pds::size_request), as `pds tile` does.
    cloud = pds::generate(method, sized ? pds::size_request(pds::find_method(method), request) : request);
  }
  const auto n = static_cast<py::ssize_t>(cloud.size());
  return adopt(std::move(cloud.coords), {n, cloud.dim});
}

py::array_t<double> generate(const std::string& method, std::optional<std::uint64_t> count,
                             std::optional<double> radius, int dim, std::vector<double> lo, std::vector<double> hi,
                             bool torus, std::uint64_t seed, int threads, std::uint64_t max_points,
                             std::map<std::string, double> params, bool sized, bool float32) {
  pds::GenerateRequest request =
      make_request(count, radius, dim, std::move(lo), std::move(hi), torus, seed, threads, max_points, params);
  request.float32 = float32;
  return run_request(method, request, sized);
}

/// Wei's multi-class dart throwing: (points, classes), as `pds generate
/// dart-throwing --classes` writes them.
py::tuple generate_classes(std::vector<double> radii, std::vector<double> matrix, int dim, std::vector<double> lo,
                           std::vector<double> hi, bool torus, std::uint64_t seed, std::uint64_t max_points,
                           std::uint64_t failures) {
  const pds::GenerateRequest request =
      make_request(std::nullopt, std::nullopt, dim, std::move(lo), std::move(hi), torus, seed, 0, max_points, {});
  const pds::MultiClassParams params{.radii = std::move(radii), .matrix = std::move(matrix), .max_failures = failures};
  pds::ClassCloud set;
  {
    py::gil_scoped_release unlocked;
    set = pds::generate_classes(params, request);
  }
  const auto n = static_cast<py::ssize_t>(set.classes.size());
  return py::make_tuple(adopt(std::move(set.points.coords), {n, set.points.dim}), adopt(std::move(set.classes), {n}));
}

#ifdef PDS_WITH_RENDER
/// A (rows, columns) array of grey levels in [0, 1], row 0 at the top, laid
/// over the request's plane bounds.
pds::ImageOnBounds image_over(const InputArray& a, const pds::GenerateRequest& request, const char* what) {
  if (request.dim != pds::kPlaneDim)
    throw pds::InvalidArgument(std::string(what) +
                               " needs dim=2 (an image covers the plane), got dim=" + std::to_string(request.dim));
  if (a.ndim() != 2 || a.shape(0) < 1 || a.shape(1) < 1 || a.shape(0) > std::numeric_limits<int>::max() ||
      a.shape(1) > std::numeric_limits<int>::max())
    throw pds::InvalidArgument(std::string(what) + " must be a non-empty array of shape (rows, columns)");
  pds::Image image(static_cast<int>(a.shape(1)), static_cast<int>(a.shape(0)));
  std::memcpy(image.pixels.data(), a.data(), image.pixels.size() * sizeof(double));
  for (const double g : image.pixels)
    if (!(g >= 0.0 && g <= 1.0))
      throw pds::InvalidArgument(std::string(what) + ": grey levels must lie in [0, 1], got " +
                                 pds::detail::format_number(g));
  std::vector<double> lo, hi;
  request.bounds(lo, hi);
  return pds::ImageOnBounds(std::move(image), {{lo[0], lo[1]}}, {{hi[0], hi[1]}});
}

/// generate() with the constraints of docs/density.md: a density image with
/// its radius range, a mask image, fixed points.
py::array_t<double> generate_constrained(const std::string& method, std::optional<std::uint64_t> count,
                                         std::optional<double> radius, int dim, std::vector<double> lo,
                                         std::vector<double> hi, bool torus, std::uint64_t seed, int threads,
                                         std::uint64_t max_points, std::map<std::string, double> params,
                                         std::optional<InputArray> density,
                                         std::optional<std::pair<double, double>> radius_range, bool invert,
                                         std::optional<InputArray> mask, std::optional<InputArray> fixed) {
  pds::GenerateRequest request = make_request(count, radius, dim, std::move(lo), std::move(hi), torus, seed, threads,
                                              max_points, std::move(params));
  pds::RequestConstraints& c = request.constraints;
  if (density.has_value() != radius_range.has_value())
    throw pds::InvalidArgument(density ? "density needs radius_range=(rmin, rmax)" : "radius_range needs density");
  if (invert && !density) throw pds::InvalidArgument("invert needs density");
  if (density) {
    c.rmin = radius_range->first;
    c.rmax = radius_range->second;
    const auto field = pds::radius_from_image(image_over(*density, request, "density"), c.rmin, c.rmax, invert);
    c.radius = [field](const double* x) { return field({{x[0], x[1]}}); };
  }
  if (mask) {
    const auto on = pds::mask_from_image(image_over(*mask, request, "mask"));
    c.inside = [on](const double* x) { return on({{x[0], x[1]}}); };
  }
  if (fixed) {
    const int d = dim_of(*fixed, "fixed");
    c.fixed.dim = d;
    c.fixed.coords.assign(fixed->data(), fixed->data() + fixed->shape(0) * d);
  }
  return run_request(method, request, false);
}
#endif

py::list methods() {
  py::list out;
  for (const pds::Method& m : pds::methods()) {
    py::list params;
    for (const pds::MethodParam& p : m.params)
      params.append(py::dict(py::arg("name") = p.name, py::arg("default") = p.default_value, py::arg("min") = p.min,
                             py::arg("max") = p.max, py::arg("integer") = p.integer, py::arg("help") = p.help));
    out.append(py::dict(py::arg("name") = m.name, py::arg("family") = std::string(pds::family_name(m.family)),
                        py::arg("summary") = m.summary, py::arg("citation") = m.citation, py::arg("docs") = m.docs,
                        py::arg("takes_count") = m.takes_count, py::arg("takes_radius") = m.takes_radius,
                        py::arg("min_distance") = m.min_distance, py::arg("maximal") = m.maximal,
                        py::arg("exact_count") = m.exact_count, py::arg("progressive") = m.progressive,
                        py::arg("deterministic") = m.deterministic, py::arg("equal_periods") = m.equal_periods,
                        py::arg("dims") = py::module_::import("builtins").attr("range")(m.dims.lo, m.dims.hi + 1),
                        py::arg("params") = params));
  }
  return out;
}

py::array_t<double> periodogram(const std::vector<InputArray>& arrays, const std::vector<double>& lo,
                                const std::vector<double>& hi, bool torus, int max_frequency) {
  return pds::visit_dim(plane_or_space_dim_of_sets(arrays), [&](auto d) {
    constexpr int D = decltype(d)::value;
    const auto sets = to_sets<D>(arrays);
    const auto domain = make_domain<D>(lo, hi, torus);
    pds::Periodogram p;
    {
      py::gil_scoped_release unlocked;
      p = pds::periodogram<D>(sets, domain, {.max_frequency = max_frequency});
    }
    // Axis 0 varies fastest in the library: as a C array the last index is k_0.
    return adopt(std::move(p.power), std::vector<py::ssize_t>(D, p.side()));
  });
}

py::tuple radial_power(const std::vector<InputArray>& arrays, const std::vector<double>& lo,
                       const std::vector<double>& hi, bool torus, int max_frequency) {
  return pds::visit_dim(plane_or_space_dim_of_sets(arrays), [&](auto d) {
    constexpr int D = decltype(d)::value;
    const auto sets = to_sets<D>(arrays);
    const auto domain = make_domain<D>(lo, hi, torus);
    pds::RadialSpectrum r;
    {
      py::gil_scoped_release unlocked;
      r = pds::radial_average(pds::periodogram<D>(sets, domain, {.max_frequency = max_frequency}));
    }
    const auto n = static_cast<py::ssize_t>(r.power.size());
    return py::make_tuple(adopt(std::move(r.frequency), {n}), adopt(std::move(r.power), {n}),
                          adopt(std::move(r.anisotropy_db), {n}));
  });
}

py::tuple pair_correlation(const std::vector<InputArray>& arrays, const std::vector<double>& lo,
                           const std::vector<double>& hi, bool torus, double r_max, double bandwidth, int steps) {
  return pds::visit_dim(plane_or_space_dim_of_sets(arrays), [&](auto d) {
    constexpr int D = decltype(d)::value;
    const auto sets = to_sets<D>(arrays);
    const auto domain = make_domain<D>(lo, hi, torus);
    pds::PairCorrelation g;
    {
      py::gil_scoped_release unlocked;
      g = pds::pair_correlation<D>(sets, domain, {.r_max = r_max, .bandwidth = bandwidth, .steps = steps});
    }
    const auto n = static_cast<py::ssize_t>(g.r.size());
    return py::make_tuple(adopt(std::move(g.r), {n}), adopt(std::move(g.g), {n}));
  });
}

/// kind: SciPy's "L2-star", "CD", "WD", "MD" (any dimension, on the points
/// scaled into the unit cube by lo, hi), or "star" (exact D*, 1 to 8 dimensions).
double discrepancy(const InputArray& array, std::vector<double> lo, std::vector<double> hi, const std::string& kind) {
  const int dim = dim_of(array, "points");
  if (kind == "star")
    return pds::visit_dim<pds::kMinDim, pds::kMaxDim>(dim, [&](auto d) {
      constexpr int D = decltype(d)::value;
      const auto points = to_points<D>(array);
      const auto domain = make_domain<D>(lo, hi, false);
      py::gil_scoped_release unlocked;
      return pds::star_discrepancy(points, domain);
    });
  const pds::DiscrepancyMethod method = pds::parse_discrepancy_method(kind == "l2-star" ? "L2-star" : kind);
  const pds::PointCloud cloud = to_cloud(array);
  py::gil_scoped_release unlocked;
  if (lo.empty() && hi.empty()) return pds::discrepancy(cloud, method);
  return pds::discrepancy(cloud, lo, hi, method);
}

/// The smallest distance between two points and a pair attaining it, any dimension.
py::tuple min_distance(const InputArray& array, std::vector<double> lo, std::vector<double> hi, bool torus) {
  const pds::PointCloud cloud = to_cloud(array);
  unit_if_empty(cloud.dim, lo, hi);
  pds::MinDistance m;
  {
    py::gil_scoped_release unlocked;
    m = pds::min_distance(cloud, lo, hi, torus);
  }
  if (!std::isfinite(m.distance)) return py::make_tuple(m.distance, py::none(), py::none());
  return py::make_tuple(m.distance, m.i, m.j);
}

#ifdef PDS_WITH_JSON
/// A chunked set (pds chunks: a manifest.json and its NPY chunks) as one
/// (N, D) array in canonical order, and the manifest's region and torus.
py::tuple read_chunks(const std::string& path) {
  pds::ChunkManifest m;
  pds::PointCloud cloud;
  {
    py::gil_scoped_release release;
    cloud = pds::read_chunks(path, &m);
  }
  const auto n = static_cast<py::ssize_t>(cloud.size());
  return py::make_tuple(adopt(std::move(cloud.coords), {n, static_cast<py::ssize_t>(m.dim)}), m.lo, m.hi,
                        !m.torus_lo.empty() && m.torus_lo == m.lo && m.torus_hi == m.hi);
}

/// The analysis report as the JSON `pds analyze` prints (the Python side
/// parses it), so the keys, their order and their values are the CLI's.
std::string analyze_json(const std::vector<InputArray>& arrays, const std::vector<double>& lo,
                         const std::vector<double>& hi, bool torus, std::optional<double> radius, int max_frequency,
                         bool spectrum, double pcf_r_max, double pcf_bandwidth) {
  if (max_frequency < 0) throw pds::InvalidArgument("max_frequency must be positive");
  const int dim = dim_of_sets(arrays);
  const pds::AnalysisOptions options{.radius = radius,
                                     .max_frequency = max_frequency,
                                     .spectrum = spectrum,
                                     .pcf = {.r_max = pcf_r_max, .bandwidth = pcf_bandwidth}};
  if (dim > pds::kMaxDim) {
    std::vector<pds::PointCloud> clouds;
    for (const InputArray& a : arrays) clouds.push_back(to_cloud(a));
    std::vector<double> l = lo, h = hi;
    unit_if_empty(dim, l, h);
    py::gil_scoped_release unlocked;
    return pds::analysis_report_json(pds::analyze(std::span<const pds::PointCloud>(clouds), l, h, torus, options));
  }
  return pds::visit_dim<pds::kMinDim, pds::kMaxDim>(dim, [&](auto d) {
    constexpr int D = decltype(d)::value;
    const auto sets = to_sets<D>(arrays);
    const auto domain = make_domain<D>(lo, hi, torus);
    py::gil_scoped_release unlocked;
    const pds::AnalysisReport report = pds::analyze<D>(sets, domain, options);
    return pds::analysis_report_json(report);
  });
}
#endif

#ifdef PDS_WITH_RENDER
py::array_t<double> render(const std::string& scene_name, const std::string& sampler_name, int width, int height,
                           int spp, const std::string& filter, std::uint64_t seed, std::uint64_t tile_count,
                           int threads, std::map<std::string, double> params) {
  if (width < 1 || height < 1 || width > pds::kMaxImageSide || height > pds::kMaxImageSide)
    throw pds::InvalidArgument("size must be between 1x1 and " + std::to_string(pds::kMaxImageSide) + "x" +
                               std::to_string(pds::kMaxImageSide) + ", got " + std::to_string(width) + "x" +
                               std::to_string(height));
  pds::Image image;
  {
    py::gil_scoped_release unlocked;
    const pds::RenderOptions options{pds::parse_filter(filter), threads};
    const auto scene = pds::make_scene(scene_name, width, height);
    const auto sampler = pds::make_image_sampler(
        sampler_name, {.spp = spp, .seed = seed, .tile_count = tile_count, .params = std::move(params)});
    image = pds::render(*scene, *sampler, width, height, options);
  }
  return adopt(std::move(image.pixels), {image.height, image.width});
}
#endif

}  // namespace

PYBIND11_MODULE(_pds, m) {
  m.doc() = "The compiled half of the pds package; use the functions of `pds` itself.";
  m.def("generate", &generate, py::arg("method"), py::arg("count"), py::arg("radius"), py::arg("dim"), py::arg("lo"),
        py::arg("hi"), py::arg("torus"), py::arg("seed"), py::arg("threads"), py::arg("max_points"), py::arg("params"),
        py::arg("sized"), py::arg("float32") = false);
  m.def("generate_classes", &generate_classes, py::arg("radii"), py::arg("matrix"), py::arg("dim"), py::arg("lo"),
        py::arg("hi"), py::arg("torus"), py::arg("seed"), py::arg("max_points"), py::arg("failures"));
#ifdef PDS_WITH_RENDER
  m.def("generate_constrained", &generate_constrained, py::arg("method"), py::arg("count"), py::arg("radius"),
        py::arg("dim"), py::arg("lo"), py::arg("hi"), py::arg("torus"), py::arg("seed"), py::arg("threads"),
        py::arg("max_points"), py::arg("params"), py::arg("density"), py::arg("radius_range"), py::arg("invert"),
        py::arg("mask"), py::arg("fixed"));
#endif
  m.def("methods", &methods);
  m.def("periodogram", &periodogram, py::arg("sets"), py::arg("lo"), py::arg("hi"), py::arg("torus"),
        py::arg("max_frequency"));
  m.def("radial_power", &radial_power, py::arg("sets"), py::arg("lo"), py::arg("hi"), py::arg("torus"),
        py::arg("max_frequency"));
  m.def("pair_correlation", &pair_correlation, py::arg("sets"), py::arg("lo"), py::arg("hi"), py::arg("torus"),
        py::arg("r_max"), py::arg("bandwidth"), py::arg("steps"));
  m.def("discrepancy", &discrepancy, py::arg("points"), py::arg("lo"), py::arg("hi"), py::arg("kind"));
  m.def("min_distance", &min_distance, py::arg("points"), py::arg("lo"), py::arg("hi"), py::arg("torus"));
#ifdef PDS_WITH_JSON
  m.def("read_chunks", &read_chunks, py::arg("path"));
  m.def("analyze_json", &analyze_json, py::arg("sets"), py::arg("lo"), py::arg("hi"), py::arg("torus"),
        py::arg("radius"), py::arg("max_frequency"), py::arg("spectrum"), py::arg("pcf_r_max"),
        py::arg("pcf_bandwidth"));
  m.attr("has_analyze") = true;
#else
  m.attr("has_analyze") = false;
#endif
#ifdef PDS_WITH_RENDER
  m.def("render", &render, py::arg("scene"), py::arg("sampler"), py::arg("width"), py::arg("height"), py::arg("spp"),
        py::arg("filter"), py::arg("seed"), py::arg("tile_count"), py::arg("threads"), py::arg("params"));
  m.attr("has_render") = true;
#else
  m.attr("has_render") = false;
#endif
  m.attr("max_points_default") = pds::kDefaultMaxPoints;
}
