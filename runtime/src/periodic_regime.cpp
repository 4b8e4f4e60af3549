#include "periodic_regime.hpp"

#include <cmath>

#include "waviness.hpp"  // generated/

namespace wavecontact::detail {

namespace {

// The emitted parts of the pressure on one side of the kink, in the order of BranchPart.
using PointForm = double (*)(const double&, const double&, const double&, const double&, const double&, const double&,
                             const double&, const double&, const double&);
using ZoneForm = double (*)(const double&, const double&, const double&, const double&, const double&, const double&);
struct SideForms {
  PointForm parts[7];
  ZoneForm own_argument, other_argument;
};

#define WAVECONTACT_SIDE(side)                                                                              \
  SideForms {                                                                                               \
    {generated::waviness_pressure_beyond_half_##side##_own<double>,                                         \
     generated::waviness_pressure_beyond_half_##side##_own_edge<double>,                                    \
     generated::waviness_pressure_beyond_half_##side##_other_cauchy<double>,                                \
     generated::waviness_pressure_beyond_half_##side##_other_cauchy_edge<double>,                           \
     generated::waviness_pressure_beyond_half_##side##_other<double>,                                       \
     generated::waviness_pressure_beyond_half_##side##_other_edge<double>,                                  \
     generated::waviness_pressure_beyond_half_##side##_jump<double>},                                       \
        generated::waviness_pressure_beyond_half_##side##_own_argument<double>,                             \
        generated::waviness_pressure_beyond_half_##side##_other_argument<double>                            \
  }
constexpr SideForms top_forms = WAVECONTACT_SIDE(top), flank_forms = WAVECONTACT_SIDE(flank);
#undef WAVECONTACT_SIDE

}  // namespace

double pressure_beyond_half(const WavinessParams& p, const ZoneAngles& zone, const PointAngles& point) {
  const SideForms& forms = point.Cx >= 0 ? top_forms : flank_forms;
  const auto part = [&](BranchPart which) {
    return forms.parts[static_cast<int>(which)](p.E, p.H1, p.b1, p.m, zone.Ca, zone.Sa, point.Cx, point.Sx, point.D);
  };
  const auto argument = [&](ZoneForm f) { return f(p.E, p.H1, p.b1, p.m, zone.Ca, zone.Sa); };
  // g_other/g_own = ((1 + m|Cx|)/(1 - m|Cx|))^2 (the other branch's pole at |Cx| = 1/m).
  const double mc = p.m * std::fabs(point.Cx);
  return beyond_branch_pressure(part, argument(forms.own_argument), argument(forms.other_argument),
                                (1 + mc) * (1 + mc) / ((1 - mc) * (1 - mc)), point.Cx == 0);
}

}  // namespace wavecontact::detail
