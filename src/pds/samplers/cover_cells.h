#pragma once
// The background grid of the flat-quadtree samplers (ebeida, maximal-darts):
// cells of edge just under r / sqrt(D), so that a sample covers its whole
// cell, and the margin inside which a sub-cell counts as covered.

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "pds/detail/format.h"
#include "pds/domain.h"
#include "pds/error.h"

namespace pds::detail {

template <int D>
struct CoverCells {
  std::array<int, D> n{};                      // cells per axis
  double count = 1.0;                          // their number, for the caller's limit before anything is allocated
  double cover2 = 0.0;                         // (r - slack)^2: a sub-cell inside this of one sample is covered
  std::array<std::vector<double>, D> corners;  // cell boundaries per axis, n + 1 each

  /// Throws InvalidArgument (naming `method`) when the radius is too small
  /// for the rounding of coordinates of the domain's magnitude.
  CoverCells(const std::string& method, const Domain<D>& domain, double r) {
    double scale = 0.0;
    for (int a = 0; a < D; ++a) {
      // Slightly more cells than extent sqrt(D) / r: a cell's diagonal stays
      // below r after rounding, so a sample covers its whole cell.
      n[a] = static_cast<int>(std::max(1.0, std::ceil(domain.extent(a) * std::sqrt(double(D)) * (1.0 + 1e-9) / r)));
      count *= n[a];
      scale = std::max({scale, std::abs(domain.lo[a]), std::abs(domain.hi[a])});
    }
    // Rounding of coordinates of this size can move a corner or a dart by a
    // few units of 2^-52 scale; a sub-cell is dropped only with that margin.
    // A region covered only by disks that overlap by less than the slack can
    // neither be proven covered nor take a dart, and refines until the level
    // limit; keeping the slack a millionth of r makes that a one in a
    // million event per near-tangency (the property sweep found a 1D torus
    // at 2.2e5 with r 4.9e-7, slack 1.6e-3 r, that broke down so).
    const double slack = 1e-12 * r + 16.0 * scale * 0x1.0p-52;
    if (slack > 1e-6 * r)
      throw InvalidArgument(method + ": radius " + format_number(r) + " is too small for coordinates of magnitude " +
                            format_number(scale));
    cover2 = (r - slack) * (r - slack);
  }

  /// The cell boundaries (call once the count is accepted).
  void make_corners(const Domain<D>& domain) {
    for (int a = 0; a < D; ++a) {
      corners[a].resize(static_cast<std::size_t>(n[a]) + 1);
      for (int i = 0; i < n[a]; ++i) corners[a][i] = domain.lo[a] + domain.extent(a) * i / n[a];
      corners[a][n[a]] = domain.hi[a];
    }
  }
};

}  // namespace pds::detail
