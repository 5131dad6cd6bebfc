// SPDX-License-Identifier: BSD-3-Clause
#include "child_process/child_process.hpp"

#include <fcntl.h>
#include <fmt/core.h>
#include <poll.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <csignal>
#include <cstring>

namespace restitution {
namespace {

constexpr int kPollMs = 20;  // how often a running child's stop request is looked at
constexpr int kNotExecuted = 127;

// The child's side, between fork and exec: only async-signal-safe calls, since other threads of the parent
// may hold locks. getppid() closes the race of a parent that died before prctl: no signal would ever come.
[[noreturn]] void exec_child(const std::vector<char*>& argv, pid_t parent, int output_fd) {
  if (prctl(PR_SET_PDEATHSIG, SIGKILL) != 0 || getppid() != parent) _exit(kNotExecuted);
  const int input = open("/dev/null", O_RDONLY);                              // NOLINT(*-vararg)
  const int sink = output_fd >= 0 ? output_fd : open("/dev/null", O_WRONLY);  // NOLINT(*-vararg)
  if (input < 0 || sink < 0 || dup2(input, STDIN_FILENO) < 0 || dup2(sink, STDOUT_FILENO) < 0 ||
      dup2(sink, STDERR_FILENO) < 0) {
    _exit(kNotExecuted);
  }
  execvp(argv[0], argv.data());
  _exit(kNotExecuted);
}

// Reads what the child prints until it closes its end, asking it to stop when told to.
void collect(int fd, pid_t child, const std::function<bool()>& stop_requested, std::string& out) {
  bool stopping = false;
  std::array<char, 4096> buffer{};
  for (;;) {
    pollfd p{fd, POLLIN, 0};
    const int ready = poll(&p, 1, kPollMs);
    if (ready < 0 && errno != EINTR) return;
    if (ready > 0) {
      const ssize_t n = read(fd, buffer.data(), buffer.size());
      if (n == 0) return;
      if (n < 0 && errno != EINTR && errno != EAGAIN) return;
      if (n > 0) out.append(buffer.data(), static_cast<std::size_t>(n));
    }
    if (!stopping && stop_requested && stop_requested()) {
      kill(child, SIGTERM);
      stopping = true;
    }
  }
}

int wait_for(pid_t child, const std::function<bool()>& stop_requested) {
  int status = 0;
  for (bool stopping = false;;) {
    const pid_t done = waitpid(child, &status, stopping ? 0 : WNOHANG);
    if (done == child) return status;
    if (done < 0 && errno != EINTR) return -1;
    if (!stopping && stop_requested && stop_requested()) {
      kill(child, SIGTERM);
      stopping = true;
    } else if (!stopping && done == 0) {
      poll(nullptr, 0, kPollMs);  // the stop request is polled
    }
  }
}

}  // namespace

ChildRun run_child(const std::vector<std::string>& command, ChildOutput output,
                   const std::function<bool()>& stop_requested) {
  ChildRun run;
  if (command.empty()) return run;
  std::vector<char*> argv;
  for (const std::string& a : command) argv.push_back(const_cast<char*>(a.c_str()));  // NOLINT: POSIX API
  argv.push_back(nullptr);
  std::array<int, 2> pipe_fds{-1, -1};
  if (output == ChildOutput::capture && pipe2(pipe_fds.data(), O_CLOEXEC) != 0) return run;
  const pid_t parent = getpid();
  const pid_t child = fork();
  if (child == 0) exec_child(argv, parent, pipe_fds[1]);
  if (pipe_fds[1] >= 0) close(pipe_fds[1]);
  if (child < 0) {
    if (pipe_fds[0] >= 0) close(pipe_fds[0]);
    return run;
  }
  if (pipe_fds[0] >= 0) {
    collect(pipe_fds[0], child, stop_requested, run.output);
    close(pipe_fds[0]);
  }
  run.status = wait_for(child, stop_requested);
  return run;
}

bool child_succeeded(int status) {
  return status >= 0 && WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

std::string child_status_text(int status) {
  if (status < 0) return "could not be started";
  if (WIFSIGNALED(status)) return fmt::format("was killed by signal {}", WTERMSIG(status));
  if (WIFEXITED(status) && WEXITSTATUS(status) == kNotExecuted)
    return fmt::format("exited with status {} (not found or not executable)", kNotExecuted);
  if (WIFEXITED(status)) return fmt::format("exited with status {}", WEXITSTATUS(status));
  return fmt::format("ended with wait status {}", status);
}

}  // namespace restitution
