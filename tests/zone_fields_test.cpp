// The other zones' field at a zone's nodes (runtime/src/contact/zone_system.*), white-box:
// ZoneFields::at_nodes, from a coarser Chebyshev grid where that field is smooth on the zone,
// against the direct evaluation at every node (ZoneFields::evaluate); and the Chebyshev
// series' values and derivative it takes (chebyshev.*).
#define BOOST_TEST_MODULE zone_fields
#include <boost/math/constants/constants.hpp>
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "contact/active_set.hpp"
#include "contact/chebyshev.hpp"
#include "contact/grid_seed.hpp"
#include "contact/zone_system.hpp"
#include "wavecontact/contact.hpp"

using namespace wavecontact;
using boost::math::double_constants::pi;
namespace chebyshev = wavecontact::detail::chebyshev;

namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();

std::vector<double> decaying_series(std::size_t n, double rate, unsigned seed) {
  std::mt19937 generator(seed);
  std::uniform_real_distribution<double> value(-1, 1);
  std::vector<double> c(n);
  for (std::size_t j = 0; j < n; ++j) c[j] = value(generator) * std::pow(rate, static_cast<double>(j));
  return c;
}

double largest(const std::vector<double>& v) {
  double m = 0;
  for (double e : v) m = std::max(m, std::fabs(e));
  return m;
}

double magnitude(const double* c, std::size_t n) {
  double sum = 0;
  for (std::size_t j = 0; j < n; ++j) sum += std::fabs(c[j]);
  return sum;
}

double largest_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double m = 0;
  for (std::size_t i = 0; i < a.size(); ++i) m = std::max(m, std::fabs(a[i] - b[i]));
  return m;
}

// The coarse and the direct field at every zone's nodes: the potentials' differences within
// 1e-13 of their largest, the slopes within 1e-9 (the preconditioner's alone); the zones that
// the coarse grid serves (4 terms <= M) listed.
std::vector<std::size_t> compare_at_every_zone(const detail::SurfaceModel& surface, const detail::Configuration& c) {
  const detail::ZoneFields fields(surface, c);
  std::vector<std::size_t> coarse;
  for (std::size_t k = 0; k < c.zones.size(); ++k) {
    const int M = static_cast<int>(c.zones[k].d.size());
    const std::vector<double> x = detail::node_angles(c.zones[k].geometry, M);
    const detail::FieldTree::Batch direct = fields.evaluate(k, x, x[static_cast<std::size_t>(M / 2)], true);
    const detail::FieldTree::Batch got = fields.at_nodes(k, x, true);
    const int terms = detail::smooth_field_terms(c.zones, k);
    if (terms > 0 && terms <= M / 4) coarse.push_back(k);
    const double scale = largest(direct.difference), slope_scale = largest(direct.slope);
    BOOST_TEST_MESSAGE("zone " << k << " (" << M << " nodes, " << terms << " terms): potentials off by "
                               << largest_difference(got.difference, direct.difference) / scale << ", slopes by "
                               << largest_difference(got.slope, direct.slope) / slope_scale);
    BOOST_TEST(got.at_reference == direct.at_reference,
               "zone " << k << ": at the reference " << got.at_reference << ", directly " << direct.at_reference);
    BOOST_TEST(largest_difference(got.difference, direct.difference) <= 1e-13 * scale,
               "zone " << k << " (" << M << " nodes, " << terms << " terms): potentials off by "
                       << largest_difference(got.difference, direct.difference) << " of " << scale);
    BOOST_TEST(largest_difference(got.slope, direct.slope) <= 1e-9 * slope_scale,
               "zone " << k << " (" << M << " nodes, " << terms << " terms): slopes off by "
                       << largest_difference(got.slope, direct.slope) << " of " << slope_scale);
  }
  return coarse;
}

}  // namespace

// values() is the inverse of coefficients(), through the table (M <= 128) and FFTW's DCT-III,
// and a shorter series is summed as its terms padded with zeros: within 32 eps of the sum of
// the terms' magnitudes (at most 12.8 eps here, 2026-11-29).
BOOST_AUTO_TEST_CASE(values_invert_the_coefficients) {
  for (int M : {16, 128, 160, 1024}) {
    const std::vector<double> c = decaying_series(static_cast<std::size_t>(M), 0.97, static_cast<unsigned>(M));
    std::vector<double> v(static_cast<std::size_t>(M));
    chebyshev::values(c.data(), M, M, v.data());
    const std::vector<double> back = chebyshev::coefficients(v);
    const double size = magnitude(c.data(), c.size());
    BOOST_TEST_MESSAGE("M = " << M << ": coefficients back off by " << largest_difference(back, c) / (eps * size)
                              << " eps");
    BOOST_TEST(largest_difference(back, c) <= 32 * eps * size,
               "M = " << M << ": coefficients back off by " << largest_difference(back, c) / (eps * size) << " eps");
    // The first 12 terms alone, against Clenshaw's sums at the nodes.
    std::vector<double> shorter(static_cast<std::size_t>(M)), summed(static_cast<std::size_t>(M));
    chebyshev::values(c.data(), 12, M, shorter.data());
    chebyshev::sums(chebyshev::Kind::t, c.data(), 12, chebyshev::nodes(M).data(), summed.data(),
                    static_cast<std::size_t>(M));
    const double size12 = magnitude(c.data(), 12);
    BOOST_TEST_MESSAGE("M = " << M << ": 12 terms off by " << largest_difference(shorter, summed) / (eps * size12)
                              << " eps");
    BOOST_TEST(largest_difference(shorter, summed) <= 32 * eps * size12,
               "M = " << M << ": 12 terms off by " << largest_difference(shorter, summed) / (eps * size12) << " eps");
  }
}

