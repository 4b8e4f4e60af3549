// The array evaluations split across threads (wavecontact/threads.hpp) give the same bits
// whatever the number of threads, on every array path.
#define BOOST_TEST_MODULE threads
#include <boost/test/unit_test.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "isa_under_test.hpp"
#include "wavecontact/contact.hpp"
#include "wavecontact/threads.hpp"
#include "wavecontact/two_scale.hpp"
#include "wavecontact/waviness.hpp"

using namespace wavecontact;

namespace {

// f(x, p) with 1 thread, then with 2, 3 and 7: the same bytes. Restores the default.
void same_bits_whatever_the_threads(const std::function<void(const Eigen::ArrayXd&, Eigen::ArrayXd&)>& f,
                                    const Eigen::ArrayXd& x, const char* what) {
  Eigen::ArrayXd alone(x.size()), split(x.size());
  set_array_kernel_threads(1);
  f(x, alone);
  for (int threads : {2, 3, 7}) {
    set_array_kernel_threads(threads);
    split.setConstant(std::nan(""));
    f(x, split);
    BOOST_TEST(std::memcmp(alone.data(), split.data(), sizeof(double) * static_cast<std::size_t>(x.size())) == 0,
               what << ": " << threads << " threads differ from one");
  }
  set_array_kernel_threads(0);
}

// Enough points to be split, and not a whole number of blocks.
const Eigen::ArrayXd points = Eigen::ArrayXd::LinSpaced(3 * static_cast<Eigen::Index>(parallel_points) + 77, -4.5, 4.5);

}  // namespace

BOOST_AUTO_TEST_CASE(waviness_pressure) {
  const WavinessParams w{1.0, 10.0, 2.0, 1.0};
  same_bits_whatever_the_threads([&](const Eigen::ArrayXd& x, Eigen::ArrayXd& p) { pressure(w, 4.0, x, p); }, points,
                                 "a <= b1/2");
  same_bits_whatever_the_threads(
      [&](const Eigen::ArrayXd& x, Eigen::ArrayXd& p) { pressure(w, 4.0, x, p, Form::paper); }, points, "printed");
  same_bits_whatever_the_threads(
      [&](const Eigen::ArrayXd& x, Eigen::ArrayXd& p) { pressure(w, 6.0, x, p); },
      Eigen::ArrayXd::LinSpaced(5 * static_cast<Eigen::Index>(parallel_points_costly) + 3, -6, 6),
      "beyond b1/2 (quadrature)");
}

BOOST_AUTO_TEST_CASE(two_scale_pressure) {
  const TwoScaleContact c({{1.0, 10.0, 0.0, 1.0}, {0.001, 64}}, 4.5);
  same_bits_whatever_the_threads([&](const Eigen::ArrayXd& x, Eigen::ArrayXd& p) { c.pressure(x, p); }, points,
                                 "two-scale");
}

BOOST_AUTO_TEST_CASE(contact_pressure) {
  const Contact c = solve_contact(Surface(WavinessParams{1.0, 10.0, 0.0, 1.0}, {{0.15, 8}}), 0.3 * M_PI);
  same_bits_whatever_the_threads(
      [&](const Eigen::ArrayXd& x, Eigen::ArrayXd& p) { c.pressure(x, p); },
      Eigen::ArrayXd::LinSpaced(50 * static_cast<Eigen::Index>(parallel_points_costly) + 3, -10, 10), "contact");
}

// Callers on several threads at once: one takes the thread pool, the others compute alone on
// their own threads (runtime/src/support/worker_pool.*); each gets the bits of a caller alone.
BOOST_AUTO_TEST_CASE(concurrent_callers_get_the_bits_of_one_alone) {
  const WavinessParams w{1.0, 10.0, 2.0, 1.0};
  set_array_kernel_threads(2);
  Eigen::ArrayXd alone(points.size());
  pressure(w, 4.0, points, alone);
  std::vector<Eigen::ArrayXd> results(4, Eigen::ArrayXd::Constant(points.size(), std::nan("")));
  std::vector<bool> same(results.size(), true);
  std::vector<std::thread> callers;
  for (std::size_t t = 0; t < results.size(); ++t) {
    callers.emplace_back([&, t] {
      for (int round = 0; round < 20; ++round) {
        pressure(w, 4.0, points, results[t]);
        same[t] = same[t] && std::memcmp(alone.data(), results[t].data(),
                                         sizeof(double) * static_cast<std::size_t>(results[t].size())) == 0;
      }
    });
  }
  for (std::thread& caller : callers) caller.join();
  for (std::size_t t = 0; t < results.size(); ++t) BOOST_TEST(same[t], "caller " << t << " differs from one alone");
  set_array_kernel_threads(0);
}

