#include "scene/scene_extensions.hpp"

#include <fmt/core.h>

#include "restitution/series.hpp"
#include "restitution/series_tables.hpp"

namespace restitution::scene::detail {
namespace {

using series::Approximation;

// Column label and source of an approximation evaluated with the published coefficients.
std::pair<std::string, std::string> describe(Approximation a) {
  switch (a) {
    case Approximation::naive_series:
      return {"naive_series", "naive series, 2008 paper Table III (c_1 ... c_10)"};
    case Approximation::delayed_recovery_series:
      return {"delayed_recovery_series", "delayed-recovery series, 2008 paper Table V (h_0 ... h_20)"};
    case Approximation::pade_1999:
      return {"pade_1999", "1999 paper's Padé [1/4] (Eq. 35, a_3 and a_4 of Eq. 33)"};
    case Approximation::simple_theory_1999:
      return {"simple_theory_1999", "1999 paper's simple theory eps + w eps^(3/5) = 1 (Eq. 27)"};
    case Approximation::pade_2011_1_4:
      return {"pade_2011_1_4", "Müller & Pöschel 2011 Padé [1/4] in sqrt(zeta)"};
    case Approximation::pade_2011_3_6:
      return {"pade_2011_3_6", "Müller & Pöschel 2011 Padé [3/6] in sqrt(zeta)"};
  }
  return {"unknown", "unknown"};
}

double evaluate(Approximation a, double zeta) {
  namespace published = series::published;
  switch (a) {
    case Approximation::naive_series:
      return series::naive_series(zeta, published::kTable3C).eps;
    case Approximation::delayed_recovery_series:
      return series::delayed_recovery_series(zeta, published::kTable5H).eps;
    case Approximation::pade_1999:
      return series::pade_1999(zeta, series::pade_1999_published()).eps;
    case Approximation::simple_theory_1999:
      return series::simple_theory_1999(zeta).eps;
    case Approximation::pade_2011_1_4:
      return series::pade_2011_1_4(zeta).eps;
    case Approximation::pade_2011_3_6:
      return series::pade_2011_3_6(zeta).eps;
  }
  return 0.0;
}

}  // namespace

void add_approximations(const Sweep& sweep, const std::vector<double>& zeta, SweepExtras& extras) {
  for (const Approximation a : sweep.approximations) {
    ApproximationColumn column;
    std::tie(column.label, column.source) = describe(a);
    column.end = series::describes_delayed_recovery(a) ? CollisionEnd::delayed_recovery : CollisionEnd::naive;
    for (const double z : zeta) column.eps.push_back(evaluate(a, z));
    extras.approximations.push_back(std::move(column));
  }
}

void add_power_law_fits(const Sweep& sweep, const std::vector<double>& /*zeta*/,
                        const std::vector<const CollisionResult*>& /*results*/, SweepExtras& extras) {
  if (!sweep.fit) return;
  extras.notes.emplace_back(
      "power-law fit: not available in this build (the asymptotics module has not been merged)");
}

std::string study_note(const ExternalStudy& study) {
  return fmt::format("{} study '{}': not available in this build (its module has not been merged)",
                     study.kind, study.name);
}

}  // namespace restitution::scene::detail
