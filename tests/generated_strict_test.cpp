// The emitted evaluators compile cleanly under -Wall -Wextra -Wpedantic -Werror (set for
// this target in CMakeLists.txt) for several scalar types, and the float and long double
// instantiations agree with the double one to their precision.
#define BOOST_TEST_MODULE generated_strict
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "wavecontact/generated/bounded_trigonometry.hpp"
#include "wavecontact/generated/profiles.hpp"
#include "wavecontact/generated/roughness_evaluators.hpp"
#include "wavecontact/generated/waviness_evaluators.hpp"

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

BOOST_AUTO_TEST_CASE(full_contact_is_the_limit_of_the_exact_roughness_pressure) {
  // At a = b1 (Ca = -1, Sa = 2, D = 1 + Cx) the exact pressure is p*_r (cos(n x^) - 1); eq. 15
  // adds the uniform 2 p*_r that full contact admits.
  const double E = 2, H2 = 0.1, b1 = 3;
  for (double xhat : {0.1, 0.9, 2.0, 3.0}) {
    const double Cx = std::cos(xhat), Sx = 1 - Cx;
    auto check = [&](int n, double partial) {
      const double pstar = M_PI * E * H2 * n / (2 * b1);
      const double full = roughness_full_contact_pressure<double>(E, H2, b1, n, std::cos(n * xhat));
      BOOST_TEST(partial + 2 * pstar == full, tt::tolerance(1e-12));
    };
    check(2, roughness_n2_pressure<double>(E, H2, b1, -1, 2, Cx, Sx, 1 + Cx));
    check(8, roughness_n8_pressure<double>(E, H2, b1, -1, 2, Cx, Sx, 1 + Cx));
    check(64, roughness_n64_pressure<double>(E, H2, b1, -1, 2, Cx, Sx, 1 + Cx));
  }
}

// The example profiles' evaluators, also held to -Werror, in float, double and long double.
BOOST_AUTO_TEST_CASE(profile_instantiations_agree) {
  auto at = [](auto zero) {
    using T = decltype(zero);
    const T Ca = std::cos(T(1.2)), Cx = std::cos(T(0.5)), E = T(1.5), b1 = 3, H1 = T(0.25);
    const T p = two_harmonic_pressure<T>(E, b1, H1, T(0.02), Ca, 1 - Ca, Cx, 1 - Cx, Cx - Ca);
    const T w = parametric_wave_curve_load_slope_factor<T>(E, H1, T(2), Ca, 1 - Ca);
    return std::make_pair(p, w);
  };
  const auto l = at(0.0L);
  const auto d = at(0.0);
  const auto f = at(0.0f);
  BOOST_TEST(d.first == static_cast<double>(l.first), tt::tolerance(1e-14));
  BOOST_TEST(f.first == static_cast<float>(l.first), tt::tolerance(1e-5f));
  BOOST_TEST(d.second == static_cast<double>(l.second), tt::tolerance(1e-14));
  BOOST_TEST(parametric_wave_curve_pole_square_0<double>(1, 3) == 2.0);  // (m+1)/(m-1)
}

// The derived bounded sine in float, double and long double (-Werror, -Wconversion).
BOOST_AUTO_TEST_CASE(bounded_sine_instantiations_agree) {
  const long double l = sinpi_quarter(0.2L);
  BOOST_TEST(sinpi_quarter(0.2) == static_cast<double>(l), tt::tolerance(1e-15));
  BOOST_TEST(sinpi_quarter(0.2f) == static_cast<float>(l), tt::tolerance(1e-6f));
}
