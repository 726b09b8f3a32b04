#!/usr/bin/env python3
"""Seeded hard light cases (arealight-cases/1) that stress the exact and peak methods.

Usage: gen_curved_cases.py COUNT SEED OUT.json
           [--kind hard|lobe-edge|near|aimed|horizon-peak|extreme|degenerate] [--lights L,...]

--kind hard (default): the lights of --lights (default disk,sphere,ellipsoid; also
polygon: convex 3- to 8-gons facing p, jittered vertices) in turn, for phong, blinn,
beckmann and ggx (in turn), each in one of
  horizon  the light's centre within its own angular size of n's horizon
  large    p close to the light: distance 1.01 to 2.5 times its size
  rim      r aimed 1e-6 to 1e-2 rad off a point of the light's silhouette
  grazing  n.v in [1e-3, 0.05]
(rim and horizon twice as often); sizes 0.03 to 1, axis ratios up to 10, a
third of the disks two-sided; N log-uniform in [1, 1e5], alpha in [1e-3, 1].
--kind lobe-edge: the lights of --lights as in hard, the mirror direction aimed at a
point of the silhouette and moved off it along the silhouette's outward normal by -3 to 3
lobe widths (sqrt(2 / (N + 2)) for phong and blinn, 2 alpha otherwise): the lobe just
inside or just outside the light's edge.
--kind near: p at a distance eps in {1e-2, 1e-3, 1e-4, 1e-5} from a light's
boundary: beside the rim of an elliptic disk (semi-axes 1, 0.4; above its plane
or in it), near the disk's plane outside its rim, outside a unit sphere and an
ellipsoid (semi-axes 1.5, 0.5, 0.8) by a factor 1 + eps; materials as above.

--kind aimed: Phong polygons (3- to 8-gons, sizes 0.1 to 2 at 1.1 to 10 times their
size) whose centre lies within 0.8 of its angular size of n's horizon, r aimed at a
point of the light or its edge (up to 0.2 rad off), N log-uniform in [1, 200]: the
low-N lobes that see a light near the horizon, where the specular moment is a small
difference of boundary terms.

--kind horizon-peak: Phong polygons the horizon cuts through the lobe's peak (the
seeded set of tests/test_shading.cpp's horizon_peak_polygons, drawn alike): N
log-uniform in [1, 1e5], r 1e-7 rad to two lobe widths (2 / sqrt(N + 2), at most 0.3
rad) above n's horizon, the light's centre within two widths of r in azimuth and 0.3
to 3 widths of the horizon in elevation, convex 3- to 8-gons 1.2 to 8 away and 0.05 to
2 times that wide.

--kind extreme: disks, spheres and ellipsoids at the ends of every range, for the
no-NaN/Inf/negative guarantee and the fp32 input conditioning: coordinates of scale
1e-6 to 1e6, lights 1e-6 to 10 times that scale, p from touching the light (its
distance 1 + 1e-7 sizes) to 1e3 sizes away, disks seen edge-on, ellipsoids and
disks flattened to 1e-6, n.v from exactly 0 through 1e-7 to 1, all four
distributions (materials as above, half the microfacet ones with an f0).

--kind degenerate: exactly degenerate but common inputs, every light type of
--lights (default: all four) and every distribution in turn, each one of
  vn       v exactly n (a top-down orthographic view), n random, the light about
           the mirror direction r = n or beside it, a fifth across the horizon
  floor    p on a floor grid of fp32-exact points (multiples of 1/8), n = v = +z,
           an axis-aligned light overhead with fp32-exact coordinates: rectangle
           (polygon), downward disk, sphere, axis-aligned ellipsoid
  axisview the floor with an axis-aligned, fp32-exact view (v = (0, 0.6, 0.8) and
           the like)
  vertex   r exactly through a corner of an axis-aligned rectangle, a point of a
           disk's rim, a sphere's or an ellipsoid's silhouette point in the plane
           of n and r (p = 0, n = +z, v = (-0.6, 0, 0.8): r = (0.6, 0, 0.8))
(a quarter of the disks and polygons two-sided, a tenth of the floor lights facing
away: 0). --scenes draws from a list of its own instead, where vn-horizon is vn with
the light always across the horizon (tests/data/degenerate_edges.cases.json: --scenes
vertex,vn-horizon).

The same COUNT, SEED and kind give the same file (near: COUNT is ignored, 96
cases). The oracle: arealight reference --cases OUT.json --out REF.json.
"""
import argparse, json, math, random


