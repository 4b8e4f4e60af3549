// I_{j,l}(z) = Int_0^1 w^(2j)/(1 + z w^2)^l dw (wavecontact/quadratic_moment.hpp), the atoms of
// the closed forms beyond a = b1/2, against independent quadrature in long double (tanh-sinh),
// in eps of double, over z from -1 + 1e-6 to 1e6, across the switches between the series and
// the closed form at z = -3/4 and z = 7; its derivative rule; and its refusals.
#define BOOST_TEST_MODULE quadratic_moment
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <string>

#include <boost/math/quadrature/tanh_sinh.hpp>

#include "wavecontact/quadratic_moment.hpp"

namespace {

constexpr double eps = 2.220446049250313e-16;

// For z < 0 in u = 1 - w, where 1 + z w^2 = (1 + z) + |z| u (2 - u) has no cancellation and
// its near-zero at z -> -1 sits at the endpoint u = 0, where tanh-sinh clusters its nodes.
long double reference(int j, int l, long double z) {
  static boost::math::quadrature::tanh_sinh<long double> integrator;  // integrate() is not const
  if (z < 0) {
    const auto f = [&](long double u) {
      return std::pow(1 - u, 2 * j) / std::pow((1 + z) - z * u * (2 - u), l);
    };
    return integrator.integrate(f, 0.0L, 1.0L, 1e-19L);
  }
  const auto f = [&](long double w) { return std::pow(w, 2 * j) / std::pow(1 + z * w * w, l); };
  return integrator.integrate(f, 0.0L, 1.0L, 1e-19L);
}

}  // namespace

BOOST_AUTO_TEST_CASE(against_quadrature_in_eps) {
  double worst = 0;
  std::string where;
  for (int j = 0; j <= 3; ++j) {
    for (int l = 1; l <= 4; ++l) {
      for (double z : {-0.999999, -0.99, -0.9, -0.7500001, -0.75, -0.5, -0.3, -1e-9, 0.0, 1e-12, 0.2,
                       0.75, 1.0, 3.0, 6.9999999, 7.0, 7.0000001, 12.0, 40.0, 1e3, 1e6}) {
        const long double exact = reference(j, l, z);
        const double got = wavecontact::quadratic_moment(j, l, z);
        const double error = static_cast<double>(std::fabs(got - exact) / exact) / eps;
        if (error > worst) {
          worst = error;
          where = "j = " + std::to_string(j) + ", l = " + std::to_string(l) + ", z = " + std::to_string(z);
        }
        BOOST_TEST(error <= 8.0, "I_{" << j << "," << l << "}(" << z << "): " << got << " vs "
                                        << static_cast<double>(exact) << ", " << error << " eps");
      }
    }
  }
  BOOST_TEST_MESSAGE("quadratic_moment vs tanh-sinh quadrature: max " << worst << " eps at " << where);
}

// dI_{j,l}/dz = -l I_{j+1,l+1}, the rule the derivation differentiates with.
BOOST_AUTO_TEST_CASE(derivative_rule) {
  for (double z : {-0.7, 0.1, 2.0}) {
    const double h = 1e-4;
    const auto I = [](double at) { return wavecontact::quadratic_moment(1, 2, at); };
    const double difference = (8 * (I(z + h) - I(z - h)) - (I(z + 2 * h) - I(z - 2 * h))) / (12 * h);
    BOOST_TEST(difference == -2 * wavecontact::quadratic_moment(2, 3, z), boost::test_tools::tolerance(1e-10));
  }
}

// Near z = -1 the moments grow like (1 + z)^(1/2 - l): with 1 + z given exactly they keep
// their digits where the three-argument form, rounding 1 + z from z, cannot.
BOOST_AUTO_TEST_CASE(one_plus_z_near_minus_one) {
  const double gap = 3e-12;  // 1 + z, exactly; z itself rounds
  const double z = -1 + gap;
  const long double exact_gap = 3e-12L;
  const long double y = std::sqrt(1 - exact_gap);
  const long double I02 = 1 / (2 * exact_gap) + std::atanh(y) / (2 * y);  // I_{0,2}(-1 + gap)
  const double with_gap = wavecontact::quadratic_moment(0, 2, z, gap);
  BOOST_TEST(static_cast<double>(std::fabs(with_gap - I02) / I02) <= 4 * eps);
}

BOOST_AUTO_TEST_CASE(refusals_name_the_argument) {
  try {
    wavecontact::quadratic_moment(0, 1, -1.0);
    BOOST_FAIL("z = -1 accepted");
  } catch (const std::domain_error& e) {
    BOOST_TEST(std::string(e.what()).find("quadratic_moment: j = 0, l = 1, z = -1, 1 + z = 0") != std::string::npos, e.what());
  }
  BOOST_CHECK_THROW(wavecontact::quadratic_moment(0, 0, 0.5), std::domain_error);
  BOOST_CHECK_THROW(wavecontact::quadratic_moment(0, 1, NAN), std::domain_error);
}
