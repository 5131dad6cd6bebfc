// SPDX-License-Identifier: BSD-3-Clause
#include "cli/dem/dem_oblique.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>

#include "cli/common/deprecated_alias.hpp"
#include "dem/deck_liggghts.hpp"
#include "dem/deck_notes.hpp"
#include "dem/dem_codes.hpp"
#include "restitution/errors.hpp"
#include "restitution/units.hpp"

namespace restitution::cli {
namespace {

using namespace restitution::oblique;

const std::vector<double> kDefaultAngles{5.0, 15.0, 30.0, 45.0, 60.0, 80.0};
// The oblique contract's range (oblique_accuracy.hpp); dem's --tolerance goes down to 1e-11 and up to 1e-2.
constexpr double kLoosestObliqueTolerance = 1e-3;

std::vector<std::string> words_of(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> words;
  for (std::string w; in >> w;) words.push_back(w);
  return words;
}

// The words after `tangential` in a LAMMPS granular line: MODEL [k_t] x_gamma_t mu.
struct TangentialWords {
  std::size_t position = 0;  // of MODEL in the line's words
  std::vector<std::string> words;
};
TangentialWords tangential_words(const std::vector<std::string>& words) {
  const auto at = std::find(words.begin(), words.end(), "tangential");
  if (at == words.end() || at + 1 == words.end())
    throw std::logic_error("a LAMMPS granular line without tangential");
  TangentialWords t;
  t.position = static_cast<std::size_t>(at - words.begin()) + 1;
  const std::size_t count = tangential_model(tangential_from_name(*(at + 1))).has_stiffness() ? 4 : 3;
  if (t.position + count > words.size()) throw std::logic_error("a LAMMPS tangential model cut short");
  t.words.assign(at + 1, at + 1 + static_cast<std::ptrdiff_t>(count));
  return t;
}

// The tangential force the words give; `null_stiffness` is what `mindlin NULL` means where the line is read.
TangentialForce tangential_of(const TangentialWords& t, double null_stiffness) {
  TangentialForce f;
  f.kind = tangential_from_name(t.words[0]);
  const bool nohistory = !tangential_model(f.kind).has_stiffness();
  if (!nohistory) f.stiffness = t.words[1] == "NULL" ? null_stiffness : std::stod(t.words[1]);
  f.damping_factor = std::stod(t.words[nohistory ? 1 : 2]);
  f.friction = std::stod(t.words[nohistory ? 2 : 3]);
  return f;
}

std::string joined(const std::vector<std::string>& words) {
  std::string out;
  for (const auto& w : words) out += (out.empty() ? "" : " ") + w;
  return out;
}

std::vector<ContractedOblique> impacts_at(const DemOblique& r, const TangentialForce& tangential) {
  std::vector<ContractedOblique> out;
  for (const double angle : r.angles_deg) {
    const ImpactVelocity v{r.speed_m_s * std::cos(angle * kRadiansPerDegree),
                           r.speed_m_s * std::sin(angle * kRadiansPerDegree), 0.0, 0.0};
    out.push_back(solve_oblique_within(r.geometry, r.normal, tangential, v, r.tolerance, r.options));
    // Never silently: an outcome the tolerance cannot be shown for is said on stderr as well.
    if (out.back().ill_conditioned) {
      fmt::print(stderr, "restitution dem: warning: oblique impact at {} deg, {}\n", angle,
                 out.back().conditioning);
    }
  }
  return out;
}

// Solves the impacts, the steps per contact and the inverse; `line_with` is the printed line that carries the
// tangential parameter, with the value found in place of the printed one. The arms are the model's (its row).
DemOblique complete(DemOblique r, const DemObliqueOptions& o,
                    const std::function<std::string(double parameter)>& line_with) {
  // The arms the model's code takes for a pair or a wall (its row).
  const ContactArms& arms = tangential_model(r.tangential.kind).arms(r.geometry.second.has_value());
  r.geometry.torque_arm = arms.torque;
  r.geometry.contact_point_arm = arms.contact_point;
  r.angles_deg = o.angles_deg.empty() ? kDefaultAngles : o.angles_deg;
  r.impacts = impacts_at(r, r.tangential);
  r.et_accuracy = o.et_accuracy;
  r.error_coefficient = tangential_model(r.tangential.kind).et_error_coefficient;
  r.steps_per_contact = std::ceil(r.error_coefficient / r.et_accuracy);
  double shortest = HUGE_VAL;
  for (const auto& i : r.impacts) shortest = std::min(shortest, i.result.contact_time_s);
  r.timestep_s = shortest / r.steps_per_contact;
  if (o.target_et) {
    TangentialInverseRequest request;
    request.geometry = r.geometry;
    request.normal = r.normal;
    request.tangential = r.tangential;
    const double angle = *o.reference_angle_deg * kRadiansPerDegree;
    request.impact = {r.speed_m_s * std::cos(angle), r.speed_m_s * std::sin(angle), 0.0, 0.0};
    request.target_et = *o.target_et;
    request.tolerance = r.tolerance;
    request.options = r.options;
    r.inverse = tangential_parameter_for(request);
    r.target_et = *o.target_et;
    r.reference_angle_deg = *o.reference_angle_deg;
    r.inverse_lines = {line_with(r.inverse->parameter)};
    TangentialForce found = r.tangential;
    (tangential_model(r.tangential.kind).has_stiffness() ? found.stiffness : found.damping_factor) =
        r.inverse->parameter;
    r.inverse_impacts = impacts_at(r, found);
  }
  return r;
}

// LAMMPS's own parameter of the model, the first after its name (k_t, or linear_nohistory's x_gamma_t),
// replaced in `line`.
std::function<std::string(double)> lammps_line_with(const std::string& line, const TangentialWords& words) {
  return [line, position = words.position](double parameter) {
    std::vector<std::string> changed = words_of(line);
    changed.at(position + 1) = fmt::format("{}", parameter);
    return joined(changed);
  };
}

void write_impacts(JsonWriter& json, const DemOblique& r, const std::vector<ContractedOblique>& impacts) {
  json.begin_array();
  for (std::size_t i = 0; i < impacts.size(); ++i) {
    const ObliqueResult& x = impacts[i].result;
    json.begin_object().field("angle_deg", r.angles_deg[i]).field("normal_restitution", x.normal_restitution);
    json.key("tangential_restitution");
    if (std::isfinite(x.tangential_restitution)) {
      json.value(x.tangential_restitution);
    } else {
      json.null();  // no slip at impact: e_t is undefined
    }
    json.field("rebound_angle_deg", x.rebound_angle_rad / kRadiansPerDegree)
        .field("spin_rad_s", x.spin_first_rad_s);
    if (r.geometry.second) json.field("spin2_rad_s", x.spin_second_rad_s);
    json.field("contact_time_s", x.contact_time_s).field("conditioning", impacts[i].conditioning);
    json.end_object();
  }
  json.end_array();
}

void print_impacts(const DemOblique& r, const std::vector<ContractedOblique>& impacts, const char* c) {
  const bool pair = r.geometry.second.has_value();  // the second sphere spins too
  fmt::print("{}   {:>9} {:>14} {:>14} {:>12} {:>14}{}\n", c, "angle_deg", "eps_n", "e_t", "rebound_deg",
             "spin_rad_s", pair ? fmt::format(" {:>14}", "spin2_rad_s") : "");
  for (std::size_t i = 0; i < impacts.size(); ++i) {
    const ObliqueResult& x = impacts[i].result;
    // The angle as given, in its shortest exact form (89.999 is not 90).
    fmt::print("{}   {:>9} {:14.10f} {:14.10f} {:12.6f} {:14.8g}{}{}\n", c,
               fmt::format("{}", r.angles_deg[i]), x.normal_restitution, x.tangential_restitution,
               x.rebound_angle_rad / kRadiansPerDegree, x.spin_first_rad_s,
               pair ? fmt::format(" {:14.8g}", x.spin_second_rad_s) : "",
               impacts[i].ill_conditioned ? "  (" + impacts[i].conditioning + ")" : "");
  }
}

}  // namespace

void add_dem_oblique_options(CLI::App& command, DemObliqueOptions& o) {
  command
      .add_option("--tangential", o.tangential,
                  "with --friction (lammps): LAMMPS's tangential model of the printed line, its oblique "
                  "outputs and --target-et: " +
                      alternatives(tangential_names_of("lammps")))
      ->check(CLI::IsMember(tangential_names_of("lammps")))
      ->capture_default_str();
  command.add_option("--tangential-stiffness", o.tangential_stiffness,
                     "k_t of --tangential in N/m (mindlin: N/m^2, its stiffness is k_t a; default NULL, 8 G* "
                     "for a pair); required by linear_history");
  command.add_option("--tangential-damping", o.tangential_damping,
                     "x_gamma_t of --tangential: the tangential damping coefficient over the normal one "
                     "(default 1)");
  CLI::Option* angle =
      command
          .add_option("--angle", o.angles_deg,
                      "with --friction (lammps, liggghts; yade's 2023.02a lines): the impact angle(s) from "
                      "the normal in "
                      "degrees, in [0, 90), at which to report what the lines give oblique impacts (default "
                      "5,15,30,45,60,80)")
          ->delimiter(',');
  add_deprecated_alias(command, angle, "--angles");
  command
      .add_option("--et-accuracy", o.et_accuracy,
                  "the accuracy of e_t the code's (LAMMPS's, LIGGGHTS's, YADE's) steps per contact are "
                  "reported for, in (0, 0.1]")
      ->capture_default_str();
  command.add_option(
      "--target-et", o.target_et,
      "with --reference-angle (lammps, liggghts; --friction): find --tangential's parameter (k_t, "
      "or linear_nohistory's x_gamma_t; liggghts: kt) that gives this tangential restitution "
      "e_t at that angle, and print its line");
  command.add_option("--reference-angle", o.reference_angle_deg,
                     "the impact angle in degrees from the normal at which --target-et holds, in (0, 90)");
}

bool tangential_chosen(const DemObliqueOptions& o) {
  return o.tangential != "mindlin" || o.tangential_stiffness || o.tangential_damping;
}

void apply_tangential_choice(dem::Deck& deck, const DemObliqueOptions& o, double friction) {
  if (!tangential_chosen(o)) return;
  // The choice rewrites LAMMPS's granular line.
  if (dem::code_entry(deck.code).oblique != dem::ObliqueReader::lammps_granular) {
    throw InvalidInput("--tangential, --tangential-stiffness and --tangential-damping are for --code lammps");
  }
  if (!(friction > 0.0)) {
    throw InvalidInput("--tangential needs --friction MU > 0: without friction the line is frictionless");
  }
  const TangentialKind kind = tangential_from_name(o.tangential);
  const TangentialModel& model = tangential_model(kind);
  if (model.has_stiffness() && model.default_stiffness == nullptr && !o.tangential_stiffness) {
    throw InvalidInput(fmt::format("--tangential {} needs --tangential-stiffness K_T in {}", model.name,
                                   model.stiffness_unit));
  }
  if (!model.has_stiffness() && o.tangential_stiffness) {
    throw InvalidInput(
        fmt::format("--tangential {} has no stiffness: drop --tangential-stiffness", model.name));
  }
  if (o.tangential_stiffness && !(*o.tangential_stiffness > 0.0 && std::isfinite(*o.tangential_stiffness))) {
    throw InvalidInput(fmt::format("--tangential-stiffness must be a positive finite number, got {}",
                                   *o.tangential_stiffness));
  }
  if (o.tangential_damping && !(*o.tangential_damping >= 0.0 && std::isfinite(*o.tangential_damping))) {
    throw InvalidInput(fmt::format("--tangential-damping must be a non-negative finite number, got {}",
                                   *o.tangential_damping));
  }
  const auto line = std::find_if(deck.lines.begin(), deck.lines.end(), [](const std::string& l) {
    return l.find(" tangential ") != std::string::npos;
  });
  if (line == deck.lines.end()) throw std::logic_error("a LAMMPS deck without a tangential model");
  std::vector<std::string> words = words_of(*line);
  const TangentialWords printed = tangential_words(words);
  const std::string damping = o.tangential_damping ? fmt::format("{}", *o.tangential_damping) : "1";
  std::vector<std::string> chosen{o.tangential};
  if (model.has_stiffness()) {
    // mindlin without a stiffness keeps the printed one (NULL for a pair, the wall's numeric 8 G*).
    chosen.push_back(o.tangential_stiffness ? fmt::format("{}", *o.tangential_stiffness) : printed.words[1]);
  }
  chosen.push_back(damping);
  chosen.push_back(printed.words.back());  // μ
  const auto first = words.begin() + static_cast<std::ptrdiff_t>(printed.position);
  words.erase(first, first + static_cast<std::ptrdiff_t>(printed.words.size()));
  words.insert(words.begin() + static_cast<std::ptrdiff_t>(printed.position), chosen.begin(), chosen.end());
  *line = joined(words);
  const std::string note = fmt::format(
      "tangential {} (--tangential): x_gamma_t = {} (tangential damping = x_gamma_t times the normal "
      "damping){}",
      joined(chosen), damping,
      !model.has_stiffness()
          ? std::string(", no history: F_t = -min(mu |F_n|, x_gamma_t eta |v_t|)")
          : fmt::format(
                ", k_t in {}{}", model.stiffness_unit,
                model.rule.growth == StiffnessGrowth::contact_radius ? " (times the contact radius a)" : ""));
  for (std::string& n : deck.notes) {
    if (n.rfind("tangential ", 0) == 0) n = note;
  }
}

bool wants_oblique(const DemObliqueOptions& o, dem::Code code, double friction) {
  const bool asked = !o.angles_deg.empty() || o.target_et || o.reference_angle_deg || tangential_chosen(o);
  const dem::CodeEntry& entry = dem::code_entry(code);
  if (entry.tangential_refusal != nullptr && tangential_chosen(o))
    throw InvalidInput(entry.tangential_refusal);
  if (entry.inverse_refusal != nullptr && (o.target_et || o.reference_angle_deg)) {
    throw InvalidInput(entry.inverse_refusal);
  }
  if (entry.oblique == dem::ObliqueReader::none) {
    if (asked) {
      throw InvalidInput(
          "--angle, --target-et and --reference-angle are for --code lammps or liggghts, --tangential for "
          "lammps (the other codes' tangential models are not modelled yet)");
    }
    return false;
  }
  for (const double a : o.angles_deg) {
    if (!(a >= 0.0 && a < 90.0)) {
      throw InvalidInput(fmt::format("--angle must be in [0, 90) degrees from the normal, got {}", a));
    }
  }
  if (!(o.et_accuracy > 0.0 && o.et_accuracy <= 0.1)) {
    throw InvalidInput(fmt::format("--et-accuracy must be in (0, 0.1], got {}", o.et_accuracy));
  }
  if (o.target_et.has_value() != o.reference_angle_deg.has_value()) {
    throw InvalidInput("give --target-et and --reference-angle together");
  }
  if (o.reference_angle_deg && !(*o.reference_angle_deg > 0.0 && *o.reference_angle_deg < 90.0)) {
    throw InvalidInput(fmt::format("--reference-angle must be in (0, 90) degrees from the normal, got {}",
                                   *o.reference_angle_deg));
  }
  if (o.target_et && !(friction > 0.0)) {
    throw InvalidInput(
        "--target-et needs --friction MU > 0: without friction e_t = -1 whatever the stiffness");
  }
  return asked || friction > 0.0;
}

namespace {

// LIGGGHTS's lines read as LIGGGHTS reads them: hertz/stiffness's kn sqrt(R* δ) and gamman m* sqrt(R* δ)
// (normal_model_hertz_stiffness.h:118-122), `tangential history`'s kt sqrt(R* δ) and gammat m* sqrt(R* δ)
// (so γ_t = gammat/gamman on the normal coefficient), the cap on the elastic force alone, torque and
// contact-point arm R - δ/2 (the liggghts_history row), limitForce on: the delayed-recovery end. The
// numbers are the writer's parameters (dem/deck_liggghts.cpp), which its lines print.
DemOblique liggghts_pair_oblique(const dem::Deck& deck, const dem::Pair& pair, const DemObliqueOptions& o,
                                 double speed_m_s, double tolerance) {
  const double mu = deck.parameter("coefficientFriction");
  if (!(mu > 0.0)) {
    throw InvalidInput(
        "--angle, --target-et and --reference-angle with --code liggghts need --friction MU > 0: without "
        "it the lines are frictionless (tangential no_history)");
  }
  DemOblique r;
  r.code = deck.code;
  const double kn = deck.parameter("kn");
  const double gamman = deck.parameter("gamman");
  const double kt = deck.parameter("kt");
  const double gammat = deck.parameter("gammat");
  const double sqrt_radius = std::sqrt(pair.effective_radius_m);
  r.normal = {LawKind::viscoelastic_hertz, kn * sqrt_radius, gamman * pair.effective_mass_kg * sqrt_radius};
  r.tangential.kind = TangentialKind::liggghts_history;
  r.tangential.stiffness = kt;
  // gammat = gamman = 0 (A = 0): no damping either way.
  if (gamman == 0.0 && gammat != 0.0) throw std::logic_error("LIGGGHTS lines with gammat but no gamman");
  r.tangential.damping_factor = gamman == 0.0 ? 0.0 : gammat / gamman;
  r.tangential.friction = mu;
  r.tangential_words = fmt::format("history, kt {}, gammat {}, coefficientFriction {}", dem::num(kt),
                                   dem::num(gammat), dem::num(mu));
  r.geometry.first = solid_sphere(pair.radius1_m, pair.mass1_kg);
  r.geometry.second = solid_sphere(pair.radius2_m, pair.mass2_kg);
  r.options.end = deck.end;  // limitForce on at the delayed-recovery end
  r.speed_m_s = speed_m_s;
  r.tolerance = std::clamp(tolerance, kSmallestObliqueTolerance, kLoosestObliqueTolerance);
  return complete(r, o, [](double parameter) { return dem::liggghts_one_type_line("kt", parameter); });
}

// LAMMPS's pair granular line read as LAMMPS reads it.
DemOblique lammps_pair_oblique(const dem::Deck& deck, const dem::Pair& pair, const DemObliqueOptions& o,
                               double speed_m_s, double tolerance) {
  DemOblique r;
  r.code = deck.code;
  const std::string& line = deck.lines.at(1);
  const TangentialWords words = tangential_words(words_of(line));
  r.tangential_words = joined(words.words);
  // pair granular: E* and η_n0 m* sqrt(R*) (dem/deck_lammps.cpp read_lammps); `mindlin NULL` is 8 G* with
  // 1/G* = 2 · 2(2 - ν)(1 + ν)/E for two types of one material (pair_granular.cpp:1021-1023, 1790).
  const dem::Coefficients normal = dem::code_entry(deck.code).read(deck, pair);
  r.normal = {LawKind::viscoelastic_hertz, normal.elastic, normal.damping};
  const double e = deck.parameter("E");
  const double nu = deck.parameter("nu");
  r.tangential = tangential_of(words, 8.0 * e / (4.0 * (2.0 - nu) * (1.0 + nu)));
  r.geometry.first = solid_sphere(pair.radius1_m, pair.mass1_kg);
  r.geometry.second = solid_sphere(pair.radius2_m, pair.mass2_kg);
  r.options.end = deck.end;
  r.speed_m_s = speed_m_s;
  r.tolerance = std::clamp(tolerance, kSmallestObliqueTolerance, kLoosestObliqueTolerance);
  return complete(r, o, lammps_line_with(line, words));
}

}  // namespace

DemOblique wall_oblique(const dem::Deck& deck, const dem::Pair& contact, const DemObliqueOptions& o,
                        double speed_m_s, double tolerance) {
  DemOblique r;
  r.code = deck.code;
  const std::string& line = deck.lines.at(0);
  const TangentialWords words = tangential_words(words_of(line));
  r.tangential_words = joined(words.words);
  // fix wall/gran granular reads hertz/material E ν as (4/3) E/(2(1 - ν)) (fix_wall_gran.cpp:160) and
  // `mindlin NULL` as E (2 - ν)(1 + ν)/4 (line 248); the damping as the pair's, on the sphere's mass.
  const double e = deck.parameter("E");
  const double nu = deck.parameter("nu");
  const double radius = contact.effective_radius_m;
  r.normal = {LawKind::viscoelastic_hertz, hertz_stiffness(e / (2.0 * (1.0 - nu)), radius),
              deck.parameter("eta_n0") * contact.effective_mass_kg * std::sqrt(radius)};
  r.tangential = tangential_of(words, e * (2.0 - nu) * (1.0 + nu) / 4.0);
  r.geometry.first = solid_sphere(radius, contact.effective_mass_kg);
  r.options.end = deck.end;
  r.speed_m_s = speed_m_s;
  r.tolerance = std::clamp(tolerance, kSmallestObliqueTolerance, kLoosestObliqueTolerance);
  return complete(r, o, lammps_line_with(line, words));
}

bool yade_lines_modelled(const dem::Deck& deck) {
  return std::any_of(deck.parameters.begin(), deck.parameters.end(),
                     [](const dem::Parameter& p) { return p.name == "betan"; });
}

DemOblique yade_pair_oblique(const dem::Deck& deck, const dem::Pair& pair, const DemObliqueOptions& o,
                             double speed_m_s, double tolerance) {
  if (!yade_lines_modelled(deck)) {
    throw InvalidInput(
        "--angle: the oblique impacts of YADE 2024.02a's (en, vn) lines are not modelled; --yade-version "
        "2023.02a prints the betan lines whose impacts are");
  }
  DemOblique r;
  r.code = deck.code;
  r.tangential_words = "Law2_ScGeom_MindlinPhys_Mindlin, betas = betan";
  // Ip2_FrictMat_FrictMat_MindlinPhys::go for one material: E* = Y/(2(1 - ν²)), G = Y/(2(1 + ν)), R* from
  // the radii, kno = (4/3) E* sqrt(R*), kso = 2 sqrt(4 R*) G/(2 - ν); Law2: cn = 2 betan sqrt(m* kn), kn =
  // (3/2) kno sqrt(δ), and cs = 2 betas sqrt(m* ks), ks = kso sqrt(δ), so cs/cn = sqrt(kso/(1.5 kno)).
  const double young = deck.parameter("young");
  const double nu = deck.parameter("poisson");
  const double betan = deck.parameter("betan");
  const double r_star = pair.radius1_m * pair.radius2_m / (pair.radius1_m + pair.radius2_m);
  const double kno = 4.0 / 3.0 * young / (2.0 * (1.0 - nu * nu)) * std::sqrt(r_star);
  const double kso = 2.0 * std::sqrt(4.0 * r_star) * young / (2.0 * (1.0 + nu)) / (2.0 - nu);
  r.geometry.first = solid_sphere(pair.radius1_m, pair.mass1_kg);
  r.geometry.second = solid_sphere(pair.radius2_m, pair.mass2_kg);
  r.normal = {LawKind::tsuji_hertz, kno, 2.0 * betan * std::sqrt(1.5 * effective_mass_kg(r.geometry) * kno)};
  r.tangential = {TangentialKind::yade_mindlin, kso, std::sqrt(kso / (1.5 * kno)),
                  std::tan(deck.parameter("frictionAngle"))};
  r.options.end = deck.end;
  r.speed_m_s = speed_m_s;
  r.tolerance = std::clamp(tolerance, kSmallestObliqueTolerance, kLoosestObliqueTolerance);
  // No inverse (refused by wants_oblique): no line carries a parameter found.
  return complete(r, o, [](double /*parameter*/) -> std::string {
    throw std::logic_error("no --target-et for YADE's lines");
  });
}

std::optional<DemOblique> pair_oblique(const dem::Deck& deck, const dem::Pair& pair,
                                       const DemObliqueOptions& o, double speed_m_s, double tolerance) {
  switch (dem::code_entry(deck.code).oblique) {
    case dem::ObliqueReader::lammps_granular:
      return lammps_pair_oblique(deck, pair, o, speed_m_s, tolerance);
    case dem::ObliqueReader::liggghts_history:
      return liggghts_pair_oblique(deck, pair, o, speed_m_s, tolerance);
    case dem::ObliqueReader::yade_mindlin:
      // YADE 2024.02a's (en, vn) lines: not modelled; said where --angle asks for them.
      if (o.angles_deg.empty() && !yade_lines_modelled(deck)) return std::nullopt;
      return yade_pair_oblique(deck, pair, o, speed_m_s, tolerance);
    case dem::ObliqueReader::none:
      break;
  }
  return std::nullopt;
}

void print_oblique_text(const DemOblique& r, const char* c) {
  fmt::print(
      "{} oblique impacts these lines give at {:g} m/s (tangential {}; e_t = -s'/s at the contact point, "
      "eps and e_t within {:g}):\n",
      c, r.speed_m_s, r.tangential_words, r.tolerance);
  print_impacts(r, r.impacts, c);
  if (r.tangential.friction == 0.0) {
    // No cap and no tangential force: neither the cap rule nor the steps e_t needs mean anything.
    fmt::print(
        "{} frictionless lines: no tangential force, e_t = -1 and the spins unchanged at every angle\n", c);
    return;
  }
  const TangentialModel& model = tangential_model(r.tangential.kind);
  fmt::print("{} {}'s rule: {}\n", c, model.code_title, model.cap_rule);
  fmt::print(
      "{} {} decides stick or slip once per step and is first order in dt: e_t within {:g} needs {:g} "
      "steps per contact (|error| <= {:g}/N, a bound over Debian's {} measured; docs/dem.md), timestep <= "
      "{:.4g} s for the shortest "
      "contact here\n",
      c, model.code_title, r.et_accuracy, r.steps_per_contact, r.error_coefficient, model.code_title,
      r.timestep_s);
  if (!r.inverse) return;
  fmt::print(
      "{} for e_t = {:g} at {:g} deg: {} = {:.10g} (e_t there {:.10f}; reachable by this parameter: [{:.6g}, "
      "{:.6g}]), the line:\n",
      c, r.target_et, r.reference_angle_deg, r.inverse->parameter_name, r.inverse->parameter,
      r.inverse->check.result.tangential_restitution, r.inverse->lowest_reachable_et,
      r.inverse->highest_reachable_et);
  for (const auto& line : r.inverse_lines) fmt::print("{}\n", line);
  fmt::print("{} which gives:\n", c);
  print_impacts(r, r.inverse_impacts, c);
}

void write_oblique_json(JsonWriter& json, const DemOblique& r) {
  json.key("oblique").begin_object();
  json.field("tangential", r.tangential_words).field("tangential_model", tangential_name(r.tangential.kind));
  json.field("tangential_stiffness", r.tangential.stiffness)
      .field("tangential_damping_factor", r.tangential.damping_factor);
  json.field("speed_m_s", r.speed_m_s).field("tolerance", r.tolerance);
  json.field("code", dem::code_name(r.code));
  const bool frictionless = r.tangential.friction == 0.0;  // no cap rule, no steps for e_t
  if (!frictionless) json.field("cap_rule", tangential_model(r.tangential.kind).cap_rule);
  json.key("impacts");
  write_impacts(json, r, r.impacts);
  if (!frictionless) {
    json.key(fmt::format("{}_steps", dem::code_name(r.code))).begin_object();
    json.field("et_accuracy", r.et_accuracy).field("error_coefficient", r.error_coefficient);
    json.field("steps_per_contact", r.steps_per_contact).field("timestep_s", r.timestep_s).end_object();
  }
  if (r.inverse) {
    json.key("inverse").begin_object();
    json.field("target_et", r.target_et).field("reference_angle_deg", r.reference_angle_deg);
    json.field("parameter", r.inverse->parameter_name).field("value", r.inverse->parameter);
    json.field("tangential_restitution", r.inverse->check.result.tangential_restitution);
    json.key("reachable_et").begin_array().value(r.inverse->lowest_reachable_et);
    json.value(r.inverse->highest_reachable_et).end_array();
    json.key("lines").begin_array();
    for (const auto& line : r.inverse_lines) json.value(line);
    json.end_array();
    json.key("impacts");
    write_impacts(json, r, r.inverse_impacts);
    json.end_object();
  }
  json.end_object();
}

}  // namespace restitution::cli
