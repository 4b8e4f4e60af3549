// The C++ side of tests/python/test_bitwise.py: values of the runtime API on fixed inputs,
// printed exactly (hexadecimal floating point), one "key value" per line. The Python module
// must give the same bits on the same inputs.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "wavecontact/contact.hpp"
#include "wavecontact/profile.hpp"
#include "wavecontact/shape_design.hpp"
#include "wavecontact/stability.hpp"
#include "wavecontact/two_scale.hpp"
#include "wavecontact/waviness.hpp"

namespace {

void put(const std::string& key, double value) { std::printf("%s %a\n", key.c_str(), value); }

void put(const std::string& key, const Eigen::ArrayXd& values) {
  for (Eigen::Index i = 0; i < values.size(); ++i) put(key + "[" + std::to_string(i) + "]", values[i]);
}

}  // namespace

int main() {
  using namespace wavecontact;
  const Eigen::ArrayXd x = Eigen::ArrayXd::LinSpaced(257, -4.5, 4.5);
  for (double m : {0.0, 2.0, 10.0}) {
    const WavinessParams w{1.0, 10.0, m, 1.0};
    const std::string tag = "m" + std::to_string(static_cast<int>(m));
    put(tag + ".pressure_array", pressure(w, 4.0, x));
    put(tag + ".pressure_paper", pressure(w, 4.0, x, Form::paper));
    put(tag + ".pressure_scalar", pressure(w, 4.0, 1.25));
    put(tag + ".pressure_beyond", pressure(w, 6.0, 5.5));
    put(tag + ".load", load(w, 4.0));
    put(tag + ".load_slope", load_slope(w, 4.0));
    put(tag + ".pa_over_pstar", pa_over_pstar(w, 4.0));
    put(tag + ".half_width", single_asperity_half_width(w, 1.5));
    put(tag + ".wave_curve", wave_curve(w, 3.3));
    put(tag + ".maximum_load", LoadCurve(w).maximum_load());
  }
  const TwoScaleParams rough{{1.0, 10.0, 0.0, 1.0}, {0.001, 64}};
  const TwoScaleContact two_scale(rough, 0.9);
  Eigen::ArrayXd p(x.size());
  const Eigen::ArrayXd inside = Eigen::ArrayXd::LinSpaced(101, -0.9, 0.9);
  Eigen::ArrayXd q(inside.size());
  two_scale.pressure(inside, q);
  put("two_scale.pressure_array", q);
  put("two_scale.roughness_scalar", two_scale.roughness_pressure(0.3));
  put("two_scale.load", two_scale.load());

  const Profile profile({"two_harmonic", {{"H1", 1.0}, {"H3", -0.05}}, 10.0, 1.0});
  put("profile.pressure", profile.pressure(3.0, 1.7));
  put("profile.load", profile.load(3.0));

  put("uniformity.max_over_mean", pressure_uniformity(2.0, 0.3).max_over_mean);

  const Surface surface(WavinessParams{1.0, 10.0, 10.0, 1.0});
  const Contact c = solve_contact(surface, 1.9 * M_PI);
  put("contact.p0", c.pressure(0.0));
  put("contact.fraction", c.contact_fraction());
  put("contact.x_end", c.zones()[0].x_end);
  put("contact.gap", c.gap(5.5));
  c.pressure(x, p);
  put("contact.pressure_array", p);
  const Surface rough_surface(WavinessParams{1.0, 10.0, 0.0, 1.0}, {{0.15, 8}});
  const std::vector<Contact> sweep = solve_contact(rough_surface, std::vector<double>{0.3, 0.6, 0.9});
  for (std::size_t i = 0; i < sweep.size(); ++i) put("sweep.p0[" + std::to_string(i) + "]", sweep[i].pressure(0.0));
  put("full_contact_load", full_contact_load(surface));
  return 0;
}
