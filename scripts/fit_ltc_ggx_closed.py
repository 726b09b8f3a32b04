#!/usr/bin/env python3
"""Closed-form GGX LTC coefficients: polynomials in the table's grid coordinates.

Reads data/ltc/ltc_ggx.txt (64 x 64 cells, columns i j a b c d A B K error, K the
second lobe's weight, 0 for GGX, which has one; grid of
include/arealight/ltc_table.hpp: u = i / 63 over rho = sqrt(alpha), w = j / 63 with
cos theta_v = 1 - w^2) and writes templates/method/ltc_ggx_fit.glsl, the functions that
method=ltc,table=fit evaluates instead of sampling the two textures.

The matrix Minv = [[a, 0, b], [0, c, 0], [d, 0, 1]] is not fitted coefficient by
coefficient: a, b and c reach ~477 at small alpha, and there the cells' (a, d) lie on
two branches of a near-degenerate optimum (rows i < 4 and i >= 4 differ in a and d by
up to 2x while the lobe they describe agrees). Each cell is taken to the lobe's own,
smooth quantities instead:
  phi  = atan2(b, a), the lobe axis' angle from n (the direction Minv maps to z);
         fitted as q = (phi - theta_v) / alpha, the off-specular shift in lobe widths,
         so that an error in q moves the axis by that fraction of the lobe's width;
  sx   = |(a, b)|^2 / (a - b d), sy = c |(a, b)| / (a - b d): the lobe's inverse
         widths along and across the plane of incidence (the Jacobian of the
         normalised map at the axis); fitted as log(sx alpha), log(sy alpha cos theta_v)
         (sy alpha ~ 0.5 / cos theta_v at small alpha: the footprint's elongation);
  d    = the skew row, fitted as it is, from rows i >= 4 only (the branch rows
         i < 4 left are where the lobe does not depend on it to the fit's accuracy);
  T    = A + B (the magnitude with F = 1) and B - w^10 (Schlick's weight at the
         lobe's axis for small alpha is (1 - cos theta_v)^5 = w^10).
The inverse (the shader's): a = N cos phi, b = N sin phi, N = sx (cos phi - d sin phi),
c = sy (cos phi - d sin phi).

Cells: j <= 62 (row 63 is cos theta_v = 0, fitted at 1e-3, and its cells scatter; the
shader clamps w to 62/63, cos theta_v >= 0.0315). Each quantity is a tensor Chebyshev
series of degree (NU, NW) in x = 2 u - 1, y = 2 w / (62/63) - 1, fitted by least
squares with Huber reweighting (3 passes, k = 1.5 MAD: the grazing rows' scattered
cells do not pull the fit), then written in the power basis of x and y (Horner, fp32).

Usage: python3 scripts/fit_ltc_ggx_closed.py   (standard library only, ~1 min)
writes templates/method/ltc_ggx_fit.glsl and prints each quantity's fit error.
"""
import math
import os
import struct

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
TABLE = "data/ltc/ltc_ggx.txt"
OUT = "templates/method/ltc_ggx_fit.glsl"
SIZE = 64
JMAX = 62
NU, NW = 9, 12
NAMES = ["q", "lsx", "lsy", "d", "t", "b"]
DOC = {
    "q": "(phi - theta_v) / alpha: the lobe axis' shift from the mirror direction, in widths",
    "lsx": "log(sx alpha): the lobe's inverse width in the plane of incidence",
    "lsy": "log(sy alpha cos theta_v): its inverse width across, less the footprint's 1 / cos",
    "d": "Minv's skew coefficient d",
    "t": "A + B: the magnitude with F = 1",
    "b": "B - w^10: the Fresnel part less Schlick's weight at the mirror direction",
}


def read_table():
    cells, rho_min, rho_max = {}, None, None
    for line in open(os.path.join(ROOT, TABLE)):
        if line.startswith("# rho_min"):
            rho_min = float(line.split()[2])
        elif line.startswith("# rho_max"):
            rho_max = float(line.split()[2])
        elif not line.startswith("#"):
            f = line.split()
            cells[int(f[0]), int(f[1])] = [float(x) for x in f[2:]]
    return cells, rho_min, rho_max


