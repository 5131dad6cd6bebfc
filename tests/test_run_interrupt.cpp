// SPDX-License-Identifier: BSD-3-Clause
// Ctrl-C during `restitution run` (issue 12, item 14): SIGINT to the process group, as a terminal sends
// it, in any phase stops the whole run with status 130, leaves no folder that looks complete, and never
// blames matplotlib. A stand-in for python (RESTITUTION_PYTHON) holds the run in its plotting phase.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include "cli_runner.hpp"

namespace restitution {
namespace {
namespace fs = std::filesystem;
using test_support::slurp;

using test_support::TempFolder;

struct Outcome {
  int raw = 0;  // wait status
  std::string err;
};

// Runs `restitution run SCENE --out DIR/out` in its own process group with RESTITUTION_PYTHON=python; once
// `ready` exists (or after `delay` when ready is empty) sends SIGINT to the group, as Ctrl-C does.
Outcome interrupted_run(const fs::path& scene, const fs::path& python, const fs::path& ready,
                        std::chrono::milliseconds delay, const fs::path& err_file) {
  const pid_t child = fork();
  if (child == 0) {
    setpgid(0, 0);
    setenv("RESTITUTION_PYTHON", python.c_str(), 1);
    const int fd = ::open(err_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    dup2(fd, STDERR_FILENO);
    // The scene's folder/out, given on the command line (a scene's own output stays relative).
    const std::string out = (scene.parent_path() / "out").string();
    execl(RESTITUTION_EXE, RESTITUTION_EXE, "run", scene.c_str(), "--out", out.c_str(),
          static_cast<char*>(nullptr));
    _exit(127);
  }
  setpgid(child, child);  // also here: whichever runs first
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  if (ready.empty()) {
    std::this_thread::sleep_for(delay);
  } else {
    while (!fs::exists(ready) && std::chrono::steady_clock::now() < deadline)
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  kill(-child, SIGINT);
  Outcome outcome;
  waitpid(child, &outcome.raw, 0);
  outcome.err = slurp(err_file.string());
  return outcome;
}

// A python that says it has matplotlib (or, with hang_on_probe, hangs there) and hangs in every plot script.
// With survives_sigint it ignores Ctrl-C in the plot script, as matplotlib's python may (it turns SIGINT into
// an exception it can catch and outlive) and ends only by the SIGTERM the program forwards.
fs::path fake_python(const fs::path& dir, bool hang_on_probe, bool survives_sigint = false) {
  const fs::path path = dir / "python";
  std::ofstream(path) << "#!/bin/sh\n"
                      << "if [ \"$1\" = -c ] && [ " << (hang_on_probe ? "1" : "0")
                      << " = 0 ]; then exit 0; fi\n"
                      << (survives_sigint ? "trap '' INT\n" : "") << "touch '" << (dir / "ready").string()
                      << "'\nexec sleep 60\n";
  fs::permissions(path, fs::perms::owner_all);
  return path;
}

fs::path write_scene(const fs::path& dir, const std::string& body) {
  const fs::path scene = dir / "scene.toml";
  std::ofstream(scene) << "output = \"unused\"\n" << body;  // interrupted_run passes --out dir/out
  return scene;
}

void expect_stopped_by_sigint(const Outcome& o, const fs::path& out) {
  const bool exited_130 = WIFEXITED(o.raw) && WEXITSTATUS(o.raw) == 130;
  const bool killed = WIFSIGNALED(o.raw) && WTERMSIG(o.raw) == SIGINT;  // a shell reports 130 too
  EXPECT_TRUE(exited_130 || killed) << "wait status " << o.raw << ", stderr: " << o.err;
  EXPECT_EQ(o.err.find("matplotlib"), std::string::npos) << o.err;
  EXPECT_FALSE(fs::exists(out / "report.md"));
  EXPECT_FALSE(fs::exists(out)) << "a new output folder of a stopped run is removed";
}

TEST(RunInterrupt, CtrlCWhilePlottingStopsTheRunWith130) {
  for (const bool in_probe : {false, true}) {
    const TempFolder dir;
    const fs::path scene = write_scene(dir.path, "[[sweep]]\nname = \"s\"\nzeta = [0.1, 0.2]\n");
    const Outcome o = interrupted_run(scene, fake_python(dir.path, in_probe), dir.path / "ready",
                                      std::chrono::milliseconds(0), dir.path / "err");
    EXPECT_TRUE(WIFEXITED(o.raw) && WEXITSTATUS(o.raw) == 130) << o.raw << " " << o.err;
    EXPECT_NE(o.err.find("interrupted by signal 2"), std::string::npos) << o.err;
    expect_stopped_by_sigint(o, dir.path / "out");
  }
}

TEST(RunInterrupt, AnEarlierReportDoesNotSurviveAStoppedRun) {
  const TempFolder dir;
  fs::create_directories(dir.path / "out");
  std::ofstream(dir.path / "out" / "report.md") << "# an earlier run\n";
  const fs::path scene = write_scene(dir.path, "[[sweep]]\nname = \"s\"\nzeta = [0.1, 0.2]\n");
  const Outcome o = interrupted_run(scene, fake_python(dir.path, false), dir.path / "ready",
                                    std::chrono::milliseconds(0), dir.path / "err");
  EXPECT_TRUE(WIFEXITED(o.raw) && WEXITSTATUS(o.raw) == 130) << o.raw << " " << o.err;
  EXPECT_FALSE(fs::exists(dir.path / "out" / "report.md"));
}

TEST(RunInterrupt, CtrlCWhilePlottingExits130EvenWhenThePlotEndsByTheForwardedTerm) {
  const TempFolder dir;
  const fs::path scene = write_scene(dir.path, "[[sweep]]\nname = \"s\"\nzeta = [0.1, 0.2]\n");
  const Outcome o = interrupted_run(scene, fake_python(dir.path, false, true), dir.path / "ready",
                                    std::chrono::milliseconds(0), dir.path / "err");
  EXPECT_TRUE(WIFEXITED(o.raw) && WEXITSTATUS(o.raw) == 130) << o.raw << " " << o.err;
  EXPECT_NE(o.err.find("interrupted by signal 2"), std::string::npos) << o.err;
  expect_stopped_by_sigint(o, dir.path / "out");
}

TEST(RunInterrupt, AnEarlierSummaryDoesNotSurviveAStoppedRun) {
  const TempFolder dir;
  fs::create_directories(dir.path / "out");
  std::ofstream(dir.path / "out" / "summary.json") << "{\"scene\": \"an earlier run\"}\n";
  const fs::path scene = write_scene(dir.path, "[[sweep]]\nname = \"s\"\nzeta = [0.1, 0.2]\n");
  const Outcome o = interrupted_run(scene, fake_python(dir.path, false), dir.path / "ready",
                                    std::chrono::milliseconds(0), dir.path / "err");
  EXPECT_TRUE(WIFEXITED(o.raw) && WEXITSTATUS(o.raw) == 130) << o.raw << " " << o.err;
  EXPECT_TRUE(fs::exists(dir.path / "out" / "s.csv")) << "the stop came after this run's first table";
  EXPECT_FALSE(fs::exists(dir.path / "out" / "summary.json"))
      << "beside this run's table, read as this run's";
}

TEST(RunInterrupt, CtrlCWhileComputingStopsAtOnce) {
  const TempFolder dir;
  // Far more work than the 300 ms before the signal.
  const fs::path scene = write_scene(
      dir.path,
      "tolerance = 1e-11\n[[sweep]]\nname = \"s\"\nzeta = { from = 0, to = 100, points = 400000 }\n");
  const auto start = std::chrono::steady_clock::now();
  const Outcome o = interrupted_run(scene, fake_python(dir.path, false), {}, std::chrono::milliseconds(300),
                                    dir.path / "err");
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(10));
  expect_stopped_by_sigint(o, dir.path / "out");
}

}  // namespace
}  // namespace restitution
