// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The numbers of the fast ε(ζ) tables (docs/fast.md), as the generator computes them and as
// src/fast/fast_table.h holds them. Natural units; s = ln ζ; g = ln(ε / (1 − ε)), the logit of ε.
#include <string>
#include <vector>

#include "restitution/contact_law.hpp"

namespace restitution::fast {

// A large-ζ law of a duration or of the maximal compression, natural units, s = ln ζ, δ = ζ^{-5/3}:
// f = e^{power s} [c1 s + c0 + δ (d2 s² + d1 s + d0) + δ² e0] (docs/fast.md derives each).
struct Law {
  double power = 0, c1 = 0, c0 = 0, d2 = 0, d1 = 0, d0 = 0, e0 = 0;
};

// Everything that differs between the two ends of the collision.
struct EndTable {
  // Forward tables on s ∈ [s_lo, s_lo + intervals / per_unit): per interval degree + 1 monomial
  // coefficients, highest power first, in t ∈ [-1, 1] across the interval.
  int intervals = 0;
  std::vector<double> logit;  // g(s)
  // ln τ_c(s) on its own number of intervals (the naive end's reaches further than its g), tau_law above.
  int tau_intervals = 0;
  std::vector<double> log_tau;
  Law tau_law;
  // Inverse table on g ∈ [g_lo, g_lo + inverse_intervals / per_unit): s(g).
  double g_lo = 0;
  int inverse_intervals = 0;
  std::vector<double> inverse;
  // (1 − ε)/ζ as a polynomial in sqrt ζ, highest power first (the series of docs/series.md), below ζ_lo.
  std::vector<double> small;
  double tau_zero = 0;  // τ_c at ζ = 0
  double tau_lo = 0;    // τ_c at ζ_lo
};

struct TableData {
  std::string settings;  // how the tables were made, one line each (no quotes or backslashes)
  int degree = 0;
  int small_terms = 0;
  double s_lo = 0;      // ln ζ_lo, start of every forward table
  double per_unit = 0;  // intervals per unit of s (and of g in the inverse tables)
  double zeta_lo = 0;   // exp(s_lo) rounded
  PerEnd<EndTable> ends;
  // Maximal compression on the delayed-recovery grid: ln x_max(s), ln τ_max(s), and their values at 0 and
  // ζ_lo; their laws above the grid.
  std::vector<double> log_x_max, log_tau_max;
  double x_max_zero = 0, tau_max_zero = 0, x_max_lo = 0, tau_max_lo = 0;
  Law x_max_law, tau_max_law;
  // Large-ζ laws (docs/asymptotics.md): naive ε = κ ζ^-5; delayed ε = X_m δ [1 − (δ/q)((10/3) ln ζ + ln A −
  // 5/2)], δ = ζ^{-5/3}.
  double kappa = 0, x_m = 0, q = 0, log_a = 0;
};

}  // namespace restitution::fast
