#pragma once
// The pds subcommands. Each add_* registers its options on the app and sets
// the callback that runs it; errors are thrown (pds::InvalidArgument for bad
// input, pds::Failure otherwise) and turned into exit codes by main().

#include <CLI/CLI.hpp>
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace pds::cli {

void add_generate(CLI::App& app);
void add_analyze(CLI::App& app);
void add_methods(CLI::App& app);
void add_compare(CLI::App& app);
void add_tile(CLI::App& app);
void add_render(CLI::App& app);
void add_render_sheet(CLI::App& app);
/// pds unbounded and pds chunks (apps/pds/unbounded.cpp).
void add_unbounded(CLI::App& app);

/// The processes that share one `chunks` run: chunk k is made by process
/// k mod size; `max_all` replaces a vector, on every process, by its
/// elementwise maximum over all of them (a collective: every process calls it
/// once per run, also when its own chunks failed). One process: no-op.
struct ChunkTeam {
  int rank = 0;
  int size = 1;
  std::function<void(std::vector<std::int64_t>&)> max_all = [](std::vector<std::int64_t>&) {};
};

/// The `chunks` subcommand alone, its chunks split over `team` (pds-mpi);
/// process 0 writes the manifest once every process has written its chunks.
void add_chunks(CLI::App& app, const ChunkTeam& team);

/// Parses and runs `app`, turning errors into exit codes (0 success, 2 bad
/// usage or input, 1 failure) and one line on stderr prefixed with the
/// app's name; quiet_usage_errors leaves out the line for bad usage (other
/// processes of the same run print it).
int run_app(CLI::App& app, int argc, char** argv, bool quiet_usage_errors = false);

/// Options every command that takes a domain shares.
struct DomainOptions {
  int dim = 2;
  bool torus = false;
  std::vector<double> bounds;  // x0,y0[,z0],x1,y1[,z1]
};

/// --dim, --torus, --bounds on `command`; dim_option false leaves out --dim
/// (when the dimension comes from a file).
void add_domain_options(CLI::App& command, DomainOptions& options, bool dim_option = true);

/// Splits --bounds into lo and hi for the dimension; empty means the unit box.
void split_bounds(const DomainOptions& options, int dim, std::vector<double>& lo, std::vector<double>& hi);

/// Throws InvalidArgument "NAME does not apply with WHAT" for the first of
/// `names` given on `command` (options a mode of a command cannot use).
void refuse_options(const CLI::App& command, std::initializer_list<const char*> names, const std::string& what);

/// The text listing every registered method, for --help.
std::string methods_help();

/// docs/methods.md: the registry as a Markdown table (a test keeps the file in
/// sync with the registry).
std::string methods_markdown();

/// The README's table of methods by family, between its `methods-table`
/// markers (a test keeps the README in sync with the registry).
std::string methods_readme_table();

}  // namespace pds::cli
