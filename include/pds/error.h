#pragma once
// Errors thrown by the library. The library never prints or exits: it throws,
// and the message names the parameter and the value that were wrong.

#include <stdexcept>
#include <string>

namespace pds {

/// Bad input: a parameter out of range, a malformed file, a request that cannot
/// be met. The command line maps it to exit status 2.
class InvalidArgument : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

/// Failure while doing valid work: a file that cannot be written, an iteration
/// bound that was hit. The command line maps it to exit status 1.
class Failure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace pds
