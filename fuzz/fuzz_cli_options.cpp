// SPDX-License-Identifier: BSD-3-Clause
// libFuzzer target: the command-line parsing of every subcommand. The input is the argument list, one
// argument per NUL-separated piece. Parsing must end in success or a CLI11 parse error whose message, as
// the program prints it, is one non-empty line; anything else (a crash, another exception, a sanitizer
// report) is a finding. The chosen action is not run: that would solve collisions and write files.
#include <CLI/CLI.hpp>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "cli/common/commands.hpp"
#include "cli/common/parse_errors.hpp"

namespace {

std::vector<std::string> arguments_of(const std::uint8_t* data, std::size_t size) {
  std::vector<std::string> arguments{"restitution"};
  std::string current;
  for (std::size_t i = 0; i < size; ++i) {
    if (data[i] == 0) {
      arguments.push_back(current);
      current.clear();
    } else {
      current += static_cast<char>(data[i]);
    }
  }
  if (!current.empty()) arguments.push_back(current);
  return arguments;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 4096) return -1;  // command lines, not files
  using namespace restitution;
  std::vector<std::string> arguments = arguments_of(data, size);
  std::vector<char*> argv;
  for (std::string& a : arguments) argv.push_back(a.data());

  CLI::App app{"restitution", "restitution"};
  app.require_subcommand(1);
  cli::Action chosen;
  cli::add_all_commands(app, chosen);
  try {
    app.parse(static_cast<int>(argv.size()), argv.data());
  } catch (const CLI::ParseError& e) {
    const std::string message = cli::describe_parse_error(app, e);
    if (message.empty() || message.find('\n') != std::string::npos) std::abort();
  }
  return 0;
}
