#pragma once
// Points computed once with SciPy (tests/data/scipy_*.txt, written by
// scripts/scipy_qmc_reference.py): the format is described there.

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace pds::test {

struct ScipyBlock {
  int dim = 0;
  std::size_t count = 0;
  std::uint64_t checksum = 0;
  std::vector<int> columns;
  std::vector<std::vector<double>> rows;  // rows[i][j]: point i, axis columns[j]
};

/// The blocks of tests/data/<file>; empty if the file cannot be read.
inline std::vector<ScipyBlock> read_scipy_blocks(const std::string& file) {
  std::ifstream in(std::string(PDS_TEST_DATA_DIR) + "/" + file);
  std::vector<ScipyBlock> blocks;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream head(line);
    std::string name;
    ScipyBlock b;
    head >> name >> b.dim >> b.count >> b.checksum;
    std::getline(in, line);
    std::istringstream cols(line);
    cols >> name;  // "columns"
    for (int c; cols >> c;) b.columns.push_back(c);
    for (std::size_t i = 0; i < b.count && std::getline(in, line); ++i) {
      std::istringstream values(line);
      std::vector<double> row;
      for (std::string v; values >> v;) row.push_back(std::strtod(v.c_str(), nullptr));  // hex floats: exact
      b.rows.push_back(row);
    }
    blocks.push_back(std::move(b));
  }
  return blocks;
}

/// The checksum of scripts/scipy_qmc_reference.py: sum of bits(x_k) (k + 1) mod 2^64.
inline std::uint64_t scipy_checksum(const std::vector<double>& coords) {
  std::uint64_t sum = 0;
  for (std::size_t k = 0; k < coords.size(); ++k) {
    std::uint64_t bits;
    std::memcpy(&bits, &coords[k], sizeof bits);
    sum += bits * (k + 1);
  }
  return sum;
}

}  // namespace pds::test
