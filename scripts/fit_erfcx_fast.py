#!/usr/bin/env python3
"""Fits the short erfcx of templates/method/peak_microfacet.glsl (AL_FAST_ARC) and prints
its coefficients.

erfcx(x) = exp(x^2) erfc(x) for x >= 0 is written t Q(t) with t = 1 / (1 + x/2), which maps
[0, inf) onto (0, 1]; Q is smooth there (Q(1) = 1, Q(t) -> 1 / (2 sqrt(pi)) as t -> 0, where
erfcx(x) ~ 1 / (x sqrt(pi))). Q is a polynomial of degree DEG in t, fitted by least squares
of the relative error on 400 Chebyshev nodes in t, reweighted toward the largest errors
(30 passes: near-minimax), then written in the power basis of t and checked with every
operation rounded to fp32 on x = 0, 0.001, ..., 20 and 1e6.

Reference values: math.erfc(x) exp(x^2) below x = 25, the asymptotic series beyond.

Usage: python3 scripts/fit_erfcx_fast.py   (standard library only, under a second)
"""
import math
import struct

DEG = 9
NODES = 400


def erfcx(x):
    if x < 25:
        return math.erfc(x) * math.exp(x * x)
    s, term = 1.0, 1.0
    for k in range(1, 8):
        term *= -(2 * k - 1) / (2 * x * x)
        s += term
    return s / (x * math.sqrt(math.pi))


def q_of_t(t):
    return erfcx(2 * (1 - t) / t) / t


def cheb(n, s):
    t = [1.0, s]
    while len(t) < n + 1:
        t.append(2 * s * t[-1] - t[-2])
    return t[: n + 1]


def solve(a, b):
    n = len(a)
    m = [row[:] + [bb] for row, bb in zip(a, b)]
    for i in range(n):
        p = max(range(i, n), key=lambda r: abs(m[r][i]))
        m[i], m[p] = m[p], m[i]
        for r in range(n):
            if r != i:
                f = m[r][i] / m[i][i]
                for c in range(i, n + 1):
                    m[r][c] -= f * m[i][c]
    return [m[i][n] / m[i][i] for i in range(n)]


def fit():
    ts = [0.5 - 0.5 * math.cos(math.pi * (k + 0.5) / NODES) for k in range(NODES)]
    ys = [q_of_t(t) for t in ts]
    basis = [cheb(DEG, 2 * t - 1) for t in ts]
    weight = [1.0] * NODES
    for _ in range(30):
        a = [[0.0] * (DEG + 1) for _ in range(DEG + 1)]
        b = [0.0] * (DEG + 1)
        for row, y, w in zip(basis, ys, weight):
            for i in range(DEG + 1):
                b[i] += w * row[i] / y
                for j in range(DEG + 1):
                    a[i][j] += w * row[i] * row[j] / (y * y)
        coef = solve(a, b)
        errs = [abs(sum(c * r for c, r in zip(coef, row)) - y) / y for row, y in zip(basis, ys)]
        worst = max(errs)
        weight = [w * (0.5 + e / worst) for w, e in zip(weight, errs)]
    # Chebyshev in s = 2 t - 1 to the power basis of t: T_(k+1) = 2 (2t - 1) T_k - T_(k-1).
    rows = [[1.0], [-1.0, 2.0]]
    while len(rows) < DEG + 1:
        n = [0.0] * (len(rows[-1]) + 1)
        for i, x in enumerate(rows[-1]):
            n[i + 1] += 4 * x
            n[i] -= 2 * x
        for i, x in enumerate(rows[-2]):
            n[i] -= x
        rows.append(n)
    power = [0.0] * (DEG + 1)
    for k in range(DEG + 1):
        for i, x in enumerate(rows[k]):
            power[i] += coef[k] * x
    return power


def f32(x):
    return struct.unpack("f", struct.pack("f", x))[0]


def check(power):
    p32 = [f32(c) for c in power]
    worst, at = 0.0, 0.0
    for x in [k * 0.001 for k in range(20001)] + [1e6]:
        t = f32(1 / f32(1 + f32(0.5 * f32(x))))
        acc = p32[-1]
        for c in reversed(p32[:-1]):
            acc = f32(f32(acc * t) + c)
        e = abs(f32(t * acc) - erfcx(x)) / erfcx(x)
        if e > worst:
            worst, at = e, x
    return worst, at


def main():
    power = fit()
    worst, at = check(power)
    print(f"// Q(t), degree {DEG}, power basis of t (highest first); fp32 max relative error "
          f"{worst:.2g} at x = {at:g}")
    for c in reversed(power):
        print(f"    AL_R({c:.9e})")


if __name__ == "__main__":
    main()
