#pragma once
// Comparing a solver's results with data/reference_solutions.csv (the __float128 Taylor reference).
#include <algorithm>
#include <cmath>
#include <vector>

#include "reference/reference_solution.hpp"
#include "reference/work_precision.hpp"
#include "restitution/collision_solver.hpp"

namespace restitution::test_support {

inline const std::vector<ReferenceRow>& reference_rows() {
  static const std::vector<ReferenceRow> rows =
      read_reference_file(reference_file_in(RESTITUTION_SOURCE_DIR));
  return rows;
}

// The contract's error (reference/work_precision.hpp).
using restitution::contract_error;

}  // namespace restitution::test_support
