#pragma once
// Test helpers for stratified point sets: how many points fall in each box of
// a grid over the unit cube, and the (t, m, s)-net check built on it.

#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <type_traits>
#include <vector>

#include "pds/point.h"

namespace pds::test {

/// Points per box of the grid with divisions[k] equal parts along axis k of
/// [0, 1)^D (box index: axis 0 fastest). Points outside the cube are counted
/// in an extra last entry, so they make every check fail.
template <int D>
std::vector<std::uint32_t> box_counts(const PointSet<D>& points,
                                      const std::type_identity_t<std::array<std::uint64_t, D>>& divisions) {
  std::uint64_t boxes = 1;
  for (auto d : divisions) boxes *= d;
  std::vector<std::uint32_t> counts(boxes + 1, 0);
  for (const auto& p : points) {
    std::uint64_t index = 0, stride = 1;
    bool inside = true;
    for (int k = 0; k < D; ++k) {
      if (!(p[k] >= 0.0 && p[k] < 1.0)) inside = false;
      const auto cell = static_cast<std::uint64_t>(std::floor(p[k] * static_cast<double>(divisions[k])));
      if (cell >= divisions[k]) inside = false;
      index += cell * stride;
      stride *= divisions[k];
    }
    ++counts[inside ? index : boxes];
  }
  return counts;
}

/// Describes the first box whose count differs from `expected`, or "".
template <int D>
std::string stratification_error(const PointSet<D>& points,
                                 const std::type_identity_t<std::array<std::uint64_t, D>>& divisions,
                                 std::uint32_t expected) {
  const auto counts = box_counts(points, divisions);
  if (counts.back() != 0) return std::to_string(counts.back()) + " points outside the unit cube";
  for (std::size_t b = 0; b + 1 < counts.size(); ++b)
    if (counts[b] != expected) {
      std::string grid;
      for (auto d : divisions) {
        if (!grid.empty()) grid += 'x';
        grid += std::to_string(d);
      }
      return "box " + std::to_string(b) + " of the " + grid + " grid holds " + std::to_string(counts[b]) +
             " points, expected " + std::to_string(expected);
    }
  return "";
}

/// "" if the points form a (t, m, D)-net in base 2: every elementary box
/// 2^-a_0 x ... x 2^-a_{D-1} with a_0 + ... = m - t holds exactly 2^t points.
template <int D>
std::string net_error(const PointSet<D>& points, int m, int t) {
  if (points.size() != (std::size_t{1} << m)) return "expected 2^m points";
  std::array<int, D> a{};
  std::string error;
  // Every composition of m - t into D non-negative parts.
  auto visit = [&](auto&& self, int axis, int left) -> void {
    if (!error.empty()) return;
    if (axis == D - 1) {
      a[axis] = left;
      std::array<std::uint64_t, D> divisions;
      for (int k = 0; k < D; ++k) divisions[k] = std::uint64_t{1} << a[k];
      error = stratification_error(points, divisions, 1u << t);
      return;
    }
    for (int v = 0; v <= left; ++v) {
      a[axis] = v;
      self(self, axis + 1, left - v);
    }
  };
  visit(visit, 0, m - t);
  return error;
}

}  // namespace pds::test
