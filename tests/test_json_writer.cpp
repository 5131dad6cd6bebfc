#include "cli/json_writer.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <nlohmann/json.hpp>

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

TEST(JsonWriter, SeventeenDigitsRoundTripAndNonFiniteIsNull) {
  JsonWriter w;
  const double third = 1.0 / 3.0;
  w.begin_array().value(third).value(std::numeric_limits<double>::infinity()).end_array();
  EXPECT_EQ(w.str(), "[0.33333333333333331,null]");
  EXPECT_EQ(nlohmann::json::parse(w.str())[0].get<double>(), third);
}

TEST(JsonWriter, EscapesControlCharacters) {
  JsonWriter w;
  w.begin_object().field("k", "a\nb\x01").end_object();
  EXPECT_EQ(nlohmann::json::parse(w.str())["k"], "a\nb\x01");
}

}  // namespace
}  // namespace restitution::cli
