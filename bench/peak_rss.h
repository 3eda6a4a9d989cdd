#pragma once
// The process's high-water resident set so far, in MB (Linux's getrusage
// reports KiB). The growth of a step is the difference of two readings.
#include <sys/resource.h>

namespace pds_bench {

inline double peak_rss_mb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

}  // namespace pds_bench
