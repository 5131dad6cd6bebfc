// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The contact law of the gas's collisions (docs/gas.md): one member of the contact-law family with its ζ at
// one impact speed, or a constant ε. What a front end gives; gas/impact_law.hpp turns it into 1 − ε(u)².
#include <optional>

#include "restitution/collision_solver.hpp"
#include "restitution/contact_law.hpp"

namespace restitution::gas {

struct ImpactLaw {
  LawKind kind = LawKind::viscoelastic_hertz;
  double zeta_at_reference = 0.0;    // ζ of the natural form at reference_speed_m_s
  double reference_speed_m_s = 1.0;  // v_ref [m/s]
  CollisionEnd end = CollisionEnd::delayed_recovery;
  // Set: ε is this constant at every speed (Haff's gas); kind and ζ are then unused.
  std::optional<double> constant_eps;
};

// Viscoelastic Hertz with ζ = β u^{1/5} (β in s^{1/5} m^{-1/5}, units.hpp).
ImpactLaw hertz_impact_law(double beta, CollisionEnd end);
// The member `kind` calibrated so that ε(velocity_m_s) = eps (InvalidInput naming eps or velocity).
ImpactLaw impact_law_from_eps(LawKind kind, double eps, double velocity_m_s, CollisionEnd end,
                              double tolerance = SolveOptions{}.tolerance);
// ε = eps at every speed, eps in (0, 1].
ImpactLaw constant_eps_law(double eps);

}  // namespace restitution::gas
