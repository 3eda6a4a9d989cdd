// libFuzzer target: the PNG reader behind pds generate --density and --mask
// (Cairo's decoder, libpng, after our header check). Any bytes either give
// an image within the size limits with every grey level in [0, 1], or raise
// InvalidArgument.
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>

#include "pds/error.h"
#include "pds/render/png.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  pds::Image image;
  try {
    image = pds::read_png(in, "fuzz.png");
  } catch (const pds::InvalidArgument&) {
    return 0;
  }
  if (image.width < 1 || image.height < 1 ||
      static_cast<std::uint64_t>(image.width) * static_cast<std::uint64_t>(image.height) > pds::kMaxReadPixels)
    std::abort();
  for (const double v : image.pixels)
    if (!(v >= 0.0 && v <= 1.0)) std::abort();
  return 0;
}
