#include "pds/io/point_file.h"

#include <unistd.h>

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <regex>
#include <sstream>
#include <system_error>
#include <vector>

#include "pds/error.h"

namespace pds {
namespace {

static_assert(std::endian::native == std::endian::little, "the NPY writer assumes a little-endian host");

std::string extension_of(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

[[noreturn]] void bad_file(const std::string& name, const std::string& what) {
  throw InvalidArgument(name + ": " + what);
}

void check_dim(int dim, const std::string& where) {
  if (dim < 1 || dim > kMaxCloudDim)
    throw InvalidArgument(where + ": " + std::to_string(dim) + " coordinates per point; supported: 1 to " +
                          std::to_string(kMaxCloudDim));
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

std::vector<std::string_view> split_fields(std::string_view line) {
  std::vector<std::string_view> fields;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    fields.push_back(
        trim(line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start)));
    if (comma == std::string_view::npos) return fields;
    start = comma + 1;
  }
}

bool parse_double(std::string_view s, double& value) {
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
  return ec == std::errc() && end == s.data() + s.size() && !s.empty();
}

}  // namespace

PointCloud read_csv(std::istream& in, const std::string& name) {
  PointCloud cloud{0, {}};
  std::string line;
  std::size_t line_no = 0;
  bool seen_first = false;
  while (std::getline(in, line)) {
    ++line_no;
    const std::string_view text = trim(line);
    if (text.empty() || text.front() == '#') continue;
    const auto fields = split_fields(text);
    const std::string where = name + ":" + std::to_string(line_no);
    if (!seen_first) {
      seen_first = true;
      cloud.dim = static_cast<int>(fields.size());
      check_dim(cloud.dim, where);
      double unused;
      if (!parse_double(fields[0], unused)) {
        // A header: names, not numbers.
        for (auto f : fields)
          if (f.empty() || parse_double(f, unused))
            bad_file(where, "malformed header '" + std::string(text) + "' (expected names such as x,y)");
        continue;
      }
    }
    if (static_cast<int>(fields.size()) != cloud.dim)
      bad_file(where, "expected " + std::to_string(cloud.dim) + " values, found " + std::to_string(fields.size()));
    for (auto f : fields) {
      double v;
      if (!parse_double(f, v)) bad_file(where, "'" + std::string(f) + "' is not a number");
      if (!std::isfinite(v)) bad_file(where, "non-finite value '" + std::string(f) + "'");
      cloud.coords.push_back(v);
    }
  }
  if (in.bad()) throw Failure(name + ": read error");
  if (!seen_first) bad_file(name, "empty file (expected a header such as x,y and one point a line)");
  return cloud;
}

std::vector<Column> coordinate_columns(int dim) {
  static const char* names[] = {"x", "y", "z", "w"};
  std::vector<Column> columns;
  for (int k = 0; k < dim; ++k) {
    // Appended, not "x" + to_string: g++ 12 warns falsely (-Wrestrict) on the operator's inlined copy.
    std::string name = k < 4 ? names[k] : "x";
    if (k >= 4) name += std::to_string(k);
    columns.push_back({name});
  }
  return columns;
}

void write_csv(std::ostream& out, const PointCloud& points) { write_csv(out, points, coordinate_columns(points.dim)); }

void write_csv(std::ostream& out, const PointCloud& table, const std::vector<Column>& columns) {
  for (std::size_t k = 0; k < columns.size(); ++k) out << (k ? "," : "") << columns[k].name;
  out << '\n';
  char buffer[32];
  std::string line;
  for (std::size_t i = 0; i < table.size(); ++i) {
    line.clear();
    for (int k = 0; k < table.dim; ++k) {
      if (k) line += ',';
      const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, table.point(i)[k]);
      line.append(buffer, end);
    }
    line += '\n';
    out << line;
  }
}

void write_ply(std::ostream& out, const PointCloud& table, const std::vector<Column>& columns) {
  out << "ply\nformat binary_little_endian 1.0\ncomment written by pds\nelement vertex " << table.size() << '\n';
  for (const Column& c : columns) out << "property " << (c.integer ? "int " : "double ") << c.name << '\n';
  out << "end_header\n";
  std::string row;
  for (std::size_t i = 0; i < table.size(); ++i) {
    row.clear();
    for (int k = 0; k < table.dim; ++k) {
      const double v = table.point(i)[k];
      if (columns[static_cast<std::size_t>(k)].integer) {
        const auto n = static_cast<std::int32_t>(v);
        row.append(reinterpret_cast<const char*>(&n), sizeof n);
      } else {
        row.append(reinterpret_cast<const char*>(&v), sizeof v);
      }
    }
    out.write(row.data(), static_cast<std::streamsize>(row.size()));
  }
}

