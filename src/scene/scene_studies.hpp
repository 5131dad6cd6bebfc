// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A scene's [[stability]] and [[work_precision]] sections: studies whose engines live in other modules (the
// stability report at the given ζ values; the work-precision measurement, every tolerance each engine
// accepts on the reference grid's fixed ζ set). scene_extensions.hpp runs them; the CLI words them together
// under "Other studies" (cli/scene/scene_text.cpp).
#include <string>
#include <vector>

#include "restitution/collision_solver.hpp"

namespace restitution::scene {

struct ExternalStudy {
  std::string kind;  // "work_precision" | "stability"
  std::string name;
  std::vector<double> zeta;  // stability: the points
  // work_precision: engines measured (work_precision_engines() names)
  std::vector<std::string> engines = {method_name(Method::taylor), method_name(Method::adams),
                                      method_name(Method::bdf)};
  int repeats = 3;  // work_precision: timed solves per point (the median is kept)
  int line = 0;
};
inline constexpr int kMaxStudyRepeats = 100;  // = kMaxWorkPrecisionRepeats (reference/work_precision.hpp)

namespace detail {
class TomlReader;
// Reads the keys of one study of `kind` (name already read). Throws InvalidInput naming the key.
ExternalStudy read_study_task(TomlReader& r, const char* kind, std::string name);
}  // namespace detail

}  // namespace restitution::scene
