// SPDX-License-Identifier: BSD-3-Clause
#include "cli/common/json_writer.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <nlohmann/json.hpp>
#include <random>
#include <string>
#include <vector>

namespace restitution::cli {
namespace {

TEST(JsonWriter, NestedObjectsAndArraysParse) {
  JsonWriter w;
  w.begin_object().field("a", 1.5).key("list").begin_array().value(1.0).value(2L).value("x\"y").end_array();
  w.key("inner").begin_object().field("flag", true).end_object().end_object();
  const auto j = nlohmann::json::parse(w.str());
  EXPECT_EQ(j["a"].get<double>(), 1.5);
  EXPECT_EQ(j["list"][2], "x\"y");
  EXPECT_EQ(j["inner"]["flag"], true);
}

TEST(JsonWriter, KeysStayInTheOrderWritten) {
  JsonWriter w;
  w.begin_object().field("zeta", 1L).field("law", "hertz").key("a").begin_array().end_array().end_object();
  EXPECT_EQ(w.str(), R"({"zeta":1,"law":"hertz","a":[]})");
}

TEST(JsonWriter, AListIsTheArrayOfItsValues) {
  // One call writes what an array of the values one at a time writes, an empty list included.
  const std::vector<std::string> lines{"pair_style granular", "a \"quoted\" line"};
  const std::vector<double> speeds{0.1, 1.0, std::numeric_limits<double>::quiet_NaN()};
  JsonWriter listed;
  listed.begin_object()
      .field("lines", lines)
      .field("v", speeds)
      .field("none", std::vector<double>{})
      .end_object();
  JsonWriter one_by_one;
  one_by_one.begin_object().key("lines").begin_array();
  for (const std::string& line : lines) one_by_one.value(line);
  one_by_one.end_array().key("v").begin_array();
  for (const double v : speeds) one_by_one.value(v);
  one_by_one.end_array().key("none").begin_array().end_array().end_object();
  EXPECT_EQ(listed.str(), one_by_one.str());
  EXPECT_EQ(listed.str(),
            R"({"lines":["pair_style granular","a \"quoted\" line"],"v":[0.1,1.0,null],"none":[]})");
}

TEST(JsonWriter, ShortestRoundTripAndNonFiniteIsNull) {
  JsonWriter w;
  const double third = 1.0 / 3.0;
  w.begin_array().value(third).value(0.1).value(std::numeric_limits<double>::infinity());
  w.value(std::numeric_limits<double>::quiet_NaN()).end_array();
  EXPECT_EQ(w.str(), "[0.3333333333333333,0.1,null,null]");
  EXPECT_EQ(nlohmann::json::parse(w.str())[0].get<double>(), third);
}

// The contract of every JSON output: each number reads back to the very double that was written.
TEST(JsonWriter, EveryDoubleReadsBackBitForBit) {
  std::vector<double> values{0.0,
                             -0.0,
                             1.0,
                             1e-10,
                             1.0 - 1e-16,
                             std::numeric_limits<double>::min(),
                             std::numeric_limits<double>::denorm_min(),
                             std::numeric_limits<double>::max(),
                             std::numeric_limits<double>::lowest(),
                             std::numeric_limits<double>::epsilon()};
  std::mt19937_64 bits(20261123);
  while (values.size() < 20000) {
    const double v = std::bit_cast<double>(bits());
    if (std::isfinite(v)) values.push_back(v);
  }
  JsonWriter w;
  w.begin_array();
  for (const double v : values) w.value(v);
  w.end_array();
  const auto j = nlohmann::json::parse(w.str());
  ASSERT_EQ(j.size(), values.size());
  for (std::size_t i = 0; i < values.size(); ++i) {
    const double back = j[i].get<double>();
    ASSERT_EQ(std::bit_cast<std::uint64_t>(back), std::bit_cast<std::uint64_t>(values[i])) << values[i];
  }
}

TEST(JsonWriter, EscapesControlCharactersAndKeepsUtf8) {
  JsonWriter w;
  w.begin_object().field("k", "a\nb\x01").field("greek", "ε ζ").end_object();
  EXPECT_EQ(nlohmann::json::parse(w.str())["k"], "a\nb\x01");
  EXPECT_NE(w.str().find("ε ζ"), std::string::npos);
}

TEST(JsonWriter, InvalidUtf8IsReplacedNotRefused) {
  JsonWriter w;
  w.begin_object()
      .field("file",
             "a\xff"
             "b")
      .end_object();
  // The invalid byte 0xFF becomes U+FFFD (EF BF BD in UTF-8); the valid text around it stays.
  EXPECT_EQ(w.str(),
            "{\"file\":\"a\xEF\xBF\xBD"
            "b\"}");
  EXPECT_EQ(nlohmann::json::parse(w.str())["file"].get<std::string>(),
            "a\xEF\xBF\xBD"
            "b");
}

}  // namespace
}  // namespace restitution::cli
