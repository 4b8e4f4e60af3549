#include "closed_forms.hpp"

#include "block_keer.hpp"
#include "hilbert.hpp"
#include "symbols.hpp"

namespace wavecontact::derive {

using GiNaC::ex;

std::vector<RootTerm> in_angles(const std::vector<RootTerm>& v_form, const GiNaC::exmap& sample) {
  std::vector<RootTerm> angle;
  for (const auto& term : v_form) angle.push_back(to_angle_atoms(term, sample));
  return angle;
}

std::vector<RootTerm> scaled(std::vector<RootTerm> terms, const ex& factor) {
  for (auto& term : terms) term.rational = (term.rational * factor).normal();
  return terms;
}

namespace {

// dF/dSa - dF/dCa of one term c sqrt(r): [(Dc r + c Dr / 2) / r] sqrt(r).
RootTerm slope_factor(const RootTerm& term) {
  auto D = [](const ex& e) { return e.diff(sym::Sa()) - e.diff(sym::Ca()); };
  const ex& c = term.rational;
  const ex& r = term.radicand;
  return {((D(c) * r + c * D(r) / 2) / r).normal(), r};
}

}  // namespace

ClosedForms derive_closed_forms(const ex& y, const GiNaC::exmap& sample) {
  ClosedForms d;
  d.profile = y;
  d.g = hilbert_rhs(y);
  d.inversion = bounded_inversion(d.g, d.radicals);
  d.load = load_integral(d.inversion, d.radicals);
  // Physical pressure p(x) = (pi/b1) p^(x^), p^ = sqrt(alpha^2 - u^2) * inversion.
  const ex edge = GiNaC::pow(sym::alpha(), 2) - sym::s();
  d.pressure_v = scaled(root_terms(d.inversion, d.radicals, edge), GiNaC::Pi / sym::b1());
  d.load_v = root_terms(d.load, d.radicals);
  d.pressure_angle = in_angles(d.pressure_v, sample);
  d.load_angle = in_angles(d.load_v, sample);
  for (const auto& term : d.load_angle) d.load_slope_factor.push_back(slope_factor(term));
  // y is even in x^, so rational in v^2 = tan^2(x^/2) = (1 - s)/(1 + s).
  const GiNaC::realsymbol& s = sym::Cx();
  d.height = in_half_angle_tangent(y).subs(sym::v() == GiNaC::sqrt((1 - s) / (1 + s))).normal();
  d.height_slope = d.height.diff(s).normal();
  d.harmonic = highest_harmonic(y);
  return d;
}

}  // namespace wavecontact::derive
