// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Makes the fast tables (TableData) from the __float128 reference engine
// (restitution/reference_solution.hpp): Chebyshev interpolation of g = ln(ε/(1 − ε)), ln τ_c, ln x_max and ln
// τ_max in s = ln ζ at the Chebyshev nodes of each interval, converted to monomials; the inverse by
// interpolating s(g) from the unrounded forward polynomials; the settings and the errors measured at random
// check points recorded in TableData::settings; the large-ζ laws of the durations and of the maximal
// compression (docs/fast.md), their free constants fitted to reference solves just above the tables.
#include <cstddef>
#include <cstdint>
#include <functional>

#include "fast/table_data.hpp"

namespace restitution::fast {

// Random check points per interval: at most this many (fast-table --checks; 2 take about 2 minutes).
inline constexpr int kMaxChecksPerInterval = 1000;
inline constexpr int kMinDegree = 2, kMaxDegree = 30;  // GeneratorSettings::degree
inline constexpr int kMaxPerUnit = 64;                 // GeneratorSettings::per_unit, a whole number >= 1

struct GeneratorSettings {
  int degree = 12;                 // polynomial degree per interval
  double per_unit = 8;             // intervals per unit of ln ζ (and of g in the inverse)
  double s_lo = -19;               // ln ζ where the tables start (the series holds below)
  double s_hi_naive = 2;           // ln ζ where the naive table of g ends (κ ζ^-5 above)
  double s_hi_naive_duration = 6;  // ln ζ where the naive table of τ_c ends (its law above)
  double s_hi_delayed = 12;        // ln ζ where the delayed-recovery table ends (two-term law above)
  int checks_per_interval = 2;     // at most kMaxChecksPerInterval
  std::uint64_t seed = 13;
};

// Throws InvalidInput for settings out of range, NumericalFailure if a reference solve fails or g is not
// monotone in s.
// `progress(done, total)` is called after each interval of the fits and of the checks (nearly all of the
// work); it may throw to stop the generation (the command line does on Ctrl-C).
TableData generate_tables(const GeneratorSettings& settings,
                          const std::function<void(std::size_t, std::size_t)>& progress = {});

}  // namespace restitution::fast
