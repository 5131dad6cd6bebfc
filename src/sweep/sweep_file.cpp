// SPDX-License-Identifier: BSD-3-Clause
// sweep_to_file: a sweep into a CSV file that an interruption does not lose (restitution/sweep.hpp). The
// files are sweep_files.hpp's, the partial file's format sweep_partial.hpp's, the lock
// files/output_lock.hpp's.
#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <string>
#include <system_error>
#include <thread>
#include <utility>
#include <vector>

#include "files/output_files.hpp"
#include "files/output_lock.hpp"
#include "restitution/errors.hpp"
#include "restitution/sweep.hpp"
#include "sweep/checked_sweep.hpp"
#include "sweep/line_reader.hpp"
#include "sweep/sweep_files.hpp"
#include "sweep/sweep_partial.hpp"
#include "sweep/sweep_table.hpp"

namespace restitution {
namespace {
namespace fs = std::filesystem;

// A row per worker, formatted on the worker and moved into the table: on its own cache line.
struct alignas(64) WorkerRow {
  std::string text;
};

// The file as messages name it: "--out 'x.csv'", or "'x.csv'" without an option.
std::string named(const SweepFile& file) {
  const std::string given = file.given.empty() ? file.path.string() : file.given;
  return file.option.empty() ? fmt::format("'{}'", given) : fmt::format("{} '{}'", file.option, given);
}

void check_columns(const SweepFile& file, std::size_t points) {
  if (!file.columns) return;
  const SweepColumns& c = *file.columns;
  if (c.velocity_m_s.size() != points || (!c.scales.empty() && c.scales.size() != points)) {
    throw InvalidInput(fmt::format(
        "{}: the sweep has {} points but its columns {} impact speeds and {} natural scales (each one per "
        "point, the scales or none)",
        named(file), points, c.velocity_m_s.size(), c.scales.size()));
  }
}

}  // namespace

SweepFileOutcome sweep_to_file(const std::vector<double>& zetas, const SolveOptions& options,
                               SweepControl control, const SweepFile& file, LawKind law) {
  check_sweep(zetas, options, law, control.threads);  // every point, before the first file is touched
  if (file.path.filename().empty() || fs::is_directory(file.path)) {
    throw InvalidInput(fmt::format("{} must name a file, not a folder", named(file)));
  }
  check_columns(file, zetas.size());
  if (file.settings.find_first_of("\r\n") != std::string::npos) {
    throw InvalidInput(
        fmt::format("{}: the settings line of its partial file holds a line break", named(file)));
  }
  // A device, FIFO or stream cannot hold a sweep: its table is made beside the file and renamed onto it,
  // which would replace /dev/full itself when run as root. A link is followed, as every output is (its
  // target's folder must exist).
  const files::OutputTarget target = files::output_target(file.path);
  if (target.in_place) {
    throw InvalidInput(fmt::format(
        "{} is not a regular file (a device, FIFO or stream): a sweep keeps FILE.partial beside its file and "
        "renames the finished table onto it; name a file",
        named(file)));
  }
  files::check_output_file(file.path);
  const fs::path& out = target.path;
  const SweepColumns* columns = file.columns ? &*file.columns : nullptr;
  SweepFileOutcome outcome;
  outcome.partial_path = out.string() + ".partial";
  outcome.points = zetas.size();
  const fs::path& partial_path = outcome.partial_path;
  const std::string header = sweep_header(options.ends, columns);

  std::error_code no_folder;  // the lock file names the folder when it cannot be made
  if (out.has_parent_path()) fs::create_directories(out.parent_path(), no_folder);
  // Before the partial file is looked at: a sweep that runs now owns it (and "resume" would be wrong).
  const files::OutputLock lock(files::sweep_lock_path(out), named(file));
  if (file.resume && !fs::exists(partial_path) && fs::exists(out)) {
    // The sweep finished (FILE.partial is removed only then): recomputing it all would not be a resume.
    outcome.status = SweepFileOutcome::Status::already_complete;
    outcome.finished = zetas.size();
    return outcome;
  }
  PartialSweep done;
  if (fs::exists(partial_path)) {
    if (!file.resume) {
      throw InvalidInput(fmt::format("'{}' holds an interrupted sweep: add {} to continue it, or delete it",
                                     partial_path.string(), file.resume_option));
    }
    FileLines lines(partial_path);
    done = read_partial_sweep(lines.lines(), partial_path, file.settings, header, zetas, file.resume_option);
    outcome.resumed = done.kept;
    outcome.damaged_lines = done.dropped;
    outcome.first_damaged_line = done.first_dropped_line;
    if (file.resuming) file.resuming(outcome);
  }
  // As many buffers as the sweep can have workers (SweepControl::threads, 0: one per core).
  const unsigned threads = control.threads;
  const unsigned writers = threads != 0 ? threads : std::thread::hardware_concurrency();
  PartialFile partial(partial_path, done.valid_bytes, file.settings + "\n" + partial_header(header) + "\n",
                      writers, file.option);

  control.already_done.clear();
  if (done.kept > 0) {
    control.already_done.assign(zetas.size(), false);
    for (std::size_t i = 0; i < zetas.size(); ++i)
      control.already_done[i] = done.row_offset[i] != PartialSweep::kNotDone;
  }
  OrderedTable table(out, header, zetas.size(),
                     done.kept > 0 ? std::move(done.row_offset) : std::vector<std::uint64_t>{}, partial_path);
  // Each worker formats its row into a string of its own and appends it to its own buffer of the partial
  // file; only the table's in-order writing is serialized, and it overlaps the other workers' solves.
  std::vector<WorkerRow> rows(std::max(1U, writers));
  control.point_computed = [&](const SweepPoint& point) {
    std::string& row = rows.at(point.worker).text;
    row = sweep_row(point, options.ends, columns);
    partial.append(point.worker, point.index, row);
  };
  control.point_finished = [&](const SweepPoint& point) {
    table.add(point.index, std::move(rows[point.worker].text));
  };

  // A failed write stops the sweep; what FILE.partial holds is valid (nothing is written after the failure).
  const auto keeping_partial = [&](const auto& step) {
    try {
      step();
    } catch (const IoError& e) {
      throw IoError(
          fmt::format("{}; the finished points in '{}' are kept: run the same command with {} once it can be "
                      "written",
                      e.what(), partial_path.string(), file.resume_option));
    }
  };
  SweepSummary summary;
  keeping_partial([&] { summary = run_checked_sweep(zetas, options, control, law); });
  outcome.finished = summary.computed + summary.skipped;
  outcome.failed = summary.failed + done.failed;
  if (summary.stopped) {
    outcome.status = SweepFileOutcome::Status::stopped;
    return outcome;
  }
  keeping_partial([&] { table.commit(); });
  fs::remove(partial_path);
  outcome.status = SweepFileOutcome::Status::complete;
  return outcome;
}

}  // namespace restitution
