// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The head-on collision's parameters that `restitution eps` and `restitution sweep` share, declared once: one
// row per field of HeadOnInputs with its name, member, unit, check and help
// (restitution/parameter_table.hpp). The commands' options are made from these rows (the name with dashes:
// --young-modulus) and a scene's
// [[sweep]] reads its `law` key from its row. What only one command has, or what the two word differently
// (eps's --zeta, --beta, --velocity, --damping-ratio; sweep's ranges, --beta, --stiffness, ...; --json,
// --out, --threads, --resume), stays the command's. A new shared parameter is a member here, a row in
// src/solver/head_on_parameters.cpp and its use in the commands.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "restitution/collision_solver.hpp"
#include "restitution/contact_law.hpp"
#include "restitution/parameter_table.hpp"
#include "restitution/solve_types.hpp"

namespace restitution {

struct HeadOnInputs {
  std::string law = law_name(LawKind::viscoelastic_hertz);
  std::string end = kBothEnds;  // an end's name or "both" (end_set_names())
  double tolerance = SolveOptions{}.tolerance;
  std::string method = method_name(SolveOptions{}.method);
  // The material (Material, without dissipation): a scene's comes from its [materials.X].
  std::optional<double> young_modulus_pa, poisson_ratio, radius_m, radius2_m, density_kg_m3, mass_kg,
      mass2_kg;
  [[nodiscard]] bool any_material() const {
    return young_modulus_pa || poisson_ratio || radius_m || radius2_m || density_kg_m3 || mass_kg || mass2_kg;
  }
};

using HeadOnField = ParameterField<HeadOnInputs>;

// The fields: law, end, tolerance, method, then the material's.
const std::vector<HeadOnField>& head_on_fields();
// The field of this name; throws std::out_of_range for a name the table lacks.
const HeadOnField& head_on_field(std::string_view name);

// The solve options the inputs name (end set, tolerance, method); throws InvalidInput for an unknown name.
SolveOptions solve_options_of(const HeadOnInputs& in);

// "bdf, adams (NOTE), auto (NOTE) or taylor (NOTE)": every method of kMethods, each followed by what
// `note` says of it (const char*; "" says nothing), so that a new method appears in every method help.
template <typename Note>
std::string method_choices(Note note) {
  std::vector<std::string> items;
  for (const Method method : kMethods) {
    const std::string said = note(method);
    items.push_back(said.empty() ? std::string(method_name(method))
                                 : std::string(method_name(method)) + " (" + said + ")");
  }
  return alternatives(items);
}

}  // namespace restitution
