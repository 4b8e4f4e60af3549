#include "wavecontact/contact.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <boost/math/tools/minima.hpp>

#include "contact/constants.hpp"
#include "contact/contact_solver.hpp"
#include "contact/solution.hpp"
#include "support/parallel.hpp"
#include "support/validate.hpp"
#include "wavecontact/angles.hpp"
#include "wavecontact/threads.hpp"

namespace wavecontact {

namespace {

using detail::pi;

void require_options(const char* function, const SolverOptions& options) {
  if (!(options.tolerance >= 1e-14 && options.tolerance <= 1e-2)) {
    detail::domain_error(function, "tolerance", options.tolerance, "1e-14 <= tolerance <= 1e-2");
  }
  if (options.nodes_per_zone != 0 && (options.nodes_per_zone < 4 || options.nodes_per_zone > 4096)) {
    detail::domain_error(function, "nodes_per_zone", options.nodes_per_zone,
                         "0 (adaptive) or 4 <= nodes_per_zone <= 4096");
  }
  if (!(options.max_seconds > 0 && options.max_seconds <= 1e6)) {
    detail::domain_error(function, "max_seconds", options.max_seconds, "0 < max_seconds <= 1e6");
  }
}

// The largest pressure on zone k (x^): every local maximum of its Chebyshev-spread sampling,
// refined by Brent's method between its neighbours.
std::pair<double, double> largest_pressure(const detail::ContactSolution& s, std::size_t k) {
  const auto& [xs, ps] = s.sampled_pressure(k);
  const double lo = s.zone(k).a, hi = s.zone(k).b;
  const int count = static_cast<int>(xs.size()) - 1;
  std::pair<double, double> best{-std::numeric_limits<double>::infinity(), lo};
  for (int i = 0; i <= count; ++i) {
    const std::size_t u = static_cast<std::size_t>(i);
    if ((i > 0 && ps[u] < ps[u - 1]) || (i < count && ps[u] < ps[u + 1])) continue;
    if (ps[u] > best.first) best = {ps[u], xs[u]};
    const double a = i > 0 ? xs[u - 1] : lo, b = i < count ? xs[u + 1] : hi;
    if (!(b > a)) continue;
    const auto [x, minus_p] = boost::math::tools::brent_find_minima([&](double t) { return -s.pressure(t); }, a, b, 52);
    if (-minus_p > best.first) best = {-minus_p, x};
  }
  return best;
}

}  // namespace

double Contact::pressure(double x) const {
  detail::require_finite("wavecontact::Contact::pressure", "x", x);
  return pi / b1_ * solution_->pressure(pi * reduce_to_period(x, b1_) / b1_);
}

void Contact::pressure(const Eigen::Ref<const Eigen::ArrayXd>& x, Eigen::Ref<Eigen::ArrayXd> p) const {
  detail::require_points("wavecontact::Contact::pressure", x, p.size());
  const double* xs = x.data();
  double* ps = p.data();
  detail::for_each_chunk(static_cast<std::size_t>(x.size()), 1, parallel_points_costly,
                         [&](std::size_t begin, std::size_t end) {
                           for (std::size_t i = begin; i < end; ++i)
                             ps[i] = pi / b1_ * solution_->pressure(pi * reduce_to_period(xs[i], b1_) / b1_);
                         });
}

double Contact::gap(double x) const {
  detail::require_finite("wavecontact::Contact::gap", "x", x);
  return solution_->gap(pi * reduce_to_period(x, b1_) / b1_);
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
  const detail::ContactSolver solver(surface.model(), options.tolerance, options.nodes_per_zone,
                                     detail::WorkBudget(options.max_seconds, options.checkpoint));
  const std::vector<detail::SolvedContact> solved = solver.solve(loads);
  const double b1 = surface.b1(), to_x = b1 / pi, to_p = pi / b1;
  std::vector<Contact> contacts;
  for (const detail::SolvedContact& s : solved) {
    Contact c;
    const detail::ContactSolution& solution = *s.solution;
    c.b1_ = b1, c.P_ = s.P, c.error_estimate_ = s.error_estimate, c.rounding_ = s.rounding, c.nodes_ = s.nodes;
    c.full_ = solution.full_contact();
    for (std::size_t k = 0; k < solution.zone_count(); ++k) {
      const detail::ZoneGeometry& z = solution.zone(k);
      const double half = solution.zone_load(k);
      const auto [p_max, x_max] = largest_pressure(solution, k);
      const ContactZone right{z.a * to_x, z.b * to_x, half, p_max * to_p, x_max * to_x};
      c.fraction_ += (z.b - z.a) / pi;
      if (p_max * to_p > c.max_pressure_) c.max_pressure_ = p_max * to_p, c.x_of_max_ = x_max * to_x;
      if (z.top() && z.valley()) {
        c.zones_.push_back({-b1, b1, s.P, right.max_pressure, right.x_of_max_pressure});
      } else if (z.top()) {
        c.zones_.push_back({-right.x_end, right.x_end, 2 * half, right.max_pressure, right.x_of_max_pressure});
      } else if (z.valley()) {
        c.zones_.push_back(
            {right.x_start, 2 * b1 - right.x_start, 2 * half, right.max_pressure, right.x_of_max_pressure});
      } else {
        c.zones_.push_back({-right.x_end, -right.x_start, half, right.max_pressure, -right.x_of_max_pressure});
        c.zones_.push_back(right);
      }
    }
    std::sort(c.zones_.begin(), c.zones_.end(),
              [](const ContactZone& a, const ContactZone& b) { return a.x_start < b.x_start; });
    c.solution_ = s.solution;
    contacts.push_back(std::move(c));
  }
  return contacts;
}

Contact solve_contact(const Surface& surface, double P, const SolverOptions& options) {
  return solve_contact(surface, std::vector<double>{P}, options).front();
}

double full_contact_load(const Surface& surface) {
  return detail::ContactSolver(surface.model(), 1e-10, 0, detail::WorkBudget(60, {})).full_contact_load();
}

SingleZoneCheck single_zone_check(const Surface& surface, double a) {
  constexpr const char* function = "wavecontact::single_zone_check";
  detail::require_half_width(function, a, surface.b1(), surface.b1(), false,
                             [&] { return "b1 = " + detail::format(surface.b1()); });
  const detail::SingleZoneResult r = detail::check_single_zone(surface.model(), pi * a / surface.b1());
  const double to_x = surface.b1() / pi;
  return {r.solution,
          r.penetrates,
          r.lowest_gap,
          r.x_of_lowest_gap * to_x,
          r.lowest_pressure * pi / surface.b1(),
          r.x_of_lowest_pressure * to_x};
}

}  // namespace wavecontact
