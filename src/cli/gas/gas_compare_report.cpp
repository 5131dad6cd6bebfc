// SPDX-License-Identifier: BSD-3-Clause
#include "cli/gas/gas_compare_report.hpp"

#include <fmt/core.h>
#include <fmt/ranges.h>

#include <cstdio>

#include "cli/common/output_files.hpp"
#include "restitution/errors.hpp"
#include "sweep/csv_field.hpp"
#include "sweep/printable_name.hpp"

namespace restitution::cli {

gas_deck::GasComparison compare_logs(const std::vector<std::string>& logs, const gas_deck::GasSetup& setup) {
  std::vector<gas_deck::CoolingCurve> curves;
  for (const auto& log : logs) {
    gas_deck::GasLog read = gas_deck::read_gas_log_file(log);
    for (const auto& note : read.notes) fmt::print(stderr, "restitution: note: {}\n", note);
    for (const auto& curve : read.curves) gas_deck::check_gas_log_setup(curve.setup, setup.log, log);
    curves.insert(curves.end(), read.curves.begin(), read.curves.end());
  }
  if (curves.empty()) {
    throw InvalidInput(fmt::format("--compare: no {} lines in {} (the output of a deck of gas --deck)",
                                   gas_deck::kGasTag, fmt::format("{}", fmt::join(logs, ", "))));
  }
  return gas_deck::compare_with_theory(setup, curves);
}

void print_comparison_text(const gas_deck::GasComparison& c) {
  if (c.collision_rate_factor_measured) {
    fmt::print("# collision-rate factor measured on the constant-eps run (Haff fit): {:.6g}\n",
               c.collision_rate_factor);
  } else {
    fmt::print("# collision-rate factor {:.6g}: Enskog's rate (no constant-eps run given to measure it)\n",
               c.collision_rate_factor);
  }
  fmt::print("{:<40} {:>14} {:>10} {:>13} {:>15}\n", "run", "max_rel_dev", "tau0", "late_exponent",
             "theory_late");
  for (const auto& r : c.runs) {
    fmt::print("{:<40} {:>14.4e} {:>10.4g} {:>13.4f} {:>15.4f}\n", printable_name(r.run),
               r.max_relative_deviation, r.haff_times, r.late_exponent, r.theory_late_exponent);
  }
}

void write_comparison_json(JsonWriter& json, const gas_deck::GasComparison& c) {
  json.field("collision_rate_factor", c.collision_rate_factor);
  json.field("collision_rate_factor_measured", c.collision_rate_factor_measured);
  json.key("runs").begin_array();
  for (const auto& r : c.runs) {
    json.begin_object().field("run", r.run).field("law", r.law);
    json.field("max_relative_deviation", r.max_relative_deviation).field("late_exponent", r.late_exponent);
    json.field("theory_late_exponent", r.theory_late_exponent).field("haff_times", r.haff_times);
    json.key("time_s").begin_array();
    for (double t : r.time_s) json.value(t);
    json.end_array().key("temperature_j").begin_array();
    for (double t : r.temperature_j) json.value(t);
    json.end_array().key("theory_temperature_j").begin_array();
    for (double t : r.theory_temperature_j) json.value(t);
    json.end_array().end_object();
  }
  json.end_array();
}

std::string write_comparison_files(const std::filesystem::path& folder, const gas_deck::GasComparison& c) {
  std::string csv =
      "run,law,time_s,temperature_j,theory_temperature_j,local_exponent,theory_local_exponent\n";
  for (const auto& r : c.runs) {
    for (std::size_t i = 0; i < r.time_s.size(); ++i) {
      // The local exponents are between consecutive times after t = 0: the one ending at time_s[i] is i - 1.
      const bool has = i >= 1 && i - 1 < r.exponent.exponent.size();
      // The run is named by its log file, whose name may hold anything: quoted, escaped, one field.
      csv += fmt::format("{},{},{},{},{},{},{}\n", quoted_field(printable_name(r.run)), r.law,
                         number17(r.time_s[i]), number17(r.temperature_j[i]),
                         number17(r.theory_temperature_j[i]), has ? number17(r.exponent.exponent[i - 1]) : "",
                         has ? number17(r.theory_exponent.exponent[i - 1]) : "");
    }
  }
  const auto data = folder / "gas_compare.csv";
  write_file_atomically(data, csv);
  return run_plot_script("gas_compare", data, folder / "gas_compare.png");
}

}  // namespace restitution::cli
