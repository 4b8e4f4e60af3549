// Numerical tests of the two-scale runtime (eqs. 15-21): docs/mathematics.md's check values, the
// Legendre load identity, the independent numerical inversion, the exact evaluation of the
// paper's eq. 20, superposition and admissibility.
#define BOOST_TEST_MODULE roughness
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <string>

#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/legendre.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>

#include "wavecontact/numerical_inversion.hpp"
#include "wavecontact/two_scale.hpp"
#include "wavecontact/waviness.hpp"

namespace tt = boost::test_tools;
using namespace wavecontact;

namespace {

using boost::math::double_constants::pi;

// Roughness only: H1 is irrelevant to the roughness parts, m = 0.
TwoScaleParams roughness_only(double H2, int n, double b1 = pi, double E = 1) { return {{1.0, b1, 0.0, E}, {H2, n}}; }

const std::vector<int> tested_n{2, 8, 16, 32, 64, 128, 256};

}  // namespace

BOOST_AUTO_TEST_CASE(math_md_check_values) {
  // docs/mathematics.md fact 4 and 6, b1 = pi, H2 = E* = 1.
  const TwoScaleContact n16(roughness_only(1, 16), 0.5 * pi / 16);
  BOOST_TEST(n16.roughness_pressure(0) == 10.21387598287078, tt::tolerance(1e-13));
  BOOST_TEST(n16.roughness_load() == 1.399144397552393, tt::tolerance(1e-13));
  const TwoScaleContact n24(roughness_only(1, 24), 0.8 * pi / 24);
  BOOST_TEST(n24.roughness_pressure(0) == 17.61295827228107, tt::tolerance(1e-13));
  BOOST_TEST(n24.roughness_load() == 1.95027427473175, tt::tolerance(1e-13));
  const TwoScaleContact paper16(roughness_only(1, 16), 0.5 * pi / 16, Form::paper);
  BOOST_TEST(paper16.roughness_pressure(0) == 10.14091356098158, tt::tolerance(1e-13));
}

// Eq. 20 summed term by term at 200 digits with the exact k_j from the runtime.
double eq20_by_direct_sum(int n, double a, double x) {
  using Real = boost::multiprecision::number<boost::multiprecision::cpp_bin_float<200>>;
  const Real alpha = tan(Real(pi) * a / (2 * pi)), u = tan(Real(pi) * x / (2 * pi));
  const Real z = 1 / (sqrt(1 + alpha * alpha) * (1 + u * u));
  Real sum = 0, power = 1;
  for (const std::string& k : expansion_coefficients(n)) {
    power *= z;
    const auto slash = k.find('/');
    const Real value = slash == std::string::npos ? Real(k) : Real(k.substr(0, slash)) / Real(k.substr(slash + 1));
    sum += value * power;
  }
  return static_cast<double>(Real(n) * n / 2 * sqrt(alpha * alpha - u * u) * sum);
}

BOOST_AUTO_TEST_CASE(paper_eq20_is_evaluated_exactly) {
  // docs/mathematics.md gives 16.61550412074067 for n = 24, a = 0.8 b2; the exact sum is
  // 16.6155041188379280 (its 1e-10 discrepancy is the double-precision cancellation
  // of summing eq. 20 term by term).
  for (int n : {16, 24, 64, 128}) {
    for (double fraction : {0.25, 0.5, 1.0}) {
      const double a = fraction * pi / n;
      const TwoScaleContact paper(roughness_only(1, n), a, Form::paper);
      for (double fx : {0.0, 0.5, 0.9}) {
        const double expected = eq20_by_direct_sum(n, a, fx * a);
        BOOST_TEST(std::abs(paper.roughness_pressure(fx * a) - expected) <= 1e-13 * n,
                   "n = " << n << ", a/b2 = " << fraction << ", x/a = " << fx);
      }
    }
  }
  BOOST_TEST(eq20_by_direct_sum(24, 0.8 * pi / 24, 0) == 16.615504118837928, tt::tolerance(1e-15));
}

