#pragma once
// Boundary sampling (variant 0 of the Dunbar-Humphreys sampler) by kernel:
// one entry point per neighbourhood kernel, each compiled in its own
// translation unit (boundary_scalar.cpp, boundary_avx512.cpp); the driver
// picks one at run time (kernel_select.h). Private to the library.

#include <array>
#include <cstdint>
#include <vector>

#include "pds/domain.h"
#include "pds/point.h"
#include "pds/samplers/dunbar_humphreys.h"

// The AVX-512 kernel needs x86-64 and GCC 12 or later (its target attribute
// "arch=x86-64-v4" and __builtin_cpu_supports("x86-64-v4")). Building with
// -DPDS_HAVE_AVX512_KERNEL=0 leaves it out (to test a build without it).
#ifndef PDS_HAVE_AVX512_KERNEL
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && __GNUC__ >= 12
#define PDS_HAVE_AVX512_KERNEL 1
#else
#define PDS_HAVE_AVX512_KERNEL 0
#endif
#endif

namespace pds::detail::dh {

/// Boundary sampling with the scalar kernel (any processor). The request is
/// validated by the caller, except for the torus period (checked here).
PointSet<2> boundary_sampling_scalar(const DunbarHumphreysParams& params, const Domain<2>& domain, std::uint64_t seed);
/// One front sample's free arcs (start, length in diamond measure) from the
/// given neighbours (plain offsets, no walls), by the scalar kernel.
std::vector<std::array<double, 2>> free_arcs_scalar(const Point<2>& p, const PointSet<2>& neighbours, double radius);

#if PDS_HAVE_AVX512_KERNEL
/// The same with the AVX-512 kernel: the same bytes. Only on a processor
/// with the x86-64-v4 level (the caller checks).
PointSet<2> boundary_sampling_avx512(const DunbarHumphreysParams& params, const Domain<2>& domain, std::uint64_t seed);
std::vector<std::array<double, 2>> free_arcs_avx512(const Point<2>& p, const PointSet<2>& neighbours, double radius);
#endif

}  // namespace pds::detail::dh
