// Runs LAMMPS and LIGGGHTS themselves on head-on collisions of two equal spheres, fed exactly the lines
// `restitution dem --json` prints, and checks the ε they measure against restitution's: two materials, both
// ends, three impact speeds per calibration (the calibration speed, a quarter and four times it).
// Both codes integrate with velocity-Verlet, first order in the time step here (the damping force is taken
// at the half-step velocity), so each case runs at dt = T/N and T/(10 N), T the natural time of the fastest
// collision, and extrapolates: ε = (10 ε_fine - ε_coarse) / 9.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"

namespace {

using nlohmann::json;

struct Material {
  const char* name;
  double young_pa, poisson, radius_m, density_kg_m3, eps, velocity_m_s;
};

// Hard steel beads and soft rubber balls: β and the speeds differ by orders of magnitude.
constexpr std::array<Material, 2> kMaterials{{
    {"steel", 2.1e11, 0.3, 0.005, 7850.0, 0.9, 1.0},
    {"rubber", 1e7, 0.45, 0.01, 1100.0, 0.6, 2.0},
}};

std::string find_on_path(const std::string& program) {
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "");
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    const std::filesystem::path candidate = std::filesystem::path(dir) / program;
    if (::access(candidate.c_str(), X_OK) == 0) return candidate.string();
  }
  return {};
}

std::string run_program(const std::string& command) {
  std::string out;
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
  if (!pipe) return out;
  std::array<char, 4096> buffer{};
  while (fgets(buffer.data(), buffer.size(), pipe.get()) != nullptr) out += buffer.data();
  return out;
}

struct Case {
  std::string code;
  Material material;
  std::string end;
};

std::string case_name(const testing::TestParamInfo<Case>& info) {
  std::string end = info.param.end == "naive" ? "naive" : "delayed";
  return info.param.code + "_" + info.param.material.name + "_" + end;
}

// The natural time T = k^{-2/5} v^{-1/5} [s] of the law, k = (4/3) E* sqrt(R_eff) / m_eff, for equal spheres.
double natural_time(const Material& m, double v) {
  const double e_star = m.young_pa / (2.0 * (1.0 - m.poisson * m.poisson));
  const double mass = 4.0 / 3.0 * M_PI * std::pow(m.radius_m, 3) * m.density_kg_m3;
  const double k = 4.0 / 3.0 * e_star * std::sqrt(m.radius_m / 2.0) / (mass / 2.0);
  return std::pow(k, -0.4) * std::pow(v, -0.2);
}

// One input deck: a pair of touching spheres per speed, 20 radii apart in y, closing at v along x.
std::string deck(const Case& c, const std::vector<std::string>& lines, const std::vector<double>& speeds,
                 int steps_per_time) {
  const Material& m = c.material;
  const double r = m.radius_m;
  const double mass = 4.0 / 3.0 * M_PI * r * r * r * m.density_kg_m3;
  const double dt = natural_time(m, speeds.back()) / steps_per_time;
  const long steps = std::lround(5.0 * natural_time(m, speeds.front()) / dt);
  const bool liggghts = c.code == "liggghts";
  std::ostringstream d;
  d.precision(17);
  d << "units si\n";
  d << (liggghts ? "atom_style granular\nnewton off\ncommunicate single vel yes\n"
                 : "atom_style sphere\ncomm_modify vel yes\n");
  d << "atom_modify map array\nboundary f f f\n";
  const double box = 20.0 * r * (speeds.size() + 1);
  d << "region box block " << -box << " " << box << " " << -box << " " << box << " " << -box << " " << box
    << " units box\ncreate_box 1 box\n";
  for (std::size_t i = 0; i < speeds.size(); ++i) {
    const double y = 20.0 * r * i;
    d << "create_atoms 1 single " << -r << " " << y << " 0 units box\n";
    d << "create_atoms 1 single " << r << " " << y << " 0 units box\n";
  }
  for (std::size_t i = 0; i < speeds.size(); ++i) {
    for (int j = 0; j < 2; ++j) {
      const std::size_t id = 2 * i + j + 1;
      d << "set atom " << id << " diameter " << 2.0 * r << "\n";
      d << "set atom " << id << " mass " << mass << "\n";
      d << "set atom " << id << " vx " << (j == 0 ? 0.5 : -0.5) * speeds[i] << "\n";
    }
  }
  for (const std::string& line : lines) d << line << "\n";
  d << "neighbor " << r << " bin\nneigh_modify delay 0\n";
  d << "timestep " << dt << "\nfix integrate all nve/sphere\n";
  d << "thermo " << steps << "\nrun " << steps << "\n";
  for (std::size_t i = 0; i < speeds.size(); ++i) {
    const std::size_t a = 2 * i + 1;
    const std::size_t b = 2 * i + 2;
    d << "variable e" << i << " equal (vx[" << b << "]-vx[" << a << "])/" << speeds[i] << "\n";
    d << "variable g" << i << " equal x[" << b << "]-x[" << a << "]-" << 2.0 * r << "\n";
    d << "print \"EPS " << i << " ${e" << i << "} ${g" << i << "}\"\n";
  }
  return d.str();
}

