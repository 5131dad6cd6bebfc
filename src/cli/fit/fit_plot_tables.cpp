// SPDX-License-Identifier: BSD-3-Clause
#include "cli/fit/fit_plot_tables.hpp"

#include <fmt/core.h>
#include <fmt/format.h>

#include <iterator>
#include <limits>

#include "fit/fit_curves.hpp"
#include "sweep/number_text.hpp"

namespace restitution::cli {
namespace {

// law_end, e.g. viscoelastic-hertz_delayed-recovery: the one underscore separates the law from the end.
std::string label(const LawFit& f) {
  return fmt::format("{}_{}", law_name(f.candidate.law), end_name(f.candidate.end));
}

}  // namespace

std::string fit_data_table(const FitData& d, const FitResult& r) {
  std::string csv = "v,eps,sigma";
  for (const LawFit& f : r.fits) csv += fmt::format(",model_{0},residual_{0}", label(f));
  csv += "\n";
  for (std::size_t i = 0; i < d.eps.size(); ++i) {
    // format_to rather than "," + text: GCC 12 warns (-Wrestrict) on that inlined concatenation, wrongly.
    fmt::format_to(std::back_inserter(csv), "{},{},{}", number17(d.velocity_m_s[i]), number17(d.eps[i]),
                   number17(d.sigma.empty() ? std::numeric_limits<double>::quiet_NaN() : d.sigma[i]));
    for (const LawFit& f : r.fits) {
      const double m = f.model_eps.empty() ? std::numeric_limits<double>::quiet_NaN() : f.model_eps[i];
      fmt::format_to(std::back_inserter(csv), ",{},{}", number17(m), number17(d.eps[i] - m));
    }
    csv += "\n";
  }
  return csv;
}

std::string fit_curves_table(const FitData& d, const FitResult& r, const FitOptions& options) {
  const FitCurves curves = fit_curves(d, r, options);
  std::string csv = "v";
  for (const FitCurve& c : curves.curves)
    csv += fmt::format(",eps_{0},low_{0},high_{0}", label(r.fits[c.fit]));
  csv += "\n";
  for (std::size_t k = 0; k < curves.velocity_m_s.size(); ++k) {
    csv += number17(curves.velocity_m_s[k]);
    for (const FitCurve& c : curves.curves)
      fmt::format_to(std::back_inserter(csv), ",{},{},{}", number17(c.eps[k]), number17(c.band_low[k]),
                     number17(c.band_high[k]));
    csv += "\n";
  }
  return csv;
}

}  // namespace restitution::cli
