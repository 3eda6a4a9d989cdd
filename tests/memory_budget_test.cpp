// --max-memory: every method's estimate (pds::peak_memory_estimate, from its
// measured memory_ratio) refuses a budget just below it before anything is
// allocated, and runs under a budget just above it.

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "pds/error.h"
#include "pds/registry.h"

namespace pds {
namespace {

GenerateRequest small_request(const Method& m) {
  GenerateRequest r;
  r.torus = true;
  if (m.takes_count)
    r.count = 256;
  else
    r.radius = 0.05;
  return r;
}

TEST(MemoryBudget, EveryMethodRefusesBelowItsEstimateAndRunsAbove) {
  for (const Method& m : methods()) {
    GenerateRequest r = small_request(m);
    const double estimate = peak_memory_estimate(m, r);
    ASSERT_GT(estimate, 0) << m.name;
    r.max_memory = estimate * 0.99;
    try {
      generate(m.name, r);
      ADD_FAILURE() << m.name << " ran above its budget";
    } catch (const InvalidArgument& e) {
      EXPECT_NE(std::string(e.what()).find("(--max-memory)"), std::string::npos) << e.what();
    }
    r.max_memory = estimate * 1.01;
    EXPECT_NO_THROW(generate(m.name, r)) << m.name;
  }
}

TEST(MemoryBudget, EstimateIsPointsTimesDimensionTimesTheMethodsRatio) {
  GenerateRequest r;
  r.dim = 3;
  r.count = 1000;
  const Method& random = find_method("random");
  EXPECT_EQ(peak_memory_estimate(random, r), 1000.0 * 3 * 8 * random.memory_ratio);
  // A request far beyond the machine is refused at once, nothing allocated.
  r.count = 50'000'000;
  r.max_memory = 512.0 * (1 << 20);
  EXPECT_THROW(generate("random", r), InvalidArgument);
  r.max_memory = -1;
  r.count = 10;
  EXPECT_THROW(generate("random", r), InvalidArgument);
}

// The sequences hold tables per axis whatever the count (Sobol's direction
// numbers, Halton's bases and permutations): 10 points in 21,201 dimensions
// held 6 MB against an estimate of 2.5 MB from the points alone.
TEST(MemoryBudget, SequencesAddTheirTablesPerAxis) {
  GenerateRequest r;
  r.dim = 21201;
  r.count = 10;
  const Method& sobol = find_method("sobol");
  ASSERT_GT(sobol.memory_per_axis, 0.0);
  EXPECT_DOUBLE_EQ(peak_memory_estimate(sobol, r),
                   10.0 * 21201 * 8 * sobol.memory_ratio + 21201 * sobol.memory_per_axis);
  EXPECT_GT(peak_memory_estimate(sobol, r), 6.0 * (1 << 20));
  for (const char* name : {"halton", "hammersley"}) EXPECT_GT(find_method(name).memory_per_axis, 0.0) << name;
  EXPECT_EQ(find_method("random").memory_per_axis, 0.0);
}

// A method whose memory grows with the dimension states a ratio per
// dimension: wei's open cells from 4D (measured, docs/wei.md).
TEST(MemoryBudget, RatioFollowsTheDimensionWhereTheMethodSaysSo) {
  const Method& wei = find_method("wei");
  GenerateRequest r;
  r.radius = 0.3;
  for (int dim = 1; dim <= wei.dims.hi; ++dim) {
    r.dim = dim;
    std::vector<double> lo, hi;
    r.bounds(lo, hi);
    const double points = typical_count(sizing_volume(lo.data(), hi.data(), dim, 0.3), 0.3, dim);
    const double ratio = dim >= 8   ? 47000
                         : dim >= 7 ? 2300
                         : dim >= 6 ? 550
                         : dim >= 5 ? 170
                         : dim >= 4 ? 50
                         : dim >= 3 ? 6.5
                                    : wei.memory_ratio;
    EXPECT_DOUBLE_EQ(peak_memory_estimate(wei, r), points * dim * 8 * ratio) << dim;
  }
}

// bridson's count takes another path (its last set, then the elimination of
// the surplus) that needs more in 3D: a count takes that ratio where larger.
TEST(MemoryBudget, ACountTakesItsOwnRatioWhereLarger) {
  const Method& bridson = find_method("bridson");
  GenerateRequest r;
  r.count = 1000;
  for (const auto& [dim, ratio] : {std::pair{1, 8.0}, {2, 8.0}, {3, 20.0}, {4, 7.0}, {8, 7.0}}) {
    r.dim = dim;
    EXPECT_DOUBLE_EQ(peak_memory_estimate(bridson, r), 1000.0 * dim * 8 * ratio) << dim;
  }
  // Without a count, the method's own ratios.
  r.count.reset();
  r.radius = 0.1;
  r.dim = 3;
  std::vector<double> lo, hi;
  r.bounds(lo, hi);
  const double points = typical_count(sizing_volume(lo.data(), hi.data(), 3, 0.1), 0.1, 3);
  EXPECT_DOUBLE_EQ(peak_memory_estimate(bridson, r), points * 3 * 8 * bridson.memory_ratio);
}

// elimination holds its candidates: asking for more of them than the
// default (5 N) scales the estimate with them; fewer keep the default's.
TEST(MemoryBudget, MoreCandidatesScaleTheEliminationEstimate) {
  const Method& elimination = find_method("elimination");
  GenerateRequest r;
  r.count = 1000;
  const double at_default = peak_memory_estimate(elimination, r);
  EXPECT_DOUBLE_EQ(at_default, 1000.0 * 2 * 8 * 18);
  r.params["candidates"] = 20;
  EXPECT_DOUBLE_EQ(peak_memory_estimate(elimination, r), 4 * at_default);
  r.params["candidates"] = 2;
  EXPECT_DOUBLE_EQ(peak_memory_estimate(elimination, r), at_default);
  // A budget between the two refuses 20 N candidates before allocating.
  r.params["candidates"] = 20;
  r.max_memory = 2 * at_default;
  EXPECT_THROW(generate("elimination", r), InvalidArgument);
}

}  // namespace
}  // namespace pds