BOOST_AUTO_TEST_CASE(load_is_the_legendre_identity) {
  // P_r = (pi/2) E* H2 n [P_{n-1}(cos a^) - P_n(cos a^)] with Boost.Math's Legendre
  // polynomials (docs/mathematics.md fact 6), on the whole range a <= b1/2.
  for (int n : tested_n) {
    for (double fa : {1e-3, 0.01, 0.1, 0.25, 0.4, 0.5}) {
      const double b1 = 2.0, E = 3.0, H2 = 0.1, a = fa * b1;
      const TwoScaleContact contact(roughness_only(H2, n, b1, E), a);
      const double c = std::cos(pi * a / b1);
      const double expected = pi / 2 * E * H2 * n * (boost::math::legendre_p(n - 1, c) - boost::math::legendre_p(n, c));
      BOOST_TEST(std::abs(contact.roughness_load() - expected) <= 1e-13 * E * H2 * n,
                 "n = " << n << ", a/b1 = " << fa << ": " << contact.roughness_load() << " vs " << expected);
    }
  }
}

BOOST_AUTO_TEST_CASE(pressure_agrees_with_numerical_inversion) {
  // docs/mathematics.md section 4, with 4n + 200 nodes; error relative to the scale E* H2 n pi/b1.
  for (int n : tested_n) {
    const double b1 = 2.5, E = 2.0, H2 = 0.01;
    const double scale = E * H2 * n * pi / b1;
    double worst = 0;
    for (double fa : {0.3 / n, 1.0 / n, 0.1, 0.37, 0.5}) {
      const double a = fa * b1;
      const TwoScaleContact contact(roughness_only(H2, n, b1, E), a);
      const double alpha = std::tan(pi * a / (2 * b1));
      const auto g = [&](double v) { return E / 2 * H2 * n * std::sin(n * 2 * std::atan(v)); };
      for (double fx : {0.0, 0.2, 0.55, 0.9, 0.999}) {
        const double x = fx * a, u = std::tan(pi * x / (2 * b1));
        const double numerical = pi / b1 * numerical_inversion(g, alpha, u, 4 * n + 200);
        worst = std::max(worst, std::abs(contact.roughness_pressure(x) - numerical) / scale);
      }
    }
    BOOST_TEST_MESSAGE("n = " << n << ": max |closed - numerical| / (E* H2 n pi/b1) = " << worst);
    BOOST_TEST(worst <= 1e-12, "n = " << n);
  }
}

BOOST_AUTO_TEST_CASE(superposition_and_vanishing_roughness) {
  const TwoScaleParams params{{1.0, 10.0, 2.0, 1.0}, {0.01, 16}};
  const double a = 3.0;
  const TwoScaleContact contact(params, a);
  BOOST_TEST_REQUIRE(contact.admissible());
  for (double x : {0.0, 1.0, 2.9}) {
    BOOST_TEST(contact.pressure(x) == contact.waviness_pressure(x) + contact.roughness_pressure(x));
    BOOST_TEST(contact.waviness_pressure(x) == pressure(params.waviness, a, x));
  }
  BOOST_TEST(contact.load() == load(params.waviness, a) + contact.roughness_load());
  const TwoScaleContact smooth({params.waviness, {0.0, 16}}, a);
  BOOST_TEST(smooth.roughness_pressure(1.0) == 0.0);
  BOOST_TEST(smooth.load() == load(params.waviness, a));
  // The load inverse finds a back.
  const auto roots = two_scale_half_widths(params, contact.load());
  BOOST_TEST_REQUIRE(!roots.empty());
  bool found = false;
  for (const auto& r : roots) found = found || (std::abs(r.a - a) < 1e-12 * a && r.stable);
  BOOST_TEST(found);
}

