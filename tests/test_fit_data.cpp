// SPDX-License-Identifier: BSD-3-Clause
// fit_data (restitution/fit.hpp): exact recovery of β from noise-free data made by the solver, the right end
// and the right law win, bad data are refused, the residual tests see a law the data leave.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "restitution/errors.hpp"
#include "restitution/fit.hpp"
#include "restitution/units.hpp"

namespace restitution {
namespace {

const std::vector<double> kSpeeds{0.01, 0.03, 0.1, 0.3, 1.0, 2.0, 5.0, 10.0};

// ε at every speed by the collision solver (not the fast table the fit uses), to 1e-11.
FitData solver_data(LawKind law, CollisionEnd end, double parameter) {
  CollisionSolver solver;
  SolveOptions options;
  options.tolerance = 1e-11;
  FitData d;
  for (const double v : kSpeeds) {
    const double zeta = law == LawKind::viscoelastic_hertz
                            ? zeta_from(parameter, v)
                            : (law == LawKind::linear_dashpot ? 2 * parameter : parameter);
    options.ends = EndSet{end};
    d.velocity_m_s.push_back(v);
    d.eps.push_back(end_of(solver.solve(ContactLaw::natural(law, zeta), options), end).eps);
  }
  return d;
}

const LawFit& fit_of(const FitResult& r, LawKind law, CollisionEnd end) {
  for (const LawFit& f : r.fits) {
    if (f.candidate.law == law && f.candidate.end == end) return f;
  }
  throw std::logic_error("no such fit");
}

TEST(FitData, RecoversBetaFromNoiseFreeSolverDataAtBothEnds) {
  for (const CollisionEnd end : kCollisionEnds) {
    for (const double beta : {0.02, 0.2, 1.0, 5.0}) {
      const FitData d = solver_data(LawKind::viscoelastic_hertz, end, beta);
      const FitResult r = fit_data(d);
      const LawFit& f = fit_of(r, LawKind::viscoelastic_hertz, end);
      ASSERT_EQ(f.status, FitStatus::converged) << f.message;
      const double error = std::abs(f.value / beta - 1.0);
      std::printf("%-16s beta = %-5g recovered %.17g  relative error %.2e\n", end_name(end), beta, f.value,
                  error);
      EXPECT_LE(error, 1e-9);
      // The scatter estimated from ~1e-13 residuals: an interval that narrow says nothing about β.
      EXPECT_LE(f.ci95.low, f.value);
      EXPECT_GE(f.ci95.high, f.value);
      ASSERT_TRUE(r.best.has_value());
      EXPECT_EQ(r.fits[*r.best].candidate.law, LawKind::viscoelastic_hertz);
      EXPECT_EQ(r.fits[*r.best].candidate.end, end) << "beta " << beta;
      EXPECT_TRUE(r.sigma_estimated);
    }
  }
}

TEST(FitData, SpeedIndependentDataChooseASpeedIndependentLaw) {
  for (const LawKind law : {LawKind::tsuji_hertz, LawKind::linear_dashpot}) {
    const double parameter = 0.3;
    const FitData d = solver_data(law, CollisionEnd::delayed_recovery, parameter);
    const FitResult r = fit_data(d);
    const LawFit& f = fit_of(r, law, CollisionEnd::delayed_recovery);
    ASSERT_EQ(f.status, FitStatus::converged) << f.message;
    EXPECT_NEAR(f.value, parameter, 1e-8 * parameter) << law_name(law);
    ASSERT_TRUE(r.best.has_value());
    // The two speed-independent members fit the same constant ε: a tie, reported as one.
    EXPECT_TRUE(speed_independent(r.fits[*r.best].candidate.law));
    EXPECT_EQ(r.tied_with_best.size(), 1U);
    EXPECT_NE(r.fits[*r.best].candidate.law, LawKind::viscoelastic_hertz);
  }
}

TEST(FitData, ConstantDataGiveIntervalsThatHoldTheValue) {
  // eps = 0.8 at three speeds, no sigma: chi2 = 0, so the scaled intervals shrink to the value, where the
  // inverse's own tolerance once ordered a Tsuji interval backwards by ~1e-12.
  FitData d;
  d.velocity_m_s = {0.5, 1.0, 2.0};
  d.eps = {0.8, 0.8, 0.8};
  for (const LawFit& f : fit_data(d).fits) {
    if (f.status != FitStatus::converged) continue;
    for (const FitInterval& i : {f.ci68, f.ci95}) {
      EXPECT_LE(i.low, f.value) << law_name(f.candidate.law) << " " << end_name(f.candidate.end);
      if (!i.high_at_edge) {
        EXPECT_LE(f.value, i.high) << law_name(f.candidate.law) << " " << end_name(f.candidate.end);
      }
    }
  }
}

TEST(FitData, KnownSigmaGivesDeltaChiSquareOneInterval) {
  // Three points at one β with σ: the 68 % bounds are where χ² rises by exactly 1.
  FitData d = solver_data(LawKind::viscoelastic_hertz, CollisionEnd::delayed_recovery, 0.2);
  d.sigma.assign(d.eps.size(), 0.01);
  FitOptions options;
  options.candidates = {{LawKind::viscoelastic_hertz, CollisionEnd::delayed_recovery}};
  const FitResult r = fit_data(d, options);
  const LawFit& f = r.fits.front();
  ASSERT_EQ(f.status, FitStatus::converged);
  EXPECT_FALSE(r.sigma_estimated);
  CollisionSolver solver;
  auto chi2 = [&](double beta) {
    double s = 0;
    for (std::size_t i = 0; i < d.eps.size(); ++i) {
      const double e = fit_model_eps(f.candidate, beta, d.velocity_m_s[i], solver);
      s += (d.eps[i] - e) * (d.eps[i] - e) / (d.sigma[i] * d.sigma[i]);
    }
    return s;
  };
  EXPECT_NEAR(chi2(f.ci68.low) - f.chi2, 1.0, 1e-9);
  EXPECT_NEAR(chi2(f.ci68.high) - f.chi2, 1.0, 1e-9);
  EXPECT_NEAR(chi2(f.ci95.high) - f.chi2, 3.841458820694124, 1e-9);
  EXPECT_LT(f.ci95.low, f.ci68.low);
  EXPECT_GT(f.ci95.high, f.ci68.high);
}

TEST(FitData, MaterialGivesTheDissipativeConstantWithIntervals) {
  FitData d = solver_data(LawKind::viscoelastic_hertz, CollisionEnd::delayed_recovery, 0.2);
  d.eps[2] *= 0.999;  // some scatter
  FitOptions options;
  options.k = 1e7;
  const FitResult r = fit_data(d, options);
  const LawFit& f = fit_of(r, LawKind::viscoelastic_hertz, CollisionEnd::delayed_recovery);
  ASSERT_TRUE(f.dissipative_constant_s.has_value());
  EXPECT_DOUBLE_EQ(*f.dissipative_constant_s, dissipative_constant_from(f.value, 1e7));
  EXPECT_DOUBLE_EQ(f.dissipative_constant_ci95.low, dissipative_constant_from(f.ci95.low, 1e7));
  EXPECT_DOUBLE_EQ(f.dissipative_constant_ci95.high, dissipative_constant_from(f.ci95.high, 1e7));
  // g* decreases with β: the bounds swap.
  ASSERT_TRUE(f.characteristic_velocity_m_s.has_value());
  EXPECT_DOUBLE_EQ(f.characteristic_velocity_ci95.low, characteristic_velocity_m_s(f.ci95.high));
  EXPECT_DOUBLE_EQ(f.characteristic_velocity_ci95.high, characteristic_velocity_m_s(f.ci95.low));
}

TEST(FitData, ResidualTrendSeesDataThatLeaveTheLaw) {
  // Viscoelastic data up to 1 m/s, then ε falling far faster (plasticity): the trend test says so for the
  // law fitted to all of them.
  FitData d = solver_data(LawKind::viscoelastic_hertz, CollisionEnd::delayed_recovery, 0.1);
  for (std::size_t i = 0; i < d.eps.size(); ++i) {
    if (d.velocity_m_s[i] > 1.0) d.eps[i] *= std::pow(d.velocity_m_s[i], -0.3);
  }
  for (std::size_t i = 0; i < d.eps.size(); ++i) d.eps[i] += (i % 2 == 0 ? 1 : -1) * 1e-4;
  d.sigma.assign(d.eps.size(), 1e-3);
  const FitResult r = fit_data(d);
  const LawFit& f = fit_of(r, LawKind::viscoelastic_hertz, CollisionEnd::delayed_recovery);
  ASSERT_TRUE(f.residuals.available);
  EXPECT_LT(f.residuals.slope_p_value, 0.01);
  EXPECT_EQ(f.residuals.verdict, "falls-with-speed");
  // The exact law on exact data has no trend.
  FitData clean = solver_data(LawKind::viscoelastic_hertz, CollisionEnd::delayed_recovery, 0.1);
  clean.sigma.assign(clean.eps.size(), 1e-3);
  const FitResult rc = fit_data(clean);
  EXPECT_EQ(fit_of(rc, LawKind::viscoelastic_hertz, CollisionEnd::delayed_recovery).residuals.verdict,
            "none");
}

TEST(FitData, TooDissipativeDataAreAtTheEdgeNeverANumber) {
  FitData d;
  d.velocity_m_s = {1.0, 2.0, 3.0};
  d.eps = {1e-12, 1e-12, 1e-12};
  FitOptions options;
  options.candidates = {{LawKind::viscoelastic_hertz, CollisionEnd::delayed_recovery}};
  const LawFit f = fit_data(d, options).fits.front();
  EXPECT_EQ(f.status, FitStatus::at_edge);
  EXPECT_TRUE(std::isnan(f.value));
  EXPECT_TRUE(f.ci95.high_at_edge);
  EXPECT_FALSE(f.message.empty());
}

TEST(FitData, NaiveEndNearCriticalDampingIsAFitNotAnError) {
  // ε ~ 1e-2 at the naive end of Tsuji and the dash-pot lies close to critical damping, where the solver
  // refuses small tolerances: the fit reports a value or its failure, never an exception.
  FitData d{{1.0, 2.0, 3.0}, {0.01, 0.012, 0.011}, {}};
  FitOptions options;
  options.candidates = {{LawKind::tsuji_hertz, CollisionEnd::naive},
                        {LawKind::linear_dashpot, CollisionEnd::naive}};
  const FitResult r = fit_data(d, options);
  for (const LawFit& f : r.fits) {
    EXPECT_EQ(f.status, FitStatus::converged) << law_name(f.candidate.law) << ": " << f.message;
    EXPECT_LT(f.value, law_name(f.candidate.law) == std::string("linear-dashpot") ? 1.0 : std::sqrt(5.0));
  }
}

TEST(FitData, BadDataAreRefusedNamingThePoint) {
  auto refused = [](FitData d, const char* needle) {
    try {
      (void)fit_data(d);
    } catch (const InvalidInput& e) {
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
      return;
    }
    ADD_FAILURE() << "accepted: " << needle;
  };
  refused({{1.0}, {0.5}, {}}, "at least 2");
  refused({{}, {}, {0.1}}, "0 points");
  refused({{1.0, 2.0}, {0.5, 1.0}, {}}, "point 1: eps");
  refused({{1.0, 2.0}, {0.5, 0.0}, {}}, "point 1: eps");
  refused({{1.0, -2.0}, {0.5, 0.4}, {}}, "point 1: the speed");
  refused({{1.0, 2.0}, {0.5, std::nan("")}, {}}, "point 1: eps");
  refused({{1.0, 2.0}, {0.5, 0.4}, {0.1, 0.0}}, "point 1: sigma");
  refused({{1.0, 2.0}, {0.5}, {}}, "2 speeds but 1");
}

// Two degrees of freedom (three points): the χ² distribution's upper tail is exp(-χ²/2) in closed form; one
// point leaves nothing to test.
TEST(FitChi2, PValueIsTheUpperTailOfTheChi2Distribution) {
  for (const double chi2 : {0.0, 0.5, 4.0, 9.21034037, 30.0}) {
    EXPECT_NEAR(chi2_p_value(chi2, 3), std::exp(-chi2 / 2.0), 1e-14 * std::exp(-chi2 / 2.0) + 1e-300) << chi2;
  }
  EXPECT_NEAR(chi2_p_value(6.634896601021214, 2), kFitSignificance, 1e-12);
  EXPECT_EQ(chi2_p_value(100.0, 1), 1.0);
}

}  // namespace
}  // namespace restitution
