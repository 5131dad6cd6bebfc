// SPDX-License-Identifier: BSD-3-Clause
#include "cli/scene/scene_fit_section.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "cli/common/output_files.hpp"
#include "cli/fit/fit_data_report.hpp"
#include "restitution/material.hpp"

namespace restitution::cli {
namespace {

FitInterval in_cm_per_s(FitInterval i) {
  i.low *= 100.0;
  i.high *= 100.0;
  return i;
}

constexpr int kCurvePoints = 101;

// law_end, e.g. viscoelastic-hertz_delayed-recovery: the one underscore separates the law from the end.
std::string label(const LawFit& f) {
  return fmt::format("{}_{}", law_name(f.candidate.law), end_name(f.candidate.end));
}

std::string data_table(const FitData& d, const FitResult& r) {
  std::string csv = "v,eps,sigma";
  for (const LawFit& f : r.fits) csv += fmt::format(",model_{0},residual_{0}", label(f));
  csv += "\n";
  for (std::size_t i = 0; i < d.eps.size(); ++i) {
    csv += number17(d.velocity_m_s[i]) + "," + number17(d.eps[i]) + "," +
           number17(d.sigma.empty() ? std::numeric_limits<double>::quiet_NaN() : d.sigma[i]);
    for (const LawFit& f : r.fits) {
      const double m = f.model_eps.empty() ? std::numeric_limits<double>::quiet_NaN() : f.model_eps[i];
      // fmt rather than "," + std::string&&: GCC 12 -O3 warns (-Wrestrict) on the inlined insert (a false
      // positive).
      csv += fmt::format(",{},{}", number17(m), number17(d.eps[i] - m));
    }
    csv += "\n";
  }
  return csv;
}

// Each converged law's ε(v) at its best value and at the bounds of its 95 % interval (ε decreases with the
// parameter: the upper bound gives the band's lower edge; a bound at the edge of the range gives none).
std::string curves_table(const FitData& d, const FitResult& r, const FitOptions& options) {
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
      csv += fmt::format(",{},{},{}", number17(c[0][k]), number17(c[1][k]), number17(c[2][k]));
    csv += "\n";
  }
  return csv;
}

std::string markdown(const scene::FitTask& task, const FitResult& r) {
  std::string md = fmt::format(
      "Data: {} ({} points, {}). Each law's one parameter by weighted least squares; 68 % and 95 % intervals "
      "from "
      "the profile of χ² (docs/fit.md); the band is the 95 % interval.\n\n",
      task.source, r.points,
      r.sigma_estimated ? "no σ: the scatter is estimated from the residuals, t quantiles" : "σ given");
  md +=
      "| law | end | parameter | value | 68 % | 95 % | χ²/dof | AIC | residuals "
      "|\n|---|---|---|---|---|---|---|---|---|\n";
  for (const LawFit& f : r.fits) {
    md += fmt::format(
        "| {} | {} | {} | {} | {} | {} | {:.4g} | {:.4g} | {} |\n", law_name(f.candidate.law),
        end_name(f.candidate.end), f.parameter,
        f.status == FitStatus::converged ? fmt::format("{:.6g}", f.value) : fit_status_name(f.status),
        interval_text(f.ci68), interval_text(f.ci95), f.chi2_per_dof, f.aic, verdict_text(f.residuals));
  }
  md += "\n";
  if (r.best) {
    const LawFit& b = r.fits[*r.best];
    md += fmt::format("Preferred (lowest AIC): **{}, {} end**", law_name(b.candidate.law),
                      end_name(b.candidate.end));
    for (const std::size_t i : r.tied_with_best)
      md += fmt::format(", tied with {}", law_name(r.fits[i].candidate.law));
    md += ".\n\n";
  }
  for (const LawFit& f : r.fits) {
    if (!f.characteristic_velocity_m_s) continue;
    md += fmt::format("* g* (1999 paper, Eq. 31), {} end: {:.4g} cm/s, 68 % {} cm/s, 95 % {} cm/s",
                      end_name(f.candidate.end), 100.0 * *f.characteristic_velocity_m_s,
                      interval_text(in_cm_per_s(f.characteristic_velocity_ci68)),
                      interval_text(in_cm_per_s(f.characteristic_velocity_ci95)));
    if (task.reference_characteristic_velocity_m_s) {
      md += fmt::format(
          "; the reference value {:.4g} cm/s is {} the 95 % interval",
          100.0 * *task.reference_characteristic_velocity_m_s,
          (f.characteristic_velocity_ci95.low_at_edge ||
           *task.reference_characteristic_velocity_m_s >= f.characteristic_velocity_ci95.low) &&
                  (f.characteristic_velocity_ci95.high_at_edge ||
                   *task.reference_characteristic_velocity_m_s <= f.characteristic_velocity_ci95.high)
              ? "inside"
              : "outside");
    }
    md += "\n";
    if (f.dissipative_constant_s) {
      md += fmt::format("* A, {} end: {:.6g} s, 95 % {} s\n", end_name(f.candidate.end),
                        *f.dissipative_constant_s, interval_text(f.dissipative_constant_ci95));
    }
  }
  md +=
      "\nResiduals (1 % level): falls-with-speed = data below the law at high speed (plasticity, fracture); "
      "rises-with-speed = below it at low speed (adhesion); runs = systematic, not monotone.\n\n";
  if (!task.note.empty()) md += task.note + "\n\n";
  return md;
}

}  // namespace

FitSection fit_section(const scene::Scene& scene, const scene::FitTask& task) {
  FitSection s;
  FitOptions options;
  options.candidates = task.candidates;
  options.tolerance = scene.tolerance;
  options.method = scene.method;
  if (task.material) s.k = elastic_constants(scene.materials.at(*task.material)).k;
  options.k = s.k;
  s.result = fit_data(task.data, options);
  s.data_csv = data_table(task.data, s.result);
  s.curves_csv = curves_table(task.data, s.result, options);
  s.markdown = markdown(task, s.result);
  return s;
}

}  // namespace restitution::cli
