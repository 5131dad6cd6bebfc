// SPDX-License-Identifier: BSD-3-Clause
// `restitution gas --deck` writes its three files as one set (issue 45, item 4), through the real program on
// the real file system: a full disk on the last file (tests/fault/write_shim.c, preloaded, failing the write
// of that file's temporary) leaves the previous set whole; a SIGKILL at each of the set's renames (the same
// shim) never leaves files of two sets side by side; Ctrl-C while the set is written exits 130 and leaves no
// temporary behind.
#include <fmt/core.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "cli_runner.hpp"
#include "haff_log.hpp"

namespace restitution {
namespace {
namespace fs = std::filesystem;
using test_support::kHaffGas;
using test_support::run_cli;
using test_support::slurp;
using test_support::TempFolder;

const std::vector<std::string> kMembers = {"deck.in", "deck_constant_eps.in", "deck.data"};

// The files of a deck of `particles` spheres written into `folder` (empty for a member not there).
std::map<std::string, std::string> deck_files(const fs::path& folder) {
  std::map<std::string, std::string> files;
  for (const std::string& m : kMembers) files[m] = fs::exists(folder / m) ? slurp((folder / m).string()) : "";
  return files;
}

std::map<std::string, std::string> fresh_deck(const fs::path& folder, int particles) {
  const auto r =
      run_cli(kHaffGas + fmt::format("--particles {} --deck '{}'", particles, (folder / "deck.in").string()));
  EXPECT_EQ(r.status, 0) << r.err;
  return deck_files(folder);
}

std::vector<char*> argv_of(const std::vector<std::string>& arguments) {
  std::vector<char*> argv{const_cast<char*>(RESTITUTION_EXE)};
  for (const std::string& a : arguments) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  return argv;
}

// `gas --deck FOLDER/deck.in` of `particles` spheres with the environment `env` (the shim preloaded when it
// is not empty); returns the wait status.
int deck_run(const fs::path& folder, int particles,
             const std::vector<std::pair<std::string, std::string>>& env) {
  std::vector<std::string> arguments;
  std::istringstream words(kHaffGas);
  for (std::string w; words >> w;) arguments.push_back(w);
  for (const std::string& a : {std::string("--particles"), std::to_string(particles), std::string("--deck"),
                               (folder / "deck.in").string()})
    arguments.push_back(a);
  const pid_t pid = fork();
  if (pid == 0) {
    std::freopen("/dev/null", "w", stdout);
    std::freopen((folder.parent_path() / "err").c_str(), "w", stderr);
#ifdef WRITE_SHIM
    if (!env.empty()) setenv("LD_PRELOAD", WRITE_SHIM, 1);
#endif
    for (const auto& [name, value] : env) setenv(name.c_str(), value.c_str(), 1);
    std::vector<char*> argv = argv_of(arguments);
    execv(RESTITUTION_EXE, argv.data());
    _exit(127);
  }
  int raw = 0;
  waitpid(pid, &raw, 0);
  return raw;
}

std::vector<std::string> temporaries_in(const fs::path& folder) {
  std::vector<std::string> found;
  for (const auto& e : fs::directory_iterator(folder)) {
    if (e.path().filename().string().find(".tmp") != std::string::npos) found.push_back(e.path().filename());
  }
  return found;
}

class DeckSet : public ::testing::Test {
 protected:
  void SetUp() override {
#ifndef WRITE_SHIM
    GTEST_SKIP() << "no fault shim in this build (sanitizers)";
#endif
    fs::create_directories(dir_.path / "deck");
    fs::create_directories(dir_.path / "new");
    old_ = fresh_deck(dir_.path / "deck", 300);
    new_ = fresh_deck(dir_.path / "new", 200);
    ASSERT_NE(old_.at("deck.data"), new_.at("deck.data"));
  }
  fs::path folder() const {
    return dir_.path / "deck";
  }
  TempFolder dir_;
  std::map<std::string, std::string> old_, new_;
};

TEST_F(DeckSet, AFullDiskOnTheLastFileLeavesThePreviousSetWhole) {
  // The law's input is written last; its temporary is cut short at byte 100, the next write fails (ENOSPC).
  const int raw = deck_run(folder(), 200,
                           {{"RESTITUTION_FAULT_SUFFIX", ".tmp"},
                            {"RESTITUTION_FAULT_NAME_PREFIX", "deck.in."},
                            {"RESTITUTION_FAULT_OFFSET", "100"}});
  const std::string err = slurp((dir_.path / "err").string());
  EXPECT_TRUE(WIFEXITED(raw) && WEXITSTATUS(raw) == 3) << raw << " " << err;
  EXPECT_NE(err.find("No space left on device"), std::string::npos) << err;
  EXPECT_EQ(deck_files(folder()), old_) << "the previous set, whole";
  EXPECT_TRUE(temporaries_in(folder()).empty());
}

TEST_F(DeckSet, ASigkillAtEachRenameNeverLeavesTwoSetsSideBySide) {
  for (int at = 1; at <= static_cast<int>(kMembers.size()); ++at) {
    for (const std::string& m : kMembers) fs::remove(folder() / m);
    for (const std::string& t : temporaries_in(folder())) fs::remove(folder() / t);
    ASSERT_EQ(fresh_deck(folder(), 300), old_);
    const int raw = deck_run(folder(), 200, {{"RESTITUTION_KILL_AT_RENAME", std::to_string(at)}});
    ASSERT_TRUE(WIFSIGNALED(raw) && WTERMSIG(raw) == SIGKILL) << "rename " << at << ": " << raw;
    // Every member present is of one set; all three present only as a whole set.
    const auto files = deck_files(folder());
    int of_old = 0;
    int of_new = 0;
    for (const std::string& m : kMembers) {
      if (files.at(m).empty()) continue;
      of_old += files.at(m) == old_.at(m) ? 1 : 0;
      of_new += files.at(m) == new_.at(m) ? 1 : 0;
      EXPECT_TRUE(files.at(m) == old_.at(m) || files.at(m) == new_.at(m)) << m << " is of neither set";
    }
    EXPECT_TRUE(of_old == 0 || of_new == 0)
        << "rename " << at << ": " << of_old << " files of the old set, " << of_new << " of the new";
  }
}

TEST_F(DeckSet, CtrlCWhileTheSetIsWrittenExitsWith130AndLeavesNoTemporary) {
  // A large deck (tens of MB of data), so that the signal lands while the temporaries are written.
  const pid_t pid = fork();
  if (pid == 0) {
    std::freopen("/dev/null", "w", stdout);
    std::freopen((dir_.path / "err").c_str(), "w", stderr);
    std::vector<std::string> arguments;
    std::istringstream words(kHaffGas);
    for (std::string w; words >> w;) arguments.push_back(w);
    for (const std::string& a : {std::string("--particles"), std::string("100000"), std::string("--deck"),
                                 (folder() / "deck.in").string()})
      arguments.push_back(a);
    std::vector<char*> argv = argv_of(arguments);
    execv(RESTITUTION_EXE, argv.data());
    _exit(127);
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (temporaries_in(folder()).empty() && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  kill(pid, SIGINT);
  int raw = 0;
  waitpid(pid, &raw, 0);
  const std::string err = slurp((dir_.path / "err").string());
  EXPECT_TRUE(WIFEXITED(raw) && WEXITSTATUS(raw) == 130) << raw << " " << err;
  EXPECT_TRUE(temporaries_in(folder()).empty()) << temporaries_in(folder()).front();
  // Stopped before the renames (the previous set) or, at the latest, after them (a whole new set).
  const auto files = deck_files(folder());
  EXPECT_TRUE(files == old_ || files.at("deck.in") != old_.at("deck.in")) << "a set mixed by the stop";
}

}  // namespace
}  // namespace restitution
