#include "pds/samplers/unbounded.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <numeric>
#include <thread>
#include <vector>

#include "nn_statistics.h"
#include "pds/analysis/distance.h"
#include "pds/analysis/maximality.h"
#include "pds/error.h"
#include "pds/rng.h"
#include "pds/samplers/ebeida.h"

namespace pds {
namespace {

template <int D>
Domain<D> box(const Point<D>& lo, const Point<D>& hi) {
  return Domain<D>::box(lo, hi);
}

/// The chunks of `region` cut at `nx` x `ny` (x `nz`) equal parts, in a
/// shuffled order when `shuffle_seed` is not 0.
template <int D>
std::vector<Domain<D>> chunks(const Domain<D>& region, const std::array<int, D>& n, std::uint64_t shuffle_seed) {
  std::vector<Domain<D>> out;
  std::array<int, D> i{};
  while (true) {
    Domain<D> c;
    for (int a = 0; a < D; ++a) {
      // Cut points computed from the index alone, so that neighbouring chunks
      // share their seam exactly.
      const auto cut = [&](int k) {
        return k == n[a] ? region.hi[a] : region.lo[a] + region.extent(a) * k / n[a];
      };
      c.lo[a] = cut(i[a]);
      c.hi[a] = cut(i[a] + 1);
    }
    out.push_back(c);
    int a = 0;
    while (a < D && i[a] == n[a] - 1) i[a++] = 0;
    if (a == D) break;
    ++i[a];
  }
  if (shuffle_seed) {
    Rng rng(shuffle_seed);
    for (std::size_t k = out.size(); k > 1; --k) std::swap(out[k - 1], out[rng.below(k)]);
  }
  return out;
}

template <int D>
PointSet<D> union_of_chunks(const UnboundedField<D>& field, const std::vector<Domain<D>>& parts) {
  PointSet<D> all;
  for (const auto& part : parts) {
    const auto points = field.sample(part);
    for (const auto& p : points) EXPECT_TRUE(part.contains(p)) << p << " outside its chunk";
    all.insert(all.end(), points.begin(), points.end());
  }
  // The documented canonical order: lexicographic in the coordinates.
  std::sort(all.begin(), all.end(), [](const Point<D>& a, const Point<D>& b) {
    return static_cast<const std::array<double, D>&>(a) < static_cast<const std::array<double, D>&>(b);
  });
  return all;
}

template <int D>
bool same_bytes(const PointSet<D>& a, const PointSet<D>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(Point<D>)) == 0;
}

TEST(Unbounded, ChunksGiveTheSameBytesAsTheWholeRegion2D) {
  const UnboundedField<2> field({.radius = 1.0}, 17);
  const auto region = box<2>({{-7.3, 2.1}}, {{24.9, 19.6}});
  const auto whole = field.sample(region);
  ASSERT_GT(whole.size(), 250u);
  EXPECT_TRUE(same_bytes(whole, union_of_chunks(field, chunks(region, {2, 2}, 0))));
  EXPECT_TRUE(same_bytes(whole, union_of_chunks(field, chunks(region, {3, 5}, 0))));
  EXPECT_TRUE(same_bytes(whole, union_of_chunks(field, chunks(region, {7, 4}, 99))));
  // No pair closer than r anywhere, seams included.
  EXPECT_GE(min_distance_brute_force(whole, region).distance, 1.0);
}

TEST(Unbounded, ChunksGiveTheSameBytesAsTheWholeRegion3D) {
  const UnboundedField<3> field({.radius = 1.0, .darts_per_cell = 4.0}, 5);
  const auto region = box<3>({{0.0, -3.0, 1.5}}, {{5.0, 3.0, 5.0}});
  const auto whole = field.sample(region);
  ASSERT_GT(whole.size(), 40u);
  EXPECT_TRUE(same_bytes(whole, union_of_chunks(field, chunks(region, {2, 1, 1}, 3))));
  EXPECT_GE(min_distance_brute_force(whole, region).distance, 1.0);
}

// The object is immutable: chunks taken in a shuffled order by 4 threads give
// the same union as one thread.
TEST(Unbounded, ThreadsShareOneField) {
  const UnboundedField<2> field({.radius = 1.0}, 23);
  const auto region = box<2>({{-10.0, -10.0}}, {{20.0, 15.0}});
  const auto parts = chunks(region, {6, 5}, 31);
  std::vector<PointSet<2>> results(parts.size());
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t)
    threads.emplace_back([&, t] {
      for (std::size_t k = static_cast<std::size_t>(t); k < parts.size(); k += 4) results[k] = field.sample(parts[k]);
    });
  for (auto& thread : threads) thread.join();
  PointSet<2> all;
  for (const auto& r : results) all.insert(all.end(), r.begin(), r.end());
  std::sort(all.begin(), all.end(), [](const Point<2>& a, const Point<2>& b) {
    return static_cast<const std::array<double, 2>&>(a) < static_cast<const std::array<double, 2>&>(b);
  });
  EXPECT_TRUE(same_bytes(field.sample(region), all));
}