// d/dtau sum c_j T_j = sum j c_j U_{j-1}: the derivative's series summed as first-kind terms
// against the second-kind sum.
BOOST_AUTO_TEST_CASE(derivative_series) {
  const std::vector<double> c = decaying_series(40, 0.8, 7);
  const std::vector<double> d = chebyshev::derivative(c);
  BOOST_TEST_REQUIRE(d.size() == c.size() - 1);
  std::vector<double> jc(c.size() - 1);
  for (std::size_t j = 1; j < c.size(); ++j) jc[j - 1] = static_cast<double>(j) * c[j];
  const std::vector<double> tau{-1, -0.93, -0.5, -0.1, 0, 0.37, 0.8, 0.999, 1};
  std::vector<double> got(tau.size()), expected(tau.size());
  chebyshev::sums(chebyshev::Kind::t, d.data(), d.size(), tau.data(), got.data(), tau.size());
  chebyshev::sums(chebyshev::Kind::u, jc.data(), jc.size(), tau.data(), expected.data(), tau.size());
  for (std::size_t i = 0; i < tau.size(); ++i) {
    BOOST_TEST(std::fabs(got[i] - expected[i]) <= 1e-13 * largest(expected),
               "at tau = " << tau[i] << ": " << got[i] << ", expected " << expected[i]);
  }
  BOOST_TEST(chebyshev::derivative({3.0}).empty());
}

// A wide zone over many asperities beside narrower ones, their densities' series falling
// like 0.9^j: the wide zone's field from the others comes from the coarse grid, the narrow
// zones' (whose neighbours lie within a few of their widths) directly.
BOOST_AUTO_TEST_CASE(coarse_field_equals_the_direct_one) {
  const Surface surface(WavinessParams{1, 10, 0, 1}, {{0.005, 64}});
  detail::Configuration c;
  c.C = 0.3;
  const std::vector<std::pair<double, double>> ends{{0, 1.2}, {1.31, 1.36}, {1.5, 1.9}, {2.6, pi}};
  const std::vector<std::size_t> nodes{1024, 48, 96, 512};
  for (std::size_t k = 0; k < ends.size(); ++k) {
    c.zones.push_back({detail::ZoneGeometry(ends[k].first, ends[k].second),
                       decaying_series(nodes[k], 0.9, static_cast<unsigned>(k + 1))});
  }
  const std::vector<std::size_t> coarse = compare_at_every_zone(*surface.model(), c);
  BOOST_TEST(coarse == (std::vector<std::size_t>{0, 3}), "the coarse grid served " << coarse.size() << " zones");
}

// The wave curve m = 10 at pa/p* = 2.86, where the top zone ends 5e-5 past the kink at b1/2
// on thousands of nodes and a second zone runs through the valley: the top zone's field
// from the other comes from 128 terms.
BOOST_AUTO_TEST_CASE(coarse_field_on_a_zone_across_the_kink) {
  const Surface surface(WavinessParams{1, 10, 10, 1});
  const auto& model = surface.model();
  const double P = 4.5 * pi * 127 / 200;
  const detail::SettleOutcome s = detail::settle(
      model, P, detail::grid_seed(*model, P, detail::seed_cells(*model), detail::working_nodes), {400}, {});
  BOOST_TEST_REQUIRE(s.contact.has_value(), "no contact: " << s.failure);
  BOOST_TEST_REQUIRE(s.contact->zones.size() == 2u);
  BOOST_TEST_REQUIRE(s.contact->zones[0].d.size() >= 1024u, "the top zone holds " << s.contact->zones[0].d.size());
  const std::vector<std::size_t> coarse = compare_at_every_zone(*model, *s.contact);
  BOOST_TEST(coarse == (std::vector<std::size_t>{0}), "the coarse grid served " << coarse.size() << " zones");
}

// Zones that touch leave no smoothness to use: every node takes the field (and overlapping
// ones, whose distance is negative, likewise).
BOOST_AUTO_TEST_CASE(touching_zones_take_the_field_at_every_node) {
  detail::Configuration c;
  c.zones.push_back({detail::ZoneGeometry(0, 1.0), decaying_series(4096, 0.9, 4)});
  c.zones.push_back({detail::ZoneGeometry(1.0, 1.5), decaying_series(48, 0.9, 5)});
  BOOST_TEST(detail::smooth_field_terms(c.zones, 0) > 4096 / 4);
  c.zones[1] = {detail::ZoneGeometry(0.9, 1.5), decaying_series(48, 0.9, 5)};
  BOOST_TEST(detail::smooth_field_terms(c.zones, 0) > 4096 / 4);
  c.zones[1] = {detail::ZoneGeometry(1.2, 1.5), decaying_series(48, 0.9, 5)};
  BOOST_TEST(detail::smooth_field_terms(c.zones, 0) <= 4096 / 4);
}

// With one zone there is no other: nothing, whatever the nodes.
BOOST_AUTO_TEST_CASE(one_zone_has_no_other_field) {
  const Surface surface(WavinessParams{1, 10, 0, 1});
  detail::Configuration c;
  c.zones.push_back({detail::ZoneGeometry(0, 2.0), decaying_series(256, 0.9, 3)});
  const detail::ZoneFields fields(*surface.model(), c);
  const std::vector<double> x = detail::node_angles(c.zones[0].geometry, 256);
  const detail::FieldTree::Batch got = fields.at_nodes(0, x, true);
  BOOST_TEST(got.at_reference == 0.0);
  BOOST_TEST(largest(got.difference) == 0.0);
  BOOST_TEST(got.slope.size() == x.size());
  BOOST_TEST(detail::smooth_field_terms(c.zones, 0) == 0);
}
