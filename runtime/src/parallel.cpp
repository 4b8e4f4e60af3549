#include "parallel.hpp"

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

#include "validate.hpp"
#include "wavecontact/threads.hpp"

namespace wavecontact {

namespace {

std::atomic<int> chosen_threads{0};  // 0: the default

int default_threads() {
  static const int threads = [] {
    if (const char* value = std::getenv("WAVECONTACT_THREADS"); value != nullptr && *value != '\0') {
      char* end = nullptr;
      const long n = std::strtol(value, &end, 10);
      if (*end != '\0' || n < 1 || n > 4096) {
        throw std::domain_error(std::string("wavecontact::array_kernel_threads: WAVECONTACT_THREADS = ") + value +
                                " is invalid (valid: an integer from 1 to 4096, or unset)");
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
  if (threads < 0) {
    detail::domain_error("wavecontact::set_array_kernel_threads", "threads", threads, ">= 1, or 0 for the default");
  }
  chosen_threads.store(threads, std::memory_order_relaxed);
}

namespace detail {

void for_each_chunk(std::size_t count, std::size_t block, std::size_t min_points,
                    const std::function<void(std::size_t, std::size_t)>& body) {
  const std::size_t blocks = (count + block - 1) / block;
  const std::size_t threads =
      count < min_points ? 1 : std::min(blocks, static_cast<std::size_t>(array_kernel_threads()));
  if (threads <= 1) {
    body(0, count);
    return;
  }
  const std::size_t per_thread = (blocks + threads - 1) / threads * block;
  std::vector<std::thread> workers;
  std::size_t begin = per_thread;
  for (; begin < count; begin += per_thread) {
    try {
      workers.emplace_back(body, begin, std::min(count, begin + per_thread));
    } catch (const std::system_error&) {
      break;  // no thread to be had: the calling thread takes the rest
    }
  }
  body(0, std::min(count, per_thread));  // the calling thread takes the first chunk
  for (; begin < count; begin += per_thread) body(begin, std::min(count, begin + per_thread));
  for (std::thread& worker : workers) worker.join();
}

}  // namespace detail
}  // namespace wavecontact
