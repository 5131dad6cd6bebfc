// SPDX-License-Identifier: BSD-3-Clause
// `restitution work-precision [--out DIR]`: error against run time of every engine on a fixed ζ set and
// tolerance ladder, both ends, against data/reference_solutions.csv: a CSV per point, a summary CSV per
// (engine, end, tolerance) and a PNG (scripts/plots/work_precision.py).
#include <fmt/core.h>

#include <cstdio>
#include <memory>

#include "cli/common/commands.hpp"
#include "cli/common/options.hpp"
#include "cli/common/progress.hpp"
#include "cli/common/stop_signals.hpp"
#include "cli/solve/work_precision_files.hpp"
#include "files/output_files.hpp"
#include "reference/work_precision.hpp"
#include "restitution/errors.hpp"

namespace restitution::cli {
namespace {

struct WorkPrecisionOptions {
  std::string out = "out/work-precision";
  std::string reference;
  int repeats = 7;
  std::vector<std::string> engines;
  std::string format = "png";
};

int run_work_precision(const WorkPrecisionOptions& o) {
  const std::filesystem::path folder(o.out);
  files::check_output_folder(folder);  // before the measurements, not after
  const std::filesystem::path reference =
      o.reference.empty() ? default_reference_file() : std::filesystem::path(o.reference);
  // Ctrl-C stops at the next point, before any file is written; one that arrives while the (atomic) files are
  // written or plotted still stops the command with its message, not the default death.
  const StopSignals signals;
  std::vector<WorkPrecisionRow> rows;
  {
    ProgressLine progress("work-precision (engine, end, tolerance)");
    rows = measure_work_precision(read_reference_file(reference), o.repeats, o.engines,
                                  progress.stoppable_callback());
  }
  const WorkPrecisionFiles written =
      write_work_precision_files(rows, folder, "work_precision", scene::figure_formats_from_list(o.format));
  if (!written.plot_warning.empty())
    std::fprintf(stderr, "restitution: warning: %s\n", written.plot_warning.c_str());
  fmt::print("wrote {} points to {}\n", rows.size(), folder.string());
  return 0;
}

}  // namespace

void add_work_precision_command(CLI::App& app, Action& chosen) {
  auto o = std::make_shared<WorkPrecisionOptions>();
  CLI::App* cmd =
      app.add_subcommand("work-precision", "error against run time of every engine, against the reference");
  cmd->add_option("--out", o->out, "output folder")->capture_default_str()->check(non_empty_path());
  cmd->add_option("--reference", o->reference,
                  "reference CSV (default: data/reference_solutions.csv of the source tree)");
  cmd->add_option(
         "--repeats", o->repeats,
         fmt::format("timed solves per point, in [1, {}] (the median is reported)", kMaxWorkPrecisionRepeats))
      ->capture_default_str()
      ->check(whole_number_in(1, kMaxWorkPrecisionRepeats));
  cmd->add_option("--engine", o->engines,
                  "measure only these engines: taylor, bdf, adams, bdf-plain, adams-plain")
      ->delimiter(',');
  add_figure_format_option(cmd, o->format);
  cmd->callback([o, &chosen] { chosen = [o] { return run_work_precision(*o); }; });
}

}  // namespace restitution::cli
