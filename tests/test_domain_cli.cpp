// SPDX-License-Identifier: BSD-3-Clause
// The domain as the command line enforces it (issue 25, items 1-4, 9, 10): out-of-range input and answers
// that a double solve cannot deliver exit 2 naming the range or the deliverable tolerance; an output path the
// file system refuses exits 3; exit 1 is left to numerical failures inside the domain.
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"

namespace restitution {
namespace {

using test_support::run_cli;

struct Case {
  const char* arguments;
  int status;
  const char* words;  // a part of stderr
};

TEST(DomainCli, OutOfRangeAndUndeliverableRequestsExitWithTheirStatusAndRange) {
  const std::vector<Case> cases = {
      // Item 1: the Taylor engine near the dash-pot's critical damping, and an answer below the smallest
      // normal double.
      {"eps --law linear-dashpot --damping-ratio 0.99998 --end naive --method taylor --tolerance 3e-11", 2,
       "rounding lets method taylor deliver only tolerance >= 1.1e-08"},
      {"eps --law linear-dashpot --damping-ratio 0.999991 --end naive --method taylor --tolerance 1e-6", 2,
       "below the smallest eps method taylor resolves"},
      {"eps --law linear-dashpot --damping-ratio 0.99997 --end naive --method bdf --tolerance 1e-6", 2,
       "below the smallest eps method bdf resolves"},
      // Item 2: Tsuji near sqrt(5), every method.
      {"eps --law tsuji-hertz --zeta 2.23584 --end naive --method bdf --tolerance 1e-10", 2,
       "ill-conditioned"},
      {"eps --law tsuji-hertz --zeta 2.2359 --end naive", 2, "rounding lets method auto deliver only"},
      {"eps --law tsuji-hertz --zeta 2.2359 --end naive --method adams --tolerance 1e-9", 2, "adams"},
      // Item 3: series outside their domain.
      {"series eval --kind pade-2011-3-6 --zeta 1e300", 2, "outside the checked range 0 <= zeta <= 1e+06"},
      {"series eval --kind simple-theory-1999 --zeta 2e6", 2, "outside the checked range"},
      {"series eval --kind naive-series --zeta 5", 2, "outside the radius of convergence"},
      // Item 4: the fast calibration refuses what the solver's refuses.
      {"calibrate --method fast --eps 1e-300 --velocity 1", 2,
       "is below eps(zeta = 1e+06) = 1.31037e-10 at the delayed-recovery end: outside the checked range"},
      {"calibrate --eps 1e-300 --velocity 1", 2,
       "is below eps(zeta = 1e+06) = 1.31037e-10 at the delayed-recovery end: outside the checked range"},
      // Item 9.
      {"reference --zeta 2e6", 2, "zeta = 2000000 is outside the checked range"},
      {"dem --code lammps --young-modulus 1e9 --poisson-ratio 0.3 --radius 0.01 --density 2500 --eps 0.9 "
       "--velocity 1 --impact-velocity 1e300",
       2, "impact speed 1e+300 m/s: zeta = 9.28"},
      // Item 10: Adams on the stiff naive tail.
      {"eps --zeta 5000 --end naive --method adams", 2, "use --method auto"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.arguments);
    const auto outcome = run_cli(c.arguments);
    EXPECT_EQ(outcome.status, c.status) << outcome.err;
    EXPECT_NE(outcome.err.find(c.words), std::string::npos) << outcome.err;
    EXPECT_EQ(outcome.err.find('\n'), outcome.err.size() - 1) << "one line: " << outcome.err;
  }
}

TEST(DomainCli, AnOutputPathTheFileSystemRefusesIsAnIoError) {
  const test_support::TempFolder folder;
  const std::string scene = (folder.path / "s.toml").string();
  std::ofstream(scene) << "output = \"" << std::string(300, 'a') << "\"\n\n[[sweep]]\nname = \"s\"\n"
                       << "zeta = { from = 0.1, to = 1.0, points = 2 }\n";
  const auto outcome = run_cli("run " + scene);
  EXPECT_EQ(outcome.status, 3) << outcome.err;
  EXPECT_NE(outcome.err.find("File name too long"), std::string::npos) << outcome.err;
}

}  // namespace
}  // namespace restitution
