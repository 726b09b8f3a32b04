#!/usr/bin/env bash
# Reruns every `arealight eval` + `shared/tools/score` measurement that the accuracy tables
# of docs/methods.md (Phong exact and peak methods), docs/microfacet.md (microfacet exact,
# O(1) nodes, the paper's method) and docs/ltc.md (LTC and its keys) quote, with their inline
# numbers (not the report- or sweep-derived tables of docs/reports.md, which come from
# docs/report*/ and docs/sweep*/), then prints each table's cells in that page's layout,
# each headed by the page it goes to. Outputs and score JSON go to out/remeasure/.
# (The name is historical: these tables lived in README.md.)
# Usage: scripts/readme_tables.sh [BUILD_DIR]   (default build; lavapipe + CPU mirror)
set -euo pipefail
cd "$(dirname "$0")/.."
A=${1:-build}/arealight
V=../shared/validation
SCORE=../shared/tools/score
O=out/remeasure
mkdir -p "$O"
: >"$O/eval.log"
PUB="typical horizon glossy stress"

# The two seeded sets the pages name; their oracle is `arealight reference`.
python3 scripts/gen_phong_cases.py 600 11 "$O/rand.cases.json"
python3 scripts/gen_microfacet_cases.py 600 7 "$O/hard.cases.json"
for s in rand hard; do
  "$A" reference --cases "$O/$s.cases.json" --out "$O/$s.ref.json" --threads 2 2>>"$O/eval.log"
done

cases() { case $1 in rand|hard) echo "$O/$1.cases.json" ;; *) echo "$V/$1.cases.json" ;; esac; }
ref() { case $1 in rand|hard) echo "$O/$1.ref.json" ;; *) echo "$V/$1.ref.json" ;; esac; }

# run TAG SET FLOOR BACKEND VARIANT: eval, then score against the oracle (--present:
# each variant runs on the cases of its distribution only).
run() {
  local tag=$1 set=$2 floor=$3 backend=$4 variant=$5
  "$A" eval --cases "$(cases "$set")" --variant "$variant" --backend "$backend" \
    --out "$O/$tag.$set.$backend.json" 2>>"$O/eval.log"
  "$SCORE" "$(ref "$set")" "$O/$tag.$set.$backend.json" --present --floor "$floor" --json \
    >"$O/$tag.$set.$backend.score.json"
}
# agree TAG SET FLOOR: the CPU mirror scored against lavapipe.
agree() {
  "$SCORE" "$O/$1.$2.vulkan.json" "$O/$1.$2.cpu.json" --present --floor "$3" --json >"$O/$1.$2.agree.json"
}

# Phong, method=exact (floor 1e-3), both precisions and backends.
for p in fp64 fp32; do for s in $PUB; do for b in vulkan cpu; do
  run phong-exact-$p $s 1e-3 $b dist=phong,method=exact,light=polygon,precision=$p
done; agree phong-exact-$p $s 1e-3; done; done

# Phong peak methods (floor 1e-2): all 12 on every set, both backends.
for m in ellipsoid pearson lorentz; do for f in tuned paper; do for sp in twoaxis sg; do
  tag=phong-$m-$f-$sp
  for s in $PUB rand; do for b in vulkan cpu; do
    run $tag $s 1e-2 $b dist=phong,method=$m,light=polygon,fit=$f,specular=$sp
  done; agree $tag $s 1e-2; done
done; done; done

