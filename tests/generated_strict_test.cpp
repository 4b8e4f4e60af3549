// The emitted evaluators compile cleanly under -Wall -Wextra -Wpedantic -Werror (set for
// this target in CMakeLists.txt) for several scalar types, and the float and long double
// instantiations agree with the double one to their precision.
#define BOOST_TEST_MODULE generated_strict
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "waviness.hpp"  // generated/

namespace tt = boost::test_tools;
using namespace wavecontact::generated;

template <typename T>
struct Point {
  // m = 2, a^ = 1.2, x^ = 0.5 in angle atoms, E = 1.5, H1 = 0.25, b1 = 3.
  T m = 2, Ca = std::cos(T(1.2)), Cx = std::cos(T(0.5));
  T Sa = 1 - Ca, Sx = 1 - Cx, D = Cx - Ca, E = T(1.5), H1 = T(0.25), b1 = 3;
  T pressure() const { return waviness_pressure_exact(E, H1, b1, m, Ca, Sa, Cx, Sx, D); }
  T paper() const { return waviness_pressure_paper(E, H1, b1, m, Ca, Sa, Cx, Sx, D); }
  T load() const { return waviness_load(E, H1, m, Ca, Sa); }
  T ratio() const { return waviness_pa_over_pstar(m, Ca, Sa); }
};

BOOST_AUTO_TEST_CASE(instantiations_agree) {
  const Point<long double> l;
  const Point<double> d;
  const Point<float> f;
  BOOST_TEST(d.pressure() == static_cast<double>(l.pressure()), tt::tolerance(1e-14));
  BOOST_TEST(f.pressure() == static_cast<float>(l.pressure()), tt::tolerance(1e-5f));
  BOOST_TEST(d.paper() == static_cast<double>(l.paper()), tt::tolerance(1e-14));
  BOOST_TEST(d.load() == static_cast<double>(l.load()), tt::tolerance(1e-14));
  BOOST_TEST(f.ratio() == static_cast<float>(l.ratio()), tt::tolerance(1e-5f));
}
