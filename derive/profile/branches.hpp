// Profiles built with |.|, such as the seed's eq. 2, y = H1 (m+1) cos x/(m |cos x| + 1).
//
// Each abs(f) is +f or -f on either side of the points where f changes sign. The engine
// joins two branches in a contact zone (beyond_branch.hpp): the one that holds at the top
// x^ = 0, and the one beyond the first sign change. So the arguments of abs() must be
// parameter-free (their sign changes are numbers), even in x^ (rational in cos x^), and
// change sign, all of them together, at no more than one point of 0 < x^ < pi, where
// v = tan(x^/2) is rational: cos x^ = (1 - r^2)/(1 + r^2) (0 as in eq. 2, 3/5, -3/5, ...).
#pragma once

#include <ginac/ginac.h>

namespace wavecontact::derive {

struct BranchSplit {
  GiNaC::ex top;    // y with every abs(f) replaced by +-f as at x^ = 0
  GiNaC::ex flank;  // y beyond the sign change (top itself when there is none)
  bool branched = false;
  GiNaC::numeric cosine;  // cos x^ at the sign change, in (-1, 1), when branched
  GiNaC::ex beta;         // v = tan(x^/2) there: sqrt((1 - cosine)/(1 + cosine))
};

// Splits y (sym::x(), the parameters) at the sign changes of its abs() arguments; y without
// abs() is its own top. Throws InputRefused (expression_input.hpp) naming the abs() and why
// when an argument depends on a parameter, is not even and rational in cos(k x^), contains
// abs() itself, changes sign where cos x^ or tan(x^/2) is irrational, or when the sign
// changes fall on more than one point of 0 < x^ < pi.
BranchSplit split_branches(const GiNaC::ex& y);

}  // namespace wavecontact::derive
