#!/usr/bin/env python3
"""Write each curved light's spinning proxy polygon as an ordinary polygon case.

Usage: proxy_polygon_cases.py IN.cases.json OUT.cases.json [--sides K] [--lights L,...]

For every disk, sphere or ellipsoid case of IN, the regular K-gon that
templates/light/spin_polygon.glsl shades at that point with orient=rim (the ellipse of
light/ellipse_record.glsl: a disk itself, a sphere's or an ellipsoid's silhouette; the
polygon's area the ellipse's, one edge crossing the rim where the line of the
mirror ray meets the light's plane), as a two-sided polygon light with the same
p, n, v and material. K <= 8 gives one case per light with the same id; a larger
K is cut into a fan of convex pieces of at most 8 vertices, ids `ID#0`, `ID#1`,
... (sum their results). Points that see no light (behind a one-sided disk,
inside a sphere or ellipsoid) are left out.

What it is for: the oracle on OUT against the oracle on IN is the proxy's own
error; a polygon method on OUT (K = 8) against the oracle on OUT is that method's
error on the same lights seen from the same points, the like-for-like yardstick
for the spinning polygon (docs/curved-lights.md). This is a second, independent
construction of the proxy (double precision, written from the template's header,
not from its code).
"""
import argparse, json, math


def add(a, b): return [x + y for x, y in zip(a, b)]
def sub(a, b): return [x - y for x, y in zip(a, b)]
def mul(s, a): return [s * x for x in a]
def dot(a, b): return sum(x * y for x, y in zip(a, b))
def norm(a): return math.sqrt(dot(a, a))
def unit(a): return mul(1.0 / norm(a), a)


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def perpendicular_pair(z):
    """Two unit vectors completing z to an orthonormal basis (any pair does: the
    rim rule fixes the polygon's turn from p and r alone)."""
    a = [1.0, 0.0, 0.0] if abs(z[0]) < 0.9 else [0.0, 1.0, 0.0]
    e1 = unit(cross(z, a))
    return e1, cross(z, e1)


def ellipse(light, p):
    """(centre - p, U, V): the light's ellipse as conjugate semi-diameters, or None
    when p sees nothing."""
    t = light["type"]
    if t == "disk":
        rel, U, V = sub(light["center"], p), light["u"], light["v"]
        side = -dot(cross(U, V), rel)
        return (rel, U, V) if side > 0 or (light.get("two_sided") and side < 0) else None
    if t == "sphere":
        to_c = sub(light["center"], p)
        d, R = norm(to_c), abs(light["radius"])
        if not d > R > 0:
            return None
        rho2 = (d - R) * (d + R) / (d * d)
        e1, e2 = perpendicular_pair(mul(1.0 / d, to_c))
        s = R * math.sqrt(rho2)
        return mul(rho2, to_c), mul(s, e1), mul(s, e2)
    if t == "ellipsoid":
        axes = light["axes"]
        to_c = sub(light["center"], p)
        yp = [-dot(a, to_c) / dot(a, a) for a in axes]  # A^-1 (p - c), A's columns orthogonal
        tt = norm(yp)
        if not tt > 1:
            return None
        rho2 = (tt - 1) * (tt + 1) / (tt * tt)
        e1, e2 = perpendicular_pair(mul(1.0 / tt, yp))
        rho = math.sqrt(rho2)
        image = lambda e: mul(rho, add(add(mul(e[0], axes[0]), mul(e[1], axes[1])), mul(e[2], axes[2])))
        return mul(rho2, to_c), image(e1), image(e2)
    return None


def proxy(case, k):
    p = case["p"]
    n, v = unit(case["n"]), unit(case["v"])
    r = unit(sub(mul(2 * dot(n, v), n), v))
    e = ellipse(case["light"], p)
    if e is None:
        return None
    C, U, V = e
    if dot(cross(U, V), C) < 0:  # light/ellipse_record.glsl: W = unit(U x V) points away from p
        V = mul(-1.0, V)
    UxV = cross(U, V)
    area = norm(UxV)
    W = mul(1.0 / area, UxV)
    da, db = cross(V, W), cross(W, U)  # dual basis of (U, V, W), times area
    pa, pb, ph = -dot(C, da) / area, -dot(C, db) / area, -dot(C, W)
    ra, rb, rh = dot(r, da) / area, dot(r, db) / area, dot(r, W)
    step = 2 * math.pi / k
    scale = math.sqrt(step / math.sin(step))  # area of the k-gon = area of the unit disc
    apothem = scale * math.cos(step / 2)
    delta = math.acos(min(apothem, 1.0))  # half the angle an edge spans inside the disc
    # r' - centre is along rh p_ab - ph r_ab; an edge's mid-angle sits delta past it.
    theta0 = math.atan2(rh * pb - ph * rb, rh * pa - ph * ra) + delta + step / 2
    return [add(add(p, C), mul(scale, add(mul(math.cos(theta0 - i * step), U),
                                           mul(math.sin(theta0 - i * step), V))))
            for i in range(k)]


def fan(k):
    """Index lists of convex pieces of a k-gon, each at most 8 vertices."""
    pieces, j = [list(range(min(8, k)))], 7
    while j < k - 1:
        pieces.append([0] + list(range(j, min(j + 7, k))))
        j += 6
    return pieces


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("cases")
    ap.add_argument("out")
    ap.add_argument("--sides", type=int, default=8, help="K, even, >= 4 (default 8)")
    ap.add_argument("--lights", default="disk,sphere,ellipsoid")
    a = ap.parse_args()
    if a.sides < 4 or a.sides % 2:
        ap.error(f"--sides {a.sides}: the rim rule needs an even K >= 4")
    keep = set(a.lights.split(","))
    with open(a.cases) as f:
        doc = json.load(f)
    out = []
    for case in doc.get("cases", []):
        if case.get("light", {}).get("type") not in keep:
            continue
        verts = proxy(case, a.sides)
        if verts is None:
            continue
        pieces = fan(a.sides)
        for m, idx in enumerate(pieces):
            c = dict(case)
            c["id"] = case["id"] if len(pieces) == 1 else f"{case['id']}#{m}"
            c["light"] = {"type": "polygon", "vertices": [verts[i] for i in idx], "two_sided": True}
            out.append(c)
    with open(a.out, "w") as f:
        json.dump({"format": doc.get("format"), "cases": out}, f, indent=1)
        f.write("\n")


if __name__ == "__main__":
    main()
