// SPDX-License-Identifier: BSD-3-Clause
// The gas deck (gas_deck/): the initial state (non-overlapping, reproducible, zero momentum, exact T), the
// scales of the cooling gas, the deck's schedule and time step, and the clustering warning.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "dem/integrator_eps.hpp"
#include "gas_deck/cooling_scales.hpp"
#include "gas_deck/gas_log.hpp"
#include "gas_deck/lammps_gas_deck.hpp"
#include "gas_deck/placement.hpp"
#include "issue_gas.hpp"
#include "restitution/errors.hpp"

namespace {

namespace gd = restitution::gas_deck;

double periodic_distance(const gd::Vec3& a, const gd::Vec3& b, double box) {
  double sum = 0.0;
  for (int k = 0; k < 3; ++k) {
    double d = std::abs(a[k] - b[k]);
    d = std::min(d, box - d);
    sum += d * d;
  }
  return std::sqrt(sum);
}

TEST(GasPlacement, NoOverlapsInsideTheBoxAndReproducible) {
  const double sigma = 0.01;
  const std::size_t n = 1500;
  const double box = std::cbrt(n * std::numbers::pi / 6.0 * std::pow(sigma, 3) / 0.25);
  const auto x = gd::random_positions(n, sigma, box, 7);
  ASSERT_EQ(x.size(), n);
  double closest = INFINITY;
  for (std::size_t i = 0; i < n; ++i) {
    for (double c : x[i]) {
      EXPECT_GE(c, 0.0);
      EXPECT_LT(c, box);
    }
    for (std::size_t j = 0; j < i; ++j) closest = std::min(closest, periodic_distance(x[i], x[j], box));
  }
  EXPECT_GE(closest, sigma);
  EXPECT_LT(closest, 1.1 * sigma) << "a gas at phi = 0.25 has near neighbours";
  EXPECT_EQ(gd::random_positions(n, sigma, box, 7), x);
  EXPECT_NE(gd::random_positions(n, sigma, box, 8), x);
  EXPECT_THROW(gd::random_positions(n, sigma, 0.8 * box, 7), restitution::InvalidInput);
}

TEST(GasPlacement, MaxwellianWithZeroMomentumAndExactTemperature) {
  const std::size_t n = 20000;
  const double rms = 1.7;
  const auto v = gd::maxwellian_velocities(n, rms, 3);
  gd::Vec3 p{};
  double squares = 0.0;
  double fourth = 0.0;
  for (const auto& u : v)
    for (int k = 0; k < 3; ++k) {
      p[k] += u[k];
      squares += u[k] * u[k];
      fourth += std::pow(u[k], 4);
    }
  for (double c : p) EXPECT_NEAR(c / n, 0.0, 1e-12);
  EXPECT_NEAR(squares / (3.0 * n), rms * rms, 1e-12);
  // Gaussian: <u^4> = 3 <u^2>^2 (kurtosis 3), to the sampling error of 6e4 components.
  EXPECT_NEAR(fourth / (3.0 * n) / std::pow(rms, 4), 3.0, 0.1);
}

TEST(GasScales, HaffTimeIsTheEnskogIntegral) {
  // 1/tau0 from dT/dt = -(pi/3) n g2 sigma^2 m (1 - eps^2) <u^3>_{u>0} at t = 0, with the one-sided Gaussian
  // of the normal relative speed (variance 2T/m) integrated numerically.
  const double sigma = 0.01, m = 4.8e-4, phi = 0.1, temperature = 5e-4, eps = 0.8;
  const auto s = gd::gas_scales(sigma, m, phi, temperature, eps);
  const double variance = 2.0 * temperature / m;
  double moment = 0.0;
  const double du = 1e-4;
  for (double u = du / 2; u < 30.0; u += du)
    moment +=
        u * u * u * std::exp(-u * u / (2.0 * variance)) / std::sqrt(2.0 * std::numbers::pi * variance) * du;
  const double cooling = std::numbers::pi / 3.0 * s.number_density_m3 * s.pair_correlation * sigma * sigma *
                         m * (1.0 - eps * eps) * moment / temperature;
  EXPECT_NEAR(s.haff_time_s * cooling / 2.0, 1.0, 1e-6);
  // L_c does not depend on the temperature; it shrinks as the dissipation grows.
  EXPECT_DOUBLE_EQ(gd::gas_scales(sigma, m, phi, 4.0 * temperature, eps).shear_critical_length_m,
                   s.shear_critical_length_m);
  EXPECT_GT(gd::gas_scales(sigma, m, phi, temperature, 0.9).shear_critical_length_m,
            s.shear_critical_length_m);
}

gd::GasDeckRequest issue_gas(std::size_t n) {
  gd::GasDeckRequest r = restitution::test_support::issue_gas();
  r.particles = n;
  r.rms_speed_m_s = 1.0;
  r.haff_times = 100.0;
  return r;
}

// LIGGGHTS 3.8.0 (run by tests/dem/gas_deck_liggghts.cpp): its prerequisites, hertz/stiffness and the model
// hertz companion, no immediate variables (it has none), and the same data file, time step and schedule.
TEST(GasDeck, LiggghtsDeckSpeaksLiggghts) {
  gd::GasDeckRequest r = issue_gas(2000);
  const gd::GasDeck lammps = gd::lammps_gas_deck(r, "gas.data");
  r.code = restitution::dem::Code::liggghts;
  const gd::GasDeck d = gd::lammps_gas_deck(r, "gas.data");
  for (const std::string& input : {d.law_input, d.constant_eps_input}) {
    for (const char* needed :
         {"units si\n", "atom_style granular\n", "newton off\n", "communicate single vel yes\n",
          "read_data gas.data\n", "run ${gas_steps}\n", "liggghts -in FILE"})
      EXPECT_NE(input.find(needed), std::string::npos) << needed;
    EXPECT_EQ(input.find("$("), std::string::npos);
    EXPECT_EQ(input.find("comm_modify"), std::string::npos);
  }
  EXPECT_NE(d.law_input.find("pair_style gran model hertz/stiffness tangential no_history limitForce on"),
            std::string::npos);
  EXPECT_NE(d.constant_eps_input.find("pair_style gran model hertz tangential no_history limitForce on"),
            std::string::npos);
  EXPECT_NE(d.constant_eps_input.find("coefficientRestitution peratomtypepair 1 0.79"), std::string::npos);
  EXPECT_EQ(d.data, lammps.data);
  EXPECT_EQ(d.time_step_s, lammps.time_step_s);
  EXPECT_EQ(d.print_times_s, lammps.print_times_s);
  EXPECT_NEAR(d.constant_eps, 0.8, 1e-9);
  r.code = restitution::dem::Code::yade;
  try {
    (void)gd::lammps_gas_deck(r, "gas.data");
    ADD_FAILURE() << "yade accepted";
  } catch (const restitution::InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("--code yade: the gas deck is written for lammps and liggghts only"),
              std::string::npos)
        << e.what();
  }
}

