// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Contact laws: the equation of motion of the compression x(τ), written once for every engine.
//
// The family (docs/contact_laws.md), in natural units (x'(0) = 1):
//     x'' + ζ x^b x' + x^a = 0,   x(0) = 0,  x'(0) = 1,
// one member per LawKind (exponents a, b in src/law/law_family.cpp). The engines see it as
//     x'' = -w(x) · (c_d · x' + c_s · x^{a-b}),   w(x) = x^b,
// with c_d = ζ, c_s = 1 in natural units (the 2008 paper's scaled Hertz form has other c_d, c_s, x'(0)).
// A non-integer power of x is 0 at x <= 0 (no force without overlap; the root of a trial step's negative x
// is never taken); an integer power keeps its smooth continuation (the linear dash-pot: only trial steps
// and the root finder see x < 0, and a force switched off there would put a jump exactly at the naive end).
// The force vanishes where c_d x' + c_s x^{a-b} = 0: the root function of the force-zero end ("clamp on",
// CollisionEnd::delayed_recovery, docs/design.md §1). The dissipated energy per unit (scaled) mass grows as
// dD/dτ = c_d · w(x) · x'^2; the elastic energy is U(x) = c_s x^{a+1}/(a+1).
#include <array>
#include <cfloat>
#include <cmath>
#include <cstddef>
#include <initializer_list>
#include <string>
#include <vector>

