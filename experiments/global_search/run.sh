#!/usr/bin/env bash
# Chooses the global-search algorithm of `frictionid fit` (see README.md in this directory).
#
#   experiments/global_search/run.sh          # binary: $FRICTIONID, else build/frictionid
#
# For T random truths of the seed model (Hertz pressure) it generates noise-free data, fits it
# with every global algorithm x budget x starts, and counts a success when every fitted
# parameter matches the truth to >= 8 digits. Writes out/ (scratch, git-ignored) and the
# committed summary results.csv and results.md next to this script. Fits run one at a time so
# that the wall times are comparable. Success counts are deterministic (every random draw is
# seeded); wall times are not.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
source "$here/../common.sh"

# The experiment's knobs (the README's table is for these values).
T=30                               # number of random truths
TRUTH_SEED=20240601                # seed of the truth draws
ALGORITHMS=(crs2 isres direct esch random)
BUDGETS=(500 3000)                 # --global-evaluations
STARTS=(1 4)                       # --starts
ROWS=300
DIGITS=8                           # success: min over parameters of -log10(rel. error) >= DIGITS

out="$here/out"
rm -rf "$out"
mkdir -p "$out/data" "$out/fits"

# Run a private copy of the binary so that a rebuild of build/ during the run (other work in the
# tree) can neither fail fits nor mix two versions into one table. It links only system libraries.
cp "$bin" "$out/frictionid"
bin="$out/frictionid"
binary_id="$("$bin" --version), sha256 $(sha256sum "$bin" | cut -c1-12)"

# 1. Truths: f, kappa, b, m log-uniform; h, a uniform; m above the consistency bound.
"$py" - "$T" "$TRUTH_SEED" > "$out/truths.csv" <<'PY'
import math, random, sys
n, seed = int(sys.argv[1]), int(sys.argv[2])
rng = random.Random(seed)
logu = lambda lo, hi: math.exp(rng.uniform(math.log(lo), math.log(hi)))
print("id,f,kappa,h,a,b,m")
for i in range(n):
    f = logu(0.2, 2.0)
    kappa = logu(0.3, 3.0)
    h = rng.uniform(-0.5, 0.5)
    a = rng.uniform(0.3, 3.5)
    b = logu(5.0, 200.0)
    m = logu(max(((1 + kappa) / kappa) ** 2, 1.5), 100.0)
    print(",".join([str(i)] + [repr(x) for x in (f, kappa, h, a, b, m)]))
PY

# 2. Noise-free data from each truth.
tail -n +2 "$out/truths.csv" | while IFS=, read -r id f kappa h a b m; do
  "$bin" generate --model seed --pressure hertz \
    --param "f=$f,kappa=$kappa,h=$h,a=$a,b=$b,m=$m" --rows "$ROWS" --seed 1 \
    --output "$out/data/truth$id.csv" --truth "$out/data/truth$id.json" > /dev/null
done

# 3. Fits, timed with bash's `time` (wall clock of the whole command, report writing included).
# Control row "none": --no-global, i.e. one local fit from the tool's default initial values.
TIMEFORMAT="%3R,%3U,%3S"   # wall, user, system seconds
load_before=$(cut -d" " -f1-3 /proc/loadavg)
echo "id,algorithm,budget,starts,exit,wall_s,user_s,sys_s" > "$out/runs.csv"
fit() {   # fit ID ALGORITHM BUDGET STARTS
  local id=$1 alg=$2 budget=$3 starts=$4 rc=0
  local dir="$out/fits/truth${id}_${alg}_${budget}_${starts}"
  local global=(--global-algorithm "$alg" --global-evaluations "$budget" --starts "$starts")
  [[ "$alg" != none ]] || global=(--no-global)
  mkdir -p "$dir"
  { time "$bin" fit "$out/data/truth$id.csv" --model seed --pressure hertz "${global[@]}" \
      --seed 1 --report "$dir/report" > "$dir/stdout" 2> "$dir/stderr" || rc=$?; } 2> "$dir/time"
  echo "$id,$alg,$budget,$starts,$rc,$(tail -n 1 "$dir/time")" >> "$out/runs.csv"
  # keep only report.json (the plots would take hundreds of MB)
  if [[ -f "$dir/report/report.json" ]]; then mv "$dir/report/report.json" "$dir/report.json"; fi
  rm -rf "$dir/report"
}
for (( id = 0; id < T; id++ )); do
  for alg in "${ALGORITHMS[@]}"; do
    for budget in "${BUDGETS[@]}"; do
      for starts in "${STARTS[@]}"; do
        fit "$id" "$alg" "$budget" "$starts"
      done
    done
  done
  fit "$id" none 0 1
  echo "run.sh: truth $((id + 1))/$T done" >&2
