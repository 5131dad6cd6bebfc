#pragma once
// A minimal streaming JSON writer for the command-line contract: numbers with 17 significant digits
// (non-finite numbers as null), strings escaped, objects and arrays nested. Writes to a std::string.
#include <string>
#include <string_view>
#include <vector>

namespace restitution::cli {

class JsonWriter {
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
  template <typename T>
  JsonWriter& field(std::string_view name, const T& v) {
    key(name);
    return value(v);
  }
  [[nodiscard]] const std::string& str() const { return out_; }

 private:
  void separate();
  void write_string(std::string_view text);
  std::string out_;
  std::vector<bool> first_in_scope_;
  bool after_key_ = false;
};

}  // namespace restitution::cli