// A region inside another gives exactly the larger one's points that lie in it.
TEST(Unbounded, SubRegionIsTheRestriction) {
  const UnboundedField<2> field({.radius = 0.5}, 3);
  const auto big = field.sample(box<2>({{0.0, 0.0}}, {{12.0, 9.0}}));
  const auto inner_region = box<2>({{2.25, 1.5}}, {{7.0, 8.125}});
  PointSet<2> expected;
  for (const auto& p : big)
    if (inner_region.contains(p)) expected.push_back(p);
  ASSERT_GT(expected.size(), 50u);
  EXPECT_TRUE(same_bytes(expected, field.sample(inner_region)));
}

TEST(Unbounded, SeedDecidesThePoints) {
  const auto region = box<2>({{0.0, 0.0}}, {{10.0, 10.0}});
  const auto a = UnboundedField<2>({.radius = 1.0}, 1).sample(region);
  EXPECT_TRUE(same_bytes(a, UnboundedField<2>({.radius = 1.0}, 1).sample(region)));
  const auto b = UnboundedField<2>({.radius = 1.0}, 2).sample(region);
  std::size_t shared = 0;
  for (const auto& p : b) shared += std::binary_search(a.begin(), a.end(), p);
  EXPECT_EQ(shared, 0u);
}

// Far from the origin, on both sides: chunk invariance and spacing still hold.
TEST(Unbounded, FarFromTheOrigin) {
  const UnboundedField<2> field({.radius = 0.75}, 8);
  const auto region = box<2>({{1e6, -3e6 - 5.0}}, {{1e6 + 9.0, -3e6 + 4.0}});
  const auto whole = field.sample(region);
  ASSERT_GT(whole.size(), 60u);
  for (const auto& p : whole) EXPECT_TRUE(region.contains(p)) << p;
  EXPECT_GE(min_distance_brute_force(whole, region).distance, 0.75);
  EXPECT_TRUE(same_bytes(whole, union_of_chunks(field, chunks(region, {3, 2}, 7))));
  // Near the 2^40-cell limit, where positions round to 2^-12 of a cell.
  const UnboundedField<2> unit({.radius = 1.0}, 8);
  const auto edge = box<2>({{7e11, -7e11}}, {{7e11 + 8.0, -7e11 + 8.0}});
  const auto far = unit.sample(edge);
  ASSERT_GT(far.size(), 25u);
  EXPECT_GE(min_distance_brute_force(far, edge).distance, 1.0);
  EXPECT_TRUE(same_bytes(far, union_of_chunks(unit, chunks(edge, {2, 3}, 5))));
}

// A chunk edge placed exactly on cell boundaries (multiples of r/sqrt(2)) and
// chunks thinner than a cell.
TEST(Unbounded, SeamsOnCellBoundariesAndThinChunks) {
  const UnboundedField<2> field({.radius = 1.0}, 4);
  const double e = field.cell_edge();
  const auto region = box<2>({{-3 * e, 0.0}}, {{9 * e, 7.0}});
  const auto whole = field.sample(region);
  EXPECT_TRUE(same_bytes(whole, union_of_chunks(field, chunks(region, {12, 1}, 0))));
  EXPECT_TRUE(same_bytes(whole, union_of_chunks(field, chunks(region, {25, 3}, 11))));
}

