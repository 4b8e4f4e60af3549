#include "branches.hpp"

#include <set>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "core/printed.hpp"
#include "core/symbols.hpp"
#include "profile/block_keer.hpp"
#include "profile/expression_input.hpp"

namespace wavecontact::derive {

using GiNaC::ex;
using GiNaC::numeric;

namespace {

[[noreturn]] void refuse(const ex& call, const std::string& why) { throw InputRefused(printed(call) + ": " + why); }

std::vector<ex> abs_calls(const ex& y) {
  std::vector<ex> calls;
  for (auto it = y.preorder_begin(); it != y.preorder_end(); ++it) {
    if (is_abs(*it)) calls.push_back(*it);
  }
  return calls;
}

// Sign changes of a polynomial's value counted along a Sturm sequence at c.
int sign_variations(const std::vector<ex>& sturm, const numeric& c) {
  int variations = 0, last = 0;
  for (const ex& p : sturm) {
    const numeric value = GiNaC::ex_to<numeric>(p.subs(sym::Cx() == c));
    const int sign = value.is_zero() ? 0 : (value.is_positive() ? 1 : -1);
    if (sign != 0 && last != 0 && sign != last) ++variations;
    if (sign != 0) last = sign;
  }
  return variations;
}

// The number of distinct real roots of the square-free polynomial p (in Cx) in (-1, 1).
int roots_inside(const ex& p) {
  const GiNaC::symbol& c = sym::Cx();
  std::vector<ex> sturm{p.expand(), p.diff(c).expand()};
  while (sturm.back().degree(c) > 0) {
    sturm.push_back((-GiNaC::rem(sturm[sturm.size() - 2], sturm.back(), c)).expand());
  }
  return sign_variations(sturm, -1) - sign_variations(sturm, 1);
}

// The points of -1 < cos x^ < 1 where the rational function f(Cx) changes sign: roots of odd
// multiplicity of its numerator and denominator.
std::set<numeric> sign_changes(const ex& call, const ex& f) {
  const GiNaC::symbol& c = sym::Cx();
  std::set<numeric> points;
  const ex nd = f.normal().numer_denom();
  for (const ex& polynomial : {nd.op(0), nd.op(1)}) {
    const ex factored = GiNaC::factor(polynomial);
    const std::vector<ex> factors = GiNaC::is_a<GiNaC::mul>(factored)
                                        ? std::vector<ex>(factored.begin(), factored.end())
                                        : std::vector<ex>{factored};
    for (const ex& factor_power : factors) {
      const bool power = GiNaC::is_a<GiNaC::power>(factor_power);
      const ex factor = power ? factor_power.op(0) : factor_power;
      if (factor.degree(c) == 0) continue;
      if (power && GiNaC::ex_to<numeric>(factor_power.op(1)).is_even()) continue;
      if (factor.degree(c) == 1) {
        const numeric root = GiNaC::ex_to<numeric>((-factor.coeff(c, 0) / factor.coeff(c, 1)).normal());
        if (root > -1 && root < 1) points.insert(root);
      } else if (roots_inside(factor) > 0) {
        refuse(call, "its argument changes sign where cos x is irrational (a root of " + printed(factor) +
                         " = 0 with cos x = " + printed(c) + "); the branch point must be a rational cos x");
      }
    }
  }
  return points;
}

// The sign of f(Cx) on the open interval (lo, hi), on which it does not change sign.
int sign_on(const ex& f, const numeric& lo, const numeric& hi) {
  for (int denominator = 2; denominator <= 1 << 12; denominator *= 2) {
    for (int k = 1; k < denominator; k += 2) {
      const ex value = f.subs(sym::Cx() == lo + (hi - lo) * numeric(k, denominator));
      if (GiNaC::is_a<numeric>(value) && !value.is_zero()) return GiNaC::ex_to<numeric>(value).is_positive() ? 1 : -1;
    }
  }
  throw std::logic_error("split_branches: no point where " + printed(f) + " is non-zero");
}

}  // namespace

BranchSplit split_branches(const ex& y) {
  struct Call {
    ex call, f;
    std::set<numeric> changes;
  };
  std::vector<Call> calls;
  std::set<numeric> changes;
  for (const ex& call : abs_calls(y)) {
    const ex argument = call.op(0);
    if (!abs_calls(argument).empty()) refuse(call, "abs() inside abs() is not supported");
    for (auto it = argument.preorder_begin(); it != argument.preorder_end(); ++it) {
      if (GiNaC::is_a<GiNaC::symbol>(*it) && *it != sym::x()) {
        refuse(call, "the argument of abs() must not depend on the parameters (" + printed(*it) +
                         "): where it changes sign must be a number");
      }
    }
    ex f;
    try {
      f = in_cosine(argument);
    } catch (const std::invalid_argument& e) {
      refuse(call, std::string("the argument of abs() must be even in x and rational in cos(k x) (") + e.what() + ")");
    }
    Call c{call, f, sign_changes(call, f)};
    changes.insert(c.changes.begin(), c.changes.end());
    calls.push_back(c);
  }
  if (changes.size() > 1) {
    std::string list;
    for (const numeric& c : changes) list += (list.empty() ? "" : ", ") + printed(c);
    throw InputRefused("the arguments of abs() change sign at cos x = " + list +
                       ": the engine joins two branches, so they may change sign at one point of "
                       "0 < x < pi only");
  }
  BranchSplit split;
  split.branched = !changes.empty();
  const numeric change = split.branched ? *changes.begin() : numeric(-1);
  GiNaC::exmap top, flank;
  for (const Call& c : calls) {
    top[c.call] = sign_on(c.f, change, 1) * c.call.op(0);
    flank[c.call] = (split.branched ? sign_on(c.f, -1, change) : sign_on(c.f, change, 1)) * c.call.op(0);
  }
  split.top = y.subs(top, GiNaC::subs_options::no_pattern);
  split.flank = y.subs(flank, GiNaC::subs_options::no_pattern);
  // Signs that cancel (abs(cos x) abs(2 cos x) = 2 cos^2 x) leave one branch: no kink.
  if (split.branched && (split.top - split.flank).normal().is_zero()) split.branched = false;
  if (split.branched) {
    split.cosine = change;
    split.beta = GiNaC::sqrt((1 - change) / (1 + change));
    if (!GiNaC::is_a<numeric>(split.beta) || !GiNaC::ex_to<numeric>(split.beta).is_rational()) {
      throw InputRefused("the arguments of abs() change sign at cos x = " + printed(change) +
                         ", where tan(x/2) = " + printed(split.beta) +
                         " is irrational; the engine needs a rational tan(x/2) = r there, "
                         "cos x = (1 - r^2)/(1 + r^2) (0, 3/5, -3/5, 12/13, ...)");
    }
  }
  return split;
}

}  // namespace wavecontact::derive
