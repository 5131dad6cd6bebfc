// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// `gas --compare LOG...` without the printing: the logs (or screen output) of a gas deck's runs read,
// streamed, each run checked to belong to the gas compared with, and compared with the kinetic theory, freely
// cooling (gas_comparison.hpp) or driven (driven_comparison.hpp). What a log leaves out (a cut last line, a
// repeated print) is handed to a callback as it is read, so a front end can say it before a later log's
// error.
#include <functional>
#include <string>
#include <vector>

#include "gas_deck/driven_comparison.hpp"
#include "gas_deck/gas_comparison.hpp"
#include "gas_deck/gas_log.hpp"

namespace restitution::gas_deck {

using LogNote = std::function<void(const std::string& note)>;

// The cooling curves of every log, in order, and with `driven` their driven lines (bath and moments).
struct ComparedLogs {
  std::vector<CoolingCurve> curves;
  DrivenLog driven;
};

// Throws InvalidInput for a missing log, one that is not a regular file, a garbled one, one of another gas
// than `setup` (naming the field), with `driven` one of another bath than the logs before it, or when no log
// holds a deck's lines; IoError for one that cannot be read.
ComparedLogs read_compared_logs(const std::vector<std::string>& logs, const GasSetup& setup, bool driven,
                                const LogNote& note);

// The freely cooling gas's runs against the theory.
GasComparison compare_logs(const std::vector<std::string>& logs, const GasSetup& setup, const LogNote& note);

// The driven gas's runs against the theory of `bath` (its relaxation time from gas::steady_state).
DrivenComparison compare_driven_logs(const std::vector<std::string>& logs, const GasSetup& setup,
                                     const gas::Thermostat& bath, double relaxation_time_s,
                                     const LogNote& note);

}  // namespace restitution::gas_deck
