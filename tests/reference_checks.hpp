// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Comparing a solver's results with data/reference_solutions.csv (the __float128 Taylor reference).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "reference/reference_solution.hpp"
#include "reference/work_precision.hpp"
#include "restitution/collision_solver.hpp"

namespace restitution::test_support {

// The shipped grid has 50 ζ values; far fewer means a truncated or emptied file.
inline constexpr std::size_t kMinReferenceRows = 40;

// The reference grid's rows; a test that reads them must fail when the file holds no row (a header alone
// would otherwise pass every loop over the rows vacuously).
inline const std::vector<ReferenceRow>& reference_rows() {
  static const std::vector<ReferenceRow> rows =
      read_reference_file(reference_file_in(RESTITUTION_SOURCE_DIR));
  if (rows.size() < kMinReferenceRows) {
    ADD_FAILURE() << "data/reference_solutions.csv holds " << rows.size() << " rows, fewer than "
                  << kMinReferenceRows;
  }
  return rows;
}

// The contract's error (reference/work_precision.hpp).
using restitution::contract_error;

}  // namespace restitution::test_support
