// SPDX-License-Identifier: BSD-3-Clause
#include "scene/scene_sections.hpp"

#include "scene/scene_adhesion.hpp"
#include "scene/scene_adhesion_run.hpp"

namespace restitution::scene {
namespace {

// Each row's functions take the kind's own task type out of the std::any and put its outcome in one.
template <class Task, auto read, auto compute>
SectionKind row(const char* name, void (*quick)(std::any&, std::size_t), const char* own_solves) {
  return {
      name,
      [](detail::TomlReader& r, const SectionContext& c) -> std::any { return read(r, c.name, c.materials); },
      [](const Scene& scene, const std::any& task) -> std::any {
        return compute(scene, std::any_cast<const Task&>(task));
      },
      quick, own_solves};
}

}  // namespace

const std::vector<SectionKind>& section_kinds() {
  static const std::vector<SectionKind> kinds = {
      row<AdhesionTask, detail::read_adhesion_task, run_adhesion_section>(
          "adhesion",
          [](std::any& task, std::size_t points) {
            thin_values(std::any_cast<AdhesionTask&>(task).speeds_m_s, points);
          },
          "the [[adhesion]] sections integrate their own collisions"),
  };
  return kinds;
}

const SectionKind* find_section_kind(std::string_view name) {
  for (const SectionKind& kind : section_kinds()) {
    if (name == kind.name) return &kind;
  }
  return nullptr;
}

}  // namespace restitution::scene
