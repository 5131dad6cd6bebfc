// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Reading the result of `fit-data --output FILE` (docs/fit.md) for `calibrate --from-fit`: the viscoelastic
// Hertz fit whose β and intervals carry over, and what they give at one speed.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "restitution/contact_law.hpp"
#include "restitution/fit.hpp"

namespace restitution::cli {

struct FitCarryOver {
  CollisionEnd end = CollisionEnd::delayed_recovery;
  double beta = 0.0;
  FitInterval ci68, ci95;
  bool sigma_estimated = false;
  std::size_t points = 0;
};

// The converged viscoelastic Hertz fit at `end` (nullopt: the one with the lowest AIC). Throws InvalidInput
// naming the file when it cannot be read, is not a fit-data report, or has no such converged fit.
FitCarryOver read_fit_result(const std::filesystem::path& path, std::optional<CollisionEnd> end);

// ε at speed v [m/s] for β and its interval (ε decreases with β, so the bounds swap; a β bound at the edge
// gives no ε bound: NaN and the flag set).
struct EpsCarryOver {
  double eps = 0.0;
  FitInterval ci68, ci95;
};
EpsCarryOver eps_at_speed(const FitCarryOver& fit, double velocity_m_s);

}  // namespace restitution::cli

namespace restitution::cli {
// `calibrate --from-fit FILE --velocity V [material]`: the fit's β with its intervals, ε at V with the
// interval β's carries over, g*, and with k the dissipative constant A with its intervals. Prints the table
// or (json) one object; returns the exit status.
int calibrate_from_fit(const std::filesystem::path& file, std::optional<CollisionEnd> end,
                       double velocity_m_s, std::optional<double> k, bool json);
}  // namespace restitution::cli

namespace restitution::cli {
class JsonWriter;
// What a fit carries over into `dem --from-fit`: A = β / ((3/2) k^{2/5}) with its intervals and ε at each
// speed with its interval. As comment lines (prefix "#" or "//") and as the fields of a JSON object
// "from_fit". These ε are the law's: `eps_given_by` names the lines that give them (the printed lines, or
// for a YADE that cannot express the law the lines of the version that can), so that no ε stands next to
// lines that do not produce it.
std::string fit_carry_over_text(const std::filesystem::path& file, const FitCarryOver& fit, double k,
                                const std::vector<double>& speeds_m_s, const std::string& eps_given_by,
                                const char* comment);
void write_fit_carry_over(JsonWriter& json, const std::filesystem::path& file, const FitCarryOver& fit,
                          double k, const std::vector<double>& speeds_m_s, const std::string& eps_given_by);
}  // namespace restitution::cli
