// A time and memory budget for one derivation of wavecontact-derive.
//
// GiNaC cannot be interrupted, and the engine's cost grows steeply with the order of a
// profile's parameter-dependent terms (docs/performance.md, "Derivation times"), so the input bounds
// of expression_input.hpp alone do not bound every derivation's time. While a budget is
// alive, a watchdog ends the process with exit status 4 (beyond reach) and a one-line message once the
// time is spent, and allocations beyond the memory budget fail (std::bad_alloc). Nothing
// is written then: the output directory is only replaced after a derivation completes.
#pragma once

#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>

namespace wavecontact::derive {

class ResourceBudget {
 public:
  // `what` names the derivation in the message, e.g. "profile p = \"...\"".
  ResourceBudget(double seconds, long megabytes, std::string what);
  ~ResourceBudget();
  ResourceBudget(const ResourceBudget&) = delete;
  ResourceBudget& operator=(const ResourceBudget&) = delete;

 private:
  std::mutex mutex_;
  std::condition_variable done_;
  bool finished_ = false;
  std::thread watchdog_;
};

}  // namespace wavecontact::derive
