#include "beyond_branch.hpp"

#include "core/symbols.hpp"
#include "engine/angle_form.hpp"
#include "engine/closed_forms.hpp"
#include "engine/hilbert.hpp"

namespace wavecontact::derive {

using GiNaC::ex;

GiNaC::exmap sample_beyond_branch(GiNaC::exmap sample, const ex& beta) {
  sample[sym::alpha()] = GiNaC::numeric(3, 2) * beta;
  sample.erase(sym::s());
  sample.erase(sym::u());
  return sample;
}

namespace {

// alpha^2 = (1 - Ca)/(1 + Ca) in a rational function of alpha^2: the argument of I_{j,l}.
ex in_zone_cosine(const ex& e) {
  const ex Ca = sym::Ca();
  return GiNaC::factor(e.subs(sym::alpha() == GiNaC::sqrt((1 - Ca) / (1 + Ca))).normal());
}

// A moment term in angle atoms: its factor c sqrt(r) by to_angle_atoms, its argument z in Ca,
// a Cauchy factor's y (which depends on the point) in all the atoms.
MomentTerm moment_in_angles(const MomentTerm& term, const GiNaC::exmap& sample) {
  const RootTerm factor = to_angle_atoms({term.rational, term.radicand}, sample);
  if (term.l == 0) return moment_term(factor.rational, factor.radicand, 0, 0, 0, 0);
  const auto in_atoms = [&sample](const ex& e) {
    return e.has(sym::s()) ? as_ex(to_angle_atoms({e, 1}, sample)) : in_zone_cosine(e);
  };
  MomentTerm angle =
      moment_term(factor.rational, factor.radicand, term.j, term.l, in_atoms(term.z), in_atoms(term.one_plus_z));
  angle.edge = term.edge;
  if (term.cauchy) {
    angle.cauchy = true;
    angle.y = in_atoms(term.y);
    angle.one_plus_y = in_atoms(term.one_plus_y);
  }
  return angle;
}

std::vector<MomentTerm> moments_in_angles(const std::vector<MomentTerm>& terms, const GiNaC::exmap& sample) {
  std::vector<MomentTerm> angle;
  for (const MomentTerm& term : terms) angle.push_back(moment_in_angles(term, sample));
  return angle;
}

// The two pieces of the zone, [0, beta] on the top branch and [beta, alpha] on the flank:
//   c sqrt(1 + alpha^2) (M_[0,beta][top] + M_[beta,alpha][flank]), as moment terms of each.
struct PieceMoments {
  std::vector<MomentTerm> top, flank;
};

PieceMoments piece_moments(const ex& top, const ex& flank, const ex& beta, const ex& c) {
  const auto scaled = [&c](std::vector<MomentTerm> terms) {
    for (MomentTerm& term : terms) {
      term.rational = (c * term.rational).normal();
      term.radicand = (term.radicand * (1 + GiNaC::pow(sym::alpha(), 2))).normal();
    }
    return terms;
  };
  return {scaled(inner_moment(top, beta)), scaled(outer_moment(flank, beta))};
}

std::vector<MomentTerm> both_pieces(const PieceMoments& pieces) {
  std::vector<MomentTerm> terms = pieces.top;
  terms.insert(terms.end(), pieces.flank.begin(), pieces.flank.end());
  return terms;
}

// dF/dSa - dF/dCa of c sqrt(r) I_{j,l}(z): the factor's (closed_forms.hpp) times I, plus
// c sqrt(r) (-l I_{j+1,l+1}(z)) dz.
std::vector<MomentTerm> moment_slope_factor(const MomentTerm& term) {
  const RootTerm factor = slope_factor({term.rational, term.radicand});
  std::vector<MomentTerm> terms{moment_term(factor.rational, factor.radicand, term.j, term.l, term.z, term.one_plus_z)};
  if (term.l > 0) {
    const ex Dz = term.z.diff(sym::Sa()) - term.z.diff(sym::Ca());
    terms.push_back(moment_term((-term.l * term.rational * Dz).normal(), term.radicand, term.j + 1, term.l + 1, term.z,
                                term.one_plus_z));
  }
  return terms;
}

// The argument z of the first top-piece term that has one (every top term's z is a multiple
// of beta^2/(alpha^2 - beta^2), which grows without bound as the edge comes down to beta).
ex top_argument(const std::vector<MomentTerm>& top) {
  for (const MomentTerm& term : top) {
    if (term.l > 0) return in_zone_cosine(term.z);
  }
  return 0;
}

// Eq. 12 split at the branch, for u on one branch ("own", f = v g(v) in t on each branch):
//   p(x) = (pi/b1) sqrt(alpha^2 - s) (M_own[(f_own(t) - f_own(s))/(t - s)]
//                                     + M_other[(f_other(t) - f_own(s))/(t - s)]),
// t - s divided out of the own piece. Near the other branch's pole the Cauchy factor stays
// beside f_other's pole factor in the other piece's moment (J_{j,l} atoms, other_cauchy);
// elsewhere that moment is split as
//   M_other[(f_other(t) - f_other(s))/(t - s)] + (f_other(s) - f_own(s)) M_other[1/(t - s)]
// (other, jump): no logarithm near the branch, where the jump vanishes, but coefficients with
// f_other's pole at s. The pieces in v-variables, each with its pole factor's argument.
BeyondBranch::SidePressure pressure_terms(const ex& f_top, const ex& f_flank, bool on_top, const ex& beta) {
  const ex t = sym::t(), s = sym::s();
  const ex& f_own = on_top ? f_top : f_flank;
  const ex& f_other = on_top ? f_flank : f_top;
  const auto divided = [&](const ex& f, const ex& at_s) { return ((f - at_s.subs(t == s)) / (t - s)).normal(); };
  const auto own_moment = on_top ? inner_moment : outer_moment;
  const auto other_moment = on_top ? outer_moment : inner_moment;
  const auto scaled = [&](std::vector<MomentTerm> terms) {
    for (MomentTerm& term : terms) {
      term.rational = (term.rational * GiNaC::Pi / sym::b1()).normal();
      term.radicand = (term.radicand * (GiNaC::pow(sym::alpha(), 2) - s)).normal();
    }
    return terms;
  };
  BeyondBranch::SidePressure side;
  side.own = scaled(own_moment(divided(f_own, f_own), beta, false));
  side.own_edge = scaled(own_moment(divided(f_own, f_own), beta, true));
  side.other_cauchy = scaled(other_moment(divided(f_other, f_own), beta, false));
  side.other_cauchy_edge = scaled(other_moment(divided(f_other, f_own), beta, true));
  side.other = scaled(other_moment(divided(f_other, f_other), beta, false));
  side.other_edge = scaled(other_moment(divided(f_other, f_other), beta, true));
  side.jump = scaled(other_moment(1 / (t - s), beta, false));
  const ex jump = (f_other - f_own).subs(t == s).normal();
  for (MomentTerm& term : side.jump) term.rational = (term.rational * jump).normal();
  const auto argument = [](const std::vector<MomentTerm>& terms) {
    for (const MomentTerm& term : terms) {
      if (term.l > 0) return term.z;
    }
    return ex(0);
  };
  side.own_argument = argument(side.own);
  side.other_argument = argument(side.other);
  return side;
}

BeyondBranch::SidePressure side_in_angles(const BeyondBranch::SidePressure& v, const GiNaC::exmap& sample) {
  return {moments_in_angles(v.own, sample),          moments_in_angles(v.own_edge, sample),
          moments_in_angles(v.other_cauchy, sample), moments_in_angles(v.other_cauchy_edge, sample),
          moments_in_angles(v.other, sample),        moments_in_angles(v.other_edge, sample),
          moments_in_angles(v.jump, sample),         in_zone_cosine(v.own_argument),
          in_zone_cosine(v.other_argument)};
}

}  // namespace

BeyondBranch derive_beyond_branch(const ex& top_g, const ex& flank_g, const ex& beta, const GiNaC::exmap& sample) {
  const GiNaC::exmap beyond = sample_beyond_branch(sample, beta);
  BeyondBranch d;
  d.beta = beta;
  d.top_g = top_g;
  d.flank_g = flank_g;
  const PieceMoments load = piece_moments(load_integrand(top_g), load_integrand(flank_g), beta, 2 * GiNaC::Pi);
  d.load_v = both_pieces(load);
  d.load_angle = moments_in_angles(d.load_v, beyond);
  PieceMoments near_branch{{}, load.flank};
  for (const MomentTerm& term : load.top) {
    for (const MomentTerm& part : large_argument_form(term)) near_branch.top.push_back(part);
  }
  d.load_near_branch_angle = moments_in_angles(both_pieces(near_branch), beyond);
  for (const MomentTerm& term : d.load_angle) {
    for (const MomentTerm& part : moment_slope_factor(term)) d.load_slope_factor.push_back(part);
  }
  d.load_slope_factor_by_parts_v =
      both_pieces(piece_moments(load_slope_integrand(top_g), load_slope_integrand(flank_g), beta, GiNaC::Pi / 2));
  d.load_slope_factor_by_parts = moments_in_angles(d.load_slope_factor_by_parts_v, beyond);
  d.top_piece_argument = top_argument(load.top);
  const GiNaC::symbol& v = sym::v();
  const ex f_top = even_in_square(v * top_g, v, sym::t()), f_flank = even_in_square(v * flank_g, v, sym::t());
  GiNaC::exmap on_top = beyond, on_flank = beyond;
  on_top[sym::u()] = beta / 2;
  on_top[sym::s()] = beta * beta / 4;
  on_flank[sym::u()] = 5 * beta / 4;
  on_flank[sym::s()] = 25 * beta * beta / 16;
  d.pressure_top_v = pressure_terms(f_top, f_flank, true, beta);
  d.pressure_flank_v = pressure_terms(f_top, f_flank, false, beta);
  d.pressure_top = side_in_angles(d.pressure_top_v, on_top);
  d.pressure_flank = side_in_angles(d.pressure_flank_v, on_flank);
  return d;
}

}  // namespace wavecontact::derive
