#!/usr/bin/env bash
# frictionid's fit against scipy.optimize.least_squares on the same problem (see README.md).
#
#   experiments/bench_fit_vs_scipy/run.sh     # binary: $FRICTIONID, else build/frictionid
#
# 0. Checks that fit_scipy.py's seed model reproduces `frictionid eval --model seed` to 1e-12
#    relative (aligned and general slip, edge cases), and stops if it does not.
# 1. For rows in 1e3 1e4 1e5 1e6: generates seed/Hertz data with 1 % noise, then alternates,
#    REPS times: frictionid's local stage alone (--no-global --param START --starts 1) on every
#    core (the default) and on one thread, the full pipeline (global stage + 4 local fits on
#    the subsample + the refinement on all rows), and least_squares from START. frictionid
#    reads the data with the scales least_squares whitens by as sigma columns
#    (fit_scipy.py with-sigma) and --noise-model columns: the same least-squares problem, where
#    its default would estimate a noise model and refit (a different problem).
# 2. Writes runs.csv (every run), results.csv and results.md (medians per size) and results.svg
#    (log-log time vs rows) next to this script; scratch in out/ (git-ignored).
# Runs one at a time; wall times depend on the machine's load (recorded in results.md).
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
source "$here/../common.sh"
command -v gnuplot > /dev/null || { echo "run.sh: gnuplot not found" >&2; exit 1; }

# The experiment's knobs (the README's table is for these values).
read -ra ROWS <<< "${ROWS_LIST:-1000 10000 100000 1000000}"
REPS=${REPS:-5}                  # repetitions for rows <= 1e5
REPS_LARGE=${REPS_LARGE:-3}      # repetitions for rows > 1e5
SCIPY_ONCE_ABOVE=${SCIPY_ONCE_ABOVE:-120}   # s: a slower scipy fit is not repeated at that size
TRUTH="f=0.85,kappa=1.3,h=0.12,a=0.9,b=20,m=7"
START="f=0.7,kappa=1,h=0.05,a=0.7,b=25,m=8"
MODEL=(--model seed --pressure hertz)
# numpy's BLAS stays serial (least_squares is single-threaded Python); frictionid runs its
# row passes on every core by default and once more with --threads 1.
export OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 MKL_NUM_THREADS=1

out="$here/out"
if [[ -n "${SUMMARY_ONLY:-}" ]]; then   # re-summarise the runs in out/ without timing anything
  [[ -f "$out/meta.sh" ]] || { echo "run.sh: no finished run in $out" >&2; exit 1; }
  source "$out/meta.sh"
else
rm -rf "$out"
mkdir -p "$out/data" "$out/runs" "$out/check"
# A private copy of the binary: a rebuild of build/ during the run (other work in the tree) can
# neither fail a run nor mix two versions into one table. It links only system libraries.
cp "$bin" "$out/frictionid"
bin="$out/frictionid"
binary_id="$("$bin" --version), sha256 $(sha256sum "$bin" | cut -c1-12)"
started=$(date +%s)

# 0. The scipy model against frictionid eval.
echo "run.sh: checking fit_scipy.py's model against frictionid eval" >&2
c="$out/check"
"$bin" generate "${MODEL[@]}" --param "$TRUTH" --rows 1000 --noise 0.01 --seed 3 \
  --output "$c/aligned.csv" > /dev/null 2>&1
"$bin" generate "${MODEL[@]}" --param "$TRUTH" --rows 1000 --noise 0.01 --seed 3 \
  --slip-angles 0,30,90,135,-60,180,270 --eps-min 1e-3 --eps-max 1e3 \
  --output "$c/general.csv" > /dev/null 2>&1
