// SPDX-License-Identifier: BSD-3-Clause
// One set of approximation names (issue 12, item 16): every name `series validate` reports is a kind
// `series eval` (and Python's series.eval) takes, giving the very numbers validate compared; every
// approximation is accepted by scene files under the same name; the old series spellings stay aliases.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "restitution/errors.hpp"
#include "restitution_series_study/series_named.hpp"
#include "restitution_series_study/series_validation.hpp"
#include "scene/scene.hpp"
#include "scene/scene_approximations.hpp"
#include "scene/scene_sections.hpp"

namespace restitution::series {
namespace {

TEST(ApproximationNames, EveryValidatedNameEvaluatesToTheValidatedNumbers) {
  ValidationOptions o;
  o.zeta_min = 0.01;
  o.zeta_max = 1.0;
  o.points_per_decade = 2;
  const ValidationReport r = validate(o);
  std::vector<double> zetas;
  for (const ValidationRow& row : r.rows) zetas.push_back(row.zeta);
  ASSERT_FALSE(r.candidates.empty());
  for (std::size_t i = 0; i < r.candidates.size(); ++i) {
    const std::string& name = r.candidates[i].name;
    const NamedEvaluation e = evaluate_by_kind(name, zetas, std::nullopt, false);
    for (std::size_t j = 0; j < zetas.size(); ++j) {
      EXPECT_EQ(e.values[j].eps, r.rows[j].errors[i].value.eps) << name << " at zeta " << zetas[j];
    }
  }
}

TEST(ApproximationNames, ScenesAndSeriesEvalShareOneSpellingPerApproximation) {
  EXPECT_EQ(scene::detail::kApproximations.size(), evaluation_kinds().size());
  for (const auto& info : scene::detail::kApproximations) {
    const std::string name = approximation_name(info.kind);
    EXPECT_EQ(approximation_named(name), info.kind) << name;
    EXPECT_NE(std::find(evaluation_kinds().begin(), evaluation_kinds().end(), name),
              evaluation_kinds().end());
    const scene::Scene s = scene::parse_scene(
        "output = \"o\"\n[[sweep]]\nzeta = [0.5]\napproximations = [\"" + name + "\"]\n", "t");
    const std::vector<series::Approximation>& named =
        scene::tasks_of<scene::Sweep>(s, "sweep")[0]->approximations;
    ASSERT_EQ(named.size(), 1U);
    EXPECT_EQ(named[0], info.kind);
    const auto outcome = test_support::run_cli("series eval --kind " + name + " --zeta 0.5 --json");
    EXPECT_EQ(outcome.status, 0) << name << ": " << outcome.err;
  }
}

TEST(ApproximationNames, TheOldSeriesSpellingsAreAliases) {
  const std::vector<double> zeta = {0.3};
  EXPECT_EQ(evaluate_by_kind("naive", zeta, std::nullopt, false).values[0].eps,
            evaluate_by_kind("naive-series", zeta, std::nullopt, false).values[0].eps);
  EXPECT_EQ(evaluate_by_kind("delayed-recovery", zeta, 20, true).values[0].eps,
            evaluate_by_kind("delayed-recovery-series:published", zeta, std::nullopt, false).values[0].eps);
  EXPECT_EQ(evaluate_by_kind("naive-series:computed-12", zeta, std::nullopt, false).values[0].eps,
            evaluate_by_kind("naive-series", zeta, 12, false).values[0].eps);
  EXPECT_THROW((void)evaluate_by_kind("pade-1999:published", zeta, std::nullopt, false), InvalidInput);
  EXPECT_THROW((void)evaluate_by_kind("naive-series:published", zeta, 3, false), InvalidInput);
  EXPECT_THROW((void)evaluate_by_kind("naive-series:computed-", zeta, std::nullopt, false), InvalidInput);
  EXPECT_THROW((void)evaluate_by_kind("nonsense", zeta, std::nullopt, false), InvalidInput);
}

}  // namespace
}  // namespace restitution::series
