"""Baseline for the benchmarks: eq. 18's k_1..k_n with SymPy, the way a user would.

    python3 sympy_kcoef.py N
expands s(v) = sin(n x)/n, v = tan(x/2), in powers of 1/(1+v^2) by polynomial division in
z = 1 + v^2 (undetermined coefficients, as in the seed paper) and prints k_1.
"""
import sys

import sympy


def coefficients(n):
    t, z = sympy.symbols("t z")
    # Im((1 + i v)^(2n)) = v P(v^2)
    P = sum((-1) ** m * sympy.binomial(2 * n, 2 * m + 1) * t ** m for m in range(n))
    shifted = sympy.Poly(sympy.expand(P.subs(t, z - 1)), z)
    return [shifted.coeff_monomial(z ** (n - j)) / n for j in range(1, n + 1)]


if __name__ == "__main__":
    print(coefficients(int(sys.argv[1]))[0])