namespace restitution {

// Named members: viscoelastic Hertz (a = 3/2, b = 1/2), linear dash-pot (1, 0), Tsuji (3/2, 1/4), Hertz with
// constant damping (3/2, 0).
enum class LawKind { viscoelastic_hertz, linear_dashpot, tsuji_hertz, hertz_constant_damping };
inline constexpr std::array<LawKind, 4> kLawKinds{LawKind::viscoelastic_hertz, LawKind::linear_dashpot,
                                                  LawKind::tsuji_hertz, LawKind::hertz_constant_damping};

// "viscoelastic-hertz" | "linear-dashpot" | "tsuji-hertz" | "hertz-constant-damping"
const char* law_name(LawKind kind);
LawKind law_from_name(const std::string& name);  // the inverse; throws InvalidInput naming the value
// Every member's name, in the order of kLawKinds (the choices of a front end's law option).
const std::vector<std::string>& law_names();
// Whether a material sets the law's damping through the dissipative constant A (so that A, β and a Material
// describe it): viscoelastic Hertz alone; the other members take their natural-form parameter only.
bool has_dissipative_constant(LawKind kind);

// The parameter a member's results are labelled with and taken in: ζ of the natural form, or for the
// linear dash-pot its damping ratio r (ζ = 2r).
struct LawParameter {
  const char* name = "zeta";        // "zeta" | "damping-ratio" (messages, option and column names)
  double zeta_per_parameter = 1.0;  // ζ = zeta_per_parameter · parameter
};
LawParameter law_parameter(LawKind kind);

// The exponents of a member: elastic force ∝ x^a, damping force ∝ x^b x'.
struct LawExponents {
  double elastic = 1.5;  // a
  double damping = 0.5;  // b
};
LawExponents law_exponents(LawKind kind);

// d ln ζ / d ln v = b + (b+1)(1-a)/(1+a) for the DEM force of ContactLaw::physical: 1/5 for viscoelastic
// Hertz, -1/5 for constant damping, 0 for Tsuji and the linear dash-pot (ε independent of the impact speed).
double speed_exponent(LawKind kind);
// True where speed_exponent is zero (to rounding).
bool speed_independent(LawKind kind);
// 2 sqrt(b+1): for the scale-invariant members (Tsuji, the dash-pot) the largest ζ below which the naive end
// exists (docs/contact_laws.md).
double naive_end_critical_zeta(LawKind kind);

// The contracted range of ζ: every ζ in [0, kLargestCheckedZeta] is checked against the reference solutions
// (docs/accuracy.md). The front ends (CLI, sweeps, scenes, calibration) refuse larger ζ with
// require_checked_zeta; the solver itself still accepts them (tests probe beyond the range).
inline constexpr double kLargestCheckedZeta = 1e6;
// The smallest ζ > 0 served: the smallest normal double (ζ = 0 itself is served, ε = 1 exactly). For small ζ
// 1 - ε = C ζ with C = 1.153 (viscoelastic Hertz), 1.405 (Tsuji), π/2 (the dash-pot), 1.788 (constant
// damping), both ends; so from this ζ on ζ, 1 - ε and the dissipated energy 1 - ε² = 2 C ζ are normal
// doubles, each carried to a relative 1.1e-16, far below the smallest tolerance (1e-13). Below it they would
// be subnormal, whose fixed spacing 4.9e-324 is a relative step of 5e-4 at ζ = 1e-320: the contract |Δε| <= T
// (1 - ε) could not hold (docs/accuracy.md).
inline constexpr double kSmallestServedZeta = DBL_MIN;
// Throws InvalidInput naming ζ and the checked range when zeta > kLargestCheckedZeta (or is not finite),
// and require_served_zeta's refusal below kSmallestServedZeta.
void require_checked_zeta(double zeta);
// Throws InvalidInput naming ζ and kSmallestServedZeta when 0 < zeta < kSmallestServedZeta. Every engine's
// check calls it, so every front end refuses such a ζ.
void require_served_zeta(double zeta);

// The time scale T = (v^{1-a} m/k)^{1/(1+a)} [s] of ContactLaw::physical (its length scale is v·T [m]):
// τ_natural · T is the time in seconds, x_natural · v · T the compression in metres.
double physical_time_scale_s(LawKind kind, double stiffness_N_per_m_a, double effective_mass_kg,
                             double impact_speed_m_s);

// One end of the collision, for callers that ask for a single end. naive: the overlap returns to x = 0
// ("clamp off"); delayed_recovery: the total force first reaches 0, c_d x' + c_s x^{a-b} = 0, where a DEM
// code that zeroes an attractive force separates the spheres ("clamp on"; docs/contact_laws.md).
enum class CollisionEnd { naive, delayed_recovery };

// Both ends, in the order a collision reaches them last (for loops over the ends).
inline constexpr std::array<CollisionEnd, 2> kCollisionEnds{CollisionEnd::naive,
                                                            CollisionEnd::delayed_recovery};

// A set of collision ends: which ends a solve computes. Built from CollisionEnd values, e.g.
// EndSet{CollisionEnd::naive}; an EndSet{} is empty.
class EndSet {
 public:
  constexpr EndSet() = default;
  constexpr EndSet(std::initializer_list<CollisionEnd> ends) {
    for (const CollisionEnd end : ends) insert(end);
  }
  [[nodiscard]] static constexpr EndSet both() {
    return {CollisionEnd::naive, CollisionEnd::delayed_recovery};
  }

  [[nodiscard]] constexpr bool contains(CollisionEnd end) const { return (bits_ & bit(end)) != 0U; }
  [[nodiscard]] constexpr bool empty() const { return bits_ == 0U; }
  constexpr void insert(CollisionEnd end) { bits_ |= bit(end); }
  constexpr void erase(CollisionEnd end) { bits_ &= ~bit(end); }
  // The union of two sets.
  [[nodiscard]] constexpr EndSet operator|(EndSet other) const {
    EndSet out;
    out.bits_ = bits_ | other.bits_;
    return out;
  }
  // Written out, not defaulted: the public headers are C++17 (docs/library.md, "C++ standard").
  [[nodiscard]] constexpr bool operator==(const EndSet& other) const { return bits_ == other.bits_; }
  [[nodiscard]] constexpr bool operator!=(const EndSet& other) const { return !(*this == other); }
  // The members in the order of kCollisionEnds (for loops over the requested ends).
  [[nodiscard]] std::vector<CollisionEnd> members() const {
    std::vector<CollisionEnd> out;
    for (const CollisionEnd end : kCollisionEnds) {
      if (contains(end)) out.push_back(end);
    }
    return out;
  }

