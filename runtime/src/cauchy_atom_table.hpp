// The atoms of the Cauchy part of the pressure beyond a change of branch (J_{j,l}(y, z),
// J'_{j,l}(y, z): runtime/include/wavecontact/quadratic_moment.hpp), tabulated over the points of
// one zone. Each is analytic in y off the cut (-inf, -1] (the integrand's 1/(1 + y w^2) for w in
// [0, 1]), so in eta = log(1 + y) within the strip |Im eta| < pi, and Chebyshev interpolation on
// a panel of unit width converges like rho^-n, rho = 2 pi + sqrt(4 pi^2 + 1) = 12.6 (Bernstein's
// ellipse up to the strip): 16 nodes leave about 2e-18 of the atoms' size. A panel [k, k + 1] is
// built from the atoms at its nodes where at least as many points as nodes fall into it, so that
// a table never costs more than the direct evaluation it replaces.
#pragma once

#include <functional>
#include <map>
#include <vector>

namespace wavecontact::detail {

class CauchyAtomTable {
 public:
  using Atoms = std::function<void(double y, double one_plus_y, double* atoms)>;
  static constexpr int nodes = 16;

  CauchyAtomTable() = default;
  // The panels that the points' eta = log(1 + y) ask for, from atoms(expm1(eta), exp(eta), out)
  // of `count` atoms at their nodes.
  CauchyAtomTable(const Atoms& atoms, int count, const std::vector<double>& etas);

  // The atoms at eta into out, if a panel holds eta.
  bool evaluate(double eta, double* out) const;

 private:
  int count_ = 0;
  std::map<long, std::vector<double>> panels_;  // panel k: the Chebyshev coefficients, atom by atom
};

}  // namespace wavecontact::detail
