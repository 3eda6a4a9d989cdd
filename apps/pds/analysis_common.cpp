#include "analysis_common.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>

#include "pds/error.h"
#include "terminal.h"

namespace pds::cli {

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

void add_generation_options(CLI::App& command, GenerationOptions& o, const GenerationOptionSet& set) {
  const auto help = [&](const std::string& text) { return set.scope.empty() ? text : text + " (" + set.scope + ")"; };
  if (set.default_count) o.count = set.default_count;
  o.count_option = command.add_option("--count,-n", o.count, help("Number of points (per set)"));
  if (set.default_count) o.count_option->capture_default_str();
  o.added = {o.count_option};
  if (set.radius) {
    o.radius_option = command.add_option("--radius,-r", o.radius, help("Minimum distance between any two samples"));
    o.added.push_back(o.radius_option);
  }
  if (set.dim)
    o.added.push_back(
        command.add_option("--dim,-d", o.domain.dim, help("Dimension (the range each method takes: pds methods)"))
            ->capture_default_str());
  if (set.domain) add_domain_options(command, o.domain, false);
  o.added.push_back(
      command
          .add_option("--seed,-s", o.seed, help("Random seed (of the first set); the same seed gives the same bytes"))
          ->capture_default_str());
  o.added.push_back(command.add_option("--threads,-t", o.threads, help("Threads for parallel methods (0: all cores)"))
                        ->capture_default_str());
  o.added.push_back(
      command.add_option("--max-points", o.max_points, help("Refuse requests that could produce more points"))
          ->capture_default_str());
  o.added.push_back(command.add_option(
      "--max-memory", o.max_memory, help("Refuse requests whose estimated peak memory exceeds this (e.g. 512M, 2G)")));
  // Not in `added`: it applies to any run, not only to generation.
  command.add_flag("--quiet,-q", o.quiet, help("No progress bar on the terminal"));
  o.added.push_back(command.add_option("--param,-P", o.params, help("Method parameter NAME=VALUE (repeatable)")));
}

GenerateRequest generation_request(const GenerationOptions& o, const GenerationOptionSet& set) {
  GenerateRequest request;
  request.dim = o.domain.dim;
  request.torus = o.domain.torus;
  split_bounds(o.domain, request.dim, request.lo, request.hi);
  if (o.count_option && o.count_option->count())
    request.count = o.count;
  else if (set.default_count)
    request.count = set.default_count;
  if (o.radius_option && o.radius_option->count()) request.radius = o.radius;
  request.seed = o.seed;
  request.threads = o.threads;
  request.max_points = o.max_points;
  if (!o.max_memory.empty()) request.max_memory = parse_size(o.max_memory, "--max-memory");
  request.params = parse_params(o.params);
  return request;
}

bool any_generation_option_given(const GenerationOptions& o) {
  for (const CLI::Option* option : o.added)
    if (option->count()) return true;
  return false;
}

double parse_size(const std::string& text, const std::string& option) {
  double value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  std::string unit(end, text.data() + text.size());
  if (unit == "B") unit.clear();
  if (unit.size() == 3 && unit.substr(1) == "iB") unit.resize(1);
  static const std::string kUnits = "KMGT";
  const auto power = unit.empty() ? 0 : kUnits.find(static_cast<char>(std::toupper(unit[0])));
  if (ec != std::errc() || unit.size() > 1 || power == std::string::npos || !(value >= 0) || !std::isfinite(value))
    throw InvalidArgument(option + " expects a size such as 512M or 2G, got '" + text + "'");
  return std::ldexp(value, 10 * static_cast<int>(unit.empty() ? 0 : power + 1));
}

PointCloud generate_with_progress(const std::string& method, GenerateRequest request, bool quiet) {
  const ProgressBar bar(method, quiet);
  request.progress = bar.progress();
  return generate(method, request);
}

void write_output(const std::string& path, const PointCloud& points, NpyType npy_type) {
  write_output(path, points, coordinate_columns(points.dim), npy_type);
}

void write_output(const std::string& path, const PointCloud& table, const std::vector<Column>& columns,
                  NpyType npy_type) {
  if (path != "-") interrupt_removes(temporary_path(path));
  write_table(path, table, columns, npy_type);
  interrupt_removes("");
}

std::vector<PointCloud> generate_sets(const std::string& method, GenerateRequest request, std::size_t sets,
                                      const Progress& progress) {
  request = size_request(find_method(method), std::move(request));
  std::vector<PointCloud> out;
  const std::uint64_t first = request.seed;
  for (std::size_t s = 0; s < sets; ++s) {
    request.seed = first + s;
    request.progress = part_of(progress, s, sets);
    out.push_back(generate(method, request));
  }
  return out;
}

void write_csv_columns(const std::string& path, const std::vector<std::string>& names,
                       const std::vector<const std::vector<double>*>& columns) {
  std::ofstream out(path);
  if (!out) throw Failure("cannot write '" + path + "'");
  for (std::size_t c = 0; c < names.size(); ++c) out << (c ? "," : "") << names[c];
  out << '\n';
  const std::size_t rows = columns.empty() ? 0 : columns[0]->size();
  char buf[64];
  for (std::size_t r = 0; r < rows; ++r) {
    for (std::size_t c = 0; c < columns.size(); ++c) {
      const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, (*columns[c])[r]);
      out << (c ? "," : "") << std::string_view(buf, end - buf);
    }
    out << '\n';
  }
  out.flush();
  if (!out) throw Failure("cannot write '" + path + "'");
}

}  // namespace pds::cli
