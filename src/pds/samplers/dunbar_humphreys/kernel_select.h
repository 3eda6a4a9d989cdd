#pragma once
// Which neighbourhood kernel boundary sampling (Dunbar-Humphreys variant 0)
// runs: the AVX-512 one where this build has it and the processor has the
// x86-64-v4 level, otherwise the scalar one. Both give the same bytes.
//
// The switch that forces the scalar kernel (to test it on a processor with
// AVX-512, or to time it):
//   - the environment variable PDS_FORCE_SCALAR, set to anything but "" or
//     "0" (read once, at the first Dunbar-Humphreys sample set), or
//   - force_scalar(true) from code (tests), which overrides the variable.
// pds::detail::dunbar_humphreys_has_vector_kernel() (the public header) still
// tells what the processor allows; dunbar_humphreys_boundary() runs the kernel
// it is asked for, whatever the switch.

#include <string>

namespace pds::detail::dh {

/// Whether the value of PDS_FORCE_SCALAR (nullptr when unset) forces the
/// scalar kernel: anything but unset, "" or "0".
bool forces_scalar(const char* value);
/// Forces the scalar kernel (true) or lets the processor decide (false),
/// for every later call in the process, overriding PDS_FORCE_SCALAR.
void force_scalar(bool force);
/// Whether the scalar kernel is forced (by force_scalar, else by PDS_FORCE_SCALAR).
bool scalar_forced();
/// Whether pds::dunbar_humphreys runs the vector kernel: the build and the
/// processor have it and the scalar one is not forced.
bool use_vector_kernel();
/// Why the vector kernel cannot run here, naming the missing processor
/// features (e.g. "the processor lacks x86-64-v4: no avx512bw avx512vl") or
/// the build's limit; empty where it can run.
std::string vector_kernel_missing();

}  // namespace pds::detail::dh
