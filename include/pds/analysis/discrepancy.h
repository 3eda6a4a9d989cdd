#pragma once
// Discrepancy: how far the fraction of points in boxes anchored at the origin
// departs from the boxes' volume. Points are first mapped to the unit cube,
// u = (x - lo) / L per axis; the boxes are [0, y) with y in [0, 1]^D.
//
// L2-star discrepancy, by Warnock's formula (Warnock 1972):
//   T^2 = 3^-D - 2^(1-D)/N sum_i prod_a (1 - u_ia^2)
//         + 1/N^2 sum_i sum_j prod_a (1 - max(u_ia, u_ja)),
// the root mean square over y of the local discrepancy A([0,y))/N - vol([0,y)).
// O(N^2 D) time, spread over threads; each row sum is added in order, so the
// value does not depend on the thread count.
//
// Star discrepancy D* = sup_y |A([0,y))/N - vol([0,y))|, computed exactly by
// enumerating the critical boxes (Niederreiter 1972): the supremum is
// attained, as a limit, at corners y whose every coordinate is a point's
// coordinate or 1, using open boxes for vol - A/N and closed boxes for
// A/N - vol. A sweep along the first axis keeps the counts of all corners of
// the other axes up to date as it passes each point: O(N (N+1)^(D-1) +
// (N+1)^D) time and (N+1)^(D-1) memory, so about 10,000 points in 2D and 460
// in 3D within the limit below.

#include <cstddef>

#include "pds/domain.h"
#include "pds/point.h"

namespace pds {

/// The most points l2_star_discrepancy accepts (N^2 pairs).
inline constexpr std::size_t kMaxL2StarPoints = 1u << 17;

/// The most work 2 N (N+1)^(D-1) + 2 (N+1)^D star_discrepancy accepts: about a second.
inline constexpr double kMaxStarDiscrepancyWork = 4e8;

/// True when star_discrepancy accepts n points in dimension dim (n >= 1).
bool star_discrepancy_feasible(std::size_t n, int dim);

/// Warnock's L2-star discrepancy T (not squared). Throws InvalidArgument for
/// an empty set, more than kMaxL2StarPoints points, or a point outside.
template <int D>
double l2_star_discrepancy(const PointSet<D>& points, const Domain<D>& domain);

/// The exact star discrepancy D*. Throws InvalidArgument for an empty set, a
/// set beyond kMaxStarDiscrepancyWork, or a point outside the domain.
template <int D>
double star_discrepancy(const PointSet<D>& points, const Domain<D>& domain);

}  // namespace pds