def quantities(cell, alpha, w):
    a, b, c, d, amp_a, amp_b = cell[:6]
    phi = math.atan2(b, a)
    n = math.hypot(a, b)
    den = a - b * d
    cos_v = max(1 - w * w, 1e-3)  # the fit's own floor (fit/ltc_fit.cpp)
    theta = math.acos(cos_v)
    return [(phi - theta) / alpha, math.log(n * n / den * alpha),
            math.log(c * n / den * alpha * cos_v), d, amp_a + amp_b, amp_b - w ** 10]


def cheb(n, x):
    t = [1.0, x]
    while len(t) < n + 1:
        t.append(2 * x * t[-1] - t[-2])
    return t[: n + 1]


def cholesky_solve(m, v):
    n = len(v)
    low = [[0.0] * n for _ in range(n)]
    for i in range(n):
        for k in range(i + 1):
            s = m[i][k] - sum(low[i][p] * low[k][p] for p in range(k))
            low[i][k] = math.sqrt(s) if i == k else s / low[k][k]
    y = [0.0] * n
    for i in range(n):
        y[i] = (v[i] - sum(low[i][p] * y[p] for p in range(i))) / low[i][i]
    x = [0.0] * n
    for i in reversed(range(n)):
        x[i] = (y[i] - sum(low[p][i] * x[p] for p in range(i + 1, n))) / low[i][i]
    return x


def weighted_ls(basis, target, weight):
    n = len(basis[0])
    m = [[0.0] * n for _ in range(n)]
    v = [0.0] * n
    for row, t, wt in zip(basis, target, weight):
        if wt == 0:
            continue
        for p in range(n):
            rp = row[p] * wt
            v[p] += rp * t
            mp = m[p]
            for q in range(p + 1):
                mp[q] += rp * row[q]
    for p in range(n):
        for q in range(p + 1, n):
            m[p][q] = m[q][p]
    return cholesky_solve(m, v)


