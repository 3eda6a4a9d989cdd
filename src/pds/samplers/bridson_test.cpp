#include "pds/samplers/bridson.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

#include "pds/analysis/distance.h"
#include "pds/analysis/relative_radius.h"
#include "pds/analysis/spectrum.h"
#include "pds/error.h"
#include "pds/rng.h"
#include "pds/samplers/elimination.h"
#include "pds/samplers/sizing.h"
#include "pds/registry.h"

namespace pds {
namespace {

template <int D>
void expect_poisson_disk(const PointSet<D>& points, const Domain<D>& domain, double radius) {
  for (const auto& p : points) ASSERT_TRUE(domain.contains(p)) << p;
  const MinDistance md = min_distance_brute_force(points, domain);
  EXPECT_GE(md.distance, radius) << domain << ": " << points[md.i] << " " << points[md.j];
}

// A 1 x 1 x 0.001 slab, thinner than the radius along z (its candidates take
// a uniform coordinate there), holds about as many points as the unit square.
void expect_slab_fills_as_the_square(const BridsonParams& params) {
  const auto slab = Domain<3>::box({0, 0, 0}, {1, 1, 0.001});
  const auto in_slab = bridson(params, slab, 3);
  expect_poisson_disk(in_slab, slab, params.radius);
  EXPECT_GT(static_cast<double>(in_slab.size()),
            0.9 * static_cast<double>(bridson(params, Domain<2>::unit(false), 3).size()));
}

TEST(Bridson, PeriodsShorterThanTheNeighbourhood) {
  // Periods of one or two cells: the margin holds several copies of a sample
  // and the min-image distance must still be the one the oracle takes.
  BridsonParams params;
  params.radius = 0.1;
  for (const auto& domain : {Domain<2>::torus({0, 0}, {1, 0.15}), Domain<2>::torus({0, 0}, {0.12, 0.31}),
                             Domain<2>::torus({-3, 5}, {-2.7, 5.05})}) {
    const auto points = bridson(params, domain, 4);
    expect_poisson_disk(points, domain, params.radius);
  }
  const auto thin = Domain<3>::torus({0, 0, 0}, {0.15, 1, 0.25});
  expect_poisson_disk(bridson(params, thin, 4), thin, params.radius);
}

TEST(Bridson, PeriodsAroundTheInteriorThreshold) {
  // The torus scan skips the min-image correction in cells whose whole
  // neighbourhood is inside the domain, which needs more than 2 (reach + 1)
  // cells along the axis (6 for r / cell edge ~1.4): periods of 5 to 9 cells
  // put the threshold on either side, and the oracle takes the min image.
  BridsonParams params;
  params.radius = 0.1;
  const double edge = 0.1 / std::sqrt(2.0);
  for (int cells = 5; cells <= 9; ++cells)
    for (std::uint64_t seed = 1; seed <= 10; ++seed) {
      const Domain<2> domain = Domain<2>::torus({0, 0}, {cells * edge * 0.999, 0.73});
      expect_poisson_disk(bridson(params, domain, seed), domain, params.radius);
    }
  const double edge3 = 0.1 / std::sqrt(3.0);
  for (int cells = 5; cells <= 9; ++cells) {
    const Domain<3> domain = Domain<3>::torus({0, 0, 0}, {cells * edge3 * 0.999, 0.5, 0.4});
    expect_poisson_disk(bridson(params, domain, 3), domain, params.radius);
  }
}

TEST(Bridson, AxesWithFewerWiderCells) {
  // Three cells of 2/3 the nominal edge across y: a sample three cells away
  // along y can be closer than r, so the neighbourhood must be wider there.
  BridsonParams params;
  params.radius = 0.1;
  for (bool torus : {false, true})
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
      const Domain<2> strip{{0, 0}, {1, 0.1415}, torus};
      expect_poisson_disk(bridson(params, strip, seed), strip, params.radius);
      const Domain<3> slab{{0, 0, 0}, {0.5, 0.5, 0.1735}, torus};
      expect_poisson_disk(bridson(params, slab, seed), slab, params.radius);
    }
}

// In 2D the grid keeps each sample as float offsets from the corner of its
// tile of 256 x 256 cells, and a sample is put on that lattice before it is
// tested. Strips 700 cells long cross tile borders (where a scan reads cells
// of two tiles) and, a million units from the origin, make the rounding of
// corner + offset move points against cell faces; every pair still holds the
// radius in the output's own doubles, and every point stays inside.
TEST(Bridson, LatticeAcrossTilesAndFarFromTheOrigin) {
  BridsonParams params;
  params.radius = 0.002;
  for (const double offset : {0.0, 1e6, -3.5e6})
    for (bool torus : {false, true}) {
      const Domain<2> strip{{offset, offset}, {offset + 1.0, offset + 0.01}, torus};
      const auto points = bridson(params, strip, 5);
      EXPECT_GT(points.size(), 1000u) << strip;
      expect_poisson_disk(points, strip, params.radius);
      EXPECT_EQ(points, bridson(params, strip, 5));
    }
}

// The lattice counts offsets in a power of two near the cell's edge, so that
// floats hold them at any scale: a square 1e-140 or 1e140 wide fills as the
// unit square does (in float units of the domain itself they would underflow
// or overflow, and nearly every candidate would be refused).
TEST(Bridson, LatticeAtEveryScale) {
  BridsonParams params;
  params.radius = 0.02;
  const auto unit = bridson(params, Domain<2>::unit(true), 3);
  for (const double scale : {1e-140, 1e-20, 1e20, 1e140}) {
    params.radius = 0.02 * scale;
    const auto square = Domain<2>::torus({0, 0}, {scale, scale});
    const auto points = bridson(params, square, 3);
    EXPECT_NEAR(static_cast<double>(points.size()), static_cast<double>(unit.size()), 0.03 * unit.size()) << scale;
    expect_poisson_disk(points, square, params.radius);
  }
}

TEST(Bridson, CountGivesExactlyThatMany) {
  for (std::uint64_t n : {1u, 2u, 7u, 1000u}) {
    GenerateRequest r;
    r.count = n;
    r.torus = n % 2 == 0;
    r.seed = n;
    EXPECT_EQ(generate("bridson", r).size(), n);
    r.dim = 3;
    EXPECT_EQ(generate("bridson", r).size(), n);
  }
  // With a radius too: the radius is only ever grown, so it still holds.
  BridsonParams params;
  params.radius = 0.03;
  params.count = 500;
  const auto domain = Domain<2>::unit(true);
  const auto points = bridson(params, domain, 9);
  ASSERT_EQ(points.size(), 500u);
  expect_poisson_disk(points, domain, 0.03);
}

// With a count the first set is only counted (1D, 2D and 4D grids never read
// the samples back) and grown again when the search keeps it: a count the
// set at the radius already meets, or misses by less than the surplus, gives
// that set, or its elimination, exactly as if it had been kept.
template <int D>
void expect_first_set_grown_again(const Domain<D>& domain, double radius) {
  const PointSet<D> all = bridson<D>({.radius = radius}, domain, 3);
  ASSERT_GT(all.size(), 100u);
  EXPECT_EQ(bridson<D>({.radius = radius, .count = all.size()}, domain, 3), all);
  const std::uint64_t fewer = all.size() - all.size() / 100;  // within the 2% surplus: no search
  EXPECT_EQ(bridson<D>({.radius = radius, .count = fewer}, domain, 3), eliminate(all, fewer, domain, {}, false));
}

TEST(Bridson, CountKeepsTheFirstSetWhenItFits) {
  expect_first_set_grown_again(Domain<1>::unit(true), 0.002);
  expect_first_set_grown_again(Domain<2>::unit(false), 0.04);
  expect_first_set_grown_again(Domain<3>::unit(true), 0.12);
  expect_first_set_grown_again(Domain<4>::unit(false), 0.3);
}

// Mean radial power at frequencies up to half the inverse mean spacing, over
// 8 sets of one method's points on the unit torus.
double low_frequency_power(const std::function<PointSet<2>(std::uint64_t seed)>& make) {
  const auto domain = Domain<2>::unit(true);
  std::vector<PointSet<2>> sets;
  for (std::uint64_t seed = 1; seed <= 8; ++seed) sets.push_back(make(seed));
  const RadialSpectrum r = radial_average(periodogram<2>(sets, domain, {.max_frequency = 16}));
  double sum = 0;
  int n = 0;
  for (std::size_t b = 0; b < r.power.size(); ++b)
    if (r.frequency[b] <= 0.5) {
      sum += r.power[b];
      ++n;
    }
  return sum / n;
}

// A count is met by searching the radius and eliminating the few extra, so
// the spectrum is the finished set's; a uniformly random subset of the set at
// the count's starting radius (the obvious alternative) has far more
// low-frequency power (white noise added).
TEST(Bridson, CountKeepsTheSpectrumOfAFinishedSet) {
  const auto domain = Domain<2>::unit(true);
  constexpr std::uint64_t n = 512;
  const double own = low_frequency_power(
      [&](std::uint64_t seed) { return bridson<2>({.radius = radius_for_count(n, domain, 0.73)}, domain, seed); });
  const double counted = low_frequency_power([&](std::uint64_t seed) {
    return bridson<2>({.radius = radius_for_count(n, domain, kBridsonCountRho), .count = n}, domain, seed);
  });
  const double random_subset = low_frequency_power([&](std::uint64_t seed) {
    PointSet<2> all = bridson<2>({.radius = radius_for_count(n, domain, kBridsonCountRho)}, domain, seed);
    Rng rng(seed);
    for (std::size_t i = 0; i < n; ++i) std::swap(all[i], all[i + rng.below(all.size() - i)]);
    all.resize(n);
    return all;
  });
  EXPECT_LT(counted, 1.2 * own) << "own radius " << own;
  EXPECT_GT(random_subset, 2.0 * counted) << "random subset " << random_subset;
}

TEST(Bridson, CountThatCannotFitIsRejected) {
  BridsonParams params;
  params.radius = 0.1;
  params.count = 200;  // above the densest packing (~139)
  EXPECT_THROW(bridson(params, Domain<2>::unit(), 1), InvalidArgument);
  params.count = 120;  // below the packing bound, above what Bridson places (~85)
  try {
    bridson(params, Domain<2>::unit(), 1);
    FAIL() << "no error";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("only"), std::string::npos) << e.what();
  }
}

