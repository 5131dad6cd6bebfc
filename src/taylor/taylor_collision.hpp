// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// One collision integrated by a Taylor-series method on the smooth formulation (taylor_series.hpp),
// templated on the number type: double for the fast engine (taylor_engine.cpp), __float128 for the
// reference solutions (src/reference/). Natural units (x'(0) = 1).
//
// Hertz spheres, three phases as in the CVODE engine (docs/accuracy.md):
//  1. compression form, u from 0 up until x' has fallen to `start_switch_velocity`;
//  2. time form through maximal compression (event x' = 0) until u falls below `end_switch_u`; the
//     delayed-recovery end ζx' + x = 0 is an event here;
//  3. compression form from there down to u = 0, reached exactly (the naive end); the delayed-recovery end,
//     if it lies this late, is an event.
// The dash-pot is smooth: one time-form phase with the events x' = 0, c_d x' + c_s x = 0 and x = 0.
//
// Steps: order p, step h = min over j in {p-1, p} of (tolerance/‖c_j‖)^{1/j} with ‖·‖ the largest
// component relative to max(|s_i|, floor_i) (Jorba & Zou, Exp. Math. 14, 99 (2005)). Events are roots of
// the step's polynomial (safeguarded Newton), so they are located to rounding error, not to a tolerance.
#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <type_traits>

#include "restitution/errors.hpp"
#include "restitution/solve_types.hpp"
#include "taylor/taylor_series.hpp"

namespace restitution::taylor {

template <class Real>
Real magnitude(Real a) {
  return a < 0 ? -a : a;
}

template <class Real>
Real unit_roundoff() {
  if constexpr (std::is_same_v<Real, double>) {
    return std::numeric_limits<double>::epsilon();
  } else {
    static_assert(sizeof(Real) == 16, "double or __float128");
    return Real(1) / (Real(4503599627370496.0) * Real(4503599627370496.0) * Real(1048576.0));  // 2^-112
  }
}

struct TaylorSettings {
  int order = 20;
  double tolerance = 1e-16;  // local truncation error per step, relative to the component scales
  EndSet ends = EndSet::both();
  // Component scales are max(|s_i|, floor_i); floors per form: compression (τ, y, I), time (u|x, y, I).
  std::array<double, kComponents> compression_floor{1e-2, 1e-2, 1e-2};
  std::array<double, kComponents> time_floor{1e-2, 1e-2, 1e-2};
  double start_switch_velocity = 0.5;
  double end_switch_fraction = 0.95;  // of u where the start phase ended
  double end_switch_u_max = 1e300;    // and never above this (large ζ: keep the stiff tail in τ)
  double time_limit = 1e6;
  long max_steps = 2000000;
};

template <class Real>
struct TaylorPoint {
  Real tau = 0, x = 0, y = 0, dissipation = 0;  // dissipation: I = ∫ w(x) y² dτ
};

template <class Real>
struct TaylorOutcome {
  bool max_found = false;
  Real tau_max = 0, x_max = 0;
  PerEnd<std::optional<TaylorPoint<Real>>> ends;
  long steps = 0;
};

// Root of f on the step between `positive` (f > 0) and `nonpositive` (f <= 0): safeguarded Newton on the
// step's polynomial. f returns ValueSlope<Real>.
template <class Real, class F>
Real polynomial_root(const F& f, Real positive, Real nonpositive) {
  Real a = positive;
  Real b = nonpositive;
  const Real fa = f(a).value;
  const Real fb = f(b).value;
  Real t = fa != fb ? a + (b - a) * fa / (fa - fb) : (a + b) / 2;
  const Real resolution = 4 * unit_roundoff<Real>() * (magnitude(a) + magnitude(b));
  for (int iteration = 0; iteration < 200; ++iteration) {
    const ValueSlope<Real> v = f(t);
    if (v.value == 0) return t;
    (v.value > 0 ? a : b) = t;
    Real next = v.slope != 0 ? t - v.value / v.slope : (a + b) / 2;
    if (!((next - a) * (next - b) < 0)) next = (a + b) / 2;  // outside the bracket: bisect
    if (magnitude(next - t) <= resolution || magnitude(a - b) <= resolution) return next;
    t = next;
  }
  return t;
}

template <class Real>
class TaylorCollision {
 public:
  TaylorCollision(const TaylorSettings& settings, double parameter_for_messages)
      : settings_(settings), parameter_(parameter_for_messages) {}

