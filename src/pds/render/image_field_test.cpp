#include "pds/render/image_field.h"

#include <gtest/gtest.h>

#include <cmath>

#include "pds/error.h"

namespace pds {
namespace {

TEST(ImageField, DarkIsDenseAndToneIsLinearInDensity) {
  Image image(2, 1);
  image.at(0, 0) = 0.0;  // black on the left
  image.at(1, 0) = 1.0;  // white on the right
  const ImageOnBounds on(image, {{0, 0}}, {{2, 1}});
  const double rmin = 0.01, rmax = 0.04;
  const auto r = radius_from_image(on, rmin, rmax, false);
  EXPECT_DOUBLE_EQ(r({{0.5, 0.5}}), rmin);  // the pixel centres
  EXPECT_DOUBLE_EQ(r({{1.5, 0.5}}), rmax);
  EXPECT_DOUBLE_EQ(r({{0.1, 0.9}}), rmin);  // constant beyond the outer centres
  // Halfway the density 1/r^2 is the mean of black's and white's.
  const double mid = r({{1.0, 0.5}});
  EXPECT_NEAR(1 / (mid * mid), 0.5 / (rmin * rmin) + 0.5 / (rmax * rmax), 1e-6 / (rmin * rmin));
  const auto inverted = radius_from_image(on, rmin, rmax, true);
  EXPECT_DOUBLE_EQ(inverted({{0.5, 0.5}}), rmax);
  EXPECT_DOUBLE_EQ(inverted({{1.5, 0.5}}), rmin);
}

TEST(ImageField, TopRowAtTheUpperBoundAndMaskOnWhereDark) {
  Image image(1, 2);
  image.at(0, 0) = 0.2;  // top row: dark
  image.at(0, 1) = 0.8;  // bottom row: light
  const ImageOnBounds on(image, {{-1, 10}}, {{1, 20}});
  const auto mask = mask_from_image(on);
  EXPECT_TRUE(mask({{0.0, 19.0}}));
  EXPECT_TRUE(mask({{0.9, 15.01}}));
  EXPECT_FALSE(mask({{0.0, 14.99}}));
  EXPECT_FALSE(mask({{-0.9, 11.0}}));
  EXPECT_FALSE(mask({{-5.0, 0.0}}));  // outside: the nearest edge pixel
  EXPECT_DOUBLE_EQ(on.smooth({{0, 17.5}}), 0.2);
  EXPECT_DOUBLE_EQ(on.smooth({{0, 15.0}}), 0.5);
}

TEST(ImageField, InvalidInput) {
  EXPECT_THROW(ImageOnBounds(Image(), {{0, 0}}, {{1, 1}}), InvalidArgument);
  EXPECT_THROW(ImageOnBounds(Image(2, 2), {{0, 0}}, {{0, 1}}), InvalidArgument);
  EXPECT_THROW(ImageOnBounds(Image(2, 2), {{0, 0}}, {{1, NAN}}), InvalidArgument);
}

}  // namespace
}  // namespace pds
