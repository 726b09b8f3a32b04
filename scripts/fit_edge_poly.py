#!/usr/bin/env python3
"""Minimax quadratic for the LTC edge integral's theta / sin(theta) in x = cos(theta).

Seed 001 fits p(x) = 0.33735186 x^2 - 0.89665001 x + pi/2 on [0, 1] and reflects
for x < 0 (theta/sin = pi / sqrt(1 - x^2) - p(|x|)). Measured here: its largest
relative error on [0, 1) is 1.15e-2, and p(1) = 1.0115, so every small edge (x -> 1)
is 1.15% too large. This script fits the same three-coefficient quadratic for the
smallest largest relative error with p(1) = 1 (exact for small edges), by Nelder-Mead
on a 4001-point grid; it prints the coefficients used in templates/method/ltc.glsl
and both fits' errors.

Usage: python3 scripts/fit_edge_poly.py      (pure Python, deterministic, ~10 s)
"""
import math

XS = [i / 4000 * 0.99999 for i in range(4001)]
HS = [math.acos(x) / math.sqrt(1 - x * x) for x in XS]


def max_rel(p):
    return max(abs(p(x) / h - 1) for x, h in zip(XS, HS))


def nelder_mead(f, x0, step, iters):
    n = len(x0)
    pts = [list(x0)] + [[x0[k] + (step if k == i else 0) for k in range(n)] for i in range(n)]
    vals = [f(p) for p in pts]
    for _ in range(iters):
        order = sorted(range(n + 1), key=lambda i: vals[i])
        pts, vals = [pts[i] for i in order], [vals[i] for i in order]
        c = [sum(p[k] for p in pts[:-1]) / n for k in range(n)]
        xr = [2 * c[k] - pts[-1][k] for k in range(n)]
        fr = f(xr)
        if fr < vals[0]:
            xe = [3 * c[k] - 2 * pts[-1][k] for k in range(n)]
            fe = f(xe)
            pts[-1], vals[-1] = (xe, fe) if fe < fr else (xr, fr)
        elif fr < vals[-2]:
            pts[-1], vals[-1] = xr, fr
        else:
            xc = [0.5 * (c[k] + pts[-1][k]) for k in range(n)]
            fc = f(xc)
            if fc < vals[-1]:
                pts[-1], vals[-1] = xc, fc
            else:
                for i in range(1, n + 1):
                    pts[i] = [0.5 * (pts[0][k] + pts[i][k]) for k in range(n)]
                    vals[i] = f(pts[i])
    return pts[0], vals[0]


def main():
    seed = lambda x: 0.33735186 * x * x - 0.89665001 * x + math.pi / 2
    print(f"seed 001: max relative error {max_rel(seed):.4e}, p(1) - 1 = {seed(1.0) - 1:.4e}")
    quad = lambda c: (lambda x: (c[0] * x + c[1]) * x + (1 - c[0] - c[1]))
    c, err = nelder_mead(lambda c: max_rel(quad(c)), [0.337, -0.897], 0.01, 3000)
    print(f"ours (p(1) = 1): c2 = {c[0]:.8f}, c1 = {c[1]:.8f}, c0 = {1 - c[0] - c[1]:.8f}, "
          f"max relative error {err:.4e}")


if __name__ == "__main__":
    main()
