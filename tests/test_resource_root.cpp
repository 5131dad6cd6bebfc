// SPDX-License-Identifier: BSD-3-Clause
// Where the program finds its scripts, scenes and data: in the build tree, the source tree named by the
// marker beside the program (src/CMakeLists.txt); and no path of the build machine compiled into the program,
// which `cmake --install` copies as it is.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "cli/common/resource_root.hpp"

namespace {

namespace fs = std::filesystem;

TEST(ResourceRoot, BuildTreeProgramsReadTheSourceTree) {
  // This test program runs from build/<preset>/tests/, one folder below the marker.
  const fs::path root = restitution::cli::resource_root();
  EXPECT_TRUE(fs::equivalent(root, RESTITUTION_SOURCE_DIR)) << root;
  EXPECT_TRUE(fs::exists(root / "scenes" / "default.toml"));
  EXPECT_TRUE(fs::is_directory(root / "scripts" / "plots"));
}

// ASan and UBSan name the source file of every instrumented check and lambda in the program, by the path the
// compiler was given (absolute, from CMake; clang 14 does not remap those with -ffile-prefix-map): there the
// path is instrumentation, not a resource lookup. The release build checks the program itself.
#if defined(__SANITIZE_ADDRESS__)
#define RESTITUTION_SANITIZED_BUILD 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(undefined_behavior_sanitizer)
#define RESTITUTION_SANITIZED_BUILD 1
#endif
#endif

TEST(ResourceRoot, NoSourcePathInTheProgram) {
#ifdef RESTITUTION_SANITIZED_BUILD
  GTEST_SKIP() << "sanitizer instrumentation names the source files; the release build checks this";
#endif
  std::ifstream program(RESTITUTION_EXE, std::ios::binary);
  ASSERT_TRUE(program) << RESTITUTION_EXE;
  const std::string bytes{std::istreambuf_iterator<char>(program), std::istreambuf_iterator<char>()};
  ASSERT_GT(bytes.size(), 100000U);
  // A compiler may build a string constant from 16-byte immediates ("/work/src/resti" + "ution/scripts"), so
  // neither end of the path may appear, not only the whole of it.
  const std::string source = RESTITUTION_SOURCE_DIR;
  const std::size_t piece = std::min<std::size_t>(source.size(), 16);
  for (const std::string& part : {source.substr(0, piece), source.substr(source.size() - piece)}) {
    EXPECT_EQ(bytes.find(part), std::string::npos) << "the program contains '" << part << "' of " << source;
  }
}

}  // namespace
