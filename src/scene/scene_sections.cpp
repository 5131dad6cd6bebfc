// SPDX-License-Identifier: BSD-3-Clause
#include "scene/scene_sections.hpp"

#include "scene/scene_adhesion.hpp"
#include "scene/scene_adhesion_run.hpp"
#include "scene/scene_oblique.hpp"
#include "scene/scene_oblique_run.hpp"

namespace restitution::scene {
namespace {

// Each row's functions take the kind's own task type out of the std::any and put its outcome in one.
template <class Task, auto read, auto compute>
SectionKind row(const char* name, void (*quick)(std::any&, std::size_t), const char* own_solves) {
  return {name, [](detail::TomlReader& r, const SectionContext& c) -> std::any { return read(r, c); },
          [](const Scene& scene, const std::any& task) -> std::any {
            return compute(scene, std::any_cast<const Task&>(task));
          },
          quick, own_solves};
}

ObliqueTask read_oblique(detail::TomlReader& r, const SectionContext& c) {
  return detail::read_oblique_task(r, c.name, c.materials, c.warnings);
}

AdhesionTask read_adhesion(detail::TomlReader& r, const SectionContext& c) {
  return detail::read_adhesion_task(r, c.name, c.materials);
}

void keep_all(std::any& /*task*/, std::size_t /*points*/) {}

}  // namespace

const std::vector<SectionKind>& section_kinds() {
  static const std::vector<SectionKind> kinds = {
      // Angles and spins are few, and Maw's diagram needs them: --quick keeps them all.
      row<ObliqueTask, read_oblique, run_oblique_section>(
          "oblique", keep_all, "the [[oblique]] sections integrate their own impacts"),
      row<AdhesionTask, read_adhesion, run_adhesion_section>(
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
