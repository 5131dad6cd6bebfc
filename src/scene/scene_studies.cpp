// SPDX-License-Identifier: BSD-3-Clause
#include "scene/scene_studies.hpp"

#include <fmt/core.h>

#include <cmath>

#include "reference/work_precision.hpp"
#include "scene/section_keys.hpp"
#include "scene/toml_reader.hpp"

namespace restitution::scene::detail {
namespace {

// Engines (names of work_precision_engines()) and repeats; the ζ set is the reference grid's.
void read_work_precision(TomlReader& r, ExternalStudy& s) {
  if (const auto engines = r.words("engines")) {
    for (const std::string& name : *engines) {
      if (!is_work_precision_engine(name))
        r.fail("engines",
               fmt::format("unknown engine \"{}\" (known: {})", name, work_precision_engine_names()));
    }
    if (engines->empty()) r.fail("engines", "expected at least one engine");
    s.engines = *engines;
  }
  if (const auto repeats = r.number("repeats")) {
    if (*repeats != std::floor(*repeats) || *repeats < 1 || *repeats > kMaxStudyRepeats)
      r.fail("repeats", fmt::format("expected a whole number in [1, {}]", kMaxStudyRepeats));
    s.repeats = static_cast<int>(*repeats);
  }
}

}  // namespace

ExternalStudy read_study_task(TomlReader& r, const char* kind, std::string name) {
  ExternalStudy s;
  s.kind = kind;
  s.line = r.line();
  s.name = std::move(name);
  if (s.kind == "work_precision") {
    read_work_precision(r, s);
    return s;
  }
  if (const auto zeta = r.numbers("zeta")) {
    check_zeta(r, *zeta);
    s.zeta = *zeta;
  }
  return s;
}

}  // namespace restitution::scene::detail
