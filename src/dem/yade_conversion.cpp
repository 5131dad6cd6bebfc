// SPDX-License-Identifier: BSD-3-Clause
#include "dem/yade_conversion.hpp"

#include <fmt/core.h>

#include <cfloat>
#include <cmath>

#include "restitution/errors.hpp"
#include "restitution/series.hpp"
#include "restitution/units.hpp"
#include "series/published_tables.hpp"

namespace restitution::dem {
namespace {

struct ValueAndSlope {
  double value = 0.0;
  double slope = 0.0;
};

// A polynomial in σ with ascending coefficients, and its derivative (Horner).
template <std::size_t N>
ValueAndSlope polynomial(double sigma, const std::array<double, N>& coef) {
  ValueAndSlope p;
  for (auto it = coef.rbegin(); it != coef.rend(); ++it) {
    p.slope = p.slope * sigma + p.value;
    p.value = p.value * sigma + *it;
  }
  return p;
}

}  // namespace

double yade_sigma(double en) {
  if (!std::isfinite(en) || en <= 0.0 || en > 1.0) {
    throw InvalidInput(fmt::format("yade: en must be in (0, 1], got {}", en));
  }
  if (en == 1.0) return 0.0;
  namespace pub = series::published;
  double sigma = 0.5;
  for (int i = 0; i < 1000; ++i) {
    const ValueAndSlope n = polynomial(sigma, pub::kPade2011Num36);
    const ValueAndSlope d = polynomial(sigma, pub::kPade2011Den36);
    const double residual = n.value / d.value - en;
    if (std::fabs(residual) <= DBL_EPSILON) break;
    sigma -= residual / ((n.slope * d.value - n.value * d.slope) / (d.value * d.value));
  }
  return sigma;
}

double yade_dissipative_constant(double en, double vn_m_s, double k) {
  if (!std::isfinite(vn_m_s) || vn_m_s <= 0.0) {
    throw InvalidInput(fmt::format("yade: vn must be finite and > 0, got {}", vn_m_s));
  }
  const double sigma = yade_sigma(en);
  // YADE's β = σ² vn^{-1/5} is the law's β = (3/2) A k^{2/5} (units.hpp), so A follows from it.
  return dissipative_constant_from(sigma * sigma * std::pow(vn_m_s, -0.2), k);
}

}  // namespace restitution::dem
