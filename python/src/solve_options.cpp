#include "solve_options.hpp"

#include <fmt/core.h>

#include "restitution/errors.hpp"

namespace restitution::python {

SolveOptions solve_options(const std::string& end, double tolerance, const std::string& method,
                           bool both_allowed) {
  SolveOptions options;
  if (both_allowed && end == "both") {
    options.ends = EndSet::both();
  } else if (both_allowed && end != "naive" && end != "delayed-recovery") {
    throw InvalidInput(fmt::format("end must be naive, delayed-recovery or both, got '{}'", end));
  } else {
    options.ends = EndSet{end_from_name(end)};
  }
  options.tolerance = tolerance;
  options.method = method_from_name(method);
  check_solve_options(options);
  return options;
}

}  // namespace restitution::python
