// SPDX-License-Identifier: BSD-3-Clause
// The plot scripts' runner (cli/common/plot_script.hpp): what it says when no figure can be made.
#include "cli/common/plot_script.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace restitution::cli {
namespace {

TEST(PlotScript, MissingPlotScriptIsReportedNotThrown) {
  EXPECT_NE(run_plot_script("no-such-plot", "a.csv", "a.png").find("not found"), std::string::npos);
}

TEST(PlotScript, FigureNamesAndWarning) {
  EXPECT_EQ(figure_file_names("fig", {"png", "svg"}), (std::vector<std::string>{"fig.png", "fig.svg"}));
  EXPECT_EQ(no_plot_warning("gas", "no plot: script x not found"),
            "restitution: warning: no gas plot: script x not found\n");
}

}  // namespace
}  // namespace restitution::cli
