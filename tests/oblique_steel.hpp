// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The 1 mm steel sphere of the oblique tests (7800 kg/m³; viscoelastic Hertz k = (4/3) E* sqrt(R*) with
// E* = 1.1e11 Pa on a wall of its material, γ = (3/2) A k with A = 1e-7 s: ε = 0.9248 at 1 m/s), and the
// independent reference's problem for an impact of the library's types with LAMMPS's linear_history.
#include <numbers>

#include "oblique/oblique_contact.hpp"
#include "oblique_reference.hpp"

namespace restitution::test_support::oblique_steel {

inline constexpr double kRadius = 1e-3;                                                           // m
inline const double kMass = 4.0 / 3.0 * std::numbers::pi * kRadius * kRadius * kRadius * 7800.0;  // kg
inline constexpr double kHertzStiffness = 4.63e9;                                                 // N/m^{3/2}
inline constexpr double kHertzDamping = 694.0;  // N s/m^{3/2}

// The reference models linear_history with torque arm R and a fixed normal: the caller's geometry says which
// spheres, `normal` and `tangential` the forces (the tangential kind is not read).
inline oblique_reference::Problem reference_problem(const oblique::ObliqueGeometry& g,
                                                    const oblique::NormalForce& normal,
                                                    const oblique::TangentialForce& tangential,
                                                    const oblique::ImpactVelocity& v) {
  oblique_reference::Problem p;
  p.radius1 = g.first.radius_m;
  p.mass1 = g.first.mass_kg;
  p.inertia1 = g.first.inertia_kg_m2;
  p.wall = !g.second;
  if (g.second) {
    p.radius2 = g.second->radius_m;
    p.mass2 = g.second->mass_kg;
    p.inertia2 = g.second->inertia_kg_m2;
  }
  p.kn = normal.stiffness;
  p.gamma_n = normal.damping;
  p.kt = tangential.stiffness;
  p.gamma_t = tangential.damping_factor;
  p.mu = tangential.friction;
  p.vn = v.normal_m_s;
  p.vt = v.tangential_m_s;
  p.spin1 = v.spin_first_rad_s;
  p.spin2 = v.spin_second_rad_s;
  return p;
}

}  // namespace restitution::test_support::oblique_steel