// ε per speed measured by the code at dt = T / steps_per_time.
std::vector<double> measure(const std::string& program, const Case& c, const std::vector<std::string>& lines,
                            const std::vector<double>& speeds, int steps_per_time) {
  const std::string path = (std::filesystem::temp_directory_path() /
                            ("restitution-dem-" + std::to_string(::getpid()) + "-" + c.code + ".in"))
                               .string();
  std::ofstream(path) << deck(c, lines, speeds, steps_per_time);
  const std::string out = run_program(program + " -in " + path + " -log none -echo none 2>&1");
  std::filesystem::remove(path);
  std::vector<double> eps(speeds.size(), NAN);
  std::istringstream in(out);
  std::string word;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    std::size_t i = 0;
    double e = NAN;
    double gap = NAN;
    if (fields >> word && word == "EPS" && fields >> i >> e >> gap && i < eps.size()) {
      EXPECT_GT(gap, 0.0) << c.code << ": the spheres at v = " << speeds[i] << " m/s still touch at the end";
      eps[i] = e;
    }
  }
  for (double e : eps) EXPECT_TRUE(std::isfinite(e)) << program << " printed no eps:\n" << out;
  return eps;
}

class DemIntegration : public testing::TestWithParam<Case> {};

TEST_P(DemIntegration, CodeMeasuresTheEpsRestitutionPredicts) {
  const Case& c = GetParam();
  const std::string program = find_on_path(c.code == "lammps" ? "lmp" : "liggghts");
  ASSERT_FALSE(program.empty()) << (c.code == "lammps" ? "lmp" : "liggghts")
                                << " not found on PATH: scripts/setup installs Debian's " << c.code;
  const Material& m = c.material;
  const double v = m.velocity_m_s;
  const std::vector<double> speeds{v / 4.0, v, 4.0 * v};
  std::ostringstream args;
  args.precision(17);
  args << "dem --code " << c.code << " --end " << c.end << " --eps " << m.eps << " --velocity " << v
       << " --young-modulus " << m.young_pa << " --poisson-ratio " << m.poisson << " --radius " << m.radius_m
       << " --density " << m.density_kg_m3 << " --speeds " << speeds[0] << " " << speeds[1] << " "
       << speeds[2] << " --json";
  const auto outcome = restitution::test_support::run_cli(args.str());
  ASSERT_EQ(outcome.status, 0) << outcome.err;
  const json out = json::parse(outcome.out);
  const auto lines = out.at("lines").get<std::vector<std::string>>();
  ASSERT_EQ(out.at("eps").size(), speeds.size());

  const std::vector<double> coarse = measure(program, c, lines, speeds, 2000);
  const std::vector<double> fine = measure(program, c, lines, speeds, 20000);
  for (std::size_t i = 0; i < speeds.size(); ++i) {
    const double predicted = out.at("eps")[i].at("eps").get<double>();
    const double extrapolated = (10.0 * fine[i] - coarse[i]) / 9.0;
    const double tolerance = 1e-6 * std::min(predicted, 1.0 - predicted);
    EXPECT_NEAR(extrapolated, predicted, tolerance)
        << c.code << " " << m.name << " " << c.end << " v = " << speeds[i] << " m/s: coarse " << coarse[i]
        << ", fine " << fine[i];
    // The extrapolation must be a correction, not the whole answer: the fine run alone is already close.
    EXPECT_NEAR(fine[i], predicted, 100.0 * tolerance);
    std::ostringstream error;
    error << std::scientific << std::setprecision(2) << (extrapolated - predicted) / tolerance;
    RecordProperty("error_over_tolerance_" + std::to_string(i), error.str());
  }
}

std::vector<Case> cases() {
  std::vector<Case> all;
  for (const char* code : {"lammps", "liggghts"}) {
    for (const Material& m : kMaterials) {
      for (const char* end : {"delayed-recovery", "naive"}) all.push_back({code, m, end});
    }
  }
  return all;
}

INSTANTIATE_TEST_SUITE_P(Codes, DemIntegration, testing::ValuesIn(cases()), case_name);

}  // namespace
