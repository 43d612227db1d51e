#!/usr/bin/env python3
"""Fit the rational approximations of rng/inverse_normal.hpp (needs mpmath only).

Three pieces, each P(x)/Q(x) with Q(0) = 1, fitted for least relative error in 60-digit arithmetic:
  centre  |q| <= 0.425, q = u - 1/2:  Phi^-1(u) = q * P(K - q^2)/Q(K - q^2), K = 0.425^2 rounded to double
          (expanded about the edge: in powers of q^2 the numerator and denominator both nearly vanish there and
          their Horner sums cancel by three orders of magnitude)
  near    t = sqrt(-2 log p) in [t0, 9], p = min(u, 1 - u): |Phi^-1(u)| = P(t - t0)/Q(t - t0)
  far     t in [9, 38] (p down to 2^-1022):                 |Phi^-1(u)| = P(t - 9)/Q(t - 9)
The fit: Sanathanan-Koerner iteration (linear least squares on P - f*Q, reweighted by the previous Q) on
Chebyshev points, then Lawson reweighting towards the minimax error. Prints the C++ coefficient tables and the
relative error of each fit on a fine grid (the fit's own error; rounding in double comes on top).
"""
import mpmath as mp

mp.mp.dps = 60
SQRT2 = mp.sqrt(2)
# The near piece is shifted by t0 rounded to double, the value the C++ code subtracts.
T0 = mp.mpf(float(mp.sqrt(-2 * mp.log(mp.mpf("0.075")))))


def phi_inv_centre(s):  # Phi^-1(1/2 + q) / q at s = q^2
    q = mp.sqrt(s)
    if q == 0:
        return mp.sqrt(2 * mp.pi)
    return SQRT2 * mp.erfinv(2 * q) / q


def phi_inv_tail(t):  # z > 0 with Phi(-z) = p = exp(-t^2/2)
    logp = -t * t / 2
    g = lambda z: mp.log(mp.erfc(z / SQRT2) / 2) - logp
    return mp.findroot(g, t - mp.log(t) / t if t > 1 else t)


def cheb_points(a, b, n):
    return [(a + b) / 2 + (b - a) / 2 * mp.cos(mp.pi * (k + mp.mpf(1) / 2) / n) for k in range(n)]


def evalr(p, q, x):
    return mp.polyval(p[::-1], x) / mp.polyval(q[::-1], x)


def lstsq(rows, rhs):
    A = mp.matrix(rows)
    b = mp.matrix(rhs)
    x, _ = mp.qr_solve(A, b)
    return [x[i] for i in range(A.cols)]


def fit(xs, fs, m, n, iters=12, lawson=40):
    w = [mp.mpf(1)] * len(xs)
    qprev = [mp.mpf(1)] * len(xs)
    p = q = None

    def solve(weights, qp):
        rows, rhs = [], []
        for x, f, wi, qv in zip(xs, fs, weights, qp):
            s = mp.sqrt(wi) / (abs(f) * qv)
            rows.append([s * x**i for i in range(m + 1)] + [-s * f * x**j for j in range(1, n + 1)])
            rhs.append(s * f)
        c = lstsq(rows, rhs)
        return c[: m + 1], [mp.mpf(1)] + c[m + 1:]

    for _ in range(iters):
        p, q = solve(w, qprev)
        qprev = [mp.polyval(q[::-1], x) for x in xs]
    for _ in range(lawson):
        err = [abs(evalr(p, q, x) / f - 1) for x, f in zip(xs, fs)]
        w = [wi * e for wi, e in zip(w, err)]
        tot = sum(w)
        w = [wi / tot for wi in w]
        for _ in range(2):
            p, q = solve(w, qprev)
            qprev = [mp.polyval(q[::-1], x) for x in xs]
    return p, q


def max_rel(p, q, f, a, b, n=2000):
    worst = mp.mpf(0)
    for k in range(n + 1):
        x = a + (b - a) * k / n
        worst = max(worst, abs(evalr(p, q, x) / f(x) - 1))
    return worst


def piece(name, f, a, b, m, n, shift):
    xs = cheb_points(a, b, 120)
    fs = [f(x) for x in xs]
    p, q = fit([x - shift for x in xs], fs, m, n)
    err = max_rel(p, q, lambda x: f(x + shift), a - shift, b - shift, 600)
    print(f"// {name}: max relative error of the fit {mp.nstr(err, 3)}")
    fmt = lambda v: float(v).hex()
    print(f"{name}_p = {{{', '.join(fmt(c) for c in p)}}}")
    print(f"{name}_q = {{{', '.join(fmt(c) for c in q)}}}")


if __name__ == "__main__":
    import sys
    deg = int(sys.argv[1]) if len(sys.argv) > 1 else 8
    print(f"// t0 = {float(T0).hex()}")
    if "tails" not in sys.argv:
        print(f"// K = {float(mp.mpf('0.425') ** 2).hex()}")
        K = mp.mpf(float(mp.mpf("0.425") ** 2))
        piece("centre", lambda x: phi_inv_centre(K - x), mp.mpf(0), K, deg, deg, 0)
    if "centre" in sys.argv:
        sys.exit()
    piece("near", phi_inv_tail, T0, mp.mpf(9), deg, deg, T0)
    piece("far", phi_inv_tail, mp.mpf(9), mp.mpf(38), deg, deg, mp.mpf(9))
