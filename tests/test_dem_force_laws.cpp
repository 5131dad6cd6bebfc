// SPDX-License-Identifier: BSD-3-Clause
// MercuryDPM and Chrono are not packaged, so their lines cannot be run. Instead this test transcribes each
// code's normal force as its source writes it (docs/dem.md names file and lines), feeds it the parameters
// `restitution dem --json` prints, integrates the head-on collision with a classical fourth-order Runge-Kutta
// method written here (no engine of the library is involved), and checks every ε the output states:
// the `eps` list at each speed and the `eps_lines` of the other sizes.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <functional>
#include <numbers>
#include <string>

#include "cli_runner.hpp"

namespace {

using nlohmann::json;

// Soft rubber-like spheres, calibrated to ε = 0.6 at 2 m/s (the speeds are v/10, v, 10 v).
constexpr double kYoungPa = 1e7;
constexpr double kPoisson = 0.45;
constexpr double kRadiusM = 0.01;
constexpr double kDensityKgM3 = 1100.0;
const std::string kMaterial = " --young-modulus 1e7 --poisson-ratio 0.45 --radius 0.01 --density 1100";

// Two equal spheres of radius r: the contact's effective radius and mass.
struct Contact {
  double effective_radius_m;
  double effective_mass_kg;
};
Contact equal_spheres(double radius_m) {
  const double mass = 4.0 / 3.0 * std::numbers::pi * radius_m * radius_m * radius_m * kDensityKgM3;
  return {radius_m / 2.0, mass / 2.0};
}

// The normal force [N] pushing the spheres apart at overlap xi [m] and overlap rate xi_dot [m/s], before
// the code's clamp at zero.
using NormalForce = std::function<double(double xi, double xi_dot)>;

// MercuryDPM, HertzianBSHPViscoelasticInteraction::computeNormalForce: stiffness = 4/3 E* sqrt(R xi),
// dissipation = 3/2 A stiffness, force = stiffness xi - dissipation v_n with v_n = -xi_dot.
NormalForce mercurydpm_force(const json& parameters, const Contact& c) {
  const double e_star = parameters.at("effective_elastic_modulus").get<double>();
  const double a = parameters.at("dissipation").get<double>();
  return [=](double xi, double xi_dot) {
    const double stiffness = 4.0 / 3.0 * e_star * std::sqrt(c.effective_radius_m * xi);
    const double dissipation = 1.5 * a * stiffness;
    return stiffness * xi - dissipation * -xi_dot;
  };
}

// Chrono, ChDefaultContactForceTorqueSMC::CalculateForceTorque, Hertz without material properties:
// kn = R sqrt(xi) Kn, gn = R sqrt(xi) m_eff Gn, Fn = kn xi - gn v_n with v_n = -xi_dot.
NormalForce chrono_force(const json& parameters, const Contact& c) {
  const double kn_material = parameters.at("Kn").get<double>();
  const double gn_material = parameters.at("Gn").get<double>();
  return [=](double xi, double xi_dot) {
    const double tmp = c.effective_radius_m * std::sqrt(xi);
    const double kn = tmp * kn_material;
    const double gn = tmp * c.effective_mass_kg * gn_material;
    return kn * xi - gn * -xi_dot;
  };
}

struct State {
  double xi, xi_dot;
};

State rk4_step(const NormalForce& force, double mass, const State& s, double h) {
  auto rate = [&](const State& y) { return State{y.xi_dot, -force(y.xi, y.xi_dot) / mass}; };
  const State k1 = rate(s);
  const State k2 = rate({s.xi + h / 2 * k1.xi, s.xi_dot + h / 2 * k1.xi_dot});
  const State k3 = rate({s.xi + h / 2 * k2.xi, s.xi_dot + h / 2 * k2.xi_dot});
  const State k4 = rate({s.xi + h * k3.xi, s.xi_dot + h * k3.xi_dot});
  return {s.xi + h / 6 * (k1.xi + 2 * k2.xi + 2 * k3.xi + k4.xi),
          s.xi_dot + h / 6 * (k1.xi_dot + 2 * k2.xi_dot + 2 * k3.xi_dot + k4.xi_dot)};
}

// ε of a head-on collision at `speed` [m/s]. Both codes clamp the force at zero; once it reaches zero while
// the spheres separate it stays zero (xi and xi_dot keep falling), so the collision's outcome is fixed there:
// the last step is cut where the unclamped force crosses zero (bisection on its length). Steps start at
// 1e-12 of the collision time and grow by 5 % up to 1/steps_per_time of it, for the sqrt(xi) start.
double integrated_eps(const NormalForce& force, const Contact& c, double speed, int steps_per_time) {
  const double rho = force(1.0, 0.0) / 1.0;  // any scale: only sets the step size
  const double time_scale = std::pow(c.effective_mass_kg / rho, 0.4) * std::pow(speed, -0.2);
  const double h_max = time_scale / steps_per_time;
  State s{0.0, speed};
  double h = 1e-12 * time_scale;
  for (long step = 0; step < 100L * steps_per_time; ++step) {
    const State next = rk4_step(force, c.effective_mass_kg, s, h);
    if (next.xi_dot < 0.0 && force(next.xi, next.xi_dot) <= 0.0) {
      double lo = 0.0;
      double hi = h;
      for (int i = 0; i < 200 && hi - lo > 1e-15 * h; ++i) {
        const double mid = 0.5 * (lo + hi);
        const State m = rk4_step(force, c.effective_mass_kg, s, mid);
        (m.xi_dot < 0.0 && force(m.xi, m.xi_dot) <= 0.0 ? hi : lo) = mid;
      }
      return -rk4_step(force, c.effective_mass_kg, s, hi).xi_dot / speed;
    }
    s = next;
    h = std::min(h * 1.05, h_max);
  }
  ADD_FAILURE() << "no end of the collision within 100 collision times";
  return NAN;
}

json dem_json(const std::string& code) {
  const auto r =
      restitution::test_support::run_cli("dem --code " + code + kMaterial + " --eps 0.6 --velocity 2 --json");
  EXPECT_EQ(r.status, 0) << r.err;
  return json::parse(r.out);
}

using ForceOf = NormalForce (*)(const json&, const Contact&);

void expect_stated_eps(const std::string& code, ForceOf force_of) {
  const json out = dem_json(code);
  const json& parameters = out.at("parameters");
  const Contact own = equal_spheres(kRadiusM);
  for (const json& row : out.at("eps")) {
    const double speed = row.at("velocity_m_s").get<double>();
    const double stated = row.at("eps").get<double>();
    const double coarse = integrated_eps(force_of(parameters, own), own, speed, 2000);
    const double fine = integrated_eps(force_of(parameters, own), own, speed, 4000);
    EXPECT_NEAR(coarse, fine, 1e-10 * fine) << code << " at " << speed << " m/s: the integration converged";
    EXPECT_NEAR(fine, stated, 1e-8 * std::min(stated, 1.0 - stated)) << code << " at " << speed << " m/s";
  }
  // The same lines for spheres of other sizes (same material): the ε the output says they give there.
  const double calibration_speed = out.at("reference_velocity_m_s").get<double>();
  for (const json& size : out.at("sizes")) {
    const Contact other = equal_spheres(kRadiusM * size.at("radius_factor").get<double>());
    const double stated = size.at("eps_lines").get<double>();
    const double eps = integrated_eps(force_of(parameters, other), other, calibration_speed, 4000);
    EXPECT_NEAR(eps, stated, 1e-8 * std::min(stated, 1.0 - stated))
        << code << " at radius factor " << size.at("radius_factor");
  }
}

TEST(DemForceLaws, MercuryDpmForceAsWrittenGivesTheStatedEps) {
  expect_stated_eps("mercurydpm", mercurydpm_force);
}

TEST(DemForceLaws, ChronoForceAsWrittenGivesTheStatedEps) {
  expect_stated_eps("chrono", chrono_force);
}

// The integration itself, on the material's own law without any code's parameters: E* from Y and nu, A
// from the MercuryDPM output, against the ε restitution states (a check that the test's integrator and
// contact are right, independent of either code's transcription).
TEST(DemForceLaws, IntegratorReproducesTheLawDirectly) {
  const json out = dem_json("mercurydpm");
  const double e_star = kYoungPa / (2.0 * (1.0 - kPoisson * kPoisson));
  const double a = out.at("dissipative_constant_s").get<double>();
  const Contact c = equal_spheres(kRadiusM);
  const NormalForce law = [=](double xi, double xi_dot) {
    const double rho = 4.0 / 3.0 * e_star * std::sqrt(c.effective_radius_m);
    return rho * (std::pow(xi, 1.5) + 1.5 * a * std::sqrt(xi) * xi_dot);
  };
  for (const json& row : out.at("eps")) {
    const double stated = row.at("eps").get<double>();
    const double eps = integrated_eps(law, c, row.at("velocity_m_s").get<double>(), 4000);
    EXPECT_NEAR(eps, stated, 1e-8 * std::min(stated, 1.0 - stated));
  }
}

}  // namespace
