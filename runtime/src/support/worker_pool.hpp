// The threads that for_each_chunk (parallel.hpp) hands its chunks to, started once and kept:
// a solve evaluates its zone system some hundred times, each in a fraction of a millisecond,
// and a thread started for each evaluation was still starting when the calling thread had
// taken every chunk (the 102-zone case of bench/contact_bench.cpp ran no faster on two
// threads than on one).
#pragma once

#include <cstddef>
#include <functional>

namespace wavecontact::detail {

// Runs work() on the calling thread and on up to `helpers` of the pool's threads at once,
// and returns when every run has returned: true. A pool already running another caller's
// work (that caller's threads, or a for_each_chunk nested in a body) runs nothing: false,
// and the caller does the work alone. work must not throw.
bool run_on_worker_pool(std::size_t helpers, const std::function<void()>& work);

// While one lives (and `active`), run_on_worker_pool called on its thread runs nothing: for
// threads that already keep every core busy between them, such as a map's, where a helper
// would only take a core from another of them and make its caller wait.
class WorkerPoolBypass {
 public:
  explicit WorkerPoolBypass(bool active);
  ~WorkerPoolBypass();
  WorkerPoolBypass(const WorkerPoolBypass&) = delete;
  WorkerPoolBypass& operator=(const WorkerPoolBypass&) = delete;

 private:
  bool before_;
};

}  // namespace wavecontact::detail
