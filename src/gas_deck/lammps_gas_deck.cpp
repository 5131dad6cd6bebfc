// SPDX-License-Identifier: BSD-3-Clause
#include "gas_deck/lammps_gas_deck.hpp"

#include <fmt/core.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <numbers>
#include <stdexcept>

#include "damping_check/constant_eps_lines.hpp"
#include "damping_check/inverse.hpp"
#include "dem/deck_eps.hpp"
#include "dem/deck_notes.hpp"
#include "dem/dem_codes.hpp"
#include "dem/integrator_eps.hpp"
#include "gas_deck/cooling_scales.hpp"
#include "gas_deck/gas_log_setup.hpp"
#include "gas_deck/placement.hpp"
#include "restitution/errors.hpp"
#include "restitution/units.hpp"

namespace restitution::gas_deck {
namespace {

// The time step is checked down to this fraction of the initial temperature (the fast speed falls 1000-fold).
constexpr int kCheckedDecadesOfSpeed = 3;
// The clustering warning: the longest shear mode grows at least this many times over the run ...
constexpr double kClusteringGrowth = 2.0;
// ... and reaches this fraction of the thermal speed.
constexpr double kClusteringAmplitude = 0.1;
// The driven gas has relaxed to e^-10 of its distance from the steady state after this many relaxation times.
constexpr double kRelaxationTimes = 10.0;
// The most time steps a deck may ask for: ~1e10 steps of 2000 spheres is already weeks of one core.
constexpr double kMostSteps = 1e10;

// The companion of the code's law lines: LAMMPS `damping tsuji` (`dem --constant-eps`), LIGGGHTS `model
// hertz` given the coefficientRestitution that its recipe (Tsuji-type damping, speed-independent ε) turns
// into the law's ε at the calibration speed.
damping_check::ConstantEpsLines model_hertz_lines(const dem::LinesResult& law, const dem::Pair& pair,
                                                  double tolerance, CollisionSolver& solver) {
  const double k =
      hertz_stiffness(pair.effective_modulus_pa, pair.effective_radius_m) / pair.effective_mass_kg;
  damping_check::ConstantEpsLines c;
  c.velocity_m_s = law.reference_velocity_m_s;
  c.eps = dem::eps_for(hertz_constants(k, law.dissipative_constant_s).beta, c.velocity_m_s, law.deck.end,
                       tolerance, solver);
  damping_check::InverseRequest request;
  request.recipe = damping_check::Recipe::liggghts_hertz;
  request.target_eps = c.eps;
  request.target_velocity_m_s = c.velocity_m_s;
  request.clamp =
      law.deck.end == CollisionEnd::delayed_recovery ? damping_check::Clamp::on : damping_check::Clamp::off;
  request.speeds_m_s = {c.velocity_m_s};
  request.tolerance = tolerance;
  c.eps_to_request = damping_check::invert_recipe(request, solver).eps_to_request;
  c.lines = {
      fmt::format("fix dem_youngs all property/global youngsModulus peratomtype {}",
                  dem::num(pair.young_modulus_pa)),
      fmt::format("fix dem_poisson all property/global poissonsRatio peratomtype {}",
                  dem::num(pair.poisson_ratio)),
      fmt::format("fix dem_restitution all property/global coefficientRestitution peratomtypepair 1 {}",
                  dem::num(c.eps_to_request)),
      "fix dem_cof all property/global coefficientFriction peratomtypepair 1 0",
      fmt::format("pair_style gran model hertz tangential no_history limitForce {}",
                  law.deck.end == CollisionEnd::delayed_recovery ? "on" : "off"),
      "pair_coeff * *"};
  return c;
}

damping_check::ConstantEpsLines companion_lines(const dem::LinesResult& law, const dem::Pair& pair,
                                                double tolerance, CollisionSolver& solver) {
  switch (dem::code_entry(law.deck.code).companion) {
    case dem::Companion::damping_tsuji:
      return damping_check::constant_eps_lines(law, pair, tolerance, solver);
    case dem::Companion::model_hertz:
      return model_hertz_lines(law, pair, tolerance, solver);
    case dem::Companion::none:
      break;
  }
  throw std::logic_error(
      fmt::format("a gas deck for {}, which has no constant-eps companion", dem::code_name(law.deck.code)));
}

// The schedule's idioms: LAMMPS evaluates $(...) in place; LIGGGHTS 3.8.0 has no immediate variables, so its
// values go through equal-style variables, substituted when the line is read.
struct ScheduleIdioms {
  std::string definitions, time, temperature, timestep, step, next_timestep;
  [[nodiscard]] std::string steps_to(double t) const;
  bool immediate = true;  // dem::CodeEntry::immediate_variables
};

ScheduleIdioms schedule_idioms(dem::Code code) {
  const bool immediate = dem::code_entry(code).immediate_variables;
  if (immediate) {
    return {"",           "$(time:%.10g)", "$(v_temperature:%.10g)",
            "$(dt:%.6g)", "$(step)",       "$(v_dt0*(v_T0/v_temperature)^0.1)",
            immediate};
  }
  return {
      "variable gas_time equal time\nvariable gas_temperature equal v_temperature\n"
      "variable gas_dt equal dt\nvariable gas_step equal step\n"
      "variable gas_next_dt equal v_dt0*(v_T0/v_temperature)^0.1\n",
      "${gas_time}",
      "${gas_temperature}",
      "${gas_dt}",
      "${gas_step}",
      "${gas_next_dt}",
      immediate};
}

std::string ScheduleIdioms::steps_to(double t) const {
  if (immediate) return fmt::format("run $(ceil(({}-time)/dt):%.0f)\n", t);
  return fmt::format("variable gas_steps equal ceil(({}-time)/dt)\nrun ${{gas_steps}}\n", t);
}

std::string data_file(const GasDeck& g, const std::vector<Vec3>& x, const std::vector<Vec3>& v,
                      double density, std::uint64_t seed) {
  fmt::memory_buffer out;
  auto it = std::back_inserter(out);
  fmt::format_to(it, "LAMMPS data file: freely cooling gas written by restitution gas --deck (seed {})\n\n",
                 seed);
  fmt::format_to(it, "{} atoms\n1 atom types\n\n", x.size());
  for (const char* axis : {"x", "y", "z"}) fmt::format_to(it, "0 {} {}lo {}hi\n", g.box_m, axis, axis);
  fmt::format_to(it, "\nAtoms # sphere\n\n");
  for (std::size_t i = 0; i < x.size(); ++i)
    fmt::format_to(it, "{} 1 {} {} {} {} {}\n", i + 1, g.diameter_m, density, x[i][0], x[i][1], x[i][2]);
  fmt::format_to(it, "\nVelocities\n\n");
  for (std::size_t i = 0; i < v.size(); ++i)
    fmt::format_to(it, "{} {} {} {} 0 0 0\n", i + 1, v[i][0], v[i][1], v[i][2]);
  return fmt::to_string(out);
}

// fix langevin on the translation (omega no, its default: frictionless spheres do not couple rotation), and
// the moments of the speed the driven gas's lines print.
std::string bath_lines(const DeckBath& b) {
  const double kelvin = b.temperature_j / kLammpsBoltzmannJK;
  return fmt::format(
      "# Langevin bath (fix_langevin.cpp of LAMMPS 20220106): drag -m v/damp and a random force uniform in\n"
      "# [-1/2, 1/2] sqrt(24 k_B T_b m/(damp dt)) per component (variance 2 k_B T_b m/(damp dt)); zero yes\n"
      "# subtracts the random forces' mean (no drift of the total momentum); T_b in K under units si:\n"
      "# {} J / {} J/K\n"
      "fix bath all langevin {} {} {} {} zero yes\n"
      "variable speed2 atom vx*vx+vy*vy+vz*vz\nvariable speed4 atom v_speed2*v_speed2\n"
      "compute moments all reduce ave v_speed2 v_speed4\n",
      b.temperature_j, kLammpsBoltzmannJK, kelvin, kelvin, b.time_s, b.seed);
}

std::string input(const GasDeck& g, dem::Code code, std::string_view law,
                  const std::vector<std::string>& header, const std::vector<std::string>& prerequisites,
                  const std::vector<std::string>& lines, const std::string& data_file_name,
                  const std::string& setup_line, const std::optional<DeckBath>& bath) {
  std::string d;
  for (const auto& h : header) d += "# " + h + "\n";
  for (const auto& p : prerequisites) d += p + "\n";
  d += "boundary p p p\n";
  d += "read_data " + data_file_name + "\n";
  for (const auto& l : lines) d += l + "\n";
  // A skin of a fifth of a diameter, checked every step: no contact is missed whatever the speeds.
  d += fmt::format("neighbor {} bin\nneigh_modify delay 0 every 1 check yes\n", 0.2 * g.diameter_m);
  d += "fix integrate all nve/sphere\n";
  d += "compute kinetic all ke\n";
  d += "variable temperature equal 2*c_kinetic/(3*atoms)\n";
  // thermo 0: output at the first and last step of each run only, which keeps c_kinetic current between runs.
  if (bath) {
    d += bath_lines(*bath);
    d += "thermo_style custom step time dt c_kinetic c_moments[1] c_moments[2]\nthermo 0\n";
  } else {
    d += "thermo_style custom step time dt c_kinetic\nthermo 0\n";
  }
  d += fmt::format("variable dt0 equal {}\nvariable T0 equal {}\n", g.time_step_s, g.initial_temperature_j);
  const ScheduleIdioms idioms = schedule_idioms(code);
  d += idioms.definitions;
  const std::string print =
      fmt::format("print \"{} law={} time_s={} temperature_j={} timestep_s={} step={}\"\n", kGasTag, law,
                  idioms.time, idioms.temperature, idioms.timestep, idioms.step);
  // The gas of this run, before its first print: --compare checks a log against the command's gas.
  d += "print \"" + setup_line + "\"\n";
  std::string prints = print;
  if (bath) {
    d += fmt::format("print \"{} bath_temperature_j={} bath_time_s={} steady_from_s={}\"\n", kDrivenSetupTag,
                     bath->temperature_j, bath->time_s, g.steady_from_s);
    prints += fmt::format(
        "print \"{} law={} time_s={} mean_v2_m2_s2=$(c_moments[1]:%.10g) "
        "mean_v4_m4_s4=$(c_moments[2]:%.10g)\"\n",
        kDrivenTag, law, idioms.time);
  }
  d += "timestep ${dt0}\nrun 0\n" + prints;
  for (double t : g.print_times_s) {
    // dt grows as the contact duration does, T^(-1/10); each block runs to the next scheduled time.
    d += "timestep " + idioms.next_timestep + "\n";
    d += idioms.steps_to(t);
    d += prints;
  }
  return d;
}

// The log-spaced times from a tenth of τ0 to the duration; with a bath up to kRelaxationTimes relaxation
// times (at most half of it), and the steady part sampled evenly after.
std::vector<double> print_schedule(const GasDeckRequest& r, GasDeck& g) {
  const double relax_end =
      r.bath ? std::min(0.5 * g.duration_s, kRelaxationTimes * r.bath->relaxation_time_s) : g.duration_s;
  const double t_first = std::max(0.1 * g.haff_time_s, 50.0 * g.time_step_s);
  std::vector<double> times;
  for (int j = 0;; ++j) {
    const double t = t_first * std::pow(10.0, static_cast<double>(j) / r.points_per_decade);
    if (t >= relax_end * (1.0 - 1e-9)) break;
    times.push_back(t);
  }
  times.push_back(relax_end);
  if (!r.bath) return times;
  g.steady_from_s = relax_end;
  const double spacing = r.bath->relaxation_time_s / kSteadySamplesPerRelaxation;
  const auto samples = static_cast<long>(std::ceil((g.duration_s - relax_end) / spacing));
  if (samples < 40) {
    throw InvalidInput(
        fmt::format("--duration: the steady half of the run ({:.4g} s) holds fewer than 10 relaxation times "
                    "({:.4g} s) to "
                    "sample; give a longer one",
                    g.duration_s - relax_end, r.bath->relaxation_time_s));
  }
  for (long k = 1; k <= samples; ++k)
    times.push_back(relax_end + (g.duration_s - relax_end) * static_cast<double>(k) / samples);
  return times;
}

// The request's own limits, before anything is solved.
void check_request(const GasDeckRequest& r) {
  if (r.particles < 2 || r.particles > kMaxParticles) {
    throw InvalidInput(
        fmt::format("--particles must be in [2, {}] (a data file of about {} bytes per sphere), got {}",
                    kMaxParticles, kDataBytesPerSphere, r.particles));
  }
  if (r.material.radius1_m != r.material.radius2_m)
    throw InvalidInput("the gas deck is for equal spheres: give one --radius");
  if (!(r.max_eps_error >= 1e-6 && r.max_eps_error <= 0.05))
    throw InvalidInput(fmt::format("--max-eps-error must be in [1e-6, 0.05], got {}", r.max_eps_error));
  if (r.points_per_decade < 1 || r.points_per_decade > 100)
    throw InvalidInput(fmt::format("--points-per-decade must be in [1, 100], got {}", r.points_per_decade));
  if (!dem::code_entry(r.code).gas_deck) {
    throw InvalidInput(fmt::format(
        "--code {}: the gas deck is written for {} only (a data file "
        "of spheres, the law's pair lines and a log-spaced schedule in their input "
        "language)",
        dem::code_name(r.code), dem::code_list(" and ", [](const dem::CodeEntry& e) { return e.gas_deck; })));
  }
  if (r.bath && !dem::code_entry(r.code).immediate_variables) {
    throw InvalidInput(
        fmt::format("--thermostat with --deck: the driven gas's deck is written for LAMMPS only "
                    "(its fix langevin and immediate variables), not --code {}",
                    dem::code_name(r.code)));
  }
}

// The largest time step that keeps the integrator's ε error within --max-eps-error at the fast end of the
// impact speeds, and the worst error it gives over the slower decades the run reaches.
void choose_time_step(const GasDeckRequest& r, const dem::Pair& pair, CollisionSolver& solver, GasDeck& g) {
  g.fast_speed_m_s = kFastSpeedFactor * std::sqrt(6.0) * r.rms_speed_m_s;
  g.time_step_s = dem::largest_time_step_s(pair, g.dissipative_constant_s, r.end, g.fast_speed_m_s,
                                           r.max_eps_error, r.tolerance, solver);
  for (int k = 0; k <= kCheckedDecadesOfSpeed; ++k) {
    const double slower = std::pow(10.0, k);
    const auto e = dem::integrator_error(pair, g.dissipative_constant_s, r.end, g.fast_speed_m_s / slower,
                                         g.time_step_s * std::pow(slower, 0.2), r.tolerance, solver);
    g.eps_error_worst = std::max(g.eps_error_worst, std::abs(e.worst_error));
  }

  // A run no code could finish is refused before a file is written (a dilute or long gas: --packing-fraction
  // 1e-300 asks for a box of 1e98 m and a run of ~1e100 steps).
  const double steps = g.duration_s / g.time_step_s;
  if (!(steps <= kMostSteps)) {
    throw InvalidInput(
        fmt::format("the run would take about {:.3g} time steps of {:.4g} s over {:.4g} s (at most {:.0e}): "
                    "give a denser gas "
                    "(--packing-fraction), a shorter --duration or a larger --max-eps-error",
                    steps, g.time_step_s, g.duration_s, kMostSteps));
  }
}

// Haff's law holds only while the constant-ε gas stays homogeneous: a warning when its shear mode will grow.
void warn_of_clustering(const GasDeckRequest& r, const GasScales& scales, GasDeck& g) {
  g.shear_critical_length_m = scales.shear_critical_length_m;
  g.shear_mode_growth = shear_mode_growth(scales, g.box_m, g.duration_s);
  // Clustering shows once the longest shear mode, of initial amplitude ~ 1/sqrt(N) of the thermal speed,
  // reaches a tenth of it by growing: only a box longer than L_c holds a growing mode, and a mode that does
  // not at least double has not grown out of the thermal noise (with N <= 100 the noise alone is a tenth).
  const double initial_amplitude = 1.0 / std::sqrt(static_cast<double>(r.particles));
  if (g.box_m > g.shear_critical_length_m && g.shear_mode_growth >= kClusteringGrowth &&
      g.shear_mode_growth * initial_amplitude >= kClusteringAmplitude) {
    g.warnings.push_back(fmt::format(
        "the constant-eps gas will cluster: its box ({:.4g} diameters) exceeds the shear-instability length "
        "L_c = {:.4g} diameters and its longest shear mode grows {:.3g}-fold in {:.4g} s ({:.3g} tau0), from "
        "about 1/sqrt(N) = {:.2g} to {:.2g} of the thermal speed; Haff's law holds only while the gas stays "
        "homogeneous (fewer particles or a shorter run keep it so)",
        g.box_m / g.diameter_m, g.shear_critical_length_m / g.diameter_m, g.shear_mode_growth, g.duration_s,
        g.duration_s / g.haff_time_s, initial_amplitude, g.shear_mode_growth * initial_amplitude));
  }
}

// The comment lines both inputs open with: what the gas is, its time step, its schedule and how to run it.
std::vector<std::string> deck_header(const GasDeckRequest& r, const GasDeck& g, const dem::LinesResult& law) {
  std::vector<std::string> header{
      fmt::format(
          "freely cooling gas written by restitution gas --deck: {} spheres of diameter {} m, mass {} kg, "
          "packing fraction {}, periodic box {} m ({:.4g} diameters), seed {}",
          r.particles, g.diameter_m, g.mass_kg, r.packing_fraction, g.box_m, g.box_m / g.diameter_m, r.seed),
      fmt::format("initial temperature T0 = m <v^2>/3 = {} J (rms speed {} m/s per direction), {} s = {:.4g} "
                  "tau0 of the constant-eps gas (tau0 = {} s)",
                  g.initial_temperature_j, r.rms_speed_m_s, g.duration_s, g.duration_s / g.haff_time_s,
                  g.haff_time_s),
      fmt::format(
          "time step: dt0 = {:.6g} s keeps the worst |eps error| of the integrator <= {:.3g} at the fast "
          "end of the impact speeds ({} x the rms relative speed = {:.4g} m/s); dt = dt0 (T0/T)^(1/10) "
          "afterwards, as the contact duration grows (worst |eps error| {:.3g} down to T0/1e6)",
          g.time_step_s, r.max_eps_error, kFastSpeedFactor, g.fast_speed_m_s, g.eps_error_worst),
      fmt::format("each line starting {} is one scheduled time (log-spaced, {} per decade): law, time_s, "
                  "temperature_j = m <v^2>/3, timestep_s, step",
                  kGasTag, r.points_per_decade),
      fmt::format("run: {}, or on several cores {} (as root add --allow-run-as-root; on oversubscribed cores "
                  "set OMPI_MCA_mpi_yield_when_idle=1), from the folder of the data file",
                  gas_deck_command(r.code, "FILE", 1), gas_deck_command(r.code, "FILE", 4)),
      "checked on " + law.deck.checked_on};
  if (r.bath) {
    header.insert(
        header.begin(),
        fmt::format("driven by a Langevin bath T_b = {} J ({} K), tau_b = {} s: it relaxes over the first "
                    "half of the run (log-spaced prints) and is sampled {} times per relaxation time "
                    "({} s) in the second, the steady part from {} s",
                    r.bath->temperature_j, r.bath->temperature_j / kLammpsBoltzmannJK, r.bath->time_s,
                    kSteadySamplesPerRelaxation, r.bath->relaxation_time_s, g.steady_from_s));
  }
  header.insert(header.end(), g.warnings.begin(), g.warnings.end());

  return header;
}

}  // namespace

GasDeck lammps_gas_deck(const GasDeckRequest& r, const std::string& data_file_name) {
  check_request(r);
  dem::LinesRequest lines_request;
  lines_request.code = r.code;
  lines_request.end = r.end;
  lines_request.material = r.material;
  lines_request.damping = r.damping;
  lines_request.tolerance = r.tolerance;
  const dem::LinesResult law = dem::check_lines(lines_request);
  const dem::Pair pair = dem::pair_of(r.material);
  CollisionSolver solver;
  const damping_check::ConstantEpsLines companion = companion_lines(law, pair, r.tolerance, solver);

  GasDeck g;
  g.dissipative_constant_s = law.dissipative_constant_s;
  g.diameter_m = 2.0 * pair.radius1_m;
  g.mass_kg = pair.mass1_kg;
  g.initial_temperature_j = g.mass_kg * r.rms_speed_m_s * r.rms_speed_m_s;
  g.constant_eps = companion.eps;
  g.calibration_speed_m_s = companion.velocity_m_s;
  const GasScales scales =
      gas_scales(g.diameter_m, g.mass_kg, r.packing_fraction, g.initial_temperature_j, companion.eps);
  g.box_m = std::cbrt(static_cast<double>(r.particles) * std::numbers::pi * std::pow(g.diameter_m, 3) /
                      (6.0 * r.packing_fraction));
  g.haff_time_s = scales.haff_time_s;
  g.duration_s = r.duration_s > 0.0 ? r.duration_s : r.haff_times * g.haff_time_s;
  if (!(g.duration_s > 0.0 && std::isfinite(g.duration_s)))
    throw InvalidInput(fmt::format("--duration must be > 0 s, got {}", g.duration_s));

  choose_time_step(r, pair, solver, g);
  warn_of_clustering(r, scales, g);
  g.print_times_s = print_schedule(r, g);

  const auto positions = random_positions(r.particles, g.diameter_m, g.box_m, r.seed);
  const auto velocities = maxwellian_velocities(r.particles, r.rms_speed_m_s, r.seed);
  g.data = data_file(g, positions, velocities,
                     g.mass_kg / (std::numbers::pi / 6.0 * std::pow(g.diameter_m, 3)), r.seed);

  const std::vector<std::string> header = deck_header(r, g, law);
  std::vector<std::string> law_header = header;
  law_header.insert(law_header.begin(), fmt::format("viscoelastic Hertz law, A = {:.10g} s ({} end)",
                                                    g.dissipative_constant_s, end_name(r.end)));
  g.law_input =
      input(g, r.code, "viscoelastic", law_header, law.deck.prerequisites, law.deck.lines, data_file_name,
            gas_log_setup_line(gas_log_setup(r, g.dissipative_constant_s, "viscoelastic")), r.bath);
  std::vector<std::string> companion_header = header;
  companion_header.insert(
      companion_header.begin(),
      fmt::format("constant-eps companion: {} given {:.10g}, which makes eps = {:.10g} at every speed (the "
                  "law's eps at {} m/s)",
                  dem::code_entry(r.code).companion_words, companion.eps_to_request, companion.eps,
                  companion.velocity_m_s));
  g.constant_eps_input = input(
      g, r.code, "constant-eps", companion_header, law.deck.prerequisites, companion.lines, data_file_name,
      gas_log_setup_line(gas_log_setup(r, g.dissipative_constant_s, "constant-eps")), r.bath);
  return g;
}

std::string gas_deck_command(dem::Code code, const std::string& path, int ranks) {
  const char* program = dem::code_entry(code).program;
  if (ranks <= 1) return fmt::format("{} -in {}", program, path);
  return fmt::format("mpirun -np {} {} -in {}", ranks, program, path);
}

}  // namespace restitution::gas_deck
