// Chebyshev series on [-1, 1]: the nodes of the first kind, the transform from values at them
// to coefficients, and Clenshaw's sums of the four kinds (T, U, V, W) a zone's density uses.
#pragma once

#include <cstddef>
#include <vector>

namespace wavecontact::detail::chebyshev {

// tau_i = cos(pi (i + 1/2) / M), i = 0 .. M - 1: decreasing from near 1 to near -1.
const std::vector<double>& nodes(int M);

// The coefficients c_0 .. c_{M-1} of the polynomial of degree M - 1 through `values` at
// nodes(M): c_j = (2 - [j = 0]) / M sum_i values_i T_j(tau_i).
std::vector<double> coefficients(const std::vector<double>& values);
// The same transform applied to values given as a pointer (count M), into `out` (M values).
void coefficients(const double* values, int M, double* out);

// The coefficients c_0 .. c_n of the polynomial of degree n through values at the extrema
// cos(pi i / n), i = 0 .. n (Clenshaw-Curtis points: they nest as n doubles).
std::vector<double> extrema_coefficients(const std::vector<double>& values);

// sum_j c_j T_j(t), by Clenshaw's recurrence.
double sum_t(const double* c, std::size_t count, double t);
// sum_j c_j U_j(t) (second kind), V_j (third: V_1 = 2t - 1), W_j (fourth: W_1 = 2t + 1).
double sum_u(const double* c, std::size_t count, double t);
double sum_v(const double* c, std::size_t count, double t);
double sum_w(const double* c, std::size_t count, double t);

}  // namespace wavecontact::detail::chebyshev
