// The verification of a contact on the whole half period (runtime/src/contact/verification.*),
// white-box: which sampled minima are refined and how, a penetration at the valley, and the
// gap sampled a stretch at a time.
#define BOOST_TEST_MODULE verification
#include <boost/math/constants/constants.hpp>
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include "contact/active_set.hpp"
#include "contact/grid_seed.hpp"
#include "contact/solution.hpp"
#include "contact/verification.hpp"
#include "contact/zone_system.hpp"
#include "wavecontact/contact.hpp"
#include "wavecontact/threads.hpp"

using namespace wavecontact;
using boost::math::double_constants::pi;

namespace {

std::vector<double> samples(double lo, double hi, int count) {
  std::vector<double> xs;
  for (int i = 0; i <= count; ++i) xs.push_back(lo + (hi - lo) * i / count);
  return xs;
}

// f at a batch of points, one at a time (f copied: the batch may outlive a temporary).
template <class F>
detail::BatchFunction batch(F f) {
  return [f](const double* x, double* values, std::size_t count) {
    for (std::size_t i = 0; i < count; ++i) values[i] = f(x[i]);
  };
}

// The contact the settling finds at P from the grid's seed (the first stage of a solve).
detail::Configuration settled(const Surface& surface, double P) {
  const auto& model = surface.model();
  const detail::SettleOutcome outcome = detail::settle(
      model, P, detail::grid_seed(*model, P, detail::seed_cells(*model), detail::working_nodes), {400}, {});
  BOOST_TEST_REQUIRE(outcome.contact.has_value(), "no contact at P = " << P << ": " << outcome.failure);
  return *outcome.contact;
}

}  // namespace

// A well whose samples all lie above 0 but whose bottom lies below it, between two samples:
// the rise to the higher neighbour (0.02) exceeds the lowest sample (0.0005), so it is refined
// and its bottom found.
BOOST_AUTO_TEST_CASE(a_well_that_may_cross_zero_is_refined) {
  const auto f = [](double x) { return (x - 0.05) * (x - 0.05) - 0.002; };
  const std::vector<double> xs = samples(-0.3, 0.4, 7);
  std::vector<double> ys;
  for (double x : xs) ys.push_back(f(x));
  BOOST_TEST_REQUIRE(*std::min_element(ys.begin(), ys.end()) > 0.0);
  const auto minima = detail::local_minima(xs, ys, batch(f), 0.0);
  BOOST_TEST_REQUIRE(minima.size() == 1u);
  BOOST_TEST(minima[0].first == 0.05, boost::test_tools::tolerance(1e-6));
  BOOST_TEST(minima[0].second == -0.002, boost::test_tools::tolerance(1e-9));
}

// Wells sampled eight times a wavelength, the lowest 0.5 above 0: every sample exceeds its
// rise, none can reach 0 and none is refined (no call of f); with no bound, each one is.
BOOST_AUTO_TEST_CASE(a_well_that_cannot_reach_zero_is_left_out) {
  int calls = 0;
  const auto f = [&](double x) { return ++calls, 1.5 + std::cos(x); };
  const std::vector<double> xs = samples(0.1, 0.1 + 6 * pi, 24);
  std::vector<double> ys;
  for (double x : xs) ys.push_back(1.5 + std::cos(x));
  BOOST_TEST(detail::local_minima(xs, ys, batch(f), 0.0).empty());
  BOOST_TEST(calls == 0);
  const auto all = detail::local_minima(xs, ys, batch(f));
  BOOST_TEST(all.size() == 3u);
  for (const auto& [x, value] : all) BOOST_TEST(value == 0.5, boost::test_tools::tolerance(1e-12));
}

