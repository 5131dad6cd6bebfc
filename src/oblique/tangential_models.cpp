// SPDX-License-Identifier: BSD-3-Clause
#include "oblique/tangential_models.hpp"

#include <fmt/core.h>

#include <array>
#include <cmath>

#include "restitution/errors.hpp"
#include "restitution/solve_types.hpp"

namespace restitution::oblique {
namespace {

// Mindlin's k_t a with k_t = 8 G* (LAMMPS's `mindlin NULL`, pair_granular.cpp:1021-1023, 1790; LIGGGHTS's
// kt as `restitution dem` prints it).
double mindlin_null(const ContactModuli& m) {
  return 8.0 * m.effective_shear_modulus_pa;
}
// YADE's kso = 2 sqrt(4 R*) G/(2 - ν) for one material (Ip2_FrictMat_FrictMat_MindlinPhys::go), which is
// 8 G* sqrt(R*): Mindlin's 8 G* a with a = sqrt(R* δ).
double yade_kso(const ContactModuli& m) {
  return 8.0 * m.effective_shear_modulus_pa * std::sqrt(m.effective_radius_m);
}

constexpr ContactArms kLammpsPair{TorqueArm::radius_minus_half_overlap, TorqueArm::radius};  // :663, :407
constexpr ContactArms kLammpsWall{TorqueArm::radius, TorqueArm::radius};  // fix_wall_gran.cpp:1512
constexpr ContactArms kHalfOverlap{TorqueArm::radius_minus_half_overlap,
                                   TorqueArm::radius_minus_half_overlap};

constexpr const char* kLammpsNormal = "any normal model of LAMMPS's pair granular";
constexpr const char* kLammpsCap =
    "the cap tests the whole trial force, elastic and damping (|F_t| > mu |F_n|), and the capped force is mu "
    "|F_n| along it";
// Measured 2026-11-27 with Debian's LAMMPS 20220106: the largest N |e_t(N) - e_t| at dt = t_c/N, the error
// falling tenfold with the step (first order).
constexpr const char* kLammpsBasis =
    "mindlin with x_gamma_t = 1, as dem prints it (tests/dem/oblique_dem_lines_lammps.cpp, pair and wall, "
    "six "
    "angles 5-80 deg, the printed line and the --target-et line): 0.48 for steel (eps = 0.9, mu = 0.3), 0.60 "
    "for glass (E = 6e10 Pa, nu = 0.25, eps = 0.7, mu = 0.5), 0.14 for steel at eps = 0.98, mu = 0.1; the "
    "linear models with x_gamma_t = 0.5 (tests/dem/oblique_lammps.cpp, nine angles, spin 0 and 300 rad/s): "
    "0.064 and 0.033, but linear_history with x_gamma_t = 1 as --tangential prints it (k_t = 4e6 N/m): 0.48; "
    "mindlin_rescale 0.59 and mindlin 0.16 at t_c/6000: so 1";
constexpr const char* kLammpsForceBasis =
    "the force histories (tests/dem/oblique_lammps.cpp, x_gamma_t = 0.5, nine angles, spin 0 and 300 rad/s, "
    "wall and two pairs, at t_c/6000): 2.44 (mindlin/force) and 2.43 (mindlin_rescale/force), so 3";

constexpr TangentialRule kLinearHistory{HistoryKind::displacement, StiffnessGrowth::constant, false,
                                        CapTest::trial_force, false};
constexpr TangentialRule kMindlin{HistoryKind::displacement, StiffnessGrowth::contact_radius, false,
                                  CapTest::trial_force, false};

// A model of LAMMPS's pair granular: its arms, any normal model, run by the study, the cap on the trial
// force.
TangentialModel lammps_model(TangentialKind kind, const char* name, TangentialRule rule, const char* unit,
                             double (*default_stiffness)(const ContactModuli&), double et_error_coefficient,
                             const char* et_error_basis) {
  return {kind,
          name,
          "lammps",
          "LAMMPS",
          "pair granular",
          rule,
          kLammpsPair,
          kLammpsWall,
          unit,
          default_stiffness,
          std::nullopt,
          kLammpsNormal,
          nullptr,
          et_error_coefficient,
          et_error_basis,
          kLammpsCap};
}

// LAMMPS: pair_granular.cpp:431-545 and fix_wall_gran.cpp:1256-1280 (docs/oblique.md derives each);
// LIGGGHTS 3.8.0: tangential_model_history.h:147-217 under hertz/stiffness, arms surface_model_default.h:
// 174-188; YADE 2023.02a: ViscoelasticPM.cpp (computeForceTorqueViscEl) and HertzMindlin.cpp
// (Law2_ScGeom_MindlinPhys_Mindlin::go, ScGeom::getIncidentVel).
const std::array<TangentialModel, 9> kModels{{
    lammps_model(TangentialKind::linear_nohistory, "linear_nohistory", {}, nullptr, nullptr, 1.0,
                 kLammpsBasis),
    lammps_model(TangentialKind::linear_history, "linear_history", kLinearHistory, "N/m", nullptr, 1.0,
                 kLammpsBasis),
    lammps_model(TangentialKind::mindlin, "mindlin", kMindlin, "N/m^2", mindlin_null, 1.0, kLammpsBasis),
    {TangentialKind::liggghts_history,
     "liggghts_history",
     "liggghts",
     "LIGGGHTS",
     "tangential history",
     {HistoryKind::displacement, StiffnessGrowth::contact_radius, false, CapTest::elastic_force, false},
     kHalfOverlap,
     kHalfOverlap,
     "N/m^2",
     mindlin_null,
     LawKind::viscoelastic_hertz,
     "liggghts_history is LIGGGHTS's tangential history under hertz/stiffness, viscoelastic Hertz",
     nullptr,
     1.0,
     "Debian's LIGGGHTS 3.8.0+repack1 on the pair lines dem prints "
     "(tests/dem/oblique_dem_lines_liggghts.cpp, "
     "N = 250 to 4000, six angles, the kt line and the --target-et 0.25 --reference-angle 20 one): 0.57 for "
     "steel (eps = 0.9, mu = 0.3), 0.78 for glass (E = 6e10 Pa, nu = 0.25, eps = 0.7, mu = 0.5), 0.19 for "
     "steel at eps = 0.98, mu = 0.1, not falling with N: so 1",
     "the cap tests the elastic force alone (kt |xi| > mu |F_n|) and the capped force carries no damping; "
     "below the cap the damped force may exceed mu |F_n|"},
    {TangentialKind::yade_viscel,
     "yade_viscel",
     "yade",
     "YADE",
     "ViscElPhys",
     {HistoryKind::displacement, StiffnessGrowth::constant, false, CapTest::elastic_force, false},
     kHalfOverlap,
     {TorqueArm::radius_minus_overlap, TorqueArm::radius_minus_overlap},
     "N/m",
     nullptr,
     LawKind::linear_dashpot,
     "YADE's ViscElPhys pairs its shear spring with a linear normal force (kn delta + cn delta')",
     "the model is in the library (docs/oblique.md)",
     std::nan(""),
     "not measured: restitution dem prints no ViscElPhys lines",
     "the cap tests the elastic shear force alone (|F_e| > tan(frictionAngle) |F_n|, F_e = -ks xi) and the "
     "capped force carries no damping; below the cap the damped force may exceed it"},
    lammps_model(
        TangentialKind::mindlin_rescale, "mindlin_rescale",
        {HistoryKind::displacement, StiffnessGrowth::contact_radius, true, CapTest::trial_force, false},
        "N/m^2", mindlin_null, 1.0, kLammpsBasis),
    lammps_model(TangentialKind::mindlin_force, "mindlin/force",
                 {HistoryKind::force, StiffnessGrowth::contact_radius, false, CapTest::trial_force, false},
                 "N/m^2", mindlin_null, 3.0, kLammpsForceBasis),
    lammps_model(TangentialKind::mindlin_rescale_force, "mindlin_rescale/force",
                 {HistoryKind::force, StiffnessGrowth::contact_radius, true, CapTest::trial_force, false},
                 "N/m^2", mindlin_null, 3.0, kLammpsForceBasis),
    {TangentialKind::yade_mindlin,
     "yade_mindlin",
     "yade",
     "YADE",
     "MindlinPhys",
     {HistoryKind::force, StiffnessGrowth::overlap, false, CapTest::elastic_force, true},
     {TorqueArm::radius_minus_half_overlap, TorqueArm::radius},
     {TorqueArm::radius_minus_overlap, TorqueArm::radius},
     "N/m^1.5",
     yade_kso,
     LawKind::tsuji_hertz,
     "YADE's MindlinPhys pairs its shear spring with the Tsuji normal force (kno delta^1.5 + cn delta', cn = "
     "2 "
     "betan sqrt(m* kn))",
     "`restitution dem --code yade --friction MU` prints its oblique impacts (docs/oblique.md)",
     3.0,
     "Debian's YADE 2023.02a on the betan lines dem prints (two 1 mm spheres, eight angles 1-85 deg, "
     "tests/dem/oblique_yade_mindlin.cpp), first order in dt: 2.31 for steel (A = 1e-7 s, eps = 0.914, mu = "
     "0.3), 2.61 for glass (E = 6e10 Pa, nu = 0.25, eps = 0.7, mu = 0.5), 1.41 for steel at eps = 0.98, mu = "
     "0.1: so 3",
     "the cap tests the elastic shear force alone (|F_e| > tan(frictionAngle) F_n, F_e' = -ks s incremental) "
     "and the capped force carries no damping; below the cap the damped force may exceed it"},
}};

}  // namespace

std::span<const TangentialModel> tangential_models() {
  return kModels;
}

const TangentialModel& tangential_model(TangentialKind kind) {
  return kModels.at(static_cast<std::size_t>(kind));
}

const TangentialModel* find_tangential_model(std::string_view name) {
  for (const TangentialModel& m : kModels) {
    if (name == m.name) return &m;
  }
  return nullptr;
}

const char* tangential_name(TangentialKind kind) {
  return tangential_model(kind).name;
}

const std::vector<std::string>& tangential_names() {
  static const std::vector<std::string> names{tangential_names_of("")};
  return names;
}

std::vector<std::string> tangential_names_of(std::string_view code) {
  std::vector<std::string> names;
  for (const TangentialModel& m : kModels) {
    if (code.empty() || code == m.code) names.emplace_back(m.name);
  }
  return names;
}

TangentialKind tangential_from_name(const std::string& name) {
  if (const TangentialModel* m = find_tangential_model(name); m != nullptr) return m->kind;
  throw InvalidInput(
      fmt::format("unknown tangential model '{}' (choose {})", name, alternatives(tangential_names())));
}

bool is_lammps_mindlin(TangentialKind kind) {
  const TangentialModel& m = tangential_model(kind);
  return std::string_view(m.code) == "lammps" && m.rule.growth == StiffnessGrowth::contact_radius;
}

}  // namespace restitution::oblique
