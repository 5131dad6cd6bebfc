// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// What the viscoelastic Hertz fit of `fit-data --out FILE` (docs/fit.md, fit/fit_report_reader.hpp) gives
// `calibrate --from-fit` and `dem --from-fit`: β and its intervals, and what they give at one speed.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "fit/fit_report_reader.hpp"

namespace restitution::cli {

// The report at `path` (fit/fit_report_reader.hpp); its InvalidInput names --from-fit FILE.
FitCarryOver read_fit_result(const std::filesystem::path& path, std::optional<CollisionEnd> end);

// ε at speed v [m/s] for the fit's β and its intervals (restitution/fit.hpp, fitted_eps_at_speed); its
// InvalidInput for a β whose ζ lies outside the checked range names --from-fit FILE.
using EpsCarryOver = FittedEps;
EpsCarryOver eps_at_speed(const FitCarryOver& fit, double velocity_m_s);

}  // namespace restitution::cli

namespace restitution::cli {
// `calibrate --from-fit FILE --velocity V [material]`: the fit's β with its intervals, ε at V with the
// interval β's carries over, g*, and with k the dissipative constant A with its intervals. Prints the table
// or (json) one object; returns the exit status. When the fit rejects its Hertz fit (FitCarryOver::rejection)
// the output says why (JSON `hertz_fit_rejected`) and gives no interval.
int calibrate_from_fit(const std::filesystem::path& file, std::optional<CollisionEnd> end,
                       double velocity_m_s, std::optional<double> k, bool json);
}  // namespace restitution::cli

namespace restitution::cli {
class JsonWriter;
// What a fit carries over into `dem --from-fit`: A = β / ((3/2) k^{2/5}) with its intervals and ε at each
// speed with its interval. As comment lines (prefix "#" or "//") and as the fields of a JSON object
// "from_fit". These ε are the law's: `eps_given_by` names the lines that give them (the printed lines, or
// for a YADE that cannot express the law the lines of the version that can), so that no ε stands next to
// lines that do not produce it. A rejected Hertz fit is said so and carries no interval, as in calibrate.
std::string fit_carry_over_text(const std::filesystem::path& file, const FitCarryOver& fit, double k,
                                const std::vector<double>& speeds_m_s, const std::string& eps_given_by,
                                const char* comment);
void write_fit_carry_over(JsonWriter& json, const std::filesystem::path& file, const FitCarryOver& fit,
                          double k, const std::vector<double>& speeds_m_s, const std::string& eps_given_by);
}  // namespace restitution::cli
