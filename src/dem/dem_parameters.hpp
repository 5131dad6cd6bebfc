// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The DEM-lines study's parameters declared once: one row per field of DemInputs with its name, member, unit,
// check and help (restitution/parameter_table.hpp). The front ends are made from this table: the options of
// `restitution dem` (the name with dashes: --impact-velocity) and the keys of a scene's [[dem]] section (the
// row's key: speeds). The material is no row: the command takes its lists of atom types (--radius ...), a
// scene a [materials.X], whose A is the row dissipative_constant. What only one front end has (the command's
// --deck, --json, --wall, --yade-version, ...; the scene's `run`) stays that front end's. A new parameter is
// a member of DemInputs, a row here and its use in request_of.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "dem/dem_codes.hpp"
#include "dem/lines_check.hpp"
#include "restitution/parameter_table.hpp"
#include "restitution/solve_types.hpp"

namespace restitution::dem {

struct DemInputs {
  std::string code;                              // a DEM code's name (code_names())
  std::optional<double> eps;                     // with velocity_m_s: A calibrated to this ε
  std::optional<double> velocity_m_s;            // the calibration speed (YADE's vn; default 1 m/s)
  std::optional<double> dissipative_constant_s;  // A [s]; a scene's comes from its material
  std::string end = end_name(CollisionEnd::delayed_recovery);
  std::vector<double> speeds_m_s;        // impact speeds to report ε at; the command's default v/10, v, 10 v
  double tolerance = kDefaultTolerance;  // a scene's is the scene's own
  double friction = 0.0;                 // Coulomb mu of the tangential model [1]
};

using DemField = ParameterField<DemInputs>;

// The fields in the order the command's help lists them (and a scene reads its keys in).
const std::vector<DemField>& dem_fields();
// The field of this name; throws std::out_of_range for a name the table lacks.
const DemField& dem_field(std::string_view name);

inline DampingSource damping_of(const DemInputs& in) {
  return {in.dissipative_constant_s, in.eps, in.velocity_m_s};
}

// A request of the study (LinesRequest, WallRequest, PolydisperseRequest) with what the inputs give: the
// code, the end, the damping, the speeds, the accuracy and friction. Throws InvalidInput for an unknown code
// or end, in that order.
template <class Request>
Request request_of(const DemInputs& in) {
  Request r;
  r.code = code_from_name(in.code);
  r.end = end_from_name(in.end);
  r.damping = damping_of(in);
  r.speeds_m_s = in.speeds_m_s;
  r.tolerance = in.tolerance;
  r.friction = in.friction;
  return r;
}

}  // namespace restitution::dem
