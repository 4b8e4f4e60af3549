#include "wavecontact/contact.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <boost/math/quadrature/tanh_sinh.hpp>
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

// The largest pressure on [lo, hi] of zone k (x^): every local maximum of the zone's
// Chebyshev-spread sampling there, refined by Brent's method between its neighbours.
std::pair<double, double> largest_pressure(const detail::ContactSolution& s, std::size_t k, double lo, double hi) {
  const auto& [xs, ps] = s.sampled_pressure(k);
  const std::size_t first = static_cast<std::size_t>(std::lower_bound(xs.begin(), xs.end(), lo) - xs.begin());
  const std::size_t last = static_cast<std::size_t>(std::upper_bound(xs.begin(), xs.end(), hi) - xs.begin());
  if (first == last) return {s.pressure((lo + hi) / 2), (lo + hi) / 2};  // a piece between samples
  std::pair<double, double> best{-std::numeric_limits<double>::infinity(), lo};
  for (std::size_t u = first; u < last; ++u) {
    if ((u > first && ps[u] < ps[u - 1]) || (u + 1 < last && ps[u] < ps[u + 1])) continue;
    if (ps[u] > best.first) best = {ps[u], xs[u]};
    const double a = u > first ? xs[u - 1] : lo, b = u + 1 < last ? xs[u + 1] : hi;
    if (!(b > a)) continue;
    const auto [x, minus_p] = boost::math::tools::brent_find_minima([&](double t) { return -s.pressure(t); }, a, b, 52);
    if (-minus_p > best.first) best = {-minus_p, x};
  }
  return best;
}

// The pieces of zone k that its narrow gaps leave (x^), with their loads (its own part of
// [0, pi]): each but the longest integrated (tanh-sinh, which takes the root at each end),
// the longest the zone's load less theirs (the gaps' corrections carry none).
struct ZonePiece {
  double a, b, load;
};
std::vector<ZonePiece> zone_pieces(const detail::ContactSolution& s, std::size_t k) {
  const detail::ZoneGeometry& z = s.zone(k);
  std::vector<ZonePiece> pieces;
  double lo = z.a;
  for (const detail::NarrowGap& g : s.narrow_gaps(k))
    pieces.push_back({lo, g.centre - g.half, 0}), lo = g.centre + g.half;
  pieces.push_back({lo, z.b, 0});
  if (pieces.size() == 1) {
    pieces[0].load = s.zone_load(k);
    return pieces;
  }
  const auto longest = std::max_element(pieces.begin(), pieces.end(),
                                        [](const ZonePiece& l, const ZonePiece& r) { return l.b - l.a < r.b - r.a; });
  double rest = s.zone_load(k);
  boost::math::quadrature::tanh_sinh<double> integrator;
  for (auto piece = pieces.begin(); piece != pieces.end(); ++piece) {
    if (piece == longest) continue;
    piece->load = integrator.integrate([&](double x) { return s.pressure(x); }, piece->a, piece->b, 1e-13);
    rest -= piece->load;
  }
  longest->load = rest;
  return pieces;
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
      for (const ZonePiece& piece : zone_pieces(solution, k)) {
        const auto [p_max, x_max] = largest_pressure(solution, k, piece.a, piece.b);
        const ContactZone right{piece.a * to_x, piece.b * to_x, piece.load, p_max * to_p, x_max * to_x};
        c.fraction_ += (piece.b - piece.a) / pi;
        if (p_max * to_p > c.max_pressure_) c.max_pressure_ = p_max * to_p, c.x_of_max_ = x_max * to_x;
        const bool top = piece.a == 0, valley = piece.b == pi;
        if (top && valley) {
          c.zones_.push_back({-b1, b1, s.P, right.max_pressure, right.x_of_max_pressure});
        } else if (top) {
          c.zones_.push_back({-right.x_end, right.x_end, 2 * piece.load, right.max_pressure, right.x_of_max_pressure});
        } else if (valley) {
          c.zones_.push_back(
              {right.x_start, 2 * b1 - right.x_start, 2 * piece.load, right.max_pressure, right.x_of_max_pressure});
        } else {
          c.zones_.push_back({-right.x_end, -right.x_start, piece.load, right.max_pressure, -right.x_of_max_pressure});
          c.zones_.push_back(right);
        }
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
