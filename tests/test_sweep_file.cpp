// SPDX-License-Identifier: BSD-3-Clause
// sweep_to_file, the library's resumable sweep into a CSV file: a sweep stopped part-way keeps FILE.partial
// and resumes to the bytes of an uninterrupted one; resuming a complete file computes nothing; a partial file
// of another sweep, or one found without resume, is refused naming it; columns not parallel to the grid too.
#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "restitution/errors.hpp"
#include "restitution/sweep.hpp"

namespace restitution {
namespace {
namespace fs = std::filesystem;

struct Folder {
  fs::path path = fs::temp_directory_path() / ("sweep_file_" + std::to_string(::getpid()));
  Folder() { fs::create_directories(path); }
  ~Folder() { fs::remove_all(path); }
};

std::string contents(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

const std::vector<double> kZetas = zeta_values({0.0, 3.0, 400, false});

SweepFile file_at(const fs::path& path, bool resume = false) {
  SweepFile file;
  file.path = path;
  file.resume = resume;
  file.settings = "# test sweep 400";
  return file;
}

SweepControl threads(unsigned count) {
  SweepControl control;
  control.threads = count;
  return control;
}

TEST(SweepFile, AStoppedSweepResumesToTheBytesOfAnUninterruptedOne) {
  const Folder dir;
  const SweepFileOutcome whole = sweep_to_file(kZetas, {}, threads(2), file_at(dir.path / "whole.csv"));
  EXPECT_EQ(whole.status, SweepFileOutcome::Status::complete);
  EXPECT_EQ(whole.finished, kZetas.size());
  EXPECT_FALSE(fs::exists(dir.path / "whole.csv.partial"));

  const fs::path out = dir.path / "stopped.csv";
  SweepControl stopping = threads(1);
  std::atomic<int> polls{0};
  stopping.stop_requested = [&polls] { return ++polls > 150; };
  const SweepFileOutcome stopped = sweep_to_file(kZetas, {}, stopping, file_at(out));
  ASSERT_EQ(stopped.status, SweepFileOutcome::Status::stopped);
  EXPECT_EQ(stopped.finished, 150U);
  EXPECT_FALSE(fs::exists(out));
  ASSERT_TRUE(fs::exists(dir.path / "stopped.csv.partial"));

  std::size_t told = 0;
  SweepFile again = file_at(out, true);
  again.resuming = [&told](const SweepFileOutcome& found) { told = found.resumed; };
  const SweepFileOutcome resumed = sweep_to_file(kZetas, {}, threads(2), again);
  EXPECT_EQ(resumed.status, SweepFileOutcome::Status::complete);
  EXPECT_EQ(resumed.resumed, 150U);
  EXPECT_EQ(told, 150U);
  EXPECT_EQ(contents(out), contents(dir.path / "whole.csv"));
  EXPECT_FALSE(fs::exists(dir.path / "stopped.csv.partial"));

  const SweepFileOutcome done = sweep_to_file(kZetas, {}, threads(2), file_at(out, true));
  EXPECT_EQ(done.status, SweepFileOutcome::Status::already_complete);
  EXPECT_EQ(done.finished, kZetas.size());
}

TEST(SweepFile, APartialFileIsRefusedWithoutResumeOrFromAnotherSweep) {
  const Folder dir;
  const fs::path out = dir.path / "s.csv";
  SweepControl stopping = threads(1);
  stopping.stop_requested = [] { return true; };
  ASSERT_EQ(sweep_to_file(kZetas, {}, stopping, file_at(out)).status, SweepFileOutcome::Status::stopped);
  const std::string partial = (dir.path / "s.csv.partial").string();
  SweepFile plain = file_at(out);
  plain.resume_option = "--again";
  try {
    sweep_to_file(kZetas, {}, threads(1), plain);
    ADD_FAILURE() << "no error";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(std::string(e.what()),
              "'" + partial + "' holds an interrupted sweep: add --again to continue it, or delete it");
  }
  SweepFile other = file_at(out, true);
  other.settings = "# another sweep";
  try {
    sweep_to_file(kZetas, {}, threads(1), other);
    ADD_FAILURE() << "no error";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find(partial + ":1: written by another sweep"), std::string::npos)
        << e.what();
  }
  EXPECT_TRUE(fs::exists(partial));  // refused, not touched
}

TEST(SweepFile, ColumnsMustHaveOneSpeedPerPoint) {
  const Folder dir;
  SweepFile file = file_at(dir.path / "v.csv");
  file.columns = SweepColumns{{1.0, 2.0}, 0.2, {}};
  EXPECT_THROW(sweep_to_file(kZetas, {}, threads(1), file), InvalidInput);
  EXPECT_FALSE(fs::exists(dir.path / "v.csv.partial"));
  file.path = dir.path;
  EXPECT_THROW(sweep_to_file(kZetas, {}, threads(1), file_at(dir.path)), InvalidInput);
}

}  // namespace
}  // namespace restitution
