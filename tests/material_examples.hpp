// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The rubber-like pair of spheres of the shipped scenes (scenes/material_sweep.toml): Y = 10 MPa, ν = 0.45,
// 1100 kg/m³, R = 1 cm, A = 5.8e-5 s, which makes β ≈ 0.2 s^{1/5} m^{-1/5} (the 2008 paper's example).
#include "restitution/material.hpp"

namespace restitution::test_support {

inline Material rubber_like() {
  Material m;
  m.young_modulus_pa = 1e7;
  m.poisson_ratio = 0.45;
  m.density_kg_m3 = 1100.0;
  m.radius1_m = m.radius2_m = 0.01;
  m.dissipative_constant_s = 5.8e-5;
  return m;
}

// The same material as a scene's [materials.rubber] table.
inline constexpr const char* kRubberLikeToml = R"([materials.rubber]
young_modulus = 1e7
poisson_ratio = 0.45
density = 1100.0
radius = 0.01
dissipative_constant = 5.8e-5
)";

}  // namespace restitution::test_support
