#pragma once
// Points in D dimensions and sets of them.
//
// Point<D> is a plain std::array so that a PointSet<D> is one contiguous block
// of D*N doubles, cheap to copy to files and to other libraries.

#include <algorithm>
#include <array>
#include <cstddef>
#include <ostream>
#include <vector>

namespace pds {

/// The dimensions a typed Point<D> is instantiated for: the Poisson disk
/// samplers whose papers are dimension-generic and the analysis run in all of
/// them (docs/dimensions.md). Most other typed code is instantiated for the
/// plane and space only (visit_dim's default range).
inline constexpr int kMinDim = 1;
inline constexpr int kMaxDim = 8;
inline constexpr int kPlaneDim = 2;
inline constexpr int kSpaceDim = 3;
/// The widest point a file or a PointCloud may hold: sequences and designs
/// are made in run-time dimensions up to Sobol's 21,201 and beyond.
inline constexpr int kMaxCloudDim = 1 << 20;

/// A point is a std::array of its coordinates; the derived type lets
/// templates deduce D (std::array's size is a size_t).
template <int D>
struct Point : std::array<double, D> {
  static constexpr int dim = D;
};

template <int D>
using PointSet = std::vector<Point<D>>;

template <int D>
std::ostream& operator<<(std::ostream& os, const Point<D>& p) {
  os << '(';
  for (int i = 0; i < D; ++i) os << (i ? ", " : "") << p[i];
  return os << ')';
}

namespace detail {
/// Asks for huge pages (Linux's transparent huge pages) over the whole pages
/// of [p, p + bytes): fewer page faults for a large block about to be
/// written. A hint, ignored where not offered.
void advise_huge_pages(void* p, std::size_t bytes) noexcept;
/// Gives the whole pages of [p, p + bytes) back to the system (they read as
/// zeros afterwards): for a block whose contents are no longer needed but
/// which its owner frees later. A hint, ignored where not offered.
void release_pages(void* p, std::size_t bytes) noexcept;
/// Gives the pages past a vector's size back to the system, its capacity
/// kept: for a vector that only shrinks, where shrink_to_fit would copy it
/// and hold both copies at once.
template <class T>
void release_unused(std::vector<T>& v) noexcept {
  release_pages(v.data() + v.size(), (v.capacity() - v.size()) * sizeof(T));
}
}  // namespace detail

/// A point set whose dimension is known only at run time: what files hold and
/// what the registry returns. Coordinates are stored point after point.
struct PointCloud {
  int dim = 2;
  std::vector<double> coords;

  std::size_t size() const { return dim > 0 ? coords.size() / static_cast<std::size_t>(dim) : 0; }
  const double* point(std::size_t i) const { return coords.data() + i * static_cast<std::size_t>(dim); }

  template <int D>
  static PointCloud from(const PointSet<D>& points) {
    // One block copy: a PointSet<D> is D doubles a point, back to back.
    static_assert(sizeof(Point<D>) == D * sizeof(double));
    PointCloud cloud{D, {}};
    cloud.coords.reserve(points.size() * D);
    detail::advise_huge_pages(cloud.coords.data(), points.size() * sizeof(Point<D>));
    const double* first = points.empty() ? nullptr : points.front().data();
    cloud.coords.assign(first, first + points.size() * D);
    return cloud;
  }

  /// The same from a set that is not needed afterwards: its pages are given
  /// back as the copy passes them, so that the two blocks are not both
  /// resident (a sampler's output and the cloud were the peak of several
  /// methods). `points` is left empty.
  template <int D>
  static PointCloud from(PointSet<D>&& points) {
    static_assert(sizeof(Point<D>) == D * sizeof(double));
    PointCloud cloud{D, {}};
    const std::size_t total = points.size() * D;
    cloud.coords.reserve(total);
    detail::advise_huge_pages(cloud.coords.data(), total * sizeof(double));
    double* first = points.empty() ? nullptr : points.front().data();
    constexpr std::size_t kChunk = (std::size_t{2} << 20) / sizeof(double);  // a huge page of doubles
    for (std::size_t done = 0; done < total; done += kChunk) {
      const std::size_t n = std::min(kChunk, total - done);
      cloud.coords.insert(cloud.coords.end(), first + done, first + done + n);
      detail::release_pages(first + done, n * sizeof(double));
    }
    PointSet<D>().swap(points);
    return cloud;
  }

  /// The points as a typed set; requires dim == D.
  template <int D>
  PointSet<D> as() const {
    PointSet<D> points(size());
    for (std::size_t i = 0; i < points.size(); ++i)
      for (int k = 0; k < D; ++k) points[i][k] = coords[i * D + k];
    return points;
  }

  bool operator==(const PointCloud&) const = default;
};

/// Calls f(std::integral_constant<int, D>{}) for the run-time dimension dim,
/// D in [Lo, Hi] (within [kMinDim, kMaxDim]); throws InvalidArgument naming
/// the range for any other dim. Without a range: the plane and space (2, 3).
template <int Lo, int Hi, class F>
decltype(auto) visit_dim(int dim, F&& f);
template <class F>
decltype(auto) visit_dim(int dim, F&& f);

}  // namespace pds

#include "pds/detail/visit_dim.h"
