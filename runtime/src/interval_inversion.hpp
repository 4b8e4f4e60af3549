// The bounded inversion of the finite Hilbert transform on several intervals (Muskhelishvili,
// Singular Integral Equations, several arcs), for the symmetric periodic contact.
//
// For an even profile y(x^) = Y(cos x^) and an even pressure, the cot-kernel of the periodic
// problem folds (cot A + cot B = 2 sin x^/(cos xi - cos x^)) into a Cauchy kernel in
// s = cos x^: with q(s) = p(s)/sqrt(1 - s^2),
//   (1/pi) PV Int_L q(t)/(t - s) dt = f(s) := (E*/2) dY/ds,   s in L,
//   P = 2 Int_L q ds,   d gap/ds = (2/E*)(Hq(s) - f(s)) off L,
// where L in [-1, 1] is the contact set (a union of intervals) and Hq the left side off L.
// Ends inside (-1, 1) are zone ends: q is bounded there (~ sqrt). s = 1 (x^ = 0, the top)
// and s = -1 (x^ = pi, the valley) may belong to L: q ~ 1/sqrt there, p finite.
//
// With X(z) = prod (z - e)^(tau_e/2) (tau = +1 at a bounded end, -1 at s = +-1) and
// kappa = (#bounded - #unbounded)/2 = (number of intervals) - (number of s = +-1 ends):
//   q(s)  = -rho_k R(s) S(s)          on interval k,
//   Hq - f = rho_out(s) R(s) S(s)      off L,
//   S(s)  = (1/pi) sum_j rho_j Int_{I_j} (f(t) - f(s))/(R(t) (t - s)) dt - f(s) Pi(s),
// R = |X|, rho = +-1 the phases of X, Pi the polynomial part of 1/X at infinity (1 for
// kappa = 0, s for full contact, 0 for kappa >= 1). The solution exists, bounded at every
// zone end, iff M_j = sum_k rho_k Int_{I_k} t^j f/R dt = 0 for j < kappa; then
// Int_L q ds = M_kappa. With the gap closed at both ends of every gap between zones (one
// rigid approach for all zones), these are the equations of the zone ends.
//
// Every integral is a Gauss-Legendre sum on panels in w, t = e +- w^2 from the nearer end e,
// which removes the end singularities; panels are graded towards nearby singular points
// (other ends, the profile's poles) and split at the profile's kinks, so the sums converge
// geometrically in the panel order. Differences of points are formed from the angles
// (cos A - cos B = 2 sin((A+B)/2) sin((B-A)/2)) and offsets from ends, without cancellation.
#pragma once

#include <complex>
#include <functional>
#include <map>
#include <memory>
#include <vector>

#include "chebyshev_panel.hpp"

namespace wavecontact::detail {

// The surface as the solver sees it.
struct SurfaceSlope {
  std::function<double(double)> height;  // Y(s), s = cos x^
  std::function<double(double)> slope;   // dY/ds
  std::vector<double> kinks;             // s in (-1, 1) where dY/ds is not analytic
  // The singular points of the analytic continuation of dY/ds from [lo, hi] (a piece between
  // kinks), which the panels must keep their distance from.
  std::function<std::vector<std::complex<double>>(double lo, double hi)> singularities;
  double resolution;  // the largest extent of a panel in x^ (radians): ~ pi/(highest harmonic)
  double E;           // reduced modulus E*
};

// A zone of the half period, 0 <= lo < hi <= pi in x^; lo = 0: through the top (the zone is
// [-hi, hi]), hi = pi: through the valley.
struct Zone {
  double lo, hi;
};

// One contact configuration (the zones of [0, pi], sorted, disjoint) with its quadrature.
class IntervalInversion {
 public:
  // How far panels are graded towards a kink (in s): the conditions on the ends integrate
  // S, for which 1e-9 is enough; the evaluators interpolate it, s log|s| included, down to
  // 1e-14 (and S must be accurate that close to the kink).
  enum class Grading { quadrature, evaluation };

  // The panels of every piece of every region as fractions of the piece (in w), by region and
  // piece: recorded by one configuration and replayed by others with the same zones (the
  // iterates of Newton's method), so that the discrete conditions are smooth in the ends.
  using Layout = std::map<std::pair<int, int>, std::vector<double>>;

  // order: Gauss-Legendre points per panel; layout: to replay and complete (a new one if null).
  IntervalInversion(const SurfaceSlope& surface, std::vector<Zone> zones, int order,
                    Grading grading = Grading::quadrature, std::shared_ptr<Layout> layout = nullptr);

  const std::shared_ptr<Layout>& layout() const { return layout_; }

  const std::vector<Zone>& zones() const { return zones_; }
  bool full_contact() const { return kappa_ < 0; }

  // The unknown zone ends (those strictly inside (0, pi)), in the order of zones(): as many
  // as residuals() returns.
  std::vector<double> free_ends() const;
  static std::vector<Zone> with_free_ends(std::vector<Zone> zones, const std::vector<double>& ends);

  // The conditions on the ends for the load P, each relative to the magnitude of its terms:
  // boundedness (kappa of them), the load, the closure of every gap between zones.
  std::vector<double> residuals(double P) const;

  // Int_L q ds = M_kappa (at the solution: P/2). Not for full contact.
  double half_load() const;

  // Builds the tables of the evaluators below (S on the zones, the gap off them): call once
  // the ends solve the equations for the load P, with Grading::evaluation.
  void prepare(double P);

  // In full contact the pressure is P/(2 pi) + p0: the same solution at another load.
  void shift_full_contact_load(double P);

