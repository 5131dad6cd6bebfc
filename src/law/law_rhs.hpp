// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// What the engines need of a law beyond the installed API (include/restitution/contact_law.hpp): the
// right-hand side inline for their inner loops, its derivatives for the Jacobians, the scales that set their
// absolute tolerances and the certificate that a naive end cannot come. Private to the library: users need
// none of it.
#include <cmath>

#include "restitution/contact_law.hpp"

namespace restitution {
namespace detail {
// x^e for x > 0. The quarter exponents of the named members are written with sqrt, which is correctly
// rounded (std::pow is not) and several times faster.
inline double positive_power(double x, double e) {
  if (e == 0.0) return 1.0;
  if (e == 1.0) return x;
  if (e == 0.5) return std::sqrt(x);
  if (e == 1.5) return x * std::sqrt(x);
  if (e == 0.25) return std::sqrt(std::sqrt(x));
  if (e == 0.75) return std::sqrt(x) * std::sqrt(std::sqrt(x));
  if (e == 1.25) return x * std::sqrt(std::sqrt(x));
  return std::pow(x, e);
}
// x^e continued to x <= 0: smoothly for an integer e, by 0 otherwise (contact_law.hpp's header comment).
inline double continued_power(double x, double e) {
  if (x > 0.0) return positive_power(x, e);
  if (e == 0.0) return 1.0;
  if (e == 1.0) return x;
  return e == std::floor(e) ? std::pow(x, e) : 0.0;
}
}  // namespace detail

// The equation of motion x'' = -w(x) (c_d x' + c_s x^{a-b}) and its derivatives, inline: ContactLaw's members
// of the same names are these.
namespace law_rhs {

inline double shape(const ContactLaw& law, double x) {  // w(x) = x^b
  return detail::continued_power(x, law.damping_exponent());
}
inline double shape_derivative(const ContactLaw& law, double x) {
  const double b = law.damping_exponent();
  if (x <= 0.0 || b == 0.0) return 0.0;
  return b / detail::positive_power(x, 1.0 - b);
}
// c_d x' + c_s x^{a-b}: the force divided by w(x); it changes sign at the force-zero end.
inline double force_factor(const ContactLaw& law, double x, double v) {
  return law.damping() * v +
         law.stiffness() * detail::continued_power(x, law.elastic_exponent() - law.damping_exponent());
}
// d x^{a-b}/dx
inline double elastic_slope(const ContactLaw& law, double x) {
  const double e = law.elastic_exponent() - law.damping_exponent();
  if (e == 1.0) return 1.0;
  if (x <= 0.0) return e == std::floor(e) ? e * std::pow(x, e - 1.0) : 0.0;
  return e * detail::positive_power(x, e - 1.0);
}
inline double acceleration(const ContactLaw& law, double x, double v) {
  return -shape(law, x) * force_factor(law, x, v);
}
inline double dacceleration_dx(const ContactLaw& law, double x, double v) {
  return -(shape_derivative(law, x) * force_factor(law, x, v) +
           shape(law, x) * (law.stiffness() * elastic_slope(law, x)));
}
inline double dacceleration_dv(const ContactLaw& law, double x) {
  return -shape(law, x) * law.damping();
}
// The dissipation integrand w(x) x'^2 (free of c_d: ContactLaw::dissipation_integrand).
inline double dissipation_integrand(const ContactLaw& law, double x, double v) {
  return shape(law, x) * v * v;
}
inline double ddissipation_integrand_dx(const ContactLaw& law, double x, double v) {
  return shape_derivative(law, x) * v * v;
}
inline double ddissipation_integrand_dv(const ContactLaw& law, double x, double v) {
  return 2.0 * shape(law, x) * v;
}

}  // namespace law_rhs

// Natural-unit magnitudes (x'(0) = 1) of the smallest compression, velocity and dissipation integral that
// decide the requested results: the tolerance policies scale absolute tolerances with them. Derived from the
// scaling of the member (docs/contact_laws.md).
struct ResolutionScales {
  double x = 1.0;
  double velocity = 1.0;
  double dissipation = 1.0;
};
ResolutionScales resolution_scales(const ContactLaw& law, EndSet ends);

// For NaiveEndExistence::decided_by_solve: a function of the state that is <= 0 only where the overlap
// provably never returns to 0 (x > 0, x' <= 0 in the invariant region x' >= -k x^{b+1}, x^{a-2b-1} <
// ζ²/(4(b+1)), k = ζ/(2(b+1)): docs/contact_laws.md), positive before maximal compression; natural units.
double naive_end_excluded(const ContactLaw& law, double x, double v);

}  // namespace restitution
