#include "waviness.hpp"

#include "angle_form.hpp"
#include "block_keer.hpp"
#include "hilbert.hpp"
#include "symbols.hpp"

namespace wavecontact::derive {

using GiNaC::ex;
using GiNaC::pow;

ex parametric_wave_curve() {
  const ex m = sym::m(), c = GiNaC::cos(sym::x());
  return sym::H1() * (m + 1) * c / (m * c + 1);
}

ex printed_eq13_rational() {
  const ex m = sym::m(), s = sym::s(), alpha2 = pow(sym::alpha(), 2);
  return sym::E() * sym::H1() * pow(m + 1, 2) * (s + 1) * (alpha2 + 1) /
         (pow(m - m * s + s + 1, 2) * (m - m * alpha2 + alpha2 + 1));
}

GiNaC::exmap sample_point_beyond_half() {
  GiNaC::exmap point = sample_point_v();
  point[sym::alpha()] = GiNaC::numeric(3, 2);  // a^ ~ 1.97 > pi/2
  point.erase(sym::s());
  point.erase(sym::u());
  return point;
}

namespace {

// alpha^2 = (1 - Ca)/(1 + Ca) in a rational function of alpha^2: the argument of I_{j,l}.
ex in_zone_cosine(const ex& e) {
  const ex Ca = sym::Ca();
  return GiNaC::factor(e.subs(sym::alpha() == GiNaC::sqrt((1 - Ca) / (1 + Ca))).normal());
}

// A moment term in angle atoms: its factor c sqrt(r) by to_angle_atoms, its argument z in Ca.
MomentTerm moment_in_angles(const MomentTerm& term, const GiNaC::exmap& sample) {
  const RootTerm factor = to_angle_atoms({term.rational, term.radicand}, sample);
  if (term.l == 0) return {factor.rational, factor.radicand, 0, 0, 0, 0};
  return {factor.rational, factor.radicand, term.j, term.l, in_zone_cosine(term.z),
          in_zone_cosine(term.one_plus_z)};
}

// The two pieces of the zone, [0, 1] on the top branch and [1, alpha] on the flank:
//   c sqrt(1 + alpha^2) (M_[0,1][top] + M_[1,alpha][flank]), as moment terms of each piece.
struct PieceMoments {
  std::vector<MomentTerm> top, flank;
};

PieceMoments piece_moments(const ex& top, const ex& flank, const ex& c) {
  const auto scaled = [&c](std::vector<MomentTerm> terms) {
    for (MomentTerm& term : terms) {
      term.rational = (c * term.rational).normal();
      term.radicand = (term.radicand * (1 + GiNaC::pow(sym::alpha(), 2))).normal();
    }
    return terms;
  };
  return {scaled(inner_moment(top, 1)), scaled(outer_moment(flank, 1))};
}

std::vector<MomentTerm> both_pieces(const PieceMoments& pieces) {
  std::vector<MomentTerm> terms = pieces.top;
  terms.insert(terms.end(), pieces.flank.begin(), pieces.flank.end());
  return terms;
}

std::vector<MomentTerm> moments_in_angles(const std::vector<MomentTerm>& terms) {
  const GiNaC::exmap sample = sample_point_beyond_half();
  std::vector<MomentTerm> angle;
  for (const MomentTerm& term : terms) angle.push_back(moment_in_angles(term, sample));
  return angle;
}

// dF/dSa - dF/dCa of c sqrt(r) I_{j,l}(z): the factor's (closed_forms.hpp) times I, plus
// c sqrt(r) (-l I_{j+1,l+1}(z)) dz.
std::vector<MomentTerm> moment_slope_factor(const MomentTerm& term) {
  const RootTerm factor = slope_factor({term.rational, term.radicand});
  std::vector<MomentTerm> terms{{factor.rational, factor.radicand, term.j, term.l, term.z, term.one_plus_z}};
  if (term.l > 0) {
    const ex Dz = term.z.diff(sym::Sa()) - term.z.diff(sym::Ca());
    terms.push_back({(-term.l * term.rational * Dz).normal(), term.radicand, term.j + 1, term.l + 1,
                     term.z, term.one_plus_z});
  }
  return terms;
}

// The load by eq. 6 in the form of MATH.md fact 7 (load_integrand). Its slope two ways:
// - the derivative of the load's terms, whose terms grow like (-cos a^)^(-1/2) as the flank
//   piece shrinks (a -> b1/2+) and cancel;
// - by parts (load_slope_integrand), no end point differentiated, whose two pieces carry the
//   jump of g' at the kink, about m times the result, and cancel where the zone reaches well
//   beyond the kink (the top piece's argument z < 0).
void derive_beyond_half(WavinessDerivation& d) {
  const ex m = sym::m(), c = GiNaC::cos(sym::x());
  d.flank_g = hilbert_rhs(sym::H1() * (m + 1) * c / (1 - m * c));
  const PieceMoments load = piece_moments(load_integrand(d.g), load_integrand(d.flank_g), 2 * GiNaC::Pi);
  d.load_beyond_half_v = both_pieces(load);
  d.load_beyond_half_angle = moments_in_angles(d.load_beyond_half_v);
  PieceMoments near_half{{}, load.flank};
  for (const MomentTerm& term : load.top) {
    for (const MomentTerm& part : large_argument_form(term)) near_half.top.push_back(part);
  }
  d.load_near_half_angle = moments_in_angles(both_pieces(near_half));
  for (const MomentTerm& term : d.load_beyond_half_angle) {
    for (const MomentTerm& part : moment_slope_factor(term)) d.load_slope_factor_beyond_half.push_back(part);
  }
  d.load_slope_factor_by_parts_v =
      both_pieces(piece_moments(load_slope_integrand(d.g), load_slope_integrand(d.flank_g), GiNaC::Pi / 2));
  d.load_slope_factor_by_parts = moments_in_angles(d.load_slope_factor_by_parts_v);
  d.top_piece_argument = in_zone_cosine(load.top.front().z);
}

}  // namespace

WavinessDerivation derive_waviness() {
  WavinessDerivation d;
  static_cast<ClosedForms&>(d) = derive_closed_forms(parametric_wave_curve());

  // The printed eq. 13 carries 1/sqrt(alpha^2 + 1) = kappa(-1)/(alpha^2 + 1).
  const unsigned kappa_minus_one = d.radicals.index_of(-1);
  d.paper_inversion = RadicalSum::monomial(
      RadicalSum::Mask{1} << kappa_minus_one,
      (printed_eq13_rational() / (pow(sym::alpha(), 2) + 1)).normal());
  d.paper_load = load_integral(d.paper_inversion, d.radicals);

  const ex edge = pow(sym::alpha(), 2) - sym::s();
  d.paper_pressure_v =
      scaled(root_terms(d.paper_inversion, d.radicals, edge), GiNaC::Pi / sym::b1());
  d.pa_over_pstar_v = scaled(d.load_v, 1 / (GiNaC::Pi * sym::E() * sym::H1()));
  d.paper_pressure_angle = in_angles(d.paper_pressure_v);
  d.pa_over_pstar_angle = in_angles(d.pa_over_pstar_v);
  derive_beyond_half(d);
  return d;
}

}  // namespace wavecontact::derive
