// SPDX-License-Identifier: BSD-3-Clause
#include "restitution/contact_law.hpp"

#include <fmt/core.h>

#include <cmath>
#include <string>

#include "law/law_rhs.hpp"
#include "restitution/errors.hpp"

namespace restitution {
namespace {

void require_finite_nonnegative(double value, const char* name) {
  if (!std::isfinite(value) || value < 0.0) {
    throw InvalidInput(fmt::format("{} must be finite and >= 0, got {}", name, value));
  }
}

void require_finite_positive(double value, const char* name) {
  if (!std::isfinite(value) || value <= 0.0) {
    throw InvalidInput(fmt::format("{} must be finite and > 0, got {}", name, value));
  }
}

// The smallest q with q·a and q·b integers (the exponents are rational with small denominators).
int smoothing_root_of(const LawExponents& e) {
  for (int q = 1; q <= 64; ++q) {
    const double qa = q * e.elastic;
    const double qb = q * e.damping;
    if (qa == std::round(qa) && qb == std::round(qb)) return q;
  }
  throw InvalidInput(fmt::format("the exponents a={} b={} are not rationals with a denominator <= 64",
                                 e.elastic, e.damping));
}

}  // namespace

void require_checked_zeta(double zeta) {
  require_finite_nonnegative(zeta, "zeta");
  if (zeta > kLargestCheckedZeta) {
    throw InvalidInput(
        fmt::format("zeta = {} is outside the checked range 0 <= zeta <= {:g}", zeta, kLargestCheckedZeta));
  }
  require_served_zeta(zeta);
}

void require_served_zeta(double zeta) {
  if (zeta > 0.0 && zeta < kSmallestServedZeta) {
    throw InvalidInput(fmt::format(
        "zeta = {} is below the smallest zeta served, {} (the smallest normal double): 1 - eps ~ zeta would "
        "be a subnormal double, too coarse to carry the tolerance; give zeta = 0 (eps = 1 exactly) or zeta "
        ">= "
        "{}",
        zeta, kSmallestServedZeta, kSmallestServedZeta));
  }
}

ContactLaw::ContactLaw(LawKind kind, double zeta) : kind_(kind), zeta_(zeta), damping_(zeta) {
  const LawExponents e = law_exponents(kind);
  a_ = e.elastic;
  b_ = e.damping;
  q_ = smoothing_root_of(e);
  energy_coefficient_ = 1.0 / (a_ + 1.0);
}

ContactLaw ContactLaw::natural(LawKind kind, double zeta) {
  // ζ = 0, every member: the undamped oscillator, ε = 1 at both ends (docs/contact_laws.md).
  require_finite_nonnegative(zeta, "zeta");
  return {kind, zeta};
}

double physical_time_scale_s(LawKind kind, double stiffness_N_per_m_a, double effective_mass_kg,
                             double impact_speed_m_s) {
  const double a = law_exponents(kind).elastic;
  return std::pow(std::pow(impact_speed_m_s, 1.0 - a) * effective_mass_kg / stiffness_N_per_m_a,
                  1.0 / (1.0 + a));
}

ContactLaw ContactLaw::physical(LawKind kind, double stiffness_N_per_m_a, double damping_coefficient,
                                double effective_mass_kg, double impact_speed_m_s) {
  require_finite_positive(stiffness_N_per_m_a, "stiffness");
  require_finite_nonnegative(damping_coefficient, "damping coefficient");
  require_finite_positive(effective_mass_kg, "effective mass");
  require_finite_positive(impact_speed_m_s, "impact speed");
  const double b = law_exponents(kind).damping;
  const double time_scale_s =
      physical_time_scale_s(kind, stiffness_N_per_m_a, effective_mass_kg, impact_speed_m_s);
  const double zeta = damping_coefficient / effective_mass_kg * std::pow(impact_speed_m_s, b) *
                      std::pow(time_scale_s, b + 1.0);
  if (!std::isfinite(zeta) || !(time_scale_s > 0.0)) {
    throw InvalidInput(fmt::format(
        "stiffness={}, damping coefficient={}, mass={} kg and speed={} m/s give a natural zeta outside the "
        "range of double",
        stiffness_N_per_m_a, damping_coefficient, effective_mass_kg, impact_speed_m_s));
  }
  return natural(kind, zeta);
}

ContactLaw ContactLaw::of_parameter(LawKind kind, double parameter) {
  const LawParameter p = law_parameter(kind);
  if (p.zeta_per_parameter == 1.0) return natural(kind, parameter);
  require_finite_nonnegative(parameter, p.name);
  return natural(kind, p.zeta_per_parameter * parameter);
}

ContactLaw ContactLaw::hertz_natural(double zeta) {
  require_finite_nonnegative(zeta, "zeta");
  return {LawKind::viscoelastic_hertz, zeta};
}

ContactLaw ContactLaw::hertz_scaled(double beta, double velocity) {
  require_finite_nonnegative(beta, "beta");
  require_finite_positive(velocity, "velocity");
  // ζ = β v^{1/5} (units.hpp's zeta_from, which stands above the law and does not serve it).
  ContactLaw law(LawKind::viscoelastic_hertz, beta * std::pow(velocity, 0.2));
  law.damping_ = beta * std::pow(velocity, -0.2);
  law.stiffness_ = std::pow(velocity, -0.4);
  law.initial_velocity_ = std::pow(velocity, 0.8);
  if (!std::isfinite(law.damping_) || !std::isfinite(law.stiffness_) || law.initial_velocity_ <= 0.0 ||
      !std::isfinite(law.initial_velocity_) || !std::isfinite(law.zeta_)) {
    throw InvalidInput(fmt::format(
        "beta={} and velocity={} give a scaled equation outside the range of double", beta, velocity));
  }
  // x scales as v^{4/5}; τ is the same in both forms (x = v^{4/5} X turns Eq. 23 into the natural form).
  law.length_scale_ = law.initial_velocity_;
  return law;
}

ContactLaw ContactLaw::linear_dashpot(double damping_ratio) {
  return of_parameter(LawKind::linear_dashpot, damping_ratio);
}

ContactLaw ContactLaw::unchecked(LawKind kind, double damping, double stiffness) {
  ContactLaw law(kind, damping);
  law.stiffness_ = stiffness;
  return law;
}

ContactLaw ContactLaw::natural_form() const {
  return {kind_, zeta_};
}

double ContactLaw::shape(double x) const {
  return law_rhs::shape(*this, x);
}
double ContactLaw::force_factor(double x, double v) const {
  return law_rhs::force_factor(*this, x, v);
}
double ContactLaw::acceleration(double x, double v) const {
  return law_rhs::acceleration(*this, x, v);
}
double ContactLaw::dissipation_integrand(double x, double v) const {
  return law_rhs::dissipation_integrand(*this, x, v);
}

double ContactLaw::elastic_energy(double x) const {
  if (x <= 0.0) return 0.0;
  return stiffness_ * energy_coefficient_ * x * x * detail::positive_power(x, a_ - 1.0);
}

double ContactLaw::force_zero_compression(double velocity) const {
  return detail::positive_power(damping_ * -velocity / stiffness_, 1.0 / (a_ - b_));
}

EndValues ContactLaw::end_values(double x, double velocity, double dissipation_integral) const {
  const double v0 = initial_velocity_;
  const double eps_from_velocity = -velocity / v0;
  if (eps_from_velocity > 0.5) {
    const double one_minus_eps_squared =
        2.0 * (damping_ * dissipation_integral + elastic_energy(x)) / (v0 * v0);
    const double one_minus_eps = one_minus_eps_squared / (1.0 + eps_from_velocity);
    return {1.0 - one_minus_eps, one_minus_eps};
  }
  return {eps_from_velocity, 1.0 - eps_from_velocity};
}

}  // namespace restitution
