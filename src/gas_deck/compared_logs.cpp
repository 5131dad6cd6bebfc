// SPDX-License-Identifier: BSD-3-Clause
#include "gas_deck/compared_logs.hpp"

#include <fmt/format.h>

#include "gas_deck/driven_log.hpp"
#include "gas_deck/gas_log_setup.hpp"
#include "gas_deck/lammps_gas_deck.hpp"
#include "restitution/errors.hpp"

namespace restitution::gas_deck {

ComparedLogs read_compared_logs(const std::vector<std::string>& logs, const GasSetup& setup, bool driven,
                                const LogNote& note) {
  ComparedLogs read;
  for (const auto& log : logs) {
    GasLog one = read_gas_log_file(log);
    for (const auto& text : one.notes) note(text);
    for (const auto& curve : one.curves) check_gas_log_setup(curve.setup, setup.log, log);
    read.curves.insert(read.curves.end(), one.curves.begin(), one.curves.end());
    if (!driven) continue;
    DrivenLog lines = read_driven_log_file(log);
    if (lines.bath && read.driven.bath &&
        lines.bath->bath_temperature_j != read.driven.bath->bath_temperature_j) {
      throw InvalidInput(
          fmt::format("--compare: {} is the log of another bath than the logs before it", log));
    }
    if (lines.bath) read.driven.bath = lines.bath;
    read.driven.runs.insert(read.driven.runs.end(), lines.runs.begin(), lines.runs.end());
  }
  if (read.curves.empty()) {
    throw InvalidInput(fmt::format("--compare: no {} lines in {} (the output of a deck of gas --deck)",
                                   kGasTag, fmt::format("{}", fmt::join(logs, ", "))));
  }
  return read;
}

GasComparison compare_logs(const std::vector<std::string>& logs, const GasSetup& setup, const LogNote& note) {
  return compare_with_theory(setup, read_compared_logs(logs, setup, false, note).curves);
}

DrivenComparison compare_driven_logs(const std::vector<std::string>& logs, const GasSetup& setup,
                                     const gas::Thermostat& bath, double relaxation_time_s,
                                     const LogNote& note) {
  const ComparedLogs read = read_compared_logs(logs, setup, true, note);
  return compare_driven(setup, bath, read.driven, read.curves, relaxation_time_s);
}

}  // namespace restitution::gas_deck
