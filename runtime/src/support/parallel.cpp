#include "support/parallel.hpp"

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <exception>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "support/validate.hpp"
#include "support/worker_pool.hpp"
#include "wavecontact/threads.hpp"

namespace wavecontact {

namespace {

std::atomic<int> chosen_threads{0};  // 0: the default

int default_threads() {
  static const int threads = [] {
    if (const char* value = std::getenv("WAVECONTACT_THREADS"); value != nullptr && *value != '\0') {
      char* end = nullptr;
      const long n = std::strtol(value, &end, 10);
      if (*end != '\0' || n < 1 || n > max_array_kernel_threads) {
        throw std::domain_error(std::string("wavecontact::array_kernel_threads: WAVECONTACT_THREADS = ") + value +
                                " is invalid (valid: an integer from 1 to " + std::to_string(max_array_kernel_threads) +
                                ", or unset)");
      }
      return static_cast<int>(n);
    }
    return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  }();
  return threads;
}

}  // namespace

int array_kernel_threads() {
  const int chosen = chosen_threads.load(std::memory_order_relaxed);
  return chosen > 0 ? chosen : default_threads();
}

void set_array_kernel_threads(int threads) {
  if (threads < 0 || threads > max_array_kernel_threads) {
    detail::domain_error("wavecontact::set_array_kernel_threads", "threads", threads,
                         "1 <= threads <= " + std::to_string(max_array_kernel_threads) + ", or 0 for the default");
  }
  chosen_threads.store(threads, std::memory_order_relaxed);
}

namespace detail {

bool for_each_chunk(std::size_t count, std::size_t block, std::size_t min_points,
                    const std::function<bool(std::size_t, std::size_t)>& check,
                    const std::function<void(std::size_t, std::size_t)>& body) {
  const std::size_t blocks = (count + block - 1) / block;
  const std::size_t threads =
      count < min_points ? 1 : std::min(blocks, static_cast<std::size_t>(array_kernel_threads()));
  if (threads <= 1) {
    if (check && !check(0, count)) return false;
    body(0, count);
    return true;
  }
  // Chunks handed out in order from a shared counter, chunks_per_thread a thread on average:
  // a thread that the machine slows down takes fewer of them, where equal shares fixed in
  // advance would all wait for it. Each point is computed alone, so which thread takes which
  // chunk does not change a bit. The checks first, all of them (a thread waits for the
  // chunks the others are checking), then the bodies.
  constexpr std::size_t chunks_per_thread = 8;
  const std::size_t chunk = (blocks + threads * chunks_per_thread - 1) / (threads * chunks_per_thread) * block;
  const std::size_t chunks = (count + chunk - 1) / chunk;
  std::atomic<std::size_t> next_check{0}, checked{0}, next_body{0};
  std::atomic<bool> held{true};
  const auto work = [&] {
    if (check) {
      for (std::size_t begin; (begin = next_check.fetch_add(chunk)) < count; checked.fetch_add(1)) {
        if (!check(begin, std::min(count, begin + chunk))) held.store(false);
      }
      while (checked.load() < chunks) std::this_thread::yield();
      if (!held.load()) return;
    }
    for (std::size_t begin; (begin = next_body.fetch_add(chunk)) < count;) body(begin, std::min(count, begin + chunk));
  };
  if (!run_on_worker_pool(threads - 1, work)) work();
  return held.load();
}

void for_each_chunk(std::size_t count, std::size_t block, std::size_t min_points,
                    const std::function<void(std::size_t, std::size_t)>& body) {
  for_each_chunk(count, block, min_points, nullptr, body);
}

void for_each_index(std::size_t count, std::size_t min_count, const std::function<void(std::size_t)>& body) {
  std::exception_ptr first;
  std::atomic<bool> failed{false};
  std::mutex guard;
  for_each_chunk(count, 1, min_count, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end && !failed.load(); ++i) {
      try {
        body(i);
      } catch (...) {
        const std::lock_guard<std::mutex> lock(guard);
        if (!first) first = std::current_exception();
        failed.store(true);
      }
    }
  });
  if (first) std::rethrow_exception(first);
}

}  // namespace detail
}  // namespace wavecontact
