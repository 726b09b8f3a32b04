#!/usr/bin/env python3
"""Seeded random Phong polygon cases (arealight-cases/1) for accuracy measurements.

Usage: gen_phong_cases.py COUNT SEED OUT.json

Convex 3- to 8-gons around the mirror direction, some crossing the horizon,
exponents log-uniform in [1, 1e5]. The same COUNT and SEED give the same file.
"""
import json, math, random, sys
if len(sys.argv) != 4:
    sys.exit(__doc__)
rnd = random.Random(int(sys.argv[2]))
def norm(a): l = math.sqrt(sum(x*x for x in a)); return [x/l for x in a]
def cross(a,b): return [a[1]*b[2]-a[2]*b[1], a[2]*b[0]-a[0]*b[2], a[0]*b[1]-a[1]*b[0]]
cases = []
for i in range(int(sys.argv[1])):
    n = [0,0,1]
    th = math.acos(1 - 0.95*rnd.random()); ph = 2*math.pi*rnd.random()
    v = [math.sin(th)*math.cos(ph), math.sin(th)*math.sin(ph), math.cos(th)]
    r = [2*v[2]*n[k] - v[k] for k in range(3)]
    d = norm([r[k] + 0.6*(rnd.random() - (0.6 if k == 2 else 0.5)) for k in range(3)])
    t1 = norm(cross(d, [0.3,0.5,0.8])); t2 = cross(d, t1)
    K = 3 + int(rnd.random()*6); dist = 1 + 4*rnd.random(); rad = (0.05 + 1.2*rnd.random())*dist*0.5
    verts = []
    for j in range(K):
        a = -2*math.pi*(j + 0.7*rnd.random())/K
        verts.append([dist*d[k] + rad*(math.cos(a)*t1[k] + math.sin(a)*t2[k]) for k in range(3)])
    N = math.exp(math.log(1e5)*rnd.random())
    cases.append({"id": f"rand-{i}", "p": [0,0,0], "n": n, "v": v,
                  "light": {"type": "polygon", "vertices": verts, "two_sided": False},
                  "material": {"distribution": "phong", "exponent": N}})
json.dump({"format": "arealight-cases/1", "cases": cases}, open(sys.argv[3], "w"))
