#include "wavecontact/profile.hpp"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <stdexcept>
#include <utility>

#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/cos_pi.hpp>
#include <boost/math/special_functions/sin_pi.hpp>

#include "closed_forms/kinked_inversion.hpp"
#include "wavecontact/generated/profiles.hpp"
#include "support/validate.hpp"
#include "wavecontact/angles.hpp"

namespace wavecontact {

namespace {

using boost::math::double_constants::pi;

std::mutex registry_mutex;

std::map<std::string, ProfileEvaluator>& registry() {
  static std::map<std::string, ProfileEvaluator> evaluators = [] {
    std::map<std::string, ProfileEvaluator> built_in;
    generated::for_each_profile_evaluator([&](const ProfileEvaluator& e) { built_in[e.name] = e; });
    return built_in;
  }();
  return evaluators;
}

std::string joined(const std::vector<std::string>& names) {
  std::string list;
  for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
  return list.empty() ? "(none)" : list;
}

// Every part of the closed-form pressure beyond the branch point is there.
bool branch_pressure_complete(const BranchEvaluators& b) {
  for (int side = 0; side < 2; ++side) {
    if (!b.own_argument[side] || !b.other_argument[side] || !b.cauchy_argument[side]) return false;
    for (int k = 0; k < 7; ++k) {
      const int count = b.atom_counts[side][k];
      if (!b.pressure_parts[side][k] || !b.part_atoms[side][k] || count < 0 || count > detail::max_branch_atoms) {
        return false;
      }
    }
  }
  return true;
}

// One side of the branch point of the zone, from the profile's emitted parts.
detail::BranchSide branch_side(const BranchEvaluators& b, const double* q, double E, double b1, const ZoneAngles& zone,
                               int side) {
  detail::BranchSideForms forms;
  for (int k = 0; k < 7; ++k) forms.atom_counts[k] = b.atom_counts[side][k];
  forms.cauchy_argument = [&b, q, E, b1, zone, side](const PointAngles& point, double* y) {
    b.cauchy_argument[side](q, E, b1, zone.Ca, zone.Sa, point.Cx, point.Sx, point.D, y);
  };
  forms.atoms = [&b, q, E, b1, zone, side](detail::BranchPart part, double y, double one_plus_y, double* atoms) {
    b.part_atoms[side][static_cast<int>(part)](q, E, b1, zone.Ca, zone.Sa, y, one_plus_y, atoms);
  };
  forms.part = [&b, q, E, b1, zone, side](detail::BranchPart part, const PointAngles& point, const double* atoms) {
    return b.pressure_parts[side][static_cast<int>(part)](q, E, b1, zone.Ca, zone.Sa, point.Cx, point.Sx, point.D,
                                                          atoms);
  };
  return detail::BranchSide(std::move(forms), b.own_argument[side](q, zone.Ca, zone.Sa),
                            b.other_argument[side](q, zone.Ca, zone.Sa));
}

}  // namespace

void register_profile(const ProfileEvaluator& evaluator) {
  const BranchEvaluators& b = evaluator.branch;
  const bool branch_complete =
      b.beta == 0 || (b.beta > 0 && std::isfinite(b.beta) && b.cosine > -1 && b.cosine < 1 && b.load &&
                      b.load_near_branch && b.top_piece_argument && b.load_slope_factor &&
                      b.load_slope_factor_by_parts && b.top_g && b.flank_g && b.flank_height && b.flank_height_slope &&
                      branch_pressure_complete(b) && b.flank_pole_squares && b.flank_pole_count >= 0);
  if (evaluator.name.empty() || !evaluator.pressure || !evaluator.load || !evaluator.load_slope_factor ||
      !evaluator.height || !evaluator.height_slope || !evaluator.pole_squares || evaluator.pole_count < 0 ||
      evaluator.harmonic < 0 || !branch_complete) {
    throw std::invalid_argument("wavecontact::register_profile: incomplete evaluator \"" + evaluator.name + "\"");
  }
  const std::lock_guard<std::mutex> lock(registry_mutex);
  registry()[evaluator.name] = evaluator;
}

ProfileEvaluator profile_evaluator(const std::string& name) {
  {
    const std::lock_guard<std::mutex> lock(registry_mutex);
    const auto it = registry().find(name);
    if (it != registry().end()) return it->second;
  }
  throw std::domain_error("wavecontact::profile_evaluator: no profile \"" + name +
                          "\" (available: " + joined(available_profiles()) +
                          "); generate one with wavecontact-derive --profile EXPR --name " + name +
                          " and register it with wavecontact::register_profile()");
}

std::vector<std::string> available_profiles() {
  const std::lock_guard<std::mutex> lock(registry_mutex);
  std::vector<std::string> names;
  for (const auto& entry : registry()) names.push_back(entry.first);
  return names;
}

Profile::Profile(const ProfileParams& params) : params_(params), evaluator_(profile_evaluator(params.name)) {
  constexpr const char* function = "wavecontact::Profile";
  detail::require_positive(function, "b1", params.b1);
  detail::require_positive(function, "E", params.E);
  for (const auto& [name, value] : params.parameters) {
    bool known = false;
    for (const auto& p : evaluator_.parameters) known = known || p == name;
    if (!known) {
      throw std::domain_error(std::string(function) + ": profile " + params.name + " has no parameter \"" + name +
                              "\" (its parameters: " + joined(evaluator_.parameters) + ")");
    }
  }
  for (const auto& name : evaluator_.parameters) {
    const auto it = params.parameters.find(name);
    if (it == params.parameters.end()) {
      throw std::domain_error(std::string(function) + ": profile " + params.name + " needs the parameter \"" + name +
                              "\" (its parameters: " + joined(evaluator_.parameters) + ")");
    }
    detail::require_finite(function, name.c_str(), it->second);
    q_.push_back(it->second);
  }
  // A real pole tau = tan^2(x^/2) > 0 bounds the zone: x < (b1/pi) 2 atan(sqrt(tau)), if it lies
  // on the branch that holds there (the top's short of beta^2, the flank's beyond).
  const BranchEvaluators& branch = evaluator_.branch;
  std::vector<double> top(static_cast<std::size_t>(evaluator_.pole_count)),
      flank(static_cast<std::size_t>(branch.flank_pole_count));
  evaluator_.pole_squares(q_.data(), top.data());
  if (branch.beta > 0) branch.flank_pole_squares(q_.data(), flank.data());
  reach_ = params.b1;
  const auto bound = [&](double t, bool on_branch) {
    if (std::isnan(t)) {
      throw std::domain_error(std::string(function) + ": profile " + params.name +
                              ": a pole of the profile is undefined at these parameters");
    }
    if (!on_branch) return;
    if (t == 0) {
      throw std::domain_error(std::string(function) + ": profile " + params.name +
                              " has a pole at x = 0 for these parameters (no contact is possible)");
    }
    if (t > 0 && std::isfinite(t)) {
      reach_ = std::min(reach_, params.b1 / pi * 2 * std::atan(std::sqrt(t)));
    }
  };
  const double beta_square = branch.beta * branch.beta;
  for (double t : top) bound(t, branch.beta == 0 || t <= beta_square);
  for (double t : flank) bound(t, t >= beta_square);
}

bool Profile::beyond_branch(double Ca) const { return evaluator_.branch.beta > 0 && Ca < evaluator_.branch.cosine; }

void Profile::check_half_width(const char* function, double a, bool closed) const {
  const bool full = closed && reach_ == params_.b1;
  detail::require_half_width(function, a, params_.b1, reach_, full, [&] {
    return reach_ == params_.b1 ? "b1 = " + detail::format(reach_)
                                : detail::format(reach_) + ", where the profile has a pole";
  });
}

double Profile::pressure(double a, double x) const {
  constexpr const char* function = "wavecontact::Profile::pressure";
  check_half_width(function, a, false);
  detail::require_finite(function, "x", x);
  const double y = std::fabs(reduce_to_period(x, params_.b1));
  if (y >= a) return 0;
  const ZoneAngles zone = zone_angles(a, params_.b1);
  const PointAngles point = point_angles(y, a, params_.b1);
  if (beyond_branch(zone.Ca)) {
    const BranchEvaluators& b = evaluator_.branch;
    const double* q = q_.data();
    const int side = point.Cx >= b.cosine ? 0 : 1;
    const double u = boost::math::sin_pi(y / (2 * params_.b1)) / boost::math::cos_pi(y / (2 * params_.b1));
    const double g_top = b.top_g(q, params_.E, u), g_flank = b.flank_g(q, params_.E, u);
    const double g_own = side == 0 ? g_top : g_flank, g_other = side == 0 ? g_flank : g_top;
    return branch_side(b, q, params_.E, params_.b1, zone, side)
        .pressure(point, g_own == 0 ? 0.0 : g_other / g_own,  // g = 0 at x = 0 only
                  point.Cx == b.cosine);
  }
  return evaluator_.pressure(q_.data(), params_.E, params_.b1, zone.Ca, zone.Sa, point.Cx, point.Sx, point.D);
}

double Profile::load(double a) const {
  constexpr const char* function = "wavecontact::Profile::load";
  check_half_width(function, a, true);
  const ZoneAngles zone = zone_angles(a, params_.b1);
  const BranchEvaluators& b = evaluator_.branch;
  const double* q = q_.data();
  const double P = !beyond_branch(zone.Ca)                          ? evaluator_.load(q, params_.E, zone.Ca, zone.Sa)
                   : b.top_piece_argument(q, zone.Ca, zone.Sa) >= 1 ? b.load_near_branch(q, params_.E, zone.Ca, zone.Sa)
                                                                    : b.load(q, params_.E, zone.Ca, zone.Sa);
  if (!std::isfinite(P)) {
    detail::domain_error(function, "a", a, "a half-width where the closed-form load is finite");
  }
  return P;
}

double Profile::load_slope(double a) const {
  constexpr const char* function = "wavecontact::Profile::load_slope";
  check_half_width(function, a, true);
  const ZoneAngles zone = zone_angles(a, params_.b1);
  const BranchEvaluators& b = evaluator_.branch;
  const double* q = q_.data();
  const double factor = !beyond_branch(zone.Ca) ? evaluator_.load_slope_factor(q, params_.E, zone.Ca, zone.Sa)
                        : b.top_piece_argument(q, zone.Ca, zone.Sa) >= 0
                            ? b.load_slope_factor_by_parts(q, params_.E, zone.Ca, zone.Sa)
                            : b.load_slope_factor(q, params_.E, zone.Ca, zone.Sa);
  // sin(pi a/b1) = sin(pi (b1 - a)/b1), b1 - a exact beyond b1/2: no digits lost as a -> b1.
  return pi / params_.b1 * boost::math::sin_pi((a > params_.b1 / 2 ? params_.b1 - a : a) / params_.b1) * factor;
}

double Profile::full_contact_pressure(double P, double x) const {
  constexpr const char* function = "wavecontact::Profile::full_contact_pressure";
  if (!evaluator_.full_contact_pressure) {
    throw std::domain_error(std::string(function) + ": profile " + params_.name +
                            " has no closed form of full contact (its evaluators were registered without one)");
  }
  if (reach_ < params_.b1) {
    throw std::domain_error(std::string(function) + ": profile " + params_.name +
                            " has a pole at x = " + detail::format(reach_) + " of the period: no full contact");
  }
  if (!(std::isfinite(P) && P >= 0)) detail::domain_error(function, "P", P, "a finite load P >= 0");
  detail::require_finite(function, "x", x);
  const double Cx = boost::math::cos_pi(reduce_to_period(x, params_.b1) / params_.b1);
  return P / (2 * params_.b1) + evaluator_.full_contact_pressure(q_.data(), params_.E, params_.b1, Cx);
}

}  // namespace wavecontact
