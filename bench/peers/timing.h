// Shared by the peer drivers: the calling thread's CPU time and the wall time
// of one call, and a CSV writer for `pds analyze`. Not part of pds.
#pragma once
#include <stdio.h>
#include <time.h>

static double pds_peer_now(clockid_t clock) {
  struct timespec ts;
  clock_gettime(clock, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

// One line that run_peers.sh parses: name dim samples cpu_s wall_s.
static void pds_peer_report(const char* name, int dim, size_t n, double cpu, double wall) {
  printf("RESULT %s dim=%d samples=%zu cpu_s=%.6f wall_s=%.6f Msamples_per_cpu_s=%.4f\n", name, dim, n, cpu, wall,
         (double)n / cpu * 1e-6);
}