TEST(Bridson, RadiusLargerThanTheDomainGivesOnePoint) {
  BridsonParams params;
  params.radius = 3.0;
  for (bool torus : {false, true}) {
    EXPECT_EQ(bridson(params, Domain<2>::unit(torus), 1).size(), 1u);
    EXPECT_EQ(bridson(params, Domain<3>::unit(torus), 1).size(), 1u);
  }
}

// A box thinner than r along some axes: annulus offsets leave it (the slab
// below grew 4 points before candidates took a uniform coordinate along
// such axes); the set now fills it about as the box of the other axes is
// filled (seed 3: 6,232 against 6,220 for the unit square; 66 in the tube
// and 73 in the strip against 68 for the unit interval).
TEST(Bridson, BoxesThinnerThanTheRadiusFillUp) {
  BridsonParams params;
  params.radius = 0.01;
  expect_slab_fills_as_the_square(params);
  const auto line = static_cast<double>(bridson(params, Domain<1>::unit(false), 3).size());
  const auto tube = Domain<3>::box({0, 0, 0}, {1, 1e-6, 1e-6});
  const auto in_tube = bridson(params, tube, 3);
  expect_poisson_disk(in_tube, tube, params.radius);
  EXPECT_GT(static_cast<double>(in_tube.size()), 0.9 * line);
  const auto strip = Domain<2>::box({0, 0}, {1, 0.001});
  const auto in_strip = bridson(params, strip, 3);
  expect_poisson_disk(in_strip, strip, params.radius);
  EXPECT_GT(static_cast<double>(in_strip.size()), 0.9 * line);
}

