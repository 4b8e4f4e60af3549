#include "closed_forms.hpp"

#include <algorithm>

#include "core/symbols.hpp"
#include "engine/hilbert.hpp"
#include "profile/block_keer.hpp"

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

RootTerm slope_factor(const RootTerm& term) {
  auto D = [](const ex& e) { return e.diff(sym::Sa()) - e.diff(sym::Ca()); };
  const ex& c = term.rational;
  const ex& r = term.radicand;
  return {((D(c) * r + c * D(r) / 2) / r).normal(), r};
}

ClosedForms derive_closed_forms(const ex& y, const GiNaC::exmap& sample) {
  return derive_closed_forms(y, split_harmonic_part(in_cosine(y)), sample);
}

ClosedForms derive_closed_forms(const ex& y, const HarmonicSplit& parts, const GiNaC::exmap& sample) {
  ClosedForms d;
  d.profile = y;
  const GiNaC::realsymbol& c = sym::Cx();
  d.height = in_cosine(y);
  d.height_slope = d.height.diff(c).normal();
  const ex nd = d.height.numer_denom();
  d.harmonic = std::max(nd.op(0).degree(c), nd.op(1).degree(c));
  d.cosine = parts.cosine;
  d.rational_height = parts.rational;
  d.rational_height_slope = parts.rational.diff(c).normal();
  // The rest R through the engine: eq. 11 by de Moivre, eq. 12, eq. 6.
  d.g = hilbert_rhs(parts.rational.subs(c == GiNaC::cos(sym::x())));
  d.inversion = bounded_inversion(d.g, d.radicals);
  d.load = load_integral(d.inversion, d.radicals);
  // Physical pressure p(x) = (pi/b1) p^(x^), p^ = sqrt(alpha^2 - u^2) * inversion.
  const ex edge = GiNaC::pow(sym::alpha(), 2) - sym::s();
  d.pressure_v = scaled(root_terms(d.inversion, d.radicals, edge), GiNaC::Pi / sym::b1());
  d.load_v = root_terms(d.load, d.radicals);
  d.pressure_angle = in_angles(d.pressure_v, sample);
  d.load_angle = in_angles(d.load_v, sample);
  for (const auto& term : d.load_angle) d.load_slope_factor.push_back(slope_factor(term));
  return d;
}

}  // namespace wavecontact::derive
