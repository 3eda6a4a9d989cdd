// pds generate dart-throwing --classes R1,R2,... [--class-matrix ...]: Wei's
// multi-class hard-disk dart throwing (docs/density.md, "Several classes").

#include "classes.h"

#include "pds/error.h"
#include "pds/io/point_file.h"
#include "pds/registry.h"
#include "pds/samplers/multi_class.h"

namespace pds::cli {

void add_class_options(CLI::App& command, ClassOptions& o) {
  command
      .add_option("--classes", o.radii,
                  "Several classes (dart-throwing only): the minimum distance within each, e.g. 0.02,0.04,0.08; "
                  "adds a class column")
      ->delimiter(',');
  command
      .add_option("--class-matrix", o.matrix,
                  "With --classes: the k x k cross-class distances, row by row (symmetric, the diagonal the radii); "
                  "default: Wei's rule")
      ->delimiter(',');
}

void generate_classes(const CLI::App& command, const std::string& method, const ClassOptions& o,
                      const GenerationOptions& generation, const std::string& output) {
  if (method != "dart-throwing")
    throw InvalidArgument("--classes is taken by dart-throwing only (Wei's multi-class dart throwing), not " + method);
  refuse_options(command,
                 {"--count", "--radius", "--density", "--radius-range", "--invert", "--mask", "--polygons", "--fixed",
                  "--mesh", "--vertex-density", "--dtype", "--max-memory"},
                 "--classes (the class radii size the set)");
  const std::map<std::string, double> params = parse_params(generation.params);
  for (const auto& entry : params)
    if (entry.first != "failures")
      throw InvalidArgument("--classes takes --param failures= only, not '" + entry.first + "'");
  validate_params(find_method(method), params);
  GenerateRequest request = generation_request(generation);
  request.params.clear();  // failures is the classes' own setting, read above
  MultiClassParams mc;
  mc.radii = o.radii;
  mc.matrix = o.matrix;
  if (const auto it = params.find("failures"); it != params.end())
    mc.max_failures = static_cast<std::uint64_t>(it->second);
  const ClassCloud set = pds::generate_classes(mc, request);
  const int dim = set.points.dim;
  PointCloud table{dim + 1, {}};
  table.coords.reserve(set.classes.size() * static_cast<std::size_t>(dim + 1));
  for (std::size_t i = 0; i < set.classes.size(); ++i) {
    const double* p = set.points.coords.data() + i * static_cast<std::size_t>(dim);
    table.coords.insert(table.coords.end(), p, p + dim);
    table.coords.push_back(set.classes[i]);
  }
  std::vector<Column> columns = coordinate_columns(request.dim);
  columns.push_back({"class", true});
  write_output(output, table, columns);
}

}  // namespace pds::cli
