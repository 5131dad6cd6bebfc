// SPDX-License-Identifier: BSD-3-Clause
#include "fit/best_hertz_fit.hpp"

namespace restitution {

std::optional<std::size_t> best_hertz_fit(const FitResult& result) {
  std::optional<std::size_t> best;
  for (std::size_t i = 0; i < result.fits.size(); ++i) {
    const LawFit& f = result.fits[i];
    if (f.candidate.law != LawKind::viscoelastic_hertz || f.status != FitStatus::converged) continue;
    if (!best || f.aic < result.fits[*best].aic) best = i;
  }
  return best;
}

}  // namespace restitution
