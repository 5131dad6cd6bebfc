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

}  // namespace restitution::scene::detail
