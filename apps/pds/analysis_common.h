#pragma once
// Shared by the subcommands that generate points (generate, analyze,
// compare, tile): one option group that becomes a GenerateRequest, sizing by
// the registry's policy, and the method parameters' parsing.

#include <CLI/CLI.hpp>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "commands.h"
#include "pds/io/point_file.h"
#include "pds/point.h"
#include "pds/registry.h"

namespace pds::cli {

/// NAME=NUMBER items of --param.
std::map<std::string, double> parse_params(const std::vector<std::string>& items);

/// The options every subcommand that generates shares: --count, --radius,
/// --dim, --torus, --bounds, --seed, --threads, --max-points, --max-memory,
/// --quiet, --param.
struct GenerationOptions {
  DomainOptions domain;
  std::uint64_t count = 0;
  double radius = 0;
  std::uint64_t seed = 0;
  int threads = 0;
  std::uint64_t max_points = kDefaultMaxPoints;
  std::string max_memory;  // e.g. 512M; empty: no budget
  bool quiet = false;      // no progress bar
  std::vector<std::string> params;
  /// Set by add_generation_options; null for options left out.
  CLI::Option* count_option = nullptr;
  CLI::Option* radius_option = nullptr;
  std::vector<CLI::Option*> added;  // every option of the group on the command
};

/// Which of the group a subcommand takes, and how its help reads.
struct GenerationOptionSet {
  bool radius = true;  // --radius (a command may own it, e.g. analyze)
  bool dim = true;     // --dim
  bool domain = true;  // --torus and --bounds
  /// The count's default when not given (0: none, the count is then absent).
  std::uint64_t default_count = 0;
  /// Prefix of every help text, e.g. "With --method: ".
  std::string scope;
};

/// Adds the group to `command`; `options` must outlive it.
void add_generation_options(CLI::App& command, GenerationOptions& options, const GenerationOptionSet& set = {});

/// The request the options say: count and radius only where given (or the
/// default count), the domain from --dim/--torus/--bounds.
GenerateRequest generation_request(const GenerationOptions& options, const GenerationOptionSet& set = {});

/// True when any option of the group was given on the command line.
bool any_generation_option_given(const GenerationOptions& options);

/// `sets` realisations of `method` with seeds seed, seed+1, ... (request.seed
/// is the first), sized by pds::size_request (a radius-only method asked for
/// a count gets the radius of relative radius kCountRelativeRadius).
/// Progress: one part per set (pds::part_of).
std::vector<PointCloud> generate_sets(const std::string& method, GenerateRequest request, std::size_t sets,
                                      const Progress& progress = {});

/// generate() with a progress bar labelled with the method (none with
/// `quiet` or off a terminal).
PointCloud generate_with_progress(const std::string& method, GenerateRequest request, bool quiet);

/// write_points() whose temporary file a Ctrl-C removes (terminal.h).
void write_output(const std::string& path, const PointCloud& points, NpyType npy_type = NpyType::Float64);
/// The same with named columns (write_table()).
void write_output(const std::string& path, const PointCloud& table, const std::vector<Column>& columns,
                  NpyType npy_type = NpyType::Float64);

/// Bytes from a size such as 512M, 2G, 1.5GiB or 1000000 (K, M, G, T: powers
/// of 1024); throws InvalidArgument naming the option.
double parse_size(const std::string& text, const std::string& option);

/// Writes a CSV with a header line and one row per index of the columns.
void write_csv_columns(const std::string& path, const std::vector<std::string>& names,
                       const std::vector<const std::vector<double>*>& columns);

}  // namespace pds::cli
