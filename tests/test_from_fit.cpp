// SPDX-License-Identifier: BSD-3-Clause
// `calibrate --from-fit` and `dem --from-fit` as a user types them: the carried β passes the domain checks of
// a typed one, a fit file edited by hand is refused naming the key (exit 2, nothing on stdout), and a Hertz
// fit that the fit itself rejects is said so, without intervals.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli_runner.hpp"

namespace restitution {
namespace {

using test_support::run_cli;
using test_support::TempFolder;

const std::string kExample = std::string(RESTITUTION_SOURCE_DIR) + "/examples/fit/rubber_drop.csv";
const std::string kMaterial = " --young-modulus 1e7 --poisson-ratio 0.45 --radius 0.01 --density 1100";

std::string write(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path) << text;
  return path.string();
}

// The fit-data report of `csv`, written to `json`.
nlohmann::json fit_report(const std::string& csv, const std::filesystem::path& json) {
  const auto r = run_cli("fit-data " + csv + " --out " + json.string());
  EXPECT_EQ(r.status, 0) << r.err;
  return nlohmann::json::parse(test_support::slurp(json.string()));
}

// ε = 0.800 ± 0.01 at 8 speeds over four decades: no speed dependence, so Tsuji (and the dash-pot) win and
// the Hertz fit has χ²/dof of about 75 and residuals that rise with the speed.
std::string speed_independent_csv(const std::filesystem::path& folder) {
  return write(folder / "flat.csv",
               "v,eps,sigma\n0.01,0.80,0.01\n0.03,0.81,0.01\n0.1,0.79,0.01\n0.3,0.80,0.01\n1,0.81,0.01\n"
               "3,0.79,0.01\n10,0.80,0.01\n30,0.80,0.01\n");
}

TEST(FromFit, CalibrateRefusesAVelocityWhoseZetaIsOutsideTheCheckedRange) {
  const TempFolder folder;
  const auto fit = fit_report(kExample, folder.path / "fit.json");
  const std::string file = (folder.path / "fit.json").string();
  const auto r = run_cli("calibrate --from-fit " + file + " --velocity 1e40");
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_NE(r.err.find("--from-fit " + file), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("outside the checked range"), std::string::npos) << r.err;
  // The same β typed is refused the same way.
  const std::string beta = nlohmann::json(fit["fits"][0]["value"]).dump();
  EXPECT_EQ(run_cli("eps --beta " + beta + " --velocity 1e40").status, 2);
  // Inside the range the same file answers.
  EXPECT_EQ(run_cli("calibrate --from-fit " + file + " --velocity 1e20").status, 0);
}

struct Edit {
  const char* name;
  std::function<void(nlohmann::json&)> change;
  const char* key;  // the message names it
};

TEST(FromFit, AHandEditedFitFileIsRefusedNamingTheKey) {
  const TempFolder folder;
  const nlohmann::json fit = fit_report(kExample, folder.path / "fit.json");
  const std::vector<Edit> edits = {
      {"beta 1e300", [](nlohmann::json& j) { j["fits"][0]["value"] = 1e300; }, "fits[0].value"},
      {"beta 0", [](nlohmann::json& j) { j["fits"][0]["value"] = 0.0; }, "fits[0].value"},
      {"beta a string", [](nlohmann::json& j) { j["fits"][0]["value"] = "0.2"; }, "fits[0].value"},
      {"interval backwards",
       [](nlohmann::json& j) {
         j["fits"][0]["ci95"] = {j["fits"][0]["ci95"][1], j["fits"][0]["ci95"][0]};
       },
       "fits[0].ci95"},
      {"68 % outside 95 %",
       [](nlohmann::json& j) { j["fits"][0]["ci68"][0] = j["fits"][0]["ci95"][0].get<double>() / 2; },
       "fits[0].ci95"},
      {"interval of one", [](nlohmann::json& j) { j["fits"][0]["ci68"] = {0.1}; }, "fits[0].ci68"},
      {"best out of range", [](nlohmann::json& j) { j["best"] = 99; }, "best"},
      {"best negative", [](nlohmann::json& j) { j["best"] = -1; }, "best"},
      {"best not the lowest AIC", [](nlohmann::json& j) { j["best"] = 2; }, "best"},
      {"tied index out of range", [](nlohmann::json& j) { j["tied_with_best"] = {4}; }, "tied_with_best[0]"},
      {"no fits", [](nlohmann::json& j) { j.erase("fits"); }, "fits"},
      {"points a float", [](nlohmann::json& j) { j["points"] = 8.5; }, "points"},
      {"sigma_estimated a string", [](nlohmann::json& j) { j["sigma_estimated"] = "no"; }, "sigma_estimated"},
      {"unknown law", [](nlohmann::json& j) { j["fits"][0]["law"] = "hooke"; }, "fits[0].law"},
      {"aic null", [](nlohmann::json& j) { j["fits"][0]["aic"] = nullptr; }, "fits[0].aic"},
      {"residual verdict a number", [](nlohmann::json& j) { j["fits"][0]["residual_tests"]["verdict"] = 1; },
       "fits[0].residual_tests.verdict"},
  };
  for (const Edit& e : edits) {
    nlohmann::json edited = fit;
    e.change(edited);
    const std::string file = write(folder.path / "edited.json", edited.dump());
    for (const std::string& command : {"calibrate --from-fit " + file + " --velocity 1",
                                       "dem --code lammps --from-fit " + file + kMaterial}) {
      const auto r = run_cli(command);
      EXPECT_EQ(r.status, 2) << e.name << ": " << r.out;
      EXPECT_TRUE(r.out.empty()) << e.name << ": " << r.out;
      EXPECT_NE(r.err.find("--from-fit " + file + ": " + e.key + ": "), std::string::npos)
          << e.name << ": " << r.err;
      EXPECT_EQ(r.err.find("json.exception"), std::string::npos) << e.name << ": " << r.err;
    }
  }
}

// Not JSON at all, or JSON that is no report: the project's words, never the JSON library's.
TEST(FromFit, TextThatIsNoReportIsRefusedInTheProjectsWords) {
  const TempFolder folder;
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"{\"fits\": [1, 2", "not JSON"},
      {"{\"points\": 1e999}", "beyond the range of a double"},
      {"[1, 2]", "must be one JSON object"},
      {"{\"points\": 3, \"sigma_estimated\": false, \"fits\": {}}", "fits: must be a non-empty list"},
      {"{\"points\": 3, \"sigma_estimated\": false, \"fits\": [{\"law\": \"viscoelastic-hertz\\u0001" +
           std::string(80, 'x') + "\"}]}",
       "'viscoelastic-hertz\\x01xxxxxxxxxxxxxxxxxxxxx...'"},
  };
  for (const auto& [text, words] : cases) {
    const std::string file = write(folder.path / "bad.json", text);
    const auto r = run_cli("calibrate --from-fit " + file + " --velocity 1");
    EXPECT_EQ(r.status, 2) << text;
    EXPECT_NE(r.err.find("--from-fit " + file + ": "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(words), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("json.exception"), std::string::npos) << r.err;
  }
  const auto endless = run_cli("calibrate --from-fit /dev/zero --velocity 1");
  EXPECT_EQ(endless.status, 2);
  EXPECT_NE(endless.err.find("larger than 64 MiB"), std::string::npos) << endless.err;
}

