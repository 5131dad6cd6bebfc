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

const std::vector<CodeEntry>& dem_codes() {
  static const std::vector<CodeEntry> table = {
      {Code::lammps, "lammps", false, "#", "lmp", "", false, true, &write_lammps, &read_lammps,
       &lammps_type_pair_lines, nullptr,
       "pair_coeff I J: E and nu are the one (Y, nu) that LAMMPS mixes into the pair's E* (and, with "
       "friction, Mindlin's G*); for two materials an effective pair, not either material's",
       &lammps_family_check_deck, "lmp -in ", 2000, kMaxDeckCollisionsLammps},
      {Code::liggghts, "liggghts", false, "#", "liggghts", "", false, true, &write_liggghts, &read_liggghts,
       &liggghts_type_pair_lines, nullptr,
       "LIGGGHTS reads kn, kt, gamman, gammat and coefficientFriction per type pair (row I, column J); "
       "hertz/stiffness uses no youngsModulus or poissonsRatio",
       &lammps_family_check_deck, "liggghts -in ", 2000, kMaxDeckCollisionsLammps},
      {Code::mercurydpm, "mercurydpm", true, "//", "", "", false, false, &write_mercurydpm, &read_mercurydpm,
       nullptr,
       "--code mercurydpm takes one radius: its species' E* and A do not depend on size or mass, so the "
       "one-radius lines are already exact for every size of one material; two materials need a mixed "
       "species per material pair, which restitution does not print",
       "", nullptr, "", 0, 0},
      // YADE's Tsuji-type damping converges more slowly in dt: 5000 coarse steps per natural time.
      {Code::yade, "yade", true, "#", "yade", "yade --version", true, false, &write_yade, &read_yade, nullptr,
       "--code yade takes one radius: YADE turns (en, vn) into one beta per material pair and gives every "
       "contact that beta, so sizes with another k_n0/m_eff get another eps(v) (and YADE 2023.02a cannot "
       "express the law at all); use lammps or liggghts for several sizes",
       "", &yade_check_deck, "yade -n -x ", 5000, kMaxDeckCollisionsYade},
      {Code::chrono, "chrono", true, "//", "", "", false, false, &write_chrono, &read_chrono, nullptr,
       "--code chrono takes one radius: Kn and Gn belong to each body's material and Chrono combines two "
       "bodies' values into a contact's, so the R_eff and m_eff they contain cannot be set per pair of "
       "sizes; use lammps or liggghts for several sizes",
       "", nullptr, "", 0, 0},
  };
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
