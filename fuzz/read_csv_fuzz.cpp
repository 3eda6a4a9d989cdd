// libFuzzer target: the CSV reader. Any bytes either parse or raise
// InvalidArgument/Failure; what parses writes back and reads again to the
// same points (the writer's shortest round-trip form).
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>

#include "pds/error.h"
#include "pds/io/point_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  pds::PointCloud cloud;
  try {
    cloud = pds::read_csv(in, "fuzz.csv");
  } catch (const pds::InvalidArgument&) {
    return 0;
  } catch (const pds::Failure&) {
    return 0;
  }
  std::ostringstream out;
  pds::write_csv(out, cloud);
  std::istringstream back(out.str());
  const pds::PointCloud again = pds::read_csv(back, "round-trip.csv");
  // NaN never equals itself; compare the bits.
  if (again.dim != cloud.dim || again.coords.size() != cloud.coords.size()) std::abort();
  for (std::size_t i = 0; i < cloud.coords.size(); ++i)
    if (!(again.coords[i] == cloud.coords[i]) && !(again.coords[i] != again.coords[i] && cloud.coords[i] != cloud.coords[i]))
      std::abort();
  return 0;
}
