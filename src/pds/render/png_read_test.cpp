#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "pds/error.h"
#include "pds/render/png.h"

namespace pds {
namespace {

// The bytes of a PNG written by write_png.
std::string png_bytes(const Image& image) {
  const auto path = std::filesystem::temp_directory_path() / ("pds_png_read_" + std::to_string(::getpid()) + ".png");
  write_png(path.string(), image);
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  std::filesystem::remove(path);
  return bytes.str();
}

std::string message(const std::string& bytes) {
  std::istringstream in(bytes);
  try {
    read_png(in, "t.png");
  } catch (const InvalidArgument& e) {
    return e.what();
  }
  return "no error";
}

TEST(PngRead, StreamRoundTripsGreyLevels) {
  Image image(7, 5);
  for (int y = 0; y < 5; ++y)
    for (int x = 0; x < 7; ++x) image.at(x, y) = (x + 7 * y) / 34.0;
  std::istringstream in(png_bytes(image));
  const Image back = read_png(in, "t.png");
  ASSERT_EQ(back.width, 7);
  ASSERT_EQ(back.height, 5);
  for (std::size_t i = 0; i < image.pixels.size(); ++i) EXPECT_NEAR(back.pixels[i], image.pixels[i], 0.5 / 255 + 1e-12);
}

TEST(PngRead, BadBytesSayWhatIsWrong) {
  const std::string good = png_bytes(Image(16, 16, 0.5));
  EXPECT_EQ(message("not a png"), "cannot read t.png as PNG: no PNG signature and header");
  EXPECT_EQ(message(""), "cannot read t.png as PNG: no PNG signature and header");
  // Cut short inside the image data: Cairo's reader fails, we say so.
  EXPECT_NE(message(good.substr(0, good.size() / 2)).find("cannot read t.png as PNG"), std::string::npos);
  // A header declaring 40000 x 40000 pixels is refused before decoding.
  std::string huge = good;
  for (int i : {16, 20}) {
    huge[i] = 0;
    huge[i + 1] = 0;
    huge[i + 2] = static_cast<char>(40000 >> 8);
    huge[i + 3] = static_cast<char>(40000 & 0xff);
  }
  EXPECT_EQ(message(huge), "cannot read t.png as PNG: 40000x40000 pixels, more than 32767 a side or 67108864 in all");
  std::string zero = good;
  for (int i = 16; i < 20; ++i) zero[i] = 0;
  EXPECT_NE(message(zero).find("0x16 pixels"), std::string::npos);
  EXPECT_THROW(read_png("/nonexistent/dir/x.png"), InvalidArgument);
}

}  // namespace
}  // namespace pds
