#pragma once
// The single table of sampling methods. It feeds the command line
// (`pds generate METHOD`, `pds --help`), the conformance tests and the docs
// index, so a method is added in exactly one place: one line in
// src/pds/registry.cpp naming its Method.

#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "pds/domain.h"
#include "pds/limits.h"
#include "pds/point.h"

namespace pds {

/// A method-specific numeric parameter (e.g. Bridson's k), settable from the
/// command line as `--param name=value`.
struct MethodParam {
  std::string name;
  double default_value = 0;
  double min = 0;  // inclusive bounds, checked before the method runs
  double max = 0;
  bool integer = false;
  std::string help;
};

/// Everything a generation request can say, with the dimension known only at
/// run time. Empty lo/hi mean the unit square/cube.
struct GenerateRequest {
  int dim = 2;
  std::vector<double> lo, hi;
  bool torus = false;
  std::optional<std::uint64_t> count;
  std::optional<double> radius;  // minimum distance between any two samples
  std::uint64_t seed = 0;
  int threads = 0;  // 0: all hardware threads
  std::uint64_t max_points = kDefaultMaxPoints;
  std::map<std::string, double> params;

  template <int D>
  Domain<D> domain() const;
  /// The value of a method parameter, or its default.
  double param(const std::string& name, double fallback) const;
};

struct Method {
  std::string name;
  std::string summary;   // one line for --help
  std::string citation;  // the paper, or "" for elementary patterns
  bool takes_count = false;
  bool takes_radius = false;
  bool maximal = false;        // promises that no point of the domain is farther than radius from a sample
  bool deterministic = false;  // ignores the seed
  std::vector<int> dims{2, 3};
  std::vector<MethodParam> params;
  /// Runs the method on a request that generate() has already validated.
  PointCloud (*run)(const GenerateRequest&) = nullptr;
};

/// All methods, in the order --help lists them.
std::span<const Method> methods();

/// The method called `name`; throws InvalidArgument naming the known ones.
const Method& find_method(const std::string& name);

/// Validates the request against the method (dimension, domain, sizing,
/// parameters, point budget) and runs it.
PointCloud generate(const std::string& method, const GenerateRequest& request);

/// Calls f(domain) with the request's typed Domain<D> and packs the returned
/// PointSet<D>; the glue between a typed sampler and the registry.
template <class F>
PointCloud run_typed(const GenerateRequest& request, F&& f) {
  return visit_dim(request.dim, [&](auto d) {
    constexpr int D = decltype(d)::value;
    return PointCloud::from<D>(f(request.domain<D>()));
  });
}

template <int D>
Domain<D> GenerateRequest::domain() const {
  Domain<D> d = Domain<D>::unit(torus);
  if (!lo.empty() || !hi.empty()) {
    if (lo.size() != static_cast<std::size_t>(D) || hi.size() != static_cast<std::size_t>(D))
      throw InvalidArgument("bounds: need " + std::to_string(D) + " lower and " + std::to_string(D) +
                            " upper values for dimension " + std::to_string(D));
    for (int i = 0; i < D; ++i) {
      d.lo[i] = lo[i];
      d.hi[i] = hi[i];
    }
  }
  d.validate();
  return d;
}

}  // namespace pds
