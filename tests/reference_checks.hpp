#pragma once
// Comparing a solver's results with data/reference_solutions.csv (the __float128 Taylor reference).
#include <algorithm>
#include <cmath>
#include <vector>

#include "restitution/collision_solver.hpp"
#include "restitution/reference_solution.hpp"

namespace restitution::test_support {

inline const std::vector<ReferenceRow>& reference_rows() {
  static const std::vector<ReferenceRow> rows =
      read_reference_file(reference_file_in(RESTITUTION_SOURCE_DIR));
  return rows;
}

// The contract's error: |ε - ε*| and |(1-ε) - (1-ε*)| relative to min(ε*, 1-ε*); at ζ = 0 (ε* = 1 exactly)
// the absolute error.
inline double contract_error(const EndResult& tested, const ReferenceEndValues& reference) {
  const double scale = std::min(reference.eps, reference.one_minus_eps);
  const double difference = std::max(std::abs(tested.eps - reference.eps),
                                     std::abs(tested.one_minus_eps - reference.one_minus_eps));
  return scale > 0 ? difference / scale : difference;
}

}  // namespace restitution::test_support
