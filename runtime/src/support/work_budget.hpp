// The work budget of one solve (of one load): a deadline, and the caller's checkpoint (which may throw to
// abandon the solve: the Python module raises KeyboardInterrupt from it on Ctrl-C).
#pragma once

#include <chrono>
#include <cstdio>
#include <functional>
#include <string>

#include "wavecontact/errors.hpp"

namespace wavecontact::detail {

class WorkBudget {
 public:
  WorkBudget(double max_seconds, std::function<void()> checkpoint)
      : start_(Clock::now()), seconds_(max_seconds), checkpoint_(std::move(checkpoint)) {}

  double elapsed() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }
  // The budget afresh, for the next piece of work (each load of a sweep has its own).
  void restart() const { start_ = Clock::now(); }

  // At a safe point: throws BeyondReach, naming `where` (how far the work got), once the
  // time is spent; runs the checkpoint every tenth of a second.
  void check(const std::function<std::string()>& where) const {
    const Clock::time_point now = Clock::now();
    if (checkpoint_ && now - last_checkpoint_ > std::chrono::milliseconds(100)) {
      last_checkpoint_ = now;
      checkpoint_();
    }
    const double spent = std::chrono::duration<double>(now - start_).count();
    if (spent > seconds_) {
      char budget[32];
      std::snprintf(budget, sizeof budget, "%g", seconds_);
      throw BeyondReach(std::string("the work budget of ") + budget + " s (max_seconds) is spent: " + where());
    }
  }

 private:
  using Clock = std::chrono::steady_clock;
  mutable Clock::time_point start_;
  mutable Clock::time_point last_checkpoint_{};
  double seconds_;
  std::function<void()> checkpoint_;
};

}  // namespace wavecontact::detail
