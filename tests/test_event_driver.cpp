// SPDX-License-Identifier: BSD-3-Clause
// The event driver of src/cvode (cvode/event_driver.hpp) on closed forms: the linear dash-pot oscillator
// x'' + 2ζx' + x = 0 (its end where x falls through 0, a non-terminal maximal compression, a mode switch by a
// restart), crossing directions, both correctors, and the smoothing u = x^{1/q} on undamped Hertz spheres.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "cvode/event_driver.hpp"
#include "law/law_rhs.hpp"
#include "restitution/errors.hpp"
#include "sundials/handles.hpp"

namespace {

using restitution::ContactLaw;
using restitution::detail::AfterEvent;
using restitution::detail::Corrector;
using restitution::detail::Crossing;
using restitution::detail::DriverPoint;
using restitution::detail::DriverSettings;
using restitution::detail::DriverStep;
using restitution::detail::EventDriver;
using restitution::detail::EventSystem;
using restitution::detail::JacobianView;
using restitution::detail::Multistep;
using restitution::detail::Smoothing;

constexpr double kPi = 3.14159265358979323846;

// x'' = -2ζx' - x with ζ read at every call (a restart hook may change it): state (x, x').
EventSystem dashpot(const double& zeta) {
  EventSystem system;
  system.size = 2;
  system.rates = [&zeta](const DriverPoint& p, double* d) {
    d[0] = p.y[1];
    d[1] = -2.0 * zeta * p.y[1] - p.y[0];
  };
  system.events = {
      {"end", [](const DriverPoint& p) { return p.y[0]; }, Crossing::falling, true},
      {"max_compression", [](const DriverPoint& p) { return p.y[1]; }, Crossing::falling, false},
  };
  return system;
}

DriverSettings settings(Multistep method, Corrector corrector, int components) {
  DriverSettings s;
  s.method = method;
  s.corrector = corrector;
  s.relative_tolerance = 1e-11;
  s.absolute_tolerance.assign(static_cast<std::size_t>(components), 1e-14);
  return s;
}

// From x = 0, x' = 1: x = e^{-ζt} sin(ωt)/ω, ω = sqrt(1 - ζ²); it ends at t = π/ω with x' = -e^{-ζπ/ω} and
// is most compressed at tan(ωt) = ω/ζ.
TEST(EventDriver, DashpotEndsAtTheClosedFormWithANonTerminalEventOnTheWay) {
  const double zeta = 0.3;
  const double omega = std::sqrt(1.0 - zeta * zeta);
  for (const auto& [method, corrector] :
       {std::pair{Multistep::adams, Corrector::fixed_point}, std::pair{Multistep::bdf, Corrector::newton}}) {
    restitution::sundials::Context context;
    EventDriver driver(dashpot(zeta), settings(method, corrector, 2), context);
    const double start[2] = {0.0, 1.0};
    driver.start(0.0, start);
    std::vector<double> max_compression_times;
    const DriverStep end = driver.run([&](DriverStep& step) {
      EXPECT_TRUE(step.event(1));
      max_compression_times.push_back(step.t);
      return AfterEvent::go_on;
    });
    ASSERT_TRUE(end.event(0));
    EXPECT_FALSE(end.reached_stop);
    EXPECT_NEAR(end.t, kPi / omega, 1e-8);
    EXPECT_NEAR(end.y[1], -std::exp(-zeta * kPi / omega), 1e-8);
    ASSERT_EQ(max_compression_times.size(), 1U);
    EXPECT_NEAR(max_compression_times[0], std::atan(omega / zeta) / omega, 1e-8);
    EXPECT_GT(driver.stats().steps, 10);
    EXPECT_GT(driver.stats().root_evaluations, 0);
    if (corrector == Corrector::newton) {
      EXPECT_GT(driver.stats().jacobian_evaluations, 0);
    }
  }
}

// The restart hook switches the mode: undamped up to maximal compression (x = 1 at t = π/2), then damped:
// from x = 1, x' = 0 the dash-pot reaches x = 0 after s = (π - atan(ω/ζ))/ω with x' = -e^{-ζs}.
TEST(EventDriver, RestartHookSwitchesTheModeAtAnEvent) {
  const double damped = 0.4;
  const double omega = std::sqrt(1.0 - damped * damped);
  for (const bool analytic_jacobian : {false, true}) {
    double zeta = 0.0;
    EventSystem system = dashpot(zeta);
    if (analytic_jacobian) {
      system.jacobian = [&zeta](const DriverPoint&, JacobianView J) {
        J(0, 1) = 1.0;
        J(1, 0) = -1.0;
        J(1, 1) = -2.0 * zeta;
      };
    }
    restitution::sundials::Context context;
    EventDriver driver(std::move(system), settings(Multistep::bdf, Corrector::newton, 2), context);
    const double start[2] = {0.0, 1.0};
    driver.start(0.0, start);
    int restarts = 0;
    const DriverStep end = driver.run([&](DriverStep& step) {
      EXPECT_NEAR(step.t, kPi / 2.0, 1e-8);
      EXPECT_NEAR(step.y[0], 1.0, 1e-9);
      step.y[1] = 0.0;  // the state the restart starts from: exactly at the turning point
      zeta = damped;
      driver.events()[1].active = false;  // x' = 0 only once
      ++restarts;
      return AfterEvent::restart;
    });
    ASSERT_TRUE(end.event(0));
    EXPECT_EQ(restarts, 1);
    const double s = (kPi - std::atan(omega / damped)) / omega;
    EXPECT_NEAR(end.t, kPi / 2.0 + s, 1e-8);
    EXPECT_NEAR(end.y[1], -std::exp(-damped * s), 1e-8);
  }
}

// Directions: x = sin t crosses 1/2 rising at π/6 and falling at 5π/6; a rising event sees only the first,
// a falling one only the second, either both. A terminal event whose direction never comes is no stop.
TEST(EventDriver, CrossingDirectionsFilterTheEvents) {
  double zeta = 0.0;
  EventSystem system = dashpot(zeta);
  system.events[1].active = false;
  const auto half = [](const DriverPoint& p) { return p.y[0] - 0.5; };
  system.events.push_back({"rising", half, Crossing::rising, false});
  system.events.push_back({"falling", half, Crossing::falling, false});
  system.events.push_back({"either", half, Crossing::either, false});
  system.events.push_back(
      {"never", [](const DriverPoint& p) { return p.y[0] + 2.0; }, Crossing::either, true});
  restitution::sundials::Context context;
  EventDriver driver(std::move(system), settings(Multistep::adams, Corrector::fixed_point, 2), context);
  const double start[2] = {0.0, 1.0};
  driver.start(0.0, start);
  std::vector<std::vector<double>> times(6);
  const DriverStep end = driver.run([&](DriverStep& step) {
    for (int i = 2; i < 5; ++i) {
      if (step.event(i)) times[static_cast<std::size_t>(i)].push_back(step.t);
    }
    return AfterEvent::go_on;
  });
  EXPECT_NEAR(end.t, kPi, 1e-8);
  ASSERT_EQ(times[2].size(), 1U);
  ASSERT_EQ(times[3].size(), 1U);
  ASSERT_EQ(times[4].size(), 2U);
  EXPECT_NEAR(times[2][0], kPi / 6.0, 1e-8);
  EXPECT_NEAR(times[3][0], 5.0 * kPi / 6.0, 1e-8);
}

// Undamped Hertz spheres x'' = -x^{3/2}, x'(0) = 1 in the smoothing u = sqrt(x): the contact ends where u
// falls through 0, at τ = 2 τ_max0 = (4/5)^{3/5} Γ(2/5) Γ(1/2)/Γ(9/10) with x' = -1 (docs/design.md §4), the
// maximal compression (5/4)^{2/5} on the way.
TEST(EventDriver, SmoothingIntegratesHertzThroughBothEnds) {
  const ContactLaw law = ContactLaw::hertz_natural(0.0);
  EventSystem system;
  system.size = 2;
  system.rates = [&law](const DriverPoint& p, double* d) {
    d[0] = p.y[1];
    d[1] = restitution::law_rhs::acceleration(law, p.y[0], p.y[1]);
  };
  system.events = {
      {"naive_end", [](const DriverPoint& p) { return p.u; }, Crossing::falling, true},
      {"max_compression", [](const DriverPoint& p) { return p.y[1]; }, Crossing::falling, false}};
  DriverSettings s = settings(Multistep::adams, Corrector::fixed_point, 3);
  s.variable_name = "sigma";
  EventDriver driver(std::move(system), s, Smoothing{&law});  // with a SUNDIALS context of its own
  const double start[2] = {0.0, 1.0};
  driver.start(0.0, start);
  double largest = 0.0;
  const DriverStep end = driver.run([&](DriverStep& step) {
    largest = step.y[0];
    return AfterEvent::go_on;
  });
  ASSERT_TRUE(end.event(0));
  const double tau_end = std::pow(0.8, 0.6) * std::tgamma(0.4) * std::tgamma(0.5) / std::tgamma(0.9);
  EXPECT_NEAR(end.tau, tau_end, 1e-8);
  EXPECT_NEAR(end.y[1], -1.0, 1e-8);
  EXPECT_NEAR(largest, std::pow(1.25, 0.4), 1e-9);
}

// What the driver refuses, by name; and an exception thrown inside a callback reaches the caller.
TEST(EventDriver, RefusesMisfitSettingsAndCarriesCallbackExceptions) {
  restitution::sundials::Context context;
  double zeta = 0.0;
  const auto message = [&](DriverSettings s, Smoothing smoothing, bool with_jacobian) {
    EventSystem system = dashpot(zeta);
    if (with_jacobian) system.jacobian = [](const DriverPoint&, JacobianView) {};
    try {
      EventDriver driver(std::move(system), std::move(s), context, smoothing);
    } catch (const restitution::InvalidInput& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  const ContactLaw law = ContactLaw::hertz_natural(0.0);
  EXPECT_NE(message(settings(Multistep::adams, Corrector::fixed_point, 3), {}, false).find("3 absolute"),
            std::string::npos);
  EXPECT_NE(message(settings(Multistep::bdf, Corrector::newton, 3), Smoothing{&law}, true).find("Jacobian"),
            std::string::npos);
  EXPECT_EQ(message(settings(Multistep::adams, Corrector::fixed_point, 3), Smoothing{&law}, false), "");

  EventSystem system = dashpot(zeta);
  system.events[1].function = [](const DriverPoint& p) -> double {
    if (p.t > 1.0) throw std::runtime_error("event function failed");
    return p.y[1];
  };
  EventDriver driver(std::move(system), settings(Multistep::adams, Corrector::fixed_point, 2), context);
  const double start[2] = {0.0, 1.0};
  driver.start(0.0, start);
  EXPECT_THROW(driver.run(), std::runtime_error);
}

}  // namespace
