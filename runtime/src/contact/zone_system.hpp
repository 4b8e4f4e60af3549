// The equations of a contact configuration (docs/contact.md): zones of the half period, each
// with its density's coefficients, and one constant C (the rigid approach). On every zone
// the logarithmic potential of all zones equals (E*/2) (y - y_top) + C at the zone's
// Chebyshev nodes (heights from the top, so that C does not cancel a height at small loads);
// q is bounded at every free end; the zones carry the load P (or, for a given single zone,
// its end conditions alone fix it). Newton's method on ends, coefficients and C together,
// its linear systems by GMRES with a preconditioner that solves each zone exactly with the
// others frozen and couples the zones through their loads (a dense system of one unknown a
// zone): the far fields are smooth and, beyond the loads', small.
#pragma once

#include <functional>
#include <optional>
#include <vector>

#include "configuration.hpp"
#include "field_tree.hpp"
#include "kink_correction.hpp"
#include "surface_model.hpp"
#include "zone.hpp"

namespace wavecontact::detail {

// Where each zone's unknowns and rows are in the packed vectors of Newton's method, and their
// scales. A free end's unknown is its place in s, where the equations are posed (the profile,
// even in x^, is a smooth function of s = cos x^: a zone through the top or the valley widens
// linearly with the load in s, like its root in x^), held as 1 - s for an end in the upper
// half (x^ <= pi/2) and 1 + s in the lower, in units of the zone's half-width h in s. A
// zone's coefficients are held as h d_j (pi h d_0 is its load: as a zone shrinks, d grows
// like 1/h, h d stays), the rows as potentials, both in units of the zone's own potential's
// magnitude h sum |d_j|, or of its rows' rounding where that is larger (row_scale, layout()).
// A zone's block holds its free ends then its coefficients (unknowns), its collocation rows
// then its end conditions (rows); C and the load row last.
struct SystemLayout {
  struct Zone {
    std::size_t at = 0;  // first unknown (= first row) of the zone's block
    int free_ends = 0, count = 0;
    double end_scale = 1, row_scale = 1;
    bool a_free = false, b_free = false;    // the ends that are unknowns (else fixed at a, b)
    bool a_upper = false, b_upper = false;  // in the upper half: held as 1 - s (else 1 + s)
    double a = 0, b = 0;
    double kink_window = 0;  // carried through (ZoneUnknowns)
    int block() const { return free_ends + count; }
  };
  std::vector<Zone> zones;
  std::vector<double> narrow_gaps;  // carried through (Configuration)
  std::size_t C_at = 0, size = 0;
  double C_scale = 1;
};

// The field of a configuration's zones: their smooth densities by the tree code, and the
// kink correction of each zone a kink lies in (null for the others).
struct ZoneFields {
  // Of c, which must outlive the fields (the tree refers to its zones).
  ZoneFields(const SurfaceModel& surface, const Configuration& c);
  const std::vector<ZoneUnknowns>& zones;
  std::vector<std::shared_ptr<const KinkCorrection>> kinks;
  std::vector<std::size_t> kinked;  // the zones that have one
  FieldTree tree;
  // The potential of every zone but `skip` (past the last: none) at a batch of nearby
  // points, as FieldTree::evaluate gives it (the kink corrections' slopes left out).
  FieldTree::Batch evaluate(std::size_t skip, const std::vector<double>& x, double x_ref, bool slopes,
                            const double* offsets = nullptr) const;
  // The same of every zone but k at zone k's nodes x (node_angles, the reference x[M/2]).
  // The others' field is analytic on the zone up to the nearest other zone: where its
  // Chebyshev series needs at most a quarter of the zone's M terms (smooth_field_terms), it
  // is evaluated at the nodes of that many and its series summed at x, the slopes from the
  // series' derivative (the other zones' kink corrections' with them). A zone across a kink
  // holds up to 32768 nodes; on the wave curve m = 10 the other zone's field there takes 128.
  FieldTree::Batch at_nodes(std::size_t k, const std::vector<double>& x, bool slopes) const;
  // The potential at one point.
  double potential(double x, std::size_t skip) const;
};

// The angles of the zone's Chebyshev nodes (chebyshev::nodes(count)).
std::vector<double> node_angles(const ZoneGeometry& g, int count);
// The nodes' places in s, m + h tau_i, less cos x_ref, each to its own precision (whatever
// the rounding of the nodes' angles).
std::vector<double> node_offsets(const ZoneGeometry& g, int count, double x_ref);

// The Chebyshev terms, in zone k's tau, that the other zones' field needs on zone k: twice
// those to 1e-17, a power of two from 32 (ZoneFields::at_nodes); 0 for no other zone.
int smooth_field_terms(const std::vector<ZoneUnknowns>& zones, std::size_t k);

// The heights y - y(x_ref) at a zone's Chebyshev nodes x (angles; the reference x_ref =
// x[M/2]) as the transform takes them: at the exact nodes, whose doubles the nodes are. At
// the nodes as placed in s (node_offsets), plus each node's rounding (chebyshev::node_roundings)
// times h and the slope dy/ds there: one node's error spreads over every coefficient, and
// next to the top the slope of roughness n is up to H n^2.
std::vector<double> node_heights(const SurfaceModel& surface, const ZoneGeometry& g, const std::vector<double>& x);

// The Chebyshev coefficients G_j of a zone's right-hand side at its nodes x (angles):
// (E/2)(y - y_top) less the other zones' potential `others` (a batch at x with the reference
// x[M/2]; empty: none) and the zone's own kink correction's. Formed as differences from the
// reference node, each without cancellation (the zone's equations keep their digits where
// the sums are large and their variation small), the constant part in G_0; C not included.
std::vector<double> right_hand_side(const SurfaceModel& surface, const ZoneGeometry& g, const std::vector<double>& x,
                                    const FieldTree::Batch& others, const KinkCorrection* kink);

// An end's distance from the top, 1 - s = 2 sin^2(x/2) (upper: x^ <= pi/2), or from the
// valley, 1 + s = 2 cos^2(x/2), without cancellation: what SystemLayout holds as its unknown.
double end_distance(double x, bool upper);

// A zone's own potential's magnitude, h sum |d_j| (its rows' natural unit).
double own_potential(const ZoneUnknowns& z);

// The rounding of each zone's T_0 row, as a potential: 8 eps of the sum it is formed from,
// |C| + (E/2)|y - y_top| + sum_l |Psi_l|, with |Psi_l| at most own_potential (|log h_l| + 2).
// Where it exceeds a small zone's own potential times 1e-9, the zone's coefficients are
// rounding at that level: no more nodes make them converge further.
std::vector<double> row_rounding(const SurfaceModel& surface, const Configuration& c);

// The load of zone k over its part of [0, pi]: pi h d_0, plus its kink correction's.
double zone_load(const Configuration& c, const ZoneFields& fields, std::size_t k);

// Called at safe points with Newton's scaled residual there (NaN outside Newton's method):
// the work budget's checks, which may throw to abandon the solve.
using Checkpoint = std::function<void(double residual)>;

class ZoneSystem {
 public:
  // The zones carry the load P over the period.
  ZoneSystem(const SurfaceModel& surface, double P) : surface_(surface), P_(P) {}

