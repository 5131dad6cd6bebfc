// SPDX-License-Identifier: BSD-3-Clause
// `restitution sweep`: ε over a grid of ζ, or of impact speeds with β or a material, in parallel, into one
// CSV file. Nothing finished is lost: each
// finished row is appended to FILE.partial (flushed every 100 ms, each line with its own checksum); the table
// is written in ζ order into FILE.tmp as the rows come, and FILE appears (renamed) only when every point is
// finished; SIGINT/SIGTERM stop the sweep after the points in progress; --resume continues from FILE.partial,
// keeping every valid row. FILE.lock keeps a second process from writing the same files meanwhile.
#include <fmt/core.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

#include "cli/common/commands.hpp"
#include "cli/common/material_options.hpp"
#include "cli/common/options.hpp"
#include "cli/common/output_files.hpp"
#include "cli/common/output_lock.hpp"
#include "cli/common/progress.hpp"
#include "cli/common/stop_signals.hpp"
#include "cli/sweep/sweep_files.hpp"
#include "cli/sweep/sweep_grid.hpp"
#include "cli/sweep/sweep_partial.hpp"
#include "cli/sweep/sweep_table.hpp"
#include "restitution/errors.hpp"
#include "restitution/material.hpp"
#include "restitution/sweep.hpp"
#include "restitution/units.hpp"

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
    if (o.material.any()) range += " material";
    if (o.stiffness) {
      range += fmt::format(" stiffness={} damping-coefficient={} effective-mass={}", number17(*o.stiffness),
                           number17(*o.damping_coefficient), number17(*o.effective_mass));
    }
  }
  if (grid.law != LawKind::viscoelastic_hertz) range = fmt::format("law={} {}", o.law, range);
  return fmt::format("# restitution sweep: {} points={} spacing={} end={} method={} tolerance={}", range,
                     o.points, o.log ? "log" : "linear", o.solver.end, o.solver.method,
                     number17(o.solver.tolerance));
}

// A row per worker, formatted on the worker and moved into the table: on its own cache line.
struct alignas(64) WorkerRow {
  std::string text;
};

std::string dropped_note(const PartialSweep& done, const fs::path& partial_path) {
  if (done.dropped == 0) return "";
  return fmt::format(
      " ({} damaged line{} of '{}' dropped, the first at line {}: their points are computed "
      "again)",
      done.dropped, done.dropped == 1 ? "" : "s", partial_path.string(), done.first_dropped_line);
}

