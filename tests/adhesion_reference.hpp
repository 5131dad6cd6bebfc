// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// An independent long-double integration of the scaled JKR collision (docs/adhesion.md §4) for
// tests/test_adhesion.cpp: classical RK4 at a fixed step, in the time form (state δ, dδ/dt, viscous work,
// the contact radius s found from δ by Newton's method on δ = u⁴ − √2 u, u = sqrt(s)) until the overlap turns
// negative on the way out, then with s itself as the independent variable (state (dδ/dt)², t, work) down to
// the break radius exactly, where the time form's sqrt singularity at s = 1/2 does not reach. The library
// integrates a Sundman form with CVODE instead.
#include <cmath>

namespace restitution::test {

struct AdhesionReference {
  bool stuck = false;
  long double eps = 0.0L;
  long double time = 0.0L;
  long double viscous_work = 0.0L;
};

enum class ReferenceDamping { lammps, viscoelastic };

namespace reference_detail {

inline long double radius_of_overlap(long double delta, long double guess) {
  const long double root2 = std::sqrt(2.0L);
  long double u = std::sqrt(guess);
  for (int i = 0; i < 60; ++i) {
    const long double step = (u * u * u * u - root2 * u - delta) / (4.0L * u * u * u - root2);
    u -= step;
    if (std::fabs(step) <= 1e-19L * u) break;
  }
  return u * u;
}
inline long double force(long double s) {
  return 4.0L / 3.0L * s * s * s - 2.0L * std::sqrt(2.0L) * std::pow(s, 1.5L);
}
inline long double overlap_slope(long double s) {
  return 2.0L * s - 1.0L / (std::sqrt(2.0L) * std::sqrt(s));
}
inline long double force_slope(long double s) {
  return 4.0L * s * s - 1.5L * std::sqrt(2.0L) * std::sqrt(s);
}
// The damping force per unit mass (scaled) at radius s and velocity p.
inline long double damping_force(ReferenceDamping kind, long double c, long double s, long double p) {
  return kind == ReferenceDamping::lammps ? c * s * p : c * p * force_slope(s) / overlap_slope(s);
}

}  // namespace reference_detail

// Impact speed V and damping c in the library's scaled units; the break at radius `break_radius`.
inline AdhesionReference adhesion_reference(ReferenceDamping kind, long double c, long double speed,
                                            long double break_radius, long double step) {
  using namespace reference_detail;
  AdhesionReference out;
  long double delta = 0.0L, p = speed, work = 0.0L, t = 0.0L, s = std::cbrt(2.0L);
  auto accel = [&](long double d, long double v, long double& s_guess) {
    s_guess = radius_of_overlap(d, s_guess);
    return -force(s_guess) - damping_force(kind, c, s_guess, v);
  };
  bool separating = false;
  while (!(separating && delta < 0.0L)) {
    long double g = s;
    const long double k1d = p, k1p = accel(delta, p, g), k1w = damping_force(kind, c, g, p) * p;
    const long double k2d = p + 0.5L * step * k1p, k2p = accel(delta + 0.5L * step * k1d, k2d, g),
                      k2w = damping_force(kind, c, g, k2d) * k2d;
    const long double k3d = p + 0.5L * step * k2p, k3p = accel(delta + 0.5L * step * k2d, k3d, g),
                      k3w = damping_force(kind, c, g, k3d) * k3d;
    const long double k4d = p + step * k3p, k4p = accel(delta + step * k3d, k4d, g),
                      k4w = damping_force(kind, c, g, k4d) * k4d;
    delta += step / 6.0L * (k1d + 2.0L * k2d + 2.0L * k3d + k4d);
    p += step / 6.0L * (k1p + 2.0L * k2p + 2.0L * k3p + k4p);
    work += step / 6.0L * (k1w + 2.0L * k2w + 2.0L * k3w + k4w);
    t += step;
    s = radius_of_overlap(delta, s);
    if (p < 0.0L) separating = true;
    if (separating && p > 0.0L) {
      out.stuck = true;
      return out;
    }
  }
  // d(p²)/ds = 2 δ'(s) (−f − damping), dt/ds = δ'(s)/p, dW/ds = damping · δ'(s), with p = −sqrt(q).
  long double q = p * p;
  const long double span = s - break_radius;
  const long n = static_cast<long>(std::ceil(span / step)) + 1;
  const long double h = -span / static_cast<long double>(n);
  auto derivative = [&](long double r, long double qq, long double out3[3]) {
    const long double v = -std::sqrt(std::fmax(qq, 0.0L));
    // The damping force times δ'(s), finite at s = 1/2 where the viscoelastic one alone is not.
    const long double d =
        kind == ReferenceDamping::lammps ? c * r * v * overlap_slope(r) : c * v * force_slope(r);
    out3[0] = 2.0L * (-overlap_slope(r) * force(r) - d);
    out3[1] = overlap_slope(r) / v;
    out3[2] = d;
  };
  for (long i = 0; i < n; ++i) {
    long double k1[3], k2[3], k3[3], k4[3];
    derivative(s, q, k1);
    derivative(s + 0.5L * h, q + 0.5L * h * k1[0], k2);
    derivative(s + 0.5L * h, q + 0.5L * h * k2[0], k3);
    derivative(s + h, q + h * k3[0], k4);
    q += h / 6.0L * (k1[0] + 2.0L * k2[0] + 2.0L * k3[0] + k4[0]);
    t += h / 6.0L * (k1[1] + 2.0L * k2[1] + 2.0L * k3[1] + k4[1]);
    work += h / 6.0L * (k1[2] + 2.0L * k2[2] + 2.0L * k3[2] + k4[2]);
    s += h;
    if (q <= 0.0L) {
      out.stuck = true;
      return out;
    }
  }
  out.eps = std::sqrt(q) / speed;
  out.time = t;
  out.viscous_work = work;
  return out;
}

}  // namespace restitution::test