  // Viscoelastic Hertz in natural units: x'' + ζ x' sqrt(x) + x^{3/2} = 0, x(0) = 0, x'(0) = 1.
  TaylorOutcome<Real> hertz(Real zeta) {
    zeta_ = zeta;
    Real u = 0;
    State<Real> s{Real(0), Real(1), Real(0)};  // (τ, y, I)
    hertz_start(u, s);
    State<Real> t{u, s[1], s[2]};  // (u, y, I)
    Real tau = s[0];
    const double u_switch =
        std::min(settings_.end_switch_fraction * static_cast<double>(u), settings_.end_switch_u_max);
    if (pending()) hertz_middle(tau, t, Real(u_switch));
    if (pending()) hertz_end(t[0], {tau, t[1], t[2]});
    if (!out_.max_found) fail("the collision ended without a maximal compression", tau);
    return out_;
  }

  // Linear dash-pot x'' + c_d x' + c_s x = 0, x(0) = 0, x'(0) = 1.
  TaylorOutcome<Real> dashpot(Real damping, Real stiffness) {
    Real tau = 0;
    State<Real> s{Real(0), Real(1), Real(0)};  // (x, y, I)
    Coefficients<Real> c;
    const int p = settings_.order;
    while (pending()) {
      count_step(tau);
      expand_dashpot_time(damping, stiffness, s, p, c);
      const Real h = Real(step_bound(c, s, settings_.time_floor));
      const State<Real> next = evaluate_state(c, p, h);
      if (!out_.max_found && next[1] <= 0) {
        const Real th = polynomial_root([&](Real q) { return evaluate(c[1], p, q); }, Real(0), h);
        record_max(tau + th, evaluate(c[0], p, th).value);
      }
      const auto force = [&](Real q) {
        const auto x = evaluate(c[0], p, q);
        const auto y = evaluate(c[1], p, q);
        return ValueSlope<Real>{damping * y.value + stiffness * x.value,
                                damping * y.slope + stiffness * x.slope};
      };
      if (settings_.ends.contains(CollisionEnd::delayed_recovery) &&
          !out_.ends[CollisionEnd::delayed_recovery] && force(h).value <= 0) {
        const Real th = polynomial_root(force, Real(0), h);
        out_.ends[CollisionEnd::delayed_recovery] = point_at(c, p, th, tau, /*time_form_x=*/true);
      }
      if (settings_.ends.contains(CollisionEnd::naive) && !out_.ends[CollisionEnd::naive] && out_.max_found &&
          next[0] <= 0) {
        const Real th = polynomial_root([&](Real q) { return evaluate(c[0], p, q); }, Real(0), h);
        out_.ends[CollisionEnd::naive] = point_at(c, p, th, tau, true);
        out_.ends[CollisionEnd::naive]->x = 0;
      }
      tau += h;
      s = next;
    }
    return out_;
  }

 private:
  [[nodiscard]] bool pending() const {
    return (settings_.ends.contains(CollisionEnd::naive) && !out_.ends[CollisionEnd::naive]) ||
           (settings_.ends.contains(CollisionEnd::delayed_recovery) &&
            !out_.ends[CollisionEnd::delayed_recovery]);
  }

  [[noreturn]] void fail(const char* what, Real tau) const {
    throw NumericalFailure(fmt::format("{} at tau={:g} after {} Taylor steps (parameter {})", what,
                                       static_cast<double>(tau), out_.steps, parameter_));
  }

  void count_step(Real tau) {
    if (++out_.steps > settings_.max_steps) fail("too many steps", tau);
    if (static_cast<double>(tau) > settings_.time_limit)
      fail("no end of the collision before the time limit", tau);
  }

