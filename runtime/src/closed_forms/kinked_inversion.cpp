#include "closed_forms/kinked_inversion.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

namespace wavecontact::detail {

namespace {

// Whether the point takes the other piece with its Cauchy factor (see BranchSide::pressure).
bool takes_cauchy(double other_over_own) { return std::fabs(other_over_own) > 2; }

}  // namespace

BranchSide::BranchSide(BranchSideForms forms, double own_argument, double other_argument)
    : forms_(std::move(forms)),
      own_(own_argument < 0 ? BranchPart::own_edge : BranchPart::own),
      other_(other_argument < 0 ? BranchPart::other_edge : BranchPart::other),
      other_cauchy_(other_argument < 0 ? BranchPart::other_cauchy_edge : BranchPart::other_cauchy) {
  for (int count : forms_.atom_counts) {
    if (count > max_branch_atoms) {
      throw std::logic_error("wavecontact::detail::BranchSide: a part has " + std::to_string(count) +
                             " atoms, more than max_branch_atoms = " + std::to_string(max_branch_atoms));
    }
  }
  forms_.atoms(own_, 0, 1, own_atoms_.data());
  forms_.atoms(other_, 0, 1, other_atoms_.data());
}

double BranchSide::part_at_point(BranchPart part, const PointAngles& point) const {
  double y[2];
  forms_.cauchy_argument(point, y);
  Atoms atoms;
  forms_.atoms(part, y[0], y[1], atoms.data());
  return forms_.part(part, point, atoms.data());
}

double BranchSide::cauchy_part(const PointAngles& point, double eta, const CauchyAtomTable* table, bool build) const {
  if (table) {
    Atoms atoms;
    if (table->evaluate(std::isfinite(eta) ? eta : eta_at(point), atoms.data(), build)) {
      return forms_.part(other_cauchy_, point, atoms.data());
    }
  }
  return part_at_point(other_cauchy_, point);
}

double BranchSide::eta_at(const PointAngles& point) const {
  double y[2];
  forms_.cauchy_argument(point, y);
  return std::log(y[1]);
}

double BranchSide::cauchy_eta(const PointAngles& point, double other_over_own) const {
  return takes_cauchy(other_over_own) ? eta_at(point) : std::numeric_limits<double>::quiet_NaN();
}

CauchyAtomTable BranchSide::cauchy_table() const {
  const BranchPart part = other_cauchy_;
  return CauchyAtomTable(
      [atoms = forms_.atoms, part](double y, double one_plus_y, double* out) { atoms(part, y, one_plus_y, out); },
      forms_.atom_counts[static_cast<int>(part)]);
}

double BranchSide::pressure(const PointAngles& point, double other_over_own, bool at_branch, double eta,
                            const CauchyAtomTable* table, bool build) const {
  const double own = forms_.part(own_, point, own_atoms_.data());
  if (takes_cauchy(other_over_own)) return own + cauchy_part(point, eta, table, build);
  const double other = forms_.part(other_, point, other_atoms_.data());
  return at_branch ? own + other : own + other + part_at_point(BranchPart::jump, point);
}

}  // namespace wavecontact::detail
