// SPDX-License-Identifier: BSD-3-Clause
// Issue 35's must-show for the gas deck (docs/gas.md, "The LAMMPS deck"): the deck `gas_deck` writes, run as
// written by Debian's LAMMPS for N = 2000 spheres (Y = 1e8 Pa, nu = 0.4, rho = 920 kg/m3, R = 5 mm, eps = 0.8
// at 2 m/s) at packing fraction 0.1 for 30 tau0: the viscoelastic T(t) within 5 % of the kinetic theory with
// the exact eps(v) over the whole run and its late local exponent within 0.05 of the theory's, the
// constant-eps companion within 5 % of Haff's law (the theory's collision rate carries one factor, measured
// on the companion run), and the viscoelastic deck under `mpirun -np 2` with the same statistics (late
// exponent within 0.05 of the serial run's). The two serial runs go side by side, then the MPI run: about 2 x
// 15 s here on an idle machine.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <future>
#include <iostream>
#include <string>

#include "cli_runner.hpp"
#include "dem/code_runner.hpp"
#include "dem/gas_deck_runs.hpp"
#include "gas_deck/gas_comparison.hpp"
#include "gas_deck/gas_log.hpp"
#include "gas_deck/lammps_gas_deck.hpp"
#include "issue_gas.hpp"

namespace {

namespace gd = restitution::gas_deck;

// Issue 35's run: N = 2000, rms speed 1 m/s per direction, 30 tau0.
gd::GasDeckRequest issue_run() {
  gd::GasDeckRequest r = restitution::test_support::issue_gas();
  r.particles = 2000;
  r.rms_speed_m_s = 1.0;
  r.haff_times = 30.0;
  return r;
}

using restitution::test_support::children_cpu_s;
using restitution::test_support::run_of;
using restitution::test_support::timed_run;
using restitution::test_support::TimedRun;

TEST(GasDeckLammps, CoolsAsTheTheorySaysSeriallyAndOnTwoRanks) {
  ASSERT_FALSE(restitution::dem::dem_program(restitution::dem::Code::lammps).empty())
      << "lmp not found on PATH: scripts/setup installs Debian's lammps";
  restitution::test_support::TempFolder folder;
  const gd::GasDeckRequest request = issue_run();
  const gd::GasDeck deck = gd::lammps_gas_deck(request, "gas.data");
  ASSERT_TRUE(deck.warnings.empty()) << deck.warnings.front();
  restitution::test_support::write_gas_deck_files(folder.path, deck);

  setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
  setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
  setenv("OMPI_MCA_btl", "self,vader", 1);
  setenv("OMPI_MCA_btl_vader_single_copy_mechanism", "none", 1);
  setenv("OMPI_MCA_mpi_yield_when_idle", "1", 1);
  const std::string in = "cd " + folder.path.string() + " && ";
  const double cpu_before = children_cpu_s();
  auto law = std::async(std::launch::async, [&] { return timed_run(in + "lmp -log none -in gas.in"); });
  auto companion =
      std::async(std::launch::async, [&] { return timed_run(in + "lmp -log none -in gas_constant_eps.in"); });
  const TimedRun serial = law.get();
  const TimedRun constant = companion.get();
  const double serial_cpu_s = children_cpu_s() - cpu_before;
  const TimedRun mpi =
      timed_run(in + "mpirun --allow-run-as-root --oversubscribe -np 2 lmp -log none -in gas.in");

  const gd::GasSetup setup = gd::gas_setup(request);
  const auto both = gd::read_gas_log(serial.output + constant.output, "serial runs").curves;
  ASSERT_EQ(both.size(), 2U) << serial.output.substr(serial.output.size() > 2000 ? serial.output.size() - 2000
                                                                                 : 0);
  const gd::GasComparison c = gd::compare_with_theory(setup, both);
  const auto& visco = run_of(c, "viscoelastic");
  const auto& haff = run_of(c, "constant-eps");
  const auto mpi_curves = gd::read_gas_log(mpi.output, "mpirun -np 2").curves;
  ASSERT_EQ(mpi_curves.size(), 1U) << mpi.output.substr(mpi.output.size() > 2000 ? mpi.output.size() - 2000
                                                                                 : 0);
  // The MPI run against the same theory, with the factor of the serial companion.
  std::vector<gd::CoolingCurve> mpi_and_companion{mpi_curves[0],
                                                  both[1].law == "constant-eps" ? both[1] : both[0]};
  // Kept by name: run_of returns a reference into the comparison, which must outlive it.
  const gd::GasComparison mpi_comparison = gd::compare_with_theory(setup, mpi_and_companion);
  const auto& visco_mpi = run_of(mpi_comparison, "viscoelastic");

  const double steps = std::stod(serial.output.substr(serial.output.rfind("step=") + 5));
  std::cout << "collision rate factor " << c.collision_rate_factor << "; duration " << visco.haff_times
            << " tau0 of the viscoelastic theory, " << deck.duration_s / deck.haff_time_s
            << " of Enskog's Haff\n"
            << "viscoelastic: max |T/T_theory - 1| " << visco.max_relative_deviation << ", late exponent "
            << visco.late_exponent << " (theory " << visco.theory_late_exponent << ")\n"
            << "constant eps: max |T/T_Haff - 1| " << haff.max_relative_deviation << ", late exponent "
            << haff.late_exponent << " (theory " << haff.theory_late_exponent << ")\n"
            << "mpirun -np 2: max |T/T_theory - 1| " << visco_mpi.max_relative_deviation << ", late exponent "
            << visco_mpi.late_exponent << "\n"
            << "wall: " << serial.wall_s << " s serial (" << steps << " steps, "
            << 1e6 * serial.wall_s / (steps * request.particles) << " us per particle-step), " << mpi.wall_s
            << " s on two ranks; CPU " << serial_cpu_s << " s for both serial runs ("
            << 1e6 * serial_cpu_s / (2.0 * steps * request.particles) << " us per particle-step), "
            << children_cpu_s() - cpu_before - serial_cpu_s << " s on two ranks\n";
  RecordProperty("collision_rate_factor", std::to_string(c.collision_rate_factor));
  RecordProperty("viscoelastic_max_relative_deviation", std::to_string(visco.max_relative_deviation));
  RecordProperty("viscoelastic_late_exponent", std::to_string(visco.late_exponent));
  RecordProperty("constant_eps_max_relative_deviation", std::to_string(haff.max_relative_deviation));
  RecordProperty("mpi_late_exponent", std::to_string(visco_mpi.late_exponent));

  EXPECT_GE(visco.haff_times, 30.0 * 0.5) << "the run must span many Haff times of its own law";
  EXPECT_GE(deck.duration_s / deck.haff_time_s, 30.0 - 1e-9);
  EXPECT_LE(visco.max_relative_deviation, 0.05);
  EXPECT_NEAR(visco.late_exponent, visco.theory_late_exponent, 0.05);
  EXPECT_LE(haff.max_relative_deviation, 0.05);
  EXPECT_LE(visco_mpi.max_relative_deviation, 0.05);
  EXPECT_NEAR(visco_mpi.late_exponent, visco.late_exponent, 0.05);
  // The two laws differ where the test looks: the viscoelastic gas cools more slowly late.
  EXPECT_GT(visco.late_exponent - haff.late_exponent, 0.1);
}

}  // namespace
