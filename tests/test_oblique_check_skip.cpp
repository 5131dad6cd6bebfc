// SPDX-License-Identifier: BSD-3-Clause
// The accuracy contract skips its check where the solve's stick/slip sequence keeps a margin and the slip at
// impact is not small (src/oblique/oblique_accuracy.hpp, kCheckMargin and kCheckSlip). Over a sweep of
// LAMMPS's six models and LIGGGHTS's (wall, and a pair as the code has it), spins 0 and ±300 rad/s and
// T = 1e-4, 1e-6, 1e-8,
// every impact whose check is skipped is one the check, run anyway, passes, and is within T (with a margin)
// of the library's own solve at rtol 1e-13; most impacts skip it (what pays for the contract's speed); and
// every impact, checked or not, is within T of that solve or flagged.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "oblique/oblique_accuracy.hpp"
#include "oblique_steel.hpp"

namespace {

using namespace restitution;
using namespace restitution::oblique;
using namespace restitution::test_support::oblique_steel;  // kRadius, kMass, kHertzStiffness, kHertzDamping

// The largest difference of the contract's outputs over their bounds (oblique_accuracy.hpp), a wall's or the
// first sphere's spin.
double error_over_tolerance(const ObliqueResult& a, const ObliqueResult& b, const ImpactVelocity& v,
                            double tolerance) {
  const double speed = std::hypot(v.normal_m_s, v.tangential_m_s);
  double r = std::max(std::abs(a.normal_restitution - b.normal_restitution),
                      std::abs(a.rebound_angle_rad - b.rebound_angle_rad));
  if (std::isfinite(b.tangential_restitution)) {
    r = std::max(r, std::abs(a.tangential_restitution - b.tangential_restitution));
  }
  r = std::max(r, std::abs(a.spin_first_rad_s - b.spin_first_rad_s) /
                      std::max(std::abs(b.spin_first_rad_s), speed / kRadius));
  return r / tolerance;
}

TEST(ObliqueCheckSkip, SkippedImpactsAreOnesTheCheckPassesAndWithinTheTolerance) {
  const NormalForce normal{LawKind::viscoelastic_hertz, kHertzStiffness, kHertzDamping};
  int impacts = 0;
  int skipped = 0;
  int flagged = 0;
  double worst = 0.0;
  for (const TangentialKind kind :
       {TangentialKind::linear_history, TangentialKind::mindlin, TangentialKind::linear_nohistory,
        TangentialKind::mindlin_rescale, TangentialKind::mindlin_force, TangentialKind::mindlin_rescale_force,
        TangentialKind::liggghts_history}) {
    // k_t of the models per sqrt(R* δ) in N/m², the others' in N/m.
    const bool per_contact_radius = is_lammps_mindlin(kind) || kind == TangentialKind::liggghts_history;
    const TangentialForce tangential{kind, per_contact_radius ? 8e10 : 2.2e6, 0.5, 0.3};
    const bool liggghts = kind == TangentialKind::liggghts_history;
    // The _rescale variants are always checked (oblique_accuracy.cpp, needs_check).
    const bool always_checked =
        kind == TangentialKind::mindlin_rescale || kind == TangentialKind::mindlin_rescale_force;
    for (const bool pair : {false, true}) {
      // Each code's arms (oblique_contact.hpp): LAMMPS R (wall) or R - δ/2 (pair's torque), LIGGGHTS R - δ/2.
      ObliqueGeometry g{solid_sphere(kRadius, kMass), std::nullopt, TorqueArm::radius};
      if (pair) {
        g.second = solid_sphere(2.0 * kRadius, 8.0 * kMass);
        g.torque_arm = TorqueArm::radius_minus_half_overlap;
      }
      if (liggghts) g.torque_arm = g.contact_point_arm = TorqueArm::radius_minus_half_overlap;
      for (const double spin : {0.0, 300.0, -300.0}) {
        for (double angle = 0.3; angle < 89.8; angle += 1.1) {
          const ImpactVelocity v{1.0, std::tan(angle * std::numbers::pi / 180.0), spin, 0.0};
          ObliqueOptions tight;
          tight.relative_tolerance = 1e-13;
          const ObliqueResult reference = solve_oblique(g, normal, tangential, v, tight);
          for (const double tolerance : {1e-4, 1e-6, 1e-8}) {
            const std::string label = std::string(tangential_name(kind)) + (pair ? " pair " : " wall ") +
                                      std::to_string(angle) + " deg, spin " + std::to_string(spin) +
                                      ", T = " + std::to_string(tolerance);
            const ContractedOblique s = solve_oblique_within(g, normal, tangential, v, tolerance);
            const double error = error_over_tolerance(s.result, reference, v, tolerance);
            // The contract itself, checked or not: within T, or flagged.
            if (!s.ill_conditioned) EXPECT_LE(error, 1.0) << label << (s.checked ? " (checked)" : "");
            if (s.ill_conditioned) ++flagged;
            if (always_checked) {
              EXPECT_TRUE(s.checked) << label;
              continue;
            }
            ++impacts;
            if (s.checked) continue;
            ++skipped;
            EXPECT_FALSE(s.ill_conditioned) << label;
            const ContractedOblique always =
                solve_oblique_within(g, normal, tangential, v, tolerance, {}, ObliqueCheck::always);
            EXPECT_FALSE(always.ill_conditioned) << label << ": " << always.conditioning;
            EXPECT_LE(error, 0.2) << label;
            worst = std::max(worst, error);
          }
        }
      }
    }
  }
  EXPECT_GT(skipped, impacts * 8 / 10) << skipped << " of " << impacts << " skipped the check";
  RecordProperty("skipped", skipped);
  RecordProperty("impacts", impacts);
  RecordProperty("flagged", flagged);
  RecordProperty("worst_error_over_T", std::to_string(worst));
}

// The impacts the check is for still get it: a short stick phase near the stick/slip boundary (18.2° on a
// steel wall, the boundary of tests/test_oblique_accuracy.cpp) and a slip at impact of 1.4e-5 m/s (16.7°
// against 300 rad/s of backspin: e_t = -s'/s divides by it).
TEST(ObliqueCheckSkip, NearTheBoundaryOrWithASmallSlipTheCheckRuns) {
  const NormalForce normal{LawKind::viscoelastic_hertz, kHertzStiffness, kHertzDamping};
  const TangentialForce tangential{TangentialKind::linear_history, 2.2e6, 0.5, 0.3};
  const ObliqueGeometry wall{solid_sphere(kRadius, kMass), std::nullopt, TorqueArm::radius};
  const auto impact = [](double angle_deg, double spin) {
    return ImpactVelocity{1.0, std::tan(angle_deg * std::numbers::pi / 180.0), spin, 0.0};
  };
  const ContractedOblique small_slip =
      solve_oblique_within(wall, normal, tangential, impact(16.7, -300.0), 1e-8);
  EXPECT_TRUE(small_slip.checked);
  int checked_near_boundary = 0;
  for (double angle = 18.195; angle < 18.215; angle += 0.001) {
    const ContractedOblique s = solve_oblique_within(wall, normal, tangential, impact(angle, 0.0), 1e-8);
    if (s.checked) ++checked_near_boundary;
    if (s.result.switch_margin <= kCheckMargin) EXPECT_TRUE(s.checked) << angle;
  }
  EXPECT_GT(checked_near_boundary, 0);
}

}  // namespace
