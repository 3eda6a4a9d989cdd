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

#include "../mapped_pages.h"
#include "pds/domain.h"
#include "pds/error.h"
#include "pds/grid_neighbourhood.h"
#include "pds/point.h"

namespace pds::detail::dh {

/// Cells of a grid window, each side of the centre cell, per axis.
using Reach = std::array<int, 2>;

/// One sample index per cell (or -1). Cells have edge <= r / sqrt(2), so a
/// set with minimum distance r has at most one sample per cell; a flat int32
/// array is smaller and faster here than the general pds::Grid's lists. The
/// windows of cells, their wrap across a torus's seam and their clipping at a
/// box's walls are pds::GridNeighbourhood's; the cell of a point (clamped
/// into the grid) and the reach of a distance stay here.
class CellGrid {
 public:
  using Window = GridNeighbourhood<2>::Window;

  CellGrid(const Domain<2>& domain, double cell_edge) : domain_(domain) {
    Reach n;
    for (int i = 0; i < 2; ++i) {
      const double cells = std::max(1.0, std::ceil(domain.extent(i) / cell_edge));
      if (cells > 1e9) throw InvalidArgument("dunbar-humphreys: radius too small for the domain");
      n[i] = static_cast<int>(cells);
      inv_edge_[i] = cells / domain.extent(i);
    }
    if (static_cast<double>(n[0]) * n[1] > static_cast<double>(std::size_t{1} << 31))
      throw InvalidArgument("dunbar-humphreys: radius too small for the domain (grid above 2^31 cells)");
    neighbourhood_ = GridNeighbourhood<2>(domain, n);
    // In huge pages where offered: the fill touches every cell, and at 10^6
    // samples (9 MB) its 4 KiB page faults were a sixth of the run.
    cells_ = map_zeroed<std::int32_t>(neighbourhood_.size(), Pages::kHuge);
    std::fill_n(cells_.get(), neighbourhood_.size(), -1);
  }
  int n(int axis) const { return neighbourhood_.cells(axis); }
  /// How many cells around a sample's cell can hold a sample within
  /// `distance`, per axis (a box one cell thin across has far smaller cells
  /// along its other axis).
  Reach reach(double distance) const {
    return {static_cast<int>(std::ceil(distance * inv_edge_[0])), static_cast<int>(std::ceil(distance * inv_edge_[1]))};
  }
  int coord(double x, int axis) const {
    const int c = static_cast<int>((x - domain_.lo[axis]) * inv_edge_[axis]);
    return std::clamp(c, 0, n(axis) - 1);
  }
  std::int32_t& at(int cx, int cy) { return cells_[static_cast<std::size_t>(cy) * n(0) + cx]; }
  std::int32_t& at(const Point<2>& p) { return at(coord(p[0], 0), coord(p[1], 1)); }

  /// The cells within `reach` cells of p's cell, each once: clipped in a box;
  /// on a torus `first` inside the grid and the block wrapping past its end,
  /// `seam` when nearest images are needed (it crosses a seam or spans an
  /// axis).
  Window window(const Point<2>& p, Reach reach) const {
    return neighbourhood_.window_around({coord(p[0], 0), coord(p[1], 1)}, reach);
  }

  /// Calls f(index) for every stored sample in the cells within `reach`
  /// cells of p's cell (each cell once, wrapping on a torus; rows in turn,
  /// x fastest).
  template <class F>
  void for_each_near(const Point<2>& p, Reach reach, F&& f) const {
    neighbourhood_.for_each_cell(window(p, reach), [&](std::size_t cell, const Reach&) {
      const std::int32_t j = cells_[cell];
      if (j >= 0) f(j);
      return true;
    });
  }

  std::size_t bytes() const { return neighbourhood_.size() * sizeof(std::int32_t); }
  /// Asks for the rows of p's window to be brought into the cache.
  void prefetch_window(const Point<2>& p, Reach reach) const {
    const Window w = window(p, reach);
    for (int y = 0; y < w.count[1]; ++y) __builtin_prefetch(row(w.first[1] + y) + w.first[0]);
  }

  // collect_near's window width: 2 radius is 2.83 cells of radius / sqrt 2,
  // up to 3.33 where rounding the cell count up shrinks the cells (a torus
  // period of 4 radius), so the reach is at most 4; a box that narrow has
  // fewer cells than that across.
  static constexpr int kMaxWindow = 9;

  /// The same samples written to `out` (room for (2 reach + 1)^2), their
  /// number returned: no branch per cell, for the hot loop of boundary
  /// sampling. `seam` tells whether the window crossed a torus seam.
  int collect_near(const Point<2>& p, Reach reach, std::int32_t* out, bool& seam) const {
    const Window w = window(p, reach);
    seam = w.seam;
    if (w.count[0] > kMaxWindow) throw std::logic_error("dunbar-humphreys: neighbour window wider than planned");
    int n = 0;
    if (w.count[0] == 7 && w.first[0] + 7 <= this->n(0)) {  // the usual case: no column wraps, 7 wide
      for (int y = 0; y < w.count[1]; ++y) {
        const std::int32_t* row = this->row(w.first[1] + y) + w.first[0];
        for (int x = 0; x < 7; ++x) {
          const std::int32_t j = row[x];
          out[n] = j;
          n += j >= 0;
        }
      }
      return n;
    }
    neighbourhood_.for_each_cell(w, [&](std::size_t cell, const Reach&) {
      const std::int32_t j = cells_[cell];
      out[n] = j;
      n += j >= 0;
      return true;
    });
    return n;
  }

 private:
  /// Row y of the grid, y in [0, 2n) (a torus window runs past the end).
  const std::int32_t* row(int y) const {
    const int n = this->n(1);
    return cells_.get() + static_cast<std::size_t>(y >= n ? y - n : y) * this->n(0);
  }

  Domain<2> domain_;
  GridNeighbourhood<2> neighbourhood_;
  double inv_edge_[2];
  MappedArray<std::int32_t> cells_;
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
