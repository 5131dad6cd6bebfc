// SPDX-License-Identifier: BSD-3-Clause
#include "cli/scene/scene_studies.hpp"

#include <fmt/core.h>

#include "cli/scene/scene_text.hpp"
#include "cli/solve/work_precision_files.hpp"
#include "scene/figure_formats.hpp"
#include "scene/scene_results.hpp"
#include "scene/scene_studies.hpp"

namespace restitution::cli {

void write_studies(const scene::Scene& scene, const std::vector<SectionResult>& studies, SectionOutput& out) {
  if (studies.empty()) return;
  out.report("## Other studies\n\n");
  JsonWriter& json = out.summary();
  json.key("studies").begin_array();
  for (const SectionResult& entry : studies) {
    const auto& task = std::any_cast<const scene::ExternalStudy&>(entry.section->task);
    const auto& study = std::any_cast<const scene::StudyOutcome&>(*entry.outcome);
    for (const std::string& line : study_lines(task, study)) {
      out.report("* " + line + "\n");
      json.value(line);
    }
    if (study.work_precision.empty()) continue;
    const std::string& name = task.name;
    const WorkPrecisionFiles files =
        write_work_precision_files(study.work_precision, out.folder(), name, scene.figure_formats);
    out.written(files.files);
    if (files.plot_warning.empty()) {
      out.report(
          fmt::format("\n![{}]({}.{})\n", name, name, scene::linked_figure_format(scene.figure_formats)));
    } else {
      out.warn(fmt::format("{}: {}", name, files.plot_warning));
      out.report(fmt::format("\n*({}; the data are in `{}.csv` and `{}_summary.csv`)*\n", files.plot_warning,
                             name, name));
    }
  }
  json.end_array();
  out.report("\n");
}

}  // namespace restitution::cli
