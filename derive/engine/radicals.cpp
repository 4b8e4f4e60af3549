#include "radicals.hpp"

#include <stdexcept>
#include <string>

#include "core/symbols.hpp"

namespace wavecontact::derive {

using GiNaC::ex;

unsigned Radicals::index_of(const ex& tau) {
  for (unsigned i = 0; i < entries_.size(); ++i) {
    if ((entries_[i].tau - tau).normal().is_zero()) return i;
  }
  if (entries_.size() >= 64) throw std::length_error("Radicals: more than 64 distinct poles");
  const ex alpha = sym::alpha();
  entries_.push_back({tau.normal(), (1 - GiNaC::pow(alpha, 2) / tau).normal(),
                      GiNaC::realsymbol("kappa" + std::to_string(entries_.size() + 1))});
  return static_cast<unsigned>(entries_.size() - 1);
}

RadicalSum RadicalSum::monomial(Mask radicals, const ex& c) {
  RadicalSum r;
  if (!c.is_zero()) r.terms_.emplace(radicals, c);
  return r;
}

RadicalSum& RadicalSum::operator+=(const RadicalSum& other) {
  for (const auto& [mask, c] : other.terms_) {
    auto [it, inserted] = terms_.emplace(mask, c);
    if (!inserted) it->second += c;
  }
  return *this;
}

RadicalSum RadicalSum::scaled(const ex& c) const {
  return transformed([&](const ex& coefficient) { return coefficient * c; });
}

RadicalSum RadicalSum::times(const RadicalSum& other, const Radicals& radicals) const {
  RadicalSum r;
  for (const auto& [ma, ca] : terms_) {
    for (const auto& [mb, cb] : other.terms_) {
      ex c = ca * cb;
      const Mask common = ma & mb;
      for (unsigned i = 0; i < radicals.size(); ++i) {
        if (common & (Mask{1} << i)) c *= radicals.square(i);
      }
      r += monomial(ma ^ mb, c);
    }
  }
  return r;
}

RadicalSum RadicalSum::normalized() const {
  RadicalSum r;
  for (const auto& [mask, c] : terms_) {
    ex n = c.normal();
    if (!n.is_zero()) r.terms_.emplace(mask, n);
  }
  return r;
}

namespace {
template <typename Root>
ex assemble(const std::map<RadicalSum::Mask, ex>& terms, const Radicals& radicals, Root root) {
  ex sum = 0;
  for (const auto& [mask, c] : terms) {
    ex term = c;
    for (unsigned i = 0; i < radicals.size(); ++i) {
      if (mask & (RadicalSum::Mask{1} << i)) term *= root(i);
    }
    sum += term;
  }
  return sum;
}
}  // namespace

ex RadicalSum::to_ex(const Radicals& radicals) const {
  return assemble(terms_, radicals, [&](unsigned i) -> ex { return radicals.symbol(i); });
}

ex RadicalSum::with_roots(const Radicals& radicals) const {
  return assemble(terms_, radicals, [&](unsigned i) -> ex { return GiNaC::sqrt(radicals.square(i)); });
}

}  // namespace wavecontact::derive
