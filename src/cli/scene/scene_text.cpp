// SPDX-License-Identifier: BSD-3-Clause
#include "cli/scene/scene_text.hpp"

#include <fmt/core.h>
#include <fmt/format.h>

#include <algorithm>

#include "scene/scene_sections.hpp"

namespace restitution::cli {
namespace {

const char* catalogue_source(series::Approximation kind) {
  switch (kind) {
    case series::Approximation::naive_series:
      return "naive series, 2008 paper Table III (c_1 ... c_10)";
    case series::Approximation::delayed_recovery_series:
      return "delayed-recovery series, 2008 paper Table V (h_0 ... h_20)";
    case series::Approximation::pade_1999:
      return "1999 paper's Padé [1/4] (Eq. 35 with a_3, a_4 of Eq. 33)";
    case series::Approximation::pade_1999_corrected:
      return "1999 paper's Padé [1/4] form with the recomputed a_3, a_4 (docs/series.md)";
    case series::Approximation::simple_theory_1999:
      return "1999 paper's simple theory eps + w eps^(3/5) = 1 (Eq. 27)";
    case series::Approximation::pade_2011_1_4:
      return "Müller & Pöschel 2011 Padé [1/4] in sqrt(zeta)";
    case series::Approximation::pade_2011_3_6:
      return "Müller & Pöschel 2011 Padé [3/6] in sqrt(zeta)";
  }
  return "";
}

std::string stability_line(const scene::ExternalStudy& study, const scene::StabilitySummary& s) {
  return fmt::format(
      "stability study '{}' (tolerance {:g}): {} point-end pairs, {} flagged; worst self-convergence {:.3g}, "
      "worst difference between engines {:.3g} (relative to min(eps, 1 - eps))",
      study.name, s.tolerance, s.pairs, s.flagged, s.worst_self_convergence, s.worst_engine_difference);
}

std::vector<std::string> work_precision_lines(const scene::ExternalStudy& study,
                                              const scene::StudyOutcome& outcome) {
  std::vector<std::string> lines;
  lines.push_back(
      fmt::format("work-precision study '{}': {} points against {} ({} timed solve{} per point; errors are "
                  "the worst over ζ, relative to min(ε*, 1 - ε*))",
                  study.name, outcome.work_precision.size(), outcome.reference_file.filename().string(),
                  study.repeats, study.repeats == 1 ? "" : "s"));
  for (const scene::WorkPrecisionHighlight& h : outcome.work_precision_highlights) {
    lines.push_back(fmt::format(
        "{}, {} end: best error {:.3g} (at tolerance {:g}); at tolerance {:g} error {:.3g} and {:.3g} µs per "
        "solve (mean over {} ζ values of the median)",
        h.best.engine, h.best.end, h.best.max_error, h.best.tolerance, h.quoted.tolerance, h.quoted.max_error,
        h.quoted.mean_median_seconds * 1e6, h.quoted.points));
  }
  return lines;
}

}  // namespace

std::string approximation_source(const scene::ApproximationColumn& column) {
  if (column.approximation) return catalogue_source(*column.approximation);
  if (column.end == CollisionEnd::naive)
    return fmt::format("derived large-zeta law kappa zeta^-5, kappa = {:.10g}", column.kappa);
  return "derived large-zeta law (3/2)^(2/3) zeta^(-5/3) with its first correction";
}

std::string comparison_text(const scene::ApproximationComparison& c, std::size_t points) {
  if (c.compared == 0)
    return "not compared (no point of this sweep has both this approximation and the numerics)";
  return fmt::format(
      "largest |relative difference| from the numerics: {:.3g}, over {} of {} points, {:.4g} <= zeta "
      "<= {:.4g}",
      c.max_abs_relative_difference, c.compared, points, c.zeta_min, c.zeta_max);
}

std::string fit_shortfall_text(const scene::FitShortfall& s) {
  return fmt::format("power-law fit at the {} end: only {} points with zeta >= {}, need {}", end_name(s.end),
                     s.points, s.zeta_min, scene::kMinFitPoints);
}

std::vector<std::string> study_lines(const scene::ExternalStudy& study, const scene::StudyOutcome& outcome) {
  switch (outcome.gap) {
    case scene::StudyGap::no_reference_file:
      return {fmt::format("work-precision study '{}': no reference file given", study.name)};
    case scene::StudyGap::no_zeta_values:
      return {fmt::format("stability study '{}': no zeta values given", study.name)};
    case scene::StudyGap::none:
      break;
  }
  if (outcome.stability) return {stability_line(study, *outcome.stability)};
  return work_precision_lines(study, outcome);
}

std::string own_collisions_text(const scene::Scene& scene) {
  std::vector<std::string> parts;
  for (const scene::SectionKind& kind : scene::section_kinds()) {
    const bool named = std::find(parts.begin(), parts.end(), kind.own_solves) != parts.end();
    if (*kind.own_solves != '\0' && !named && scene::has_sections(scene, kind.name))
      parts.emplace_back(kind.own_solves);
  }
  if (parts.empty()) return "";
  return fmt::format("not counted here: {}", fmt::join(parts, "; "));
}

}  // namespace restitution::cli