  // The coefficients that solve each zone's equations with the others' field as it is, and
  // C with which they carry P (one block-Jacobi sweep): a start for new zones or node counts.
  void relax(Configuration& c) const;

  // Newton's method from `c` until the scaled residuals are below `tolerance`. Returns the
  // configuration reached and whether it converged; a step that would close a stretch
  // (a zone, a gap between zones, the stretch to the top or the valley) stops it with that
  // stretch named (outcome), for the continuation to change the zones.
  enum class Outcome { converged, stretch_closes, failed };
  struct Result {
    Outcome outcome = Outcome::failed;
    Configuration configuration;
    // For stretch_closes: the stretch between consecutive ends of [0, a_1, b_1, ..., pi].
    std::size_t stretch = 0;
    double residual = 0;  // the largest scaled residual reached
    int iterations = 0;
    // Where Newton's method stopped short of the tolerance, the configuration returned moved by
    // the Newton step computed there (its linear system solved to a hundredth at least):
    // how far it is from the solution (newton_corrected, without another linear solve).
    std::optional<Configuration> corrected;
  };
  // ends_fixed: the ends stay where c has them, their conditions dropped (the linear
  // system of the coefficients and C alone: a consistent start for given zones).
  // Each zone keeps the kink window it comes with where that fits it (its discretisation: the
  // refinement compares node counts of one), else the window is chosen for it (choose_windows).
  Result newton(Configuration c, double tolerance, const Checkpoint& checkpoint, bool ends_fixed = false) const;

