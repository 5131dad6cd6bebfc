// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A synthetic log of a gas deck's constant-eps run for `gas --compare`: Haff's law at 0.9 of Enskog's
// collision rate, for the gas of test_gas_deck_cli.cpp's kGas (tau0 from `gas --json` of a constant eps).
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cli_runner.hpp"

namespace restitution::test_support {

// The `gas` options of that gas, ready for more options.
inline const std::string kHaffGas =
    "gas --young-modulus 1e8 --poisson-ratio 0.4 --density 920 --radius 0.005 --eps 0.8 --velocity 2 "
    "--packing-fraction 0.1 --rms-speed 1 --haff-times 30 ";

// Writes the log to `path`; returns false when the theory's tau0 or the deck's setup line could not be had.
inline bool write_haff_log(const std::filesystem::path& path) {
  // T0 = m rms^2 with rms 1 m/s.
  const auto theory = run_cli(
      "gas --radius 0.005 --density 920 --law tsuji-hertz --eps 0.8 --velocity 2 --packing-fraction 0.1 "
      "--rms-speed 1 --haff-times 30 --json");
  if (theory.status != 0) return false;
  const double tau0 = nlohmann::json::parse(theory.out).at("tau0_s").get<double>();
  const double t0 = 920.0 * 4.0 / 3.0 * M_PI * std::pow(0.005, 3);
  // The run begins with the setup line its deck prints (the gas, which --compare checks against its own):
  // taken from a deck of this gas written in a folder of its own (the log's name may hold characters a shell
  // would read).
  const TempFolder deck_folder;
  const bool deck_written =
      run_cli(kHaffGas + "--particles 20 --deck " + (deck_folder.path / "g.in").string()).status == 0;
  const std::string input =
      deck_written ? slurp((deck_folder.path / "g_constant_eps.in").string()) : std::string();
  const auto setup = input.find("restitution-gas-setup ");
  if (setup == std::string::npos) return false;
  std::ofstream log(path);
  log.precision(15);
  log << "LAMMPS (29 Sep 2021 - Update 2)\n" << input.substr(setup, input.find('"', setup) - setup) << "\n";
  for (int i = 0; i <= 30; ++i) {
    const double t = i == 0 ? 0.0 : 0.1 * tau0 * std::pow(10.0, (i - 1) / 10.0);
    log << "restitution-gas law=constant-eps time_s=" << t
        << " temperature_j=" << t0 / std::pow(1.0 + 0.9 * t / tau0, 2) << " timestep_s=5e-06 step=" << i
        << "\n";
  }
  return static_cast<bool>(log);
}

}  // namespace restitution::test_support