def unit(v):
    l = math.sqrt(sum(x * x for x in v))
    return [x / l for x in v]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def add(a, b, s=1.0):
    return [x + s * y for x, y in zip(a, b)]


def scale(a, s):
    return [x * s for x in a]


class Gen:
    def __init__(self, seed):
        self.rng = random.Random(seed)

    def rand_unit(self):
        while True:
            v = [self.rng.gauss(0, 1) for _ in range(3)]
            if dot(v, v) > 1e-6:
                return unit(v)

    def frame(self, z):
        x = unit(cross(z, self.rand_unit()))
        return x, cross(z, x)

    def polygon_facing(self, p, c, size, min_decade):
        """A convex 3- to 8-gon about c facing p, jittered vertices, half-widths size and
        size * 10^u, u in [min_decade, 0]; counter-clockwise seen from p (the contract's
        front face: b, w, p - c right-handed)."""
        b, w = self.frame(unit(add(c, p, -1)))
        k = self.rng.randint(3, 8)
        ang = sorted(2 * math.pi * (j + self.rng.uniform(0, 0.7)) / k for j in range(k))
        wide = 10 ** self.rng.uniform(min_decade, 0)
        return [add(add(c, b, size * math.cos(t)), w, -size * wide * math.sin(t)) for t in ang]

    def material(self, dist):
        if dist in ("phong", "blinn"):
            return {"distribution": dist, "exponent": 10 ** self.rng.uniform(0, 5)}
        return {"distribution": dist, "alpha": 10 ** self.rng.uniform(-3, 0)}


