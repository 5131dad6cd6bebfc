// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Taylor coefficients of the collision's equations of motion, for the Taylor-series engines (double: the
// fast engine; __float128: the reference solutions). Templated on the number type; only + - * / are used.
//
// Why not through ContactLaw: ContactLaw evaluates the right-hand side at a point, which is what CVODE
// needs. A Taylor method needs the whole series of the right-hand side, built by recurrences that are
// specific to each algebraic form (1/y, y/u, products). The facts are the same as in ContactLaw
// (x'' = -w(x)(c_d x' + c_s x), dI/dτ = w(x) x'^2, I the dissipation integral) written for
// w(x) = sqrt(x) (Hertz, natural units: c_d = ζ, c_s = 1) and w(x) = 1 (dash-pot); tests compare both
// engines on the same laws.
//
// Three forms (docs/design.md §4, docs/accuracy.md):
//  * Hertz, compression form: independent u = sqrt(x), state (τ, y, I), y = x':
//        dτ/du = 2u/y,  dy/du = -2ζu² - 2u⁴/y,  dI/du = 2u²y          (analytic while y != 0)
//  * Hertz, time form: independent τ, state (u, y, I):
//        u' = y/(2u),  y' = -(ζuy + u³),  I' = u y²                     (analytic while u != 0)
//  * dash-pot, time form: independent τ, state (x, y, I):
//        x' = y,  y' = -(c_d y + c_s x),  I' = y²
// Coefficients are normalised: c[i][k] = s_i^{(k)}(t0) / k!.
#include <array>

