#include "analysis_common.h"

#include <charconv>
#include <fstream>

#include "pds/analysis/relative_radius.h"
#include "pds/error.h"

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

std::vector<PointCloud> generate_sets(const std::string& method, GenerateRequest request, std::size_t sets) {
  const Method& m = find_method(method);
  if (request.count && !request.radius && !m.takes_count && m.takes_radius) {
    double volume = 1.0;
    visit_dim(request.dim, [&](auto d) {
      volume = request.domain<decltype(d)::value>().volume();
      return 0;
    });
    request.radius = 2.0 * 0.75 * max_packing_radius(volume, *request.count, request.dim);
    request.count.reset();
  }
  std::vector<PointCloud> out;
  const std::uint64_t first = request.seed;
  for (std::size_t s = 0; s < sets; ++s) {
    request.seed = first + s;
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
