// SPDX-License-Identifier: BSD-3-Clause
// Evaluators of the truncated series, closed forms of the undamped collision, approximation names.
#include <cmath>
#include <numbers>
#include <span>

#include "restitution/errors.hpp"
#include "restitution/series.hpp"
#include "series/arguments.hpp"

namespace restitution::series {
namespace {

using detail::check_zeta;

std::span<const double> as_span(CoefficientSpan coefficients) {
  return {coefficients.data(), coefficients.size()};
}

// Σ_{k>=1} coef[k-1] x^k by Horner, no constant term.
double horner_without_constant(double x, std::span<const double> coef) {
  double acc = 0.0;
  for (auto it = coef.rbegin(); it != coef.rend(); ++it) acc = (acc + *it) * x;
  return acc;
}

}  // namespace

double c1_closed_form() {
  return std::sqrt(std::numbers::pi) / (std::pow(2.0, 0.2) * std::pow(5.0, 0.4)) * std::tgamma(0.6) /
         std::tgamma(2.1);
}

double undamped_max_time() {
  return std::pow(0.8, 0.6) * std::tgamma(0.4) * std::sqrt(std::numbers::pi) / (2.0 * std::tgamma(0.9));
}

double undamped_max_compression() {
  return std::pow(1.25, 0.4);
}

Value naive_series(double zeta, CoefficientSpan c) {
  check_zeta(zeta);
  const double correction = horner_without_constant(zeta, as_span(c));  // ε - 1
  return {1.0 + correction, -correction};
}

Value delayed_recovery_series(double zeta, CoefficientSpan h) {
  check_zeta(zeta);
  const std::span<const double> terms = as_span(h);
  if (terms.empty()) throw InvalidInput("the delayed-recovery series needs h_0");
  const double correction = horner_without_constant(std::sqrt(zeta), terms.subspan(1));
  return {terms[0] + correction, (1.0 - terms[0]) - correction};
}

double power_series(double zeta, CoefficientSpan coefficients) {
  check_zeta(zeta);
  const std::span<const double> coef = as_span(coefficients);
  if (coef.empty()) return 0.0;
  return coef[0] + horner_without_constant(zeta, coef.subspan(1));
}

double implied_large_zeta_exponent(Approximation a) {
  switch (a) {
    case Approximation::pade_1999:  // (d1 w)/(d5 w⁴)
    case Approximation::pade_1999_corrected:
      return -3.0;
    case Approximation::simple_theory_1999:  // ε^{1/5} -> w^{-1/3}
      return -5.0 / 3.0;
    case Approximation::pade_2011_1_4:  // σ/σ⁴ and σ³/σ⁶ in σ = sqrt(ζ)
    case Approximation::pade_2011_3_6:
      return -1.5;
    case Approximation::naive_series:
    case Approximation::delayed_recovery_series:
      break;
  }
  return std::nan("");  // a truncated series grows like its last term
}

}  // namespace restitution::series