// A contact whose zone loops run on the pool (79 zones a period), solved on three threads at
// once: each the contact solved alone, bit for bit.
BOOST_AUTO_TEST_CASE(concurrent_contact_solves_get_the_contact_solved_alone) {
  const Surface surface(WavinessParams{1.0, 10.0, 0.0, 1.0}, {{0.15, 256}});
  const Contact alone = solve_contact(surface, 0.2 * M_PI);
  BOOST_TEST_REQUIRE(alone.zones_per_period() > 64);
  std::vector<std::optional<Contact>> contacts(3);
  std::vector<std::thread> callers;
  for (std::optional<Contact>& c : contacts) callers.emplace_back([&] { c = solve_contact(surface, 0.2 * M_PI); });
  for (std::thread& caller : callers) caller.join();
  for (const std::optional<Contact>& c : contacts) {
    BOOST_TEST_REQUIRE(c->zones().size() == alone.zones().size());
    for (std::size_t k = 0; k < alone.zones().size(); ++k) {
      BOOST_TEST(c->zones()[k].x_start == alone.zones()[k].x_start);
      BOOST_TEST(c->zones()[k].x_end == alone.zones()[k].x_end);
    }
    BOOST_TEST(c->pressure(0.0) == alone.pressure(0.0));
  }
}

// A child of fork() (as Python's multiprocessing makes) has none of its parent's pool
// threads: its parallel calls finish all the same (they must not wait for a helper that does
// not exist), with the parent's bits.
BOOST_AUTO_TEST_CASE(a_forked_child_computes_with_the_parents_bits) {
  const WavinessParams w{1.0, 10.0, 2.0, 1.0};
  set_array_kernel_threads(2);
  Eigen::ArrayXd parent(points.size());
  pressure(w, 4.0, points, parent);  // the parent's pool exists
  const pid_t child = fork();
  BOOST_TEST_REQUIRE(child >= 0);
  if (child == 0) {
    Eigen::ArrayXd p(points.size());
    pressure(w, 4.0, points, p);
    _exit(std::memcmp(parent.data(), p.data(), sizeof(double) * static_cast<std::size_t>(p.size())) == 0 ? 0 : 1);
  }
  int status = 0;
  BOOST_TEST_REQUIRE(waitpid(child, &status, 0) == child);
  BOOST_TEST(WIFEXITED(status));
  BOOST_TEST(WEXITSTATUS(status) == 0, "the child's pressure differs from the parent's");
  set_array_kernel_threads(0);
}

// A point that is not finite, in the first, a middle or the last chunk of a split array: the
// domain error names it and p is left as it was, whatever the threads.
BOOST_AUTO_TEST_CASE(non_finite_point_refused_before_any_is_written) {
  const WavinessParams w{1.0, 10.0, 2.0, 1.0};
  for (int threads : {1, 2, 7}) {
    set_array_kernel_threads(threads);
    for (const Eigen::Index at : {Eigen::Index{0}, points.size() / 2, points.size() - 1}) {
      for (const double bad : {std::nan(""), HUGE_VAL, -HUGE_VAL}) {
        Eigen::ArrayXd x = points, p = Eigen::ArrayXd::Constant(points.size(), 42.0);
        x[at] = bad;
        bool refused = false;
        try {
          pressure(w, 4.0, x, p);
        } catch (const std::domain_error& e) {
          refused = std::string(e.what()).find("wavecontact::pressure: x = ") == 0;
          BOOST_TEST(refused, "the message: " << e.what());
        }
        BOOST_TEST(refused, "x[" << at << "] = " << bad << ", " << threads << " threads: not refused");
        BOOST_TEST((p == 42.0).all(), "x[" << at << "] = " << bad << ", " << threads << " threads: p written");
      }
    }
  }
  set_array_kernel_threads(0);
}

BOOST_AUTO_TEST_CASE(thread_count_is_validated) {
  BOOST_CHECK_THROW(set_array_kernel_threads(-1), std::domain_error);
  set_array_kernel_threads(3);
  BOOST_TEST(array_kernel_threads() == 3);
  set_array_kernel_threads(0);
  BOOST_TEST(array_kernel_threads() >= 1);
}
