// SPDX-License-Identifier: BSD-3-Clause
// The table of DEM codes (dem/dem_codes.hpp): every entry is whole and agrees with itself, names round-trip,
// and the CLI's --code choices, its help and the scene parser take their names from it.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "cli_runner.hpp"
#include "dem/check_deck.hpp"
#include "dem/check_deck_codes.hpp"
#include "dem/deck.hpp"
#include "dem/dem_codes.hpp"
#include "dem/polydisperse_lines.hpp"
#include "material_examples.hpp"
#include "restitution/errors.hpp"
#include "scene/scene.hpp"
#include "scene/scene_dem.hpp"
#include "scene/scene_sections.hpp"

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

// The facets that gas decks, oblique impacts, production time steps and check decks read from the table:
// each is there whole, or absent whole.
TEST(DemCodes, EveryFacetIsWholeOrAbsent) {
  for (const CodeEntry& e : dem::dem_codes()) {
    SCOPED_TRACE(e.name);
    ASSERT_NE(e.title, nullptr);
    EXPECT_FALSE(std::string(e.title).empty());
    // A LAMMPS-family check deck has its atom style; only it evaluates $(...) in place.
    const bool lammps_family = e.check_deck == &dem::lammps_family_check_deck;
    EXPECT_EQ(lammps_family, e.check_deck_atom_style != nullptr);
    if (e.immediate_variables) EXPECT_TRUE(lammps_family);
    if (lammps_family) EXPECT_EQ(std::string(e.check_deck_atom_style).rfind("atom_style ", 0), 0U);
    // A companion has the words its header gives it; a gas deck is a LAMMPS-family input with a companion
    // and a program to run it.
    EXPECT_EQ(e.companion == dem::Companion::none, e.companion_words == nullptr);
    if (e.gas_deck) {
      EXPECT_TRUE(lammps_family);
      EXPECT_NE(e.companion, dem::Companion::none);
      EXPECT_FALSE(std::string(e.program).empty());
    }
    // The velocity-Verlet the production options model is a program's integrator.
    if (e.velocity_verlet) EXPECT_FALSE(std::string(e.program).empty());
    // Oblique impacts: a reader comes with a check deck and its steps, or none of them.
    const bool oblique = e.oblique != dem::ObliqueReader::none;
    EXPECT_EQ(oblique, e.oblique_check_steps > 0);
    if (oblique) EXPECT_NE(e.check_deck, nullptr);
    // --tangential rewrites LAMMPS's granular line: every other reader says why it refuses it.
    if (oblique) EXPECT_EQ(e.oblique == dem::ObliqueReader::lammps_granular, e.tangential_refusal == nullptr);
    if (!oblique) EXPECT_EQ(e.tangential_refusal, nullptr);
    if (!oblique) EXPECT_EQ(e.inverse_refusal, nullptr);
  }
}

// What the CLI refuses, it refuses with the table's words, for every code.
TEST(DemCodes, TheCommandLineRefusesByTheTable) {
  const std::string lines =
      " --young-modulus 2.1e11 --poisson-ratio 0.3 --radius 0.001 --density 7850 --eps 0.9 --velocity 1 "
      "--yade-version 2023.02a --friction 0.3";
  for (const CodeEntry& e : dem::dem_codes()) {
    SCOPED_TRACE(e.name);
    const std::string dem = std::string("dem --code ") + e.name + lines;
    const auto tangential =
        test_support::run_cli(dem + " --tangential linear_history --tangential-stiffness 1e6");
    if (e.tangential_refusal != nullptr) {
      EXPECT_EQ(tangential.status, 2);
      EXPECT_NE(tangential.err.find(e.tangential_refusal), std::string::npos) << tangential.err;
    }
    const auto inverse = test_support::run_cli(dem + " --target-et 0.3 --reference-angle 20");
    EXPECT_EQ(inverse.status, e.oblique != dem::ObliqueReader::none && e.inverse_refusal == nullptr ? 0 : 2)
        << inverse.err;
    if (e.inverse_refusal != nullptr) EXPECT_NE(inverse.err.find(e.inverse_refusal), std::string::npos);
    const auto steps = test_support::run_cli(dem + " --timestep 1e-7");
    EXPECT_EQ(steps.status, e.velocity_verlet ? 0 : 2) << steps.err;
    test_support::TempFolder folder;
    const auto gas = test_support::run_cli(
        std::string(
            "gas --young-modulus 1e8 --poisson-ratio 0.4 --density 920 --radius 0.005 --eps 0.8 "
            "--velocity 2 --packing-fraction 0.1 --rms-speed 1 --haff-times 30 --particles 20 --code ") +
        e.name + " --deck " + (folder.path / "g.in").string());
    EXPECT_EQ(gas.status, e.gas_deck ? 0 : 2) << gas.err;
    if (e.gas_deck) {
      // The companion's header names the code's own damping; the commands its program.
      const std::string companion = test_support::slurp((folder.path / "g_constant_eps.in").string());
      EXPECT_NE(companion.find(e.companion_words), std::string::npos);
      EXPECT_NE(gas.out.find(std::string(e.program) + " -in g.in"), std::string::npos) << gas.out;
    }
  }
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
    ASSERT_EQ(scene::tasks_of<scene::DemTask>(s, "dem").size(), 1U);
    EXPECT_EQ(dem::code_from_name(scene::tasks_of<scene::DemTask>(s, "dem")[0]->inputs.code), e.code)
        << e.name;
  }
}

}  // namespace
}  // namespace restitution
