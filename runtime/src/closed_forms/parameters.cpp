#include "wavecontact/parameters.hpp"

#include "support/validate.hpp"

namespace wavecontact {

double reduced_modulus(double E1, double nu1, double E2, double nu2) {
  constexpr const char* function = "wavecontact::reduced_modulus";
  detail::require_positive(function, "E1", E1);
  detail::require_positive(function, "E2", E2);
  for (auto [name, nu] : {std::pair{"nu1", nu1}, std::pair{"nu2", nu2}}) {
    if (!(std::isfinite(nu) && nu > -1 && nu <= 0.5)) {
      detail::domain_error(function, name, nu, "-1 < nu <= 0.5");
    }
  }
  return 1 / ((1 - nu1 * nu1) / E1 + (1 - nu2 * nu2) / E2);  // eq. 7
}

void validate(const WavinessParams& p, const char* function) {
  detail::require_scale(function, "H1", p.H1);
  detail::require_scale(function, "b1", p.b1);
  detail::require_scale(function, "E", p.E);
  if (!(std::isfinite(p.m) && p.m >= 0 && p.m <= max_shape)) {
    detail::domain_error(function, "m", p.m, "0 <= m <= " + detail::format(max_shape));
  }
}

}  // namespace wavecontact
