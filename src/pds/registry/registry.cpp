#include "pds/registry.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "descriptors.h"
#include "pds/detail/format.h"
#include "pds/error.h"
#include "pds/float32.h"

namespace pds {

std::span<const Method> methods() {
  using namespace registry_detail;
  // The one table of methods, in the order --help lists them.
  static const std::vector<Method> table = {
      white_noise_method(),
      regular_method(),
      jittered_method(),
      halton_method(),
      hammersley_method(),
      sobol_method(),
      multi_jittered_method(),
      latin_hypercube_method(),
      dart_throwing_method(),
      bridson_method(),
      best_candidate_method(),
      elimination_method(),
      dunbar_humphreys_method(),
      wei_method(),
#ifdef PDS_WITH_CGAL
      jones_method(),
#endif
      ebeida_method(),
      maximal_darts_method(),
#ifdef PDS_WITH_CGAL
      fpo_method(),
#endif
      gbn_method(),
  };
  return table;
}

std::string_view family_name(Family family) {
  switch (family) {
    case Family::white_noise:
      return "white noise";
    case Family::stratified:
      return "grid and stratified";
    case Family::sequence:
      return "low-discrepancy sequences";
    case Family::poisson_disk:
      return "Poisson disk";
    case Family::fast_poisson_disk:
      return "fast Poisson disk";
    case Family::maximal_poisson_disk:
      return "maximal Poisson disk";
    case Family::optimized:
      return "optimized blue noise";
  }
  return "?";
}

const Method& find_method(const std::string& name) {
  for (const Method& m : methods())
    if (m.name == name) return m;
  std::string known;
  for (const Method& m : methods()) known += (known.empty() ? "" : ", ") + m.name;
  throw InvalidArgument("unknown method '" + name + "' (known: " + known + ")");
}

std::vector<int> DimRange::tested() const {
  std::vector<int> dims;
  for (int d = lo; d <= hi && d <= kMaxDim; ++d) dims.push_back(d);
  // The top of the range too, up to Sobol's 21,201; past that (random and
  // Latin hypercube go to kMaxCloudDim) memory, not code, is what changes.
  const int top = hi <= 21201 ? hi : 21201;
  for (int d : {hi > 64 ? 64 : 0, hi > 1000 ? 1000 : 0, top > kMaxDim ? top : 0})
    if (d > kMaxDim && d >= lo && (dims.empty() || d > dims.back())) dims.push_back(d);
  return dims;
}

void GenerateRequest::bounds(std::vector<double>& lo_out, std::vector<double>& hi_out) const {
  if (dim < 1 || dim > kMaxCloudDim)
    throw InvalidArgument("dimension " + std::to_string(dim) + " is not supported (supported: 1 to " +
                          std::to_string(kMaxCloudDim) + ")");
  const auto n = static_cast<std::size_t>(dim);
  if (lo.empty() && hi.empty()) {
    lo_out.assign(n, 0.0);
    hi_out.assign(n, 1.0);
    return;
  }
  if (lo.size() != n || hi.size() != n)
    throw InvalidArgument("bounds: need " + std::to_string(dim) + " lower and " + std::to_string(dim) +
                          " upper values for dimension " + std::to_string(dim));
  for (std::size_t i = 0; i < n; ++i) validate_axis(static_cast<int>(i), lo[i], hi[i]);
  lo_out = lo;
  hi_out = hi;
}

double GenerateRequest::param(const std::string& name, double fallback) const {
  const auto it = params.find(name);
  return it == params.end() ? fallback : it->second;
}

void validate_params(const Method& m, const std::map<std::string, double>& params) {
  for (const auto& entry : params) {
    const std::string& name = entry.first;
    const double value = entry.second;
    const auto it =
        std::find_if(m.params.begin(), m.params.end(), [&](const MethodParam& p) { return p.name == name; });
    if (it == m.params.end()) {
      std::string known;
      for (const MethodParam& p : m.params) known += (known.empty() ? "" : ", ") + p.name;
      throw InvalidArgument(m.name + " has no parameter '" + name + "' (" +
                            (known.empty() ? std::string("it takes none") : "known: " + known) + ")");
    }
    if (!std::isfinite(value) || value < it->min || value > it->max || (it->integer && value != std::floor(value)))
      throw InvalidArgument(m.name + ": parameter " + name + " must be " + (it->integer ? "an integer " : "") + "in [" +
                            detail::format_number(it->min) + ", " + detail::format_number(it->max) + "], got " +
                            detail::format_number(value));
  }
}

namespace {

// A radius field, a mask, fixed points: only where the method takes them,
// and sized by the field's range or a radius, never by a count (except for
// a method that takes only a count: elimination).
void validate_constraints(const Method& m, const GenerateRequest& r) {
  const RequestConstraints& c = r.constraints;
  if (!c.active()) return;
  if (!m.constraints) {
    std::string takers;
    for (const Method& t : methods())
      if (t.constraints) takers += (takers.empty() ? "" : ", ") + t.name;
    throw InvalidArgument(m.name + " does not take a density, a mask or fixed points (" + takers + " do)");
  }
  if (c.fixed.size() > 0 && c.fixed.dim != r.dim)
    throw InvalidArgument("fixed points have dimension " + std::to_string(c.fixed.dim) + ", the request " +
                          std::to_string(r.dim));
  if (r.count && m.takes_radius)
    throw InvalidArgument(m.name +
                          ": --count is not taken with a density, a mask or fixed points (size by the radius)");
  // Rounding would move the fixed points and could break the pair rule.
  if (r.float32)
    throw InvalidArgument(m.name +
                          ": float32 output is not taken with a density, a mask or fixed points (use float64)");
  if (!c.radius) return;
  if (r.radius) throw InvalidArgument(m.name + ": a density takes a radius range, not --radius");
  require_radius(c.rmin, "rmin");
  require_radius(c.rmax, "rmax");
  if (!(c.rmin <= c.rmax))
    throw InvalidArgument("radius range needs rmin <= rmax, got " + detail::format_number(c.rmin) + " > " +
                          detail::format_number(c.rmax));
  visit_dim<kMinDim, kMaxDim>(r.dim, [&](auto d) {
    require_radius_budget(r.domain<decltype(d)::value>(), c.rmin, r.max_points);
    return 0;
  });
}

void validate(const Method& m, const GenerateRequest& r) {
  if (!m.dims.contains(r.dim))
    throw InvalidArgument(m.name + ": dimension " + std::to_string(r.dim) +
                          " is not supported (supported: " + m.dims.text() + ")");
  validate_constraints(m, r);
  if (r.dim > kMaxDim) {
    // Run-time dimensions: sequences and designs, which take a count only.
    std::vector<double> lo, hi;
    r.bounds(lo, hi);  // validates them
    if (r.radius) throw InvalidArgument(m.name + " does not take --radius (use --count)");
  } else {
    visit_dim<kMinDim, kMaxDim>(r.dim, [&](auto d) {
      constexpr int D = decltype(d)::value;
      const Domain<D> domain = r.domain<D>();  // validates the bounds
      if (m.equal_periods && domain.periodic) {
        bool square = true;
        for (int i = 1; i < D; ++i) square = square && domain.extent(i) == domain.extent(0);
        if (!square) throw InvalidArgument(m.name + " runs on a torus with equal periods only (square --bounds)");
      }
      if (r.radius) {
        if (!m.takes_radius) throw InvalidArgument(m.name + " does not take --radius (use --count)");
        require_radius_budget(domain, *r.radius, r.max_points);
        // An axis a million times thinner than the radius is a lower-dimensional
        // set in disguise; dart throwing ran for minutes on one 1e-100 wide.
        for (int a = 0; a < D; ++a)
          if (*r.radius > 1e6 * domain.extent(a))
            throw InvalidArgument("bounds: axis " + std::to_string(a) + " is " +
                                  detail::format_number(domain.extent(a)) +
                                  " wide, more than 10^6 times thinner than the radius " +
                                  detail::format_number(*r.radius) + " (sample in fewer dimensions)");
      }
      return 0;
    });
  }
  if (r.count) {
    if (!m.takes_count) throw InvalidArgument(m.name + " does not take --count (use --radius)");
    require_count(*r.count, r.max_points);
    // count x dim doubles, twice (the set and a copy on its way out), refused
    // before anything is allocated.
    require_point_budget(static_cast<double>(*r.count), r.dim, r.max_points,
                         "count " + std::to_string(*r.count) + " in dimension " + std::to_string(r.dim), 2.0);
  }
  if (!r.count && !r.radius && !r.constraints.radius) {
    if (m.takes_count && m.takes_radius) throw InvalidArgument(m.name + " needs --count or --radius");
    throw InvalidArgument(m.name + (m.takes_count ? " needs --count" : " needs --radius"));
  }
  if (r.threads < 0) throw InvalidArgument("threads must be 0 (all) or positive, got " + std::to_string(r.threads));
  if (!(r.max_memory >= 0) || !std::isfinite(r.max_memory))
    throw InvalidArgument("max-memory must be a size of 0 (none) or more, got " + detail::format_number(r.max_memory));
  if (r.max_memory > 0) {
    const double need = peak_memory_estimate(m, r);
    if (need > r.max_memory)
      throw InvalidArgument(m.name + ": the request needs about " + detail::format_number(need / (1 << 20)) +
                            " MiB at its peak, above the budget of " + detail::format_number(r.max_memory / (1 << 20)) +
                            " MiB (--max-memory)");
  }
  validate_params(m, r.params);
}

// Runs the method so that its output, rounded to float32, keeps the
// promises of the request (pds/float32.h explains the radius it samples at).
PointCloud run_float32(const Method& m, const GenerateRequest& request) {
  std::vector<double> lo, hi;
  request.bounds(lo, hi);
  const double spacing = float32_spacing(lo, hi);
  if (!request.radius || !m.min_distance) {
    PointCloud points = m.run(request);
    round_to_float32(points, lo, hi);
    return points;
  }
  const double r = *request.radius;
  GenerateRequest inflated = request;
  // The bound makes the first attempt succeed; the check guards the bound.
  constexpr int kAttempts = 4;
  for (int attempt = 0; attempt < kAttempts; ++attempt) {
    inflated.radius = float32_sampling_radius(r, request.dim, spacing, attempt);
    PointCloud points = m.run(inflated);
    round_to_float32(points, lo, hi);
    if (!find_pair_closer_than(points, lo, hi, request.torus, r)) return points;
  }
  throw Failure(m.name + ": float32 rounding brought two points closer than radius " + detail::format_number(r) +
                " in " + std::to_string(kAttempts) + " attempts (use float64)");
}

}  // namespace

double peak_memory_estimate(const Method& method, const GenerateRequest& request) {
  double points = request.count ? static_cast<double>(*request.count) : 0.0;
  // A radius field sizes the set by its range: at most the count at rmin.
  const std::optional<double> radius = request.constraints.radius ? request.constraints.rmin : request.radius;
  if (radius) {
    std::vector<double> lo, hi;
    request.bounds(lo, hi);
    const double typical =
        typical_count(sizing_volume(lo.data(), hi.data(), request.dim, *radius), *radius, request.dim);
    points = request.count ? std::min(points, typical) : typical;  // a count stops the run
  }
  points += static_cast<double>(request.constraints.fixed.size());
  const auto from_dim = [&](const std::vector<std::pair<int, double>>& ratios, double ratio) {
    for (const auto& [dim, r] : ratios)
      if (request.dim >= dim) ratio = r;
    return ratio;
  };
  double ratio = from_dim(method.memory_ratio_from_dim, method.memory_ratio);
  if (request.count) ratio = std::max(ratio, from_dim(method.count_memory_ratio_from_dim, 0.0));
  if (!method.memory_scales_with.empty()) {
    const auto param = std::ranges::find(method.params, method.memory_scales_with, &MethodParam::name);
    const auto given = request.params.find(method.memory_scales_with);
    if (param != method.params.end() && given != request.params.end() && given->second > param->default_value)
      ratio *= given->second / param->default_value;
  }
  return points * request.dim * static_cast<double>(sizeof(double)) * ratio + request.dim * method.memory_per_axis;
}

PointCloud generate(const std::string& method, const GenerateRequest& request) {
  const Method& m = find_method(method);
  validate(m, request);
  return request.float32 ? run_float32(m, request) : m.run(request);
}

ClassCloud generate_classes(const MultiClassParams& params, const GenerateRequest& request) {
  if (request.count || request.radius)
    throw InvalidArgument("classes: the class radii size the set; a count or a radius is not taken");
  if (!request.params.empty())
    throw InvalidArgument("classes: method parameters are not taken (failures is the classes' own setting)");
  if (request.constraints.active() || request.float32 || request.max_memory > 0)
    throw InvalidArgument("classes: a density, a mask, fixed points, float32 or a memory budget are not taken");
  if (params.radii.empty()) throw InvalidArgument("classes: need at least one class radius");
  for (const double r : params.radii) require_radius(r, "class radius");
  ClassCloud out;
  out.points = visit_dim<kMinDim, kMaxDim>(request.dim, [&](auto d) {
    constexpr int D = decltype(d)::value;
    const Domain<D> domain = request.domain<D>();
    // Each class alone is a Poisson disk set at its own radius, whatever the
    // cross distances: the sum of their packings bounds the count.
    double most = 0.0;
    for (const double r : params.radii) most += packing_count(sizing_volume(domain, r), r, D);
    require_point_budget(most, D, request.max_points,
                         std::to_string(params.radii.size()) + " classes (the densest packing of each at its radius)");
    MultiClassSet<D> set = multi_class<D>(params, domain, request.seed);
    out.classes = std::move(set.classes);
    return PointCloud::from<D>(set.points);
  });
  return out;
}

}  // namespace pds
