// SPDX-License-Identifier: BSD-3-Clause
// One encoding of the end of a collision: CollisionEnd indexes results and selections, and has one spelling.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "restitution/collision_solver.hpp"
#include "restitution/errors.hpp"

namespace restitution {
namespace {

TEST(CollisionEnd, NamesRoundTripWithOneSpelling) {
  EXPECT_STREQ(end_name(CollisionEnd::naive), "naive");
  EXPECT_STREQ(end_name(CollisionEnd::delayed_recovery), "delayed-recovery");
  for (const CollisionEnd end : kCollisionEnds) EXPECT_EQ(end_from_name(end_name(end)), end);
  EXPECT_THROW(end_from_name("delayed_recovery"), InvalidInput);
  EXPECT_NE(kCollisionEnds[0], kCollisionEnds[1]);
}

TEST(CollisionEnd, KeysAreIdentifiers) {
  EXPECT_STREQ(end_key(CollisionEnd::naive), "naive");
  EXPECT_STREQ(end_key(CollisionEnd::delayed_recovery), "delayed_recovery");
}

TEST(EndSet, SetOfOneEndHoldsThatEndOnly) {
  for (const CollisionEnd end : kCollisionEnds) {
    const EndSet set{end};
    for (const CollisionEnd other : kCollisionEnds) EXPECT_EQ(set.contains(other), other == end);
    EXPECT_EQ(set.members(), std::vector<CollisionEnd>{end});
  }
}

TEST(EndSet, BothEmptyUnionAndErase) {
  EXPECT_TRUE(EndSet{}.empty());
  EXPECT_EQ(EndSet::both().members(),
            std::vector<CollisionEnd>(kCollisionEnds.begin(), kCollisionEnds.end()));
  EXPECT_EQ(EndSet{CollisionEnd::naive} | EndSet{CollisionEnd::delayed_recovery}, EndSet::both());
  EndSet set = EndSet::both();
  set.erase(CollisionEnd::naive);
  EXPECT_EQ(set, EndSet{CollisionEnd::delayed_recovery});
  set.erase(CollisionEnd::delayed_recovery);
  EXPECT_TRUE(set.empty());
  EXPECT_EQ(SolveOptions{}.ends, EndSet::both());
}

TEST(CollisionEnd, PerEndHoldsOneValuePerEnd) {
  PerEnd<int> values;
  values[CollisionEnd::naive] = 1;
  values[CollisionEnd::delayed_recovery] = 2;
  EXPECT_EQ(values[CollisionEnd::naive], 1);
  EXPECT_EQ(values[CollisionEnd::delayed_recovery], 2);
}

TEST(CollisionEnd, ResultIsIndexedByEnd) {
  CollisionSolver solver;
  const CollisionResult both = solver.solve(ContactLaw::hertz_natural(1.0), {});
  EXPECT_NE(&both[CollisionEnd::naive], &both[CollisionEnd::delayed_recovery]);
  // The delayed-recovery end comes first, with the larger ε (less time to dissipate).
  EXPECT_GT(both[CollisionEnd::delayed_recovery]->eps, both[CollisionEnd::naive]->eps);
  for (const CollisionEnd end : kCollisionEnds) {
    SolveOptions options;
    options.ends = EndSet{end};
    const CollisionResult one = solver.solve(ContactLaw::hertz_natural(1.0), options);
    ASSERT_TRUE(one[end].has_value());
    for (const CollisionEnd other : kCollisionEnds) {
      if (other != end) EXPECT_FALSE(one[other].has_value());
    }
    // Both solves honour |ε - ε_exact| <= tolerance · min(ε, 1 - ε) at this end.
    const double eps = both[end]->eps;
    EXPECT_NEAR(end_of(one, end).eps, eps, 2 * SolveOptions{}.tolerance * std::min(eps, 1 - eps));
  }
}

}  // namespace
}  // namespace restitution
