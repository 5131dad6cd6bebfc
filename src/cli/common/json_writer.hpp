// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The streaming interface the commands use to build their JSON, backed by nlohmann::ordered_json (keys
// stay in the order written). Serialisation is nlohmann's: compact, strings escaped, UTF-8 passed through,
// doubles in the shortest form that reads back to the same double, non-finite numbers as null.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace restitution::cli {

// The implicit destructor is noexcept, yet nlohmann's may allocate: it flattens nested values onto a stack
// to avoid deep recursion. An allocation failure there ends the program, which is what we want.
class JsonWriter {  // NOLINT(bugprone-exception-escape)
 public:
  JsonWriter& begin_object();
  JsonWriter& end_object();
  JsonWriter& begin_array();
  JsonWriter& end_array();
  JsonWriter& key(std::string_view name);
  JsonWriter& value(double number);
  JsonWriter& value(long number);
  JsonWriter& value(int number) { return value(static_cast<long>(number)); }
  JsonWriter& value(bool flag);
  JsonWriter& value(std::string_view text);
  JsonWriter& value(const char* text) { return value(std::string_view(text)); }
  JsonWriter& null();
  // A list as one array of its values, in order.
  JsonWriter& value(const std::vector<std::string>& texts);
  JsonWriter& value(const std::vector<double>& numbers);
  template <typename T>
  JsonWriter& field(std::string_view name, const T& v) {
    key(name);
    return value(v);
  }
  // The document written so far, serialised (compact, one line).
  [[nodiscard]] std::string str() const;

 private:
  // Places a value under the pending key of the innermost open object, or appends it to the innermost open
  // array, or makes it the document; returns where it now lives.
  nlohmann::ordered_json& put(nlohmann::ordered_json value);
  void close();

  nlohmann::ordered_json document_;
  // The open containers, innermost last. A container only grows while it is innermost, so the pointers to
  // its ancestors' elements stay valid.
  std::vector<nlohmann::ordered_json*> open_;
  std::optional<std::string> key_;
};

}  // namespace restitution::cli
