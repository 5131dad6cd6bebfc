// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Scene files: what to compute, on what, how accurately and where to write (TOML; format in README.md and
// scenes/*.toml). This header holds the parsed scene as plain values and the parser; planning and running
// are in scene_plan.hpp and scene_run.hpp. The parser validates everything it can: unknown keys, wrong
// types and out-of-range values throw InvalidInput naming the file, the line and the key.
#include <any>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "restitution/calibration.hpp"
#include "restitution/collision_solver.hpp"
#include "restitution/material.hpp"
#include "restitution/series.hpp"

namespace restitution::scene {

// Columns a sweep table can hold (every requested end gets its own columns).
struct Quantities {
  bool eps = true;
  bool one_minus_eps = true;
  bool duration = true;         // τ_c (and seconds for a material)
  bool max_compression = true;  // time and size of maximal compression (and SI for a material)
};

// An empirical law ε = coefficient · (v / velocity_unit_m_s)^exponent to compare with (the 1999 paper's
// ice fit: coefficient 0.32, exponent -0.234, v in cm/s).
struct EmpiricalLaw {
  double coefficient = 0.0;
  double exponent = 0.0;
  double velocity_unit_m_s = 1.0;
};

// A power-law fit ε ≈ a ζ^p over ζ >= zeta_min (the asymptotics module).
struct PowerLawFitRequest {
  double zeta_min = 0.0;
};

enum class Axes { linear, log_log, log_x };

// ε tables over ζ (the natural form of any member of the family), or, for viscoelastic Hertz, over impact
// speeds with β, a material or the 1999 paper's g*.
struct Sweep {
  LawKind law = LawKind::viscoelastic_hertz;
  std::string name;
  std::string title;
  std::string note;  // free text for the report: what to look for
  EndSet ends = EndSet::both();
  Quantities quantities;
  std::vector<double> zeta;          // the variable when no velocity is given
  std::vector<double> velocity_m_s;  // the variable with beta, material or characteristic_velocity
  std::optional<double> beta;        // s^{1/5} m^{-1/5}
  std::optional<std::string> material;
  std::optional<double> characteristic_velocity_m_s;  // 1999 paper's g*
  // Approximations to evaluate beside the numerics (`approximations = [...]`, names as in
  // src/scene/scene_approximations.hpp; `compare_series = true` adds the 2008 series of every requested end).
  std::vector<series::Approximation> approximations;
  std::optional<EmpiricalLaw> empirical;
  std::optional<PowerLawFitRequest> fit;
  bool asymptotics = false;  // the derived large-ζ laws of both ends (asymptotics module) as columns
  Axes axes = Axes::linear;
  int line = 0;  // where the [[sweep]] starts, for messages
};

// One collision with its trajectory x, x', x'' (the 2008 paper's Fig. 3).
struct Trajectory {
  LawKind law = LawKind::viscoelastic_hertz;
  std::string name;
  std::string title;
  EndSet ends = EndSet::both();
  std::optional<double> zeta;
  std::optional<double> velocity_m_s;
  std::optional<double> beta;
  std::optional<std::string> material;
  int line = 0;
};

struct CalibrationTask {
  LawKind law = LawKind::viscoelastic_hertz;  // β, g* and A for viscoelastic Hertz only
  std::string name;
  double eps = 0.0;
  double velocity_m_s = 0.0;
  CollisionEnd end = CollisionEnd::delayed_recovery;
  std::optional<std::string> material;
  int line = 0;
  int eps_line = 0;  // of the eps key: its range is known only when the calibration runs
  std::string path;  // "calibration[i]", as the parser names it: the run step's refusal names it so too
};

// The linear dash-pot against its closed forms (2008 paper Eqs. 10 and 12): an exact check.
struct DashpotCheck {
  std::string name;
  std::string title;
  EndSet ends = EndSet::both();
  std::vector<double> damping_ratio;
  int line = 0;
};

// A section of a kind in the table of scene_sections.hpp: its task, of the kind's own type.
struct SectionTask {
  std::string kind;  // the row's name, [[kind]] in the file
  std::string name;
  int line = 0;  // where the section starts
  std::any task;
};

struct Scene {
  std::string file_name;
  std::string title;
  std::string description;
  std::filesystem::path output;  // as written in the file (relative paths: to the working directory)
  double tolerance = SolveOptions{}.tolerance;
  Method method = SolveOptions{}.method;
  std::vector<std::string> figure_formats{"png"};  // `format`: each figure in each (figure_formats.hpp)
  std::map<std::string, Material> materials;
  std::vector<std::string> warnings;  // a key read by its old name, each naming the new one
  // Every section, of a kind of the table (scene_sections.hpp: the planner's [[sweep]], [[trajectory]],
  // [[calibration]], [[dashpot]], then [[dem]], [[damping_check]], [[gas]], [[oblique]], [[adhesion]],
  // [[fit]],
  // [[work_precision]], [[stability]]), by kind in the table's order, each kind's in file order.
  std::vector<SectionTask> sections;
};

// Parses and validates a scene. file_name is used in messages only. Throws InvalidInput.
Scene parse_scene(std::string_view toml_text, std::string_view file_name);

// Reads the file and parses it. Throws InvalidInput naming the file when it cannot be read.
Scene load_scene(const std::filesystem::path& path);

// Caps every section's ranges at `points` values (first and last kept; each row says which) and times each
// work-precision point once: CI's small settings.
void make_quick(Scene& scene, std::size_t points);
// Keeps `points` of the values, spread evenly, the first and the last among them (points < 2: all).
void thin_values(std::vector<double>& values, std::size_t points);

}  // namespace restitution::scene
