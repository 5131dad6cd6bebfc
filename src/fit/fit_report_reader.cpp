// SPDX-License-Identifier: BSD-3-Clause
#include "fit/fit_report_reader.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>

#include "restitution/errors.hpp"
#include "restitution/fit.hpp"
#include "restitution/units.hpp"

namespace restitution {
// In a namespace of its own: the library compiles in unity batches, whose files share the anonymous one.
namespace fit_report_reading {
namespace {

using Json = nlohmann::json;

constexpr std::size_t kShownCharacters = 40;

// A value from the file as a message shows it: the type for containers, at most 40 characters of a string
// with bytes outside printable ASCII escaped (a hand-edited file may hold anything).
std::string shown(const Json& v) {
  switch (v.type()) {
    case Json::value_t::null:
      return "null";
    case Json::value_t::boolean:
      return v.get<bool>() ? "true" : "false";
    case Json::value_t::number_integer:
      return fmt::format("{}", v.get<std::int64_t>());
    case Json::value_t::number_unsigned:
      return fmt::format("{}", v.get<std::uint64_t>());
    case Json::value_t::number_float:
      return fmt::format("{}", v.get<double>());
    case Json::value_t::string: {
      const auto& s = v.get_ref<const std::string&>();
      std::string out = "'";
      for (std::size_t i = 0; i < std::min(s.size(), kShownCharacters); ++i) {
        const auto c = static_cast<unsigned char>(s[i]);
        out += (c >= 0x20 && c < 0x7f) ? std::string(1, static_cast<char>(c)) : fmt::format("\\x{:02x}", c);
      }
      return out + (s.size() > kShownCharacters ? "...'" : "'");
    }
    case Json::value_t::array:
      return fmt::format("a list of {} value{}", v.size(), v.size() == 1 ? "" : "s");
    case Json::value_t::object:
      return "an object";
    default:
      return "a value of no JSON type";
  }
}

// Checks one report, naming each value by its path in the file ("fits[2].ci95[1]").
class ReportReader {
 public:
  explicit ReportReader(std::string file) : file_(std::move(file)) {}

  [[noreturn]] void refuse(const std::string& key, const std::string& problem) const {
    throw InvalidInput(fmt::format("{}: {}: {}", file_, key, problem));
  }

  const Json& member(const Json& object, const std::string& path, const char* key) const {
    const std::string name = path.empty() ? key : path + "." + key;
    const auto it = object.find(key);
    if (it == object.end()) refuse(name, "missing (not a fit-data report?)");
    return *it;
  }

  [[nodiscard]] bool boolean(const Json& v, const std::string& key) const {
    if (!v.is_boolean()) refuse(key, fmt::format("must be true or false, got {}", shown(v)));
    return v.get<bool>();
  }

  [[nodiscard]] const std::string& text(const Json& v, const std::string& key) const {
    if (!v.is_string()) refuse(key, fmt::format("must be a string, got {}", shown(v)));
    return v.get_ref<const std::string&>();
  }

  [[nodiscard]] double finite(const Json& v, const std::string& key) const {
    if (!v.is_number()) refuse(key, fmt::format("must be a number, got {}", shown(v)));
    const double x = v.get<double>();
    if (!std::isfinite(x)) refuse(key, fmt::format("must be a finite number, got {}", x));
    return x;
  }

  [[nodiscard]] double nonnegative(const Json& v, const std::string& key) const {
    const double x = finite(v, key);
    if (x < 0.0) refuse(key, fmt::format("must be >= 0, got {}", x));
    return x;
  }

  // A whole number in [low, high].
  [[nodiscard]] std::size_t index(const Json& v, const std::string& key, std::size_t low,
                                  std::size_t high) const {
    std::optional<std::uint64_t> n;
    if (v.is_number_unsigned()) {
      n = v.get<std::uint64_t>();
    } else if (v.is_number_integer() && v.get<std::int64_t>() >= 0) {
      n = static_cast<std::uint64_t>(v.get<std::int64_t>());
    }
    if (!n || *n < low || *n > high) {
      refuse(key, fmt::format("must be a whole number in [{}, {}], got {}", low, high, shown(v)));
    }
    return static_cast<std::size_t>(*n);
  }