def hard_case(g, index, dist, ltype, scen=None):
    rng = g.rng
    scen = scen or rng.choice(["horizon", "large", "rim", "grazing", "rim", "horizon"])
    p = [rng.uniform(-3, 3) for _ in range(3)]
    n = g.rand_unit()
    size = 10 ** rng.uniform(-1.5, 0)
    d = size * (10 ** rng.uniform(0.005, 0.4) if scen == "large" else 10 ** rng.uniform(0.02, 1.3))
    if scen == "horizon":
        e1, _ = g.frame(n)
        ang = rng.uniform(-0.6, 0.6) * size / d
        dirc = unit(add(scale(e1, math.cos(ang)), n, math.sin(ang)))
    else:
        while True:
            dirc = g.rand_unit()
            if dot(dirc, n) > 0.05:
                break
    c = add(p, dirc, d)
    if ltype == "polygon":
        verts = g.polygon_facing(p, c, size, -1)
        k = len(verts)
        light = {"type": "polygon", "vertices": verts, "two_sided": rng.random() < 0.3}

        def rim(th):
            j = int(th / (2 * math.pi) * k) % k
            t = rng.random()
            return add(scale(verts[j], 1 - t), verts[(j + 1) % k], t)
    elif ltype == "disk":
        a = g.rand_unit()
        b, w = g.frame(a)
        u, vv = scale(b, size), scale(w, size * 10 ** rng.uniform(-1, 0))
        if dot(cross(u, vv), add(p, c, -1)) < 0:
            vv = scale(vv, -1)
        light = {"type": "disk", "center": c, "u": u, "v": vv, "two_sided": rng.random() < 0.3}
        rim = lambda th: add(add(c, u, math.cos(th)), vv, math.sin(th))
    elif ltype == "sphere":
        R = d * rng.uniform(0.3, 0.99) if scen == "large" else size
        R = min(R, 0.9 * d)
        light = {"type": "sphere", "center": c, "radius": R}
        z = unit(add(c, p, -1))
        e1, e2 = g.frame(z)
        rho2 = 1 - (R / d) ** 2
        cs, rs = add(p, add(c, p, -1), rho2), R * math.sqrt(rho2)
        rim = lambda th: add(add(cs, e1, rs * math.cos(th)), e2, rs * math.sin(th))
    else:
        a0 = g.rand_unit()
        a1, a2 = g.frame(a0)
        lengths = [size, size * 10 ** rng.uniform(-1, 0), size * 10 ** rng.uniform(-1, 0)]
        axes = [scale(a0, lengths[0]), scale(a1, lengths[1]), scale(a2, lengths[2])]
        yp = [dot(add(p, c, -1), axes[k]) / dot(axes[k], axes[k]) for k in range(3)]
        t = math.sqrt(dot(yp, yp))
        if t <= 1.02:
            return None
        light = {"type": "ellipsoid", "center": c, "axes": axes}
        f1, f2 = g.frame(scale(yp, 1 / t))
        rho = math.sqrt(1 - 1 / t ** 2)

        def rim(th):
            y = add(add(scale(yp, 1 / t ** 2), f1, rho * math.cos(th)), f2, rho * math.sin(th))
            return add(c, add(add(scale(axes[0], y[0]), axes[1], y[1]), axes[2], y[2]))
    if scen == "rim":
        tdir = unit(add(rim(rng.uniform(0, 2 * math.pi)), p, -1))
        off = g.rand_unit()
        off = unit(add(off, tdir, -dot(off, tdir)))
        tdir = unit(add(tdir, off, 10 ** rng.uniform(-6, -2)))
        if dot(tdir, n) < 0.02:
            return None
        v = add(scale(n, 2 * dot(n, tdir)), tdir, -1)
    elif scen == "lobe-edge":
        # The lobe's axis u lobe widths outside (u > 0) or inside the silhouette at one of
        # its points, along the silhouette's outward normal as p sees it.
        q = rim(rng.uniform(0, 2 * math.pi))
        tdir = unit(add(q, p, -1))
        out = add(q, c, -1)
        out = unit(add(out, tdir, -dot(out, tdir)))
        mat = g.material(dist)
        width = (math.sqrt(2 / (mat["exponent"] + 2)) if "exponent" in mat else 2 * mat["alpha"])
        tdir = unit(add(tdir, out, math.tan(min(rng.uniform(-3, 3) * width, 1.2))))
        if dot(tdir, n) < 0.02:
            return None
        v = add(scale(n, 2 * dot(n, tdir)), tdir, -1)
        return {"id": "lobe-edge-%s-%s-%03d" % (ltype, dist, index), "p": p, "n": n, "v": v,
                "light": light, "material": mat}
    elif scen == "grazing":
        e1, _ = g.frame(n)
        cv = 10 ** rng.uniform(-3, -1.3)
        v = add(scale(e1, math.sqrt(1 - cv * cv)), n, cv)
    else:
        while True:
            v = g.rand_unit()
            if dot(v, n) > 0.02:
                break
    return {"id": "hard-%s-%s-%s-%03d" % (scen, ltype, dist, index), "p": p, "n": n, "v": v,
            "light": light, "material": g.material(dist)}