done
load_after=$(cut -d" " -f1-3 /proc/loadavg)

# 4. Score and summarise.
"$py" - "$out" "$here" "$DIGITS" "$T" "$binary_id" "$(nproc)" "$load_before" "$load_after" <<'PY'
import csv, json, math, os, statistics, sys
out, here, need, T = sys.argv[1], sys.argv[2], float(sys.argv[3]), int(sys.argv[4])
binary_id, cpus, load_before, load_after = sys.argv[5:9]
truths = {r["id"]: r for r in csv.DictReader(open(os.path.join(out, "truths.csv")))}
names = ["f", "kappa", "h", "a", "b", "m"]

def digits(fit, true):
    err = abs(fit - true) / abs(true)
    return 17.0 if err == 0 else min(17.0, -math.log10(err))

fits, groups = [], {}
for r in csv.DictReader(open(os.path.join(out, "runs.csv"))):
    key = (r["algorithm"], int(r["budget"]), int(r["starts"]))
    path = os.path.join(out, "fits", f"truth{r['id']}_{key[0]}_{key[1]}_{key[2]}", "report.json")
    row = dict(id=r["id"], algorithm=key[0], budget=key[1], starts=key[2], exit=int(r["exit"]),
               wall_s=float(r["wall_s"]), cpu_s=round(float(r["user_s"]) + float(r["sys_s"]), 3),
               min_digits="", worst="", cost="", global_evaluations="", success=0)
    if row["exit"] == 0 and os.path.exists(path):
        rep = json.load(open(path))
        d = {n: digits(rep["parameters"][n]["value"], float(truths[r["id"]][n])) for n in names}
        worst = min(d, key=d.get)
        row.update(min_digits=round(d[worst], 2), worst=worst, cost=rep["statistics"]["cost"],
                   global_evaluations=rep["global_search"]["evaluations"], success=int(d[worst] >= need))
    fits.append(row)
    groups.setdefault(key, []).append(row)

with open(os.path.join(out, "fits.csv"), "w", newline="") as fh:
    w = csv.DictWriter(fh, fieldnames=list(fits[0]))
    w.writeheader(); w.writerows(fits)

summary = []
for (alg, budget, starts), rows in groups.items():
    ok = sum(r["success"] for r in rows)
    failed = sum(r["exit"] != 0 for r in rows)
    dig = [r["min_digits"] if r["min_digits"] != "" else 0.0 for r in rows]
    summary.append(dict(algorithm=alg, budget=budget, starts=starts, fits=len(rows), successes=ok,
                        success_rate=round(ok / len(rows), 3),
                        median_wall_s=round(statistics.median(r["wall_s"] for r in rows), 3),
                        median_cpu_s=round(statistics.median(r["cpu_s"] for r in rows), 3),
                        median_min_digits=round(statistics.median(dig), 1), failed_exit=failed))

with open(os.path.join(here, "results.csv"), "w", newline="") as fh:
    w = csv.DictWriter(fh, fieldnames=list(summary[0]))
    w.writeheader(); w.writerows(summary)

lines = [f"Seed model, Hertz pressure, {T} random noise-free truths, {need:g}-digit success criterion; "
         f"{binary_id}, {cpus} CPUs, fits run one at a time, load average {load_before} before and "
         f"{load_after} after.", "",
         "| algorithm | budget | starts | successes | success rate | median wall [s] | median CPU [s] | median min digits | exit != 0 |",
         "|---|---:|---:|---:|---:|---:|---:|---:|---:|"]
for s in summary:
    name = "none (--no-global)" if s["algorithm"] == "none" else s["algorithm"]
    lines.append(f"| {name} | {s['budget']} | {s['starts']} | {s['successes']}/{s['fits']} | "
                 f"{100 * s['success_rate']:.0f} % | {s['median_wall_s']:.3f} | {s['median_cpu_s']:.3f} | "
                 f"{s['median_min_digits']:.1f} | {s['failed_exit']} |")
open(os.path.join(here, "results.md"), "w").write("\n".join(lines) + "\n")
print("\n".join(lines))
PY