 private:
  static constexpr unsigned bit(CollisionEnd end) { return 1U << static_cast<unsigned>(end); }
  unsigned bits_ = 0;
};

// One value per collision end, indexed by CollisionEnd (the only way to reach a value).
template <typename T>
class PerEnd {
 public:
  [[nodiscard]] constexpr const T& operator[](CollisionEnd end) const { return values_[index(end)]; }
  [[nodiscard]] constexpr T& operator[](CollisionEnd end) { return values_[index(end)]; }

 private:
  static constexpr std::size_t index(CollisionEnd end) { return static_cast<std::size_t>(end); }
  std::array<T, 2> values_{};
};

// Whether the naive end (x back to 0) exists: for every ζ (viscoelastic Hertz), below a critical ζ known in
// closed form (the dash-pot, Tsuji), or decided by the solve (constant damping: the overlap may approach 0
// only as τ -> ∞, which the CVODE engine certifies during the solve).
enum class NaiveEndExistence { always, below_critical_zeta, decided_by_solve };

// ε and 1 - ε at an end, each computed in the form that keeps its relative accuracy.
struct EndValues {
  double eps = 0.0;
  double one_minus_eps = 0.0;
};

// A member of the family with its coefficients: a value with invariants, built by the factories below.
class ContactLaw {
 public:
  // The natural viscoelastic Hertz law at ζ = 0 (undamped Hertz spheres).
  ContactLaw() = default;

  // The natural form x'' + ζ x^b x' + x^a = 0, x'(0) = 1 of a member; ζ >= 0 finite (ζ = 0: ε = 1, every
  // member).
  static ContactLaw natural(LawKind kind, double zeta);
  // A DEM force F = k ξ^a + γ ξ^b ξ' on effective mass m at impact speed v (SI: k in N/m^a, γ in
  // N s/m^{1+b}, m in kg, v in m/s), as its natural form: ζ = (γ/m) v^b T^{b+1} with the time scale
  // T = (v^{1-a} m/k)^{1/(1+a)} s and the length scale v·T m. Throws InvalidInput naming a bad argument.
  static ContactLaw physical(LawKind kind, double stiffness_N_per_m_a, double damping_coefficient,
                             double effective_mass_kg, double impact_speed_m_s);
  // The natural form of a member from its labelled parameter (law_parameter: ζ, or r for the dash-pot).
  static ContactLaw of_parameter(LawKind kind, double parameter);
  // Viscoelastic Hertz in natural units: x'' + ζ x' sqrt(x) + x^{3/2} = 0, x'(0) = 1.
  static ContactLaw hertz_natural(double zeta);
  // Viscoelastic Hertz in the 2008 paper's scaling (its Eq. 23):
  // x'' + β v^{-1/5} x' sqrt(x) + v^{-2/5} x^{3/2} = 0, x'(0) = v^{4/5};
  // β in s^{1/5} m^{-1/5} (after the paper's scaling of length and time), v the impact speed.
  static ContactLaw hertz_scaled(double beta, double velocity);
  // Linear dash-pot x'' + 2 r x' + x = 0, x'(0) = 1 (time in units of 1/ω0; r = β/ω0 of the 2008 paper):
  // the member linear_dashpot at ζ = 2r.
  static ContactLaw linear_dashpot(double damping_ratio);
  // Coefficients taken as given, no check at all: only for tests of how the engines report a broken law
  // (a NaN force, no stiffness).
  static ContactLaw unchecked(LawKind kind, double damping, double stiffness);

