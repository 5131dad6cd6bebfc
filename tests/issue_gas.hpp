// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Issue 35's gas, written once for the tests and the benchmarks: Y = 1e8 Pa, nu = 0.4, rho = 920 kg/m^3,
// R = 5 mm, eps = 0.8 at 2 m/s (the viscoelastic law calibrated there), packing fraction 0.1. The caller adds
// the number of spheres, the initial temperature and the span of time it needs.
#include "gas_deck/lammps_gas_deck.hpp"

namespace restitution::test_support {

inline gas_deck::GasDeckRequest issue_gas() {
  gas_deck::GasDeckRequest r;
  r.material.young_modulus_pa = 1e8;
  r.material.poisson_ratio = 0.4;
  r.material.density_kg_m3 = 920.0;
  r.material.radius1_m = r.material.radius2_m = 0.005;
  r.damping.eps = 0.8;
  r.damping.velocity_m_s = 2.0;
  r.packing_fraction = 0.1;
  return r;
}

}  // namespace restitution::test_support
