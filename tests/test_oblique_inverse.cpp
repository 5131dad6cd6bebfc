// SPDX-License-Identifier: BSD-3-Clause
// The inverse of the oblique solve (src/oblique/oblique_inverse.hpp): the k_t (linear_history, mindlin) or
// γ_t (linear_nohistory) it finds, fed back into the solve, gives the requested e_t within the tolerance; for
// linear_history also in the independent reference (tests/oblique_reference.hpp); a target out of the
// model's reach is refused naming the reachable range.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "oblique/oblique_inverse.hpp"
#include "oblique_reference.hpp"
#include "oblique_steel.hpp"
#include "restitution/errors.hpp"

namespace {

using namespace restitution;
using namespace restitution::oblique;

using namespace restitution::test_support::oblique_steel;  // kRadius, kMass, kHertzStiffness, kHertzDamping

TangentialInverseRequest request_for(TangentialKind kind, bool pair, double angle_deg, double target) {
  TangentialInverseRequest r;
  r.geometry = {solid_sphere(kRadius, kMass), std::nullopt, TorqueArm::radius};
  if (pair) {
    r.geometry.second = solid_sphere(kRadius, kMass);
    r.geometry.torque_arm = TorqueArm::radius_minus_half_overlap;  // LAMMPS's pair
  }
  r.normal = {LawKind::viscoelastic_hertz, kHertzStiffness, kHertzDamping};
  r.tangential = {kind, 0.0, kind == TangentialKind::linear_nohistory ? 0.0 : 0.5, 0.3};
  const double a = angle_deg * std::numbers::pi / 180.0;
  r.impact = {std::cos(a), std::sin(a), 0.0, 0.0};
  r.target_et = target;
  return r;
}

struct Case {
  TangentialKind kind;
  bool pair;
  double angle_deg;
  double target;
  double tolerance;
};

class ObliqueInverse : public ::testing::TestWithParam<Case> {};

TEST_P(ObliqueInverse, ParameterFedBackGivesTheTarget) {
  const Case& c = GetParam();
  TangentialInverseRequest request = request_for(c.kind, c.pair, c.angle_deg, c.target);
  request.tolerance = c.tolerance;
  const TangentialInverseResult found = tangential_parameter_for(request);
  ASSERT_GT(found.parameter, 0.0);
  EXPECT_LE(found.lowest_reachable_et, c.target);
  EXPECT_GE(found.highest_reachable_et, c.target);
  // Fed back through the contracted solve, apart from the inverse's own solves.
  TangentialForce t = request.tangential;
  (c.kind == TangentialKind::linear_nohistory ? t.damping_factor : t.stiffness) = found.parameter;
  const ContractedOblique again =
      solve_oblique_within(request.geometry, request.normal, t, request.impact, c.tolerance);
  EXPECT_FALSE(again.ill_conditioned) << again.conditioning;
  EXPECT_NEAR(again.result.tangential_restitution, c.target, c.tolerance);
  if (c.kind == TangentialKind::linear_history && !c.pair) {
    // The independent reference with the k_t found (torque arm R, a wall: its own model).
    const oblique_reference::Problem p =
        reference_problem(request.geometry, request.normal, t, request.impact);
    oblique_reference::Integrator reference(p);
    const oblique_reference::Outcome o = reference.run(again.result.contact_time_s / 2e4);
    EXPECT_NEAR(static_cast<double>(-o.slip_final / o.slip_initial), c.target, c.tolerance);
  }
}

INSTANTIATE_TEST_SUITE_P(Models, ObliqueInverse,
                         ::testing::Values(Case{TangentialKind::linear_history, false, 20.0, 0.3, 1e-8},
                                           Case{TangentialKind::linear_history, false, 30.0, 0.0, 1e-6},
                                           Case{TangentialKind::linear_history, false, 10.0, 0.5, 1e-10},
                                           Case{TangentialKind::mindlin, true, 20.0, 0.3, 1e-8},
                                           Case{TangentialKind::mindlin, false, 15.0, 0.4, 1e-8},
                                           Case{TangentialKind::linear_nohistory, false, 20.0, -0.2, 1e-8},
                                           Case{TangentialKind::linear_nohistory, true, 30.0, -0.5, 1e-8}));

TEST(ObliqueInverse, RefusesAnUnreachableTargetNamingTheRange) {
  for (const TangentialKind kind :
       {TangentialKind::linear_history, TangentialKind::mindlin, TangentialKind::linear_nohistory}) {
    try {
      tangential_parameter_for(request_for(kind, false, 20.0, 0.99));
      ADD_FAILURE() << tangential_name(kind) << " reached e_t = 0.99";
    } catch (const InvalidInput& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find("out of reach"), std::string::npos) << message;
      EXPECT_NE(message.find("gives e_t in ["), std::string::npos) << message;
    }
  }
}

TEST(ObliqueInverse, RefusesWhatNoParameterCanDo) {
  TangentialInverseRequest frictionless = request_for(TangentialKind::linear_history, false, 20.0, 0.3);
  frictionless.tangential.friction = 0.0;
  EXPECT_THROW(tangential_parameter_for(frictionless), InvalidInput);
  TangentialInverseRequest undamped = request_for(TangentialKind::linear_nohistory, false, 20.0, 0.3);
  undamped.normal.damping = 0.0;
  EXPECT_THROW(tangential_parameter_for(undamped), InvalidInput);
  TangentialInverseRequest head_on = request_for(TangentialKind::linear_history, false, 0.0, 0.3);
  EXPECT_THROW(tangential_parameter_for(head_on), InvalidInput);
  TangentialInverseRequest loose = request_for(TangentialKind::linear_history, false, 20.0, 0.3);
  loose.tolerance = 0.1;
  EXPECT_THROW(tangential_parameter_for(loose), InvalidInput);
}

}  // namespace
