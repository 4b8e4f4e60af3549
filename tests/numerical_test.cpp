// Numerical tests of the runtime: docs/mathematics.md's check values, Westergaard, the independent
// numerical inversion (docs/mathematics.md section 4), the load identity (docs/mathematics.md fact 7), and the
// domain checks. Uses the runtime only.
#define BOOST_TEST_MODULE numerical
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <string>

#include <boost/math/constants/constants.hpp>
#include <boost/math/quadrature/tanh_sinh.hpp>

#include "wavecontact/angles.hpp"
#include "wavecontact/numerical_inversion.hpp"
#include "wavecontact/stability.hpp"
#include "wavecontact/waviness.hpp"

namespace tt = boost::test_tools;
using wavecontact::Form;
using wavecontact::WavinessParams;

namespace {

using boost::math::double_constants::pi;

// G(x^) = -(E*/2) y'(x^) of the parametric wave curve on the top half of the asperity,
// written from eq. 2 by hand (independent of derive/).
double slope_rhs(const WavinessParams& p, double xhat) {
  const double denominator = p.m * std::cos(xhat) + 1;
  return p.E * p.H1 / 2 * (p.m + 1) * std::sin(xhat) / (denominator * denominator);
}

// The pressure by the independent numerical inversion, in physical units.
double numerical_pressure(const WavinessParams& p, double a, double x, int nodes) {
  const double alpha = std::tan(pi * a / (2 * p.b1)), u = std::tan(pi * x / (2 * p.b1));
  const auto g = [&](double v) { return slope_rhs(p, 2 * std::atan(v)); };
  return pi / p.b1 * wavecontact::numerical_inversion(g, alpha, u, nodes);
}

// docs/mathematics.md fact 7: P = 2 sqrt(2) Int_0^a^ G(x^) sin(x^/2) / sqrt(cos x^ - cos a^) dx^.
double load_by_quadrature(const WavinessParams& p, double a) {
  const double ahat = pi * a / p.b1;
  boost::math::quadrature::tanh_sinh<double> integrator;
  const auto f = [&](double xhat, double complement) {
    // cos x - cos a = 2 sin((a+x)/2) sin((a-x)/2); near the upper end the integrator's
    // complement (b - x > 0 there) gives a - x without cancellation.
    const double gap = complement > 0 ? complement : ahat - xhat;
    const double difference = 2 * std::sin((ahat + xhat) / 2) * std::sin(gap / 2);
    return slope_rhs(p, xhat) * std::sin(xhat / 2) / std::sqrt(difference);
  };
  return 2 * std::sqrt(2.0) * integrator.integrate(f, 0.0, ahat);
}

}  // namespace

BOOST_AUTO_TEST_CASE(math_md_check_values) {
  struct Row {
    double m, a_over_b1, x_over_a, exact, printed, load;
  };
  const Row rows[] = {
      {2, 0.45, 0, 0.5375117929804417, 0.4946785116549152, 1.525693430655888},
      {10, 0.45, 0, 0.3234091494997856, 0.2532608275678914, 1.070213575867781},
      {0.2, 0.3, 0.5, 0.3514344805563268, 0.3514391509721434, 0.6003844994822082},
      {5, 0.4, 0.25, 0.2569750078646253, 0.2389751377024990, 0.6548011577944177},
  };
  for (const Row& r : rows) {
    const WavinessParams p{1, pi, r.m, 1};
    const double a = r.a_over_b1 * pi, x = r.x_over_a * a;
    BOOST_TEST(wavecontact::pressure(p, a, x, Form::exact) == r.exact, tt::tolerance(1e-13));
    BOOST_TEST(wavecontact::pressure(p, a, x, Form::paper) == r.printed, tt::tolerance(1e-13));
    BOOST_TEST(wavecontact::load(p, a) == r.load, tt::tolerance(1e-13));
  }
}

BOOST_AUTO_TEST_CASE(m_zero_is_westergaard) {
  const WavinessParams p{0.8, 3.0, 0.0, 2.0};
  const double pstar = pi * p.E * p.H1 / (2 * p.b1);
  BOOST_TEST(wavecontact::pstar(p) == pstar, tt::tolerance(1e-15));
  for (double fa : {0.01, 0.2, 0.37, 0.5}) {
    const double a = fa * p.b1;
    const double sa = std::sin(pi * a / (2 * p.b1));
    BOOST_TEST(wavecontact::pa_over_pstar(p, a) == sa * sa, tt::tolerance(1e-14));
    for (double fx : {0.0, 0.3, 0.8, 0.99}) {
      const double x = fx * a, sx = std::sin(pi * x / (2 * p.b1));
      const double westergaard = 2 * pstar * std::cos(pi * x / (2 * p.b1)) * std::sqrt(sa * sa - sx * sx);
      for (Form form : {Form::exact, Form::paper}) {
        BOOST_TEST(wavecontact::pressure(p, a, x, form) == westergaard, tt::tolerance(1e-13));
      }
    }
  }
}

