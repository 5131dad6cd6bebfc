// SPDX-License-Identifier: BSD-3-Clause
#include "cli/scene/scene_outputs.hpp"

#include <fmt/core.h>

#include <algorithm>

#include "cli/common/build_json.hpp"
#include "cli/common/json_writer.hpp"
#include "cli/common/plot_script.hpp"
#include "cli/common/result_json.hpp"
#include "cli/common/stop_signals.hpp"
#include "cli/scene/scene_section_writers.hpp"
#include "cli/scene/scene_tables.hpp"
#include "cli/scene/scene_text.hpp"
#include "files/output_files.hpp"
#include "scene/figure_formats.hpp"

namespace restitution::cli {
namespace {

namespace fs = std::filesystem;

class SceneWriter : private SectionOutput {
 public:
  SceneWriter(const scene::Scene& s, const scene::SceneResults& r, fs::path folder)
      : scene_(s), results_(r), folder_(std::move(folder)) {}

  WrittenOutputs write(double seconds) {
    out_.warnings = scene_.warnings;
    report_ = fmt::format("# {}\n\n", scene_.title.empty() ? scene_.file_name : scene_.title);
    json_.begin_object();
    json_.field("scene", scene_.file_name).field("title", scene_.title);
    json_.field("tolerance", scene_.tolerance).field("method", method_name(scene_.method));
    // Sections in the order the scene file lists them, each by its row; then the rows written together
    // (the calibrations, the studies).
    std::vector<std::size_t> order;
    for (std::size_t i = 0; i < scene_.sections.size(); ++i) {
      if (find_section_writer(scene_.sections[i].kind)->write != nullptr) order.push_back(i);
    }
    std::stable_sort(order.begin(), order.end(), [this](std::size_t a, std::size_t b) {
      return scene_.sections[a].line < scene_.sections[b].line;
    });
    for (const std::size_t i : order) section(i);
    sections_together();
    footer(seconds);
    write_file("summary.json", finish_json_document(json_) + "\n");
    write_file("report.md", report_);  // last: its presence says the folder is complete
    return std::move(out_);
  }

 private:
  void write_file(const std::string& name, const std::string& content) {
    throw_if_interrupted();  // Ctrl-C stops the run here, between files, never inside one
    files::write_file_atomically(folder_ / name, content);
    out_.files.push_back(name);
  }

  // A section of the table of kinds (scene/scene_sections.hpp), written by its row of section_writers().
  void section(std::size_t i) {
    const scene::SectionTask& s = scene_.sections[i];
    find_section_writer(s.kind)->write(scene_, s, results_.sections[i], *this);
  }
  // The sections whose rows share a write_together function, each function once with all of them.
  void sections_together() {
    std::vector<decltype(cli::SectionWriter::write_together)> done;
    for (const cli::SectionWriter& writer : section_writers()) {
      const auto together = writer.write_together;
      if (together == nullptr || std::find(done.begin(), done.end(), together) != done.end()) continue;
      done.push_back(together);
      std::vector<SectionResult> sections;
      for (std::size_t i = 0; i < scene_.sections.size(); ++i) {
        if (find_section_writer(scene_.sections[i].kind)->write_together == together)
          sections.push_back({&scene_.sections[i], &results_.sections[i]});
      }
      together(scene_, sections, *this);
    }
  }
  void file(const std::string& name, const std::string& content) override { write_file(name, content); }
  [[nodiscard]] const fs::path& folder() const override { return folder_; }
  void written(const std::vector<std::string>& names) override {
    out_.files.insert(out_.files.end(), names.begin(), names.end());
  }
  void report(const std::string& markdown) override { report_ += markdown; }
  JsonWriter& summary() override { return json_; }
  void warn(const std::string& line) override { out_.warnings.push_back(line); }

  // Runs a plot script; returns the markdown image link, or a note saying why there is no plot.
  std::string plot(const std::string& script, const std::string& name,
                   const std::vector<std::string>& arguments) override {
    const std::vector<std::string>& formats = scene_.figure_formats;
    const std::string why =
        run_plot_script(script, folder_ / (name + ".csv"), folder_ / (name + ".png"), arguments, formats);
    if (!why.empty()) {
      out_.warnings.push_back(fmt::format("{}: {}", name, why));
      return fmt::format("*({}; the data are in `{}.csv`)*\n\n", why, name);
    }
    for (const std::string& figure : figure_file_names(name, formats)) out_.files.push_back(figure);
    return fmt::format("![{}]({}.{})\n\n", name, name, scene::linked_figure_format(formats));
  }

  void footer(double seconds) {
    const SolverStats& s = results_.total;
    const std::size_t distinct = results_.plan.jobs.size();
    const std::string elsewhere = own_collisions_text(scene_);
    // A scene of [[gas]] or [[oblique]] sections alone integrates nothing of the shared plan: the report says
    // so rather than "0 distinct collisions integrated".
    const std::string work =
        results_.collisions == 0 && !elsewhere.empty()
            ? fmt::format("no collision of the shared plan integrated ({}), in {:.2f} s", elsewhere, seconds)
            : fmt::format(
                  "{} distinct collisions integrated once each (every output that needs a collision shares "
                  "its solve) plus {} for calibrations, in {:.2f} s; tolerance {} on ε relative to "
                  "min(ε, 1 - ε), method {}; {} steps, {} right-hand-side evaluations in total{}",
                  distinct, results_.collisions - distinct, seconds, report_number(scene_.tolerance),
                  method_name(scene_.method), s.steps, s.rhs_evaluations,
                  elsewhere.empty() ? "" : " (" + elsewhere + ")");
    report_ += fmt::format("## How this was computed\n\nScene `{}`; {}. {}\n", scene_.file_name, work,
                           scene_.description.empty() ? "" : "\n\n" + scene_.description + "\n");
    // The code that computed the numbers, as summary.json names it (docs/release.md).
    report_ += fmt::format("\nComputed by {}.\n", build_description());
    json_.field("collisions", static_cast<long>(results_.collisions));
    json_.field("distinct_collisions", static_cast<long>(results_.plan.jobs.size()));
    json_.field("seconds", seconds);
    json_.key("stats").begin_object();
    json_.field("steps", s.steps).field("rhs_evaluations", s.rhs_evaluations);
    json_.field("jacobian_evaluations", s.jacobian_evaluations).field("root_evaluations", s.root_evaluations);
    json_.end_object();
  }

  const scene::Scene& scene_;
  const scene::SceneResults& results_;
  fs::path folder_;
  std::string report_;
  JsonWriter json_;
  WrittenOutputs out_;
};

}  // namespace

WrittenOutputs write_scene_outputs(const scene::Scene& scene, const scene::SceneResults& results,
                                   const fs::path& folder, double seconds) {
  files::check_output_folder(folder);
  // A write that fails half-way must not leave a folder that looks like a result (item 11 of issue 12).
  const bool existed = fs::exists(folder);
  // The report and summary of an earlier run would describe files this run replaces: gone until the new ones
  // are written (the summary's numbers beside the new tables would read as this run's), so that a run that
  // stops half-way leaves no folder that looks complete.
  std::error_code ignored;
  if (existed) {
    for (const char* name : {"report.md", "summary.json"}) fs::remove(folder / name, ignored);
  }
  try {
    return SceneWriter(scene, results, folder).write(seconds);
  } catch (...) {
    if (!existed) fs::remove_all(folder, ignored);
    throw;
  }
}

}  // namespace restitution::cli