// The array overloads against the point ones: the vectorised series (zone coefficients
// from the generated roughness_n<N>_legendre) for a <= b1/2, the point loop beyond and for
// the printed form; points in several periods, outside the zone, and counts that leave a
// tail shorter than a SIMD vector and a block.
BOOST_AUTO_TEST_CASE(array_api_matches_point_api) {
  for (int n : tested_n) {
    for (double fa : {0.1, 0.3, 0.5, 0.7}) {
      const TwoScaleParams params{{1.0, 10.0, 2.0, 1.0}, {0.004 / n, n}};
      const double a = fa * params.waviness.b1;
      for (Form form : {Form::exact, Form::paper}) {
        if (form == Form::paper && fa > 0.5) continue;
        const TwoScaleContact contact(params, a, form);
        const Eigen::ArrayXd xs = Eigen::ArrayXd::LinSpaced(1031, -25.0, 25.0);
        Eigen::ArrayXd rough(xs.size()), total(xs.size());
        contact.roughness_pressure(xs, rough);
        const bool admissible = contact.admissible();  // m = 2 is not, beyond b1/2
        if (admissible) contact.pressure(xs, total);
        const double roughness_scale = pi / params.waviness.b1 * params.waviness.E * params.roughness.H2 * n;
        const double scale = pi / params.waviness.b1 * params.waviness.E * params.waviness.H1 + roughness_scale;
        double worst = 0, worst_total = 0;
        for (Eigen::Index i = 0; i < xs.size(); ++i) {
          worst = std::max(worst, std::abs(rough[i] - contact.roughness_pressure(xs[i])));
          if (admissible) worst_total = std::max(worst_total, std::abs(total[i] - contact.pressure(xs[i])));
        }
        // Both paths sum n terms, each within ~n eps of the 40-digit reference (accuracy_test).
        BOOST_TEST(worst <= 4 * n * 2.220446049250313e-16 * roughness_scale,
                   "n = " << n << ", a = " << a << ": roughness " << worst / roughness_scale << " of scale");
        BOOST_TEST(worst_total <= 4 * n * 2.220446049250313e-16 * scale,
                   "n = " << n << ", a = " << a << ": total " << worst_total / scale << " of scale");
      }
    }
  }
  const TwoScaleContact contact({{1.0, 10.0, 2.0, 1.0}, {0.001, 16}}, 3.0);
  Eigen::ArrayXd short_p(2);
  BOOST_CHECK_THROW(contact.roughness_pressure(Eigen::ArrayXd::Zero(3), short_p), std::domain_error);
  BOOST_CHECK_THROW(contact.pressure(Eigen::ArrayXd::Constant(2, std::nan("")), short_p), std::domain_error);
}

BOOST_AUTO_TEST_CASE(negative_total_pressure_is_reported) {
  // Large roughness on a flat-topped wave: the single zone would need tension.
  const TwoScaleParams params{{1.0, 10.0, 10.0, 1.0}, {0.5, 8}};
  const TwoScaleContact contact(params, 4.0);
  BOOST_TEST(!contact.admissible());
  BOOST_TEST(contact.most_negative_pressure() < 0);
  BOOST_TEST(contact.most_negative_x() < 4.0);
  try {
    contact.pressure(0.0);
    BOOST_FAIL("no exception for an inadmissible zone");
  } catch (const std::domain_error& e) {
    const std::string message = e.what();
    BOOST_TEST(message.find("at x = ") != std::string::npos, message);
    BOOST_TEST(message.find("p = -") != std::string::npos, message);
  }
  try {
    Eigen::ArrayXd p(1);
    contact.pressure(Eigen::ArrayXd::Zero(1), p);
    BOOST_FAIL("no exception for an inadmissible zone (array API)");
  } catch (const std::domain_error& e) {
    const std::string message = e.what();
    BOOST_TEST(message.find("at x = ") != std::string::npos, message);
    BOOST_TEST(message.find("p = -") != std::string::npos, message);
  }
}

BOOST_AUTO_TEST_CASE(invalid_roughness_is_refused) {
  const WavinessParams w{1.0, 10.0, 2.0, 1.0};
  BOOST_CHECK_THROW(TwoScaleContact({w, {0.1, 7}}, 1.0), std::domain_error);
  BOOST_CHECK_THROW(TwoScaleContact({w, {0.1, 0}}, 1.0), std::domain_error);
  BOOST_CHECK_THROW(TwoScaleContact({w, {-0.1, 8}}, 1.0), std::domain_error);
  BOOST_CHECK_THROW(TwoScaleContact({w, {0.1, 8}}, 10.0), std::domain_error);
  BOOST_CHECK_THROW(TwoScaleContact({w, {0.1, 8}}, 6.0, Form::paper), std::domain_error);
  BOOST_CHECK_THROW(expansion_coefficients(5), std::domain_error);
  BOOST_CHECK_THROW(expansion_coefficients(max_roughness_n + 2), std::domain_error);
  BOOST_CHECK_THROW(TwoScaleContact({w, {0.1, 1 << 30}}, 1.0, Form::paper), std::domain_error);
  BOOST_CHECK_THROW(TwoScaleContact({w, {0.1, 96}}, 1.0), std::domain_error);  // not generated
  BOOST_CHECK_THROW(two_scale_half_widths({w, {0.1, 8}}, -1.0), std::domain_error);
  BOOST_CHECK_THROW(roughness_full_contact_pressure({w, {0.1, 8}}, std::nan("")), std::domain_error);
  BOOST_TEST(expansion_coefficients(6).at(1) == "140/3");
}
