// The pre-check of scene text that keeps toml++ 3.3.0 away from its undefined behaviour on non-ASCII
// characters where it tests for whitespace, while non-ASCII text in strings and comments stays allowed.
#include "scene/toml_text_check.hpp"

#include <gtest/gtest.h>

#include <string>

#include "restitution/errors.hpp"
#include "restitution/scene.hpp"

namespace restitution::scene {
namespace {

std::string error_of(std::string_view text) {
  try {
    check_scene_text(text, "s.toml");
  } catch (const InvalidInput& e) {
    return e.what();
  }
  return {};
}

TEST(SceneTextCheck, NonAsciiInStringsAndCommentsIsAllowed) {
  EXPECT_EQ(error_of("title = \"Ramírez, Pöschel: ε(ζ)\"  # ζ = β v^{1/5}\n"), "");
  EXPECT_EQ(error_of("note = 'literal ε'\n"), "");
  EXPECT_EQ(error_of("note = \"\"\"\nmulti ε \"quoted\" ζ\n\"\"\"\nx = 1\n"), "");
  EXPECT_EQ(error_of("note = '''\nmulti ε\n'''\n"), "");
  EXPECT_EQ(error_of("note = \"\"\"a\\\n   b ε\"\"\"\n"), "");  // line-ending backslash, then ASCII
  EXPECT_EQ(error_of("note = \"escaped \\\" quote ε\"\n"), "");
  EXPECT_EQ(error_of("\xEF\xBB\xBFtitle = \"with a byte-order mark\"\n"), "");
}

TEST(SceneTextCheck, NonAsciiWhereTomlTestsForWhitespaceIsRefusedWithItsLine) {
  EXPECT_EQ(error_of("a = 1\nb = 2\xEF\xBF\xBD\n"),
            "s.toml:2: non-ASCII character outside a string or comment");
  EXPECT_EQ(error_of("é = 1\n"), "s.toml:1: non-ASCII character outside a string or comment");
  EXPECT_EQ(error_of("a = \"x\" ε\n"), "s.toml:1: non-ASCII character outside a string or comment");
  // The fuzzer's input: U+FEFD where toml++ skips whitespace.
  EXPECT_NE(error_of("a = [1,\xEF\xBB\xBD 2]\n").find("s.toml:1: non-ASCII"), std::string::npos);
  EXPECT_NE(error_of("n = \"\"\"x\\\n\n  ε\"\"\"\n").find("s.toml:3: non-ASCII character after a backslash"),
            std::string::npos);
  EXPECT_NE(error_of("n = \"\"\"x\\ε\"\"\"\n").find("after a backslash"), std::string::npos);
}

TEST(SceneTextCheck, InvalidUtf8IsRefusedWithItsLine) {
  EXPECT_EQ(error_of("a = 1\n# \xC3\x28\n"), "s.toml:2: not valid UTF-8 text");
  EXPECT_EQ(error_of("t = \"\xED\xA0\x80\"\n"), "s.toml:1: not valid UTF-8 text");  // a surrogate
  EXPECT_EQ(error_of("t = \"\xC0\xAF\"\n"), "s.toml:1: not valid UTF-8 text");      // overlong
}

TEST(SceneTextCheck, ParseSceneAppliesIt) {
  EXPECT_THROW(parse_scene("title = \"x\"\nδ = 1\n", "scene.toml"), InvalidInput);
  try {
    parse_scene("title = \"x\"\nδ = 1\n", "scene.toml");
  } catch (const InvalidInput& e) {
    EXPECT_EQ(std::string(e.what()), "scene.toml:2: non-ASCII character outside a string or comment");
  }
}

}  // namespace
}  // namespace restitution::scene
