// SPDX-License-Identifier: BSD-3-Clause
// The scales of a contact law that the engines' tolerance policies need, derived from the member's
// exponents (docs/contact_laws.md): where its ends lie, how small the quantities deciding them become,
// and whether the naive end exists.
#include <algorithm>
#include <cmath>

#include "law/law_rhs.hpp"
#include "restitution/contact_law.hpp"

namespace restitution {

NaiveEndExistence ContactLaw::naive_end_existence() const {
  const double balance = naive_balance();
  if (balance > 0.0) return NaiveEndExistence::always;
  if (balance == 0.0) return NaiveEndExistence::below_critical_zeta;
  return NaiveEndExistence::decided_by_solve;
}

bool ContactLaw::naive_end_may_exist() const {
  if (naive_end_existence() != NaiveEndExistence::below_critical_zeta) return true;
  return zeta_ / critical_zeta() < 1.0;
}

double naive_end_excluded(const ContactLaw& law, double x, double v) {
  // In the region x' >= -k x^{b+1} with k = ζ/(2(b+1)), d/dτ (x' + k x^{b+1}) = k(ζ - k(b+1)) x^{2b+1} - x^a
  // on its boundary, positive while x^{a-2b-1} < ζ²/(4(b+1)): for a - 2b - 1 = -naive_balance() > 0 every
  // smaller x keeps it positive, so once x' <= 0 the state never leaves the region, where x decays at most
  // like a power or an exponential of τ and never reaches 0.
  const double zeta = law.zeta();
  const double b = law.damping_exponent();
  const double k = zeta / (2.0 * (b + 1.0));
  const double x_certified = std::pow(zeta * zeta / (4.0 * (b + 1.0)), 1.0 / -law.naive_balance());
  const double outside = -(v + k * detail::continued_power(x, b + 1.0));
  return std::max({outside, x - x_certified, v});
}

double ContactLaw::naive_end_conditioning(double naive_eps) const {
  if (naive_end_existence() != NaiveEndExistence::decided_by_solve) return 1.0;
  // Measured error of ε over tolerance ≈ 2e-3/ε at the default local tolerances: 50 ε brings it to ~0.1.
  return std::min(1.0, 50.0 * naive_eps);
}

ContactLaw::Conditioning ContactLaw::input_conditioning(EndSet ends) const {
  Conditioning c;
  c.condition = kBoundedCondition;
  if (!ends.contains(CollisionEnd::naive) ||
      naive_end_existence() != NaiveEndExistence::below_critical_zeta) {
    return c;
  }
  // ln ε = -π ζ / sqrt(D), D = 4(b+1) - ζ² (docs/contact_laws.md), so d ln ε / d ln ζ = -4π(b+1) ζ / D^{3/2}
  // = -πρ/(1-ρ²)^{3/2}. D by fma: near critical damping it is the difference of two nearly equal numbers.
  const double four_b1 = 4.0 * (b_ + 1.0);
  const double d = std::fma(-zeta_, zeta_, four_b1);
  if (d <= 0.0) return c;  // no naive end: refused before the conditioning matters
  c.condition = std::max(c.condition, M_PI * four_b1 * zeta_ / (d * std::sqrt(d)));
  c.log_eps = -M_PI * zeta_ / std::sqrt(d);
  return c;
}

double ContactLaw::indistinguishable_ends_zeta() const {
  return std::pow(1e-30, (a_ - b_) / (b_ + 1.0));
}

ResolutionScales resolution_scales(const ContactLaw& law, EndSet ends) {
  const bool naive_end = ends.contains(CollisionEnd::naive);
  ResolutionScales m;
  const double zeta = law.zeta();
  const double a = law.elastic_exponent();
  const double b = law.damping_exponent();
  if (law.kind() == LawKind::linear_dashpot) {
    // The dash-pot's own (measured, docs/accuracy.md) scales, in its damping ratio r.
    const double r = law.parameter();
    if (r > 1.0) {
      // Overdamped: x_max ~ 1/(2r) and, at the delayed-recovery end, ε ~ 1/(4 r^2) for large r.
      m.x = 1.0 / (2.0 * r);
      m.velocity = 1.0 / (4.0 * r * r);
    }
    if (naive_end && r < 1.0) {
      // The naive end is approached with x ~ ε (τ_c - τ): near critical damping (ε ~ 1e-31 at r = 0.999)
      // x must be resolved down to ε's scale, not to one.
      const double eps = std::exp(-M_PI * r / std::sqrt(1.0 - r * r));
      m.velocity = std::min(m.velocity, eps);
      m.x = std::min(m.x, eps);
    }
    m.dissipation = 1.0 / std::max(1.0, r);
    return m;
  }
  const double z = std::max(zeta, 1.0);
  // Large ζ: the damping stops the compression at x_max ~ ζ^{-1/(b+1)}; the force-zero end follows at that
  // x with x' ~ x^{a-b}/ζ ~ ζ^{-(a+1)/(b+1)} (viscoelastic Hertz: ζ^{-2/3}, ζ^{-5/3}).
  m.x = std::pow(z, -1.0 / (b + 1.0));
  m.velocity = std::pow(z, -(a + 1.0) / (b + 1.0));
  if (naive_end) {
    const double balance = law.naive_balance();
    if (balance > 0.0) {
      // The naive end is reached through the scale where x'', ζ x^b x' and x^a balance: x ~ ζ^{-2/balance},
      // x' ~ ζ^{1 - 2(1+b)/balance} (viscoelastic Hertz: ζ^{-4}, ζ^{-5}; docs/design.md §4).
      m.x = std::pow(z, -2.0 / balance);
      m.velocity = std::pow(z, 1.0 - 2.0 * (1.0 + b) / balance);
    } else if (balance == 0.0) {
      // As for the dash-pot near critical damping: resolve x and x' down to ε's scale.
      // ρ = ζ/(2 sqrt(b+1)) plays the dash-pot's damping ratio; ε = exp(-πρ/sqrt(1 - ρ²)).
      const double rho = zeta / law.critical_zeta();
      if (rho < 1.0) {
        const double eps = std::exp(-M_PI * rho / std::sqrt(1.0 - rho * rho));
        m.velocity = std::min(m.velocity, eps);
        m.x = std::min(m.x, eps);
      }
    }
  }
  m.dissipation = 1.0 / z;
  return m;
}

double ContactLaw::conditioning(EndSet ends) const {
  const bool naive_end = ends.contains(CollisionEnd::naive);
  // Near critical damping the two modes of a scale-invariant member cancel at the naive end to
  // ω = sqrt(1 - ρ²) and amplify the local errors by about 1/ω in ε (measured on the dash-pot: error ratio 10
  // at r = 0.999 and 20 at r = 0.9999 with the plain rtol).
  if (!naive_end || naive_end_existence() != NaiveEndExistence::below_critical_zeta) return 1.0;
  const double rho = kind_ == LawKind::linear_dashpot ? parameter() : zeta_ / critical_zeta();
  if (rho >= 1.0) return 1.0;
  return std::min(1.0, 0.1 * std::sqrt(1.0 - rho * rho));
}

double ContactLaw::time_limit(EndSet ends) const {
  const bool naive_end = ends.contains(CollisionEnd::naive);
  if (kind_ == LawKind::linear_dashpot) {
    const double r = parameter();
    return (naive_end && r < 1.0) ? 100.0 * (10.0 + M_PI / std::sqrt(1.0 - r * r)) : 1000.0;
  }
  // Viscoelastic Hertz's naive tail relaxes slowly over ~ζ·ln(ζ^{10/3}) (docs/design.md §4); generous
  // margin, also for the ends of the other members (their ends lie earlier or are certified absent).
  return time_scale_ * 1000.0 * (1.0 + zeta_) * (1.0 + std::log1p(zeta_));
}

}  // namespace restitution
