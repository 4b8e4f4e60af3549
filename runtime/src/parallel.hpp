// Runs an array evaluation over chunks of its points on array_kernel_threads() threads
// (wavecontact/threads.hpp).
#pragma once

#include <cstddef>
#include <functional>

namespace wavecontact::detail {

// body(begin, end) for contiguous chunks covering [0, count), each a whole number of `block`
// points but the last; on the calling thread alone below min_points (parallel_points or
// parallel_points_costly). body must not throw (the inputs are checked before).
void for_each_chunk(std::size_t count, std::size_t block, std::size_t min_points,
                    const std::function<void(std::size_t, std::size_t)>& body);

}  // namespace wavecontact::detail
