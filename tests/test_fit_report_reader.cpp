// SPDX-License-Identifier: BSD-3-Clause
// The reader of fit-data's report (fit/fit_report_reader.hpp): what the writer (cli/fit/fit_data_report.hpp)
// writes reads back to the fit's own numbers, the carried-over fit is the lowest-AIC Hertz fit (or the one at
// the end asked for), the report's own verdict rejects what its tests reject, A and ε carry β's intervals
// over as fit_data computes them itself, and bad reports are refused naming the file and the key.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "cli/fit/fit_data_report.hpp"
#include "fit/best_hertz_fit.hpp"
#include "fit/fit_report_reader.hpp"
#include "restitution/errors.hpp"
#include "restitution/fit.hpp"
#include "restitution/units.hpp"

namespace {

using namespace restitution;

// ε(v) of viscoelastic Hertz at the delayed-recovery end for β = 0.2, with a deterministic scatter of ±0.004.
FitData drop_data() {
  FitData d;
  const double eps[] = {0.8472, 0.8549, 0.8212, 0.8203, 0.7917, 0.7988, 0.7874, 0.7805, 0.7504, 0.7425};
  const double v[] = {0.2, 0.2, 0.5, 0.5, 1.0, 1.0, 2.0, 2.0, 5.0, 5.0};
  for (int i = 0; i < 10; ++i) {
    d.velocity_m_s.push_back(v[i]);
    d.eps.push_back(eps[i]);
    d.sigma.push_back(0.01);
  }
  return d;
}

constexpr double kK = 3.7e5;  // ρ/m_eff of some material [s^-2 m^-1/2]

struct Report {
  FitData data = drop_data();
  FitResult result;
  std::string json;
};

Report make_report() {
  Report r;
  FitOptions options;
  options.k = kK;
  r.result = fit_data(r.data, options);
  r.json = cli::fit_json({"drop.csv", &r.data, &r.result, options.k});
  return r;
}

// The index of the converged Hertz fit with the lowest AIC (at `end` when given), from the fit itself.
std::size_t lowest_hertz(const FitResult& result, std::optional<CollisionEnd> end) {
  std::optional<std::size_t> out;
  for (std::size_t i = 0; i < result.fits.size(); ++i) {
    const LawFit& f = result.fits[i];
    if (f.candidate.law != LawKind::viscoelastic_hertz || f.status != FitStatus::converged) continue;
    if (end && f.candidate.end != *end) continue;
    if (!out || f.aic < result.fits[*out].aic) out = i;
  }
  return out.value();
}

void expect_interval_eq(const FitInterval& a, const FitInterval& b, double relative) {
  EXPECT_EQ(a.low_at_edge, b.low_at_edge);
  EXPECT_EQ(a.high_at_edge, b.high_at_edge);
  if (!a.low_at_edge) EXPECT_NEAR(a.low, b.low, relative * std::abs(b.low));
  if (!a.high_at_edge) EXPECT_NEAR(a.high, b.high, relative * std::abs(b.high));
}

TEST(FitReportReader, ReadsBackWhatTheWriterWrote) {
  const Report r = make_report();
  for (const std::optional<CollisionEnd> end :
       {std::optional<CollisionEnd>(), std::optional(CollisionEnd::naive),
        std::optional(CollisionEnd::delayed_recovery)}) {
    const FitCarryOver c = parse_fit_report(r.json, "drop.json", end);
    const LawFit& f = r.result.fits[lowest_hertz(r.result, end)];
    EXPECT_EQ(c.end, f.candidate.end);
    if (end) EXPECT_EQ(c.end, *end);
    EXPECT_EQ(c.beta, f.value);  // JSON numbers read back to the same double
    expect_interval_eq(c.ci68, f.ci68, 0.0);
    expect_interval_eq(c.ci95, f.ci95, 0.0);
    EXPECT_EQ(c.points, r.data.eps.size());
    EXPECT_EQ(c.sigma_estimated, r.result.sigma_estimated);
    ASSERT_EQ(c.fits.size(), r.result.fits.size());
    EXPECT_EQ(c.fits[c.chosen].law, LawKind::viscoelastic_hertz);
    EXPECT_EQ(c.file, "drop.json");
  }
}

TEST(FitReportReader, CarriesTheFitWhoseATheReportGives) {
  // The report's A comes from best_hertz_fit; --from-fit without --end must carry that same fit.
  const Report r = make_report();
  const std::optional<std::size_t> best = best_hertz_fit(r.result);
  ASSERT_TRUE(best.has_value());
  EXPECT_EQ(*best, lowest_hertz(r.result, std::nullopt));
  EXPECT_EQ(parse_fit_report(r.json, "drop.json", std::nullopt).chosen, *best);
  FitResult none = r.result;
  for (LawFit& f : none.fits) {
    if (f.candidate.law == LawKind::viscoelastic_hertz) f.status = FitStatus::at_edge;
  }
  EXPECT_FALSE(best_hertz_fit(none).has_value());
}

TEST(FitReportReader, CarriesTheIntervalsOverAsTheFitItselfDoes) {
  const Report r = make_report();
  const FitCarryOver c = parse_fit_report(r.json, "drop.json", std::nullopt);
  const LawFit& f = r.result.fits[c.chosen];
  ASSERT_TRUE(f.dissipative_constant_s.has_value());
  const CarriedDissipativeConstant a = carried_dissipative_constant(c, kK);
  EXPECT_NEAR(a.value_s, *f.dissipative_constant_s, 1e-14 * *f.dissipative_constant_s);
  expect_interval_eq(a.ci68, f.dissipative_constant_ci68, 1e-14);
  expect_interval_eq(a.ci95, f.dissipative_constant_ci95, 1e-14);
  // ε falls as β rises: the carried ε lies inside its intervals, and the 95 % one holds the 68 % one.
  for (const double v : {0.1, 1.0, 10.0}) {
    const FittedEps e = carried_eps_at_speed(c, v);
    EXPECT_LE(e.ci95.low, e.ci68.low);
    EXPECT_LE(e.ci68.low, e.eps);
    EXPECT_LE(e.eps, e.ci68.high);
    EXPECT_LE(e.ci68.high, e.ci95.high);
  }
}

TEST(FitReportReader, TheReportsOwnTestsRejectAFitAnotherLawBeats) {
  const Report r = make_report();
  nlohmann::json j = nlohmann::json::parse(r.json);
  // Give the dash-pot (speed-independent, converged) the lowest AIC: it becomes the report's best fit.
  std::optional<std::size_t> dashpot;
  for (std::size_t i = 0; i < j["fits"].size(); ++i) {
    if (j["fits"][i]["law"] == "linear-dashpot") dashpot = i;
  }
  ASSERT_TRUE(dashpot.has_value());
  j["fits"][*dashpot]["aic"] = -1000.0;
  j["best"] = *dashpot;
  j["tied_with_best"] = nlohmann::json::array();
  const FitCarryOver c = parse_fit_report(j.dump(), "drop.json", std::nullopt);
  EXPECT_TRUE(c.rejection.rejected());
  ASSERT_TRUE(c.rejection.better_fit.has_value());
  EXPECT_EQ(*c.rejection.better_fit, *dashpot);
  EXPECT_EQ(c.fits[*c.rejection.better_fit].law, LawKind::linear_dashpot);
  // The unchanged report does not reject its own best fit.
  EXPECT_FALSE(parse_fit_report(r.json, "drop.json", std::nullopt).rejection.rejected());
}

void expect_refused(const std::string& text, const std::string& message) {
  try {
    (void)parse_fit_report(text, "f.json", std::nullopt);
    ADD_FAILURE() << "accepted: " << text;
  } catch (const InvalidInput& e) {
    EXPECT_EQ(std::string(e.what()), message);
  }
}

TEST(FitReportReader, RefusesBadReportsNamingTheFileAndTheKey) {
  const Report r = make_report();
  expect_refused("[1]", "f.json: must be one JSON object (a fit-data report), got a list of 1 value");
  expect_refused("{", "f.json: not JSON (a fit-data report), the syntax breaks at byte 2");
  nlohmann::json j = nlohmann::json::parse(r.json);
  j.erase("points");
  expect_refused(j.dump(), "f.json: points: missing (not a fit-data report?)");
  j = nlohmann::json::parse(r.json);
  j["fits"][0]["ci68"] = {0.5, 0.6};  // does not hold the value
  try {
    (void)parse_fit_report(j.dump(), "f.json", std::nullopt);
    ADD_FAILURE() << "accepted an interval without the value";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(std::string(e.what()).rfind("f.json: fits[0].ci68: must hold the value", 0), 0u) << e.what();
  }
}

TEST(FitReportReader, RefusesAFolderAndAMissingFile) {
  EXPECT_THROW((void)read_fit_report(RESTITUTION_SOURCE_DIR, std::nullopt), InvalidInput);
  EXPECT_THROW((void)read_fit_report("/nonexistent/fit.json", std::nullopt), InvalidInput);
}

}  // namespace
