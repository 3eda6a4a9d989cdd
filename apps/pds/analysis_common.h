#pragma once
// Shared by `pds analyze` and `pds compare`: obtaining realisations of a
// method (consecutive seeds) and the method parameters' parsing.

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "pds/point.h"
#include "pds/registry.h"

namespace pds::cli {

/// NAME=NUMBER items of --param.
std::map<std::string, double> parse_params(const std::vector<std::string>& items);

/// `sets` realisations of `method` with seeds seed, seed+1, ... (request.seed
/// is the first). A method that takes only a radius, asked for a count, gets
/// the radius at which a maximal Poisson disk set has about that many points
/// (relative radius 0.75, Lagae & Dutre 2008).
std::vector<PointCloud> generate_sets(const std::string& method, GenerateRequest request, std::size_t sets);

/// Writes a CSV with a header line and one row per index of the columns.
void write_csv_columns(const std::string& path, const std::vector<std::string>& names,
                       const std::vector<const std::vector<double>*>& columns);

}  // namespace pds::cli
