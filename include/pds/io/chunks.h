#pragma once
// Chunked point sets: the directory `pds chunks` and `pds-mpi chunks` write
// (docs/unbounded.md, "The chunk files"), one NPY file a chunk plus
// manifest.json. The reader checks the manifest (format "pds-chunks",
// version 1, dimension 2 or 3, each chunk's file a plain name in the
// manifest's directory, its box and count, the counts adding up to `count`)
// and each chunk against it (its dimension, its count, every point inside its
// chunk's half-open box). Errors name the file and what is wrong
// (InvalidArgument). In pds::json (nlohmann_json, used privately).

#include <cstdint>
#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

#include "pds/point.h"

namespace pds {

struct ChunkManifest {
  struct Chunk {
    std::string file;  // a plain file name, in the manifest's directory
    std::vector<double> lo, hi;
    std::uint64_t count = 0;
  };
  int dim = 0;
  double radius = 0.0;
  std::uint64_t seed = 0;
  std::vector<double> lo, hi;              // the region
  std::vector<double> torus_lo, torus_hi;  // empty unless the field lives on a torus
  std::uint64_t count = 0;
  std::vector<Chunk> chunks;
};

/// Parses and checks a manifest's text (no chunk file is opened).
ChunkManifest parse_chunk_manifest(std::istream& in, const std::string& name);

/// Reads the manifest at `path` and calls f(chunk, points) for each chunk in
/// the manifest's order, one chunk in memory at a time, each checked; returns
/// the manifest.
ChunkManifest for_each_chunk(const std::string& path,
                             const std::function<void(const ChunkManifest::Chunk&, const PointCloud&)>& f);

/// The whole chunked set as one point cloud, sorted lexicographically (x,
/// then y, then z): the canonical order, in which the union of a region's
/// chunks has the bytes of the region sampled whole.
PointCloud read_chunks(const std::string& path, ChunkManifest* manifest = nullptr);

}  // namespace pds
