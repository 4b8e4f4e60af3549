// Chebyshev series on [-1, 1]: the nodes of the first kind, the transform from values at them
// to coefficients, and Clenshaw's sums of the four kinds (T, U, V, W) a zone's density uses.
#pragma once

#include <cstddef>
#include <vector>

namespace wavecontact::detail::chebyshev {

// tau_i = cos(pi (i + 1/2) / M), i = 0 .. M - 1: decreasing from near 1 to near -1.
const std::vector<double>& nodes(int M);
// How far each exact node lies from nodes(M)[i], its double (half an ulp at most, to a few
// digits): the transform takes the doubles for the exact nodes.
const std::vector<double>& node_roundings(int M);

// The coefficients c_0 .. c_{M-1} of the polynomial of degree M - 1 through `values` at
// nodes(M): c_j = (2 - [j = 0]) / M sum_i values_i T_j(tau_i).
std::vector<double> coefficients(const std::vector<double>& values);
// The same transform applied to values given as a pointer (count M), into `out` (M values,
// apart from `values`).
void coefficients(const double* values, int M, double* out);

// The values at nodes(M) of the series c_0 .. c_{count-1} (count <= M) into `out` (M values):
// the inverse of coefficients.
void values(const double* c, int count, int M, double* out);

// The coefficients of the series' derivative d/dtau (one term fewer; none for a constant).
std::vector<double> derivative(const std::vector<double>& c);

// The coefficients c_0 .. c_n of the polynomial of degree n through values at the extrema
// cos(pi i / n), i = 0 .. n (Clenshaw-Curtis points: they nest as n doubles).
std::vector<double> extrema_coefficients(const std::vector<double>& values);

// sum_j c_j P_j(t) at t[0 .. points) into out, P_j of the first kind T_j, the second U_j, the
// third V_j (V_1 = 2t - 1) or the fourth W_j (W_1 = 2t + 1), the points' recurrences side by side.
enum class Kind { t, u, v, w };
void sums(Kind kind, const double* c, std::size_t count, const double* t, double* out, std::size_t points);

}  // namespace wavecontact::detail::chebyshev
