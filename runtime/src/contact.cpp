#include "wavecontact/contact.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include <boost/math/constants/constants.hpp>
#include <boost/math/tools/minima.hpp>

#include "contact_solver.hpp"
#include "parallel.hpp"
#include "validate.hpp"
#include "wavecontact/angles.hpp"
#include "wavecontact/threads.hpp"

namespace wavecontact {

namespace {

constexpr double pi = boost::math::double_constants::pi;

void require_options(const char* function, const SolverOptions& options) {
  if (!(options.tolerance >= 1e-14 && options.tolerance <= 1e-2)) {
    detail::domain_error(function, "tolerance", options.tolerance, "1e-14 <= tolerance <= 1e-2");
  }
  if (options.order != 0 && (options.order < 4 || options.order > 64)) {
    detail::domain_error(function, "order", options.order, "0 (adaptive) or 4 <= order <= 64");
  }
  if (!(options.max_seconds > 0 && options.max_seconds <= 1e6)) {
    detail::domain_error(function, "max_seconds", options.max_seconds, "0 < max_seconds <= 1e6");
  }
}

// The largest pressure on [lo, hi] (x^): every sample that is a local maximum, refined by
// Brent's method between its neighbouring samples (the largest sample need not be next to
// the largest pressure).
std::pair<double, double> largest_pressure(const detail::IntervalInversion& inversion, double lo, double hi) {
  std::vector<detail::IntervalInversion::Sample> samples;
  for (const auto& s : inversion.pressure_samples()) {
    if (s.x >= lo && s.x <= hi) samples.push_back(s);
  }
  std::sort(samples.begin(), samples.end(),
            [](const auto& a, const auto& b) { return a.x < b.x || (a.x == b.x && a.value > b.value); });
  // Panels share their end points, whose two samples may differ in the last bit: the higher.
  samples.erase(std::unique(samples.begin(), samples.end(), [](const auto& a, const auto& b) { return a.x == b.x; }),
                samples.end());
  if (samples.empty()) return {0, lo};
  std::pair<double, double> best{-std::numeric_limits<double>::infinity(), lo};
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const bool left = i == 0 || samples[i].value >= samples[i - 1].value;
    const bool right = i + 1 == samples.size() || samples[i].value >= samples[i + 1].value;
    if (!left || !right) continue;
    if (samples[i].value > best.first) best = {samples[i].value, samples[i].x};
    const double a = i > 0 ? samples[i - 1].x : lo, b = i + 1 < samples.size() ? samples[i + 1].x : hi;
    if (!(b > a)) continue;
    const auto [x, minus_p] = boost::math::tools::brent_find_minima(
        [&](double t) { return -inversion.pressure(t); }, a, b, 52);
    if (-minus_p > best.first) best = {-minus_p, x};
  }
  return best;
}

}  // namespace

double Contact::pressure(double x) const {
  detail::require_finite("wavecontact::Contact::pressure", "x", x);
  return pi / b1_ * inversion_->pressure(pi * reduce_to_period(x, b1_) / b1_);
}

void Contact::pressure(const Eigen::Ref<const Eigen::ArrayXd>& x, Eigen::Ref<Eigen::ArrayXd> p) const {
  detail::require_points("wavecontact::Contact::pressure", x, p.size());
  const double* xs = x.data();
  double* ps = p.data();
  detail::for_each_chunk(static_cast<std::size_t>(x.size()), 1, parallel_points_costly,
                         [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) ps[i] = pi / b1_ * inversion_->pressure(pi * reduce_to_period(xs[i], b1_) / b1_);
  });
}

double Contact::gap(double x) const {
  detail::require_finite("wavecontact::Contact::gap", "x", x);
  return inversion_->gap(pi * reduce_to_period(x, b1_) / b1_);
}

std::vector<Contact> solve_contact(const Surface& surface, const std::vector<double>& loads,
                                   const SolverOptions& options) {
  constexpr const char* function = "wavecontact::solve_contact";
  require_options(function, options);
  // Below this load the contact is a single zone of a width beyond the resolution of x.
  const double lowest = min_load_ratio * surface.E() * surface.height_scale();
  for (double P : loads) {
    if (!(std::isfinite(P) && P >= lowest && P <= max_scale * max_scale)) {
      detail::domain_error(function, "P", P,
                           detail::format(lowest) + " = " + detail::format(min_load_ratio) +
                               " E* max|y| <= P <= " + detail::format(max_scale * max_scale));
    }
  }
  const detail::ContactSolver solver(surface.slope(), options.tolerance, options.order,
                                     detail::WorkBudget(options.max_seconds, options.checkpoint));
  const std::vector<detail::SolvedContact> solved = solver.solve(loads);
  const double b1 = surface.b1(), to_x = b1 / pi, to_p = pi / b1;
  std::vector<Contact> contacts;
  for (const detail::SolvedContact& s : solved) {
    Contact c;
    const std::shared_ptr<const detail::IntervalInversion>& inversion = s.inversion;
    c.b1_ = b1, c.P_ = s.P, c.error_estimate_ = s.error_estimate, c.order_ = s.order;
    c.full_ = inversion->full_contact();
    for (std::size_t k = 0; k < s.zones.size(); ++k) {
      const detail::Zone& z = s.zones[k];
      const double half = inversion->zone_load(k);
      const auto [p_max, x_max] = largest_pressure(*inversion, z.lo, z.hi);
      const ContactZone right{z.lo * to_x, z.hi * to_x, half, p_max * to_p, x_max * to_x};
      c.fraction_ += (z.hi - z.lo) / pi;
      if (p_max * to_p > c.max_pressure_) c.max_pressure_ = p_max * to_p, c.x_of_max_ = x_max * to_x;
      if (z.lo == 0 && z.hi == pi) {
        c.zones_.push_back({-b1, b1, s.P, right.max_pressure, right.x_of_max_pressure});
      } else if (z.lo == 0) {  // through the top
        c.zones_.push_back({-right.x_end, right.x_end, 2 * half, right.max_pressure, right.x_of_max_pressure});
      } else if (z.hi == pi) {  // through the valley
        c.zones_.push_back({right.x_start, 2 * b1 - right.x_start, 2 * half, right.max_pressure, right.x_of_max_pressure});
      } else {
        c.zones_.push_back({-right.x_end, -right.x_start, half, right.max_pressure, -right.x_of_max_pressure});
        c.zones_.push_back(right);
      }
    }
    std::sort(c.zones_.begin(), c.zones_.end(),
              [](const ContactZone& a, const ContactZone& b) { return a.x_start < b.x_start; });
    c.inversion_ = inversion;
    contacts.push_back(std::move(c));
  }
  return contacts;
}

Contact solve_contact(const Surface& surface, double P, const SolverOptions& options) {
  return solve_contact(surface, std::vector<double>{P}, options).front();
}

double full_contact_load(const Surface& surface) {
  return detail::ContactSolver(surface.slope(), 1e-10).full_contact_load();
}

SingleZoneCheck single_zone_check(const Surface& surface, double a) {
  constexpr const char* function = "wavecontact::single_zone_check";
  detail::require_half_width(function, a, surface.b1(), surface.b1(), false, "b1 = " + detail::format(surface.b1()));
  const detail::SingleZoneResult r = detail::check_single_zone(surface.slope(), pi * a / surface.b1());
  const double to_x = surface.b1() / pi;
  return {r.solution, r.penetrates, r.lowest_gap, r.x_of_lowest_gap * to_x,
          r.lowest_pressure * pi / surface.b1(), r.x_of_lowest_pressure * to_x};
}

}  // namespace wavecontact
