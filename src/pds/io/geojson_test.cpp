#include "pds/io/geojson.h"

#include <gtest/gtest.h>

#include <sstream>

#include "pds/error.h"

namespace pds {
namespace {

Region parse(const std::string& text) {
  std::istringstream in(text);
  return read_geojson(in, "t.geojson");
}

TEST(GeoJson, PolygonWithHole) {
  const Region r = parse(R"({"type": "Polygon", "coordinates": [
      [[0, 0], [1, 0], [1, 1], [0, 1], [0, 0]],
      [[0.25, 0.25], [0.75, 0.25], [0.75, 0.75], [0.25, 0.75], [0.25, 0.25]]]})");
  ASSERT_EQ(r.polygons.size(), 1u);
  EXPECT_EQ(r.polygons[0].outer.size(), 5u);
  ASSERT_EQ(r.polygons[0].holes.size(), 1u);
  EXPECT_TRUE(r.contains(Point<2>{{0.1, 0.5}}));
  EXPECT_FALSE(r.contains(Point<2>{{0.5, 0.5}}));
}

TEST(GeoJson, FeatureCollectionOfMultiPolygons) {
  const Region r = parse(R"({"type": "FeatureCollection", "features": [
      {"type": "Feature", "properties": {}, "geometry": {"type": "MultiPolygon", "coordinates": [
          [[[0, 0], [1, 0], [0, 1]]], [[[2, 2], [3, 2], [3, 3, 10]]]]}},
      {"type": "Feature", "geometry": {"type": "Polygon", "coordinates": [[[5, 5], [6, 5], [6, 6]]]}}]})");
  EXPECT_EQ(r.polygons.size(), 3u);
  EXPECT_TRUE(r.contains(Point<2>{{0.2, 0.2}}));
  EXPECT_TRUE(r.contains(Point<2>{{2.9, 2.5}}));
  EXPECT_TRUE(r.contains(Point<2>{{5.9, 5.5}}));
  EXPECT_FALSE(r.contains(Point<2>{{0.9, 0.9}}));
}

TEST(GeoJson, BadFilesSayWhatIsWrong) {
  const auto message = [](const std::string& text) {
    try {
      parse(text);
    } catch (const InvalidArgument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message("{"), "t.geojson: not valid JSON");
  EXPECT_EQ(message(R"({"type": "Point", "coordinates": [0, 0]})"),
            "t.geojson: geometry type \"Point\" is not a Polygon or MultiPolygon");
  EXPECT_EQ(message(R"({"type": "Polygon"})"), "t.geojson: Polygon without \"coordinates\"");
  EXPECT_NE(message(R"({"type": "Polygon", "coordinates": [[[0, 0], [1, "a"], [0, 1]]]})").find("position"),
            std::string::npos);
  EXPECT_NE(message(R"({"type": "Polygon", "coordinates": [[[0, 0], [1, 0]]]})").find("2 vertices"), std::string::npos);
  EXPECT_EQ(message(R"({"type": "FeatureCollection", "features": []})"), "t.geojson: no polygon");
  EXPECT_EQ(message("[1, 2]"), "t.geojson: expected a GeoJSON object with a \"type\"");
  EXPECT_THROW(read_geojson("/nonexistent/x.geojson"), InvalidArgument);
}

}  // namespace
}  // namespace pds