  // Each kink correction's window chosen for the zones as they are.
  void choose_windows(Configuration& c) const;

  // Whether every zone's kink window lies within the zone and is at least a quarter of the
  // one chosen for it as it is now (ends move during a solve; a window that no longer fits,
  // or that the zone has far outgrown, is chosen again by the next).
  bool windows_fit(const Configuration& c) const;

  // The scaled residuals of c (for tests and for the solver's checks).
  std::vector<double> residuals(const Configuration& c) const;

  // The solution of the equations linearised at c (a solution) with each zone's T_0 row
  // shifted by shift[k] (a potential): how far a perturbation of the equations, such as their
  // rounding, moves the contact.
  Configuration perturbed(const Configuration& c, const std::vector<double>& shift) const;
  // c moved by one more Newton step, its linear system solved to a hundredth: how far c is
  // from the equations' solution (Newton's own error, which the refinement's change between
  // two node counts does not see where both solutions share it).
  Configuration newton_corrected(const Configuration& c) const;

 private:
  // A point of Newton's method: the configuration, its packed unknowns, its residuals and
  // the other zones' field's slope at each zone's nodes (for the preconditioner).
  struct Linearisation {
    Configuration c;
    SystemLayout layout;
    std::vector<double> X, F;
    std::vector<std::vector<double>> external_slope;
    double step = 1;        // the fraction of Newton's step that reached it
    bool descended = true;  // whether the residual's 2-norm fell on the way
  };
  Linearisation linearise(Configuration c, bool ends_fixed) const;
  // Newton's step s = -J^-1 F at `at`, by linear_solve to the relative tolerance `forcing`.
  std::vector<double> newton_step(const Linearisation& at, double forcing, double difference_step) const;
  // The point lambda s from `at` along Newton's step s, lambda halved up to 8 times while the
  // residual's 2-norm does not fall (not at all at the rounding floor).
  Linearisation backtrack(const Linearisation& at, const std::vector<double>& step, double lambda,
                          bool at_rounding) const;
  // The point with the ends of Newton's step s from `at` and the coefficients and C that solve
  // the other equations there: Newton's step for the ends alone, the coefficients eliminated
  // (the step of the Schur complement, with the coefficients solved for anew).
  Linearisation eliminated(const Linearisation& at, const std::vector<double>& step, double forcing,
                           double difference_step) const;
  // J s = rhs at `at`, to the relative tolerance, by preconditioned GMRES; J's products are
  // forward differences whose step is difference_step of the product vector's largest entry.
  std::vector<double> linear_solve(const Linearisation& at, const std::vector<double>& rhs, double tolerance,
                                   double difference_step) const;

  // `window` if it fits the zone, else the largest that does (KinkCorrection::radius_for).
  double fitting_window(const ZoneGeometry& zone, double window) const;
  SystemLayout layout(const Configuration& c, bool ends_fixed) const;  // fixed for one Newton solve
  std::vector<double> pack(const Configuration& c, const SystemLayout& L) const;
  Configuration unpack(const std::vector<double>& X, const SystemLayout& L) const;
  std::vector<double> residual(const Configuration& c, const SystemLayout& L,
                               std::vector<std::vector<double>>* external_slope) const;

  const SurfaceModel& surface_;
  double P_;
};

}  // namespace wavecontact::detail