TEST(FromFit, ARejectedHertzFitIsSaidSoAndCarriesNoInterval) {
  const TempFolder folder;
  const std::filesystem::path file = folder.path / "flat.json";
  const nlohmann::json fit = fit_report(speed_independent_csv(folder.path), file);
  ASSERT_EQ(fit["best_law"], "tsuji-hertz");  // the premise: the fit itself prefers a constant ε
  const std::string from_fit = " --from-fit " + file.string();

  const auto text = run_cli("calibrate --velocity 0.1" + from_fit);
  ASSERT_EQ(text.status, 0) << text.err;
  EXPECT_NE(text.out.find("warning: the fit rejects viscoelastic Hertz"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("best law is tsuji-hertz"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("chi2/dof = "), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("rises-with-speed"), std::string::npos) << text.out;
  EXPECT_EQ(text.out.find("95 % ["), std::string::npos) << text.out;

  const auto json = nlohmann::json::parse(run_cli("calibrate --velocity 0.1 --json" + from_fit).out);
  ASSERT_TRUE(json.contains("hertz_fit_rejected"));
  EXPECT_EQ(json["hertz_fit_rejected"].size(), 3U) << json["hertz_fit_rejected"];
  for (const char* key : {"beta_ci95", "eps_ci68", "eps_ci95"}) EXPECT_FALSE(json.contains(key)) << key;
  // The ε it still gives lies outside every measurement's σ, which is why no interval stands next to it.
  EXPECT_GT(json["eps"].get<double>(), 0.85);

  const auto dem = run_cli("dem --code lammps" + from_fit + kMaterial);
  ASSERT_EQ(dem.status, 0) << dem.err;
  EXPECT_NE(dem.out.find("# warning: the fit rejects viscoelastic Hertz"), std::string::npos) << dem.out;
  EXPECT_EQ(dem.out.find("the fit's uncertainty"), std::string::npos) << dem.out;
  const auto dem_json = nlohmann::json::parse(run_cli("dem --code lammps --json" + from_fit + kMaterial).out);
  ASSERT_TRUE(dem_json["from_fit"].contains("hertz_fit_rejected"));
  EXPECT_FALSE(dem_json["from_fit"].contains("dissipative_constant_ci95"));
  for (const auto& e : dem_json["from_fit"]["eps"]) EXPECT_FALSE(e.contains("ci95")) << e;
}

// The converse: a fit that the data support carries its intervals and no warning; and the Hertz end that
// lost to the other is said so when asked for by --end.
TEST(FromFit, AnAcceptedFitCarriesItsIntervalsAndTheOtherEndIsNotTheBest) {
  const TempFolder folder;
  const std::filesystem::path file = folder.path / "fit.json";
  const nlohmann::json fit = fit_report(kExample, file);
  ASSERT_EQ(fit["best_end"], "delayed-recovery");
  const auto json =
      nlohmann::json::parse(run_cli("calibrate --json --velocity 1 --from-fit " + file.string()).out);
  EXPECT_FALSE(json.contains("hertz_fit_rejected")) << json;
  EXPECT_TRUE(json.contains("eps_ci95"));
  const auto naive = nlohmann::json::parse(
      run_cli("calibrate --json --velocity 1 --end naive --from-fit " + file.string()).out);
  ASSERT_TRUE(naive.contains("hertz_fit_rejected")) << naive;
  EXPECT_NE(
      naive["hertz_fit_rejected"][0].get<std::string>().find("viscoelastic-hertz, delayed-recovery end"),
      std::string::npos)
      << naive;
}

// Noise-free data of one ε: the speed-independent fits have zero-width intervals whose bounds come out a
// rounding step apart in either order, and σ is estimated, so χ² tests nothing: the report is read, and the
// one reason left is the lower AIC of Tsuji.
TEST(FromFit, AReportOfNoiseFreeDataIsReadAndOnlyTheAicSpeaks) {
  const TempFolder folder;
  const std::filesystem::path file = folder.path / "exact.json";
  fit_report(write(folder.path / "exact.csv", "v,eps\n0.5,0.8\n1,0.8\n2,0.8\n"), file);
  const auto r = run_cli("calibrate --json --velocity 1 --from-fit " + file.string());
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["hertz_fit_rejected"].size(), 1U) << j;
  EXPECT_NE(j["hertz_fit_rejected"][0].get<std::string>().find("tsuji-hertz"), std::string::npos) << j;
}

}  // namespace
}  // namespace restitution
