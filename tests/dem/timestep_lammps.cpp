// SPDX-License-Identifier: BSD-3-Clause
// `restitution dem --timestep DT` against LAMMPS itself: the ε error it reports for LAMMPS's integrator at a
// production time step (no extrapolation, no fine dt) is the one LAMMPS makes. The gas of issue 35 (Y = 1e8
// Pa, nu = 0.4, rho = 920 kg/m3, R = 5 mm, eps = 0.8 at 2 m/s) at dt = 5e-6 s: one deck holds a pair per
// phase (where between two steps the contact starts, as a gas samples it), built from the prerequisites and
// lines the command prints; the mean and the worst ε error over the phases agree within 20 %.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "dem/code_runner.hpp"
#include "dem/process_output.hpp"
#include "dem/steel_beads.hpp"

namespace {

using nlohmann::json;
using restitution::test_support::run_json;

constexpr double kTimeStepS = 5e-6;
constexpr double kRadiusM = 0.005;
constexpr double kDensity = 920.0;
constexpr double kSpeed = 2.0;
constexpr int kPhases = 16;  // the command's own phase count is independent of this one

// One pair per phase p: the surfaces (p + 0.5) / kPhases of a step's approach apart, closing at kSpeed.
std::string phase_deck(const json& dem) {
  std::string d;
  for (const auto& line : dem.at("prerequisites")) d += line.get<std::string>() + "\n";
  d += "atom_modify map array sort 0 0.0\nboundary f f f\n";
  const double spacing = 4.0 * kRadiusM;
  d += "region box block -0.02 0.02 " + std::to_string(-spacing) + " " + std::to_string(spacing * kPhases) +
       " -0.01 0.01 units box\ncreate_box 1 box\n";
  char buffer[256];
  for (int p = 0; p < kPhases; ++p) {
    const double gap = (p + 0.5) / kPhases * kSpeed * kTimeStepS;
    const double y = spacing * p;
    std::snprintf(buffer, sizeof buffer, "create_atoms 1 single %.17g %.17g 0 units box\n",
                  -kRadiusM - gap / 2, y);
    d += buffer;
    std::snprintf(buffer, sizeof buffer, "create_atoms 1 single %.17g %.17g 0 units box\n",
                  kRadiusM + gap / 2, y);
    d += buffer;
  }
  std::snprintf(buffer, sizeof buffer, "set group all diameter %.17g\nset group all density %.17g\n",
                2 * kRadiusM, kDensity);
  d += buffer;
  for (int i = 1; i <= 2 * kPhases; ++i) {
    std::snprintf(buffer, sizeof buffer, "set atom %d vx %.17g\n", i, (i % 2 == 1 ? 0.5 : -0.5) * kSpeed);
    d += buffer;
  }
  for (const auto& line : dem.at("lines")) d += line.get<std::string>() + "\n";
  std::snprintf(buffer, sizeof buffer, "neighbor %.17g bin\nneigh_modify delay 0\ntimestep %.17g\n", kRadiusM,
                kTimeStepS);
  d += buffer;
  d += "fix integrate all nve/sphere\nrun 400\n";  // 2 ms: the contact lasts 0.24 ms
  for (int p = 0; p < kPhases; ++p) {
    std::snprintf(buffer, sizeof buffer, "print \"PHASE %d $((vx[%d]-vx[%d])/%.17g) $(x[%d]-x[%d]-%.17g)\"\n",
                  p, 2 * p + 2, 2 * p + 1, kSpeed, 2 * p + 2, 2 * p + 1, 2 * kRadiusM);
    d += buffer;
  }
  return d;
}

TEST(TimestepLammps, ReportedEpsErrorIsTheOneLammpsMakes) {
  const std::string program = restitution::dem::dem_program(restitution::dem::Code::lammps);
  ASSERT_FALSE(program.empty()) << "lmp not found on PATH: scripts/setup installs Debian's lammps";
  const json dem = run_json(
      "dem --code lammps --young-modulus 1e8 --poisson-ratio 0.4 --density 920 --radius 0.005 --eps 0.8 "
      "--velocity 2 --impact-velocity 2 --timestep 5e-6 --json");
  const double eps_law = dem.at("eps").at(0).at("eps").get<double>();
  const json& reported = dem.at("timestep").at("errors").at(0);
  const double mean_reported = reported.at("mean_eps_error").get<double>();
  const double worst_reported = reported.at("worst_eps_error").get<double>();

  const std::string out =
      restitution::dem::output_with_input_file(phase_deck(dem), ".in", [&](const std::string& path) {
        return std::vector<std::string>{program, "-log", "none", "-in", path};
      }).output;
  const auto measured = restitution::dem::tagged_eps(out, "PHASE", kPhases);
  double mean = 0.0;
  double worst = 0.0;
  for (int p = 0; p < kPhases; ++p) {
    ASSERT_TRUE(std::isfinite(measured.eps[p])) << "no eps for phase " << p << ":\n" << out;
    ASSERT_GT(measured.gap_m[p], 0.0) << "phase " << p << " still in contact";
    const double error = measured.eps[p] - eps_law;
    mean += error / kPhases;
    if (std::abs(error) > std::abs(worst)) worst = error;
  }
  RecordProperty("lammps_mean_eps_error", std::to_string(mean));
  RecordProperty("lammps_worst_eps_error", std::to_string(worst));
  EXPECT_GT(std::abs(mean), 1e-5) << "dt this large must make a visible error";
  EXPECT_NEAR(mean_reported / mean, 1.0, 0.2) << "reported " << mean_reported << ", LAMMPS " << mean;
  EXPECT_NEAR(worst_reported / worst, 1.0, 0.2) << "reported " << worst_reported << ", LAMMPS " << worst;
}

}  // namespace
