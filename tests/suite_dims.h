#pragma once
// The dimensions the registry-wide suites (conformance, short periods, the
// property sweep) run a method in.

#include <algorithm>
#include <vector>

#include "pds/registry.h"

namespace pds::testing_suites {

/// DimRange::tested(), less the dimensions past 5 for ebeida and wei: there
/// an exact run takes seconds to minutes even for tens of points
/// (docs/dimensions.md), at every size these suites draw. Their own tests
/// check 6D to 8D, boxes and tori, with the same oracles
/// (src/pds/samplers/ebeida_test.cpp, wei_test.cpp), and the command-line
/// tests run both through the registry in 8D.
inline std::vector<int> suite_dims(const Method& m) {
  std::vector<int> dims = m.dims.tested();
  if (m.name == "ebeida" || m.name == "wei") std::erase_if(dims, [](int d) { return d > 5; });
  return dims;
}

}  // namespace pds::testing_suites
