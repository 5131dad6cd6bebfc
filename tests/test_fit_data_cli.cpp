// SPDX-License-Identifier: BSD-3-Clause
// `restitution fit-data`: the report, and bad input refused with exit 2, one line, nothing written.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cli_runner.hpp"

namespace restitution {
namespace {

using test_support::run_cli;

std::string write_csv(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::temp_directory_path() / ("restitution-fit-" + name + ".csv");
  std::ofstream(path) << text;
  return path.string();
}

const std::string kExample = std::string(RESTITUTION_SOURCE_DIR) + "/examples/fit/rubber_drop.csv";

TEST(FitDataCli, JsonHasTheDocumentedKeys) {
  const auto r = run_cli("fit-data " + kExample +
                         " --json --young-modulus 1e7 --poisson-ratio 0.4 --radius 0.01 --density 1100");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["fits"].size(), 4U);
  for (const auto& f : j["fits"]) {
    for (const char* key :
         {"law", "end", "parameter", "value", "ci68", "ci95", "chi2_per_dof", "aic", "converged"}) {
      EXPECT_TRUE(f.contains(key)) << key;
    }
    EXPECT_LE(f["ci95"][0].get<double>(), f["ci68"][0].get<double>());
    EXPECT_GE(f["ci95"][1].get<double>(), f["ci68"][1].get<double>());
  }
  EXPECT_EQ(j["fits"][0]["parameter"], "beta");
  EXPECT_EQ(j["fits"][3]["parameter"], "damping-ratio");
  EXPECT_FALSE(j["sigma_estimated"].get<bool>());
  // The example was made at the delayed-recovery end with beta = 0.2.
  EXPECT_EQ(j["best_law"], "viscoelastic-hertz");
  EXPECT_EQ(j["best_end"], "delayed-recovery");
  EXPECT_LE(j["fits"][0]["ci95"][0].get<double>(), 0.2);
  EXPECT_GE(j["fits"][0]["ci95"][1].get<double>(), 0.2);
  EXPECT_TRUE(j["dissipative_constant_s"].contains("ci95"));
}

TEST(FitDataCli, WithoutSigmaTheReportSaysTheScatterIsEstimated) {
  const auto path = write_csv("nosigma", "eps,v\n0.8,0.5\n0.78,1\n0.75,2\n");
  const auto r = run_cli("fit-data " + path);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("estimated from the residuals"), std::string::npos) << r.out;
  const auto j = nlohmann::json::parse(run_cli("fit-data " + path + " --json").out);
  EXPECT_TRUE(j["sigma_estimated"].get<bool>());
}

// A spreadsheet's byte-order mark is not part of the header; one point with σ has no χ²/dof, said so.
TEST(FitDataCli, ByteOrderMarkAndZeroDegreesOfFreedom) {
  const auto bom = write_csv("bom", "\xEF\xBB\xBFv,eps,sigma\n1,0.5,0.01\n");
  const auto r = run_cli("fit-data " + bom);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("1 point, "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("- (0 dof)"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("nan"), std::string::npos) << r.out;
}

TEST(FitDataCli, BadInputExitsTwoNamingTheLineAndWritesNothing) {
  const auto out = std::filesystem::temp_directory_path() / "restitution-fit-bad-out.json";
  std::filesystem::remove(out);
  struct Case {
    const char* name;
    const char* text;
    const char* needle;
  };
  for (const Case& c : {Case{"eps", "v,eps\n1,0.5\n2,1.2\n", ":3:3: column 'eps'"},
                        Case{"speed", "v,eps\n1,0.5\n-2,0.4\n", ":3:1: column 'v'"},
                        Case{"nan", "v,eps\n1,0.5\n2,nan\n", ":3:3: column 'eps'"},
                        Case{"sigma", "v,eps,sigma\n1,0.5,0.1\n2,0.4,0\n", ":3:7: column 'sigma'"},
                        Case{"text", "v,eps\n1,0.5\n2,abc\n", "'abc' is not a decimal number"},
                        Case{"fields", "v,eps\n1,0.5,3\n", ":2:1: 3 fields"},
                        Case{"header", "v,f\n1,0.5\n", "unknown column 'f'"}, Case{"empty", "", "empty"},
                        Case{"one", "v,eps\n1,0.5\n", "restitution-fit-one.csv: 1 point cannot fit"}}) {
    const auto path = write_csv(c.name, c.text);
    const auto r = run_cli("fit-data " + path + " --out " + out.string());
    EXPECT_EQ(r.status, 2) << c.name << ": " << r.err;
    EXPECT_NE(r.err.find(c.needle), std::string::npos) << c.name << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
    EXPECT_FALSE(std::filesystem::exists(out)) << c.name;
  }
}

}  // namespace
}  // namespace restitution

