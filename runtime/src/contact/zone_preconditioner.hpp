// The preconditioner of one Newton step of the zone system (zone_system.hpp): each zone's
// block of the Jacobian with the other zones frozen, solved exactly, and the coupling of the
// zones' T_0 and T_1 rows through their loads W_l = pi h_l d_l0, their first moments and C,
// solved exactly by Woodbury's identity (a dense system of two unknowns a zone, and C; the
// loads alone beyond most_zones_with_first_moments). The far fields beyond these are smooth
// and small: GMRES takes them. On the bench map's lines at m = 0 (up to 12 zones) the first
// moments took GMRES's products from 53 900 to 43 700 (3.2 to 2.6 a linear solve), and
// |J M^-1 - I| from 15.5 to 2.6 on three zones at n = 32. A zone alone, without a kink
// correction, has no far field: the preconditioner is then the Jacobian itself
// (ZoneSystem::linear_solve).
//
// A zone's block is an arrowhead: its coefficients meet their own collocation rows on the
// diagonal (log(2/h) for T_0, 1 for T_j: row j is scaled by j), the ends add a column each (the own potential's
// change with h, and the nodes' motion through the field, at the ends' present places), the
// end conditions a row each. It is solved through the Schur complement on the ends (at most
// 2 x 2): O(nodes) a zone.
#pragma once

#include <array>
#include <vector>

#include <Eigen/Dense>

#include "constants.hpp"
#include "surface_model.hpp"
#include "zone_system.hpp"

namespace wavecontact::detail {

// The most zones in half a period whose coupling takes each zone's first moment besides its
// load. Beyond, the coupling's K^2 fields and the dense coarse system of 2K + 1 unknowns cost
// what the products they save do: 40 campaign sweeps of seed 1 with 120 to 600 zones took
// 50.5, 50.4, 51.1 and 51.2 s with the first moments up to 0, 128, 256 and 384 zones.
inline constexpr std::size_t most_zones_with_first_moments = 128;

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
    double row_scale = 1;
    std::vector<double> diagonal;  // D
    Eigen::MatrixXd E, S;          // count x ends, ends x count
    Eigen::FullPivLU<EndMatrix> schur;
    // g[b] = B^-1 e_b / row_scale, the response to the others' field in row T_b, and
    // delta(a, b) = moment a of g[b].
    std::array<Eigen::VectorXd, 2> g;
    Eigen::Matrix2d delta = Eigen::Matrix2d::Zero();
    // The first moment's change with h d_1 and with each free end (at fixed h d).
    double first_moment_of_d1 = 0;
    std::array<double, 2> first_moment_of_end{};
    Eigen::VectorXd solve(const double* r) const;
    // Moment a of a change y of the block's unknowns: the load W = pi h d_0 (a = 0), or the
    // first moment about the zone's centre, W (m - m0) + (pi/2) h^2 d_1 (a = 1), which its
    // ends move too.
    double moment(const Eigen::VectorXd& y, int a) const {
      if (a == 0) return pi * row_scale * y[ends];
      double first = first_moment_of_d1 * y[ends + 1];
      for (int e = 0; e < ends; ++e) first += first_moment_of_end[static_cast<std::size_t>(e)] * y[e];
      return first;
    }
  };
  std::vector<Block> blocks_;
  int moments_ = 1;  // a zone's moments in the coupling: its load, and its first moment
  // Row (k, b): the T_b coefficient over zone k of the potential of zone l's unit moment a,
  // in column (l, a) (moments_ rows and columns a zone).
  Eigen::MatrixXd coupling_;
  Eigen::PartialPivLU<Eigen::MatrixXd> coarse_;
  double C_scale_ = 1;
  std::size_t C_at_ = 0;
};

}  // namespace wavecontact::detail
