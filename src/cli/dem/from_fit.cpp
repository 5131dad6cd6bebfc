// SPDX-License-Identifier: BSD-3-Clause
#include "cli/dem/from_fit.hpp"

#include <fmt/core.h>

#include <cmath>

#include "cli/common/build_json.hpp"
#include "restitution/errors.hpp"
#include "restitution/units.hpp"

namespace restitution::cli {

EpsCarryOver eps_at_speed(const FitCarryOver& fit, double velocity_m_s) {
  try {
    return fitted_eps_at_speed(fit.beta, fit.ci68, fit.ci95, fit.end, velocity_m_s);
  } catch (const InvalidInput& e) {
    throw InvalidInput(fmt::format("--from-fit {}: beta = {} at v = {} m/s: {}", fit.file, fit.beta,
                                   velocity_m_s, e.what()));
  }
}

}  // namespace restitution::cli

#include "cli/fit/fit_data_report.hpp"

namespace restitution::cli {
namespace {

FitInterval scaled(FitInterval i, double factor) {
  if (!i.low_at_edge) i.low *= factor;
  if (!i.high_at_edge) i.high *= factor;
  return i;
}

// Why the fit rejects its Hertz fit, in one line; the intervals it would carry over then do not describe
// the data, so none is printed.
std::string rejection_text(const FitCarryOver& fit) {
  std::string out = "warning: the fit rejects viscoelastic Hertz for its data: ";
  for (std::size_t i = 0; i < fit.rejected_because.size(); ++i) {
    out += (i == 0 ? "" : "; ") + fit.rejected_because[i];
  }
  return out + "; its intervals describe the scatter about a law the data do not follow and are left out";
}

void write_rejection(JsonWriter& json, const FitCarryOver& fit) {
  json.key("hertz_fit_rejected").begin_array();
  for (const std::string& reason : fit.rejected_because) json.value(reason);
  json.end_array();
}

// `[low, high]` after a value, or nothing for a rejected fit.
std::string interval_words(const FitCarryOver& fit, const char* level, const FitInterval& interval) {
  return fit.rejected_because.empty() ? fmt::format(", {} {}", level, interval_text(interval)) : "";
}

}  // namespace

int calibrate_from_fit(const std::filesystem::path& file, std::optional<CollisionEnd> end,
                       double velocity_m_s, std::optional<double> k, bool json) {
  if (!std::isfinite(velocity_m_s) || velocity_m_s <= 0.0) {
    throw InvalidInput(fmt::format("velocity must be finite and > 0, got {}", velocity_m_s));
  }
  const FitCarryOver fit = read_fit_result(file, end);
  const EpsCarryOver eps = eps_at_speed(fit, velocity_m_s);
  const double factor = k ? dissipative_constant_from(1.0, *k) : 0.0;
  const bool intervals = fit.rejected_because.empty();
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
    if (k) {
      w.field("k", *k).field("dissipative_constant_s", dissipative_constant_from(fit.beta, *k));
      if (intervals) {
        write_interval(w, "dissipative_constant_ci68", scaled(fit.ci68, factor));
        write_interval(w, "dissipative_constant_ci95", scaled(fit.ci95, factor));
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
  if (k) {
    fmt::print("  A (dissipative constant)    {:.9g} s{}{}\n", dissipative_constant_from(fit.beta, *k),
               interval_words(fit, "68 %", scaled(fit.ci68, factor)),
               interval_words(fit, "95 %", scaled(fit.ci95, factor)));
  }
  return 0;
}

}  // namespace restitution::cli

namespace restitution::cli {

std::string fit_carry_over_text(const std::filesystem::path& file, const FitCarryOver& fit, double k,
                                const std::vector<double>& speeds_m_s, const std::string& eps_given_by,
                                const char* comment) {
  const double factor = dissipative_constant_from(1.0, k);
  std::string out =
      fmt::format("{} from the fit {} ({} points{}): beta = {:.9g}{}; A = {:.9g} s{}{}\n", comment,
                  file.string(), fit.points, fit.sigma_estimated ? ", scatter estimated" : "", fit.beta,
                  interval_words(fit, "95 %", fit.ci95), dissipative_constant_from(fit.beta, k),
                  interval_words(fit, "68 %", scaled(fit.ci68, factor)),
                  interval_words(fit, "95 %", scaled(fit.ci95, factor)));
  if (!fit.rejected_because.empty()) out += fmt::format("{} {}\n", comment, rejection_text(fit));
  out += fmt::format("{} the law's eps{}, given by {}:\n", comment,
                     fit.rejected_because.empty() ? " with the fit's uncertainty" : "", eps_given_by);
  for (const double v : speeds_m_s) {
    const EpsCarryOver e = eps_at_speed(fit, v);
    out += fmt::format("{}   v = {:<10.6g} m/s  eps = {:.6f}{}\n", comment, v, e.eps,
                       fit.rejected_because.empty()
                           ? fmt::format(", 95 % {} (the fit's uncertainty)", interval_text(e.ci95))
                           : std::string());
  }
  return out;
}

void write_fit_carry_over(JsonWriter& json, const std::filesystem::path& file, const FitCarryOver& fit,
                          double k, const std::vector<double>& speeds_m_s, const std::string& eps_given_by) {
  const double factor = dissipative_constant_from(1.0, k);
  const bool intervals = fit.rejected_because.empty();
  json.key("from_fit").begin_object().field("file", file.string()).field("end", end_name(fit.end));
  json.field("sigma_estimated", fit.sigma_estimated);
  if (!intervals) write_rejection(json, fit);
  json.field("beta", fit.beta);
  if (intervals) {
    write_interval(json, "beta_ci68", fit.ci68);
    write_interval(json, "beta_ci95", fit.ci95);
  }
  json.field("dissipative_constant_s", dissipative_constant_from(fit.beta, k));
  if (intervals) {
    write_interval(json, "dissipative_constant_ci68", scaled(fit.ci68, factor));
    write_interval(json, "dissipative_constant_ci95", scaled(fit.ci95, factor));
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
