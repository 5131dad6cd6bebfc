// SPDX-License-Identifier: BSD-3-Clause
#include "cli/common/output_files.hpp"

#include <gtest/gtest.h>

#include <fmt/core.h>
#include <unistd.h>
#include <cmath>
#include <filesystem>

#include <fstream>

#include "cli/common/io_error.hpp"
#include "restitution/errors.hpp"

namespace restitution::cli {
namespace {
namespace fs = std::filesystem;

fs::path fresh_folder(const char* name) {
  const fs::path folder = fs::temp_directory_path() / fmt::format("restitution-test-{}-{}", name, getpid());
  fs::remove_all(folder);
  return folder;
}

TEST(OutputFiles, AtomicWriteLeavesOnlyTheFinalFile) {
  const fs::path folder = fresh_folder("atomic");
  check_output_folder(folder / "nested");
  write_file_atomically(folder / "nested" / "a.csv", "x,y\n1,2\n");
  std::ifstream in(folder / "nested" / "a.csv");
  std::string first;
  std::getline(in, first);
  EXPECT_EQ(first, "x,y");
  EXPECT_FALSE(fs::exists(folder / "nested" / "a.csv.tmp"));
  fs::remove_all(folder);
}

TEST(OutputFiles, UnwritableOutputsAreRefused) {
  const fs::path folder = fresh_folder("file-in-the-way");
  fs::create_directories(folder);
  std::ofstream(folder / "plain-file") << "x";
  EXPECT_THROW(check_output_folder(folder / "plain-file"), IoError);
  EXPECT_THROW(check_output_folder(folder / "plain-file" / "below"), IoError);
  EXPECT_THROW(check_output_file(folder), InvalidInput);  // a folder where a file is expected
  fs::remove_all(folder);
}

// Checking a folder creates nothing: a run that fails before writing leaves no empty folder (item 11).
TEST(OutputFiles, CheckingCreatesNothingAndTheFirstWriteCreatesTheFolder) {
  const fs::path folder = fresh_folder("lazy");
  check_output_folder(folder / "a" / "b");
  EXPECT_FALSE(fs::exists(folder));
  write_file_atomically(folder / "a" / "b" / "t.csv", "x\n");
  EXPECT_TRUE(fs::is_regular_file(folder / "a" / "b" / "t.csv"));
  fs::remove_all(folder);
}

// A symlink is followed and its target replaced; the link stays a link (item 8).
TEST(OutputFiles, SymlinkTargetIsReplacedAndTheLinkKept) {
  const fs::path folder = fresh_folder("symlink");
  fs::create_directories(folder / "data");
  std::ofstream(folder / "data" / "real.csv") << "old\n";
  fs::create_symlink("data/real.csv", folder / "link.csv");
  write_file_atomically(folder / "link.csv", "new\n");
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(folder / "link.csv")));
  std::ifstream in(folder / "data" / "real.csv");
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "new");
  EXPECT_FALSE(fs::exists(folder / "data" / "real.csv.tmp"));
  // A dangling link: its target is created.
  fs::create_symlink("data/later.csv", folder / "dangling.csv");
  write_file_atomically(folder / "dangling.csv", "x\n");
  EXPECT_TRUE(fs::is_regular_file(folder / "data" / "later.csv"));
  fs::remove_all(folder);
}

// Devices, FIFOs and /dev/stdout are written in place, never replaced by a regular file (item 8).
TEST(OutputFiles, StreamsAreWrittenInPlace) {
  EXPECT_TRUE(output_target("/dev/null").in_place);
  EXPECT_TRUE(output_target("/dev/stdout").in_place);
  write_file_atomically("/dev/null", "x\n");
  EXPECT_TRUE(fs::is_character_file("/dev/null"));
  EXPECT_THROW(write_file_atomically("/dev/full", "x\n"), IoError);
}

TEST(OutputFiles, NumbersHaveSeventeenDigits) {
  EXPECT_EQ(number17(0.1), "0.10000000000000001");
  EXPECT_EQ(number17(std::nan("")), "nan");
  EXPECT_EQ(number17(-INFINITY), "-inf");
}

TEST(OutputFiles, MissingPlotScriptIsReportedNotThrown) {
  EXPECT_NE(run_plot_script("no-such-plot", "a.csv", "a.png").find("not found"), std::string::npos);
}

}  // namespace
}  // namespace restitution::cli
