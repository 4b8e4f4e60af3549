#include "closed_forms/cauchy_atom_table.hpp"

#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>

#include <boost/math/constants/constants.hpp>

namespace wavecontact::detail {

CauchyAtomTable::CauchyAtomTable(Atoms atoms, int count)
    : atoms_(std::move(atoms)), count_(count), panels_(std::make_unique<Panel[]>(panel_count)) {
  if (count < 0 || count > max_branch_atoms) {
    throw std::logic_error("wavecontact::detail::CauchyAtomTable: count = " + std::to_string(count) +
                           " atoms (valid: 0 to max_branch_atoms = " + std::to_string(max_branch_atoms) + ")");
  }
}

CauchyAtomTable::Panel* CauchyAtomTable::panel_of(double eta) const {
  if (!(eta >= static_cast<double>(first_panel) && eta < static_cast<double>(first_panel + panel_count)))
    return nullptr;
  return &panels_[static_cast<std::size_t>(static_cast<long>(std::floor(eta)) - first_panel)];
}

void CauchyAtomTable::build(Panel& panel, long k) const {
  std::call_once(panel.once, [&] {
    using boost::math::double_constants::pi;
    // Chebyshev nodes of the first kind, xi_i = cos(theta_i), eta = k + (1 + xi)/2. A panel whose
    // nodes leave the atoms' domain (the points themselves lie in it) is not built: its points
    // take the atoms directly.
    std::vector<double> values(static_cast<std::size_t>(nodes * count_));
    try {
      for (int i = 0; i < nodes; ++i) {
        const double eta = static_cast<double>(k) + (1 + std::cos(pi * (i + 0.5) / nodes)) / 2;
        atoms_(std::expm1(eta), std::exp(eta), &values[static_cast<std::size_t>(i * count_)]);
      }
    } catch (const std::domain_error&) {
      panel.built.store(true, std::memory_order_release);
      return;
    }
    std::vector<double>& c = panel.coefficients;
    c.assign(static_cast<std::size_t>(nodes * count_), 0.0);
    for (int j = 0; j < nodes; ++j) {
      for (int a = 0; a < count_; ++a) {
        double sum = 0;
        for (int i = 0; i < nodes; ++i)
          sum += values[static_cast<std::size_t>(i * count_ + a)] * std::cos(pi * j * (i + 0.5) / nodes);
        c[static_cast<std::size_t>(j * count_ + a)] = (j == 0 ? 1.0 : 2.0) * sum / nodes;
      }
    }
    panel.built.store(true, std::memory_order_release);
  });
}

void CauchyAtomTable::tabulate(const std::vector<double>& etas) const {
  std::map<long, std::size_t> points;
  for (double eta : etas) {
    if (panel_of(eta)) ++points[static_cast<long>(std::floor(eta))];
  }
  for (const auto& [k, n] : points) {
    if (n >= static_cast<std::size_t>(nodes)) build(*panel_of(static_cast<double>(k)), k);
  }
}

bool CauchyAtomTable::evaluate(double eta, double* out, bool build_panel) const {
  Panel* panel = panel_of(eta);
  if (!panel) return false;
  const long k = static_cast<long>(std::floor(eta));
  if (!panel->built.load(std::memory_order_acquire)) {
    if (!build_panel) return false;
    build(*panel, k);
  }
  const std::vector<double>& c = panel->coefficients;
  if (c.empty()) return false;
  // T_j(xi) once (|T_j| <= 1: the recurrence's rounding grows like j eps), then each atom's sum.
  const double xi = 2 * (eta - static_cast<double>(k)) - 1;
  double T[nodes];
  T[0] = 1;
  T[1] = xi;
  for (int j = 2; j < nodes; ++j) T[j] = 2 * xi * T[j - 1] - T[j - 2];
  for (int a = 0; a < count_; ++a) {  // two partial sums (even and odd j), the small terms first
    double even = 0, odd = 0;
    for (int j = nodes - 2; j >= 0; j -= 2) {
      even += c[static_cast<std::size_t>(j * count_ + a)] * T[j];
      odd += c[static_cast<std::size_t>((j + 1) * count_ + a)] * T[j + 1];
    }
    out[a] = even + odd;
  }
  return true;
}

}  // namespace wavecontact::detail
