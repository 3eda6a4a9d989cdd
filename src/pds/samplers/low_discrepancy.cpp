// Checks and registry parameters shared by the low-discrepancy sequences; the
// digit arithmetic itself is inline in the header (see there for the design).

#include "pds/samplers/low_discrepancy.h"

#include "pds/error.h"

namespace pds {

void require_index_range(const std::string& method, std::uint64_t first, std::uint64_t count) {
  if (first >= kSequenceIndexLimit || count > kSequenceIndexLimit - first)
    throw InvalidArgument(method + ": indices first " + std::to_string(first) + " + count " + std::to_string(count) +
                          " exceed the sequence's 2^32 points");
}

Scramble scramble_from(const std::string& method, int value) {
  if (value < 0 || value > 2)
    throw InvalidArgument(method + ": scramble must be 0 (none), 1 (digit permutation) or 2 (Owen), got " +
                          std::to_string(value));
  return static_cast<Scramble>(value);
}

MethodParam scramble_param() {
  return {.name = "scramble",
          .default_value = 0,
          .min = 0,
          .max = 2,
          .integer = true,
          .help = "0: the exact sequence (no seed); 1: random digit permutation; 2: Owen scrambling (1, 2 use --seed)"};
}

MethodParam first_param() {
  return {.name = "first",
          .default_value = 0,
          .min = 0,
          .max = static_cast<double>(kSequenceIndexLimit - 1),
          .integer = true,
          .help = "index of the first point: --count points from here continue an earlier run"};
}

}  // namespace pds
