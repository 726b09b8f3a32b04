#!/usr/bin/env python3
"""Writes the cases of given case files that have one distribution and light type, in file
order, ids and values as there (tests/data/ltc_ggx_polygon_public.cases.json is made so):

  scripts/extract_cases.py --dist ggx --light polygon --comment TEXT --out FILE CASES.json...
"""
import argparse
import json


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--dist", required=True)
    ap.add_argument("--light", required=True)
    ap.add_argument("--comment", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("cases", nargs="+")
    args = ap.parse_args()
    picked = []
    for path in args.cases:
        for c in json.load(open(path))["cases"]:
            if c["material"]["distribution"] == args.dist and c["light"]["type"] == args.light:
                picked.append(c)
    doc = {"format": "arealight-cases/1", "comment": args.comment, "cases": picked}
    with open(args.out, "w") as f:
        json.dump(doc, f, indent=1)
        f.write("\n")
    print("%s: %d cases" % (args.out, len(picked)))


if __name__ == "__main__":
    main()
