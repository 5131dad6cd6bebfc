// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// What the oblique-impact checks against the DEM codes share (tests/dem/oblique_*.cpp): the impact angles, an
// impact's outputs as a code reports them, the impact velocity of a unit speed, Richardson's extrapolation of
// a first-order integrator, the record of the largest e_t difference, LIGGGHTS's and YADE's runs of printed
// lines and the run of a check deck's oblique section.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "dem/code_runner.hpp"
#include "oblique/oblique_contact.hpp"

namespace restitution::test_support {

// Nearly head-on to grazing, degrees from the normal.
inline const std::vector<double> kObliqueAnglesDeg{1.0, 5.0, 10.0, 20.0, 30.0, 45.0, 60.0, 75.0, 85.0};

// One impact as a code reports it: e_t, the rebound angle (degrees) and the spins (rad/s, ours: -ω_y).
struct ObliqueOutcome {
  double et = 0.0, rebound_deg = 0.0, spin = 0.0, spin2 = 0.0;
};

// Speed 1 m/s at angle_deg from the normal, the first sphere spinning at spin_rad_s.
inline oblique::ImpactVelocity impact_at(double angle_deg, double spin_rad_s) {
  const double a = angle_deg * std::numbers::pi / 180.0;
  return {std::cos(a), std::sin(a), spin_rad_s, 0.0};
}

// The dt → 0 limit of a first-order integrator from runs at dt (coarse) and dt/10 (fine).
inline double extrapolate_first_order(double coarse, double fine) {
  return fine + (fine - coarse) / 9.0;
}

// Checks a code's impact, extrapolated from runs at dt (coarse) and dt/10 (fine), against the library's
// `predicted` one: e_t within 1e-4 relative (1e-5 absolute near 0), the rebound angle and the spins (the
// second for a pair) within 1e-4 relative. Returns |Δe_t|.
inline double expect_extrapolated_agreement(const ObliqueOutcome& coarse, const ObliqueOutcome& fine,
                                            const oblique::ObliqueResult& predicted, bool pair,
                                            double radius_m, const std::string& label) {
  const auto extrapolate = extrapolate_first_order;
  const double et = extrapolate(coarse.et, fine.et);
  const std::string where =
      label + ": coarse e_t " + std::to_string(coarse.et) + ", fine " + std::to_string(fine.et);
  EXPECT_NEAR(et, predicted.tangential_restitution,
              std::max(1e-4 * std::abs(predicted.tangential_restitution), 1e-5))
      << where;
  const double rebound_deg = predicted.rebound_angle_rad * 180.0 / std::numbers::pi;
  EXPECT_NEAR(extrapolate(coarse.rebound_deg, fine.rebound_deg), rebound_deg,
              1e-4 * std::abs(rebound_deg) + 1e-5)
      << where;
  EXPECT_NEAR(extrapolate(coarse.spin, fine.spin), predicted.spin_first_rad_s,
              1e-4 * std::abs(predicted.spin_first_rad_s) + 1e-5 / radius_m)
      << where;
  if (pair) {
    EXPECT_NEAR(extrapolate(coarse.spin2, fine.spin2), predicted.spin_second_rad_s,
                1e-4 * std::abs(predicted.spin_second_rad_s) + 1e-5 / radius_m)
        << where;
  }
  return std::abs(et - predicted.tangential_restitution);
}

// The largest |e_t difference| of a test, in its XML record and on stdout.
inline void record_largest_et_difference(double largest) {
  std::ostringstream text;
  text << std::scientific << largest;
  testing::Test::RecordProperty("largest_et_difference", text.str());
  std::cout << "largest |e_t difference|: " << text.str() << "\n";
}

inline constexpr double kObliqueRunRadius = 1e-3;  // m: the steel beads of the checks (density 7800 kg/m³)

// LIGGGHTS (`program`) on `lines` (as `restitution dem --code liggghts` prints them) at 1 m/s, one collision
// per angle of two 1 mm steel spheres (or one on a primitive zplane), run_time s at dt s. The deck:
// LIGGGHTS's slip is vtr = vt - d × (R - δ/2) ω / r with d from the other body to the moving sphere (+z), so
// our spins are -ω_y, as in LAMMPS. A pair: atom 2k+2 moves onto atom 2k+1 at rest; a wall: atom k+1 onto a
// primitive zplane at z = 0.
inline std::vector<ObliqueOutcome> run_liggghts_oblique(const std::string& program,
                                                        const std::vector<std::string>& lines, bool wall,
                                                        double spin, double dt, double run_time,
                                                        const std::vector<double>& angles_deg) {
  TempFolder folder;
  const auto steps = static_cast<long>(std::ceil(run_time / dt));
  const std::size_t per_angle = wall ? 1 : 2;
  std::ostringstream deck;
  deck.precision(17);
  deck << "units si\natom_style granular\natom_modify map array\nnewton off\ncommunicate single vel yes\n"
       << "boundary f f f\nregion box block -0.05 0.05 -0.01 0.01 -0.01 0.01 units box\ncreate_box 1 box\n";
  for (std::size_t i = 0; i < angles_deg.size(); ++i) {
    const double x = -0.04 + 0.01 * static_cast<double>(i);
    if (!wall) deck << "create_atoms 1 single " << x << " 0 0 units box\n";
    deck << "create_atoms 1 single " << x << " 0 " << (wall ? kObliqueRunRadius : 2.0 * kObliqueRunRadius)
         << " units box\n";
  }
  deck << "set type 1 diameter " << 2.0 * kObliqueRunRadius << "\nset type 1 density 7800\n";
  for (std::size_t i = 0; i < angles_deg.size(); ++i) {
    const double a = angles_deg[i] * std::numbers::pi / 180.0;
    deck << "set atom " << per_angle * (i + 1) << " vx " << std::sin(a) << " vy 0 vz " << -std::cos(a)
         << " omegax 0 omegay " << -spin << " omegaz 0\n";
  }
  deck << "# the lines `restitution dem --code liggghts` printed:\n";
  for (const std::string& line : lines) deck << line << "\n";
  deck << "neighbor " << 0.1 * kObliqueRunRadius << " bin\nneigh_modify delay 0\n";
  if (wall) {
    // The wall takes the pair style's model words, then the primitive, then its settings
    // (tangential_damping, limitForce), and the per-type-pair parameters of type 1.
    const std::string models = "model hertz/stiffness tangential history";
    const std::string& style = lines.at(5);
    const std::size_t after_models = style.find(models) + models.size();
    deck << "fix w all wall/gran " << models << " primitive type 1 zplane 0.0" << style.substr(after_models)
         << "\n";
  }
  deck << "fix 1 all nve/sphere\ntimestep " << dt << "\nthermo " << steps << "\n"
       << "dump d all custom " << steps << " " << (folder.path / "out.dump").string() << " id vx vz omegay\n"
       << "dump_modify d sort id format \"%d %.17g %.17g %.17g\"\nrun " << steps << "\n";
  std::ofstream(folder.path / "in.liggghts") << deck.str();
  const std::string command = program + " -log none -in " + (folder.path / "in.liggghts").string() + " > " +
                              (folder.path / "out.txt").string() + " 2>&1";
  EXPECT_EQ(std::system(command.c_str()), 0) << command << "\n" << slurp((folder.path / "out.txt").string());
  std::istringstream dump(slurp((folder.path / "out.dump").string()));
  std::vector<std::string> rows;
  for (std::string line; std::getline(dump, line);) rows.push_back(line);
  const std::size_t atoms = per_angle * angles_deg.size();
  EXPECT_GE(rows.size(), atoms) << deck.str();
  std::vector<std::array<double, 3>> v(atoms);  // vx, vz, ω_y by id - 1
  for (std::size_t k = rows.size() - std::min(rows.size(), atoms); k < rows.size(); ++k) {
    std::istringstream row(rows.at(k));
    long id = 0;
    std::array<double, 3> values{};
    row >> id >> values[0] >> values[1] >> values[2];
    v.at(static_cast<std::size_t>(id - 1)) = values;
  }
  std::vector<ObliqueOutcome> out(angles_deg.size());
  for (std::size_t i = 0; i < angles_deg.size(); ++i) {
    const auto& moving = v[per_angle * (i + 1) - 1];
    const std::array<double, 3> rest = wall ? std::array<double, 3>{} : v[per_angle * i];
    const double s0 = std::sin(angles_deg[i] * std::numbers::pi / 180.0) + kObliqueRunRadius * spin;
    const double dvx = moving[0] - rest[0];
    const double dvz = moving[1] - rest[1];
    out[i] = {-(dvx - kObliqueRunRadius * moving[2] - kObliqueRunRadius * rest[2]) / s0,
              std::atan2(dvx, dvz) * 180.0 / std::numbers::pi, -moving[2], -rest[2]};
  }
  return out;
}

// YADE (`program`) on `yade_lines` (the material's append, the Ip2 functor, the Law2 functor, as `restitution
// dem --code yade` prints them) at 1 m/s, one collision per angle of two 1 mm spheres 10 mm apart (body 2k+1
// onto body 2k at rest) or one on a utils.wall at z = 0 (body k), run_time s at dt s. YADE's contact-point
// velocity is v + ω × c with c from the centre to the contact point, below the moving sphere: our spins are
// -ω_y, as for LAMMPS.
inline std::vector<ObliqueOutcome> run_yade_oblique(const std::string& program,
                                                    const std::vector<std::string>& yade_lines,
                                                    const std::vector<double>& angles_deg, bool wall,
                                                    double spin, double dt, double run_time) {
  TempFolder folder;
  const auto steps = static_cast<long>(std::ceil(run_time / dt));
  std::ostringstream script;
  script.precision(17);
  script << "import math\nR, SPIN = " << kObliqueRunRadius << ", " << spin << "\nANGLES = [";
  for (const double a : angles_deg) script << a << ", ";
  script << "]\nWALL = " << (wall ? "True" : "False") << "\n"
         << "mat = " << yade_lines.at(0) << "\nIP2 = " << yade_lines.at(1) << "\nLAW2 = " << yade_lines.at(2)
         << "\n"
         << R"(moving = []
for i, a in enumerate(ANGLES):
    x = -0.04 + 0.01 * i
    if not WALL:
        O.bodies.append(sphere((x, 0, 0), R, material=mat))
    b = O.bodies.append(sphere((x, 0, R if WALL else 2 * R), R, material=mat))
    O.bodies[b].state.vel = Vector3(math.sin(math.radians(a)), 0, -math.cos(math.radians(a)))
    O.bodies[b].state.angVel = Vector3(0, -SPIN, 0)
    moving.append(b)
if WALL:
    O.bodies.append(utils.wall(0, axis=2, material=mat))
O.engines = [
    ForceResetter(),
    InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Wall_Aabb()]),
    InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Wall_Sphere_ScGeom()],
                    [IP2], [LAW2]),
    NewtonIntegrator(damping=0, gravity=(0, 0, 0)),
]
)"
         << "O.dt = " << dt << "\nO.run(" << steps << ", True)\n"
         << R"(for i, b in enumerate(moving):
    s = O.bodies[b].state
    r = O.bodies[b - 1].state if not WALL else None
    print('RESTITUTION_OBLIQUE %d %.17g %.17g %.17g %.17g' % (
        i, s.vel[0] - (r.vel[0] if r else 0), s.vel[2] - (r.vel[2] if r else 0), s.angVel[1],
        r.angVel[1] if r else 0))
)";
  std::ofstream(folder.path / "oblique.py") << script.str();
  const std::string output_path = (folder.path / "out.txt").string();
  const std::string command =
      program + " -n -x " + (folder.path / "oblique.py").string() + " > " + output_path + " 2>&1";
  EXPECT_EQ(std::system(command.c_str()), 0) << command << "\n" << slurp(output_path);
  std::vector<ObliqueOutcome> out(angles_deg.size());
  std::size_t read = 0;
  std::istringstream lines(slurp(output_path));
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("RESTITUTION_OBLIQUE ", 0) != 0) continue;
    std::istringstream row(line.substr(20));
    std::size_t i = 0;
    std::array<double, 4> v{};  // Δvx, Δvz, ω_y of the moving sphere and of the one at rest
    row >> i >> v[0] >> v[1] >> v[2] >> v[3];
    const auto [dvx, dvz, wy, wy_rest] = v;
    const double s0 = impact_at(angles_deg.at(i), spin).tangential_m_s + kObliqueRunRadius * spin;
    out.at(i) = {-(dvx - kObliqueRunRadius * wy - kObliqueRunRadius * wy_rest) / s0,
                 std::atan2(dvx, dvz) * 180.0 / std::numbers::pi, -wy, -wy_rest};
    ++read;
  }
  EXPECT_EQ(read, angles_deg.size()) << script.str() << "\n" << slurp(output_path);
  return out;
}

