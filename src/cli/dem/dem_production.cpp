// SPDX-License-Identifier: BSD-3-Clause
#include "cli/dem/dem_production.hpp"

#include <fmt/core.h>

#include "dem/dem_codes.hpp"

namespace restitution::cli {

void add_production_options(CLI::App& cmd, ProductionOptions& o) {
  cmd.add_option("--timestep", o.timestep,
                 "time step dt in s of a production run (lammps, liggghts): report the eps error their "
                 "velocity-Verlet makes at dt at each speed, mean and worst over where the contact starts "
                 "between steps");
  cmd.add_option(
      "--max-eps-error", o.max_eps_error,
      "largest |eps error| in [1e-7, 0.1] allowed (lammps, liggghts): report the largest dt that keeps "
      "the worst one within it at each speed");
  cmd.add_flag(
      "--constant-eps", o.constant_eps,
      "also print the constant-eps companion lines (lammps: damping tsuji giving the law's eps at the "
      "calibration speed at every speed)");
}

bool any_production_option(const ProductionOptions& o) {
  return o.timestep || o.max_eps_error || o.constant_eps;
}

Production production(const dem::LinesResult& r, const Material& material, const ProductionOptions& o,
                      double tolerance) {
  return damping_check::check_production(r, material,
                                         {o.timestep, o.max_eps_error, o.constant_eps, tolerance});
}

void print_production_text(const dem::LinesResult& r, const Production& p, const ProductionOptions& o) {
  const char* c = dem::code_entry(r.deck.code).comment;
  fmt::print("{} contact duration of the law at each speed:\n", c);
  for (std::size_t i = 0; i < r.eps.size(); ++i)
    fmt::print("{}   v = {:<10.6g} m/s  contact {:.6g} s\n", c, r.eps[i].velocity_m_s,
               p.contact_duration_s[i]);
  if (o.timestep) {
    fmt::print(
        "{} eps error of velocity-Verlet (fix nve/sphere) at dt = {} s, over {} phases of the contact "
        "start:\n",
        c, *o.timestep, dem::kIntegratorPhases);
    for (const auto& e : p.errors) {
      fmt::print("{}   v = {:<10.6g} m/s  dt/contact = {:.4g}  mean {:+.3e}  worst {:+.3e}\n", c,
                 e.velocity_m_s, *o.timestep / e.contact_duration_s, e.mean_error, e.worst_error);
    }
  }
  if (o.max_eps_error) {
    fmt::print("{} largest dt keeping the worst |eps error| <= {}:", c, *o.max_eps_error);
    for (std::size_t i = 0; i < r.eps.size(); ++i)
      fmt::print(" {:.4g} s at {:g} m/s;", p.largest_time_step_s[i], r.eps[i].velocity_m_s);
    fmt::print(" all speeds: {:.4g} s\n", *p.largest_time_step_all_s);
  }
  if (p.constant_eps) {
    fmt::print(
        "{} constant-eps companion (instead of the lines above): eps = {:.10g} at every speed, the law's at "
        "{:g} m/s; damping tsuji given {:.10g}:\n",
        c, p.constant_eps->eps, p.constant_eps->velocity_m_s, p.constant_eps->eps_to_request);
    for (const auto& line : p.constant_eps->lines) fmt::print("{}   {}\n", c, line);
  }
}

void write_production_json(JsonWriter& json, const dem::LinesResult& r, const Production& p,
                           const ProductionOptions& o) {
  json.key("contact_durations").begin_array();
  for (std::size_t i = 0; i < r.eps.size(); ++i) {
    json.begin_object().field("velocity_m_s", r.eps[i].velocity_m_s);
    json.field("contact_duration_s", p.contact_duration_s[i]).end_object();
  }
  json.end_array();
  if (o.timestep) {
    json.key("timestep")
        .begin_object()
        .field("time_step_s", *o.timestep)
        .field("phases", dem::kIntegratorPhases);
    json.key("errors").begin_array();
    for (const auto& e : p.errors) {
      json.begin_object().field("velocity_m_s", e.velocity_m_s).field("eps_law", e.eps_law);
      json.field("mean_eps_error", e.mean_error).field("worst_eps_error", e.worst_error).end_object();
    }
    json.end_array().end_object();
  }
  if (o.max_eps_error) {
    json.key("max_eps_error").begin_object().field("bound", *o.max_eps_error);
    json.field("largest_time_step_s", *p.largest_time_step_all_s);
    json.key("per_speed").begin_array();
    for (std::size_t i = 0; i < r.eps.size(); ++i) {
      json.begin_object().field("velocity_m_s", r.eps[i].velocity_m_s);
      json.field("largest_time_step_s", p.largest_time_step_s[i]).end_object();
    }
    json.end_array().end_object();
  }
  if (p.constant_eps) {
    json.key("constant_eps").begin_object().field("eps", p.constant_eps->eps);
    json.field("velocity_m_s", p.constant_eps->velocity_m_s)
        .field("eps_to_request", p.constant_eps->eps_to_request);
    json.field("lines", p.constant_eps->lines).end_object();
  }
}

}  // namespace restitution::cli
