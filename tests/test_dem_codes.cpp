// SPDX-License-Identifier: BSD-3-Clause
// The table of DEM codes (dem/dem_codes.hpp): every entry is whole and agrees with itself, names round-trip,
// and the CLI's --code choices, its help and the scene parser take their names from it.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "cli_runner.hpp"
#include "dem/check_deck.hpp"
#include "dem/deck.hpp"
#include "dem/dem_codes.hpp"
#include "dem/polydisperse_lines.hpp"
#include "material_examples.hpp"
#include "restitution/errors.hpp"
#include "scene/scene.hpp"

namespace restitution {
namespace {

using dem::CodeEntry;

TEST(DemCodes, EveryEntryIsWholeAndNamesRoundTrip) {
  std::set<std::string> names;
  std::set<dem::Code> codes;
  for (const CodeEntry& e : dem::dem_codes()) {
    SCOPED_TRACE(e.name);
    EXPECT_TRUE(names.insert(e.name).second) << "name twice";
    EXPECT_TRUE(codes.insert(e.code).second) << "code twice";
    EXPECT_EQ(dem::code_from_name(e.name), e.code);
    EXPECT_STREQ(dem::code_name(e.code), e.name);
    EXPECT_EQ(&dem::code_entry(e.code), &e);
    ASSERT_NE(e.write, nullptr);
    ASSERT_NE(e.read, nullptr);
    EXPECT_TRUE(std::string(e.comment) == "#" || std::string(e.comment) == "//");
    // Several atom types: a writer, or the reason there is none (never both, never neither).
    EXPECT_NE(e.polydisperse == nullptr, e.one_radius_only == nullptr);
    if (e.polydisperse != nullptr) EXPECT_FALSE(std::string(e.polydisperse_note).empty());
    // A check deck needs a command to run it, a default step count and a size bound.
    const bool deck = e.check_deck != nullptr;
    EXPECT_EQ(deck, dem::has_check_deck(e.code));
    EXPECT_EQ(deck, !std::string(e.check_deck_run).empty());
    EXPECT_EQ(deck, e.check_deck_steps > 0);
    EXPECT_EQ(deck, e.max_deck_collisions > 0);
    if (deck) {
      EXPECT_EQ(dem::check_deck_command(e.code, "f.in"), std::string(e.check_deck_run) + "f.in");
      // The deck runs the code's program.
      EXPECT_EQ(std::string(e.check_deck_run).rfind(std::string(e.program) + " ", 0), 0U);
    } else {
      EXPECT_THROW((void)dem::check_deck_command(e.code, "f.in"), InvalidInput);
    }
    // Scenes run only programs; a version query names the program it asks.
    if (e.scene_runs) EXPECT_FALSE(std::string(e.program).empty());
    if (!std::string(e.version_query).empty())
      EXPECT_EQ(std::string(e.version_query).rfind(std::string(e.program) + " ", 0), 0U);
  }
  EXPECT_EQ(names.size(), 5U);  // lammps, liggghts, mercurydpm, yade, chrono
}

TEST(DemCodes, EveryWriterWritesItsCodeAndClampingCodesRefuseTheNaiveEnd) {
  // Each writer's β read back is checked per code in test_dem.cpp (EachCode, over this table).
  const dem::Pair pair = dem::pair_of(test_support::rubber_like());
  for (const CodeEntry& e : dem::dem_codes()) {
    const dem::Deck deck = dem::make_deck(e.code, CollisionEnd::delayed_recovery, pair, 5.8e-5, 1.0, 0.3);
    EXPECT_EQ(deck.code, e.code) << e.name;
    EXPECT_FALSE(deck.lines.empty()) << e.name;
    EXPECT_EQ(dem::always_clamps(e.code), e.always_clamps) << e.name;
    if (e.always_clamps) {
      EXPECT_THROW((void)dem::make_deck(e.code, CollisionEnd::naive, pair, 5.8e-5, 1.0), InvalidInput)
          << e.name;
    } else {
      EXPECT_NO_THROW((void)dem::make_deck(e.code, CollisionEnd::naive, pair, 5.8e-5, 1.0)) << e.name;
    }
  }
}

TEST(DemCodes, OneRadiusCodesRefuseSeveralTypesWithTheirReason) {
  for (const CodeEntry& e : dem::dem_codes()) {
    if (e.polydisperse != nullptr) continue;
    dem::PolydisperseRequest request;
    request.code = e.code;
    request.types = {{0.01, 1100.0, 1e7, 0.45, 1}, {0.02, 1100.0, 1e7, 0.45, 1}};
    request.damping.dissipative_constant_s = 5.8e-5;
    try {
      (void)dem::polydisperse_lines(request);
      ADD_FAILURE() << e.name << " took several types";
    } catch (const InvalidInput& error) {
      EXPECT_EQ(std::string(error.what()), e.one_radius_only);
    }
  }
}

TEST(DemCodes, NameListsComeFromTheTable) {
  EXPECT_EQ(dem::code_list(" or "), "lammps, liggghts, mercurydpm, yade or chrono");
  EXPECT_EQ(dem::code_list(" and ", [](const CodeEntry& e) { return e.check_deck != nullptr; }),
            "lammps, liggghts and yade");
  try {
    (void)dem::code_from_name("gromacs");
    ADD_FAILURE() << "gromacs accepted";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find(dem::code_list(" or ")), std::string::npos) << e.what();
  }
  const auto help = test_support::run_cli("dem --help");
  ASSERT_EQ(help.status, 0) << help.err;
  EXPECT_NE(test_support::unwrapped_help(help.out).find("DEM code: " + dem::code_list(" or ")),
            std::string::npos)
      << help.out;
  for (const std::string& name : dem::code_names()) {
    // Every name is a --code choice (CLI11 refuses the others with exit 2).
    const auto run = test_support::run_cli("dem --code " + name + " --help");
    EXPECT_EQ(run.status, 0) << name << run.err;
  }
  EXPECT_EQ(test_support::run_cli("dem --code gromacs --dissipative-constant 1e-5").status, 2);
}

TEST(DemCodes, ScenesHoldTheCode) {
  for (const CodeEntry& e : dem::dem_codes()) {
    const std::string text =
        std::string(
            "output = \"out\"\n[materials.rubber]\nyoung_modulus = 1e7\npoisson_ratio = 0.45\n"
            "density = 1100.0\nradius = 0.01\ndissipative_constant = 5.8e-5\n"
            "[[dem]]\nname = \"d\"\ncode = \"") +
        e.name + "\"\nmaterial = \"rubber\"\nspeeds = [1]\n";
    const scene::Scene s = scene::parse_scene(text, "codes.toml");
    ASSERT_EQ(s.dems.size(), 1U);
    EXPECT_EQ(s.dems[0].code, e.code) << e.name;
  }
}

}  // namespace
}  // namespace restitution
