// SPDX-License-Identifier: BSD-3-Clause
#include "scene/section_keys.hpp"

#include <fmt/core.h>

#include "restitution/calibration.hpp"
#include "restitution/errors.hpp"
#include "scene/toml_reader.hpp"

namespace restitution::scene::detail {

void check_eps(const TomlReader& r, const char* key, const std::vector<double>& values) {
  r.check_each(
      key, values, [](double e) { return e > 0.0 && e < 1.0; }, "a value in (0, 1)");
}

void check_positive(const TomlReader& r, const char* key, const std::vector<double>& values) {
  r.check_each(
      key, values, [](double v) { return v > 0.0; }, "a value > 0");
}

void check_zeta(const TomlReader& r, const std::vector<double>& zeta) {
  r.check_each(
      "zeta", zeta, [](double z) { return z >= 0.0 && z <= kLargestCheckedZeta; },
      fmt::format("0 <= zeta <= {:g} (the checked range)", kLargestCheckedZeta));
}

CollisionEnd read_end(TomlReader& r) {
  const auto w = r.text("end");
  if (!w) return CalibrationRequest{}.end;
  try {
    return end_from_name(*w);
  } catch (const InvalidInput& e) {
    r.fail("end", e.what());
  }
}

EndSet read_ends(TomlReader& r) {
  const auto words = r.words("ends");
  if (!words) return EndSet::both();
  EndSet ends;
  for (const std::string& w : *words) {
    try {
      ends = ends | end_set_from_name(w);
    } catch (const InvalidInput& e) {
      r.fail("ends", e.what());
    }
  }
  if (ends.empty()) r.fail("ends", "no end requested");
  return ends;
}

LawKind read_law(TomlReader& r) {
  const auto name = r.text("law");
  if (!name) return LawKind::viscoelastic_hertz;
  try {
    return law_from_name(*name);
  } catch (const InvalidInput& e) {
    r.fail("law", e.what());
  }
}

void check_law_zeta(TomlReader& r, LawKind law, EndSet ends, const std::vector<double>& zeta) {
  if (law == LawKind::viscoelastic_hertz || !ends.contains(CollisionEnd::naive)) return;
  r.check_each(
      "zeta", zeta, [law](double z) { return ContactLaw::natural(law, z).naive_end_may_exist(); },
      fmt::format("zeta < {:.17g}, where the naive end of {} exists (or ends = \"delayed-recovery\")",
                  naive_end_critical_zeta(law), law_name(law)));
}

}  // namespace restitution::scene::detail