  [[nodiscard]] LawKind kind() const { return kind_; }
  [[nodiscard]] double zeta() const { return zeta_; }  // ζ of the natural form
  // The parameter results are labelled with: ζ, or the damping ratio r = ζ/2 for the linear dash-pot.
  [[nodiscard]] double parameter() const { return zeta_ / law_parameter(kind_).zeta_per_parameter; }
  // "zeta" | "damping-ratio": the name of parameter() in messages.
  [[nodiscard]] const char* parameter_name() const { return law_parameter(kind_).name; }
  [[nodiscard]] double damping() const { return damping_; }                    // c_d
  [[nodiscard]] double stiffness() const { return stiffness_; }                // c_s
  [[nodiscard]] double initial_velocity() const { return initial_velocity_; }  // x'(0) in the law's units
  // x_natural = x / length_scale, τ_natural = τ / time_scale (1 for a natural law).
  [[nodiscard]] double length_scale() const { return length_scale_; }
  [[nodiscard]] double time_scale() const { return time_scale_; }
  [[nodiscard]] bool is_natural() const { return initial_velocity_ == 1.0 && time_scale_ == 1.0; }
  // The same law in natural units (ContactLaw::natural(kind(), zeta())).
  [[nodiscard]] ContactLaw natural_form() const;
  [[nodiscard]] double elastic_exponent() const { return a_; }  // a
  [[nodiscard]] double damping_exponent() const { return b_; }  // b
  [[nodiscard]] bool speed_independent() const { return restitution::speed_independent(kind_); }

  // The smooth variable near x = 0: u = x^{1/q} with q the smallest integer making q·a and q·b integers
  // (2 for viscoelastic Hertz and constant damping, 4 for Tsuji, 1 for the dash-pot). The solution has
  // terms τ^{b+2}, τ^{a+2}, ... at τ = 0: analytic in u, not in τ (docs/design.md §4).
  [[nodiscard]] int smoothing_root() const { return q_; }
  [[nodiscard]] double compression_of(double u) const {  // x = u^q
    if (q_ == 2) return u * u;
    if (q_ == 4) return (u * u) * (u * u);
    return q_ == 1 ? u : std::pow(u, q_);
  }
  [[nodiscard]] double dcompression_du(double u) const {  // q u^{q-1}
    if (q_ == 2) return 2.0 * u;
    if (q_ == 4) return 4.0 * u * u * u;
    return q_ == 1 ? 1.0 : q_ * std::pow(u, q_ - 1);
  }
  [[nodiscard]] double smooth_variable(double x) const {  // u = x^{1/q}
    if (q_ == 2) return std::sqrt(x);
    if (q_ == 4) return std::sqrt(std::sqrt(x));
    return q_ == 1 ? x : std::pow(x, 1.0 / q_);
  }

  // The equation of motion x'' = -w(x) (c_d x' + c_s x^{a-b}), in the law's own units.
  [[nodiscard]] double shape(double x) const;  // w(x) = x^b
  // c_d x' + c_s x^{a-b}: the force divided by w(x); it changes sign at the force-zero end.
  [[nodiscard]] double force_factor(double x, double v) const;
  [[nodiscard]] double acceleration(double x, double v) const;
  // The dissipated energy is D = c_d · ∫ w(x) x'^2 dτ; the integrand is kept free of c_d so that it stays
  // of order one as c_d -> 0 and D keeps full relative accuracy.
  [[nodiscard]] double dissipation_integrand(double x, double v) const;
  // U(x) = c_s x^{a+1}/(a+1), 0 without overlap (written x·x·x^{a-1}: every member has a >= 1).
  [[nodiscard]] double elastic_energy(double x) const;

  // ε and 1 - ε at an end reached at compression x (law's units) with velocity `velocity` and dissipation
  // integral I = ∫ w(x) x'^2 dτ: ε from the velocity, 1 - ε from the energy balance
  // 1 - ε² = 2(c_d I + U(x))/v0², each where it keeps full relative accuracy (ε <= 1/2 and ε > 1/2).
  [[nodiscard]] EndValues end_values(double x, double velocity, double dissipation_integral) const;

  // What the tolerance policies need (natural units unless said otherwise), derived from the scaling of
  // the member (docs/contact_laws.md): a factor (<= 1) on the local tolerance where the end is
  // ill-conditioned, and a time limit (law's own τ) no end lies beyond.
  [[nodiscard]] double conditioning(EndSet ends) const;
  [[nodiscard]] double time_limit(EndSet ends) const;

