// SPDX-License-Identifier: BSD-3-Clause
// The reference solutions over a grid (reference/reference_solution.hpp, hertz_references): each the same as
// one hertz_reference at its ζ, in the grid's order, progress reported after each, and stopped by a progress
// callback that throws.
#include <gtest/gtest.h>

#include <stdexcept>
#include <utility>
#include <vector>

#include "reference/reference_solution.hpp"

namespace {

using namespace restitution;

TEST(HertzReferences, EachIsTheSingleSolutionInGridOrder) {
  const std::vector<double> zetas{2.0, 0.1};
  std::vector<std::pair<std::size_t, std::size_t>> calls;
  const std::vector<ReferenceSolution> s =
      hertz_references(zetas, [&](std::size_t done, std::size_t total) { calls.emplace_back(done, total); });
  ASSERT_EQ(s.size(), 2U);
  for (std::size_t i = 0; i < 2; ++i) {
    const ReferenceSolution one = hertz_reference(zetas[i]);
    EXPECT_EQ(static_cast<double>(s[i].parameter), zetas[i]);
    EXPECT_TRUE(s[i].ends[CollisionEnd::delayed_recovery]->eps ==
                one.ends[CollisionEnd::delayed_recovery]->eps);
  }
  EXPECT_EQ(calls, (std::vector<std::pair<std::size_t, std::size_t>>{{1, 2}, {2, 2}}));
}

TEST(HertzReferences, AThrowingProgressStopsTheLoop) {
  std::size_t calls = 0;
  EXPECT_THROW(hertz_references({0.1, 0.2, 0.3},
                                [&](std::size_t, std::size_t) {
                                  ++calls;
                                  throw std::runtime_error("stop");
                                }),
               std::runtime_error);
  EXPECT_EQ(calls, 1U);
}

}  // namespace
