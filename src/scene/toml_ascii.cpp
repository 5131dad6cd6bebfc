// SPDX-License-Identifier: BSD-3-Clause
#include "scene/toml_ascii.hpp"

#include <fmt/core.h>

#include "restitution/errors.hpp"

namespace restitution::scene {
namespace {

struct CodePoint {
  char32_t value = 0;
  std::size_t length = 0;  // 0: not valid UTF-8
};

// Strict UTF-8: no overlong forms, surrogates or code points past U+10FFFF.
CodePoint decode(std::string_view text, std::size_t i) {
  const auto byte = static_cast<unsigned char>(text[i]);
  std::size_t length = 0;
  char32_t code = 0;
  if (byte < 0x80) return {byte, 1};
  if ((byte & 0xE0U) == 0xC0U) {
    length = 2;
    code = byte & 0x1FU;
  } else if ((byte & 0xF0U) == 0xE0U) {
    length = 3;
    code = byte & 0x0FU;
  } else if ((byte & 0xF8U) == 0xF0U) {
    length = 4;
    code = byte & 0x07U;
  }
  bool valid = length > 0 && i + length <= text.size();
  for (std::size_t k = 1; valid && k < length; ++k) {
    const auto next = static_cast<unsigned char>(text[i + k]);
    valid = (next & 0xC0U) == 0x80U;
    code = (code << 6U) | (next & 0x3FU);
  }
  constexpr char32_t kSmallest[] = {0, 0, 0x80, 0x800, 0x10000};
  valid = valid && code >= kSmallest[length] && code <= 0x10FFFF && (code < 0xD800 || code > 0xDFFF);
  return valid ? CodePoint{code, length} : CodePoint{};
}

constexpr std::string_view kTripleQuote = R"(""")";

enum class Context { outside, comment, basic, literal, multi_line_basic, multi_line_literal };

bool starts_with(std::string_view text, std::size_t i, std::string_view prefix) {
  return text.substr(i, prefix.size()) == prefix;
}

class AsciiRewriter {
 public:
  AsciiRewriter(std::string_view text, std::string_view file_name) : text_(text), file_(file_name) {}

  std::string run() {
    // Every code point must decode, wherever it stands.
    for (std::size_t i = 0; i < text_.size();) {
      const CodePoint c = decode(text_, i);
      if (c.length == 0) fail(i, "not valid UTF-8 text");
      i += c.length;
    }
    out_.reserve(text_.size() + text_.size() / 4);
    std::size_t i = starts_with(text_, 0, "\xEF\xBB\xBF") ? 3 : 0;  // a byte-order mark is allowed first
    while (i < text_.size()) i = step(i);
    return std::move(out_);
  }

 private:
  [[noreturn]] void fail(std::size_t at, std::string_view what) const {
    std::size_t line = 1;
    for (std::size_t i = 0; i < at; ++i) line += text_[i] == '\n' ? 1 : 0;
    throw InvalidInput(fmt::format("{}:{}: {}", file_, line, what));
  }

  [[nodiscard]] bool ascii(std::size_t i) const { return static_cast<unsigned char>(text_[i]) < 0x80; }

  // Writes the non-ASCII character at i as a TOML escape and returns where the next one begins.
  std::size_t escape(std::size_t i) {
    const CodePoint c = decode(text_, i);
    const auto value = static_cast<unsigned>(c.value);
    out_ += value <= 0xFFFFU ? fmt::format("\\u{:04X}", value) : fmt::format("\\U{:08X}", value);
    return i + c.length;
  }

  std::size_t copy(std::size_t i, std::size_t count = 1) {
    out_.append(text_.substr(i, count));
    return i + count;
  }

  // Consumes one token of the current context starting at i and returns where the next begins.
  std::size_t step(std::size_t i) {
    switch (context_) {
      case Context::outside:
        return outside(i);
      case Context::comment:
        if (text_[i] == '\n') context_ = Context::outside;
        if (ascii(i)) return copy(i);
        out_ += '?';  // comments carry no value; one mark per character keeps them readable
        return i + decode(text_, i).length;
      case Context::basic:
        if (text_[i] == '"' || text_[i] == '\n') context_ = Context::outside;
        return basic_content(i);
      case Context::multi_line_basic:
        if (text_[i] == '"') return close_multi_line(i, '"');
        return basic_content(i);
      case Context::literal:
        if (text_[i] == '\'') {
          context_ = Context::outside;
          out_ += '"';
          return i + 1;
        }
        if (text_[i] == '\n') context_ = Context::outside;  // unterminated: toml++ reports it
        return literal_content(i);
      case Context::multi_line_literal:
        if (text_[i] == '\'') return close_multi_line(i, '\'');
        return literal_content(i);
    }
    return i + 1;
  }

  std::size_t outside(std::size_t i) {
    if (!ascii(i)) fail(i, "non-ASCII character outside a string or comment");
    switch (text_[i]) {
      case '#':
        context_ = Context::comment;
        return copy(i);
      case '"':
        return open(i, kTripleQuote, Context::multi_line_basic, Context::basic);
      case '\'':
        return open(i, "'''", Context::multi_line_literal, Context::literal);
      default:
        return copy(i);
    }
  }

  // Opens a string; literal strings are written as basic strings, so their delimiters become quotes.
  std::size_t open(std::size_t i, std::string_view triple, Context multi, Context single) {
    const bool is_multi = starts_with(text_, i, triple);
    context_ = is_multi ? multi : single;
    out_ += is_multi ? kTripleQuote : "\"";
    return i + (is_multi ? 3 : 1);
  }

  std::size_t basic_content(std::size_t i) {
    if (!ascii(i)) return escape(i);
    // A backslash before a line break is copied alone so the break still ends a single-line string.
    if (text_[i] != '\\' || i + 1 >= text_.size() || text_[i + 1] == '\n') return copy(i);
    if (!ascii(i + 1)) fail(i + 1, "a backslash followed by a non-ASCII character is no TOML escape");
    return copy(i, 2);  // the escape's letter (or the whitespace of a line-ending backslash)
  }

  std::size_t literal_content(std::size_t i) {
    if (!ascii(i)) return escape(i);
    if (text_[i] == '\\' || text_[i] == '"') out_ += '\\';
    return copy(i);
  }

  // A multi-line string ends at a run of three to five quotes, of which all but the last three belong to
  // the content. Longer runs are malformed: refused here for literal strings, whose quotes change, and
  // left to toml++ for basic strings.
  std::size_t close_multi_line(std::size_t i, char quote) {
    std::size_t end = i;
    while (end < text_.size() && text_[end] == quote) ++end;
    const std::size_t run = end - i;
    if (quote == '"' || run < 3) {
      if (run >= 3) context_ = Context::outside;
      out_.append(run, quote);
      return end;
    }
    if (run > 5) fail(i, "more than five single quotes in a row in a multi-line literal string");
    context_ = Context::outside;
    out_.append(run - 3, '\'');
    out_ += kTripleQuote;
    return end;
  }

  std::string_view text_;
  std::string_view file_;
  std::string out_;
  Context context_ = Context::outside;
};

}  // namespace

std::string ascii_toml_text(std::string_view text, std::string_view file_name) {
  return AsciiRewriter(text, file_name).run();
}

}  // namespace restitution::scene
