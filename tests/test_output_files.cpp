// SPDX-License-Identifier: BSD-3-Clause
// The files module's writes and checks (src/files): complete-or-absent files, streams in place, outputs kept
// apart from inputs and from each other, sets of files written together.
#include "files/output_files.hpp"

#include <fmt/core.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <stdexcept>
#include <string>

#include "files/file_set.hpp"
#include "files/output_guards.hpp"
#include "files/scratch_file.hpp"
#include "files/temporary_file.hpp"
#include "restitution/errors.hpp"
#include "sweep/number_text.hpp"

namespace restitution::files {
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

std::string slurp_file(const fs::path& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::size_t entries_in(const fs::path& folder) {
  return static_cast<std::size_t>(std::distance(fs::directory_iterator(folder), fs::directory_iterator()));
}

// One place under three names: a symbolic link to it, a hard link, a path through `..`; another file is not
// it, whether or not either exists yet.
TEST(OutputGuards, SameFilePlaceSeesThroughLinksAndDots) {
  const fs::path folder = fresh_folder("same-place");
  fs::create_directories(folder / "sub");
  std::ofstream(folder / "a.csv") << "x\n";
  fs::create_symlink("a.csv", folder / "soft.csv");
  fs::create_hard_link(folder / "a.csv", folder / "hard.csv");
  EXPECT_TRUE(same_file_place(folder / "soft.csv", folder / "a.csv"));
  EXPECT_TRUE(same_file_place(folder / "hard.csv", folder / "a.csv"));
  EXPECT_TRUE(same_file_place(folder / "sub" / ".." / "a.csv", folder / "a.csv"));
  fs::create_symlink("later.csv", folder / "dangling.csv");
  EXPECT_TRUE(same_file_place(folder / "dangling.csv", folder / "later.csv"));  // where writing would go
  EXPECT_FALSE(same_file_place(folder / "b.csv", folder / "a.csv"));
  EXPECT_FALSE(same_file_place(folder / "sub" / "a.csv", folder / "a.csv"));
  fs::remove_all(folder);
}

TEST(OutputGuards, OutputsApartNameBothOptions) {
  const fs::path folder = fresh_folder("apart");
  fs::create_directories(folder);
  std::ofstream(folder / "in.csv") << "x\n";
  fs::create_symlink("in.csv", folder / "link.csv");
  const auto message = [](const auto& check) -> std::string {
    try {
      check();
    } catch (const InvalidInput& e) {
      return e.what();
    }
    return "no error";
  };
  const std::string link = (folder / "link.csv").string();
  const std::string in = (folder / "in.csv").string();
  EXPECT_EQ(message([&] {
              check_outputs_apart({{"--out", folder / "link.csv"}}, {{"--data", folder / "in.csv"}});
            }),
            fmt::format(
                "--out '{}' is the input --data '{}': writing it would replace the input; name another file",
                link, in));
  EXPECT_EQ(
      message([&] {
        check_outputs_apart({{"--out", folder / "o.csv"}, {"--plot", folder / "o.csv"}}, {});
      }),
      fmt::format("--out '{0}' and --plot '{0}' are the same file: one would replace the other; name two "
                  "files",
                  (folder / "o.csv").string()));
  EXPECT_NO_THROW(check_outputs_apart({{"--out", folder / "o.csv"}, {"--plot", folder / "o.png"}},
                                      {{"--data", folder / "in.csv"}}));
  fs::remove_all(folder);
}

// A link into a folder that does not exist would make folders along the link's target: every output named
// on the command line is refused so, and nothing is created; a plain name in a missing folder is the user's.
TEST(OutputGuards, NoFolderIsCreatedThroughALink) {
  const fs::path folder = fresh_folder("through-link");
  fs::create_directories(folder);
  fs::create_symlink("missing/out.json", folder / "link.json");
  EXPECT_THROW(check_output_file(folder / "link.json"), InvalidInput);
  EXPECT_FALSE(fs::exists(folder / "missing"));
  fs::create_symlink("out.json", folder / "near.json");
  EXPECT_NO_THROW(check_output_file(folder / "near.json"));
  EXPECT_NO_THROW(check_output_file(folder / "plain.json"));
  EXPECT_NO_THROW(check_output_file(folder / "new" / "plain.json"));
  fs::remove_all(folder);
}

// A set is written whole, and a stop before the renames leaves the previous set and no temporary behind.
TEST(FileSet, AStopBeforeTheRenamesKeepsThePreviousSet) {
  const fs::path folder = fresh_folder("file-set");
  const std::string first = "first\n";
  const std::string second = "second\n";
  write_file_set({{folder / "a.txt", &first}, {folder / "b.txt", &first}}, [] {});
  EXPECT_EQ(slurp_file(folder / "a.txt"), first);
  EXPECT_EQ(slurp_file(folder / "b.txt"), first);
  int checks = 0;
  const auto stop_at_the_end = [&checks] {
    if (++checks == 3) throw std::runtime_error("stopped");  // after both temporaries were written
  };
  EXPECT_THROW(write_file_set({{folder / "a.txt", &second}, {folder / "b.txt", &second}}, stop_at_the_end),
               std::runtime_error);
  EXPECT_EQ(slurp_file(folder / "a.txt"), first);
  EXPECT_EQ(slurp_file(folder / "b.txt"), first);
  EXPECT_EQ(entries_in(folder), 2U);
  write_file_set({{folder / "a.txt", &second}, {folder / "b.txt", &second}}, [] {});
  EXPECT_EQ(slurp_file(folder / "b.txt"), second);
  EXPECT_EQ(entries_in(folder), 2U);
  fs::remove_all(folder);
}

// A plot's scratch data: under a random name beside the image, gone when the scope is left, by an exception
// too.
TEST(ScratchFile, WrittenBesideUnderARandomNameAndRemovedHoweverTheScopeIsLeft) {
  const fs::path folder = fresh_folder("scratch");
  fs::path first;
  {
    const ScratchFile scratch(folder / "m.png", "data.csv", "x,y\n");
    first = scratch.path();
    EXPECT_EQ(first.parent_path(), folder);  // the folder is made by the write
    EXPECT_TRUE(
        std::regex_match(first.filename().string(), std::regex(R"(m\.png\.[0-9a-f]{12}\.data\.csv)")));
    EXPECT_EQ(slurp_file(first), "x,y\n");
    const ScratchFile second(folder / "m.png", "data.csv", "");
    EXPECT_NE(second.path(), first);
  }
  EXPECT_FALSE(fs::exists(first));
  try {
    const ScratchFile scratch(folder / "m.png", "data.csv", "x\n");
    first = scratch.path();
    throw std::runtime_error("plot failed");
  } catch (const std::runtime_error&) {
  }
  EXPECT_FALSE(fs::exists(first));
  EXPECT_EQ(entries_in(folder), 0U);
  fs::remove_all(folder);
}

// A rename that fails (a folder in the target's place) removes the temporary and names the target.
TEST(TemporaryFile, AFailedRenameLeavesNoTemporary) {
  const fs::path folder = fresh_folder("rename");
  fs::create_directories(folder / "taken" / "inside");
  const fs::path temporary = write_temporary_beside(folder / "taken", "x\n");
  EXPECT_TRUE(fs::is_regular_file(temporary));
  try {
    rename_onto(temporary, folder / "taken");
    ADD_FAILURE() << "renamed onto a folder";
  } catch (const IoError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(fmt::format("cannot write '{}': ", (folder / "taken").string()), 0),
              0U);
  }
  EXPECT_FALSE(fs::exists(temporary));
  EXPECT_EQ(entries_in(folder), 1U);
  fs::remove_all(folder);
}

}  // namespace
}  // namespace restitution::files
