// SPDX-License-Identifier: BSD-3-Clause
// The fast ε(ζ) table (restitution/fast.hpp): against the __float128 reference rows, its inverse, its domain,
// and the exported C header (same text as the compiled one; compiled by gcc and g++, same bits).
#include <gtest/gtest.h>

#include <unistd.h>
#include <nlohmann/json.hpp>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "reference_checks.hpp"
#include "restitution/calibration.hpp"
#include "restitution/errors.hpp"
#include "restitution/fast.hpp"

namespace {

// A folder of this process's own, so that two checkouts testing at once do not delete each other's files.
std::filesystem::path per_process_folder(const std::string& name) {
  return std::filesystem::temp_directory_path() / (name + "-" + std::to_string(::getpid()));
}

using namespace restitution;
using restitution::test_support::reference_rows;
constexpr double kContract = 1e-13;
constexpr CollisionEnd kEnds[] = {CollisionEnd::naive, CollisionEnd::delayed_recovery};

// The contract: ε and 1 − ε (each from its own function) each within 1e-13 of itself, relative; this bounds
// |Δε| / min(ε, 1 − ε) through whichever of the two a double carries.
double contract_error(double zeta, CollisionEnd end, double eps, double one_minus_eps) {
  const double e = fast::eps(zeta, end), c = fast::one_minus_eps(zeta, end);
  const auto relative = [](double value, double exact) {
    return exact == 0.0 ? std::abs(value) : std::abs(value - exact) / exact;
  };
  return std::max(relative(e, eps), relative(c, one_minus_eps));
}

TEST(Fast, EveryReferenceRowWithinTheContract) {
  for (const ReferenceRow& row : reference_rows()) {
    for (const CollisionEnd end : kEnds) {
      const auto& values = row.ends[end];
      if (!values) continue;
      EXPECT_LE(contract_error(row.zeta, end, values->eps, values->one_minus_eps), kContract)
          << "zeta " << row.zeta << " " << end_name(end);
      EXPECT_NEAR(fast::collision_duration(row.zeta, end) / values->tau, 1.0, kContract)
          << "tau_c at zeta " << row.zeta << " " << end_name(end);
    }
    const MaxCompression m = fast::max_compression(row.zeta);
    EXPECT_NEAR(m.x / row.x_max, 1.0, kContract) << "x_max at zeta " << row.zeta;
    EXPECT_NEAR(m.tau / row.tau_max, 1.0, kContract) << "tau_max at zeta " << row.zeta;
  }
}

// The durations and the maximal compression switch from their tables to their large-ζ laws (naive τ_c at
// ζ = e^6, the others at e^12) without a visible step, and the laws have their derived limits: τ_c grows
// like (10/3) ζ ln ζ at the naive end; ζ^{2/3} x_max → (3/2)^{2/3}; ζ^{2/3} τ_c and ζ^{2/3} τ_max grow like
// (10/3) ln ζ / q and (5/3) ln ζ / q, q = (3/2)^{1/3}, at the delayed-recovery end.
TEST(Fast, DurationsContinuousAtTheLawsAndTheirLimits) {
  // The relative step of f at ln ζ = s0: the change of ln f across ±h, less what its slope (measured across
  // ±H, off the switch's influence) accounts for.
  const auto step = [](auto f, double s0) {
    const auto ln_f = [&f](double s) { return std::log(f(std::exp(s))); };
    const double h = 1e-9;
    const double wide = 1e-4;
    const double slope = (ln_f(s0 + wide) - ln_f(s0 - wide)) / (2 * wide);
    return std::abs(ln_f(s0 + h) - ln_f(s0 - h) - 2 * h * slope);
  };
  const auto naive_tau = [](double z) { return fast::collision_duration(z, CollisionEnd::naive); };
  const auto delayed_tau = [](double z) {
    return fast::collision_duration(z, CollisionEnd::delayed_recovery);
  };
  const auto x_max = [](double z) { return fast::max_compression(z).x; };
  const auto tau_max = [](double z) { return fast::max_compression(z).tau; };
  EXPECT_LT(step(naive_tau, 6.0), 1e-13);
  EXPECT_LT(step(delayed_tau, 12.0), 1e-13);
  EXPECT_LT(step(x_max, 12.0), 1e-13);
  EXPECT_LT(step(tau_max, 12.0), 1e-13);
  const double q = std::cbrt(1.5);
  const double big = 1e300;
  const double s = std::log(big);
  const double scale = std::pow(big, 2.0 / 3.0);
  EXPECT_NEAR(naive_tau(big) / (big * s), 10.0 / 3.0, 1e-2);
  // exp(−(2/3) ln ζ) rounds its argument, 460 here: 460 · 1.1e-16 relative
  EXPECT_NEAR(x_max(big) * scale, std::pow(1.5, 2.0 / 3.0), 1e-13);
  EXPECT_NEAR(delayed_tau(big) * scale / s, 10.0 / (3.0 * q), 1e-2);
  EXPECT_NEAR(tau_max(big) * scale / s, 5.0 / (3.0 * q), 1e-2);
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(naive_tau(inf), inf);
  EXPECT_EQ(delayed_tau(inf), 0.0);
  EXPECT_EQ(x_max(inf), 0.0);
  EXPECT_EQ(tau_max(inf), 0.0);
}

TEST(Fast, LimitsAndDomain) {
  for (const CollisionEnd end : kEnds) {
    EXPECT_EQ(fast::eps(0.0, end), 1.0);
    EXPECT_EQ(fast::one_minus_eps(0.0, end), 0.0);
    EXPECT_EQ(fast::eps(std::numeric_limits<double>::infinity(), end), 0.0);
    EXPECT_EQ(fast::one_minus_eps(std::numeric_limits<double>::infinity(), end), 1.0);
    EXPECT_EQ(fast::zeta_from_eps(1.0, end), 0.0);
    EXPECT_THROW(fast::eps(-1e-300, end), InvalidInput);
    EXPECT_THROW(fast::one_minus_eps(std::nan(""), end), InvalidInput);
    for (const double bad : {0.0, -0.5, 1.0 + 1e-15, std::nan("")})
      EXPECT_THROW(fast::zeta_from_eps(bad, end), InvalidInput) << bad;
    EXPECT_THROW(fast::collision_duration(-1.0, end), InvalidInput);
  }
  EXPECT_THROW(fast::max_compression(-1.0), InvalidInput);
}

// ε decreases with ζ (monotone on a fine grid through every region), and 1 − ε follows it.
TEST(Fast, MonotoneAndComplementary) {
  for (const CollisionEnd end : kEnds) {
    double previous = 1.0;
    for (double s = -30; s <= 20; s += 1e-3) {
      const double zeta = std::exp(s), e = fast::eps(zeta, end);
      ASSERT_LE(e, previous) << "zeta " << zeta << " " << end_name(end);
      previous = e;
      ASSERT_NEAR(e + fast::one_minus_eps(zeta, end), 1.0, 4e-16) << "zeta " << zeta;
    }
  }
}

// The inverse: ε(ζ(ε)) = ε to the contract, for ε log-uniform down to 1e-300 and 1 − ε down to 1e-16.
TEST(Fast, InverseMeetsTheContractInEps) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(std::log(1e-300), std::log(0.5));
  std::uniform_real_distribution<double> v(std::log(1e-16), std::log(0.5));
  for (const CollisionEnd end : kEnds) {
    double worst = 0;
    for (int k = 0; k < 20000; ++k) {
      const double small = std::exp(k % 2 == 0 ? u(rng) : v(rng));
      const double eps = k % 2 == 0 ? small : 1.0 - small;
      const double complement = 1.0 - eps;  // exact when eps >= 1/2
      const double zeta = fast::zeta_from_eps(eps, end);
      ASSERT_TRUE(std::isfinite(zeta) && zeta >= 0.0) << eps;
      // ε(ζ) rounds ζ to a double: allow its effect, |d ln ε / d ln ζ| <= 5 ulp-sized steps.
      const double rounding = 5 * std::numeric_limits<double>::epsilon();
      const double err = k % 2 == 0 ? std::abs(fast::eps(zeta, end) / eps - 1)
                                    : std::abs(fast::one_minus_eps(zeta, end) / complement - 1);
      worst = std::max(worst, err);
      ASSERT_LE(err, kContract + rounding) << "eps " << eps << " zeta " << zeta << " " << end_name(end);
    }
    RecordProperty(std::string("worst_inverse_") + end_name(end), std::to_string(worst));
  }
}

