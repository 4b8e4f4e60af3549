// Run-to-run deterministic views of GiNaC expressions.
//
// GiNaC orders the operands of sums and products by hash values that change from run
// to run (they depend on type-info addresses), and normal() and factor() may flip the
// sign of a numerator/denominator pair accordingly. Everything derive/ writes to disk
// goes through these functions so that generated files are byte-identical on every run.
#pragma once

#include <string>
#include <vector>

#include <ginac/ginac.h>

namespace wavecontact::derive {

// A parsable string (GiNaC syntax) whose operands are sorted by their own canonical
// strings.
std::string canonical_string(const GiNaC::ex& e);

// The canonical string of base^exponent, without building the power (which GiNaC may store
// with the sign of an even power's base flipped).
std::string canonical_string(const GiNaC::ex& base, const GiNaC::numeric& exponent);

// The operands of a sum or product, sorted by canonical string.
std::vector<GiNaC::ex> sorted_operands(const GiNaC::ex& e);

// Whether the sum is negative at a generic point fixed by the names of its symbols and the
// canonical strings of its function calls (whatever form GiNaC stores it in); where it is 0 or
// undefined there, whether its term that sorts first, signs ignored, is negative. Either way
// e and -e get opposite answers, so flipping the sum when this holds fixes its sign.
bool leading_term_negative(const GiNaC::ex& sum);

// A rational function as "(numerator)/(denominator)" with expanded, sorted polynomials
// and the sign fixed so that the denominator's first term has a positive coefficient.
std::string canonical_rational(const GiNaC::ex& e);

}  // namespace wavecontact::derive
