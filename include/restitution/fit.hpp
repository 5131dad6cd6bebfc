// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Fitting measured coefficients of restitution ε(v) (docs/fit.md): for each candidate law the one free
// parameter by (weighted) least squares, intervals from the profile of χ², χ² per degree of freedom, AIC and
// BIC to compare the laws, and tests of the residuals against ln v that say where the data leave a law.
//
// Candidates: viscoelastic Hertz at either end (parameter β [s^{1/5} m^{-1/5}], ζ = β v^{1/5}, ε from the
// certified fast table, restitution/fast.hpp), and the speed-independent members (Tsuji: ζ, the linear
// dash-pot: the damping ratio r = ζ/2), whose one ε serves every data point (ε from the collision solver).
// Library code: nothing is printed; errors are InvalidInput naming the problem.
#include <cstddef>
#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "restitution/collision_solver.hpp"
#include "restitution/contact_law.hpp"

namespace restitution {

// Measurements: impact speeds v [m/s] > 0, ε in (0, 1), and either no σ (the scatter is estimated from the
// residuals) or one σ > 0 per point (standard deviation of ε). Speeds may repeat.
struct FitData {
  std::vector<double> velocity_m_s;
  std::vector<double> eps;
  std::vector<double> sigma;  // empty, or one per point
};

// The σ a fit takes. χ² = Σ (Δε/σ)² and its sums are formed in double precision: 1/σ² overflows below
// σ ~ 1e-154 and underflows above ~1e154; within these bounds no sum of a million points leaves the range.
// (ε lies in (0, 1): a σ above 1 already says the point constrains nothing, one below 1e-16 is finer than a
// double can resolve ε.)
inline constexpr double kSmallestFitSigma = 1e-100;
inline constexpr double kLargestFitSigma = 1e100;

// Throws InvalidInput naming the first bad point (index from 0) or the problem: fewer points than
// 2 (one parameter, plus one for the scatter when σ is estimated; 1 with σ), sizes that differ, a NaN,
// ε outside (0, 1), v <= 0, σ outside [kSmallestFitSigma, kLargestFitSigma].
void check_fit_data(const FitData& data);

// One law at one end of the collision. The speed-independent members fit the same ε at either end (only
// their parameter differs); fit_data uses kDefaultSpeedIndependentEnd unless told otherwise.
inline constexpr CollisionEnd kDefaultSpeedIndependentEnd = CollisionEnd::delayed_recovery;
struct FitCandidate {
  LawKind law = LawKind::viscoelastic_hertz;
  CollisionEnd end = CollisionEnd::delayed_recovery;
};
// Viscoelastic Hertz at the delayed-recovery and naive ends, Tsuji and the linear dash-pot (at
// kDefaultSpeedIndependentEnd).
std::vector<FitCandidate> default_fit_candidates();
// The default candidates restricted to the named laws (law_from_name; empty: all; viscoelastic-hertz brings
// both ends), the speed-independent ones at `speed_independent_end` (end_from_name). Throws InvalidInput
// naming an unknown law or end, or a law that is not a candidate (naming the candidates).
std::vector<FitCandidate> fit_candidates(const std::vector<std::string>& law_names,
                                         const std::string& speed_independent_end);
// "beta" | "zeta" | "damping-ratio": the name of the fitted parameter of a law.
const char* fit_parameter_name(LawKind law);

enum class FitStatus {
  converged,
  at_edge,        // the best value lies at ζ = kLargestCheckedZeta (or β -> 0): no number is reported
  not_converged,  // the minimiser or a solve failed; message says why
};
const char* fit_status_name(FitStatus status);  // "converged" | "at-edge" | "not-converged"

// A confidence interval of the parameter. A bound beyond the checked range (ζ > kLargestCheckedZeta at the
// largest speed) is not a number: the flag is set and the value is NaN. A lower bound of 0 is a number
// (ζ = 0, elastic spheres, lies in the checked range).
struct FitInterval {
  double low = 0.0;
  double high = 0.0;
  bool low_at_edge = false;
  bool high_at_edge = false;
};

// Residuals against ln v: a weighted straight line r = a + b (ln v - mean) (the slope b and its two-sided
// p-value from the t distribution, or the normal one with known σ) and a Wald-Wolfowitz runs test of the
// residuals' signs ordered by speed (one-sided p-value for too few runs). Available with >= 3 points and
// >= 2 distinct speeds; otherwise the verdict is "n/a" and `unavailable` says why.
// The level of every verdict on a law (the residual tests' and the χ² test's): 1 %.
inline constexpr double kFitSignificance = 0.01;

// With σ given, χ² of a law that describes `points` measurements follows the χ² distribution of points − 1
// degrees of freedom: the probability of a χ² at least this large (1 when points < 2). With σ estimated from
// the residuals χ²/dof is that estimate and the test says nothing: do not call it then.
double chi2_p_value(double chi2, std::size_t points);

// Whether a fit-data report's own tests reject one of its fits (docs/fit.md): another law has a lower AIC
// (ties excepted), χ² is improbably large for the data's σ, or the residuals trend with the speed. Where a
// fit is carried over (`dem --from-fit`) the intervals of a rejected fit describe the scatter about a law the
// data do not follow, not the data. Typed reasons; a front end words them.
// One fit of a report, as far as judging it needs.
struct ReportedFit {
  LawKind law = LawKind::viscoelastic_hertz;
  CollisionEnd end = CollisionEnd::delayed_recovery;
  double chi2 = 0.0;
  double aic = 0.0;
  std::string residual_verdict;  // ResidualTests::verdict when the tests ran, else empty
};

struct FitRejection {
  std::optional<std::size_t> better_fit;  // the report's best fit, when it is not this one nor tied with it
  // χ²/dof and its p-value, when p < kFitSignificance with the data's own σ (never with σ estimated).
  std::optional<double> chi2_per_dof;
  double chi2_p_value = 1.0;
  // "falls-with-speed", "rises-with-speed" or "runs" when the residual tests found that; empty otherwise.
  std::string residual_trend;

