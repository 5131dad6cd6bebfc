// Runs Debian's YADE (`yade -n -x`, 2023.02a) on the lines `restitution dem --code yade` prints for the YADE
// on PATH, unchanged (each line exec'd / eval'd verbatim), in head-on collisions of two steel beads at three
// speeds, and checks that YADE measures the ε the output says these lines give, within 1e-5 relative.
// YADE's leap-frog integrator is first order in dt for this velocity-dependent force: each speed runs at
// dt = T/n and T/(10 n) (n = 5000, T the natural time of that speed) and ε is Richardson-extrapolated; the
// Tsuji force's x^{1/4} leaves a remainder that converges slowly (measured at eps = 0.5: 1.6e-6 after
// extrapolating from n = 1000, 2e-7 from n = 5000), as in the LAMMPS Tsuji checks.
#include <gtest/gtest.h>
#include <unistd.h>
#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"

namespace {

using nlohmann::json;

constexpr double kYoungPa = 2.1e11, kPoisson = 0.3, kRadiusM = 0.005, kDensity = 7850.0;
const std::string kMaterial = " --young-modulus 2.1e11 --poisson-ratio 0.3 --radius 0.005 --density 7850";

json run_json(const std::string& arguments) {
  const auto r = restitution::test_support::run_cli(arguments);
  EXPECT_EQ(r.status, 0) << arguments << ": " << r.err;
  return json::parse(r.out);
}

// A Python string literal holding `text` verbatim (json's quoting is valid Python for these lines).
std::string python_literal(const std::string& text) {
  return json(text).dump();
}

// The script: per speed a fresh scene, the material line exec'd, the Ip2 and Law2 lines eval'd as printed.
std::string script(const std::vector<std::string>& lines, const std::vector<double>& speeds, int n) {
  std::ostringstream s;
  s.precision(17);
  s << "import math\nR = " << kRadiusM << "\nrho = " << kDensity << "\nY = " << kYoungPa
    << "\nnu = " << kPoisson << "\nLINES = [";
  for (const auto& line : lines) s << python_literal(line) << ", ";
  s << "]\nspeeds = [";
  for (double v : speeds) s << v << ", ";
  s << "]\nn = " << n << R"(
e_star = Y / (2 * (1 - nu * nu))
m_eff = rho * 4 / 3 * math.pi * R ** 3 / 2
k = 4 / 3 * e_star * math.sqrt(R / 2) / m_eff
for i, v in enumerate(speeds):
    O.reset()
    exec(LINES[0])
    O.bodies.append([sphere((-R, 0, 0), R), sphere((R, 0, 0), R)])
    O.bodies[0].state.vel = Vector3(v / 2, 0, 0)
    O.bodies[1].state.vel = Vector3(-v / 2, 0, 0)
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb()]),
                 InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [eval(LINES[1])], [eval(LINES[2])]),
                 NewtonIntegrator(damping=0)]
    O.dt = k ** -0.4 * v ** -0.2 / n
    O.run(6 * n, True)
    eps = (O.bodies[1].state.vel[0] - O.bodies[0].state.vel[0]) / v
    gap = O.bodies[1].state.pos[0] - O.bodies[0].state.pos[0] - 2 * R
    print("RESTITUTION_EPS %d %.17g %.17g" % (i, eps, gap))
)";
  return s.str();
}

struct YadeRun {
  std::vector<double> eps, gap;
  std::string output;
};

YadeRun run_yade(const std::vector<std::string>& lines, const std::vector<double>& speeds, int n) {
  char name[] = "/tmp/restitution-yade-XXXXXX.py";
  const int fd = mkstemps(name, 3);
  EXPECT_GE(fd, 0);
  close(fd);
  std::ofstream(name) << script(lines, speeds, n);
  YadeRun run;
  run.eps.assign(speeds.size(), NAN);
  run.gap.assign(speeds.size(), NAN);
  const std::unique_ptr<FILE, int (*)(FILE*)> pipe(
      popen(("yade -n -x " + std::string(name) + " 2>&1").c_str(), "r"), pclose);
  std::array<char, 4096> buffer{};
  while (pipe && fgets(buffer.data(), buffer.size(), pipe.get()) != nullptr) run.output += buffer.data();
  std::filesystem::remove(name);
  // yade prints banners and warnings: only our own line counts.
  std::istringstream in(run.output);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    std::string word;
    std::size_t i = 0;
    double e = NAN, gap = NAN;
    if (fields >> word && word == "RESTITUTION_EPS" && fields >> i >> e >> gap && i < speeds.size()) {
      run.eps[i] = e;
      run.gap[i] = gap;
    }
  }
  return run;
}

