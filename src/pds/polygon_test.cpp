#include "pds/polygon.h"

#include <gtest/gtest.h>

#include <cmath>

#include "pds/error.h"
#include "pds/rng.h"

namespace pds {
namespace {

Ring square(double x0, double y0, double x1, double y1) {
  return {Point<2>{{x0, y0}}, Point<2>{{x1, y0}}, Point<2>{{x1, y1}}, Point<2>{{x0, y1}}};
}

TEST(Polygon, EvenOddAgainstClosedForms) {
  // A regular 64-gon against its inscribed and circumscribed circles, either
  // orientation, with and without GeoJSON's repeated closing vertex.
  Ring ring;
  const int n = 64;
  for (int i = 0; i <= n; ++i)
    ring.push_back(Point<2>{{0.5 + 0.4 * std::cos(2 * M_PI * i / n), 0.5 + 0.4 * std::sin(2 * M_PI * i / n)}});
  Ring reversed(ring.rbegin(), ring.rend());
  Ring open(ring.begin(), ring.end() - 1);
  const double inner = 0.4 * std::cos(M_PI / n);
  Rng rng(1);
  for (int q = 0; q < 20000; ++q) {
    const Point<2> x{{rng.uniform(), rng.uniform()}};
    const double d = std::hypot(x[0] - 0.5, x[1] - 0.5);
    if (d < inner) {
      ASSERT_TRUE(ring_contains(ring, x) && ring_contains(reversed, x) && ring_contains(open, x)) << x;
    } else if (d > 0.4) {
      ASSERT_FALSE(ring_contains(ring, x) || ring_contains(reversed, x) || ring_contains(open, x)) << x;
    }
  }
}

TEST(Polygon, HolesAndSeveralPolygons) {
  Region region;
  region.polygons.push_back({square(0, 0, 1, 1), {square(0.25, 0.25, 0.75, 0.75)}});
  region.polygons.push_back({square(0.4, 0.4, 0.6, 0.6), {}});  // an island inside the hole
  region.polygons.push_back({square(2, 2, 3, 3), {}});
  EXPECT_TRUE(region.contains(Point<2>{{0.1, 0.1}}));
  EXPECT_FALSE(region.contains(Point<2>{{0.3, 0.3}}));  // in the hole
  EXPECT_TRUE(region.contains(Point<2>{{0.5, 0.5}}));   // on the island
  EXPECT_TRUE(region.contains(Point<2>{{2.5, 2.1}}));
  EXPECT_FALSE(region.contains(Point<2>{{1.5, 1.5}}));
  EXPECT_FALSE(region.contains(Point<2>{{-0.1, 0.5}}));
  EXPECT_NO_THROW(region.validate("test"));
}

TEST(Polygon, ValidateNamesTheFault) {
  Region empty;
  EXPECT_THROW(empty.validate("f"), InvalidArgument);
  Region two;
  two.polygons.push_back({{Point<2>{{0, 0}}, Point<2>{{1, 0}}}, {}});
  EXPECT_THROW(two.validate("f"), InvalidArgument);
  Region nan;
  nan.polygons.push_back({square(0, 0, 1, 1), {{Point<2>{{0, 0}}, Point<2>{{NAN, 0}}, Point<2>{{1, 1}}}}});
  try {
    nan.validate("f.geojson");
    FAIL();
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("hole 1"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace pds
