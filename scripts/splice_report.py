#!/usr/bin/env python3
"""Replace some rows of committed reports (or sweeps) by the rows of a newer one of the same cases.

A change to one family's shaders (e.g. the LTC tables) leaves every other row of the
per-light reports as measured; re-running those reports whole costs tens of minutes. This
takes a report of the changed variants, run on the same case files with their point-light
baselines (`arealight report ... --variants method=ltc --out NEW`), and puts each of its
rows whose variant has every KEY=VALUE of --only (repeatable) and none of --skip into every
report under DEST that has a row of the same variant (never the point-light baselines: the
other rows' time ratios were measured against theirs). Each row keeps what it was measured with: its own lavapipe time ratio
against the point light of the run it comes from. Afterwards run `arealight replot DEST...`,
which recomputes the Pareto and recommended marks and redraws the markdown and plots.
Sweeps (sweep.json) work the same way, a row being a variant at one value of the swept
parameter; source and destination must sweep the same axis.

Usage: python3 scripts/splice_report.py NEW/report.json DEST/report.json... [--only method=ltc]
       [--skip dist=ggx]
Standard library only. Refuses (and writes nothing) when the case files differ.
"""
import json
import sys


def main(argv):
    skip, only = [], []
    args = []
    i = 0
    while i < len(argv):
        if argv[i] in ("--skip", "--only"):
            (skip if argv[i] == "--skip" else only).append(argv[i + 1])
            i += 2
        else:
            args.append(argv[i])
            i += 1
    if len(args) < 2:
        sys.exit(__doc__)
    src_path, dests = args[0], args[1:]
    src = json.load(open(src_path))
    def wanted(variant):
        keys = variant.split(",")
        return ("method=point" not in keys and all(o in keys for o in only)
                and not any(s in keys for s in skip))

    # A sweep's rows are one per variant and value of its parameter (e.g. alpha).
    param = src.get("parameter")
    def key(r):
        return (r["variant"], r[param]) if param else r["variant"]
    rows = {key(r): r for r in src["rows"] if wanted(r["variant"])}
    out = {}
    for path in dests:
        d = json.load(open(path))
        if d["case_files"] != src["case_files"]:
            sys.exit(f"{path}: case files {d['case_files']} differ from {src_path}'s")
        if d.get("parameter") != param or d.get("axis") != src.get("axis"):
            sys.exit(f"{path}: axis {d.get('axis')} ({d.get('parameter')}) differs from "
                     f"{src_path}'s")
        n = 0
        for k, r in enumerate(d["rows"]):
            if key(r) in rows:
                d["rows"][k] = rows[key(r)]
                n += 1
        out[path] = (d, n)
    for path, (d, n) in out.items():
        with open(path, "w") as f:
            json.dump(d, f, indent=1, ensure_ascii=False)
            f.write("\n")
        print(f"{path}: {n} rows replaced from {src_path}")


if __name__ == "__main__":
    main(sys.argv[1:])
