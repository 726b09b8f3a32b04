#!/usr/bin/env python3
"""The HLSL library against the GLSL library on lavapipe: for every fp32 family (each
(distribution, method, light) at its default keys, at precision=fp32 where the default is
fp64), `arealight eval --backend vulkan` with --lang glsl and --lang hlsl over the given
case files, and the largest relative difference (floor 1e-3) of every quantity.

  scripts/hlsl_check.py [--arealight build/arealight] CASES.json...

Prints one line per family and the worst; exits 1 if any difference exceeds --tol (1e-5).
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile


def families(arealight):
    names = subprocess.run([arealight, "variants"], check=True, capture_output=True,
                           text=True).stdout.split()
    seen, out = set(), []
    for name in names:
        keys = dict(kv.split("=") for kv in name.split(","))
        fam = (keys["dist"], keys["method"], keys["light"])
        if fam in seen:
            continue
        seen.add(fam)
        out.append("dist=%s,method=%s,light=%s" % fam)
    return out


def run(arealight, variant, cases, lang, out):
    cmd = [arealight, "eval", "--backend", "vulkan", "--lang", lang, "--cases", cases,
           "--variant", variant, "--out", out]
    return subprocess.run(cmd, capture_output=True, text=True)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--arealight", default="build/arealight")
    ap.add_argument("--tol", type=float, default=1e-5)
    ap.add_argument("cases", nargs="+")
    args = ap.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        merged = {"format": "arealight-cases/1", "cases": []}
        for path in args.cases:
            merged["cases"] += json.load(open(path))["cases"]
        cases = os.path.join(tmp, "cases.json")
        json.dump(merged, open(cases, "w"))
        worst_all, bad, checked = 0.0, 0, 0
        for base in families(args.arealight):
            res = {}
            # The default keys, or precision=fp32 where the default is fp64 (the HLSL
            # library is fp32 only): both languages run the same variant.
            for variant in (base, base + ",precision=fp32"):
                res = {}
                for lang in ("glsl", "hlsl"):
                    out = os.path.join(tmp, lang + ".json")
                    if run(args.arealight, variant, cases, lang, out).returncode != 0:
                        break
                    res[lang] = {x["id"]: x for x in json.load(open(out))["results"]}
                if len(res) == 2:
                    break
            if len(res) != 2:
                print("%-60s no fp32 form" % base)
                continue
            worst, where = 0.0, ""
            for cid, g in res["glsl"].items():
                h = res["hlsl"][cid]
                for q in ("diffuse", "specular", "ndf", "moment"):
                    if g.get(q) is None:
                        continue
                    d = abs(h[q] - g[q]) / max(abs(g[q]), 1e-3)
                    if d > worst:
                        worst, where = d, "%s %s" % (cid, q)
            checked += len(res["glsl"])
            worst_all = max(worst_all, worst)
            bad += worst > args.tol
            print("%-70s %4d cases  max rel diff %.2e %s" % (variant, len(res["glsl"]), worst, where))
            sys.stdout.flush()
        print("families over tolerance %g: %d; worst %.2e over %d case results" %
              (args.tol, bad, worst_all, checked))
        return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
