#include "scene/scene_extensions.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "analysis/asymptotics.hpp"
#include "analysis/power_law_fit.hpp"
#include "analysis/stability_report.hpp"
#include "reference/work_precision.hpp"
#include "restitution/series.hpp"
#include "restitution/series_tables.hpp"
#include "scene/scene_approximations.hpp"
#include "series_study/series_named.hpp"

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
    column.source = info.source;
    column.end = info.end;
    const series::Pade1999 corrected =
        a == Approximation::pade_1999_corrected ? series::pade_1999_corrected() : series::Pade1999{};
    for (const double z : zeta) column.eps.push_back(evaluate(a, z, corrected));
    extras.approximations.push_back(std::move(column));
  }
}

void add_power_law_fits(const Sweep& sweep, const std::vector<double>& zeta,
                        const std::vector<const CollisionResult*>& results, SweepExtras& extras) {
  if (sweep.asymptotics) {
    // The derived laws: naive ε = κ ζ^{-5}, delayed recovery with its first correction (docs/asymptotics.md).
    const double kappa = asymptotics::naive_prefactor().value;
    for (const CollisionEnd end : sweep.ends.members()) {
      ApproximationColumn column;
      column.end = end;
      column.label = end == CollisionEnd::naive ? "naive_asymptotic" : "delayed_recovery_asymptotic";
      column.source = end == CollisionEnd::naive
                          ? fmt::format("derived large-zeta law kappa zeta^-5, kappa = {:.10g}", kappa)
                          : "derived large-zeta law (3/2)^(2/3) zeta^(-5/3) with its first correction";
      for (const double z : zeta) {
        column.eps.push_back(z <= 0.0                     ? std::nan("")
                             : end == CollisionEnd::naive ? asymptotics::naive_eps(z, kappa)
                                                          : asymptotics::delayed_recovery_eps(z, 2));
      }
      extras.approximations.push_back(std::move(column));
    }
  }
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
    if (z.size() < 3) {
      extras.notes.push_back(
          fmt::format("power-law fit at the {} end: only {} points with zeta >= {}, need 3", end_name(end),
                      z.size(), sweep.fit->zeta_min));
      continue;
    }
    const PowerLawFit fit = fit_power_law(z, eps);
    extras.fits.push_back({end, fit.prefactor, fit.exponent, fit.exponent_stderr, z.size()});
  }
}

namespace {

// Per engine and end: the best worst-over-ζ error of the tolerance ladder, and the worst error and mean
// median solve time at 1e-10 (or the tightest tolerance the engine accepts, when that is looser).
std::vector<std::string> work_precision_summary(const std::vector<WorkPrecisionRow>& rows) {
  constexpr double kQuotedTolerance = 1e-10;
  const std::vector<WorkPrecisionGroup> groups = group_work_precision(rows);
  std::vector<std::string> lines;
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
    lines.push_back(fmt::format(
        "{}, {} end: best error {:.3g} (at tolerance {:g}); at tolerance {:g} error {:.3g} and {:.3g} µs per "
        "solve (mean over {} ζ values of the median)",
        best->engine, best->end, best->max_error, best->tolerance, quoted->tolerance, quoted->max_error,
        quoted->mean_median_seconds * 1e6, quoted->points));
    first = last + 1;
  }
  return lines;
}

StudyOutcome work_precision_study(const ExternalStudy& study, const std::filesystem::path& reference_file) {
  StudyOutcome out;
  if (reference_file.empty()) {
    out.summary.push_back(fmt::format("work-precision study '{}': no reference file given", study.name));
    return out;
  }
  out.work_precision =
      measure_work_precision(read_reference_file(reference_file), study.repeats, study.engines);
  out.summary.push_back(
      fmt::format("work-precision study '{}': {} points against {} ({} timed solve{} per point; errors are "
                  "the worst over ζ, relative to min(ε*, 1 - ε*))",
                  study.name, out.work_precision.size(), reference_file.filename().string(), study.repeats,
                  study.repeats == 1 ? "" : "s"));
  for (std::string& line : work_precision_summary(out.work_precision)) out.summary.push_back(std::move(line));
  return out;
}

}  // namespace

StudyOutcome run_study(const ExternalStudy& study, double tolerance,
                       const std::filesystem::path& reference_file) {
  if (study.kind == "work_precision") return work_precision_study(study, reference_file);
  StudyOutcome out;
  if (study.zeta.empty()) {
    out.summary.push_back(fmt::format("stability study '{}': no zeta values given", study.name));
    return out;
  }
  StabilityOptions options;
  options.tolerance = std::max(tolerance, 100.0 * kMinTolerance);
  const StabilityReport report = stability_report(study.zeta, options);
  double worst_self = 0.0;
  double worst_engines = 0.0;
  for (const StabilityPoint& p : report.points) {
    worst_self = std::max(worst_self, p.self_convergence);
    for (const EngineCheck& e : p.engines) {
      if (e.solved) worst_engines = std::max(worst_engines, e.relative_difference);
    }
  }
  out.summary.push_back(fmt::format(
      "stability study '{}' (tolerance {:g}): {} point-end pairs, {} flagged; worst self-convergence {:.3g}, "
      "worst difference between engines {:.3g} (relative to min(eps, 1 - eps))",
      study.name, options.tolerance, report.points.size(), report.flagged(), worst_self, worst_engines));
  return out;
}

}  // namespace restitution::scene::detail
