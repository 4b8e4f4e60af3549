#include "support/worker_pool.hpp"

#include <pthread.h>

#include <atomic>
#include <condition_variable>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

namespace wavecontact::detail {

namespace {

thread_local bool working = false;  // this thread runs a pool's work, or bypasses the pool

// Runs work on this thread, marked as pool work.
void run_marked(const std::function<void()>& work) {
  working = true;
  work();
  working = false;
}

class WorkerPool {
 public:
  bool run(std::size_t helpers, const std::function<void()>& work) {
    if (working) return false;  // nested: this thread may hold busy_ itself
    std::unique_lock<std::mutex> caller(busy_, std::try_to_lock);
    if (!caller.owns_lock()) return false;
    grow(helpers);
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      job_ = &work;
      open_ = std::min(helpers, workers_);
    }
    wake_.notify_all();
    run_marked(work);
    std::unique_lock<std::mutex> lock(mutex_);
    open_ = 0;  // a thread that wakes only now finds nothing to join
    done_.wait(lock, [this] { return running_ == 0; });
    job_ = nullptr;
    return true;
  }

 private:
  // Threads up to `helpers`, detached: the pool lives as long as the process.
  void grow(std::size_t helpers) {
    while (workers_ < helpers) {
      try {
        std::thread([this] { serve(); }).detach();
      } catch (const std::system_error&) {
        return;  // no thread to be had: fewer helpers
      }
      ++workers_;
    }
  }

  void serve() {
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
      wake_.wait(lock, [this] { return open_ > 0; });
      --open_, ++running_;
      const std::function<void()>& work = *job_;
      lock.unlock();
      run_marked(work);
      lock.lock();
      if (--running_ == 0) done_.notify_one();
    }
  }

  std::mutex busy_;   // held by the caller whose work the pool runs
  std::mutex mutex_;  // guards what follows
  std::condition_variable wake_, done_;
  std::size_t workers_ = 0;  // grown by the holder of busy_ only
  const std::function<void()>* job_ = nullptr;
  std::size_t open_ = 0;     // helpers that may still join the work
  std::size_t running_ = 0;  // helpers running it
};

// Never destroyed: its threads wait for work until the process ends. A child of fork()
// has none of them, and starts a pool of its own.
std::atomic<WorkerPool*> instance{nullptr};

WorkerPool& pool() {
  WorkerPool* current = instance.load(std::memory_order_acquire);
  if (current != nullptr) return *current;
  static std::once_flag forks;
  std::call_once(forks, [] { pthread_atfork(nullptr, nullptr, [] { instance.store(nullptr); }); });
  auto* fresh = new WorkerPool;
  if (instance.compare_exchange_strong(current, fresh, std::memory_order_acq_rel)) return *fresh;
  delete fresh;
  return *current;
}

}  // namespace

bool run_on_worker_pool(std::size_t helpers, const std::function<void()>& work) { return pool().run(helpers, work); }

WorkerPoolBypass::WorkerPoolBypass(bool active) : before_(working) { working = working || active; }

WorkerPoolBypass::~WorkerPoolBypass() { working = before_; }

}  // namespace wavecontact::detail
