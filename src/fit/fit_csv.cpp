// SPDX-License-Identifier: BSD-3-Clause
// The fit CSV reader (restitution/fit.hpp): a byte-by-byte RFC 4180 record reader that holds one record
// at a time, so memory is the numbers (24 bytes a row), not the text, and every bound is checked as the bytes
// arrive.
#include "restitution/fit.hpp"

#include <fmt/core.h>
#include <sys/stat.h>
#include <sys/vfs.h>

#include <charconv>
#include <cmath>
#include <fstream>
#include <istream>
#include <optional>
#include <sstream>
#include <vector>

#include "fit/fit_csv_columns.hpp"
#include "restitution/errors.hpp"

namespace restitution {
namespace {

constexpr std::size_t kExcerptLength = 40;

struct Field {
  std::string text;
  int line = 0;
  int column = 0;
};

// Records of a CSV file: fields split at commas outside quotes, "" inside quotes read as one quote, blanks
// around a field dropped, CR, LF and CRLF all ending a line, blank and '#' lines skipped.
class RecordReader {
 public:
  RecordReader(std::istream& in, std::string name, const FitCsvLimits& limits)
      : in_(*in.rdbuf()), name_(std::move(name)), limits_(limits) {
    // A spreadsheet's UTF-8 byte-order mark before the header is not part of the first column's name.
    for (const int expected : {0xEF, 0xBB, 0xBF}) {
      const int c = raw();
      if (c == std::char_traits<char>::eof()) break;
      pending_.push_back(c);
      if (c != expected) break;
    }
    if (pending_ == std::vector<int>{0xEF, 0xBB, 0xBF}) pending_.clear();
  }

  [[nodiscard]] const std::string& name() const { return name_; }

  // The next record, false at the end of the file.
  bool next(std::vector<Field>& fields) {
    while (true) {
      fields.clear();
      int c = skip_blanks(get());
      if (c == kEnd) return false;
      if (c == '\n') continue;
      if (c == '#') {
        while (c != '\n' && c != kEnd) c = get();
        continue;
      }
      while (true) {
        Field field{"", line_, column_};
        c = c == '"' ? quoted(field) : unquoted(field, c);
        fields.push_back(std::move(field));
        if (c != ',') return true;  // the end of the line or of the file
        c = skip_blanks(get());
      }
    }
  }

  [[noreturn]] void fail(int line, int column, const std::string& what) const {
    throw InvalidInput(fmt::format("{}:{}:{}: {}", name_, line, column, what));
  }

 private:
  static constexpr int kEnd = std::char_traits<char>::eof();

  int raw() {
    const int c = in_.sbumpc();
    if (c == kEnd) return c;
    if (++bytes_ > limits_.max_bytes) {
      throw InvalidInput(fmt::format("{}:{}: longer than {} bytes, the bound of a fit CSV (docs/fit.md)",
                                     name_, line_, limits_.max_bytes));
    }
    return c;
  }

  // The next byte, every line end as '\n'; counts lines and columns and bounds the line's length.
  int get() {
    int c = kEnd;
    if (next_ < pending_.size()) {
      c = pending_[next_++];
    } else {
      c = raw();
    }
    if (c == kEnd) return c;
    if (at_line_start_) {
      ++line_;
      column_ = 0;
      at_line_start_ = false;
    }
    ++column_;
    if (static_cast<std::size_t>(column_) > limits_.max_line_bytes) {
      throw InvalidInput(
          fmt::format("{}:{}: the line is longer than {} bytes, the bound of a fit CSV (docs/fit.md)", name_,
                      line_, limits_.max_line_bytes));
    }
    if (c == '\r') {
      if (in_.sgetc() == '\n') raw();
      c = '\n';
    }
    if (c == '\n') at_line_start_ = true;
    return c;
  }

  int skip_blanks(int c) {
    while (c == ' ' || c == '\t') c = get();
    return c;
  }

  void append(Field& field, int c) const {
    if (field.text.size() >= limits_.max_line_bytes) {
      fail(field.line, field.column,
           fmt::format("a field longer than {} bytes, the bound of a fit CSV", limits_.max_line_bytes));
    }
    field.text += static_cast<char>(c);
  }

