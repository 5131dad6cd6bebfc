#include "scene/toml_text_check.hpp"

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
  if (byte < 0x80) {
    return {byte, 1};
  } else if ((byte & 0xE0U) == 0xC0U) {
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

enum class Context { outside, comment, basic, literal, multi_line_basic, multi_line_literal };

bool starts_with(std::string_view text, std::size_t i, std::string_view prefix) {
  return text.substr(i, prefix.size()) == prefix;
}

class TextChecker {
 public:
  TextChecker(std::string_view text, std::string_view file_name) : text_(text), file_(file_name) {}

  void run() {
    // Every code point must decode, wherever it stands.
    for (std::size_t i = 0; i < text_.size();) {
      const CodePoint c = decode(text_, i);
      if (c.length == 0) fail(line_at(i), "not valid UTF-8 text");
      i += c.length;
    }
    std::size_t i = starts_with(text_, 0, "\xEF\xBB\xBF") ? 3 : 0;  // a byte-order mark is allowed first
    while (i < text_.size()) i = step(i);
  }

 private:
  [[noreturn]] void fail(std::size_t line, std::string_view what) const {
    throw InvalidInput(fmt::format("{}:{}: {}", file_, line, what));
  }

  [[nodiscard]] std::size_t line_at(std::size_t end) const {
    std::size_t line = 1;
    for (std::size_t i = 0; i < end; ++i) line += text_[i] == '\n' ? 1 : 0;
    return line;
  }

  [[nodiscard]] bool ascii(std::size_t i) const { return static_cast<unsigned char>(text_[i]) < 0x80; }

  // Consumes one token of the current context starting at i and returns where the next begins.
  std::size_t step(std::size_t i) {
    const char c = text_[i];
    switch (context_) {
      case Context::outside:
        if (!ascii(i)) fail(line_at(i), "non-ASCII character outside a string or comment");
        if (c == '#') context_ = Context::comment;
        if (c == '"') return open(i, "\"\"\"", Context::multi_line_basic, Context::basic);
        if (c == '\'') return open(i, "'''", Context::multi_line_literal, Context::literal);
        return i + 1;
      case Context::comment:
        if (c == '\n') context_ = Context::outside;
        return i + 1;
      case Context::basic:
        if (c == '\\') return i + 2;  // an escape: toml++ reads its letter without a whitespace test
        if (c == '"' || c == '\n') context_ = Context::outside;
        return i + 1;
      case Context::literal:
        if (c == '\'' || c == '\n') context_ = Context::outside;
        return i + 1;
      case Context::multi_line_basic:
        if (c == '\\') return after_backslash(i);
        return close(i, '"');
      case Context::multi_line_literal:
        return close(i, '\'');
    }
    return i + 1;
  }

  std::size_t open(std::size_t i, std::string_view triple, Context multi, Context single) {
    if (starts_with(text_, i, triple)) {
      context_ = multi;
      return i + 3;
    }
    context_ = single;
    return i + 1;
  }

  // A multi-line string ends at a run of three or more quotes (up to two of them belong to the content).
  std::size_t close(std::size_t i, char quote) {
    if (text_[i] != quote) return i + 1;
    std::size_t end = i;
    while (end < text_.size() && text_[end] == quote) ++end;
    if (end - i >= 3) context_ = Context::outside;
    return end;
  }

  // After a backslash toml++ tests the next character for whitespace, and after a line-ending backslash it
  // skips whitespace by testing every character up to the first that is not.
  std::size_t after_backslash(std::size_t i) {
    std::size_t next = i + 1;
    if (next < text_.size() && ascii(next) && text_[next] != ' ' && text_[next] != '\t' &&
        text_[next] != '\r' && text_[next] != '\n') {
      return next + 1;  // an ordinary escape such as \n or \\ .
    }
    while (next < text_.size() &&
           (text_[next] == ' ' || text_[next] == '\t' || text_[next] == '\r' || text_[next] == '\n')) {
      ++next;
    }
    if (next < text_.size() && !ascii(next)) {
      fail(line_at(next),
           "non-ASCII character after a backslash in a multi-line string (escape it as \\uXXXX)");
    }
    return next;
  }

  std::string_view text_;
  std::string_view file_;
  Context context_ = Context::outside;
};

}  // namespace

void check_scene_text(std::string_view text, std::string_view file_name) {
  TextChecker(text, file_name).run();
}

}  // namespace restitution::scene
