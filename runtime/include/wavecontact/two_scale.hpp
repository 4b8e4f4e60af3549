// The two-scale profile (eq. 1): the parametric wave curve plus the roughness harmonic
// r(x) = H2 cos(n pi x/b1), n even (eq. 3), one contact zone |x| <= a < b1 per period,
// superposed (eq. 21).
//
// The roughness pressure is the exact solution of eq. 17 in its Legendre-Dirichlet form
// (derived and proven against the engine in derive/formulas/roughness.*):
//   p_r(x) = (pi/b1) (E* H2 n/sqrt2) sqrt(cos x^ - cos a^) sum_{j<n} P_{n-1-j}(cos a^) cos((j+1/2) x^),
//   P_r    = (pi/2) E* H2 n [P_{n-1}(cos a^) - P_n(cos a^)],
// a sum of n terms bounded by 1, accurate in double precision for any even n. Its
// evaluators are generated per n (generated/roughness_n<N>.hpp, every even n <= 64, 128
// and 256 built in); others are generated with `wavecontact-derive --n N` or the CMake
// function wavecontact_generate() and registered here. The seed's eq. 19/20 (Form::paper)
// is evaluated exactly for any n, through sum_j k_j z^j = cos(t) sin(2 n t)/(n sin t),
// cos^2(t) = z.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "wavecontact/angles.hpp"
#include "wavecontact/parameters.hpp"
#include "wavecontact/stability.hpp"

namespace wavecontact {

// The largest wavelength ratio accepted (wavecontact-derive's limit too).
inline constexpr int max_roughness_n = 4096;

struct RoughnessParams {
  double H2;  // height of the roughness harmonic [length], >= 0
  int n;      // wavelength ratio b1/b2, even, 2 <= n <= max_roughness_n
};

struct TwoScaleParams {
  WavinessParams waviness;
  RoughnessParams roughness;
};

// The generated evaluators of one n (generated/roughness_n<N>.hpp): the pressure at one
// point, the load, and the zone's Legendre coefficients P_0..P_{n-1}(Ca) (out[k] = P_k)
// from which the array path sums the same series over many points.
struct RoughnessEvaluator {
  int n;
  double (*pressure)(const double& E, const double& H2, const double& b1, const double& Ca, const double& Sa,
                     const double& Cx, const double& Sx, const double& D);
  double (*load)(const double& E, const double& H2, const double& Ca, const double& Sa);
  void (*legendre)(const double& Ca, double* out);
};

// Adds (or replaces) the evaluators for evaluator.n, e.g. those generated for a new n.
void register_roughness_evaluator(const RoughnessEvaluator& evaluator);

// The evaluators for n; throws std::domain_error naming the commands that generate them
// if n is neither built in nor registered.
RoughnessEvaluator roughness_evaluator(int n);

// Every n with evaluators, in increasing order.
std::vector<int> available_roughness_n();

// The k_j of eq. 18, j = 1..n, exactly: k_j = (-1)^(n-j) C(n-1+j, n-j) 2^(2j-1)/n, printed
// as integers (or p/q). Any even n, 2 <= n <= max_roughness_n.
std::vector<std::string> expansion_coefficients(int n);

// One contact zone of half-width a: 0 < a < b1 for the exact form, 0 < a <= b1/2 for the
// printed one (eq. 19/20 is stated for that range). Construction costs O(n^2) for the
// admissibility scan; each pressure costs O(n). The array overloads take the points x
// (any period) and write p (p.size() == x.size()) without allocating; for the exact form
// with a <= b1/2 on a CPU with AVX2 and FMA they sum the series with the zone's Legendre
// coefficients, computed once, across blocks of points (vectorised).
class TwoScaleContact {
 public:
  TwoScaleContact(const TwoScaleParams& params, double a, Form form = Form::exact);

  double waviness_pressure(double x) const;
  double roughness_pressure(double x) const;
  // p_waviness + p_roughness; throws std::domain_error if the zone is not admissible.
  double pressure(double x) const;

  void roughness_pressure(const Eigen::Ref<const Eigen::ArrayXd>& x, Eigen::Ref<Eigen::ArrayXd> p) const;
  // Throws std::domain_error if the zone is not admissible.
  void pressure(const Eigen::Ref<const Eigen::ArrayXd>& x, Eigen::Ref<Eigen::ArrayXd> p) const;

  double waviness_load() const { return waviness_load_; }
  double roughness_load() const { return roughness_load_; }
  double load() const { return waviness_load_ + roughness_load_; }

  // The single-zone solution is the contact only if p >= 0 in the whole zone (checked on
  // 16 n + 64 evenly spaced points and 10 points approaching the edge) and, for the exact
  // form, the gap is >= 0 everywhere off it (wavecontact::single_zone_check(): a neighbouring
  // asperity or the valley must not penetrate). Otherwise the contact has more zones:
  // wavecontact::solve_contact().
  bool admissible() const { return admissible_; }
  double most_negative_x() const { return most_negative_x_; }
  double most_negative_pressure() const { return most_negative_pressure_; }
  // The lowest gap off the zone [length] (< 0: penetration; 0 if not checked) and where.
  double lowest_gap() const { return lowest_gap_; }
  double x_of_lowest_gap() const { return x_of_lowest_gap_; }

  double half_width() const { return a_; }

 private:
  // p += p_roughness at every point (arguments already checked).
  void add_roughness_pressure(const Eigen::Ref<const Eigen::ArrayXd>& x, Eigen::Ref<Eigen::ArrayXd> p) const;
  void require_admissible(const char* function) const;

  TwoScaleParams params_;
  double a_;
  Form form_;
  ZoneAngles zone_;
  RoughnessEvaluator evaluator_{};
  std::vector<double> legendre_;  // P_k(Ca), k < n (exact form)
  double waviness_load_ = 0, roughness_load_ = 0;
  bool admissible_ = true;
  double most_negative_x_ = 0, most_negative_pressure_ = 0;
  double lowest_gap_ = 0, x_of_lowest_gap_ = 0;
};

// Eq. 15: the roughness harmonic in full contact at its onset,
// p_rf(x) = p*_r (cos(n pi x/b1) + 1), p*_r = pi E* H2 n/(2 b1).
double roughness_full_contact_pressure(const TwoScaleParams& params, double x);

// Every half-width a in (0, b1) at which the two-scale load (exact form) equals P, in
// increasing order (the load need not be monotone when H2 n is large, nor beyond b1/2),
// each with its stability (the load rises through P) and admissibility. Found by
// bracketing on 16 n + 128 intervals and TOMS 748 in each.
std::vector<Equilibrium> two_scale_half_widths(const TwoScaleParams& params, double P);

void validate(const RoughnessParams& params, const char* function);

}  // namespace wavecontact
