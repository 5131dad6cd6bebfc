// SPDX-License-Identifier: BSD-3-Clause
// `restitution sweep`: ε over a grid of ζ, or of impact speeds with β or a material, in parallel, into one
// CSV file through the library's sweep_to_file (restitution/sweep.hpp), which keeps every finished row in
// FILE.partial for --resume. Here: the options, the grid, the settings line and the messages;
// SIGINT/SIGTERM stop the sweep after the points in progress.
#include <fmt/core.h>

#include <filesystem>
#include <memory>
#include <string>
#include <utility>

#include "cli/common/commands.hpp"
#include "cli/common/deprecated_alias.hpp"
#include "cli/common/head_on_options.hpp"
#include "cli/common/options.hpp"
#include "cli/common/progress.hpp"
#include "cli/common/stop_signals.hpp"
#include "cli/sweep/sweep_adhesion.hpp"
#include "cli/sweep/sweep_grid.hpp"
#include "files/output_files.hpp"
#include "restitution/errors.hpp"
#include "restitution/material.hpp"
#include "restitution/sweep.hpp"
#include "restitution/units.hpp"
#include "sweep/number_text.hpp"

namespace restitution::cli {
namespace {
namespace fs = std::filesystem;

// The first line of the partial file: a resumed sweep must have the same settings.
std::string settings_line(const SweepOptions& o, const SweepGrid& grid) {
  std::string range = fmt::format("zeta-min={} zeta-max={}", number17(o.zeta_min.value_or(0.0)),
                                  number17(o.zeta_max.value_or(0.0)));
  if (grid.velocity) {
    range =
        fmt::format("velocity-min={} velocity-max={}", number17(*o.velocity_min), number17(*o.velocity_max));
    if (grid.velocity->beta) range += fmt::format(" beta={}", number17(*grid.velocity->beta));
    if (o.inputs.any_material()) range += " material";
    if (o.stiffness) {
      range += fmt::format(" stiffness={} damping-coefficient={} effective-mass={}", number17(*o.stiffness),
                           number17(*o.damping_coefficient), number17(*o.effective_mass));
    }
  }
  if (grid.law != LawKind::viscoelastic_hertz) range = fmt::format("law={} {}", o.inputs.law, range);
  return fmt::format("# restitution sweep: {} points={} spacing={} end={} method={} tolerance={}", range,
                     o.points, o.log ? "log" : "linear", o.inputs.end, o.inputs.method,
                     number17(o.inputs.tolerance));
}

std::string dropped_note(const SweepFileOutcome& done) {
  if (done.damaged_lines == 0) return "";
  return fmt::format(
      " ({} damaged line{} of '{}' dropped, the first at line {}: their points are computed "
      "again)",
      done.damaged_lines, done.damaged_lines == 1 ? "" : "s", done.partial_path.string(),
      done.first_damaged_line);
}

int run_sweep_command(const SweepOptions& given) {
  const SweepOptions o = with_ranges(given);
  if (o.adhesion.any()) return run_adhesive_sweep(o);
  if (o.threads && (*o.threads < 1 || *o.threads > kMaxSweepThreads)) {
    throw InvalidInput(fmt::format("--threads must lie in [1, {}] (default: all cores), got {}",
                                   kMaxSweepThreads, *o.threads));
  }
  SweepGrid grid = sweep_grid(o);
  const SolveOptions solve = solve_options_of(o.inputs);
  SweepControl control;
  control.threads = o.threads ? static_cast<unsigned>(*o.threads) : 0U;
  check_sweep(grid.zetas, solve, grid.law, control.threads);  // every point, before the first file is touched
  if (fs::path(o.out).filename().empty() || fs::is_directory(o.out)) {
    throw InvalidInput(fmt::format("--out '{}' must name a file, not a folder", o.out));
  }
  // A symlink is followed: FILE.partial is kept beside the file it points to, which is replaced at the end.
  const files::OutputTarget target = files::output_target(o.out);
  if (target.in_place) {
    throw InvalidInput(
        fmt::format("--out '{}' is not a regular file (a device, FIFO or /dev/stdout): a sweep "
                    "keeps FILE.partial beside its file for --resume; give a file name",
                    o.out));
  }
  files::check_output_file(o.out);  // names the file when its folder refuses it
  SweepFile file;
  file.path = target.path;
  file.resume = o.resume;
  file.settings = settings_line(o, grid);
  file.columns = std::move(grid.velocity);  // after settings_line, which reads its beta
  file.given = o.out;
  file.option = "--out";
  file.resume_option = "--resume";
  file.resuming = [](const SweepFileOutcome& done) {
    fmt::print(stderr, "restitution: resuming: {} of {} points already finished, computing {}{}\n",
               done.resumed, done.points, done.points - done.resumed, dropped_note(done));
  };
  control.stop_requested = [] { return stop_signal_received() != 0; };

  SweepFileOutcome outcome;
  {
    const StopSignals signals;
    ProgressLine progress("sweep");  // ended before any message below
    control.progress = progress.callback();
    outcome = sweep_to_file(grid.zetas, solve, control, file, grid.law);
  }
  switch (outcome.status) {
    case SweepFileOutcome::Status::already_complete:
      fmt::print(stderr,
                 "restitution: nothing to resume: '{}' is complete (no '{}'); delete it to compute the sweep "
                 "again\n",
                 o.out, outcome.partial_path.string());
      return 0;
    case SweepFileOutcome::Status::stopped: {
      const int signal_number = stop_signal_received();
      fmt::print(
          stderr,
          "restitution: interrupted by signal {}: {} of {} points finished and kept in '{}'; run the same "
          "command with --resume to continue\n",
          signal_number, outcome.finished, outcome.points, outcome.partial_path.string());
      return 128 + signal_number;
    }
    case SweepFileOutcome::Status::complete:
      break;
  }
  fmt::print("wrote {}: {} points, {} failed\n", o.out, outcome.points, outcome.failed);
  if (outcome.failed > 0) {
    fmt::print(stderr, "restitution: numerical failure: {} of {} points failed; their rows in '{}' say why\n",
               outcome.failed, outcome.points, o.out);
    return 1;
  }
  return 0;
}

}  // namespace

void add_sweep_command(CLI::App& app, Action& chosen) {
  auto o = std::make_shared<SweepOptions>();
  CLI::App* cmd = app.add_subcommand(
      "sweep",
      "eps over a grid of zeta, or of impact speeds with beta or a material, in parallel, into a CSV file");
  add_head_on_options(*cmd, o->inputs, {"law"});
  cmd->add_option("--zeta-range", o->zeta_range,
                  fmt::format("FROM:TO:N: N values, in [1, {}], of zeta >= 0 of the law's natural form x'' + "
                              "zeta x^b x' + x^a = 0 (the linear dash-pot: zeta = 2 r), FROM and TO included",
                              kMaxSweepPoints));
  deprecate_old_form({cmd->add_option("--zeta-min", o->zeta_min), cmd->add_option("--zeta-max", o->zeta_max)},
                     "--zeta-min A --zeta-max B --points N", "--zeta-range A:B:N");
  cmd->add_option("--velocity-range", o->velocity_range,
                  fmt::format("instead of zeta, FROM:TO:N: N impact speeds in m/s, in [1, {}], FROM and TO "
                              "included (with --beta, a material or the physical coefficients)",
                              kMaxSweepPoints));
  deprecate_old_form({cmd->add_option("--velocity-min", o->velocity_min),
                      cmd->add_option("--velocity-max", o->velocity_max)},
                     "--velocity-min V1 --velocity-max V2 --points N", "--velocity-range V1:V2:N");
  cmd->add_option("--beta", o->beta, "viscoelastic Hertz: beta in s^(1/5) m^(-1/5), zeta = beta v^(1/5)");
  cmd->add_option("--stiffness", o->stiffness,
                  "any law, in physical units: k in N/m^a of the force F = k xi^a + gamma xi^b xi'");
  cmd->add_option("--damping-coefficient", o->damping_coefficient,
                  "any law, in physical units: gamma in N s/m^(1+b) of that force");
  cmd->add_option("--effective-mass", o->effective_mass,
                  "any law, in physical units: the effective mass m_eff in kg (adds SI columns)");
  add_head_on_material_options(*cmd, o->inputs);
  cmd->add_option(
      "--dissipative-constant", o->dissipative_constant,
      "material: the dissipative constant A in s (adds SI columns: durations, maximal compression); with "
      "--adhesion: A of the adhesive model (default 0: elastic)");
  add_adhesion_options(*cmd, o->adhesion);
  // The old forms' count (hidden with them; their min and max options say they are old).
  cmd->add_option("--points", o->points)
      ->check(whole_number_in(1, static_cast<long long>(kMaxSweepPoints)))
      ->group("");
  cmd->add_flag("--log", o->log, "space the grid logarithmically (needs a minimum > 0); default: linearly");
  add_head_on_options(*cmd, o->inputs, {"end", "tolerance", "method"});
  cmd->add_option("--threads", o->threads,
                  fmt::format("worker threads, in [1, {}] (default: all cores)", kMaxSweepThreads));
  cmd->add_option("--out", o->out, "the CSV file to write (FILE.partial holds the rows while it runs)")
      ->required()
      ->check(non_empty_path());
  cmd->add_flag("--resume", o->resume, "continue an interrupted sweep from FILE.partial");
  cmd->callback([o, &chosen] { chosen = [o] { return run_sweep_command(*o); }; });
}

}  // namespace restitution::cli
