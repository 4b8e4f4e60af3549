// The preconditioner of one Newton step of the zone system (zone_system.hpp): each zone's
// block of the Jacobian with the other zones frozen, solved exactly, and the coupling of the
// zones' T_0 rows through their loads W_l = pi h_l d_l0 and C, solved exactly by Woodbury's
// identity (a dense system of one unknown a zone, and C). The far fields beyond the loads'
// are smooth and small: GMRES takes them. A zone alone, without a kink correction, has no
// far field: the preconditioner is then the Jacobian itself (ZoneSystem::linear_solve).
//
// A zone's block is an arrowhead: its coefficients meet their own collocation rows on the
// diagonal (log(2/h) for T_0, 1 for T_j: row j is scaled by j), the ends add a column each (the own potential's
// change with h, and the nodes' motion through the field, at the ends' present places), the
// end conditions a row each. It is solved through the Schur complement on the ends (at most
// 2 x 2): O(nodes) a zone.
#pragma once

#include <vector>

#include <Eigen/Dense>

#include "surface_model.hpp"
#include "zone_system.hpp"

namespace wavecontact::detail {

class ZonePreconditioner {
 public:
  // external_slope[k]: the others' field's slope at zone k's nodes (from the residual).
  ZonePreconditioner(const SurfaceModel& surface, const Configuration& c, const SystemLayout& L,
                     const std::vector<std::vector<double>>& external_slope, double P);

  std::vector<double> apply(const std::vector<double>& r) const;

 private:
  // At most two free ends a zone: their vectors and the Schur complement without the heap.
  using EndVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 2, 1>;
  using EndMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 2, 2>;
  // [E D; 0 S] [e; d] = [r_c; r_s], D diagonal: d = D^-1 (r_c - E e), (S D^-1 E) e = S D^-1 r_c - r_s.
  struct Block {
    std::size_t at = 0;
    int ends = 0, count = 0;
    std::vector<double> diagonal;  // D
    Eigen::MatrixXd E, S;          // count x ends, ends x count
    Eigen::FullPivLU<EndMatrix> schur;
    Eigen::VectorXd load_row;  // dW / d(unknowns), scaled, in the unknowns' order
    Eigen::VectorXd g;         // B^-1 e_0 / row_scale
    double delta = 0;          // load_row . g
    Eigen::VectorXd solve(const double* r) const;
  };
  std::vector<Block> blocks_;
  Eigen::MatrixXd coupling_;  // the T_0 potential on zone k of a unit load on zone l
  Eigen::PartialPivLU<Eigen::MatrixXd> coarse_;
  double C_scale_ = 1;
  std::size_t C_at_ = 0;
};

}  // namespace wavecontact::detail
