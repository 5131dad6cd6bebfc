// SPDX-License-Identifier: BSD-3-Clause
// The driven deck's read-back and block averages (src/gas_deck/driven_log.cpp, driven_comparison.cpp;
// docs/gas.md, "The driven gas"): the lines the deck prints are read strictly, and block averages of a known
// series give its mean and the spread of its block means.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>

#include "cli_runner.hpp"
#include "gas_deck/driven_comparison.hpp"
#include "gas_deck/driven_log.hpp"
#include "restitution/errors.hpp"

namespace restitution::gas_deck {
namespace {

TEST(DrivenBlockAverage, MeanAndErrorOfTheBlockMeans) {
  // Four blocks of 1 s sampled 10 times each, block k holding the constant k: mean 1.5, the block means'
  // standard deviation sqrt(5/3) over sqrt(4).
  std::vector<double> t, v;
  for (int i = 1; i <= 40; ++i) {
    t.push_back(10.0 + 0.1 * i - 0.05);
    v.push_back(std::floor((t.back() - 10.0) / 1.0));
  }
  const BlockAverage b = block_average(t, v, 10.0, 1.0);
  EXPECT_EQ(b.blocks, 4);
  EXPECT_DOUBLE_EQ(b.mean, 1.5);
  EXPECT_NEAR(b.error, std::sqrt(5.0 / 3.0) / 2.0, 1e-14);
  // Samples before the steady part are left out; a stub of a last block too.
  t.insert(t.begin(), 5.0);
  v.insert(v.begin(), 1e9);
  t.push_back(14.05);
  v.push_back(-1e9);
  const BlockAverage stub = block_average(t, v, 10.0, 1.0);
  EXPECT_EQ(stub.blocks, 4);
  EXPECT_DOUBLE_EQ(stub.mean, 1.5);
}

TEST(DrivenLog, ReadsTheBathAndTheMomentsStrictly) {
  const test_support::TempFolder folder;
  const auto log = folder.path / "driven.log";
  std::ofstream(log) << "print \"restitution-driven law=viscoelastic time_s=$(time)\"\n"
                     << "restitution-driven-setup bath_temperature_j=0.001 bath_time_s=2 steady_from_s=0.5\n"
                     << "restitution-driven law=viscoelastic time_s=0 mean_v2_m2_s2=3 mean_v4_m4_s4=15\r\n"
                     << "restitution-driven law=viscoelastic time_s=0.1 mean_v2_m2_s2=2.5 mean_v4_m4_s4=10\n"
                     << "restitution-driven law=viscoelastic time_s=0.2 mean_v2_m2_s2=2.5 mean_v4";
  const DrivenLog read = read_driven_log_file(log);
  ASSERT_TRUE(read.bath);
  EXPECT_EQ(read.bath->bath_temperature_j, 0.001);
  EXPECT_EQ(read.bath->steady_from_s, 0.5);
  ASSERT_EQ(read.runs.size(), 1U);
  EXPECT_EQ(read.runs[0].time_s.size(), 2U);  // the cut last line left out
  EXPECT_EQ(read.runs[0].mean_v4_m4_s4[1], 10.0);
  std::ofstream(log) << "restitution-driven law=viscoelastic time_s=0 mean_v2_m2_s2=3abc mean_v4_m4_s4=15\n";
  try {
    (void)read_driven_log_file(log);
    ADD_FAILURE() << "a garbled number was read";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("line 1"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("mean_v2_m2_s2"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace restitution::gas_deck
