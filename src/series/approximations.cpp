// SPDX-License-Identifier: BSD-3-Clause
// Closed-form approximations: the 1999 paper's Padé [1/4] and simple theory, the 2011 Padé approximants.
#include <array>
#include <cmath>
#include <span>
#include <string>

#include "restitution/errors.hpp"
#include "restitution/series.hpp"
#include "series/arguments.hpp"
#include "series/published_tables.hpp"

namespace restitution::series {
namespace {

using detail::check_zeta;

double polynomial(double x, std::span<const double> coef) {
  double acc = 0.0;
  for (auto it = coef.rbegin(); it != coef.rend(); ++it) acc = acc * x + *it;
  return acc;
}

// ε = N/D with N, D ascending in x and N_0 = D_0 = 1; 1 - ε = (D - N)/D term by term, so that equal
// leading coefficients cancel exactly and 1 - ε keeps its relative accuracy as x -> 0.
template <std::size_t NN, std::size_t ND>
Value rational(double x, const std::array<double, NN>& num, const std::array<double, ND>& den) {
  static_assert(ND >= NN);
  std::array<double, ND> difference = den;
  for (std::size_t i = 0; i < NN; ++i) difference[i] -= num[i];
  const double d = polynomial(x, den);
  return {polynomial(x, num) / d, polynomial(x, difference) / d};
}

}  // namespace

Pade1999 pade_1999_coefficients(double a2, double a3, double a4) {
  // The 1999 paper's Table I (series ε = 1 - w + a2 w² - a3 w³ + a4 w⁴).
  const double d0 = a4 - 2.0 * a3 - a2 * a2 + 3.0 * a2 - 1.0;
  if (d0 == 0.0) throw InvalidInput("Padé 1999: d_0 = a4 - 2 a3 - a2² + 3 a2 - 1 vanishes");
  Pade1999 d{};
  d.d1 = (1.0 - a2 + a3 - 2.0 * a4 + (a2 - 1.0) * (3.0 * a2 - 2.0 * a3)) / d0;
  d.d2 = ((a3 - a2) * (1.0 - 2.0 * a2) - a4) / d0;
  d.d3 = (a3 + a2 * a2 * (a2 - 1.0) - a4 * (a2 + 1.0)) / d0;
  d.d4 = (a4 * (a3 - 1.0) + (a3 - a2) * (a2 * a2 - 2.0 * a3)) / d0;
  d.d5 = (2.0 * (a3 - a2) * (a4 - a2 * a3) - (a4 - a2 * a2) * (a4 - a2 * a2) - a3 * (a3 - a2 * a2)) / d0;
  return d;
}

Pade1999 pade_1999_published() {
  return pade_1999_coefficients(0.6, published::kA3, published::kA4);
}

Value pade_1999(double zeta, const Pade1999& d) {
  check_zeta(zeta);
  const double w = c1_closed_form() * zeta;
  return rational(w, std::array{1.0, d.d1}, std::array{1.0, d.d2, d.d3, d.d4, d.d5});
}

Value simple_theory_1999(double zeta) {
  check_zeta(zeta);
  const double w = c1_closed_form() * zeta;
  // u = ε^{1/5} solves f(u) = u⁵ + w u³ - 1 = 0; f is increasing and convex on u > 0 and
  // f(min(1, w^{-1/3})) >= 0, so Newton from there decreases monotonically onto the root.
  double u = w <= 1.0 ? 1.0 : std::cbrt(1.0 / w);
  for (int iteration = 0; iteration < 200; ++iteration) {
    const double u2 = u * u;
    const double f = u2 * u2 * u + w * u2 * u - 1.0;
    const double next = u - f / (5.0 * u2 * u2 + 3.0 * w * u2);
    if (!(next < u)) break;  // monotone descent has stopped: converged to rounding
    u = next;
  }
  const double u3 = u * u * u;
  return {u3 * u * u, w * u3};  // 1 - ε = w ε^{3/5}
}

Value pade_2011_1_4(double zeta) {
  check_zeta(zeta);
  return rational(std::sqrt(zeta), published::kPade2011Num14, published::kPade2011Den14);
}

Value pade_2011_3_6(double zeta) {
  check_zeta(zeta);
  return rational(std::sqrt(zeta), published::kPade2011Num36, published::kPade2011Den36);
}

}  // namespace restitution::series
