// The threads of the array evaluations (waviness.hpp, two_scale.hpp, contact.hpp): a large
// enough array is split into contiguous chunks of whole SIMD blocks (about 8 a thread), which
// the threads take in turn from a shared counter. Every point is computed as it would be
// alone, so the results are the same bits whatever the number of threads. The contact solver
// (solve_contact) takes the same threads for its zones' equations from 32 zones in half a
// period, each zone's computed alone: its results, too, are the same bits.
#pragma once

#include <cstddef>

namespace wavecontact {

// Below this many points an array is evaluated on the calling thread: the closed forms (a few
// ns a point), and the evaluators that cost microseconds a point (the quadrature beyond
// b1/2, the contact's pressure).
inline constexpr std::size_t parallel_points = 32768;
inline constexpr std::size_t parallel_points_costly = 64;

inline constexpr int max_array_kernel_threads = 4096;

// The most threads an array evaluation uses: set_array_kernel_threads(), else the environment
// variable WAVECONTACT_THREADS (read once; std::domain_error naming it and its value unless it
// is an integer from 1 to max_array_kernel_threads), else the CPU's hardware threads.
int array_kernel_threads();

// Caps the threads (1: the calling thread only); 0 returns to the default above. Throws
// std::domain_error for a count below 0 or above max_array_kernel_threads.
void set_array_kernel_threads(int threads);

}  // namespace wavecontact