// A minimum at an end sample, as at a zone's end, where a gap left penetrating by an end
// condition met to 1e-3 dips like -a d + d^(3/2) (d from the end): the dip, 1.5e-10 deep at
// 4.4e-7 from the end, lies wholly within the first of the samples 0.1 apart, and is found by
// the probes towards the end at either end of the samples, then refined by Brent's method;
// with the probes kept farther from the end than the dip, it is not.
BOOST_AUTO_TEST_CASE(a_dip_beside_an_end_sample_is_found) {
  const double a = 1e-3, bottom = std::pow(2 * a / 3, 2), depth = -4 * a * a * a / 27;
  for (const bool at_right : {false, true}) {
    const double end = at_right ? 1.0 : 0.0;
    const auto f = [&](double x) {
      const double d = std::fabs(x - end);
      return -a * d + d * std::sqrt(d);
    };
    const std::vector<double> xs = samples(0, 1, 10);
    std::vector<double> ys;
    for (double x : xs) ys.push_back(f(x));
    BOOST_TEST_REQUIRE(*std::min_element(ys.begin(), ys.end()) == 0.0);
    const auto minima = detail::local_minima(xs, ys, batch(f), 0.0);
    BOOST_TEST_REQUIRE(minima.size() == 1u, (at_right ? "right" : "left") << " end: " << minima.size() << " minima");
    // Brent's method to 40 bits: the bottom's place within 2.6e-9 (its value to 4e-15).
    BOOST_TEST(std::fabs(minima[0].first - end) == bottom, boost::test_tools::tolerance(0.02));
    BOOST_TEST(minima[0].second == depth, boost::test_tools::tolerance(1e-4));
    // With no probe nearer the end than 1e-3 (as where a zone's series resolves nothing
    // nearer), the end sample stands after the six probes 0.05 to 0.0016 from it.
    int calls = 0;
    const auto counted = [&](double x) { return ++calls, f(x); };
    const auto coarse = detail::local_minima(xs, ys, batch(counted), 0.0, 1e-3);
    BOOST_TEST_REQUIRE(coarse.size() == 1u);
    BOOST_TEST(coarse[0].first == end);
    BOOST_TEST(coarse[0].second == 0.0);
    BOOST_TEST(calls == 6);
  }
}

// Where the function grows away from the end sample (a gap with its end condition met, like
// d^(3/2)), the end is the minimum: one batch of the probes, no point alone after it.
BOOST_AUTO_TEST_CASE(an_end_sample_without_a_dip_is_the_minimum_after_one_batch) {
  std::vector<std::size_t> batches;
  const detail::BatchFunction f = [&](const double* x, double* values, std::size_t count) {
    batches.push_back(count);
    for (std::size_t i = 0; i < count; ++i) values[i] = x[i] * std::sqrt(x[i]);
  };
  const std::vector<double> xs = samples(0, 1, 10);
  std::vector<double> ys;
  for (double x : xs) ys.push_back(x * std::sqrt(x));
  const auto minima = detail::local_minima(xs, ys, f, 0.0);
  BOOST_TEST_REQUIRE(minima.size() == 1u);
  BOOST_TEST(minima[0].first == 0.0);
  BOOST_TEST(minima[0].second == 0.0);
  BOOST_TEST(batches == std::vector<std::size_t>{static_cast<std::size_t>(detail::end_probes)},
             boost::test_tools::per_element());
}

// The contact of one zone [0, a^] at P = 0.97 pi on m = 0, H2 = 0.0084, n = 8 penetrates at the
// valley (the contact there has a second zone at it). The penetration is reported at the
// valley itself, with the gap's curvature there, which the gap, even about the valley, gives
// over a step four times as long within 1e-3. (Found a rounding short of the valley, it had a
// quarter of that for room, and the new zone closed at once; at the valley, a second
// difference of no length: no curvature.)
BOOST_AUTO_TEST_CASE(a_penetration_at_the_valley_is_there_with_its_curvature) {
  const Surface surface(WavinessParams{1, 10, 0, 1}, {{0.0084339300685716458, 8}});
  const auto& model = surface.model();
  const double P = 0.97 * pi;
  detail::Configuration c = settled(surface, P);
  BOOST_TEST_REQUIRE(c.zones.size() == 2u);
  BOOST_TEST_REQUIRE(c.zones.back().geometry.valley());
  c.zones.pop_back();
  const detail::ZoneSystem::Result one = detail::ZoneSystem(*model, P).newton(c, 1e-12, {});
  BOOST_TEST_REQUIRE((one.outcome == detail::ZoneSystem::Outcome::converged));
  const detail::ContactSolution solution(model, one.configuration);
  const detail::Verification v =
      detail::verify(solution, detail::gap_tolerance * model->height_range, detail::pressure_tolerance);
  BOOST_TEST_REQUIRE(v.penetrations.size() == 1u);
  const detail::Penetration& p = v.penetrations[0];
  BOOST_TEST(p.x == pi);
  BOOST_TEST(p.depth == solution.gap(pi), boost::test_tools::tolerance(1e-12));
  const double h = 4e-3 * model->resolution;
  const double curvature = 2 * (solution.gap(pi - h) - solution.gap(pi)) / (h * h);
  BOOST_TEST(curvature > 0.0);
  BOOST_TEST(p.curvature == curvature, boost::test_tools::tolerance(1e-3));
}