  // The normalised pressure p^(x^), |x^| <= pi, 0 off the zones.
  double pressure(double x) const;
  // The gap (y(0) - y(x^)) - (u(0) - u(x^)) up to the constant that makes it 0 on the zones.
  double gap(double x) const;
  // Int of p^ over zone k of [0, pi] (x^ >= 0 only; the mirror image carries as much).
  double zone_load(std::size_t k) const;
  // eps times the sum of the magnitudes of the terms of the pressure at x^ over its value:
  // the rounding error of p relative to p.
  double rounding_amplification(double x) const;

  // The rounding error of the pressure relative to its largest value, at the pressure
  // samples (prepare()): where many zones cluster, the product R of the several-interval
  // formula spans many orders of magnitude and S is a sum of terms far larger than itself.
  double rounding() const { return rounding_; }

  struct Sample {
    double x, value;
  };
  // The pressure on the zones and the gap off them, at the Chebyshev points of every panel.
  const std::vector<Sample>& pressure_samples() const { return pressure_samples_; }
  const std::vector<Sample>& gap_samples() const { return gap_samples_; }

 private:
  // A reference point: a zone end (tau = +1 bounded, -1 at s = +-1: the top or the valley in
  // contact) or a kink of the profile (tau = 0). Points are held as offsets from one.
  struct Reference {
    double angle, s;
    int tau;
  };
  struct Node {
    double offset, f, weight;  // t = s[ref] + offset
    double from_center;        // t - center_
    int ref;
  };
  // The nodes of S grouped by reference, as arrays (the sum over them vectorises).
  struct NodeBlock {
    int ref;
    std::vector<double> offset, f, weight;
  };
  // An evaluation point: s, held as an offset from a reference (ref >= 0), or with its
  // offsets from every reference (ref < 0, a point given by its angle).
  struct Point {
    double s;
    int ref;
    double offset;
    std::vector<double> to_ref;
  };
  struct Region {  // [lo, hi] in s; lo_end/hi_end: end indices, -1 at s = -1 / 1 off L
    double lo, hi;
    int lo_end, hi_end;
    int id;  // the interval's index, or 1000 + the index among the regions off L
  };
  // A panel: t = s[anchor] + dir w^2, wa <= w <= wb; panels of one anchor are listed outwards.
  // Next to a kink (kink >= 0, at w = wk) its points are held as offsets from the kink.
  struct Panel {
    int anchor;
    double dir, wa, wb;
    int kink = -1;
    double wk = 0;
  };
  struct PanelTable {  // the evaluators' data on one panel
    Panel panel;
    double start;            // gap at w = wa (gap tables)
    std::vector<double> B;   // Chebyshev coefficients of the gap's antiderivative in w
    ChebyshevPanel values;   // S (pressure tables)
  };

  double difference(int i, int j) const { return differences_[i * refs_.size() + j]; }  // s_i - s_j
  double to_ref(const Point& p, int r) const {  // s - s_r
    return p.ref < 0 ? p.to_ref[r] : r == p.ref ? p.offset : difference(p.ref, r) + p.offset;
  }
  Point point_at_angle(double x) const;
  Point point_at_offset(int ref, double offset) const;
  // The point of a panel at w = mid + half xi, from the kink where it is closer.
  Point panel_point(const Panel& panel, double xi) const;
  // xi of the point p in the panel (w(p) in [wa, wb]), or nothing.
  bool locate(const Panel& panel, const Point& p, double& xi) const;
  double product_R(const Point& p, int skip) const;  // prod |s - e|^(tau/2) over ends e != skip
  double S(const Point& p, double* terms = nullptr) const;
  // The pressure at p (angle x, on s-interval k) and the rounding amplification, from S there.
  double pressure_from_S(const Point& p, double x, int k, double S_at) const;
  double amplification_from_S(double S_at, double terms) const;
  double f(double s) const { return 0.5 * surface_.E * surface_.slope(s); }
  double Pi(double s) const { return kappa_ > 0 ? 0 : kappa_ == 0 ? 1 : s; }
  double phase_outside(double s) const;  // i^(sum of tau over the ends above s)
  std::vector<Panel> panels(const Region& r) const;
  // Gauss-Legendre nodes (order points per panel) on the panels of r: weight_power = -1
  // integrates F/R, +1 F R. Integrals of S over the zones take order_ + 1 points, which
  // interlace with (and so avoid) the nodes of S itself.
  void add_nodes(const Region& r, int weight_power, double sign, std::vector<Node>& out,
                 int order) const;
  void add_panel_nodes(const Panel& panel, int weight_power, double sign, std::vector<Node>& out,
                       int order) const;
  std::vector<Region> regions_off() const;
  Region interval(int k) const;
  // M_0 .. M_kappa (the last for the load) and the sums of the magnitudes of their terms.
  struct Moments {
    std::vector<double> sum, magnitude;
  };
  Moments moments() const;

  SurfaceSlope surface_;
  std::vector<Zone> zones_;
  int order_;
  double narrowest_;  // the narrowest panel next to a kink, in s
  std::shared_ptr<Layout> layout_;
  std::vector<Reference> refs_;       // the ends in increasing s, then the kinks
  std::vector<double> differences_;  // s_i - s_j of the references, row-major
  int ends_ = 0;                      // how many of refs_ are ends
  std::vector<int> rho_;         // per s-interval
  int kappa_ = 0;
  double center_ = 0, half_span_ = 1;  // of the ends, for the moment polynomials
  std::vector<Node> nodes_;            // F/R on the intervals, signed by rho
  std::vector<NodeBlock> blocks_;      // the same, by reference
  double full_contact_constant_ = 0;   // p = -S + C in full contact
  double load_ = 0;                    // the load of prepare()
  std::vector<PanelTable> zone_tables_, gap_tables_;
  std::vector<Sample> pressure_samples_, gap_samples_;
  double rounding_ = 0;
};

}  // namespace wavecontact::detail
