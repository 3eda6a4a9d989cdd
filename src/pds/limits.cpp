#include "pds/limits.h"

#include <unistd.h>

#include <cmath>
#include <sstream>

#include "pds/analysis/relative_radius.h"
#include "pds/detail/format.h"
#include "pds/error.h"

namespace pds {
namespace {

double physical_memory_bytes() {
  const long pages = sysconf(_SC_PHYS_PAGES);
  const long page_size = sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || page_size <= 0) return INFINITY;
  return static_cast<double>(pages) * static_cast<double>(page_size);
}

}  // namespace

void require_radius(double r, const char* name) {
  if (!std::isfinite(r) || !(r > 0.0))
    throw InvalidArgument(std::string(name) + " must be positive and finite, got " + detail::format_number(r));
  // Spacing is decided on squared distances against r^2: below this r^2 is
  // subnormal and has lost the bits that decide it; above, (3r)^2 overflows.
  if (!(r >= kMinRadius && r <= kMaxRadius))
    throw InvalidArgument(std::string(name) + " " + detail::format_number(r) +
                          " is outside [1e-150, 1e150]: its squared distances would leave the normal doubles "
                          "(scale the domain instead)");
}

void require_count(std::uint64_t n, std::uint64_t max_points) {
  if (n == 0) throw InvalidArgument("count must be at least 1, got 0");
  if (n > max_points)
    throw InvalidArgument("count " + std::to_string(n) + " is above the cap of " + std::to_string(max_points) +
                          " points (raise it with --max-points)");
}

void require_point_budget(double points, int dim, std::uint64_t max_points, const std::string& what,
                          double copies) {
  if (!(points <= static_cast<double>(max_points)))
    throw InvalidArgument(what + " could produce up to " + detail::format_number(points) +
                          " points, above the cap of " + std::to_string(max_points) + " (raise it with --max-points)");
  // The points themselves plus the working structures of a sampler: about
  // four copies. Refuse before allocating rather than fail half-way.
  const double bytes = points * dim * sizeof(double) * copies;
  const double available = physical_memory_bytes();
  if (bytes > available)
    throw InvalidArgument(what + " would need about " + detail::format_number(bytes / (1 << 30)) +
                          " GiB, more than this machine's " + detail::format_number(available / (1 << 30)) + " GiB");
}

double packing_count(double volume, double r, int dim) {
  // Densest packing of balls of radius r/2; boxes gain at most a boundary
  // layer, which the factor 1.2 and the +1 cover for the sizes that matter.
  return 1.2 * volume / packing_volume_per_point(r / 2.0, dim) + 1.0;
}

double typical_count(double volume, double r, int dim) { return 0.6 * packing_count(volume, r, dim); }

}  // namespace pds