TEST(Fast, InverseRecoversZeta) {
  for (const CollisionEnd end : kEnds) {
    for (double s = std::log(1e-6); s < std::log(1e6); s += 0.0137) {
      // ε rounded to a double moves ζ by about 1.1e-16 / (1 − ε) relative (|d ln(1 − ε)/d ln ζ| >= 1/2)
      const double zeta = std::exp(s), rounding = 2.3e-16 / fast::one_minus_eps(zeta, end);
      EXPECT_NEAR(fast::zeta_from_eps(fast::eps(zeta, end), end) / zeta, 1.0, 1e-12 + rounding) << zeta;
    }
  }
}

// Calibration through the table agrees with root finding on the solver, without a single integration, and
// reaches ε below the solver's range (ζ > 1e4).
TEST(FastCalibration, AgreesWithTheSolverAndNeedsNoSolve) {
  CollisionSolver solver;
  for (const CollisionEnd end : kEnds) {
    for (const double eps : {0.95, 0.8, 0.3, 0.01}) {
      CalibrationRequest request;
      request.eps = eps;
      request.velocity_m_s = 2.0;
      request.end = end;
      request.k = 3.0e5;
      const Calibration solved = calibrate(request, solver);
      request.fast = true;
      const Calibration fast = calibrate(request, solver);
      EXPECT_EQ(fast.solves, 0);
      EXPECT_NEAR(fast.zeta / solved.zeta, 1.0, 1e-8) << eps << " " << end_name(end);
      EXPECT_NEAR(*fast.dissipative_constant_s / *solved.dissipative_constant_s, 1.0, 1e-8);
      EXPECT_NEAR(fast.eps_at_zeta / eps, 1.0, 1e-13);
    }
  }
  CalibrationRequest beyond;
  beyond.eps = 1e-9;
  beyond.velocity_m_s = 1.0;
  beyond.fast = true;
  EXPECT_NEAR(fast::eps(calibrate(beyond, solver).zeta, CollisionEnd::delayed_recovery) / 1e-9, 1.0, 1e-13);
  beyond.eps = 1.0;
  EXPECT_THROW((void)calibrate(beyond, solver), InvalidInput);
  // An ε that only a ζ above the checked range gives is refused by both paths, in the same words.
  beyond.eps = 1e-300;
  std::string fast_message, solved_message;
  try {
    (void)calibrate(beyond, solver);
  } catch (const InvalidInput& e) {
    fast_message = e.what();
  }
  beyond.fast = false;
  try {
    (void)calibrate(beyond, solver);
  } catch (const InvalidInput& e) {
    solved_message = e.what();
  }
  EXPECT_NE(fast_message.find("outside the checked range"), std::string::npos) << fast_message;
  EXPECT_EQ(fast_message.substr(0, fast_message.find(" = ", 14)),
            solved_message.substr(0, solved_message.find(" = ", 14)));
}

