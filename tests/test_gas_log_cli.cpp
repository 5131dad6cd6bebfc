// SPDX-License-Identifier: BSD-3-Clause
// `restitution gas --compare LOG` on logs as they go wrong: garbled numbers, a run cut while printing, CRLF
// line ends, two runs appended to one log, a FIFO, a device, a folder, a missing file, a line without end,
// and logs of another gas than the command's. The logs are Haff's law at 0.9 of Enskog's rate, opened by the
// setup line of a deck that `gas --deck` wrote for the same options (so they are what a real run prints).
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

#include "cli_runner.hpp"

namespace {

using restitution::test_support::run_cli;
using restitution::test_support::slurp;
using restitution::test_support::spawn_cli;
using restitution::test_support::TempFolder;

const std::string kGas =
    "gas --young-modulus 1e8 --poisson-ratio 0.4 --density 920 --radius 0.005 --eps 0.8 --velocity 2 "
    "--packing-fraction 0.1 --rms-speed 1 --haff-times 30 ";

// The text of the deck's `print "restitution-gas-setup law=LAW ..."` command in `input`.
std::string setup_line(const std::string& input) {
  const std::string start = "print \"restitution-gas-setup ";
  const auto at = input.find(start);
  if (at == std::string::npos) return "";
  const auto begin = at + 7;
  return input.substr(begin, input.find('"', begin) - begin);
}

// The setup line of the constant-eps run of a deck written with `options` (kGas unless given).
std::string deck_setup(const std::string& options = kGas) {
  TempFolder folder;
  const auto r = run_cli(options + "--particles 20 --deck " + (folder.path / "g.in").string());
  EXPECT_EQ(r.status, 0) << r.err;
  return setup_line(slurp((folder.path / "g_constant_eps.in").string()));
}

// A constant-eps run of the gas of kGas: T0 = m rms^2, Haff's law at 0.9 of the rate of `gas --json`'s tau0.
std::string haff_log(const std::string& setup, const std::string& law = "constant-eps") {
  static const double tau0 = [] {
    const auto theory = run_cli(
        "gas --radius 0.005 --density 920 --law tsuji-hertz --eps 0.8 --velocity 2 --packing-fraction 0.1 "
        "--rms-speed 1 --haff-times 30 --json");
    return nlohmann::json::parse(theory.out).at("tau0_s").get<double>();
  }();
  const double t0 = 920.0 * 4.0 / 3.0 * M_PI * std::pow(0.005, 3);
  std::ostringstream log;
  log.precision(10);
  log << "LAMMPS (7 Jan 2022)\nprint \"" << setup << "\"\n" << setup << "\n";
  for (int i = 0; i <= 30; ++i) {
    const double t = i == 0 ? 0.0 : 0.1 * tau0 * std::pow(10.0, (i - 1) / 10.0);
    log << "restitution-gas law=" << law << " time_s=" << t
        << " temperature_j=" << t0 / std::pow(1.0 + 0.9 * t / tau0, 2) << " timestep_s=5e-06 step=" << i
        << "\n";
  }
  log << "Total wall time: 0:00:01\n";
  return log.str();
}

struct Compared {
  int status = -1;
  std::string out, err;
  nlohmann::json json;  // null unless it exited 0
};

Compared compare(const std::string& log_text, const std::string& options = kGas) {
  TempFolder folder;
  const auto path = folder.path / "run.log";
  std::ofstream(path, std::ios::binary) << log_text;
  const auto r = run_cli(options + "--json --compare " + path.string());
  Compared c{r.status, r.out, r.err, nullptr};
  if (r.status == 0) c.json = nlohmann::json::parse(r.out);
  return c;
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

// The token `key=VALUE` of the print at `time_index` (0-based) of haff_log.
std::string token_of(const std::string& log, int time_index, const std::string& key) {
  const auto line = log.find("step=" + std::to_string(time_index) + "\n");
  const auto start = log.rfind("restitution-gas law=", line);
  const auto at = log.find(" " + key + "=", start) + 1;
  return log.substr(at, log.find(' ', at) - at);
}

TEST(GasLogCli, AWellFormedLogOfTheCommandsGasIsCompared) {
  const Compared c = compare(haff_log(deck_setup()));
  ASSERT_EQ(c.status, 0) << c.err;
  EXPECT_NEAR(c.json.at("collision_rate_factor").get<double>(), 0.9, 1e-6);
  EXPECT_TRUE(c.json.at("collision_rate_factor_measured").get<bool>());
  EXPECT_EQ(c.json.at("runs")[0].at("time_s").size(), 30U);
}

TEST(GasLogCli, ANumberIsTheWholeToken) {
  const std::string log = haff_log(deck_setup());
  const std::string temperature = token_of(log, 7, "temperature_j");
  const std::string value = temperature.substr(temperature.find('=') + 1);
  for (const std::string& garbled : {value + "abc", value.substr(0, 1) + "n" + value.substr(1),
                                     value.substr(0, 3) + "-2" + value.substr(3), std::string("0x1p-3"),
                                     std::string("inf"), std::string("+") + value, std::string("")}) {
    const Compared c = compare(replaced(log, temperature, "temperature_j=" + garbled));
    EXPECT_EQ(c.status, 2) << garbled << ": " << c.out;
    EXPECT_NE(c.err.find("run.log:11:"), std::string::npos) << c.err;  // the line of the eighth print
  }
  const Compared step = compare(replaced(log, "step=7\n", "step=7x\n"));
  EXPECT_EQ(step.status, 2) << step.out;
}

TEST(GasLogCli, ALineWithoutEveryFieldIsRefused) {
  const std::string log = haff_log(deck_setup());
  // A print cut after its temperature, then the log goes on (a killed run and another appended).
  const auto at = log.find(" timestep_s=5e-06 step=12\n");
  const Compared c = compare(log.substr(0, at) + "\n" + log.substr(at + 1));
  EXPECT_EQ(c.status, 2) << c.out;
  EXPECT_NE(c.err.find("half-written"), std::string::npos) << c.err;
  const Compared setup =
      compare(haff_log(replaced(deck_setup(), " packing_fraction=", " packing_fraction=0.1 x=")));
  EXPECT_EQ(setup.status, 2) << setup.out;
}

TEST(GasLogCli, ALastLineCutWhilePrintingIsLeftOutWithANote) {
  const std::string log = haff_log(deck_setup());
  const std::string whole = log.substr(0, log.find("Total wall time"));
  // Cut inside the last print's temperature: "temperature_j=1.05" of a run killed while writing.
  const auto last = whole.rfind("temperature_j=");
  const Compared c = compare(whole.substr(0, last + 18));
  ASSERT_EQ(c.status, 0) << c.err;
  EXPECT_NE(c.err.find("the last line is cut off"), std::string::npos) << c.err;
  EXPECT_EQ(c.json.at("runs")[0].at("time_s").size(), 29U);
  EXPECT_LT(c.json.at("runs")[0].at("max_relative_deviation").get<double>(), 1e-6);
}

TEST(GasLogCli, CrlfLineEndsReadAsLf) {
  const std::string log = haff_log(deck_setup());
  std::string crlf;
  for (const char ch : log) crlf += ch == '\n' ? std::string("\r\n") : std::string(1, ch);
  const Compared lf = compare(log);
  const Compared c = compare(crlf);
  ASSERT_EQ(c.status, 0) << c.err;
  ASSERT_EQ(lf.status, 0) << lf.err;
  EXPECT_EQ(c.json.at("runs")[0].at("temperature_j"), lf.json.at("runs")[0].at("temperature_j"));
}

TEST(GasLogCli, ASecondRunAppendedOrATimeGoingBackIsReported) {
  const std::string log = haff_log(deck_setup());
  const Compared twice = compare(log + log);
  EXPECT_EQ(twice.status, 2) << twice.out;
  EXPECT_NE(twice.err.find("second run"), std::string::npos) << twice.err;
  // The prints of a second run without its setup line: the time goes back to 0.
  const std::string prints = log.substr(log.find("restitution-gas law="));
  const Compared back = compare(log + prints);
  EXPECT_EQ(back.status, 2) << back.out;
  EXPECT_NE(back.err.find("is not after"), std::string::npos) << back.err;
  // A print repeated to the bit (a block that ran no step) is counted once, and said so.
  const auto seventh = log.find("restitution-gas law=constant-eps time_s=", log.find("step=6\n"));
  const std::string line = log.substr(seventh, log.find('\n', seventh) + 1 - seventh);
  const Compared repeat = compare(log.substr(0, seventh) + line + log.substr(seventh));
  ASSERT_EQ(repeat.status, 0) << repeat.err;
  EXPECT_NE(repeat.err.find("1 repeated print"), std::string::npos) << repeat.err;
  EXPECT_EQ(repeat.json.at("runs")[0].at("time_s").size(), 30U);
}

TEST(GasLogCli, APrintWithoutItsSetupLineIsRefused) {
  std::string log = haff_log(deck_setup());
  const auto at = log.find("\nrestitution-gas-setup ");
  log.erase(at + 1, log.find('\n', at + 1) - at);
  const Compared c = compare(log);
  EXPECT_EQ(c.status, 2) << c.out;
  EXPECT_NE(c.err.find("restitution-gas-setup"), std::string::npos) << c.err;
}

TEST(GasLogCli, OnlyARegularFileIsRead) {
  TempFolder folder;
  const auto fifo = folder.path / "fifo.log";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  // Bounded: a reader that opens the FIFO waits for a writer forever.
  const pid_t pid =
      spawn_cli({"gas", "--radius",           "0.005",      "--density",   "920", "--young-modulus",
                 "1e8", "--poisson-ratio",    "0.4",        "--eps",       "0.8", "--velocity",
                 "2",   "--packing-fraction", "0.1",        "--rms-speed", "1",   "--haff-times",
                 "30",  "--compare",          fifo.string()},
                folder.path / "err");
  int raw = 0;
  for (int i = 0; i < 600 && waitpid(pid, &raw, WNOHANG) == 0; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  if (waitpid(pid, &raw, WNOHANG) == 0) {
    kill(pid, SIGKILL);
    waitpid(pid, &raw, 0);
    FAIL() << "--compare FIFO still waiting after 30 s";
  }
  EXPECT_TRUE(WIFEXITED(raw) && WEXITSTATUS(raw) == 2) << slurp((folder.path / "err").string());
  EXPECT_NE(slurp((folder.path / "err").string()).find("not a regular file"), std::string::npos);
  for (const std::string& special : {std::string("/dev/zero"), folder.path.string()}) {
    const auto r = run_cli(kGas + "--compare " + special);
    EXPECT_EQ(r.status, 2) << special << ": " << r.err;
    EXPECT_NE(r.err.find("not a regular file"), std::string::npos) << r.err;
  }
}

TEST(GasLogCli, AMissingLogIsABadInputNotAnOutputFailure) {
  TempFolder folder;
  const auto r = run_cli(kGas + "--compare " + (folder.path / "missing.log").string());
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("--compare: no file"), std::string::npos) << r.err;
}

TEST(GasLogCli, ALineBeyondTheBoundIsRefused) {
  const std::string log = haff_log(deck_setup());
  const Compared c = compare(log.substr(0, 200) + std::string(3U << 20U, 'x') + "\n" + log.substr(200));
  EXPECT_EQ(c.status, 2) << c.out;
  EXPECT_NE(c.err.find("longer than 1 MiB"), std::string::npos) << c.err;
}

TEST(GasLogCli, ALogOfAnotherGasIsRefusedNamingTheField) {
  const std::string log = haff_log(deck_setup());
  const auto other = [&](const std::string& from, const std::string& to) {
    return compare(log, replaced(kGas, from, to));
  };
  const Compared phi = other("--packing-fraction 0.1", "--packing-fraction 0.2");
  EXPECT_EQ(phi.status, 2) << phi.out;
  EXPECT_NE(phi.err.find("the log's packing_fraction 0.1 is not the command's 0.2 (--packing-fraction)"),
            std::string::npos)
      << phi.err;
  const Compared t0 = other("--rms-speed 1", "--rms-speed 2");
  EXPECT_EQ(t0.status, 2) << t0.out;
  EXPECT_NE(t0.err.find("initial_temperature_j"), std::string::npos) << t0.err;
  const Compared material = other("--density 920", "--density 2500");
  EXPECT_EQ(material.status, 2) << material.out;
  EXPECT_NE(material.err.find("mass_kg"), std::string::npos) << material.err;
  const Compared law = other("--eps 0.8", "--eps 0.7");
  EXPECT_EQ(law.status, 2) << law.out;
  EXPECT_NE(law.err.find("dissipative_constant_s"), std::string::npos) << law.err;
  const Compared end = other("--haff-times 30", "--haff-times 30 --end naive");
  EXPECT_EQ(end.status, 2) << end.out;
  EXPECT_NE(end.err.find("end"), std::string::npos) << end.err;
}

TEST(GasLogCli, TheFactorIsSaidMeasuredOnlyWhenAConstantEpsRunWasGiven) {
  TempFolder folder;
  const std::string setup = deck_setup();
  const std::string visco = replaced(setup, "law=constant-eps", "law=viscoelastic");
  std::ofstream(folder.path / "v.log") << haff_log(visco, "viscoelastic");
  const auto text = run_cli(kGas + "--compare " + (folder.path / "v.log").string());
  ASSERT_EQ(text.status, 0) << text.err;
  EXPECT_EQ(text.out.find("measured on the constant-eps run"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("no constant-eps run given"), std::string::npos) << text.out;
  const Compared json = compare(haff_log(visco, "viscoelastic"));
  ASSERT_EQ(json.status, 0) << json.err;
  EXPECT_FALSE(json.json.at("collision_rate_factor_measured").get<bool>());
}

}  // namespace

// 45.11: plotting 10,000 compared logs took over five minutes with no bound; the count is refused before any
// file is read.
TEST(GasLogCli, MoreLogsThanAFigureCanShowAreRefused) {
  std::string logs;
  for (int i = 0; i < 65; ++i) logs += " missing.log";
  const auto r = restitution::test_support::run_cli(kGas + "--compare" + logs);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("--compare takes at most 64 logs"), std::string::npos) << r.err;
}
