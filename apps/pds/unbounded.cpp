// pds unbounded / pds chunks: samples of the unbounded, chunk-invariant field
// (pds/samplers/unbounded.h, docs/unbounded.md) in one region, or in a grid
// of chunks written one NPY file each plus a JSON manifest.

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "unbounded.h"

#include "analysis_common.h"
#include "commands.h"
#include "pds/detail/format.h"
#include "pds/error.h"
#include "pds/io/point_file.h"
#include "pds/limits.h"
#include "pds/parallel.h"
#include "pds/point.h"
#include "pds/samplers/unbounded.h"

namespace pds::cli {
namespace {

struct UnboundedOptions {
  double radius = 0.0;
  std::uint64_t seed = 0;
  std::vector<double> region;  // x0,y0[,z0],x1,y1[,z1]
  std::vector<double> torus;   // the same, when the field lives on a torus
  std::string torus_option = "--torus";  // where the torus came from, for messages
  double darts_per_cell = UnboundedParams{}.darts_per_cell;
  std::uint64_t max_points = kDefaultMaxPoints;
  double chunk = 0.0;  // pds chunks only
  int threads = 0;     // pds chunks only
  std::string output;
};

void add_field_options(CLI::App& cmd, UnboundedOptions& o) {
  cmd.add_option("--radius,-r", o.radius, "Minimum distance between any two samples")->required();
  cmd.add_option("--seed,-s", o.seed, "Seed of the field: the same seed gives the same set everywhere")
      ->capture_default_str();
  cmd.add_option("--region", o.region, "Box as lo then hi corners, x0,y0,x1,y1 (2D) or x0,y0,z0,x1,y1,z1 (3D)")
      ->delimiter(',')
      ->required();
  cmd.add_option("--torus", o.torus,
                 "The field on this torus (lo then hi corners, as --region) instead of the whole plane; "
                 "--region must lie inside it")
      ->delimiter(',');
  cmd.add_option("--darts-per-cell", o.darts_per_cell,
                 "Expected darts a cell of edge r/sqrt(D) before open cells are refined: only the work depends on it "
                 "(docs/unbounded.md)")
      ->capture_default_str();
  cmd.add_option("--max-points", o.max_points, "Refuse regions that could hold more points")->capture_default_str();
}

int region_dim(const UnboundedOptions& o) {
  if (o.region.size() != 4 && o.region.size() != 6)
    throw InvalidArgument("--region needs 4 values (2D) or 6 (3D): lo corner then hi corner, got " +
                          std::to_string(o.region.size()));
  return static_cast<int>(o.region.size() / 2);
}

/// Runs f2 or f3 for the dimension --region gives.
void by_dim(const UnboundedOptions& o, void (*f2)(const UnboundedOptions&), void (*f3)(const UnboundedOptions&)) {
  (region_dim(o) == 2 ? f2 : f3)(o);
}

template <int D>
Domain<D> box_of(const std::vector<double>& values, const std::string& option) {
  if (values.size() != 2 * D)
    throw InvalidArgument(option + " needs " + std::to_string(2 * D) + " values for dimension " + std::to_string(D) +
                          " (as --region), got " + std::to_string(values.size()));
  Domain<D> box;
  for (int a = 0; a < D; ++a) {
    box.lo[a] = values[static_cast<std::size_t>(a)];
    box.hi[a] = values[static_cast<std::size_t>(a + D)];
    validate_axis(a, box.lo[a], box.hi[a]);
  }
  return box;
}

template <int D>
Domain<D> region_of(const UnboundedOptions& o) {
  return box_of<D>(o.region, "--region");
}

template <int D>
UnboundedField<D> field_of(const UnboundedOptions& o) {
  const UnboundedParams params{.radius = o.radius, .darts_per_cell = o.darts_per_cell, .max_points = o.max_points};
  if (o.torus.empty()) return UnboundedField<D>(params, o.seed);
  Domain<D> torus = box_of<D>(o.torus, o.torus_option);
  torus.periodic = true;
  return UnboundedField<D>(params, o.seed, torus);
}

nlohmann::ordered_json stats_json(const UnboundedStats& s) {
  nlohmann::ordered_json j;
  j["cells_touched"] = s.cells_touched;
  j["darts_settled"] = s.darts_settled;
  j["max_depth"] = s.max_depth;
  j["max_level"] = s.max_level;
  j["margin_cells"] = s.margin_cells;
  return j;
}

template <int D>
void run_unbounded(const UnboundedOptions& o) {
  UnboundedStats stats;
  const PointSet<D> points = field_of<D>(o).sample(region_of<D>(o), &stats);
  write_output(o.output, PointCloud::from(points));
  if (o.output == "-") return;
  nlohmann::ordered_json out;
  out["file"] = o.output;
  out["count"] = points.size();
  out["stats"] = stats_json(stats);
  std::cout << out.dump(2) << std::endl;
}

/// Chunk k of `n` along an axis: cut points from the index alone, so that
/// neighbouring chunks share their seam exactly.
double cut(double lo, double hi, double size, std::int64_t k, std::int64_t n) {
  return k >= n ? hi : lo + size * static_cast<double>(k);
}

template <int D>
void run_chunks(const UnboundedOptions& o, const ChunkTeam& team) {
  const UnboundedField<D> field = field_of<D>(o);
  const Domain<D> region = region_of<D>(o);
  if (!(std::isfinite(o.chunk) && o.chunk > 0.0))
    throw InvalidArgument("--chunk: " + detail::format_number(o.chunk) + " is not a positive finite size");
  std::array<std::int64_t, D> n{};
  double total = 1.0;
  for (int a = 0; a < D; ++a) {
    const double count = std::ceil(region.extent(a) / o.chunk);
    total *= count;
    if (!(total <= 1e6))
      throw InvalidArgument("--chunk: " + detail::format_number(o.chunk) + " cuts the region into more than 10^6 chunks");
    n[a] = static_cast<std::int64_t>(count);
    // A last chunk that rounding leaves empty is not made.
    if (n[a] > 1 && !(cut(region.lo[a], region.hi[a], o.chunk, n[a] - 1, n[a]) < region.hi[a])) --n[a];
  }
  // The whole region's budget is checked once, before any file is written.
  require_point_budget(packing_count(region.volume(), o.radius, D), D, o.max_points,
                       "radius " + detail::format_number(o.radius) + " over a region of volume " +
                           detail::format_number(region.volume()),
                       1.0);
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::create_directories(o.output, ec);
  if (!fs::is_directory(o.output)) throw Failure("cannot create the directory " + o.output);

  nlohmann::ordered_json manifest;
  manifest["format"] = "pds-chunks";
  manifest["version"] = 1;
  manifest["method"] = "unbounded";
  manifest["dim"] = D;
  manifest["radius"] = o.radius;
  manifest["seed"] = o.seed;
  manifest["darts_per_cell"] = o.darts_per_cell;
  manifest["region"] = {{"lo", std::vector<double>(region.lo.begin(), region.lo.end())},
                        {"hi", std::vector<double>(region.hi.begin(), region.hi.end())}};
  if (o.torus.empty()) {
    manifest["torus"] = nullptr;
  } else {
    const Domain<D> torus = box_of<D>(o.torus, o.torus_option);
    manifest["torus"] = {{"lo", std::vector<double>(torus.lo.begin(), torus.lo.end())},
                         {"hi", std::vector<double>(torus.hi.begin(), torus.hi.end())}};
  }
  manifest["chunk"] = o.chunk;
  manifest["order"] = "each file: lexicographic in the coordinates; chunk [lo, hi) half-open";
  // The chunks in index order (the first axis fastest), then sampled and
  // written on up to --threads threads, each chunk to its own file.
  std::vector<Domain<D>> parts;
  std::vector<std::array<std::int64_t, D>> indices;
  std::array<std::int64_t, D> i{};
  while (true) {
    Domain<D> part;
    for (int a = 0; a < D; ++a) {
      part.lo[a] = cut(region.lo[a], region.hi[a], o.chunk, i[a], n[a]);
      part.hi[a] = cut(region.lo[a], region.hi[a], o.chunk, i[a] + 1, n[a]);
    }
    parts.push_back(part);
    indices.push_back(i);
    int a = 0;
    while (a < D && i[a] == n[a] - 1) i[a++] = 0;
    if (a == D) break;
    ++i[a];
  }
  const auto name_of = [](const std::array<std::int64_t, D>& index) {
    std::string name = "chunk";
    for (std::int64_t k : index) {
      name += '_';
      name += std::to_string(k);
    }
    return name + ".npy";
  };
  // This process's chunks (k mod size), sampled and written on its threads.
  // Each chunk's count and stats go into a table that every process fills
  // for its own chunks and leaves zero elsewhere, so that the elementwise
  // maximum over the processes is the whole table; its last entry says
  // whether any process failed. Every process reaches max_all once, also
  // after a failure, so that none waits for ever.
  constexpr std::size_t kFields = 4;  // count, margin, depth, level
  std::vector<std::size_t> mine;
  for (std::size_t k = static_cast<std::size_t>(team.rank); k < parts.size(); k += static_cast<std::size_t>(team.size))
    mine.push_back(k);
  std::vector<std::int64_t> table(parts.size() * kFields + 1, 0);
  std::string error;
  try {
    parallel_for(0, mine.size(), 1, o.threads, [&](std::size_t begin, std::size_t end) {
      for (std::size_t q = begin; q < end; ++q) {
        const std::size_t k = mine[q];
        UnboundedStats stats;
        const PointSet<D> points = field.sample(parts[k], &stats);
        write_points((fs::path(o.output) / name_of(indices[k])).string(), PointCloud::from(points));
        table[k * kFields] = static_cast<std::int64_t>(points.size());
        table[k * kFields + 1] = stats.margin_cells;
        table[k * kFields + 2] = stats.max_depth;
        table[k * kFields + 3] = stats.max_level;
      }
    });
  } catch (const std::exception& e) {
    error = e.what();
    table.back() = 1;
  }
  team.max_all(table);
  if (!error.empty()) throw Failure(error);
  if (table.back() != 0) throw Failure("another process failed to write its chunks; no manifest written");
  if (team.rank != 0) return;
  std::uint64_t count = 0;
  std::int64_t max_margin = 0, max_depth = 0, max_level = 0;
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (std::size_t k = 0; k < parts.size(); ++k) {
    max_margin = std::max(max_margin, table[k * kFields + 1]);
    max_depth = std::max(max_depth, table[k * kFields + 2]);
    max_level = std::max(max_level, table[k * kFields + 3]);
    count += static_cast<std::uint64_t>(table[k * kFields]);
    nlohmann::ordered_json entry;
    entry["file"] = name_of(indices[k]);
    entry["index"] = std::vector<std::int64_t>(indices[k].begin(), indices[k].end());
    entry["lo"] = std::vector<double>(parts[k].lo.begin(), parts[k].lo.end());
    entry["hi"] = std::vector<double>(parts[k].hi.begin(), parts[k].hi.end());
    entry["count"] = table[k * kFields];
    list.push_back(entry);
  }
  manifest["count"] = count;
  manifest["max_margin_cells"] = max_margin;
  manifest["max_depth"] = max_depth;
  manifest["max_level"] = max_level;
  manifest["chunks"] = list;
  const std::string path = (fs::path(o.output) / "manifest.json").string();
  std::ofstream file(path);
  file << manifest.dump(2) << '\n';
  if (!file.flush()) throw Failure("cannot write " + path);
  nlohmann::ordered_json out;
  out["manifest"] = path;
  out["chunks"] = list.size();
  out["count"] = count;
  std::cout << out.dump(2) << std::endl;
}

template <int D>
void write_field_samples(const UnboundedOptions& o) {
  write_output(o.output, PointCloud::from(field_of<D>(o).sample(region_of<D>(o))));
}

}  // namespace

void add_unbounded_generate_options(CLI::App& command, UnboundedGenerateOptions& o) {
  command.add_flag("--unbounded", o.unbounded,
                   "The samples inside --region of the unbounded field of --seed, one maximal Poisson disk set on the "
                   "whole plane or space (ebeida, maximal-darts, dart-throwing; docs/unbounded.md); with --torus the "
                   "field lives on the torus --bounds");
  command
      .add_option("--region", o.region,
                  "With --unbounded: the box to sample, lo then hi corners (x0,y0,x1,y1 or x0,y0,z0,x1,y1,z1)")
      ->delimiter(',');
}

void generate_unbounded(const CLI::App& command, const std::string& method, const UnboundedGenerateOptions& options,
                        const GenerationOptions& generation, const std::string& output) {
  if (!options.unbounded) throw InvalidArgument("--region needs --unbounded (a box of the unbounded field)");
  // The field is maximal dart throwing: the process these methods sample in a
  // bounded domain (dart-throwing until darts keep missing, nearly).
  if (method != "ebeida" && method != "maximal-darts" && method != "dart-throwing")
    throw InvalidArgument("--unbounded is taken by ebeida, maximal-darts and dart-throwing (the field is maximal dart "
                          "throwing, their process), not " + method);
  refuse_options(command, {"--threads"}, "--unbounded (pds chunks -t samples a region on several threads)");
  refuse_options(command,
                 {"--count", "--density", "--radius-range", "--invert", "--mask", "--polygons", "--fixed", "--mesh",
                  "--vertex-density", "--classes", "--class-matrix", "--dtype", "--max-memory", "--param"},
                 "--unbounded (the field takes --radius, --seed, --region, --max-points, and --torus with --bounds)");
  if (!(generation.radius_option && generation.radius_option->count()))
    throw InvalidArgument("--unbounded needs --radius (the field's minimum distance)");
  UnboundedOptions o;
  o.radius = generation.radius;
  o.seed = generation.seed;
  o.region = options.region;
  o.max_points = generation.max_points;
  o.output = output;
  if (o.region.empty()) throw InvalidArgument("--unbounded needs --region (the box to sample)");
  const int dim = region_dim(o);
  if (const CLI::Option* d = command.get_option_no_throw("--dim"); d && d->count() && generation.domain.dim != dim)
    throw InvalidArgument("--dim " + std::to_string(generation.domain.dim) + " does not match --region, which has " +
                          std::to_string(o.region.size()) + " values (dimension " + std::to_string(dim) + ")");
  if (generation.domain.torus) {
    if (generation.domain.bounds.empty())
      throw InvalidArgument("--unbounded --torus needs --bounds: the torus the field lives on");
    o.torus = generation.domain.bounds;
    o.torus_option = "--bounds (the torus of --unbounded)";
  } else if (!generation.domain.bounds.empty()) {
    throw InvalidArgument("--bounds with --unbounded is the torus of a periodic field and needs --torus; the box to "
                          "sample is --region");
  }
  by_dim(o, write_field_samples<2>, write_field_samples<3>);
}

void add_unbounded(CLI::App& app) {
  auto opt = std::make_shared<UnboundedOptions>();
  CLI::App* cmd = app.add_subcommand(
      "unbounded", "Samples of the unbounded Poisson disk field of a seed inside a region (docs/unbounded.md)");
  add_field_options(*cmd, *opt);
  cmd->add_option("--output,-o", opt->output, "Output file (.npy or .csv); '-' for CSV on stdout")->required();
  cmd->callback([opt] { by_dim(*opt, run_unbounded<2>, run_unbounded<3>); });

  add_chunks(app, ChunkTeam{});
}

void add_chunks(CLI::App& app, const ChunkTeam& team) {
  auto chunks = std::make_shared<UnboundedOptions>();
  CLI::App* ccmd = app.add_subcommand(
      "chunks", "The unbounded field over a region in chunks: one NPY per chunk and manifest.json in a directory");
  add_field_options(*ccmd, *chunks);
  ccmd->add_option("--chunk", chunks->chunk, "Chunk edge (the last chunk along an axis is clipped)")->required();
  ccmd->add_option("--output,-o", chunks->output, "Output directory")->required();
  ccmd->add_option("--threads,-t", chunks->threads, "Threads sampling chunks (0: all cores); the files do not depend on it")
      ->capture_default_str();
  ccmd->callback([chunks, team] {
    if (region_dim(*chunks) == 2)
      run_chunks<2>(*chunks, team);
    else
      run_chunks<3>(*chunks, team);
  });
}

}  // namespace pds::cli
