// pi, once for the contact solver, and the zones below which its loops over zones stay on one
// thread.
#pragma once

#include <cstddef>

#include <boost/math/constants/constants.hpp>

namespace wavecontact::detail {

using boost::math::double_constants::pi;

// Fewer zones' rows are not worth starting a thread (wavecontact/threads.hpp).
constexpr std::size_t zones_for_threads = 32;

}  // namespace wavecontact::detail