cat > "$c/edge.csv" <<'CSV'
v_x,v_y,omega,N,R
0,0,0,1000,0.05
0,0,2,1000,0.05
0,0,-2,1000,0.05
0.1,0,0,1000,0.05
-0.1,0,0,1000,0.05
0,0.1,0,1000,0.05
0.1,0,2,1000,0.05
0.1,0,-2,1000,0.05
0.05,0.05,-2,1000,0.05
-0.07,0.02,3,500,0.02
1e-9,0,2,1000,0.05
0.1,0,2,1000,0.05
1e9,0,2,1000,0.05
0,-1e9,2,1000,0.05
CSV
: > "$out/check.txt"
for data in aligned general edge; do
  for p in "$TRUTH" "$START" "f=2,kappa=0.2,h=-0.6,a=3,b=500,m=90"; do
    "$bin" eval "${MODEL[@]}" --param "$p" --input "$c/$data.csv" --output "$c/pred.csv" \
      > /dev/null 2>&1
    if ! "$py" "$here/fit_scipy.py" check "$c/$data.csv" "$c/pred.csv" --param "$p" \
         > "$c/out.txt"; then
      cat "$c/out.txt" >&2
      echo "run.sh: fit_scipy.py's model disagrees with frictionid eval ($data, $p)" >&2
      exit 1
    fi
    echo "$data, $p: $(tail -n 1 "$c/out.txt")" >> "$out/check.txt"
  done
done
cat "$out/check.txt" >&2

# 1. Timed runs, one at a time. `time` gives wall, user and system seconds of a whole command.
TIMEFORMAT="%3R,%3U,%3S"
load_before=$(cut -d" " -f1-3 /proc/loadavg)
echo "rows,rep,method,exit,wall_s,user_s,sys_s" > "$out/runs.csv"
run() {   # run ROWS REP METHOD COMMAND...  (the command runs in its run directory)
  local n=$1 rep=$2 method=$3 rc=0
  shift 3
  local dir="$out/runs/${n}_${rep}_${method}"
  mkdir -p "$dir"
  { time (cd "$dir" && "$@" > stdout 2> stderr) || rc=$?; } 2> "$dir/time"
  echo "$n,$rep,$method,$rc,$(tail -n 1 "$dir/time")" >> "$out/runs.csv"
  # keep report.json only (the plots of 1e6 rows take tens of MB)
  if [[ -d "$dir/report" ]]; then
    [[ ! -f "$dir/report/report.json" ]] || mv "$dir/report/report.json" "$dir/report.json"
    rm -rf "$dir/report"
  fi
  [[ $rc -eq 0 ]] || echo "run.sh: $method at $n rows, repetition $rep, exited with $rc" >&2
}
for n in "${ROWS[@]}"; do
  data="$out/data/rows$n.csv"
  "$bin" generate "${MODEL[@]}" --param "$TRUTH" --rows "$n" --noise 0.01 --seed 3 \
    --output "$data" > /dev/null 2>&1
  sdata="$out/data/rows${n}_sigma.csv"
  "$py" "$here/fit_scipy.py" with-sigma "$data" "$sdata"
  reps=$REPS
  (( n <= 100000 )) || reps=$REPS_LARGE
  scipy_on=1
  for (( rep = 1; rep <= reps; rep++ )); do
    run "$n" "$rep" local "$bin" fit "$sdata" "${MODEL[@]}" --noise-model columns \
      --no-global --param "$START" --starts 1 --report report
    run "$n" "$rep" local1 "$bin" fit "$sdata" "${MODEL[@]}" --noise-model columns \
      --no-global --param "$START" --starts 1 --threads 1 --report report
    run "$n" "$rep" full "$bin" fit "$sdata" "${MODEL[@]}" --noise-model columns --report report
    if (( scipy_on )); then
      run "$n" "$rep" scipy "$py" "$here/fit_scipy.py" fit "$data" --param "$START" \
        --aligned-only --json result.json
      t=$("$py" -c 'import json,sys; print(json.load(open(sys.argv[1]))["wall_s"])' \
            "$out/runs/${n}_${rep}_scipy/result.json" 2> /dev/null || echo 0)
      if "$py" -c 'import sys; sys.exit(not float(sys.argv[1]) > float(sys.argv[2]))' \
           "$t" "$SCIPY_ONCE_ABOVE"; then
        scipy_on=0
        echo "run.sh: scipy took $t s at $n rows (> $SCIPY_ONCE_ABOVE s): not repeated" >&2
      fi
    fi
    echo "run.sh: $n rows, repetition $rep/$reps done ($(( $(date +%s) - started )) s so far)" >&2
  done
  rm -f "$data"
