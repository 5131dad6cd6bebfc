// SPDX-License-Identifier: BSD-3-Clause
// The rewrite of scene text to ASCII-only TOML that keeps toml++ 3.3.0 away from its undefined behaviour
// on non-ASCII characters: values and line numbers must survive it, its output must be ASCII whatever the
// input, and what it refuses must be refused with the line.
#include "scene/toml_ascii.hpp"

#include <fmt/core.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <iterator>
#include <optional>
#include <random>
#include <string>

#include "cli_runner.hpp"
#include "restitution/errors.hpp"
#include "scene/scene.hpp"
#include "scene/scene_plan.hpp"
#include "scene/scene_sections.hpp"
#include "scene/toml_reader.hpp"

namespace restitution::scene {
namespace {

std::string error_of(std::string_view text) {
  try {
    (void)ascii_toml_text(text, "s.toml");
  } catch (const InvalidInput& e) {
    return e.what();
  }
  return {};
}

bool is_ascii(std::string_view text) {
  return std::all_of(text.begin(), text.end(), [](char c) { return static_cast<unsigned char>(c) < 0x80; });
}

// Parses the rewritten text and returns the string at `key`.
std::string string_value(std::string_view text, std::string_view key) {
  const std::string ascii = ascii_toml_text(text, "s.toml");
  EXPECT_TRUE(is_ascii(ascii)) << ascii;
  const toml::table table = toml::parse(ascii);
  const auto value = table[key].value<std::string>();
  EXPECT_TRUE(value.has_value()) << "no string at " << key << " in " << ascii;
  return value.value_or("");
}

TEST(TomlAscii, NonAsciiTextInStringsKeepsItsValue) {
  EXPECT_EQ(string_value("t = \"Ramírez, Pöschel: ε(ζ)\"\n", "t"), "Ramírez, Pöschel: ε(ζ)");
  EXPECT_EQ(string_value("t = \"four bytes: \xF0\x9F\x98\x80.\"\n", "t"), "four bytes: \xF0\x9F\x98\x80.");
  EXPECT_EQ(string_value("t = \"escaped \\\" quote ε\\n\"\n", "t"), "escaped \" quote ε\n");
  EXPECT_EQ(string_value("t = \"\"\"\nmulti ε \"quoted\" ζ\n\"\"\"\n", "t"), "multi ε \"quoted\" ζ\n");
  // A line-ending backslash followed by a non-ASCII character: the case toml++ itself tests for whitespace.
  EXPECT_EQ(string_value("t = \"\"\"a\\\n\n   ε b\"\"\"\n", "t"), "aε b");
  // TOML's whitespace is space and tab only: a no-break space after a line-ending backslash is content.
  // toml++ 3.3.0 alone trims it (and U+00A1 on would be undefined behaviour); the rewrite restores it.
  EXPECT_EQ(string_value("t = \"\"\"a\\\n\u00A0b\"\"\"\n", "t"), "a\u00A0b");
  EXPECT_EQ(string_value("\"ключ ε\" = \"v\"\n", "ключ ε"), "v");
}

TEST(TomlAscii, LiteralStringsBecomeBasicStringsWithTheSameValue) {
  EXPECT_EQ(string_value("t = 'literal ε'\n", "t"), "literal ε");
  EXPECT_EQ(string_value("t = 'C:\\path\\n \"quoted\" é'\n", "t"), "C:\\path\\n \"quoted\" é");
  EXPECT_EQ(string_value("t = '''\nline ε\\\nnext \"x\" ''two'' '''\n", "t"),
            "line ε\\\nnext \"x\" ''two'' ");
  EXPECT_EQ(string_value("t = '''ends with quotes'''''\n", "t"), "ends with quotes''");
  EXPECT_EQ(string_value("t = '''ends with \"'''\n", "t"), "ends with \"");
  EXPECT_EQ(string_value("'ключ ε' = 'v'\n", "ключ ε"), "v");
}

TEST(TomlAscii, CommentsAndTheByteOrderMarkCarryNoValue) {
  const std::string ascii = ascii_toml_text("\xEF\xBB\xBFt = 1  # ζ = β v^{1/5}\n", "s.toml");
  EXPECT_EQ(ascii, "t = 1  # ? = ? v^{1/5}\n");
}

TEST(TomlAscii, AsciiTextWithoutLiteralStringsIsUnchanged) {
  for (const char* name : {"default", "trajectory", "material_sweep", "calibration", "dashpot", "dem"}) {
    const std::string text =
        test_support::slurp(std::string(RESTITUTION_SOURCE_DIR "/scenes/") + name + ".toml");
    ASSERT_FALSE(text.empty()) << name;
    const std::string ascii = ascii_toml_text(text, name);
    EXPECT_TRUE(is_ascii(ascii)) << name;
    EXPECT_EQ(toml::parse(ascii), toml::parse(text)) << name;
    if (is_ascii(text) && text.find('\'') == std::string::npos) EXPECT_EQ(ascii, text) << name;
  }
}

// Random documents built from the pieces that matter (non-ASCII characters, quotes, backslashes, escapes,
// line breaks, comments; some mutated into malformed text) must parse to the same table before and after the
// rewrite, or fail both times. The characters avoid U+00A0 and the ranges where toml++ 3.3.0 itself
// misbehaves (see NonAsciiTextInStringsKeepsItsValue), so that it can read the original.
std::optional<toml::table> parsed(const std::string& text) {
  try {
    return toml::parse(text);
  } catch (const toml::parse_error&) {
    return std::nullopt;
  }
}

TEST(TomlAscii, RandomDocumentsParseToTheSameTablesOrFailBothTimes) {
  std::mt19937 random(20261122);
  const auto pick = [&random](const auto& list) { return list[random() % std::size(list)]; };
  const char* const characters[] = {"\u0080", "\u4E00", "\uFFFD", "\U0001F600", "\U0010FFFF"};
  const char* const marks[] = {"\\", "\"", "'",    "\\n", "\\\"", "\\u00e9", "\\\\",   " ", "\t", "#",
                               "=",  "\n", "\\\n", "''",  "\"\"", "'''",     "\"\"\"", "a", "b"};
  const auto content = [&](std::size_t length) {
    std::string text;
    for (std::size_t i = 0; i < length; ++i) {
      const auto kind = random() % 6;
      text += kind < 2 ? pick(characters) : kind < 3 ? pick(marks) : "x";
    }
    return text;
  };
  const auto comment = [&] { return std::string(pick(characters)) + "#'\"\\" + pick(characters); };
  const char* const forms[] = {"\"{}\"", "'{}'", "\"\"\"{}\"\"\"", "'''{}'''"};
  int well_formed = 0;
  for (int document = 0; document < 10000; ++document) {
    std::string text = "# " + comment() + "\n";
    for (int line = 0; line < 3; ++line) {
      const std::string key = fmt::format(fmt::runtime(pick(forms)), fmt::format("k{}{}", line, content(1)));
      const std::string value = fmt::format(fmt::runtime(pick(forms)), content(random() % 10));
      text += fmt::format("{} = {}  # {}\n", key, value, comment());
    }
    if (random() % 4 == 0) text.insert(random() % text.size(), content(1));
    const auto before = parsed(text);
    std::string ascii;
    try {
      ascii = ascii_toml_text(text, "s.toml");
    } catch (const InvalidInput&) {
      EXPECT_FALSE(before.has_value()) << "refused, yet toml++ reads it:\n" << text;
      continue;
    }
    const auto after = parsed(ascii);
    ASSERT_EQ(before.has_value(), after.has_value()) << text << "\n--- rewritten ---\n" << ascii;
    if (before) EXPECT_EQ(*before, *after) << text;
    well_formed += before.has_value() ? 1 : 0;
  }
  EXPECT_GT(well_formed, 400);  // enough well-formed documents to have compared values
}

TEST(TomlAscii, MalformedTextComesOutAsciiWithItsLines) {
  const std::string finding =
      test_support::slurp(RESTITUTION_SOURCE_DIR "/fuzz/findings/scene-toml-unreachable-1");
  ASSERT_FALSE(finding.empty());
  for (const std::string& text :
       {finding, std::string("a = 08bb\"0bbbyamír al.\"\nb = 'x\nc = \"é\n"),
        std::string("a = \"x\\\ny = 'é'\n"), std::string("t = '''never closed ε\n\n"),
        std::string("t = \"\"\"x\\ \xCE\xB5\"\"\"\n")}) {
    const std::string ascii = ascii_toml_text(text, "s.toml");
    EXPECT_TRUE(is_ascii(ascii)) << ascii;
    EXPECT_EQ(std::count(ascii.begin(), ascii.end(), '\n'), std::count(text.begin(), text.end(), '\n'));
  }
}

TEST(TomlAscii, WhatCannotBeRewrittenIsRefusedWithItsLine) {
  EXPECT_EQ(error_of("a = 1\nb = 2\xEF\xBF\xBD\n"),
            "s.toml:2: non-ASCII character outside a string or comment");
  EXPECT_EQ(error_of("é = 1\n"), "s.toml:1: non-ASCII character outside a string or comment");
  EXPECT_EQ(error_of("a = [1,\xEF\xBB\xBD 2]\n"),
            "s.toml:1: non-ASCII character outside a string or comment");
  EXPECT_EQ(error_of("n = \"x\\ε\"\n"),
            "s.toml:1: a backslash followed by a non-ASCII character is no TOML escape");
  EXPECT_EQ(error_of("n = \"\"\"\nx\\ε\"\"\"\n"),
            "s.toml:2: a backslash followed by a non-ASCII character is no TOML escape");
  EXPECT_EQ(error_of("n = '''x''''''\n"),
            "s.toml:1: more than five single quotes in a row in a multi-line literal string");
}

TEST(TomlAscii, InvalidUtf8IsRefusedWithItsLine) {
  EXPECT_EQ(error_of("a = 1\n# \xC3\x28\n"), "s.toml:2: not valid UTF-8 text");
  EXPECT_EQ(error_of("t = \"\xED\xA0\x80\"\n"), "s.toml:1: not valid UTF-8 text");      // a surrogate
  EXPECT_EQ(error_of("t = \"\xC0\xAF\"\n"), "s.toml:1: not valid UTF-8 text");          // overlong
  EXPECT_EQ(error_of("t = \"\xF4\x90\x80\x80\"\n"), "s.toml:1: not valid UTF-8 text");  // past U+10FFFF
}

TEST(TomlAscii, ParseSceneUsesIt) {
  try {
    (void)parse_scene("title = \"x\"\nδ = 1\n", "scene.toml");
    ADD_FAILURE() << "a non-ASCII bare key was accepted";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(std::string(e.what()), "scene.toml:2: non-ASCII character outside a string or comment");
  }
  // The fuzzer's seed with non-ASCII text in every kind of string keeps that text in the scene.
  const Scene scene = load_scene(RESTITUTION_SOURCE_DIR "/fuzz/corpus/scene/unicode_strings.toml");
  EXPECT_EQ(scene.title, "Ramírez, Pöschel: ε(ζ) ''quoted'' \"x\" \\\n");
  EXPECT_EQ(scene.output, std::filesystem::path("out/ε literal \\path"));
  const auto sweeps = scene::tasks_of<scene::Sweep>(scene, "sweep");
  ASSERT_EQ(sweeps.size(), 2U);
  EXPECT_EQ(sweeps[0]->note, "multi-line ε \"quoted\" ε ζ continued\n");
  EXPECT_EQ(sweeps[1]->note, "Ramírez — 粒子 \xF0\x9F\x98\x80");
}

// Each input the scene fuzzer found must end in a clean error naming the file, as fuzz/fuzz_scene.cpp asks
// (under the sanitizer build, undefined behaviour on the way aborts the test).
TEST(SceneFuzzFindings, EachEndsInACleanErrorNamingTheFile) {
  int replayed = 0;
  for (const auto& entry : std::filesystem::directory_iterator(RESTITUTION_SOURCE_DIR "/fuzz/findings")) {
    if (entry.path().filename() == "README") continue;
    const std::string text = test_support::slurp(entry.path().string());
    try {
      (void)plan_scene(parse_scene(text, "finding.toml"));
    } catch (const InvalidInput& e) {
      EXPECT_EQ(std::string(e.what()).rfind("finding.toml:", 0), 0U) << e.what();
    }
    ++replayed;
  }
  EXPECT_GE(replayed, 2);
}

}  // namespace
}  // namespace restitution::scene