// The check lines of a deck `restitution dem --code CODE --friction MU --deck` wrote, run by CODE's program.
struct CheckDeckRun {
  std::size_t head_on = 0;    // restitution-check lines
  std::size_t oblique = 0;    // restitution-oblique-check lines
  double largest_diff = 0.0;  // the largest |diff| of those
};

// Runs `deck` with `code`'s program and checks each oblique line against `impacts` (the command's JSON
// oblique.impacts, in order): its code, angle and et_restitution as printed, |diff| <= tolerance and et_code
// within tolerance of the printed e_t.
inline CheckDeckRun run_oblique_check_deck(dem::Code code, const std::filesystem::path& deck,
                                           const nlohmann::json& impacts, double tolerance) {
  CheckDeckRun run;
  const std::string program = dem::dem_program(code);
  EXPECT_FALSE(program.empty()) << dem::code_name(code) << " not found on PATH: scripts/setup installs it";
  if (program.empty()) return run;
  const auto out = deck.parent_path() / "out.txt";
  const std::string command = program + " -log none -in " + deck.string() + " > " + out.string() + " 2>&1";
  EXPECT_EQ(std::system(command.c_str()), 0) << command << "\n" << slurp(out.string());
  std::istringstream text(slurp(out.string()));
  const std::string code_field = std::string(" code=") + dem::code_name(code) + " ";
  for (std::string line; std::getline(text, line);) {
    if (line.rfind("restitution-check ", 0) == 0) ++run.head_on;
    if (line.rfind("restitution-oblique-check ", 0) != 0) continue;
    if (run.oblique >= impacts.size()) {
      ADD_FAILURE() << "more oblique check lines than impacts: " << line;
      break;
    }
    const auto field = [&](const std::string& key) {
      const std::size_t at = line.find(" " + key + "=");
      EXPECT_NE(at, std::string::npos) << key << " in " << line;
      return at == std::string::npos ? NAN : std::stod(line.substr(at + key.size() + 2));
    };
    const auto& impact = impacts[run.oblique];
    EXPECT_NE(line.find(code_field), std::string::npos) << line;
    EXPECT_EQ(field("angle"), impact["angle_deg"].get<double>()) << line;
    EXPECT_NEAR(field("et_restitution"), impact["tangential_restitution"].get<double>(), 1e-12) << line;
    const double diff = field("diff");
    EXPECT_NEAR(diff, 0.0, tolerance) << line;
    EXPECT_NEAR(field("et_code"), impact["tangential_restitution"].get<double>(), tolerance) << line;
    // NaN (an unparsed diff) must not pass as small.
    run.largest_diff = std::isnan(diff) ? diff : std::max(run.largest_diff, std::abs(diff));
    ++run.oblique;
  }
  return run;
}

}  // namespace restitution::test_support
