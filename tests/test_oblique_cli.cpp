// SPDX-License-Identifier: BSD-3-Clause
// `restitution oblique` end to end: the material and the angles reach the solve in the right units (a
// grazing impact on a wall obeys the gross-sliding closed form computed from the printed numbers alone), the
// CSV is the JSON's numbers, and bad input exits with status 2 naming the problem.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>

#include "cli_runner.hpp"

namespace {

using restitution::test_support::lines_of;
using restitution::test_support::run_cli;
using restitution::test_support::slurp;
using restitution::test_support::TempFolder;

const std::string kSteel =
    "oblique --young-modulus 2e11 --poisson-ratio 0.3 --radius 1e-3 --density 7800 --dissipative-constant "
    "1e-7";

TEST(ObliqueCli, GrazingWallImpactSlidesByTheClosedForm) {
  const auto r =
      run_cli(kSteel +
              " --wall --tangential linear_history --tangential-stiffness 2.2e6 --tangential-damping 0.5 "
              "--friction 0.2 --angle 75,85 --impact-velocity 2 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["impacts"].size(), 2U);
  for (const auto& impact : j["impacts"]) {
    const double angle = impact["angle_deg"].get<double>() * std::numbers::pi / 180.0;
    const double vn = 2.0 * std::cos(angle);
    const double s0 = 2.0 * std::sin(angle);
    const double eps = impact["normal_restitution"].get<double>();
    const double et = impact["tangential_restitution"].get<double>();
    ASSERT_EQ(impact["modes"].size(), 1U);
    EXPECT_EQ(impact["modes"][0]["mode"], "slip");
    // Solid sphere on a wall: Δs = -μ (1 + ε) v_n (1 + m R²/I) = -3.5 μ (1 + ε) v_n, and s' = -e_t s.
    EXPECT_NEAR(-et * s0 - s0, -3.5 * 0.2 * (1.0 + eps) * vn, 1e-9 * s0);
    // The rebound angle is that of the centre's velocity: tan = u'/(ε v_n), u' = s0 - μ(1 + ε) v_n.
    const double rebound = std::atan2(s0 - 0.2 * (1.0 + eps) * vn, eps * vn) * 180.0 / std::numbers::pi;
    EXPECT_NEAR(impact["rebound_angle_deg"].get<double>(), rebound, 1e-8);
  }
}

TEST(ObliqueCli, CsvHoldsTheJsonNumbers) {
  TempFolder folder;
  const auto csv_path = folder.path / "oblique.csv";
  const auto r = run_cli(kSteel + " --tangential mindlin --friction 0.3 --angle 10,30,60 --json --out " +
                         csv_path.string());
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const auto lines = lines_of(slurp(csv_path));
  ASSERT_EQ(lines.size(), 4U);
  EXPECT_EQ(lines[0].rfind("angle_deg,normal_restitution,tangential_restitution,", 0), 0U);
  for (std::size_t i = 0; i < 3; ++i) {
    const auto& impact = j["impacts"][i];
    std::vector<double> row;
    std::size_t begin = 0;
    const std::string& line = lines[i + 1];
    for (std::size_t end; (end = line.find(',', begin)) != std::string::npos; begin = end + 1) {
      row.push_back(std::stod(line.substr(begin, end - begin)));
    }
    EXPECT_EQ(line.substr(begin), "solved");  // the last column, status
    ASSERT_EQ(row.size(), 14U);
    EXPECT_EQ(row[0], impact["angle_deg"].get<double>());
    EXPECT_EQ(row[2], impact["tangential_restitution"].get<double>());
    EXPECT_EQ(row[4], impact["spin_rad_s"].get<double>());
    EXPECT_EQ(row[9], static_cast<double>(impact["modes"].size() - 1));
  }
}

TEST(ObliqueCli, BadInputExitsWithStatus2NamingTheProblem) {
  const struct {
    std::string arguments, message;
  } cases[] = {
      {" --tangential mindlin --angle 10", "--friction"},
      {" --tangential linear_history --friction 0.3 --angle 10", "--tangential-stiffness"},
      {" --tangential mindlin --friction 0.3 --angle 90", "--angle"},
      {" --tangential mindlin --friction 0.3", "--angle"},
      {" --tangential mindlin --friction -0.3 --angle 10", "friction"},
      {" --tangential mindlin/rescale --friction 0.3 --angle 10", "--tangential"},
      {" --tangential mindlin --friction 0.3 --angle 10 --wall --radius2 2e-3", "--wall"},
      {" --tangential mindlin --friction 0.3 --angle 10 --impact-velocity 0", "--impact-velocity"},
  };
  for (const auto& c : cases) {
    const auto r = run_cli(kSteel + c.arguments);
    EXPECT_EQ(r.status, 2) << c.arguments << ": " << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.arguments << ": " << r.err;
    EXPECT_TRUE(r.out.empty()) << c.arguments;
  }
}

}  // namespace
