// SPDX-License-Identifier: BSD-3-Clause
#include "gas_deck/gas_log_setup.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "dem/deck.hpp"
#include "gas_deck/gas_log_tokens.hpp"
#include "restitution/errors.hpp"
#include "restitution/solve_types.hpp"

namespace restitution::gas_deck {
namespace {

// Two numbers printed with 10 significant digits agree when they differ by less than the last printed digit
// of the larger (half a unit from each rounding).
constexpr double kPrintedPrecision = 1e-9;

std::string printed(double x) {
  return fmt::format("{:.10g}", x);
}

}  // namespace

GasLogSetup gas_log_setup(const GasDeckRequest& request, double dissipative_constant_s,
                          std::string_view law) {
  const dem::Pair pair = dem::pair_of(request.material);
  GasLogSetup s;
  s.law = law;
  s.end = end_name(request.end);
  s.diameter_m = 2.0 * pair.radius1_m;
  s.mass_kg = pair.mass1_kg;
  s.young_modulus_pa = pair.young_modulus_pa;
  s.poisson_ratio = pair.poisson_ratio;
  s.dissipative_constant_s = dissipative_constant_s;
  s.packing_fraction = request.packing_fraction;
  s.initial_temperature_j = pair.mass1_kg * request.rms_speed_m_s * request.rms_speed_m_s;
  return s;
}

std::string gas_log_setup_line(const GasLogSetup& setup) {
  std::string line = fmt::format("{} law={} end={}", kGasSetupTag, setup.law, setup.end);
  for (const auto& f : kGasLogSetupFields) line += fmt::format(" {}={}", f.key, printed(setup.*f.value));
  return line;
}

std::optional<GasLogSetup> parse_gas_log_setup(std::string_view line) {
  const auto tokens = split_tokens(line);
  if (tokens.size() != 3 + kGasLogSetupFields.size() || tokens[0] != kGasSetupTag) return std::nullopt;
  GasLogSetup s;
  const auto law = value_of(tokens[1], "law");
  const auto end = value_of(tokens[2], "end");
  if (!law || !end || law->empty() || end->empty()) return std::nullopt;
  s.law = *law;
  s.end = *end;
  for (std::size_t i = 0; i < kGasLogSetupFields.size(); ++i) {
    const auto text = value_of(tokens[3 + i], kGasLogSetupFields[i].key);
    const auto value = text ? whole_number(*text) : std::nullopt;
    if (!value) return std::nullopt;
    s.*kGasLogSetupFields[i].value = *value;
  }
  return s;
}

void check_gas_log_setup(const GasLogSetup& log, const GasLogSetup& command, const std::string& source) {
  if (log.end != command.end) {
    throw InvalidInput(fmt::format("--compare {}: the log's end {} is not the command's {} (--end)", source,
                                   log.end, command.end));
  }
  for (const auto& f : kGasLogSetupFields) {
    const double a = log.*f.value;
    const double b = command.*f.value;
    if (std::abs(a - b) <= kPrintedPrecision * std::max(std::abs(a), std::abs(b))) continue;
    throw InvalidInput(fmt::format("--compare {}: the log's {} {} is not the command's {} ({})", source,
                                   f.key, printed(a), printed(b), f.option));
  }
}

}  // namespace restitution::gas_deck
