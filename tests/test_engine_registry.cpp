// SPDX-License-Identifier: BSD-3-Clause
// The registry of engines (src/solver/engine_registry.hpp): which engine computes each method, its name and
// floor, and whether it covers a law, its ends and the options (its own check()).
#include <gtest/gtest.h>

#include <string>

#include "restitution/errors.hpp"
#include "solver/engine_registry.hpp"
#include "taylor/taylor_engine.hpp"

namespace restitution {
namespace {

TEST(EngineRegistry, MapsEveryMethodToItsEngineOnce) {
  for (const Method method : {Method::bdf, Method::adams, Method::automatic}) {
    EXPECT_EQ(std::string(engine_of(method).name), "CVODE");
    EXPECT_EQ(min_tolerance(method), kMinTolerance);
  }
  EXPECT_EQ(std::string(engine_of(Method::taylor).name), "Taylor");
  EXPECT_EQ(min_tolerance(Method::taylor), kMinTaylorTolerance);
  Engines engines;
  EXPECT_EQ(&engines(Method::bdf), &engines(Method::adams));  // one CVODE engine for its three methods
  EXPECT_EQ(&engines(Method::bdf), &engines(Method::automatic));
  EXPECT_NE(&engines(Method::bdf), &engines(Method::taylor));
}

TEST(EngineRegistry, EachMethodsEngineChecksWhatItServes) {
  Engines engines;
  // Whether the engine of options.method serves this law, its ends and these options: its check() passes.
  const auto covers = [&engines](const ContactLaw& law, const SolveOptions& options) {
    try {
      engines(options.method).check(law, options);
      return true;
    } catch (const InvalidInput&) {
      return false;
    }
  };
  SolveOptions options;
  options.method = Method::taylor;
  EXPECT_TRUE(covers(ContactLaw::hertz_natural(1.0), options));
  EXPECT_FALSE(covers(ContactLaw::natural(LawKind::tsuji_hertz, 1.0), options));
  EXPECT_FALSE(covers(ContactLaw::hertz_natural(1000.0), options));  // naive end beyond 100
  options.ends = EndSet{CollisionEnd::delayed_recovery};
  EXPECT_TRUE(covers(ContactLaw::hertz_natural(1000.0), options));
  options.method = Method::adams;
  options.ends = EndSet{CollisionEnd::naive};
  EXPECT_TRUE(covers(ContactLaw::natural(LawKind::tsuji_hertz, 1.0), options));
  EXPECT_FALSE(covers(ContactLaw::hertz_natural(5000.0), options));  // the stiff tail
  options.method = Method::automatic;
  EXPECT_TRUE(covers(ContactLaw::hertz_natural(5000.0), options));
}

}  // namespace
}  // namespace restitution
