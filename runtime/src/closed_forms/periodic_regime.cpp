#include "closed_forms/periodic_regime.hpp"

#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "support/parallel.hpp"
#include "kernels/pressure_simd.hpp"
#include "wavecontact/generated/waviness_evaluators.hpp"

namespace wavecontact::detail {

namespace {

// The emitted forms of one side of the kink, the parts in the order of BranchPart.
using PartAtoms = void (*)(const double&, const double&, const double&, const double&, const double&, const double&,
                           const double&, const double&, double*);
using Part = double (*)(const double&, const double&, const double&, const double&, const double&, const double&,
                        const double&, const double&, const double&, const double*);
using ZoneForm = double (*)(const double&, const double&, const double&, const double&, const double&, const double&);
struct SideForms {
  PartAtoms atoms[7];
  int atom_counts[7];
  Part parts[7];
  void (*cauchy_argument)(const double&, const double&, const double&, const double&, const double&, const double&,
                          const double&, const double&, const double&, double*);
  ZoneForm own_argument, other_argument;
};

#define WAVECONTACT_PART(side, part) generated::waviness_pressure_beyond_half_##side##_##part
#define WAVECONTACT_PARTS(side, suffix, after)                                                               \
  WAVECONTACT_PART(side, own##suffix)                                                                        \
  after, WAVECONTACT_PART(side, own_edge##suffix) after, WAVECONTACT_PART(side, other_cauchy##suffix) after, \
      WAVECONTACT_PART(side, other_cauchy_edge##suffix) after, WAVECONTACT_PART(side, other##suffix) after,  \
      WAVECONTACT_PART(side, other_edge##suffix) after, WAVECONTACT_PART(side, jump##suffix) after
#define WAVECONTACT_SIDE(side)                                                                       \
  SideForms {                                                                                        \
    {WAVECONTACT_PARTS(side, _atoms, <double>)}, {WAVECONTACT_PARTS(side, _atoms_outputs, )},        \
        {WAVECONTACT_PARTS(side, , <double>)}, WAVECONTACT_PART(side, cauchy_argument)<double>,      \
        WAVECONTACT_PART(side, own_argument)<double>, WAVECONTACT_PART(side, other_argument)<double> \
  }
constexpr SideForms top_forms = WAVECONTACT_SIDE(top), flank_forms = WAVECONTACT_SIDE(flank);
#undef WAVECONTACT_SIDE
#undef WAVECONTACT_PARTS
#undef WAVECONTACT_PART

BranchSide side_of_zone(const WavinessParams& p, const ZoneAngles& zone, bool top) {
  const SideForms& forms = top ? top_forms : flank_forms;
  BranchSideForms bound;
  for (int k = 0; k < 7; ++k) bound.atom_counts[k] = forms.atom_counts[k];
  bound.cauchy_argument = [p, zone, &forms](const PointAngles& point, double* y) {
    forms.cauchy_argument(p.E, p.H1, p.b1, p.m, zone.Ca, zone.Sa, point.Cx, point.Sx, point.D, y);
  };
  bound.atoms = [p, zone, &forms](BranchPart part, double y, double one_plus_y, double* atoms) {
    forms.atoms[static_cast<int>(part)](p.E, p.H1, p.b1, p.m, zone.Ca, zone.Sa, y, one_plus_y, atoms);
  };
  bound.part = [p, zone, &forms](BranchPart part, const PointAngles& point, const double* atoms) {
    return forms.parts[static_cast<int>(part)](p.E, p.H1, p.b1, p.m, zone.Ca, zone.Sa, point.Cx, point.Sx, point.D,
                                               atoms);
  };
  return BranchSide(std::move(bound), forms.own_argument(p.E, p.H1, p.b1, p.m, zone.Ca, zone.Sa),
                    forms.other_argument(p.E, p.H1, p.b1, p.m, zone.Ca, zone.Sa));
}

// g_other/g_own = ((1 + m|Cx|)/(1 - m|Cx|))^2 (the other branch's pole at |Cx| = 1/m).
double other_over_own(double m, double Cx) {
  const double mc = m * std::fabs(Cx);
  return (1 + mc) * (1 + mc) / ((1 - mc) * (1 - mc));
}

}  // namespace

BeyondHalfZone::BeyondHalfZone(const WavinessParams& params, double a, const ZoneAngles& zone, bool on_touch)
    : m_(params.m),
      a_(a),
      b1_(params.b1),
      on_touch_(on_touch),
      top_(side_of_zone(params, zone, true)),
      flank_(side_of_zone(params, zone, false)),
      top_table_(top_.cauchy_table()),
      flank_table_(flank_.cauchy_table()) {}

double BeyondHalfZone::pressure(const PointAngles& point, double eta) const {
  return side(point).pressure(point, other_over_own(m_, point.Cx), point.Cx == 0, eta, &table(point), on_touch_);
}

void BeyondHalfZone::pressures(const double* x, double* p, std::size_t count, std::size_t min_points) const {
  // The angles once per point (the point's side by the sign of Cx), then (unless built on touch)
  // the tables' panels from the points that take the Cauchy part, then the pressure.
  std::vector<PointAngles> points(count);
  std::vector<double> etas(count, std::numeric_limits<double>::quiet_NaN());
  std::vector<unsigned char> inside(count, 0);
  for_each_chunk(count, simd_block, min_points, [&](std::size_t begin, std::size_t end) {
    simd_point_angles(b1_, a_, x + begin, end - begin, &points[begin], &inside[begin]);
    for (std::size_t i = begin; i < end; ++i) {
      if (inside[i]) etas[i] = side(points[i]).cauchy_eta(points[i], other_over_own(m_, points[i].Cx));
    }
  });
  if (!on_touch_) {
    std::vector<double> top_etas, flank_etas;
    for (std::size_t i = 0; i < count; ++i) {
      if (std::isfinite(etas[i])) (points[i].Cx >= 0 ? top_etas : flank_etas).push_back(etas[i]);
    }
    top_table_.tabulate(top_etas);
    flank_table_.tabulate(flank_etas);
  }
  for_each_chunk(count, simd_block, min_points, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) p[i] = inside[i] ? pressure(points[i], etas[i]) : 0.0;
  });
}

double BeyondHalfZone::pressure(double x) const {
  PointAngles point;
  unsigned char inside = 0;
  simd_point_angles(b1_, a_, &x, 1, &point, &inside);
  return inside ? pressure(point, std::numeric_limits<double>::quiet_NaN()) : 0.0;
}

double pressure_beyond_half(const WavinessParams& p, const ZoneAngles& zone, const PointAngles& point) {
  return side_of_zone(p, zone, point.Cx >= 0).pressure(point, other_over_own(p.m, point.Cx), point.Cx == 0);
}

}  // namespace wavecontact::detail
