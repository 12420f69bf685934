#!/usr/bin/env bash
# How long does an exact-model fit of 10,000 rows take, and where does the time go?
#
#   experiments/exact_fit_10k/run.sh     # binary: $FRICTIONID, else build/frictionid
#
# Generates 10,000 rows (default design, 1 % noise) from the exact model for three set-ups,
# fits each REPS times with the default settings and writes results.md: median wall time of the
# whole command and the split that `fit` prints (reading, global stage, local fits,
# statistics, report). Scratch in out/ (git-ignored).
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
source "$here/../common.sh"
REPS=${REPS:-5}
ROWS=${ROWS:-10000}
out="$here/out"
rm -rf "$out"
mkdir -p "$out"
cp "$bin" "$out/frictionid"
bin="$out/frictionid"
binary_id="$("$bin" --version), sha256 $(sha256sum "$bin" | cut -c1-12)"
load_before=$(cut -d" " -f1-3 /proc/loadavg)

# name | pressure the data come from | contact spot of the data and the fit | fit options
setups=(
  "hertz (fixed law)|hertz|circle|--pressure hertz"
  "power:1.5 (exponent n fitted from power:1)|power:1.5|circle|--pressure power:1"
  "power:1.5 (n fixed at 1.5)|power:1.5|circle|--pressure power:1.5 --fix n=1.5"
  "hertz on ellipse:0.7 (h_y fitted too)|hertz|ellipse:0.7|--pressure hertz"
  "parabolic on rect:0.7 (h_y fitted too)|parabolic|rect:0.7|--pressure parabolic"
)
TIMEFORMAT="%3R"
echo "setup,rep,wall_s,read_s,global_s,local_s,statistics_s,report_s,iterations,f,kappa,h,n,h_y" \
  > "$out/runs.csv"
for s in "${setups[@]}"; do
  IFS='|' read -r name law contact opts <<< "$s"
  data="$out/data_${law//[:.]/_}_${contact//[:.]/_}.csv"
  tilt=""
  [[ "$contact" == circle ]] || tilt=",h_y=-0.1"
  [[ -f "$data" ]] || "$bin" generate --model exact --pressure "$law" --contact "$contact" \
    --param "f=0.85,kappa=1.3,h=0.12$tilt" --rows "$ROWS" --noise 0.01 --seed 4 \
    --output "$data" > /dev/null 2>&1
  for (( rep = 1; rep <= REPS; rep++ )); do
    # shellcheck disable=SC2086
    wall=$( { time "$bin" fit "$data" --model exact --contact "$contact" $opts \
                --report "$out/report" \
                > "$out/stdout" 2> /dev/null; } 2>&1 )
    times=$(sed -n 's/^time: reading \([0-9.]*\) s, global stage \([0-9.]*\) s, local fits \([0-9.]*\) s, statistics and predictions \([0-9.]*\) s, report \([0-9.]*\) s$/\1,\2,\3,\4,\5/p' "$out/stdout")
    params=$("$py" -c '
import json, sys
r = json.load(open(sys.argv[1]))
p = r["parameters"]
print(",".join([str(r["solver"]["iterations"])] +
               [repr(p[k]["value"]) if k in p else "" for k in ("f", "kappa", "h", "n", "h_y")]))' \
      "$out/report/report.json")
    echo "$name,$rep,$wall,$times,$params" >> "$out/runs.csv"
  done
  echo "run.sh: $name done" >&2
done
load_after=$(cut -d" " -f1-3 /proc/loadavg)

"$py" - "$out/runs.csv" "$here/results.md" "$binary_id" "$ROWS" "$load_before" \
  "$load_after" "$(getconf _NPROCESSORS_ONLN)" <<'PY'
import csv, statistics, sys
runs, out, binary_id, rows, before, after, cpus = sys.argv[1:8]
by = {}
for r in csv.DictReader(open(runs)):
    by.setdefault(r["setup"], []).append(r)
lines = [f"{binary_id}; {rows} rows of `generate --model exact` (default design, 1 % noise, "
         f"truth f = 0.85, κ = 1.3, h = 0.12, on a non-circular spot h_y = -0.1), default "
         f"`fit` settings with the data's `--contact`, {cpus} CPUs, load "
         f"average {before} before and {after} after. Medians over "
         f"{len(next(iter(by.values())))} runs; wall = the whole command.", "",
         "| set-up | wall [s] | reading | global stage | local fits | statistics | report | "
         "iterations | f | κ | h | n | h_y |",
         "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
for name, rs in by.items():
    med = lambda k: statistics.median(float(r[k]) for r in rs)
    val = lambda k: f"{float(rs[0][k]):.6g}" if rs[0][k] else "–"
    lines.append(f"| {name} | {med('wall_s'):.2f} | {med('read_s'):.3f} | {med('global_s'):.3f} | "
                 f"{med('local_s'):.3f} | {med('statistics_s'):.3f} | {med('report_s'):.3f} | "
                 f"{rs[0]['iterations']} | {val('f')} | {val('kappa')} | {val('h')} | {val('n')} | "
                 f"{val('h_y')} |")
open(out, "w").write("\n".join(lines) + "\n")
print("\n".join(lines))
PY
