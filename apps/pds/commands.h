#pragma once
// The pds subcommands. Each add_* registers its options on the app and sets
// the callback that runs it; errors are thrown (pds::InvalidArgument for bad
// input, pds::Failure otherwise) and turned into exit codes by main().

#include <CLI/CLI.hpp>
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

/// The text listing every registered method, for --help.
std::string methods_help();

/// docs/methods.md: the registry as a Markdown table (a test keeps the file in
/// sync with the registry).
std::string methods_markdown();

/// The README's table of methods by family, between its `methods-table`
/// markers (a test keeps the README in sync with the registry).
std::string methods_readme_table();

}  // namespace pds::cli