  // [low, high]: numbers >= 0, or null for a bound beyond the checked range.
  FitInterval interval(const Json& fit, const std::string& path, const char* key) const {
    const std::string name = path + "." + key;
    const Json& pair = member(fit, path, key);
    if (!pair.is_array() || pair.size() != 2) {
      refuse(name, fmt::format("must be [low, high] (numbers, or null at the edge), got {}", shown(pair)));
    }
    FitInterval out;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    out.low_at_edge = pair[0].is_null();
    out.high_at_edge = pair[1].is_null();
    out.low = out.low_at_edge ? nan : nonnegative(pair[0], name + "[0]");
    out.high = out.high_at_edge ? nan : nonnegative(pair[1], name + "[1]");
    return out;
  }

  // `inner` (the value as [value, value], or the 68 % interval) lies in `outer`. fit-data's bounds are roots
  // found to about 1e-12 relative, so a zero-width interval (noise-free data) can come out a rounding step on
  // the wrong side: within kRoundingSlack that is set right, beyond it the file is refused.
  void require_inside(FitInterval& outer, const FitInterval& inner, double value, const std::string& key,
                      const std::string& what) const {
    constexpr double kRoundingSlack = 1e-9;
    const double slack = kRoundingSlack * value;
    const bool low_ok = outer.low_at_edge || (!inner.low_at_edge && outer.low <= inner.low + slack);
    const bool high_ok = outer.high_at_edge || (!inner.high_at_edge && outer.high >= inner.high - slack);
    if (!low_ok || !high_ok) {
      refuse(key, fmt::format("must hold {}, got {}", what, interval_words(outer)));
    }
    if (!outer.low_at_edge) outer.low = std::min(outer.low, inner.low);
    if (!outer.high_at_edge) outer.high = std::max(outer.high, inner.high);
  }

  static std::string interval_words(const FitInterval& i) {
    auto bound = [](double x, bool edge) { return edge ? std::string("null") : fmt::format("{}", x); };
    return fmt::format("[{}, {}]", bound(i.low, i.low_at_edge), bound(i.high, i.high_at_edge));
  }