bool yade_on_path() {
  return std::system("yade --version >/dev/null 2>&1") == 0;
}

class YadeLines : public testing::TestWithParam<double> {};

TEST_P(YadeLines, YadeMeasuresTheEpsTheOutputStates) {
  ASSERT_TRUE(yade_on_path()) << "yade not found on PATH: scripts/setup installs Debian's yade";
  const double target = GetParam();
  std::ostringstream args;
  args << "dem --code yade --eps " << target << " --velocity 1 --json" << kMaterial;
  const json out = run_json(args.str());
  // The YADE on PATH is Debian's 2023.02a: no vn, so the lines carry the Tsuji-type betan and the output
  // states a constant ε, with the exact law's lines only as a labelled alternative.
  EXPECT_EQ(out.at("yade_version"), "2023.02a");
  EXPECT_EQ(out.at("yade_version_source"), "yade on PATH");
  ASSERT_TRUE(out.contains("yade_exact_law"));
  const auto lines = out.at("lines").get<std::vector<std::string>>();
  for (const auto& line : lines) EXPECT_EQ(line.find("vn="), std::string::npos) << line;
  std::vector<double> speeds, stated;
  for (const auto& e : out.at("eps")) {
    speeds.push_back(e.at("velocity_m_s").get<double>());
    stated.push_back(e.at("eps").get<double>());
  }
  ASSERT_EQ(speeds.size(), 3U);
  const YadeRun coarse = run_yade(lines, speeds, 5000);
  const YadeRun fine = run_yade(lines, speeds, 50000);
  for (std::size_t i = 0; i < speeds.size(); ++i) {
    ASSERT_TRUE(std::isfinite(coarse.eps[i]) && std::isfinite(fine.eps[i])) << fine.output;
    EXPECT_GT(fine.gap[i], 0.0) << "still in contact at v = " << speeds[i];
    const double measured = (10.0 * fine.eps[i] - coarse.eps[i]) / 9.0;
    const double relative = (measured - stated[i]) / stated[i];
    EXPECT_LT(std::abs(relative), 1e-5)
        << "v = " << speeds[i] << ": coarse " << coarse.eps[i] << ", fine " << fine.eps[i]
        << ", extrapolated " << measured << ", stated " << stated[i];
    std::ostringstream text;
    text << std::scientific << relative;
    testing::Test::RecordProperty("relative_difference_" + std::to_string(i), text.str());
  }
}

INSTANTIATE_TEST_SUITE_P(Eps, YadeLines, testing::Values(0.5, 0.8),
                         [](const testing::TestParamInfo<double>& p) {
                           return p.param == 0.5 ? "eps05" : "eps08";
                         });

// --yade-version names another YADE: 2024.02a takes vn, so the lines are the exact law's (en, vn) and no
// alternative is printed; an unknown version is refused naming the option.
TEST(YadeLinesVersion, OptionTargetsTheNamedVersion) {
  const json exact =
      run_json("dem --code yade --eps 0.8 --velocity 1 --yade-version 2024.02a --json" + kMaterial);
  EXPECT_EQ(exact.at("yade_version"), "2024.02a");
  EXPECT_FALSE(exact.contains("yade_exact_law"));
  EXPECT_NE(exact.at("lines").at(1).get<std::string>().find("vn="), std::string::npos);
  const json old =
      run_json("dem --code yade --eps 0.8 --velocity 1 --yade-version 2023.02a --json" + kMaterial);
  // The old version's lines state one ε at every speed; the exact law's ε(v) sits under yade_exact_law only.
  for (const auto& e : old.at("eps")) EXPECT_NEAR(e.at("eps").get<double>(), 0.8, 1e-9);
  EXPECT_EQ(old.at("yade_exact_law").at("eps"), exact.at("eps"));
  const auto bad =
      restitution::test_support::run_cli("dem --code yade --eps 0.8 --yade-version 7" + kMaterial);
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("--yade-version"), std::string::npos) << bad.err;
}

}  // namespace
