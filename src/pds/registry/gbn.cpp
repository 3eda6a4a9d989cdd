// Registry entry of Gaussian blue noise (samplers/gbn.h).
#include "pds/samplers/gbn.h"

#include "descriptors.h"

namespace pds::registry_detail {

const Method& gbn_method() {
  static const Method method{
      .name = "gbn",
      .family = Family::optimized,
      .docs = "docs/gbn.md",
      .summary =
          "Gaussian blue noise (Ahmed, Ren, Wonka): gradient descent on a Gaussian kernel over all pairs from "
          "white noise; exact count, no hard minimum distance, any dimension",
      .citation = "A. G. M. Ahmed, J. Ren, P. Wonka, Gaussian Blue Noise, ACM TOG 41(6), SIGGRAPH Asia 2022",
      .takes_count = true,
      .exact_count = true,
      .dims = {1, 8},
      .memory_ratio = 4,
      .params = {{"iterations", 1000, 1, 1000000, true, "gradient steps"},
                 {"sigma", 0.7, 0.05, 10, false, "the kernel's standard deviation in mean spacings"},
                 {"step", 0.25, 1e-6, 10, false, "the step, a fraction of the kernel-weighted neighbour sum"}},
      .run =
          [](const GenerateRequest& r) {
            return run_typed<1, 8>(r, [&](const auto& domain) {
              GbnParams params;
              params.count = *r.count;
              params.iterations = static_cast<int>(r.param("iterations", 1000));
              params.sigma = r.param("sigma", 0.7);
              params.step = r.param("step", 0.25);
              params.threads = r.threads;
              params.progress = r.progress;
              return gbn(params, domain, r.seed);
            });
          },
  };
  return method;
}

}  // namespace pds::registry_detail