namespace restitution {
namespace {

TEST(FitDataCli, CalibrateFromFitCarriesTheIntervalsOver) {
  const auto json_path = (std::filesystem::temp_directory_path() / "restitution-fit-carry.json").string();
  ASSERT_EQ(test_support::run_cli("fit-data " + kExample + " --out " + json_path).status, 0);
  const auto r =
      test_support::run_cli("calibrate --from-fit " + json_path +
                            " --velocity 3 --json --young-modulus 1e7 --poisson-ratio 0.45 --radius "
                            "0.01 --density 1100");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const auto fit = nlohmann::json::parse(test_support::slurp(json_path));
  EXPECT_EQ(j["beta"], fit["fits"][0]["value"]);
  // ε decreases with β: the upper β bound gives the lower ε bound.
  EXPECT_LT(j["eps_ci95"][0].get<double>(), j["eps"].get<double>());
  EXPECT_GT(j["eps_ci95"][1].get<double>(), j["eps"].get<double>());
  EXPECT_LT(j["dissipative_constant_ci95"][0].get<double>(), j["dissipative_constant_s"].get<double>());
  const auto bad = test_support::run_cli("calibrate --from-fit /nonexistent.json --velocity 1");
  EXPECT_EQ(bad.status, 2);
}

TEST(FitDataCli, DemFromFitUsesTheFitsAAndSaysItsUncertainty) {
  const auto json_path = (std::filesystem::temp_directory_path() / "restitution-fit-dem.json").string();
  ASSERT_EQ(test_support::run_cli("fit-data " + kExample + " --out " + json_path).status, 0);
  const std::string material = " --young-modulus 1e7 --poisson-ratio 0.45 --radius 0.01 --density 1100";
  const auto r = test_support::run_cli("dem --code lammps --json --from-fit " + json_path + material);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["dissipative_constant_s"], j["from_fit"]["dissipative_constant_s"]);
  EXPECT_EQ(j["end"], "delayed-recovery");
  ASSERT_EQ(j["from_fit"]["eps"].size(), j["eps"].size());
  for (std::size_t i = 0; i < j["eps"].size(); ++i) {
    // The lines' ε at each speed lies in the interval the fit carries over.
    const double eps = j["eps"][i]["eps"].get<double>();
    EXPECT_NEAR(eps, j["from_fit"]["eps"][i]["eps"].get<double>(), 1e-9);
    EXPECT_LT(j["from_fit"]["eps"][i]["ci95"][0].get<double>(), eps);
    EXPECT_GT(j["from_fit"]["eps"][i]["ci95"][1].get<double>(), eps);
  }
  EXPECT_EQ(j["from_fit"]["eps_given_by"], "the lines above");
  EXPECT_EQ(test_support::run_cli("dem --code lammps --eps 0.5 --from-fit " + json_path + material).status,
            2);
}

// YADE 2023.02a cannot express the law: its lines give one ε at every speed, so the fit's ε(v) must be
// attributed to the lines of the version that can, never to the printed ones.
TEST(FitDataCli, DemFromFitOnAYadeWithoutTheLawNamesTheLinesThatGiveItsEps) {
  const auto json_path = (std::filesystem::temp_directory_path() / "restitution-fit-yade.json").string();
  ASSERT_EQ(test_support::run_cli("fit-data " + kExample + " --out " + json_path).status, 0);
  const std::string request = "dem --code yade --yade-version 2023.02a --from-fit " + json_path +
                              " --young-modulus 1e7 --poisson-ratio 0.45 --radius 0.01 --density 1100";
  const auto r = test_support::run_cli(request + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_TRUE(j.contains("yade_exact_law"));
  const std::string given_by = j["from_fit"]["eps_given_by"].get<std::string>();
  EXPECT_NE(given_by.find("2024.02a lines only, not the lines above"), std::string::npos) << given_by;
  ASSERT_EQ(j["from_fit"]["eps"].size(), j["yade_exact_law"]["eps"].size());
  for (std::size_t i = 0; i < j["from_fit"]["eps"].size(); ++i) {
    EXPECT_NEAR(j["from_fit"]["eps"][i]["eps"].get<double>(),
                j["yade_exact_law"]["eps"][i]["eps"].get<double>(), 1e-9);
  }
  const auto text = test_support::run_cli(request);
  ASSERT_EQ(text.status, 0) << text.err;
  EXPECT_NE(text.out.find("given by the YADE 2024.02a lines only"), std::string::npos) << text.out;
}

}  // namespace
}  // namespace restitution
