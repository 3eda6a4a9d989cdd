#include "pds/registry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "pds/error.h"

namespace pds {
namespace {

// generate() must reject the request with a message containing `fragment`.
void expect_rejected(const std::string& method, const GenerateRequest& r, const std::string& fragment) {
  try {
    generate(method, r);
    ADD_FAILURE() << method << ": accepted, expected an error mentioning '" << fragment << "'";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

GenerateRequest with_count(std::uint64_t n) {
  GenerateRequest r;
  r.count = n;
  return r;
}

GenerateRequest with_radius(double radius) {
  GenerateRequest r;
  r.radius = radius;
  return r;
}

TEST(Registry, NamesAreUniqueAndEveryEntryIsComplete) {
  std::set<std::string> names;
  for (const Method& m : methods()) {
    EXPECT_TRUE(names.insert(m.name).second) << m.name;
    EXPECT_FALSE(m.summary.empty()) << m.name;
    EXPECT_TRUE(m.takes_count || m.takes_radius) << m.name;
    EXPECT_NE(m.run, nullptr) << m.name;
    for (const MethodParam& p : m.params) {
      EXPECT_LE(p.min, p.default_value) << m.name << " " << p.name;
      EXPECT_LE(p.default_value, p.max) << m.name << " " << p.name;
      EXPECT_FALSE(p.help.empty()) << m.name << " " << p.name;
    }
  }
  for (const char* name : {"random", "regular", "jittered"}) EXPECT_TRUE(names.count(name)) << name;
  expect_rejected("no-such-method", with_count(10), "unknown method 'no-such-method' (known: random");
}

TEST(Registry, RejectsBadRadii) {
  for (double r : {0.0, -0.1, double(NAN), double(INFINITY), -double(INFINITY)})
    expect_rejected("regular", with_radius(r), "radius must be positive and finite");
  expect_rejected("random", with_radius(0.1), "random does not take --radius");
  // Radii whose squares leave the normal doubles: spacing could not be decided exactly.
  for (double r : {1e-151, 1e-200, 4.9e-324, 1e151, 1e300})
    expect_rejected("regular", with_radius(r), "is outside [1e-150, 1e150]");
}

TEST(Registry, RejectsBadCounts) {
  expect_rejected("random", with_count(0), "count must be at least 1, got 0");
  GenerateRequest r = with_count(1001);
  r.max_points = 1000;
  expect_rejected("random", r, "count 1001 is above the cap of 1000");
  expect_rejected("random", with_count(kDefaultMaxPoints + 1), "above the cap");
  expect_rejected("random", GenerateRequest{}, "random needs --count");
  expect_rejected("jittered", with_count(997), "nearest counts that can: 992 and 999");
}

TEST(Registry, RejectsUnsupportedDimensions) {
  for (int dim : {0, 1, 3, -2}) {
    GenerateRequest r = with_count(16);
    r.dim = dim;
    expect_rejected("jones", r, "dimension " + std::to_string(dim) + " is not supported");  // 2
  }
  for (int dim : {0, kMaxDim + 1}) {
    GenerateRequest r = with_count(16);
    r.dim = dim;
    expect_rejected("jittered", r, "dimension " + std::to_string(dim) + " is not supported");  // 1-8
  }
  for (int dim : {0, -2, kMaxCloudDim + 1}) {
    GenerateRequest r = with_count(16);
    r.dim = dim;
    expect_rejected("random", r, "dimension " + std::to_string(dim) + " is not supported");  // 1-2^20
  }
  GenerateRequest r = with_count(16);
  r.dim = 21202;
  expect_rejected("sobol", r, "sobol: dimension 21202 is not supported (supported: 1-21201)");
}

TEST(Registry, RejectsBadBounds) {
  GenerateRequest r = with_count(16);
  r.lo = {0, 0};
  r.hi = {1, 0};
  expect_rejected("random", r, "axis 1 is empty");
  r.hi = {1, NAN};
  expect_rejected("random", r, "non-finite bound");
  r.lo = {0, -INFINITY};
  r.hi = {1, 1};
  expect_rejected("random", r, "non-finite bound");
  r.lo = {0, 0, 0};
  expect_rejected("random", r, "bounds: need 2 lower and 2 upper");
}

TEST(Registry, RefusesRequestsBeyondThePointBudgetBeforeAllocating) {
  // A tiny radius over the unit square could produce ~1.2e12 points.
  expect_rejected("regular", with_radius(1e-6), "above the cap of 100000000");
  GenerateRequest r = with_radius(1e-3);
  r.max_points = 1000;
  expect_rejected("regular", r, "raise it with --max-points");
  // Raising the cap past what the machine holds is refused by memory.
  GenerateRequest huge = with_radius(1e-7);
  huge.max_points = ~std::uint64_t{0};
  expect_rejected("regular", huge, "GiB, more than this machine's");
}

TEST(Registry, ThinDomainsAreSizedByTheirAxesNotTheirVolume) {
  // A 1000 x 1e-6 x 1e-6 box has volume 1e-9 but holds ~10^5 points at
  // r = 0.01 along its long axis: every radius method must refuse it under a
  // cap of 1500 (CI's fuzzer found ebeida running past its time limit on a box
  // like it; wei and dart-throwing returned 7 * 10^4 points).
  GenerateRequest r = with_radius(0.01);
  r.dim = 3;
  r.lo = {0, 0, 0};
  r.hi = {1000, 1e-6, 1e-6};
  r.max_points = 1500;
  int methods_checked = 0;
  for (const Method& m : methods())
    if (m.takes_radius && m.dims.contains(3)) {
      expect_rejected(m.name, r, "with axes shorter than the radius counted as the radius");
      ++methods_checked;
    }
  EXPECT_GE(methods_checked, 6);
  // The memory estimate counts them too (--max-memory refused nothing here).
  EXPECT_GT(peak_memory_estimate(find_method("dart-throwing"), r), 1e6);
  // The same box, short enough to fit the cap, is sampled along its length.
  r.hi = {1, 1e-6, 1e-6};
  const PointCloud line = generate("dart-throwing", r);
  EXPECT_GT(line.size(), 40u);
  EXPECT_LE(line.size(), 101u);
  // A count in such a box becomes a radius sized by its length (the volume
  // alone gave r = 1.4e-4 for 100 points: Bridson needed 1.4 GB).
  GenerateRequest counted;
  counted.dim = 3;
  counted.lo = {0, 0, 0};
  counted.hi = {100, 1e-6, 1e-6};
  counted.count = 100;
  EXPECT_EQ(generate("bridson", counted).size(), 100u);
  EXPECT_GT(*size_request(find_method("ebeida"), counted).radius, 0.5);
}

// Each class is a Poisson disk set at its own radius whatever the cross
// distances, so the classes' packings add up: four classes at 0.01 apart
// from themselves and 0.001 from each other returned 27,540 points under a
// cap of 14,000 when only the densest class was counted.
TEST(Registry, ClassesAreBudgetedTogether) {
  MultiClassParams params;
  params.radii = {0.01, 0.01, 0.01, 0.01};
  params.matrix.assign(16, 0.001);
  for (int c = 0; c < 4; ++c) params.matrix[static_cast<std::size_t>(c * 5)] = 0.01;
  GenerateRequest r;
  r.max_points = 14000;
  try {
    generate_classes(params, r);
    ADD_FAILURE() << "four classes accepted under a cap of one class's packing";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("4 classes"), std::string::npos) << e.what();
  }
  r.count = 10;
  EXPECT_THROW(generate_classes(params, r), InvalidArgument);
}

TEST(Registry, RejectsUnknownMethodParameters) {
  GenerateRequest r = with_count(16);
  r.params["k"] = 30;
  expect_rejected("random", r, "random has no parameter 'k' (it takes none)");
}

TEST(Registry, RejectsNegativeThreads) {
  GenerateRequest r = with_count(16);
  r.threads = -1;
  expect_rejected("random", r, "threads must be 0 (all) or positive, got -1");
}

}  // namespace
}  // namespace pds
