#!/usr/bin/env python3
"""Seeded random microfacet polygon cases (arealight-cases/1) for accuracy measurements.

Usage: gen_microfacet_cases.py COUNT SEED OUT.json [--kind hard|typical|near-horizon]

blinn, beckmann and ggx materials lit by convex 3- to 8-gons, counter-clockwise
toward the emitting side; a quarter of the lights are two-sided, half of those
seen from the back. About a third of the materials carry a Schlick f0, uniform
in [0, 1]. Each case is built about n = +z and then turned by a random rotation
(no axis is special, CONTRACT.md section 1). The same COUNT, SEED and kind give
the same file.

--kind hard (default) cycles through what breaks approximations:
  grazing  n.v in [1e-3, 0.1], the light about the mirror direction r
  horizon  the light crosses the horizon plane of n
  large    the light subtends more than 60 degrees
  edge     r within a small angle (1e-4 to 0.03 rad) of one of the light's
           edges, inside or outside
  sharp    alpha in [0.001, 0.02] or N in [1e3, 1e5], the light about r
  rough    alpha = 1 or N = 1
and the distributions within each kind; away from sharp and rough, alpha is
log-uniform in [0.001, 1] and N in [1, 1e5].
--kind typical: n.v in [0.2, 1], lights about r (some crossing the horizon),
alpha log-uniform in [0.05, 1], N in [2, 1000].
--kind near-horizon: lights wholly above the horizon, 2 to 12 degrees in angular
radius, their centres 1 to 20 degrees above it at any azimuth (off the lobe as
often as on it), n.v in [0.02, 1], alpha log-uniform in [0.03, 0.8] (N through
alpha = sqrt(2 / (N + 2))): where an LTC's lobe keeps mass at the horizon that
f (n.w) does not have (docs/ltc.md).

Case ids name the kind, the distribution and the index: hard-grazing-ggx-17.
"""
import argparse, json, math, random

HARD_KINDS = ["grazing", "horizon", "large", "edge", "sharp", "rough"]
DISTRIBUTIONS = ["ggx", "beckmann", "blinn"]

def norm(a): l = math.sqrt(sum(x*x for x in a)); return [x/l for x in a]
def cross(a, b): return [a[1]*b[2]-a[2]*b[1], a[2]*b[0]-a[0]*b[2], a[0]*b[1]-a[1]*b[0]]
def dot(a, b): return sum(x*y for x, y in zip(a, b))
def add(a, b, s=1.0): return [x + s*y for x, y in zip(a, b)]
def scale(a, s): return [s*x for x in a]
def angle(a, b): return math.atan2(math.sqrt(dot(cross(a, b), cross(a, b))), dot(a, b))
def loguniform(rnd, lo, hi): return math.exp(math.log(lo) + (math.log(hi) - math.log(lo))*rnd.random())

def perpendicular(a, rnd):
    """A random unit vector orthogonal to the unit vector a."""
    while True:
        t = cross(a, [rnd.gauss(0, 1) for _ in range(3)])
        if dot(t, t) > 1e-6:
            return norm(t)

def view(rnd, lo, hi, log=False):
    """v with n.v in [lo, hi] about n = +z, and its mirror direction r."""
    c = loguniform(rnd, lo, hi) if log else lo + (hi - lo)*rnd.random()
    s, ph = math.sqrt(1 - c*c), 2*math.pi*rnd.random()
    v = [s*math.cos(ph), s*math.sin(ph), c]
    return v, [-v[0], -v[1], c]

def polygon_about(rnd, d, dist, rad):
    """A convex 3- to 8-gon in the plane orthogonal to the unit d at distance dist, its
    vertices on the circle of radius rad about dist*d (points on a circle are in convex
    position; the jitter keeps every turn well away from straight)."""
    t1 = perpendicular(d, rnd); t2 = cross(d, t1)
    K = 3 + int(rnd.random()*6)
    verts = []
    for j in range(K):
        a = 2*math.pi*(j + 0.7*rnd.random())/K
        verts.append([dist*d[k] + rad*(math.cos(a)*t1[k] + math.sin(a)*t2[k]) for k in range(3)])
    return verts

