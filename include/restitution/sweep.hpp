// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Sweeps over ζ: many independent collisions solved in parallel, one CollisionSolver per thread.
// Each point's result depends only on its ζ and the SolveOptions (a reused solver gives bitwise the same
// numbers as a fresh one), so a parallel sweep equals a serial one whatever thread computed which point.
// The library never prints and holds no global state: the caller passes a stop request (for signals)
// and receives each finished point through a callback.
#include <cstddef>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "restitution/collision_solver.hpp"
#include "restitution/units.hpp"

namespace restitution {

// ζ_i for i = 0 … points-1 from zeta_min to zeta_max (both included exactly), equally spaced in ζ or,
// with logarithmic spacing, in ln ζ. The same grid serves other variables (impact speeds): `variable`
// names the bounds in messages ("zeta" -> zeta-min, zeta-max).
struct ZetaGrid {
  double zeta_min = 0.0;
  double zeta_max = 1.0;
  std::size_t points = 2;
  bool logarithmic = false;
  const char* variable = "zeta";
};
inline constexpr std::size_t kMaxSweepPoints = 10'000'000;
// The most worker threads a sweep or a scene run is asked for (command line and Python check it).
inline constexpr unsigned kMaxSweepThreads = 1024;

// Throws InvalidInput naming VARIABLE-min, VARIABLE-max or points: non-finite or negative bounds, min > max,
// logarithmic spacing with zeta-min = 0, points outside [1, kMaxSweepPoints], one point with min != max.
std::vector<double> zeta_values(const ZetaGrid& grid);

// `n` >= 1 values from `from` to `to`, evenly spaced, both ends exactly as given: value i is
// (from (n-1-i) + to i) / (n-1), one rounding, so that whole-number ends give the nearest double (28, not
// 28.000000000000004). The one linear grid of `oblique --angle-range` and of a scene's { from, to, points }.
std::vector<double> evenly_spaced(double from, double to, std::size_t n);

// One finished point: its index in the grid, its ζ, and either the result or the numerical failure.
struct SweepPoint {
  std::size_t index = 0;
  double zeta = 0.0;
  std::optional<CollisionResult> result;  // empty when the point failed
  std::string error;                      // the NumericalFailure message when it failed
  // The sweep thread that computed it, 0 … threads-1 (the thread count as SweepControl::threads, 0 meaning
  // std::thread::hardware_concurrency()): point_computed may keep a buffer per thread without a lock.
  unsigned worker = 0;
};

struct SweepControl {
  unsigned threads = 0;  // 0: std::thread::hardware_concurrency()
  // Polled before each point: once it returns true no new point starts; points in progress finish.
  std::function<bool()> stop_requested;
  // Called once per solved point on the worker thread that solved it, concurrently with the other workers
  // and before point_finished: for work that touches only the point's own data (formatting its row into a
  // slot of its own), so that it overlaps the other threads' solves instead of queueing behind one lock.
  // An exception thrown here stops the sweep and is rethrown.
  std::function<void(const SweepPoint&)> point_computed;
  // Called once per finished point, never concurrently (the sweep serializes the calls), in completion
  // order, which may differ from grid order. An exception thrown here stops the sweep and is rethrown.
  std::function<void(const SweepPoint&)> point_finished;
  // Called after each finished point with (points finished, points in the sweep), already finished ones
  // counted: never concurrently, `done` increasing by one per call up to the total.
  std::function<void(std::size_t done, std::size_t total)> progress;
  // Indices of points already finished (by an interrupted run): they are not computed again.
  std::vector<bool> already_done;
};

struct SweepSummary {
  std::size_t computed = 0;  // points finished by this call (successful or failed)
  std::size_t failed = 0;    // of which failed numerically
  std::size_t skipped = 0;   // already done before this call
  bool stopped = false;      // stop_requested ended the sweep before every point was finished
};

// Throws InvalidInput naming the first ζ that is outside the checked range or that the options cannot be
// solved at (e.g. the Taylor engine's naive end beyond ζ = 100, the dash-pot's naive end at r >= 1): run it
// before writing anything. ζ is the natural form's (ContactLaw::natural) for every member of the family.
// The points are checked on `threads` threads (0: all cores), as a sweep runs.
void check_sweep(const std::vector<double>& zetas, const SolveOptions& options,
                 LawKind law = LawKind::viscoelastic_hertz, unsigned threads = 0);

// Solves the law's natural form at every ζ with the same options. Throws InvalidInput for bad options
// before any point is computed; a NumericalFailure at one point marks that point failed and the sweep goes
// on.
SweepSummary run_sweep(const std::vector<double>& zetas, const SolveOptions& options,
                       const SweepControl& control, LawKind law = LawKind::viscoelastic_hertz);

// A sweep into a CSV file that survives an interruption. While it runs, every finished row is appended to
// PATH.partial (flushed every 100 ms, each line with its own checksum) and the table is written in ζ order
// into PATH.tmp; PATH appears (renamed) only when every point is finished, and PATH.partial is then removed.
// A stopped sweep (SweepControl::stop_requested) keeps PATH.partial; the same call with `resume` continues
// from it, keeping every valid row, and writes the same bytes as an uninterrupted sweep. PATH.lock keeps a
// second process from writing the same files meanwhile.

// The columns of an ε(v) table after ζ: the impact speed of each point, β when given and, with natural
// scales per speed, SI durations and the maximal compression's time and size.
struct SweepColumns {
  std::vector<double> velocity_m_s;   // m/s, parallel to the sweep's ζ values
  std::optional<double> beta;         // s^{1/5} m^{-1/5}: a column after velocity_m_s, when given
  std::vector<NaturalScales> scales;  // parallel to velocity_m_s, or empty: no SI columns
};

struct SweepFileOutcome;

struct SweepFile {
  std::filesystem::path path;  // the CSV file (a regular file, not a folder)
  bool resume = false;         // continue from PATH.partial; without it an existing PATH.partial is refused
  // Line 1 of PATH.partial, the sweep's identity: a resumed sweep must have the same (one line, no '\n').
  std::string settings;
  std::optional<SweepColumns> columns;  // an ε(v) table; empty: ζ only
  // How messages name things, in the caller's words: the file as given (empty: PATH), the option or
  // argument that gave it ("--out"; empty: none) and what asks to resume ("--resume", "resume=True").
  std::string given;
  std::string option;
  std::string resume_option = "resume";
  // Called once PATH.partial was read, before any point is computed (status is not yet final).
  std::function<void(const SweepFileOutcome&)> resuming;
};

struct SweepFileOutcome {
  enum class Status {
    complete,          // PATH is written and PATH.partial removed
    already_complete,  // resume asked, PATH exists and PATH.partial does not: nothing was computed
    stopped            // stop_requested ended the sweep: PATH.partial keeps every finished point
  };
  Status status = Status::complete;
  std::filesystem::path partial_path;  // PATH.partial
  std::size_t points = 0;              // in the sweep
  std::size_t finished = 0;            // points finished, those of PATH.partial included
  std::size_t resumed = 0;             // valid rows found in PATH.partial (not computed again)
  std::size_t damaged_lines = 0;       // lines of PATH.partial dropped as damaged (their points recomputed)
  std::size_t first_damaged_line = 0;  // line number (1-based) of the first of them, 0: none
  std::size_t failed = 0;  // points that failed numerically (their rows say why), resumed ones too
};

// check_sweep, then run_sweep into SweepFile::path as described above. `control` gives the threads, the stop
// request and the progress callback; its point callbacks and already_done are the file's own. Throws
// InvalidInput (a folder as PATH, columns not parallel to zetas, another process writing PATH, PATH.partial
// without resume or written by another sweep) before any point is computed, IoError naming the file when a
// write fails (PATH.partial then keeps what was finished).
SweepFileOutcome sweep_to_file(const std::vector<double>& zetas, const SolveOptions& options,
                               SweepControl control, const SweepFile& file,
                               LawKind law = LawKind::viscoelastic_hertz);

}  // namespace restitution