namespace {

constexpr char kNpyMagic[] = "\x93NUMPY";

// Pulls `key`'s value out of the header dictionary, e.g. 'descr': '<f8'.
std::string header_value(const std::string& header, const std::string& key, const std::string& name) {
  const std::regex pattern("['\"]" + key + "['\"]\\s*:\\s*('[^']*'|\"[^\"]*\"|True|False|\\([^)]*\\))");
  std::smatch m;
  if (!std::regex_search(header, m, pattern)) bad_file(name, "NPY header has no '" + key + "'");
  return m[1];
}

}  // namespace

PointCloud read_npy(std::istream& in, const std::string& name) {
  char magic[8];
  if (!in.read(magic, 8) || std::memcmp(magic, kNpyMagic, 6) != 0) bad_file(name, "not an NPY file (bad magic)");
  const int major = static_cast<unsigned char>(magic[6]);
  std::uint32_t header_len = 0;
  if (major == 1) {
    unsigned char b[2];
    if (!in.read(reinterpret_cast<char*>(b), 2)) bad_file(name, "truncated NPY header");
    header_len = b[0] | (b[1] << 8);
  } else if (major == 2 || major == 3) {
    unsigned char b[4];
    if (!in.read(reinterpret_cast<char*>(b), 4)) bad_file(name, "truncated NPY header");
    header_len = b[0] | (b[1] << 8) | (b[2] << 16) | (static_cast<std::uint32_t>(b[3]) << 24);
  } else {
    bad_file(name, "unsupported NPY version " + std::to_string(major));
  }
  if (header_len > (1u << 20)) bad_file(name, "NPY header too long");
  std::string header(header_len, '\0');
  if (!in.read(header.data(), header_len)) bad_file(name, "truncated NPY header");

  std::string descr = header_value(header, "descr", name);
  descr = descr.substr(1, descr.size() - 2);
  const bool fortran = header_value(header, "fortran_order", name) == "True";
  const std::string shape = header_value(header, "shape", name);

  std::size_t item = 0;
  bool swap = false;
  if (descr == "<f8" || descr == ">f8") {
    item = 8;
  } else if (descr == "<f4" || descr == ">f4") {
    item = 4;
  } else {
    bad_file(name, "NPY dtype '" + descr + "' is not supported (float32 '<f4' or float64 '<f8')");
  }
  swap = descr[0] == '>';

  std::vector<std::uint64_t> dims;
  {
    const std::regex number("[0-9]+");
    for (auto it = std::sregex_iterator(shape.begin(), shape.end(), number); it != std::sregex_iterator(); ++it) {
      // More digits than 64 bits hold (stoull would throw out_of_range): too large.
      if (it->str().size() > 19) bad_file(name, "NPY shape " + shape + " is too large");
      dims.push_back(std::stoull(it->str()));
    }
  }
  if (dims.size() != 2) bad_file(name, "NPY shape " + shape + " is not (N, D)");
  const std::uint64_t n = dims[0];
  const int dim = dims[1] > static_cast<std::uint64_t>(kMaxCloudDim) ? 0 : static_cast<int>(dims[1]);
  check_dim(dim, name);
  if (n > std::numeric_limits<std::uint64_t>::max() / (item * dim) || n * item * dim > (std::uint64_t{1} << 40))
    bad_file(name, "NPY shape " + shape + " is too large");

  // Check the payload size before allocating for it.
  const auto here = in.tellg();
  if (here >= 0) {
    in.seekg(0, std::ios::end);
    const auto end = in.tellg();
    in.seekg(here);
    if (end - here < static_cast<std::streamoff>(n * item * dim))
      bad_file(name, "truncated NPY data: shape " + shape + " needs " + std::to_string(n * item * dim) +
                         " bytes, file has " + std::to_string(end - here));
  }
  std::vector<unsigned char> raw(n * item * dim);
  if (!in.read(reinterpret_cast<char*>(raw.data()), static_cast<std::streamsize>(raw.size())))
    bad_file(name, "truncated NPY data");

  PointCloud cloud{dim, std::vector<double>(n * dim)};
  for (std::uint64_t i = 0; i < n; ++i)
    for (int k = 0; k < dim; ++k) {
      // Element (i, k) sits at i*dim + k in C order and at k*n + i in Fortran order.
      const std::uint64_t at = fortran ? k * n + i : i * dim + k;
      unsigned char bytes[8];
      std::memcpy(bytes, raw.data() + at * item, item);
      if (swap) std::reverse(bytes, bytes + item);
      double v;
      if (item == 8) {
        std::memcpy(&v, bytes, 8);
      } else {
        float f;
        std::memcpy(&f, bytes, 4);
        v = f;
      }
      if (!std::isfinite(v))
        bad_file(name, "non-finite value in row " + std::to_string(i) + ", column " + std::to_string(k));
      cloud.coords[i * dim + k] = v;
    }
  return cloud;
}

