// The square roots that the finite Hilbert inversion introduces.
//
// Every pole t = tau of an integrand (in t = v^2) contributes the radical
//   kappa(tau) = sqrt(1 - alpha^2/tau),
// real and positive whenever tau lies off [0, alpha^2] (docs/mathematics.md section 2). Closed forms
// are kept as sums over square-free products of these radicals with rational
// coefficients, so that kappa^2 is always reduced and cancellations happen in normal().
#pragma once

#include <cstdint>
#include <map>
#include <vector>

#include <ginac/ginac.h>

namespace wavecontact::derive {

class Radicals {
 public:
  // Index of kappa(tau); the same pole (equal after normal()) always gets the same index.
  unsigned index_of(const GiNaC::ex& tau);

  std::size_t size() const { return entries_.size(); }
  const GiNaC::ex& pole(unsigned i) const { return entries_.at(i).tau; }
  // kappa_i^2 = 1 - alpha^2/tau_i, in normal form.
  const GiNaC::ex& square(unsigned i) const { return entries_.at(i).square; }
  // The symbol kappa<i+1> that stands for kappa_i in printed closed forms.
  const GiNaC::realsymbol& symbol(unsigned i) const { return entries_.at(i).symbol; }

 private:
  struct Entry {
    GiNaC::ex tau;
    GiNaC::ex square;
    GiNaC::realsymbol symbol;
  };
  std::vector<Entry> entries_;
};

// sum_S c_S prod_{i in S} kappa_i, S a set of radical indices (bit mask).
class RadicalSum {
 public:
  using Mask = std::uint64_t;

  RadicalSum() = default;
  static RadicalSum rational(const GiNaC::ex& c) { return monomial(0, c); }
  static RadicalSum monomial(Mask radicals, const GiNaC::ex& c);

  RadicalSum& operator+=(const RadicalSum& other);
  RadicalSum scaled(const GiNaC::ex& c) const;
  // Product, with kappa_i^2 replaced by its square.
  RadicalSum times(const RadicalSum& other, const Radicals& radicals) const;
  // Every coefficient through normal(); zero terms dropped.
  RadicalSum normalized() const;
  // Coefficients with f applied, e.g. a substitution.
  template <typename F>
  RadicalSum transformed(F&& f) const {
    RadicalSum r;
    for (const auto& [mask, c] : terms_) r.terms_.emplace(mask, f(c));
    return r;
  }

  const std::map<Mask, GiNaC::ex>& terms() const { return terms_; }
  bool is_zero() const { return terms_.empty(); }

  // As an expression in the kappa symbols.
  GiNaC::ex to_ex(const Radicals& radicals) const;
  // As an expression with kappa_i replaced by sqrt(square_i).
  GiNaC::ex with_roots(const Radicals& radicals) const;

 private:
  std::map<Mask, GiNaC::ex> terms_;
};

}  // namespace wavecontact::derive
