// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Runs the `restitution` executable for end-to-end tests: captures stdout, stderr and the exit status.
#include <sys/wait.h>
#include <unistd.h>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <sstream>
#include <string>
#include <vector>

namespace restitution::test_support {

struct CliOutcome {
  int status = -1;
  std::string out;
  std::string err;
};

inline std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

// The lines of a text, each without its '\n'; a last line without one is left out (a torn row of a file).
inline std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::size_t begin = 0;
  for (std::size_t end; (end = text.find('\n', begin)) != std::string::npos; begin = end + 1)
    lines.push_back(text.substr(begin, end - begin));
  return lines;
}

// The subcommands listed under "Subcommands:" in a --help text.
inline std::vector<std::string> subcommands_in(const std::string& help) {
  std::vector<std::string> names;
  bool listing = false;
  for (const std::string& line : lines_of(help)) {
    if (line.rfind("Subcommands:", 0) == 0) {
      listing = true;
    } else if (listing && line.size() > 2 && line[0] == ' ' && line[2] != ' ') {
      names.push_back(line.substr(2, line.find(' ', 2) - 2));
    } else if (listing && (line.empty() || line[0] != ' ')) {
      listing = false;
    }
  }
  return names;
}

// A --help text with the wrapping to 80 columns undone (src/cli/common/help_format): each option, entry and
// paragraph on one line again, so that a test finds a phrase wherever the wrap fell. A line indented four or
// more spaces continues the one before; a list of choices broken after its comma joins without a space.
inline std::string unwrapped_help(const std::string& text) {
  std::string out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    const auto first = line.find_first_not_of(' ');
    if (!out.empty() && first != std::string::npos && first >= 4) {
      out.pop_back();  // the '\n' of the line continued
      const auto open = out.rfind('\n') == std::string::npos ? 0 : out.rfind('\n');
      const bool in_choices = out.back() == ',' && out.find('{', open) != std::string::npos &&
                              out.find('}', out.find('{', open)) == std::string::npos;
      out += (in_choices ? "" : " ") + line.substr(first);
    } else {
      out += line;
    }
    out += '\n';
  }
  return out;
}

// `arguments` is appended to the executable's path as given (shell syntax: quote what needs quoting).
inline CliOutcome run_cli(const std::string& arguments) {
  char out_name[] = "/tmp/restitution-cli-out-XXXXXX";
  char err_name[] = "/tmp/restitution-cli-err-XXXXXX";
  const int out_fd = mkstemp(out_name);
  const int err_fd = mkstemp(err_name);
  close(out_fd);
  close(err_fd);
  // Appended piece by piece: GCC 12 at -O1 warned falsely (-Wstringop-overflow) on the chain of + here.
  std::string command = RESTITUTION_EXE;
  for (const char* piece : std::initializer_list<const char*>{" ", arguments.c_str(), " >", out_name, " 2>",
                                                              err_name, " </dev/null"})
    command += piece;
  const int raw = std::system(command.c_str());
  CliOutcome outcome;
  outcome.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);
  outcome.out = slurp(out_name);
  outcome.err = slurp(err_name);
  std::remove(out_name);
  std::remove(err_name);
  return outcome;
}

// A fresh folder under /tmp, removed with everything in it at the end of the scope.
struct TempFolder {
  std::filesystem::path path;
  TempFolder() {
    char name[] = "/tmp/restitution-test-XXXXXX";
    path = mkdtemp(name);
  }
  ~TempFolder() { std::filesystem::remove_all(path); }
  TempFolder(const TempFolder&) = delete;
  TempFolder& operator=(const TempFolder&) = delete;
};

// Starts the program in the background with stdout to /dev/null and stderr to `err`; returns its process id.
inline pid_t spawn_cli(const std::vector<std::string>& arguments, const std::filesystem::path& err) {
  const pid_t pid = fork();
  if (pid == 0) {
    std::freopen("/dev/null", "w", stdout);
    std::freopen(err.c_str(), "w", stderr);
    std::vector<char*> argv{const_cast<char*>(RESTITUTION_EXE)};
    for (const std::string& a : arguments) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    execv(RESTITUTION_EXE, argv.data());
    _exit(127);
  }
  return pid;
}

// Waits for a process spawn_cli started; its exit status, or 128 + the signal that ended it.
inline int wait_cli(pid_t pid) {
  int raw = 0;
  waitpid(pid, &raw, 0);
  return WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);
}

}  // namespace restitution::test_support