def cases_in_turn(make, count, seed, lights):
    """COUNT cases of make(g, index, dist, light), every distribution in turn and, after
    each four, the next light type; a None from make is drawn again."""
    g, cases, i = Gen(seed), [], 0
    dists = ["phong", "blinn", "beckmann", "ggx"]
    while len(cases) < count:
        i += 1
        c = make(g, len(cases), dists[i % 4], lights[(i // 4) % len(lights)])
        if c:
            cases.append(c)
    return cases


def aimed_cases(count, seed):
    g = Gen(seed)
    rng = g.rng
    cases = []
    for i in range(count):
        n = g.rand_unit()
        e1, e2 = g.frame(n)
        size = 10 ** rng.uniform(-1, 0.3)
        d = size * 10 ** rng.uniform(0.05, 1)
        ang = rng.uniform(-0.8, 0.8) * size / d
        az = rng.uniform(0, 2 * math.pi)
        h = add(scale(e1, math.cos(az)), e2, math.sin(az))
        c = scale(unit(add(scale(h, math.cos(ang)), n, math.sin(ang))), d)
        verts = g.polygon_facing([0, 0, 0], c, size, -0.7)
        k = len(verts)
        j, t = rng.randrange(k), rng.random()
        q = add(scale(verts[j], 1 - t), verts[(j + 1) % k], t)
        if rng.random() < 0.5:
            q = add(scale(q, 0.7), c, 0.3)
        tdir = unit(add(unit(q), g.rand_unit(), rng.uniform(0, 0.2)))
        if dot(tdir, n) < 0.01:
            tdir = unit(add(tdir, n, 0.02 - dot(tdir, n)))
        v = add(scale(n, 2 * dot(n, tdir)), tdir, -1)
        N = 10 ** rng.uniform(0, 2.3)
        if dot(v, n) <= 1e-3:
            continue
        cases.append({"id": "aimed-%04d" % i, "p": [0, 0, 0], "n": n, "v": unit(v),
                      "light": {"type": "polygon", "vertices": verts, "two_sided": False},
                      "material": {"distribution": "phong", "exponent": N}})
    return cases


def horizon_peak_cases(count, seed):
    rng = random.Random(seed)
    n = [0.0, 0.0, 1.0]
    cases = []
    for i in range(count):
        N = math.exp(math.log(1e5) * rng.random())
        width = 2 / math.sqrt(N + 2)
        er = 10 ** rng.uniform(-7, math.log10(min(0.3, 2 * width)))
        r = [math.cos(er), 0.0, math.sin(er)]
        v = add(scale(n, 2 * r[2]), r, -1)
        az = rng.uniform(-2, 2) * width
        el = rng.uniform(-1, 1) * width * rng.choice([0.3, 1.0, 3.0])
        d = [math.cos(el) * math.cos(az), math.cos(el) * math.sin(az), math.sin(el)]
        dist = rng.uniform(1.2, 8)
        half = 0.5 * rng.uniform(0.05, 1) * dist * rng.choice([0.05, 0.2, 1.0, 2.0])
        t1 = unit(cross(d, [rng.random() - 0.5, 0.5, 0.8]))
        t2 = cross(d, t1)
        k = rng.choice([3, 4, 5, 6, 8])
        aspect = rng.uniform(0.2, 1)
        verts = []
        for j in range(k):
            a = -2 * math.pi * (j + 0.7 * rng.random()) / k  # clockwise about d: faces p
            verts.append(add(add(scale(d, dist), t1, half * math.cos(a)), t2,
                             half * aspect * math.sin(a)))
        cases.append({"id": "horizon-peak-%04d" % i, "p": [0, 0, 0], "n": n, "v": unit(v),
                      "light": {"type": "polygon", "vertices": verts, "two_sided": False},
                      "material": {"distribution": "phong", "exponent": N}})
    return cases


def extreme_cases(count, seed):
    g = Gen(seed)
    rng = g.rng
    cases = []
    for i in range(count):
        span = 10 ** rng.uniform(-6, 6)
        p = [rng.uniform(-1, 1) * span for _ in range(3)]
        n = g.rand_unit()
        t, _ = g.frame(n)
        mode = rng.random()
        cv = 0.0 if mode < 0.1 else 10 ** rng.uniform(-7, -3) if mode < 0.2 else rng.uniform(0, 1)
        v = add(scale(n, cv), t, math.sqrt(1 - cv * cv))
        size = span * 10 ** rng.uniform(-6, 1)
        toward = g.rand_unit() if rng.random() < 0.5 else unit(add(scale(n, rng.uniform(-0.1, 1)), g.rand_unit(), 0.3))
        c = add(p, toward, size * (1 + 10 ** rng.uniform(-7, 3)))
        ltype = ("disk", "sphere", "ellipsoid")[i % 3]
        if ltype == "disk":
            # Facing p, or containing the line to p (edge-on) one time in five.
            a, b = g.frame(toward)
            if rng.random() < 0.2:
                a, b = toward, a
            light = {"type": "disk", "center": c, "u": scale(a, size),
                     "v": scale(b, size * 10 ** rng.uniform(-6, 0)), "two_sided": rng.random() < 0.5}
        elif ltype == "sphere":
            light = {"type": "sphere", "center": c, "radius": size}
        else:
            a = g.rand_unit()
            b, e = g.frame(a)
            s = [size * 10 ** rng.uniform(-6, 0) for _ in range(3)]
            s[rng.randrange(3)] = size
            light = {"type": "ellipsoid", "center": c, "axes": [scale(a, s[0]), scale(b, s[1]), scale(e, s[2])]}
        mat = g.material(("phong", "blinn", "beckmann", "ggx")[(i // 3) % 4])
        if mat["distribution"] != "phong" and rng.random() < 0.5:
            mat["f0"] = rng.uniform(0, 1)
        cases.append({"id": "extreme-%04d" % i, "p": p, "n": n, "v": v, "light": light, "material": mat})
    return cases


DEGENERATE_SCENES = ["vn", "vn", "floor", "axisview", "vertex"]


def degenerate_case(g, index, dist, ltype, scenes=DEGENERATE_SCENES):
    rng = g.rng
    scen = rng.choice(scenes)
    across = scen == "vn-horizon"
    if across:
        scen = "vn"
    mat = g.material(dist)
    sided = rng.random() < 0.25
    if scen == "vn":
        p = [rng.uniform(-3, 3) for _ in range(3)]
        n = g.rand_unit()
        size = 10 ** rng.uniform(-1.5, 0)
        d = size * 10 ** rng.uniform(0.05, 1.3)
        e1, _ = g.frame(n)
        if rng.random() < 0.2 or across:  # across the horizon
            ang = rng.uniform(-0.6, 0.6) * size / d
        else:  # about r = n, up to twice the light's angular size off it
            ang = math.pi / 2 - rng.uniform(0, 2) * size / d
        c = add(p, unit(add(scale(e1, math.cos(ang)), n, math.sin(ang))), d)
        toward = unit(add(p, c, -1))
        if ltype == "polygon":
            light = {"type": "polygon", "vertices": g.polygon_facing(p, c, size, -1), "two_sided": sided}
        elif ltype == "disk":
            a, b = g.frame(unit(add(c, p, -1)))
            light = {"type": "disk", "center": c, "u": scale(a, size),
                     "v": scale(b, size * 10 ** rng.uniform(-1, 0)), "two_sided": sided}
            if dot(cross(light["u"], light["v"]), toward) < 0:
                light["v"] = scale(light["v"], -1)
        elif ltype == "sphere":
            light = {"type": "sphere", "center": c, "radius": min(size, 0.9 * d)}
        else:
            a0 = g.rand_unit()
            a1, a2 = g.frame(a0)
            s = [size, size * 10 ** rng.uniform(-1, 0), size * 10 ** rng.uniform(-1, 0)]
            if d <= 1.5 * size:
                return None
            light = {"type": "ellipsoid", "center": c, "axes": [scale(a0, s[0]), scale(a1, s[1]), scale(a2, s[2])]}
        return {"id": "degenerate-vn-%s-%s-%03d" % (ltype, dist, index), "p": p, "n": n, "v": list(n),
                "light": light, "material": mat}
    n = [0.0, 0.0, 1.0]
    if scen == "vertex":
        p, v = [0.0, 0.0, 0.0], [-0.6, 0.0, 0.8]
        h = rng.choice([1.0, 2.0, 4.0])
        q = [0.75 * h, 0.0, h]  # on r = (0.6, 0, 0.8)
        w, l = rng.choice([0.25, 0.5, 1.0]), rng.choice([0.25, 0.5, 1.0])
        sx, sy = rng.choice([-1, 1]), rng.choice([-1, 1])
        if ltype == "polygon":
            # Corner q, the rectangle on either side of r in x and y.
            vs = [q, [q[0] + sx * w, 0.0, h], [q[0] + sx * w, sy * l, h], [q[0], sy * l, h]]
            if sx * sy > 0:  # counter-clockwise seen from below: facing p
                vs = vs[::-1]
            light = {"type": "polygon", "vertices": vs, "two_sided": sided}
        elif ltype == "disk":
            R = w
            light = {"type": "disk", "center": [q[0] + sx * R, 0.0, h], "u": [R, 0.0, 0.0],
                     "v": [0.0, -R * rng.choice([1.0, 0.5]), 0.0], "two_sided": sided}
        elif ltype == "sphere":
            # Centre on the x-z line through q perpendicular to r, at distance R: r touches it.
            R = w
            light = {"type": "sphere", "center": [q[0] + sx * 0.8 * R, 0.0, h - sx * 0.6 * R], "radius": R}
        else:
            R = w
            light = {"type": "ellipsoid", "center": [q[0] + sx * 0.8 * R, 0.0, h - sx * 0.6 * R],
                     "axes": [[R, 0.0, 0.0], [0.0, 2 * R, 0.0], [0.0, 0.0, R]]}
        return {"id": "degenerate-vertex-%s-%s-%03d" % (ltype, dist, index), "p": p, "n": n, "v": v,
                "light": light, "material": mat}
    p = [rng.randint(-16, 16) / 8, rng.randint(-16, 16) / 8, 0.0]
    v = list(n) if scen == "floor" else rng.choice(
        [[0.0, 0.6, 0.8], [0.8, 0.0, 0.6], [-0.6, 0.0, 0.8], [0.0, -0.28, 0.96], [0.96, 0.0, 0.28]])
    h = rng.choice([0.5, 1.0, 2.0, 3.0])
    cx, cy = rng.randint(-8, 8) / 4, rng.randint(-8, 8) / 4
    a, b = rng.choice([0.25, 0.5, 1.0]), rng.choice([0.25, 0.5, 1.0])
    away = rng.random() < 0.1
    if ltype == "polygon":
        vs = [[cx - a, cy - b, h], [cx - a, cy + b, h], [cx + a, cy + b, h], [cx + a, cy - b, h]]
        if away:
            vs = vs[::-1]
        light = {"type": "polygon", "vertices": vs, "two_sided": sided}
    elif ltype == "disk":
        light = {"type": "disk", "center": [cx, cy, h], "u": [a, 0.0, 0.0],
                 "v": [0.0, b if away else -b, 0.0], "two_sided": sided}
    elif ltype == "sphere":
        light = {"type": "sphere", "center": [cx, cy, h], "radius": min(a, h / 2)}
    else:
        light = {"type": "ellipsoid", "center": [cx, cy, h],
                 "axes": [[a, 0.0, 0.0], [0.0, b, 0.0], [0.0, 0.0, min(a, b, h / 2)]]}
    return {"id": "degenerate-%s-%s-%s-%03d" % (scen, ltype, dist, index), "p": p, "n": n, "v": v,
            "light": light, "material": mat}


def near_cases(seed):
    g = Gen(seed)
    rng = g.rng
    rnd = lambda: [rng.uniform(-0.6, 0.6), rng.uniform(-0.6, 0.6), 1.0]
    disk = {"type": "disk", "center": [0, 0, 0], "u": [1, 0, 0], "v": [0, -0.4, 0], "two_sided": True}
    axes = [[1.5, 0, 0], [0, 0.5, 0], [0, 0, 0.8]]
    cases, i = [], 0

    def add_case(kind, eps, p, light):
        nonlocal i
        dist = ["phong", "ggx", "blinn", "beckmann"][(i + i // 4) % 4]  # every kind, every dist
        cases.append({"id": "near-%s-%d-%g" % (kind, i, eps), "p": p, "n": rnd(), "v": rnd(),
                      "material": g.material(dist), "light": light})
        i += 1

    for eps in [1e-2, 1e-3, 1e-4, 1e-5]:
        for _ in range(6):
            th = rng.uniform(0, 2 * math.pi)
            rim = [math.cos(th), 0.4 * math.sin(th), 0]
            out = unit([0.4 * math.cos(th), math.sin(th), 0])
            ang = rng.uniform(0.02, math.pi - 0.02)
            add_case("rim", eps, [rim[0] + eps * math.cos(ang) * out[0],
                                  rim[1] + eps * math.cos(ang) * out[1], eps * math.sin(ang)], disk)
            add_case("plane", eps, [rng.uniform(1.2, 3), rng.uniform(-1, 1), eps * rng.choice([-1, 1])],
                     disk)
            y = g.rand_unit()
            add_case("sphere", eps, scale(y, 1 + eps),
                     {"type": "sphere", "center": [0, 0, 0], "radius": 1.0})
            add_case("ellipsoid", eps, [axes[k][k] * y[k] * (1 + eps) for k in range(3)],
                     {"type": "ellipsoid", "center": [0, 0, 0], "axes": axes})
    return cases


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("count", type=int)
    ap.add_argument("seed", type=int)
    ap.add_argument("out")
    ap.add_argument("--kind", choices=["hard", "lobe-edge", "near", "aimed", "horizon-peak", "extreme",
                                       "degenerate"],
                    default="hard")
    ap.add_argument("--scenes", default=None,
                    help="comma-separated scenes of --kind degenerate, drawn evenly (vn, vn-horizon: "
                    "v = n with the light across the horizon, floor, axisview, vertex; default: "
                    "vn twice as often as each other, vn-horizon none)")
    ap.add_argument("--lights", default=None,
                    help="comma-separated light types of --kind hard (polygon, disk, sphere, ellipsoid; "
                    "default: the curved three) and degenerate (default: all four)")
    a = ap.parse_args()
    lights = (a.lights or ("polygon,disk,sphere,ellipsoid" if a.kind == "degenerate"
                           else "disk,sphere,ellipsoid")).split(",")
    bad = [t for t in lights if t not in ("polygon", "disk", "sphere", "ellipsoid")]
    if bad:
        ap.error("unknown light type %s in --lights" % ", ".join(bad))
    if a.kind == "hard":
        cases = cases_in_turn(hard_case, a.count, a.seed, lights)
    elif a.kind == "lobe-edge":
        cases = cases_in_turn(lambda g, i, d, t: hard_case(g, i, d, t, "lobe-edge"), a.count, a.seed,
                              lights)
    elif a.kind == "aimed":
        cases = aimed_cases(a.count, a.seed)
    elif a.kind == "horizon-peak":
        cases = horizon_peak_cases(a.count, a.seed)
    elif a.kind == "extreme":
        cases = extreme_cases(a.count, a.seed)
    elif a.kind == "degenerate":
        scenes = a.scenes.split(",") if a.scenes else DEGENERATE_SCENES
        bad = [t for t in scenes if t not in ("vn", "vn-horizon", "floor", "axisview", "vertex")]
        if bad:
            ap.error("unknown scene %s in --scenes" % ", ".join(bad))
        cases = cases_in_turn(lambda g, i, d, t: degenerate_case(g, i, d, t, scenes), a.count,
                              a.seed, lights)
    else:
        cases = near_cases(a.seed)
    with open(a.out, "w") as f:
        json.dump({"format": "arealight-cases/1", "cases": cases}, f, indent=1)
        f.write("\n")


if __name__ == "__main__":
    main()
