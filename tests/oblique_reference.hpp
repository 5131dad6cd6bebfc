// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// An independent reference for the oblique contact (src/oblique/): written apart from the library, in SI
// units and long double, classical RK4 with a fixed step, each stick/slip switch and the end located by
// bisection on the length of the step that crosses it. Viscoelastic Hertz F_n = k δ^{3/2} + γ sqrt(δ) δ' with
// LAMMPS's linear_history tangential force, torque arm R, the delayed-recovery end. Where the library
// evaluates the slip -> stick condition in closed form (h in src/oblique/oblique_model.hpp), this reference
// takes it as LAMMPS's step states it: from the rescaled (capped) displacement, does a short stick step keep
// the trial force beyond the cap? It differentiates σF_trial - C along the stick motion numerically (central
// differences of two RK4 steps of ±ε).
#include <array>
#include <cmath>
#include <vector>

namespace oblique_reference {

using Real = long double;

struct Problem {
  Real radius1 = 0, mass1 = 0, inertia1 = 0;
  bool wall = true;
  Real radius2 = 0, mass2 = 0, inertia2 = 0;
  Real kn = 0, gamma_n = 0;          // F_n = kn δ^{3/2} + gamma_n sqrt(δ) δ'
  Real kt = 0, gamma_t = 0, mu = 0;  // linear_history
  Real vn = 0, vt = 0, spin1 = 0, spin2 = 0;
};

struct Switch {
  Real time = 0;
  bool stick = true;  // the mode entered
};

struct Outcome {
  Real eps = 0, slip_initial = 0, slip_final = 0, contact_time = 0;
  std::vector<Switch> switches;
};

class Integrator {
 public:
  explicit Integrator(const Problem& p) : p_(p) {
    meff_ = p.wall ? p.mass1 : p.mass1 * p.mass2 / (p.mass1 + p.mass2);
  }

  // Integrates with RK4 steps of at most `step` seconds.
  Outcome run(Real step) {
    using Y = std::array<Real, 6>;  // δ, δ', ξ, u, ω1, ω2
    Y y{0, p_.vn, 0, p_.vt, p_.spin1, p_.spin2};
    Outcome out;
    out.slip_initial = slip(y);
    // At first contact the trial force and the cap both grow as sqrt(δ) (γ_t γ sqrt(δ) |s| against
    // μ γ sqrt(δ) v_n): the contact starts sliding where γ_t |s| > μ v_n.
    stick_ = !(p_.gamma_t * std::fabs(out.slip_initial) > p_.mu * p_.vn);
    sign_ = out.slip_initial > 0 ? -1 : 1;
    out.switches.push_back({0, stick_});
    Real t = 0;
    for (long n = 0; n < 100000000; ++n) {
      // Graded steps from first contact, where δ ~ t and sqrt(δ) is not smooth: each step 1/20 of the time
      // elapsed, from 1e-9 of the step on (the local error stays ~(h/t)^5 t^{3/2}).
      const Real h = std::fmin(step, std::fmax(1e-9L * step, 0.05L * t));
      const Y next = rk4(y, h, stick_);
      const bool ends = t > 0 && force_factor(y) > 0 && force_factor(next) <= 0;
      const bool switches = indicator(y) > 0 && indicator(next) <= 0;
      if (!ends && !switches) {
        y = next;
        t += h;
        continue;
      }
      // The first crossing in the step, by bisection on the sub-step.
      Real lo = 0;
      Real hi = h;
      const auto crossed = [&](Real sub) {
        const Y z = rk4(y, sub, stick_);
        return (ends && force_factor(z) <= 0) || (switches && indicator(z) <= 0);
      };
      for (int k = 0; k < 90; ++k) {
        const Real mid = 0.5L * (lo + hi);
        (crossed(mid) ? hi : lo) = mid;
      }
      y = rk4(y, hi, stick_);
      t += hi;
      if (force_factor(y) <= 0) break;
      // A switch.
      if (stick_) {
        sign_ = trial(y) < 0 ? -1 : 1;
        stick_ = false;
      } else {
        y[2] = capped_displacement(y);
        stick_ = true;
      }
      out.switches.push_back({t, stick_});
    }
    out.eps = -y[1] / p_.vn;
    out.slip_final = slip(y);
    out.contact_time = t;
    return out;
  }

 private:
  using Y = std::array<Real, 6>;
  [[nodiscard]] Real slip(const Y& y) const {
    return y[3] + p_.radius1 * y[4] + (p_.wall ? 0 : p_.radius2 * y[5]);
  }
  [[nodiscard]] Real normal_force(const Y& y) const {
    const Real r = std::sqrt(std::fmax(y[0], 0.0L));
    return r * (p_.kn * y[0] + p_.gamma_n * y[1]);
  }
  [[nodiscard]] Real force_factor(const Y& y) const { return p_.kn * y[0] + p_.gamma_n * y[1]; }
  [[nodiscard]] Real cap(const Y& y) const { return p_.mu * std::fabs(normal_force(y)); }
  [[nodiscard]] Real viscous(const Y& y) const {
    return p_.gamma_t * p_.gamma_n * std::sqrt(std::fmax(y[0], 0.0L));
  }
  [[nodiscard]] Real trial(const Y& y) const { return -p_.kt * y[2] - viscous(y) * slip(y); }
  [[nodiscard]] Real capped_displacement(const Y& y) const {
    return -(sign_ * cap(y) + viscous(y) * slip(y)) / p_.kt;
  }
  // > 0 while the mode lasts.
  [[nodiscard]] Real indicator(const Y& y) const {
    if (stick_) return cap(y) - std::fabs(trial(y));
    Y z = y;
    z[2] = capped_displacement(y);
    const Real h = 1e-7L * step_scale();
    const auto beyond = [&](const Y& w) { return sign_ * trial(w) - cap(w); };
    return (beyond(rk4(z, h, true)) - beyond(rk4(z, -h, true))) / (2 * h);
  }
  [[nodiscard]] Real step_scale() const { return std::pow(meff_ * meff_ / (p_.kn * p_.kn * p_.vn), 0.2L); }
  [[nodiscard]] Y rates(const Y& y, bool stick) const {
    const Real fn = normal_force(y);
    const Real ft = stick ? trial(y) : sign_ * cap(y);
    Y d{};
    d[0] = y[1];
    d[1] = -fn / meff_;
    d[2] = stick ? slip(y) : 0;
    d[3] = ft / meff_;
    d[4] = p_.radius1 * ft / p_.inertia1;
    d[5] = p_.wall ? 0 : p_.radius2 * ft / p_.inertia2;
    return d;
  }
  [[nodiscard]] Y rk4(const Y& y, Real h, bool stick) const {
    const auto add = [](const Y& a, const Y& b, Real c) {
      Y r;
      for (std::size_t i = 0; i < r.size(); ++i) r[i] = a[i] + c * b[i];
      return r;
    };
    const Y k1 = rates(y, stick);
    const Y k2 = rates(add(y, k1, h / 2), stick);
    const Y k3 = rates(add(y, k2, h / 2), stick);
    const Y k4 = rates(add(y, k3, h), stick);
    Y r;
    for (std::size_t i = 0; i < r.size(); ++i) r[i] = y[i] + h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
    return r;
  }

  Problem p_;
  Real meff_ = 0;
  bool stick_ = true;
  Real sign_ = 1;
};

}  // namespace oblique_reference
