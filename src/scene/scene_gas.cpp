// SPDX-License-Identifier: BSD-3-Clause
#include "scene/scene_gas.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "restitution/errors.hpp"
#include "restitution/material.hpp"
#include "restitution_gas/gas_parameters.hpp"
#include "scene/parameter_keys.hpp"
#include "scene/toml_reader.hpp"

namespace restitution::scene {
namespace {

// `a2 = 0.02`, "haff" or "evolving", in the words of `gas --a2` (the library checks the number's range).
void read_sonine_a2(detail::TomlReader& r, const gas::GasField& f, gas::GasInputs& in) {
  const toml::node* node = r.take(f.name);
  if (node->is_number()) {
    in.a2 = *r.number(f.name);
    return;
  }
  const auto* word = node->as_string();
  if (word == nullptr || std::find(f.words.begin(), f.words.end(), word->get()) == f.words.end()) {
    r.fail(f.name, "a number, \"haff\" (van Noije & Ernst's a2 of the Haff eps) or \"evolving\" (a2(t))");
  }
  gas::set_sonine_word(in, word->get());
}

// The section's inputs with the material's spheres (and its A when the section gives no eps).
gas::GasInputs inputs_of(const Scene& scene, const GasTask& task) {
  const Material& m = scene.materials.at(task.material);
  if (m.radius1_m != m.radius2_m || (m.mass1_kg && m.mass1_kg != m.mass2_kg)) {
    throw InvalidInput(fmt::format("material: [materials.{}] has two sizes; the gas is of one (monodisperse)",
                                   task.material));
  }
  gas::GasInputs in = task.inputs;
  if (!task.own_tolerance) in.tolerance = scene.tolerance;
  in.radius_m = m.radius1_m;
  in.density_kg_m3 = m.density_kg_m3;
  if (!m.density_kg_m3) in.mass_kg = m.mass1_kg;
  in.young_modulus_pa = m.young_modulus_pa;
  in.poisson_ratio = m.poisson_ratio;
  if (!in.eps) in.dissipative_constant_s = material_constants(m).dissipative_constant_s;
  return in;
}

}  // namespace

void detail::read_gas_keys(TomlReader& r, gas::GasInputs& in) {
  // The spheres' fields are no keys (from [materials.X] when the section runs); a2 is a number or a word.
  for (const gas::GasField& f : gas::gas_fields()) {
    if (!read_parameter_key(r, f, in) && f.kind == gas::FieldKind::number_or_word && r.has(f.name)) {
      read_sonine_a2(r, f, in);
    }
  }
  check_parameter_groups(r, gas::gas_fields(), gas::gas_field_groups(), in);
}

GasOutcome run_gas_section(const Scene& scene, const GasTask& task) {
  GasOutcome out;
  try {
    // The command's spelling in messages: one path to the request for both (--tolerance, ...).
    const gas::GasInputs inputs = inputs_of(scene, task);
    out.request = gas::cooling_request(inputs, gas::ArgumentStyle::option);
    out.thermostat = gas::thermostat_of(inputs, gas::ArgumentStyle::option);
    if (out.thermostat) {
      gas::DrivenCurve driven = gas::driven_curve({out.request, *out.thermostat});
      out.curve = std::move(driven.curve);
      out.steady = driven.steady;
    } else {
      out.curve = gas::cooling_curve(out.request);
    }
  } catch (const InvalidInput& e) {
    throw InvalidInput(fmt::format("{}: gas \"{}\": {}", scene.file_name, task.name, e.what()));
  }
  return out;
}

}  // namespace restitution::scene
