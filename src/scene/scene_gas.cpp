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

void read_word(detail::TomlReader& r, const gas::GasField& f, gas::GasInputs& in) {
  const auto word = r.text(f.name);
  if (!word) return;
  try {
    f.check_word(*word);
  } catch (const InvalidInput& e) {
    r.fail(f.name, e.what());
  }
  in.*f.word = *word;
}

void read_number(detail::TomlReader& r, const gas::GasField& f, gas::GasInputs& in) {
  std::optional<double> value = r.number(f.name);
  if (!value && f.required) r.fail(f.name, fmt::format("missing: {}", f.required));
  if (f.kind == gas::FieldKind::number && !value) value = in.*f.number;  // the default is checked too
  if (value && f.range) {
    const bool whole = f.kind == gas::FieldKind::whole_number;
    r.check_each(
        f.name, {*value}, [&](double v) { return f.range->contains(v) && (!whole || v == std::floor(v)); },
        f.range->text);
  }
  if (!value) return;
  if (f.kind == gas::FieldKind::optional_number) in.*f.optional_number = value;
  if (f.kind == gas::FieldKind::number) in.*f.number = *value;
  if (f.kind == gas::FieldKind::whole_number) in.*f.whole_number = static_cast<int>(*value);
}

bool given(const gas::GasInputs& in, const char* name) {
  return (in.*gas::gas_field(name).optional_number).has_value();
}

void check_groups(const detail::TomlReader& r, const gas::GasInputs& in) {
  for (const gas::FieldGroup& g : gas::gas_field_groups()) {
    const bool first = given(in, g.first);
    const bool second = given(in, g.second);
    if (g.rule == gas::FieldGroup::together && first != second) r.fail(first ? g.first : g.second, g.message);
    if (g.rule == gas::FieldGroup::exactly_one && first == second) r.fail(g.first, g.message);
  }
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
  for (const gas::GasField& f : gas::gas_fields()) {
    if (f.from_material) continue;  // the spheres' fields: from [materials.X] when the section runs
    switch (f.kind) {
      case gas::FieldKind::word:
      case gas::FieldKind::optional_word:
        read_word(r, f, in);
        break;
      case gas::FieldKind::number_or_word:
        if (r.has(f.name)) read_sonine_a2(r, f, in);
        break;
      default:
        read_number(r, f, in);  // also refuses a required key's absence and checks a default's range
    }
  }
  check_groups(r, in);
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