BOOST_AUTO_TEST_CASE(closed_form_agrees_with_numerical_inversion) {
  // Relative to the zone's centre pressure; m = 1 (no pole) and m near 1 included.
  for (double m : {0.0, 0.2, 0.999, 1.0, 1.001, 2.0, 10.0, 100.0}) {
    const WavinessParams p{1.3, 2.0, m, 0.7};
    for (double fa : {0.05, 0.25, 0.45, 0.5}) {
      const double a = fa * p.b1, scale = wavecontact::pressure(p, a, 0.0);
      for (double fx : {0.0, 0.4, 0.9, 0.999}) {
        const double x = fx * a;
        const double closed = wavecontact::pressure(p, a, x);
        const double numerical = numerical_pressure(p, a, x, 4000);
        BOOST_TEST(std::abs(closed - numerical) / scale <= 1e-12, "m = " << m << " a/b1 = " << fa << " x/a = " << fx
                                                                         << ": closed " << closed << ", numerical "
                                                                         << numerical);
      }
    }
  }
}

BOOST_AUTO_TEST_CASE(load_agrees_with_x_space_quadrature) {
  for (double m : {0.0, 0.2, 1.0, 2.0, 10.0, 1e3}) {
    const WavinessParams p{1.0, 5.0, m, 3.0};
    for (double fa : {0.02, 0.3, 0.5}) {
      const double a = fa * p.b1;
      BOOST_TEST(wavecontact::load(p, a) == load_by_quadrature(p, a), tt::tolerance(1e-12));
      BOOST_TEST(wavecontact::mean_pressure(p, a) == wavecontact::load(p, a) / (2 * p.b1), tt::tolerance(1e-15));
    }
  }
}

BOOST_AUTO_TEST_CASE(pressure_is_periodic_even_and_zero_outside) {
  const WavinessParams p{1.0, 4.0, 3.0, 1.0};
  const double a = 1.5;
  for (double x : {0.0, 0.3, 1.2, 1.4999}) {
    const double value = wavecontact::pressure(p, a, x);
    BOOST_TEST(wavecontact::pressure(p, a, -x) == value, tt::tolerance(1e-15));
    // x + 8 rounds by up to 1e-15 absolute, 1e-11 of a - x at the last point.
    BOOST_TEST(wavecontact::pressure(p, a, x + 2 * p.b1) == value, tt::tolerance(1e-10));
    BOOST_TEST(wavecontact::pressure(p, a, x - 6 * p.b1) == value, tt::tolerance(1e-10));
  }
  for (double x : {1.5, 2.0, 4.0, -3.0, 6.2}) BOOST_TEST(wavecontact::pressure(p, a, x) == 0.0);
  Eigen::ArrayXd xs(4);
  xs << 0.0, 0.7, 1.2, 3.0;
  const Eigen::ArrayXd ps = wavecontact::pressure(p, a, xs);
  // The array path has its own atoms (vectorised where the CPU allows): equal to a few ulp.
  for (Eigen::Index i = 0; i < xs.size(); ++i) {
    BOOST_TEST(ps[i] == wavecontact::pressure(p, a, xs[i]), tt::tolerance(1e-14));
  }
  Eigen::ArrayXd into(4);
  wavecontact::pressure(p, a, xs, into);
  BOOST_TEST((into == ps).all());
  Eigen::ArrayXd wrong_size(3);
  BOOST_CHECK_THROW(wavecontact::pressure(p, a, xs, wrong_size), std::domain_error);
}

