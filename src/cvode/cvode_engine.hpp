// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The CVODE engine (`--method bdf|adams|auto`): BDF or Adams on the smooth formulation, with tolerances from
// the tolerance policy. Holds one integrator per method, reused across solves; one engine per thread.
#include <optional>

#include "cvode/cvode_integrator.hpp"
#include "engine/engine.hpp"
#include "sundials/handles.hpp"

namespace restitution {

// The methods CVODE integrates a collision with: `method` from the start and, when set, `tail` from the
// delayed-recovery end on while the naive end is pending. The one place that decides `automatic`
// (resolve_method reports the method the result carries: the tail's when there is one).
struct MethodChoice {
  Method method = Method::adams;
  std::optional<Method> tail;
};
MethodChoice choose_methods(const ContactLaw& law, Method requested, EndSet ends);
// The method a result of choose_methods carries (the tail's when there is one): what sets CVODE's rounding.
Method resolve_method(const ContactLaw& law, Method requested, EndSet ends);

// Largest ζ for which method adams computes the naive end (viscoelastic Hertz): the overdamped tail after the
// delayed-recovery end is stiff and Adams' steps grow like ζ^{5/3} (258 000 at ζ = 1000, 811 000 at 2000,
// past the million steps of one phase from ζ ~ 2500, at any tolerance). auto switches to BDF there instead.
inline constexpr double kAdamsNaiveZetaMax = 2000.0;

class CvodeEngine final : public Engine {
 public:
  CvodeEngine() = default;  // allocates no SUNDIALS object before the first solve: cheap for a check
  ~CvodeEngine() override = default;
  CvodeEngine(const CvodeEngine&) = delete;
  CvodeEngine& operator=(const CvodeEngine&) = delete;
  CvodeEngine(CvodeEngine&&) = delete;
  CvodeEngine& operator=(CvodeEngine&&) = delete;

  void check(const ContactLaw& law, const SolveOptions& options) const override;
  // Method::automatic is resolved here, to BDF or Adams (resolve_method).
  CollisionResult solve(const ContactLaw& law, const SolveOptions& options) override;

 private:
  detail::CvodeIntegrator& integrator(Method method);

  std::optional<sundials::Context> context_;  // before the integrators, which use it until destroyed
  std::optional<detail::CvodeIntegrator> bdf_;
  std::optional<detail::CvodeIntegrator> adams_;
  std::optional<detail::CvodeIntegrator> sundman_;  // Adams on the Sundman form's 4 components
};

}  // namespace restitution
