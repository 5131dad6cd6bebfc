// SPDX-License-Identifier: BSD-3-Clause
// `restitution reference`: the high-precision reference solutions (Taylor method in __float128) on the fixed
// ζ grid, written as data/reference_solutions.csv; or one ζ printed with 34 significant digits.
#include <fmt/core.h>
#include <quadmath.h>

#include <memory>
#include <optional>

#include "cli/common/commands.hpp"
#include "cli/common/options.hpp"
#include "cli/common/progress.hpp"
#include "cli/common/stop_signals.hpp"
#include "files/output_files.hpp"
#include "reference/reference_solution.hpp"
#include "restitution/errors.hpp"

namespace restitution::cli {
namespace {

struct ReferenceOptions {
  std::string out;
  std::optional<double> zeta;
};

std::string digits(__float128 value) {
  char buffer[64];
  quadmath_snprintf(buffer, sizeof buffer, "%.33Qe", value);
  return buffer;
}

int run_reference(const ReferenceOptions& o) {
  if (o.zeta && !o.out.empty()) {
    throw InvalidInput("give --zeta Z (printed) or --out FILE (the whole grid), not both");
  }
  if (o.zeta) {
    require_checked_zeta(*o.zeta);
    const ReferenceSolution s = hertz_reference(*o.zeta);
    fmt::print("zeta {:.17g}: agreement of the two orders {:.3g}, {} steps\n", s.parameter, s.agreement,
               s.steps);
    fmt::print("  maximal compression  tau = {}  x = {}\n", digits(s.tau_max), digits(s.x_max));
    for (const CollisionEnd e : kCollisionEnds) {
      const auto& end = s.ends[e];
      if (!end) continue;
      fmt::print("  {:<17} eps = {}  1-eps = {}\n  {:<17} tau = {}  x = {}\n", end_name(e), digits(end->eps),
                 digits(end->one_minus_eps), "", digits(end->tau), digits(end->x));
    }
    return 0;
  }
  if (o.out.empty()) throw InvalidInput("give --out FILE (or --zeta Z for one value)");
  files::check_output_file(o.out);  // before the work, not after
  // Ctrl-C stops after the solution in progress; --out is written (atomically) only at the end.
  const StopSignals signals;
  std::vector<ReferenceSolution> solutions;
  {
    ProgressLine progress("reference solutions");
    solutions = hertz_references(reference_zeta_grid(), [&](std::size_t done, std::size_t total) {
      progress.update(done, total);
      if (done < total) throw_if_interrupted();
    });
  }
  const std::filesystem::path path(o.out);
  files::write_file_atomically(path, reference_csv(solutions));
  fmt::print("wrote {} reference solutions to {}\n", solutions.size(), path.string());
  return 0;
}

}  // namespace

void add_reference_command(CLI::App& app, Action& chosen) {
  auto o = std::make_shared<ReferenceOptions>();
  CLI::App* cmd = app.add_subcommand(
      "reference", "high-precision reference solutions (Taylor method in __float128, independent of CVODE)");
  cmd->add_option("--out", o->out,
                  "CSV file to write for the whole grid (the repository keeps data/reference_solutions.csv)")
      ->check(non_empty_path());
  cmd->add_option("--zeta", o->zeta, "print the reference for one zeta >= 0 instead");
  cmd->callback([o, &chosen] { chosen = [o] { return run_reference(*o); }; });
}

}  // namespace restitution::cli
