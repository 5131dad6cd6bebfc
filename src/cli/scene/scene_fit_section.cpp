// SPDX-License-Identifier: BSD-3-Clause
#include "cli/scene/scene_fit_section.hpp"

#include <fmt/core.h>

#include "cli/fit/fit_data_report.hpp"
#include "cli/fit/fit_plot_tables.hpp"
#include "restitution/material.hpp"

namespace restitution::cli {
namespace {

FitInterval in_cm_per_s(FitInterval i) {
  i.low *= 100.0;
  i.high *= 100.0;
  return i;
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

void write_fit_section(const scene::Scene& /*scene*/, const scene::FitTask& task,
                       const scene::FitOutcome& fit, SectionOutput& out) {
  out.file(task.name + ".csv", fit_data_table(task.data, fit.result));
  const std::string curves = task.name + "_curves.csv";
  out.file(curves, fit_curves_table(task.data, fit.result, fit.options));
  out.report(fmt::format("## {}\n\n", task.title));
  out.report(out.plot("fit_data", task.name,
                      {"--curves", (out.folder() / curves).string(), "--data-label", task.data_label}));
  out.report(markdown(task, fit.result));
  JsonWriter& json = out.summary();
  json.key("fit_" + task.name).begin_object();
  write_fit_json(json, FitReportInput{task.source, &task.data, &fit.result, fit.options.k});
  json.end_object();
}

}  // namespace restitution::cli
