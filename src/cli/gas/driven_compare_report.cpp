// SPDX-License-Identifier: BSD-3-Clause
#include "cli/gas/driven_compare_report.hpp"

#include <fmt/core.h>
#include <fmt/format.h>

#include "cli/gas/gas_compare_report.hpp"
#include "gas_deck/gas_log.hpp"
#include "restitution/errors.hpp"

namespace restitution::cli {

gas_deck::DrivenComparison compare_driven_logs(const std::vector<std::string>& logs,
                                               const gas_deck::GasSetup& setup, const gas::Thermostat& bath,
                                               double relaxation_time_s) {
  std::vector<gas_deck::CoolingCurve> curves;
  gas_deck::DrivenLog driven;
  for (const auto& log : logs) {
    gas_deck::GasLog read = gas_deck::read_gas_log_file(log);
    for (const auto& note : read.notes) fmt::print(stderr, "restitution: note: {}\n", note);
    for (const auto& curve : read.curves) gas_deck::check_gas_log_setup(curve.setup, setup.log, log);
    curves.insert(curves.end(), read.curves.begin(), read.curves.end());
    gas_deck::DrivenLog one = gas_deck::read_driven_log_file(log);
    if (one.bath && driven.bath && one.bath->bath_temperature_j != driven.bath->bath_temperature_j) {
      throw InvalidInput(
          fmt::format("--compare: {} is the log of another bath than the logs before it", log));
    }
    if (one.bath) driven.bath = one.bath;
    driven.runs.insert(driven.runs.end(), one.runs.begin(), one.runs.end());
  }
  if (curves.empty()) {
    throw InvalidInput(fmt::format("--compare: no {} lines in {} (the output of a deck of gas --deck)",
                                   gas_deck::kGasTag, fmt::format("{}", fmt::join(logs, ", "))));
  }
  return gas_deck::compare_driven(setup, bath, driven, curves, relaxation_time_s);
}

void print_driven_comparison_text(const gas_deck::DrivenComparison& c) {
  fmt::print(
      "# Langevin bath T_b = {:.6g} J, tau_b = {:.6g} s; steady part from {:.6g} s, blocks of {:g} "
      "relaxation "
      "times ({:.4g} s)\n",
      c.bath.bath_temperature_j, c.bath.bath_time_s, c.steady_from_s, gas_deck::kBlockRelaxationTimes,
      gas_deck::kBlockRelaxationTimes * c.relaxation_time_s);
  fmt::print("# collision-rate factor {:.6g}{}\n", c.collision_rate_factor,
             c.collision_rate_factor_measured ? " (measured on the constant-eps run's steady temperature)"
                                              : ": Enskog's rate (no constant-eps run given to measure it)");
  fmt::print("{:<40} {:>14} {:>10} {:>14} {:>9} {:>11} {:>9} {:>11} {:>13}\n", "run", "T_s_j", "+-",
             "theory_T_s_j", "T_s/th-1", "a2", "+-", "theory_a2", "relax_maxdev");
  for (const auto& r : c.runs) {
    fmt::print("{:<40} {:>14.7e} {:>10.3e} {:>14.7e} {:>9.5f} {:>11.4e} {:>9.2e} {:>11.4e} {:>13.5f}\n",
               r.run, r.steady_temperature_j.mean, r.steady_temperature_j.error,
               r.theory_steady_temperature_j,
               r.steady_temperature_j.mean / r.theory_steady_temperature_j - 1.0, r.steady_a2.mean,
               r.steady_a2.error, r.theory_steady_a2, r.relaxation_max_deviation);
  }
}

void write_driven_comparison_json(JsonWriter& json, const gas_deck::DrivenComparison& c) {
  json.key("driven_comparison").begin_object();
  json.field("bath_temperature_j", c.bath.bath_temperature_j).field("bath_time_s", c.bath.bath_time_s);
  json.field("steady_from_s", c.steady_from_s).field("relaxation_time_s", c.relaxation_time_s);
  json.field("block_relaxation_times", gas_deck::kBlockRelaxationTimes);
  json.field("collision_rate_factor", c.collision_rate_factor);
  json.field("collision_rate_factor_measured", c.collision_rate_factor_measured);
  json.key("runs").begin_array();
  for (const auto& r : c.runs) {
    json.begin_object().field("run", r.run).field("law", r.law);
    json.field("steady_temperature_j", r.steady_temperature_j.mean)
        .field("steady_temperature_error_j", r.steady_temperature_j.error)
        .field("blocks", static_cast<long>(r.steady_temperature_j.blocks));
    json.field("theory_steady_temperature_j", r.theory_steady_temperature_j);
    json.field("steady_a2", r.steady_a2.mean).field("steady_a2_error", r.steady_a2.error);
    json.field("theory_steady_a2", r.theory_steady_a2);
    json.field("relaxation_max_deviation", r.relaxation_max_deviation);
    for (const auto& [name, values] :
         {std::pair{"time_s", &r.time_s}, std::pair{"temperature_j", &r.temperature_j},
          std::pair{"theory_temperature_j", &r.theory_temperature_j}}) {
      json.key(name).begin_array();
      for (const double v : *values) json.value(v);
      json.end_array();
    }
    json.end_object();
  }
  json.end_array().end_object();
}

}  // namespace restitution::cli
