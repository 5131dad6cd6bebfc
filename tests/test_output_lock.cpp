// SPDX-License-Identifier: BSD-3-Clause
// Two writers of the same files: the second is refused at once (exit 2) naming the first's process id, the
// first finishes untouched; a lock left by a killed process is taken over. The lock itself (OutputLock,
// FolderLock), then two sweeps to one --out, two --resume at once with the first killed, two runs into one
// folder.
#include <fmt/core.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "cli_runner.hpp"
#include "files/output_lock.hpp"
#include "restitution/errors.hpp"

namespace restitution {
namespace {
namespace fs = std::filesystem;
using test_support::run_cli;
using test_support::slurp;
using test_support::spawn_cli;
using test_support::TempFolder;
using test_support::wait_cli;

std::string refusal(const fs::path& lock_file) {
  try {
    const files::OutputLock second(lock_file, "--out 'x'");
  } catch (const InvalidInput& e) {
    return e.what();
  }
  return "not refused";
}

// The id of a process that has ended.
pid_t ended_process() {
  const pid_t pid = fork();
  if (pid == 0) _exit(0);
  waitpid(pid, nullptr, 0);
  return pid;
}

// Waits until the lock file names `pid` (the process holds the lock); false after 60 s.
bool wait_for_lock(const fs::path& lock_file, pid_t pid) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (std::chrono::steady_clock::now() < deadline) {
    if (slurp(lock_file) == fmt::format("{}\n", pid)) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  return false;
}

std::size_t line_count(const fs::path& path) {
  const std::string text = slurp(path);
  return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
}

TEST(OutputLock, ASecondHolderIsRefusedNamingTheFirstAndTheFileGoesWithTheLock) {
  const TempFolder dir;
  const fs::path lock_file = dir.path / "s.csv.lock";
  {
    const files::OutputLock first(lock_file, "--out 's.csv'");
    EXPECT_EQ(slurp(lock_file), fmt::format("{}\n", getpid()));
    const std::string message = refusal(lock_file);  // another open file: flock refuses it in one process too
    EXPECT_NE(message.find(
                  fmt::format("--out 'x' is being written by another restitution run (process {}", getpid())),
              std::string::npos)
        << message;
  }
  EXPECT_FALSE(fs::exists(lock_file));
  EXPECT_EQ(refusal(lock_file), "not refused");
}

TEST(OutputLock, AStaleLockIsTakenOver) {
  const TempFolder dir;
  const fs::path lock_file = dir.path / "s.csv.lock";
  std::ofstream(lock_file) << ended_process() << "\n";  // what a killed sweep leaves
  {
    const files::OutputLock taken(lock_file, "--out 's.csv'");
    EXPECT_EQ(slurp(lock_file), fmt::format("{}\n", getpid()));
  }
  EXPECT_FALSE(fs::exists(lock_file));
}

TEST(FolderLock, LocksBesideTheFolderAndRemovesOnlyTheEmptyFoldersItMade) {
  const TempFolder dir;
  const fs::path folder = dir.path / "a" / "b" / "results";
  const fs::path lock_file = dir.path / "a" / "b" / "results.lock";
  EXPECT_EQ(files::folder_lock_path(folder), lock_file);
  EXPECT_EQ(files::folder_lock_path(folder / ""), lock_file);
  {
    const files::FolderLock lock(folder, "--out 'a/b/results'");
    EXPECT_TRUE(fs::exists(lock_file));
    EXPECT_FALSE(fs::exists(folder)) << "made by the first file written into it, not by the lock";
    EXPECT_NE(refusal(lock_file), "not refused");
  }
  EXPECT_FALSE(fs::exists(dir.path / "a")) << "a run that wrote nothing leaves no folder";
  {
    const files::FolderLock lock(folder, "--out 'a/b/results'");
    fs::create_directories(folder);
    std::ofstream(folder / "report.md") << "done\n";
  }
  EXPECT_TRUE(fs::exists(folder / "report.md"));
  EXPECT_FALSE(fs::exists(lock_file));
}

// A sweep of about a second on two threads.
std::vector<std::string> sweep_arguments(const fs::path& out) {
  return {"sweep", "--zeta-range", "0:10:40000", "--method", "taylor", "--tolerance", "1e-2",
          "--end", "naive",        "--threads",  "2",        "--out",  out.string()};
}

std::string command_of(const std::vector<std::string>& arguments) {
  std::string command;
  for (const std::string& a : arguments) command += (command.empty() ? "" : " ") + a;
  return command;
}

TEST(CliLock, ASecondSweepToTheSameOutIsRefusedAtOnceAndTheFirstFinishes) {
  const TempFolder dir;
  const fs::path out = dir.path / "s.csv";
  const pid_t first = spawn_cli(sweep_arguments(out), dir.path / "first.err");
  ASSERT_TRUE(wait_for_lock(out.string() + ".lock", first));
  for (const std::string resume : {"", " --resume"}) {
    const auto start = std::chrono::steady_clock::now();
    const auto second = run_cli(command_of(sweep_arguments(out)) + resume);
    EXPECT_EQ(second.status, 2) << second.err;
    EXPECT_NE(second.err.find(fmt::format("(process {}", first)), std::string::npos) << second.err;
    EXPECT_EQ(second.err.find("add --resume"), std::string::npos) << second.err;
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5)) << "refused at once";
  }
  EXPECT_EQ(wait_cli(first), 0) << slurp(dir.path / "first.err");
  EXPECT_EQ(line_count(out), 40001U);
  EXPECT_FALSE(fs::exists(out.string() + ".partial"));
  EXPECT_FALSE(fs::exists(out.string() + ".lock"));
}

