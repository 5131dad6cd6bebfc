// SPDX-License-Identifier: BSD-3-Clause
#include "scene/scene_extensions.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "analysis/asymptotics.hpp"
#include "analysis/power_law_fit.hpp"
#include "analysis/stability_report.hpp"
#include "reference/work_precision.hpp"
#include "restitution/series.hpp"
#include "restitution_series_study/series_named.hpp"
#include "scene/scene_approximations.hpp"
#include "series/published_tables.hpp"

namespace restitution::scene::detail {
namespace {

using series::Approximation;

// `corrected`: the recomputed Padé 1999 coefficients, computed once per column.
double evaluate(Approximation a, double zeta, const series::Pade1999& corrected) {
  namespace published = series::published;
  switch (a) {
    case Approximation::naive_series:
      return series::naive_series(zeta, published::kTable3C).eps;
    case Approximation::delayed_recovery_series:
      return series::delayed_recovery_series(zeta, published::kTable5H).eps;
    case Approximation::pade_1999:
      return series::pade_1999(zeta, series::pade_1999_published()).eps;
    case Approximation::pade_1999_corrected:
      return series::pade_1999(zeta, corrected).eps;
    case Approximation::simple_theory_1999:
      return series::simple_theory_1999(zeta).eps;
    case Approximation::pade_2011_1_4:
      return series::pade_2011_1_4(zeta).eps;
    case Approximation::pade_2011_3_6:
      return series::pade_2011_3_6(zeta).eps;
  }
  return 0.0;
}

}  // namespace

const ApproximationInfo& approximation_info(series::Approximation kind) {
  for (const ApproximationInfo& info : kApproximations) {
    if (info.kind == kind) return info;
  }
  throw std::logic_error("approximation without an entry in kApproximations");
}

void add_approximations(const Sweep& sweep, const std::vector<double>& zeta, SweepExtras& extras) {
  for (const Approximation a : sweep.approximations) {
    const ApproximationInfo& info = approximation_info(a);
    ApproximationColumn column;
    column.label = info.label;
    column.approximation = a;
    column.end = info.end;
    const series::Pade1999 corrected =
        a == Approximation::pade_1999_corrected ? series::pade_1999_corrected() : series::Pade1999{};
    for (const double z : zeta) column.eps.push_back(evaluate(a, z, corrected));
    extras.approximations.push_back(std::move(column));
  }
  if (!sweep.asymptotics) return;
  // The derived laws: naive ε = κ ζ^{-5}, delayed recovery with its first correction (docs/asymptotics.md).
  const double kappa = asymptotics::naive_prefactor().value;
  for (const CollisionEnd end : sweep.ends.members()) {
    ApproximationColumn column;
    column.end = end;
    column.label = end == CollisionEnd::naive ? "naive_asymptotic" : "delayed_recovery_asymptotic";
    if (end == CollisionEnd::naive) column.kappa = kappa;
    for (const double z : zeta) {
      column.eps.push_back(z <= 0.0                     ? std::nan("")
                           : end == CollisionEnd::naive ? asymptotics::naive_eps(z, kappa)
                                                        : asymptotics::delayed_recovery_eps(z, 2));
    }
    extras.approximations.push_back(std::move(column));
  }
}

void add_power_law_fits(const Sweep& sweep, const std::vector<double>& zeta,
                        const std::vector<const CollisionResult*>& results, SweepExtras& extras) {
  if (!sweep.fit) return;
  for (const CollisionEnd end : sweep.ends.members()) {
    std::vector<double> z;
    std::vector<double> eps;
    for (std::size_t i = 0; i < zeta.size(); ++i) {
      if (zeta[i] >= sweep.fit->zeta_min && results[i] != nullptr) {
        z.push_back(zeta[i]);
        eps.push_back(end_of(*results[i], end).eps);
      }
    }
    if (z.size() < kMinFitPoints) {
      extras.fit_shortfalls.push_back({end, z.size(), sweep.fit->zeta_min});
      continue;
    }
    const PowerLawFit fit = fit_power_law(z, eps);
    extras.fits.push_back({end, fit.prefactor, fit.exponent, fit.exponent_stderr, z.size()});
  }
}

namespace {

// Per engine and end: the best worst-over-ζ error of the tolerance ladder, and the worst error and mean
// median solve time at kQuotedTolerance (or the tightest tolerance the engine accepts, when that is looser).
std::vector<WorkPrecisionHighlight> work_precision_highlights(const std::vector<WorkPrecisionRow>& rows) {
  const std::vector<WorkPrecisionGroup> groups = group_work_precision(rows);
  std::vector<WorkPrecisionHighlight> highlights;
  for (std::size_t first = 0; first < groups.size();) {
    std::size_t last = first;  // groups of one engine and end are adjacent, loosest tolerance first
    while (last + 1 < groups.size() && groups[last + 1].engine == groups[first].engine &&
           groups[last + 1].end == groups[first].end)
      ++last;
    const WorkPrecisionGroup* best = &groups[first];
    const WorkPrecisionGroup* quoted = &groups[first];
    for (std::size_t i = first; i <= last; ++i) {
      if (groups[i].max_error < best->max_error) best = &groups[i];
      if (groups[i].tolerance >= kQuotedTolerance * (1 - 1e-9)) quoted = &groups[i];
    }
    highlights.push_back({*best, *quoted});
    first = last + 1;
  }
  return highlights;
}

StudyOutcome work_precision_study(const ExternalStudy& study, const std::filesystem::path& reference_file) {
  StudyOutcome out;
  if (reference_file.empty()) {
    out.gap = StudyGap::no_reference_file;
    return out;
  }
  out.reference_file = reference_file;
  out.work_precision =
      measure_work_precision(read_reference_file(reference_file), study.repeats, study.engines);
  out.work_precision_highlights = work_precision_highlights(out.work_precision);
  return out;
}

}  // namespace

StudyOutcome run_study(const ExternalStudy& study, double tolerance,
                       const std::filesystem::path& reference_file) {
  if (study.kind == "work_precision") return work_precision_study(study, reference_file);
  StudyOutcome out;
  if (study.zeta.empty()) {
    out.gap = StudyGap::no_zeta_values;
    return out;
  }
  StabilityOptions options;
  options.tolerance = std::max(tolerance, 100.0 * kMinTolerance);
  const StabilityReport report = stability_report(study.zeta, options);
  StabilitySummary summary;
  summary.tolerance = options.tolerance;
  summary.pairs = report.points.size();
  summary.flagged = report.flagged();
  for (const StabilityPoint& p : report.points) {
    summary.worst_self_convergence = std::max(summary.worst_self_convergence, p.self_convergence);
    for (const EngineCheck& e : p.engines) {
      if (e.solved)
        summary.worst_engine_difference = std::max(summary.worst_engine_difference, e.relative_difference);
    }
  }
  out.stability = summary;
  return out;
}

}  // namespace restitution::scene::detail
