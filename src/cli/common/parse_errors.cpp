// SPDX-License-Identifier: BSD-3-Clause
#include "cli/common/parse_errors.hpp"

#include <fmt/core.h>
#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <string_view>

namespace restitution::cli {
namespace {

// The option called `name` ("--zeta") in the app or any of its subcommands, or null.
const CLI::Option* find_option(const CLI::App& app, const std::string& name) {
  for (const CLI::Option* option : app.get_options()) {
    if (option->check_name(name)) return option;
  }
  for (const CLI::App* sub : app.get_subcommands({})) {
    if (const CLI::Option* option = find_option(*sub, name)) return option;
  }
  return nullptr;
}

std::string expected_value(const CLI::Option* option) {
  if (option == nullptr) return "a valid value";
  // A checked option's type reads "UINT:UINT in [1 - 1024]": its first word is the type.
  std::string type = option->get_type_name();
  type = type.substr(0, type.find_first_of(": "));
  if (type == "FLOAT") return "a number";
  if (type == "UINT") return "a whole number >= 0";
  if (type == "INT") return "a whole number";
  return "a valid " + type;
}

std::string describe(const CLI::App& app, const std::string& message);

// number_problem of `text`, or of each item of a comma-separated list (options typed "FLOAT[,...]").
std::string number_text_problem(const std::string& text, bool list) {
  if (text.find_first_not_of(" \t") == std::string::npos) return "the value is empty, expected a number";
  if (!list) return number_problem(text);
  for (std::size_t start = 0; start <= text.size();) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    std::string problem = number_problem(text.substr(start, comma - start));
    if (!problem.empty()) return problem;
    start = comma + 1;
  }
  return "";
}

}  // namespace

std::string number_problem(const std::string& text) {
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(text.c_str(), &end);
  if (errno == ERANGE && std::isinf(value)) {
    return fmt::format(
        "'{}' is beyond the range of a double (magnitude at most 1.8e308): not a finite number", text);
  }
  // strtod reports ERANGE with 0 only for a nonzero number below the smallest subnormal (4.9e-324): run as
  // 0 it would answer another question than the one typed.
  if (errno == ERANGE && value == 0.0) {
    return fmt::format(
        "'{}' is nonzero but below the smallest double (4.9e-324): it would be read as 0; write 0 if 0 is "
        "meant",
        text);
  }
  return "";  // not a number at all is CLI11's conversion error, described below
}

void check_number_texts(CLI::App& app) {
  for (CLI::Option* option : app.get_options()) {
    const std::string type = option->get_type_name();
    if (type.rfind("FLOAT", 0) == 0) {
      const bool list = type.find(',') != std::string::npos;
      // No description: --help is unchanged.
      option->check(
          CLI::Validator([list](std::string& text) { return number_text_problem(text, list); }, ""));
    }
  }
  for (CLI::App* sub : app.get_subcommands({})) check_number_texts(*sub);
}

std::string one_line(std::string message) {
  for (char& c : message) {
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '?';
  }
  return message;
}

std::string describe_parse_error(const CLI::App& app, const CLI::ParseError& error) {
  return one_line(describe(app, error.what()));
}

namespace {

// The subcommand that was being parsed (`series eval`'s `eval`), or the app itself.
const CLI::App& chosen_command(const CLI::App& app) {
  for (const CLI::App* sub : app.get_subcommands()) return chosen_command(*sub);
  return app;
}

// "restitution eps" for the chosen command.
std::string command_path(const CLI::App& command) {
  const CLI::App* parent = command.get_parent();
  return parent == nullptr ? command.get_name() : command_path(*parent) + " " + command.get_name();
}

// CLI11: "The following arguments were not expected: 1 --eps": say instead what the command takes.
std::string describe_unexpected(const CLI::App& app, const std::string& arguments) {
  const CLI::App& command = chosen_command(app);
  std::vector<std::string> names;
  std::vector<std::string> positionals;
  for (const CLI::Option* option : command.get_options()) {
    // Hidden options (old spellings) stay unmentioned, as in --help.
    if (option->get_group().empty() || option->get_name() == "--help") continue;
    (option->nonpositional() ? names : positionals).push_back(option->get_name());
  }
  std::string takes = names.empty() ? std::string("no options") : fmt::format("{}", fmt::join(names, ", "));
  if (!positionals.empty()) takes += fmt::format(" and the argument {}", fmt::join(positionals, ", "));
  const std::string path = command_path(command);
  return fmt::format("{} does not take '{}': it takes {} ({} --help says what each means)", path, arguments,
                     takes, path);
}

std::string describe(const CLI::App& app, const std::string& message) {
  for (const std::string_view extras :
       {"The following argument was not expected: ", "The following arguments were not expected: "}) {
    if (message.rfind(extras, 0) != 0) continue;
    // CLI11 lists them last first: the command's own list is in the order typed.
    const std::vector<std::string> typed = chosen_command(app).remaining();
    return describe_unexpected(
        app, typed.empty() ? message.substr(extras.size()) : fmt::format("{}", fmt::join(typed, " ")));
  }
  // CLI11: "Could not convert: --zeta = abc" for a value of the wrong type.
  constexpr std::string_view kConversion = "Could not convert: ";
  if (message.rfind(kConversion, 0) == 0) {
    const std::size_t equals = message.find(" = ", kConversion.size());
    if (equals != std::string::npos) {
      const std::string name = message.substr(kConversion.size(), equals - kConversion.size());
      const std::string value = message.substr(equals + 3);
      return fmt::format("{} expects {}, got '{}'", name, expected_value(find_option(app, name)), value);
    }
  }
  // CLI11: "--zeta: 1 required FLOAT missing" for an option given without its value.
  const std::size_t colon = message.find(": ");
  if (colon != std::string::npos && message.rfind("--", 0) == 0) {
    const std::string name = message.substr(0, colon);
    const std::string rest = message.substr(colon + 2);
    if (rest.find("required") != std::string::npos && rest.find("missing") != std::string::npos) {
      return fmt::format("{} needs a value: {}", name, expected_value(find_option(app, name)));
    }
    // CLI11: "--zeta: At Most 1 required but received 2" for an option repeated.
    if (rest.rfind("At Most 1 required", 0) == 0) return fmt::format("{} is given more than once", name);
  }
  return message;
}

}  // namespace
}  // namespace restitution::cli