  // After the opening quote: returns the byte after the field (',', '\n' or the end).
  int quoted(Field& field) {
    while (true) {
      int c = get();
      if (c == kEnd) fail(field.line, field.column, "a quote opened here is never closed");
      if (c == '"') {
        c = get();
        if (c != '"') {
          c = skip_blanks(c);
          if (c != ',' && c != '\n' && c != kEnd) {
            fail(line_, column_,
                 "text after the closing quote of a field (double a quote inside quotes: \"\")");
          }
          return c;
        }
      }
      append(field, c);
    }
  }

  int unquoted(Field& field, int c) {
    while (c != ',' && c != '\n' && c != kEnd) {
      if (c == '"') fail(line_, column_, "a quote inside an unquoted field (quote the whole field)");
      append(field, c);
      c = get();
    }
    while (!field.text.empty() && (field.text.back() == ' ' || field.text.back() == '\t'))
      field.text.pop_back();
    return c;
  }

  std::streambuf& in_;
  std::string name_;
  FitCsvLimits limits_;
  std::vector<int> pending_;
  std::size_t next_ = 0;
  std::size_t bytes_ = 0;
  int line_ = 0;
  int column_ = 0;
  bool at_line_start_ = true;
};

// Order of magnitude of a decimal literal (the exponent of its first nonzero digit): tells an overflow from
// an underflow. `text` is a valid literal with a nonzero digit.
long decimal_magnitude(std::string_view text) {
  const auto e = text.find_first_of("eE");
  const std::string_view mantissa = text.substr(0, e);
  long exponent = 0;
  if (e != std::string_view::npos) {
    std::string_view digits = text.substr(e + 1);
    if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
    // An exponent beyond long is far beyond a double's range either way: its sign is what matters.
    if (std::from_chars(digits.data(), digits.data() + digits.size(), exponent).ec != std::errc{}) {
      exponent = digits.front() == '-' ? -100000 : 100000;
    }
  }
  const auto point = mantissa.find('.');
  const auto integer_end = point == std::string_view::npos ? mantissa.size() : point;
  const auto first = mantissa.find_first_of("123456789");
  const long position = first < integer_end ? static_cast<long>(integer_end - first) - 1
                                            : -static_cast<long>(first - integer_end);
  return exponent + position;
}

bool is_digit(char c) {
  return c >= '0' && c <= '9';
}

// A decimal number: [+-]digits[.digits][(e|E)[+-]digits], at least one digit before the exponent. No hex,
// no inf, no nan. Returns the message when it is not one, or is one beyond the range of a double.
std::optional<std::string> decimal_number(std::string_view text, double& value) {
  std::size_t i = 0;
  const auto digits = [&] {
    const std::size_t start = i;
    while (i < text.size() && is_digit(text[i])) ++i;
    return i - start;
  };
  if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
  const std::size_t sign = i;
  std::size_t mantissa_digits = digits();
  if (i < text.size() && text[i] == '.') {
    ++i;
    mantissa_digits += digits();
  }
  bool valid = mantissa_digits > 0;
  if (valid && i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    ++i;
    if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
    valid = digits() > 0;
  }
  if (!valid || i != text.size()) {
    return text.empty() ? std::string("empty, expected a decimal number")
                        : fmt::format("'{}' is not a decimal number", quoted_excerpt(text));
  }
  const std::string_view body = text.substr(text[0] == '+' ? 1 : 0);
  const auto [end, error] = std::from_chars(body.data(), body.data() + body.size(), value);
  const bool nonzero = text.substr(sign).find_first_of("123456789") < text.substr(sign).find_first_of("eE");
  if (error == std::errc::result_out_of_range || (nonzero && value == 0.0) || std::isinf(value)) {
    return fmt::format("'{}' is {} the range of a double", quoted_excerpt(text),
                       decimal_magnitude(text.substr(sign)) < 0 ? "below" : "beyond");
  }
  if (error != std::errc{} || end != body.data() + body.size()) {
    return fmt::format("'{}' is not a decimal number", quoted_excerpt(text));
  }
  return std::nullopt;
}

class RowReader {
 public:
  RowReader(RecordReader& records, const fit_detail::FitColumns& columns, const std::vector<Field>& header)
      : records_(records), columns_(columns), header_(header) {}

  [[nodiscard]] double number(const std::vector<Field>& row, std::size_t at) const {
    double value = 0.0;
    if (const auto problem = decimal_number(row[at].text, value)) fail(row[at], at, *problem);
    return value;
  }

