// SPDX-License-Identifier: BSD-3-Clause
#include "scene/scene_fit.hpp"

#include <fmt/core.h>

#include <filesystem>

#include "restitution/errors.hpp"
#include "restitution/fit.hpp"
#include "scene/scene.hpp"
#include "scene/scene_inputs.hpp"
#include "scene/toml_reader.hpp"

namespace restitution::scene {

FitOutcome run_fit_section(const Scene& scene, const FitTask& task) {
  FitOutcome out;
  out.options.candidates = task.candidates;
  out.options.tolerance = scene.tolerance;
  out.options.method = scene.method;
  if (task.material) out.options.k = elastic_constants(scene.materials.at(*task.material)).k;
  out.result = fit_data(task.data, out.options);
  return out;
}

namespace detail {

FitTask read_fit_task(TomlReader& r, std::string name, const std::map<std::string, Material>& materials) {
  FitTask t;
  t.line = r.line();
  t.name = std::move(name);
  t.title = r.text("title").value_or(t.name);
  t.note = r.text("note").value_or("");
  if (const auto label = r.text("data_label")) {
    if (label->empty()) r.fail("data_label", "empty: say what the data points are (default \"measured\")");
    t.data_label = *label;
  }
  const auto file = r.text("data");
  auto v = r.numbers("v");
  auto eps = r.numbers("eps");
  auto sigma = r.numbers("sigma");
  if (file) {
    if (v || eps || sigma) r.fail("data", "give either a data file or inline v, eps (and sigma), not both");
    // Relative to the scene file, so a scene and its data move together; within the scene's folder, since
    // a scene may come from someone else (scene_inputs.hpp). A regular file only, never a device, a FIFO or
    // the machine's /proc.
    const std::filesystem::path path = contained_input(r, "data", *file);
    t.source = *file;
    t.data = read_fit_csv(path, FitCsvSource::regular_file);
  } else {
    if (!v || !eps) r.fail(v ? "eps" : "v", "missing: give data = \"file.csv\" or the lists v and eps");
    t.source = "inline";
    t.data = {*v, *eps, sigma.value_or(std::vector<double>{})};
  }
  try {
    check_fit_data(t.data);
  } catch (const InvalidInput& e) {
    r.fail(file ? "data" : "eps", e.what());
  }
  try {
    t.candidates =
        fit_candidates(r.words("laws").value_or(std::vector<std::string>{}),
                       r.text("speed_independent_end").value_or(end_name(kDefaultSpeedIndependentEnd)));
  } catch (const InvalidInput& e) {
    r.fail("laws", e.what());
  }
  if (t.candidates.empty()) r.fail("laws", "empty: leave the key out for every law");
  t.material = r.text("material");
  if (t.material && !materials.contains(*t.material)) {
    r.fail("material", fmt::format("no [materials.{}] in this scene", *t.material));
  }
  t.reference_characteristic_velocity_m_s = r.number("reference_characteristic_velocity");
  if (t.reference_characteristic_velocity_m_s && !(*t.reference_characteristic_velocity_m_s > 0.0)) {
    r.fail("reference_characteristic_velocity", "expected a speed > 0 in m/s");
  }
  return t;
}

}  // namespace detail
}  // namespace restitution::scene
