// Runs an array evaluation over chunks of its points, or the contact solver over its zones, on
// array_kernel_threads() threads (wavecontact/threads.hpp).
#pragma once

#include <cstddef>
#include <functional>

namespace wavecontact::detail {

// body(begin, end) for contiguous chunks covering [0, count), each a whole number of `block`
// points but the last, taken in turn by the threads (a thread may take several, in any order);
// on the calling thread alone below min_points (parallel_points or parallel_points_costly).
// body must not throw (the inputs are checked before).
void for_each_chunk(std::size_t count, std::size_t block, std::size_t min_points,
                    const std::function<void(std::size_t, std::size_t)>& body);

// The same after check(begin, end) on every chunk, by the same threads, and only if it held on
// all of them (nothing is written otherwise): whether it held. Neither may throw.
bool for_each_chunk(std::size_t count, std::size_t block, std::size_t min_points,
                    const std::function<bool(std::size_t, std::size_t)>& check,
                    const std::function<void(std::size_t, std::size_t)>& body);

// body(i) for every i of [0, count), on the same threads when count >= min_count (else on the
// calling thread). A body may throw: the first exception is rethrown here, after every thread
// has stopped (the remaining indices are then skipped).
void for_each_index(std::size_t count, std::size_t min_count, const std::function<void(std::size_t)>& body);

}  // namespace wavecontact::detail