  [[noreturn]] void fail(const Field& field, std::size_t at, const std::string& what) const {
    records_.fail(field.line, field.column,
                  fmt::format("column '{}': {}", quoted_excerpt(header_[at].text), what));
  }

  void add(const std::vector<Field>& row, FitData& data) const {
    const Field& first = row.front();
    if (row.size() != columns_.width) {
      records_.fail(first.line, first.column,
                    fmt::format("{} field{}, the header names {}", row.size(), row.size() == 1 ? "" : "s",
                                columns_.width));
    }
    const double v = number(row, columns_.speed);
    if (v <= 0.0) {
      fail(row[columns_.speed], columns_.speed, fmt::format("the speed must be > 0 m/s, got {}", v));
    }
    const double eps = number(row, columns_.eps);
    if (eps <= 0.0 || eps >= 1.0)
      fail(row[columns_.eps], columns_.eps, fmt::format("must be in (0, 1), got {}", eps));
    if (columns_.sigma) {
      const double sigma = number(row, *columns_.sigma);
      if (!(sigma >= kSmallestFitSigma && sigma <= kLargestFitSigma)) {
        fail(row[*columns_.sigma], *columns_.sigma,
             fmt::format("must be in [{:g}, {:g}], got {}", kSmallestFitSigma, kLargestFitSigma, sigma));
      }
      data.sigma.push_back(sigma);
    }
    data.velocity_m_s.push_back(v);
    data.eps.push_back(eps);
  }

 private:
  RecordReader& records_;
  const fit_detail::FitColumns& columns_;
  const std::vector<Field>& header_;
};

bool in_machine_file_system(const std::filesystem::path& path) {
  struct statfs info {};
  if (statfs(path.c_str(), &info) != 0) return false;
  constexpr long kProcMagic = 0x9fa0;
  constexpr long kSysfsMagic = 0x62656572;
  return info.f_type == kProcMagic || info.f_type == kSysfsMagic;
}

}  // namespace

std::string quoted_excerpt(std::string_view text) {
  std::string out;
  for (std::size_t i = 0; i < text.size() && i < kExcerptLength; ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    out += c >= 0x20 && c < 0x7F ? std::string(1, static_cast<char>(c)) : fmt::format("\\x{:02x}", c);
  }
  if (text.size() > kExcerptLength) out += "...";
  return out;
}

FitData parse_fit_csv(std::istream& in, const std::string& name, const FitCsvLimits& limits) {
  RecordReader records(in, name, limits);
  std::vector<Field> header;
  if (!records.next(header))
    throw InvalidInput(fmt::format("{}: empty: no header and no measurements", name));
  std::vector<fit_detail::HeaderField> names;
  names.reserve(header.size());
  for (const Field& f : header) names.push_back({f.text, f.column});
  const fit_detail::FitColumns columns =
      fit_detail::fit_columns(names, fmt::format("{}:{}", name, header.front().line));
  const RowReader rows(records, columns, header);
  FitData data;
  std::vector<Field> row;
  while (records.next(row)) {
    if (data.eps.size() == limits.max_rows) {
      records.fail(
          row.front().line, row.front().column,
          fmt::format("more than {} measurements, the bound of a fit CSV (docs/fit.md)", limits.max_rows));
    }
    rows.add(row, data);
  }
  if (data.eps.empty()) throw InvalidInput(fmt::format("{}: a header but no measurements", name));
  return data;
}

FitData parse_fit_csv(const std::string& text, const std::string& name, const FitCsvLimits& limits) {
  std::istringstream in(text);
  return parse_fit_csv(in, name, limits);
}

FitData read_fit_csv(const std::filesystem::path& path, FitCsvSource source, const FitCsvLimits& limits) {
  const std::string name = path.string();
  std::error_code error;
  const auto status = std::filesystem::status(path, error);
  if (std::filesystem::is_directory(status))
    throw InvalidInput(fmt::format("{}: a folder, not a CSV file", name));
  if (source == FitCsvSource::regular_file && std::filesystem::exists(status)) {
    // Checked before opening: opening a FIFO would wait for a writer.
    if (!std::filesystem::is_regular_file(status) || in_machine_file_system(path)) {
      throw InvalidInput(fmt::format(
          "{}: not a regular file (a device, FIFO, socket or /proc or /sys entry): a scene's data "
          "is a CSV file",
          name));
    }
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InvalidInput(fmt::format("{}: cannot be read", name));
  return parse_fit_csv(in, name, limits);
}

}  // namespace restitution
