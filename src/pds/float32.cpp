#include "pds/float32.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "pds/detail/format.h"
#include "pds/domain.h"
#include "pds/error.h"
#include "pds/grid.h"

namespace pds {
namespace {

constexpr double kFloatMax = std::numeric_limits<float>::max();

// The smallest float32 >= x and the largest float32 < x (x within float32's range).
float float_at_or_above(double x) {
  float f = static_cast<float>(x);
  if (static_cast<double>(f) < x) f = std::nextafter(f, std::numeric_limits<float>::infinity());
  return f;
}
float float_below(double x) {
  float f = static_cast<float>(x);
  if (!(static_cast<double>(f) < x)) f = std::nextafter(f, -std::numeric_limits<float>::infinity());
  return f;
}

}  // namespace

double float32_spacing(const std::vector<double>& lo, const std::vector<double>& hi) {
  double magnitude = 0.0;
  for (std::size_t a = 0; a < lo.size(); ++a) {
    magnitude = std::max({magnitude, std::abs(lo[a]), std::abs(hi[a])});
    if (!(std::abs(lo[a]) < kFloatMax && std::abs(hi[a]) < kFloatMax))
      throw InvalidArgument("float32: bounds on axis " + std::to_string(a) + " [" + detail::format_number(lo[a]) +
                            ", " + detail::format_number(hi[a]) + ") lie beyond float32's range (use float64)");
    if (!(static_cast<double>(float_at_or_above(lo[a])) < hi[a]))
      throw InvalidArgument("float32: axis " + std::to_string(a) + " [" + detail::format_number(lo[a]) + ", " +
                            detail::format_number(hi[a]) + ") holds no float32 value (use float64)");
  }
  // The gap above the float just past the magnitude: no gap below it is wider.
  const float above = std::nextafter(float_at_or_above(magnitude), std::numeric_limits<float>::infinity());
  return static_cast<double>(std::nextafter(above, std::numeric_limits<float>::infinity())) -
         static_cast<double>(above);
}

double float32_sampling_radius(double r, int dim, double spacing, int attempt) {
  const double inflation = 2.0 * std::sqrt(static_cast<double>(dim)) * spacing;
  if (inflation > kFloat32MaxInflation * r)
    throw InvalidArgument(
        "float32: radius " + detail::format_number(r) + " is too small for float32 coordinates spaced " +
        detail::format_number(spacing) + " at this domain's magnitude (need radius >= " +
        detail::format_number(inflation / kFloat32MaxInflation) + "; use float64 or move the domain nearer 0)");
  return (r + std::ldexp(inflation, attempt)) * (1.0 + 1e-12);
}

void round_to_float32(PointCloud& points, const std::vector<double>& lo, const std::vector<double>& hi) {
  const auto dim = static_cast<std::size_t>(points.dim);
  for (std::size_t k = 0; k < points.coords.size(); ++k) {
    const std::size_t a = k % dim;
    double x = static_cast<float>(points.coords[k]);
    if (x < lo[a]) x = float_at_or_above(lo[a]);
    if (!(x < hi[a])) x = float_below(hi[a]);
    points.coords[k] = x;
  }
}

bool find_pair_closer_than(const PointCloud& points, const std::vector<double>& lo, const std::vector<double>& hi,
                           bool torus, double r, ClosePair* pair) {
  return visit_dim<kMinDim, kMaxDim>(points.dim, [&](auto d) {
    constexpr int D = decltype(d)::value;
    const Domain<D> domain = Domain<D>::from_bounds(lo.data(), hi.data(), torus);
    Grid<D> grid = Grid<D>::for_conflicts(domain, r);
    const double r2 = r * r;
    for (const Point<D>& p : points.as<D>()) {
      bool found = false;
      grid.for_each_within(p, r, [&](std::int32_t j, double d2) {
        if (!(d2 < r2)) return true;
        found = true;
        if (pair) *pair = {static_cast<std::size_t>(j), grid.size(), std::sqrt(d2)};
        return false;
      });
      if (found) return true;
      grid.insert(p);
    }
    return false;
  });
}

}  // namespace pds
