// SPDX-License-Identifier: BSD-3-Clause
// One vocabulary across commands, scene keys and messages (issue 44, item 13; docs/cli.md, "Spellings"): the
// new spellings work, the old ones still do with one warning line naming the new, --help lists only the new;
// messages name what was typed; a scene's ranges and [[gas]] keys are the command line's.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "cli_runner.hpp"

namespace {

using restitution::test_support::CliOutcome;
using restitution::test_support::lines_of;
using restitution::test_support::run_cli;
using restitution::test_support::slurp;
using restitution::test_support::TempFolder;

const std::string kSteel =
    " --young-modulus 2e11 --poisson-ratio 0.3 --radius 1e-3 --density 7800 --dissipative-constant 1e-7";
const std::string kRubber = " --young-modulus 1e7 --poisson-ratio 0.45 --radius 0.01 --density 1100";

// The old spelling gives the new one's output, with exactly one warning line on stderr that names the new.
void expect_alias(const std::string& old_arguments, const std::string& new_arguments,
                  const std::string& now) {
  const CliOutcome current = run_cli(new_arguments);
  const CliOutcome old = run_cli(old_arguments);
  ASSERT_EQ(current.status, 0) << new_arguments << ": " << current.err;
  EXPECT_EQ(current.err, "") << new_arguments;
  EXPECT_EQ(old.status, 0) << old_arguments << ": " << old.err;
  EXPECT_EQ(old.out, current.out) << old_arguments;
  const std::vector<std::string> warning = lines_of(old.err);
  ASSERT_EQ(warning.size(), 1U) << old.err;
  EXPECT_NE(warning[0].find("deprecated"), std::string::npos) << warning[0];
  EXPECT_NE(warning[0].find("use " + now), std::string::npos) << warning[0];
}

TEST(Vocabulary, ImpactVelocityAndTheOldSpeedAndSpeeds) {
  expect_alias("oblique" + kSteel + " --friction 0.3 --angle 30 --speed 2 --json",
               "oblique" + kSteel + " --friction 0.3 --angle 30 --impact-velocity 2 --json",
               "--impact-velocity");
  // dem's list, space-separated as before or comma-separated; repeated, the warning is still one line.
  const std::string dem = "dem --code lammps --eps 0.8 --velocity 1 --json" + kRubber;
  expect_alias(dem + " --speeds 0.5 2 --speeds 4", dem + " --impact-velocity 0.5,2,4", "--impact-velocity");
  EXPECT_NE(run_cli(dem + " --impact-velocity 0.5 2").out.find("{\"velocity_m_s\":2.0,"), std::string::npos);
}

TEST(Vocabulary, AngleForDemAsForOblique) {
  const std::string dem = "dem --code lammps --friction 0.3 --json" + kSteel;
  expect_alias(dem + " --angles 10,40", dem + " --angle 10,40", "--angle");
}

TEST(Vocabulary, OutForEveryOutput) {
  const TempFolder t;
  const std::string csv = std::string(RESTITUTION_SOURCE_DIR) + "/examples/fit/rubber_drop.csv";
  const std::string a = (t.path / "a.json").string();
  const std::string b = (t.path / "b.json").string();
  const CliOutcome old = run_cli("fit-data " + csv + " --output " + a);
  const CliOutcome now = run_cli("fit-data " + csv + " --out " + b);
  ASSERT_EQ(now.status, 0) << now.err;
  ASSERT_EQ(old.status, 0) << old.err;
  EXPECT_EQ(lines_of(old.err).size(), 1U) << old.err;
  EXPECT_NE(old.err.find("--output is deprecated"), std::string::npos) << old.err;
  EXPECT_EQ(slurp(a), slurp(b));
  EXPECT_FALSE(slurp(a).empty());

  const std::string scene = std::string(RESTITUTION_SOURCE_DIR) + "/scenes/dashpot.toml --quick";
  const CliOutcome run_old = run_cli("run " + scene + " --output " + (t.path / "old").string());
  EXPECT_EQ(run_old.status, 0) << run_old.err;
  EXPECT_NE(run_old.err.find("--output is deprecated"), std::string::npos) << run_old.err;
  EXPECT_TRUE(std::filesystem::exists(t.path / "old" / "report.md"));
  // The folder's name right after --out, the scene after it: the old spelling takes one value as the new.
  const CliOutcome ordered = run_cli("run --output " + (t.path / "third").string() + " " + scene);
  EXPECT_EQ(ordered.status, 0) << ordered.err;
}

// A sweep's old --zeta-min A --zeta-max B --points N writes the bytes of --zeta-range A:B:N, in either
// spacing.
TEST(Vocabulary, OneRangeSyntaxForSweep) {
  const TempFolder t;
  for (const auto& [old_form, new_form] : std::vector<std::pair<std::string, std::string>>{
           {"--zeta-min 0.1 --zeta-max 10 --points 5 --log", "--zeta-range 0.1:10:5 --log"},
           {"--zeta-min 0 --zeta-max 2 --points 4", "--zeta-range 0:2:4"}}) {
    const std::string a = (t.path / "old.csv").string();
    const std::string b = (t.path / "new.csv").string();
    const CliOutcome old = run_cli("sweep " + old_form + " --out " + a);
    const CliOutcome now = run_cli("sweep " + new_form + " --out " + b);
    ASSERT_EQ(now.status, 0) << new_form << ": " << now.err;
    EXPECT_EQ(now.err, "") << new_form;
    ASSERT_EQ(old.status, 0) << old_form << ": " << old.err;
    const std::vector<std::string> warning = lines_of(old.err);
    ASSERT_EQ(warning.size(), 1U) << old.err;
    EXPECT_NE(warning[0].find("--zeta-min A --zeta-max B --points N is deprecated"), std::string::npos)
        << warning[0];
    EXPECT_NE(warning[0].find("use --zeta-range A:B:N"), std::string::npos) << warning[0];
    EXPECT_EQ(slurp(a), slurp(b)) << new_form;  // the settings line of a resumable file included
    EXPECT_GT(lines_of(slurp(b)).size(), 4U) << new_form;
  }
  for (const auto& [arguments, message] : std::vector<std::pair<std::string, std::string>>{
           {"--zeta-range 0:2", "--zeta-range must be FROM:TO:N"},
           {"--zeta-range 0:2:0", "N must be a whole number in [1, 10000000]"},
           {"--zeta-range 3:2:3", "--zeta-range '3:2:3': zeta-min (3) must not exceed zeta-max (2)"},
           {"--zeta-range 0:2:3 --points 3", "give it alone"},
           {"--points 3", "give --zeta-range FROM:TO:N"}}) {
    const CliOutcome r = run_cli("sweep " + arguments + " --out " + (t.path / "bad.csv").string());
    EXPECT_EQ(r.status, 2) << arguments;
    EXPECT_EQ(lines_of(r.err).size(), 1U) << r.err;
    EXPECT_NE(r.err.find(message), std::string::npos) << arguments << ": " << r.err;
  }
}

// The other ranges of the old form: a sweep's impact speeds, fit's ζ (its old default of 9 points written
// out) and damping-check's speeds (its defaults are the range 0.1:10:5) give the bytes of FROM:TO:N.
TEST(Vocabulary, OneRangeSyntaxForSpeedsAndFits) {
  const TempFolder t;
  const std::string a = (t.path / "old.csv").string();
  const std::string b = (t.path / "new.csv").string();
  const CliOutcome old =
      run_cli("sweep --beta 0.2 --velocity-min 0.01 --velocity-max 100 --points 5 --log --out " + a);
  const CliOutcome now = run_cli("sweep --beta 0.2 --velocity-range 0.01:100:5 --log --out " + b);
  ASSERT_EQ(now.status, 0) << now.err;
  EXPECT_EQ(now.err, "");
  ASSERT_EQ(old.status, 0) << old.err;
  ASSERT_EQ(lines_of(old.err).size(), 1U) << old.err;
  EXPECT_NE(old.err.find("use --velocity-range V1:V2:N"), std::string::npos) << old.err;
  EXPECT_EQ(slurp(a), slurp(b));
  EXPECT_EQ(lines_of(slurp(b)).size(), 6U);  // the header and five speeds

  expect_alias("fit --end naive --zeta-min 10 --zeta-max 1e5 --points 4 --json",
               "fit --end naive --zeta-range 10:1e5:4 --json", "--zeta-range A:B:N");
  expect_alias("fit --end delayed-recovery --zeta-min 1 --zeta-max 10",
               "fit --end delayed-recovery --zeta-range 1:10:9", "--zeta-range A:B:N");
  const std::string check = "damping-check --recipe pade-1-4 --eps 0.5 --json";
  expect_alias(check + " --velocity-min 0.2 --velocity-max 5 --points 3", check + " --velocity-range 0.2:5:3",
               "--velocity-range V1:V2:N");
  EXPECT_EQ(run_cli(check).out, run_cli(check + " --velocity-range 0.1:10:5").out);

  for (const auto& [arguments, message] : std::vector<std::pair<std::string, std::string>>{
           {"fit --end naive", "--zeta-range FROM:TO:N is required"},
           {"fit --end naive --zeta-range 1:10:9 --points 3", "give it alone"},
           {"fit --end naive --zeta-range 1:10:2", "N must be a whole number in [3, 100000]"},
           {"fit --end naive --zeta-range 0:10:9", "--zeta-range '0:10:9': need 0 < zeta-min < zeta-max"},
           {"sweep --beta 0.2 --velocity-range 0:1:3 --out " + a,
            "--velocity-range '0:1:3': velocity must be"},
           {"sweep --beta 0.2 --velocity-range 1:2:3 --points 3 --out " + a, "give it alone"},
           {"sweep --beta 0.2 --velocity-range 1:2:3 --zeta-range 0:1:3 --out " + a, "not both"},
           {check + " --velocity-range -1:2:3", "--velocity-range '-1:2:3': the smallest impact speed"},
           {check + " --velocity-range 1:2:3 --points 3", "give it alone"}}) {
    const CliOutcome r = run_cli(arguments);
    EXPECT_EQ(r.status, 2) << arguments;
    EXPECT_NE(r.err.find(message), std::string::npos) << arguments << ": " << r.err;
  }
}

// dem's old --radius-range RMIN,RMAX --classes N prints the bytes of --radius-range RMIN:RMAX:N.
TEST(Vocabulary, OneRangeSyntaxForDem) {
  const std::string dem =
      "dem --code liggghts --young-modulus 2.1e11 --poisson-ratio 0.3 --density 7850 --eps 0.9 --velocity 1 "
      "--json";
  expect_alias(dem + " --radius-range 0.001,0.004 --classes 4", dem + " --radius-range 0.001:0.004:4",
               "--radius-range RMIN:RMAX:N");
  const CliOutcome classes = run_cli(dem + " --radius-range 0.001:0.004:4");
  EXPECT_NE(classes.out.find("0.004"), std::string::npos);
  for (const auto& [arguments, message] : std::vector<std::pair<std::string, std::string>>{
           {" --radius-range 0.004:0.001:4", "--radius-range must be RMIN:RMAX:N with 0 < RMIN < RMAX"},
           {" --radius-range 0.001:0.004:101", "N must be a whole number in [1, 100]"},
           {" --radius-range 0.001:0.004:4 --classes 4", "drop --classes"},
           {" --radius-range 0.001,0.004", "--radius-range RMIN:RMAX:N"}}) {
    const CliOutcome r = run_cli(dem + arguments);
    EXPECT_EQ(r.status, 2) << arguments;
    EXPECT_NE(r.err.find(message), std::string::npos) << arguments << ": " << r.err;
  }
}

TEST(Vocabulary, HelpListsOnlyTheNewSpellings) {
  for (const auto& [command, old_name, new_name] :
       std::vector<std::tuple<std::string, std::string, std::string>>{
           {"oblique", "--speed ", "--impact-velocity"},
           {"dem", "--speeds", "--impact-velocity"},
           {"dem", "--angles", "--angle "},
           {"run", "--output", "--out "},
           {"fit-data", "--output", "--out "},
           {"sweep", "--zeta-min", "--zeta-range"},
           {"sweep", "--velocity-min", "--velocity-range"},
           {"fit", "--zeta-min", "--zeta-range"},
           {"damping-check", "--velocity-min", "--velocity-range"},
           {"dem", "--classes", "--radius-range RMIN:RMAX:N"}}) {
    const std::string help = run_cli(command + " --help").out;
    EXPECT_EQ(help.find(old_name), std::string::npos) << command << " --help lists " << old_name;
    EXPECT_NE(help.find(new_name), std::string::npos) << command << " --help lacks " << new_name;
  }
}

TEST(Vocabulary, UnexpectedArgumentsAreAnsweredWithWhatTheCommandTakes) {
  const CliOutcome r = run_cli("eps 1 --velocity 0.8 --eps");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(lines_of(r.err).size(), 1U) << r.err;
  EXPECT_NE(r.err.find("restitution eps does not take '1 --eps'"), std::string::npos) << r.err;  // as typed
  EXPECT_NE(r.err.find("it takes --zeta, --beta, --velocity"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("not expected"), std::string::npos) << r.err;
  // A subcommand of a group, and hidden old spellings left unmentioned.
  const CliOutcome eval = run_cli("series eval --kind naive-series --zeta 0.5 extra");
  EXPECT_NE(eval.err.find("restitution series eval does not take 'extra': it takes --kind"),
            std::string::npos)
      << eval.err;
  const CliOutcome dem = run_cli("dem --code lammps 3" + kRubber);
  EXPECT_NE(dem.err.find("--impact-velocity"), std::string::npos) << dem.err;
  EXPECT_EQ(dem.err.find("--speeds"), std::string::npos) << dem.err;
}

TEST(Vocabulary, MessagesNameWhatWasTyped) {
  const CliOutcome range = run_cli("oblique" + kSteel + " --friction 0.3 --angle-range 1:95:5");
  EXPECT_EQ(range.status, 2);
  EXPECT_NE(range.err.find("--angle-range"), std::string::npos) << range.err;
  EXPECT_EQ(range.err.find("--angle must"), std::string::npos) << range.err;
  const CliOutcome first = run_cli(
      "gas --radius 0.005 --density 920 --eps 0.8 --velocity 2 --packing-fraction 0.1 --rms-speed 1 "
      "--haff-times 1000 --first-time 1e10");
  EXPECT_EQ(first.status, 2);
  EXPECT_NE(first.err.find("--first-time must be below the duration"), std::string::npos) << first.err;
  EXPECT_EQ(first.err.find("first_time"), std::string::npos) << first.err;
  const CliOutcome speed = run_cli("oblique" + kSteel + " --friction 0.3 --angle 10 --impact-velocity 0");
  EXPECT_NE(speed.err.find("--impact-velocity must be"), std::string::npos) << speed.err;
}

TEST(Vocabulary, AFigureNotMadeIsSaidOnce) {
  const TempFolder t;
  setenv("RESTITUTION_PYTHON", "/nonexistent/python3", 1);  // no matplotlib: the warning is what is tested
  const CliOutcome r =
      run_cli("oblique" + kSteel + " --friction 0.3 --angle 30 --plot " + (t.path / "maw.png").string());
  unsetenv("RESTITUTION_PYTHON");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("no oblique plot: /nonexistent/python3 cannot import matplotlib"), std::string::npos)
      << r.err;
  EXPECT_EQ(r.err.find("no plot: no plot"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("plot: no plot"), std::string::npos) << r.err;
}

const std::string kMaterial = R"([materials.steel]
young_modulus = 2e11
poisson_ratio = 0.3
density = 7800.0
radius = 1e-3
dissipative_constant = 1e-7
)";

// Column `column` (0-based) of a CSV's rows, as text.
std::vector<std::string> column_of(const std::string& csv, std::size_t column) {
  std::vector<std::string> values;
  const std::vector<std::string> rows = lines_of(csv);
  for (std::size_t i = 1; i < rows.size(); ++i) {
    std::size_t start = 0;
    for (std::size_t c = 0; c < column; ++c) start = rows[i].find(',', start) + 1;
    values.push_back(rows[i].substr(start, rows[i].find(',', start) - start));
  }
  return values;
}

TEST(Vocabulary, SceneAngleRangeIsTheCommandLinesGrid) {
  const TempFolder t;
  const std::filesystem::path scene = t.path / "o.toml";
  std::ofstream(scene)
      << "output = \"o\"\n" + kMaterial +
             "[[oblique]]\nname = \"grid\"\nmaterial = \"steel\"\nfriction = 0.3\nplot = false\n"
             "angles = { from = 1.0, to = 43.0, points = 15 }\nimpact_velocity = 2.0\n";
  const CliOutcome run = run_cli("run " + scene.string() + " --out " + (t.path / "out").string());
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_EQ(run.err.find("warning"), std::string::npos) << run.err;
  const std::string cli_csv = (t.path / "cli.csv").string();
  const CliOutcome cli = run_cli(
      "oblique" + kSteel + " --friction 0.3 --angle-range 1:43:15 --impact-velocity 2 --out " + cli_csv);
  ASSERT_EQ(cli.status, 0) << cli.err;
  const std::vector<std::string> from_scene = column_of(slurp((t.path / "out" / "grid.csv").string()), 1);
  const std::vector<std::string> from_cli = column_of(slurp(cli_csv), 0);
  EXPECT_EQ(from_scene, from_cli);
  ASSERT_EQ(from_cli.size(), 15U);
  EXPECT_EQ(from_cli[9], "28");  // (1·5 + 43·9)/14 in one rounding; 1 + (9/14)·42 is 28.000000000000004

  // The old key still works, with one warning naming the new.
  std::ofstream(scene)
      << "output = \"o\"\n" + kMaterial +
             "[[oblique]]\nname = \"grid\"\nmaterial = \"steel\"\nfriction = 0.3\nplot = false\n"
             "angles = [30.0]\nspeed = 2.0\n";
  const CliOutcome old = run_cli("run " + scene.string() + " --out " + (t.path / "old").string());
  EXPECT_EQ(old.status, 0) << old.err;
  EXPECT_NE(old.err.find("the key speed is deprecated and will be removed in 0.5.0; use impact_velocity"),
            std::string::npos)
      << old.err;
}

TEST(Vocabulary, GasSceneTakesTheCommandsSettings) {
  const TempFolder t;
  const std::filesystem::path scene = t.path / "g.toml";
  std::ofstream(scene)
      << "output = \"o\"\n[materials.pe]\nyoung_modulus = 1e8\npoisson_ratio = 0.4\n"
         "density = 920.0\nradius = 0.005\ndissipative_constant = 1e-5\n"
         "[[gas]]\nname = \"g\"\nmaterial = \"pe\"\npacking_fraction = 0.1\nrms_speed = 1.0\n"
         "haff_times = 100.0\nfirst_time = 0.5\ncollision_rate_factor = 1.2\ntolerance = 1e-8\n";
  const CliOutcome run = run_cli("run " + scene.string() + " --out " + (t.path / "out").string());
  ASSERT_EQ(run.status, 0) << run.err;
  const std::string cli_csv = (t.path / "cli.csv").string();
  const CliOutcome cli = run_cli(
      "gas --radius 0.005 --density 920 --young-modulus 1e8 --poisson-ratio 0.4 --dissipative-constant 1e-5 "
      "--packing-fraction 0.1 --rms-speed 1 --haff-times 100 --first-time 0.5 --collision-rate-factor 1.2 "
      "--tolerance 1e-8 --out " +
      cli_csv);
  ASSERT_EQ(cli.status, 0) << cli.err;
  const std::string table = slurp((t.path / "out" / "g.csv").string());
  EXPECT_EQ(table, slurp(cli_csv));
  EXPECT_EQ(column_of(table, 0).front(), "0.5");
}

}  // namespace
