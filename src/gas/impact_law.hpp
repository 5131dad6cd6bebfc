// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The energy a collision of the gas loses, 1 − ε(u)², as a function of the normal impact speed u [m/s], for
// one member of the contact-law family (docs/gas.md). A member with fixed physical coefficients has
// ζ(u) = ζ_ref (u / v_ref)^p with p = speed_exponent(kind) (1/5 for viscoelastic Hertz: ζ = β u^{1/5}), so
// one ζ at one speed fixes ε(u) at every speed. Viscoelastic Hertz is read from the certified fast table
// (restitution/fast.hpp, |Δε| <= 1e-13 min(ε, 1 − ε)); the other members are solved with the collision
// solver, once for the speed-independent ones, on a grid in ln ζ interpolated for constant damping.
#include <map>
#include <memory>
#include <optional>

#include "restitution/collision_solver.hpp"
#include "restitution_gas/impact_law.hpp"

namespace restitution::gas {

// 1 − ε² of a law at any impact speed. Holds a solver and a cache: one per thread.
class ImpactDissipation {
 public:
  // tolerance: accuracy of each solve for the members without a fast table (SolveOptions::tolerance).
  explicit ImpactDissipation(const ImpactLaw& law, double tolerance = SolveOptions{}.tolerance);
  ~ImpactDissipation();
  ImpactDissipation(ImpactDissipation&& other) noexcept;
  ImpactDissipation& operator=(ImpactDissipation&& other) noexcept;
  ImpactDissipation(const ImpactDissipation&) = delete;
  ImpactDissipation& operator=(const ImpactDissipation&) = delete;

  [[nodiscard]] const ImpactLaw& law() const { return law_; }
  // ζ(u) = ζ_ref (u / v_ref)^p.
  [[nodiscard]] double zeta_at_speed(double speed_m_s) const;
  // The speed exponent p of ε(u) (0 for a constant ε).
  [[nodiscard]] double speed_exponent() const { return exponent_; }
  // 1 − ε² at ζ of the natural form, and at impact speed u [m/s].
  double loss_at_zeta(double zeta);
  double loss_at_speed(double speed_m_s) { return loss_at_zeta(zeta_at_speed(speed_m_s)); }

 private:
  double solved_loss(double zeta);
  double interpolated_loss(double zeta);

  ImpactLaw law_;
  double exponent_ = 0.0;
  double tolerance_ = 0.0;
  double constant_loss_ = -1.0;  // the speed-independent members: 1 − ε², once solved
  std::unique_ptr<CollisionSolver> solver_;
  std::map<long, double> grid_;  // ln(1 − ε²) at ln ζ = k · kGridStep, computed when first needed
};

}  // namespace restitution::gas
