// Parallel sweep over ζ: worker threads take the next unfinished index from a shared counter, each with
// its own CollisionSolver; finished points go to the caller's callback one at a time.
#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>

#include "restitution/errors.hpp"
#include "restitution/sweep.hpp"

namespace restitution {
namespace {

class SweepRun {
 public:
  SweepRun(const std::vector<double>& zetas, const SolveOptions& options, const SweepControl& control)
      : zetas_(zetas), options_(options), control_(control) {}

  SweepSummary run(unsigned threads) {
    if (threads <= 1) {
      work();
    } else {
      std::vector<std::jthread> workers;
      workers.reserve(threads);
      for (unsigned t = 0; t < threads; ++t) workers.emplace_back([this] { work(); });
    }  // the jthreads join here
    if (error_) std::rethrow_exception(error_);
    summary_.stopped = stop_.load();
    return summary_;
  }

 private:
  [[nodiscard]] bool done_before(std::size_t i) const {
    return i < control_.already_done.size() && control_.already_done[i];
  }

  void work() {
    CollisionSolver solver;
    while (true) {
      if (control_.stop_requested && control_.stop_requested()) stop_ = true;
      if (stop_) return;
      const std::size_t i = next_.fetch_add(1);
      if (i >= zetas_.size()) return;
      if (done_before(i)) continue;
      try {
        finish(solve_point(solver, i));
      } catch (...) {
        // Anything but a numerical failure of the point (a failing callback, an allocation) ends the sweep.
        const std::lock_guard lock(mutex_);
        if (!error_) error_ = std::current_exception();
        stop_ = true;
        return;
      }
    }
  }

  SweepPoint solve_point(CollisionSolver& solver, std::size_t i) const {
    SweepPoint point;
    point.index = i;
    point.zeta = zetas_[i];
    try {
      point.result = solver.solve(ContactLaw::hertz_natural(point.zeta), options_);
    } catch (const NumericalFailure& e) {
      point.error = e.what();
    }
    return point;
  }

  void finish(const SweepPoint& point) {
    const std::lock_guard lock(mutex_);
    ++summary_.computed;
    if (!point.result) ++summary_.failed;
    if (control_.point_finished) control_.point_finished(point);
  }

  const std::vector<double>& zetas_;
  const SolveOptions& options_;
  const SweepControl& control_;
  std::atomic<std::size_t> next_{0};
  std::atomic<bool> stop_{false};
  std::mutex mutex_;  // guards summary_, error_ and the callback
  SweepSummary summary_;
  std::exception_ptr error_;
};

}  // namespace

void check_sweep(const std::vector<double>& zetas, const SolveOptions& options) {
  check_solve_options(options);
  for (const double zeta : zetas) {
    require_checked_zeta(zeta);
    check_solvable(ContactLaw::hertz_natural(zeta), options);
  }
}

SweepSummary run_sweep(const std::vector<double>& zetas, const SolveOptions& options,
                       const SweepControl& control) {
  check_sweep(zetas, options);
  if (!control.already_done.empty() && control.already_done.size() != zetas.size()) {
    throw InvalidInput("already_done must be empty or hold one flag per point of the sweep");
  }
  const auto skipped =
      static_cast<std::size_t>(std::count(control.already_done.begin(), control.already_done.end(), true));
  const std::size_t remaining = zetas.size() - skipped;
  unsigned threads =
      control.threads != 0 ? control.threads : std::max(1U, std::thread::hardware_concurrency());
  threads = static_cast<unsigned>(std::min<std::size_t>(threads, std::max<std::size_t>(remaining, 1)));
  SweepSummary summary = SweepRun(zetas, options, control).run(threads);
  summary.skipped = skipped;
  summary.stopped = summary.stopped && summary.computed + skipped < zetas.size();
  return summary;
}

}  // namespace restitution
