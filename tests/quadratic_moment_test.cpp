// The atoms of the closed forms beyond a = b1/2 (wavecontact/detail/quadratic_moment.hpp) against
// independent quadrature in long double (tanh-sinh), in eps of double: I_{j,l}(z) =
// Int_0^1 w^(2j)/(1 + z w^2)^l dw over z from -1 + 1e-6 to 1e6, across the switches between the
// series and the closed form at z = -3/4 and z = 7, its derivative rule and its refusals; the
// edge basis I'_{j,l}(z) (powers of 1 - w^2); and the two-factor moments J_{j,l}(y, z), J'_{j,l}(y, z)
// across their switches, with y and z near -1 and coinciding.
#define BOOST_TEST_MODULE quadratic_moment
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include <boost/math/quadrature/tanh_sinh.hpp>

#include "wavecontact/detail/quadratic_moment.hpp"

namespace {

constexpr double eps = 2.220446049250313e-16;

// For z < 0 in u = 1 - w, where 1 + z w^2 = (1 + z) + |z| u (2 - u) has no cancellation and
// its near-zero at z -> -1 sits at the endpoint u = 0, where tanh-sinh clusters its nodes.
long double reference(int j, int l, long double z) {
  static boost::math::quadrature::tanh_sinh<long double> integrator;  // integrate() is not const
  if (z < 0) {
    const auto f = [&](long double u) { return std::pow(1 - u, 2 * j) / std::pow((1 + z) - z * u * (2 - u), l); };
    return integrator.integrate(f, 0.0L, 1.0L, 1e-19L);
  }
  const auto f = [&](long double w) { return std::pow(w, 2 * j) / std::pow(1 + z * w * w, l); };
  return integrator.integrate(f, 0.0L, 1.0L, 1e-19L);
}

// 1 + y w^2 in u = 1 - w, without cancellation for y < 0 (given 1 + y exactly).
long double factor(long double y, long double one_plus_y, long double u) {
  return y < 0 ? one_plus_y - y * u * (2 - u) : 1 + y * (1 - u) * (1 - u);
}

// J_{j,l}(y, z), or J'_{j,l}(y, z) with edge, likewise in u = 1 - w (1 - w^2 = u (2 - u)).
long double two_factor_reference(bool edge, int j, int l, long double y, long double one_plus_y, long double z,
                                 long double one_plus_z) {
  static boost::math::quadrature::tanh_sinh<long double> integrator;
  const auto f = [&](long double u) {
    return std::pow(edge ? u * (2 - u) : (1 - u) * (1 - u), j) /
           (factor(y, one_plus_y, u) * std::pow(factor(z, one_plus_z, u), l));
  };
  return integrator.integrate(f, 0.0L, 1.0L, 1e-19L);
}

}  // namespace

