// Checks shared by the low-discrepancy sequences; the
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

}  // namespace pds
