#pragma once
// The single table of sampling methods, a layer above the samplers: the
// samplers are typed free functions that know nothing of it, and each entry
// (src/pds/registry/<family>.cpp) wires a run-time GenerateRequest to one of
// them. The table feeds the command line (`pds generate METHOD`, `pds
// --help`, `pds compare`'s default rows), docs/methods.md and the README's
// method table (both generated, and kept in sync by tests), and the
// conformance tests (every method that promises a minimum distance gets the
// all-pairs oracle, every one with a rho band the relative-radius check), so
// a method is added in one place: its entry and one line in the table.

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "pds/domain.h"
#include "pds/limits.h"
#include "pds/point.h"
#include "pds/progress.h"
#include "pds/samplers/constraints.h"
#include "pds/samplers/multi_class.h"

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

/// SamplingConstraints (samplers/constraints.h) with the dimension known only
/// at run time: a point is `dim` doubles. Methods with Method::constraints
/// take them; sized by the field's [rmin, rmax] or by the request's radius.
struct RequestConstraints {
  std::function<double(const double*)> radius;  // r(x); empty: the request's radius
  double rmin = 0, rmax = 0;
  std::function<bool(const double*)> inside;  // empty: the whole domain
  PointCloud fixed;                           // dim must be the request's (when not empty)

  bool active() const { return static_cast<bool>(radius) || static_cast<bool>(inside) || fixed.size() > 0; }
  /// The typed constraints for the domain's dimension.
  template <int D>
  SamplingConstraints<D> typed(const Domain<D>&) const {
    SamplingConstraints<D> c;
    if (radius) c.radius = [f = radius](const Point<D>& x) { return f(x.data()); };
    c.rmin = rmin;
    c.rmax = rmax;
    if (inside) c.inside = [f = inside](const Point<D>& x) { return f(x.data()); };
    c.fixed = fixed.as<D>();
    return c;
  }
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
  /// Refuse, before allocating, requests whose estimated peak memory
  /// (peak_memory_estimate) exceeds this many bytes; 0: no budget but the
  /// machine's memory.
  double max_memory = 0;
  std::map<std::string, double> params;
  /// Output rounded to float32 that keeps the promises (pds/float32.h): every
  /// point in [lo, hi), and with a radius every pair at least that far apart,
  /// decided on the rounded coordinates. The doubles returned are float32 values.
  bool float32 = false;
  /// Progress and cancellation (pds/progress.h), reported by the methods
  /// that can run for long: best-candidate, dart-throwing, jones, fpo.
  Progress progress;
  RequestConstraints constraints;  // radius field, mask, fixed points (docs/density.md)

  template <int D>
  Domain<D> domain() const;
  /// The request's bounds in any dimension (empty lo/hi: the unit cube),
  /// validated as Domain<D>::validate does; throws InvalidArgument.
  void bounds(std::vector<double>& lo_out, std::vector<double>& hi_out) const;
  /// The value of a method parameter, or its default.
  double param(const std::string& name, double fallback) const;
};

/// The groups the README and docs list methods in.
enum class Family {
  white_noise,
  stratified,
  sequence,
  poisson_disk,
  fast_poisson_disk,
  maximal_poisson_disk,
  optimized
};
std::string_view family_name(Family family);

/// The relative radius (Lagae & Dutre 2008; analysis/relative_radius.h) a
/// method's sets reach at `radius` on the conformance domains (a 1.25 x 1
/// box or torus in 2D, 1 x 1.5 x 0.8 in 3D; tests/poisson_disk_conformance_test.cpp):
/// measured over seeds 1-5 and widened by the spread the set size gives. A
/// box packs more points along its faces, so its band sits higher.
struct RhoBand {
  int dim = 2;
  bool torus = false;
  double radius = 0;
  double lo = 0, hi = 0;
};

/// The dimensions a method runs in, both ends included.
struct DimRange {
  int lo = kPlaneDim, hi = kSpaceDim;
  constexpr DimRange() = default;
  constexpr DimRange(int first, int last) : lo(first), hi(last) {}  // both ends: no {2} meaning 2-3
  bool contains(int dim) const { return dim >= lo && dim <= hi; }
  /// "2", "2-3", "1-21201": for --help, pds methods and error messages.
  std::string text() const { return lo == hi ? std::to_string(lo) : std::to_string(lo) + "-" + std::to_string(hi); }
  /// The dimensions tests run a method in: all of them up to kMaxDim, then
  /// a few far ones (run-time dimensions are one code path).
  std::vector<int> tested() const;
  bool operator==(const DimRange&) const = default;
};

