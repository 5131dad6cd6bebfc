// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Reading the report `fit-data --out FILE` writes (docs/fit.md) back into typed values, for `calibrate
// --from-fit` and `dem --from-fit`: the file comes from outside (it may be edited by hand), so every value
// used is checked for its type, finiteness and order, every index for its range, and the Hertz fit that
// carries over is judged by the report's own tests (judge_reported_fit, restitution/fit.hpp).
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "restitution/contact_law.hpp"
#include "restitution/fit.hpp"

namespace restitution {

// The largest report read [bytes]: a fit-data report holds a few numbers per data point, so this admits
// about a million points; anything larger (or endless, such as /dev/zero) is refused after reading that much.
inline constexpr std::size_t kMaxFitReportBytes = std::size_t{64} << 20;

// The viscoelastic Hertz fit a report carries over.
struct FitCarryOver {
  std::string file;  // as messages name it
  CollisionEnd end = CollisionEnd::delayed_recovery;
  double beta = 0.0;       // [s^{1/5} m^{-1/5}], > 0, with a finite g* > 0
  FitInterval ci68, ci95;  // low <= beta <= high where a number; ci95 contains ci68
  bool sigma_estimated = false;
  std::size_t points = 0;
  // Every fit of the report (law, end, χ², AIC, residual verdict; only the converged ones' numbers are read)
  // and which of them carries over.
  std::vector<ReportedFit> fits;
  std::size_t chosen = 0;
  // The report's own verdict on fits[chosen]: when it rejects the fit, the intervals describe the scatter
  // about a law the data do not follow, not the data, and are not carried over.
  FitRejection rejection;
};

// The converged viscoelastic Hertz fit at `end` (nullopt: the one with the lowest AIC) of the report in
// `text`. Throws InvalidInput "FILE: KEY: problem" (FILE is `file`) for anything that is not a well-formed
// fit-data report, or when it has no such converged fit.
FitCarryOver parse_fit_report(const std::string& text, const std::string& file,
                              std::optional<CollisionEnd> end);

// The same for the file at `path` (at most kMaxFitReportBytes), named by its path.
FitCarryOver read_fit_report(const std::filesystem::path& path, std::optional<CollisionEnd> end);

// ε at speed v [m/s] that the carried fit gives, with the intervals its β's carry over (fitted_eps_at_speed);
// its InvalidInput for a β whose ζ lies outside the checked range reads "FILE: beta = B at v = V m/s: why".
FittedEps carried_eps_at_speed(const FitCarryOver& fit, double velocity_m_s);

// The dissipative constant A [s] the carried β gives a material of k = ρ/m_eff [s^-2 m^-1/2]
// (dissipative_constant_from), with β's intervals scaled alike (A is β times a constant of the material).
struct CarriedDissipativeConstant {
  double value_s = 0.0;
  FitInterval ci68, ci95;  // [s]
};
CarriedDissipativeConstant carried_dissipative_constant(const FitCarryOver& fit, double k);

}  // namespace restitution
