// SPDX-License-Identifier: BSD-3-Clause
// `restitution oblique --tolerance T` as the accuracy contract (src/oblique/oblique_accuracy.hpp): each
// impact says how it is conditioned in the JSON, an impact at the stick/slip boundary is flagged there, in
// the table and on stderr, and a tolerance outside the contract exits with status 2 naming the range.
#include <fmt/core.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <numbers>
#include <optional>
#include <string>

#include "cli_runner.hpp"
#include "oblique/oblique_accuracy.hpp"
#include "restitution/units.hpp"

namespace {

using restitution::test_support::run_cli;
using namespace restitution;
using namespace restitution::oblique;

const std::string kSteel =
    "oblique --young-modulus 2e11 --poisson-ratio 0.3 --radius 1e-3 --density 7800 --dissipative-constant "
    "1e-7 --wall --wall-young-modulus 2e11 --wall-poisson-ratio 0.3 --tangential linear_history "
    "--tangential-stiffness 2.2e6 --tangential-damping 0.5 "
    "--friction 0.3";

// An angle where the wall impact of kSteel at T = 1e-10 is flagged by the library, with the command's
// numbers: near the stick/slip boundary (where a second stick phase appears, near 18.2°:
// tests/test_oblique_accuracy.cpp) found by bisection on the number of switches, then in steps of 1e-4°
// around it.
std::optional<double> flagged_angle_deg() {
  const double radius = 1e-3;
  const double k = hertz_stiffness(effective_modulus_pa(2e11, 0.3), radius);
  const ObliqueGeometry g{solid_sphere(radius, sphere_mass_kg(radius, 7800.0)), std::nullopt,
                          TorqueArm::radius};
  const NormalForce normal{LawKind::viscoelastic_hertz, k, 1.5e-7 * k};
  const TangentialForce tangential{TangentialKind::linear_history, 2.2e6, 0.5, 0.3};
  const auto impact = [](double angle) {
    const double a = angle * (std::numbers::pi / 180.0);
    return ImpactVelocity{std::cos(a), std::sin(a), 0.0, 0.0};
  };
  ObliqueOptions options;
  options.relative_tolerance = 1e-13;
  const auto switches_at = [&](double angle) {
    return solve_oblique(g, normal, tangential, impact(angle), options).switches.size();
  };
  double below = 5.0;
  double above = 20.0;
  const std::size_t switches_below = switches_at(below);
  for (int i = 0; i < 40; ++i) {
    const double mid = 0.5 * (below + above);
    (switches_at(mid) == switches_below ? below : above) = mid;
  }
  for (int i = -100; i <= 100; ++i) {
    const double angle = above + 1e-4 * i;
    if (solve_oblique_within(g, normal, tangential, impact(angle), 1e-10).ill_conditioned) return angle;
  }
  return std::nullopt;
}

TEST(ObliqueAccuracyCli, SaysWhereTheOutcomeIsIllConditioned) {
  const std::optional<double> angle = flagged_angle_deg();
  ASSERT_TRUE(angle) << "no ill-conditioned impact within 0.01 degrees of the boundary";
  const auto r = run_cli(kSteel + fmt::format(" --angle 5,{:.17g},45 --json", *angle));
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["impacts"].size(), 3U);
  EXPECT_EQ(j["impacts"][0]["conditioning"], "well-conditioned");
  EXPECT_EQ(j["impacts"][2]["conditioning"], "well-conditioned");
  const std::string flagged = j["impacts"][1]["conditioning"];
  EXPECT_EQ(flagged.rfind("ill-conditioned", 0), 0U) << flagged;
  // The angle as given, in its shortest exact form.
  EXPECT_NE(r.err.find(fmt::format("warning: at {} deg, spin 0 rad/s, ill-conditioned", *angle)),
            std::string::npos)
      << r.err;
  EXPECT_DOUBLE_EQ(j["impacts"][1]["relative_tolerance"].get<double>(), 1e-13);

  const auto table = run_cli(kSteel + fmt::format(" --angle {:.17g}", *angle));
  ASSERT_EQ(table.status, 0) << table.err;
  EXPECT_NE(table.out.find("ill-conditioned"), std::string::npos) << table.out;
}

TEST(ObliqueAccuracyCli, RefusesAToleranceOutsideTheContract) {
  for (const char* tolerance : {"1e-11", "0.01", "0"}) {
    const auto r = run_cli(kSteel + " --angle 20 --tolerance " + tolerance);
    EXPECT_EQ(r.status, 2) << tolerance;
    EXPECT_NE(r.err.find("--tolerance must be in [1e-10, 0.01)"), std::string::npos) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
  }
}

}  // namespace
