// SPDX-License-Identifier: BSD-3-Clause
// Nothing is left behind (issue 38, item 5): an I/O error while a command writes its output removes the
// temporary FILE.tmp, and a plot script never outlives `restitution run` nor writes after it (SIGKILL or
// SIGTERM of the run while a plot is drawn). The I/O error comes from RLIMIT_FSIZE with SIGXFSZ ignored: a
// write past the limit fails with EFBIG, like a full disk, without root.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "cli_runner.hpp"

namespace restitution {
namespace {
namespace fs = std::filesystem;
using test_support::CliOutcome;
using test_support::run_cli;
using test_support::slurp;
using test_support::TempFolder;

// run_cli with every file the program writes limited to `bytes`. The limit and the ignored SIGXFSZ are set
// in this process around the call and inherited by the program; stdout and stderr stay below the limit.
CliOutcome run_cli_with_file_size_limit(const std::string& arguments, rlim_t bytes) {
  rlimit saved{};
  getrlimit(RLIMIT_FSIZE, &saved);
  const rlimit limited{bytes, saved.rlim_max};
  const auto previous = std::signal(SIGXFSZ, SIG_IGN);
  setrlimit(RLIMIT_FSIZE, &limited);
  CliOutcome outcome = run_cli(arguments);
  setrlimit(RLIMIT_FSIZE, &saved);
  std::signal(SIGXFSZ, previous);
  return outcome;
}

std::vector<std::string> files_in(const fs::path& folder) {
  std::vector<std::string> names;
  if (!fs::exists(folder)) return names;
  for (const auto& entry : fs::recursive_directory_iterator(folder)) names.push_back(entry.path().string());
  return names;
}

bool any_name_contains(const fs::path& folder, const std::string& part) {
  for (const std::string& name : files_in(folder)) {
    if (fs::path(name).filename().string().find(part) != std::string::npos) return true;
  }
  return false;
}

// 1 KiB: more than any of these commands prints, less than the first file each writes.
constexpr rlim_t kLimit = 1024;

TEST(OutputLeftovers, AFailedWriteLeavesNoTemporaryFile) {
  const std::string source = RESTITUTION_SOURCE_DIR;
  const std::vector<std::string> commands = {
      "fit-data " + source + "/examples/fit/rubber_drop.csv --out OUT/fit.json",
      "export c-header --out OUT/fast.h",
      "series certify --out OUT/coefficients.csv",
      // An existing folder: a run that fails keeps it (it may hold other files), so only the cleanup of the
      // failed write itself removes the temporary.
      "run " + source + "/scenes/trajectory.toml --quick --out OUT",
  };
  for (std::string command : commands) {
    const TempFolder dir;
    command.replace(command.find("OUT"), 3, dir.path.string());
    const CliOutcome r = run_cli_with_file_size_limit(command, kLimit);
    EXPECT_EQ(r.status, 3) << command << "\n" << r.err;
    EXPECT_NE(r.err.find("File too large"), std::string::npos) << command << "\n" << r.err;
    EXPECT_FALSE(any_name_contains(dir.path, ".tmp")) << command << "\n"
                                                      << testing::PrintToString(files_in(dir.path));
  }
}

// A stand-in for python (RESTITUTION_PYTHON): says it has matplotlib; as a plot script, records its pid, says
// it is drawing (`ready`), writes the image (its third argument) after `seconds` and exits with
// `exit_status`.
fs::path slow_plotting_python(const fs::path& dir, double seconds, int exit_status = 0) {
  const fs::path path = dir / "python";
  std::ofstream(path) << "#!/usr/bin/python3\n"
                      << "import os, sys, time\n"
                      << "if sys.argv[1] == '-c':\n    sys.exit(0)\n"
                      << "open('" << (dir / "pid").string() << "', 'w').write(str(os.getpid()))\n"
                      << "os.rename('" << (dir / "pid").string() << "', '" << (dir / "ready").string()
                      << "')\n"
                      << "time.sleep(" << seconds << ")\n"
                      << "open(sys.argv[3], 'w').write('png')\n"
                      << "sys.exit(" << exit_status << ")\n";
  fs::permissions(path, fs::perms::owner_all);
  return path;
}

// Starts `restitution run` on a one-trajectory scene into dir/out with the slow python; returns its pid and
// the plot script's once the plot is being drawn.
std::pair<pid_t, pid_t> run_until_plotting(const fs::path& dir) {
  const fs::path scene = dir / "scene.toml";
  std::ofstream(scene) << "output = \"unused\"\n[[trajectory]]\nname = \"t\"\nzeta = 0.5\n";
  const fs::path python = slow_plotting_python(dir, 2.0);
  const std::string out = (dir / "out").string();
  const pid_t run = fork();
  if (run == 0) {
    setenv("RESTITUTION_PYTHON", python.c_str(), 1);
    const int null = ::open("/dev/null", O_WRONLY);
    dup2(null, STDOUT_FILENO);
    dup2(null, STDERR_FILENO);
    execl(RESTITUTION_EXE, RESTITUTION_EXE, "run", scene.c_str(), "--out", out.c_str(),
          static_cast<char*>(nullptr));
    _exit(127);
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!fs::exists(dir / "ready") && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return {run, std::stoi(slurp((dir / "ready").string()))};
}

// Gone, or a zombie nobody has reaped yet (an orphan's new parent may be slow to): no longer running.
bool running(pid_t pid) {
  const std::string stat = slurp("/proc/" + std::to_string(pid) + "/stat");
  if (stat.empty()) return false;
  const std::size_t state = stat.rfind(") ");
  return state != std::string::npos && stat.at(state + 2) != 'Z';
}

// Waits longer than the plot would have taken to write its image.
void wait_past_the_plot() {
  std::this_thread::sleep_for(std::chrono::milliseconds(2500));
}

TEST(OutputLeftovers, AKilledRunTakesItsPlotWithIt) {
  const TempFolder dir;
  const auto [run, plot] = run_until_plotting(dir.path);
  ASSERT_TRUE(running(plot));
  kill(run, SIGKILL);
  int status = 0;
  waitpid(run, &status, 0);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL);
  wait_past_the_plot();
  EXPECT_FALSE(running(plot)) << "the plot script outlived the killed run";
  if (running(plot)) kill(plot, SIGKILL);
  EXPECT_FALSE(any_name_contains(dir.path / "out", ".png"))
      << testing::PrintToString(files_in(dir.path / "out"));
}

TEST(OutputLeftovers, SigtermToTheRunAloneStopsItsPlot) {
  // Not the process group, as Ctrl-C would: only the run hears it and must stop its plot.
  const TempFolder dir;
  const auto [run, plot] = run_until_plotting(dir.path);
  const auto start = std::chrono::steady_clock::now();
  kill(run, SIGTERM);
  int status = 0;
  waitpid(run, &status, 0);
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::milliseconds(1500))
      << "waited for the plot";
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 128 + SIGTERM) << status;
  wait_past_the_plot();
  EXPECT_FALSE(running(plot));
  if (running(plot)) kill(plot, SIGKILL);
  EXPECT_FALSE(fs::exists(dir.path / "out")) << testing::PrintToString(files_in(dir.path / "out"));
}