TEST(GasDeck, TimeStepScheduleAndPrerequisites) {
  const gd::GasDeck d = gd::lammps_gas_deck(issue_gas(2000), "gas.data");
  for (const std::string& input : {d.law_input, d.constant_eps_input}) {
    for (const char* needed :
         {"units si\n", "atom_style sphere\n", "comm_modify vel yes\n", "boundary p p p\n",
          "read_data gas.data\n", "fix integrate all nve/sphere\n", "mpirun"})
      EXPECT_NE(input.find(needed), std::string::npos) << needed;
  }
  EXPECT_NE(d.law_input.find("damping viscoelastic limit_damping"), std::string::npos);
  EXPECT_NE(d.constant_eps_input.find("damping tsuji limit_damping"), std::string::npos);
  EXPECT_NEAR(d.constant_eps, 0.8, 1e-9);
  // The time step meets the bound at the fast end of the impact speeds, and barely.
  EXPECT_LE(d.eps_error_worst, 1e-3);
  EXPECT_GT(d.eps_error_worst, 0.3e-3);
  EXPECT_NEAR(d.fast_speed_m_s, 3.0 * std::sqrt(6.0), 1e-12);
  // Log-spaced: ten per decade up to the duration, which is 100 tau0.
  EXPECT_NEAR(d.duration_s / d.haff_time_s, 100.0, 1e-9);
  ASSERT_GT(d.print_times_s.size(), 20U);
  EXPECT_DOUBLE_EQ(d.print_times_s.back(), d.duration_s);
  for (std::size_t i = 1; i + 1 < d.print_times_s.size(); ++i)
    EXPECT_NEAR(d.print_times_s[i] / d.print_times_s[i - 1], std::pow(10.0, 0.1), 1e-12);
  // The data file holds every sphere and velocity.
  EXPECT_NE(d.data.find("2000 atoms\n"), std::string::npos);
  EXPECT_NE(d.data.find("\n2000 1 0.01 "), std::string::npos);
}

