// SPDX-License-Identifier: BSD-3-Clause
#include "dem/oblique_lines.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>

#include "dem/deck_lammps.hpp"
#include "dem/deck_liggghts.hpp"
#include "dem/deck_notes.hpp"
#include "dem/dem_codes.hpp"
#include "restitution/errors.hpp"
#include "restitution/units.hpp"

namespace restitution::dem {
namespace {

using namespace restitution::oblique;

// The oblique contract's range (oblique_accuracy.hpp); dem's --tolerance goes down to 1e-11 and up to 1e-2.
constexpr double kLoosestObliqueTolerance = 1e-3;

// The tangential force LAMMPS's line gives; `null_stiffness` is what `mindlin NULL` means where it is read.
TangentialForce tangential_of(const GranularTangential& t, double null_stiffness) {
  TangentialForce f;
  f.kind = t.kind;
  if (tangential_model(t.kind).has_stiffness()) f.stiffness = t.stiffness.value_or(null_stiffness);
  f.damping_factor = t.damping_factor;
  f.friction = t.friction;
  return f;
}

const GranularTangential& granular_tangential_of(const Deck& deck) {
  if (!deck.granular_tangential) throw std::logic_error("a LAMMPS deck without a tangential model");
  return *deck.granular_tangential;
}

std::vector<ContractedOblique> impacts_at(const ObliqueLines& r, const TangentialForce& tangential) {
  std::vector<ContractedOblique> out;
  for (const double angle : r.angles_deg) {
    const ImpactVelocity v{r.speed_m_s * std::cos(angle * kRadiansPerDegree),
                           r.speed_m_s * std::sin(angle * kRadiansPerDegree), 0.0, 0.0};
    out.push_back(solve_oblique_within(r.geometry, r.normal, tangential, v, r.tolerance, r.options));
  }
  return out;
}

// The inverse at the reference angle, the line carrying the parameter found and its impacts.
void add_inverse(ObliqueLines& r, const ObliqueLinesRequest& o,
                 const std::function<std::string(double parameter)>& line_with) {
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

// Solves the impacts, the steps per contact and the inverse; `line_with` is the printed line that carries the
// tangential parameter, with the value found in place of the printed one.
ObliqueLines complete(ObliqueLines r, const ObliqueLinesRequest& o,
                      const std::function<std::string(double parameter)>& line_with) {
  // The arms the model's code takes for a pair or a wall (its row).
  const ContactArms& arms = tangential_model(r.tangential.kind).arms(r.geometry.second.has_value());
  r.geometry.torque_arm = arms.torque;
  r.geometry.contact_point_arm = arms.contact_point;
  r.tolerance = std::clamp(r.tolerance, kSmallestObliqueTolerance, kLoosestObliqueTolerance);
  r.angles_deg = o.angles_deg.empty() ? kDefaultObliqueAngles : o.angles_deg;
  r.impacts = impacts_at(r, r.tangential);
  r.et_accuracy = o.et_accuracy;
  r.error_coefficient = tangential_model(r.tangential.kind).et_error_coefficient;
  r.steps_per_contact = std::ceil(r.error_coefficient / r.et_accuracy);
  double shortest = HUGE_VAL;
  for (const auto& i : r.impacts) shortest = std::min(shortest, i.result.contact_time_s);
  r.timestep_s = shortest / r.steps_per_contact;
  if (o.target_et) add_inverse(r, o, line_with);
  return r;
}

// LAMMPS's own parameter of the model, the first after its name (k_t, or linear_nohistory's x_gamma_t), in
// the deck's granular line.
std::function<std::string(double)> lammps_line_with(const Deck& deck) {
  return [deck](double parameter) {
    GranularTangential changed = granular_tangential_of(deck);
    if (tangential_model(changed.kind).has_stiffness()) {
      changed.stiffness = parameter;
    } else {
      changed.damping_factor = parameter;
    }
    return granular_line(deck, changed);
  };
}

// The fields every reader sets alike.
ObliqueLines started(const Deck& deck, double speed_m_s, double tolerance) {
  ObliqueLines r;
  r.code = deck.code;
  r.options.end = deck.end;
  r.speed_m_s = speed_m_s;
  r.tolerance = tolerance;
  return r;
}

// LIGGGHTS's lines read as LIGGGHTS reads them: hertz/stiffness's kn sqrt(R* δ) and gamman m* sqrt(R* δ)
// (normal_model_hertz_stiffness.h:118-122), `tangential history`'s kt sqrt(R* δ) and gammat m* sqrt(R* δ)
// (so γ_t = gammat/gamman on the normal coefficient), the cap on the elastic force alone, torque and
// contact-point arm R - δ/2 (the liggghts_history row), limitForce on: the delayed-recovery end. The
// numbers are the writer's parameters (dem/deck_liggghts.cpp), which its lines print.
ObliqueLines liggghts_pair_oblique(const Deck& deck, const Pair& pair, const ObliqueLinesRequest& o,
                                   double speed_m_s, double tolerance) {
  const double mu = deck.parameter("coefficientFriction");
  if (!(mu > 0.0)) {
    throw InvalidInput(
        "--angle, --target-et and --reference-angle with --code liggghts need --friction MU > 0: without "
        "it the lines are frictionless (tangential no_history)");
  }
  ObliqueLines r = started(deck, speed_m_s, tolerance);
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
  r.tangential_words =
      fmt::format("history, kt {}, gammat {}, coefficientFriction {}", num(kt), num(gammat), num(mu));
  r.geometry.first = solid_sphere(pair.radius1_m, pair.mass1_kg);
  r.geometry.second = solid_sphere(pair.radius2_m, pair.mass2_kg);
  return complete(r, o, [](double parameter) { return liggghts_one_type_line("kt", parameter); });
}

// LAMMPS's pair granular line read as LAMMPS reads it, from the model its writer recorded.
ObliqueLines lammps_pair_oblique(const Deck& deck, const Pair& pair, const ObliqueLinesRequest& o,
                                 double speed_m_s, double tolerance) {
  ObliqueLines r = started(deck, speed_m_s, tolerance);
  const GranularTangential& printed = granular_tangential_of(deck);
  r.tangential_words = granular_tangential_words(printed);
  // pair granular: E* and η_n0 m* sqrt(R*) (dem/deck_lammps.cpp read_lammps); `mindlin NULL` is 8 G* with
  // 1/G* = 2 · 2(2 - ν)(1 + ν)/E for two types of one material (pair_granular.cpp:1021-1023, 1790).
  const Coefficients normal = code_entry(deck.code).read(deck, pair);
  r.normal = {LawKind::viscoelastic_hertz, normal.elastic, normal.damping};
  const double e = deck.parameter("E");
  const double nu = deck.parameter("nu");
  r.tangential = tangential_of(printed, 8.0 * e / (4.0 * (2.0 - nu) * (1.0 + nu)));
  r.geometry.first = solid_sphere(pair.radius1_m, pair.mass1_kg);
  r.geometry.second = solid_sphere(pair.radius2_m, pair.mass2_kg);
  return complete(r, o, lammps_line_with(deck));
}

}  // namespace

bool tangential_chosen(const ObliqueLinesRequest& o) {
  return o.tangential != "mindlin" || o.tangential_stiffness || o.tangential_damping;
}

namespace {

// The refusals of apply_tangential_choice; the chosen model's row.
const TangentialModel& checked_choice(const Deck& deck, const ObliqueLinesRequest& o, double friction) {
  // The choice rewrites LAMMPS's granular line.
  if (code_entry(deck.code).oblique != ObliqueReader::lammps_granular) {
    throw InvalidInput("--tangential, --tangential-stiffness and --tangential-damping are for --code lammps");
  }
  if (!(friction > 0.0)) {
    throw InvalidInput("--tangential needs --friction MU > 0: without friction the line is frictionless");
  }
  const TangentialModel& model = tangential_model(tangential_from_name(o.tangential));
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
  return model;
}

}  // namespace

void apply_tangential_choice(Deck& deck, const ObliqueLinesRequest& o, double friction) {
  if (!tangential_chosen(o)) return;
  const TangentialModel& model = checked_choice(deck, o, friction);
  GranularTangential chosen = granular_tangential_of(deck);
  chosen.kind = model.kind;
  // mindlin without a stiffness keeps the printed one (NULL for a pair, the wall's numeric 8 G*).
  if (!model.has_stiffness()) {
    chosen.stiffness.reset();
  } else if (o.tangential_stiffness) {
    chosen.stiffness = *o.tangential_stiffness;
  }
  chosen.damping_factor = o.tangential_damping.value_or(1.0);
  set_granular_tangential(deck, chosen);
  const std::string note = fmt::format(
      "tangential {} (--tangential): x_gamma_t = {} (tangential damping = x_gamma_t times the normal "
      "damping){}",
      granular_tangential_words(chosen), num(chosen.damping_factor),
      !model.has_stiffness()
          ? std::string(", no history: F_t = -min(mu |F_n|, x_gamma_t eta |v_t|)")
          : fmt::format(
                ", k_t in {}{}", model.stiffness_unit,
                model.rule.growth == StiffnessGrowth::contact_radius ? " (times the contact radius a)" : ""));
  for (std::string& n : deck.notes) {
    if (n.rfind("tangential ", 0) == 0) n = note;
  }
}

bool wants_oblique(const ObliqueLinesRequest& o, Code code, double friction) {
  const bool asked = !o.angles_deg.empty() || o.target_et || o.reference_angle_deg || tangential_chosen(o);
  const CodeEntry& entry = code_entry(code);
  if (entry.tangential_refusal != nullptr && tangential_chosen(o))
    throw InvalidInput(entry.tangential_refusal);
  if (entry.inverse_refusal != nullptr && (o.target_et || o.reference_angle_deg)) {
    throw InvalidInput(entry.inverse_refusal);
  }
  if (entry.oblique == ObliqueReader::none) {
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

ObliqueLines wall_oblique(const Deck& deck, const Pair& contact, const ObliqueLinesRequest& o,
                          double speed_m_s, double tolerance) {
  ObliqueLines r = started(deck, speed_m_s, tolerance);
  const GranularTangential& printed = granular_tangential_of(deck);
  r.tangential_words = granular_tangential_words(printed);
  // fix wall/gran granular reads hertz/material E ν as (4/3) E/(2(1 - ν)) (fix_wall_gran.cpp:160) and
  // `mindlin NULL` as E (2 - ν)(1 + ν)/4 (line 248); the damping as the pair's, on the sphere's mass.
  const double e = deck.parameter("E");
  const double nu = deck.parameter("nu");
  const double radius = contact.effective_radius_m;
  r.normal = {LawKind::viscoelastic_hertz, hertz_stiffness(e / (2.0 * (1.0 - nu)), radius),
              deck.parameter("eta_n0") * contact.effective_mass_kg * std::sqrt(radius)};
  r.tangential = tangential_of(printed, e * (2.0 - nu) * (1.0 + nu) / 4.0);
  r.geometry.first = solid_sphere(radius, contact.effective_mass_kg);
  return complete(r, o, lammps_line_with(deck));
}

bool yade_lines_modelled(const Deck& deck) {
  return std::any_of(deck.parameters.begin(), deck.parameters.end(),
                     [](const Parameter& p) { return p.name == "betan"; });
}

ObliqueLines yade_pair_oblique(const Deck& deck, const Pair& pair, const ObliqueLinesRequest& o,
                               double speed_m_s, double tolerance) {
  if (!yade_lines_modelled(deck)) {
    throw InvalidInput(
        "--angle: the oblique impacts of YADE 2024.02a's (en, vn) lines are not modelled; --yade-version "
        "2023.02a prints the betan lines whose impacts are");
  }
  ObliqueLines r = started(deck, speed_m_s, tolerance);
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
  // No inverse (refused by wants_oblique): no line carries a parameter found.
  return complete(r, o, [](double /*parameter*/) -> std::string {
    throw std::logic_error("no --target-et for YADE's lines");
  });
}

std::optional<ObliqueLines> pair_oblique(const Deck& deck, const Pair& pair, const ObliqueLinesRequest& o,
                                         double speed_m_s, double tolerance) {
  switch (code_entry(deck.code).oblique) {
    case ObliqueReader::lammps_granular:
      return lammps_pair_oblique(deck, pair, o, speed_m_s, tolerance);
    case ObliqueReader::liggghts_history:
      return liggghts_pair_oblique(deck, pair, o, speed_m_s, tolerance);
    case ObliqueReader::yade_mindlin:
      // YADE 2024.02a's (en, vn) lines: not modelled; said where --angle asks for them.
      if (o.angles_deg.empty() && !yade_lines_modelled(deck)) return std::nullopt;
      return yade_pair_oblique(deck, pair, o, speed_m_s, tolerance);
    case ObliqueReader::none:
      break;
  }
  return std::nullopt;
}

}  // namespace restitution::dem
