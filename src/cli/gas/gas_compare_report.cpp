// SPDX-License-Identifier: BSD-3-Clause
#include "cli/gas/gas_compare_report.hpp"

#include <fmt/core.h>

#include <cstdio>

#include "cli/common/plot_script.hpp"
#include "files/output_files.hpp"
#include "files/printable_name.hpp"
#include "sweep/csv_field.hpp"
#include "sweep/number_text.hpp"

namespace restitution::cli {

void print_log_note(const std::string& note) {
  fmt::print(stderr, "restitution: note: {}\n", note);
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
    fmt::print("{:<40} {:>14.4e} {:>10.4g} {:>13.4f} {:>15.4f}\n", files::printable_name(r.run),
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
    json.field("time_s", r.time_s).field("temperature_j", r.temperature_j);
    json.field("theory_temperature_j", r.theory_temperature_j).end_object();
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
      csv += fmt::format("{},{},{},{},{},{},{}\n", quoted_field(files::printable_name(r.run)), r.law,
                         number17(r.time_s[i]), number17(r.temperature_j[i]),
                         number17(r.theory_temperature_j[i]), has ? number17(r.exponent.exponent[i - 1]) : "",
                         has ? number17(r.theory_exponent.exponent[i - 1]) : "");
    }
  }
  const auto data = folder / "gas_compare.csv";
  files::write_file_atomically(data, csv);
  return run_plot_script("gas_compare", data, folder / "gas_compare.png");
}

}  // namespace restitution::cli
