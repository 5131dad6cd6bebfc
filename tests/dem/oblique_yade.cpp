// SPDX-License-Identifier: BSD-3-Clause
// Debian's YADE (2023.02a) on oblique impacts against src/oblique/'s yade_viscel: ViscElMat with kn, cn, ks,
// cs and frictionAngle under Ip2_ViscElMat_ViscElMat_ViscElPhys and Law2_ScGeom_ViscElPhys_Basic (the
// linear dash-pot kn δ + cn δ' clamped at 0 and the shear spring ks capped at tan(frictionAngle) F_n, cs
// added below the cap), with and without cs; a 1 mm steel sphere on a `utils.wall` and two equal spheres,
// nine impact angles from nearly head-on (1°) to grazing (85°), with and without initial spin (300 rad/s).
// One scene holds one collision per angle (10 mm apart); it runs at dt = t_c/n and t_c/(10 n) (n = 20000) and
// every output is Richardson-extrapolated (YADE's leap-frog is first order in dt for these forces). e_t, the
// rebound angle and the spins agree within 1e-4 relative (1e-5 absolute where e_t is near 0); measured
// |Δe_t| <= 1.3e-8 without cs, <= 1.8e-6 with it. The wall's arm is R - δ (with R - δ/2 the wall was off by
// 3e-4 in e_t and 3e-4 relative in the spin).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "dem/oblique_runs.hpp"
#include "dem/yade_runner.hpp"
#include "oblique/oblique_contact.hpp"

namespace {

using namespace restitution;
using namespace restitution::oblique;

constexpr double kRadius = 1e-3;
constexpr double kDensity = 7800.0;
const double kMass = 4.0 / 3.0 * std::numbers::pi * kRadius * kRadius * kRadius * kDensity;
// The contact's coefficients. YADE combines two materials' values as 1/(1/a + 1/b)
// (contactParameterCalculation in ViscoelasticPM.cpp), so a material of one kind gives the contact half of
// its own: the script sets twice these.
constexpr double kNormalStiffness = 1e7;  // N/m
constexpr double kNormalDamping = 1.2;    // N s/m: ε ≈ 0.9
constexpr double kShearStiffness = 2e6;   // N/m
constexpr double kFriction = 0.3;
const std::vector<double>& kAnglesDeg = restitution::test_support::kObliqueAnglesDeg;
constexpr int kCoarseSteps = 20000;

using Outcome = restitution::test_support::ObliqueOutcome;

using restitution::test_support::impact_at;
using restitution::test_support::run_yade_oblique;

// The ViscElMat lines of the contact (the material's append, Ip2, Law2) for run_yade_oblique.
std::vector<std::string> viscel_lines(double shear_damping) {
  std::ostringstream material;
  material.precision(17);
  material << "O.materials.append(ViscElMat(kn=" << 2.0 * kNormalStiffness << ", cn=" << 2.0 * kNormalDamping
           << ", ks=" << 2.0 * kShearStiffness << ", cs=" << 2.0 * shear_damping
           << ", frictionAngle=math.atan(" << kFriction << "), density=" << kDensity << "))";
  return {material.str(), "Ip2_ViscElMat_ViscElMat_ViscElPhys()", "Law2_ScGeom_ViscElPhys_Basic()"};
}

// (wall, shear damping cs [N s/m], initial spin [rad/s])
class ObliqueYade : public ::testing::TestWithParam<std::tuple<bool, double, double>> {};

TEST_P(ObliqueYade, ImpactsAgreeWithin1e4) {
  const auto [wall, shear_damping, spin] = GetParam();
  const std::string program = dem::yade_program();
  ASSERT_FALSE(program.empty()) << "yade not found on PATH: scripts/setup installs Debian's yade";
  // The arms, in the torque and the contact-point velocity, reach ScGeom's contact point: halfway through
  // the overlap for two spheres, R - δ/2 (Ig2_Sphere_Sphere_ScGeom), the centre projected onto the wall, R -
  // δ (Ig2_Wall_Sphere_ScGeom).
  const TorqueArm arm = wall ? TorqueArm::radius_minus_overlap : TorqueArm::radius_minus_half_overlap;
  ObliqueGeometry geometry{solid_sphere(kRadius, kMass), std::nullopt, arm};
  geometry.contact_point_arm = arm;
  if (!wall) geometry.second = solid_sphere(kRadius, kMass);
  ObliqueOptions options;
  options.relative_tolerance = 1e-12;
  options.end = CollisionEnd::delayed_recovery;  // YADE zeroes an attractive normal force
  const NormalForce normal{LawKind::linear_dashpot, kNormalStiffness, kNormalDamping};
  const TangentialForce tangential{TangentialKind::yade_viscel, kShearStiffness,
                                   shear_damping / kNormalDamping, kFriction};
  std::vector<ObliqueResult> predicted;
  double shortest = 1.0;
  double longest = 0.0;
  for (const double angle : kAnglesDeg) {
    predicted.push_back(solve_oblique(geometry, normal, tangential, impact_at(angle, spin), options));
    shortest = std::min(shortest, predicted.back().contact_time_s);
    longest = std::max(longest, predicted.back().contact_time_s);
  }
  const double dt = shortest / kCoarseSteps;
  const auto coarse =
      run_yade_oblique(program, viscel_lines(shear_damping), kAnglesDeg, wall, spin, dt, 1.1 * longest);
  const auto fine = run_yade_oblique(program, viscel_lines(shear_damping), kAnglesDeg, wall, spin, dt / 10.0,
                                     1.1 * longest);
  double largest = 0.0;
  for (std::size_t i = 0; i < kAnglesDeg.size(); ++i) {
    const std::string label = std::string(wall ? "wall" : "pair") + ", cs " + std::to_string(shear_damping) +
                              " at " + std::to_string(kAnglesDeg[i]) + " deg, spin " + std::to_string(spin);
    largest = std::max(largest, restitution::test_support::expect_extrapolated_agreement(
                                    coarse[i], fine[i], predicted[i], !wall, kRadius, label));
  }
  restitution::test_support::record_largest_et_difference(largest);
}

INSTANTIATE_TEST_SUITE_P(Cases, ObliqueYade,
                         ::testing::Combine(::testing::Bool(), ::testing::Values(0.0, 0.6),
                                            ::testing::Values(0.0, 300.0)));

}  // namespace
