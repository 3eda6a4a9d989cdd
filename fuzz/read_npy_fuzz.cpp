// libFuzzer target: the NPY reader. Any bytes either parse or raise
// InvalidArgument/Failure; what parses writes back (float64) and reads again
// to the same points.
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <string>

#include "pds/error.h"
#include "pds/io/point_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  pds::PointCloud cloud;
  try {
    cloud = pds::read_npy(in, "fuzz.npy");
  } catch (const pds::InvalidArgument&) {
    return 0;
  } catch (const pds::Failure&) {
    return 0;
  }
  std::ostringstream out;
  pds::write_npy(out, cloud);
  std::istringstream back(out.str());
  const pds::PointCloud again = pds::read_npy(back, "round-trip.npy");
  // An empty set (shape (0, D)) has no buffer: memcmp must not see its null pointer.
  if (again.dim != cloud.dim || again.coords.size() != cloud.coords.size() ||
      (!cloud.coords.empty() &&
       std::memcmp(again.coords.data(), cloud.coords.data(), cloud.coords.size() * sizeof(double)) != 0))
    std::abort();
  return 0;
}
