#include "beyond_branch.hpp"

#include "angle_form.hpp"
#include "closed_forms.hpp"
#include "symbols.hpp"

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

// A moment term in angle atoms: its factor c sqrt(r) by to_angle_atoms, its argument z in Ca.
MomentTerm moment_in_angles(const MomentTerm& term, const GiNaC::exmap& sample) {
  const RootTerm factor = to_angle_atoms({term.rational, term.radicand}, sample);
  if (term.l == 0) return {factor.rational, factor.radicand, 0, 0, 0, 0};
  return {factor.rational, factor.radicand, term.j, term.l, in_zone_cosine(term.z),
          in_zone_cosine(term.one_plus_z)};
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
  std::vector<MomentTerm> terms{{factor.rational, factor.radicand, term.j, term.l, term.z, term.one_plus_z}};
  if (term.l > 0) {
    const ex Dz = term.z.diff(sym::Sa()) - term.z.diff(sym::Ca());
    terms.push_back({(-term.l * term.rational * Dz).normal(), term.radicand, term.j + 1, term.l + 1,
                     term.z, term.one_plus_z});
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

}  // namespace

BeyondBranch derive_beyond_branch(const ex& top_g, const ex& flank_g, const ex& beta,
                                  const GiNaC::exmap& sample) {
  const GiNaC::exmap beyond = sample_beyond_branch(sample, beta);
  BeyondBranch d;
  d.beta = beta;
  d.top_g = top_g;
  d.flank_g = flank_g;
  const PieceMoments load =
      piece_moments(load_integrand(top_g), load_integrand(flank_g), beta, 2 * GiNaC::Pi);
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
  d.load_slope_factor_by_parts_v = both_pieces(
      piece_moments(load_slope_integrand(top_g), load_slope_integrand(flank_g), beta, GiNaC::Pi / 2));
  d.load_slope_factor_by_parts = moments_in_angles(d.load_slope_factor_by_parts_v, beyond);
  d.top_piece_argument = top_argument(load.top);
  return d;
}

}  // namespace wavecontact::derive
