#pragma once
// A write that failed after its destination was accepted (disk full, a closed pipe, /dev/full): the
// program exits with status 3, distinct from bad input (2) and numerical failure (1).
#include <stdexcept>

namespace restitution::cli {

class IoError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Flushes stdout; throws IoError when anything written to it was lost.
void flush_standard_output();

}  // namespace restitution::cli
