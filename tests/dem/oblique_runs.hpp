// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// What the oblique-impact checks against the DEM codes share (tests/dem/oblique_*.cpp): the impact angles, an
// impact's outputs as a code reports them, the impact velocity of a unit speed, Richardson's extrapolation of
// a first-order integrator and the record of the largest e_t difference.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <numbers>
#include <sstream>
#include <vector>

#include "oblique/oblique_contact.hpp"

namespace restitution::test_support {

// Nearly head-on to grazing, degrees from the normal.
inline const std::vector<double> kObliqueAnglesDeg{1.0, 5.0, 10.0, 20.0, 30.0, 45.0, 60.0, 75.0, 85.0};

// One impact as a code reports it: e_t, the rebound angle (degrees) and the spins (rad/s, ours: -ω_y).
struct ObliqueOutcome {
  double et = 0.0, rebound_deg = 0.0, spin = 0.0, spin2 = 0.0;
};

// Speed 1 m/s at angle_deg from the normal, the first sphere spinning at spin_rad_s.
inline oblique::ImpactVelocity impact_at(double angle_deg, double spin_rad_s) {
  const double a = angle_deg * std::numbers::pi / 180.0;
  return {std::cos(a), std::sin(a), spin_rad_s, 0.0};
}

// The dt → 0 limit of a first-order integrator from runs at dt (coarse) and dt/10 (fine).
inline double extrapolate_first_order(double coarse, double fine) {
  return fine + (fine - coarse) / 9.0;
}

// The largest |e_t difference| of a test, in its XML record and on stdout.
inline void record_largest_et_difference(double largest) {
  std::ostringstream text;
  text << std::scientific << largest;
  testing::Test::RecordProperty("largest_et_difference", text.str());
  std::cout << "largest |e_t difference|: " << text.str() << "\n";
}

}  // namespace restitution::test_support
