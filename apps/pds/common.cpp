#include <iostream>
#include <memory>
#include <sstream>

#include "commands.h"
#include "pds/error.h"
#include "pds/registry.h"

namespace pds::cli {

void add_domain_options(CLI::App& command, DomainOptions& options, bool dim_option) {
  if (dim_option) command.add_option("--dim,-d", options.dim, "Dimension (each method's range: pds methods)")->capture_default_str();
  command.add_flag("--torus", options.torus, "Periodic domain: distances wrap around the bounds");
  command
      .add_option("--bounds", options.bounds,
                  "Domain box as lo then hi corners, e.g. 0,0,2,1 (default: the unit square/cube)")
      ->delimiter(',');
}

void refuse_options(const CLI::App& command, std::initializer_list<const char*> names, const std::string& what) {
  for (const char* name : names)
    if (const CLI::Option* option = command.get_option_no_throw(name); option && option->count())
      throw InvalidArgument(std::string(name) + " does not apply with " + what);
}

void split_bounds(const DomainOptions& options, int dim, std::vector<double>& lo, std::vector<double>& hi) {
  lo.clear();
  hi.clear();
  if (options.bounds.empty()) return;
  if (options.bounds.size() != static_cast<std::size_t>(2 * dim))
    throw InvalidArgument("--bounds needs " + std::to_string(2 * dim) + " values for dimension " + std::to_string(dim) +
                          " (lo corner then hi corner), got " + std::to_string(options.bounds.size()));
  lo.assign(options.bounds.begin(), options.bounds.begin() + dim);
  hi.assign(options.bounds.begin() + dim, options.bounds.end());
}

namespace {

std::string sizing_of(const Method& m) {
  return m.takes_count && m.takes_radius ? "count or radius" : m.takes_count ? "count" : "radius";
}

/// What the method promises, e.g. "minimum distance, maximal, exact count".
std::string guarantees_of(const Method& m) {
  std::string out;
  auto add = [&](bool on, const char* what) {
    if (on) out += (out.empty() ? "" : ", ") + std::string(what);
  };
  add(m.min_distance, "minimum distance");
  add(m.maximal, "maximal");
  add(m.exact_count, "exact count");
  add(m.progressive, "progressive");
  add(m.deterministic, "no randomness");
  return out;
}

}  // namespace

std::string methods_help() {
  std::ostringstream os;
  os << "Methods (pds generate METHOD):\n";
  for (const Method& m : methods()) {
    os << "  " << m.name << std::string(m.name.size() < 18 ? 18 - m.name.size() : 1, ' ') << m.summary << "\n";
    const std::string promises = guarantees_of(m);
    os << std::string(20, ' ') << "takes --" << (m.takes_count && m.takes_radius ? "count or --radius" : sizing_of(m))
       << "; dims " << m.dims.text() << (promises.empty() ? "" : "; " + promises) << "\n";
    for (const MethodParam& p : m.params)
      os << std::string(20, ' ') << "--param " << p.name << "=" << p.default_value << "  " << p.help << "\n";
  }
  os << "\n--radius is the minimum distance between any two samples (Bridson's and SciPy's convention),\n"
        "not the radius of the disks around them.";
  return os.str();
}

std::string methods_markdown() {
  std::ostringstream os;
  os << "# Methods\n\n"
        "Generated from the registry by `pds methods --markdown`; a test fails when this file and the\n"
        "registry disagree. `--radius` is the minimum distance between any two samples. Guarantees:\n"
        "*minimum distance* (every pair at least `--radius` apart), *maximal* (no room left for another\n"
        "sample), *exact count* (`--count N` gives N points), *progressive* (every prefix is itself well\n"
        "spread); the conformance tests check each one the registry claims.\n\n"
        "| method | family | what it makes | sizing | dims | guarantees | parameters (default) | reference | page |\n"
        "|---|---|---|---|---|---|---|---|---|\n";
  for (const Method& m : methods()) {
    std::string params;
    const std::string dims = m.dims.text();
    for (const MethodParam& p : m.params) {
      std::ostringstream v;
      v << p.default_value;
      params += (params.empty() ? "" : "; ") + ("`" + p.name + "` (" + v.str() + ") " + p.help);
    }
    const std::string promises = guarantees_of(m);
    const std::string page = m.docs.substr(m.docs.rfind('/') + 1);
    os << "| `" << m.name << "` | " << family_name(m.family) << " | " << m.summary << " | " << sizing_of(m) << " | "
       << dims << " | " << (promises.empty() ? "-" : promises) << " | " << (params.empty() ? "none" : params) << " | "
       << (m.citation.empty() ? "-" : m.citation) << " | [" << page << "](" << page << ") |\n";
  }
  return os.str();
}

std::string methods_readme_table() {
  std::ostringstream os;
  os << "| family | methods | page |\n|---|---|---|\n";
  for (Family family : {Family::white_noise, Family::stratified, Family::sequence, Family::poisson_disk,
                        Family::fast_poisson_disk, Family::maximal_poisson_disk, Family::optimized}) {
    std::string names, pages;
    for (const Method& m : methods()) {
      if (m.family != family) continue;
      names += (names.empty() ? "`" : ", `") + m.name + "`";
      const std::string link = "[" + m.docs.substr(m.docs.rfind('/') + 1) + "](" + m.docs + ")";
      if (pages.find(link) == std::string::npos) pages += (pages.empty() ? "" : ", ") + link;
    }
    if (!names.empty()) os << "| " << family_name(family) << " | " << names << " | " << pages << " |\n";
  }
  return os.str();
}

void add_methods(CLI::App& app) {
  auto markdown = std::make_shared<bool>(false), readme = std::make_shared<bool>(false);
  CLI::App* cmd = app.add_subcommand("methods", "List the registered methods");
  cmd->add_flag("--markdown", *markdown, "Print the Markdown table of docs/methods.md");
  cmd->add_flag("--readme", *readme, "Print the README's method table (by family)");
  cmd->callback([markdown, readme] {
    std::cout << (*readme ? methods_readme_table() : *markdown ? methods_markdown() : methods_help() + "\n");
  });
}

}  // namespace pds::cli