TEST(FastCalibration, CommandLine) {
  const std::string material =
      " --young-modulus 1e7 --poisson-ratio 0.45 --radius 0.01 --density 1100 --json";
  const auto fast = test_support::run_cli("calibrate --eps 0.8 --velocity 1 --method fast" + material);
  const auto solved = test_support::run_cli("calibrate --eps 0.8 --velocity 1" + material);
  ASSERT_EQ(fast.status, 0) << fast.err;
  ASSERT_EQ(solved.status, 0) << solved.err;
  const auto f = nlohmann::json::parse(fast.out), s = nlohmann::json::parse(solved.out);
  EXPECT_EQ(f["method"], "fast");
  EXPECT_EQ(f["solves"], 0);
  EXPECT_NEAR(f["beta"].get<double>() / s["beta"].get<double>(), 1.0, 1e-8);
  EXPECT_NEAR(f["dissipative_constant_s"].get<double>() / s["dissipative_constant_s"].get<double>(), 1.0,
              1e-8);
  EXPECT_EQ(test_support::run_cli("calibrate --eps 0 --velocity 1 --method fast").status, 2);
}

std::string source_file(const std::string& relative) {
  return test_support::slurp(std::string(RESTITUTION_SOURCE_DIR) + "/" + relative);
}

// The generated header in the source tree is what the library compiled, and what `export c-header` writes.
TEST(FastHeader, ExportIsTheCompiledHeader) {
  EXPECT_EQ(fast::c_header(), source_file("src/fast/fast_table.h"));
  const auto dir = per_process_folder("restitution-fast-export");
  std::filesystem::create_directories(dir);
  const auto out = test_support::run_cli("export c-header --out " + (dir / "r.h").string());
  ASSERT_EQ(out.status, 0) << out.err;
  EXPECT_EQ(test_support::slurp((dir / "r.h").string()), fast::c_header());
  EXPECT_EQ(test_support::run_cli("export c-header").status, 2);
  EXPECT_EQ(test_support::run_cli("export").status, 2);
  std::filesystem::remove_all(dir);
}