done
load_after=$(cut -d" " -f1-3 /proc/loadavg)
elapsed=$(( $(date +%s) - started ))
printf 'binary_id=%q\nload_before=%q\nload_after=%q\nelapsed=%q\n' \
  "$binary_id" "$load_before" "$load_after" "$elapsed" > "$out/meta.sh"
fi

# 2. Summary.
"$py" - "$out" "$here" "$binary_id" "$(getconf _NPROCESSORS_ONLN)" "$load_before" "$load_after" "$elapsed" \
  "$START" <<'PY'
import csv, json, math, os, re, statistics, sys

out, here, binary_id, cpus, load_before, load_after, elapsed, start = sys.argv[1:9]
TIME = re.compile(r"time: reading [0-9.]+ s, global stage ([0-9.]+) s, local fits ([0-9.]+) s, "
                  r"statistics and predictions ([0-9.]+) s")

runs = []
for r in csv.DictReader(open(os.path.join(out, "runs.csv"))):
    d = os.path.join(out, "runs", f"{r['rows']}_{r['rep']}_{r['method']}")
    row = dict(rows=int(r["rows"]), rep=int(r["rep"]), method=r["method"], exit=int(r["exit"]),
               command_wall_s=float(r["wall_s"]),
               command_cpu_s=round(float(r["user_s"]) + float(r["sys_s"]), 3),
               global_s="", local_s="", statistics_s="", solver_wall_s="", solver_cpu_s="",
               cost="", iterations="", nfev="", njev="", termination="")
    if row["exit"] == 0 and r["method"] in ("local", "local1", "full"):
        m = TIME.search(open(os.path.join(d, "stdout")).read())
        rep = json.load(open(os.path.join(d, "report.json")))
        row.update(global_s=float(m.group(1)), local_s=float(m.group(2)),
                   statistics_s=float(m.group(3)), solver_wall_s=float(m.group(2)),
                   cost=rep["statistics"]["cost"], iterations=rep["solver"]["iterations"],
                   termination=rep["solver"]["termination"])
    elif row["exit"] == 0:
        res = json.load(open(os.path.join(d, "result.json")))
        row.update(solver_wall_s=res["wall_s"], solver_cpu_s=res["cpu_s"], cost=res["cost"],
                   nfev=res["nfev"], njev=res["njev"], termination=res["message"])
    runs.append(row)
with open(os.path.join(here, "runs.csv"), "w", newline="") as fh:
    w = csv.DictWriter(fh, fieldnames=list(runs[0]))
    w.writeheader()
    w.writerows(runs)

def ok(n, method):
    return [r for r in runs if r["rows"] == n and r["method"] == method and r["exit"] == 0]

def med(rs, key):
    return statistics.median(r[key] for r in rs) if rs else float("nan")

def one(rs, key):
    """The value every run of a series agrees on (fits are deterministic), else the median."""
    vals = {r[key] for r in rs}
    return vals.pop() if len(vals) == 1 else med(rs, key)