BOOST_AUTO_TEST_CASE(against_quadrature_in_eps) {
  double worst = 0;
  std::string where;
  for (int j = 0; j <= 3; ++j) {
    for (int l = 1; l <= 4; ++l) {
      for (double z : {-0.999999, -0.99, -0.9, -0.7500001, -0.75, -0.5,      -0.3, -1e-9, 0.0, 1e-12, 0.2,
                       0.75,      1.0,   3.0,  6.9999999,  7.0,   7.0000001, 12.0, 40.0,  1e3, 1e6}) {
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

// J_{j,l}(y, z) = Int_0^1 w^(2j)/((1 + y w^2)(1 + z w^2)^l) dw and J'_{j,l}(y, z) (numerator
// (1 - w^2)^j) against quadrature, across the switch between partial fractions and the series
// at 1 + y = 5 (1 + z) and (1 + z)/5, with y and z coinciding and near -1 (1 + y, 1 + z given
// exactly). J' within 64 eps (measured 44, at j = l = 3; 1 - w^2 cancels there), J within 32.
BOOST_AUTO_TEST_CASE(two_factor_moment_against_quadrature_in_eps) {
  struct Arguments {
    double one_plus_y, one_plus_z;
  };
  std::vector<Arguments> grid;
  for (double one_plus_z : {1e-9, 2e-4, 0.01, 0.3, 0.5, 0.7, 1.0, 1.3, 2.0, 3.0, 4.0}) {
    for (double ratio :
         {1e-6, 0.1, 0.19999, 0.2, 0.20001, 0.5, 0.9, 0.999999, 1.0, 1.000001, 1.2, 2.0, 4.9999, 5.0, 5.0001, 10.0}) {
      const double one_plus_y = one_plus_z * ratio;
      if (one_plus_y <= 5.0) grid.push_back({one_plus_y, one_plus_z});
    }
  }
  for (const bool edge : {false, true}) {
    double worst = 0;
    std::string where;
    for (const Arguments& a : grid) {
      const double y = a.one_plus_y - 1, z = a.one_plus_z - 1;
      for (int j = 0; j <= 3; ++j) {
        for (int l = edge ? j : 0; l <= 3; ++l) {
          const long double exact = two_factor_reference(edge, j, l, y, a.one_plus_y, z, a.one_plus_z);
          const double got = edge ? wavecontact::two_factor_edge_moment(j, l, y, a.one_plus_y, z, a.one_plus_z)
                                  : wavecontact::two_factor_moment(j, l, y, a.one_plus_y, z, a.one_plus_z);
          const double error = static_cast<double>(std::fabs(got - exact) / exact) / eps;
          std::ostringstream at;
          at << (edge ? "J'_{" : "J_{") << j << "," << l << "}(y = -1 + " << a.one_plus_y << ", z = -1 + "
             << a.one_plus_z << ")";
          if (error > worst) {
            worst = error;
            where = at.str();
          }
          BOOST_TEST(error <= (edge ? 64.0 : 32.0),
                     at.str() << ": " << got << " vs " << static_cast<double>(exact) << ", " << error << " eps");
        }
      }
    }
    BOOST_TEST_MESSAGE((edge ? "two_factor_edge_moment" : "two_factor_moment")
                       << " vs tanh-sinh quadrature: max " << worst << " eps at " << where);
  }
}

// I'_{j,l}(z) = Int_0^1 (1 - w^2)^j/(1 + z w^2)^l dw against quadrature, across its switches at
// z = -3/4, 0 and 7.
BOOST_AUTO_TEST_CASE(edge_moment_against_quadrature_in_eps) {
  static boost::math::quadrature::tanh_sinh<long double> integrator;
  double worst = 0;
  std::string where;
  for (double one_plus_z : {1e-12, 1e-6, 2e-4, 0.01, 0.2, 0.2499999, 0.25, 0.2500001, 0.6, 1.0, 1.0000001, 1.5, 4.0,
                            7.9999999, 8.0, 8.0000001, 20.0, 1e3, 1e6}) {
    const long double z = one_plus_z - 1.0L;
    for (int j = 0; j <= 4; ++j) {
      for (int l = 0; l <= 4; ++l) {
        // In u = 1 - w: (1 - w^2) = u (2 - u), 1 + z w^2 as factor() does.
        const auto f = [&](long double u) { return std::pow(u * (2 - u), j) / std::pow(factor(z, one_plus_z, u), l); };
        const long double exact = integrator.integrate(f, 0.0L, 1.0L, 1e-19L);
        const double got = wavecontact::edge_moment(j, l, static_cast<double>(z), one_plus_z);
        const double error = static_cast<double>(std::fabs(got - exact) / exact) / eps;
        std::ostringstream at;
        at << "I'_{" << j << "," << l << "}(-1 + " << one_plus_z << ")";
        if (error > worst) {
          worst = error;
          where = at.str();
        }
        BOOST_TEST(error <= 16.0,
                   at.str() << ": " << got << " vs " << static_cast<double>(exact) << ", " << error << " eps");
      }
    }
  }
  BOOST_TEST_MESSAGE("edge_moment vs tanh-sinh quadrature: max " << worst << " eps at " << where);
  BOOST_CHECK_THROW(wavecontact::edge_moment(0, 1, -1.0, 0.0), std::domain_error);
}

BOOST_AUTO_TEST_CASE(two_factor_moment_refusals) {
  try {
    wavecontact::two_factor_moment(0, 1, -1.0, 0.0, 0.5, 1.5);
    BOOST_FAIL("y = -1 accepted");
  } catch (const std::domain_error& e) {
    BOOST_TEST(std::string(e.what()).find("two_factor_moment: j = 0, l = 1, y = -1, 1 + y = 0") != std::string::npos,
               e.what());
  }
  BOOST_CHECK_THROW(wavecontact::two_factor_moment(0, 2, 10.0, 11.0, 9.0, 10.0),
                    std::domain_error);  // the series beyond 4
  BOOST_CHECK_THROW(wavecontact::two_factor_moment(-1, 2, 0.0, 1.0, 0.0, 1.0), std::domain_error);
  BOOST_CHECK_NO_THROW(wavecontact::two_factor_moment(0, 2, 10.0, 11.0, 1.0, 2.0));  // far apart
}

BOOST_AUTO_TEST_CASE(refusals_name_the_argument) {
  try {
    wavecontact::quadratic_moment(0, 1, -1.0);
    BOOST_FAIL("z = -1 accepted");
  } catch (const std::domain_error& e) {
    BOOST_TEST(std::string(e.what()).find("quadratic_moment: j = 0, l = 1, z = -1, 1 + z = 0") != std::string::npos,
               e.what());
  }
  BOOST_CHECK_THROW(wavecontact::quadratic_moment(0, 0, 0.5), std::domain_error);
  BOOST_CHECK_THROW(wavecontact::quadratic_moment(0, 1, NAN), std::domain_error);
}
