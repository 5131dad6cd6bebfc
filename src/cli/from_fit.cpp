// SPDX-License-Identifier: BSD-3-Clause
#include "cli/from_fit.hpp"

#include <fmt/core.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>

#include "cli/build_json.hpp"
#include "restitution/errors.hpp"
#include "restitution/fast.hpp"
#include "restitution/units.hpp"

namespace restitution::cli {
namespace {

FitInterval interval_of(const nlohmann::json& pair) {
  FitInterval out;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  out.low_at_edge = pair.at(0).is_null();
  out.high_at_edge = pair.at(1).is_null();
  out.low = out.low_at_edge ? nan : pair.at(0).get<double>();
  out.high = out.high_at_edge ? nan : pair.at(1).get<double>();
  return out;
}

}  // namespace

FitCarryOver read_fit_result(const std::filesystem::path& path, std::optional<CollisionEnd> end) {
  std::ifstream in(path);
  if (!in) throw InvalidInput(fmt::format("--from-fit {}: cannot be read", path.string()));
  try {
    const nlohmann::json j = nlohmann::json::parse(in);
    const nlohmann::json* chosen = nullptr;
    for (const nlohmann::json& f : j.at("fits")) {
      if (f.at("law") != law_name(LawKind::viscoelastic_hertz) || !f.at("converged").get<bool>()) continue;
      if (end && end_from_name(f.at("end").get<std::string>()) != *end) continue;
      if (chosen == nullptr || f.at("aic").get<double>() < chosen->at("aic").get<double>()) chosen = &f;
    }
    if (chosen == nullptr) {
      throw InvalidInput(fmt::format("--from-fit {}: no converged viscoelastic-hertz fit{}", path.string(),
                                     end ? fmt::format(" at the {} end", end_name(*end)) : std::string()));
    }
    FitCarryOver out;
    out.end = end_from_name(chosen->at("end").get<std::string>());
    out.beta = chosen->at("value").get<double>();
    out.ci68 = interval_of(chosen->at("ci68"));
    out.ci95 = interval_of(chosen->at("ci95"));
    out.sigma_estimated = j.at("sigma_estimated").get<bool>();
    out.points = j.at("points").get<std::size_t>();
    return out;
  } catch (const nlohmann::json::exception& e) {
    throw InvalidInput(fmt::format("--from-fit {}: not a fit-data report ({})", path.string(), e.what()));
  }
}

EpsCarryOver eps_at_speed(const FitCarryOver& fit, double velocity_m_s) {
  auto eps = [&](double beta) { return fast::eps(zeta_from(beta, velocity_m_s), fit.end); };
  auto map = [&](const FitInterval& b) {
    FitInterval out;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    out.low_at_edge = b.high_at_edge;
    out.low = b.high_at_edge ? nan : eps(b.high);
    out.high_at_edge = b.low_at_edge;
    out.high = b.low_at_edge ? nan : eps(b.low);
    return out;
  };
  return {eps(fit.beta), map(fit.ci68), map(fit.ci95)};
}

}  // namespace restitution::cli

#include "cli/fit_data_report.hpp"