TEST(CliLock, ASecondResumeIsRefusedAndAfterKillingTheFirstTheSweepResumes) {
  const TempFolder dir;
  const fs::path out = dir.path / "s.csv";
  const fs::path partial = out.string() + ".partial";
  const fs::path lock_file = out.string() + ".lock";
  std::vector<std::string> resume = sweep_arguments(out);
  resume.emplace_back("--resume");
  // An interrupted sweep to resume.
  const pid_t interrupted = spawn_cli(sweep_arguments(out), dir.path / "interrupted.err");
  ASSERT_TRUE(wait_for_lock(lock_file, interrupted));
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (line_count(partial) < 1000 && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  kill(interrupted, SIGINT);
  ASSERT_EQ(wait_cli(interrupted), 130);
  const std::size_t kept = line_count(partial) - 2;

  const pid_t first = spawn_cli(resume, dir.path / "first.err");
  ASSERT_TRUE(wait_for_lock(lock_file, first));
  const auto second = run_cli(command_of(resume));
  EXPECT_EQ(second.status, 2) << second.err;
  EXPECT_NE(second.err.find(fmt::format("(process {}", first)), std::string::npos) << second.err;
  kill(first, SIGKILL);  // no chance to remove its lock file: a stale lock
  EXPECT_EQ(wait_cli(first), 128 + SIGKILL);
  ASSERT_TRUE(fs::exists(lock_file));
  EXPECT_GE(line_count(partial) - 2, kept) << "no finished point is lost";

  const auto last = run_cli(command_of(resume));
  ASSERT_EQ(last.status, 0) << last.err;
  EXPECT_FALSE(fs::exists(lock_file));
  const fs::path fresh = dir.path / "fresh.csv";
  ASSERT_EQ(run_cli(command_of(sweep_arguments(fresh))).status, 0);
  EXPECT_EQ(slurp(out), slurp(fresh));
}

TEST(CliLock, ASecondRunIntoTheSameFolderIsRefusedAtOnce) {
  const TempFolder dir;
  const fs::path folder = dir.path / "results";
  const std::string scene = std::string(RESTITUTION_SOURCE_DIR) + "/scenes/trajectory.toml";
  const pid_t first = spawn_cli({"run", scene, "--quick", "--out", folder.string()}, dir.path / "first.err");
  ASSERT_TRUE(wait_for_lock(folder.string() + ".lock", first));
  const std::string other = std::string(RESTITUTION_SOURCE_DIR) + "/scenes/dashpot.toml";
  const auto start = std::chrono::steady_clock::now();
  const auto second = run_cli("run " + other + " --quick --out " + folder.string());
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5)) << "refused at once";
  EXPECT_EQ(second.status, 2) << second.err;
  EXPECT_NE(second.err.find(fmt::format("--out '{}' is being written by another restitution run (process {}",
                                        folder.string(), first)),
            std::string::npos)
      << second.err;
  EXPECT_EQ(wait_cli(first), 0) << slurp(dir.path / "first.err");
  EXPECT_TRUE(fs::exists(folder / "report.md"));
  EXPECT_FALSE(fs::exists(folder.string() + ".lock"));
}

TEST(CliLock, TwoRunsThroughASymlinkedFolderAreSerialised) {
  const TempFolder dir;
  const fs::path folder = dir.path / "same2";
  fs::create_directories(folder);
  fs::create_directory_symlink(folder, dir.path / "link-to-same2");
  const std::string scene = std::string(RESTITUTION_SOURCE_DIR) + "/scenes/trajectory.toml";
  const pid_t first = spawn_cli({"run", scene, "--quick", "--out", folder.string()}, dir.path / "first.err");
  ASSERT_TRUE(wait_for_lock(folder.string() + ".lock", first));
  const std::string other = std::string(RESTITUTION_SOURCE_DIR) + "/scenes/dashpot.toml";
  const auto second = run_cli("run " + other + " --quick --out " + (dir.path / "link-to-same2").string());
  EXPECT_EQ(second.status, 2) << second.err;
  EXPECT_NE(second.err.find(fmt::format("is being written by another restitution run (process {}", first)),
            std::string::npos)
      << second.err;
  EXPECT_EQ(wait_cli(first), 0) << slurp(dir.path / "first.err");
  EXPECT_FALSE(fs::exists(dir.path / "link-to-same2.lock"));
}

}  // namespace
}  // namespace restitution
