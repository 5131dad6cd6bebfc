// SPDX-License-Identifier: BSD-3-Clause
// Where the program finds its scripts, scenes and data: in the build tree, the source tree named by the
// marker beside the program (src/CMakeLists.txt); and no path of the build machine compiled into the program,
// which `cmake --install` copies as it is.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "cli/resource_root.hpp"

namespace {

namespace fs = std::filesystem;

TEST(ResourceRoot, BuildTreeProgramsReadTheSourceTree) {
  // This test program runs from build/<preset>/tests/, one folder below the marker.
  const fs::path root = restitution::cli::resource_root();
  EXPECT_TRUE(fs::equivalent(root, RESTITUTION_SOURCE_DIR)) << root;
  EXPECT_TRUE(fs::exists(root / "scenes" / "default.toml"));
  EXPECT_TRUE(fs::is_directory(root / "scripts" / "plots"));
}

TEST(ResourceRoot, NoSourcePathInTheProgram) {
  std::ifstream program(RESTITUTION_EXE, std::ios::binary);
  ASSERT_TRUE(program) << RESTITUTION_EXE;
  const std::string bytes{std::istreambuf_iterator<char>(program), std::istreambuf_iterator<char>()};
  ASSERT_GT(bytes.size(), 100000U);
  EXPECT_EQ(bytes.find(RESTITUTION_SOURCE_DIR), std::string::npos)
      << "the program contains the source path " << RESTITUTION_SOURCE_DIR;
}

}  // namespace
