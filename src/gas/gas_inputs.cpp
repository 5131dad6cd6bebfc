// SPDX-License-Identifier: BSD-3-Clause
#include "restitution_gas/gas_inputs.hpp"

#include <fmt/core.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>

#include "gas/collision_integral.hpp"
#include "restitution/collision_solver.hpp"
#include "restitution/errors.hpp"
#include "restitution/material.hpp"
#include "restitution/units.hpp"
#include "restitution_gas/gas_parameters.hpp"

namespace restitution::gas {
namespace {

// The argument as the caller spells it.
std::string spelled(const char* keyword, ArgumentStyle style) {
  return style == ArgumentStyle::keyword ? keyword : option_name(keyword);
}

class Rules {
 public:
  explicit Rules(ArgumentStyle style) : style_(style) {}

  [[nodiscard]] std::string operator()(const char* keyword) const { return spelled(keyword, style_); }

  // Exactly one of two arguments.
  template <class T>
  const T& one_of(const std::optional<T>& a, const char* a_name, const std::optional<T>& b,
                  const char* b_name) const {
    if (a.has_value() == b.has_value()) {
      throw InvalidInput(fmt::format("give exactly one of {} and {}", (*this)(a_name), (*this)(b_name)));
    }
    return a ? *a : *b;
  }

  void require_positive(const std::optional<double>& value, const char* keyword, const char* unit) const {
    if (value && !(std::isfinite(*value) && *value > 0.0)) {
      throw InvalidInput(fmt::format("{} must be finite and > 0{}, got {}", (*this)(keyword), unit, *value));
    }
  }

