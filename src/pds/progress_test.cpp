#include "pds/progress.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <thread>
#include <vector>

#include "pds/analysis/report.h"
#include "pds/registry.h"
#include "pds/render/render.h"

namespace pds {
namespace {

struct Report {
  double done, total;
};

// A Progress that records every report and never stops the run.
Progress recorder(std::vector<Report>& reports) {
  return {[&reports](double done, double total) {
    reports.push_back({done, total});
    return true;
  }};
}

// The methods that report, each on a request of a fraction of a second.
GenerateRequest request_for(const std::string& method) {
  GenerateRequest r;
  r.torus = true;
  r.seed = 5;
  if (method == "sobol" || method == "halton" || method == "hammersley" || method == "latin-hypercube" ||
      method == "random") {
    r.dim = 20;
    r.count = 50000;
    if (method != "latin-hypercube" && method != "random") r.params["scramble"] = 2;
  } else if (method == "jittered" || method == "multi-jittered" || method == "regular") {
    r.count = 1 << 20;  // 16 reports at one in 65,536 points
  } else if (method == "gbn") {
    r.count = 500;
    r.params["iterations"] = 100;
  } else if (method == "fpo" || method == "best-candidate" || method == "elimination") {
    r.count = method == "fpo" ? 500 : 2000;
  } else {
    r.radius = 0.01;
  }
  return r;
}

class ProgressOfMethod : public ::testing::TestWithParam<std::string> {};

TEST_P(ProgressOfMethod, ReportsMonotoneProgressToTheTotalAndChangesNoByte) {
  GenerateRequest r = request_for(GetParam());
  std::vector<Report> reports;
  r.progress.report = [&](double done, double total) {
    reports.push_back({done, total});
    return true;
  };
  const PointCloud with = generate(GetParam(), r);
  ASSERT_GE(reports.size(), 10u);
  EXPECT_EQ(reports.front().done, 0.0);
  for (std::size_t i = 0; i < reports.size(); ++i) {
    EXPECT_EQ(reports[i].total, reports.front().total);
    EXPECT_LE(reports[i].done, reports[i].total);
    if (i > 0) {
      EXPECT_GE(reports[i].done, reports[i - 1].done) << "report " << i;
    }
  }
  EXPECT_EQ(reports.back().done, reports.back().total);
  EXPECT_LE(reports.size(), 1000u + 1000u);  // throttled to about a thousand
  r.progress = {};
  EXPECT_EQ(generate(GetParam(), r), with);  // progress changes no byte
}

TEST_P(ProgressOfMethod, CancellationStopsTheRun) {
  GenerateRequest r = request_for(GetParam());
  int calls = 0;
  r.progress.report = [&](double, double) { return ++calls < 5; };
  EXPECT_THROW(generate(GetParam(), r), Cancelled);
  EXPECT_EQ(calls, 5);  // nothing reported after the refusal
}

std::vector<std::string> reporting_methods() {
  std::vector<std::string> out = {"best-candidate", "bridson", "dart-throwing", "elimination", "ebeida",
                                  "maximal-darts",  "wei",     "dunbar-humphreys", "gbn",        "sobol",
                                  "halton",         "hammersley", "latin-hypercube", "random", "jittered",
                                  "multi-jittered", "regular"};
  for (const Method& m : methods())
    if (m.name == "jones" || m.name == "fpo") out.push_back(m.name);  // with the CGAL component
  return out;
}

INSTANTIATE_TEST_SUITE_P(Methods, ProgressOfMethod, ::testing::ValuesIn(reporting_methods()), [](const auto& info) {
  std::string n = info.param;
  for (char& c : n)
    if (c == '-') c = '_';
  return n;
});

TEST(ProgressOfAnalysis, OneUnitPerSetThenWithinTheSpectrumAndThePairCorrelation) {
  GenerateRequest r;
  r.count = 200;
  r.torus = true;
  std::vector<PointSet<2>> sets;
  for (std::uint64_t seed = 0; seed < 5; ++seed) {
    r.seed = seed;
    sets.push_back(generate("jittered", r).as<2>());
  }
  std::vector<Report> reports;
  AnalysisOptions options;
  options.max_frequency = 64;  // 65 rows of frequencies: 5 chunks, reported in batches
  options.progress.report = [&](double done, double total) {
    reports.push_back({done, total});
    return true;
  };
  const Domain<2> domain = Domain<2>::unit(true);
  const AnalysisReport with = analyze<2>(sets, domain, options);
  // One unit a set (0 to 5), then the spectrum (5 to 6) and the pair
  // correlation (6 to 7), each with reports inside its unit.
  ASSERT_FALSE(reports.empty());
  int inside_spectrum = 0, inside_pcf = 0;
  for (std::size_t i = 0; i < reports.size(); ++i) {
    EXPECT_EQ(reports[i].total, 7.0);
    if (i > 0) {
      EXPECT_GE(reports[i].done, reports[i - 1].done);
    }
    inside_spectrum += reports[i].done > 5 && reports[i].done < 6;
    inside_pcf += reports[i].done > 6 && reports[i].done < 7;
  }
  for (int k = 0; k <= 5; ++k)
    EXPECT_NE(std::find_if(reports.begin(), reports.end(), [&](const Report& x) { return x.done == k; }), reports.end())
        << k;
  EXPECT_GE(inside_spectrum, 1);
  EXPECT_GE(inside_pcf, 3);
  EXPECT_EQ(reports.back().done, 7.0);
  // The batches the spectrum runs in with a listener change nothing.
  options.progress = {};
  const AnalysisReport without = analyze<2>(sets, domain, options);
  ASSERT_TRUE(with.spectrum && without.spectrum);
  EXPECT_EQ(with.spectrum->peak_power, without.spectrum->peak_power);
  EXPECT_EQ(with.rho_min, without.rho_min);
  EXPECT_EQ(periodogram<2>(sets, domain, {.max_frequency = 64}).power,
            periodogram<2>(sets, domain, {.max_frequency = 64}, {[](double, double) { return true; }}).power);
  // Cancelled in the sets, in the spectrum and in the pair correlation.
  for (double stop : {2.0, 5.5, 6.5}) {
    options.progress.report = [stop](double done, double) { return done < stop; };
    EXPECT_THROW(analyze<2>(sets, domain, options), Cancelled) << stop;
  }
}

// One set in 6D: no spectrum, and the set's unit moves measure by measure
// (spacing, then each discrepancy), and a stop between them cancels.
TEST(ProgressOfAnalysis, WithinOneSetMeasureByMeasure) {
  GenerateRequest r;
  r.count = 300;
  r.dim = 6;
  const PointSet<6> set = generate("random", r).as<6>();
  const std::vector<PointSet<6>> sets = {set};
  std::vector<Report> reports;
  AnalysisOptions options;
  options.progress.report = [&](double done, double total) {
    reports.push_back({done, total});
    return true;
  };
  const Domain<6> domain = Domain<6>::unit();
  const AnalysisReport with = analyze<6>(sets, domain, options);
  int inside = 0;
  for (std::size_t i = 0; i < reports.size(); ++i) {
    EXPECT_EQ(reports[i].total, 3.0);
    if (i > 0) {
      EXPECT_GT(reports[i].done, reports[i - 1].done);
    }
    inside += reports[i].done > 0 && reports[i].done < 1;
  }
  EXPECT_GE(inside, 4);
  EXPECT_EQ(reports.back().done, 3.0);
  options.progress = {};
  EXPECT_EQ(analyze<6>(sets, domain, options).mixture_discrepancy, with.mixture_discrepancy);
  options.progress.report = [](double done, double) { return done < 0.5; };
  EXPECT_THROW(analyze<6>(sets, domain, options), Cancelled);
}

// Past 8 dimensions: the nearest neighbours, then each discrepancy.
TEST(ProgressOfAnalysis, PastEightDimensionsMeasureByMeasure) {
  GenerateRequest r;
  r.count = 300;
  r.dim = 12;
  const std::vector<PointCloud> sets = {generate("random", r), generate("halton", r)};
  const std::vector<double> lo(12, 0.0), hi(12, 1.0);
  std::vector<Report> reports;
  AnalysisOptions options;
  options.progress.report = [&](double done, double total) {
    reports.push_back({done, total});
    return true;
  };
  const AnalysisReport with = analyze(std::span<const PointCloud>(sets), lo, hi, false, options);
  ASSERT_EQ(reports.size(), 10u);  // 0, the neighbours, four a set (the last of them is the end)
  for (std::size_t i = 0; i < reports.size(); ++i) {
    EXPECT_EQ(reports[i].total, 9.0);
    EXPECT_EQ(reports[i].done, static_cast<double>(std::min<std::size_t>(i, 9)));
  }
  options.progress = {};
  EXPECT_EQ(analyze(std::span<const PointCloud>(sets), lo, hi, false, options).mixture_discrepancy,
            with.mixture_discrepancy);
  options.progress.report = [](double done, double) { return done < 3; };
  EXPECT_THROW(analyze(std::span<const PointCloud>(sets), lo, hi, false, options), Cancelled);
}

// 1,200 points in 12D: each discrepancy is two blocks of rows, and the
// first block is heard inside its measure's unit.
TEST(ProgressOfAnalysis, InsideOneDiscrepancy) {
  GenerateRequest r;
  r.count = 1200;
  r.dim = 12;
  std::vector<Report> reports;
  AnalysisOptions options;
  options.progress = recorder(reports);
  const std::vector<PointCloud> sets = {generate("halton", r)};
  analyze(std::span<const PointCloud>(sets), std::vector<double>(12, 0.0), std::vector<double>(12, 1.0), false,
          options);
  int inside = 0;
  for (std::size_t i = 0; i < reports.size(); ++i) {
    if (i > 0) {
      EXPECT_GT(reports[i].done, reports[i - 1].done);
    }
    inside += reports[i].done != std::floor(reports[i].done);
  }
  EXPECT_EQ(inside, 4);  // one a discrepancy
  EXPECT_EQ(reports.back().done, 5.0);
  options.progress.report = [](double done, double) { return done < 2.5; };
  EXPECT_THROW(analyze(std::span<const PointCloud>(sets), std::vector<double>(12, 0.0), std::vector<double>(12, 1.0),
                       false, options),
               Cancelled);
}

TEST(ProgressOfRender, BlocksInRoundsTheSameImageAndCancellation) {
  const auto scene = make_scene("zone-plate", 300, 200);
  const auto sampler = make_image_sampler("jittered", {.spp = 2, .seed = 4});
  RenderOptions options;
  options.block = 8;  // 38 x 25 blocks: several rounds of 64
  const Image plain = render(*scene, *sampler, 300, 200, options);
  std::vector<Report> reports;
  options.progress.report = [&](double done, double total) {
    reports.push_back({done, total});
    return true;
  };
  EXPECT_EQ(render(*scene, *sampler, 300, 200, options).pixels, plain.pixels);
  ASSERT_GE(reports.size(), 10u);
  for (std::size_t i = 1; i < reports.size(); ++i) EXPECT_GT(reports[i].done, reports[i - 1].done);
  EXPECT_EQ(reports.back().done, 38.0 * 25.0);
  EXPECT_EQ(reports.back().total, 38.0 * 25.0);
  options.progress.report = [](double done, double) { return done < 100; };
  EXPECT_THROW(render(*scene, *sampler, 300, 200, options), Cancelled);
}

TEST(ProgressPartOf, MapsEachPartIntoTheWhole) {
  std::vector<Report> reports;
  Progress whole{[&](double done, double total) {
    reports.push_back({done, total});
    return true;
  }};
  for (std::size_t part = 0; part < 3; ++part) {
    ProgressReporter reporter(part_of(whole, part, 3), 10);
    reporter.update(5);
    reporter.finish();
  }
  ASSERT_EQ(reports.size(), 9u);
  EXPECT_EQ(reports[1].done, 0.5);
  EXPECT_EQ(reports[4].done, 1.5);
  EXPECT_EQ(reports[8].done, 3.0);
  EXPECT_EQ(reports[8].total, 3.0);
  EXPECT_FALSE(part_of(Progress{}, 0, 3));  // no callback, nothing to call
}

// poll() repeats the last report once a tenth of a second has passed, so a
// stretch of work that moves no count (a refinement) still hears a stop.
TEST(ProgressPoll, RepeatsTheLastReportAfterATenthOfASecondAndHearsAStop) {
  std::vector<Report> reports;
  bool stop = false;
  Progress progress{[&](double done, double total) {
    reports.push_back({done, total});
    return !stop;
  }};
  ProgressReporter reporter(progress, 10);
  reporter.update(4);
  const std::size_t before = reports.size();
  std::this_thread::sleep_for(std::chrono::milliseconds(120));
  reporter.poll();
  ASSERT_EQ(reports.size(), before + 1);
  EXPECT_EQ(reports.back().done, 4.0);  // the same count: monotone
  stop = true;
  std::this_thread::sleep_for(std::chrono::milliseconds(120));
  EXPECT_THROW(reporter.poll(), Cancelled);
  ProgressReporter silent(Progress{}, 10);
  EXPECT_NO_THROW(silent.poll());  // no callback, nothing to ask
}

}  // namespace
}  // namespace pds
