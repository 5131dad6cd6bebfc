// SPDX-License-Identifier: BSD-3-Clause
#include "cli/fit/fit_plot_tables.hpp"

#include <fmt/core.h>
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <limits>

#include "cli/common/output_files.hpp"
#include "restitution/collision_solver.hpp"

namespace restitution::cli {
namespace {

constexpr int kCurvePoints = 101;  // speeds of the curves, log-spaced over the data's

// law_end, e.g. viscoelastic-hertz_delayed-recovery: the one underscore separates the law from the end.
std::string label(const LawFit& f) {
  return fmt::format("{}_{}", law_name(f.candidate.law), end_name(f.candidate.end));
}

}  // namespace

std::string fit_data_table(const FitData& d, const FitResult& r) {
  std::string csv = "v,eps,sigma";
  for (const LawFit& f : r.fits) csv += fmt::format(",model_{0},residual_{0}", label(f));
  csv += "\n";
  for (std::size_t i = 0; i < d.eps.size(); ++i) {
    // format_to rather than "," + text: GCC 12 warns (-Wrestrict) on that inlined concatenation, wrongly.
    fmt::format_to(std::back_inserter(csv), "{},{},{}", number17(d.velocity_m_s[i]), number17(d.eps[i]),
                   number17(d.sigma.empty() ? std::numeric_limits<double>::quiet_NaN() : d.sigma[i]));
    for (const LawFit& f : r.fits) {
      const double m = f.model_eps.empty() ? std::numeric_limits<double>::quiet_NaN() : f.model_eps[i];
      fmt::format_to(std::back_inserter(csv), ",{},{}", number17(m), number17(d.eps[i] - m));
    }
    csv += "\n";
  }
  return csv;
}

// Each converged law's ε(v) at its best value and at the bounds of its 95 % interval (ε decreases with the
// parameter: the upper bound gives the band's lower edge; a bound at the edge of the range gives none).
std::string fit_curves_table(const FitData& d, const FitResult& r, const FitOptions& options) {
  const auto [lo, hi] = std::minmax_element(d.velocity_m_s.begin(), d.velocity_m_s.end());
  std::vector<const LawFit*> shown;
  for (const LawFit& f : r.fits) {
    if (f.status == FitStatus::converged) shown.push_back(&f);
  }
  CollisionSolver solver;
  SolveOptions solve;
  solve.tolerance = options.tolerance;
  solve.method = options.method;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  // Columns of ε per law: best, low edge, high edge of the band.
  std::vector<std::array<std::vector<double>, 3>> columns(shown.size());
  std::vector<double> speeds(kCurvePoints);
  for (int k = 0; k < kCurvePoints; ++k) {
    speeds[k] = *lo * std::pow(*hi / *lo, static_cast<double>(k) / (kCurvePoints - 1));
  }
  for (std::size_t j = 0; j < shown.size(); ++j) {
    const LawFit& f = *shown[j];
    const std::array<double, 3> parameters{f.value, f.ci95.high_at_edge ? nan : f.ci95.high, f.ci95.low};
    for (int c = 0; c < 3; ++c) {
      auto eps_at = [&](double v) {
        return std::isnan(parameters[c]) ? nan : fit_model_eps(f.candidate, parameters[c], v, solver, solve);
      };
      // A speed-independent law needs one solve per parameter.
      const double constant = speed_independent(f.candidate.law) ? eps_at(1.0) : nan;
      for (const double v : speeds)
        columns[j][c].push_back(speed_independent(f.candidate.law) ? constant : eps_at(v));
    }
  }
  std::string csv = "v";
  for (const LawFit* f : shown) csv += fmt::format(",eps_{0},low_{0},high_{0}", label(*f));
  csv += "\n";
  for (int k = 0; k < kCurvePoints; ++k) {
    csv += number17(speeds[k]);
    for (const auto& c : columns)
      fmt::format_to(std::back_inserter(csv), ",{},{},{}", number17(c[0][k]), number17(c[1][k]),
                     number17(c[2][k]));
    csv += "\n";
  }
  return csv;
}

}  // namespace restitution::cli
