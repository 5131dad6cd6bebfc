// SPDX-License-Identifier: BSD-3-Clause
#include "cli/solve/work_precision_files.hpp"

#include <fmt/core.h>

#include "cli/common/plot_script.hpp"
#include "cli/common/resource_root.hpp"
#include "files/output_files.hpp"
#include "sweep/number_text.hpp"

namespace restitution::cli {
namespace {

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
  std::string csv = "engine,end,tolerance,max_error,mean_median_us,max_median_us,zeta_points\n";
  for (const WorkPrecisionGroup& g : group_work_precision(rows)) {
    csv +=
        fmt::format("{},{},{},{},{},{},{}\n", g.engine, g.end, number17(g.tolerance), number17(g.max_error),
                    number17(g.mean_median_seconds * 1e6), number17(g.max_median_seconds * 1e6), g.points);
  }
  return csv;
}

}  // namespace

std::filesystem::path default_reference_file() {
  return reference_file_in(resource_root());
}

WorkPrecisionFiles write_work_precision_files(const std::vector<WorkPrecisionRow>& rows,
                                              const std::filesystem::path& folder, const std::string& stem,
                                              const std::vector<std::string>& formats) {
  WorkPrecisionFiles out;
  const std::string points = stem + ".csv";
  const std::string summary = stem + "_summary.csv";
  const std::string png = stem + ".png";
  files::write_file_atomically(folder / points, points_csv(rows));
  files::write_file_atomically(folder / summary, summary_csv(rows));
  out.files = {points, summary};
  out.plot_warning = run_plot_script("work_precision", folder / summary, folder / png, {}, formats);
  if (out.plot_warning.empty()) {
    for (const std::string& figure : figure_file_names(stem, formats)) out.files.push_back(figure);
  }
  return out;
}

}  // namespace restitution::cli
