#pragma once
#include <string>
#include <type_traits>

#include "pds/error.h"

namespace pds {

template <class F>
decltype(auto) visit_dim(int dim, F&& f) {
  switch (dim) {
    case 2:
      return f(std::integral_constant<int, 2>{});
    case 3:
      return f(std::integral_constant<int, 3>{});
    default:
      throw InvalidArgument("dimension " + std::to_string(dim) + " is not supported (supported: " +
                            std::to_string(kMinDim) + " to " + std::to_string(kMaxDim) + ")");
  }
}

}  // namespace pds