  [[nodiscard]] bool rejected() const { return better_fit || chi2_per_dof || !residual_trend.empty(); }
};

// The verdict on fits[chosen] of a report of `points` data points whose lowest-AIC fit is fits[best] and
// whose fits tied with it are `tied`.
FitRejection judge_reported_fit(const std::vector<ReportedFit>& fits, std::size_t chosen, std::size_t best,
                                const std::vector<std::size_t>& tied, bool sigma_estimated,
                                std::size_t points);

// ε at speed v [m/s] that a fitted β [s^{1/5} m^{-1/5}] and its intervals give at `end` (ε decreases with β,
// so the bounds swap; a β bound at the edge, or one whose ζ at v lies beyond the checked range, gives no ε
// bound: NaN and the flag set). Throws InvalidInput when β's own ζ = β v^{1/5} lies outside the checked
// range (require_checked_zeta), as for a β typed with `eps --beta`.
struct FittedEps {
  double eps = 0.0;
  FitInterval ci68, ci95;
};
FittedEps fitted_eps_at_speed(double beta, const FitInterval& ci68, const FitInterval& ci95, CollisionEnd end,
                              double velocity_m_s);

struct ResidualTests {
  bool available = false;
  double slope = 0.0;        // d(ε_measured - ε_law)/d ln v
  double slope_error = 0.0;  // its standard error
  double slope_p_value = 1.0;
  int runs = 0;
  double runs_expected = 0.0;
  double runs_p_value = 1.0;
  // "none" | "falls-with-speed" (data drop below the law at high speed: plasticity, fracture) |
  // "rises-with-speed" (data below the law at low speed: adhesion) | "runs" (systematic, not monotone):
  // the verdict at the 1 % level; "n/a" when the tests could not run.
  std::string verdict = "n/a";
  std::string unavailable = "no fit";  // "too few points" | "one speed" | "no fit"; empty when available
};

struct LawFit {
  FitCandidate candidate;
  std::string parameter;  // fit_parameter_name
  FitStatus status = FitStatus::not_converged;
  std::string message;  // why, when not converged or at the edge
  double value = 0.0;   // the best parameter (NaN unless converged)
  FitInterval ci68;     // Δχ² = 1 (known σ) or the t quantile of 68.27 % (estimated σ)
  FitInterval ci95;     // Δχ² = 3.84 or the t quantile of 95 %
  double chi2 = 0.0;    // Σ w (ε_i - ε_law)², w = 1/σ² (1 when σ is estimated)
  int dof = 0;          // points - 1
  double chi2_per_dof = 0.0;
  double aic =
      0.0;  // Gaussian likelihood: χ² + 2 (known σ) or n ln(χ²/n) + 4 (estimated σ and the parameter)
  double bic = 0.0;
  ResidualTests residuals;
  std::vector<double> model_eps;  // ε of the fitted law at each data speed
  // Viscoelastic Hertz only: the 1999 paper's g* = (C1 β)^{-5} [m/s] with its intervals (decreasing in β,
  // so the bounds swap), and with FitOptions::k the dissipative constant A = β / ((3/2) k^{2/5}) [s].
  std::optional<double> characteristic_velocity_m_s;
  FitInterval characteristic_velocity_ci68, characteristic_velocity_ci95;
  std::optional<double> dissipative_constant_s;
  FitInterval dissipative_constant_ci68, dissipative_constant_ci95;
};

struct FitOptions {
  std::vector<FitCandidate> candidates = default_fit_candidates();
  // Accuracy of each solve for the speed-independent members (the Hertz fits use the fast table, 1e-13).
  double tolerance = SolveOptions{}.tolerance;
  Method method = Method::automatic;
  std::optional<double> k;  // ρ/m_eff [s^-2 m^-1/2] of a material (ElasticConstants::k): gives A
};

struct FitResult {
  std::vector<LawFit> fits;  // in the order of FitOptions::candidates
  // The index of the preferred fit (lowest AIC among the converged ones); nullopt when none converged.
  std::optional<std::size_t> best;
  // Fits whose AIC lies within 1e-9 (relative) of the best one's: the data cannot tell them apart (the
  // speed-independent members always tie with each other).
  std::vector<std::size_t> tied_with_best;
  bool sigma_estimated = false;
  double level68 = 0.0;  // the coverage of ci68 (0.6827, one standard deviation)
  double level95 = 0.95;
  std::size_t points = 0;
};

// Checks the data (check_fit_data) and fits every candidate. Throws InvalidInput for bad data or options;
// a fit that fails is reported in its LawFit, never thrown.
FitResult fit_data(const FitData& data, const FitOptions& options = {});

// ε of a candidate law with parameter `parameter` (β, ζ or the damping ratio) at impact speed v [m/s]:
// the model curve of a fit. The solver is used for the speed-independent members only.
double fit_model_eps(const FitCandidate& candidate, double parameter, double velocity_m_s,
                     CollisionSolver& solver, const SolveOptions& options = {});

// The CSV of measured coefficients of restitution that `fit-data` and scenes' [[fit]] read (docs/fit.md):
// a header naming the speed, eps and optionally sigma columns (the usual spellings, any order, an optional
// leading index column), then one measurement per line; RFC 4180 quoting; CR, LF or CRLF line ends; lines
// starting with '#' and blank lines are skipped. The file is parsed as it is read: only the numbers are held,
// and the bounds below are checked while reading, so that a device or an endless stream is refused early.
struct FitCsvLimits {
  std::size_t max_bytes = std::size_t{256} << 20;  // the whole file, comments included
  std::size_t max_line_bytes = 4096;               // one line (and one quoted field)
  std::size_t max_rows = 1'000'000;                // measurements
};

// Where a file may come from. The command line takes any readable file (a pipe too: the bounds stop an
// endless one); a scene, a file received from someone else, reads regular files only (no device, FIFO,
// socket, nor a /proc or /sys entry, whose contents are the machine's, not data).
enum class FitCsvSource { any_readable, regular_file };

// Throws InvalidInput naming the file, the line and the column of the first bad field (not a decimal number,
// a number beyond the range of a double, v <= 0, eps outside (0, 1), sigma outside
// [kSmallestFitSigma, kLargestFitSigma], a missing or extra field, a broken quote), an unknown, ambiguous or
// missing column, a bound exceeded, a file that cannot be read or has no measurements. A message echoes at
// most 40 characters of the offending field, non-printable bytes escaped.
FitData read_fit_csv(const std::filesystem::path& path, FitCsvSource source = FitCsvSource::any_readable,
                     const FitCsvLimits& limits = {});
// The same for a stream or text already in memory; `name` is the file name the messages give.
FitData parse_fit_csv(std::istream& in, const std::string& name, const FitCsvLimits& limits = {});
FitData parse_fit_csv(const std::string& text, const std::string& name, const FitCsvLimits& limits = {});

// At most 40 characters of `text` for a message, bytes outside printable ASCII as \xNN, "..." when cut.
std::string quoted_excerpt(std::string_view text);

}  // namespace restitution
