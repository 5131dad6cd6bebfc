// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Typed errors of the library. The command-line program maps them to exit statuses:
// InvalidInput -> 2 (bad usage or input), NumericalFailure -> 1, IoError -> 3.
#include <stdexcept>
#include <string>

namespace restitution {

// A parameter, option or file content that the library refuses; the message names it.
class InvalidInput : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// The integrator could not deliver the requested result to the requested accuracy;
// the message names the parameter, the end of the collision, the tolerance and the solver's flag.
class NumericalFailure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A file or folder that cannot be created or written (disk full, no permission, a path through a file):
// the input was fine, the system refused; the message names the path.
class IoError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace restitution