TEST(Unbounded, ReportsItsWork) {
  const UnboundedField<2> field({.radius = 1.0}, 9);
  UnboundedStats stats;
  const auto points = field.sample(box<2>({{0.0, 0.0}}, {{40.0, 40.0}}), &stats);
  EXPECT_GT(stats.cells_touched, 3200u);  // the region has 57^2 cells
  EXPECT_GT(stats.darts_settled, points.size());
  EXPECT_GE(stats.max_depth, 1);
  EXPECT_LT(stats.max_depth, kMaxUnboundedDepth);
  EXPECT_GE(stats.margin_cells, 2);  // at least the neighbours of the edge cells
}

TEST(Unbounded, RefusesBadInput) {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  for (double r : {0.0, -1.0, nan, inf})
    EXPECT_THROW(UnboundedField<2>({.radius = r}, 1), InvalidArgument) << r;
  for (double t : {0.0, -1.0, nan, 65.0})
    EXPECT_THROW(UnboundedField<2>({.radius = 1.0, .darts_per_cell = t}, 1), InvalidArgument) << t;
  // The budget counts the cells the region touches (a margin of 12 a side):
  // 10 x 10 touches room for 1,166 points, 100 x 100 for 19,000.
  const UnboundedField<2> field({.radius = 1.0, .max_points = 2000}, 1);
  EXPECT_THROW(field.sample(box<2>({{0.0, 0.0}}, {{0.0, 1.0}})), InvalidArgument);   // empty
  EXPECT_THROW(field.sample(box<2>({{0.0, 2.0}}, {{1.0, 1.0}})), InvalidArgument);   // inverted
  EXPECT_THROW(field.sample(box<2>({{0.0, nan}}, {{1.0, 1.0}})), InvalidArgument);   // not finite
  EXPECT_THROW(field.sample(Domain<2>::unit(true)), InvalidArgument);                // a torus
  EXPECT_THROW(field.sample(box<2>({{0.0, 0.0}}, {{100.0, 100.0}})), InvalidArgument);  // over max_points
  EXPECT_THROW(field.sample(box<2>({{1e13, 0.0}}, {{1e13 + 1.0, 1.0}})), InvalidArgument);  // too far out
  EXPECT_NO_THROW(field.sample(box<2>({{0.0, 0.0}}, {{10.0, 10.0}})));
  // Long and thin: a small volume, but a memo of 10^8 cells.
  EXPECT_THROW(field.sample(box<2>({{0.0, 0.0}}, {{1e7, 1e-6}})), InvalidArgument);
}

// On a torus: chunks across the wrap, distances that wrap.
TEST(Unbounded, Torus) {
  const auto torus = Domain<2>::torus({{-3.0, 2.0}}, {{17.0, 14.5}});
  const UnboundedField<2> field({.radius = 1.0}, 12, torus);
  const auto whole = field.sample(Domain<2>::box(torus.lo, torus.hi));
  ASSERT_GT(whole.size(), 120u);
  for (const auto& p : whole) EXPECT_TRUE(torus.contains(p)) << p;
  EXPECT_GE(min_distance_brute_force(whole, torus).distance, 1.0);
  const auto region = Domain<2>::box(torus.lo, torus.hi);
  EXPECT_TRUE(same_bytes(whole, union_of_chunks(field, chunks(region, {3, 4}, 21))));
  EXPECT_TRUE(same_bytes(whole, union_of_chunks(field, chunks(region, {7, 2}, 0))));
  // Not the plane's set, and refusals.
  EXPECT_FALSE(same_bytes(whole, UnboundedField<2>({.radius = 1.0}, 12).sample(region)));
  EXPECT_THROW(UnboundedField<2>({.radius = 1.0}, 1, Domain<2>::torus({{0.0, 0.0}}, {{3.0, 10.0}})), InvalidArgument);
  EXPECT_THROW(UnboundedField<2>({.radius = 1.0}, 1, Domain<2>::box({{0.0, 0.0}}, {{10.0, 10.0}})), InvalidArgument);
  EXPECT_THROW(field.sample(box<2>({{-4.0, 2.0}}, {{0.0, 3.0}})), InvalidArgument);
  // 3D, smallest torus allowed (5 cells an axis).
  const auto cube = Domain<3>::torus({{0.0, 0.0, 0.0}}, {{3.0, 3.0, 3.0}});
  const UnboundedField<3> small({.radius = 1.0}, 2, cube);
  const auto points = small.sample(Domain<3>::box(cube.lo, cube.hi));
  EXPECT_GE(min_distance_brute_force(points, cube).distance, 1.0);
  EXPECT_TRUE(same_bytes(points, union_of_chunks(small, chunks(Domain<3>::box(cube.lo, cube.hi), {2, 3, 2}, 4))));
}

