#include "block_vector.h"

#include <gtest/gtest.h>

#include <cstdint>

namespace pds::detail {
namespace {

TEST(BlockVector, ElementsStayWhereTheyAreWhileItGrows) {
  BlockVector<std::uint32_t, 4> v;  // blocks of 16
  v.push_back(7);
  const std::uint32_t* first = &v[0];
  for (std::uint32_t i = 1; i < 1000; ++i) v.push_back(7 + i);
  EXPECT_EQ(&v[0], first);  // a vector would have moved it
  ASSERT_EQ(v.size(), 1000u);
  for (std::uint32_t i = 0; i < 1000; ++i) ASSERT_EQ(v[i], 7 + i);
}

TEST(BlockVector, TruncateKeepsThePrefixAndGrowsAgain) {
  BlockVector<int, 4> v;
  for (int i = 0; i < 100; ++i) v.push_back(i);
  v.truncate(33);  // into the third block
  ASSERT_EQ(v.size(), 33u);
  for (int i = 0; i < 33; ++i) ASSERT_EQ(v[static_cast<std::size_t>(i)], i);
  for (int i = 33; i < 70; ++i) v.push_back(-i);
  ASSERT_EQ(v.size(), 70u);
  for (int i = 0; i < 33; ++i) EXPECT_EQ(v[static_cast<std::size_t>(i)], i);
  for (int i = 33; i < 70; ++i) EXPECT_EQ(v[static_cast<std::size_t>(i)], -i);
  v.truncate(32);  // a block boundary
  v.truncate(0);
  EXPECT_EQ(v.size(), 0u);
  v.push_back(5);
  EXPECT_EQ(v[0], 5);
}

TEST(BlockVector, ReleasedBlocksLeaveTheRestReadable) {
  BlockVector<int, 4> v;
  for (int i = 0; i < 64; ++i) v.push_back(i);
  v.release_before(40);  // frees blocks 0 and 1 (elements 0-31)
  for (int i = 32; i < 64; ++i) EXPECT_EQ(v[static_cast<std::size_t>(i)], i);
  v.push_back(64);
  EXPECT_EQ(v[64], 64);
  EXPECT_EQ(v.size(), 65u);
}

// Narrow: the values as the narrow type (a cast); wide: as they are. Both
// read back as the wide type, release blocks alike, and grow past a block.
TEST(NarrowableBlockVector, KeepsValuesInEitherWidth) {
  NarrowableBlockVector<std::uint64_t, std::uint16_t, 4> narrow(true), wide(false);
  for (std::uint64_t i = 0; i < 100; ++i) {
    narrow.push_back(1000 + i);
    wide.push_back((i << 40) + i);  // would not survive 16 bits
  }
  ASSERT_EQ(narrow.size(), 100u);
  ASSERT_EQ(wide.size(), 100u);
  for (std::uint64_t i = 0; i < 100; ++i) {
    EXPECT_EQ(narrow[i], 1000 + i);
    EXPECT_EQ(wide[i], (i << 40) + i);
  }
  narrow.release_before(40);
  wide.release_before(40);
  for (std::uint64_t i = 32; i < 100; ++i) {
    EXPECT_EQ(narrow[i], 1000 + i);
    EXPECT_EQ(wide[i], (i << 40) + i);
  }
}

}  // namespace
}  // namespace pds::detail
