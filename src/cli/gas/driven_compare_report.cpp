// SPDX-License-Identifier: BSD-3-Clause
#include "cli/gas/driven_compare_report.hpp"

#include <fmt/core.h>

namespace restitution::cli {

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
    json.field("time_s", r.time_s).field("temperature_j", r.temperature_j);
    json.field("theory_temperature_j", r.theory_temperature_j).end_object();
  }
  json.end_array().end_object();
}

}  // namespace restitution::cli
