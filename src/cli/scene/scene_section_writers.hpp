// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The writers of the scene sections in the table of scene/scene_sections.hpp, one row per kind keyed by the
// same name (tests/test_scene_sections.cpp checks both tables list the same kinds): each writes its
// section's files, figure, report paragraph and summary.json object through a SectionOutput, which `run`'s
// writer (scene_outputs.cpp) provides.
#include <any>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "cli/common/json_writer.hpp"
#include "scene/scene.hpp"

namespace restitution::cli {

// What a section's writer may do in the scene's output folder.
class SectionOutput {
 public:
  virtual ~SectionOutput() = default;
  // Writes NAME into the folder, atomically.
  virtual void file(const std::string& name, const std::string& content) = 0;
  // The folder, for what writes its files itself (then named with `written`) or names a file to a script.
  [[nodiscard]] virtual const std::filesystem::path& folder() const = 0;
  virtual void written(const std::vector<std::string>& names) = 0;
  // Draws NAME.csv with scripts/plots/SCRIPT.py into NAME.<format>; returns the report's image link, or a
  // note why there is no figure (also a warning).
  virtual std::string plot(const std::string& script, const std::string& name,
                           const std::vector<std::string>& arguments) = 0;
  virtual void report(const std::string& markdown) = 0;
  // summary.json, inside its top-level object: a section adds one key.
  virtual JsonWriter& summary() = 0;
  // One line on stderr after the run.
  virtual void warn(const std::string& line) = 0;
};

// A section and its outcome, as the writers of several sections at once receive them.
struct SectionResult {
  const scene::SectionTask* section;
  const std::any* outcome;
};

struct SectionWriter {
  const char* name;  // the scene_sections.hpp row it writes
  // Writes one section, in the scene file's order among the sections; or null, and
  void (*write)(const scene::Scene& scene, const scene::SectionTask& section, const std::any& outcome,
                SectionOutput& out);
  // writes every section of the rows that share this function at once, after the others, in the table's
  // order (the calibrations' table; the studies: "Other studies").
  void (*write_together)(const scene::Scene& scene, const std::vector<SectionResult>& sections,
                         SectionOutput& out);
};

const std::vector<SectionWriter>& section_writers();
// nullptr when no row has the name.
const SectionWriter* find_section_writer(std::string_view name);

}  // namespace restitution::cli
