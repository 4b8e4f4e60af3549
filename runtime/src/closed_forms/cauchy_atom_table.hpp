// The atoms of the Cauchy part of the pressure beyond a change of branch (J_{j,l}(y, z),
// J'_{j,l}(y, z): runtime/include/wavecontact/detail/quadratic_moment.hpp), tabulated over the points of
// one zone. Each is analytic in y off the cut (-inf, -1] (the integrand's 1/(1 + y w^2) for w in
// [0, 1]), so in eta = log(1 + y) within the strip |Im eta| < pi, and Chebyshev interpolation on
// a panel of unit width converges like rho^-n, rho = 2 pi + sqrt(4 pi^2 + 1) = 12.6 (Bernstein's
// ellipse up to the strip): 16 nodes leave about 2e-18 of the atoms' size. A panel costs its 16
// nodes' direct evaluations once; a point in it then costs one sum of 16 terms an atom.
#pragma once

#include <atomic>
#include <functional>
#include <memory>
#include <mutex>
#include <vector>

namespace wavecontact::detail {

// The most atoms of one part of the pressure beyond a change of branch (the emitted
// <part>_atoms_outputs).
inline constexpr int max_branch_atoms = 32;

// The panels [k, k + 1] of eta, first_panel <= k < first_panel + panel_count, each built at most
// once and then only read: any number of threads may evaluate and build at once.
class CauchyAtomTable {
 public:
  using Atoms = std::function<void(double y, double one_plus_y, double* atoms)>;
  static constexpr int nodes = 16;  // even
  // 1 + y from e^-128 to e^64: beyond it the atoms are computed directly.
  static constexpr long first_panel = -128, panel_count = 192;

  // The table of `count` <= max_branch_atoms atoms, atoms(expm1(eta), exp(eta), out); no panel
  // is built yet.
  CauchyAtomTable(Atoms atoms, int count);

  // Builds the panels into which at least `nodes` of these eta fall (where a panel's cost is at
  // most the direct evaluations it replaces).
  void tabulate(const std::vector<double>& etas) const;
  // The atoms at eta into out from its panel, which is built first if `build`; false where no
  // panel serves eta (not built, out of range, or its nodes leave the atoms' domain).
  bool evaluate(double eta, double* out, bool build) const;

 private:
  struct Panel {
    std::once_flag once;
    std::atomic<bool> built{false};
    std::vector<double> coefficients;  // node by node, the atoms interleaved; empty: none
  };
  // The panel of eta, or null out of range.
  Panel* panel_of(double eta) const;
  void build(Panel& panel, long k) const;

  Atoms atoms_;
  int count_;
  std::unique_ptr<Panel[]> panels_;
};

}  // namespace wavecontact::detail
