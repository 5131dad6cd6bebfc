// SPDX-License-Identifier: BSD-3-Clause
// A full disk under a running sweep, without root. A write(2) to FILE.partial, or separately to FILE.tmp, is
// cut short at a chosen byte of the file and the next one fails with ENOSPC, while later writes go through
// (space freed after the failure: tests/fault/write_shim.c, preloaded); and a failure that persists, a file
// size limit (RLIMIT_FSIZE with SIGXFSZ ignored). At 10 places each the sweep ends with status 3, every
// complete line on disk is a whole row of the sweep (no write after the failed one), and --resume then keeps
// every point that was on disk and finishes a table byte-identical to an uninterrupted sweep's.
#include <fmt/core.h>
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "cli_runner.hpp"

namespace restitution {
namespace {
namespace fs = std::filesystem;
using test_support::lines_of;
using test_support::slurp;
using test_support::TempFolder;

constexpr std::size_t kPoints = 10000;
constexpr int kPlaces = 10;

// Small and fast (~0.3 s): Taylor at a loose tolerance, the naive end, two threads.
std::vector<std::string> sweep_arguments(const fs::path& out) {
  return {"sweep",
          "--zeta-range",
          "0:10:" + std::to_string(kPoints),
          "--method",
          "taylor",
          "--tolerance",
          "1e-2",
          "--end",
          "naive",
          "--threads",
          "2",
          "--out",
          out.string()};
}

struct Fault {
  std::string suffix;              // of the file whose write fails once (the shim), or empty
  long long offset = 0;            // the byte of that file where it fails
  long long file_size_limit = -1;  // RLIMIT_FSIZE in bytes, or -1
};

// Runs the program with the fault; returns its exit status (128 + signal when killed).
int run_with_fault(const std::vector<std::string>& arguments, const Fault& fault, const fs::path& err) {
  const pid_t pid = fork();
  if (pid == 0) {
    std::freopen("/dev/null", "w", stdout);
    std::freopen(err.c_str(), "w", stderr);
    if (!fault.suffix.empty()) {
#ifdef WRITE_SHIM
      setenv("LD_PRELOAD", WRITE_SHIM, 1);
#endif
      setenv("RESTITUTION_FAULT_SUFFIX", fault.suffix.c_str(), 1);
      setenv("RESTITUTION_FAULT_OFFSET", std::to_string(fault.offset).c_str(), 1);
    }
    if (fault.file_size_limit >= 0) {
      std::signal(SIGXFSZ, SIG_IGN);  // stays ignored across exec: the write fails with EFBIG instead
      const rlimit limit{static_cast<rlim_t>(fault.file_size_limit),
                         static_cast<rlim_t>(fault.file_size_limit)};
      setrlimit(RLIMIT_FSIZE, &limit);
    }
    std::vector<char*> argv{const_cast<char*>(RESTITUTION_EXE)};
    for (const std::string& a : arguments) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    execv(RESTITUTION_EXE, argv.data());
    _exit(127);
  }
  int raw = 0;
  waitpid(pid, &raw, 0);
  return WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);
}

// The points whose lines are complete on disk. Each complete line after the first two must be "INDEX,ROW,CRC"
// with ROW the row of the uninterrupted table: a line cut off and then followed by a later write is not.
std::set<std::size_t> points_on_disk(const fs::path& partial, const std::vector<std::string>& table) {
  std::set<std::size_t> points;
  if (!fs::exists(partial)) return points;
  const std::vector<std::string> lines = lines_of(slurp(partial));
  for (std::size_t n = 2; n < lines.size(); ++n) {
    const std::string& line = lines[n];
    const std::size_t index = std::stoul(line);
    EXPECT_LT(index, kPoints) << "line " << n + 1 << ": " << line;
    if (index >= kPoints) continue;
    const std::string expected = fmt::format("{},{},", index, table[index + 1]);
    EXPECT_EQ(line.substr(0, line.size() - 8), expected) << "line " << n + 1 << " is no whole row";
    points.insert(index);
  }
  return points;
}

class SweepFaults : public ::testing::Test {
 protected:
  void SetUp() override {
#ifndef WRITE_SHIM
    GTEST_SKIP() << "no write shim in this build (sanitizers)";
#endif
    const fs::path reference = dir_.path / "reference.csv";
    ASSERT_EQ(run_with_fault(sweep_arguments(reference), {}, dir_.path / "reference.err"), 0);
    table_text_ = slurp(reference);
    table_ = lines_of(table_text_);
    ASSERT_EQ(table_.size(), kPoints + 1);
  }

