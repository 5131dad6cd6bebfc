// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The steel beads the DEM tests collide (tests/dem/), and `restitution ... --json` run for them.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <string>

#include "cli_runner.hpp"
#include "dem/deck.hpp"
#include "restitution/material.hpp"

namespace restitution::test_support {

constexpr double kYoungPa = 2.1e11, kPoisson = 0.3, kRadiusM = 0.005, kDensity = 7850.0;

inline dem::Pair steel() {
  Material material;
  material.young_modulus_pa = kYoungPa;
  material.poisson_ratio = kPoisson;
  material.radius1_m = material.radius2_m = kRadiusM;
  material.density_kg_m3 = kDensity;
  return dem::pair_of(material);
}

// The JSON the CLI prints for `arguments`, expecting exit status 0.
inline nlohmann::json run_json(const std::string& arguments) {
  const auto r = run_cli(arguments);
  EXPECT_EQ(r.status, 0) << arguments << ": " << r.err;
  return nlohmann::json::parse(r.out);
}

}  // namespace restitution::test_support
