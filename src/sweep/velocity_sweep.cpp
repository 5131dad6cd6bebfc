// SPDX-License-Identifier: BSD-3-Clause
#include "sweep/velocity_sweep.hpp"

#include <fmt/core.h>

#include <string>
#include <utility>

#include "restitution/errors.hpp"

namespace restitution {
namespace {

void check_zeta_of_velocity(double zeta, double v, const std::string& subject) {
  if (zeta > kLargestCheckedZeta) {
    throw InvalidInput(
        fmt::format("velocity {} m/s with {} gives zeta = {:g}, outside the checked range 0 "
                    "<= zeta <= {:g}",
                    v, subject, zeta, kLargestCheckedZeta));
  }
}

}  // namespace

VelocitySweep velocity_sweep(LawKind law, const VelocitySubject& subject, std::vector<double> speeds_m_s) {
  VelocitySweep sweep;
  if (!subject.physical) sweep.columns.beta = subject.beta;
  for (const double v : speeds_m_s) {
    if (subject.physical) {
      const PhysicalCoefficients& c = *subject.physical;
      const double zeta = ContactLaw::physical(law, c.stiffness, c.damping, c.effective_mass_kg, v).zeta();
      check_zeta_of_velocity(zeta, v, "these coefficients");
      sweep.zetas.push_back(zeta);
      sweep.columns.scales.push_back(physical_scales(law, c, v));
    } else {
      const double zeta = zeta_from(subject.beta.value_or(0.0), v);
      check_zeta_of_velocity(zeta, v, fmt::format("beta {}", subject.beta.value_or(0.0)));
      sweep.zetas.push_back(zeta);
      if (subject.hertz_k) sweep.columns.scales.push_back(natural_scales(*subject.hertz_k, v));
    }
  }
  sweep.columns.velocity_m_s = std::move(speeds_m_s);
  return sweep;
}

}  // namespace restitution
