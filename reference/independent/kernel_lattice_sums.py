#!/usr/bin/env python3
"""Independent evaluation of the kernel case's lattice-sum error (condition (20)), numpy only.

Written from the kernels' published shapes (Schoenberg's B-splines M4, M5, M6 in Monaghan's 2005
form; Wendland's C2, C4, C6 in Dehnen & Aly 2012, Table 1), rescaled to support radius h, with the
normalisation found here by Gauss-Legendre quadrature on each polynomial piece (exact to round-off),
not taken from sph/. The bounds C of verification/cases/operators/kernel.cpp (Theory) are 1.5 times
the largest err n^p this prints.

Error definition (the case's): over the shifts h' = h + k dx/16, k = 0 .. 16 P - 1, one period P dx
of the knots (P = 2, 5, 3 for M4, M5, M6; 2 for the one-piece Wendland functions), the worst of
|dx^d sum_j W(|x_j|, h') - 1| (h'/h)^p, p the order the kernel's smoothness predicts.

Usage: kernel_lattice_sums.py [n ...]     (default 64 128 256 512); prints err and err n^p_bound.
"""
import math
import sys

import numpy as np

H = 0.137  # the case's default support radius


def pp(*terms):
    """sum_k c_k (a_k - q)_+^m_k: a B-spline in q = r/h."""
    return lambda q: sum(c * np.maximum(a - q, 0.0) ** m for c, a, m in terms)


def wend(m, *coef):
    """(1 - q)_+^m (c0 + c1 q + ...): a Wendland function."""
    return lambda q: np.maximum(1.0 - q, 0.0) ** m * sum(c * q ** i for i, c in enumerate(coef))


# name: (shape per dimension, knots, predicted order per dimension, bound exponent p per dimension)
KERNELS = {
    "cubic_spline": ([pp((1, 1, 3), (-4, .5, 3))] * 3, [.5, 1], [4, 4.5, 5], [3.5, 4.0, 4.5]),
    "quartic_spline": ([pp((1, 1, 4), (-5, .6, 4), (10, .2, 4))] * 3, [.2, .6, 1], [5, 5.5, 6], [4.2, 4.7, 5.2]),
    "quintic_spline": ([pp((1, 1, 5), (-6, 2 / 3, 5), (15, 1 / 3, 5))] * 3, [1 / 3, 2 / 3, 1], [6, 6.5, 7],
                       [5.2, 5.7, 6.2]),
    "wendland_c2": ([wend(3, 1, 3), wend(4, 1, 4), wend(4, 1, 4)], [1], [4, 5, 6], [3.5, 4.5, 5.5]),
    "wendland_c4": ([wend(5, 1, 5, 8), wend(6, 1, 6, 35 / 3), wend(6, 1, 6, 35 / 3)], [1], [6, 7, 8],
                    [5.5, 6.5, 7.5]),
    "wendland_c6": ([wend(7, 1, 7, 19, 21), wend(8, 1, 8, 25, 32), wend(8, 1, 8, 25, 32)], [1], [8, 9, 10],
                    [7.5, 8.5, 9.5]),
}


def norm(shape, knots, d):
    """1 / integral of shape(r) over the unit ball in d dimensions (support 1)."""
    x, w = np.polynomial.legendre.leggauss(20)
    edges = [0.0] + sorted(knots)
    total = 0.0
    for a, b in zip(edges, edges[1:]):
        r = (b - a) / 2 * x + (a + b) / 2
        total += (b - a) / 2 * np.sum(w * r ** (d - 1) * shape(r))
    return 1.0 / ({1: 2.0, 2: 2 * math.pi, 3: 4 * math.pi}[d] * total)


def period(knots):
    for p in range(1, 13):
        if all(abs(p * q - round(p * q)) < 1e-9 for q in knots):
            return max(p, 2)
    return 12


def shells(k, d):
    """{m: how many lattice points j in [-k, k]^d have |j|^2 = m}."""
    a = np.arange(-k, k + 1) ** 2
    if d == 1:
        s = a
    elif d == 2:
        s = (a[:, None] + a[None, :]).ravel()
    else:
        s = (a[:, None, None] + a[None, :, None] + a[None, None, :]).ravel()
    counts = np.bincount(s)
    m = np.nonzero(counts)[0]
    return m, counts[m]


def error(shape, sigma, knots, d, n, p):
    dx, P = 1.0 / n, period(knots)
    k = math.ceil((H + P * dx) / dx)
    m, c = shells(k, d)
    r = np.sqrt(m) * dx
    worst = 0.0
    for s in range(16 * P):
        h = H + s * dx / 16
        terms = c * dx ** d * sigma / h ** d * shape(r / h)
        e = abs(math.fsum(list(terms) + [-1.0])) * (h / H) ** p
        worst = max(worst, e)
    return worst


def main():
    levels = [int(a) for a in sys.argv[1:]] or [64, 128, 256, 512]
    for name, (shapes, knots, order, bound_p) in KERNELS.items():
        for d in (1, 2, 3):
            sigma = norm(shapes[d - 1], knots, d)
            errs = [error(shapes[d - 1], sigma, knots, d, n, order[d - 1]) for n in levels]
            scaled = ", ".join(f"{e * n ** bound_p[d - 1]:.4g}" for e, n in zip(errs, levels))
            print(f"{name} {d}D err: " + ", ".join(f"{e:.4e}" for e in errs) +
                  f"; err n^{bound_p[d - 1]}: {scaled}")


if __name__ == "__main__":
    main()
