// Full contact (a = b1, MATH.md fact 11) in closed form: p = pa + p_fc, where for
// y = sum_k y_k cos(k x^)
//   p_fc(x) = (E*/2)(pi/b1) sum_k k y_k cos(k x^) = (E*/2)(pi/b1) d(y~)/dx^,
// y~ the conjugate function of y. Under v = tan(x^/2) (eq. 4) the conjugate function is the
// Hilbert transform on the line, y~(v) = H[Y](v) = (1/pi) PV Int Y(u^2)/(v - u) du for
// y(x^) = Y(t), t = v^2, and for a pole 1/(t - tau), tau < 0, H = v/(sqrt(-tau)(v^2 - tau)):
// so H[Y] is the sum over Y's poles of the residues at t = tau of Y(t) v/(sqrt(-t)(v^2 - t)),
// taken from the Taylor series at tau (with 1/sqrt(-t) = (1/sqrt(-tau)) (1 + h/tau)^(-1/2),
// h = t - tau). A cosine sum's part is the sum itself (harmonic_series.hpp).
#pragma once

#include <ginac/ginac.h>

namespace wavecontact::derive {

// p_fc(x) for the profile y(x^) = R(Cx) (rational in sym::Cx() and the parameters, its
// poles in t at roots of factors linear in t, none on t >= 0), as an expression in
// sym::E(), sym::b1(), sym::Cx() and the parameters, with sqrt(-tau) of every pole.
// Throws std::invalid_argument if a denominator factor is not linear in t.
GiNaC::ex full_contact_pressure(const GiNaC::ex& R);

}  // namespace wavecontact::derive
