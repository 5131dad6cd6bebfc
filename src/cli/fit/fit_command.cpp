// SPDX-License-Identifier: BSD-3-Clause
// `restitution fit`: least-squares power law ε ≈ c ζ^p over a ζ range at one end, with local slopes from the
// solver and the derived large-ζ law beside it (docs/asymptotics.md).
#include <fmt/core.h>

#include <memory>
#include <optional>

#include "analysis/power_law_study.hpp"
#include "cli/common/build_json.hpp"
#include "cli/common/commands.hpp"
#include "cli/common/deprecated_alias.hpp"
#include "cli/common/json_writer.hpp"
#include "cli/common/progress.hpp"
#include "cli/common/range_option.hpp"
#include "restitution/collision_solver.hpp"
#include "restitution/errors.hpp"

namespace restitution::cli {
namespace {

struct PowerLawFitOptions {
  std::string end;
  std::string zeta_range;  // FROM:TO:N; the old form is zeta_min, zeta_max and points
  std::optional<double> zeta_min, zeta_max;
  std::optional<long long> points;  // signed and wide: a huge or negative count is reported, not wrapped
  double tolerance = SolveOptions{}.tolerance;
  bool json = false;
};

constexpr long long kMaxFitPoints = 100000;
constexpr long long kDefaultFitPoints = 9;  // of the old form without --points

// The ζ grid: --zeta-range FROM:TO:N, or the old --zeta-min/--zeta-max/--points; throws InvalidInput naming
// the option the user typed.
std::vector<double> fit_zetas(const PowerLawFitOptions& o) {
  if (o.zeta_range.empty()) {
    if (!o.zeta_min || !o.zeta_max) {
      throw InvalidInput(
          fmt::format("--zeta-range FROM:TO:N is required: N log-spaced zeta, ends included, N in "
                      "[3, {}]",
                      kMaxFitPoints));
    }
    const long long points = o.points.value_or(kDefaultFitPoints);
    if (points > kMaxFitPoints) {
      throw InvalidInput(fmt::format("--points must be at most {}, got {}", kMaxFitPoints, points));
    }
    return log_grid(*o.zeta_min, *o.zeta_max, static_cast<int>(points));
  }
  if (o.zeta_min || o.zeta_max || o.points) {
    throw InvalidInput(
        "--zeta-range FROM:TO:N takes the place of --zeta-min, --zeta-max and --points: give it alone");
  }
  const RangeText range =
      parse_range(o.zeta_range, "--zeta-range", "zeta, N >= 3 log-spaced points", 3, kMaxFitPoints);
  try {
    return log_grid(range.from, range.to, static_cast<int>(range.count));
  } catch (const InvalidInput& e) {
    throw InvalidInput(fmt::format("--zeta-range '{}': {}", o.zeta_range, e.what()));
  }
}

int run_fit(const PowerLawFitOptions& o) {
  const CollisionEnd end = end_from_name(o.end);
  const std::vector<double> zetas = fit_zetas(o);
  const PowerLawStudy study = [&] {
    ProgressLine progress("fit");  // ends its line before the results print
    return power_law_study(zetas, end, o.tolerance, progress.callback());
  }();
  const PowerLawFit& fit = study.fit;
  const std::vector<double>& eps = study.eps;
  const std::vector<LocalSlope>& slopes = study.slopes;
  if (o.json) {
    JsonWriter json;
    json.begin_object()
        .field("end", end_name(end))
        .field("exponent_zeta", fit.exponent)
        .field("exponent_velocity", fit.exponent / 5.0)
        .field("stderr", fit.exponent_stderr)
        .field("prefactor", fit.prefactor)
        .field("log_prefactor_stderr", fit.log_prefactor_stderr)
        .field("max_residual", fit.max_residual)
        .field("points", fit.points)
        .field("zeta_min", zetas.front())
        .field("zeta_max", zetas.back())
        .field("tolerance", o.tolerance);
    json.key("derived").begin_object();
    json.field("exponent_zeta", study.derived_exponent)
        .field("prefactor", study.derived_prefactor)
        .end_object();
    json.key("local_slopes").begin_array();
    for (std::size_t i = 0; i < slopes.size(); ++i) {
      const LocalSlope& s = slopes[i];
      json.begin_object().field("zeta", s.zeta).field("slope", s.slope).field("error", s.error_estimate);
      json.field("eps", eps[i]);
      json.end_object();
    }
    json.end_array();
    fmt::print("{}\n", finish_json_document(json));
    return 0;
  }
  fmt::print("{} end, zeta in [{:g}, {:g}], {} points, tolerance {:g}\n", end_name(end), zetas.front(),
             zetas.back(), fit.points, o.tolerance);
  fmt::print("  fit:     eps = {:.10g} * zeta^({:.10g} +- {:.2g})  (velocity exponent {:.10g})\n",
             fit.prefactor, fit.exponent, fit.exponent_stderr, fit.exponent / 5.0);
  fmt::print("  derived: eps = {:.10g} * zeta^({:.10g}) as zeta -> infinity\n", study.derived_prefactor,
             study.derived_exponent);
  fmt::print("  {:>14} {:>20} {:>12}\n", "zeta", "d ln eps/d ln zeta", "error");
  for (const LocalSlope& s : slopes)
    fmt::print("  {:>14.6g} {:>20.12g} {:>12.2g}\n", s.zeta, s.slope, s.error_estimate);
  return 0;
}

}  // namespace

void add_fit_command(CLI::App& app, Action& chosen) {
  auto o = std::make_shared<PowerLawFitOptions>();
  CLI::App* cmd = app.add_subcommand("fit", "least-squares power law of eps against zeta at one end");
  cmd->add_option("--end", o->end, "end of the collision: naive or delayed-recovery")
      ->required()
      ->check(CLI::IsMember(end_names()));
  cmd->add_option(
      "--zeta-range", o->zeta_range,
      fmt::format("FROM:TO:N: N log-spaced zeta > 0 of the fit, ends included, N in [3, {}]", kMaxFitPoints));
  deprecate_old_form({cmd->add_option("--zeta-min", o->zeta_min), cmd->add_option("--zeta-max", o->zeta_max)},
                     "--zeta-min A --zeta-max B --points N", "--zeta-range A:B:N");
  cmd->add_option("--points", o->points)->group("");  // the old form's count, hidden with it
  cmd->add_option("--tolerance", o->tolerance, "accuracy of each fitted eps, in [1e-11, 1e-2]")
      ->capture_default_str();
  cmd->add_flag("--json", o->json,
                "print one JSON object (numbers in the shortest form that reads back to the same double)");
  cmd->callback([o, &chosen] { chosen = [o] { return run_fit(*o); }; });
}

}  // namespace restitution::cli
