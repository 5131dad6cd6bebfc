// SPDX-License-Identifier: BSD-3-Clause
// Every command's --plot FILE (gas, oblique, fit-data) writes FILE in the format its extension names (png,
// pdf, svg), and refuses any other name with exit 2 naming the formats that work: one rule for every command,
// never a figure under another name than the one typed (issue 44, item 5: `gas --plot g.jpg` wrote g.png,
// `oblique --plot m.svg` wrote m.png, both exit 0 without a word). Runs the program and matplotlib.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "cli_runner.hpp"

namespace {

using restitution::test_support::CliOutcome;
using restitution::test_support::run_cli;
using restitution::test_support::slurp;
using restitution::test_support::TempFolder;

const std::string kGas =
    "gas --radius 0.005 --density 920 --eps 0.8 --velocity 2 --packing-fraction 0.1 --rms-speed 1 "
    "--haff-times 10 --points-per-decade 2";
const std::string kOblique =
    "oblique --young-modulus 2e11 --poisson-ratio 0.3 --radius 1e-3 --density 7800 --dissipative-constant "
    "1e-7 "
    "--wall --tangential "
    "mindlin "
    "--friction 0.3 --angle-range 5:45:20";
const std::string kFitData =
    std::string("fit-data ") + RESTITUTION_SOURCE_DIR + "/examples/fit/rubber_drop.csv";

std::vector<std::string> files_in(const std::filesystem::path& folder) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(folder))
    names.push_back(entry.path().filename());
  std::sort(names.begin(), names.end());
  return names;
}

CliOutcome plot(const std::string& command, const std::filesystem::path& file, const std::string& more = "") {
  return run_cli(command + " --plot " + file.string() + more);
}

TEST(PlotFileNames, AnUnknownExtensionIsRefusedByEveryCommand) {
  for (const std::string& command : {kGas, kOblique, kFitData}) {
    for (const std::string name : {"figure.jpg", "figure", "figure.PNG", "figure.png.bak"}) {
      const TempFolder folder;
      const CliOutcome r = plot(command, folder.path / name);
      EXPECT_EQ(r.status, 2) << command << " --plot " << name << ": " << r.err;
      EXPECT_NE(r.err.find("--plot"), std::string::npos) << r.err;
      EXPECT_NE(r.err.find(".png, .pdf, .svg"), std::string::npos) << r.err;
      EXPECT_TRUE(r.out.empty()) << r.out;
      EXPECT_TRUE(files_in(folder.path).empty()) << command << " --plot " << name << " wrote a file";
    }
  }
}

TEST(PlotFileNames, TheExtensionIsTheFormat) {
  const std::vector<std::pair<std::string, std::string>> cases = {{kGas, "gas.svg"},
                                                                  {kGas, "gas.pdf"},
                                                                  {kOblique, "maw.svg"},
                                                                  {kFitData, "fit.pdf"},
                                                                  {kFitData, "fit.png"}};
  for (const auto& [command, name] : cases) {
    const TempFolder folder;
    const CliOutcome r = plot(command, folder.path / name);
    ASSERT_EQ(r.status, 0) << command << " --plot " << name << ": " << r.err;
    EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
    // That file and nothing else: no figure in another format, no scratch table left behind.
    EXPECT_EQ(files_in(folder.path), std::vector<std::string>{name}) << command;
    const std::string head = slurp((folder.path / name).string()).substr(0, 5);
    const std::string format = name.substr(name.rfind('.') + 1);
    if (format == "pdf") EXPECT_EQ(head, "%PDF-") << name;
    if (format == "png") EXPECT_EQ(head.substr(1, 3), "PNG") << name;
    if (format == "svg")
      EXPECT_NE(slurp((folder.path / name).string()).find("<svg"), std::string::npos) << name;
  }
}

TEST(PlotFileNames, FormatAddsFormatsToTheOneThePlotNames) {
  for (const std::string& command : {kGas, kOblique, kFitData}) {
    const TempFolder folder;
    const CliOutcome r = plot(command, folder.path / "f.svg", " --format pdf,svg");
    ASSERT_EQ(r.status, 0) << command << ": " << r.err;
    EXPECT_EQ(files_in(folder.path), (std::vector<std::string>{"f.pdf", "f.svg"})) << command;
    // --format draws nothing by itself: without --plot it is a usage error, not a silently ignored option.
    const CliOutcome alone = run_cli(command + " --format pdf");
    EXPECT_EQ(alone.status, 2) << command << ": " << alone.err;
    EXPECT_NE(alone.err.find("--plot"), std::string::npos) << alone.err;
  }
}

}  // namespace