struct Method {
  std::string name;
  Family family = Family::white_noise;
  std::string docs;      // the page that explains it, relative to the repository root
  std::string summary;   // one line for --help
  std::string citation;  // the paper, or "" for elementary patterns
  bool takes_count = false;
  bool takes_radius = false;
  bool min_distance = false;       // with --radius, every pair of samples is at least that far apart
  bool maximal = false;            // with --radius, no point of the domain is farther than radius from a sample
  bool exact_count = false;        // with --count N, exactly N points (or InvalidArgument)
  bool progressive = false;        // every prefix of the output is itself a well-spread set
  bool deterministic = false;      // ignores the seed
  bool compare = false;            // one of `pds compare`'s default rows
  bool equal_periods = false;  // on a torus, equal periods only (generate() refuses the rest; boxes of any shape)
  bool constraints = false;        // takes GenerateRequest::constraints (radius field, mask, fixed points)
  DimRange dims;
  std::vector<RhoBand> rho;  // expected relative radius, where measured
  /// Peak memory a run allocates over the size of its output (8 bytes a
  /// coordinate), measured by scripts/peak_memory.py (docs/reliability.md;
  /// 10^6 points in 1D and 2D, 3 10^5 in 3D) and rounded up with a margin:
  /// the factor of peak_memory_estimate, which is to bound the peak.
  double memory_ratio = 4;
  /// Where a dimension needs another ratio: (D, ratio) pairs, ascending in
  /// D, each taking over memory_ratio from D on (measured in that dimension).
  std::vector<std::pair<int, double>> memory_ratio_from_dim;
  /// With a count, where the count takes a path that needs more (bridson: its
  /// last set, then the elimination of the surplus): (D, ratio) pairs as
  /// above, each the ratio from D on wherever it is the larger.
  std::vector<std::pair<int, double>> count_memory_ratio_from_dim;
  /// A parameter whose value the memory grows with (elimination's
  /// candidates): above its default, the ratio is scaled by value / default.
  std::string memory_scales_with;
  /// Bytes a run holds per axis whatever the count (sequences' tables of
  /// direction numbers, bases and digit permutations): 21,201 axes of Sobol
  /// hold 6 MB for 10 points.
  double memory_per_axis = 0;
  std::vector<MethodParam> params;
  /// Runs the method on a request that generate() has already validated.
  PointCloud (*run)(const GenerateRequest&) = nullptr;
};

/// All methods, in the order --help lists them.
std::span<const Method> methods();

/// The method called `name`; throws InvalidArgument naming the known ones.
const Method& find_method(const std::string& name);

/// Throws InvalidArgument for a parameter the method does not have, or a
/// value outside its range (or not an integer where it must be one).
void validate_params(const Method& m, const std::map<std::string, double>& params);

/// Validates the request against the method (dimension, domain, sizing,
/// parameters, point budget) and runs it; with request.float32, rounds the
/// result keeping its promises (a method that promises a minimum distance
/// samples at the slightly larger radius of float32_sampling_radius).
PointCloud generate(const std::string& method, const GenerateRequest& request);

/// Several classes of samples (Wei's multi-class dart throwing,
/// pds/samplers/multi_class.h) for the request's dimension, domain and seed:
/// `points` of dimension request.dim and the class of each (0 to k - 1).
/// The sum of the classes' densest packings, each at its own radius, must fit
/// request.max_points. The request's count, radius, parameters, constraints,
/// float32 and max_memory are not taken (InvalidArgument); it runs on one
/// thread whatever request.threads says.
struct ClassCloud {
  PointCloud points;
  std::vector<std::uint32_t> classes;
};
ClassCloud generate_classes(const MultiClassParams& params, const GenerateRequest& request);

/// The peak memory in bytes a request to `method` is expected to allocate:
/// its points (the count, or for a radius pds::typical_count, an estimate)
/// x dim x 8 bytes x the method's memory_ratio (or memory_ratio_from_dim's
/// for the request's dimension; with a count, count_memory_ratio_from_dim's
/// where larger; scaled by memory_scales_with's value over its default where
/// that is above 1), plus dim x memory_per_axis. The process
/// itself (about 14 MB) is not counted. GenerateRequest::max_memory and
/// --max-memory refuse by it.
double peak_memory_estimate(const Method& method, const GenerateRequest& request);

/// The relative radius (Lagae & Dutre 2008; analysis/relative_radius.h) at
/// which a count is turned into a radius for a method that takes only a
/// radius. Maximal Poisson disk sets reach about 0.72-0.90 depending on the
/// method (the rho bands of each entry), so at 0.75 such a method places
/// about the requested count or somewhat more, never far fewer.
inline constexpr double kCountRelativeRadius = 0.75;

/// The one count-to-radius policy above the samplers, used wherever a count
/// is asked of any method (pds compare, pds analyze --method, pds tile,
/// tiled render samplers): a request with a count and no radius, for a
/// method that takes only a radius, becomes the request for the minimum
/// distance at which `count` points have relative radius
/// kCountRelativeRadius in the request's domain (pds::radius_for_count);
/// every other request is returned unchanged, so methods that take a count
/// keep their own sizing (dart throwing's and Bridson's `rho` parameters).
/// Throws InvalidArgument for a count of 0 or bad bounds.
GenerateRequest size_request(const Method& method, GenerateRequest request);

/// Calls f(domain) with the request's typed Domain<D> and packs the returned
/// PointSet<D>; the glue between a typed sampler and the registry. Lo, Hi:
/// the dimensions the sampler is instantiated for (the plane and space unless
/// said otherwise).
template <int Lo = kPlaneDim, int Hi = kSpaceDim, class F>
PointCloud run_typed(const GenerateRequest& request, F&& f) {
  return visit_dim<Lo, Hi>(request.dim, [&](auto d) {
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
    d = Domain<D>::from_bounds(lo.data(), hi.data(), torus);
  }
  d.validate();
  return d;
}

}  // namespace pds