def facing_origin(verts):
    """The winding whose front (CONTRACT.md section 1) faces p = 0."""
    N = cross(add(verts[1], verts[0], -1), add(verts[2], verts[0], -1))
    return verts if dot(N, verts[0]) < 0 else verts[::-1]

def rotation_taking(a, b, rnd):
    """A rotation taking the unit a to the unit b, with a random spin about b."""
    a1 = perpendicular(a, rnd); a2 = cross(a, a1)
    b1 = perpendicular(b, rnd); b2 = cross(b, b1)
    return lambda x: add(add(scale(b, dot(x, a)), b1, dot(x, a1)), b2, dot(x, a2))

def random_rotation(rnd):
    """A uniformly distributed rotation (normalized Gaussian quaternion)."""
    w, x, y, z = norm([rnd.gauss(0, 1) for _ in range(4)])
    R = [[1-2*(y*y+z*z), 2*(x*y-w*z), 2*(x*z+w*y)],
         [2*(x*y+w*z), 1-2*(x*x+z*z), 2*(y*z-w*x)],
         [2*(x*z-w*y), 2*(y*z+w*x), 1-2*(x*x+y*y)]]
    return lambda a: [dot(row, a) for row in R]

def above(verts, eps=1e-3):
    """Whether some of the light lies above the horizon of n = +z."""
    return any(x[2] > eps*math.sqrt(dot(x, x)) for x in verts)

def near(rnd, r, spread, lift=0.0):
    """A direction about r, jittered by up to spread and raised by lift along n = +z."""
    return norm([r[k] + spread*(rnd.random() - 0.5) + (lift if k == 2 else 0.0) for k in range(3)])

def light_about(rnd, d, rho_lo, rho_hi):
    """A polygon of angular radius in [rho_lo, rho_hi] about d, 1 to 5 away."""
    dist = 1 + 4*rnd.random()
    rho = rho_lo + (rho_hi - rho_lo)*rnd.random()
    return polygon_about(rnd, d, dist, dist*math.tan(rho))

def hard_geometry(rnd, kind):
    """(v, vertices) about n = +z for a hard kind, retried until it is of that kind."""
    while True:
        if kind == "grazing":
            v, r = view(rnd, 1e-3, 0.1, log=True)
            verts = light_about(rnd, near(rnd, r, 0.6, 0.15), 0.05, 0.6)
            ok = True
        elif kind == "horizon":
            v, r = view(rnd, 0.1, 0.9)
            az = math.atan2(r[1], r[0]) + (rnd.random() - 0.5)*2.0
            el = -0.2 + 0.5*rnd.random()
            d = [math.cos(el)*math.cos(az), math.cos(el)*math.sin(az), math.sin(el)]
            verts = light_about(rnd, d, abs(el) + 0.05, abs(el) + 0.6)
            ok = any(x[2] < 0 for x in verts)
        elif kind == "large":
            v, r = view(rnd, 0.05, 1.0)
            u = rnd.random()
            d = norm(add(scale(r, u), near(rnd, [0, 0, 1], 0.8), 1 - u))
            verts = light_about(rnd, d, math.radians(40), math.radians(75))
            dirs = [norm(x) for x in verts]
            ok = max(angle(a, b) for a in dirs for b in dirs) > math.radians(60)
        elif kind == "edge":
            v, r = view(rnd, 0.1, 1.0)
            local = light_about(rnd, [0, 0, 1], math.radians(5), math.radians(30))
            i = int(rnd.random()*len(local))
            a, b = local[i], local[(i + 1) % len(local)]
            e = add(a, add(b, a, -1), 0.2 + 0.6*rnd.random())
            # Toward the centre, across the edge: r lands inside or outside, off by about
            # `offset` radians.
            edge = norm(add(b, a, -1))
            inward = norm(add([0, 0, e[2]], e, -1))
            inward = norm(add(inward, edge, -dot(inward, edge)))
            offset = loguniform(rnd, 1e-4, 0.03)*(1 if rnd.random() < 0.5 else -1)
            target = add(e, inward, offset*math.sqrt(dot(e, e)))
            R = rotation_taking(norm(target), r, rnd)
            verts = [R(x) for x in local]
            ok = True
        elif kind == "sharp":
            v, r = view(rnd, 0.05, 1.0)
            verts = light_about(rnd, near(rnd, r, 0.3), math.radians(2), math.radians(30))
            ok = True
        else:  # rough
            v, r = view(rnd, 0.05, 1.0)
            verts = light_about(rnd, near(rnd, r, 1.0, 0.2), 0.1, 0.8)
            ok = True
        if ok and above(verts):
            return v, verts

