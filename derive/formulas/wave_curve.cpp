#include "wave_curve.hpp"

#include "core/symbols.hpp"
#include "engine/hilbert.hpp"
#include "profile/block_keer.hpp"

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

WavinessDerivation derive_waviness() {
  WavinessDerivation d;
  static_cast<ClosedForms&>(d) = derive_closed_forms(parametric_wave_curve());

  // The printed eq. 13 carries 1/sqrt(alpha^2 + 1) = kappa(-1)/(alpha^2 + 1).
  const unsigned kappa_minus_one = d.radicals.index_of(-1);
  d.paper_inversion = RadicalSum::monomial(RadicalSum::Mask{1} << kappa_minus_one,
                                           (printed_eq13_rational() / (pow(sym::alpha(), 2) + 1)).normal());
  d.paper_load = load_integral(d.paper_inversion, d.radicals);

  const ex edge = pow(sym::alpha(), 2) - sym::s();
  d.paper_pressure_v = scaled(root_terms(d.paper_inversion, d.radicals, edge), GiNaC::Pi / sym::b1());
  d.pa_over_pstar_v = scaled(d.load_v, 1 / (GiNaC::Pi * sym::E() * sym::H1()));
  d.paper_pressure_angle = in_angles(d.paper_pressure_v);
  d.pa_over_pstar_angle = in_angles(d.pa_over_pstar_v);
  const ex m = sym::m(), c = GiNaC::cos(sym::x());
  d.beyond_half = derive_beyond_branch(d.g, hilbert_rhs(sym::H1() * (m + 1) * c / (1 - m * c)), 1, sample_point_v());
  return d;
}

}  // namespace wavecontact::derive
