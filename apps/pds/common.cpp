#include <charconv>
#include <sstream>

#include "commands.h"
#include "pds/error.h"
#include "pds/registry.h"

namespace pds::cli {

void add_domain_options(CLI::App& command, DomainOptions& options, bool dim_option) {
  if (dim_option) command.add_option("--dim,-d", options.dim, "Dimension (2 or 3)")->capture_default_str();
  command.add_flag("--torus", options.torus, "Periodic domain: distances wrap around the bounds");
  command.add_option("--bounds", options.bounds,
                     "Domain box as lo then hi corners, e.g. 0,0,2,1 (default: the unit square/cube)")
      ->delimiter(',');
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

std::map<std::string, double> parse_params(const std::vector<std::string>& items) {
  std::map<std::string, double> params;
  for (const std::string& item : items) {
    const auto eq = item.find('=');
    double value = 0;
    const char* begin = item.data() + (eq == std::string::npos ? 0 : eq + 1);
    const char* end = item.data() + item.size();
    const auto [ptr, ec] = std::from_chars(begin, end, value);
    if (eq == std::string::npos || eq == 0 || ec != std::errc() || ptr != end)
      throw InvalidArgument("--param expects NAME=NUMBER, got '" + item + "'");
    params[item.substr(0, eq)] = value;
  }
  return params;
}

std::string methods_help() {
  std::ostringstream os;
  os << "Methods (pds generate METHOD):\n";
  for (const Method& m : methods()) {
    os << "  " << m.name << std::string(m.name.size() < 18 ? 18 - m.name.size() : 1, ' ') << m.summary << "\n";
    std::string sizing = m.takes_count && m.takes_radius ? "--count or --radius" : m.takes_count ? "--count" : "--radius";
    os << std::string(20, ' ') << "takes " << sizing << (m.maximal ? "; maximal" : "")
       << (m.deterministic ? "; no randomness" : "") << "\n";
    for (const MethodParam& p : m.params)
      os << std::string(20, ' ') << "--param " << p.name << "=" << p.default_value << "  " << p.help << "\n";
  }
  os << "\n--radius is the minimum distance between any two samples (Bridson's and SciPy's convention),\n"
        "not the radius of the disks around them.";
  return os.str();
}

}  // namespace pds::cli