summary = []
for n in sorted({r["rows"] for r in runs}):
    lo, l1, fu, sc = ok(n, "local"), ok(n, "local1"), ok(n, "full"), ok(n, "scipy")
    c_lo, c_fu, c_sc = one(lo, "cost"), one(fu, "cost"), one(sc, "cost")
    s = dict(rows=n, runs_local=len(lo), runs_full=len(fu), runs_scipy=len(sc),
             frictionid_local_s=med(lo, "local_s"),
             frictionid_local_1thread_s=med(l1, "local_s"),
             frictionid_local_command_s=med(lo, "command_wall_s"),
             frictionid_local_command_cpu_s=med(lo, "command_cpu_s"),
             frictionid_full_s=med(fu, "command_wall_s"),
             frictionid_full_cpu_s=med(fu, "command_cpu_s"),
             frictionid_full_global_s=med(fu, "global_s"),
             frictionid_full_local_s=med(fu, "local_s"),
             scipy_s=med(sc, "solver_wall_s"), scipy_cpu_s=med(sc, "solver_cpu_s"),
             scipy_command_s=med(sc, "command_wall_s"))
    s["ratio_scipy_to_local"] = s["scipy_s"] / s["frictionid_local_s"]
    s["ratio_scipy_to_local_1thread"] = s["scipy_s"] / s["frictionid_local_1thread_s"]
    # Work-normalised: per row and per Jacobian (Ceres: iteration; scipy: njev, i.e. 1 + 6
    # finite-difference evaluations and one SVD of the scaled Jacobian).
    s["frictionid_local_us_per_row_iteration"] = \
        med([dict(v=r["local_s"] / max(r["iterations"], 1)) for r in lo], "v") / n * 1e6
    s["scipy_us_per_row_jacobian"] = \
        med([dict(v=r["solver_wall_s"] / max(r["njev"], 1)) for r in sc], "v") / n * 1e6
    s.update(cost_frictionid_local=c_lo, cost_frictionid_full=c_fu, cost_scipy=c_sc,
             rel_diff_scipy_vs_local=(c_sc - c_lo) / c_lo,
             rel_diff_full_vs_local=(c_fu - c_lo) / c_lo,
             iterations_local=one(lo, "iterations"), scipy_nfev=one(sc, "nfev"),
             scipy_njev=one(sc, "njev"),
             cost_spread_local=max(r["cost"] for r in lo) - min(r["cost"] for r in lo),
             cost_spread_scipy=max(r["cost"] for r in sc) - min(r["cost"] for r in sc))
    summary.append(s)
with open(os.path.join(here, "results.csv"), "w", newline="") as fh:
    w = csv.DictWriter(fh, fieldnames=list(summary[0]))
    w.writeheader()
    for s in summary:
        w.writerow({k: (repr(v) if k.startswith(("cost", "rel_diff")) else f"{v:.6g}")
                    if isinstance(v, float) else v for k, v in s.items()})

def slope(key, pts=None):
    pts = [s for s in summary if s[key] > 0] if pts is None else pts
    x = [math.log10(s["rows"]) for s in pts]
    y = [math.log10(s[key]) for s in pts]
    mx, my = sum(x) / len(x), sum(y) / len(y)
    return sum((a - mx) * (b - my) for a, b in zip(x, y)) / sum((a - mx) ** 2 for a in x)

top = summary[-2:]
for s in summary:
    s["frictionid_local_s_per_iteration"] = s["frictionid_local_us_per_row_iteration"] * s["rows"] * 1e-6
slopes = {k: (slope(k), slope(k, top)) for k in
          ("frictionid_local_s", "frictionid_local_1thread_s", "frictionid_local_s_per_iteration",
           "frictionid_full_s", "scipy_s")}

def e(n):
    k = round(math.log10(n))
    return f"1e{k}" if 10 ** k == n else str(n)

def sig(v, d=3):
    return f"{v:.{d}g}" if abs(v) >= 1e-3 else f"{v:.2e}"