  // One failing sweep and its resume; `name` labels the case in messages.
  void fail_then_resume(const Fault& fault, const std::string& name) {
    SCOPED_TRACE(name);
    const fs::path folder = dir_.path / name;
    fs::create_directories(folder);
    const fs::path out = folder / "s.csv";
    const fs::path partial = out.string() + ".partial";
    const int status = run_with_fault(sweep_arguments(out), fault, folder / "fault.err");
    EXPECT_EQ(status, 3) << slurp(folder / "fault.err");
    EXPECT_FALSE(fs::exists(out));
    EXPECT_FALSE(fs::exists(out.string() + ".tmp"));
    const std::set<std::size_t> on_disk = points_on_disk(partial, table_);

    std::vector<std::string> resume = sweep_arguments(out);
    resume.emplace_back("--resume");
    const fs::path err = folder / "resume.err";
    ASSERT_EQ(run_with_fault(resume, {}, err), 0) << slurp(err);
    EXPECT_NE(
        slurp(err).find(fmt::format("resuming: {} of {} points already finished", on_disk.size(), kPoints)),
        std::string::npos)
        << slurp(err);
    EXPECT_EQ(slurp(out), table_text_) << "not the uninterrupted table";
    EXPECT_FALSE(fs::exists(partial));
    EXPECT_FALSE(fs::exists(out.string() + ".lock"));
    points_kept_ += on_disk.size();
  }

  // 10 places in a file of `size` bytes: two in its first line, the rest spread over the file.
  static std::vector<long long> places(long long size) {
    std::vector<long long> at{0, 37};
    for (int k = 1; static_cast<int>(at.size()) < kPlaces; ++k) at.push_back(size * k / (kPlaces - 1));
    return at;
  }

  TempFolder dir_;
  std::string table_text_;
  std::vector<std::string> table_;
  std::size_t points_kept_ = 0;
};

TEST_F(SweepFaults, TheWriteToThePartialFileFailsOnceAndSpaceComesBack) {
  // Places the sweep writes while it runs: the partial file is larger than the table (each row with its
  // index and checksum), and what the two workers' buffers (256 KiB each) hold at the end is written once the
  // table is complete, when a failure no longer matters.
  for (const long long offset : places(static_cast<long long>(table_text_.size()) - 600'000)) {
    fail_then_resume({".partial", offset, -1}, fmt::format("partial-{}", offset));
  }
  EXPECT_GT(points_kept_, kPoints) << "the failures came so early that no finished point was at stake";
}

TEST_F(SweepFaults, TheWriteToTheTableFailsOnceAndSpaceComesBack) {
  // Any place in the table: its last bytes are written before the rename.
  for (const long long offset : places(static_cast<long long>(table_text_.size()) - 1)) {
    fail_then_resume({".tmp", offset, -1}, fmt::format("tmp-{}", offset));
  }
  EXPECT_GT(points_kept_, kPoints);
}

TEST_F(SweepFaults, AFileSizeLimitPersists) {
  // From a limit inside the partial file's first lines to one near the table's end.
  std::vector<long long> limits = places(static_cast<long long>(table_text_.size()) - 1);
  limits[0] = 100;
  for (const long long limit : limits) {
    fail_then_resume({"", 0, limit}, fmt::format("limit-{}", limit));
  }
  EXPECT_GT(points_kept_, kPoints);
}

}  // namespace
}  // namespace restitution
