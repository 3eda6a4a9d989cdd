#pragma once
// The background grid of the Dunbar-Humphreys sampler (all three variants):
// one sample index per cell, and the windows of cells around a sample.
// Private to src/pds/samplers/dunbar_humphreys*.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

#include "pds/domain.h"
#include "pds/error.h"
#include "pds/point.h"

namespace pds::detail::dh {

/// Cells of a grid window, each side of the centre cell, per axis.
using Reach = std::array<int, 2>;

/// One sample index per cell (or -1). Cells have edge <= r / sqrt(2), so a
/// set with minimum distance r has at most one sample per cell; a flat int32
/// array is smaller and faster here than the general pds::Grid's lists.
class CellGrid {
 public:
  CellGrid(const Domain<2>& domain, double cell_edge) : domain_(domain) {
    for (int i = 0; i < 2; ++i) {
      const double n = std::max(1.0, std::ceil(domain.extent(i) / cell_edge));
      if (n > 1e9) throw InvalidArgument("dunbar-humphreys: radius too small for the domain");
      n_[i] = static_cast<int>(n);
      inv_edge_[i] = n / domain.extent(i);
    }
    if (static_cast<double>(n_[0]) * n_[1] > static_cast<double>(std::size_t{1} << 31))
      throw InvalidArgument("dunbar-humphreys: radius too small for the domain (grid above 2^31 cells)");
    cells_.assign(static_cast<std::size_t>(n_[0]) * n_[1], -1);
  }
  int n(int axis) const { return n_[axis]; }
  /// How many cells around a sample's cell can hold a sample within
  /// `distance`, per axis (a box one cell thin across has far smaller cells
  /// along its other axis).
  Reach reach(double distance) const {
    return {static_cast<int>(std::ceil(distance * inv_edge_[0])), static_cast<int>(std::ceil(distance * inv_edge_[1]))};
  }
  int coord(double x, int axis) const {
    const int c = static_cast<int>((x - domain_.lo[axis]) * inv_edge_[axis]);
    return std::clamp(c, 0, n_[axis] - 1);
  }
  std::int32_t& at(int cx, int cy) { return cells_[static_cast<std::size_t>(cy) * n_[0] + cx]; }
  std::int32_t& at(const Point<2>& p) { return at(coord(p[0], 0), coord(p[1], 1)); }

  /// Calls f(index) for every stored sample in the cells within `reach`
  /// cells of p's cell (each cell once, wrapping on a torus).
  template <class F>
  void for_each_near(const Point<2>& p, Reach reach, F&& f) const {
    int first[2], last[2];
    window(p, reach, first, last);
    for (int y = first[1]; y <= last[1]; ++y) {
      const std::int32_t* row = this->row(y);
      for (int x = first[0]; x <= last[0]; ++x) {
        const std::int32_t j = row[wrapped(x, 0)];
        if (j >= 0) f(j);
      }
    }
  }

  /// The window of cells within `reach` of p's cell as [first, last] per
  /// axis; true when it needs no nearest image (in a box always; on a torus
  /// when it neither crosses a seam nor covers a whole axis).
  bool plain_window(const Point<2>& p, Reach reach, int first[2], int last[2]) const {
    window(p, reach, first, last);
    return !(first[0] < 0 || first[1] < 0 || last[0] >= n_[0] || last[1] >= n_[1] ||
             (domain_.periodic && (last[0] - first[0] + 1 == n_[0] || last[1] - first[1] + 1 == n_[1])));
  }
  std::size_t bytes() const { return cells_.size() * sizeof(std::int32_t); }
  /// Asks for the rows of p's window to be brought into the cache.
  void prefetch_window(const Point<2>& p, Reach reach) const {
    int first[2], last[2];
    window(p, reach, first, last);
    for (int y = first[1]; y <= last[1]; ++y) __builtin_prefetch(row(y) + std::max(first[0], 0));
  }
  /// Row y of the grid (y in [-n, 2n), wrapped).
  const std::int32_t* row_pointer(int y) const { return row(y); }

  // collect_near's window width: 2 radius is 2.83 cells of radius / sqrt 2,
  // up to 3.33 where rounding the cell count up shrinks the cells (a torus
  // period of 4 radius), so the reach is at most 4; a box that narrow has
  // fewer cells than that across.
  static constexpr int kMaxWindow = 9;

  /// The same samples written to `out` (room for (2 reach + 1)^2), their
  /// number returned: no branch per cell, for the hot loop of boundary
  /// sampling. `seam` tells whether the window crossed a torus seam.
  int collect_near(const Point<2>& p, Reach reach, std::int32_t* out, bool& seam) const {
    int first[2], last[2];
    seam = !plain_window(p, reach, first, last);
    const int width = last[0] - first[0] + 1;
    if (width > kMaxWindow) throw std::logic_error("dunbar-humphreys: neighbour window wider than planned");
    int n = 0;
    if (width == 7 && first[0] >= 0 && last[0] < n_[0]) {  // the usual case: no column wraps, 7 wide
      for (int y = first[1]; y <= last[1]; ++y) {
        const std::int32_t* row = this->row(y) + first[0];
        for (int x = 0; x < 7; ++x) {
          const std::int32_t j = row[x];
          out[n] = j;
          n += j >= 0;
        }
      }
      return n;
    }
    int columns[kMaxWindow];
    for (int x = 0; x < width; ++x) columns[x] = wrapped(first[0] + x, 0);
    for (int y = first[1]; y <= last[1]; ++y) {
      const std::int32_t* row = this->row(y);
      for (int x = 0; x < width; ++x) {
        const std::int32_t j = row[columns[x]];
        out[n] = j;
        n += j >= 0;
      }
    }
    return n;
  }

 private:
  /// The cell range [first, last] per axis within `reach` of p's cell:
  /// clipped in a box, possibly past the ends (to be wrapped) on a torus.
  void window(const Point<2>& p, Reach reach, int first[2], int last[2]) const {
    for (int i = 0; i < 2; ++i) {
      const int c = coord(p[i], i);
      first[i] = c - reach[i];
      last[i] = c + reach[i];
      if (domain_.periodic) {
        if (last[i] - first[i] + 1 >= n_[i]) {
          first[i] = 0;
          last[i] = n_[i] - 1;
        }
      } else {
        first[i] = std::max(first[i], 0);
        last[i] = std::min(last[i], n_[i] - 1);
      }
    }
  }
  int wrapped(int c, int axis) const { return c < 0 ? c + n_[axis] : (c >= n_[axis] ? c - n_[axis] : c); }
  const std::int32_t* row(int y) const { return cells_.data() + static_cast<std::size_t>(wrapped(y, 1)) * n_[0]; }

  Domain<2> domain_;
  int n_[2];
  double inv_edge_[2];
  std::vector<std::int32_t> cells_;
};

/// Appends q to the samples and records it in its grid cell; returns its index.
inline std::int32_t append_sample(PointSet<2>& points, CellGrid& grid, const Point<2>& q) {
  if (points.size() >= static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
    throw InvalidArgument("dunbar-humphreys: more than 2^31 - 1 samples");
  const auto index = static_cast<std::int32_t>(points.size());
  points.push_back(q);
  grid.at(q) = index;
  return index;
}

}  // namespace pds::detail::dh
