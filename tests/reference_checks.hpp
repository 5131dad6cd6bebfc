#pragma once
// Comparing a solver's results with data/reference_solutions.csv (the __float128 Taylor reference).
#include <algorithm>
#include <cmath>
#include <vector>

#include "restitution/collision_solver.hpp"
#include "restitution/reference_solution.hpp"
#include "restitution/work_precision.hpp"

namespace restitution::test_support {

inline const std::vector<ReferenceRow>& reference_rows() {
  static const std::vector<ReferenceRow> rows =
      read_reference_file(reference_file_in(RESTITUTION_SOURCE_DIR));
  return rows;
}

// The contract's error (restitution/work_precision.hpp).
using restitution::contract_error;

}  // namespace restitution::test_support
