// The symbols every derivation shares. GiNaC identifies a symbol by object, not by
// name, so all of derive/ takes them from here.
#pragma once

#include <ginac/ginac.h>

namespace wavecontact::derive::sym {

// Coordinates (period normalised to 2*pi, docs/mathematics.md section 2).
const GiNaC::realsymbol& x();      // normalised coordinate x^ = pi x / b1
const GiNaC::realsymbol& xi();     // integration coordinate of the kernel
const GiNaC::realsymbol& v();      // v = tan(x^/2)            (eq. 4)
const GiNaC::realsymbol& u();      // u = tan(xi/2)            (eq. 4)
const GiNaC::realsymbol& alpha();  // alpha = tan(a^/2)        (eq. 4)
const GiNaC::realsymbol& t();      // t = v^2, variable of the inversion engine
const GiNaC::realsymbol& s();      // s = u^2

// Physical parameters.
const GiNaC::realsymbol& E();    // reduced modulus E* (eq. 7)
const GiNaC::realsymbol& H1();   // waviness height (eq. 2)
const GiNaC::realsymbol& b1();   // waviness half-period (eq. 2)
const GiNaC::realsymbol& m();    // shape parameter of the parametric wave curve (eq. 2)
const GiNaC::realsymbol& H2();   // roughness height (eq. 3)
const GiNaC::realsymbol& n();    // wavelength ratio b1/b2 (eq. 3), as a parameter
const GiNaC::realsymbol& Cnx();  // cos(n x^), the roughness phase (eq. 15)

// Angle atoms of the well-conditioned (eq. 14) form; the runtime computes them
// without cancellation (runtime/include/wavecontact/angles.hpp).
const GiNaC::realsymbol& Ca();  // cos a^
const GiNaC::realsymbol& Sa();  // 1 - cos a^ = 2 sin^2(a^/2)
const GiNaC::realsymbol& Cx();  // cos x^
const GiNaC::realsymbol& Sx();  // 1 - cos x^ = 2 sin^2(x^/2)
const GiNaC::realsymbol& D();   // cos x^ - cos a^ = 2 sin((a^+x^)/2) sin((a^-x^)/2)

}  // namespace wavecontact::derive::sym
