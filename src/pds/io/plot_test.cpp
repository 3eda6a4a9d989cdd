#include "pds/io/plot.h"

#include <cairo.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "pds/error.h"
#include "pds/samplers/random.h"
#include "pds/samplers/regular.h"

namespace pds {
namespace {

namespace fs = std::filesystem;

class Plot : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("pds_plot_test_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  fs::path dir_;
};

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream os;
  os << in.rdbuf();
  return os.str();
}

/// A decoded PNG; the test fails when the file is not a valid PNG.
struct Png {
  explicit Png(const std::string& path) : surface(cairo_image_surface_create_from_png(path.c_str())) {}
  ~Png() { cairo_surface_destroy(surface); }
  bool valid() const { return cairo_surface_status(surface) == CAIRO_STATUS_SUCCESS; }
  int width() const { return cairo_image_surface_get_width(surface); }
  int height() const { return cairo_image_surface_get_height(surface); }
  /// Green channel (the pictures are grey or black on white) of a pixel.
  int grey(int x, int y) const {
    cairo_surface_flush(surface);
    const auto* row = cairo_image_surface_get_data(surface) + y * cairo_image_surface_get_stride(surface);
    return static_cast<int>((reinterpret_cast<const std::uint32_t*>(row)[x] >> 8) & 0xff);
  }
  cairo_surface_t* surface;
};

TEST_F(Plot, PointsAsPngSvgAndPdf) {
  // One point at the centre of the unit square: dark there, white in the corners.
  const PointSet<2> one{{{0.5, 0.5}}};
  plot_points(one, Domain<2>::unit(), path("p.png"), {.size = 200});
  Png png(path("p.png"));
  ASSERT_TRUE(png.valid());
  EXPECT_EQ(png.width(), 216);  // 200 plus an 8 pixel margin on each side
  EXPECT_EQ(png.height(), 216);
  EXPECT_LT(png.grey(108, 108), 64);
  EXPECT_EQ(png.grey(30, 30), 255);

  // A 2:1 domain keeps its aspect ratio; SVG and PDF carry the same size in points.
  const auto wide = Domain<2>::box({0, 0}, {2, 1});
  const auto points = white_noise<2>({300}, wide, 1);
  plot_points(points, wide, path("p.svg"), {.size = 400, .disk_radius = 0.02});
  const std::string svg = slurp(path("p.svg"));
  EXPECT_EQ(svg.rfind("<?xml", 0), 0u);
  EXPECT_NE(svg.find("width=\"416pt\" height=\"216pt\""), std::string::npos) << svg.substr(0, 300);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
  plot_points(points, wide, path("p.pdf"), {.size = 400});
  const std::string pdf = slurp(path("p.pdf"));
  EXPECT_EQ(pdf.rfind("%PDF-", 0), 0u);
  EXPECT_NE(pdf.find("%%EOF"), std::string::npos);
}

TEST_F(Plot, SpectrumImageHasDcAtTheCentre) {
  // A regular 8 x 8 grid: P = 64 (18 dB, white) at the lattice frequencies,
  // 0 (black) elsewhere. K = 20, 41 frequencies a side, 13 pixels each.
  const std::vector<PointSet<2>> sets{regular<2>({{8, 8, 1}}, Domain<2>::unit(true))};
  const Periodogram p = periodogram<2>(sets, Domain<2>::unit(true), {.max_frequency = 20});
  plot_spectrum(p, path("s.png"));
  Png png(path("s.png"));
  ASSERT_TRUE(png.valid());
  ASSERT_EQ(png.width(), 41 * 13);
  ASSERT_EQ(png.height(), 41 * 13);
  auto pixel = [&](int kx, int ky) { return png.grey((kx + 20) * 13 + 6, (20 - ky) * 13 + 6); };
  EXPECT_EQ(pixel(0, 0), 255);
  EXPECT_EQ(pixel(8, 0), 255);
  EXPECT_EQ(pixel(-8, 16), 255);
  EXPECT_EQ(pixel(1, 0), 0);
  EXPECT_EQ(pixel(4, 4), 0);
  // White noise on the linear scale: P = 1 is mid-grey (P / 2 of white).
  const std::vector<PointSet<2>> one{{{{0.3, 0.6}}}};  // a single point: P = 1 exactly
  plot_spectrum(periodogram<2>(one, Domain<2>::unit(true), {.max_frequency = 4}), path("l.png"),
                {.scale = SpectrumScale::Linear, .size = 90});
  Png flat(path("l.png"));
  ASSERT_TRUE(flat.valid());
  EXPECT_EQ(flat.width(), 90);
  EXPECT_EQ(flat.grey(45, 45), 128);
  EXPECT_EQ(flat.grey(5, 80), 128);
}

TEST_F(Plot, ChartsAndComparisonSheet) {
  const auto domain = Domain<2>::unit(true);
  std::vector<PointSet<2>> sets{white_noise<2>({256}, domain, 1), white_noise<2>({256}, domain, 2)};
  const Periodogram p = periodogram<2>(sets, domain, {.max_frequency = 16});
  const RadialSpectrum r = radial_average(p);
  plot_radial(r, path("r.png"), {.width = 640, .height = 480});
  Png radial(path("r.png"));
  ASSERT_TRUE(radial.valid());
  EXPECT_EQ(radial.width(), 640);
  EXPECT_EQ(radial.height(), 480);
  plot_radial(r, path("r.svg"));
  EXPECT_NE(slurp(path("r.svg")).find("width=\"800pt\" height=\"600pt\""), std::string::npos);

  plot_pair_correlation(pair_correlation<2>(sets, domain), path("g.pdf"));
  EXPECT_EQ(slurp(path("g.pdf")).rfind("%PDF-", 0), 0u);

  std::vector<ComparisonRow> rows(2);
  for (int i = 0; i < 2; ++i) rows[i] = {"row" + std::to_string(i), sets[i], domain, p, r};
  plot_comparison(rows, path("c.png"), 100);
  Png sheet(path("c.png"));
  ASSERT_TRUE(sheet.valid());
  EXPECT_EQ(sheet.width(), 3 * 100 + 4 * 12);
  EXPECT_EQ(sheet.height(), 30 + 2 * (28 + 100 + 12));
}

TEST_F(Plot, RejectsBadInput) {
  const PointSet<2> one{{{0.5, 0.5}}};
  EXPECT_THROW(plot_points(one, Domain<2>::unit(), path("p.jpg")), InvalidArgument);
  EXPECT_THROW(plot_points(one, Domain<2>::unit(), path("p.png"), {.size = 10}), InvalidArgument);
  EXPECT_THROW(plot_comparison({}, path("c.png")), InvalidArgument);
  EXPECT_THROW(plot_points(one, Domain<2>::unit(), (dir_ / "missing" / "p.png").string()), Failure);
  EXPECT_EQ(image_format_for("A.SVG"), ImageFormat::Svg);
}

}  // namespace
}  // namespace pds