  // Largest step whose truncation error stays below the tolerance (Jorba & Zou).
  [[nodiscard]] double step_bound(const Coefficients<Real>& c, const State<Real>& s,
                                  const std::array<double, kComponents>& floor) const {
    double h = std::numeric_limits<double>::max();
    for (const int j : {settings_.order - 1, settings_.order}) {
      double norm = 0;
      for (std::size_t i = 0; i < kComponents; ++i) {
        const double scale = std::max(std::abs(static_cast<double>(s[i])), floor[i]);
        norm = std::max(norm, std::abs(static_cast<double>(c[i][static_cast<std::size_t>(j)])) / scale);
      }
      if (norm > 0) h = std::min(h, std::pow(settings_.tolerance / norm, 1.0 / j));
    }
    return h;
  }

  void record_max(Real tau, Real x) {
    out_.max_found = true;
    out_.tau_max = tau;
    out_.x_max = x;
  }

  // The state at θ into a step of a time form (x or u first) as a point of the trajectory.
  TaylorPoint<Real> point_at(const Coefficients<Real>& c, int p, Real th, Real tau, bool time_form_x) const {
    const Real first = evaluate(c[0], p, th).value;
    return {tau + th, time_form_x ? first : first * first, evaluate(c[1], p, th).value,
            evaluate(c[2], p, th).value};
  }

  // Phase 1: u from 0 up while x' > start_switch_velocity.
  void hertz_start(Real& u, State<Real>& s) {
    Coefficients<Real> c;
    const int p = settings_.order;
    const Real quarter = Real(settings_.start_switch_velocity) / 2;
    while (s[1] > Real(settings_.start_switch_velocity)) {
      count_step(s[0]);
      expand_hertz_compression(zeta_, u, s, p, c);
      Real h = Real(step_bound(c, s, settings_.compression_floor));
      State<Real> next = evaluate_state(c, p, h);
      while (!(next[1] > quarter)) {  // never step close to x' = 0, where this form is singular
        h /= 2;
        next = evaluate_state(c, p, h);
      }
      u += h;
      s = next;
    }
  }

  // Phase 2: τ through maximal compression until u < u_switch (or the requested ends are found).
  void hertz_middle(Real& tau, State<Real>& s, Real u_switch) {
    Coefficients<Real> c;
    const int p = settings_.order;
    while (true) {
      count_step(tau);
      expand_hertz_time(zeta_, s, p, c);
      Real h = Real(step_bound(c, s, settings_.time_floor));
      State<Real> next = evaluate_state(c, p, h);
      while (!(next[0] > s[0] / 4)) {  // never step close to u = 0, where this form is singular
        h /= 2;
        next = evaluate_state(c, p, h);
      }
      if (!out_.max_found && next[1] <= 0) {
        const Real th = polynomial_root([&](Real q) { return evaluate(c[1], p, q); }, Real(0), h);
        const Real um = evaluate(c[0], p, th).value;
        record_max(tau + th, um * um);
      }
      const auto force = [&](Real q) {
        const auto uu = evaluate(c[0], p, q);
        const auto y = evaluate(c[1], p, q);
        return ValueSlope<Real>{zeta_ * y.value + uu.value * uu.value,
                                zeta_ * y.slope + 2 * uu.value * uu.slope};
      };
      if (settings_.ends.contains(CollisionEnd::delayed_recovery) &&
          !out_.ends[CollisionEnd::delayed_recovery] && zeta_ > 0 && force(h).value <= 0) {
        const Real th = polynomial_root(force, Real(0), h);
        out_.ends[CollisionEnd::delayed_recovery] = point_at(c, p, th, tau, false);
        if (!pending()) return;
      }
      tau += h;
      s = next;
      if (out_.max_found && s[0] < u_switch) return;
    }
  }

