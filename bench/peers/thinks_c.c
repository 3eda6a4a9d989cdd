/* thinks/poisson-disk-sampling, current C header include/thinks/tph_poisson.h
 * (commit e436117): tph_poisson_create on the unit square or cube (a box: it
 * has no tiling), float coordinates (the header's default). Times only that
 * call. Usage: thinks_c DIM RADIUS [K=30] [SEED=0] [OUT.csv] */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define TPH_POISSON_IMPLEMENTATION
#include "thinks/tph_poisson.h"
#include "timing.h"

int main(int argc, char** argv) {
  if (argc < 3) return fprintf(stderr, "usage: %s DIM RADIUS [K] [SEED] [OUT.csv]\n", argv[0]), 2;
  const int dim = atoi(argv[1]);
  const tph_poisson_real lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1};
  const tph_poisson_args args = {.bounds_min = lo,
                                 .bounds_max = hi,
                                 .radius = (tph_poisson_real)strtod(argv[2], NULL),
                                 .ndims = (int32_t)dim,
                                 .max_sample_attempts = (uint32_t)(argc > 3 ? atoi(argv[3]) : 30),
                                 .seed = (uint64_t)(argc > 4 ? atoll(argv[4]) : 0)};
  tph_poisson_sampling sampling;
  memset(&sampling, 0, sizeof sampling);
  const double c0 = pds_peer_now(CLOCK_THREAD_CPUTIME_ID), w0 = pds_peer_now(CLOCK_MONOTONIC);
  const int ret = tph_poisson_create(&args, NULL, &sampling);
  const double c1 = pds_peer_now(CLOCK_THREAD_CPUTIME_ID), w1 = pds_peer_now(CLOCK_MONOTONIC);
  if (ret != TPH_POISSON_SUCCESS) return fprintf(stderr, "tph_poisson_create: %d\n", ret), 1;
  const tph_poisson_real* s = tph_poisson_get_samples(&sampling);
  const size_t n = (size_t)sampling.nsamples;
  pds_peer_report("thinks-c", dim, n, c1 - c0, w1 - w0);
  if (argc > 5) {
    FILE* f = fopen(argv[5], "w");
    fputs(dim == 2 ? "x,y\n" : "x,y,z\n", f);
    for (size_t i = 0; i < n; ++i)
      for (int d = 0; d < dim; ++d) fprintf(f, d + 1 < dim ? "%.9g," : "%.9g\n", (double)s[i * (size_t)dim + (size_t)d]);
    fclose(f);
  }
  tph_poisson_destroy(&sampling);
  return 0;
}