TEST(OutputLeftovers, APlotBecomesItsImageOnlyWhenItSucceeds) {
  for (const int exit_status : {0, 1}) {
    const TempFolder dir;
    const fs::path scene = dir.path / "scene.toml";
    std::ofstream(scene) << "output = \"unused\"\n[[trajectory]]\nname = \"t\"\nzeta = 0.5\n";
    setenv("RESTITUTION_PYTHON", slow_plotting_python(dir.path, 0.0, exit_status).c_str(), 1);
    const CliOutcome r = run_cli("run " + scene.string() + " --out " + (dir.path / "out").string());
    unsetenv("RESTITUTION_PYTHON");
    EXPECT_EQ(r.status, 0) << r.err;
    if (exit_status == 0) {
      EXPECT_EQ(slurp((dir.path / "out" / "t.png").string()), "png");
    } else {  // the image the failed script wrote is no plot
      EXPECT_NE(r.err.find("no plot: scene_trajectory.py failed with status 1"), std::string::npos) << r.err;
      EXPECT_FALSE(any_name_contains(dir.path / "out", ".png"));
    }
    EXPECT_FALSE(any_name_contains(dir.path / "out", ".tmp"))
        << testing::PrintToString(files_in(dir.path / "out"));
  }
}

}  // namespace
}  // namespace restitution
