#!/usr/bin/env python3
"""Finds report rows whose errors the current shaders no longer give.

Reports are regenerated in parts (scripts/splice_report.py puts a new run's rows into the
committed reports), so a row can outlive the shader it measured: a change to a template
that its author did not expect to move that variant leaves the row, and with it
data/quality/measured.json and the scene selection, describing older code. This re-runs
every row's variant on its report's case files with the CPU mirror (`arealight eval
--backend cpu`, which computes the shader's own math), pools relL2 per quantity against
the case files' reference results (X.ref.json beside X.cases.json), and runs each row
whose committed relL2 differs from the mirror's by more than --rel of the larger and more
than --abs again on lavapipe (`--backend vulkan`, what the reports measure): the mirror's
fp32 exp and log are not the driver's, and small errors differ between them (beckmann
lorentz polygon ndf 0.0145 on the mirror, 0.0129 on lavapipe). A row is listed as stale
when lavapipe's relL2 differs from it as well.

Usage: python3 scripts/check_reports.py [--arealight build/arealight] [--jobs 2]
       [--rel 0.1] [--abs 2e-4] [REPORT.json ...]   (default: docs/report*/report.json)
Exit status: 0 when every row matches, 1 when some row is stale, 2 on bad input.
Standard library only. About a minute for every committed report on two cores.
"""
import argparse
import concurrent.futures
import glob
import json
import math
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
QUANTITIES = ("diffuse", "specular", "ndf", "moment")


def fail(msg):
    print("check_reports: " + msg, file=sys.stderr)
    sys.exit(2)


def load_json(path):
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError) as e:
        fail(f"{path}: {e}")


def ref_of(cases_path):
    ref = cases_path[: -len(".cases.json")] + ".ref.json" if cases_path.endswith(".cases.json") else ""
    if not ref or not os.path.exists(ref):
        fail(f"{cases_path}: no reference results beside it ({ref or 'X.ref.json'})")
    return {r["id"]: r for r in load_json(ref)["results"]}


def evaluate(arealight, variant, cases_path, tmp, backend="cpu"):
    out = os.path.join(tmp, f"{abs(hash((variant, cases_path, backend)))}.json")
    run = subprocess.run([arealight, "eval", "--cases", cases_path, "--variant", variant,
                          "--backend", backend, "--out", out], capture_output=True, text=True)
    if run.returncode != 0:
        fail(f"{variant} on {cases_path}: arealight eval failed: {run.stderr.strip()}")
    return load_json(out)["results"]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("reports", nargs="*")
    ap.add_argument("--arealight", default=os.path.join(ROOT, "build", "arealight"))
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--rel", type=float, default=0.1)
    ap.add_argument("--abs", type=float, default=2e-4)
    args = ap.parse_args()
    reports = args.reports or sorted(glob.glob(os.path.join(ROOT, "docs", "report*", "report.json")))
    if not reports:
        fail("no report given or found")
    jobs, rows = {}, []
    for path in reports:
        rep = load_json(path)
        files = [f if os.path.isabs(f) else os.path.join(ROOT, f) for f in rep["case_files"]]
        for row in rep["rows"]:
            rows.append((path, row, files))
            for f in files:
                jobs[(row["variant"], f)] = None
    refs = {f: ref_of(f) for (_, f) in jobs}
    with tempfile.TemporaryDirectory() as tmp, \
            concurrent.futures.ThreadPoolExecutor(max_workers=max(args.jobs, 1)) as pool:
        futures = {key: pool.submit(evaluate, args.arealight, key[0], key[1], tmp) for key in jobs}
        # Progress: one line rewritten in place on a terminal, a line per 200 otherwise.
        live = sys.stderr.isatty()
        done = 0
        for key, fut in futures.items():
            jobs[key] = fut.result()
            done += 1
            line = f"check_reports: {done}/{len(futures)} evaluations"
            if live:
                print("\r" + line, end="\n" if done == len(futures) else "", file=sys.stderr,
                      flush=True)
            elif done % 200 == 0 or done == len(futures):
                print(line, file=sys.stderr)

        def pooled(results, q):
            num = den = 0.0
            for f, res in results:
                for r in res:
                    ref = refs[f].get(r["id"], {})
                    if q in r and q in ref:
                        num += (r[q] - ref[q]) ** 2
                        den += ref[q] ** 2
            return math.sqrt(num / den) if den > 0 else None

        def off(now, committed):
            return abs(now - committed) > max(args.rel * max(now, committed), args.abs)

        stale = confirmed = 0
        for path, row, files in rows:
            cpu = [(f, jobs[(row["variant"], f)]) for f in files]
            vulkan = None
            for q in QUANTITIES:
                committed = row.get("error", {}).get(q, {}).get("rel_l2")
                now = pooled(cpu, q) if committed is not None else None
                if now is None or not off(now, committed):
                    continue
                if vulkan is None:
                    vulkan = [(f, evaluate(args.arealight, row["variant"], f, tmp, "vulkan"))
                              for f in files]
                    confirmed += 1
                lp = pooled(vulkan, q)
                if lp is not None and off(lp, committed):
                    stale += 1
                    print(f"{os.path.relpath(path, ROOT)}: {row['variant']}: {q} relL2 "
                          f"{committed:.4g} in the report, {lp:.4g} now on lavapipe "
                          f"({now:.4g} on the CPU mirror)")
    print(f"check_reports: {len(rows)} rows of {len(reports)} report{'s' * (len(reports) != 1)}, {confirmed} re-run on "
          f"lavapipe, {stale} stale (a quantity's relL2 off by more than {args.rel:g} "
          f"relative and {args.abs:g})", file=sys.stderr)
    return 1 if stale else 0


if __name__ == "__main__":
    sys.exit(main())
