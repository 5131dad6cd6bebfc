// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Python's end/tolerance/method arguments -> the library's SolveOptions.
#include <string>

#include "restitution/collision_solver.hpp"

namespace restitution::python {

// end: "naive", "delayed-recovery" or, where both_allowed, "both"; method: "auto", "bdf", "adams",
// "taylor". Throws InvalidInput naming the argument and the value.
SolveOptions solve_options(const std::string& end, double tolerance, const std::string& method,
                           bool both_allowed);

}  // namespace restitution::python
