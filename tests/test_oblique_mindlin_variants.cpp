// SPDX-License-Identifier: BSD-3-Clause
// LAMMPS's incremental Mindlin variants (mindlin_rescale, mindlin/force, mindlin_rescale/force) against what
// is exact about them (docs/oblique.md): while the contact loads (a grows) the _rescale variants do nothing,
// so each is its base model until maximal compression (mindlin/force is not mindlin there: mindlin's -κξ
// grows with κ at a fixed ξ, the incremental H' = -κ s does not); and the elastic contact slides throughout
// from where the slip's h stays below 0 to the end, ψ₁ = 4χ − (2/3)c with c the factor on μ F_n' in h at δ →
// 0: 1 for mindlin, 3/2 for mindlin/force (no κ'/κ term: Maw, Barber & Fawcett's incremental −1 and 4χ − 1),
// 1/2 for mindlin_rescale (κ'/κ + a'/a) and 1 for mindlin_rescale/force (a'/a). The gross-slip closed form,
// the frictionless contact and the accuracy contract cover them with the other models
// (tests/test_oblique.cpp, tests/test_oblique_accuracy.cpp), `dem --tangential`
// tests/test_dem_tangential.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "oblique/oblique_contact.hpp"
#include "oblique_steel.hpp"
#include "restitution_oblique/oblique_study.hpp"

namespace {

using namespace restitution;
using namespace restitution::oblique;
using namespace restitution::test_support::oblique_steel;  // kRadius, kMass, kHertzStiffness

constexpr double kDegree = std::numbers::pi / 180.0;

struct Onset {
  const char* model;
  double end_factor;  // c: the factor on μ F_n' in the slip's h at the end of the contact
};

class MindlinGrossSlipOnset : public ::testing::TestWithParam<Onset> {};

TEST_P(MindlinGrossSlipOnset, IsWhereTheEndOfContactKeepsSliding) {
  const Onset onset_case = GetParam();
  ObliqueInputs in;
  in.material.young_modulus_pa = 2e11;
  in.material.poisson_ratio = 0.3;
  in.material.radius1_m = in.material.radius2_m = 1e-3;
  in.material.density_kg_m3 = 7800.0;
  in.dissipative_constant_s = 0.0;  // elastic
  in.wall = true;
  in.tangential = onset_case.model;
  in.friction = 0.3;
  in.angles_deg = {10.0};  // replaced below: the setup's χ needs one
  const ObliqueSetup setup = oblique_setup(in, ArgumentStyle::keyword);
  const double kappa_over_mu = 2.0 * 0.7 / (1.7 * 0.3);  // ψ = κ s/(μ v_n), κ = 2(1 − ν)/(2 − ν)
  const double end_psi = -2.0 / 3.0 * onset_case.end_factor;
  const double onset = 4.0 * maw_chi(setup) + end_psi;
  in.angles_deg.clear();
  for (const double psi : {onset - 0.02, onset + 0.02})
    in.angles_deg.push_back(std::atan(psi / kappa_over_mu) / kDegree);
  const std::vector<ObliqueImpact> impacts = oblique_sweep(oblique_setup(in, ArgumentStyle::keyword));
  ASSERT_EQ(impacts.size(), 2U);
  EXPECT_GT(impacts[0].result.switches.size(), 1U) << "sticks before the onset";
  ASSERT_EQ(impacts[1].result.switches.size(), 1U) << "slides throughout beyond it";
  EXPECT_EQ(impacts[1].result.switches[0].mode, ContactMode::slip);
  EXPECT_NEAR(impacts[1].psi_out, end_psi + 0.02, 1e-6);
}

INSTANTIATE_TEST_SUITE_P(Models, MindlinGrossSlipOnset,
                         ::testing::Values(Onset{"mindlin", 1.0}, Onset{"mindlin/force", 1.5},
                                           Onset{"mindlin_rescale", 0.5},
                                           Onset{"mindlin_rescale/force", 1.0}),
                         [](const auto& info) {
                           std::string name = info.param.model;
                           for (char& c : name)
                             if (c == '/') c = '_';
                           return name;
                         });

// Until maximal compression (t_c/2 for elastic Hertz) a _rescale variant is its base model: the same
// switches at the same times; after it, where a shrinks, the outcome differs.
TEST(MindlinRescale, IsTheBaseModelWhileTheContactLoads) {
  const ObliqueGeometry wall{solid_sphere(kRadius, kMass), std::nullopt, TorqueArm::radius};
  const NormalForce elastic{LawKind::viscoelastic_hertz, kHertzStiffness, 0.0};
  ObliqueOptions options;
  options.end = CollisionEnd::naive;
  options.relative_tolerance = 1e-12;
  for (const auto& [base, rescaled] :
       {std::pair{TangentialKind::mindlin, TangentialKind::mindlin_rescale},
        std::pair{TangentialKind::mindlin_force, TangentialKind::mindlin_rescale_force}}) {
    int switches_while_loading = 0;
    for (const double angle : {8.0, 15.0, 20.0, 30.0}) {
      const ImpactVelocity v{std::cos(angle * kDegree), std::sin(angle * kDegree), 0.0, 0.0};
      const ObliqueResult a = solve_oblique(wall, elastic, {base, 1.81e11, 0.0, 0.3}, v, options);
      const ObliqueResult b = solve_oblique(wall, elastic, {rescaled, 1.81e11, 0.0, 0.3}, v, options);
      const std::string label = std::string(tangential_name(rescaled)) + " at " + std::to_string(angle);
      EXPECT_NEAR(a.contact_time_s, b.contact_time_s, 1e-10 * a.contact_time_s) << label;
      const double loaded = 0.5 * a.contact_time_s;
      std::size_t i = 0;
      for (; i < a.switches.size() && a.switches[i].time_s < loaded; ++i) {
        ASSERT_LT(i, b.switches.size()) << label;
        EXPECT_EQ(a.switches[i].mode, b.switches[i].mode) << label;
        EXPECT_NEAR(a.switches[i].time_s, b.switches[i].time_s, 1e-9 * a.contact_time_s) << label;
        if (i > 0) ++switches_while_loading;
      }
      if (i < b.switches.size()) EXPECT_GE(b.switches[i].time_s, loaded) << label;
      // The rescale acts while unloading: a sticking contact's history shrinks with a.
      EXPECT_GT(std::abs(a.tangential_restitution - b.tangential_restitution), 1e-3) << label;
    }
    EXPECT_GE(switches_while_loading, 1) << "no switch before maximal compression: nothing compared";
  }
}

}  // namespace
