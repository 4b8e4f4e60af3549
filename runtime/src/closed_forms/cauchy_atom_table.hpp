// The atoms of the Cauchy part of the pressure beyond a change of branch (J_{j,l}(y, z),
// J'_{j,l}(y, z): runtime/include/wavecontact/detail/quadratic_moment.hpp), tabulated over the points of
// one zone. Each is analytic in y off the cut (-inf, -1] (the integrand's 1/(1 + y w^2) for w in
// [0, 1]), so in eta = log(1 + y) within the strip |Im eta| < pi, and Chebyshev interpolation on
// a panel of unit width converges like rho^-n, rho = 2 pi + sqrt(4 pi^2 + 1) = 12.6 (Bernstein's
// ellipse up to the strip): 16 nodes leave about 2e-18 of the atoms' size. A panel [k, k + 1] is
// built from the atoms at its nodes where at least as many points as nodes fall into it, so that
// a table never costs more than the direct evaluation it replaces.
#pragma once

#include <functional>
#include <vector>

namespace wavecontact::detail {

// The most atoms of one part of the pressure beyond a change of branch (the emitted
// <part>_atoms_outputs).
inline constexpr int max_branch_atoms = 32;

class CauchyAtomTable {
 public:
  using Atoms = std::function<void(double y, double one_plus_y, double* atoms)>;
  static constexpr int nodes = 16;  // even

  CauchyAtomTable() = default;
  // The panels that the points' eta = log(1 + y) ask for, from atoms(expm1(eta), exp(eta), out)
  // of `count` <= max_branch_atoms atoms at their nodes.
  CauchyAtomTable(const Atoms& atoms, int count, const std::vector<double>& etas);

  bool empty() const { return panels_.empty(); }
  // The atoms at eta into out, if a panel holds eta.
  bool evaluate(double eta, double* out) const;

 private:
  int count_ = 0;
  long first_ = 0;                           // the panel [first_ + i, first_ + i + 1] at i: its Chebyshev coefficients,
  std::vector<std::vector<double>> panels_;  // node by node, the atoms interleaved (empty: none)
};

}  // namespace wavecontact::detail