  // Phase 3: u from u0 down to 0 (the naive end, exactly); state (τ, y, I).
  void hertz_end(Real u, State<Real> s) {
    Coefficients<Real> c;
    const int p = settings_.order;
    while (true) {
      count_step(s[0]);
      expand_hertz_compression(zeta_, u, s, p, c);
      Real h = Real(step_bound(c, s, settings_.compression_floor));
      bool last = h >= u;
      State<Real> next = evaluate_state(c, p, last ? -u : -h);
      while (!(next[1] < s[1] / 16)) {  // x' < 0 here: never step close to x' = 0
        h = (last ? u : h) / 2;
        last = false;
        next = evaluate_state(c, p, -h);
      }
      const Real step = last ? -u : -h;
      const auto force = [&](Real q) {
        const auto y = evaluate(c[1], p, q);
        const Real uq = u + q;
        return ValueSlope<Real>{zeta_ * y.value + uq * uq, zeta_ * y.slope + 2 * uq};
      };
      if (settings_.ends.contains(CollisionEnd::delayed_recovery) &&
          !out_.ends[CollisionEnd::delayed_recovery] && zeta_ > 0 && force(step).value <= 0) {
        const Real ue = delayed_root_u(c, p, u, step, polynomial_root(force, Real(0), step));
        const Real th = ue - u;
        out_.ends[CollisionEnd::delayed_recovery] = TaylorPoint<Real>{
            evaluate(c[0], p, th).value, ue * ue, evaluate(c[1], p, th).value, evaluate(c[2], p, th).value};
        if (!pending()) return;
      }
      s = next;
      if (last) break;
      u += step;
    }
    const TaylorPoint<Real> end{s[0], Real(0), s[1], s[2]};
    if (settings_.ends.contains(CollisionEnd::naive)) out_.ends[CollisionEnd::naive] = end;
    if (settings_.ends.contains(CollisionEnd::delayed_recovery) &&
        !out_.ends[CollisionEnd::delayed_recovery]) {
      // ζx' + x can only reach zero at x = 0 when ζ = 0, where both ends coincide.
      if (zeta_ != 0) fail("no delayed-recovery end before the overlap vanished", s[0]);
      out_.ends[CollisionEnd::delayed_recovery] = end;
    }
  }

  // u at the delayed-recovery end, where u² = -ζ y. polynomial_root locates the step fraction θ to a rounding
  // error of the step, i.e. u = u0 + θ to an absolute ~1e-16; for small ζ the root lies at u ~ sqrt(ζ) and
  // that error would swamp it (and U(x) = 0.4 u^5 with it). Newton on u itself, from the double estimate
  // sqrt(-ζ y), keeps its relative accuracy: y varies slowly near the end, so one or two steps converge.
  Real delayed_root_u(const Coefficients<Real>& c, int p, Real u0, Real step, Real theta) const {
    const double guess = -static_cast<double>(zeta_ * evaluate(c[1], p, theta).value);
    if (!(guess > 0)) return u0 + theta;
    Real ue = Real(std::sqrt(guess));
    for (int iteration = 0; iteration < 4; ++iteration) {
      const ValueSlope<Real> y = evaluate(c[1], p, ue - u0);
      const Real slope = zeta_ * y.slope + 2 * ue;
      if (slope == 0) break;
      ue -= (zeta_ * y.value + ue * ue) / slope;
    }
    const bool in_step = ue >= u0 + step && ue <= u0;  // step < 0: from u0 down to u0 + step
    return in_step ? ue : u0 + theta;
  }

  TaylorSettings settings_;
  double parameter_;
  Real zeta_ = 0;
  TaylorOutcome<Real> out_;
};

// ε and 1-ε of an end from the velocity and from the energy balance 1-ε² = 2(D + U(x_end)) (natural units),
// each from the form that keeps full relative accuracy in its regime (as the CVODE engine does).
template <class Real>
struct EndValues {
  Real eps, one_minus_eps;
};

template <class Real>
EndValues<Real> end_values(Real damping, Real elastic_energy, const TaylorPoint<Real>& p) {
  const Real eps_from_velocity = -p.y;
  if (eps_from_velocity > Real(0.5)) {
    const Real one_minus_eps = 2 * (damping * p.dissipation + elastic_energy) / (1 + eps_from_velocity);
    return {1 - one_minus_eps, one_minus_eps};
  }
  return {eps_from_velocity, 1 - eps_from_velocity};
}

}  // namespace restitution::taylor
