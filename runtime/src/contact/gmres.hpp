// Restarted GMRES with right preconditioning (Saad, Iterative Methods for Sparse Linear
// Systems, 9.3.2): the Newton steps of the zone system.
#pragma once

#include <functional>
#include <vector>

namespace wavecontact::detail {

using LinearMap = std::function<std::vector<double>(const std::vector<double>&)>;

// x with |b - A x| <= tolerance |b|, from x = 0: GMRES(restart) on A M^-1 u = b, x = M^-1 u,
// at most `restarts` cycles (the best x reached otherwise).
std::vector<double> gmres(const LinearMap& A, const LinearMap& M_inverse, const std::vector<double>& b,
                          double tolerance, int restart, int restarts);

}  // namespace wavecontact::detail
