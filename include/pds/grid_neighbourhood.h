#pragma once
// The cell arithmetic of a uniform background grid over a box or a torus:
// which cells lie near a cell or a point, once each or once per periodic
// image, with the wrap across a torus's seam and the clipping at a box's
// faces written in one place.
//
// Two ways to ask:
//  * A Window is a block of cells, [first, first + count) along each axis,
//    each cell visited once: clipped to the grid on a box; on a torus wrapped
//    across the seam, and the whole axis when the block spans a period (so a
//    cell is never visited twice). The caller decides the block (the cells
//    within `reach` cells of a centre cell, or the cells that a distance
//    around a point can touch), so its own rounding stays its own.
//  * A Stencil is a list of cell offsets (for example every cell whose gap to
//    the centre cell is below a distance, nearest first). Each offset names
//    one periodic image: on a torus whose period along an axis is a few cells
//    or less, several offsets fall on the same cell, and for_each_image()
//    reports by how many whole periods each lies from the stored cell. Cells
//    outside a box are skipped. A cell whose stencil stays inside the grid
//    takes precomputed linear offsets (the interior shortcut).
//
// Axes may have different cell counts and widths (a box one cell thin along
// one axis has far smaller cells along another). Visiting order is fixed:
// windows with axis 0 fastest; stencils in their list order.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <utility>
#include <vector>

#include "pds/domain.h"

namespace pds {

template <int D>
class GridNeighbourhood {
 public:
  using Coords = std::array<int, D>;

  /// A block of cells, each visited once (see the file comment).
  struct Window {
    Coords first{};  // on a torus in [0, cells); the block may run past the end and wraps
    Coords count{};
    bool empty = false;  // a box window that misses the grid
    bool seam = false;   // torus only: it crosses the seam or spans a whole period, so
                         // coordinates differ from the nearest images'
  };

  /// Cell offsets relative to a centre cell (see the file comment).
  struct Stencil {
    std::vector<Coords> steps;
    std::vector<std::ptrdiff_t> linear;  // the same steps as index offsets
    Coords reach{};                      // the largest |step| along each axis
  };

  GridNeighbourhood() = default;
  /// `cells` cells along each axis of the domain, of edge extent / cells.
  /// The most cells a stencil reaches along an axis (a torus a 4096th of the
  /// distance thin needs 4096 images of each cell).
  static constexpr int kMaxStencilReach = 4096;

  GridNeighbourhood(const Domain<D>& domain, const Coords& cells) : periodic_(domain.periodic), cells_(cells) {
    std::size_t stride = 1;
    for (int a = 0; a < D; ++a) {
      edge_[a] = domain.extent(a) / cells[a];
      stride_[a] = stride;
      stride *= static_cast<std::size_t>(cells[a]);
    }
    size_ = stride;
  }

  bool periodic() const { return periodic_; }
  int cells(int axis) const { return cells_[axis]; }
  const Coords& cells() const { return cells_; }
  double edge(int axis) const { return edge_[axis]; }
  std::size_t stride(int axis) const { return stride_[axis]; }
  std::size_t size() const { return size_; }

  std::size_t index(const Coords& c) const {
    std::size_t i = 0;
    for (int a = 0; a < D; ++a) i += static_cast<std::size_t>(c[a]) * stride_[a];
    return i;
  }
  Coords coords(std::size_t index) const {
    Coords c;
    for (int a = 0; a < D; ++a) {
      c[a] = static_cast<int>(index % static_cast<std::size_t>(cells_[a]));
      index /= static_cast<std::size_t>(cells_[a]);
    }
    return c;
  }

  /// The cell coordinate u (any integer) taken into [0, cells) along a torus
  /// axis, and how many whole periods u lies above it (u = cell + periods n).
  int wrap(int u, int axis, int& periods) const {
    const int n = cells_[axis];
    if (u >= 0 && u < n) {
      periods = 0;
      return u;
    }
    periods = u / n - (u % n < 0 ? 1 : 0);
    return u - periods * n;
  }

  // ---- windows -------------------------------------------------------------

