// SPDX-License-Identifier: BSD-3-Clause
// The oblique outputs of `restitution dem` computed in the library (src/dem/oblique_lines.cpp): LAMMPS's
// writer records the tangential model it prints (dem::GranularTangential) and the readers take it from that
// record, never from the text; the record and the printed line agree word for word, a --tangential choice
// changes both, `mindlin NULL` is read as 8 G*, and the inverse finds the stiffness that made an e_t again.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "dem/deck.hpp"
#include "dem/deck_lammps.hpp"
#include "dem/oblique_lines.hpp"
#include "dem/wall_lines.hpp"
#include "restitution/errors.hpp"

namespace {

using namespace restitution;

constexpr double kYoung = 2e11;
constexpr double kNu = 0.3;
constexpr double kMu = 0.3;

dem::Pair steel_pair() {
  Material m;
  m.young_modulus_pa = kYoung;
  m.poisson_ratio = kNu;
  m.radius1_m = m.radius2_m = 1e-3;
  m.density_kg_m3 = 7800.0;
  m.dissipative_constant_s = 1e-7;
  return dem::pair_of(m);
}

// The words after `tangential` and before `damping` of a printed line, read from the text alone.
std::vector<std::string> printed_tangential_words(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> words;
  bool inside = false;
  for (std::string w; in >> w;) {
    if (w == "damping" && inside) break;
    if (inside) words.push_back(w);
    if (w == "tangential") inside = true;
  }
  return words;
}

std::vector<std::string> words_of(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> words;
  for (std::string w; in >> w;) words.push_back(w);
  return words;
}

TEST(ObliqueLines, TheRecordIsThePrintedPairLine) {
  for (const double mu : {0.0, kMu}) {
    const dem::Deck deck =
        dem::make_deck(dem::Code::lammps, CollisionEnd::delayed_recovery, steel_pair(), 1e-7, 1.0, mu);
    ASSERT_TRUE(deck.granular_tangential.has_value());
    const dem::GranularTangential& t = *deck.granular_tangential;
    EXPECT_FALSE(t.wall);
    EXPECT_EQ(t.friction, mu);
    EXPECT_EQ(dem::granular_line(deck, t), deck.lines.at(1));
    EXPECT_EQ(printed_tangential_words(deck.lines.at(1)), words_of(dem::granular_tangential_words(t)));
  }
}

TEST(ObliqueLines, TheWallRecordHoldsItsNumericStiffness) {
  dem::WallRequest request;
  request.code = dem::Code::lammps;
  request.sphere.young_modulus_pa = kYoung;
  request.sphere.poisson_ratio = kNu;
  request.sphere.radius1_m = request.sphere.radius2_m = 1e-3;
  request.sphere.density_kg_m3 = 7800.0;
  request.damping.dissipative_constant_s = 1e-7;
  request.friction = kMu;
  const dem::WallResult r = dem::wall_lines(request);
  ASSERT_TRUE(r.deck.granular_tangential.has_value());
  const dem::GranularTangential& t = *r.deck.granular_tangential;
  EXPECT_TRUE(t.wall);
  ASSERT_TRUE(t.stiffness.has_value());
  const std::vector<std::string> printed = printed_tangential_words(r.deck.lines.at(0));
  ASSERT_EQ(printed.size(), 4U);
  EXPECT_EQ(std::stod(printed[1]), *t.stiffness);  // the number printed reads back to the record's
  EXPECT_EQ(dem::granular_line(r.deck, t), r.deck.lines.at(0));
}

TEST(ObliqueLines, AChoiceChangesTheRecordAndTheLineAlike) {
  dem::Deck deck =
      dem::make_deck(dem::Code::lammps, CollisionEnd::delayed_recovery, steel_pair(), 1e-7, 1.0, kMu);
  dem::ObliqueLinesRequest o;
  o.tangential = "linear_history";
  o.tangential_stiffness = 1e6;
  o.tangential_damping = 0.5;
  dem::apply_tangential_choice(deck, o, kMu);
  const dem::GranularTangential& t = *deck.granular_tangential;
  EXPECT_EQ(t.kind, oblique::TangentialKind::linear_history);
  EXPECT_EQ(t.stiffness, 1e6);
  EXPECT_EQ(t.damping_factor, 0.5);
  EXPECT_EQ(t.friction, kMu);
  EXPECT_EQ(printed_tangential_words(deck.lines.at(1)),
            (std::vector<std::string>{"linear_history", "1000000", "0.5", "0.3"}));
}

TEST(ObliqueLines, MindlinNullIsEightTimesTheEffectiveShearModulus) {
  const dem::Pair pair = steel_pair();
  const dem::Deck deck =
      dem::make_deck(dem::Code::lammps, CollisionEnd::delayed_recovery, pair, 1e-7, 1.0, kMu);
  dem::ObliqueLinesRequest o;
  o.angles_deg = {30.0};
  const auto r = dem::pair_oblique(deck, pair, o, 1.0, 1e-8);
  ASSERT_TRUE(r.has_value());
  // G = Y/(2(1 + ν)) per sphere, 1/G* = 2 (2 - ν)/G for two of them.
  const double g_star = kYoung / (2.0 * (1.0 + kNu)) / (2.0 * (2.0 - kNu));
  EXPECT_NEAR(r->tangential.stiffness, 8.0 * g_star, 1e-12 * 8.0 * g_star);
  EXPECT_EQ(r->tangential.friction, kMu);
  ASSERT_EQ(r->impacts.size(), 1U);
  EXPECT_EQ(r->steps_per_contact, std::ceil(r->error_coefficient / r->et_accuracy));
  EXPECT_NEAR(r->timestep_s * r->steps_per_contact, r->impacts[0].result.contact_time_s, 1e-20);
}

TEST(ObliqueLines, TheInverseFindsTheStiffnessThatMadeAnEt) {
  const dem::Pair pair = steel_pair();
  dem::Deck deck = dem::make_deck(dem::Code::lammps, CollisionEnd::delayed_recovery, pair, 1e-7, 1.0, kMu);
  const double k_t = 1e11;  // N/m², not the default 8 G* (e_t at 30° has one root near this scale)
  dem::ObliqueLinesRequest o;
  o.tangential_stiffness = k_t;
  dem::apply_tangential_choice(deck, o, kMu);
  o.angles_deg = {30.0};
  const auto made = dem::pair_oblique(deck, pair, o, 1.0, 1e-9);
  ASSERT_TRUE(made.has_value());
  const double et = made->impacts.at(0).result.tangential_restitution;
  o.target_et = et;
  o.reference_angle_deg = 30.0;
  const auto found = dem::pair_oblique(deck, pair, o, 1.0, 1e-9);
  ASSERT_TRUE(found && found->inverse);
  EXPECT_NEAR(found->inverse->parameter / k_t, 1.0, 1e-6);
  // The line printed for it carries that number, and reads back to it.
  const std::vector<std::string> words = printed_tangential_words(found->inverse_lines.at(0));
  ASSERT_EQ(words.size(), 4U);
  EXPECT_EQ(std::stod(words[1]), found->inverse->parameter);
  EXPECT_NEAR(found->inverse_impacts.at(0).result.tangential_restitution, et, 1e-8);
}

TEST(ObliqueLines, RefusesByTheOption) {
  dem::ObliqueLinesRequest o;
  o.angles_deg = {95.0};
  EXPECT_THROW(dem::wants_oblique(o, dem::Code::lammps, kMu), InvalidInput);
  o.angles_deg = {30.0};
  o.target_et = 0.2;
  EXPECT_THROW(dem::wants_oblique(o, dem::Code::lammps, kMu), InvalidInput);  // no reference angle
  o.reference_angle_deg = 30.0;
  EXPECT_THROW(dem::wants_oblique(o, dem::Code::lammps, 0.0), InvalidInput);  // no friction
  EXPECT_TRUE(dem::wants_oblique(o, dem::Code::lammps, kMu));
  dem::ObliqueLinesRequest none;
  EXPECT_FALSE(dem::wants_oblique(none, dem::Code::lammps, 0.0));
}

}  // namespace
