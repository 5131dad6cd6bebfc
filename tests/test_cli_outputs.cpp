// SPDX-License-Identifier: BSD-3-Clause
// Every command that prints or writes a file, through the executable: a failed write to stdout fails the
// command with status 3; symlinks given as output keep being symlinks; streams are never replaced by
// files; checks that need no computing come before it; a resume of a finished sweep says so.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "cli_runner.hpp"

namespace restitution {
namespace {

namespace fs = std::filesystem;
using test_support::run_cli;
using test_support::slurp;

fs::path fresh_folder(const std::string& name) {
  const fs::path folder =
      fs::temp_directory_path() / ("restitution-cli-outputs-" + std::to_string(::getpid()) + name);
  fs::remove_all(folder);
  fs::create_directories(folder);
  return folder;
}

// Item 9: stdout that cannot take the result (/dev/full) is an I/O failure, status 3, for every printer.
TEST(CliOutputs, FailedWriteToStdoutIsStatusThree) {
  for (const char* command :
       {"eps --zeta 1", "eps --zeta 1 --json", "calibrate --eps 0.8 --velocity 1",
        "series eval --kind naive --zeta 0.5", "series coefficients --kind naive --count 5",
        "fit --end naive --zeta-range 10:20:3", "--help"}) {
    // run_cli redirects stdout itself: run the executable directly, stdout on /dev/full.
    const fs::path err = fs::temp_directory_path() / ("restitution-full-" + std::to_string(::getpid()));
    const std::string line = std::string(RESTITUTION_EXE) + " " + command + " >/dev/full 2>" + err.string();
    const int raw = std::system(line.c_str());
    const std::string message = slurp(err.string());
    fs::remove(err);
    EXPECT_EQ(WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, 3) << command << "\n" << message;
    EXPECT_NE(message.find("restitution: I/O error: cannot write to standard output"), std::string::npos)
        << command << "\n"
        << message;
  }
}

// Item 8: a symlink given as output stays a symlink, its target gets the table; /dev/stdout is never
// replaced (the sweep refuses it, it keeps FILE.partial beside its file).
TEST(CliOutputs, SymlinksAndStreamsAreNotReplaced) {
  const fs::path folder = fresh_folder("links");
  fs::create_directories(folder / "data");
  std::ofstream(folder / "data" / "real.csv") << "old\n";
  fs::create_symlink("data/real.csv", folder / "link.csv");
  auto r = run_cli("sweep --zeta-range 0:1:3 --out " + (folder / "link.csv").string());
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(folder / "link.csv")));
  EXPECT_EQ(slurp((folder / "data" / "real.csv").string()).rfind("zeta,", 0), 0U);
  r = run_cli("sweep --zeta-range 0:1:3 --out /dev/stdout");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("is not a regular file"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status("/dev/stdout")));
  fs::remove_all(folder);
}

// Item 15: --resume of a sweep that finished says so and computes nothing.
TEST(CliOutputs, ResumingAFinishedSweepSaysItIsComplete) {
  const fs::path folder = fresh_folder("resume");
  const std::string sweep = "sweep --zeta-range 0:1:3 --out " + (folder / "s.csv").string();
  ASSERT_EQ(run_cli(sweep).status, 0);
  const auto r = run_cli(sweep + " --resume");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("nothing to resume"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  fs::remove_all(folder);
}

// Item 12: what can be refused without computing is refused before anything is computed or written.
TEST(CliOutputs, RefusalsComeBeforeTheWork) {
  const fs::path folder = fresh_folder("early");
  std::ofstream(folder / "a-file") << "x\n";
  const std::string file = (folder / "a-file").string();
  for (const std::string& command :
       {"sweep --zeta-range 1e-3:1e3:1000 --log --method taylor --out " + (folder / "t.csv").string(),
        "work-precision --out " + file, "reference --out " + folder.string(),
        "series certify --order 12 --out " + folder.string(), "series validate --out " + file}) {
    const auto r = run_cli(command);
    // 2 for the Taylor limit, 3 for a path that cannot be written: either way before the work.
    EXPECT_TRUE(r.status == 2 || r.status == 3) << command << "\n" << r.err;
    EXPECT_FALSE(fs::exists(folder / "t.csv.partial")) << command;
  }
  fs::remove_all(folder);
}

}  // namespace
}  // namespace restitution
