// SPDX-License-Identifier: BSD-3-Clause
// restitution.fit_data: a fit of measured eps(v) with every candidate law (restitution/fit.hpp), returned as
// a dict with the keys of `restitution fit-data --json` (docs/fit.md); a bound at the edge of the checked
// range is None.
#include <pybind11/stl.h>

#include <optional>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "restitution/fit.hpp"
#include "restitution/material.hpp"
#include "without_gil.hpp"

namespace py = pybind11;

namespace restitution::python {
namespace {

py::object bound(double value, bool edge) {
  return edge ? py::object(py::none()) : py::object(py::float_(value));
}

py::list interval(const FitInterval& i) {
  py::list out;
  out.append(bound(i.low, i.low_at_edge));
  out.append(bound(i.high, i.high_at_edge));
  return out;
}

py::dict fit_dict(const LawFit& f) {
  py::dict d;
  d["law"] = law_name(f.candidate.law);
  d["end"] = end_name(f.candidate.end);
  d["parameter"] = f.parameter;
  d["status"] = fit_status_name(f.status);
  d["converged"] = f.status == FitStatus::converged;
  d["message"] = f.message;
  d["value"] = bound(f.value, f.status != FitStatus::converged);
  d["ci68"] = interval(f.ci68);
  d["ci95"] = interval(f.ci95);
  d["chi2"] = f.chi2;
  d["dof"] = f.dof;
  d["chi2_per_dof"] = f.chi2_per_dof;
  d["aic"] = f.aic;
  d["bic"] = f.bic;
  py::dict r;
  r["available"] = f.residuals.available;
  r["slope_per_ln_v"] = f.residuals.slope;
  r["slope_error"] = f.residuals.slope_error;
  r["slope_p_value"] = f.residuals.slope_p_value;
  r["runs"] = f.residuals.runs;
  r["runs_expected"] = f.residuals.runs_expected;
  r["runs_p_value"] = f.residuals.runs_p_value;
  r["verdict"] = f.residuals.verdict;
  if (!f.residuals.available) r["unavailable"] = f.residuals.unavailable;
  d["residual_tests"] = r;
  if (f.characteristic_velocity_m_s) {
    d["characteristic_velocity_m_s"] = *f.characteristic_velocity_m_s;
    d["characteristic_velocity_ci68"] = interval(f.characteristic_velocity_ci68);
    d["characteristic_velocity_ci95"] = interval(f.characteristic_velocity_ci95);
  }
  if (f.dissipative_constant_s) {
    d["dissipative_constant_s"] = *f.dissipative_constant_s;
    d["dissipative_constant_ci68"] = interval(f.dissipative_constant_ci68);
    d["dissipative_constant_ci95"] = interval(f.dissipative_constant_ci95);
  }
  d["model_eps"] = f.model_eps;
  return d;
}

py::dict result_dict(const FitResult& r) {
  py::dict d;
  py::list fits;
  for (const LawFit& f : r.fits) fits.append(fit_dict(f));
  d["fits"] = fits;
  d["best"] = r.best ? py::object(py::int_(*r.best)) : py::object(py::none());
  d["tied_with_best"] = r.tied_with_best;
  d["sigma_estimated"] = r.sigma_estimated;
  d["levels"] = py::dict(py::arg("ci68") = r.level68, py::arg("ci95") = r.level95);
  d["points"] = r.points;
  return d;
}

}  // namespace

void bind_fit(py::module_& m) {
  m.def(
      "fit_data",
      [](std::vector<double> v, std::vector<double> eps, std::optional<std::vector<double>> sigma,
         std::optional<std::vector<std::string>> laws, const std::string& speed_independent_end,
         const std::optional<Material>& material, double tolerance, const std::string& method) {
        FitData data{std::move(v), std::move(eps), sigma.value_or(std::vector<double>{})};
        FitOptions options;
        options.candidates = fit_candidates(laws.value_or(std::vector<std::string>{}), speed_independent_end);
        options.tolerance = tolerance;
        options.method = method_from_name(method);
        if (material) options.k = elastic_constants(*material).k;
        return result_dict(without_gil([&] { return fit_data(data, options); }));
      },
      py::arg("v"), py::arg("eps"), py::arg("sigma"), py::arg("laws"), py::arg("speed_independent_end"),
      py::arg("material"), py::arg("tolerance"), py::arg("method"),
      "Fit measured eps(v); see restitution.fit_data.");
  m.attr("default_speed_independent_end") = end_name(kDefaultSpeedIndependentEnd);
}

}  // namespace restitution::python