  // For decided_by_solve: a factor (<= 1) on the local tolerance for a naive end with this ε, found by a
  // first solve. Close to the largest ζ with a naive end the trajectory passes close to the saddle at x = 0
  // and ε's absolute error stays ~1e-3 · tolerance while ε -> 0 (measured against an independent
  // integration, tests/test_contact_law_family.cpp); 1 for the other members.
  [[nodiscard]] double naive_end_conditioning(double naive_eps) const;
  [[nodiscard]] NaiveEndExistence naive_end_existence() const;
  // For below_critical_zeta: whether the naive end exists at this ζ (ζ < 2 sqrt(b+1): r < 1 for the
  // dash-pot, ζ < sqrt(5) for Tsuji); for always true; for decided_by_solve true (the solve decides).
  [[nodiscard]] bool naive_end_may_exist() const;
  // The critical ζ of a scale-invariant member, naive_end_critical_zeta(kind()): the naive end exists below
  // it (ζ = 2 for the dash-pot, r = 1; sqrt(5) for Tsuji).
  [[nodiscard]] double critical_zeta() const { return naive_end_critical_zeta(kind_); }
  // The naive end's balance 1 - a + 2b: its sign decides how the overlap behaves as x -> 0
  // (docs/contact_laws.md). Positive (viscoelastic Hertz): inertia wins near x = 0 and the naive end always
  // exists, reached through x ~ ζ^{-2/(1-a+2b)} at large ζ. Zero (the dash-pot, Tsuji): the law is
  // scale-invariant near x = 0 and the naive end exists for ζ < 2 sqrt(b+1). Negative (constant damping):
  // damping wins near x = 0 and the overlap may only approach 0 as τ -> ∞.
  [[nodiscard]] double naive_balance() const { return 1.0 - a_ + 2.0 * b_; }
  // How ε at the requested ends depends on ζ (docs/accuracy.md, "Conditioning"): `condition` bounds
  // |d ln q / d ln ζ| with q = min(ε, 1 - ε), the factor by which a relative perturbation of ζ, or a rounding
  // of the solve that acts like one, grows in the result. In closed form for the naive end of the
  // scale-invariant members, πρ/(1-ρ²)^{3/2} with ρ = ζ/(2 sqrt(b+1)), which diverges at critical damping;
  // elsewhere bounded by kBoundedCondition (ε and 1 - ε are powers of ζ at both extremes of the checked
  // range; constant damping's naive end near its critical ζ is decided by the solve, naive_end_conditioning).
  // `log_eps` is ln of the closed-form naive ε where one is known (0 otherwise: no bound); a logarithm, since
  // near critical damping ε underflows (ln ε = -2963 at r = 1 - 5.6e-7).
  struct Conditioning {
    double condition = 1.0;
    double log_eps = 0.0;
  };
  static constexpr double kBoundedCondition = 10.0;
  [[nodiscard]] Conditioning input_conditioning(EndSet ends) const;
  // Below this ζ the force-zero end lies within rounding of x = 0 (ζ|x'| = x^{a-b} there): the two ends
  // differ in 1 - ε by a relative ζ^{(b+1)/(a-b)} < 1e-30, and the engines report the naive end's ε for it.
  [[nodiscard]] double indistinguishable_ends_zeta() const;
  // The compression at the force-zero end for such a ζ, from the velocity there.
  [[nodiscard]] double force_zero_compression(double velocity) const;

 private:
  ContactLaw(LawKind kind, double zeta);

  LawKind kind_ = LawKind::viscoelastic_hertz;
  double a_ = 1.5;
  double b_ = 0.5;
  int q_ = 2;
  double energy_coefficient_ = 0.4;  // 1/(a+1)
  double zeta_ = 0.0;
  double damping_ = 0.0;
  double stiffness_ = 1.0;
  double initial_velocity_ = 1.0;
  double length_scale_ = 1.0;
  double time_scale_ = 1.0;
};

}  // namespace restitution