TEST(GasDeck, WarnsWhereTheConstantEpsGasClusters) {
  // Issue 35: at phi = 0.1, eps = 0.8 and 100 tau0 the box of 2000 spheres (21.9 diameters) stayed
  // homogeneous, that of 4000 (27.6) formed a shear flow.
  const gd::GasDeck small = gd::lammps_gas_deck(issue_gas(2000), "gas.data");
  const gd::GasDeck large = gd::lammps_gas_deck(issue_gas(4000), "gas.data");
  EXPECT_GT(small.box_m, small.shear_critical_length_m) << "both boxes are above L_c: growth decides";
  EXPECT_TRUE(small.warnings.empty());
  ASSERT_EQ(large.warnings.size(), 1U);
  EXPECT_NE(large.warnings[0].find("cluster"), std::string::npos);
  EXPECT_NE(large.constant_eps_input.find("will cluster"), std::string::npos);
}

TEST(GasLog, ReadsTheTaggedLinesOnly) {
  const std::string setup =
      " end=delayed-recovery diameter_m=0.01 mass_kg=0.0004817108736 young_modulus_pa=100000000 "
      "poisson_ratio=0.4 dissipative_constant_s=1e-05 packing_fraction=0.1 "
      "initial_temperature_j=0.0004817108736\n";
  const std::string log =
      "print \"restitution-gas law=viscoelastic time_s=$(time) ...\"\n"
      "restitution-gas-setup law=viscoelastic" +
      setup +
      "restitution-gas law=viscoelastic time_s=0 temperature_j=2 timestep_s=1e-6 step=0\n"
      "restitution-gas-setup law=constant-eps" +
      setup +
      "restitution-gas law=constant-eps time_s=0 temperature_j=2 timestep_s=1e-6 step=0\n"
      "restitution-gas law=viscoelastic time_s=1 temperature_j=0.5 timestep_s=1e-6 step=10\n"
      "restitution-gas law=viscoelastic time_s=10 temperature_j=0.005 timestep_s=1e-6 step=100\n";
  const auto read = gd::read_gas_log(log, "log");
  ASSERT_EQ(read.curves.size(), 2U);
  EXPECT_TRUE(read.notes.empty());
  EXPECT_EQ(read.curves[0].law, "viscoelastic");
  EXPECT_EQ(read.curves[0].time_s, (std::vector<double>{0, 1, 10}));
  EXPECT_EQ(read.curves[0].line, (std::vector<std::size_t>{3, 6, 7}));
  EXPECT_EQ(read.curves[1].setup.packing_fraction, 0.1);
  const auto e = gd::local_exponent(read.curves[0].time_s, read.curves[0].temperature_j);
  ASSERT_EQ(e.exponent.size(), 1U);
  EXPECT_DOUBLE_EQ(e.exponent[0], -2.0);
  EXPECT_THROW(gd::read_gas_log("restitution-gas law=x time_s=1 temperature_j=-1\n", "log"),
               restitution::InvalidInput);
}

}  // namespace
