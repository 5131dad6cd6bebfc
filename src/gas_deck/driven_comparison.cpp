// SPDX-License-Identifier: BSD-3-Clause
#include "gas_deck/driven_comparison.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "restitution/errors.hpp"

namespace restitution::gas_deck {

BlockAverage block_average(const std::vector<double>& time_s, const std::vector<double>& values,
                           double from_s, double block_s) {
  std::vector<double> sums, counts;
  for (std::size_t i = 0; i < time_s.size(); ++i) {
    if (time_s[i] <= from_s) continue;
    const auto block = static_cast<std::size_t>((time_s[i] - from_s) / block_s);
    if (block >= sums.size()) {
      sums.resize(block + 1, 0.0);
      counts.resize(block + 1, 0.0);
    }
    sums[block] += values[i];
    counts[block] += 1.0;
  }
  // The last block counts only when it is (nearly) whole: a stub of a few samples is not independent of it.
  while (!counts.empty() && counts.back() < 0.75 * counts.front()) {
    counts.pop_back();
    sums.pop_back();
  }
  BlockAverage b;
  b.blocks = static_cast<int>(sums.size());
  if (b.blocks == 0) return b;
  std::vector<double> means;
  for (std::size_t k = 0; k < sums.size(); ++k) means.push_back(sums[k] / counts[k]);
  for (const double m : means) b.mean += m / static_cast<double>(means.size());
  double variance = 0.0;
  for (const double m : means) variance += (m - b.mean) * (m - b.mean);
  if (b.blocks > 1) b.error = std::sqrt(variance / (b.blocks - 1) / b.blocks);
  return b;
}

namespace {

const DrivenMoments& moments_of(const DrivenLog& log, const std::string& law, const std::string& source) {
  for (const DrivenMoments& m : log.runs) {
    if (m.law == law) return m;
  }
  throw InvalidInput(fmt::format("--compare: {} has no {} lines of the {} run (not a driven deck's log)",
                                 source, kDrivenTag, law));
}

// The theory of one run: T(t) at the relaxation part's times and the steady state.
gas::DrivenCurve theory_of(const GasSetup& setup, const gas::Thermostat& bath, const std::string& law,
                           const std::vector<double>& times_s, double factor) {
  gas::DrivenRequest r;
  r.gas.particles = setup.particles;
  r.gas.law = law == "constant-eps" ? gas::constant_eps_law(setup.constant_eps) : setup.law;
  r.gas.initial_temperature_j = setup.log.initial_temperature_j;
  r.gas.a2_evolving = true;  // from the deck's Maxwellian start
  r.gas.collision_rate_factor = factor;
  r.gas.times_s = times_s;
  r.gas.duration = times_s.back();
  r.thermostat = bath;
  return gas::driven_curve(r);
}

// c from the constant-ε run's steady temperature T_m: the collisions' loss ζT ∝ c T^{3/2} for a constant ε,
// so q − 2γT_m = c (q − 2γT₁)(T_m/T₁)^{3/2} with T₁ the theory's T_s at c = 1.
double measured_factor(const GasSetup& setup, const gas::Thermostat& bath, double measured_j,
                       const std::vector<double>& times_s) {
  const double t1 = theory_of(setup, bath, "constant-eps", times_s, 1.0).steady.temperature_j;
  const double q = bath.heating_j_s();
  const double drag = 2.0 * bath.drag_hz();
  return (q - drag * measured_j) / ((q - drag * t1) * std::pow(measured_j / t1, 1.5));
}

}  // namespace

DrivenComparison compare_driven(const GasSetup& setup, const gas::Thermostat& bath, const DrivenLog& log,
                                const std::vector<CoolingCurve>& curves, double relaxation_time_s) {
  if (!log.bath) throw InvalidInput("--compare: the logs hold no run of a driven deck (no bath line)");
  if (log.bath->bath_temperature_j != bath.bath_temperature_j || log.bath->bath_time_s != bath.bath_time_s) {
    throw InvalidInput(fmt::format(
        "--compare: the logs' bath (T_b = {} J, tau_b = {} s) is not the command's (--bath-temperature {}, "
        "--bath-time {})",
        log.bath->bath_temperature_j, log.bath->bath_time_s, bath.bath_temperature_j, bath.bath_time_s));
  }
  DrivenComparison c;
  c.bath = bath;
  c.steady_from_s = log.bath->steady_from_s;
  c.relaxation_time_s = relaxation_time_s;
  const double block_s = kBlockRelaxationTimes * relaxation_time_s;
  for (const CoolingCurve& curve : curves) {
    DrivenRunComparison run;
    run.run = curve.source + " " + curve.law;
    run.law = curve.law;
    run.steady_temperature_j = block_average(curve.time_s, curve.temperature_j, c.steady_from_s, block_s);
    const DrivenMoments& m = moments_of(log, curve.law, curve.source);
    std::vector<double> a2;
    for (std::size_t i = 0; i < m.time_s.size(); ++i)
      a2.push_back(0.6 * m.mean_v4_m4_s4[i] / (m.mean_v2_m2_s2[i] * m.mean_v2_m2_s2[i]) - 1.0);
    run.steady_a2 = block_average(m.time_s, a2, c.steady_from_s, block_s);
    if (run.steady_temperature_j.blocks < kFewestBlocks || run.steady_a2.blocks < kFewestBlocks) {
      throw InvalidInput(
          fmt::format("--compare: {} holds {} blocks of {:.4g} s in its steady part, fewer than {}", run.run,
                      run.steady_temperature_j.blocks, block_s, kFewestBlocks));
    }
    for (std::size_t i = 0; i < curve.time_s.size(); ++i) {
      if (curve.time_s[i] > 0.0 && curve.time_s[i] < c.steady_from_s) {
        run.time_s.push_back(curve.time_s[i]);
        run.temperature_j.push_back(curve.temperature_j[i]);
      }
    }
    if (run.time_s.empty()) throw InvalidInput(fmt::format("--compare: {} has no relaxation part", run.run));
    c.runs.push_back(std::move(run));
  }
  for (const DrivenRunComparison& run : c.runs) {
    if (run.law != "constant-eps") continue;
    c.collision_rate_factor = measured_factor(setup, bath, run.steady_temperature_j.mean, run.time_s);
    c.collision_rate_factor_measured = true;
  }
  for (DrivenRunComparison& run : c.runs) {
    const gas::DrivenCurve theory = theory_of(setup, bath, run.law, run.time_s, c.collision_rate_factor);
    run.theory_temperature_j = theory.curve.temperature_j;
    run.theory_steady_temperature_j = theory.steady.temperature_j;
    run.theory_steady_a2 = theory.steady.a2;
    for (std::size_t i = 0; i < run.time_s.size(); ++i) {
      run.relaxation_max_deviation = std::max(
          run.relaxation_max_deviation, std::abs(run.temperature_j[i] / run.theory_temperature_j[i] - 1.0));
    }
  }
  return c;
}

}  // namespace restitution::gas_deck
