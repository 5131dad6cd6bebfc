// SPDX-License-Identifier: BSD-3-Clause
#include "gas_deck/gas_log.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "gas_deck/lammps_gas_deck.hpp"
#include "restitution/errors.hpp"

namespace restitution::gas_deck {
namespace {

// The value of `key=` in `line`; NaN when absent or not a number.
double field(const std::string& line, const std::string& key) {
  const auto at = line.find(" " + key + "=");
  if (at == std::string::npos) return NAN;
  const char* begin = line.c_str() + at + key.size() + 2;
  char* end = nullptr;
  const double x = std::strtod(begin, &end);
  return end == begin ? NAN : x;
}

std::string word(const std::string& line, const std::string& key) {
  const auto at = line.find(" " + key + "=");
  if (at == std::string::npos) return "";
  const auto begin = at + key.size() + 2;
  return line.substr(begin, line.find(' ', begin) - begin);
}

}  // namespace

std::vector<CoolingCurve> read_gas_log(const std::string& text, const std::string& source) {
  std::vector<CoolingCurve> curves;
  std::istringstream in(text);
  std::string line;
  const std::string tag(kGasTag);
  for (long number = 1; std::getline(in, line); ++number) {
    if (line.rfind(tag + " ", 0) != 0) continue;  // the echoed `print "..."` command starts with print
    const std::string law = word(line, "law");
    const double t = field(line, "time_s");
    const double temperature = field(line, "temperature_j");
    if (law.empty() || !std::isfinite(t) || !(temperature > 0.0) || !std::isfinite(temperature)) {
      throw InvalidInput(fmt::format("{}:{}: a {} line without law, time_s and temperature_j > 0: {}", source,
                                     number, tag, line));
    }
    auto it = std::find_if(curves.begin(), curves.end(), [&](const CoolingCurve& c) { return c.law == law; });
    if (it == curves.end()) {
      curves.push_back({law, source, {}, {}});
      it = std::prev(curves.end());
    }
    it->time_s.push_back(t);
    it->temperature_j.push_back(temperature);
  }
  return curves;
}

LocalExponent local_exponent(const std::vector<double>& time_s, const std::vector<double>& temperature_j) {
  LocalExponent e;
  for (std::size_t i = 1; i < time_s.size(); ++i) {
    if (!(time_s[i - 1] > 0.0) || !(time_s[i] > time_s[i - 1])) continue;
    e.time_s.push_back(std::sqrt(time_s[i - 1] * time_s[i]));
    e.exponent.push_back(std::log(temperature_j[i] / temperature_j[i - 1]) /
                         std::log(time_s[i] / time_s[i - 1]));
  }
  return e;
}

}  // namespace restitution::gas_deck