/// Sequential dart throwing on a torus of side L with `darts` uniform darts,
/// the process the field runs on the plane: the reference law.
PointSet<2> torus_rsa(double L, double r, std::uint64_t darts, std::uint64_t seed) {
  const int n = static_cast<int>(L / r);  // cells of edge >= r: neighbours within one cell
  const double edge = L / n;
  std::vector<std::vector<Point<2>>> grid(static_cast<std::size_t>(n) * n);
  PointSet<2> points;
  Rng rng(seed);
  for (std::uint64_t k = 0; k < darts; ++k) {
    const Point<2> p{{rng.uniform(0.0, L), rng.uniform(0.0, L)}};
    const int cx = std::min(n - 1, static_cast<int>(p[0] / edge)), cy = std::min(n - 1, static_cast<int>(p[1] / edge));
    bool free = true;
    for (int dx = -1; dx <= 1 && free; ++dx)
      for (int dy = -1; dy <= 1 && free; ++dy)
        for (const auto& q : grid[static_cast<std::size_t>((cx + dx + n) % n) * n + (cy + dy + n) % n]) {
          double ddx = std::abs(q[0] - p[0]), ddy = std::abs(q[1] - p[1]);
          ddx = std::min(ddx, L - ddx);
          ddy = std::min(ddy, L - ddy);
          if (ddx * ddx + ddy * ddy < r * r) {
            free = false;
            break;
          }
        }
    if (free) {
      grid[static_cast<std::size_t>(cx) * n + cy].push_back(p);
      points.push_back(p);
    }
  }
  return points;
}

