// pi, once for the contact solver.
#pragma once

#include <boost/math/constants/constants.hpp>

namespace wavecontact::detail {

inline constexpr double pi = boost::math::double_constants::pi;

}  // namespace wavecontact::detail
