// SPDX-License-Identifier: BSD-3-Clause
#include "adhesion/jkr_branch.hpp"

namespace restitution::adhesion {
namespace {

// ∫ f(s) δ'(s) ds (docs/adhesion.md §2).
double branch_antiderivative(double s) {
  const double s2 = s * s;
  return (8.0 / 15.0) * s2 * s2 * s - (4.0 * kSqrt2 / 3.0) * s2 * s * std::sqrt(s) + s2;
}

}  // namespace

double jkr_potential(double s) {
  // G(s0) = −(3/5)2^{2/3} exactly; the closed form keeps U(s0) = 0 to the bit.
  return branch_antiderivative(s) + 0.6 * std::cbrt(4.0);
}

double jkr_break_work(double break_radius) {
  if (break_radius == kDisplacementControlledBreakRadius) return 0.1 + 0.6 * std::cbrt(4.0);
  if (break_radius == kForceControlledBreakRadius) return 0.6 * std::cbrt(4.0) - 0.4 * std::cbrt(81.0 / 64.0);
  return jkr_potential(break_radius);
}

}  // namespace restitution::adhesion