void write_npy(std::ostream& out, const PointCloud& points, NpyType type) {
  const bool f32 = type == NpyType::Float32;
  std::string header = std::string("{'descr': '") + (f32 ? "<f4" : "<f8") + "', 'fortran_order': False, 'shape': (" +
                       std::to_string(points.size()) + ", " + std::to_string(points.dim) + "), }";
  // Pad with spaces and a newline so the data starts on a 64-byte boundary.
  const std::size_t preamble = 10;
  const std::size_t total = (preamble + header.size() + 1 + 63) / 64 * 64;
  header.append(total - preamble - header.size() - 1, ' ');
  header += '\n';
  out.write(kNpyMagic, 6);
  out.put('\x01');
  out.put('\x00');
  out.put(static_cast<char>(header.size() & 0xff));
  out.put(static_cast<char>(header.size() >> 8));
  out << header;
  if (f32) {
    std::vector<float> data(points.coords.begin(), points.coords.end());
    out.write(reinterpret_cast<const char*>(data.data()), static_cast<std::streamsize>(data.size() * sizeof(float)));
  } else {
    out.write(reinterpret_cast<const char*>(points.coords.data()),
              static_cast<std::streamsize>(points.coords.size() * sizeof(double)));
  }
}

PointCloud read_points(const std::string& path) {
  if (path == "-") return read_csv(std::cin, "<stdin>");
  const std::string ext = extension_of(path);
  if (ext != ".csv" && ext != ".npy")
    throw InvalidArgument(path + ": unknown point file extension '" + ext + "' (use .csv or .npy)");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InvalidArgument(path + ": cannot open: " + std::strerror(errno));
  return ext == ".csv" ? read_csv(in, path) : read_npy(in, path);
}

std::string temporary_path(const std::string& path) { return path + ".tmp." + std::to_string(::getpid()); }

void write_points(const std::string& path, const PointCloud& points, NpyType npy_type) {
  write_table(path, points, coordinate_columns(points.dim), npy_type);
}

void write_table(const std::string& path, const PointCloud& table, const std::vector<Column>& columns,
                 NpyType npy_type) {
  if (columns.size() != static_cast<std::size_t>(table.dim))
    throw InvalidArgument(path + ": " + std::to_string(columns.size()) + " column names for " +
                          std::to_string(table.dim) + " columns");
  for (std::size_t k = 0; k < columns.size(); ++k)
    if (columns[k].integer)
      for (std::size_t i = 0; i < table.size(); ++i) {
        const double v = table.point(i)[k];
        if (!(v == std::floor(v) && v >= -2147483648.0 && v < 2147483648.0))
          throw InvalidArgument(path + ": column " + columns[k].name + " holds " + std::to_string(v) +
                                ", not a 32-bit integer");
      }
  if (path == "-") {
    write_csv(std::cout, table, columns);
    std::cout.flush();
    if (!std::cout) throw Failure("<stdout>: write error");
    return;
  }
  const std::string ext = extension_of(path);
  if (ext != ".csv" && ext != ".npy" && ext != ".ply")
    throw InvalidArgument(path + ": unknown point file extension '" + ext + "' (use .csv, .npy or .ply)");
  const std::string temp = temporary_path(path);
  {
    std::ofstream out(temp, std::ios::binary | std::ios::trunc);
    if (!out) throw Failure(path + ": cannot write: " + std::strerror(errno));
    if (ext == ".csv")
      write_csv(out, table, columns);
    else if (ext == ".ply")
      write_ply(out, table, columns);
    else
      write_npy(out, table, npy_type);
    out.flush();
    if (!out) {
      std::remove(temp.c_str());
      throw Failure(path + ": write error");
    }
  }
  std::error_code ec;
  std::filesystem::rename(temp, path, ec);
  if (ec) {
    std::remove(temp.c_str());
    throw Failure(path + ": cannot write: " + ec.message());
  }
}

}  // namespace pds
