// Symbolic regression tests of the roughness derivation (derive/formulas/roughness.*): eq. 18's
// coefficients, the product form (eq. 16/17), the engine's exact inversion and the
// Legendre-Dirichlet stable form, the paper's eq. 19.
#define BOOST_TEST_MODULE roughness_symbolic
#include <boost/test/unit_test.hpp>

#include <chrono>

#include "core/symbols.hpp"
#include "engine/angle_form.hpp"
#include "engine/hilbert.hpp"
#include "formulas/roughness.hpp"
#include "profile/block_keer.hpp"

using namespace wavecontact::derive;
using GiNaC::ex;
using GiNaC::numeric;

namespace {

// The n that generated/ ships: every even n from 2 to 64, 128 and 256.
std::vector<int> default_n() {
  std::vector<int> n;
  for (int k = 2; k <= 64; k += 2) n.push_back(k);
  n.push_back(128);
  n.push_back(256);
  return n;
}

void check_equal(const ex& got, const ex& expected, const std::string& what) {
  const ex difference = (got - expected).normal();
  BOOST_TEST(difference.is_zero(),
             what << "\n  got:      " << got << "\n  expected: " << expected << "\n  difference: " << difference);
}

}  // namespace

BOOST_AUTO_TEST_CASE(golden_coefficients) {
  // docs/mathematics.md section 2.
  const std::vector<std::vector<long>> golden{
      {-2, 4}, {-2, 20, -48, 32}, {-2, 84, -1008, 5280, -14080, 19968, -14336, 4096}};
  for (const auto& expected : golden) {
    const int n = static_cast<int>(expected.size());
    const auto k = expansion_coefficients(n);
    for (int j = 0; j < n; ++j) BOOST_TEST(k[j] == numeric(expected[j]), "n = " << n << ", j = " << j + 1);
  }
  BOOST_CHECK_THROW(expansion_coefficients(7), std::invalid_argument);
  BOOST_CHECK_THROW(expansion_coefficients(0), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(coefficients_for_every_generated_n) {
  std::vector<int> ns = default_n();
  ns.push_back(1024);
  for (int n : ns) {
    const auto start = std::chrono::steady_clock::now();
    const auto k = expansion_coefficients(n);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (n == 64 || n == 256 || n == 1024) {
      BOOST_TEST_MESSAGE("k_1..k_n for n = " << n << ": " << seconds << " s");
    }
    numeric sum = 0, largest = 0;
    for (int j = 1; j <= n; ++j) {
      BOOST_TEST(k[j - 1] == chebyshev_coefficient(n, j), "n = " << n << ", j = " << j);
      sum += k[j - 1];
      largest = std::max(largest, GiNaC::abs(k[j - 1]), [](const numeric& a, const numeric& b) { return a < b; });
    }
    // sum_j k_j = lim_{v->0} s(v)/v = lim sin(n x)/(n tan(x/2)) = 2 (docs/mathematics.md fact 5).
    BOOST_TEST(sum == numeric(2), "sum of k_j for n = " << n);
    if (n == 16 || n == 32 || n == 128) BOOST_TEST_MESSAGE("n = " << n << ": max |k_j| = " << largest.to_double());
    if (n <= 256) BOOST_TEST(expansion_matches_de_moivre(n, k), "eq. 18 = de Moivre for n = " << n);
  }
}

BOOST_AUTO_TEST_CASE(product_form_equals_de_moivre_for_every_generated_n) {
  for (int n : default_n()) {
    const double deviation = product_form_deviation(n, 60);
    BOOST_TEST(deviation < 1e-50, "eq. 16/17 product vs de Moivre, n = " << n << ": " << deviation);
  }
}

BOOST_AUTO_TEST_CASE(engine_inversion_is_the_legendre_dirichlet_form) {
  for (int n : {2, 4, 6, 8}) {
    Radicals radicals;
    const RadicalSum inversion = bounded_inversion(hilbert_rhs(roughness_profile(n)), radicals);
    const auto terms = root_terms(inversion, radicals, GiNaC::pow(sym::alpha(), 2) - sym::s());
    BOOST_TEST_REQUIRE(terms.size() == 1u);
    const ex engine_squared = GiNaC::pow(terms[0].rational, 2) * terms[0].radicand;
    const ex stable = legendre_dirichlet_pressure(n);
    check_equal(engine_squared, atoms_in_v_variables(GiNaC::pow(stable, 2)), "p_r^2, n = " + std::to_string(n));
    // Same sign at a point of the domain (small zone: the roughness pressure is positive there).
    GiNaC::exmap point = sample_point_v();
    point[sym::alpha()] = numeric(1, 20);
    point[sym::u()] = numeric(1, 40);
    point[sym::s()] = numeric(1, 1600);
    point[sym::H2()] = 1;
    const ex at_point = as_ex(terms[0]).subs(point).evalf();
    const ex stable_at_point = atoms_in_v_variables(stable).subs(point).evalf();
    BOOST_TEST(GiNaC::ex_to<numeric>(at_point).is_positive());
    BOOST_TEST(GiNaC::ex_to<numeric>(stable_at_point).is_positive());
    // The load (docs/mathematics.md fact 6).
    check_equal(load_integral(inversion, radicals).with_roots(radicals),
                atoms_in_v_variables(legendre_dirichlet_load(n)), "P_r, n = " + std::to_string(n));
  }
}

BOOST_AUTO_TEST_CASE(eq19_is_exact_for_j1_only) {
  const ex v = sym::v();
  for (int j : {1, 2, 3}) {
    Radicals radicals;
    const RadicalSum exact = bounded_inversion(v / GiNaC::pow(1 + GiNaC::pow(v, 2), j), radicals);
    const RadicalSum paper = eq19_term(j, radicals);
    const ex difference = (exact.with_roots(radicals) - paper.with_roots(radicals)).normal();
    if (j == 1) {
      BOOST_TEST(difference.is_zero(), "eq. 19, j = 1: " << difference);
      // The Westergaard-type solution sqrt(alpha^2 - u^2) / ((u^2 + 1) sqrt(alpha^2 + 1)).
      const ex westergaard = 1 / ((1 + sym::s()) * GiNaC::sqrt(1 + GiNaC::pow(sym::alpha(), 2)));
      check_equal(exact.with_roots(radicals), westergaard, "j = 1 term");
    } else {
      BOOST_TEST(!difference.is_zero(), "eq. 19 must not be exact for j = " << j);
    }
  }
}

BOOST_AUTO_TEST_CASE(legendre_dirichlet_form_solves_eq5_for_large_n) {
  // Independent of the engine: the forward transform (1/pi) PV Int p(u)/(v - u) du of the
  // stable form, at 40 digits by the midpoint rule in u = alpha cos(theta), must give
  // g(v) = (E*/2) H2 n sin(n x^(v)) (normalised: E* = H2 = 1, b1 = pi).
  const long saved = GiNaC::Digits;
  GiNaC::Digits = 40;
  const numeric alpha(1, 2);
  const numeric ca = GiNaC::ex_to<numeric>(((1 - alpha * alpha) / (1 + alpha * alpha)).evalf());
  for (int n : {16, 64, 256}) {
    std::vector<numeric> P{1, ca};
    for (int k = 1; k < n; ++k) P.push_back(((2 * k + 1) * ca * P[k] - k * P[k - 1]) / (k + 1));
    // F(u) = p^(u) sqrt(alpha^2 - u^2), p^ = (n/sqrt2) sqrt(cos x - cos a) sum_j P_{n-1-j} cos((j+1/2) x).
    auto F = [&](const numeric& u) {
      const numeric x = GiNaC::ex_to<numeric>((2 * GiNaC::atan(u)).evalf());
      numeric sum = 0;
      for (int j = 0; j < n; ++j) sum += P[n - 1 - j] * GiNaC::cos((j + numeric(1, 2)) * x);
      return numeric(n) / GiNaC::sqrt(numeric(2)) * GiNaC::sqrt(GiNaC::cos(x) - ca) * sum *
             GiNaC::sqrt(alpha * alpha - u * u);
    };
    const int nodes = 4 * n + 200;
    for (const numeric& v : {numeric(1, 5), numeric(9, 20)}) {
      const numeric Fv = F(v);
      numeric integral = 0;
      for (int k = 0; k < nodes; ++k) {
        const numeric u = alpha * GiNaC::ex_to<numeric>(GiNaC::cos(GiNaC::Pi * (k + numeric(1, 2)) / nodes).evalf());
        integral += (F(u) - Fv) / (v - u);
      }
      integral = integral / nodes;
      const numeric g = numeric(n, 2) * GiNaC::ex_to<numeric>(GiNaC::sin(n * 2 * GiNaC::atan(v)).evalf());
      const double residual = (GiNaC::abs(integral - g) / n).to_double();
      BOOST_TEST_MESSAGE("n = " << n << ", v = " << v << ": |forward transform - g| / n = " << residual);
      BOOST_TEST(residual < 1e-25, "n = " << n << ", v = " << v);
    }
  }
  GiNaC::Digits = saved;
}
