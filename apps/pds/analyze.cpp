// pds analyze FILE ...: measure a point set and print one JSON object.

#include <cmath>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "commands.h"
#include "pds/analysis/distance.h"
#include "pds/analysis/maximality.h"
#include "pds/analysis/relative_radius.h"
#include "pds/error.h"
#include "pds/io/point_file.h"
#include "pds/registry.h"

namespace pds::cli {
namespace {

using Json = nlohmann::ordered_json;

struct AnalyzeOptions {
  std::string file;
  DomainOptions domain;
  double radius = 0;
};

Json number_or_null(double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); }

template <int D>
Json analyze(const PointSet<D>& points, const Domain<D>& domain, std::optional<double> radius) {
  for (std::size_t i = 0; i < points.size(); ++i)
    if (!domain.contains(points[i])) {
      std::ostringstream os;
      os << "point " << i << " " << points[i] << " lies outside the domain " << domain
         << " (give --bounds to match the file)";
      throw InvalidArgument(os.str());
    }
  Json out;
  out["count"] = points.size();
  out["dim"] = D;
  out["domain"] = {{"lo", domain.lo}, {"hi", domain.hi}, {"torus", domain.periodic}};
  const NearestNeighbors nn = nearest_neighbors(points, domain);
  MinDistance m;
  double sum = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    sum += nn.distance[i];
    if (nn.distance[i] < m.distance) {
      m.distance = nn.distance[i];
      m.i = std::min<std::size_t>(i, nn.index[i]);
      m.j = std::max<std::size_t>(i, nn.index[i]);
    }
  }
  out["min_distance"] = number_or_null(m.distance);
  if (std::isfinite(m.distance)) out["min_distance_pair"] = {m.i, m.j};
  out["mean_nn_distance"] = number_or_null(points.size() > 1 ? sum / points.size() : NAN);
  out["relative_radius"] = relative_radius(m.distance, domain.volume(), points.size(), D);
  out["max_packing_radius"] = points.empty() ? Json(nullptr) : Json(max_packing_radius(domain.volume(), points.size(), D));
  if (radius) {
    out["radius"] = *radius;
    out["min_distance_holds"] = !(m.distance < *radius);
    const Maximality<D> mx = check_maximality(points, domain, *radius);
    out["maximal"] = mx.maximal;
    Json detail;
    detail["exact"] = mx.tolerance == 0.0;
    detail["tolerance"] = mx.tolerance;
    if (mx.gap) {
      detail["gap"] = *mx.gap;
      detail["gap_distance"] = number_or_null(mx.gap_distance);
    }
    detail["cells_checked"] = mx.cells_checked;
    out["maximality"] = detail;
  }
  return out;
}

}  // namespace

void add_analyze(CLI::App& app) {
  auto opt = std::make_shared<AnalyzeOptions>();
  CLI::App* cmd = app.add_subcommand("analyze", "Measure a point set (CSV or NPY; '-' reads CSV from stdin)");
  cmd->add_option("file", opt->file, "Point file (.csv or .npy), or '-'")->required();
  add_domain_options(*cmd, opt->domain, false);
  auto* radius = cmd->add_option("--radius,-r", opt->radius,
                                 "Minimum distance to check; also reports maximality at this radius");
  cmd->callback([opt, radius] {
    std::optional<double> r;
    if (radius->count()) {
      require_radius(opt->radius);
      r = opt->radius;
    }
    const PointCloud cloud = read_points(opt->file);
    Json out;
    out["file"] = opt->file;
    const Json body = visit_dim(cloud.dim, [&](auto d) {
      constexpr int D = decltype(d)::value;
      GenerateRequest spec;  // reuses the request's bounds handling
      spec.dim = D;
      spec.torus = opt->domain.torus;
      split_bounds(opt->domain, D, spec.lo, spec.hi);
      return analyze<D>(cloud.as<D>(), spec.domain<D>(), r);
    });
    out.update(body);
    std::cout << out.dump(2) << std::endl;
  });
}

}  // namespace pds::cli