 private:
  ArgumentStyle style_;
};

// Mass [kg] and diameter [m] of the gas's spheres: radius with mass or density.
GasParticles particles_of(const GasInputs& in, const Rules& name) {
  if (!in.radius_m) {
    throw InvalidInput(
        fmt::format("the gas needs {} (and {} or {})", name("radius"), name("density"), name("mass")));
  }
  name.require_positive(in.radius_m, "radius", " m");
  name.require_positive(in.density_kg_m3, "density", " kg/m^3");
  name.require_positive(in.mass_kg, "mass", " kg");
  GasParticles p;
  p.diameter_m = 2.0 * *in.radius_m;
  (void)name.one_of(in.mass_kg, "mass", in.density_kg_m3, "density");
  p.mass_kg = in.mass_kg ? *in.mass_kg : sphere_mass_kg(*in.radius_m, *in.density_kg_m3);
  if (!std::isnormal(p.mass_kg)) {
    throw InvalidInput(fmt::format("{} and {} give a sphere mass of {} kg, beyond the doubles",
                                   name("radius"), name("density"), p.mass_kg));
  }
  if (!in.packing_fraction) throw InvalidInput(fmt::format("the gas needs {}", name("packing_fraction")));
  if (!(*in.packing_fraction > 0.0 && *in.packing_fraction < 0.5)) {
    throw InvalidInput(fmt::format("{} must be in (0, 0.5) (a homogeneous fluid), got {}",
                                   name("packing_fraction"), *in.packing_fraction));
  }
  p.packing_fraction = *in.packing_fraction;
  return p;
}

// τ₀ inside the range the theory computes in (restitution_gas/cooling.hpp), or a refusal naming the packing
// fraction and the range of it that works for the other inputs: τ₀ ∝ 1/(φ g₂(φ)) with g₂ growing with φ, so
// scaling φ by the factor τ₀ is off brings τ₀ inside (or further, by g₂).
void check_haff_time(const CoolingRequest& r, const GasInputs& in, const Rules& name) {
  const double log_tau0 = log_haff_time(r);
  const double log_longest = std::log(kLongestHaffTimeS);
  const double log_shortest = std::log(kShortestHaffTimeS);
  if (log_tau0 >= log_shortest && log_tau0 <= log_longest) return;
  const double phi = r.particles.packing_fraction;
  const bool too_long = log_tau0 > log_longest;
  const double bound = phi * std::exp(log_tau0 - (too_long ? log_longest : log_shortest));
  const std::string why = fmt::format(
      "{} = {:g} with these spheres, law and {} gives the Haff time tau0 = 1e{:.0f} s, outside "
      "[{:g}, {:g}] s where the theory's times and rates are doubles",
      name("packing_fraction"), phi, in.rms_speed_m_s ? name("rms_speed") : name("temperature"),
      log_tau0 / std::log(10.0), kShortestHaffTimeS, kLongestHaffTimeS);
  if (too_long && bound < 0.5) {
    throw InvalidInput(
        fmt::format("{}: {} must be in [{:.3g}, 0.5) here", why, name("packing_fraction"), bound));
  }
  if (!too_long) {
    throw InvalidInput(
        fmt::format("{}: {} must be in (0, {:.3g}] here", why, name("packing_fraction"), bound));
  }
  throw InvalidInput(fmt::format("{}: no packing fraction below 0.5 brings it inside", why));
}

ImpactLaw law_of(const GasInputs& in, const Rules& name) {
  LawKind kind = LawKind::viscoelastic_hertz;
  CollisionEnd end = CollisionEnd::delayed_recovery;
  try {
    kind = law_from_name(in.law);
  } catch (const InvalidInput& e) {
    throw InvalidInput(fmt::format("{}: {}", name("law"), e.what()));
  }
  try {
    end = end_from_name(in.end);
  } catch (const InvalidInput& e) {
    throw InvalidInput(fmt::format("{}: {}", name("end"), e.what()));
  }
  if (in.dissipative_constant_s) {
    if (in.eps || in.velocity_m_s) {
      throw InvalidInput(
          fmt::format("{} excludes {} and {}", name("dissipative_constant"), name("eps"), name("velocity")));
    }
    if (!has_dissipative_constant(kind)) {
      throw InvalidInput(fmt::format("{} belongs to {} viscoelastic-hertz; {} {} takes {} and {}",
                                     name("dissipative_constant"), name("law"), name("law"), in.law,
                                     name("eps"), name("velocity")));
    }
    if (!in.young_modulus_pa || !in.poisson_ratio) {
      throw InvalidInput(fmt::format("{} needs the material's {} and {}", name("dissipative_constant"),
                                     name("young_modulus"), name("poisson_ratio")));
    }
    MaterialFields f;
    f.young_modulus_pa = in.young_modulus_pa;
    f.poisson_ratio = in.poisson_ratio;
    f.radius_m = in.radius_m;
    f.density_kg_m3 = in.density_kg_m3;
    f.mass_kg = in.mass_kg;
    f.dissipative_constant_s = in.dissipative_constant_s;
    return hertz_impact_law(material_constants(material_from_fields(f)).hertz.beta, end);
  }
  if (!in.eps || !in.velocity_m_s) {
    throw InvalidInput(fmt::format(
        "the law needs {} with {} (the impact speed in m/s it was measured at), or {} with the material",
        name("eps"), name("velocity"), name("dissipative_constant")));
  }
  return impact_law_from_eps(kind, *in.eps, *in.velocity_m_s, end, in.tolerance);
}

}  // namespace

CoolingRequest cooling_request(const GasInputs& in, ArgumentStyle style) {
  const Rules name(style);
  CoolingRequest r;
  // Checked for every law, also viscoelastic Hertz, whose ε comes from the fast table and whose calibration
  // would otherwise take any number: the same range wherever the gas solves a collision (the default method).
  const double smallest = min_tolerance(SolveOptions{}.method);
  if (!(in.tolerance >= smallest && in.tolerance <= kMaxTolerance)) {
    throw InvalidInput(fmt::format("{} must be in [{:g}, {:g}] (the accuracy of each eps solve), got {}",
                                   name("tolerance"), smallest, kMaxTolerance, in.tolerance));
  }
  r.particles = particles_of(in, name);
  r.law = law_of(in, name);
  const double speed_or_temperature =
      name.one_of(in.rms_speed_m_s, "rms_speed", in.temperature_j, "temperature");
  r.initial_temperature_j = in.rms_speed_m_s
                                ? r.particles.mass_kg * speed_or_temperature * speed_or_temperature
                                : speed_or_temperature;
  name.require_positive(in.rms_speed_m_s, "rms_speed", " m/s");
  name.require_positive(in.temperature_j, "temperature", " J");
  if (!std::isnormal(r.initial_temperature_j)) {
    throw InvalidInput(fmt::format("{} gives T0 = {} J, beyond the doubles",
                                   in.rms_speed_m_s ? name("rms_speed") : name("temperature"),
                                   r.initial_temperature_j));
  }
  name.require_positive(in.duration_s, "duration", " s");
  name.require_positive(in.haff_times, "haff_times", "");
  r.duration = name.one_of(in.duration_s, "duration", in.haff_times, "haff_times");
  r.duration_in_haff_times = in.haff_times.has_value();
  if (!std::isfinite(in.first_time_s) || in.first_time_s < 0.0) {
    throw InvalidInput(fmt::format("{} must be finite and >= 0 s (0: six decades), got {}",
                                   name("first_time"), in.first_time_s));
  }
  if (in.points_per_decade < 1 || in.points_per_decade > 1000) {
    throw InvalidInput(
        fmt::format("{} must be in [1, 1000], got {}", name("points_per_decade"), in.points_per_decade));
  }
  name.require_positive(std::optional<double>(in.collision_rate_factor), "collision_rate_factor", "");
  r.first_time_s = in.first_time_s;
  r.points_per_decade = in.points_per_decade;
  r.collision_rate_factor = in.collision_rate_factor;
  r.tolerance = in.tolerance;
  if (int{in.a2_of_haff_eps} + int{in.a2.has_value()} + int{in.a2_evolving} > 1) {
    throw InvalidInput(fmt::format("{}: one of a number, haff and evolving", name("a2")));
  }
  r.a2_evolving = in.a2_evolving;
  check_haff_time(r, in, name);
  // Here rather than only in cooling_curve, which knows no spelling: the message names the caller's.
  const double duration_s = r.duration_in_haff_times ? r.duration * std::exp(log_haff_time(r)) : r.duration;
  if (r.first_time_s >= duration_s) {
    throw InvalidInput(fmt::format("{} must be below the duration {} s (0: six decades below it), got {}",
                                   name("first_time"), duration_s, r.first_time_s));
  }
  if (in.a2_of_haff_eps) {
    r.a2 = sonine_a2_constant_eps(haff_reference(r).eps);  // the Maxwellian gas's Haff ε
  } else {
    r.a2 = in.a2;
  }
  return r;
}

std::optional<Thermostat> thermostat_of(const GasInputs& in, ArgumentStyle style) {
  const Rules name(style);
  const bool langevin = in.thermostat == "langevin";
  if (in.thermostat.empty() || (!langevin && in.thermostat != "white-noise")) {
    if (!in.thermostat.empty()) {
      throw InvalidInput(
          fmt::format("{} must be langevin or white-noise, got '{}'", name("thermostat"), in.thermostat));
    }
    for (const auto& [value, keyword] :
         {std::pair{in.bath_temperature_j, "bath_temperature"}, std::pair{in.bath_time_s, "bath_time"},
          std::pair{in.power_w, "power"}}) {
      if (value) throw InvalidInput(fmt::format("{} needs {}", name(keyword), name("thermostat")));
    }
    return std::nullopt;
  }
  Thermostat t;
  t.kind = langevin ? ThermostatKind::langevin : ThermostatKind::white_noise;
  const std::optional<double>& extra =
      langevin ? in.power_w : (in.bath_temperature_j ? in.bath_temperature_j : in.bath_time_s);
  if (extra) {
    throw InvalidInput(fmt::format(
        "{} {} takes {}", name("thermostat"), in.thermostat,
        langevin
            ? fmt::format("{} and {}, not {}", name("bath_temperature"), name("bath_time"), name("power"))
            : fmt::format("{}, not {} or {}", name("power"), name("bath_temperature"), name("bath_time"))));
  }
  for (const auto& [value, keyword, unit] :
       {std::tuple{langevin ? in.bath_temperature_j : in.power_w, langevin ? "bath_temperature" : "power",
                   langevin ? " J" : " W"},
        std::tuple{langevin ? in.bath_time_s : in.power_w, langevin ? "bath_time" : "power",
                   langevin ? " s" : " W"}}) {
    if (!value)
      throw InvalidInput(fmt::format("{} {} needs {}", name("thermostat"), in.thermostat, name(keyword)));
    name.require_positive(value, keyword, unit);
  }
  t.bath_temperature_j = in.bath_temperature_j.value_or(0.0);
  t.bath_time_s = in.bath_time_s.value_or(0.0);
  t.power_w = in.power_w.value_or(0.0);
  if (!std::isfinite(t.heating_j_s())) {
    throw InvalidInput(fmt::format("{} / {} overflows: the heating 2 T_b/tau_b is beyond the doubles",
                                   name("bath_temperature"), name("bath_time")));
  }
  return t;
}

std::vector<CurveColumn> curve_columns(const CoolingCurve& c) {
  std::vector<CurveColumn> columns{{"time_s", &c.time_s},
                                   {"temperature_j", &c.temperature_j},
                                   {"haff_temperature_j", &c.haff_temperature_j},
                                   {"local_exponent", &c.local_exponent},
                                   {"cooling_rate_hz", &c.cooling_rate_hz},
                                   {"collision_frequency_hz", &c.collision_frequency_hz},
                                   {"collisions_per_particle", &c.collisions_per_particle},
                                   {"effective_eps", &c.effective_eps}};
  if (c.a2_evolving) columns.push_back({"a2", &c.sonine_a2});
  return columns;
}

}  // namespace restitution::gas