// The generator end to end on a small range: it runs, records its settings, measures errors inside the
// contract; bad settings exit with status 2.
TEST(FastTable, GeneratorOnASmallRange) {
  const auto dir = per_process_folder("restitution-fast-table");
  std::filesystem::create_directories(dir);
  const std::string out = (dir / "t.h").string();
  const auto r = test_support::run_cli(
      "fast-table --out " + out +
      " --s-lo 0 --s-hi-naive 0.25 --s-hi-naive-duration 0.25 --s-hi-delayed 0.25 --checks 3");
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string text = test_support::slurp(out);
  EXPECT_NE(text.find("--s-lo 0 --s-hi-naive 0.25"), std::string::npos);
  EXPECT_NE(text.find("static inline double restitution_eps_naive(double zeta)"), std::string::npos);
  const auto at = r.out.find("max |d eps| / min(eps, 1-eps): naive ");
  ASSERT_NE(at, std::string::npos) << r.out;
  double naive = 1;
  double delayed = 1;
  ASSERT_EQ(std::sscanf(r.out.c_str() + at, "max |d eps| / min(eps, 1-eps): naive %lf, delayed recovery %lf",
                        &naive, &delayed),
            2);
  EXPECT_LT(naive, 1e-14);
  EXPECT_LT(delayed, 1e-14);
  EXPECT_EQ(test_support::run_cli("fast-table --out " + out + " --degree 1").status, 2);
  EXPECT_EQ(test_support::run_cli("fast-table --out " + out + " --s-lo 3").status, 2);
  EXPECT_EQ(test_support::run_cli("fast-table").status, 2);
  std::filesystem::remove_all(dir);
}

// A C program on the header: reads arguments as hex floats, prints the ten functions as hex floats.
constexpr const char* kDriver = R"C(#include "restitution_fast.h"
#include <stdio.h>
#include <stdlib.h>
int main(int argc, char **argv) {
  char line[128];
  FILE *in = fopen(argv[1], "r");
  if (argc < 2 || !in) return 3;
  while (fgets(line, sizeof line, in)) {
    double z = strtod(line, NULL);
    printf("%a %a %a %a %a %a ", restitution_eps_naive(z), restitution_eps_delayed_recovery(z),
           restitution_one_minus_eps_naive(z), restitution_one_minus_eps_delayed_recovery(z),
           restitution_zeta_from_eps_naive(z), restitution_zeta_from_eps_delayed_recovery(z));
    printf("%a %a %a %a\n", restitution_duration_naive(z), restitution_duration_delayed_recovery(z),
           restitution_max_compression(z), restitution_max_compression_time(z));
  }
  fclose(in);
  return 0;
}
)C";

