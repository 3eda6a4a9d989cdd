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

// The factors a split of `count` within the aspect limit can give each axis:
// in such a split every edge lies within a factor kMaxStratumAspect of the
// smallest, so between g / limit and g limit, where g^D = volume / count;
// a factor is the axis's extent over its edge. (Widened a little: the window
// only saves work, the aspect test decides.)
template <int D>
std::array<std::array<std::uint64_t, 2>, D> factor_windows(const Domain<D>& domain, std::uint64_t count) {
  double log_volume = 0.0;
  for (int i = 0; i < D; ++i) log_volume += std::log(domain.extent(i));
  const double log_g = (log_volume - std::log(static_cast<double>(count))) / D;
  const double log_limit = std::log(kMaxStratumAspect) + 1e-6;
  const double most = static_cast<double>(count);
  std::array<std::array<std::uint64_t, 2>, D> windows;
  for (int i = 0; i < D; ++i) {
    const double centre = std::log(domain.extent(i)) - log_g;
    const double lo = std::clamp(std::floor(std::exp(centre - log_limit)), 1.0, most);
    const double hi = std::clamp(std::ceil(std::exp(centre + log_limit)), 1.0, most);
    windows[i] = {static_cast<std::uint64_t>(lo), static_cast<std::uint64_t>(hi)};
  }
  return windows;
}

// Calls f(cells) for every way of writing n as a product of D positive
// factors, in axis order (each divisor a ascending, then n / a), whose cells
// keep the aspect (longest edge over shortest) within kMaxStratumAspect: a
// branch is dropped once its axes so far pass it (the final aspect can only
// be larger), and divisors outside the axis's window are not tried, which
// keeps high dimensions and large counts cheap.
template <int D, class F>
void for_each_factorisation(const Domain<D>& domain, const std::array<std::array<std::uint64_t, 2>, D>& windows,
                            std::uint64_t n, std::array<int, D>& cells, int axis, double shortest, double longest,
                            F&& f) {
  const auto fits = [&](std::uint64_t factor, double& lo, double& hi) {
    if (factor > static_cast<std::uint64_t>(std::numeric_limits<int>::max())) return false;
    const double edge = domain.extent(axis) / static_cast<double>(factor);
    lo = std::min(shortest, edge);
    hi = std::max(longest, edge);
    return hi / lo <= kMaxStratumAspect;
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
    for_each_factorisation<D>(domain, windows, n / factor, cells, axis + 1, lo, hi, f);
  };
  // a itself is tried within [first, last]; n / a within the window when a
  // lies in [n / last, n / first]. Other divisors are skipped, in order.
  const auto [first, last] = windows[static_cast<std::size_t>(axis)];
  const std::uint64_t paired_first = n / last, paired_last = n / first + 1;
  // (a <= n / a: a^2 <= n without overflow, a window's start may lie far past sqrt(n).)
  for (std::uint64_t a = std::max<std::uint64_t>(1, std::min(first, paired_first)); a <= n / a; ++a) {
    const bool own = a >= first && a <= last, paired = a >= paired_first && a <= paired_last;
    if (!own && !paired) {
      if (a > last && a > paired_last) break;
      a = (a < first && (first < paired_first || a > paired_last)) ? first - 1 : paired_first - 1;
      continue;
    }
    if (n % a) continue;
    visit(a);
    if (n / a != a) visit(n / a);
  }
}

// The split of `count` with the least aspect, if one keeps within
// kMaxStratumAspect (aspect set to it); else aspect is infinite.
template <int D>
std::array<int, D> best_split(const Domain<D>& domain, std::uint64_t count, double& aspect) {
  std::array<int, D> cells{}, best{};
  aspect = std::numeric_limits<double>::infinity();
  for_each_factorisation<D>(domain, factor_windows(domain, count), count, cells, 0,
                            std::numeric_limits<double>::infinity(), 0.0, [&](const std::array<int, D>& c) {
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
