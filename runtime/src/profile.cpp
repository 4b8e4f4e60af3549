#include "wavecontact/profile.hpp"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <stdexcept>

#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/sin_pi.hpp>

#include "profiles.hpp"  // generated/
#include "validate.hpp"
#include "wavecontact/angles.hpp"

namespace wavecontact {

namespace {

constexpr double pi = boost::math::double_constants::pi;

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

}  // namespace

void register_profile(const ProfileEvaluator& evaluator) {
  if (evaluator.name.empty() || !evaluator.pressure || !evaluator.load ||
      !evaluator.load_slope_factor || !evaluator.height || !evaluator.height_slope ||
      !evaluator.pole_squares || evaluator.pole_count < 0 || evaluator.harmonic < 0) {
    throw std::invalid_argument("wavecontact::register_profile: incomplete evaluator \"" +
                                evaluator.name + "\"");
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
                          "); generate one with wavecontact-derive --profile EXPR --name " +
                          name + " and register it with wavecontact::register_profile()");
}

std::vector<std::string> available_profiles() {
  const std::lock_guard<std::mutex> lock(registry_mutex);
  std::vector<std::string> names;
  for (const auto& entry : registry()) names.push_back(entry.first);
  return names;
}

Profile::Profile(const ProfileParams& params)
    : params_(params), evaluator_(profile_evaluator(params.name)) {
  constexpr const char* function = "wavecontact::Profile";
  detail::require_positive(function, "b1", params.b1);
  detail::require_positive(function, "E", params.E);
  for (const auto& [name, value] : params.parameters) {
    bool known = false;
    for (const auto& p : evaluator_.parameters) known = known || p == name;
    if (!known) {
      throw std::domain_error(std::string(function) + ": profile " + params.name +
                              " has no parameter \"" + name + "\" (its parameters: " +
                              joined(evaluator_.parameters) + ")");
    }
  }
  for (const auto& name : evaluator_.parameters) {
    const auto it = params.parameters.find(name);
    if (it == params.parameters.end()) {
      throw std::domain_error(std::string(function) + ": profile " + params.name +
                              " needs the parameter \"" + name + "\" (its parameters: " +
                              joined(evaluator_.parameters) + ")");
    }
    detail::require_finite(function, name.c_str(), it->second);
    q_.push_back(it->second);
  }
  // A real pole tau = tan^2(x^/2) > 0 bounds the zone: x < (b1/pi) 2 atan(sqrt(tau)).
  std::vector<double> tau(static_cast<std::size_t>(evaluator_.pole_count));
  evaluator_.pole_squares(q_.data(), tau.data());
  reach_ = params.b1;
  for (double t : tau) {
    if (std::isnan(t)) {
      throw std::domain_error(std::string(function) + ": profile " + params.name +
                              ": a pole of the profile is undefined at these parameters");
    }
    if (t == 0) {
      throw std::domain_error(std::string(function) + ": profile " + params.name +
                              " has a pole at x = 0 for these parameters (no contact is possible)");
    }
    if (t > 0 && std::isfinite(t)) {
      reach_ = std::min(reach_, params.b1 / pi * 2 * std::atan(std::sqrt(t)));
    }
  }
}

void Profile::check_half_width(const char* function, double a, bool closed) const {
  const bool full = closed && reach_ == params_.b1;
  if (!(std::isfinite(a) && a > 0 && (a < reach_ || (full && a == reach_)))) {
    const std::string bound = reach_ == params_.b1
                                  ? "b1 = " + detail::format(reach_)
                                  : detail::format(reach_) + ", where the profile has a pole";
    detail::domain_error(function, "a", a, std::string("0 < a ") + (full ? "<= " : "< ") + bound);
  }
}

double Profile::pressure(double a, double x) const {
  constexpr const char* function = "wavecontact::Profile::pressure";
  check_half_width(function, a, false);
  detail::require_finite(function, "x", x);
  const double y = std::fabs(reduce_to_period(x, params_.b1));
  if (y >= a) return 0;
  const ZoneAngles zone = zone_angles(a, params_.b1);
  const PointAngles point = point_angles(y, a, params_.b1);
  return evaluator_.pressure(q_.data(), params_.E, params_.b1, zone.Ca, zone.Sa, point.Cx,
                             point.Sx, point.D);
}

double Profile::load(double a) const {
  constexpr const char* function = "wavecontact::Profile::load";
  check_half_width(function, a, true);
  const ZoneAngles zone = zone_angles(a, params_.b1);
  const double P = evaluator_.load(q_.data(), params_.E, zone.Ca, zone.Sa);
  if (!std::isfinite(P)) {
    detail::domain_error(function, "a", a, "a half-width where the closed-form load is finite");
  }
  return P;
}

double Profile::load_slope(double a) const {
  constexpr const char* function = "wavecontact::Profile::load_slope";
  check_half_width(function, a, true);
  const ZoneAngles zone = zone_angles(a, params_.b1);
  return pi / params_.b1 * boost::math::sin_pi(a / params_.b1) *
         evaluator_.load_slope_factor(q_.data(), params_.E, zone.Ca, zone.Sa);
}

}  // namespace wavecontact
