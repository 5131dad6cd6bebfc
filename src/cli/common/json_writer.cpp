// SPDX-License-Identifier: BSD-3-Clause
#include "cli/common/json_writer.hpp"

#include <cmath>
#include <stdexcept>
#include <utility>

namespace restitution::cli {

nlohmann::ordered_json& JsonWriter::put(nlohmann::ordered_json value) {
  if (open_.empty()) {
    document_ = std::move(value);
    return document_;
  }
  nlohmann::ordered_json& scope = *open_.back();
  if (scope.is_object()) {
    if (!key_) throw std::logic_error("JsonWriter: a value in an object needs a key first");
    nlohmann::ordered_json& slot = scope[*key_];
    key_.reset();
    slot = std::move(value);
    return slot;
  }
  scope.push_back(std::move(value));
  return scope.back();
}

void JsonWriter::close() {
  if (open_.empty()) throw std::logic_error("JsonWriter: nothing open to close");
  open_.pop_back();
}

JsonWriter& JsonWriter::begin_object() {
  open_.push_back(&put(nlohmann::ordered_json::object()));
  return *this;
}

JsonWriter& JsonWriter::end_object() {
  close();
  return *this;
}

JsonWriter& JsonWriter::begin_array() {
  open_.push_back(&put(nlohmann::ordered_json::array()));
  return *this;
}

JsonWriter& JsonWriter::end_array() {
  close();
  return *this;
}

JsonWriter& JsonWriter::key(std::string_view name) {
  key_ = std::string(name);
  return *this;
}

JsonWriter& JsonWriter::value(double number) {
  // nlohmann writes non-finite numbers as null too; said here so that the contract does not hang on it.
  put(std::isfinite(number) ? nlohmann::ordered_json(number) : nlohmann::ordered_json(nullptr));
  return *this;
}

JsonWriter& JsonWriter::value(long number) {
  put(number);
  return *this;
}

JsonWriter& JsonWriter::value(bool flag) {
  put(flag);
  return *this;
}

JsonWriter& JsonWriter::null() {
  put(nullptr);
  return *this;
}

JsonWriter& JsonWriter::value(std::string_view text) {
  put(std::string(text));
  return *this;
}

JsonWriter& JsonWriter::value(const std::vector<std::string>& texts) {
  begin_array();
  for (const std::string& text : texts) value(text);
  return end_array();
}

JsonWriter& JsonWriter::value(const std::vector<double>& numbers) {
  begin_array();
  for (const double number : numbers) value(number);
  return end_array();
}

std::string JsonWriter::str() const {
  // Text that is not valid UTF-8 (a file name, say) is written with replacement characters, not refused.
  return document_.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
}

}  // namespace restitution::cli