  /// The cells [lo, hi] along each axis (inclusive; any integers), clipped
  /// or wrapped (see Window).
  Window window(const Coords& lo, const Coords& hi) const {
    Window w;
    for (int a = 0; a < D; ++a) {
      int first = lo[a], last = hi[a];
      if (periodic_) {
        if (last - first + 1 >= cells_[a]) {
          first = 0;
          last = cells_[a] - 1;
          w.seam = true;
        } else {
          int periods;
          const int start = wrap(first, a, periods);
          w.seam = w.seam || periods != 0 || start + (last - first) >= cells_[a];
          last = start + (last - first);
          first = start;
        }
      } else {
        first = std::max(first, 0);
        last = std::min(last, cells_[a] - 1);
        if (first > last) w.empty = true;
      }
      w.first[a] = first;
      w.count[a] = last - first + 1;
    }
    return w;
  }

  /// The cells within reach[a] cells of `centre` along each axis.
  Window window_around(const Coords& centre, const Coords& reach) const {
    Coords lo, hi;
    for (int a = 0; a < D; ++a) {
      lo[a] = centre[a] - reach[a];
      hi[a] = centre[a] + reach[a];
    }
    return window(lo, hi);
  }

  /// Calls f(index, coords) for every cell of the window, axis 0 fastest; f
  /// returns false to stop. Returns false if stopped.
  template <class F>
  bool for_each_cell(const Window& w, F&& f) const {
    if (w.empty) return true;
    Coords offset{}, c;
    while (true) {
      std::size_t row = 0;
      for (int a = 1; a < D; ++a) {
        const int u = w.first[a] + offset[a];
        c[a] = u >= cells_[a] ? u - cells_[a] : u;
        row += static_cast<std::size_t>(c[a]) * stride_[a];
      }
      for (int k = 0; k < w.count[0]; ++k) {
        const int u = w.first[0] + k;
        c[0] = u >= cells_[0] ? u - cells_[0] : u;
        if (!f(row + static_cast<std::size_t>(c[0]), static_cast<const Coords&>(c))) return false;
      }
      int axis = 1;
      while (axis < D && ++offset[axis] == w.count[axis]) offset[axis++] = 0;
      if (axis >= D) return true;
    }
  }

  /// For a window that does not cross a torus's seam: calls f(index) with the
  /// first cell of each row (the window's count[0] cells from there on are
  /// consecutive indices), axes 1.. in for_each_cell's order.
  template <class F>
  void for_each_row(const Window& w, F&& f) const {
    if (w.empty) return;
    Coords offset{};
    while (true) {
      std::size_t row = static_cast<std::size_t>(w.first[0]);
      for (int a = 1; a < D; ++a) row += static_cast<std::size_t>(w.first[a] + offset[a]) * stride_[a];
      f(row);
      int axis = 1;
      while (axis < D && ++offset[axis] == w.count[axis]) offset[axis++] = 0;
      if (axis >= D) return;
    }
  }

  // ---- stencils ------------------------------------------------------------

  /// The squared gap between a cell and the cell at `step` from it: along
  /// each axis (|step| - 1) edges, none for |step| <= 1.
  double gap2(const Coords& step) const {
    double g2 = 0.0;
    for (int a = 0; a < D; ++a) {
      const double gap = std::max(0, std::abs(step[a]) - 1) * edge_[a];
      g2 += gap * gap;
    }
    return g2;
  }

