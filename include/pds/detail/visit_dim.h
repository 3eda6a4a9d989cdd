#pragma once
#include <string>
#include <type_traits>
#include <utility>

#include "pds/error.h"

namespace pds {

namespace detail {

// f(D) for the run-time dim, D tried from D up to Hi (dim is known in range).
template <int D, int Hi, class F>
decltype(auto) visit_dim_from(int dim, F& f) {
  if constexpr (D == Hi) {
    return f(std::integral_constant<int, D>{});
  } else {
    if (dim == D) return f(std::integral_constant<int, D>{});
    return visit_dim_from<D + 1, Hi>(dim, f);
  }
}

}  // namespace detail

template <int Lo, int Hi, class F>
decltype(auto) visit_dim(int dim, F&& f) {
  static_assert(kMinDim <= Lo && Lo <= Hi && Hi <= kMaxDim);
  if (dim < Lo || dim > Hi)
    throw InvalidArgument("dimension " + std::to_string(dim) + " is not supported (supported: " +
                          (Lo == Hi ? std::to_string(Lo) : std::to_string(Lo) + " to " + std::to_string(Hi)) + ")");
  return detail::visit_dim_from<Lo, Hi>(dim, f);
}

template <class F>
decltype(auto) visit_dim(int dim, F&& f) {
  return visit_dim<kPlaneDim, kSpaceDim>(dim, std::forward<F>(f));
}

}  // namespace pds
