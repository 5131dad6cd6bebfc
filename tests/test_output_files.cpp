#include "cli/output_files.hpp"

#include <gtest/gtest.h>

#include <fmt/core.h>
#include <unistd.h>
#include <cmath>
#include <filesystem>

#include <fstream>

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
  prepare_output_folder(folder / "nested");
  write_file_atomically(folder / "nested" / "a.csv", "x,y\n1,2\n");
  std::ifstream in(folder / "nested" / "a.csv");
  std::string first;
  std::getline(in, first);
  EXPECT_EQ(first, "x,y");
  EXPECT_FALSE(fs::exists(folder / "nested" / "a.csv.tmp"));
  fs::remove_all(folder);
}

TEST(OutputFiles, UnwritableFolderIsAnIoError) {
  EXPECT_THROW(prepare_output_folder("/proc/restitution-cannot-exist"), IoError);
  const fs::path folder = fresh_folder("file-in-the-way");
  fs::create_directories(folder);
  std::ofstream(folder / "plain-file") << "x";
  EXPECT_THROW(prepare_output_folder(folder / "plain-file"), IoError);
  EXPECT_THROW(write_file_atomically(folder / "missing" / "a.csv", "x"), IoError);
  fs::remove_all(folder);
}

TEST(OutputFiles, NumbersHaveSeventeenDigits) {
  EXPECT_EQ(number17(0.1), "0.10000000000000001");
  EXPECT_EQ(number17(std::nan("")), "nan");
  EXPECT_EQ(number17(-INFINITY), "-inf");
}

TEST(OutputFiles, MissingPlotScriptIsReportedNotThrown) {
  EXPECT_NE(run_plot_script("no-such-plot", {}).find("not found"), std::string::npos);
}

}  // namespace
}  // namespace restitution::cli
