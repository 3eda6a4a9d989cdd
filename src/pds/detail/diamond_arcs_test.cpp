#include "pds/detail/diamond_arcs.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

namespace pds::detail {
namespace {

constexpr double kPi = std::numbers::pi;

double true_angle(double t) {
  const auto [x, y] = diamond_direction(t);
  const double a = std::atan2(y, x);
  return a < 0.0 ? a + 2.0 * kPi : a;
}

// True when t lies strictly inside `arc` (diamond angles, wrapping at 4).
bool inside(const DiamondArc& arc, double t) {
  const double past = diamond_past(t, arc.lo);
  return past > 0.0 && past < arc.len;
}

double distance_to_end(const DiamondArc& arc, double t) {
  const double end = std::fmod(arc.lo + arc.len, 4.0);
  auto circular = [](double a, double b) { return std::min(std::abs(a - b), 4.0 - std::abs(a - b)); };
  return std::min(circular(t, arc.lo), circular(t, end));
}

TEST(DiamondAngle, IncreasesWithTheTrueAngleAndInvertsDiamondDirection) {
  const int n = 100000;
  double previous = -1.0;
  for (int k = 0; k < n; ++k) {
    const double theta = 2.0 * kPi * k / n;
    const double t = diamond_angle(std::cos(theta), std::sin(theta));
    ASSERT_GT(t, previous) << "theta " << theta;
    ASSERT_LT(t, 4.0);
    previous = t;
    EXPECT_NEAR(true_angle(t), theta, 1e-14 + 1e-15 * theta) << "t " << t;
    const auto [x, y] = diamond_direction(t);
    EXPECT_NEAR(diamond_angle(x, y), t, 4e-16 * 4.0);
  }
}

// The one-division arc agrees with diamond_arc to a few ulps, for ends of
// unequal size near 1, on the axes and across the wrap at 4, and an arc a
// few ulps long (or empty) never comes out as almost a full turn.
TEST(DiamondArc, OneDivisionFormMatchesTwoDivisions) {
  Rng rng(21);
  const auto circular = [](double a, double b) { return std::min(std::abs(a - b), 4.0 - std::abs(a - b)); };
  int wrapped = 0, tiny = 0;
  for (int trial = 0; trial < 200000; ++trial) {
    // Every 8th start on an axis (exact components), every 4th arc tiny.
    const double theta = trial % 8 == 0 ? 0.5 * kPi * rng.below(4) : rng.uniform(0.0, 2.0 * kPi);
    const double width = trial % 4 == 0 ? 1e-15 * rng.below(8) : rng.uniform(0.0, 2.1);
    const double sa = rng.uniform(0.25, 1.0), sb = trial % 4 == 0 ? sa : rng.uniform(0.25, 1.0);
    const double ax = trial % 8 == 0 ? std::round(std::cos(theta)) : std::cos(theta);
    const double ay = trial % 8 == 0 ? std::round(std::sin(theta)) : std::sin(theta);
    const double bx = width == 0.0 ? ax : std::cos(theta + width), by = width == 0.0 ? ay : std::sin(theta + width);
    const DiamondArc two = diamond_arc(sa * ax, sa * ay, sb * bx, sb * by);
    const DiamondArc one = diamond_arc_one_division(sa * ax, sa * ay, sb * bx, sb * by);
    ASSERT_GE(one.lo, 0.0) << "trial " << trial;
    ASSERT_LT(one.lo, 4.0) << "trial " << trial;
    ASSERT_GE(one.len, 0.0) << "trial " << trial;
    ASSERT_LE(one.len, 2.1) << "trial " << trial;
    ASSERT_LE(circular(one.lo, two.lo), 4e-15) << "trial " << trial;
    if (two.len < 3.0) {
      ASSERT_NEAR(one.len, two.len, 8e-15) << "trial " << trial;
    }
    if (width == 0.0 && sa == sb) {
      ASSERT_EQ(one.len, 0.0) << "trial " << trial;
    }
    wrapped += one.lo + one.len > 4.0;
    tiny += width < 1e-14;
  }
  EXPECT_GT(wrapped, 1000);  // the wrap at 4 was exercised
  EXPECT_GT(tiny, 40000);
  // An end that rounds a hair before its start: an empty arc, not a full turn
  // (diamond_arc, for which this is a legitimate almost full turn, says 4 - 3e-15).
  int reversed = 0;
  for (int k = 0; k < 1000; ++k) {
    const double theta = rng.uniform(0.0, 2.0 * kPi);
    const double ax = std::cos(theta), ay = std::sin(theta), bx = std::cos(theta - 3e-15), by = std::sin(theta - 3e-15);
    if (!(diamond_arc(ax, ay, bx, by).len > 3.0)) continue;  // rounded onto the start
    ASSERT_EQ(diamond_arc_one_division(ax, ay, bx, by).len, 0.0) << "theta " << theta;
    ++reversed;
  }
  EXPECT_GT(reversed, 500);
}

// The free set equals the complement of the blocked arcs, before and after
// cuts, at random probes away from the arcs' ends (where rounding decides).
TEST(FreeArcs, ComplementAndCutsMatchBruteForce) {
  Rng rng(11);
  FreeArcs free;
  for (int trial = 0; trial < 2000; ++trial) {
    std::vector<DiamondArc> blocked(rng.below(11));
    for (auto& a : blocked) a = {rng.uniform(0.0, 4.0), rng.uniform(0.0, 2.0)};
    std::vector<double> lo, len;
    for (const auto& a : blocked) lo.push_back(a.lo), len.push_back(a.len);
    free.assign_complement_unsorted(lo.data(), len.data(), static_cast<int>(lo.size()));
    const int cuts = static_cast<int>(rng.below(4));
    for (int c = 0; c < cuts; ++c) {
      const DiamondArc cut{rng.uniform(0.0, 4.0), rng.uniform(0.0, 1.5)};
      free.remove(cut);
      blocked.push_back(cut);
    }
    for (const DiamondArc& a : free.arcs()) {
      ASSERT_GE(a.lo, 0.0);
      ASSERT_LT(a.lo, 4.0);
      ASSERT_GT(a.len, 0.0);
    }
    for (int probe = 0; probe < 100; ++probe) {
      const double t = rng.uniform(0.0, 4.0);
      bool near_end = false, is_blocked = false, is_free = false;
      for (const DiamondArc& a : blocked) {
        near_end |= distance_to_end(a, t) < 1e-9;
        is_blocked |= inside(a, t);
      }
      for (const DiamondArc& a : free.arcs()) {
        near_end |= distance_to_end(a, t) < 1e-9;
        is_free |= inside(a, t);
      }
      if (near_end) continue;
      ASSERT_NE(is_free, is_blocked) << "trial " << trial << " t " << t;
    }
    EXPECT_EQ(free.empty(), free.arcs().empty());
  }
}

// The free arcs by the textbook method: sort the blocked arcs by start, then
// sweep once, opening a gap wherever the next start lies past what is
// covered so far (from 0, where arcs wrapping past 4 already cover).
std::vector<DiamondArc> sorted_sweep(std::vector<DiamondArc> blocked) {
  std::stable_sort(blocked.begin(), blocked.end(),
                   [](const DiamondArc& a, const DiamondArc& b) { return a.lo < b.lo; });
  std::vector<DiamondArc> free;
  double covered = 0.0;
  for (const auto& a : blocked) covered = std::max(covered, a.lo + a.len - 4.0);
  for (const auto& a : blocked) {
    if (a.lo - covered > 1e-13) free.push_back({covered, a.lo - covered});
    covered = std::max(covered, a.lo + a.len);
  }
  if (4.0 - covered > 1e-13) free.push_back({covered, 4.0 - covered});
  return free;
}

// The sort-free complement computes the same free arcs as the sorted sweep,
// bit for bit (only their order differs), including arcs that share a start.
TEST(FreeArcs, UnsortedComplementEqualsTheSortedSweep) {
  Rng rng(12);
  const auto by_start = [](std::vector<DiamondArc> arcs) {
    std::sort(arcs.begin(), arcs.end(),
              [](const DiamondArc& a, const DiamondArc& b) { return a.lo < b.lo || (a.lo == b.lo && a.len < b.len); });
    return arcs;
  };
  for (int trial = 0; trial < 5000; ++trial) {
    std::vector<DiamondArc> blocked(rng.below(FreeArcs::kMaxBlocked + 1));
    for (auto& a : blocked) a = {rng.uniform(0.0, 4.0), rng.uniform(0.0, 1.2)};
    if (blocked.size() > 2 && trial % 3 == 0) blocked[1].lo = blocked[0].lo;  // a shared start
    std::vector<double> lo, len;
    for (const auto& a : blocked) lo.push_back(a.lo), len.push_back(a.len);
    FreeArcs unsorted;
    unsorted.assign_complement_unsorted(lo.data(), len.data(), static_cast<int>(lo.size()));
    const auto a = by_start(sorted_sweep(blocked));
    const auto b = by_start({unsorted.arcs().begin(), unsorted.arcs().end()});
    ASSERT_EQ(a.size(), b.size()) << "trial " << trial;
    for (std::size_t i = 0; i < a.size(); ++i) {
      ASSERT_EQ(a[i].lo, b[i].lo) << "trial " << trial;
      ASSERT_EQ(a[i].len, b[i].len) << "trial " << trial;
    }
  }
}

double chi_square_of_true_angles(const FreeArcs& free, bool corrected, int draws, int bins) {
  Rng rng(5);
  std::vector<double> counts(static_cast<std::size_t>(bins));
  for (int i = 0; i < draws; ++i) {
    const double t = corrected ? free.sample(rng) : free.at(rng.uniform());
    counts[std::min(static_cast<std::size_t>(bins - 1),
                    static_cast<std::size_t>(true_angle(t) / (2.0 * kPi) * bins))] += 1;
  }
  const double expected = static_cast<double>(draws) / bins;
  double chi2 = 0.0;
  for (double c : counts) chi2 += (c - expected) * (c - expected) / expected;
  return chi2;
}

// sample() is uniform in true angle over the whole circle; uniform diamond
// angles alone (at()) are not: twice as dense on the axes as on the diagonals.
TEST(FreeArcs, SampleIsUniformInTrueAngle) {
  FreeArcs free;
  free.assign_complement_unsorted(nullptr, nullptr, 0);
  // 83.0: the 1e-5 upper quantile of chi-square with 35 degrees of freedom
  // (Wilson-Hilferty).
  EXPECT_LT(chi_square_of_true_angles(free, true, 360000, 36), 83.0);
  EXPECT_GT(chi_square_of_true_angles(free, false, 360000, 36), 1000.0);
}

// Over two free arcs each gets draws in proportion to its true angular length,
// and every draw lies inside a free arc.
TEST(FreeArcs, SampleSplitsBetweenArcsByTrueLength) {
  const double lo[2] = {0.9, 3.7}, len[2] = {1.6, 0.6};  // free: [0.3, 0.9) and [2.5, 3.7)
  FreeArcs free;
  free.assign_complement_unsorted(lo, len, 2);
  ASSERT_EQ(free.arcs().size(), 2u);
  const auto length = [](double lo, double hi) {
    double d = true_angle(hi) - true_angle(lo);
    return d < 0.0 ? d + 2.0 * kPi : d;
  };
  const double first = length(0.3, 0.9), second = length(2.5, 3.7);
  const double p = first / (first + second);
  Rng rng(8);
  const int draws = 100000;
  int in_first = 0;
  for (int i = 0; i < draws; ++i) {
    const double t = free.sample(rng);
    ASSERT_TRUE((t >= 0.3 && t < 0.9) || (t >= 2.5 && t < 3.7)) << t;
    in_first += t < 0.9;
  }
  const double sd = std::sqrt(p * (1.0 - p) / draws);
  EXPECT_NEAR(static_cast<double>(in_first) / draws, p, 5.0 * sd);
}

}  // namespace
}  // namespace pds::detail
