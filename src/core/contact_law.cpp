#include "restitution/contact_law.hpp"

#include <fmt/core.h>
#include <cmath>

#include <string>

#include "restitution/errors.hpp"

namespace restitution {
namespace {

void require_finite_nonnegative(double value, const char* name) {
  if (!std::isfinite(value) || value < 0.0) {
    throw InvalidInput(fmt::format("{} must be finite and >= 0, got {}", name, value));
  }
}

}  // namespace

void require_checked_zeta(double zeta) {
  require_finite_nonnegative(zeta, "zeta");
  if (zeta > kLargestCheckedZeta) {
    throw InvalidInput(
        fmt::format("zeta = {} is outside the checked range 0 <= zeta <= {:g}", zeta, kLargestCheckedZeta));
  }
}

const char* law_name(LawKind kind) {
  return kind == LawKind::viscoelastic_hertz ? "viscoelastic-hertz" : "linear-dashpot";
}

ContactLaw ContactLaw::hertz_natural(double zeta) {
  require_finite_nonnegative(zeta, "zeta");
  ContactLaw law;
  law.kind = LawKind::viscoelastic_hertz;
  law.damping = zeta;
  law.parameter = zeta;
  return law;
}

ContactLaw ContactLaw::hertz_scaled(double beta, double velocity) {
  require_finite_nonnegative(beta, "beta");
  if (!std::isfinite(velocity) || velocity <= 0.0) {
    throw InvalidInput(fmt::format("velocity must be finite and > 0, got {}", velocity));
  }
  ContactLaw law;
  law.kind = LawKind::viscoelastic_hertz;
  law.damping = beta * std::pow(velocity, -0.2);
  law.stiffness = std::pow(velocity, -0.4);
  law.initial_velocity = std::pow(velocity, 0.8);
  law.parameter = beta * std::pow(velocity, 0.2);
  if (!std::isfinite(law.damping) || !std::isfinite(law.stiffness) || law.initial_velocity <= 0.0 ||
      !std::isfinite(law.initial_velocity) || !std::isfinite(law.parameter)) {
    throw InvalidInput(fmt::format(
        "beta={} and velocity={} give a scaled equation outside the range of double", beta, velocity));
  }
  // x scales as v^{4/5}; τ is the same in both forms (x = v^{4/5} X turns Eq. 23 into the natural form).
  law.length_scale = law.initial_velocity;
  return law;
}

ContactLaw ContactLaw::linear_dashpot(double damping_ratio) {
  if (!std::isfinite(damping_ratio) || damping_ratio <= 0.0) {
    throw InvalidInput(fmt::format("damping-ratio must be finite and > 0, got {}", damping_ratio));
  }
  ContactLaw law;
  law.kind = LawKind::linear_dashpot;
  law.damping = 2.0 * damping_ratio;
  law.parameter = damping_ratio;
  return law;
}

}  // namespace restitution