// The gap of a contact of several zones (m = 0, H2 = 0.02, n = 32), sampled a stretch at a
// time in one batch of the tree code, against the gap point by point: the same to rounding.
BOOST_AUTO_TEST_CASE(gaps_in_one_batch_equal_the_gap_point_by_point) {
  const Surface surface(WavinessParams{1, 10, 0, 1}, {{0.02, 32}});
  const auto& model = surface.model();
  const detail::ContactSolution solution(model, settled(surface, 0.5));
  BOOST_TEST_REQUIRE(solution.zone_count() >= 3u);
  double largest = 0;
  for (std::size_t k = 0; k < solution.zone_count(); ++k) {
    const double lo = solution.zone(k).b, hi = k + 1 < solution.zone_count() ? solution.zone(k + 1).a : pi;
    const std::vector<double> xs = samples(lo, hi, 40);
    std::vector<double> batch(xs.size());
    solution.gaps(xs.data(), batch.data(), xs.size());
    for (std::size_t i = 0; i < xs.size(); ++i) {
      const double one = solution.gap(xs[i]);
      largest = std::max(largest, std::fabs(batch[i] - one));
      BOOST_TEST(std::fabs(batch[i] - one) <= 1e-12 * model->height_range,
                 "x^ = " << xs[i] << ": " << batch[i] << " in the batch, " << one << " alone");
    }
  }
  BOOST_TEST_MESSAGE(solution.zone_count() << " zones; largest difference " << largest);
}

// Many points on long series are shared out to the threads (ContactSolution::pressures): a
// zone across the kink of m = 5.1 with its series lengthened to 4096 terms, 3001 points over
// the half period: the same bits as each point alone, with one thread or two.
BOOST_AUTO_TEST_CASE(pressures_shared_out_equal_each_point_alone) {
  const Surface surface(WavinessParams{1, 10, 5.1034742561862432, 1}, {{0.2, 24}});
  detail::Configuration c = settled(surface, 3.1645124715907493);
  for (detail::ZoneUnknowns& z : c.zones) {
    const std::size_t n = z.d.size();
    z.d.resize(4096);
    for (std::size_t j = n; j < z.d.size(); ++j) z.d[j] = 1e-9 * std::sin(static_cast<double>(j));
  }
  const detail::ContactSolution solution(surface.model(), c);
  const std::vector<double> xs = samples(0, pi, 3000);
  std::vector<double> alone(xs.size());
  for (std::size_t i = 0; i < xs.size(); ++i) alone[i] = solution.pressure(xs[i]);
  for (int threads : {1, 2}) {
    set_array_kernel_threads(threads);
    std::vector<double> shared(xs.size(), std::nan(""));
    solution.pressures(xs.data(), shared.data(), xs.size());
    for (std::size_t i = 0; i < xs.size(); ++i) {
      BOOST_TEST(shared[i] == alone[i],
                 threads << " threads, x^ = " << xs[i] << ": " << shared[i] << " shared, " << alone[i] << " alone");
    }
  }
  set_array_kernel_threads(0);
}
