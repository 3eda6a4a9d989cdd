#pragma once
// The registry's entries, one function per method, defined by family in the
// files beside this one; registry.cpp lists them in one table. The samplers
// know nothing of these: an entry wires a GenerateRequest to a sampler's
// typed Params.

#include "pds/registry.h"

namespace pds::registry_detail {

const Method& white_noise_method();
const Method& regular_method();
const Method& jittered_method();
const Method& multi_jittered_method();
const Method& latin_hypercube_method();
const Method& halton_method();
const Method& hammersley_method();
const Method& sobol_method();
const Method& dart_throwing_method();
const Method& bridson_method();
const Method& best_candidate_method();
const Method& elimination_method();
const Method& dunbar_humphreys_method();
const Method& wei_method();
const Method& ebeida_method();
const Method& maximal_darts_method();
const Method& gbn_method();
#ifdef PDS_WITH_CGAL
const Method& jones_method();
const Method& fpo_method();
#endif

}  // namespace pds::registry_detail
