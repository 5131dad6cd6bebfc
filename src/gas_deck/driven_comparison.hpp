// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A driven gas deck's runs against the kinetic theory (restitution_gas/driven.hpp; docs/gas.md, "The driven
// gas"): the steady temperature and a₂ of each run by block averages of its steady part, the relaxation T(t)
// before it, and the theory's with the collision-rate factor measured on the constant-ε run's steady
// temperature.
//
// Blocks: the steady part's samples (kSteadySamplesPerRelaxation per relaxation time τ of the theory) are cut
// into consecutive blocks of kBlockRelaxationTimes τ. The fluctuations of T decay as e^{−t/τ} (τ = 1/λ of the
// linearised balance), so block means kBlockRelaxationTimes τ apart are nearly independent: the error bar is
// the standard deviation of the block means over √K, K the number of blocks (at least kFewestBlocks).
#include <string>
#include <vector>

#include "gas_deck/driven_log.hpp"
#include "gas_deck/gas_comparison.hpp"
#include "restitution_gas/driven.hpp"

namespace restitution::gas_deck {

inline constexpr double kBlockRelaxationTimes = 4.0;
inline constexpr int kFewestBlocks = 3;

struct BlockAverage {
  double mean = 0.0;
  double error = 0.0;  // standard deviation of the block means / √blocks
  int blocks = 0;
};

struct DrivenRunComparison {
  std::string run;  // the log and law: "gas.log viscoelastic"
  std::string law;
  // Measured in the steady part: T = m⟨v²⟩/3, a₂ = (3/5)⟨v⁴⟩/⟨v²⟩² − 1.
  BlockAverage steady_temperature_j, steady_a2;
  double theory_steady_temperature_j = 0.0, theory_steady_a2 = 0.0;  // the theory's T_s and stationary a₂
  // The relaxation part (t < steady_from_s): the run's T(t) and the theory's at the same times from the same
  // T0.
  std::vector<double> time_s, temperature_j, theory_temperature_j;
  double relaxation_max_deviation = 0.0;  // max |T/T_theory − 1| there
};

struct DrivenComparison {
  gas::Thermostat bath;
  double steady_from_s = 0.0;
  double relaxation_time_s = 0.0;  // the theory's, of the viscoelastic gas (the blocks' unit)
  double collision_rate_factor = 1.0;
  bool collision_rate_factor_measured = false;
  std::vector<DrivenRunComparison> runs;
};

// Throws InvalidInput when a run has no steady part of kFewestBlocks blocks, no moments for its law, or its
// bath is not `bath`.
DrivenComparison compare_driven(const GasSetup& setup, const gas::Thermostat& bath, const DrivenLog& log,
                                const std::vector<CoolingCurve>& curves, double relaxation_time_s);

// The block average of `values` sampled at `time_s` (ascending) from `from_s` on, in blocks of `block_s`.
BlockAverage block_average(const std::vector<double>& time_s, const std::vector<double>& values,
                           double from_s, double block_s);

}  // namespace restitution::gas_deck