for d in blinn beckmann ggx; do
  # exact at its defaults (floor 1e-3) and in fp32, both backends; the default on the hard set.
  for p in fp64 fp32; do for s in $PUB; do for b in vulkan cpu; do
    run $d-exact-$p $s 1e-3 $b dist=$d,method=exact,light=polygon,precision=$p
  done; agree $d-exact-$p $s 1e-3; done; done
  run $d-exact-fp64 hard 1e-3 vulkan dist=$d,method=exact,light=polygon
  # O(1) node counts (floor 1e-2).
  for n in 2 3 16; do
    [ $n = 16 ] && [ $d != ggx ] && continue
    for s in $PUB hard; do
      run $d-exact-n$n $s 1e-2 vulkan dist=$d,method=exact,light=polygon,nodes=$n,radial=2,precision=fp32
    done
  done
  # The paper's method (floor 1e-2) at its defaults and with split=single / factor=closest.
  for m in lorentz pearson ellipsoid; do
    for k in "" split=single factor=closest; do
      tag=$d-$m${k:+-${k#*=}}
      for s in $PUB; do run $tag $s 1e-2 vulkan dist=$d,method=$m,light=polygon${k:+,$k}; done
    done
    run $d-$m hard 1e-2 vulkan dist=$d,method=$m,light=polygon
  done
done

# LTC (floor 1e-2): every distribution, both backends; GGX's keys.
for d in ggx beckmann blinn phong; do for s in $PUB; do for b in vulkan cpu; do
  run $d-ltc $s 1e-2 $b dist=$d,method=ltc,light=polygon
done; agree $d-ltc $s 1e-2; done; done
for k in edge=poly horizon=proxy precision=fp16; do for s in $PUB; do
  run ggx-ltc-${k#*=} $s 1e-2 vulkan dist=ggx,method=ltc,light=polygon,$k
done; done

python3 - "$O" <<'PY'
import json, sys, glob, os
O = sys.argv[1]
def sc(tag, s, b="vulkan"):
    return json.load(open(f"{O}/{tag}.{s}.{b}.score.json"))["quantities"]
def ag(tag, s):
    return json.load(open(f"{O}/{tag}.{s}.agree.json"))["quantities"]
def e(x):  # 2 significant digits, as the pages write them: 6.6e-8
    m, x_ = f"{x:.1e}".split("e")
    return f"{m}e{int(x_)}"
def mixed(x):  # decimals from 0.1 up, as in the microfacet tables
    return f"{x:#.2g}" if x >= 0.1 else e(x)
def dec(x):  # decimals, as in the LTC tables
    return f"{x:#.2g}" if x >= 1e-4 else e(x)
PUB = ["typical", "horizon", "glossy", "stress"]
def bad(tag, sets, backends=("vulkan",)):
    return sum(q["missing"] + q["bad"] for s in sets for b in backends for q in sc(tag, s, b).values())

print("== docs/methods.md: phong exact, floor 1e-3, p95 / max (fp32: worse of lavapipe and mirror)")
for p in ["fp64", "fp32"]:
    for s in PUB:
        cells = []
        for q in ["diffuse", "specular", "moment"]:
            v = [sc(f"phong-exact-{p}", s, b)[q] for b in ("vulkan", "cpu")]
            cells.append(f"{e(max(x['p95'] for x in v))} / {e(max(x['max'] for x in v))}")
        print(f"| {s}, {p} | " + " | ".join(cells) + " |")
    print(f"  {p}: mirror vs lavapipe max rel", e(max(q["max"] for s in PUB for q in ag(f"phong-exact-{p}", s).values())),
          " missing+bad", bad(f"phong-exact-{p}", PUB, ("vulkan", "cpu")))

print("== docs/methods.md: phong peak, floor 1e-2, relL2 / p95")
rows = [("ellipsoid", "tuned", "twoaxis"), ("pearson", "tuned", "twoaxis"), ("lorentz", "tuned", "twoaxis"),
        ("ellipsoid", "paper", "twoaxis"), ("pearson", "paper", "twoaxis"), ("lorentz", "paper", "twoaxis"),
        ("ellipsoid", "tuned", "sg")]
cols = [("typical", "moment"), ("typical", "specular"), ("glossy", "moment"), ("glossy", "specular"),
        ("horizon", "moment"), ("rand", "moment")]
for m, f, sp in rows:
    t = f"phong-{m}-{f}-{sp}"
    cells = [f"{e(sc(t, s)[q]['relL2'])} / {e(sc(t, s)[q]['p95'])}" for s, q in cols]
    if sp == "sg":
        r = sc(t, "rand")["specular"]
        cells[5] = f"specular {e(r['relL2'])} / {e(r['p95'])}"
    print(f"| {m}{', fit=paper' if f == 'paper' else ''}{', specular=sg' if sp == 'sg' else ''} | " + " | ".join(cells) + " |")
tags = [os.path.basename(p).split(".")[0] for p in glob.glob(f"{O}/phong-*-*-*.typical.vulkan.json")]
tags = sorted({t for t in tags if not t.startswith("phong-exact")})
print(f"  {len(tags)} peak variants, missing+bad over all sets and both backends:",
      sum(bad(t, PUB + ["rand"], ("vulkan", "cpu")) for t in tags))
print("  mirror vs lavapipe max rel:", e(max(q["max"] for t in tags for s in PUB + ["rand"] for q in ag(t, s).values())))

print("== docs/microfacet.md: microfacet exact default, floor 1e-3, p95 / max")
for d in ["blinn", "beckmann", "ggx"]:
    for s in PUB:
        v = sc(f"{d}-exact-fp64", s)
        print(f"| {d} | {s} | " + " | ".join(f"{e(v[q]['p95'])} / {e(v[q]['max'])}" for q in ["diffuse", "specular", "ndf"]) + " |")
print("  fp64 mirror vs lavapipe max rel:", e(max(q["max"] for d in ["blinn", "beckmann", "ggx"] for s in PUB for q in ag(f"{d}-exact-fp64", s).values())),
      " missing+bad:", sum(bad(f"{d}-exact-fp64", PUB, ("vulkan", "cpu")) for d in ["blinn", "beckmann", "ggx"]))
for d in ["blinn", "beckmann", "ggx"]:
    h = sc(f"{d}-exact-fp64", "hard")
    print(f"  hard {d}: relL2 ndf {e(h['ndf']['relL2'])} specular {e(h['specular']['relL2'])};"
          f" max ndf {e(h['ndf']['max'])} specular {e(h['specular']['max'])} ({h['specular']['worst']})")
for b in ["vulkan", "cpu"]:
    p95 = max((sc(f"{d}-exact-fp32", s, b)[q]["p95"], d, s, q) for d in ["blinn", "beckmann", "ggx"] for s in PUB for q in ["specular", "ndf", "diffuse"])
    mx = max((sc(f"{d}-exact-fp32", s, b)[q]["max"], d, s, q) for d in ["blinn", "beckmann", "ggx"] for s in PUB for q in ["specular", "ndf", "diffuse"])
    print(f"  fp32 on {b}: largest p95 {e(p95[0])} {p95[1:]}; largest max {e(mx[0])} {mx[1:]}")
    for d in ["blinn", "beckmann", "ggx"]:
        for s in PUB:
            v = sc(f"{d}-exact-fp32", s, b)
            print(f"    {d} {s} (n={v['specular']['n']}) p95 / max:", "  ".join(f"{q} {e(v[q]['p95'])} / {e(v[q]['max'])}" for q in ["diffuse", "specular", "ndf"]))

print("== docs/microfacet.md: O(1) nodes, floor 1e-2, specular relL2 / p95")
for d, n in [("blinn", 2), ("blinn", 3), ("beckmann", 2), ("beckmann", 3), ("ggx", 2), ("ggx", 3), ("ggx", 16)]:
    cells = [f"{mixed(sc(f'{d}-exact-n{n}', s)['specular']['relL2'])} / {mixed(sc(f'{d}-exact-n{n}', s)['specular']['p95'])}" for s in PUB + ["hard"]]
    print(f"| {d}, nodes={n} | " + " | ".join(cells) + " |")

print("== docs/microfacet.md: paper's method, floor 1e-2, specular relL2 / p95 (ndf relL2)")
for d in ["blinn", "beckmann", "ggx"]:
    for m in ["lorentz", "pearson", "ellipsoid"]:
        cells = []
        for s in PUB:
            v = sc(f"{d}-{m}", s)
            cells.append(f"{mixed(v['specular']['relL2'])} / {mixed(v['specular']['p95'])} ({mixed(v['ndf']['relL2'])})")
        print(f"| {d}, {m} | " + " | ".join(cells) + " |")
for k in ["single", "closest"]:
    r = {s: [sc(f"{d}-{m}-{k}", s)["specular"]["relL2"] / sc(f"{d}-{m}", s)["specular"]["relL2"]
             for d in ["blinn", "beckmann", "ggx"] for m in ["lorentz", "pearson", "ellipsoid"]] for s in PUB}
    print(f"  {k} / default specular relL2 ratio per set (min..max):", {s: f"{min(v):.2f}..{max(v):.2f}" for s, v in r.items()})
    if k == "closest":
        for d in ["blinn", "beckmann", "ggx"]:
            print(f"    {d}:", {s: " ".join(f"{sc(f'{d}-{m}-closest', s)['specular']['relL2'] / sc(f'{d}-{m}', s)['specular']['relL2']:.2f}" for m in ["lorentz", "pearson", "ellipsoid"]) for s in PUB})
print("  hard set specular relL2, exact nodes=3 / pearson:",
      " / ".join(mixed(sc(f"{d}-exact-n3", "hard")["specular"]["relL2"]) for d in ["blinn", "beckmann", "ggx"]), "|",
      " / ".join(mixed(sc(f"{d}-pearson", "hard")["specular"]["relL2"]) for d in ["blinn", "beckmann", "ggx"]))

print("== docs/ltc.md: LTC, floor 1e-2, specular relL2")
for d in ["ggx", "beckmann", "blinn", "phong"]:
    print(f"| {d} | " + " | ".join(dec(sc(f"{d}-ltc", s)["specular"]["relL2"]) for s in PUB) + " |")
print("  diffuse relL2 max:", e(max(sc(f"{d}-ltc", s)["diffuse"]["relL2"] for d in ["ggx", "beckmann", "blinn", "phong"] for s in PUB)))
print("  mirror vs lavapipe max rel:", e(max(q["max"] for d in ["ggx", "beckmann", "blinn", "phong"] for s in PUB for q in ag(f"{d}-ltc", s).values())))
for k in ["poly", "proxy", "fp16"]:
    print(f"| ltc,{k} | " + " | ".join(dec(sc(f"ggx-ltc-{k}", s)["specular"]["relL2"]) for s in PUB) + " |")
PY
