// The conditions every contact must meet, checked point by point against the public API
// (contact_test, contact_regression_test).
#pragma once

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <string>

#include "wavecontact/contact.hpp"

namespace wavecontact::test {

// A contact: p >= 0 on its zones and p -> 0 at their ends, gap >= 0 off them, the zones'
// loads adding up to P, and the gap closing at both ends of every gap (one rigid approach):
// the gap is 0 at the zone ends, computed from either side.
inline void check_contact(const Contact& c, double b1, const std::string& what) {
  double zone_loads = 0;
  for (const ContactZone& z : c.zones()) {
    zone_loads += z.load;
    for (int i = 1; i < 50; ++i) {
      const double x = z.x_start + (z.x_end - z.x_start) * i / 50;
      BOOST_TEST(c.pressure(x) >= -1e-12 * c.max_pressure(), what << ": p(" << x << ") = " << c.pressure(x));
    }
    if (!c.full_contact()) {
      const double h = 1e-10 * b1;
      BOOST_TEST(c.pressure(z.x_end - h) < 1e-3 * c.max_pressure(), what << ": p at a zone end");
      BOOST_TEST(std::fabs(c.gap(z.x_end + h)) < 1e-9, what << ": gap just past " << z.x_end);
      BOOST_TEST(std::fabs(c.gap(z.x_start - h)) < 1e-9, what << ": gap just before " << z.x_start);
    }
  }
  BOOST_TEST(zone_loads == c.load(), boost::test_tools::tolerance(1e-10));
  for (int i = 0; i <= 2000; ++i) {
    const double x = -b1 + 2 * b1 * i / 2000;
    BOOST_TEST(c.gap(x) >= -1e-9, what << ": gap(" << x << ") = " << c.gap(x));
  }
}

}  // namespace wavecontact::test