def typical_geometry(rnd):
    while True:
        v, r = view(rnd, 0.2, 1.0)
        verts = light_about(rnd, near(rnd, r, 0.6, -0.06), 0.05, 0.55)
        if above(verts):
            return v, verts

def near_horizon_geometry(rnd):
    while True:
        v, r = view(rnd, 0.02, 1.0)
        el = math.radians(1 + 19*rnd.random())
        az = 2*math.pi*rnd.random()
        d = [math.cos(el)*math.cos(az), math.cos(el)*math.sin(az), math.sin(el)]
        verts = light_about(rnd, d, math.radians(2), min(math.radians(12), 0.9*el + math.radians(1)))
        if all(x[2] > 0 for x in verts):
            return v, verts

def material(rnd, dist, kind):
    if kind == "rough":
        lo_a, hi_a, lo_n, hi_n = 1.0, 1.0, 1.0, 1.0
    elif kind == "sharp":
        lo_a, hi_a, lo_n, hi_n = 0.001, 0.02, 1e3, 1e5
    elif kind == "edge":
        lo_a, hi_a, lo_n, hi_n = 0.001, 0.3, 20.0, 1e5
    elif kind == "typical":
        lo_a, hi_a, lo_n, hi_n = 0.05, 1.0, 2.0, 1000.0
    elif kind == "near-horizon":
        lo_a, hi_a, lo_n, hi_n = 0.03, 0.8, 2/0.8**2 - 2, 2/0.03**2 - 2
    else:
        lo_a, hi_a, lo_n, hi_n = 0.001, 1.0, 1.0, 1e5
    m = {"distribution": dist}
    if dist == "blinn":
        m["exponent"] = loguniform(rnd, lo_n, hi_n)
    else:
        m["alpha"] = loguniform(rnd, lo_a, hi_a)
    if rnd.random() < 1/3:
        m["f0"] = rnd.random()
    return m

def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("count", type=int)
    ap.add_argument("seed", type=int)
    ap.add_argument("out")
    ap.add_argument("--kind", choices=["hard", "typical", "near-horizon"], default="hard")
    args = ap.parse_args()
    rnd = random.Random(args.seed)
    cases = []
    for i in range(args.count):
        if args.kind == "hard":
            # Every kind with every distribution within 18 consecutive cases.
            kind = HARD_KINDS[i % len(HARD_KINDS)]
            dist = DISTRIBUTIONS[(i // len(HARD_KINDS)) % len(DISTRIBUTIONS)]
            v, verts = hard_geometry(rnd, kind)
        else:
            kind = args.kind
            dist = DISTRIBUTIONS[i % len(DISTRIBUTIONS)]
            v, verts = typical_geometry(rnd) if kind == "typical" else near_horizon_geometry(rnd)
        verts = facing_origin(verts)
        two_sided = rnd.random() < 0.25
        if two_sided and rnd.random() < 0.5:
            verts = verts[::-1]
        R = random_rotation(rnd)
        name = f"hard-{kind}-{dist}-{i}" if args.kind == "hard" else f"{kind}-{dist}-{i}"
        cases.append({"id": name, "p": [0, 0, 0], "n": R([0, 0, 1]), "v": R(v),
                      "light": {"type": "polygon", "vertices": [R(x) for x in verts],
                                "two_sided": two_sided},
                      "material": material(rnd, dist, kind)})
    with open(args.out, "w") as f:
        json.dump({"format": "arealight-cases/1", "cases": cases}, f)

if __name__ == "__main__":
    main()
