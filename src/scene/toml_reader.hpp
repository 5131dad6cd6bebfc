// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Strict reading of one TOML table for the scene parser: every read marks its key as used, finish() rejects
// the keys nobody read, and every error names the file, the line and the key (toml++ source positions).
#include <functional>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

// toml++ 3.3.0's internal checks (TOML_ASSERT_ASSUME) fail on some malformed input before its parser reports
// the error itself: four sites found by fuzz/fuzz_scene.cpp (inputs in fuzz/findings/toml-assert-*). As an
// assert they abort the sanitizer and fuzz builds; under NDEBUG they become __builtin_assume with clang,
// i.e. undefined behaviour. Compiled out here, for every compiler and build type, toml++ runs as Debian's
// g++ release build of it does (GCC 12 has no __builtin_assume) and goes on to a clean parse error, on the
// same path that ASan and UBSan watch in CI. This is the only place toml++ is included.
#pragma push_macro("NDEBUG")
#undef NDEBUG
#define TOML_ASSERT(expr) static_cast<void>(0)
#define TOML_ENABLE_FORMATTERS 0
#include <toml++/toml.h>
#pragma pop_macro("NDEBUG")

namespace restitution::scene::detail {

class TomlReader {
 public:
  // path: how the table is named in messages ("" for the root, "sweep[2]", "materials.rubber").
  TomlReader(const toml::table& table, std::string path, std::string_view file_name);

  [[nodiscard]] int line() const;
  [[nodiscard]] int line_of(std::string_view key) const;
  [[nodiscard]] bool has(std::string_view key) const;
  // Marks the key as read and returns its node (nullptr when absent).
  const toml::node* take(std::string_view key);

  std::optional<double> number(std::string_view key);
  std::optional<std::string> text(std::string_view key);
  std::optional<bool> flag(std::string_view key);
  // A list of numbers, or a range { from, to, points, spacing = "linear" | "log" }.
  std::optional<std::vector<double>> numbers(std::string_view key);
  // One string or a list of strings.
  std::optional<std::vector<std::string>> words(std::string_view key);
  const toml::table* table(std::string_view key);
  const toml::array* array_of_tables(std::string_view key);

  // Throws InvalidInput "file:line: path.key: message" at the key's line (the table's when absent).
  [[noreturn]] void fail(std::string_view key, std::string_view message) const;
  // Checks each value with `valid`; on failure names the key and what was expected.
  void check_each(std::string_view key, const std::vector<double>& values,
                  const std::function<bool(double)>& valid, std::string_view expected) const;
  // Rejects every key that was not read.
  void finish() const;

  [[nodiscard]] std::string child_path(std::string_view key) const;
  // How messages name the table ("sweep[2]"): for a step after the parser that names the section as it does.
  [[nodiscard]] const std::string& path() const { return path_; }
  [[nodiscard]] std::string_view file_name() const { return file_name_; }

 private:
  [[noreturn]] void fail_at(int line, std::string_view key, std::string_view message) const;
  const toml::table& table_;
  std::string path_;
  std::string file_name_;
  std::set<std::string, std::less<>> used_;
};

// Throws InvalidInput "FILE:LINE: '1e-400' is nonzero but below the smallest double ..." for a float of
// `root` that toml++ read as 0 from a nonzero literal (it rounds an underflow to 0 without a word). `text` is
// the text `root` was parsed from (ASCII: toml++'s columns are its bytes).
void refuse_underflowing_floats(const toml::table& root, std::string_view text, std::string_view file_name);

}  // namespace restitution::scene::detail
