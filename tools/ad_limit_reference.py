#!/usr/bin/env python3
"""Reference values of the limiting Anderson-Darling distribution, independent of Marsaglia & Marsaglia (2004).

A^2 -> sum_j Y_j^2 / (j (j + 1)) with Y_j iid N(0,1) (Anderson & Darling 1952), whose characteristic function is
phi(s) = prod_j (1 - 2is/(j(j+1)))^(-1/2). Gil-Pelaez inversion: P(A^2 > x) = 1/2 + (1/pi) int_0^inf
Im(exp(-isx) phi(s))/s ds. The product is taken over j <= 3000 with the rest to first order (exp(is/(J+1))).
Needs mpmath. Prints x and P(A^2 > x).
"""
import cmath
import math

from mpmath import quad

J = 3000


def log_phi(s):
    acc = sum(cmath.log(1 - 2j * s / (k * (k + 1))) for k in range(1, J + 1))
    return -0.5 * (acc - 2j * s / (J + 1))


def upper_tail(x):
    def f(s):
        s = float(s)
        if s == 0:
            return 1.0 - x  # the limit: E[A^2] - x
        return cmath.exp(-1j * s * x + log_phi(s)).imag / s
    return 0.5 + quad(f, [0, 1, 5, 20, 60, 200, 600, 2000]) / math.pi


if __name__ == "__main__":
    for x in [0.5, 1.0, 1.5, 1.933, 2.492, 3.857, 6.0]:
        print(f"{x} {float(upper_tail(x)):.7f}")
