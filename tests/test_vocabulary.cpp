// SPDX-License-Identifier: BSD-3-Clause
// One vocabulary: every name of a method, an end (and the "both" set) and a law is spelled once, beside its
// enum, and every front end parses it there; the defaults come from SolveOptions.
#include <gtest/gtest.h>

#include <string>

#include "cli_runner.hpp"
#include "restitution/calibration.hpp"
#include "restitution/collision_solver.hpp"
#include "restitution/errors.hpp"

namespace restitution {
namespace {

using test_support::run_cli;

TEST(Vocabulary, NamesRoundTrip) {
  ASSERT_EQ(method_names().size(), kMethods.size());
  for (const Method m : kMethods) EXPECT_EQ(method_from_name(method_name(m)), m);
  for (const CollisionEnd e : kCollisionEnds) {
    EXPECT_EQ(end_from_name(end_name(e)), e);
    EXPECT_EQ(end_set_from_name(end_name(e)), EndSet{e});
  }
  EXPECT_EQ(end_set_from_name(kBothEnds), EndSet::both());
  for (const LawKind k : kLawKinds) EXPECT_EQ(law_from_name(law_name(k)), k);
  EXPECT_EQ(law_names().size(), kLawKinds.size());
}

TEST(Vocabulary, UnknownNamesAreRefusedWithTheList) {
  EXPECT_THROW((void)method_from_name("rk4"), InvalidInput);
  EXPECT_THROW((void)end_set_from_name("middle"), InvalidInput);
  try {
    (void)end_set_from_name("middle");
  } catch (const InvalidInput& e) {
    EXPECT_STREQ(e.what(), "end must be naive, delayed-recovery or both, got 'middle'");
  }
  // The command line used to map an unknown method silently to auto.
  const auto r = run_cli("eps --zeta 1 --method rk4");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(run_cli("calibrate --eps 0.5 --velocity 1 --method rk4").status, 2);
  EXPECT_EQ(run_cli("calibrate --eps 0.5 --velocity 1 --end both").status, 2);
  EXPECT_EQ(
      run_cli("sweep --zeta-min 0 --zeta-max 1 --points 2 --law hooke --out /tmp/restitution-vocabulary.csv")
          .status,
      2);
}

TEST(Vocabulary, DefaultsAreSolveOptions) {
  EXPECT_EQ(CalibrationRequest{}.tolerance, SolveOptions{}.tolerance);
  EXPECT_EQ(CalibrationRequest{}.method, SolveOptions{}.method);
  const auto r = run_cli("eps --help");
  EXPECT_NE(r.out.find("--tolerance FLOAT=1e-10"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace restitution
