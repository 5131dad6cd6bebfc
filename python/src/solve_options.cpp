// SPDX-License-Identifier: BSD-3-Clause
#include "solve_options.hpp"

#include "restitution/errors.hpp"

namespace restitution::python {

SolveOptions solve_options(const std::string& end, double tolerance, const std::string& method,
                           bool both_allowed) {
  SolveOptions options;
  options.ends = both_allowed ? end_set_from_name(end) : EndSet{end_from_name(end)};
  options.tolerance = tolerance;
  options.method = method_from_name(method);
  check_solve_options(options);
  return options;
}

}  // namespace restitution::python
