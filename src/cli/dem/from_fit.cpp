// SPDX-License-Identifier: BSD-3-Clause
#include "cli/dem/from_fit.hpp"

#include <fmt/core.h>

#include <cmath>

#include "cli/common/build_json.hpp"
#include "restitution/errors.hpp"
#include "restitution/units.hpp"

namespace restitution::cli {

namespace {
// The library names the file; the command line names the option too.
template <typename Call>
auto naming_from_fit(Call call) {
  try {
    return call();
  } catch (const InvalidInput& e) {
    throw InvalidInput(fmt::format("--from-fit {}", e.what()));
  }
}
}  // namespace

FitCarryOver read_fit_result(const std::filesystem::path& path, std::optional<CollisionEnd> end) {
  return naming_from_fit([&] { return read_fit_report(path, end); });
}

EpsCarryOver eps_at_speed(const FitCarryOver& fit, double velocity_m_s) {
  return naming_from_fit([&] { return carried_eps_at_speed(fit, velocity_m_s); });
}

}  // namespace restitution::cli

#include "cli/fit/fit_data_report.hpp"

namespace restitution::cli {
namespace {

// The report's reasons for rejecting the fit that carries over (FitRejection), in words.
std::vector<std::string> rejection_reasons(const FitCarryOver& fit) {
  const FitRejection& verdict = fit.rejection;
  std::vector<std::string> out;
  if (verdict.better_fit) {
    const ReportedFit& better = fit.fits[*verdict.better_fit];
    out.push_back(fmt::format("the fit's best law is {}, {} end (AIC {:.4g} against {:.4g})",
                              law_name(better.law), end_name(better.end), better.aic,
                              fit.fits[fit.chosen].aic));
  }
  if (verdict.chi2_per_dof) {
    out.push_back(fmt::format("chi2/dof = {:.4g} with the data's sigma (p = {:.2g} < {:g})",
                              *verdict.chi2_per_dof, verdict.chi2_p_value, kFitSignificance));
  }
  if (!verdict.residual_trend.empty()) {
    out.push_back(fmt::format("its residuals: {} at the 1 % level", verdict.residual_trend));
  }
  return out;
}

// Why the fit rejects its Hertz fit, in one line; the intervals it would carry over then do not describe
// the data, so none is printed.
std::string rejection_text(const FitCarryOver& fit) {
  std::string out = "warning: the fit rejects viscoelastic Hertz for its data: ";
  const std::vector<std::string> reasons = rejection_reasons(fit);
  for (std::size_t i = 0; i < reasons.size(); ++i) out += (i == 0 ? "" : "; ") + reasons[i];
  return out + "; its intervals describe the scatter about a law the data do not follow and are left out";
}

void write_rejection(JsonWriter& json, const FitCarryOver& fit) {
  json.field("hertz_fit_rejected", rejection_reasons(fit));
}

// `[low, high]` after a value, or nothing for a rejected fit.
std::string interval_words(const FitCarryOver& fit, const char* level, const FitInterval& interval) {
  return fit.rejection.rejected() ? "" : fmt::format(", {} {}", level, interval_text(interval));
}

}  // namespace

int calibrate_from_fit(const std::filesystem::path& file, std::optional<CollisionEnd> end,
                       double velocity_m_s, std::optional<double> k, bool json) {
  if (!std::isfinite(velocity_m_s) || velocity_m_s <= 0.0) {
    throw InvalidInput(fmt::format("velocity must be finite and > 0, got {}", velocity_m_s));
  }
  const FitCarryOver fit = read_fit_result(file, end);
  const EpsCarryOver eps = eps_at_speed(fit, velocity_m_s);
  const std::optional<CarriedDissipativeConstant> a =
      k ? std::optional(carried_dissipative_constant(fit, *k)) : std::nullopt;
  const bool intervals = !fit.rejection.rejected();
  if (json) {
    JsonWriter w;
    w.begin_object().field("from_fit", file.string()).field("end", end_name(fit.end));
    w.field("sigma_estimated", fit.sigma_estimated).field("points", static_cast<long>(fit.points));
    if (!intervals) write_rejection(w, fit);
    w.field("beta", fit.beta);
    if (intervals) {
      write_interval(w, "beta_ci68", fit.ci68);
      write_interval(w, "beta_ci95", fit.ci95);
    }
    w.field("velocity_m_s", velocity_m_s).field("zeta", zeta_from(fit.beta, velocity_m_s));
    w.field("eps", eps.eps);
    if (intervals) {
      write_interval(w, "eps_ci68", eps.ci68);
      write_interval(w, "eps_ci95", eps.ci95);
    }
    w.field("characteristic_velocity_m_s", characteristic_velocity_m_s(fit.beta));
    if (a) {
      w.field("k", *k).field("dissipative_constant_s", a->value_s);
      if (intervals) {
        write_interval(w, "dissipative_constant_ci68", a->ci68);
        write_interval(w, "dissipative_constant_ci95", a->ci95);
      }
    }
    fmt::print("{}\n", finish_json_document(w));
    return 0;
  }
  fmt::print("calibration from the fit {} ({} points{}), {} end\n", file.string(), fit.points,
             fit.sigma_estimated ? ", scatter estimated from the residuals" : "", end_name(fit.end));
  if (!intervals) fmt::print("  {}\n", rejection_text(fit));
  fmt::print("  beta                        {:.9g} s^(1/5) m^(-1/5){}{}\n", fit.beta,
             interval_words(fit, "68 %", fit.ci68), interval_words(fit, "95 %", fit.ci95));
  fmt::print("  eps at v = {} m/s{:<9}{:.9g}{}{}{}\n", velocity_m_s, "", eps.eps,
             interval_words(fit, "68 %", eps.ci68), interval_words(fit, "95 %", eps.ci95),
             intervals ? " (carried over from beta's intervals)" : "");
  fmt::print("  g* (1999 paper, Eq. 31)     {:.9g} m/s\n", characteristic_velocity_m_s(fit.beta));
  if (a) {
    fmt::print("  A (dissipative constant)    {:.9g} s{}{}\n", a->value_s,
               interval_words(fit, "68 %", a->ci68), interval_words(fit, "95 %", a->ci95));
  }
  return 0;
}

}  // namespace restitution::cli