 private:
  std::string file_;
};

// One entry of `fits`, as far as the carry-over needs it.
struct Entry {
  LawKind law = LawKind::viscoelastic_hertz;
  CollisionEnd end = CollisionEnd::delayed_recovery;
  bool converged = false;
  double value = 0.0;
  FitInterval ci68, ci95;
  double chi2 = 0.0;
  double aic = 0.0;
  std::string verdict;  // of the residual tests, when they ran
};

LawKind fitted_law(const ReportReader& r, const Json& v, const std::string& key) {
  const std::string& name = r.text(v, key);
  std::string names;
  for (const FitCandidate& c : default_fit_candidates()) {
    if (name == law_name(c.law)) return c.law;
    if (names.find(law_name(c.law)) == std::string::npos)
      names += (names.empty() ? "" : ", ") + std::string(law_name(c.law));
  }
  r.refuse(key, fmt::format("{} is not a law fit-data fits ({})", shown(v), names));
}

CollisionEnd collision_end(const ReportReader& r, const Json& v, const std::string& key) {
  const std::string& name = r.text(v, key);
  for (const CollisionEnd end : kCollisionEnds) {
    if (name == end_name(end)) return end;
  }
  r.refuse(key, fmt::format("must be naive or delayed-recovery, got {}", shown(v)));
}

Entry read_entry(const ReportReader& r, const Json& fit, const std::string& path, std::size_t points) {
  if (!fit.is_object()) r.refuse(path, fmt::format("must be an object, got {}", shown(fit)));
  Entry e;
  e.law = fitted_law(r, r.member(fit, path, "law"), path + ".law");
  e.end = collision_end(r, r.member(fit, path, "end"), path + ".end");
  e.converged = r.boolean(r.member(fit, path, "converged"), path + ".converged");
  if (!e.converged) return e;  // its numbers are not used
  const bool hertz = e.law == LawKind::viscoelastic_hertz;
  e.value = r.nonnegative(r.member(fit, path, "value"), path + ".value");
  if (hertz) {
    // fit-data reports β = 0 (no dissipation) as at-edge, and every β it reports has a g* that is a number.
    const double g = e.value > 0.0 ? characteristic_velocity_m_s(e.value) : 0.0;
    if (!std::isfinite(g) || g == 0.0) {
      r.refuse(
          path + ".value",
          fmt::format("beta = {} has no finite g* > 0 (1999 paper, Eq. 31): not a fitted beta", e.value));
    }
  }
  e.ci68 = r.interval(fit, path, "ci68");
  e.ci95 = r.interval(fit, path, "ci95");
  if (hertz) {
    // The intervals that carry over hold the value, and the 95 % one holds the 68 % one.
    const FitInterval point{e.value, e.value, false, false};
    r.require_inside(e.ci68, point, e.value, path + ".ci68",
                     fmt::format("the value {} (low <= value <= high)", e.value));
    r.require_inside(e.ci95, point, e.value, path + ".ci95",
                     fmt::format("the value {} (low <= value <= high)", e.value));
    r.require_inside(e.ci95, e.ci68, e.value, path + ".ci95",
                     fmt::format("ci68 {}", ReportReader::interval_words(e.ci68)));
  }
  e.chi2 = r.nonnegative(r.member(fit, path, "chi2"), path + ".chi2");
  const Json& dof = r.member(fit, path, "dof");
  if (!dof.is_number_integer() || dof.get<std::int64_t>() != static_cast<std::int64_t>(points) - 1) {
    r.refuse(path + ".dof", fmt::format("must be points - 1 = {}, got {}", points - 1, shown(dof)));
  }
  // With σ estimated, AIC = n ln(χ²/n) + 4 is -inf for χ² = 0 (data the law meets exactly), which JSON
  // writes as null.
  const Json& aic = r.member(fit, path, "aic");
  e.aic = aic.is_null() && e.chi2 == 0.0 ? -std::numeric_limits<double>::infinity()
                                         : r.finite(aic, path + ".aic");
  const std::string tests = path + ".residual_tests";
  const Json& residuals = r.member(fit, path, "residual_tests");
  if (!residuals.is_object()) r.refuse(tests, fmt::format("must be an object, got {}", shown(residuals)));
  const bool available = r.boolean(r.member(residuals, tests, "available"), tests + ".available");
  const std::string& verdict = r.text(r.member(residuals, tests, "verdict"), tests + ".verdict");
  if (available) e.verdict = verdict;
  return e;
}

}  // namespace
}  // namespace fit_report_reading

FitCarryOver parse_fit_report(const std::string& text, const std::string& file,
                              std::optional<CollisionEnd> end) {
  using namespace fit_report_reading;
  const ReportReader r(file);
  Json j;
  try {
    j = Json::parse(text);
  } catch (const Json::parse_error& e) {
    throw InvalidInput(
        fmt::format("{}: not JSON (a fit-data report), the syntax breaks at byte {}", file, e.byte));
  } catch (const Json::exception&) {
    // The one other failure of parsing: a number beyond the range of a double (1e999).
    throw InvalidInput(fmt::format("{}: holds a number beyond the range of a double", file));
  }
  if (!j.is_object()) {
    throw InvalidInput(
        fmt::format("{}: must be one JSON object (a fit-data report), got {}", file, shown(j)));
  }
  FitCarryOver out;
  out.file = file;
  out.points = r.index(r.member(j, "", "points"), "points", 1, std::numeric_limits<std::uint32_t>::max());
  out.sigma_estimated = r.boolean(r.member(j, "", "sigma_estimated"), "sigma_estimated");
  const Json& list = r.member(j, "", "fits");
  if (!list.is_array() || list.empty())
    r.refuse("fits", fmt::format("must be a non-empty list, got {}", shown(list)));
  std::vector<Entry> fits;
  for (std::size_t i = 0; i < list.size(); ++i) {
    fits.push_back(read_entry(r, list[i], fmt::format("fits[{}]", i), out.points));
  }
  // `best` is the converged fit with the lowest AIC, null when none converged (fit-data's choose_best).
  const Json& best_value = r.member(j, "", "best");
  std::optional<std::size_t> best;
  if (!best_value.is_null()) {
    best = r.index(best_value, "best", 0, fits.size() - 1);
    if (!fits[*best].converged) r.refuse("best", fmt::format("fits[{}] did not converge", *best));
  }
  for (std::size_t i = 0; i < fits.size(); ++i) {
    if (!fits[i].converged) continue;
    if (!best) r.refuse("best", fmt::format("is null, but fits[{}] converged", i));
    if (fits[i].aic < fits[*best].aic) {
      r.refuse("best", fmt::format("fits[{}] has a lower aic than fits[{}]", i, *best));
    }
  }
  const Json& tied_value = r.member(j, "", "tied_with_best");
  if (!tied_value.is_array())
    r.refuse("tied_with_best", fmt::format("must be a list, got {}", shown(tied_value)));
  std::vector<std::size_t> tied;
  for (std::size_t i = 0; i < tied_value.size(); ++i) {
    const std::string key = fmt::format("tied_with_best[{}]", i);
    tied.push_back(r.index(tied_value[i], key, 0, fits.size() - 1));
    if (!fits[tied.back()].converged) r.refuse(key, fmt::format("fits[{}] did not converge", tied.back()));
  }
  std::optional<std::size_t> chosen;
  for (std::size_t i = 0; i < fits.size(); ++i) {
    const Entry& f = fits[i];
    if (f.law != LawKind::viscoelastic_hertz || !f.converged || (end && f.end != *end)) continue;
    if (!chosen || f.aic < fits[*chosen].aic) chosen = i;
  }
  if (!chosen) {
    throw InvalidInput(fmt::format("{}: no converged viscoelastic-hertz fit{}", file,
                                   end ? fmt::format(" at the {} end", end_name(*end)) : std::string()));
  }
  const Entry& f = fits[*chosen];
  out.end = f.end;
  out.beta = f.value;
  out.ci68 = f.ci68;
  out.ci95 = f.ci95;
  for (const Entry& e : fits) out.fits.push_back({e.law, e.end, e.chi2, e.aic, e.verdict});
  out.chosen = *chosen;
  out.rejection = judge_reported_fit(out.fits, *chosen, *best, tied, out.sigma_estimated, out.points);
  return out;
}

FitCarryOver read_fit_report(const std::filesystem::path& path, std::optional<CollisionEnd> end) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) {
    throw InvalidInput(fmt::format("{}: is a folder, not a fit-data report", path.string()));
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InvalidInput(fmt::format("{}: cannot be read", path.string()));
  // Read in pieces up to the bound, so that an endless or huge file costs no more than the bound.
  std::string text;
  std::array<char, 1 << 16> buffer{};
  while (in.read(buffer.data(), buffer.size()) || in.gcount() > 0) {
    text.append(buffer.data(), static_cast<std::size_t>(in.gcount()));
    if (text.size() > kMaxFitReportBytes) {
      throw InvalidInput(fmt::format("{}: larger than {} MiB, not a fit-data report", path.string(),
                                     kMaxFitReportBytes >> 20));
    }
  }
  if (in.bad()) throw InvalidInput(fmt::format("{}: cannot be read", path.string()));
  return parse_fit_report(text, path.string(), end);
}

FittedEps carried_eps_at_speed(const FitCarryOver& fit, double velocity_m_s) {
  try {
    return fitted_eps_at_speed(fit.beta, fit.ci68, fit.ci95, fit.end, velocity_m_s);
  } catch (const InvalidInput& e) {
    throw InvalidInput(
        fmt::format("{}: beta = {} at v = {} m/s: {}", fit.file, fit.beta, velocity_m_s, e.what()));
  }
}

CarriedDissipativeConstant carried_dissipative_constant(const FitCarryOver& fit, double k) {
  const double factor = dissipative_constant_from(1.0, k);
  const auto scaled = [factor](FitInterval interval) {
    if (!interval.low_at_edge) interval.low *= factor;
    if (!interval.high_at_edge) interval.high *= factor;
    return interval;
  };
  return {dissipative_constant_from(fit.beta, k), scaled(fit.ci68), scaled(fit.ci95)};
}

}  // namespace restitution