// The field is maximal dart throwing (random sequential adsorption run to
// saturation): its count density and mean nearest-neighbour distance match
// ebeida's on a torus of the same size, 10 + 10 seeds (Welch's t), whatever
// darts_per_cell (it only says when refinement starts); on the torus so do
// the fraction of close neighbours and the radially averaged power, annulus by
// annulus (the periodogram needs the torus: a window's edges add their own
// power). The test sees the difference from dart throwing stopped at 8 darts
// a cell, in the count and in the spectrum (largest t 10.6; the field's 3.0
// and 3.3).
TEST(Unbounded, StatisticsOfMaximalDartThrowing) {
  const double r = 1.0, L = 24.0;
  const auto region = box<2>({{0.0, 0.0}}, {{L, L}});
  const auto inner = box<2>({{3.0, 3.0}}, {{L - 3.0, L - 3.0}});  // nearest neighbours found inside the region
  const auto torus = Domain<2>::torus({{0.0, 0.0}}, {{L, L}});
  testing_stats::Realisations ref, stopped;
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    ref.add(ebeida<2>({.radius = r}, torus, 1000 + seed), torus, r, true);
    stopped.add(torus_rsa(L, r, static_cast<std::uint64_t>(8 * 33 * 33), seed), torus, r, true);
  }
  const std::vector<double>& count_ref = ref.count;
  const std::vector<double>& nn_ref = ref.mean_over_r;
  EXPECT_GT(std::abs(testing_stats::welch_t(stopped.count, count_ref)), testing_stats::kMaxT);
  EXPECT_GT(testing_stats::max_spectrum_t(stopped.spectrum, ref.spectrum), testing_stats::kMaxSpectrumT);  // 10.6
  for (const double T : {0.5, 8.0}) {
    const UnboundedParams params{.radius = r, .darts_per_cell = T};
    std::vector<double> count_field, nn_field;
    testing_stats::Realisations periodic_sets;
    for (std::uint64_t seed = 1; seed <= 10; ++seed) {
      const auto field = UnboundedField<2>(params, seed).sample(region);
      count_field.push_back(static_cast<double>(field.size()));
      const auto nn = nearest_neighbors(field, region);
      double sum = 0.0;
      int m = 0;
      for (std::size_t i = 0; i < field.size(); ++i)
        if (inner.contains(field[i])) sum += nn.distance[i], ++m;
      nn_field.push_back(sum / m);
      // On the torus there is no window: the whole set.
      periodic_sets.add(UnboundedField<2>(params, seed, torus).sample(region), torus, r, true);
    }
    EXPECT_LT(std::abs(testing_stats::welch_t(count_field, count_ref)), testing_stats::kMaxT) << T;
    EXPECT_LT(std::abs(testing_stats::welch_t(nn_field, nn_ref)), testing_stats::kMaxT) << T;
    EXPECT_LT(std::abs(testing_stats::welch_t(periodic_sets.count, count_ref)), testing_stats::kMaxT) << T;
    EXPECT_LT(std::abs(testing_stats::welch_t(periodic_sets.mean_over_r, nn_ref)), testing_stats::kMaxT) << T;
    EXPECT_LT(std::abs(testing_stats::welch_t(periodic_sets.fraction_near, ref.fraction_near)), testing_stats::kMaxT)
        << T;
    EXPECT_LT(testing_stats::max_spectrum_t(periodic_sets.spectrum, ref.spectrum), testing_stats::kMaxSpectrumT) << T;
  }
}

// Maximal across chunk seams: the union of chunks leaves no point farther
// than r from every sample (check_maximality proves it cell by cell). On a
// torus the whole set is checked; on the plane a window, with the samples
// of a frame r wide around it (they cover its edge).
TEST(Unbounded, MaximalAcrossSeams) {
  const auto torus = Domain<2>::torus({{-3.0, 2.0}}, {{17.0, 14.5}});
  const UnboundedField<2> periodic({.radius = 1.0}, 12, torus);
  const auto whole = union_of_chunks(periodic, chunks(Domain<2>::box(torus.lo, torus.hi), {3, 4}, 21));
  const auto m = check_maximality(whole, torus, 1.0);
  EXPECT_TRUE(m.maximal) << (m.gap ? *m.gap : Point<2>{});
  EXPECT_EQ(m.tolerance, 0.0);

  const UnboundedField<2> field({.radius = 1.0}, 31);
  const auto window = box<2>({{-5.0, 3.0}}, {{15.0, 18.0}});
  const auto frame = box<2>({{-6.0, 2.0}}, {{16.0, 19.0}});
  const auto points = union_of_chunks(field, chunks(frame, {4, 3}, 2));
  // The analysis's grid clamps the frame's samples into its edge cells, where
  // the window's points find them.
  const auto plane = check_maximality(points, window, 1.0);
  EXPECT_TRUE(plane.maximal) << (plane.gap ? *plane.gap : Point<2>{});

  const auto cube = Domain<3>::torus({{0.0, 0.0, 0.0}}, {{4.0, 4.0, 4.0}});
  const UnboundedField<3> space({.radius = 1.0}, 3, cube);
  const auto points3 = union_of_chunks(space, chunks(Domain<3>::box(cube.lo, cube.hi), {2, 1, 3}, 5));
  EXPECT_TRUE(check_maximality(points3, cube, 1.0).maximal);
  EXPECT_GE(min_distance_brute_force(points3, cube).distance, 1.0);
}

}  // namespace
}  // namespace pds
