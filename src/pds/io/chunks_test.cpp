#include "pds/io/chunks.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "pds/error.h"
#include "pds/io/point_file.h"

namespace pds {
namespace {

namespace fs = std::filesystem;

/// A directory of three chunks of [0, 2) x [0, 2) and its manifest.
struct ChunkDir {
  fs::path dir = fs::temp_directory_path() / ("pds_chunks_test_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
                                               ::testing::UnitTest::GetInstance()->current_test_info()->name());
  ChunkDir() {
    fs::create_directories(dir);
    write_points((dir / "chunk_0_0.npy").string(), PointCloud{2, {0.25, 0.5, 0.75, 0.125}});
    write_points((dir / "chunk_1_0.npy").string(), PointCloud{2, {1.5, 0.5}});
    write_points((dir / "chunk_0_1.npy").string(), PointCloud{2, {0.5, 1.5}});
  }
  ~ChunkDir() { fs::remove_all(dir); }
  std::string manifest(const std::string& text) const {
    const std::string path = (dir / "manifest.json").string();
    std::ofstream(path) << text;
    return path;
  }
};

const char* kGood = R"({"format": "pds-chunks", "version": 1, "method": "unbounded", "dim": 2, "radius": 0.1,
  "seed": 3, "region": {"lo": [0, 0], "hi": [2, 2]}, "torus": null, "chunk": 1, "count": 4,
  "chunks": [{"file": "chunk_0_0.npy", "index": [0, 0], "lo": [0, 0], "hi": [1, 1], "count": 2},
             {"file": "chunk_1_0.npy", "index": [1, 0], "lo": [1, 0], "hi": [2, 1], "count": 1},
             {"file": "chunk_0_1.npy", "index": [0, 1], "lo": [0, 1], "hi": [1, 2], "count": 1}]})";

TEST(Chunks, ReadsTheChunksInCanonicalOrder) {
  const ChunkDir d;
  ChunkManifest m;
  const PointCloud all = read_chunks(d.manifest(kGood), &m);
  EXPECT_EQ(all, (PointCloud{2, {0.25, 0.5, 0.5, 1.5, 0.75, 0.125, 1.5, 0.5}}));  // sorted lexicographically
  EXPECT_EQ(m.dim, 2);
  EXPECT_EQ(m.count, 4u);
  EXPECT_EQ(m.seed, 3u);
  EXPECT_TRUE(m.torus_lo.empty());
  ASSERT_EQ(m.chunks.size(), 3u);
  EXPECT_EQ(m.chunks[1].file, "chunk_1_0.npy");
}

TEST(Chunks, RefusesBadManifests) {
  const ChunkDir d;
  const auto refused = [&](std::string text, const std::string& fragment) {
    try {
      read_chunks(d.manifest(text));
      ADD_FAILURE() << "accepted: " << text;
    } catch (const InvalidArgument& e) {
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
  };
  const auto edit = [](std::string s, const std::string& from, const std::string& to) {
    s.replace(s.find(from), from.size(), to);
    return s;
  };
  const auto with = [&](const std::string& from, const std::string& to) { return edit(kGood, from, to); };
  refused("{", "not valid JSON");
  refused("[1, 2]", "not a JSON object");
  refused(with("pds-chunks", "other"), "not a chunk manifest");
  refused(with("\"version\": 1", "\"version\": 2"), "version 2");
  refused(with("\"dim\": 2", "\"dim\": 4"), "'dim'");
  refused(with("\"radius\": 0.1", "\"radius\": -1"), "'radius'");
  refused(with("\"count\": 4", "\"count\": 5"), "add up to 4");
  refused(with("\"count\": 1}", "\"count\": 2}"), "exceed");
  refused(with("chunk_1_0.npy\"", "../chunk_1_0.npy\""), "plain file name");
  refused(with("chunk_1_0.npy\"", "missing.npy\""), "missing.npy");
  refused(with("\"lo\": [1, 0]", "\"lo\": [1]"), "chunk 1.lo");
  refused(with("\"lo\": [1, 0], \"hi\": [2, 1], \"count\": 1", "\"lo\": [1, 0], \"hi\": [1.25, 1], \"count\": 1"),
          "outside its chunk");
  refused(edit(with("\"count\": 2}", "\"count\": 1}"), "\"count\": 4", "\"count\": 3"), "holds 2 points");
  refused(with("\"region\": {\"lo\": [0, 0], \"hi\": [2, 2]}", "\"region\": {\"lo\": [0, 0], \"hi\": [0, 2]}"),
          "'region' is empty");
}

// The manifest alone (what the fuzz target feeds).
TEST(Chunks, ParsesTheManifestText) {
  std::istringstream in(kGood);
  const ChunkManifest m = parse_chunk_manifest(in, "m.json");
  EXPECT_EQ(m.chunks.size(), 3u);
  EXPECT_EQ(m.lo, (std::vector<double>{0, 0}));
  std::istringstream bad("{\"format\": \"pds-chunks\"}");
  EXPECT_THROW(parse_chunk_manifest(bad, "m.json"), InvalidArgument);
}

}  // namespace
}  // namespace pds
