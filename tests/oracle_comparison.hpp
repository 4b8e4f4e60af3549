// The contact solver's answer against the boundary-element oracle (bem_oracle.hpp): the
// profiles written here from eqs. 1-3 (not taken from the runtime), and the comparison of
// zones, contact fraction, p(0) and the largest pressure, each within the oracle's error
// estimate (doubled: Richardson's estimate is itself an estimate) plus the solver's.
#pragma once

#include <boost/math/constants/constants.hpp>
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "bem_oracle.hpp"
#include "wavecontact/contact.hpp"

namespace wavecontact::test {

// Eqs. 1-3 over the normalised period: the wave curve and roughness harmonics (H, n).
inline std::function<double(double)> surface_profile(double H1, double m,
                                                     const std::vector<std::pair<double, int>>& harmonics) {
  return [=](double x) {
    const double c = std::cos(x);
    double y = H1 * (m + 1) * c / (m * std::fabs(c) + 1);
    for (const auto& [H, n] : harmonics) y += H * std::cos(n * x);
    return y;
  };
}

inline std::function<double(double)> two_scale_profile(double H1, double m, double H2, int n) {
  return surface_profile(H1, m, {{H2, n}});
}

// Eq. 2 changes branch at x^ = pi/2 for m > 0.
inline std::vector<double> kinks(double m) { return m > 0 ? std::vector<double>{M_PI / 2} : std::vector<double>{}; }

// |a - b| <= twice the oracle's estimate plus the solver's.
inline void agree(double solver, double oracle, double oracle_error, double solver_error, const std::string& what) {
  const double allowed = 2 * oracle_error + solver_error;
  BOOST_TEST(std::fabs(solver - oracle) <= allowed, what << ": solver " << solver << ", oracle " << oracle << " +- "
                                                         << oracle_error << " (difference "
                                                         << std::fabs(solver - oracle) << ")");
}

// The solver's contact (physical units, b1) against the oracle (normalised: x^ = pi x/b1,
// p^ = p b1/pi). The zone ends agree within the oracle's estimate, or, given end_resolution
// (x^; for many zones, where the sub-grid fit's estimate is too tight for the smallest
// zones), within it.
inline void compare(const Contact& c, const BemEstimate& bem, double b1, const std::string& name,
                    double end_resolution = 0) {
  using boost::math::double_constants::pi;
  const double to_x = pi / b1, to_p = b1 / pi;
  // Zones of [0, pi] from the solver's zones of the period.
  std::vector<double> ends;
  for (const ContactZone& z : c.zones()) {
    if (z.x_end <= 0) continue;  // mirror images
    ends.push_back(std::max(0.0, z.x_start) * to_x);
    ends.push_back(std::min(b1, z.x_end) * to_x);
  }
  BOOST_TEST_REQUIRE(ends.size() == bem.zone_ends.size(), name << ": the solver has " << ends.size() / 2
                                                               << " zones in [0, b1], the oracle "
                                                               << bem.zone_ends.size() / 2);
  const double end_error = c.error_estimate() * 2 * pi;
  double worst = 0;
  for (std::size_t i = 0; i < ends.size(); ++i) {
    const double oracle_error = end_resolution > 0 ? end_resolution / 2 : bem.zone_ends_error[i];
    agree(ends[i], bem.zone_ends[i], oracle_error, end_error, name + ", zone end " + std::to_string(i));
    worst = std::max(worst, std::fabs(ends[i] - bem.zone_ends[i]));
  }
  const double p_error = c.error_estimate() * c.max_pressure() * to_p;
  agree(c.contact_fraction(), bem.contact_fraction, bem.contact_fraction_error, c.error_estimate(),
        name + ", contact fraction");
  agree(c.pressure(0) * to_p, bem.p0, bem.p0_error, p_error, name + ", p(0)");
  agree(c.max_pressure() * to_p, bem.max_pressure, bem.max_pressure_error, p_error, name + ", max p");
  BOOST_TEST_MESSAGE(name << ": " << ends.size() / 2 << " zone(s) in [0, b1], ends within " << worst << " (x^), p(0) "
                          << c.pressure(0) * to_p << " vs " << bem.p0 << " +- " << bem.p0_error << ", max p "
                          << c.max_pressure() * to_p << " vs " << bem.max_pressure << " +- " << bem.max_pressure_error);
}

}  // namespace wavecontact::test