TEST(Bridson, MoreCandidatesPackMorePoints) {
  const auto domain = Domain<2>::unit(true);
  BridsonParams params;
  params.radius = 0.02;
  std::size_t few = 0, many = 0;
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    params.k = 3;
    few += bridson(params, domain, seed).size();
    params.k = 100;
    const auto dense = bridson(params, domain, seed);
    many += dense.size();
    expect_poisson_disk(dense, domain, params.radius);
  }
  EXPECT_GT(many, few + 3 * 100) << few << " vs " << many;
}

TEST(Bridson, SurfaceCandidatesKeepTheRadiusAndPackDenser) {
  // Candidates at 1.001 r from their active sample: each new sample nearly
  // touches one other, so the set is denser, and still no pair is closer
  // than r (box and torus, the plane and 4D).
  BridsonParams params;
  for (bool torus : {false, true}) {
    const Domain<2> plane{{-1, 0}, {1, 0.5}, torus};
    params.radius = 0.02;
    params.surface = false;
    const std::size_t annulus = bridson(params, plane, 5).size();
    params.surface = true;
    const auto dense = bridson(params, plane, 5);
    expect_poisson_disk(dense, plane, params.radius);
    EXPECT_GT(dense.size(), annulus * 5 / 4) << annulus << " vs " << dense.size();
    const Domain<4> space{{0, 0, 0, 0}, {1, 1, 1, 1}, torus};
    params.radius = 0.2;
    expect_poisson_disk(bridson(params, space, 5), space, params.radius);
  }
}

