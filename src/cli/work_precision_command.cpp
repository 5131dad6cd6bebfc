// `restitution work-precision [--out DIR]`: error against run time of every engine on a fixed ζ set and
// tolerance ladder, both ends, against data/reference_solutions.csv: a CSV per point, a summary CSV per
// (engine, end, tolerance) and a PNG (scripts/plots/work_precision.py).
#include <fmt/core.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <memory>
#include <tuple>

#include "cli/commands.hpp"
#include "cli/output_files.hpp"
#include "restitution/errors.hpp"
#include "restitution/work_precision.hpp"

namespace restitution::cli {
namespace {

struct WorkPrecisionOptions {
  std::string out = "out/work-precision";
  std::string reference;
  int repeats = 7;
  std::vector<std::string> engines;
};

std::string points_csv(const std::vector<WorkPrecisionRow>& rows) {
  std::string csv = "engine,end,tolerance,zeta,error,median_us,rhs_evaluations,steps\n";
  for (const WorkPrecisionRow& r : rows) {
    csv += fmt::format("{},{},{},{},{},{},{},{}\n", r.engine, r.end, number17(r.tolerance), number17(r.zeta),
                       number17(r.error), number17(r.median_seconds * 1e6), r.rhs_evaluations, r.steps);
  }
  return csv;
}

// Per (engine, end, tolerance): the worst error over the ζ set, the mean and the worst of the median times.
std::string summary_csv(const std::vector<WorkPrecisionRow>& rows) {
  struct Summary {
    double max_error = 0, sum_us = 0, max_us = 0;
    int points = 0;
  };
  std::map<std::tuple<std::string, std::string, double>, Summary> groups;
  for (const WorkPrecisionRow& r : rows) {
    Summary& s = groups[{r.engine, r.end, -r.tolerance}];
    s.max_error = std::max(s.max_error, r.error);
    s.sum_us += r.median_seconds * 1e6;
    s.max_us = std::max(s.max_us, r.median_seconds * 1e6);
    ++s.points;
  }
  std::string csv = "engine,end,tolerance,max_error,mean_median_us,max_median_us,zeta_points\n";
  for (const auto& [key, s] : groups) {
    csv +=
        fmt::format("{},{},{},{},{},{},{}\n", std::get<0>(key), std::get<1>(key), number17(-std::get<2>(key)),
                    number17(s.max_error), number17(s.sum_us / s.points), number17(s.max_us), s.points);
  }
  return csv;
}

int run_work_precision(const WorkPrecisionOptions& o) {
  if (o.repeats < 1) throw InvalidInput(fmt::format("--repeats must be >= 1, got {}", o.repeats));
  const std::filesystem::path reference =
      o.reference.empty() ? reference_file_in(std::filesystem::path(RESTITUTION_SCRIPTS_DIR).parent_path())
                          : std::filesystem::path(o.reference);
  const std::vector<WorkPrecisionRow> rows =
      measure_work_precision(read_reference_file(reference), o.repeats, o.engines);
  const std::filesystem::path folder(o.out);
  prepare_output_folder(folder);
  write_file_atomically(folder / "work_precision.csv", points_csv(rows));
  write_file_atomically(folder / "work_precision_summary.csv", summary_csv(rows));
  const std::string plot = run_plot_script(
      "work_precision",
      {(folder / "work_precision_summary.csv").string(), (folder / "work_precision.png").string()});
  if (!plot.empty()) std::fprintf(stderr, "restitution: warning: %s\n", plot.c_str());
  fmt::print("wrote {} points to {}\n", rows.size(), folder.string());
  return 0;
}

}  // namespace

void add_work_precision_command(CLI::App& app, Action& chosen) {
  auto o = std::make_shared<WorkPrecisionOptions>();
  CLI::App* cmd =
      app.add_subcommand("work-precision", "error against run time of every engine, against the reference");
  cmd->add_option("--out", o->out, "output folder")->capture_default_str();
  cmd->add_option("--reference", o->reference,
                  "reference CSV (default: data/reference_solutions.csv of the source tree)");
  cmd->add_option("--repeats", o->repeats, "timed solves per point (the median is reported)")
      ->capture_default_str();
  cmd->add_option("--engine", o->engines,
                  "measure only these engines: taylor, bdf, adams, bdf-plain, adams-plain")
      ->delimiter(',');
  cmd->callback([o, &chosen] { chosen = [o] { return run_work_precision(*o); }; });
}

}  // namespace restitution::cli
