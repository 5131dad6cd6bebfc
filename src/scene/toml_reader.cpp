// SPDX-License-Identifier: BSD-3-Clause
#include "scene/toml_reader.hpp"

#include <fmt/core.h>

#include <cmath>

#include "restitution/errors.hpp"
#include "restitution/sweep.hpp"

namespace restitution::scene::detail {
namespace {

constexpr long kMaxPoints = 1000000;

std::optional<double> as_number(const toml::node& node) {
  if (const auto* f = node.as_floating_point()) return f->get();
  if (const auto* i = node.as_integer()) return static_cast<double>(i->get());
  return std::nullopt;
}

}  // namespace

TomlReader::TomlReader(const toml::table& table, std::string path, std::string_view file_name)
    : table_(table), path_(std::move(path)), file_name_(file_name) {}

int TomlReader::line() const {
  return static_cast<int>(table_.source().begin.line);
}

int TomlReader::line_of(std::string_view key) const {
  for (const auto& [k, v] : table_) {
    if (k.str() == key)
      return static_cast<int>(k.source().begin.line != 0 ? k.source().begin.line : v.source().begin.line);
  }
  return line();
}

bool TomlReader::has(std::string_view key) const {
  return table_.contains(key);
}

const toml::node* TomlReader::take(std::string_view key) {
  const toml::node* node = table_.get(key);
  if (node != nullptr) used_.emplace(key);
  return node;
}

std::string TomlReader::child_path(std::string_view key) const {
  return path_.empty() ? std::string(key) : fmt::format("{}.{}", path_, key);
}

void TomlReader::fail_at(int at_line, std::string_view key, std::string_view message) const {
  const std::string where = key.empty() ? (path_.empty() ? std::string("scene") : path_) : child_path(key);
  throw InvalidInput(fmt::format("{}:{}: {}: {}", file_name_, at_line, where, message));
}

void TomlReader::fail(std::string_view key, std::string_view message) const {
  fail_at(key.empty() ? line() : line_of(key), key, message);
}

std::optional<double> TomlReader::number(std::string_view key) {
  const toml::node* node = take(key);
  if (node == nullptr) return std::nullopt;
  const auto value = as_number(*node);
  if (!value) fail(key, "expected a number");
  if (!std::isfinite(*value)) fail(key, "expected a finite number");
  return value;
}

std::optional<std::string> TomlReader::text(std::string_view key) {
  const toml::node* node = take(key);
  if (node == nullptr) return std::nullopt;
  const auto* s = node->as_string();
  if (s == nullptr) fail(key, "expected a string");
  return s->get();
}

std::optional<bool> TomlReader::flag(std::string_view key) {
  const toml::node* node = take(key);
  if (node == nullptr) return std::nullopt;
  const auto* b = node->as_boolean();
  if (b == nullptr) fail(key, "expected true or false");
  return b->get();
}

std::optional<std::vector<double>> TomlReader::numbers(std::string_view key) {
  const toml::node* node = take(key);
  if (node == nullptr) return std::nullopt;
  std::vector<double> values;
  if (const auto* list = node->as_array()) {
    for (const toml::node& item : *list) {
      const auto value = as_number(item);
      if (!value || !std::isfinite(*value)) fail(key, "expected a list of finite numbers");
      values.push_back(*value);
    }
    if (values.empty()) fail(key, "the list is empty");
    return values;
  }
  if (const auto* range = node->as_table()) {
    TomlReader r(*range, child_path(key), file_name_);
    const auto from = r.number("from");
    const auto to = r.number("to");
    const auto points = r.number("points");
    const std::string spacing = r.text("spacing").value_or("linear");
    r.finish();
    if (!from || !to || !points) fail(key, "a range needs from, to and points");
    if (*points != std::floor(*points) || *points < 1 || *points > kMaxPoints) {
      r.fail("points", fmt::format("expected a whole number in [1, {}]", kMaxPoints));
    }
    if (spacing != "linear" && spacing != "log") r.fail("spacing", R"(expected "linear" or "log")");
    if (*to < *from) r.fail("to", "must be >= from");
    const bool log = spacing == "log";
    if (log && *from <= 0.0) r.fail("from", "must be > 0 for spacing = \"log\"");
    const auto n = static_cast<long>(*points);
    if (n == 1 && *to != *from) r.fail("points", "one point needs from = to");
    // A linear range is the command line's grid (oblique --angle-range), point for point.
    if (!log) return evenly_spaced(*from, *to, static_cast<std::size_t>(n));
    for (long i = 0; i < n; ++i) {
      const double s = n == 1 ? 0.0 : static_cast<double>(i) / static_cast<double>(n - 1);
      // The ends are the numbers the user wrote (exp(log(0.01)) is 0.010000000000000004).
      values.push_back(i == n - 1 ? *to
                       : i == 0   ? *from
                                  : std::exp(std::log(*from) + s * (std::log(*to) - std::log(*from))));
    }
    return values;
  }
  if (const auto value = as_number(*node)) {
    if (!std::isfinite(*value)) fail(key, "expected a finite number");
    return std::vector<double>{*value};
  }
  fail(key, "expected a number, a list of numbers or a range { from, to, points, spacing }");
}

std::optional<std::vector<std::string>> TomlReader::words(std::string_view key) {
  const toml::node* node = take(key);
  if (node == nullptr) return std::nullopt;
  if (const auto* s = node->as_string()) return std::vector<std::string>{s->get()};
  const auto* list = node->as_array();
  if (list == nullptr) fail(key, "expected a string or a list of strings");
  std::vector<std::string> out;
  for (const toml::node& item : *list) {
    const auto* s = item.as_string();
    if (s == nullptr) fail(key, "expected a list of strings");
    out.push_back(s->get());
  }
  return out;
}

const toml::table* TomlReader::table(std::string_view key) {
  const toml::node* node = take(key);
  if (node == nullptr) return nullptr;
  const auto* t = node->as_table();
  if (t == nullptr) fail(key, "expected a table");
  return t;
}

const toml::array* TomlReader::array_of_tables(std::string_view key) {
  const toml::node* node = take(key);
  if (node == nullptr) return nullptr;
  const auto* a = node->as_array();
  if (a == nullptr || !a->is_array_of_tables()) fail(key, fmt::format("expected [[{}]] tables", key));
  return a;
}

void TomlReader::check_each(std::string_view key, const std::vector<double>& values,
                            const std::function<bool(double)>& valid, std::string_view expected) const {
  for (const double v : values) {
    if (!valid(v)) fail(key, fmt::format("expected {}, got {}", expected, v));
  }
}

void TomlReader::finish() const {
  for (const auto& [k, v] : table_) {
    if (used_.find(k.str()) == used_.end()) {
      fail_at(static_cast<int>(k.source().begin.line), k.str(), "unknown key");
    }
  }
}

namespace {

// The literal that starts at (line, column), 1-based, of `text`.
std::string_view literal_at(std::string_view text, std::size_t line, std::size_t column) {
  std::size_t at = 0;
  for (std::size_t l = 1; l < line && at != std::string_view::npos; ++l) {
    at = text.find('\n', at);
    if (at != std::string_view::npos) ++at;
  }
  if (at == std::string_view::npos || column == 0 || at + column - 1 >= text.size()) return {};
  const std::string_view rest = text.substr(at + column - 1);
  return rest.substr(0, rest.find_first_not_of("0123456789+-._eE"));
}

// A decimal float literal with a nonzero digit before its exponent.
bool nonzero_literal(std::string_view literal) {
  const std::string_view mantissa = literal.substr(0, literal.find_first_of("eE"));
  return mantissa.find_first_of("123456789") != std::string_view::npos;
}

void check_floats(const toml::node& node, std::string_view text, std::string_view file_name) {
  if (const auto* table = node.as_table()) {
    for (const auto& [key, value] : *table) check_floats(value, text, file_name);
  } else if (const auto* array = node.as_array()) {
    for (const toml::node& item : *array) check_floats(item, text, file_name);
  } else if (const auto* number = node.as_floating_point(); number != nullptr && number->get() == 0.0) {
    const toml::source_position at = node.source().begin;
    const std::string_view literal = literal_at(text, at.line, at.column);
    if (nonzero_literal(literal)) {
      throw InvalidInput(fmt::format(
          "{}:{}: '{}' is nonzero but below the smallest double (4.9e-324): it would be read as 0; write 0 "
          "if 0 is meant",
          file_name, at.line, literal));
    }
  }
}

}  // namespace

void refuse_underflowing_floats(const toml::table& root, std::string_view text, std::string_view file_name) {
  check_floats(root, text, file_name);
}

}  // namespace restitution::scene::detail
