#include "pds/detail/format.h"
#include "pds/samplers/strata.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "pds/detail/instantiate.h"
#include "pds/error.h"

namespace pds {
namespace {

// Calls f(cells) for every way of writing n as a product of D positive
// factors, in axis order, whose cells keep the aspect (longest edge over
// shortest) within `limit`: a branch is dropped once its axes so far pass
// it (the final aspect can only be larger), which keeps high dimensions cheap.
template <int D, class F>
void for_each_factorisation(const Domain<D>& domain, std::uint64_t n, std::array<int, D>& cells, int axis,
                            double shortest, double longest, double limit, F&& f) {
  const auto fits = [&](std::uint64_t factor, double& lo, double& hi) {
    if (factor > static_cast<std::uint64_t>(std::numeric_limits<int>::max())) return false;
    const double edge = domain.extent(axis) / static_cast<double>(factor);
    lo = std::min(shortest, edge);
    hi = std::max(longest, edge);
    return hi / lo <= limit;
  };
  double lo, hi;
  if (axis == D - 1) {
    if (!fits(n, lo, hi)) return;
    cells[axis] = static_cast<int>(n);
    f(cells);
    return;
  }
  auto visit = [&](std::uint64_t factor) {
    if (!fits(factor, lo, hi)) return;
    cells[axis] = static_cast<int>(factor);
    for_each_factorisation<D>(domain, n / factor, cells, axis + 1, lo, hi, limit, f);
  };
  for (std::uint64_t a = 1; a * a <= n; ++a) {
    if (n % a) continue;
    visit(a);
    if (n / a != a) visit(n / a);
  }
}

// The split of `count` with the least aspect within `limit` (aspect set to
// it), or aspect infinite when none keeps within it.
template <int D>
std::array<int, D> best_split(const Domain<D>& domain, std::uint64_t count, double& aspect,
                              double limit = kMaxStratumAspect) {
  std::array<int, D> cells{}, best{};
  aspect = std::numeric_limits<double>::infinity();
  for_each_factorisation<D>(domain, count, cells, 0, std::numeric_limits<double>::infinity(), 0.0, limit,
                            [&](const std::array<int, D>& c) {
                              const double a = strata_aspect<D>(domain, c);
                              if (a < aspect) {
                                aspect = a;
                                best = c;
                              }
                            });
  return best;
}

template <int D>
bool splits_well(const Domain<D>& domain, std::uint64_t count) {
  double aspect;
  best_split<D>(domain, count, aspect);
  return aspect <= kMaxStratumAspect;
}

}  // namespace

template <int D>
double strata_aspect(const Domain<D>& domain, const std::array<int, D>& cells) {
  double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
  for (int i = 0; i < D; ++i) {
    const double edge = domain.extent(i) / cells[i];
    lo = std::min(lo, edge);
    hi = std::max(hi, edge);
  }
  return hi / lo;
}

template <int D>
std::array<int, D> strata_for_count(const Domain<D>& domain, std::uint64_t count) {
  double aspect;
  const std::array<int, D> best = best_split(domain, count, aspect);
  if (aspect <= kMaxStratumAspect) return best;

  // Say which counts would work; they are dense near any count, so a short
  // bounded search finds them.
  std::string below = "none", above = "none";
  for (std::uint64_t k = count - 1; k >= 1 && count - k <= 100000; --k)
    if (splits_well(domain, k)) {
      below = std::to_string(k);
      break;
    }
  for (std::uint64_t k = count + 1; k - count <= 100000; ++k)
    if (splits_well(domain, k)) {
      above = std::to_string(k);
      break;
    }
  throw InvalidArgument("count " + std::to_string(count) + " cannot be split into a grid of near-cubic strata over " +
                        "this domain (no split of it into " + std::to_string(D) +
                        " factors keeps the cells' longest edge within " + detail::format_number(kMaxStratumAspect) +
                        " times the shortest); nearest counts that can: " + below + " and " + above);
}

template <int D>
std::array<int, D> strata_for_spacing(const Domain<D>& domain, double spacing) {
  std::array<int, D> cells{};
  for (int i = 0; i < D; ++i) {
    const double n = std::floor(domain.extent(i) / spacing);
    if (n > static_cast<double>(std::numeric_limits<int>::max()))
      throw InvalidArgument("spacing " + detail::format_number(spacing) + " is too small for the domain");
    cells[i] = std::max(1, static_cast<int>(n));
    // Rounding can put two centres a hair closer than extent / n: drop cells
    // until every computed gap holds.
    auto gaps_hold = [&](int m) {
      if (m == 1) return true;
      for (int j = 0; j + 1 < m; ++j)
        if (stratum_centre(domain, i, j + 1, m) - stratum_centre(domain, i, j, m) < spacing) return false;
      return !domain.periodic ||
             std::abs(domain.delta(stratum_centre(domain, i, m - 1, m), stratum_centre(domain, i, 0, m), i)) >= spacing;
    };
    while (!gaps_hold(cells[i])) --cells[i];
  }
  return cells;
}

#define PDS_INSTANTIATE(D)                                                          \
  template std::array<int, D> strata_for_count<D>(const Domain<D>&, std::uint64_t); \
  template std::array<int, D> strata_for_spacing<D>(const Domain<D>&, double);      \
  template double strata_aspect<D>(const Domain<D>&, const std::array<int, D>&);
PDS_FOR_EACH_DIM(PDS_INSTANTIATE)
#undef PDS_INSTANTIATE

}  // namespace pds
