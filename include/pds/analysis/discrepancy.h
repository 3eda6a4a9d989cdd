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

//
// Centered (CD), wrap-around (WD) and mixture (MD) discrepancies (Hickernell,
// "A generalized discrepancy and quadrature error bound", Math. Comp. 67,
// 1998; Zhou, Fang & Ning, "Mixture discrepancy for quasi-random point
// sets", J. Complexity 29, 2013), by their closed forms, O(N^2 D):
//   CD^2 = (13/12)^D - 2/N sum_i prod_a (1 + |u_ia - 1/2|/2 - |u_ia - 1/2|^2/2)
//          + 1/N^2 sum_ij prod_a (1 + |u_ia - 1/2|/2 + |u_ja - 1/2|/2 - |u_ia - u_ja|/2)
//   WD^2 = -(4/3)^D + 1/N^2 sum_ij prod_a (3/2 - |u_ia - u_ja| + |u_ia - u_ja|^2)
//   MD^2 = (19/12)^D - 2/N sum_i prod_a (5/3 - |u_ia - 1/2|/4 - |u_ia - 1/2|^2/4)
//          + 1/N^2 sum_ij prod_a (15/8 - |u_ia - 1/2|/4 - |u_ja - 1/2|/4
//                                 - 3/4 |u_ia - u_ja| + |u_ia - u_ja|^2/2)
// discrepancy() takes the dimension at run time (any D >= 1) and returns what
// SciPy's scipy.stats.qmc.discrepancy(x, method=...) returns, the same double
// on the same points (same order of operations): the squares CD^2, WD^2,
// MD^2 for "CD", "WD", "MD", and T (not squared) for "L2-star", which is
// exactly l2_star_discrepancy() here. Points outside the unit cube are first
// scaled into it by the box's bounds, u = (x - lo) / (hi - lo), which is what
// qmc.scale(x, lo, hi, reverse=True) does; then the result equals SciPy's on
// the scaled points.

#include <array>
#include <cstddef>
#include <span>
#include <string_view>

#include "pds/domain.h"
#include "pds/point.h"
#include "pds/progress.h"

namespace pds {

/// The most points l2_star_discrepancy and discrepancy accept (N^2 pairs).
inline constexpr std::size_t kMaxL2StarPoints = 1u << 17;

/// The most work 2 N (N+1)^(D-1) + 2 (N+1)^D star_discrepancy accepts: about a second.
inline constexpr double kMaxStarDiscrepancyWork = 4e8;

/// The discrepancies of discrepancy(), by SciPy's names (discrepancy_method_name).
enum class DiscrepancyMethod { L2Star, Centered, WrapAround, Mixture };
inline constexpr std::array<DiscrepancyMethod, 4> kDiscrepancyMethods = {
    DiscrepancyMethod::L2Star, DiscrepancyMethod::Centered, DiscrepancyMethod::WrapAround, DiscrepancyMethod::Mixture};

/// "L2-star", "CD", "WD", "MD": SciPy's names.
std::string_view discrepancy_method_name(DiscrepancyMethod method);
/// The method of a SciPy name; throws InvalidArgument listing them for another.
DiscrepancyMethod parse_discrepancy_method(std::string_view name);

/// SciPy's qmc.discrepancy(points, method=...) for points in the closed unit
/// cube [0, 1]^dim, any dim >= 1 (see above: squared for CD, WD, MD; T for
/// L2-star). Runs on several threads; the same double for any thread count.
/// Throws InvalidArgument for no points, more than kMaxL2StarPoints, a
/// dimension below 1 or a coordinate outside [0, 1] (or NaN). `progress`
/// (optional) hears the rows of the O(N^2 D) double sum done, out of N, from
/// the calling thread, about every 2^20 pairs; returning false stops the run
/// with pds::Cancelled. The result is the same double with or without it.
double discrepancy(const PointCloud& unit_points, DiscrepancyMethod method, const Progress& progress = {});

/// The same after scaling the box [lo, hi] (closed) onto the unit cube.
double discrepancy(const PointCloud& points, std::span<const double> lo, std::span<const double> hi,
                   DiscrepancyMethod method, const Progress& progress = {});

/// True when star_discrepancy accepts n points in dimension dim (n >= 1).
bool star_discrepancy_feasible(std::size_t n, int dim);

/// Warnock's L2-star discrepancy T (not squared), the same double as
/// discrepancy(u, DiscrepancyMethod::L2Star) on the scaled points u. Throws InvalidArgument for
/// an empty set, more than kMaxL2StarPoints points, or a point outside.
/// `progress` as for discrepancy().
template <int D>
double l2_star_discrepancy(const PointSet<D>& points, const Domain<D>& domain, const Progress& progress = {});

/// The exact star discrepancy D*. Throws InvalidArgument for an empty set, a
/// set beyond kMaxStarDiscrepancyWork, or a point outside the domain.
template <int D>
double star_discrepancy(const PointSet<D>& points, const Domain<D>& domain);

}  // namespace pds
