// SPDX-License-Identifier: BSD-3-Clause
// The table of tangential models (src/oblique/tangential_models.cpp): every row whole, the names unique and
// round-tripping, and the front ends taking their names and units from it (the command line's help and
// choices, a scene's stiffness keys).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <set>
#include <string>
#include <string_view>

#include "cli_runner.hpp"
#include "dem/dem_codes.hpp"
#include "oblique/tangential_models.hpp"
#include "restitution/errors.hpp"
#include "restitution/solve_types.hpp"

namespace {

using namespace restitution;
using namespace restitution::oblique;
using namespace restitution::test_support;

bool filled(const char* text) {
  return text != nullptr && *text != '\0';
}

TEST(TangentialModels, RowsFollowTheEnumAndAreWhole) {
  const ContactModuli steel{2e11 / (2.0 * (1.0 - 0.09)), 2e11 / (4.0 * 1.7 * 1.3), 5e-4};
  std::size_t index = 0;
  for (const TangentialModel& m : tangential_models()) {
    SCOPED_TRACE(m.name);
    EXPECT_EQ(static_cast<std::size_t>(m.kind), index++);  // tangential_model(kind) indexes by the kind
    EXPECT_TRUE(filled(m.name));
    EXPECT_NO_THROW(dem::code_from_name(m.code));  // a code of the DEM table
    EXPECT_TRUE(filled(m.code_title));
    EXPECT_TRUE(filled(m.source));
    // A stiffness has a unit; a default stiffness only where there is one, positive for a material.
    EXPECT_EQ(m.has_stiffness(), m.stiffness_unit != nullptr);
    EXPECT_EQ(m.rule.history != HistoryKind::none, m.has_stiffness());
    if (m.default_stiffness != nullptr) {
      EXPECT_TRUE(m.has_stiffness());
      const double k = m.default_stiffness(steel);
      EXPECT_TRUE(k > 0.0 && std::isfinite(k)) << k;
    }
    // No stiffness growth or rescale without a history to grow or rescale.
    if (!m.has_stiffness()) {
      EXPECT_EQ(m.rule.growth, StiffnessGrowth::constant);
      EXPECT_FALSE(m.rule.rescales_on_unloading);
    }
    EXPECT_TRUE(filled(m.normal_law_words));
    // A model the study refuses says why, and pairs with a law of its own.
    if (!m.runs_in_study()) {
      EXPECT_TRUE(filled(m.study_refusal));
      EXPECT_TRUE(m.normal_law.has_value());
    }
    EXPECT_TRUE(filled(m.et_error_basis));
    EXPECT_TRUE(m.et_error_coefficient > 0.0 ||
                (std::isnan(m.et_error_coefficient) &&
                 std::string_view(m.et_error_basis).starts_with("not measured")));
    EXPECT_TRUE(filled(m.cap_rule));
  }
}

TEST(TangentialModels, NamesAreUniqueAndRoundTrip) {
  std::set<std::string> seen;
  for (const TangentialModel& m : tangential_models()) {
    EXPECT_TRUE(seen.insert(m.name).second) << m.name;
    EXPECT_EQ(find_tangential_model(m.name), &m);
    EXPECT_EQ(tangential_from_name(m.name), m.kind);
    EXPECT_STREQ(tangential_name(m.kind), m.name);
    EXPECT_EQ(&tangential_model(m.kind), &m);
  }
  EXPECT_EQ(tangential_names().size(), seen.size());
  EXPECT_EQ(find_tangential_model("mindlin/rescale"), nullptr);
  try {
    tangential_from_name("mindlin/rescale");
    FAIL() << "accepted a name no row has";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find(alternatives(tangential_names())), std::string::npos) << e.what();
  }
}

// The help of `oblique --tangential` lists the models the study runs and `dem --tangential` LAMMPS's, both
// in the table's order; and `dem` takes each of LAMMPS's models.
TEST(TangentialModels, TheCommandLineListsTheTable) {
  std::vector<std::string> runs;
  for (const TangentialModel& m : tangential_models()) {
    if (m.runs_in_study()) runs.emplace_back(m.name);
  }
  const std::string oblique = unwrapped_help(run_cli("oblique --help").out);
  std::string listed = "tangential model: ";
  for (std::size_t i = 0; i < runs.size(); ++i) listed += (i ? ", " : "") + runs[i];
  EXPECT_NE(oblique.find(listed + " (docs/oblique.md)"), std::string::npos) << oblique;

  const std::string dem = unwrapped_help(run_cli("dem --help").out);
  EXPECT_NE(dem.find("--target-et: " + alternatives(tangential_names_of("lammps"))), std::string::npos)
      << dem;
  for (const std::string& name : tangential_names_of("lammps")) {
    const CliOutcome out = run_cli(
        "dem --code lammps --eps 0.9 --velocity 1 --young-modulus 2.1e11 --poisson-ratio 0.3 --radius "
        "0.005 --density 7850 --friction 0.3 --angles 20 --tangential " +
        name +
        (tangential_model(tangential_from_name(name)).default_stiffness != nullptr ||
                 !tangential_model(tangential_from_name(name)).has_stiffness()
             ? ""
             : " --tangential-stiffness 4e6"));
    EXPECT_EQ(out.status, 0) << name << ": " << out.err;
    EXPECT_NE(out.out.find("tangential " + name), std::string::npos) << name;
  }
}

// A scene's mindlin_stiffness is the k_t of every model whose k_t is per contact radius (N/m²), LIGGGHTS's
// too; tangential_stiffness that of the others (N/m). A k_t far beyond what the solve resolves shows which
// key a model read.
TEST(TangentialModels, SceneStiffnessKeysFollowTheUnit) {
  const TempFolder folder;
  const auto run_scene = [&](const std::string& model, const std::string& key) {
    const std::string path = (folder.path / "scene.toml").string();
    std::ofstream(path)
        << "title = \"t\"\noutput = \"out\"\n[materials.steel]\nyoung_modulus = 2e11\npoisson_ratio = "
           "0.3\ndensity = 7800.0\n"
           "radius = 1e-3\ndissipative_constant = 1e-9\n[[oblique]]\nname = \"o\"\n"
           "material = \"steel\"\nwall = true\nplot = false\nfriction = 0.3\nangles = [20.0]\n"
           "model = [\""
        << model << "\"]\n"
        << key << " = 1e30\n";
    return run_cli("run " + path + " --output " + (folder.path / "out").string());
  };
  for (const std::string model : {"mindlin", "liggghts_history", "mindlin/force"}) {
    EXPECT_EQ(run_scene(model, "mindlin_stiffness").status, 2) << model;
    EXPECT_EQ(run_scene(model, "tangential_stiffness").status, 0) << model;
  }
  EXPECT_EQ(run_scene("linear_history", "tangential_stiffness").status, 2);
}

}  // namespace
