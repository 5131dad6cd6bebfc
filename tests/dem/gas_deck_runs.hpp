// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// What the gas deck tests (gas_deck_lammps.cpp, gas_deck_liggghts.cpp) share: the deck's files, a run of a
// DEM code with its output and wall time, the CPU time of the finished child processes, and one law's run of
// a comparison.
#include <sys/resource.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "dem/process_output.hpp"
#include "gas_deck/gas_comparison.hpp"
#include "gas_deck/lammps_gas_deck.hpp"

namespace restitution::test_support {

struct TimedRun {
  std::string output;
  double wall_s = 0.0;
};

// Runs `command` in a shell (standard error folded into the output) and times it.
inline TimedRun timed_run(const std::string& command) {
  const auto start = std::chrono::steady_clock::now();
  TimedRun r;
  r.output = dem::output_of(command + " 2>&1");
  r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

// CPU seconds of every finished child process so far (the shells popen ran, and the codes they started).
inline double children_cpu_s() {
  rusage u{};
  getrusage(RUSAGE_CHILDREN, &u);
  return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

// The deck's files in `folder`: gas.in, gas_constant_eps.in and the data file gas.data they read (the deck
// must have been written for "gas.data").
inline void write_gas_deck_files(const std::filesystem::path& folder, const gas_deck::GasDeck& deck) {
  std::ofstream(folder / "gas.data") << deck.data;
  std::ofstream(folder / "gas.in") << deck.law_input;
  std::ofstream(folder / "gas_constant_eps.in") << deck.constant_eps_input;
}

// The run of `law` ("viscoelastic" or "constant-eps") in a comparison.
inline const gas_deck::RunComparison& run_of(const gas_deck::GasComparison& c, const std::string& law) {
  for (const auto& r : c.runs)
    if (r.law == law) return r;
  throw std::runtime_error("no " + law + " run");
}
// Not of a temporary: the reference would outlive it (ASan found one such use after free).
const gas_deck::RunComparison& run_of(gas_deck::GasComparison&& c, const std::string& law) = delete;

}  // namespace restitution::test_support
