#!/usr/bin/env python3
"""Fits GGX's D by the moment mixture of templates/method/peak_microfacet.glsl
(fit=tuned) and prints the template's tables.

D_GGX(theta; alpha) ~ c0/pi + sum_j w_j (N_j + 2)/(2 pi) cos^N_j(theta), j = 1..3,
N_j = rho_j (2/alpha^2 - 2) (at least 1), c0 = 1 - sum w_j (normalized by
construction). Per alpha, Nelder-Mead (warm-started from the previous alpha) minimizes
the RMS over theta of (a) the relative error of the cumulative int_cap D dh about n
and (b) the error of D on patches of solid angle 0.003, 0.03 and 0.3 sr, both against
the score metric's absolute floor 0.01 (shared/tools/score --floor 1e-2).

Usage: python3 scripts/fit_peak_mixture.py > tables.glsl   (pure Python, ~10 min)
"""
import json
import math
import sys

K = 3
ALPHAS = [0.001, 0.002, 0.004, 0.008, 0.016, 0.03, 0.05, 0.075, 0.1, 0.14, 0.2, 0.27,
          0.35, 0.45, 0.55, 0.65, 0.75, 0.85, 0.95, 1.0]


def d_ggx(c, a):
    a2 = a * a
    q = (1 - c * c) + a2 * c * c
    return a2 / (math.pi * q * q)


def lobe(c, n):
    return (n + 2) / (2 * math.pi) * c ** n


def grid(a):
    th = set()
    for i in range(1, 121):
        th.add(min(1.5707, a * 0.08 * i))
    for i in range(1, 61):
        th.add(1.5707 * i / 60)
    return sorted(th)


def make_crit(a):
    th = grid(a)
    cs = [math.cos(t) for t in th]
    ds = [d_ggx(c, a) for c in cs]
    sn = [math.sin(t) for t in th]

    def crit(p):
        n, w = p[:K], p[K:2 * K]
        c0 = 1 - sum(w)
        errs = []
        gx = gm = 0.0
        prev, dp, sp = 0.0, d_ggx(1.0, a), 0.0
        mp = c0 / math.pi + sum(w[j] * (n[j] + 2) / (2 * math.pi) for j in range(K))
        for t, c, d, s in zip(th, cs, ds, sn):
            m = c0 / math.pi + sum(w[j] * lobe(c, n[j]) for j in range(K))
            h = t - prev
            gx += math.pi * h * (dp * sp + d * s)
            gm += math.pi * h * (mp * sp + m * s)
            prev, dp, mp, sp = t, d, m, s
            errs.append(abs(gm - gx) / max(gx, 0.01))
            for op in (0.003, 0.03, 0.3):
                errs.append(abs(m - d) * op / max(d * op, 0.01))
        return math.sqrt(sum(e * e for e in errs) / len(errs))
    return crit


def nelder_mead(f, x0, step, iters):
    n = len(x0)
    pts = [x0[:]] + [[x0[j] + (step[j] if j == i else 0) for j in range(n)] for i in range(n)]
    vals = [f(p) for p in pts]
    for _ in range(iters):
        order = sorted(range(n + 1), key=lambda i: vals[i])
        pts = [pts[i] for i in order]
        vals = [vals[i] for i in order]
        cen = [sum(p[j] for p in pts[:-1]) / n for j in range(n)]
        xr = [cen[j] + (cen[j] - pts[-1][j]) for j in range(n)]
        fr = f(xr)
        if fr < vals[0]:
            xe = [cen[j] + 2 * (cen[j] - pts[-1][j]) for j in range(n)]
            fe = f(xe)
            pts[-1], vals[-1] = (xe, fe) if fe < fr else (xr, fr)
        elif fr < vals[-2]:
            pts[-1], vals[-1] = xr, fr
        else:
            xc = [cen[j] + 0.5 * (pts[-1][j] - cen[j]) for j in range(n)]
            fc = f(xc)
            if fc < vals[-1]:
                pts[-1], vals[-1] = xc, fc
            else:
                for i in range(1, n + 1):
                    pts[i] = [pts[0][j] + 0.5 * (pts[i][j] - pts[0][j]) for j in range(n)]
                    vals[i] = f(pts[i])
    i = min(range(n + 1), key=lambda i: vals[i])
    return pts[i], vals[i]


def params_from(x, a):
    nb = 2 / (a * a) - 2
    return [max(nb * math.exp(x[j]), 1.0) for j in range(K)] + [abs(x[K + j]) for j in range(K)]


def main():
    # Warm start from 0.001 outwards; the first alpha, fitted from a cold start, lands
    # in a worse minimum than its neighbour, so it takes alpha = 0.002's shape (the
    # mixture is self-similar in theta / alpha there).
    x = [math.log(0.6 * 10 ** (-j)) for j in range(K)] + [0.8 / K] * K
    rows = []
    for a in ALPHAS:
        crit = make_crit(a)

        def f(x):
            return crit(params_from(x, a)) + (1e3 if 1 - sum(abs(t) for t in x[K:]) < 0 else 0)
        x, _ = nelder_mead(f, x, [0.3] * K + [0.1] * K, 600 * K)
        x, v = nelder_mead(f, x, [0.1] * K + [0.03] * K, 600 * K)
        p = params_from(x, a)
        nb = 2 / (a * a) - 2
        # At alpha = 1 every exponent is 1 whatever rho (nb = 0): keep the last rho.
        lrho = [math.log(p[j] / nb) for j in range(K)] if nb > 0 else rows[-1]["lrho"]
        rows.append({"alpha": a, "lrho": lrho, "w": p[K:], "crit": v})
        print(json.dumps(rows[-1]), file=sys.stderr, flush=True)
    rows[0]["lrho"], rows[0]["w"] = rows[1]["lrho"], rows[1]["w"]

    def table(name, xs):
        # A literal the stitcher can suffix (f or lf): always with a point or exponent.
        def lit(x):
            t = f"{x:.6g}"
            return t if any(ch in t for ch in ".e") else t + ".0"
        items = [f"AL_R({lit(x)})" for x in xs]
        lines = [", ".join(items[i:i + 5]) for i in range(0, len(items), 5)]
        return (f"const real {name}[{len(xs)}] = {{\n    " + ",\n    ".join(lines) + "};")
    print(table("AL_PMF_T_LOGA", [math.log(r["alpha"]) for r in rows]))
    for j in range(K):
        print(table(f"AL_PMF_T_LRHO{j}", [r["lrho"][j] for r in rows]))
        print(table(f"AL_PMF_T_W{j}", [r["w"][j] for r in rows]))


if __name__ == "__main__":
    main()