std::vector<double> header_points() {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> s(std::log(1e-12), std::log(1e8)), unit(0.0, 1.0);
  std::vector<double> points{0.0, 1.0, -1.0, 0.5, 1e-300, 1e300};
  while (points.size() < 10000) points.push_back(points.size() % 2 == 0 ? std::exp(s(rng)) : unit(rng));
  return points;
}

std::uint64_t bits(double x) {
  return std::bit_cast<std::uint64_t>(x);
}

// NaN for every domain error in C, an exception in C++: compare those as "NaN" against "throws".
double library_or_nan(double (*f)(double, CollisionEnd), double x, CollisionEnd end) {
  try {
    return f(x, end);
  } catch (const InvalidInput&) {
    return std::nan("");
  }
}

double max_compression_x(double zeta, CollisionEnd /*end*/) {
  return fast::max_compression(zeta).x;
}
double max_compression_tau(double zeta, CollisionEnd /*end*/) {
  return fast::max_compression(zeta).tau;
}

TEST(FastHeader, CompilesAsC99AndCxxAndAgreesBitForBit) {
  const auto dir = per_process_folder("restitution-fast-header");
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "restitution_fast.h") << fast::c_header();
  std::ofstream(dir / "driver.c") << kDriver;
  const std::vector<double> points = header_points();
  {
    std::ofstream list(dir / "points.txt");
    for (const double x : points) {
      char buffer[64];
      std::snprintf(buffer, sizeof buffer, "%a\n", x);
      list << buffer;
    }
  }
  const std::string d = dir.string();
  const std::string compilers[] = {"gcc -std=c99 -Wall -Wextra -Werror -pedantic -O2 -x c",
                                   "g++ -std=c++17 -Wall -Wextra -Werror -O2 -x c++"};
  for (const std::string& compiler : compilers) {
    const std::string build =
        compiler + " " + d + "/driver.c -o " + d + "/driver -lm 2> " + d + "/errors.txt";
    ASSERT_EQ(std::system(build.c_str()), 0) << build << "\n" << test_support::slurp(d + "/errors.txt");
    ASSERT_EQ(std::system((d + "/driver " + d + "/points.txt > " + d + "/values.txt").c_str()), 0);
    std::ifstream values(d + "/values.txt");
    std::string line;
    std::size_t i = 0;
    for (; std::getline(values, line) && i < points.size(); ++i) {
      std::istringstream fields(line);
      std::string field;
      const double x = points[i];
      const double expected[] = {library_or_nan(fast::eps, x, CollisionEnd::naive),
                                 library_or_nan(fast::eps, x, CollisionEnd::delayed_recovery),
                                 library_or_nan(fast::one_minus_eps, x, CollisionEnd::naive),
                                 library_or_nan(fast::one_minus_eps, x, CollisionEnd::delayed_recovery),
                                 library_or_nan(fast::zeta_from_eps, x, CollisionEnd::naive),
                                 library_or_nan(fast::zeta_from_eps, x, CollisionEnd::delayed_recovery),
                                 library_or_nan(fast::collision_duration, x, CollisionEnd::naive),
                                 library_or_nan(fast::collision_duration, x, CollisionEnd::delayed_recovery),
                                 library_or_nan(max_compression_x, x, CollisionEnd::naive),
                                 library_or_nan(max_compression_tau, x, CollisionEnd::naive)};
      for (const double want : expected) {
        ASSERT_TRUE(fields >> field);
        const double got = std::strtod(field.c_str(), nullptr);
        if (std::isnan(want)) {
          EXPECT_TRUE(std::isnan(got)) << compiler << " at " << x;
        } else {
          EXPECT_EQ(bits(got), bits(want)) << compiler << " at " << x << ": " << got << " vs " << want;
        }
      }
    }
    EXPECT_EQ(i, points.size()) << compiler;
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
