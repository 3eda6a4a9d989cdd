// Run-time choice of boundary sampling's neighbourhood kernel (declarations
// and the force-scalar switch in kernel_select.h).
#include "kernel_select.h"

#include <atomic>
#include <cstdlib>
#include <cstring>

#include "boundary.h"
#include "pds/samplers/dunbar_humphreys.h"

namespace pds::detail {

bool dunbar_humphreys_has_vector_kernel() {
#if PDS_HAVE_AVX512_KERNEL
  // The kernel is compiled for the whole x86-64-v4 level (AVX-512 F, BW, CD,
  // DQ, VL with AVX2, BMI2, ...), so the processor must have all of it.
  static const bool has = __builtin_cpu_supports("x86-64-v4");
  return has;
#else
  return false;
#endif
}

namespace dh {
namespace {

/// The switch: read from the environment the first time it is asked for.
std::atomic<bool>& forced() {
  static std::atomic<bool> flag{forces_scalar(std::getenv("PDS_FORCE_SCALAR"))};
  return flag;
}

}  // namespace

bool forces_scalar(const char* value) { return value != nullptr && *value != '\0' && std::strcmp(value, "0") != 0; }

void force_scalar(bool force) { forced().store(force, std::memory_order_relaxed); }

bool scalar_forced() { return forced().load(std::memory_order_relaxed); }

bool use_vector_kernel() { return dunbar_humphreys_has_vector_kernel() && !scalar_forced(); }

std::string vector_kernel_missing() {
#if PDS_HAVE_AVX512_KERNEL
  if (dunbar_humphreys_has_vector_kernel()) return "";
  std::string missing = "the processor lacks x86-64-v4 (AVX-512 F, BW, CD, DQ, VL over x86-64-v3):";
  // __builtin_cpu_supports takes literal names only.
  if (!__builtin_cpu_supports("x86-64-v3")) missing += " no x86-64-v3";
  if (!__builtin_cpu_supports("avx512f")) missing += " no avx512f";
  if (!__builtin_cpu_supports("avx512bw")) missing += " no avx512bw";
  if (!__builtin_cpu_supports("avx512cd")) missing += " no avx512cd";
  if (!__builtin_cpu_supports("avx512dq")) missing += " no avx512dq";
  if (!__builtin_cpu_supports("avx512vl")) missing += " no avx512vl";
  return missing;
#else
  return "this build has no AVX-512 kernel (it needs x86-64 and GCC 12 or later, without -DPDS_HAVE_AVX512_KERNEL=0)";
#endif
}

}  // namespace dh
}  // namespace pds::detail
