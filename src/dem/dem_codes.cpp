// SPDX-License-Identifier: BSD-3-Clause
// The table of DEM codes: adding one is its value of `Code`, its entry here with the include of its header,
// and its own files (docs/design.md, "A new DEM code").
#include "dem/dem_codes.hpp"

#include <fmt/core.h>

#include <stdexcept>

#include "dem/check_deck.hpp"
#include "dem/check_deck_codes.hpp"
#include "dem/deck_chrono.hpp"
#include "dem/deck_lammps.hpp"
#include "dem/deck_liggghts.hpp"
#include "dem/deck_mercurydpm.hpp"
#include "dem/deck_yade.hpp"
#include "restitution/errors.hpp"

namespace restitution::dem {
namespace {

// YADE's lines give their impacts at --angle; YADE takes kso from Y and nu, so no --target-et.
constexpr const char* kYadeObliqueRefusal =
    "--target-et, --reference-angle and --tangential are for --code lammps (or liggghts)";

CodeEntry lammps_entry() {
  return {.code = Code::lammps,
          .name = "lammps",
          .title = "LAMMPS",
          .always_clamps = false,
          .comment = "#",
          .program = "lmp",
          .version_query = "",
          .eps_conversion = false,
          .scene_runs = true,
          .write = &write_lammps,
          .read = &read_lammps,
          .polydisperse = &lammps_type_pair_lines,
          .one_radius_only = nullptr,
          .polydisperse_note =
              "pair_coeff I J: E and nu are the one (Y, nu) that LAMMPS mixes into the pair's E* (and, with "
              "friction, Mindlin's G*); for two materials an effective pair, not either material's",
          .check_deck = &lammps_family_check_deck,
          .check_deck_run = "lmp -in ",
          .check_deck_steps = 2000,
          .max_deck_collisions = kMaxDeckCollisionsLammps,
          .write_wall = &write_lammps_wall,
          .wall =
              "fix wall/gran granular reads hertz/material E nu as the modulus factor (4/3) E/(2 (1 - nu)) "
              "(fix_wall_gran.cpp:160), the pair as (4/3)/(2 (1 - nu^2)/E) (pair_granular.cpp:1008-1011, "
              "1780), and mindlin NULL as E (2 - nu)(1 + nu)/4 (line 248) against the pair's 8 G*; damping "
              "viscoelastic is eta_n0 m a on a wall (m the sphere's mass, a = sqrt(R delta)) as in a pair "
              "(m_eff): the wall lines carry E = 2 (1 - nu) E* and a numeric k_t",
          .check_deck_atom_style = "atom_style sphere\ncomm_modify vel yes\n",
          .immediate_variables = true,
          .velocity_verlet = true,
          .gas_deck = true,
          .companion = Companion::damping_tsuji,
          .companion_words = "damping tsuji",
          .oblique = ObliqueReader::lammps_granular,
          // |diff| <= 2e-7 on 1 mm steel at 2000 steps per contact.
          .oblique_check_steps = 2000,
          .tangential_refusal = nullptr,
          .inverse_refusal = nullptr};
}

CodeEntry liggghts_entry() {
  return {
      .code = Code::liggghts,
      .name = "liggghts",
      .title = "LIGGGHTS",
      .always_clamps = false,
      .comment = "#",
      .program = "liggghts",
      .version_query = "",
      .eps_conversion = false,
      .scene_runs = true,
      .write = &write_liggghts,
      .read = &read_liggghts,
      .polydisperse = &liggghts_type_pair_lines,
      .one_radius_only = nullptr,
      .polydisperse_note =
          "LIGGGHTS reads kn, kt, gamman, gammat and coefficientFriction per type pair (row I, column J); "
          "hertz/stiffness uses no youngsModulus or poissonsRatio",
      .check_deck = &lammps_family_check_deck,
      .check_deck_run = "liggghts -in ",
      .check_deck_steps = 2000,
      .max_deck_collisions = kMaxDeckCollisionsLammps,
      .write_wall = nullptr,
      .wall =
          "--wall does not support liggghts: its walls are meshes or primitives whose contact takes the "
          "wall's atom type in the per-type-pair kn and gamman (hertz/stiffness), not yet checked by a "
          "run here; use the type pair of the sphere's and the wall's types",
      // LIGGGHTS 3.8.0 reads LAMMPS's input but has no $(...): equal-style variables.
      .check_deck_atom_style = "atom_style granular\nnewton off\ncommunicate single vel yes\n",
      .immediate_variables = false,
      .velocity_verlet = true,
      .gas_deck = true,
      .companion = Companion::model_hertz,
      .companion_words = "model hertz coefficientRestitution",
      .oblique = ObliqueReader::liggghts_history,
      // LIGGGHTS decides stick or slip once per step, so its e_t is less smoothly first order: on the 1 mm
      // steel lines of docs/dem.md (six angles) the largest |diff| was 8.0e-6 at 2000 and 1.8e-6 at 10000
      // (its printed steps for e_t within 1e-4; glass 1.6e-6, steel at eps 0.98 4.2e-7).
      .oblique_check_steps = 10000,
      .tangential_refusal =
          "--tangential, --tangential-stiffness and --tangential-damping are for --code lammps: the "
          "liggghts "
          "lines carry one tangential model, `tangential history` with kt = 8 G* and gammat = gamman",
      .inverse_refusal = nullptr};
}

// MercuryDPM's BSHP species always clamps the normal force at zero.
CodeEntry mercurydpm_entry() {
  return {
      .code = Code::mercurydpm,
      .name = "mercurydpm",
      .title = "MercuryDPM",
      .always_clamps = true,
      .comment = "//",
      .program = "",
      .version_query = "",
      .eps_conversion = false,
      .scene_runs = false,
      .write = &write_mercurydpm,
      .read = &read_mercurydpm,
      .polydisperse = nullptr,
      .one_radius_only =
          "--code mercurydpm takes one radius: its species' E* and A do not depend on size or mass, so the "
          "one-radius lines are already exact for every size of one material; two materials need a mixed "
          "species per material pair, which restitution does not print",
      .polydisperse_note = "",
      .check_deck = nullptr,
      .check_deck_run = "",
      .check_deck_steps = 0,
      .max_deck_collisions = 0,
      .write_wall = nullptr,
      .wall =
          "--wall does not support mercurydpm: a wall shares the particles' species, whose E* and A do "
          "not depend on mass or radius; no wall convention of its own is checked here",
      .check_deck_atom_style = nullptr,
      .immediate_variables = false,
      .velocity_verlet = false,
      .gas_deck = false,
      .companion = Companion::none,
      .companion_words = nullptr,
      .oblique = ObliqueReader::none,
      .oblique_check_steps = 0,
      .tangential_refusal = nullptr,
      .inverse_refusal = nullptr};
}

// YADE's Mindlin law always clamps; its Tsuji-type damping converges more slowly in dt (5000 coarse
// steps per natural time).
CodeEntry yade_entry() {
  return {
      .code = Code::yade,
      .name = "yade",
      .title = "YADE",
      .always_clamps = true,
      .comment = "#",
      .program = "yade",
      .version_query = "yade --version",
      .eps_conversion = true,
      .scene_runs = false,
      .write = &write_yade,
      .read = &read_yade,
      .polydisperse = nullptr,
      .one_radius_only =
          "--code yade takes one radius: YADE turns (en, vn) into one beta per material pair and gives "
          "every "
          "contact that beta, so sizes with another k_n0/m_eff get another eps(v) (and YADE 2023.02a cannot "
          "express the law at all); use lammps or liggghts for several sizes",
      .polydisperse_note = "",
      .check_deck = &yade_check_deck,
      .check_deck_run = "yade -n -x ",
      .check_deck_suffix = ".py",
      .check_deck_steps = 5000,
      .max_deck_collisions = kMaxDeckCollisionsYade,
      .write_wall = nullptr,
      .wall =
          "--wall does not support yade: a wall is a body with its own material and the same Ip2 as two "
          "spheres (no run checked here)",
      .check_deck_atom_style = nullptr,
      .immediate_variables = false,
      .velocity_verlet = false,
      .gas_deck = false,
      .companion = Companion::none,
      .companion_words = nullptr,
      .oblique = ObliqueReader::yade_mindlin,
      // Its first-order rest is still 1.1e-5 at 2000 (1 mm steel at 60 deg; dem/oblique_check_deck.hpp).
      .oblique_check_steps = 20000,
      .tangential_refusal = kYadeObliqueRefusal,
      .inverse_refusal = kYadeObliqueRefusal};
}

// Chrono's SMC contact always clamps.
CodeEntry chrono_entry() {
  return {
      .code = Code::chrono,
      .name = "chrono",
      .title = "Chrono",
      .always_clamps = true,
      .comment = "//",
      .program = "",
      .version_query = "",
      .eps_conversion = false,
      .scene_runs = false,
      .write = &write_chrono,
      .read = &read_chrono,
      .polydisperse = nullptr,
      .one_radius_only =
          "--code chrono takes one radius: Kn and Gn belong to each body's material and Chrono combines two "
          "bodies' values into a contact's, so the R_eff and m_eff they contain cannot be set per pair of "
          "sizes; use lammps or liggghts for several sizes",
      .polydisperse_note = "",
      .check_deck = nullptr,
      .check_deck_run = "",
      .check_deck_steps = 0,
      .max_deck_collisions = 0,
      .write_wall = nullptr,
      .wall =
          "--wall does not support chrono: a wall is a body whose material Chrono combines with the "
          "sphere's (no run checked here)",
      .check_deck_atom_style = nullptr,
      .immediate_variables = false,
      .velocity_verlet = false,
      .gas_deck = false,
      .companion = Companion::none,
      .companion_words = nullptr,
      .oblique = ObliqueReader::none,
      .oblique_check_steps = 0,
      .tangential_refusal = nullptr,
      .inverse_refusal = nullptr};
}

}  // namespace

const std::vector<CodeEntry>& dem_codes() {
  static const std::vector<CodeEntry> table = {lammps_entry(), liggghts_entry(), mercurydpm_entry(),
                                               yade_entry(), chrono_entry()};
  return table;
}

const CodeEntry& code_entry(Code code) {
  for (const CodeEntry& e : dem_codes()) {
    if (e.code == code) return e;
  }
  throw std::logic_error(fmt::format("DEM code {} has no entry", static_cast<int>(code)));
}

Code code_from_name(std::string_view name) {
  for (const CodeEntry& e : dem_codes()) {
    if (name == e.name) return e.code;
  }
  throw InvalidInput(fmt::format("code must be {}, got '{}'", code_list(" or "), std::string(name)));
}

const char* code_name(Code code) {
  return code_entry(code).name;
}

bool always_clamps(Code code) {
  return code_entry(code).always_clamps;
}

std::vector<std::string> code_names(bool (*keep)(const CodeEntry&)) {
  std::vector<std::string> names;
  for (const CodeEntry& e : dem_codes()) {
    if (keep == nullptr || keep(e)) names.emplace_back(e.name);
  }
  return names;
}

std::string code_list(std::string_view last, bool (*keep)(const CodeEntry&)) {
  const std::vector<std::string> names = code_names(keep);
  std::string text;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i > 0) text += i + 1 == names.size() ? std::string(last) : std::string(", ");
    text += names[i];
  }
  return text;
}

}  // namespace restitution::dem