BOOST_AUTO_TEST_CASE(inverse_load_is_monotone_and_bounded) {
  // m = 0.5: P(a) rises all the way to full contact, so every load has one zone.
  const WavinessParams p{1.0, 10.0, 0.5, 1.0};
  double previous = 0;
  for (double fa : {0.01, 0.1, 0.3, 0.45, 0.5, 0.6, 0.9}) {
    const double P = wavecontact::load(p, fa * p.b1);
    BOOST_TEST(P > previous);
    previous = P;
    BOOST_TEST(wavecontact::contact_half_width(p, P) == fa * p.b1, tt::tolerance(1e-13));
    BOOST_TEST(
        wavecontact::contact_half_width_for_pa_over_pstar(p, wavecontact::pa_over_pstar(p, fa * p.b1)) == fa * p.b1,
        tt::tolerance(1e-13));
    if (fa <= 0.5) {
      BOOST_TEST(wavecontact::single_asperity_half_width(p, P) == fa * p.b1, tt::tolerance(1e-13));
    }
  }
  BOOST_CHECK_THROW(wavecontact::single_asperity_half_width(p, wavecontact::load(p, 5.0) * 1.001), std::domain_error);
  const double full = wavecontact::load(p, p.b1);
  BOOST_TEST(wavecontact::LoadCurve(p).full_contact_load() == full);
  BOOST_CHECK_THROW(wavecontact::contact_half_width(p, full * 1.001), std::domain_error);
}

BOOST_AUTO_TEST_CASE(reduced_modulus_is_eq_7) {
  const double E = wavecontact::reduced_modulus(210e9, 0.3, 3e9, 0.4);
  BOOST_TEST(E == 1 / ((1 - 0.09) / 210e9 + (1 - 0.16) / 3e9), tt::tolerance(1e-15));
  BOOST_CHECK_THROW(wavecontact::reduced_modulus(-1, 0.3, 1, 0.3), std::domain_error);
  BOOST_CHECK_THROW(wavecontact::reduced_modulus(1, 0.6, 1, 0.3), std::domain_error);
  BOOST_CHECK_THROW(wavecontact::reduced_modulus(1, 0.3, 1, -1.0), std::domain_error);
}

BOOST_AUTO_TEST_CASE(domain_errors_name_function_parameter_and_value) {
  const WavinessParams p{1.0, 10.0, 2.0, 1.0};
  auto message = [](auto&& f) -> std::string {
    try {
      f();
    } catch (const std::domain_error& e) {
      return e.what();
    }
    return "no exception";
  };
  const std::string too_wide = message([&] { wavecontact::pressure(p, 10.5, 0.0); });
  BOOST_TEST(too_wide.find("wavecontact::pressure") != std::string::npos, too_wide);
  BOOST_TEST(too_wide.find("a = 10.5") != std::string::npos, too_wide);
  // The printed eq. 14 continued beyond b1/2 has a pole at cos(pi a/b1) = -1/m.
  const std::string pole = message([&] { wavecontact::pressure(p, 7.0, 0.0, Form::paper); });
  BOOST_TEST(pole.find("pole") != std::string::npos, pole);
  const std::string negative_m = message([&] { wavecontact::load(WavinessParams{1.0, 10.0, -1.0, 1.0}, 1.0); });
  BOOST_TEST(negative_m.find("wavecontact::load: m = -1") != std::string::npos, negative_m);
  BOOST_CHECK_THROW(wavecontact::pressure(p, 1.0, std::nan("")), std::domain_error);
  BOOST_CHECK_THROW(wavecontact::pressure(WavinessParams{0.0, 10.0, 2.0, 1.0}, 1.0, 0.0), std::domain_error);
  BOOST_CHECK_THROW(wavecontact::pressure(WavinessParams{1.0, -10.0, 2.0, 1.0}, 1.0, 0.0), std::domain_error);
  BOOST_CHECK_THROW(wavecontact::pressure(WavinessParams{1.0, 10.0, 2.0, INFINITY}, 1.0, 0.0), std::domain_error);
  BOOST_CHECK_THROW(wavecontact::load(p, 0.0), std::domain_error);
  BOOST_CHECK_THROW(wavecontact::zone_angles(11.0, 10.0), std::domain_error);
  BOOST_CHECK_THROW(wavecontact::point_angles(2.0, 1.0, 10.0), std::domain_error);
  BOOST_CHECK_THROW(wavecontact::point_angles(0.5, 1.0, 0.0), std::domain_error);
  BOOST_CHECK_THROW(wavecontact::wave_curve(p, INFINITY), std::domain_error);
  BOOST_CHECK_THROW(wavecontact::contact_half_width_for_pa_over_pstar(p, std::nan("")), std::domain_error);
  BOOST_CHECK_THROW(wavecontact::numerical_inversion([](double v) { return v; }, 0.5, 0.7, 10), std::domain_error);
  BOOST_CHECK_THROW(wavecontact::contact_half_width(p, -1.0), std::domain_error);
}
