// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// An independent integration of the contact-law family for the tests, sharing nothing with the engines:
// x'' + ζ x^b x' + x^a = 0, x(0) = 0, x'(0) = 1, in long double, after the Sundman-type change of the
// independent variable dτ/ds = u^{q-1} with u = x^{1/q}. In s the system is polynomial in (u, x'):
//     du/ds = x'/q,  dx'/ds = -(ζ u^{qb} x' + u^{qa}) u^{q-1},  dτ/ds = u^{q-1},  dI/ds = u^{qb} x'^2
//     u^{q-1},
// smooth through x = 0 and through maximal compression, so fixed-step classical Runge–Kutta converges at its
// full order 4 and Richardson extrapolation of two step sizes removes the leading error. Ends are located
// by bisection on the step fraction (a partial RK4 step is a fourth-order interpolant).
#include <cmath>
#include <optional>
#include <stdexcept>

namespace restitution::test_support {

struct FamilyEnd {
  long double eps = 0, one_minus_eps = 0, tau = 0, x = 0;
};

struct FamilyMember {
  long double a, b;
  int q;
  long double zeta;
};

namespace family_detail {

struct State {
  long double u, v, tau, dissipation;
};

inline long double ipow(long double u, int n) {
  long double r = 1;
  for (int i = 0; i < n; ++i) r *= u;
  return r;
}

inline State rhs(const FamilyMember& m, const State& s) {
  const int qa = static_cast<int>(std::lround(m.q * m.a));
  const int qb = static_cast<int>(std::lround(m.q * m.b));
  // u may dip a rounding error below 0 in the last partial step: the powers are of |u| with its sign for
  // odd q·a (only trial steps see it).
  const long double w = m.q == 1 ? 1.0L : ipow(s.u, m.q - 1);
  const long double damping = ipow(s.u, qb);
  return {s.v / m.q, -(m.zeta * damping * s.v + ipow(s.u, qa)) * w, w, damping * s.v * s.v * w};
}

inline State add(const State& s, const State& k, long double h) {
  return {s.u + h * k.u, s.v + h * k.v, s.tau + h * k.tau, s.dissipation + h * k.dissipation};
}

inline State rk4(const FamilyMember& m, const State& s, long double h) {
  const State k1 = rhs(m, s);
  const State k2 = rhs(m, add(s, k1, h / 2));
  const State k3 = rhs(m, add(s, k2, h / 2));
  const State k4 = rhs(m, add(s, k3, h));
  return {
      s.u + h / 6 * (k1.u + 2 * k2.u + 2 * k3.u + k4.u), s.v + h / 6 * (k1.v + 2 * k2.v + 2 * k3.v + k4.v),
      s.tau + h / 6 * (k1.tau + 2 * k2.tau + 2 * k3.tau + k4.tau),
      s.dissipation + h / 6 * (k1.dissipation + 2 * k2.dissipation + 2 * k3.dissipation + k4.dissipation)};
}

// Naive end: u = 0 after maximal compression. Force-zero end: ζ x' + x^{a-b} = 0, i.e.
// ζ x' u^{qb} + u^{qa} = 0 divided by u^{qb}.
inline long double end_function(const FamilyMember& m, const State& s, bool naive) {
  if (naive) return s.u;
  const int e = static_cast<int>(std::lround(m.q * (m.a - m.b)));
  return m.zeta * s.v + ipow(s.u, e);
}

inline FamilyEnd end_of(const FamilyMember& m, const State& s) {
  const long double x = ipow(s.u > 0 ? s.u : 0, m.q);
  const long double eps_v = -s.v;
  const long double energy = m.zeta * s.dissipation + std::pow(x, m.a + 1) / (m.a + 1);
  FamilyEnd end{eps_v, 1 - eps_v, s.tau, x};
  if (eps_v > 0.5L) {
    end.one_minus_eps = 2 * energy / (1 + eps_v);
    end.eps = 1 - end.one_minus_eps;
  }
  return end;
}

// One fixed-step run; nullopt if the end was not reached before s_max.
inline std::optional<FamilyEnd> run(const FamilyMember& m, bool naive, long double h, long double s_max) {
  State s{0, 1, 0, 0};
  for (long double t = 0; t < s_max; t += h) {
    const State next = rk4(m, s, h);
    const bool past_max = s.v < 0 || next.v < 0;
    if (past_max && end_function(m, next, naive) <= 0 && end_function(m, s, naive) > 0) {
      long double lo = 0;
      long double hi = h;
      for (int i = 0; i < 200 && hi - lo > 0; ++i) {
        const long double mid = (lo + hi) / 2;
        if (mid == lo || mid == hi) break;
        (end_function(m, rk4(m, s, mid), naive) > 0 ? lo : hi) = mid;
      }
      State at = rk4(m, s, (lo + hi) / 2);
      if (naive) at.u = 0;
      return end_of(m, at);
    }
    s = next;
  }
  return std::nullopt;
}

}  // namespace family_detail

struct FamilyReference {
  FamilyEnd end;
  long double error_estimate = 0;  // of ε relative to min(ε, 1 - ε)
};

// Richardson-extrapolated RK4 with steps h and h/2; the estimate compares with the extrapolation from h/2
// and h/4. Throws if the end is not reached within s_max.
inline FamilyReference family_reference(const FamilyMember& m, bool naive, long double h, long double s_max) {
  using family_detail::run;
  const auto e1 = run(m, naive, h, s_max);
  const auto e2 = run(m, naive, h / 2, s_max);
  const auto e3 = run(m, naive, h / 4, s_max);
  if (!e1 || !e2 || !e3) throw std::runtime_error("the reference integration found no end");
  const auto extrapolate = [](const FamilyEnd& coarse, const FamilyEnd& fine) {
    FamilyEnd r;
    r.eps = (16 * fine.eps - coarse.eps) / 15;
    r.one_minus_eps = (16 * fine.one_minus_eps - coarse.one_minus_eps) / 15;
    r.tau = (16 * fine.tau - coarse.tau) / 15;
    r.x = (16 * fine.x - coarse.x) / 15;
    return r;
  };
  const FamilyEnd a = extrapolate(*e1, *e2);
  const FamilyEnd b = extrapolate(*e2, *e3);
  const long double scale = std::min(b.eps, b.one_minus_eps);
  const long double difference =
      b.eps < 0.5L ? std::fabs(a.eps - b.eps) : std::fabs(a.one_minus_eps - b.one_minus_eps);
  return {b, difference / scale};
}

}  // namespace restitution::test_support
