// SPDX-License-Identifier: BSD-3-Clause
#include "gas/impact_law.hpp"

#include <fmt/core.h>

#include <array>
#include <cmath>

#include "restitution/calibration.hpp"
#include "restitution/errors.hpp"
#include "restitution/fast.hpp"

namespace restitution::gas {
namespace {

// The grid of the solved members in ln ζ: degree-5 Lagrange interpolation of ln(1 − ε²) at this spacing is
// accurate to ~1e-11 relative (ln(1 − ε²) is smooth in ln ζ, its sixth derivative of order one; the
// interpolation error is h^6/720 · max|f^(6)| times the Lebesgue factor of about 3).
constexpr double kGridStep = 1.0 / 16.0;
constexpr int kStencil = 6;

double loss_of(const EndResult& e) {
  return e.one_minus_eps * (1.0 + e.eps);
}

}  // namespace

ImpactLaw hertz_impact_law(double beta, CollisionEnd end) {
  if (!std::isfinite(beta) || beta < 0.0) {
    throw InvalidInput(fmt::format("beta must be finite and >= 0, got {}", beta));
  }
  ImpactLaw law;
  law.kind = LawKind::viscoelastic_hertz;
  law.zeta_at_reference = beta;
  law.reference_speed_m_s = 1.0;
  law.end = end;
  return law;
}

ImpactLaw impact_law_from_eps(LawKind kind, double eps, double velocity_m_s, CollisionEnd end,
                              double tolerance) {
  CalibrationRequest request;
  request.law = kind;
  request.eps = eps;
  request.velocity_m_s = velocity_m_s;
  request.end = end;
  request.tolerance = tolerance;
  request.fast = kind == LawKind::viscoelastic_hertz;
  CollisionSolver solver;
  ImpactLaw law;
  law.kind = kind;
  law.zeta_at_reference = calibrate(request, solver).zeta;
  law.reference_speed_m_s = velocity_m_s;
  law.end = end;
  return law;
}

ImpactLaw constant_eps_law(double eps) {
  if (!std::isfinite(eps) || eps <= 0.0 || eps > 1.0) {
    throw InvalidInput(fmt::format("eps must be in (0, 1], got {}", eps));
  }
  ImpactLaw law;
  law.constant_eps = eps;
  return law;
}

ImpactDissipation::ImpactDissipation(const ImpactLaw& law, double tolerance)
    : law_(law), tolerance_(tolerance) {
  if (law.constant_eps) {
    const double e = *law.constant_eps;
    if (!(e > 0.0 && e <= 1.0)) throw InvalidInput(fmt::format("eps must be in (0, 1], got {}", e));
    constant_loss_ = (1.0 - e) * (1.0 + e);
    return;
  }
  if (!std::isfinite(law.zeta_at_reference) || law.zeta_at_reference < 0.0) {
    throw InvalidInput(fmt::format("zeta must be finite and >= 0, got {}", law.zeta_at_reference));
  }
  if (!std::isfinite(law.reference_speed_m_s) || law.reference_speed_m_s <= 0.0) {
    throw InvalidInput(fmt::format("velocity must be finite and > 0, got {}", law.reference_speed_m_s));
  }
  exponent_ = restitution::speed_independent(law.kind) ? 0.0 : restitution::speed_exponent(law.kind);
  if (law.kind == LawKind::viscoelastic_hertz) return;
  solver_ = std::make_unique<CollisionSolver>();
  if (exponent_ == 0.0) constant_loss_ = solved_loss(law.zeta_at_reference);
}

ImpactDissipation::~ImpactDissipation() = default;
ImpactDissipation::ImpactDissipation(ImpactDissipation&&) noexcept = default;
ImpactDissipation& ImpactDissipation::operator=(ImpactDissipation&&) noexcept = default;

double ImpactDissipation::zeta_at_speed(double speed_m_s) const {
  if (law_.constant_eps || exponent_ == 0.0) return law_.zeta_at_reference;
  return law_.zeta_at_reference * std::pow(speed_m_s / law_.reference_speed_m_s, exponent_);
}

double ImpactDissipation::loss_at_zeta(double zeta) {
  if (constant_loss_ >= 0.0) return constant_loss_;
  if (zeta == 0.0) return 0.0;
  if (law_.kind == LawKind::viscoelastic_hertz) {
    const double one_minus = fast::one_minus_eps(zeta, law_.end);
    return one_minus * (2.0 - one_minus);
  }
  return interpolated_loss(zeta);
}

double ImpactDissipation::solved_loss(double zeta) {
  SolveOptions options;
  options.tolerance = tolerance_;
  options.ends = EndSet{law_.end};
  return loss_of(end_of(solver_->solve(ContactLaw::natural(law_.kind, zeta), options), law_.end));
}

// Constant damping (ζ ∝ u^{-1/5}): slow impacts have ζ beyond the checked range, where ε -> 0 and 1 − ε² ->
// 1; they are held at the loss of the range's end (their weight in the gas is that of speeds 1e-30 below the
// thermal one).
double ImpactDissipation::interpolated_loss(double zeta) {
  const double top = std::log(kLargestCheckedZeta) - kStencil * kGridStep;
  const double s = std::min(std::log(zeta), top);
  const auto first = static_cast<long>(std::floor(s / kGridStep)) - kStencil / 2 + 1;
  std::array<double, kStencil> nodes{};
  for (int j = 0; j < kStencil; ++j) {
    const long k = first + j;
    auto it = grid_.find(k);
    if (it == grid_.end()) {
      it = grid_.emplace(k, std::log(solved_loss(std::exp(static_cast<double>(k) * kGridStep)))).first;
    }
    nodes[static_cast<std::size_t>(j)] = it->second;
  }
  // Lagrange in the grid's own coordinate, x = s / h - first ∈ [kStencil/2 - 1, kStencil/2).
  const double x = s / kGridStep - static_cast<double>(first);
  double value = 0.0;
  for (int j = 0; j < kStencil; ++j) {
    double weight = 1.0;
    for (int i = 0; i < kStencil; ++i) {
      if (i != j) weight *= (x - i) / static_cast<double>(j - i);
    }
    value += weight * nodes[static_cast<std::size_t>(j)];
  }
  return std::exp(value);
}

}  // namespace restitution::gas