namespace restitution::taylor {

inline constexpr int kMaxOrder = 48;
inline constexpr int kComponents = 3;

template <class Real>
using Series = std::array<Real, kMaxOrder + 1>;
template <class Real>
using Coefficients = std::array<Series<Real>, kComponents>;
template <class Real>
using State = std::array<Real, kComponents>;

// 1/n for the orders used (a division per coefficient would cost more than the products).
template <class Real>
Real reciprocal(int n) {
  static const std::array<Real, kMaxOrder + 2> table = [] {
    std::array<Real, kMaxOrder + 2> t{};
    for (std::size_t i = 1; i < t.size(); ++i) t[i] = Real(1) / Real(static_cast<int>(i));
    return t;
  }();
  return table[static_cast<std::size_t>(n)];
}

// Σ_{j=first..k} a_j b_{k-j}, in four independent partial sums: the loop is otherwise bound by the
// latency of one long chain of additions (measured: the engine's steps 1.6x faster).
template <class Real>
Real convolution(const Series<Real>& a, const Series<Real>& b, int k, int first = 0) {
  Real s0 = 0, s1 = 0, s2 = 0, s3 = 0;
  int j = first;
  for (; j + 3 <= k; j += 4) {
    const auto uj = static_cast<std::size_t>(j);
    const auto ik = static_cast<std::size_t>(k);
    s0 += a[uj] * b[ik - uj];
    s1 += a[uj + 1] * b[ik - uj - 1];
    s2 += a[uj + 2] * b[ik - uj - 2];
    s3 += a[uj + 3] * b[ik - uj - 3];
  }
  for (; j <= k; ++j) s0 += a[static_cast<std::size_t>(j)] * b[static_cast<std::size_t>(k - j)];
  return (s0 + s1) + (s2 + s3);
}

// Hertz compression form about u0 with state s = (τ, y, I).
template <class Real>
void expand_hertz_compression(Real zeta, Real u0, const State<Real>& s, int order, Coefficients<Real>& c) {
  auto& tau = c[0];
  auto& y = c[1];
  auto& dissipation = c[2];
  for (std::size_t i = 0; i < kComponents; ++i) c[i][0] = s[i];
  // U = u0 + h: U² and U⁴ are polynomials of degree 2 and 4.
  const std::array<Real, 3> u2{u0 * u0, 2 * u0, Real(1)};
  const std::array<Real, 5> u4{u2[0] * u2[0], 2 * u2[0] * u2[1], 2 * u2[0] * u2[2] + u2[1] * u2[1],
                               2 * u2[1] * u2[2], Real(1)};
  Series<Real> r{};  // 1/y
  const Real inv_y0 = 1 / y[0];
  for (int k = 0; k < order; ++k) {
    const auto uk = static_cast<std::size_t>(k);
    const Real acc = (k == 0 ? Real(1) : Real(0)) - convolution(y, r, k, 1);
    r[uk] = acc * inv_y0;
    const Real dtau = 2 * (u0 * r[uk] + (k >= 1 ? r[uk - 1] : Real(0)));
    Real dy = k <= 2 ? -2 * zeta * u2[uk] : Real(0);
    for (std::size_t j = 0; j <= std::min<std::size_t>(4, uk); ++j) dy -= 2 * u4[j] * r[uk - j];
    Real ddis = 0;
    for (std::size_t j = 0; j <= std::min<std::size_t>(2, uk); ++j) ddis += 2 * u2[j] * y[uk - j];
    const Real inv = reciprocal<Real>(k + 1);
    tau[uk + 1] = dtau * inv;
    y[uk + 1] = dy * inv;
    dissipation[uk + 1] = ddis * inv;
  }
}

// Hertz time form with state s = (u, y, I). x = u² is carried as its own series through x' = y (exact),
// and u·y = (2/3) d(u·x)/dτ, so that y' = -(ζ·uy + u·x) and I' = uy·y cost three products per order in all
// (y/u, u·x, uy·y) instead of five.
template <class Real>
void expand_hertz_time(Real zeta, const State<Real>& s, int order, Coefficients<Real>& c) {
  auto& u = c[0];
  auto& y = c[1];
  auto& dissipation = c[2];
  for (std::size_t i = 0; i < kComponents; ++i) c[i][0] = s[i];
  Series<Real> q{};   // y/u
  Series<Real> uy{};  // u·y
  Series<Real> x{};   // u²
  Series<Real> ux{};  // u·x = u³
  x[0] = u[0] * u[0];
  ux[0] = x[0] * u[0];
  const Real inv_u0 = 1 / u[0];
  for (int k = 0; k < order; ++k) {
    const auto uk = static_cast<std::size_t>(k);
    const Real inv = reciprocal<Real>(k + 1);
    q[uk] = (y[uk] - convolution(u, q, k, 1)) * inv_u0;
    u[uk + 1] = q[uk] * inv / 2;
    x[uk + 1] = y[uk] * inv;
    ux[uk + 1] = convolution(u, x, k + 1);
    uy[uk] = Real(2) / 3 * Real(k + 1) * ux[uk + 1];
    y[uk + 1] = -(zeta * uy[uk] + ux[uk]) * inv;
    dissipation[uk + 1] = convolution(uy, y, k) * inv;
  }
}

// Dash-pot time form with state s = (x, y, I).
template <class Real>
void expand_dashpot_time(Real damping, Real stiffness, const State<Real>& s, int order,
                         Coefficients<Real>& c) {
  auto& x = c[0];
  auto& y = c[1];
  auto& dissipation = c[2];
  for (std::size_t i = 0; i < kComponents; ++i) c[i][0] = s[i];
  for (int k = 0; k < order; ++k) {
    const auto uk = static_cast<std::size_t>(k);
    const Real inv = reciprocal<Real>(k + 1);
    x[uk + 1] = y[uk] * inv;
    y[uk + 1] = -(damping * y[uk] + stiffness * x[uk]) * inv;
    dissipation[uk + 1] = convolution(y, y, k) * inv;
  }
}

// Value and derivative of one component's polynomial at h (Horner).
template <class Real>
struct ValueSlope {
  Real value;
  Real slope;
};

template <class Real>
ValueSlope<Real> evaluate(const Series<Real>& a, int order, Real h) {
  Real value = a[static_cast<std::size_t>(order)];
  Real slope = 0;
  for (int k = order - 1; k >= 0; --k) {
    slope = slope * h + value;
    value = value * h + a[static_cast<std::size_t>(k)];
  }
  return {value, slope};
}

template <class Real>
State<Real> evaluate_state(const Coefficients<Real>& c, int order, Real h) {
  State<Real> s{};
  for (std::size_t i = 0; i < kComponents; ++i) {
    Real value = c[i][static_cast<std::size_t>(order)];
    for (int k = order - 1; k >= 0; --k) value = value * h + c[i][static_cast<std::size_t>(k)];
    s[i] = value;
  }
  return s;
}

}  // namespace restitution::taylor