namespace restitution::cli {

std::string fit_carry_over_text(const std::filesystem::path& file, const FitCarryOver& fit, double k,
                                const std::vector<double>& speeds_m_s, const std::string& eps_given_by,
                                const char* comment) {
  const CarriedDissipativeConstant a = carried_dissipative_constant(fit, k);
  std::string out =
      fmt::format("{} from the fit {} ({} points{}): beta = {:.9g}{}; A = {:.9g} s{}{}\n", comment,
                  file.string(), fit.points, fit.sigma_estimated ? ", scatter estimated" : "", fit.beta,
                  interval_words(fit, "95 %", fit.ci95), a.value_s, interval_words(fit, "68 %", a.ci68),
                  interval_words(fit, "95 %", a.ci95));
  if (!!fit.rejection.rejected()) out += fmt::format("{} {}\n", comment, rejection_text(fit));
  out += fmt::format("{} the law's eps{}, given by {}:\n", comment,
                     !fit.rejection.rejected() ? " with the fit's uncertainty" : "", eps_given_by);
  for (const double v : speeds_m_s) {
    const EpsCarryOver e = eps_at_speed(fit, v);
    out += fmt::format("{}   v = {:<10.6g} m/s  eps = {:.6f}{}\n", comment, v, e.eps,
                       !fit.rejection.rejected()
                           ? fmt::format(", 95 % {} (the fit's uncertainty)", interval_text(e.ci95))
                           : std::string());
  }
  return out;
}

void write_fit_carry_over(JsonWriter& json, const std::filesystem::path& file, const FitCarryOver& fit,
                          double k, const std::vector<double>& speeds_m_s, const std::string& eps_given_by) {
  const CarriedDissipativeConstant a = carried_dissipative_constant(fit, k);
  const bool intervals = !fit.rejection.rejected();
  json.key("from_fit").begin_object().field("file", file.string()).field("end", end_name(fit.end));
  json.field("sigma_estimated", fit.sigma_estimated);
  if (!intervals) write_rejection(json, fit);
  json.field("beta", fit.beta);
  if (intervals) {
    write_interval(json, "beta_ci68", fit.ci68);
    write_interval(json, "beta_ci95", fit.ci95);
  }
  json.field("dissipative_constant_s", a.value_s);
  if (intervals) {
    write_interval(json, "dissipative_constant_ci68", a.ci68);
    write_interval(json, "dissipative_constant_ci95", a.ci95);
  }
  json.field("eps_given_by", eps_given_by);
  json.key("eps").begin_array();
  for (const double v : speeds_m_s) {
    const EpsCarryOver e = eps_at_speed(fit, v);
    json.begin_object().field("velocity_m_s", v).field("eps", e.eps);
    if (intervals) {
      write_interval(json, "ci68", e.ci68);
      write_interval(json, "ci95", e.ci95);
    }
    json.end_object();
  }
  json.end_array().end_object();
}

}  // namespace restitution::cli
