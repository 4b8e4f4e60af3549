#include "resource_budget.hpp"

#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>

#include "exit_status.hpp"

namespace wavecontact::derive {

namespace {

#if defined(__SANITIZE_ADDRESS__)
constexpr bool address_sanitizer = true;  // reserves terabytes of address space
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool address_sanitizer = true;
#else
constexpr bool address_sanitizer = false;
#endif
#else
constexpr bool address_sanitizer = false;
#endif

}  // namespace

ResourceBudget::ResourceBudget(double seconds, long megabytes, std::string what) {
  if (!address_sanitizer) {
    const rlim_t bytes = static_cast<rlim_t>(megabytes) * 1024 * 1024;
    rlimit limit{};
    if (getrlimit(RLIMIT_AS, &limit) == 0 && (limit.rlim_max == RLIM_INFINITY || bytes < limit.rlim_max)) {
      limit.rlim_cur = bytes;
      setrlimit(RLIMIT_AS, &limit);
    }
  }
  watchdog_ = std::thread([this, seconds, what = std::move(what)] {
    std::unique_lock<std::mutex> lock(mutex_);
    if (done_.wait_for(lock, std::chrono::duration<double>(seconds), [this] { return finished_; })) {
      return;
    }
    std::fprintf(stderr,
                 "wavecontact-derive: %s: the derivation exceeds its budget of %g s "
                 "(--max-seconds); nothing is written. Its cost grows steeply with the order "
                 "of the profile's parameter-dependent terms: fewer parameters or a lower "
                 "order derive faster\n",
                 what.c_str(), seconds);
    std::fflush(stderr);
    std::_Exit(exit_status::beyond_reach);
  });
}

ResourceBudget::~ResourceBudget() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    finished_ = true;
  }
  done_.notify_one();
  watchdog_.join();
}

}  // namespace wavecontact::derive
