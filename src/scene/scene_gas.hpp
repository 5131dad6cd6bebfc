// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A scene's [[gas]] section (docs/scenes.md, docs/gas.md): its keys read through the gas study's table
// (restitution_gas/gas_parameters.hpp), and the section computed as `restitution gas` computes it: the
// cooling curve of the material's spheres with the law's eps(v) beside Haff's law, or the driven gas's
// relaxation and steady state. Typed values; the CLI writes the CSV, the plot and the words.
#include <map>
#include <optional>
#include <string>

#include "restitution_gas/cooling.hpp"
#include "restitution_gas/driven.hpp"
#include "restitution_gas/gas_inputs.hpp"
#include "scene/scene.hpp"

namespace restitution::scene {

// The freely cooling or driven gas of a material's spheres from kinetic theory (docs/gas.md): T(t) and the
// local exponent of the law's eps(v) beside Haff's law of a constant eps. The keys are the gas study's table
// (restitution_gas/gas_parameters.hpp) but for the spheres', which come from the material when it runs.
struct GasTask {
  std::string name;
  std::string title;
  std::string material;  // a [materials.X]: radius, density or mass (and A without eps)
  gas::GasInputs inputs;
  bool own_tolerance = false;  // false: the scene's tolerance, as run (--quick loosens it), not inputs'
  int line = 0;
};

struct GasOutcome {
  gas::CoolingRequest request;
  gas::CoolingCurve curve;
  std::optional<gas::Thermostat> thermostat;  // the driven gas's, with its steady state
  std::optional<gas::SteadyState> steady;
};

// Throws InvalidInput naming the scene, the section and the problem when the gas cannot be computed.
GasOutcome run_gas_section(const Scene& scene, const GasTask& task);

namespace detail {
class TomlReader;
// Reads every key of the table that a scene gives (not the spheres': the material's) into `inputs`, with the
// table's ranges and pairs. Throws InvalidInput naming the key.
void read_gas_keys(TomlReader& r, gas::GasInputs& inputs);
// Reads one [[gas]] (name already read): title, material, then the table's keys (scene_gas_task.cpp).
GasTask read_gas_task(TomlReader& r, std::string name, const std::map<std::string, Material>& materials);
}  // namespace detail

}  // namespace restitution::scene
