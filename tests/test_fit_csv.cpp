// SPDX-License-Identifier: BSD-3-Clause
// The fit CSV reader's bounds (restitution/fit.hpp), each met exactly and exceeded by one, and the
// excerpt that messages quote.
#include <gtest/gtest.h>

#include <string>

#include "restitution/errors.hpp"
#include "restitution/fit.hpp"

namespace restitution {
namespace {

std::string refusal(const std::string& text, const FitCsvLimits& limits) {
  try {
    parse_fit_csv(text, "f.csv", limits);
  } catch (const InvalidInput& e) {
    return e.what();
  }
  ADD_FAILURE() << "accepted: " << text;
  return {};
}

std::string rows(int n) {
  std::string out = "v,eps\n";
  for (int i = 1; i <= n; ++i) out += std::to_string(i) + ",0.5\n";
  return out;
}

TEST(FitCsv, RowBoundIsMetAndRefusedOneBeyond) {
  FitCsvLimits limits;
  limits.max_rows = 8;
  EXPECT_EQ(parse_fit_csv(rows(8), "f.csv", limits).eps.size(), 8U);
  EXPECT_EQ(refusal(rows(9), limits),
            "f.csv:10:1: more than 8 measurements, the bound of a fit CSV (docs/fit.md)");
  EXPECT_EQ(FitCsvLimits{}.max_rows, 1'000'000U);  // docs/fit.md and the 1e6-row memory figure
}

TEST(FitCsv, ByteAndLineBounds) {
  FitCsvLimits limits;
  const std::string text = rows(3);
  limits.max_bytes = text.size();
  EXPECT_EQ(parse_fit_csv(text, "f.csv", limits).eps.size(), 3U);
  limits.max_bytes = text.size() - 1;
  EXPECT_NE(refusal(text, limits).find("longer than " + std::to_string(text.size() - 1) + " bytes"),
            std::string::npos);
  limits = {};
  limits.max_line_bytes = 8;  // "v,eps\n" and "1,0.5\n" fit; a longer line does not
  EXPECT_EQ(parse_fit_csv("v,eps\n1,0.5\n2,0.5\n", "f.csv", limits).eps.size(), 2U);
  EXPECT_EQ(refusal("v,eps\n1,0.5\n2,0.50000\n", limits),
            "f.csv:3: the line is longer than 8 bytes, the bound of a fit CSV (docs/fit.md)");
}

TEST(FitCsv, QuotedFieldsMayHoldCommasAndLineEnds) {
  // A doubled quote belongs to the name: 'e"ps"' is no accepted name.
  EXPECT_NE(refusal("\"v\",\"e\"\"ps\"\"\"\n1,0.5\n", {}).find("unknown column 'e\"ps\"'"),
            std::string::npos);
  // A quoted field spanning lines: the line count goes on, the next row's line is right.
  EXPECT_EQ(refusal("\"v\nspeed\",eps\n1,0.5\n", {}).substr(0, 12), "f.csv:1:1: u");
  EXPECT_NE(refusal(",v,eps\n\"row\none, a\",1,0.5\nx,2,abc\n", {}).find("f.csv:4:5: column 'eps'"),
            std::string::npos);
}

TEST(FitCsv, ExcerptIsShortAndEscaped) {
  EXPECT_EQ(quoted_excerpt("abc"), "abc");
  EXPECT_EQ(quoted_excerpt(std::string("a\0b\n\x7f\xff", 6)), "a\\x00b\\x0a\\x7f\\xff");
  // Compared in two parts: GCC 12 at -O1 warns falsely (-Wstringop-overflow) on a string + literal here.
  const std::string long_excerpt = quoted_excerpt(std::string(41, 'x'));
  EXPECT_EQ(long_excerpt.substr(0, 40), std::string(40, 'x'));
  EXPECT_EQ(long_excerpt.substr(40), "...");
}

}  // namespace
}  // namespace restitution
