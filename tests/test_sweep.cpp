// SPDX-License-Identifier: BSD-3-Clause
// Parallel sweeps: the grid, serial == parallel bit for bit, order, resume without recomputation, failed
// points marked, cancellation keeping finished rows, and the CLI's atomic final file.
#include <fmt/core.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>
#include <csignal>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <thread>

#include "cli_runner.hpp"
#include "restitution/errors.hpp"
#include "restitution/sweep.hpp"
#include "sweep/sweep_table.hpp"

namespace restitution {
namespace {
namespace fs = std::filesystem;
using test_support::lines_of;
using test_support::run_cli;
using test_support::slurp;
using test_support::spawn_cli;
using test_support::wait_cli;

SolveOptions quick_options() {
  SolveOptions options;
  options.tolerance = 1e-8;
  return options;
}

// Every field of the two results, compared as bits (EXPECT_EQ on doubles is exact).
void expect_identical(const CollisionResult& a, const CollisionResult& b, double zeta) {
  EXPECT_EQ(a.max_compression.tau, b.max_compression.tau) << zeta;
  EXPECT_EQ(a.max_compression.x, b.max_compression.x) << zeta;
  EXPECT_EQ(a.stats.steps, b.stats.steps) << zeta;
  EXPECT_EQ(a.stats.rhs_evaluations, b.stats.rhs_evaluations) << zeta;
  for (const CollisionEnd end : kCollisionEnds) {
    ASSERT_EQ(a[end].has_value(), b[end].has_value()) << zeta;
    if (!a[end]) continue;
    const EndResult& x = *a[end];
    const EndResult& y = *b[end];
    EXPECT_EQ(x.eps, y.eps) << zeta;
    EXPECT_EQ(x.one_minus_eps, y.one_minus_eps) << zeta;
    EXPECT_EQ(x.tau, y.tau) << zeta;
    EXPECT_EQ(x.x, y.x) << zeta;
  }
}

std::vector<SweepPoint> sweep_in_order(const std::vector<double>& zetas, const SolveOptions& options,
                                       unsigned threads) {
  std::vector<SweepPoint> points(zetas.size());
  SweepControl control;
  control.threads = threads;
  control.point_finished = [&](const SweepPoint& p) { points.at(p.index) = p; };
  const SweepSummary summary = run_sweep(zetas, options, control);
  EXPECT_EQ(summary.computed, zetas.size());
  EXPECT_FALSE(summary.stopped);
  return points;
}

TEST(ZetaGrid, EndsAreExactAndSpacingIsEven) {
  const std::vector<double> linear = zeta_values({0.0, 2.0, 5, false});
  EXPECT_EQ(linear, (std::vector<double>{0.0, 0.5, 1.0, 1.5, 2.0}));
  const std::vector<double> log = zeta_values({1e-3, 1e3, 7, true});
  ASSERT_EQ(log.size(), 7U);
  EXPECT_EQ(log.front(), 1e-3);
  EXPECT_EQ(log.back(), 1e3);
  for (std::size_t i = 0; i < log.size(); ++i) EXPECT_NEAR(log[i], std::pow(10.0, -3.0 + i), 1e-12 * log[i]);
  EXPECT_EQ(zeta_values({0.7, 0.7, 1, false}), std::vector<double>{0.7});
  // No point steps past the range by rounding, linear or logarithmic.
  EXPECT_EQ(zeta_values({100.0, 100.0, 7, false}), std::vector<double>(7, 100.0));
  EXPECT_EQ(zeta_values({100.0, 100.0, 7, true}), std::vector<double>(7, 100.0));
  for (const bool logarithmic : {false, true}) {
    for (const double z : zeta_values({0.3, 100.0, 1001, logarithmic})) {
      EXPECT_GE(z, 0.3);
      EXPECT_LE(z, 100.0);
    }
  }
}

TEST(ZetaGrid, RefusesBadGridsNamingTheKey) {
  const auto message = [](const ZetaGrid& g) {
    try {
      zeta_values(g);
    } catch (const InvalidInput& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(message({-1.0, 1.0, 3, false}).find("zeta-min"), std::string::npos);
  EXPECT_NE(message({0.0, INFINITY, 3, false}).find("zeta-max"), std::string::npos);
  EXPECT_NE(message({0.0, NAN, 3, false}).find("zeta-max"), std::string::npos);
  EXPECT_NE(message({2.0, 1.0, 3, false}).find("must not exceed"), std::string::npos);
  EXPECT_NE(message({0.0, 1.0, 0, false}).find("points"), std::string::npos);
  EXPECT_NE(message({0.0, 1.0, 1, false}).find("points = 1"), std::string::npos);
  EXPECT_NE(message({0.0, 1.0, 3, true}).find("logarithmic"), std::string::npos);
}

TEST(Sweep, ParallelEqualsSerialBitForBitAndAFreshSolverPerPoint) {
  const std::vector<double> zetas = zeta_values({1e-4, 1e3, 24, true});
  const SolveOptions options = quick_options();
  const std::vector<SweepPoint> serial = sweep_in_order(zetas, options, 1);
  const std::vector<SweepPoint> parallel = sweep_in_order(zetas, options, 3);
  for (std::size_t i = 0; i < zetas.size(); ++i) {
    ASSERT_TRUE(serial[i].result && parallel[i].result) << zetas[i];
    EXPECT_EQ(serial[i].index, i);
    EXPECT_EQ(serial[i].zeta, zetas[i]);
    expect_identical(*serial[i].result, *parallel[i].result, zetas[i]);
    // A solver that has never solved anything gives the same bits as the reused one.
    CollisionSolver fresh;
    expect_identical(*serial[i].result, fresh.solve(ContactLaw::hertz_natural(zetas[i]), options), zetas[i]);
  }
}

TEST(Sweep, EachPointIsReportedOnceAndCallbacksNeverOverlap) {
  const std::vector<double> zetas = zeta_values({0.0, 5.0, 30, false});
  std::multiset<std::size_t> seen;
  std::atomic<int> inside{0};
  bool overlapped = false;
  SweepControl control;
  control.threads = 4;
  control.point_finished = [&](const SweepPoint& p) {
    overlapped = overlapped || inside.fetch_add(1) != 0;
    seen.insert(p.index);
    std::this_thread::sleep_for(std::chrono::microseconds(200));
    inside.fetch_sub(1);
  };
  run_sweep(zetas, quick_options(), control);
  EXPECT_FALSE(overlapped);
  ASSERT_EQ(seen.size(), zetas.size());
  for (std::size_t i = 0; i < zetas.size(); ++i) EXPECT_EQ(seen.count(i), 1U) << i;
}

TEST(Sweep, ResumeComputesOnlyTheUnfinishedPoints) {
  const std::vector<double> zetas = zeta_values({0.1, 10.0, 12, true});
  SweepControl control;
  control.threads = 2;
  control.already_done.assign(zetas.size(), false);
  for (std::size_t i = 0; i < zetas.size(); i += 3) control.already_done[i] = true;
  std::set<std::size_t> computed;
  control.point_finished = [&](const SweepPoint& p) { computed.insert(p.index); };
  const SweepSummary summary = run_sweep(zetas, quick_options(), control);
  EXPECT_EQ(summary.skipped, 4U);
  EXPECT_EQ(summary.computed, 8U);
  for (std::size_t i = 0; i < zetas.size(); ++i) EXPECT_EQ(computed.count(i), i % 3 == 0 ? 0U : 1U) << i;
}

TEST(Sweep, NumericalFailureMarksThePointAndTheRestGoesOn) {
  // With at most 400 CVODE steps per phase the long naive tail of large ζ cannot be integrated (it needs
  // thousands of steps), while small ζ need far fewer.
  SolveOptions options = quick_options();
  options.ends = EndSet{CollisionEnd::naive};
  options.max_steps_per_phase = 400;
  const std::vector<double> zetas{0.01, 0.5, 300.0, 1.0, 1000.0};
  const std::vector<SweepPoint> points = sweep_in_order(zetas, options, 2);
  for (const std::size_t ok : {0U, 1U, 3U}) EXPECT_TRUE(points[ok].result) << points[ok].error;
  for (const std::size_t bad : {2U, 4U}) {
    ASSERT_FALSE(points[bad].result);
    const std::string& e = points[bad].error;
    EXPECT_NE(e.find(fmt::format("zeta={}", zetas[bad])), std::string::npos) << e;
    EXPECT_NE(e.find("flag -1"), std::string::npos) << e;
    EXPECT_NE(e.find("the naive end"), std::string::npos) << e;
    EXPECT_NE(e.find("tolerance 1e-08"), std::string::npos) << e;
  }
}

TEST(Sweep, StopRequestKeepsFinishedPointsAndStartsNoNewOne) {
  const std::vector<double> zetas = zeta_values({0.0, 3.0, 200, false});
  std::atomic<std::size_t> finished{0};
  SweepControl control;
  control.threads = 2;
  control.stop_requested = [&] { return finished.load() >= 5; };
  control.point_finished = [&](const SweepPoint&) { finished.fetch_add(1); };
  const SweepSummary summary = run_sweep(zetas, quick_options(), control);
  EXPECT_TRUE(summary.stopped);
  EXPECT_GE(summary.computed, 5U);
  EXPECT_LE(summary.computed, 5U + 2U);  // at most the points in progress when the stop came
  EXPECT_EQ(summary.computed, finished.load());
}

TEST(Sweep, ACallbackErrorStopsTheSweepAndIsRethrown) {
  SweepControl control;
  control.threads = 2;
  control.point_finished = [](const SweepPoint&) { throw InvalidInput("disk full"); };
  EXPECT_THROW(run_sweep(zeta_values({0.0, 1.0, 20, false}), quick_options(), control), InvalidInput);
}

TEST(Sweep, BadOptionsAreRefusedBeforeAnyPoint) {
  bool called = false;
  SweepControl control;
  control.point_finished = [&](const SweepPoint&) { called = true; };
  SolveOptions options = quick_options();
  options.tolerance = 1e-13;
  EXPECT_THROW(run_sweep({1.0, 2.0}, options, control), InvalidInput);
  EXPECT_THROW(run_sweep({1.0, -2.0}, quick_options(), control), InvalidInput);
  EXPECT_THROW(run_sweep({1.0, NAN}, quick_options(), control), InvalidInput);
  control.already_done = {true};
  EXPECT_THROW(run_sweep({1.0, 2.0}, quick_options(), control), InvalidInput);
  EXPECT_FALSE(called);
}

// The check runs on the pool in chunks; whichever thread meets a refused point first, the message names the
// first one in grid order, as a serial check would. Here thread 2 meets index 4096 (the first of the second
// chunk) long before thread 1 reaches index 4095 (the last of the first).
TEST(Sweep, TheCheckNamesTheFirstRefusedPointInGridOrderOnAnyThreadCount) {
  std::vector<double> zetas(3 * 4096, 1.0);
  zetas[4095] = 2e6;
  zetas[4096] = 3e6;
  for (const unsigned threads : {1U, 2U, 4U}) {
    try {
      check_sweep(zetas, quick_options(), LawKind::viscoelastic_hertz, threads);
      ADD_FAILURE() << "no refusal on " << threads << " threads";
    } catch (const InvalidInput& e) {
      EXPECT_NE(std::string(e.what()).find("zeta = 2000000 "), std::string::npos) << e.what();
    }
  }
}

// --- The CSV table -----------------------------------------------------------------------------------

TEST(SweepTable, FailedRowsKeepTheColumnsAndQuoteTheMessage) {
  const EndSet both = EndSet::both();
  const std::string header = sweep_header(both);
  SweepPoint failed;
  failed.zeta = 2.5;
  failed.error = "CVODE failed, \"badly\"\nat tau=3";
  const std::string row = sweep_row(failed, both);
  const auto count = [](const std::string& s) { return std::count(s.begin(), s.end(), ','); };
  // The message's own comma sits inside quotes: one more comma than the header.
  EXPECT_EQ(count(row), count(header) + 1);
  EXPECT_EQ(row.rfind("2.5,", 0), 0U);
  EXPECT_NE(row.find(",failed,\"CVODE failed, \"\"badly\"\" at tau=3\""), std::string::npos) << row;
  EXPECT_EQ(row.find('\n'), std::string::npos);
}

// --- End to end ----------------------------------------------------------------------------------------

struct TempFolder {
  fs::path path;
  TempFolder() {
    char name[] = "/tmp/restitution-sweep-XXXXXX";
    path = mkdtemp(name);
  }
  ~TempFolder() { fs::remove_all(path); }
};

TEST(CliSweep, WritesRowsInZetaOrderMatchingTheLibrary) {
  const TempFolder dir;
  const fs::path out = dir.path / "sub" / "s.csv";
  const auto outcome = run_cli(
      "sweep --zeta-range 0.01:100:9 --log --end delayed-recovery "
      "--tolerance 1e-8 --threads 2 --out " +
      out.string());
  ASSERT_EQ(outcome.status, 0) << outcome.err;
  EXPECT_FALSE(fs::exists(out.string() + ".partial"));
  const std::vector<std::string> lines = lines_of(slurp(out));
  ASSERT_EQ(lines.size(), 10U);
  EXPECT_EQ(
      lines[0],
      "zeta,delayed_recovery_eps,delayed_recovery_one_minus_eps,delayed_recovery_tau,delayed_recovery_x,"
      "max_compression_tau,max_compression_x,steps,status,error");
  SolveOptions options = quick_options();
  options.ends = EndSet{CollisionEnd::delayed_recovery};
  const std::vector<double> zetas = zeta_values({0.01, 100.0, 9, true});
  CollisionSolver solver;
  for (std::size_t i = 0; i < zetas.size(); ++i) {
    SweepPoint p{i, zetas[i], solver.solve(ContactLaw::hertz_natural(zetas[i]), options), ""};
    EXPECT_EQ(lines[i + 1], sweep_row(p, options.ends));
  }
}

TEST(CliSweep, OneThreadAndTwoThreadsWriteTheSameBytes) {
  const TempFolder dir;
  const std::string common = "sweep --zeta-range 0:20:25 --tolerance 1e-8 --out ";
  ASSERT_EQ(run_cli(common + (dir.path / "one.csv").string() + " --threads 1").status, 0);
  ASSERT_EQ(run_cli(common + (dir.path / "two.csv").string() + " --threads 2").status, 0);
  EXPECT_EQ(slurp(dir.path / "one.csv"), slurp(dir.path / "two.csv"));
}

std::size_t line_count(const fs::path& path) {
  const std::string text = slurp(path);
  return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
}

// Sends the signal once the run has added `rows` rows of its own to the partial file. Counting from what the
// file already holds matters on resume: an earlier run may have left more rows than asked for, and a signal
// sent before the new process installed its handler kills it without a word.
int interrupt_after_rows(const std::vector<std::string>& arguments, const fs::path& partial, std::size_t rows,
                         int signal_number, const fs::path& err) {
  const std::size_t before = fs::exists(partial) ? line_count(partial) : 2;  // 2: the settings and the header
  const pid_t pid = spawn_cli(arguments, err);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (line_count(partial) < before + rows && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  kill(pid, signal_number);
  return wait_cli(pid);
}

TEST(CliSweep, SignalsKeepFinishedRowsAndResumeFinishesWithoutRecomputing) {
  const TempFolder dir;
  const fs::path out = dir.path / "s.csv";
  const fs::path partial = out.string() + ".partial";
  // 6000 points: about a second of work, so the signals land mid-sweep on a machine a few times faster.
  constexpr std::size_t kPoints = 6000;
  const std::vector<std::string> arguments{
      "sweep", "--zeta-range", "0:30:" + std::to_string(kPoints), "--threads", "2", "--out", out.string()};
  // SIGINT first, then SIGTERM on the resumed sweep.
  std::vector<std::string> run = arguments;
  for (const int signal_number : {SIGINT, SIGTERM}) {
    // One file per run: a run killed before it wrote anything must not pass on the last run's message.
    const fs::path err = dir.path / fmt::format("err{}.txt", signal_number);
    const int status = interrupt_after_rows(run, partial, 20 + 10 * signal_number, signal_number, err);
    ASSERT_EQ(status, 128 + signal_number) << slurp(err);
    EXPECT_NE(slurp(err).find("interrupted by signal " + std::to_string(signal_number)), std::string::npos)
        << slurp(err);
    EXPECT_NE(slurp(err).find("--resume"), std::string::npos);
    EXPECT_FALSE(fs::exists(out)) << "an interrupted sweep must not leave a final file";
    EXPECT_FALSE(fs::exists(out.string() + ".tmp")) << "nor the final file in progress";
    ASSERT_TRUE(fs::exists(partial));
    run.emplace_back("--resume");
  }
  const std::size_t kept = line_count(partial) - 2;
  ASSERT_GT(kept, 20U);
  ASSERT_LT(kept, kPoints);
  // Without --resume the partial file is refused rather than overwritten.
  std::string command = arguments.front();
  for (std::size_t i = 1; i < arguments.size(); ++i) command += " " + arguments[i];
  const auto refused = run_cli(command);
  EXPECT_EQ(refused.status, 2);
  EXPECT_NE(refused.err.find("--resume"), std::string::npos) << refused.err;
  // Simulate a kill in the middle of a write: a cut-off last line is computed again, not trusted.
  { std::ofstream(partial, std::ios::app) << "7,0.14"; }

  const auto resumed = run_cli(command + " --resume");
  ASSERT_EQ(resumed.status, 0) << resumed.err;
  EXPECT_NE(resumed.err.find(
                fmt::format("{} of {} points already finished, computing {}", kept, kPoints, kPoints - kept)),
            std::string::npos)
      << resumed.err;
  EXPECT_FALSE(fs::exists(partial));
  // The same bytes as a sweep that was never interrupted.
  const fs::path fresh = dir.path / "fresh.csv";
  std::string fresh_command = command.substr(0, command.find("--out")) + "--out " + fresh.string();
  ASSERT_EQ(run_cli(fresh_command).status, 0);
  EXPECT_EQ(slurp(out), slurp(fresh));
}

TEST(CliSweep, ResumeRefusesThePartialFileOfAnotherSweep) {
  const TempFolder dir;
  const fs::path out = dir.path / "s.csv";
  {
    std::ofstream(out.string() + ".partial") << "# restitution sweep: zeta-min=0 zeta-max=1 points=3\nzeta\n";
  }
  const auto outcome = run_cli("sweep --zeta-range 0:2:3 --resume --out " + out.string());
  EXPECT_EQ(outcome.status, 2);
  EXPECT_NE(outcome.err.find("written by another sweep"), std::string::npos) << outcome.err;
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace restitution
