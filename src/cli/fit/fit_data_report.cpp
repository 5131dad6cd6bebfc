// SPDX-License-Identifier: BSD-3-Clause
#include "cli/fit/fit_data_report.hpp"

#include <fmt/core.h>

#include <cmath>

#include "cli/common/build_json.hpp"
#include "fit/best_hertz_fit.hpp"

namespace restitution::cli {

void write_interval(JsonWriter& json, const char* name, const FitInterval& i) {
  json.key(name).begin_array();
  if (i.low_at_edge) {
    json.null();
  } else {
    json.value(i.low);
  }
  if (i.high_at_edge) {
    json.null();
  } else {
    json.value(i.high);
  }
  json.end_array();
}

std::string interval_text(const FitInterval& i) {
  auto bound = [](double x, bool edge) { return edge ? std::string("edge") : fmt::format("{:.6g}", x); };
  return fmt::format("[{}, {}]", bound(i.low, i.low_at_edge), bound(i.high, i.high_at_edge));
}

std::string verdict_text(const ResidualTests& tests) {
  return tests.available ? tests.verdict : fmt::format("{} ({})", tests.verdict, tests.unavailable);
}

namespace {

void residuals_field(JsonWriter& json, const ResidualTests& r) {
  json.key("residual_tests").begin_object().field("available", r.available);
  if (r.available) {
    json.field("slope_per_ln_v", r.slope)
        .field("slope_error", r.slope_error)
        .field("slope_p_value", r.slope_p_value);
    json.field("runs", r.runs).field("runs_expected", r.runs_expected).field("runs_p_value", r.runs_p_value);
  }
  json.field("verdict", r.verdict);
  if (!r.available) json.field("unavailable", r.unavailable);
  json.end_object();
}

void fit_object(JsonWriter& json, const LawFit& f) {
  json.begin_object();
  json.field("law", law_name(f.candidate.law)).field("end", end_name(f.candidate.end));
  json.field("parameter", f.parameter).field("status", fit_status_name(f.status));
  json.field("converged", f.status == FitStatus::converged);
  if (!f.message.empty()) json.field("message", f.message);
  if (f.status == FitStatus::converged) {
    json.field("value", f.value);
  } else {
    json.key("value").null();
  }
  write_interval(json, "ci68", f.ci68);
  write_interval(json, "ci95", f.ci95);
  json.field("chi2", f.chi2).field("dof", f.dof).field("chi2_per_dof", f.chi2_per_dof);
  json.field("aic", f.aic).field("bic", f.bic);
  residuals_field(json, f.residuals);
  if (f.characteristic_velocity_m_s) {
    json.field("characteristic_velocity_m_s", *f.characteristic_velocity_m_s);
    write_interval(json, "characteristic_velocity_ci68", f.characteristic_velocity_ci68);
    write_interval(json, "characteristic_velocity_ci95", f.characteristic_velocity_ci95);
  }
  if (f.dissipative_constant_s) {
    json.field("dissipative_constant_s", *f.dissipative_constant_s);
    write_interval(json, "dissipative_constant_ci68", f.dissipative_constant_ci68);
    write_interval(json, "dissipative_constant_ci95", f.dissipative_constant_ci95);
  }
  json.field("model_eps", f.model_eps).end_object();
}

}  // namespace

void write_fit_json(JsonWriter& json, const FitReportInput& in) {
  const FitData& d = *in.data;
  const FitResult& r = *in.result;
  json.field("source", in.source).field("points", static_cast<long>(r.points));
  json.field("sigma_estimated", r.sigma_estimated);
  json.key("levels").begin_object().field("ci68", r.level68).field("ci95", r.level95).end_object();
  json.key("data").begin_object();
  json.field("v", d.velocity_m_s).field("eps", d.eps);
  if (!d.sigma.empty()) json.field("sigma", d.sigma);
  json.end_object();
  json.key("fits").begin_array();
  for (const LawFit& f : r.fits) fit_object(json, f);
  json.end_array();
  if (r.best) {
    json.field("best", static_cast<long>(*r.best));
    json.field("best_law", law_name(r.fits[*r.best].candidate.law));
    json.field("best_end", end_name(r.fits[*r.best].candidate.end));
  } else {
    json.key("best").null();
  }
  json.key("tied_with_best").begin_array();
  for (const std::size_t i : r.tied_with_best) json.value(static_cast<long>(i));
  json.end_array();
  if (in.k) {
    json.field("k", *in.k);
    // The Hertz fit whose A a DEM code should take.
    const std::optional<std::size_t> hertz = best_hertz_fit(r);
    if (hertz && r.fits[*hertz].dissipative_constant_s) {
      const LawFit& h = r.fits[*hertz];
      json.key("dissipative_constant_s").begin_object();
      json.field("end", end_name(h.candidate.end)).field("value", *h.dissipative_constant_s);
      write_interval(json, "ci68", h.dissipative_constant_ci68);
      write_interval(json, "ci95", h.dissipative_constant_ci95);
      json.end_object();
    }
  }
}

std::string fit_json(const FitReportInput& in) {
  JsonWriter json;
  json.begin_object();
  write_fit_json(json, in);
  return finish_json_document(json);
}

std::string fit_table(const FitReportInput& in) {
  const FitResult& r = *in.result;
  std::string out = fmt::format("fit-data: {}, {} point{}, ", in.source, r.points, r.points == 1 ? "" : "s");
  out += r.sigma_estimated
             ? fmt::format(
                   "no sigma column: the scatter is estimated from the residuals (t quantiles, {} dof)\n",
                   r.points - 1)
             : "sigma from the data (profile of chi2: delta 1 and 3.84)\n";
  out += fmt::format("{:<19} {:<17} {:<14} {:<13} {:<27} {:<27} {:>10} {:>10}  {}\n", "law", "end",
                     "parameter", "value", "68 % interval", "95 % interval", "chi2/dof", "AIC", "residuals");
  for (const LawFit& f : r.fits) {
    const std::string value = f.status == FitStatus::converged ? fmt::format("{:.7g}", f.value)
                                                               : std::string(fit_status_name(f.status));
    // No degrees of freedom (as many points as parameters): χ²/dof is undefined, said so rather than nan.
    const std::string chi2_per_dof =
        f.dof > 0 ? fmt::format("{:.4g}", f.chi2_per_dof) : std::string("- (0 dof)");
    out += fmt::format("{:<19} {:<17} {:<14} {:<13} {:<27} {:<27} {:>10} {:>10.4g}  {}\n",
                       law_name(f.candidate.law), end_name(f.candidate.end), f.parameter, value,
                       interval_text(f.ci68), interval_text(f.ci95), chi2_per_dof, f.aic,
                       verdict_text(f.residuals));
    if (!f.message.empty()) out += fmt::format("  {}: {}\n", law_name(f.candidate.law), f.message);
  }
  if (r.best) {
    const LawFit& b = r.fits[*r.best];
    out += fmt::format("best (lowest AIC): {}, {} end", law_name(b.candidate.law), end_name(b.candidate.end));
    for (const std::size_t i : r.tied_with_best) {
      out += fmt::format("; tied with {}, {} end (the data cannot tell them apart)",
                         law_name(r.fits[i].candidate.law), end_name(r.fits[i].candidate.end));
    }
    out += "\n";
  } else {
    out += "best: none (no fit converged)\n";
  }
  for (const LawFit& f : r.fits) {
    if (!f.characteristic_velocity_m_s) continue;
    out +=
        fmt::format("g* (1999 paper, Eq. 31), {} end: {:.6g} m/s, 95 % {} m/s\n", end_name(f.candidate.end),
                    *f.characteristic_velocity_m_s, interval_text(f.characteristic_velocity_ci95));
    if (f.dissipative_constant_s) {
      out += fmt::format("A (dissipative constant), {} end: {:.6g} s, 95 % {} s\n", end_name(f.candidate.end),
                         *f.dissipative_constant_s, interval_text(f.dissipative_constant_ci95));
    }
  }
  out +=
      "residuals: none | falls-with-speed (plasticity?) | rises-with-speed (adhesion?) | runs, at the 1 % "
      "level; n/a: not tested (fewer than 3 points, one speed or no fit)\n";
  return out;
}

}  // namespace restitution::cli