// SciPy's loop (scipy = true) through the same grids: box and torus, 1 to 4
// dimensions (the 4D one is the conflict grid), periods of one or two cells,
// axes with fewer, wider cells, the sphere's candidates.
TEST(Bridson, ScipyLoopKeepsTheRadiusEverywhere) {
  BridsonParams params;
  params.scipy = true;
  for (bool torus : {false, true})
    for (bool surface : {false, true}) {
      params.surface = surface;
      for (std::uint64_t seed = 1; seed <= 4; ++seed) {
        params.radius = 0.02;
        const Domain<1> line{{-1}, {1}, torus};
        expect_poisson_disk(bridson(params, line, seed), line, params.radius);
        const Domain<2> plane{{-1, 0}, {1, 0.5}, torus};
        expect_poisson_disk(bridson(params, plane, seed), plane, params.radius);
        params.radius = 0.1;
        const Domain<2> strip{{0, 0}, {1, 0.1415}, torus};
        expect_poisson_disk(bridson(params, strip, seed), strip, params.radius);
        const Domain<2> short_period{{0, 0}, {0.12, 0.31}, torus};
        expect_poisson_disk(bridson(params, short_period, seed), short_period, params.radius);
        const Domain<3> slab{{0, 0, 0}, {0.5, 0.5, 0.1735}, torus};
        expect_poisson_disk(bridson(params, slab, seed), slab, params.radius);
        const Domain<3> cube{{0, 0, 0}, {1, 1, 1}, torus};
        expect_poisson_disk(bridson(params, cube, seed), cube, params.radius);
        params.radius = 0.25;
        const Domain<4> space{{0, 0, 0, 0}, {1, 1, 1, 1}, torus};
        expect_poisson_disk(bridson(params, space, seed), space, params.radius);
        // Odd dimensions past 4: the 32-bit offsets of two trials share the
        // middle draw, and the ball's hits take D bits each.
        params.radius = 0.4;
        const Domain<5> five{{0, 0, 0, 0, 0}, {1, 1, 1, 1, 1}, torus};
        expect_poisson_disk(bridson(params, five, seed), five, params.radius);
        params.radius = 0.6;
        const Domain<7> seven{{0, 0, 0, 0, 0, 0, 0}, {1, 1, 1, 1, 1, 1, 1}, torus};
        expect_poisson_disk(bridson(params, seven, seed), seven, params.radius);
      }
    }
  // A box thinner than the radius along one axis (its candidates take a
  // uniform coordinate there): the slab fills as the square does.
  params.surface = false;
  params.radius = 0.01;
  expect_slab_fills_as_the_square(params);
}

TEST(Bridson, ScipyLoopIsDeterministicAndItsOwn) {
  BridsonParams params;
  params.radius = 0.03;
  const auto domain = Domain<2>::unit(false);
  const auto bridsons = bridson(params, domain, 9);
  params.scipy = true;
  const auto first = bridson(params, domain, 9);
  EXPECT_EQ(first, bridson(params, domain, 9));
  EXPECT_NE(first, bridson(params, domain, 10));
  EXPECT_NE(first, bridsons);
  // With a count: exactly that many, through the same loop.
  params.count = 500;
  const auto counted = bridson(params, domain, 9);
  EXPECT_EQ(counted.size(), 500u);
  expect_poisson_disk(counted, domain, params.radius);
}