  /// Every offset but the centre whose gap2() is below distance^2 (1 +
  /// tolerance), nearest first (ties in the order of enumeration, axis 0
  /// fastest). The tolerance widens the test against rounding and must stay
  /// far below a cell (offsets are sought within ceil(distance / edge) + 1
  /// cells). Not cut at half a period: on a short torus the far offsets are
  /// further images of the same cells.
  Stencil stencil_within(double distance, double tolerance = 0.0) const {
    const double max_gap2 = distance * distance * (1.0 + tolerance);
    Coords reach;
    for (int a = 0; a < D; ++a) {
      // In double first: an axis far shorter than the distance would overflow
      // an int. A box has no cells beyond its own; a torus needs every image,
      // and more than kMaxStencilReach of them is refused.
      double r = std::ceil(distance / edge_[a]) + 1.0;
      if (!periodic_) r = std::min(r, static_cast<double>(cells_[a]));
      if (!(r <= kMaxStencilReach))
        throw InvalidArgument("grid: distance " + detail::format_number(distance) + " spans more than " +
                              std::to_string(kMaxStencilReach) + " cells of axis " + std::to_string(a) +
                              " (a period of " + detail::format_number(edge_[a] * cells_[a]) +
                              "): the domain is too thin for this radius");
      reach[a] = static_cast<int>(r);
    }
    std::vector<std::pair<double, Coords>> found;
    Coords o;
    for (int a = 0; a < D; ++a) o[a] = -reach[a];
    while (true) {
      bool self = true;
      for (int a = 0; a < D; ++a) self = self && o[a] == 0;
      const double g2 = gap2(o);
      if (!self && g2 < max_gap2) found.push_back({g2, o});
      int a = 0;
      while (a < D && ++o[a] > reach[a]) {
        o[a] = -reach[a];
        ++a;
      }
      if (a == D) break;
    }
    std::stable_sort(found.begin(), found.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    std::vector<Coords> steps;
    steps.reserve(found.size());
    for (const auto& [g2, step] : found) steps.push_back(step);
    return stencil(std::move(steps));
  }

  /// A stencil of the given offsets, in that order.
  Stencil stencil(std::vector<Coords> steps) const {
    Stencil s;
    s.steps = std::move(steps);
    s.linear.reserve(s.steps.size());
    for (const Coords& step : s.steps) {
      std::ptrdiff_t linear = 0;
      for (int a = 0; a < D; ++a) {
        linear += step[a] * static_cast<std::ptrdiff_t>(stride_[a]);
        s.reach[a] = std::max(s.reach[a], std::abs(step[a]));
      }
      s.linear.push_back(linear);
    }
    return s;
  }

  /// The offsets of `s` for which keep(step) holds, in the same order.
  template <class Keep>
  Stencil filter(const Stencil& s, Keep&& keep) const {
    std::vector<Coords> steps;
    for (const Coords& step : s.steps)
      if (keep(step)) steps.push_back(step);
    return stencil(std::move(steps));
  }

  /// Whether every offset of `s` from cell c stays inside the grid (no wrap).
  bool interior(const Stencil& s, const Coords& c) const {
    bool inside = true;
    for (int a = 0; a < D; ++a) inside = inside && c[a] >= s.reach[a] && c[a] + s.reach[a] < cells_[a];
    return inside;
  }

  /// Calls f(index) for the cell at each offset of `s` from cell c (index
  /// `cell`), in order, skipping cells outside a box; stops when f returns
  /// true and returns whether it did.
  template <class F>
  bool any(const Stencil& s, const Coords& c, std::size_t cell, F&& f) const {
    if (interior(s, c)) {
      for (const std::ptrdiff_t off : s.linear)
        if (f(static_cast<std::size_t>(static_cast<std::ptrdiff_t>(cell) + off))) return true;
      return false;
    }
    for (const Coords& step : s.steps) {
      std::size_t index = 0;
      if (!image(c, step, index, nullptr)) continue;
      if (f(index)) return true;
    }
    return false;
  }

  /// Calls f(index, periods) for the cell at each offset of `s` from cell c
  /// (index `cell`), in order: `periods` says by how many whole periods along
  /// each axis the offset's cell lies from the stored one (zero on a box and
  /// away from a torus's seam). Cells outside a box are skipped.
  template <class F>
  void for_each_image(const Stencil& s, const Coords& c, std::size_t cell, F&& f) const {
    const Coords none{};
    if (interior(s, c)) {
      for (const std::ptrdiff_t off : s.linear)
        f(static_cast<std::size_t>(static_cast<std::ptrdiff_t>(cell) + off), none);
      return;
    }
    for (const Coords& step : s.steps) {
      std::size_t index = 0;
      Coords periods{};
      if (image(c, step, index, &periods)) f(index, static_cast<const Coords&>(periods));
    }
  }

 private:
  /// The cell at `step` from c: false outside a box.
  bool image(const Coords& c, const Coords& step, std::size_t& index, Coords* periods) const {
    index = 0;
    for (int a = 0; a < D; ++a) {
      int u = c[a] + step[a];
      if (periodic_) {
        int p;
        u = wrap(u, a, p);
        if (periods) (*periods)[a] = p;
      } else if (u < 0 || u >= cells_[a]) {
        return false;
      }
      index += static_cast<std::size_t>(u) * stride_[a];
    }
    return true;
  }

  bool periodic_ = false;
  Coords cells_{};
  std::array<double, D> edge_{};
  std::array<std::size_t, D> stride_{};
  std::size_t size_ = 0;
};

}  // namespace pds
