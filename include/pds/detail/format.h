#pragma once
// How numbers appear in error messages: six significant digits, "nan" and
// "inf" spelled out, so a message names the value the caller passed.

#include <sstream>
#include <string>

namespace pds::detail {

inline std::string format_number(double v) {
  std::ostringstream os;
  os.precision(6);
  os << v;
  return os.str();
}

}  // namespace pds::detail