// The loop's law is SciPy's: the mean size of a finished set over seeds 1-40
// equals SciPy's within the error of the two means, and Bridson's loop,
// which packs about 3% more, is told apart. SciPy's figures were measured
// once (SciPy 1.10.1, Debian's python3-scipy):
//   for s in 1..40: len(scipy.stats.qmc.PoissonDisk(d, radius=r, seed=s).fill_space())
// d = 2, r = 0.02: mean 1520.525, standard deviation 11.629;
// d = 3, r = 0.08: mean 1179.9, standard deviation 13.097.
TEST(Bridson, ScipyLoopFollowsScipysLaw) {
  struct Case {
    int dim;
    double radius, scipy_mean, scipy_sd;
  };
  constexpr int kSeeds = 40;
  for (const Case& c : {Case{2, 0.02, 1520.525, 11.629}, Case{3, 0.08, 1179.9, 13.097}}) {
    const auto mean_and_sd = [&](bool scipy) {
      double sum = 0, sum2 = 0;
      for (std::uint64_t seed = 1; seed <= kSeeds; ++seed) {
        GenerateRequest r;
        r.dim = c.dim;
        r.radius = c.radius;
        r.seed = seed;
        r.params = {{"scipy", scipy ? 1.0 : 0.0}};
        const auto n = static_cast<double>(generate("bridson", r).size());
        sum += n;
        sum2 += n * n;
      }
      const double mean = sum / kSeeds;
      return std::pair{mean, std::sqrt((sum2 - kSeeds * mean * mean) / (kSeeds - 1))};
    };
    const auto [ours, ours_sd] = mean_and_sd(true);
    const auto [bridsons, bridsons_sd] = mean_and_sd(false);
    // Four standard errors of the difference of two means.
    const double tolerance = 4.0 * std::sqrt((ours_sd * ours_sd + c.scipy_sd * c.scipy_sd) / kSeeds);
    EXPECT_NEAR(ours, c.scipy_mean, tolerance) << c.dim << "D";
    EXPECT_GT(bridsons - c.scipy_mean, tolerance) << c.dim << "D: Bridson's loop " << bridsons;
  }
}

// With a count, progress runs through the first set, the radii tried and the
// elimination, monotone to the end, and changes no byte.
TEST(Bridson, CountReportsProgressThroughEveryStage) {
  BridsonParams params;
  params.radius = 0.005;
  params.count = 20000;
  const auto domain = Domain<2>::unit(true);
  const auto quiet = bridson(params, domain, 4);
  std::vector<double> done;
  params.progress.report = [&](double d, double total) {
    EXPECT_EQ(total, 11.0);  // kCountParts: the first set, 8 steps, the first set again, the elimination
    done.push_back(d);
    return true;
  };
  EXPECT_EQ(bridson(params, domain, 4), quiet);
  ASSERT_GE(done.size(), 10u);
  for (std::size_t i = 1; i < done.size(); ++i) EXPECT_GE(done[i], done[i - 1]) << i;
  EXPECT_EQ(done.back(), 11.0);
}

TEST(Bridson, BadParameters) {
  BridsonParams params;
  params.radius = 0.1;
  params.k = 0;
  EXPECT_THROW(bridson(params, Domain<2>::unit(), 1), InvalidArgument);
  params.k = -3;
  EXPECT_THROW(bridson(params, Domain<3>::unit(), 1), InvalidArgument);
  params.k = 30;
  params.radius = -1;
  EXPECT_THROW(bridson(params, Domain<2>::unit(), 1), InvalidArgument);
  params.radius = 1e-7;  // 10^14 cells
  EXPECT_THROW(bridson(params, Domain<2>::unit(), 1), InvalidArgument);
  GenerateRequest r;
  r.radius = 0.1;
  r.params = {{"k", 0}};
  EXPECT_THROW(generate("bridson", r), InvalidArgument);
  r.params = {{"k", 2.5}};
  EXPECT_THROW(generate("bridson", r), InvalidArgument);
  r.params = {{"m", 1}};
  EXPECT_THROW(generate("bridson", r), InvalidArgument);
}

}  // namespace
}  // namespace pds
