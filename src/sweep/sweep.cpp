// SPDX-License-Identifier: BSD-3-Clause
// Parallel sweep over ζ on the library's thread pool (src/parallel): each worker thread has its own
// CollisionSolver; finished points go to the caller's callback one at a time.
#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>

#include "parallel/brief_lock.hpp"
#include "parallel/parallel_for.hpp"
#include "restitution/errors.hpp"
#include "restitution/sweep.hpp"
#include "sweep/checked_sweep.hpp"

namespace restitution {
namespace {

class SweepRun {
 public:
  SweepRun(const std::vector<double>& zetas, LawKind law, const SolveOptions& options,
           const SweepControl& control, std::size_t skipped)
      : zetas_(zetas), law_(law), options_(options), control_(control), skipped_(skipped) {}

  SweepSummary run(unsigned threads) {
    detail::ParallelRun run{zetas_.size(), threads, control_.stop_requested};
    // A failing callback or allocation ends the sweep (the pool rethrows it); a point's own numerical
    // failure is recorded with the point.
    summary_.stopped = detail::parallel_for(run, [this]() -> detail::IndexBody {
      auto solver = std::make_shared<CollisionSolver>();
      const unsigned worker = next_worker_.fetch_add(1);
      return [this, solver, worker](std::size_t i) {
        if (!done_before(i)) finish(solve_point(*solver, i, worker));
      };
    });
    return summary_;
  }

 private:
  [[nodiscard]] bool done_before(std::size_t i) const {
    return i < control_.already_done.size() && control_.already_done[i];
  }

  SweepPoint solve_point(CollisionSolver& solver, std::size_t i, unsigned worker) const {
    SweepPoint point;
    point.index = i;
    point.worker = worker;
    point.zeta = zetas_[i];
    try {
      point.result = solver.solve(ContactLaw::natural(law_, point.zeta), options_);
    } catch (const NumericalFailure& e) {
      point.error = e.what();
    }
    return point;
  }

  void finish(const SweepPoint& point) {
    if (control_.point_computed) control_.point_computed(point);  // outside the lock: see SweepControl
    const std::lock_guard lock(mutex_);
    ++summary_.computed;
    if (!point.result) ++summary_.failed;
    if (control_.point_finished) control_.point_finished(point);
    if (control_.progress) control_.progress(skipped_ + summary_.computed, zetas_.size());
  }

  const std::vector<double>& zetas_;
  LawKind law_;
  const SolveOptions& options_;
  const SweepControl& control_;
  std::size_t skipped_;  // points finished before this run, counted in the progress
  std::atomic<unsigned> next_worker_{0};
  detail::BriefLock mutex_;  // guards summary_ and the callback
  SweepSummary summary_;
};

}  // namespace

void check_sweep(const std::vector<double>& zetas, const SolveOptions& options, LawKind law,
                 unsigned threads) {
  check_solve_options(options);
  // The points are checked in chunks on the pool (a serial check of 1e5 points was ~1 % of a Taylor
  // sweep's work, on one thread while the others waited). The first refused point in grid order is
  // reported, as a serial check would.
  constexpr std::size_t kChunk = 4096;
  const std::size_t chunks = (zetas.size() + kChunk - 1) / kChunk;
  std::mutex mutex;
  std::size_t first_refused = zetas.size();
  std::exception_ptr refusal;
  detail::parallel_for({chunks, detail::thread_count(threads, chunks), {}}, [&]() -> detail::IndexBody {
    return [&](std::size_t chunk) {
      const std::size_t end = std::min(zetas.size(), (chunk + 1) * kChunk);
      for (std::size_t i = chunk * kChunk; i < end; ++i) {
        try {
          require_checked_zeta(zetas[i]);
          check_solvable(ContactLaw::natural(law, zetas[i]), options);
        } catch (const InvalidInput&) {
          const std::lock_guard lock(mutex);
          if (i < first_refused) {
            first_refused = i;
            refusal = std::current_exception();
          }
          return;
        }
      }
    };
  });
  if (refusal) std::rethrow_exception(refusal);
}

SweepSummary run_sweep(const std::vector<double>& zetas, const SolveOptions& options,
                       const SweepControl& control, LawKind law) {
  check_sweep(zetas, options, law, control.threads);
  return run_checked_sweep(zetas, options, control, law);
}

SweepSummary run_checked_sweep(const std::vector<double>& zetas, const SolveOptions& options,
                               const SweepControl& control, LawKind law) {
  if (!control.already_done.empty() && control.already_done.size() != zetas.size()) {
    throw InvalidInput("already_done must be empty or hold one flag per point of the sweep");
  }
  const auto skipped =
      static_cast<std::size_t>(std::count(control.already_done.begin(), control.already_done.end(), true));
  const std::size_t remaining = zetas.size() - skipped;
  SweepSummary summary =
      SweepRun(zetas, law, options, control, skipped).run(detail::thread_count(control.threads, remaining));
  summary.skipped = skipped;
  summary.stopped = summary.stopped && summary.computed + skipped < zetas.size();
  return summary;
}

}  // namespace restitution
