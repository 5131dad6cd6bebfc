// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The Sundman form of a contact's smoothing and CVODE's error weights for the event driver
// (event_driver.hpp), inline: they run per right-hand side or per step. The head-on integrator
// (cvode_integrator.cpp) keeps its own copies, fused into its right-hand side and unrolled for its 3- and
// 4-component states: through these helpers its 400-point delayed-end sweep took 0.4 % more instructions
// (its right-hand side 4.6 %, its error weights 10 %: the loops over a run-time size are not unrolled).
// Private to the library.
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstddef>

#include "restitution/contact_law.hpp"

namespace restitution::detail {

// dτ/dσ = u^{q-1} in the smoothing u = x^{1/q} (ContactLaw::smoothing_root) with dτ = u^{q-1} dσ.
inline double sundman_time_rate(const ContactLaw& law, double u) {
  return law.dcompression_du(u) / law.smoothing_root();
}

// Turns the time-form rates of a state (x, y_1, ..., y_{n-1}) at smooth variable u, d[0] = dx/dτ and d[i] =
// dy_i/dτ, in place into the Sundman form's (u, y_1, ..., y_{n-1}, τ): du/dσ = (dx/dτ)/q, dy_i/dσ =
// u^{q-1} dy_i/dτ, and dτ/dσ = u^{q-1} into d[n]. Analytic in u and σ for viscoelastic Hertz where the time
// form has sqrt singularities at x = 0 (docs/design.md §4).
inline void to_sundman_rates(const ContactLaw& law, double u, double* d, int n) {
  const double dtau = sundman_time_rate(law, u);
  d[0] = d[0] / law.smoothing_root();
  for (int i = 1; i < n; ++i) d[i] = d[i] * dtau;
  d[n] = dtau;
}

// CVODE stops with "too much accuracy requested" (flag -2) where DBL_EPSILON/rtol > 1; below 2 DBL_EPSILON
// its steps are bound by rounding anyway (near critical damping, where the tolerance policy asks for less).
inline double cvode_relative_tolerance(double requested) {
  return std::max(requested, 2.0 * DBL_EPSILON);
}

// CVODE's error weights 1/(rtol |y_i| + atol_i) in one loop: the same arithmetic as CVodeSVtolerances
// (N_VAbs, N_VLinearSum, N_VInv), without its four vector calls per step (~2 % of a solve's instructions).
// Returns -1 where a weight's scale is not positive (an error to CVODE, as its own).
inline int error_weights(double rtol, const double* atol, const double* y, double* w, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) {
    const double scale = rtol * std::abs(y[i]) + atol[i];
    if (scale <= 0.0) return -1;
    w[i] = 1.0 / scale;
  }
  return 0;
}

}  // namespace restitution::detail