lines = [
    f"Seed model, Hertz pressure, truth f=0.85,kappa=1.3,h=0.12,a=0.9,b=20,m=7, 1 % noise, "
    f"4 channels; start {start}. {binary_id}; {cpus} CPUs shared with other work, load average "
    f"{load_before} before and {load_after} after; whole run {elapsed} s. Times are wall-clock "
    f"medians: frictionid local = its reported \"local fits\" time (Ceres only), on {cpus} "
    f"threads (the default) and on 1; full = the whole `fit` command (CSV read, global stage, "
    f"local fits, statistics, report); scipy = the least_squares call only (single-threaded). "
    f"Costs are ½Σr² at the end of each fit.", "",
    "| rows | runs (local/full/scipy) | frictionid local [s] | frictionid local, 1 thread [s] "
    "| frictionid full [s] | scipy [s] | scipy / local | scipy / local, 1 thread "
    "| cost frictionid | cost scipy | rel. diff |",
    "|---:|:---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
for s in summary:
    lines.append(
        f"| {e(s['rows'])} | {s['runs_local']}/{s['runs_full']}/{s['runs_scipy']} | "
        f"{sig(s['frictionid_local_s'])} | {sig(s['frictionid_local_1thread_s'])} | "
        f"{sig(s['frictionid_full_s'])} | {sig(s['scipy_s'])} | "
        f"{s['ratio_scipy_to_local']:.1f} | {s['ratio_scipy_to_local_1thread']:.1f} | "
        f"{s['cost_frictionid_local']:.12g} | "
        f"{s['cost_scipy']:.12g} | {s['rel_diff_scipy_vs_local']:+.1e} |")
lines += ["", "Work per fit and CPU time (medians; frictionid CPU is the whole command's user + "
          "system time, scipy CPU is the least_squares call's process time):", "",
          "| rows | Ceres iterations | scipy nfev / njev (each njev = 6 extra evaluations) | "
          "frictionid local µs per row per iteration | scipy µs per row per Jacobian | "
          "frictionid full: global / local [s] | frictionid local command CPU [s] | "
          "frictionid full CPU [s] | scipy CPU [s] | full-pipeline cost rel. diff vs local |",
          "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
for s in summary:
    lines.append(
        f"| {e(s['rows'])} | {s['iterations_local']} | {s['scipy_nfev']} / {s['scipy_njev']} | "
        f"{s['frictionid_local_us_per_row_iteration']:.2f} | {s['scipy_us_per_row_jacobian']:.2f} | "
        f"{sig(s['frictionid_full_global_s'])} / {sig(s['frictionid_full_local_s'])} | "
        f"{sig(s['frictionid_local_command_cpu_s'])} | {sig(s['frictionid_full_cpu_s'])} | "
        f"{sig(s['scipy_cpu_s'])} | {s['rel_diff_full_vs_local']:+.1e} |")
lines += ["", "Log-log slope of time vs rows (least squares over all sizes; over the two largest):",
          ""]
for k, (a, b) in slopes.items():
    lines.append(f"- {k.replace('_s', '').replace('_', ' ')}: {a:.3f} (all), {b:.3f} "
                 f"({e(top[0]['rows'])}-{e(top[1]['rows'])})")
lines += ["", "Model check (fit_scipy.py vs `frictionid eval --model seed`):", ""]
lines += [f"- {l.strip()}" for l in open(os.path.join(out, "check.txt"))]
open(os.path.join(here, "results.md"), "w").write("\n".join(lines) + "\n")
print("\n".join(lines))
PY

gnuplot <<GP
set terminal svg size 720,480 dynamic font "sans,12"
set output "$here/results.svg"
set datafile separator ","
set logscale xy
set format x "10^{%L}"
set format y "10^{%L}"
set xlabel "rows (4 channels each)"
set ylabel "wall time [s], median"
set key top left
set grid
set title "Seed-model fit: frictionid (Ceres) vs scipy least_squares" noenhanced
set offsets graph 0.05, graph 0.05, graph 0.05, graph 0.05
plot "$here/results.csv" using "rows":"frictionid_local_s" with linespoints pt 7 title "frictionid local stage (Ceres), every core", \
     "" using "rows":"frictionid_local_1thread_s" with linespoints pt 6 title "frictionid local stage, 1 thread", \
     "" using "rows":"frictionid_full_s" with linespoints pt 5 title "frictionid full pipeline (whole command)", \
     "" using "rows":"scipy_s" with linespoints pt 9 title "scipy least_squares (trf, 2-point)" noenhanced
GP
echo "run.sh: wrote $here/results.md, results.csv, runs.csv and results.svg in ${elapsed} s" >&2
