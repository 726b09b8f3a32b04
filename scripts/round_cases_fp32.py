#!/usr/bin/env python3
"""Round every number of an arealight-cases/1 file to the nearest fp32 value.

Usage: round_cases_fp32.py IN.cases.json OUT.cases.json [--lights L,...]

The shading library (CONTRACT 5) takes fp32 inputs, so a shader sees each case
rounded this way. The oracle run on the rounded file (arealight reference) gives
the values those inputs really have: the difference from the oracle of the
unrounded file is the error no fp32-input shader can avoid (the input's
conditioning), and the difference of a shader from it is the shader's own.
--lights keeps only cases of those light types (default: all).
"""
import argparse, json, struct


def rounded(x, key=None):
    if key == "id":
        return x
    if isinstance(x, float) or (isinstance(x, int) and not isinstance(x, bool)):
        return struct.unpack("f", struct.pack("f", float(x)))[0]
    if isinstance(x, list):
        return [rounded(y) for y in x]
    if isinstance(x, dict):
        return {k: rounded(v, k) for k, v in x.items()}
    return x


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("cases")
    ap.add_argument("out")
    ap.add_argument("--lights", default="")
    a = ap.parse_args()
    with open(a.cases) as f:
        doc = json.load(f)
    keep = set(a.lights.split(",")) if a.lights else None
    doc["cases"] = [rounded(c) for c in doc.get("cases", [])
                    if keep is None or c.get("light", {}).get("type") in keep]
    with open(a.out, "w") as f:
        json.dump(doc, f, indent=1)
        f.write("\n")


if __name__ == "__main__":
    main()