namespace restitution::cli {
namespace {

FitInterval scaled(FitInterval i, double factor) {
  if (!i.low_at_edge) i.low *= factor;
  if (!i.high_at_edge) i.high *= factor;
  return i;
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
  if (json) {
    JsonWriter w;
    w.begin_object().field("from_fit", file.string()).field("end", end_name(fit.end));
    w.field("sigma_estimated", fit.sigma_estimated).field("points", static_cast<long>(fit.points));
    w.field("beta", fit.beta);
    write_interval(w, "beta_ci68", fit.ci68);
    write_interval(w, "beta_ci95", fit.ci95);
    w.field("velocity_m_s", velocity_m_s).field("zeta", zeta_from(fit.beta, velocity_m_s));
    w.field("eps", eps.eps);
    write_interval(w, "eps_ci68", eps.ci68);
    write_interval(w, "eps_ci95", eps.ci95);
    w.field("characteristic_velocity_m_s", characteristic_velocity_m_s(fit.beta));
    if (k) {
      w.field("k", *k).field("dissipative_constant_s", dissipative_constant_from(fit.beta, *k));
      write_interval(w, "dissipative_constant_ci68", scaled(fit.ci68, factor));
      write_interval(w, "dissipative_constant_ci95", scaled(fit.ci95, factor));
    }
    fmt::print("{}\n", finish_json_document(w));
    return 0;
  }
  fmt::print("calibration from the fit {} ({} points{}), {} end\n", file.string(), fit.points,
             fit.sigma_estimated ? ", scatter estimated from the residuals" : "", end_name(fit.end));
  fmt::print("  beta                        {:.9g} s^(1/5) m^(-1/5), 68 % {}, 95 % {}\n", fit.beta,
             interval_text(fit.ci68), interval_text(fit.ci95));
  fmt::print("  eps at v = {} m/s{:<9}{:.9g}, 68 % {}, 95 % {} (carried over from beta's intervals)\n",
             velocity_m_s, "", eps.eps, interval_text(eps.ci68), interval_text(eps.ci95));
  fmt::print("  g* (1999 paper, Eq. 31)     {:.9g} m/s\n", characteristic_velocity_m_s(fit.beta));
  if (k) {
    fmt::print("  A (dissipative constant)    {:.9g} s, 68 % {}, 95 % {}\n",
               dissipative_constant_from(fit.beta, *k), interval_text(scaled(fit.ci68, factor)),
               interval_text(scaled(fit.ci95, factor)));
  }
  return 0;
}

}  // namespace restitution::cli

namespace restitution::cli {

std::string fit_carry_over_text(const std::filesystem::path& file, const FitCarryOver& fit, double k,
                                const std::vector<double>& speeds_m_s, const std::string& eps_given_by,
                                const char* comment) {
  const double factor = dissipative_constant_from(1.0, k);
  std::string out = fmt::format(
      "{} from the fit {} ({} points{}): beta = {:.9g}, 95 % {}; A = {:.9g} s, 68 % {} s, 95 % {} s\n",
      comment, file.string(), fit.points, fit.sigma_estimated ? ", scatter estimated" : "", fit.beta,
      interval_text(fit.ci95), dissipative_constant_from(fit.beta, k),
      interval_text(scaled(fit.ci68, factor)), interval_text(scaled(fit.ci95, factor)));
  out += fmt::format("{} the law's eps with the fit's uncertainty, given by {}:\n", comment, eps_given_by);
  for (const double v : speeds_m_s) {
    const EpsCarryOver e = eps_at_speed(fit, v);
    out += fmt::format("{}   v = {:<10.6g} m/s  eps = {:.6f}, 95 % {} (the fit's uncertainty)\n", comment, v,
                       e.eps, interval_text(e.ci95));
  }
  return out;
}

void write_fit_carry_over(JsonWriter& json, const std::filesystem::path& file, const FitCarryOver& fit,
                          double k, const std::vector<double>& speeds_m_s, const std::string& eps_given_by) {
  const double factor = dissipative_constant_from(1.0, k);
  json.key("from_fit").begin_object().field("file", file.string()).field("end", end_name(fit.end));
  json.field("sigma_estimated", fit.sigma_estimated).field("beta", fit.beta);
  write_interval(json, "beta_ci68", fit.ci68);
  write_interval(json, "beta_ci95", fit.ci95);
  json.field("dissipative_constant_s", dissipative_constant_from(fit.beta, k));
  write_interval(json, "dissipative_constant_ci68", scaled(fit.ci68, factor));
  write_interval(json, "dissipative_constant_ci95", scaled(fit.ci95, factor));
  json.field("eps_given_by", eps_given_by);
  json.key("eps").begin_array();
  for (const double v : speeds_m_s) {
    const EpsCarryOver e = eps_at_speed(fit, v);
    json.begin_object().field("velocity_m_s", v).field("eps", e.eps);
    write_interval(json, "ci68", e.ci68);
    write_interval(json, "ci95", e.ci95);
    json.end_object();
  }
  json.end_array().end_object();
}

}  // namespace restitution::cli
