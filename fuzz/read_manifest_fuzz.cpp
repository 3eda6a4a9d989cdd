// libFuzzer target: the chunk manifest reader (pds analyze and pds.read_chunks
// on a `pds chunks` directory). Any bytes either give a manifest that keeps
// the reader's promises (dimension 2 or 3, finite non-empty region, every
// chunk a plain file name with corners of that dimension, counts adding up)
// or raise InvalidArgument.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>

#include "pds/error.h"
#include "pds/io/chunks.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  pds::ChunkManifest m;
  try {
    m = pds::parse_chunk_manifest(in, "fuzz.json");
  } catch (const pds::InvalidArgument&) {
    return 0;
  }
  if (m.dim < 2 || m.dim > 3 || m.lo.size() != static_cast<std::size_t>(m.dim) || m.hi.size() != m.lo.size())
    std::abort();
  for (std::size_t a = 0; a < m.lo.size(); ++a)
    if (!(m.lo[a] < m.hi[a]) || !std::isfinite(m.lo[a]) || !std::isfinite(m.hi[a])) std::abort();
  std::uint64_t total = 0;
  for (const auto& c : m.chunks) {
    if (c.file.empty() || c.file.find('/') != std::string::npos || c.file == "..") std::abort();
    if (c.lo.size() != static_cast<std::size_t>(m.dim) || c.hi.size() != c.lo.size()) std::abort();
    total += c.count;
  }
  if (total != m.count) std::abort();
  return 0;
}