def robust_fit(basis, target, mask):
    weight = [1.0 if k else 0.0 for k in mask]
    for _ in range(3):
        coef = weighted_ls(basis, target, weight)
        res = [sum(c * b for c, b in zip(coef, row)) - t for row, t in zip(basis, target)]
        used = sorted(abs(r) for r, k in zip(res, mask) if k)
        scale = max(1.4826 * used[len(used) // 2], 1e-12)
        weight = [0.0 if not k else min(1.0, 1.5 * scale / max(abs(r), 1e-300))
                  for r, k in zip(res, mask)]
    return coef


def cheb_to_power(n):
    """Rows: T_k(x) as power-basis coefficients."""
    rows = [[1.0] + [0.0] * n, [0.0, 1.0] + [0.0] * (n - 1)]
    while len(rows) < n + 1:
        a, b = rows[-1], rows[-2]
        rows.append([2 * (a[p - 1] if p > 0 else 0.0) - b[p] for p in range(n + 1)])
    return rows[: n + 1]


def to_power(coef):
    pu, pw = cheb_to_power(NU), cheb_to_power(NW)
    out = [[0.0] * (NW + 1) for _ in range(NU + 1)]
    for k in range(NU + 1):
        for l in range(NW + 1):
            c = coef[k * (NW + 1) + l]
            for p in range(NU + 1):
                for q in range(NW + 1):
                    out[p][q] += c * pu[k][p] * pw[l][q]
    return out


def f32(x):
    return struct.unpack("f", struct.pack("f", x))[0]


def horner32(power, x, y):
    """The shader's evaluation, every operation rounded to fp32 (fma as mul + add)."""
    x, y = f32(x), f32(y)
    acc = 0.0
    for p in reversed(range(NU + 1)):
        row = 0.0
        for q in reversed(range(NW + 1)):
            row = f32(f32(row * y) + f32(power[p][q]))
        acc = f32(f32(acc * x) + row)
    return acc


def main():
    cells, rho_min, rho_max = read_table()
    pts = [(i, j) for i in range(SIZE) for j in range(JMAX + 1)]
    basis, values = [], []
    for i, j in pts:
        u, w = i / (SIZE - 1), j / (SIZE - 1)
        rho = rho_min + u * (rho_max - rho_min)
        cu, cw = cheb(NU, 2 * u - 1), cheb(NW, 2 * w / (JMAX / (SIZE - 1)) - 1)
        basis.append([cu[k] * cw[l] for k in range(NU + 1) for l in range(NW + 1)])
        values.append(quantities(cells[i, j], rho * rho, w))
    fits = {}
    report = []
    for t, name in enumerate(NAMES):
        mask = [not (name == "d" and i < 4) for i, j in pts]
        coef = robust_fit(basis, [v[t] for v in values], mask)
        power = to_power(coef)
        errs = []
        for (i, j), v, k in zip(pts, values, mask):
            x, y = 2 * i / (SIZE - 1) - 1, 2 * j / JMAX - 1
            errs.append((abs(horner32(power, x, y) - v[t]), i, j, k))
        inner = [e for e in errs if e[3] and e[2] <= 60]
        rms = math.sqrt(sum(e[0] ** 2 for e in inner) / len(inner))
        worst = max(inner)
        worst_all = max(e for e in errs if e[3])
        line = (f"{name:4s} rows j <= 60: rms {rms:.2e}, max {worst[0]:.2e} at (i, j) = "
                f"({worst[1]}, {worst[2]}); all fitted rows: max {worst_all[0]:.2e} at "
                f"({worst_all[1]}, {worst_all[2]}); sum |power coefficients| "
                f"{sum(abs(c) for r in power for c in r):.3g}")
        print(line)
        report.append(line)
        fits[name] = power
    write_template(fits, report, rho_min, rho_max)


def poly_text(name, power):
    lines = [f"// {DOC[name]}.", f"real al_ltc_fit_{name}(real x, real y) {{"]
    for p in range(NU + 1):
        expr = f"AL_R({power[p][NW]:.9e})"
        for q in reversed(range(NW)):
            expr = f"{expr} * y + AL_R({power[p][q]:.9e})" if q == NW - 1 else \
                f"({expr}) * y + AL_R({power[p][q]:.9e})"
        lines.append(f"    real r{p} = {expr};")
    acc = f"r{NU}"
    for p in reversed(range(NU)):
        acc = f"({acc}) * x + r{p}" if p < NU - 1 else f"{acc} * x + r{p}"
    lines.append(f"    return {acc};")
    lines.append("}")
    return "\n".join(lines)


def write_template(fits, report, rho_min, rho_max):
    head = [
        f"// generated by arealight from {TABLE} by scripts/fit_ltc_ggx_closed.py; do not edit",
        "// GGX LTC coefficients in closed form (method=ltc,table=fit): per quantity a",
        f"// polynomial of degree {NU} in x = 2 u - 1 and {NW} in y = 2 w / (62/63) - 1, the",
        "// table's grid coordinates (u over rho = sqrt(alpha), w = sqrt(1 - cos theta_v);",
        "// include/arealight/ltc_table.hpp), least squares with Huber weights on the cells",
        "// j <= 62 (the script's docstring: which quantities, and why these). Domain:",
        "// x, y in [-1, 1] (the caller clamps). Error against the table's cells, fp32",
        "// evaluation (the script's output):",
    ]
    head += ["//   " + r for r in report]
    head += [
        f"// rho_min {rho_min:.17g}, rho_max {rho_max:.17g} (the table's header).",
        "",
    ]
    body = [poly_text(n, fits[n]) for n in NAMES]
    text = "\n".join(head) + "\n" + "\n\n".join(body) + "\n"
    with open(os.path.join(ROOT, OUT), "w") as f:
        f.write(text)
    print(f"wrote {OUT}")


if __name__ == "__main__":
    main()