int run_sweep_command(const SweepOptions& o) {
  if (o.threads && (*o.threads < 1 || *o.threads > kMaxSweepThreads)) {
    throw InvalidInput(fmt::format("--threads must lie in [1, {}] (default: all cores), got {}",
                                   kMaxSweepThreads, *o.threads));
  }
  const SweepGrid grid = sweep_grid(o);
  const std::vector<double>& zetas = grid.zetas;
  const VelocityAxis* velocity = grid.velocity ? &*grid.velocity : nullptr;
  const SolveOptions solve = solve_options(o.solver);
  const unsigned threads = o.threads ? static_cast<unsigned>(*o.threads) : 0U;
  check_sweep(zetas, solve, grid.law, threads);  // every point, before the first file is touched
  if (fs::path(o.out).filename().empty() || fs::is_directory(o.out)) {
    throw InvalidInput(fmt::format("--out '{}' must name a file, not a folder", o.out));
  }
  // A symlink is followed: FILE.partial is kept beside the file it points to, which is replaced at the end.
  const OutputTarget target = output_target(o.out);
  if (target.in_place) {
    throw InvalidInput(
        fmt::format("--out '{}' is not a regular file (a device, FIFO or /dev/stdout): a sweep "
                    "keeps FILE.partial beside its file for --resume; give a file name",
                    o.out));
  }
  const fs::path& out = target.path;
  check_output_file(o.out);  // names the file when its folder refuses it
  const fs::path partial_path = out.string() + ".partial";
  const std::string settings = settings_line(o, grid);
  const std::string header = sweep_header(solve.ends, velocity);

  std::error_code no_folder;  // check_output_file said it can be made; the lock file names it if not
  if (out.has_parent_path()) fs::create_directories(out.parent_path(), no_folder);
  // Before the partial file is looked at: a sweep that runs now owns it (and "add --resume" would be wrong).
  const OutputLock lock(sweep_lock_path(out), fmt::format("--out '{}'", o.out));
  PartialSweep done;
  if (o.resume && !fs::exists(partial_path) && fs::exists(out)) {
    // The sweep finished (FILE.partial is removed only then): recomputing it all would not be a resume.
    fmt::print(stderr,
               "restitution: nothing to resume: '{}' is complete (no '{}'); delete it to compute the sweep "
               "again\n",
               o.out, partial_path.string());
    return 0;
  }
  if (fs::exists(partial_path)) {
    if (!o.resume) {
      throw InvalidInput(
          fmt::format("'{}' holds an interrupted sweep: add --resume to continue it, or delete it",
                      partial_path.string()));
    }
    FileLines lines(partial_path);
    done = read_partial_sweep(lines.lines(), partial_path, settings, header, zetas);
    fmt::print(stderr, "restitution: resuming: {} of {} points already finished, computing {}{}\n", done.kept,
               zetas.size(), zetas.size() - done.kept, dropped_note(done, partial_path));
  }
  // As many buffers as the sweep can have workers (SweepControl::threads, 0: one per core).
  const unsigned writers = threads != 0 ? threads : std::thread::hardware_concurrency();
  PartialFile partial(partial_path, done.valid_bytes, settings + "\n" + partial_header(header) + "\n",
                      writers);

  SweepControl control;
  control.threads = threads;
  if (done.kept > 0) {
    control.already_done.assign(zetas.size(), false);
    for (std::size_t i = 0; i < zetas.size(); ++i)
      control.already_done[i] = done.row_offset[i] != PartialSweep::kNotDone;
  }
  OrderedTable table(out, header, zetas.size(),
                     done.kept > 0 ? std::move(done.row_offset) : std::vector<std::uint64_t>{}, partial_path);
  control.stop_requested = [] { return stop_signal_received() != 0; };
  // Each worker formats its row into a string of its own and appends it to its own buffer of the partial
  // file; only the table's in-order writing is serialized, and it overlaps the other workers' solves.
  std::vector<WorkerRow> rows(std::max(1U, writers));
  control.point_computed = [&](const SweepPoint& point) {
    std::string& row = rows.at(point.worker).text;
    row = sweep_row(point, solve.ends, velocity);
    partial.append(point.worker, point.index, row);
  };
  control.point_finished = [&](const SweepPoint& point) {
    table.add(point.index, std::move(rows[point.worker].text));
  };

  // A failed write stops the sweep; what FILE.partial holds is valid (nothing is written after the failure).
  const auto keeping_partial = [&partial_path](const auto& step) {
    try {
      step();
    } catch (const IoError& e) {
      throw IoError(
          fmt::format("{}; the finished points in '{}' are kept: run the same command with --resume "
                      "once it can be written",
                      e.what(), partial_path.string()));
    }
  };
  SweepSummary summary;
  keeping_partial([&] {
    const StopSignals signals;
    ProgressLine progress("sweep");  // ended before any message below
    control.progress = progress.callback();
    summary = run_sweep(zetas, solve, control, grid.law);
  });
  const std::size_t finished = summary.computed + summary.skipped;
  if (summary.stopped) {
    const int signal_number = stop_signal_received();
    fmt::print(
        stderr,
        "restitution: interrupted by signal {}: {} of {} points finished and kept in '{}'; run the same "
        "command with --resume to continue\n",
        signal_number, finished, zetas.size(), partial_path.string());
    return 128 + signal_number;
  }

  keeping_partial([&] { table.commit(); });
  fs::remove(partial_path);
  const std::size_t failed = summary.failed + done.failed;
  fmt::print("wrote {}: {} points, {} failed\n", o.out, zetas.size(), failed);
  if (failed > 0) {
    fmt::print(stderr, "restitution: numerical failure: {} of {} points failed; their rows in '{}' say why\n",
               failed, zetas.size(), o.out);
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
  add_law_option(*cmd, o->law);
  cmd->add_option("--zeta-min", o->zeta_min,
                  "smallest zeta >= 0 of the law's natural form x'' + zeta x^b x' + x^a = 0 (the linear "
                  "dash-pot: zeta = 2 r)");
  cmd->add_option("--zeta-max", o->zeta_max, "largest zeta >= zeta-min");
  cmd->add_option("--velocity-min", o->velocity_min,
                  "instead of zeta: smallest impact speed in m/s (with --beta or a material)");
  cmd->add_option("--velocity-max", o->velocity_max, "largest impact speed in m/s");
  cmd->add_option("--beta", o->beta, "viscoelastic Hertz: beta in s^(1/5) m^(-1/5), zeta = beta v^(1/5)");
  cmd->add_option("--stiffness", o->stiffness,
                  "any law, in physical units: k in N/m^a of the force F = k xi^a + gamma xi^b xi'");
  cmd->add_option("--damping-coefficient", o->damping_coefficient,
                  "any law, in physical units: gamma in N s/m^(1+b) of that force");
  cmd->add_option("--effective-mass", o->effective_mass,
                  "any law, in physical units: the effective mass m_eff in kg (adds SI columns)");
  add_material_options(*cmd, o->material);
  cmd->add_option(
      "--dissipative-constant", o->dissipative_constant,
      "material: the dissipative constant A in s (adds SI columns: durations, maximal compression)");
  cmd->add_option("--points", o->points,
                  fmt::format("number of grid values, in [1, {}] (both bounds included)", kMaxSweepPoints))
      ->required()
      ->check(whole_number_in(1, static_cast<long long>(kMaxSweepPoints)));
  cmd->add_flag("--log", o->log, "space the grid logarithmically (needs a minimum > 0); default: linearly");
  add_solver_options(*cmd, o->solver);
  cmd->add_option("--threads", o->threads,
                  fmt::format("worker threads, in [1, {}] (default: all cores)", kMaxSweepThreads));
  cmd->add_option("--out", o->out, "the CSV file to write (FILE.partial holds the rows while it runs)")
      ->required()
      ->check(non_empty_path());
  cmd->add_flag("--resume", o->resume, "continue an interrupted sweep from FILE.partial");
  cmd->callback([o, &chosen] { chosen = [o] { return run_sweep_command(*o); }; });
}

}  // namespace restitution::cli
