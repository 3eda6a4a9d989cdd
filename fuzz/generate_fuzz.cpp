// libFuzzer target: a run-time generation request, as the command line and
// the Python module build it, from arbitrary bytes (method, dimension,
// bounds, torus, count or radius, parameters by name and value). generate()
// must validate it: a valid set (inside the domain) or InvalidArgument /
// Failure, never a crash, a hang or a huge allocation (the point budget is
// kept small here).
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>

#include "pds/error.h"
#include "pds/registry.h"

namespace {

struct Bytes {
  const std::uint8_t* data;
  std::size_t size;
  template <class T>
  T take() {
    T value{};
    const std::size_t n = size < sizeof(T) ? size : sizeof(T);
    if (n > 0) std::memcpy(&value, data, n);
    data += n;
    size -= n;
    return value;
  }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Bytes in{data, size};
  const auto all = pds::methods();
  const pds::Method& m = all[in.take<std::uint8_t>() % all.size()];
  pds::GenerateRequest r;
  // Keeps each run well inside the 10 s a unit may take under the
  // sanitizers (fpo optimised 3761 points in 10 s there); larger budgets are
  // the same code. Counts reach past it, so the budget check is fuzzed too.
  r.max_points = 1500;
  r.dim = in.take<std::uint8_t>() % 5;
  r.torus = in.take<std::uint8_t>() & 1;
  r.seed = in.take<std::uint64_t>();
  r.threads = in.take<std::uint8_t>() % 3;
  const std::uint8_t flags = in.take<std::uint8_t>();
  if (flags & 1) {
    const int n = flags >> 4 & 7;
    for (int i = 0; i < n; ++i) r.lo.push_back(in.take<double>());
    for (int i = 0; i < n; ++i) r.hi.push_back(in.take<double>());
  }
  if (flags & 2) r.count = in.take<std::uint32_t>() % 1600;
  if (flags & 4) r.radius = in.take<double>();
  if (flags & 8) {
    const std::uint8_t which = in.take<std::uint8_t>();
    const std::string name = m.params.empty() ? "k" : m.params[which % m.params.size()].name;
    double value = in.take<double>();
    // dart-throwing's failure bound is the user's own loop bound (up to 1e15
    // darts): a large one is a long run by request, not a hang.
    if (name == "failures" && value > 1e5) value = 1e5;
    // fpo's sweep budget likewise (its default, 1000, is ~10x the 10 s above).
    if (name == "sweeps" && value > 100) value = 100;
    // gbn's steps likewise (its default of 1,000 over 1,500 points in 3D
    // took past 10 s; 20 steps at sigma 10, all pairs, stay near 2 s).
    if (name == "iterations" && value > 20) value = 20;
    r.params[(which & 0x80) ? name + "x" : name] = value;
  }
  if (m.name == "fpo" && !r.params.count("sweeps")) r.params["sweeps"] = 100;
  if (m.name == "gbn" && !r.params.count("iterations")) r.params["iterations"] = 20;
  // From 4D best-candidate is Mitchell's literal loop, m N^2 / 2 candidates:
  // 1,426 points in 4D took 20 s under the sanitizers (1 s without).
  if (m.name == "best-candidate" && r.dim >= 4) r.max_points = 500;
  try {
    const pds::PointCloud cloud = pds::generate(m.name, r);
    if (cloud.dim != r.dim) std::abort();
    if (r.count && m.exact_count && cloud.size() != *r.count) std::abort();
    pds::visit_dim(r.dim, [&](auto d) {
      constexpr int D = decltype(d)::value;
      const pds::Domain<D> domain = r.domain<D>();
      for (const auto& p : cloud.as<D>())
        if (!domain.contains(p)) std::abort();
      return 0;
    });
  } catch (const pds::InvalidArgument&) {
  } catch (const pds::Failure&) {
  }
  return 0;
}
