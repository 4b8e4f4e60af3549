// pi, once for the contact solver.
#pragma once

#include <boost/math/constants/constants.hpp>

namespace wavecontact::detail {

using boost::math::double_constants::pi;

}  // namespace wavecontact::detail
