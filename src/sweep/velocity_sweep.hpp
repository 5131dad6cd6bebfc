// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// An ε(v) sweep's grid (`restitution sweep --velocity-range`): the ζ of each impact speed and the table's
// columns after ζ, for β (viscoelastic Hertz, with a material's k also the SI columns) or for the physical
// coefficients of ContactLaw::physical (every law).
#include <optional>
#include <vector>

#include "restitution/contact_law.hpp"
#include "restitution/sweep.hpp"
#include "restitution/units.hpp"

namespace restitution {

// Exactly one of `beta` and `physical`; `hertz_k` [s^-2 m^-1/2] only with `beta`.
struct VelocitySubject {
  std::optional<double> beta;  // s^{1/5} m^{-1/5}
  std::optional<double> hertz_k;
  std::optional<PhysicalCoefficients> physical;
};

struct VelocitySweep {
  std::vector<double> zetas;  // of the law's natural form, parallel to columns.velocity_m_s
  SweepColumns columns;       // β only for the β form; scales with hertz_k or the physical coefficients
};

// Throws InvalidInput naming the first speed whose ζ is beyond kLargestCheckedZeta ("velocity V m/s with beta
// B gives zeta = Z, outside the checked range ...", "with these coefficients" for the physical form).
VelocitySweep velocity_sweep(LawKind law, const VelocitySubject& subject, std::vector<double> speeds_m_s);

}  // namespace restitution
